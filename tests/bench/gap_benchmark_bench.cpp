// Structural gap diagnosis speed (docs/performance/gap.md):
// one FRF residual evaluation of the fork-and-wheel benchmark structure (8 DOFs,
// 160 lines, mass loading with modal damping and with a non-proportional C),
// one whole diagnosis of a hidden mass (the benchmark's first effect case), and
// issue 16's figure: one diagnosis of a 5-DOF model against 5 FRFs x 1,600
// lines (relative noise and an additive floor, noise estimated from the data)
// with the default bootstrap (200 samples), without and with pairs.
// The larger hidden-truth benchmark itself runs as
// MOZZI_GAP_BENCH_FULL=1 tests/validation_gap_structural_benchmark.
#include <benchmark/benchmark.h>

#include "core/gap/engine/bootstrap.h"
#include "validation/gap/structural_benchmark_runner.h"

namespace {

using namespace mozzi;

void residuals(benchmark::State& state, bool viscous) {
  const auto s = viscous ? gap_bench::viscousC(gap_bench::forkWheel()) : gap_bench::forkWheel();
  gap_bench::BenchConfig cfg;
  std::mt19937_64 rng(1);
  const auto frf =
      gap_bench::measure(s.model, gap_bench::Truth(s.model.dofCount()), gap_bench::defaultMeasurement(s, cfg), rng);
  core::gap::structural::StructuralOptions so;
  so.noise = core::gap::structural::StructuralOptions::NoiseSource::Stated;
  auto p = core::gap::structural::makeFrfProblem(s.model, frf, so);
  if (!p) {
    state.SkipWithError(p.error().describe().c_str());
    return;
  }
  const std::vector<double> theta{1.0, 1.0};
  const double dm = 0.2;
  std::vector<double> r(static_cast<std::size_t>((*p)->residualCount()));
  for (auto _ : state) {
    benchmark::DoNotOptimize((*p)->residuals({theta.data(), 0, &dm}, r.data()));
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

// Issue 16: the seat subframe (5 DOFs), reference 3+Z, its 5 responses on
// 1,600 lines 5-350 Hz, 1% relative noise plus a floor of 1% of the median
// |H|, a hidden 0.4 kg at 3+Z; default options (bootstrap 200, 8
// multistarts). Targets: <= 3 s, <= 10 s with pairs (PairMode::Always).
void diagnoseSubframe(benchmark::State& state, bool pairs) {
  const auto s = gap_bench::seatSubframe();
  gap_bench::Truth truth(s.model.dofCount());
  truth.dm(4, 4) = 0.4;
  gap_bench::Measurement m;
  m.responses = s.model.labels;
  m.references = {"3+Z"};
  m.lowHz = s.bandLowHz;
  m.highHz = s.bandHighHz;
  m.lines = 1600;
  m.relativeNoise = 0.01;
  m.floorNoise = 0.01;
  std::mt19937_64 rng(16);
  const auto frf = gap_bench::measure(s.model, truth, m, rng);
  std::string verdict;
  for (auto _ : state) {
    core::gap::engine::clearNullCache();
    auto p = core::gap::structural::makeFrfProblem(s.model, frf);
    if (!p) {
      state.SkipWithError(p.error().describe().c_str());
      return;
    }
    core::gap::DiagnosisOptions opt;
    opt.pairs = pairs ? core::gap::DiagnosisOptions::PairMode::Always : core::gap::DiagnosisOptions::PairMode::Never;
    auto d = core::gap::diagnose(**p, opt);
    if (!d) {
      state.SkipWithError(d.error().describe().c_str());
      return;
    }
    verdict = core::gap::verdictName(d->verdict);
    state.counters["residuals"] = (*p)->residualCount();
    state.counters["pairs"] = d->pair.pairsFitted;
  }
  state.SetLabel(verdict);
}
void BM_GapDiagnose5Dof5Frf1600Lines(benchmark::State& state) {
  diagnoseSubframe(state, false);
}
void BM_GapDiagnose5Dof5Frf1600LinesPairs(benchmark::State& state) {
  diagnoseSubframe(state, true);
}
BENCHMARK(BM_GapDiagnose5Dof5Frf1600Lines)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_GapDiagnose5Dof5Frf1600LinesPairs)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
