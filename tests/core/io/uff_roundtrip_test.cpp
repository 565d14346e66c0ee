// Write -> read gives the same numbers for every dataset type: binary 58b bit
// for bit (both byte orders, single and double), ASCII to the digits the
// format prints (E13.5: 6 significant digits; E20.12: 13; D25.16/17: exact).
#include "core/io/uff/uff.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>

namespace mozzi::core::io::uff {
namespace {

// Relative error bound of a value printed with d significant digits: half a
// unit in the last printed place, 0.5 * 10^(1-d).
constexpr double kSingleDigits = 0.5e-5;   // E13.5 -> 6 significant digits
constexpr double kDoubleDigits = 0.5e-12;  // E20.12 -> 13 significant digits

bool nearRel(double a, double b, double rel) {
  return std::abs(a - b) <= rel * std::abs(b) + 1e-300;
}

// v rounded to the nearest float. Through a volatile: g++ 12 -O2 was seen to
// fold a plain (double)(float)v in the lambda below.
double toFloat(double v) {
  volatile float f = static_cast<float>(v);
  return f;
}

Function58 makeFunction(OrdinateType type, bool even, Eigen::Index n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Function58 f;
  f.idLines = {"Test record", "NONE", "21-Nov-26 05:40:00", "Mozzi test", "NONE"};
  f.functionType = isComplex(type) ? FunctionType::Frf : FunctionType::TimeResponse;
  f.functionId = 3;
  f.versionNumber = 1;
  f.loadCase = 2;
  f.response = Channel58{"ACC 21", 21, 3};
  f.reference = Channel58{"HAMMER", 1, -2};
  f.ordinateType = type;
  f.evenSpacing = even;
  f.abscissaMin = 0.5;
  f.abscissaIncrement = 0.25;
  f.zAxisValue = 0.0;
  f.abscissaAxis = AxisInfo{18, 0, 0, 0, "Frequency", "Hz"};
  f.ordinateNumerator = AxisInfo{12, 1, 0, 0, "Acceleration", "m/s^2"};
  f.ordinateDenominator = AxisInfo{13, 0, 1, 0, "Force", "N"};
  f.zAxis = AxisInfo{};
  // Values over many decades, as measured data have; for single precision
  // they are rounded to float first, which is what a single record can hold.
  auto value = [&]() {
    double v = u(rng) * std::pow(10.0, std::floor(u(rng) * 8.0));
    if (!isDouble(type)) v = toFloat(v);
    return v;
  };
  if (isComplex(type)) {
    f.complex.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) f.complex[i] = Complex(value(), value());
  } else {
    f.real.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) f.real[i] = value();
  }
  if (!even) {
    f.abscissa.resize(n);
    double x = 0.125;
    for (Eigen::Index i = 0; i < n; ++i) {
      x += 0.5 + 0.25 * u(rng);
      f.abscissa[i] = isDouble(type) ? x : toFloat(x);
    }
  }
  return f;
}

UffFile single(DatasetData d) {
  UffFile f;
  f.datasets.push_back(makeDataset(std::move(d)));
  return f;
}

Result<UffFile> roundTrip(const UffFile& in, WriteOptions options = {}) {
  auto bytes = writeBytes(in, options);
  if (!bytes) return bytes.error();
  return readBytes(*bytes);
}

