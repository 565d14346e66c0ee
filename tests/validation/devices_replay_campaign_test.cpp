// A campaign re-run from its recording: the five hits of a simulated hammer
// campaign on fork A with wheel (thesis Table 11, right) are written to a
// Universal File (58b, function type 1, one load case per hit, double
// precision), played back by the replay driver, cut at the trigger marks it
// gives, and identified again. The replayed hits equal the recorded ones bit
// for bit, so the identification gives the same modes to the last bit and
// both give back Table 11.
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/io/uff/uff.h"
#include "devices_campaign.h"

namespace mozzi::devices {
namespace {

namespace uff = core::io::uff;

std::string writeHits(const std::vector<core::signal::TimeRecord>& hits) {
  uff::UffFile file;
  for (std::size_t k = 0; k < hits.size(); ++k) {
    const auto& h = hits[k];
    for (std::size_t c = 0; c < h.channels.size(); ++c) {
      const auto& ch = h.channels[c];
      uff::Function58 f;
      f.functionType = uff::FunctionType::TimeResponse;
      f.loadCase = static_cast<int>(k + 1);
      f.response = uff::Channel58::fromDof(ch.dof);
      f.ordinateType = uff::OrdinateType::RealDouble;
      f.abscissaMin = -static_cast<double>(h.preTriggerSamples) / h.sampleRateHz;
      f.abscissaIncrement = 1.0 / h.sampleRateHz;
      f.abscissaAxis.specificDataType = 17;
      f.ordinateNumerator.specificDataType = ch.transducer.kind == core::signal::TransducerKind::Force ? 13 : 12;
      f.ordinateNumerator.unitsLabel = ch.transducer.unit;
      f.real = h.samples.col(static_cast<Eigen::Index>(c));
      f.binary = true;
      file.datasets.push_back(uff::makeDataset(f));
    }
  }
  const std::string path =
      (std::filesystem::temp_directory_path() / ("mozzi_rerun_" + std::to_string(::getpid()) + ".uff")).string();
  EXPECT_TRUE(uff::writeFile(path, file).ok());
  return path;
}

TEST(DevicesReplayCampaign, ReRunFromTheRecordingGivesTheSameModes) {
  testing::HammerCampaign c;
  c.specimen = "fork-a-with-wheel";
  c.sampleRateHz = 512.0;
  c.recordSeconds = 4.0;
  c.bandLowHz = 15.0;
  c.bandHighHz = 90.0;
  c.responseRange = 4;
  auto live = testing::runHammerCampaign(c);
  ASSERT_TRUE(live.has_value());
  ASSERT_EQ(live->records, 5);
  const std::string path = writeHits(live->hits);

  // Replay every channel of the recording as fast as it is taken.
  auto dev = sim::makeReplayDriver()->create(DeviceDescriptor{"sim-replay", "", 0, 0, "", path}).value();
  AcquisitionConfig cfg;
  cfg.sampleRateHz = c.sampleRateHz;
  for (int i = 0; i < 4; ++i) {
    ChannelConfig ch;
    ch.input = i;
    cfg.channels.push_back(ch);
  }
  cfg.parameters["sim.realtime"] = false;
  auto run = testing::acquire(*dev, cfg);
  ASSERT_TRUE(run.has_value());
  EXPECT_EQ(run->end.reason, EndReason::Completed);
  ASSERT_EQ(run->triggers.size(), 5u);

  std::vector<core::signal::TimeRecord> hits;
  for (std::size_t k = 0; k < run->triggers.size(); ++k) {
    const auto& rec = live->hits[k];
    const std::int64_t first = run->triggers[k].sample - rec.preTriggerSamples;
    core::signal::TimeRecord tr = rec;  // the same channel description as the live campaign
    tr.samples = run->values.middleRows(first, rec.samples.rows());
    ASSERT_EQ(std::memcmp(tr.samples.data(), rec.samples.data(), sizeof(double) * rec.samples.size()), 0)
        << "hit " << k;
    hits.push_back(tr);
  }
  auto again = testing::identifyHits(hits, c);
  ASSERT_TRUE(again.has_value());
  const auto& a = live->identification.model.modes;
  const auto& b = again->model.modes;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t r = 0; r < a.size(); ++r) {
    EXPECT_EQ(a[r].frequencyHz(), b[r].frequencyHz());
    EXPECT_EQ(a[r].zeta(), b[r].zeta());
  }
  // And the recording still gives Table 11 (right): 22.3, 23.5, 67.2 Hz within 0.5%.
  for (double f : {22.3, 23.5, 67.2}) {
    double best = 1e9;
    for (const auto& m : b) best = std::min(best, std::abs(m.frequencyHz() - f) / f);
    std::printf("Table 11 (right) %.1f Hz: replayed campaign within %.3f%%\n", f, 100 * best);
    EXPECT_LT(best, 0.005) << f;
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace mozzi::devices
