// The replay driver: time records written to a Universal File (58, function
// type 1, double and single precision, ASCII and binary) come back from the
// stream bit for bit in engineering units, with the recorded trigger instants
// marked; bad recordings are refused at open() with the file and record named.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>

#include "core/io/uff/uff.h"
#include "devices/common/driver.h"
#include "devices/sim/sim_drivers.h"
#include "validation/devices_campaign.h"

namespace mozzi::devices {
namespace {

namespace uff = core::io::uff;
using namespace std::chrono_literals;

std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("mozzi_replay_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

uff::Function58 timeRecord(int loadCase, const char* dof, int dataType, const char* unit, const core::Vector& x,
                           double fs, int pre, uff::OrdinateType type, bool binary) {
  uff::Function58 f;
  f.functionType = uff::FunctionType::TimeResponse;
  f.loadCase = loadCase;
  f.response = uff::Channel58::fromDof(*core::parseDof(dof));
  f.ordinateType = type;
  f.evenSpacing = true;
  f.abscissaMin = -pre / fs;
  f.abscissaIncrement = 1.0 / fs;
  f.abscissaAxis.specificDataType = 17;
  f.ordinateNumerator.specificDataType = dataType;
  f.ordinateNumerator.unitsLabel = unit;
  f.real = x;
  f.binary = binary;
  return f;
}

// Three channels (force and two accelerations), `cases` load cases of n
// samples with 10% pre-trigger; values with full double mantissas.
uff::UffFile recording(int cases, Eigen::Index n, double fs, uff::OrdinateType type, bool binary, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 50.0);
  uff::UffFile file;
  const char* dofs[] = {"1:+Z", "1:+Z", "3:-Y"};
  const int kinds[] = {13, 12, 12};
  const char* units[] = {"N", "m/s^2", "m/s^2"};
  for (int lc = 1; lc <= cases; ++lc)
    for (int c = 0; c < 3; ++c) {
      core::Vector x(n);
      for (Eigen::Index i = 0; i < n; ++i) x(i) = g(rng);
      if (type == uff::OrdinateType::RealSingle) x = x.cast<float>().cast<double>();
      file.datasets.push_back(
          uff::makeDataset(timeRecord(lc, dofs[c], kinds[c], units[c], x, fs, static_cast<int>(n / 10), type, binary)));
    }
  return file;
}

core::Matrix expectedSamples(const uff::UffFile& file) {
  const auto recs = file.all<uff::Function58>();
  const Eigen::Index n = recs.front()->real.size();
  const Eigen::Index cases = static_cast<Eigen::Index>(recs.size() / 3);
  core::Matrix m(n * cases, 3);
  for (std::size_t k = 0; k < recs.size(); ++k)
    m.block(static_cast<Eigen::Index>(k / 3) * n, static_cast<Eigen::Index>(k % 3), n, 1) = recs[k]->real;
  return m;
}

std::unique_ptr<Device> replayOf(const std::string& path) {
  return sim::makeReplayDriver()->create(DeviceDescriptor{"sim-replay", "", 0, 0, "", path}).value();
}

AcquisitionConfig allChannels(double fs, bool realtime) {
  AcquisitionConfig cfg;
  cfg.sampleRateHz = fs;
  for (int i = 0; i < 3; ++i) {
    ChannelConfig c;
    c.input = i;
    cfg.channels.push_back(c);
  }
  cfg.parameters["sim.realtime"] = realtime;
  return cfg;
}

testing::Acquired replay(const std::string& path, AcquisitionConfig cfg) {
  auto dev = replayOf(path);
  auto r = testing::acquire(*dev, cfg, 30s);
  return r ? *r : testing::Acquired{{}, {}, {}, {}, StreamEnd{EndReason::Error, 0, "not run"}};
}

bool bitIdentical(const core::Matrix& a, const core::Matrix& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) return false;
  for (Eigen::Index c = 0; c < a.cols(); ++c)
    for (Eigen::Index r = 0; r < a.rows(); ++r)
      if (std::memcmp(&a(r, c), &b(r, c), sizeof(double)) != 0) return false;
  return true;
}

TEST(ReplayDriver, DoubleAndSinglePrecisionRecordsComeBackBitForBit) {
  struct Case {
    uff::OrdinateType type;
    bool binary;
  };
  for (const Case k : {Case{uff::OrdinateType::RealDouble, true}, Case{uff::OrdinateType::RealDouble, false},
                       Case{uff::OrdinateType::RealSingle, true}, Case{uff::OrdinateType::RealSingle, false}}) {
    const double fs = 2048.0;
    const auto file = recording(3, 1000, fs, k.type, k.binary, 5);
    const std::string path = tempPath("bits.uff");
    ASSERT_TRUE(uff::writeFile(path, file).ok());
    // What the file holds after a round trip through the writer (ASCII double
    // precision is written with 17 digits: exact).
    auto back = uff::readFile(path);
    ASSERT_TRUE(back.ok());
    const core::Matrix expected = expectedSamples(*back);
    auto cfg = allChannels(fs, false);
    cfg.blockScans = 333;  // blocks that straddle the load cases
    const auto r = replay(path, cfg);
    EXPECT_EQ(r.end.reason, EndReason::Completed);
    EXPECT_EQ(r.end.samplesDelivered, 3000);
    EXPECT_TRUE(bitIdentical(r.values, expected)) << "type " << static_cast<int>(k.type) << " binary " << k.binary;
    EXPECT_DOUBLE_EQ(r.header.sampleRateHz, fs);
    ASSERT_EQ(r.header.channels.size(), 3u);
    EXPECT_EQ(r.header.channels[0].transducer.unit, "N");
    EXPECT_EQ(r.header.channels[0].transducer.kind, core::signal::TransducerKind::Force);
    EXPECT_EQ(core::formatDof(r.header.channels[2].dof), "3:-Y");
    // One mark per load case at its recorded trigger instant (100 pre-trigger samples).
    ASSERT_EQ(r.triggers.size(), 3u);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(r.triggers[static_cast<std::size_t>(i)].sample, 1000 * i + 100);
    std::remove(path.c_str());
  }
}

TEST(ReplayDriver, ChannelSubsetLoopAndScanCount) {
  const double fs = 1000.0;
  const auto file = recording(2, 500, fs, uff::OrdinateType::RealDouble, true, 9);
  const std::string path = tempPath("loop.uff");
  ASSERT_TRUE(uff::writeFile(path, file).ok());
  const core::Matrix all = expectedSamples(file);
  AcquisitionConfig cfg = allChannels(fs, false);
  cfg.channels = {cfg.channels[2], cfg.channels[0]};  // acc 3:-Y and force (configure orders them by input)
  cfg.scanCount = 2500;                               // two and a half passes
  cfg.parameters["replay.loop"] = true;
  const auto r = replay(path, cfg);
  EXPECT_EQ(r.end.reason, EndReason::Completed);
  ASSERT_EQ(r.values.rows(), 2500);
  for (Eigen::Index i = 0; i < 2500; ++i) {
    ASSERT_EQ(r.values(i, 0), all(i % 1000, 0)) << i;
    ASSERT_EQ(r.values(i, 1), all(i % 1000, 2)) << i;
  }
  std::remove(path.c_str());
}

TEST(ReplayDriver, RealTimePacingTakesTheRecordedDuration) {
  const double fs = 1000.0;
  const auto file = recording(1, 300, fs, uff::OrdinateType::RealDouble, true, 3);
  const std::string path = tempPath("pace.uff");
  ASSERT_TRUE(uff::writeFile(path, file).ok());
  auto cfg = allChannels(fs, true);
  cfg.blockScans = 50;
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = replay(path, cfg);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r.values.rows(), 300);
  // Paced: not before the recorded 0.3 s have passed (a lower bound only; a
  // busy machine may take longer).
  EXPECT_GE(elapsed, 0.29);
  std::remove(path.c_str());
}