void expectSameHeader(const Function58& a, const Function58& b) {
  EXPECT_EQ(a.idLines, b.idLines);
  EXPECT_EQ(a.functionType, b.functionType);
  EXPECT_EQ(a.functionId, b.functionId);
  EXPECT_EQ(a.versionNumber, b.versionNumber);
  EXPECT_EQ(a.loadCase, b.loadCase);
  EXPECT_EQ(a.response.entityName, b.response.entityName);
  EXPECT_EQ(a.response.node, b.response.node);
  EXPECT_EQ(a.response.direction, b.response.direction);
  EXPECT_EQ(a.reference.entityName, b.reference.entityName);
  EXPECT_EQ(a.reference.node, b.reference.node);
  EXPECT_EQ(a.reference.direction, b.reference.direction);
  EXPECT_EQ(a.ordinateType, b.ordinateType);
  EXPECT_EQ(a.evenSpacing, b.evenSpacing);
  EXPECT_EQ(a.abscissaMin, b.abscissaMin);  // 0.5 and 0.25 are exact in E13.5
  if (a.evenSpacing) {
    EXPECT_EQ(a.abscissaIncrement, b.abscissaIncrement);
  }
  EXPECT_EQ(a.ordinateNumerator.specificDataType, b.ordinateNumerator.specificDataType);
  EXPECT_EQ(a.ordinateNumerator.lengthExponent, b.ordinateNumerator.lengthExponent);
  EXPECT_EQ(a.ordinateDenominator.forceExponent, b.ordinateDenominator.forceExponent);
  EXPECT_EQ(a.ordinateNumerator.unitsLabel, b.ordinateNumerator.unitsLabel);
  EXPECT_EQ(a.abscissaAxis.label, b.abscissaAxis.label);
}

const OrdinateType kTypes[] = {OrdinateType::RealSingle, OrdinateType::RealDouble, OrdinateType::ComplexSingle,
                               OrdinateType::ComplexDouble};

TEST(UffRoundTrip, Binary58IsBitExactForEveryFormAndByteOrder) {
  for (OrdinateType type : kTypes) {
    for (bool even : {true, false}) {
      for (ByteOrder order : {ByteOrder::LittleEndian, ByteOrder::BigEndian}) {
        SCOPED_TRACE("type " + std::to_string(static_cast<int>(type)) + (even ? " even" : " uneven") +
                     (order == ByteOrder::BigEndian ? " big endian" : " little endian"));
        const Function58 f = makeFunction(type, even, 1001, 7);
        WriteOptions opt;
        opt.encoding = Encoding58::Binary;
        opt.byteOrder = order;
        auto back = roundTrip(single(f), opt);
        ASSERT_TRUE(back.ok()) << back.error().describe();
        const auto* g = back->datasets.at(0).get<Function58>();
        ASSERT_NE(g, nullptr);
        EXPECT_TRUE(g->binary);
        EXPECT_EQ(g->byteOrder, order);
        expectSameHeader(f, *g);
        ASSERT_EQ(g->pointCount(), 1001);
        // Bit-exact: compare the bytes of the doubles.
        if (isComplex(type)) {
          EXPECT_EQ(std::memcmp(f.complex.data(), g->complex.data(), sizeof(Complex) * 1001), 0);
        } else {
          EXPECT_EQ(std::memcmp(f.real.data(), g->real.data(), sizeof(double) * 1001), 0);
        }
        if (!even) {
          EXPECT_EQ(std::memcmp(f.abscissa.data(), g->abscissa.data(), sizeof(double) * 1001), 0);
        }
      }
    }
  }
}

TEST(UffRoundTrip, BigEndianBlockHoldsBigEndianBytes) {
  // Independent check of the byte order: 1.0f is 3F 80 00 00 big endian.
  Function58 f = makeFunction(OrdinateType::RealSingle, true, 1, 1);
  f.real[0] = 1.0;
  WriteOptions opt;
  opt.encoding = Encoding58::Binary;
  opt.byteOrder = ByteOrder::BigEndian;
  auto bytes = writeBytes(single(f), opt);
  ASSERT_TRUE(bytes.ok());
  EXPECT_NE(bytes->find(std::string("\x3f\x80\x00\x00", 4)), std::string::npos);
  EXPECT_NE(bytes->find("    58b     2     2          11           4"), std::string::npos);
}

