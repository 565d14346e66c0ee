// CSV exchange: round trips (export writes 17 significant digits, so the
// doubles come back bit-exact: tolerance 0), unit conversion on import against
// hand-computed SI values, and errors that name the line and column.

#include "core/io/csv/csv_exchange.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <sstream>

namespace mozzi::core::io::csv {
namespace {

TimeTable sampleTime() {
  TimeTable t;
  t.sampleRateHz = 51200.0;
  t.startTimeS = -0.001;
  t.channels = {{"hammer", Dof{1, Direction::Y, false}, "force", "N"},
                {"accel 21:-Z", Dof{21, Direction::Z, true}, "acceleration", "m/s^2"}};
  t.samples.resize(300, 2);
  for (int r = 0; r < 300; ++r) {
    t.samples(r, 0) = r < 10 ? 100.0 * std::sin(M_PI * r / 10.0) : 0.0;
    t.samples(r, 1) = 3.0 * std::exp(-0.01 * r) * std::sin(0.3 * r) + 1e-7 / 3.0;
  }
  return t;
}

TEST(CsvExchange, TimeRecordRoundTripIsExact) {
  const TimeTable in = sampleTime();
  std::ostringstream out;
  ASSERT_TRUE(writeTimeCsv(in, out).ok());
  const std::string text = out.str();
  EXPECT_EQ(text.rfind("# mozzi-csv 1, time-record\n", 0), 0u);
  EXPECT_NE(text.find("time [s],hammer 1:+Y [N],accel 21:-Z [m/s^2]\n"), std::string::npos) << text.substr(0, 200);
  auto back = readTimeCsv(text, "mem.csv");
  ASSERT_TRUE(back.ok()) << back.error().describe();
  EXPECT_EQ(back->sampleRateHz, in.sampleRateHz);
  EXPECT_EQ(back->startTimeS, in.startTimeS);
  EXPECT_TRUE(back->samples == in.samples);
  ASSERT_EQ(back->channels.size(), 2u);
  EXPECT_EQ(back->channels[0].dof, in.channels[0].dof);
  EXPECT_EQ(back->channels[1].dof, in.channels[1].dof);
  EXPECT_EQ(back->channels[1].quantity, "acceleration");
  EXPECT_EQ(back->channels[1].unit, "m/s^2");
}

TEST(CsvExchange, ForeignTimeFileWithNonSiUnitsAndSemicolons) {
  // As a spreadsheet might save it: BOM, semicolons, CRLF, ms and g and kN.
  const std::string text =
      "\xEF\xBB\xBFTime [ms];Force 1:+Z [kN];Acc 2:+Z [g]\r\n"
      "0;0.5;1\r\n"
      "0.5;0.25;-2\r\n"
      "1.0;0;0.5\r\n";
  auto t = readTimeCsv(text, "lab.csv");
  ASSERT_TRUE(t.ok()) << t.error().describe();
  // dt = 0.5 ms -> 2000 Hz; representable exactly except for the 1e-3 factor.
  EXPECT_NEAR(t->sampleRateHz, 2000.0, 1e-9);
  EXPECT_EQ(t->samples.rows(), 3);
  EXPECT_DOUBLE_EQ(t->samples(0, 0), 500.0);           // 0.5 kN = 500 N
  EXPECT_DOUBLE_EQ(t->samples(1, 1), -2.0 * 9.80665);  // standard gravity
  EXPECT_EQ(t->channels[1].dof, (Dof{2, Direction::Z, false}));
  EXPECT_EQ(t->channels[0].unit, "N");
}

TEST(CsvExchange, TimeErrorsNameLineAndColumn) {
  auto noUnit = readTimeCsv("time [s],force\n0,1\n", "a.csv");
  ASSERT_FALSE(noUnit.ok());
  EXPECT_EQ(noUnit.error().where, "a.csv:1, column 2");
  EXPECT_NE(noUnit.error().message.find("no unit"), std::string::npos);

  auto bad = readTimeCsv("time [s],force [N]\n0,1\n0.1,abc\n", "b.csv");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().where, "b.csv:3, column 2");

