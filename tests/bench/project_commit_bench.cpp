// Hit-commit latency of the project store (issue 4 target: < 20 ms for a
// 4-channel, 16384-sample hit), for both sample encodings and for
// synchronous = FULL (the store's setting) against NORMAL (for comparison
// only). Figures and the choice they support: docs/performance/project.md.
//
//   /tmp/build-store/tests/project_commit_bench --benchmark_min_time=2
//
// Each iteration is one commitHit into a growing project on the temp file
// system, i.e. encode + INSERT + COMMIT with its WAL fsync.

#include <benchmark/benchmark.h>
#include <sqlite3.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <random>
#include <vector>

#include "core/io/project_store.h"
#include "core/io/sample_codec.h"

namespace {

namespace fs = std::filesystem;
using namespace mozzi::core;
using namespace mozzi::core::io;

// A realistic impact: half-sine force pulse on channel 0, three accelerometers
// with four decaying modes each, digitised by a 24-bit converter over +/-10 V
// (the resolution of typical impact-testing front ends) and scaled to SI.
Eigen::MatrixXf realisticHit(std::uint32_t seed) {
  constexpr int kSamples = 16384;
  constexpr double kRate = 25600.0;
  const double lsbVolts = 20.0 / (1 << 24);
  const double sensitivity[4] = {2.25e-3, 1.02e-3, 1.02e-3, 1.02e-3};  // V per N, V per m/s^2
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 3e-5);  // volts rms at the input
  Eigen::MatrixXf s(kSamples, 4);
  for (int r = 0; r < kSamples; ++r) {
    const double t = r / kRate;
    double volts[4];
    volts[0] = (r < 12 ? 0.4 * std::sin(M_PI * r / 12.0) : 0.0);
    for (int c = 1; c < 4; ++c) {
      double a = 0;
      const double fn[4] = {42.0, 118.0, 260.0, 515.0};
      for (int m = 0; m < 4; ++m)
        a += (0.3 / (m + 1)) * std::exp(-2 * M_PI * fn[m] * 0.015 * t) * std::sin(2 * M_PI * fn[m] * t + c);
      volts[c] = a;
    }
    for (int c = 0; c < 4; ++c) {
      const double quantised = std::round((volts[c] + noise(rng)) / lsbVolts) * lsbVolts;
      s(r, c) = static_cast<float>(quantised / sensitivity[c]);
    }
  }
  return s;
}

void runCommits(benchmark::State& state, const fs::path& dir) {
  const auto encoding = static_cast<SampleEncoding>(state.range(0));
  const bool full = state.range(1) != 0;
  const bool idleCheckpoint = state.range(2) != 0;
  auto store = ProjectStore::create((dir / "bench.mozzi").string(), "bench");
  if (!store) {
    state.SkipWithError(store.error().describe().c_str());
    return;
  }
  store->setHitEncoding(encoding);
  if (!full) sqlite3_exec(store->connection(), "PRAGMA synchronous = NORMAL", nullptr, nullptr, nullptr);
  auto specimen = store->addSpecimen("Frame A", "frame", "");
  StoredCampaign campaign;
  campaign.specimenId = *specimen;
  campaign.name = "bench";
  auto campaignId = store->addCampaign(campaign);
  StoredHit hit;
  hit.campaignId = *campaignId;
  hit.point = Dof{1, Direction::Z, false};
  hit.sampleRateHz = 25600.0;
  hit.samples = realisticHit(1);
  std::int64_t storedBytes = 0;
  int sequence = 0;
  std::vector<double> latencyMs;
  for (auto _ : state) {
    hit.sequence = ++sequence;
    const auto t0 = std::chrono::steady_clock::now();
    auto id = store->commitHit(hit);
    latencyMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    if (!id) {
      state.SkipWithError(id.error().describe().c_str());
      break;
    }
    benchmark::DoNotOptimize(*id);
    if (idleCheckpoint) {
      // The acquisition engine's idle time between hits (seconds in a real
      // campaign) is not part of the commit latency.
      state.PauseTiming();
      (void)store->checkpoint();
      state.ResumeTiming();
    }
  }
  if (!latencyMs.empty()) {
    // Worst and 99th-percentile wall-clock latency: the figure a technician
    // waits for before the next hit is armed.
    std::sort(latencyMs.begin(), latencyMs.end());
    state.counters["p99_ms"] = latencyMs[latencyMs.size() * 99 / 100];
    state.counters["max_ms"] = latencyMs.back();
  }
  if (auto list = store->hits(*campaignId); list && !list->empty()) storedBytes = list->front().storedBytes;
  state.counters["stored_bytes"] = static_cast<double>(storedBytes);
  state.counters["ratio"] = static_cast<double>(storedBytes) / (16384.0 * 4 * 4);
  state.SetBytesProcessed(state.iterations() * 16384 * 4 * 4);
}

void commitHit(benchmark::State& state) {
  const fs::path dir = fs::temp_directory_path() / ("mozzi_bench_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  runCommits(state, dir);  // closes the project before the folder goes
  fs::remove_all(dir);
}
// Args: encoding (0 raw, 1 shuffled zlib), synchronous FULL (1) or NORMAL (0),
// checkpoint between hits (1) or leave it to SQLite's auto-checkpoint (0).
BENCHMARK(commitHit)
    ->Args({0, 1, 0})
    ->Args({0, 1, 1})
    ->Args({1, 1, 0})
    ->Args({1, 1, 1})
    ->Args({0, 0, 0})
    ->Args({1, 0, 0})
    ->Unit(benchmark::kMillisecond);

void encodeOnly(benchmark::State& state) {
  const Eigen::MatrixXf s = realisticHit(2);
  for (auto _ : state) {
    auto blob = encodeSamples(s.data(), static_cast<std::size_t>(s.size()), SampleEncoding::ShuffledZlib);
    benchmark::DoNotOptimize(blob);
  }
  state.SetBytesProcessed(state.iterations() * s.size() * 4);
}
BENCHMARK(encodeOnly)->Unit(benchmark::kMillisecond);

void decodeOnly(benchmark::State& state) {
  const Eigen::MatrixXf s = realisticHit(3);
  const auto count = static_cast<std::size_t>(s.size());
  auto blob = encodeSamples(s.data(), count, SampleEncoding::ShuffledZlib);
  const auto crc = sampleCrc32(reinterpret_cast<const std::uint8_t*>(s.data()), count * 4);
  for (auto _ : state) {
    auto values = decodeSamples(blob->data(), blob->size(), SampleEncoding::ShuffledZlib, count, crc, "bench");
    benchmark::DoNotOptimize(values);
  }
  state.SetBytesProcessed(state.iterations() * s.size() * 4);
}
BENCHMARK(decodeOnly)->Unit(benchmark::kMillisecond);

}  // namespace