TEST(UffRoundTrip, Ascii58KeepsTheFormatsDigits) {
  for (OrdinateType type : kTypes) {
    for (bool even : {true, false}) {
      SCOPED_TRACE("type " + std::to_string(static_cast<int>(type)) + (even ? " even" : " uneven"));
      const Function58 f = makeFunction(type, even, 997, 11);
      WriteOptions opt;
      opt.encoding = Encoding58::Ascii;
      auto back = roundTrip(single(f), opt);
      ASSERT_TRUE(back.ok()) << back.error().describe();
      const auto* g = back->datasets.at(0).get<Function58>();
      ASSERT_NE(g, nullptr);
      EXPECT_FALSE(g->binary);
      expectSameHeader(f, *g);
      ASSERT_EQ(g->pointCount(), 997);
      const double rel = isDouble(type) ? kDoubleDigits : kSingleDigits;
      double worst = 0.0;
      for (Eigen::Index i = 0; i < 997; ++i) {
        if (isComplex(type)) {
          EXPECT_TRUE(nearRel(g->complex[i].real(), f.complex[i].real(), rel)) << i;
          EXPECT_TRUE(nearRel(g->complex[i].imag(), f.complex[i].imag(), rel)) << i;
          worst = std::max(worst, std::abs(g->complex[i].real() - f.complex[i].real()) / std::abs(f.complex[i].real()));
        } else {
          EXPECT_TRUE(nearRel(g->real[i], f.real[i], rel)) << i << ": " << g->real[i] << " vs " << f.real[i];
          worst = std::max(worst, std::abs(g->real[i] - f.real[i]) / std::abs(f.real[i]));
        }
        // Uneven abscissae are printed E13.5 in every layout.
        if (!even) {
          EXPECT_TRUE(nearRel(g->abscissa[i], f.abscissa[i], kSingleDigits)) << i;
        }
      }
      EXPECT_GT(worst, 0.0);  // the ASCII form really rounds (the test is not comparing a copy)
      // Writing what was read reproduces the same text: the digits are stable.
      auto once = writeBytes(*back, opt);
      auto twice = roundTrip(*back, opt);
      ASSERT_TRUE(once.ok() && twice.ok());
      auto again = writeBytes(*twice, opt);
      ASSERT_TRUE(again.ok());
      EXPECT_EQ(*once, *again);
    }
  }
}