  auto uneven = readTimeCsv("time [s],force [N]\n0,1\n0.1,1\n0.25,1\n0.3,1\n", "c.csv");
  ASSERT_FALSE(uneven.ok());
  EXPECT_NE(uneven.error().message.find("evenly"), std::string::npos);

  auto unit = readTimeCsv("time [s],force [furlong]\n0,1\n1,2\n", "d.csv");
  ASSERT_FALSE(unit.ok());
  EXPECT_NE(unit.error().message.find("furlong"), std::string::npos);

  auto nan = readTimeCsv("time [s],force [N]\n0,nan\n1,2\n", "e.csv");
  ASSERT_FALSE(nan.ok());
  EXPECT_EQ(nan.error().where, "e.csv:2, column 2");

  auto ragged = readTimeCsv("time [s],force [N]\n0,1,3\n", "f.csv");
  ASSERT_FALSE(ragged.ok());
  EXPECT_NE(ragged.error().message.find("expected 2 fields"), std::string::npos);

  EXPECT_FALSE(readTimeCsv("", "g.csv").ok());
  EXPECT_FALSE(readTimeCsv("force [N]\n1\n2\n", "h.csv").ok());  // no time and no rate
  auto withRate = readTimeCsv("# sample_rate_hz = 100\nforce [N]\n1\n2\n", "i.csv");
  ASSERT_TRUE(withRate.ok()) << withRate.error().describe();
  EXPECT_EQ(withRate->sampleRateHz, 100.0);
}

FrfMatrix sampleFrf() {
  FrfMatrix f;
  f.type = FrfType::Accelerance;
  f.frequencyHz = Vector::LinSpaced(50, 1.0, 500.0);
  f.responses = {Dof{21, Direction::Z, false}, Dof{22, Direction::X, true}};
  f.references = {Dof{1, Direction::Z, false}};
  ComplexMatrix h(50, 2);
  Matrix c(50, 2);
  for (int k = 0; k < 50; ++k) {
    // Single-DOF accelerance -w^2/(k - m w^2 + i c w) with m = 1 kg, fn = 100 Hz, zeta = 2 %.
    const double w = 2 * M_PI * f.frequencyHz[k];
    const double wn = 2 * M_PI * 100.0;
    h(k, 0) = -w * w / Complex(wn * wn - w * w, 2 * 0.02 * wn * w);
    h(k, 1) = 0.3 * h(k, 0) * Complex(0.0, 1.0);
    c(k, 0) = 0.99;
    c(k, 1) = 0.5 + 0.4 * std::cos(0.1 * k);
  }
  f.h = {h};
  f.coherence = {c};
  return f;
}

TEST(CsvExchange, FrfRoundTripIsExact) {
  const FrfMatrix in = sampleFrf();
  std::ostringstream out;
  ASSERT_TRUE(writeFrfCsv(in, out).ok());
  EXPECT_NE(
      out.str().find("frequency [Hz],H 21:+Z/1:+Z re [m/s^2/N],H 21:+Z/1:+Z im [m/s^2/N],coherence 21:+Z/1:+Z [1]"),
      std::string::npos);
  auto back = readFrfCsv(out.str(), "frf.csv");
  ASSERT_TRUE(back.ok()) << back.error().describe();
  EXPECT_EQ(back->type, FrfType::Accelerance);
  EXPECT_EQ(back->frequencyHz, in.frequencyHz);
  EXPECT_EQ(back->responses, in.responses);
  EXPECT_EQ(back->references, in.references);
  EXPECT_EQ(back->h[0], in.h[0]);
  EXPECT_EQ(back->coherence[0], in.coherence[0]);
}

TEST(CsvExchange, FrfUnitsSetTypeAndScale) {
  // 2 mm/N at 10 Hz is receptance 2e-3 m/N; 1 g/N is 9.80665 (m/s^2)/N.
  auto r = readFrfCsv("frequency [Hz],H 3:+X/1:+X re [mm/N],H 3:+X/1:+X im [mm/N]\n10,2,-1\n20,1,0\n", "r.csv");
  ASSERT_TRUE(r.ok()) << r.error().describe();
  EXPECT_EQ(r->type, FrfType::Receptance);
  EXPECT_DOUBLE_EQ(r->h[0](0, 0).real(), 2e-3);
  EXPECT_DOUBLE_EQ(r->h[0](0, 0).imag(), -1e-3);
  auto g = readFrfCsv("frequency [Hz],H 3:+X/1:+X re [g/N],H 3:+X/1:+X im [g/N]\n10,1,0\n", "g.csv");
  ASSERT_TRUE(g.ok());
  EXPECT_EQ(g->type, FrfType::Accelerance);
  EXPECT_DOUBLE_EQ(g->h[0](0, 0).real(), 9.80665);

  auto mixed = readFrfCsv("frequency [Hz],H 3:+X/1:+X re [m/N],H 3:+X/1:+X im [m/s/N]\n10,1,0\n", "m.csv");
  ASSERT_FALSE(mixed.ok());
  EXPECT_EQ(mixed.error().where, "m.csv:1, column 3");
  auto partial = readFrfCsv("frequency [Hz],H 3:+X/1:+X re [m/N]\n10,1\n", "p.csv");
  ASSERT_FALSE(partial.ok());
  EXPECT_NE(partial.error().message.find("lacks its re or im"), std::string::npos);
  auto notIncreasing =
      readFrfCsv("frequency [Hz],H 3:+X/1:+X re [m/N],H 3:+X/1:+X im [m/N]\n10,1,0\n10,1,0\n", "n.csv");
  ASSERT_FALSE(notIncreasing.ok());
  EXPECT_EQ(notIncreasing.error().where, "n.csv:3, column 1");
}

TEST(CsvExchange, ModalTableRoundTripAndLossFactor) {
  ModalTable in;
  in.dofs = {Dof{1, Direction::X, false}, Dof{2, Direction::RZ, true}};
  in.modes.push_back({41.25, 0.0125, ComplexVector(2)});
  in.modes.push_back({97.0, 0.031, ComplexVector(2)});
  in.modes[0].shape << Complex(1.0, 0.0), Complex(-0.25, 0.01);
  in.modes[1].shape << Complex(0.1, -0.2), Complex(1.0, 0.0);
  std::ostringstream out;
  ASSERT_TRUE(writeModalCsv(in, out).ok());
  auto back = readModalCsv(out.str(), "modes.csv");
  ASSERT_TRUE(back.ok()) << back.error().describe();
  EXPECT_EQ(back->dofs, in.dofs);
  ASSERT_EQ(back->modes.size(), 2u);
  EXPECT_EQ(back->modes[1].frequencyHz, 97.0);
  EXPECT_EQ(back->modes[1].dampingRatio, 0.031);
  EXPECT_EQ(back->modes[0].shape, in.modes[0].shape);

  // ICATS-style table: loss factor eta in percent; zeta = eta / 2 (DESIGN.md).
  auto eta = readModalCsv("mode [1],frequency [Hz],loss factor [%]\n1,120,3.0\n", "icats.csv");
  ASSERT_TRUE(eta.ok()) << eta.error().describe();
  EXPECT_DOUBLE_EQ(eta->modes[0].dampingRatio, 0.015);
  EXPECT_TRUE(eta->dofs.empty());
  EXPECT_FALSE(readModalCsv("mode [1],frequency [Hz]\n1,120\n", "x.csv").ok());
}

TEST(CsvExchange, FilesRoundTripThroughDisk) {
  const auto dir = std::filesystem::temp_directory_path() / ("mozzi_csv_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "frf.csv").string();
  ASSERT_TRUE(exportFrfCsv(sampleFrf(), path).ok());
  auto back = importFrfCsv(path);
  ASSERT_TRUE(back.ok()) << back.error().describe();
  EXPECT_EQ(back->h[0], sampleFrf().h[0]);
  auto missing = importTimeCsv((dir / "none.csv").string());
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().code, ErrorCode::NotFound);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mozzi::core::io::csv
