// Campaign engine latencies (issue 15 targets), at 8 channels (hammer and
// seven accelerometers) x 51.2 kS/s with 2 s records (102400 scans, 3.3 MB
// of float32 per hit):
//   TriggerToVerdict: the last device block of a hit (50 ms, 2560 scans)
//     reaches the engine -> the software trigger completes the record ->
//     float32 rounding -> hit quality -> rules, including the poor-coherence
//     rule (argument 1), which tries the hit on a copy of the point's running
//     average of two hits. Target <= 50 ms.
//   RunningFrfUpdate: the accepted hit added to the point's average and its
//     FRF (stored band) recomputed for the live plot (after the verdict).
//   HitCommit: ProjectStore::commitHit of that hit into a project on the
//     build folder's disk (encode, INSERT, COMMIT with the WAL fsync),
//     checkpoint between hits as the engine does. Target <= 20 ms.
// Figures: docs/performance/campaign.md.
//
//   build/tests/campaign_hit_bench --benchmark_min_time=2

#include <benchmark/benchmark.h>
#include <unistd.h>
#include <Eigen/LU>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "core/io/project_store.h"
#include "core/signal/hit_synthesis.h"
#include "devices/campaign/campaign_definition.h"
#include "devices/campaign/hit_pipeline.h"
#include "devices/common/trigger.h"

