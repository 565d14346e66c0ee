// Structural gap diagnosis speed (docs/performance.md, "Gap diagnosis"):
// one FRF residual evaluation of the fork-and-wheel benchmark structure (8 DOFs,
// 160 lines, mass loading with modal damping and with a non-proportional C), and
// one whole diagnosis of a hidden mass (the benchmark's first effect case).
// The larger hidden-truth benchmark itself runs as
// MOZZI_GAP_BENCH_FULL=1 tests/validation_gap_structural_benchmark.
#include <benchmark/benchmark.h>

#include "validation/gap/structural_benchmark_runner.h"

namespace {

using namespace mozzi;

void residuals(benchmark::State& state, bool viscous) {
  const auto s = viscous ? gap_bench::viscousC(gap_bench::forkWheel()) : gap_bench::forkWheel();
  gap_bench::BenchConfig cfg;
  std::mt19937_64 rng(1);
  const auto frf =
      gap_bench::measure(s.model, gap_bench::Truth(s.model.dofCount()), gap_bench::defaultMeasurement(s, cfg), rng);
  auto p = core::gap::structural::makeFrfProblem(s.model, frf);
  if (!p) {
    state.SkipWithError(p.error().describe().c_str());
    return;
  }
  const std::vector<double> theta{1.0, 1.0};
  const double dm = 0.2;
  std::vector<double> r(static_cast<std::size_t>((*p)->residualCount()));
  for (auto _ : state) {
    benchmark::DoNotOptimize((*p)->residuals(theta.data(), 0, &dm, r.data()));
  }
  state.counters["residuals"] = static_cast<double>(r.size());
}
void BM_GapFrfResidualsModalDamping(benchmark::State& state) {
  residuals(state, false);
}
void BM_GapFrfResidualsViscousC(benchmark::State& state) {
  residuals(state, true);
}
BENCHMARK(BM_GapFrfResidualsModalDamping)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_GapFrfResidualsViscousC)->Unit(benchmark::kMicrosecond);

void BM_GapDiagnoseHiddenMass(benchmark::State& state) {
  const gap_bench::BenchConfig cfg;
  const auto cases = gap_bench::makeCases(cfg);
  const gap_bench::Case* c = nullptr;
  for (const auto& k : cases)
    if (k.kind == gap_bench::CaseKind::Effect) {
      c = &k;
      break;
    }
  for (auto _ : state) {
    const auto r = gap_bench::runCase(*c, cfg, 7);
    if (!r.ok) state.SkipWithError(r.error.c_str());
  }
}
BENCHMARK(BM_GapDiagnoseHiddenMass)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
