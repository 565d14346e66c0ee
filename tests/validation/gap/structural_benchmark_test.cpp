// Structural sim-to-real gap benchmark with hidden truth (issues 10 and 16,
// GAP.md "Testing it honestly"): four lumped structures (one and two hammer
// references), every catalogue effect at two sizes (masses at two DOFs),
// controls with no effect, two effects at once, designed-ambiguous pairs, an
// out-of-catalogue effect and one spring of a calibrated group off on its own,
// under measurement noise with a relative part and an additive floor, with and
// without coherence records, from 0.3% to 3%. The diagnosis sees only the
// nominal model and the noisy FRFs (its noise model comes from the data or
// the coherence, never from the generator). Prints the per-case table, the
// issue 16 targets per noise model and the summary; asserts the targets.
//
// CI size by default: each structure under one noise model (rotating over
// rel 1%, rel+floor 1%, rel+floor 0.3% with coherence, rel+floor 3%), bootstrap
// 20. MOZZI_GAP_BENCH_FULL=1 runs every structure under all nine noise models
// (relative only / with floor / with floor and coherence x 0.3%, 1%, 3%),
// 4 controls each: docs/validation/gap-structural.md. MOZZI_GAP_BENCH_THREADS=N
// spreads the cases over N threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <thread>

#include "validation/gap/structural_benchmark_runner.h"

namespace mozzi::gap_bench {
namespace {

TEST(GapStructuralBenchmark, HiddenTruthTargets) {
  const char* fullEnv = std::getenv("MOZZI_GAP_BENCH_FULL");
  const bool full = fullEnv && std::string(fullEnv) == "1";
  const BenchConfig cfg = full ? fullConfig() : BenchConfig{};
  const auto cases = makeCases(cfg);
  std::printf("%s benchmark: %zu diagnoses\n", full ? "Full" : "CI-sized", cases.size());
  printHeader();
  // MOZZI_GAP_BENCH_THREADS=N runs the cases on N threads (each diagnosis is
  // single-threaded and seeded by its case index: the results do not depend
  // on N, only the order of the printed rows does).
  int threads = 1;
  if (const char* t = std::getenv("MOZZI_GAP_BENCH_THREADS")) threads = std::max(1, std::atoi(t));
  std::vector<CaseResult> results(cases.size());
  std::atomic<std::size_t> next{0};
  std::mutex printMutex;
  // MOZZI_GAP_BENCH_ONLY=i runs case i alone (its index in the printed
  // table, same seed) and prints the diagnosis's explanation: for a look at
  // one case; the targets are not asserted then.
  if (const char* only = std::getenv("MOZZI_GAP_BENCH_ONLY")) {
    const auto i = static_cast<std::size_t>(std::atol(only));
    ASSERT_LT(i, cases.size());
    const CaseResult r = runCase(cases[i], cfg, cfg.seed + 1000 + i);
    printCase(r);
    std::printf("%s\n", r.explanation.c_str());
    return;
  }
  auto worker = [&] {
    for (std::size_t i = next++; i < cases.size(); i = next++) {
      results[i] = runCase(cases[i], cfg, cfg.seed + 1000 + i);
      const std::lock_guard<std::mutex> lock(printMutex);
      printCase(results[i]);
      std::fflush(stdout);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  std::map<std::string, std::vector<CaseResult>> byNoise;
  for (std::size_t i = 0; i < cases.size(); ++i) byNoise[cases[i].noise.name].push_back(results[i]);
  std::printf("\nIssue 16 targets per noise model\n");
  std::printf("  %-18s %-17s %-17s %-17s %-17s %-9s %s\n", "noise model", "top-1 (>=90%)", "controls none",
              "false attrib.", "two both named", "size err", "s/diag");
  std::printf("  %-18s %-17s %-17s %-17s %-17s %-9s\n", "", "", "(>=90%)", "(<=5%)", "(>=70%)", "(<5%)");
  for (const auto& noise : cfg.noises) {
    if (byNoise.count(noise.name)) printNoiseRow(noise.name, summarise(byNoise[noise.name]));
  }
  std::printf(
      "\nVerdicts per case and noise model (right answers / cases; E effect, P partial, N none, "
      "A ambiguous, U unexplained, I not identifiable)\n");
  printVerdictTable(results, cfg.noises);
  const Summary s = summarise(results);
  printSummary(s);
  EXPECT_EQ(s.failures, 0);
  // Issue 16 targets over all noise models.
  EXPECT_GE(s.top1, 0.9 * s.effectCases);
  EXPECT_GE(s.controlNone, 0.9 * s.controls);
  // False attributions at most 5% plus two binomial standard deviations
  // sqrt(0.05 * 0.95 / n) (GAP.md's pre-registered bound; at n = 12 that is 17.6%).
  const double n = s.controls;
  EXPECT_LE(s.controlAttributions / n, 0.05 + 2 * std::sqrt(0.05 * 0.95 / n));
  // Two effects at once: both members named in 70% (issue 16's target; 8/8
  // measured on 27 Nov, docs/validation/gap-structural.md).
  EXPECT_GE(s.twoBothNamed, 0.7 * s.twoEffects);
  EXPECT_LT(s.medianSizeError, 0.05);
  // Issue 10 targets.
  EXPECT_GE(s.medianShrink, 80.0);
  EXPECT_LE(s.ambiguousWrong, 0.1 * s.ambiguous);
  EXPECT_LE(s.outOfCatalogueClean, 0.2 * s.outOfCatalogue);
  if (full) {
    // Top-1 in every noise model (the full run has 64 effect cases per model).
    for (const auto& noise : cfg.noises) {
      const Summary sn = summarise(byNoise[noise.name]);
      EXPECT_GE(sn.top1, 0.9 * sn.effectCases) << noise.name;
    }
  }
}

}  // namespace
}  // namespace mozzi::gap_bench