namespace {

namespace fs = std::filesystem;
using namespace mozzi;
using namespace mozzi::devices::campaign;

constexpr double kRate = 51200.0;
constexpr int kAccelerometers = 7;

// A 7-DOF chain with modes from 30 to 900 Hz (mass-normalised shapes), a
// 1 ms half-sine hit of 200 N, noise as the simulated station's.
core::signal::TimeRecord syntheticHit(std::uint64_t seed) {
  const int n = kAccelerometers;
  core::Matrix phi(n, n);
  for (int i = 0; i < n; ++i)
    for (int r = 0; r < n; ++r) phi(i, r) = std::sin((i + 1) * (r + 1) * M_PI / (n + 1)) * 0.5;
  std::vector<double> f = {30, 80, 150, 260, 400, 620, 900}, zeta(7, 0.02);
  const core::Matrix inv = phi.inverse();
  core::Matrix w2 = core::Matrix::Zero(n, n), c = core::Matrix::Zero(n, n);
  for (int r = 0; r < n; ++r) {
    const double w = 2 * M_PI * f[static_cast<std::size_t>(r)];
    w2(r, r) = w * w;
    c(r, r) = 2 * 0.02 * w;
  }
  core::signal::LinearMdof sys;
  sys.mass = inv.transpose() * inv;
  sys.stiffness = inv.transpose() * w2 * inv;
  sys.damping = inv.transpose() * c * inv;
  core::signal::HammerHitSpec spec;
  spec.sampleRateHz = kRate;
  spec.sampleCount = static_cast<Eigen::Index>(2.0 * kRate);
  spec.preTriggerSamples = static_cast<Eigen::Index>(0.2 * kRate);
  spec.oversampling = 1;
  spec.peakForceN = 200.0;
  spec.pulseWidthS = 1e-3;
  spec.forceNoiseRms = 0.05;
  spec.responseNoiseRms = 0.002;
  spec.seed = seed;
  auto hit = core::signal::synthesizeHammerHit(sys, spec);
  if (!hit) {
    std::fprintf(stderr, "cannot synthesise the hit: %s\n", hit.error().describe().c_str());
    std::abort();
  }
  return std::move(*hit);
}

CampaignDefinition benchDefinition() {
  CampaignDefinition d;
  for (int i = 1; i <= kAccelerometers; ++i) d.points.push_back(core::Dof{i, core::Direction::Z, false});
  ChannelAssignment h;
  h.input = 0;
  h.transducer = {core::signal::TransducerKind::Force, "PCB 086C03", "", 2.25, "N", true};
  h.roving = true;
  d.channels.push_back(h);
  for (int i = 1; i <= kAccelerometers; ++i) {
    ChannelAssignment a;
    a.input = i;
    a.transducer = {core::signal::TransducerKind::Acceleration, "PCB M352C65", "", 10.0, "m/s^2", true};
    a.dof = core::Dof{i, core::Direction::Z, false};
    d.channels.push_back(a);
  }
  d.acquisition = {kRate, 2.0, 0.1, 10.0};
  d.hitsPerPoint = 5;
  d.rules.minCoherence = 0.5;
  d.driver = "sim-hammer";
  return d;
}

struct Fixture {
  CampaignDefinition def = benchDefinition();
  core::signal::TimeRecord hit = syntheticHit(1);
  std::unique_ptr<PointAverage> average;
  Fixture() {
    average = std::make_unique<PointAverage>(def);
    for (std::uint64_t s : {2, 3}) {
      auto r = syntheticHit(s);
      r.samples = samplesFromStored(storedSamples(r.samples));
      (void)average->add(r);
    }
  }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

void TriggerToVerdict(benchmark::State& state) {
  auto& fx = fixture();
  const bool coherenceRule = state.range(0) != 0;
  fx.def.rules.minCoherence = coherenceRule ? 0.5 : 0.0;
  const auto& samples = fx.hit.samples;
  const Eigen::Index block = 2560;  // 50 ms at 51.2 kS/s, the driver's block
  const Eigen::Index n = samples.rows();
  // The device stream: 0.5 s of quiet (the ring fills), the hit, 0.1 s more.
  const Eigen::Index lead = static_cast<Eigen::Index>(0.5 * kRate) - fx.hit.preTriggerSamples;
  core::Matrix stream = core::Matrix::Zero(lead + n + 2 * block, samples.cols());
  stream.middleRows(lead, n) = samples;
  devices::SoftwareTriggerConfig tc;
  tc.level = fx.def.acquisition.triggerLevel;
  tc.recordScans = fx.def.recordScans();
  tc.preTriggerFraction = fx.def.acquisition.preTriggerFraction;
  tc.fullScale.assign(static_cast<std::size_t>(samples.cols()), 1e6);
  // The block that completes the record.
  Eigen::Index lastStart = -1;
  {
    auto trig = devices::SoftwareTrigger::create(tc, static_cast<int>(samples.cols())).value();
    for (Eigen::Index s = 0; s + block <= stream.rows() && lastStart < 0; s += block)
      if (!trig.feed(s, stream.middleRows(s, block)).empty()) lastStart = s;
  }
  if (lastStart < 0) {
    state.SkipWithError("the trigger never completes a record");
    return;
  }
  for (auto _ : state) {
    state.PauseTiming();
    auto trig = devices::SoftwareTrigger::create(tc, static_cast<int>(samples.cols())).value();
    for (Eigen::Index s = 0; s < lastStart; s += block) (void)trig.feed(s, stream.middleRows(s, block));
    state.ResumeTiming();
    auto records = trig.feed(lastStart, stream.middleRows(lastStart, block));
    if (records.size() != 1) {
      state.SkipWithError("the last block completes no record");
      break;
    }
    auto tr = timeRecordFor(fx.def, fx.def.points[0], kRate, tc.fullScale,
                            samplesFromStored(storedSamples(records.front().samples)));
    tr.preTriggerSamples = records.front().preTriggerScans;
    auto verdict = judgeHit(fx.def, tr, fx.average.get());
    if (!verdict || (coherenceRule && !verdict->meanCoherence)) {
      state.SkipWithError(verdict ? "the coherence rule did not run" : verdict.error().describe().c_str());
      break;
    }
    benchmark::DoNotOptimize(verdict);
  }
}
// Argument: the poor-coherence rule off (0) or on (1).
BENCHMARK(TriggerToVerdict)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

void RunningFrfUpdate(benchmark::State& state) {
  auto& fx = fixture();
  auto tr = fx.hit;
  tr.samples = samplesFromStored(storedSamples(tr.samples));
  for (auto _ : state) {
    state.PauseTiming();
    PointAverage copy = *fx.average;
    state.ResumeTiming();
    (void)copy.add(tr);
    auto f = copy.frf();
    benchmark::DoNotOptimize(f);
  }
}
BENCHMARK(RunningFrfUpdate)->Unit(benchmark::kMillisecond)->UseRealTime();

void HitCommit(benchmark::State& state) {
  const fs::path dir = fs::path(MOZZI_BINARY_DIR) / "bench";
  fs::create_directories(dir);
  const std::string path = (dir / ("campaign_commit_" + std::to_string(::getpid()) + ".mozzi")).string();
  auto store = core::io::ProjectStore::create(path, "bench").value();
  const auto sp = store.addSpecimen("bench", "frame", "").value();
  core::io::StoredCampaign c;
  c.specimenId = sp;
  c.name = "bench";
  const auto cid = store.addCampaign(c).value();
  core::io::StoredHit hit;
  hit.campaignId = cid;
  hit.point = core::Dof{1, core::Direction::Z, false};
  hit.sampleRateHz = kRate;
  hit.samples = storedSamples(fixture().hit.samples);
  int seq = 0;
  for (auto _ : state) {
    hit.sequence = ++seq;
    auto id = store.commitHit(hit);
    if (!id) state.SkipWithError(id.error().describe().c_str());
    state.PauseTiming();
    (void)store.checkpoint();  // the engine's idle time between hits
    state.ResumeTiming();
  }
  state.counters["MB_per_hit"] = static_cast<double>(hit.samples.size()) * 4.0 / 1e6;
  for (const char* s : {"", "-wal", "-shm"}) fs::remove(path + s);
}
BENCHMARK(HitCommit)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