TEST(UffRoundTrip, EveryOtherDatasetType) {
  UffFile in;
  Header151 h{"frame_A",
              "Motorcycle frame A, front-constrained",
              "Mozzi",
              "21-Nov-26 05:40:00",
              "21-Nov-26",
              "Mozzi 0.1",
              "21-Nov-26 05:41:00"};
  in.datasets.push_back(makeDataset(h));
  Units164 u;
  u.unitsCode = 5;
  u.description = "MM (milli newton)";
  u.lengthFactor = 1000.0;
  u.forceFactor = 1.0 / 3.0;  // not a short decimal: D25.17 must keep it exactly
  u.temperatureFactor = 1.0;
  u.temperatureOffset = 273.15;
  in.datasets.push_back(makeDataset(u));
  NodeSet n15;
  n15.datasetType = 15;
  n15.nodes = {{1, 0, 0, 11, Vector3(0.1234567, -2.5, 1e-3)}, {22, 1, 2, 7, Vector3(-51.619, 51.619, 50.0)}};
  in.datasets.push_back(makeDataset(n15));
  NodeSet n2411;
  n2411.datasetType = 2411;
  n2411.nodes = {{1, 0, 0, 11, Vector3(1.0 / 3.0, -0.1, 2.0 / 7.0)}, {1000000, 3, 3, 1, Vector3(1e-20, 6e22, -0.0)}};
  in.datasets.push_back(makeDataset(n2411));
  CoordinateSystemSet c18;
  c18.datasetType = 18;
  CoordinateSystem a;
  a.label = 4;
  a.name = "SYS4";
  a.origin = Vector3(2.4, -0.95, 0.0);
  a.xPoint = Vector3(1.4, -0.95, 0.0);
  a.xzPoint = Vector3(1.4, -0.95, -1.0);
  c18.systems = {a};
  in.datasets.push_back(makeDataset(c18));
  CoordinateSystemSet c2420;
  c2420.datasetType = 2420;
  c2420.partName = "Swing-arm A";
  CoordinateSystem b;
  b.label = 2;
  b.name = "rotated";
  const double s = std::sin(0.3);
  const double co = std::cos(0.3);
  b.axes << co, s, 0, -s, co, 0, 0, 0, 1;
  b.origin = Vector3(0.5, 0.25, -1.0 / 3.0);
  c2420.systems = {b};
  in.datasets.push_back(makeDataset(c2420));
  TraceLine82 t;
  t.traceNumber = 3;
  t.color = 8;
  t.description = "Dalle";
  t.nodes = {34, 33, 36, 35, 32, 31, 34, 0, 33, 32, 0};
  in.datasets.push_back(makeDataset(t));
  ModalData55 m;
  m.idLines = {"Mode 1", "NONE", "NONE", "NONE", "NONE"};
  m.analysisType = AnalysisType::NormalMode;
  m.integerValues = {1, 1};
  m.realValues = {18.4, 1.0, 0.0123, 0.0};
  m.nodes = {{1, ComplexVector::Constant(3, Complex(-1.46518, 0))},
             {2, ComplexVector::Constant(3, Complex(0.150162, 0))}};
  in.datasets.push_back(makeDataset(m));
  ModalData55 mc = m;
  mc.analysisType = AnalysisType::ComplexEigenSecondOrder;
  mc.complexData = true;
  mc.realValues = {-0.1111111, 41.11111, 4111.111, -3111.111, -111111.0, -211111.0};
  mc.nodes = {
      {111111, (ComplexVector(3) << Complex(0, 0), Complex(0.1111111, 0.09111111), Complex(0.007111111, 0.004111111))
                   .finished()}};
  in.datasets.push_back(makeDataset(mc));

  auto back = roundTrip(in);
  ASSERT_TRUE(back.ok()) << back.error().describe();
  ASSERT_EQ(back->datasets.size(), in.datasets.size());
  EXPECT_TRUE(back->warnings.empty()) << back->warnings.front().describe();

  const auto* h2 = back->datasets[0].get<Header151>();
  ASSERT_NE(h2, nullptr);
  EXPECT_EQ(h2->modelName, h.modelName);
  EXPECT_EQ(h2->description, h.description);
  EXPECT_EQ(h2->uffWritten, h.uffWritten);

  const auto* u2 = back->datasets[1].get<Units164>();
  ASSERT_NE(u2, nullptr);
  EXPECT_EQ(u2->unitsCode, 5);
  EXPECT_EQ(u2->description, u.description);
  EXPECT_EQ(u2->forceFactor, u.forceFactor);  // 18 digits: exact
  EXPECT_EQ(u2->temperatureOffset, 273.15);

  const auto* n2 = back->datasets[2].get<NodeSet>();
  ASSERT_NE(n2, nullptr);
  EXPECT_EQ(n2->datasetType, 15);
  ASSERT_EQ(n2->nodes.size(), 2u);
  EXPECT_EQ(n2->nodes[1].label, 22);
  EXPECT_EQ(n2->nodes[1].displacementCs, 2);
  EXPECT_EQ(n2->nodes[1].color, 7);
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(nearRel(n2->nodes[0].xyz[i], n15.nodes[0].xyz[i], kSingleDigits)) << i;

  const auto* n3 = back->datasets[3].get<NodeSet>();
  ASSERT_NE(n3, nullptr);
  EXPECT_EQ(n3->datasetType, 2411);
  EXPECT_EQ(n3->nodes[0].xyz, n2411.nodes[0].xyz);  // D25.16: 17 digits, exact
  EXPECT_EQ(n3->nodes[1].xyz, n2411.nodes[1].xyz);
  EXPECT_EQ(n3->nodes[1].label, 1000000);

  const auto* c2 = back->datasets[4].get<CoordinateSystemSet>();
  ASSERT_NE(c2, nullptr);
  EXPECT_EQ(c2->datasetType, 18);
  EXPECT_EQ(c2->systems[0].name, "SYS4");
  EXPECT_EQ(c2->systems[0].origin, a.origin);  // short decimals, exact in E13.5
  EXPECT_EQ(c2->systems[0].xzPoint, a.xzPoint);
  EXPECT_NEAR(c2->systems[0].axes(0, 0), -1.0, 1e-15);
  EXPECT_NEAR(c2->systems[0].axes(2, 2), -1.0, 1e-15);

  const auto* c3 = back->datasets[5].get<CoordinateSystemSet>();
  ASSERT_NE(c3, nullptr);
  EXPECT_EQ(c3->datasetType, 2420);
  EXPECT_EQ(c3->partName, "Swing-arm A");
  EXPECT_EQ(c3->systems[0].axes, b.axes);  // D25.16: exact
  EXPECT_EQ(c3->systems[0].origin, b.origin);

  const auto* t2 = back->datasets[6].get<TraceLine82>();
  ASSERT_NE(t2, nullptr);
  EXPECT_EQ(t2->nodes, t.nodes);
  EXPECT_EQ(t2->description, "Dalle");
  EXPECT_EQ(t2->color, 8);

  const auto* m2 = back->datasets[7].get<ModalData55>();
  ASSERT_NE(m2, nullptr);
  EXPECT_EQ(m2->analysisType, AnalysisType::NormalMode);
  EXPECT_EQ(m2->modeNumber(), 1);
  EXPECT_EQ(m2->realValues, m.realValues);  // all exact in 6 digits
  ASSERT_EQ(m2->nodes.size(), 2u);
  EXPECT_EQ(m2->nodes[1].values, m.nodes[1].values);

  const auto* m3 = back->datasets[8].get<ModalData55>();
  ASSERT_NE(m3, nullptr);
  EXPECT_TRUE(m3->complexData);
  ASSERT_EQ(m3->realValues.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_TRUE(nearRel(m3->realValues[i], mc.realValues[i], kSingleDigits)) << i;
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(nearRel(m3->nodes[0].values[i].real(), mc.nodes[0].values[i].real(), kSingleDigits));
    EXPECT_TRUE(nearRel(m3->nodes[0].values[i].imag(), mc.nodes[0].values[i].imag(), kSingleDigits));
  }
}