TEST(ReplayDriver, BadRecordingsAreRefusedWithAClearError) {
  auto openError = [](const std::string& path) {
    auto dev = replayOf(path);
    auto r = dev->open();
    EXPECT_FALSE(r.ok()) << path;
    EXPECT_EQ(dev->state(), DeviceState::Closed);
    return r.ok() ? std::string() : r.error().describe();
  };
  EXPECT_NE(openError("").find("no recording named"), std::string::npos);
  EXPECT_NE(openError(tempPath("missing.uff")).find("missing.uff"), std::string::npos);

  const std::string path = tempPath("bad.uff");
  {  // an FRF file: no time records
    uff::UffFile f;
    uff::Function58 frf;
    frf.functionType = uff::FunctionType::Frf;
    frf.ordinateType = uff::OrdinateType::ComplexDouble;
    frf.response = uff::Channel58::fromDof(*core::parseDof("1:+Z"));
    frf.reference = frf.response;
    frf.abscissaIncrement = 1.0;
    frf.complex = core::ComplexVector::Ones(8);
    f.datasets.push_back(uff::makeDataset(frf));
    ASSERT_TRUE(uff::writeFile(path, f).ok());
    EXPECT_NE(openError(path).find("no time records"), std::string::npos);
  }
  {  // load case 2 lacks a channel
    auto f = recording(2, 100, 1000.0, uff::OrdinateType::RealDouble, false, 1);
    f.datasets.pop_back();
    ASSERT_TRUE(uff::writeFile(path, f).ok());
    const auto e = openError(path);
    EXPECT_NE(e.find("load case 2"), std::string::npos) << e;
    EXPECT_NE(e.find("same channels"), std::string::npos) << e;
  }
  {  // a second record at another sample rate
    auto f = recording(1, 100, 1000.0, uff::OrdinateType::RealDouble, false, 1);
    f.datasets[1].get<uff::Function58>()->abscissaIncrement = 1.0 / 500.0;
    ASSERT_TRUE(uff::writeFile(path, f).ok());
    const auto e = openError(path);
    EXPECT_NE(e.find("channel 2"), std::string::npos) << e;
  }
  {  // not a universal file at all
    FILE* fp = std::fopen(path.c_str(), "w");
    std::fputs("    -1\n    58\nthis is not a dataset\n", fp);
    std::fclose(fp);
    EXPECT_FALSE(openError(path).empty());
  }
  std::remove(path.c_str());

  // A rate other than the recording's is refused by configure.
  const auto good = recording(1, 100, 1000.0, uff::OrdinateType::RealDouble, false, 1);
  ASSERT_TRUE(uff::writeFile(path, good).ok());
  auto dev = replayOf(path);
  ASSERT_TRUE(dev->open().ok());
  EXPECT_FALSE(dev->configure(allChannels(2000.0, false)).ok());
  EXPECT_TRUE(dev->configure(allChannels(1000.0, false)).ok());
  dev->close();
  std::remove(path.c_str());
}

}  // namespace
}  // namespace mozzi::devices