TEST(UffRoundTrip, VendorFilesSurviveConversionBothWays) {
  // Sample_UFF58b_bin.uff (binary, single) -> ASCII -> binary keeps every
  // float: E13.5 is 6 digits, not enough for a float (needs 9), so the ASCII
  // leg rounds; the binary leg must return exactly what ASCII held.
  const std::string path = std::string(MOZZI_SHARED_DATA_DIR) + "/uff/Sample_UFF58b_bin.uff";
  auto bin = readFile(path);
  ASSERT_TRUE(bin.ok());
  WriteOptions toBin;
  toBin.encoding = Encoding58::Binary;
  auto again = roundTrip(*bin, toBin);
  ASSERT_TRUE(again.ok()) << again.error().describe();
  EXPECT_EQ(again->datasets.at(0).get<Function58>()->real, bin->datasets.at(0).get<Function58>()->real);
  WriteOptions toAscii;
  toAscii.encoding = Encoding58::Ascii;
  auto ascii = roundTrip(*bin, toAscii);
  ASSERT_TRUE(ascii.ok()) << ascii.error().describe();
  const Vector& a = ascii->datasets.at(0).get<Function58>()->real;
  const Vector& b = bin->datasets.at(0).get<Function58>()->real;
  ASSERT_EQ(a.size(), b.size());
  for (Eigen::Index i = 0; i < a.size(); ++i) ASSERT_TRUE(nearRel(a[i], b[i], kSingleDigits)) << i;
}

TEST(UffRoundTrip, WriterRefusesWhatTheFormatCannotHold) {
  Function58 f = makeFunction(OrdinateType::RealDouble, true, 4, 3);
  f.real[2] = std::nan("");
  auto r = writeBytes(single(f));
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("dataset 58"), std::string::npos);
  EXPECT_NE(r.error().message.find("NaN"), std::string::npos);

  Function58 g = makeFunction(OrdinateType::RealDouble, false, 4, 3);
  g.abscissa.resize(3);
  auto r2 = writeBytes(single(g));
  ASSERT_FALSE(r2.ok());
  EXPECT_NE(r2.error().message.find("uneven abscissa has 3 values for 4 points"), std::string::npos);

  Dataset skipped;
  skipped.type = 2414;
  skipped.data = SkippedDataset{10};
  std::ostringstream out;
  auto r3 = writeDataset(out, skipped);
  ASSERT_FALSE(r3.ok());
  EXPECT_EQ(r3.error().code, ErrorCode::Unsupported);
}

}  // namespace
}  // namespace mozzi::core::io::uff
