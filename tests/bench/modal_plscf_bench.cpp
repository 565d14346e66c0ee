// pLSCF stabilization timing (issue 5 targets: ModeLAB beam chart, 9 FRFs x
// 48,000 lines, orders up to 120 under 0.05 s; 100 FRFs x 20,000 lines,
// orders up to 120, under 0.2 s single reference and 2 s with three).
// Results and commands: docs/performance/modal.md. Also LSCE on the beam.

#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>
#include <vector>

#include "core/modal/lsce.h"
#include "core/modal/plscf.h"
#include "modelab_beam.h"
#include "synthetic_frfs.h"

namespace mozzi::core::modal {
namespace {

const FrfMatrix& beam() {
  return bench::modelabBeam();
}

// 100 responses x `refs` references, 20,000 lines (0.1 .. 2000 Hz), the
// 20-mode set of synthetic_frfs.h.
FrfMatrix synthetic(int refs) {
  return bench::syntheticFrfs(100, 20000, 0.1, refs);
}

// Times `estimator(frf, options)` (pLSCF or LSCE stabilization) over orders 2..range(0).
template <typename Options, typename Estimator>
void runStabilization(benchmark::State& state, const FrfMatrix& frf, double lo, double hi, Estimator estimator) {
  Options opt;
  opt.bandLowHz = lo;
  opt.bandHighHz = hi;
  opt.minOrder = 2;
  opt.maxOrder = static_cast<int>(state.range(0));
  opt.orderStep = 1;
  std::size_t poles = 0;
  for (auto _ : state) {
    auto d = estimator(frf, opt);
    if (!d.ok()) {
      state.SkipWithError(d.error().describe().c_str());
      return;
    }
    poles = d->poles.size();
    benchmark::DoNotOptimize(poles);
  }
  state.counters["poles"] = static_cast<double>(poles);
}

void runStabilization(benchmark::State& state, const FrfMatrix& frf, double lo, double hi) {
  runStabilization<PlscfOptions>(state, frf, lo, hi, plscfStabilization);
}

void BM_BeamChart(benchmark::State& state) {
  runStabilization(state, beam(), 65.0, 1000.0);
}
BENCHMARK(BM_BeamChart)->Arg(60)->Arg(120)->Unit(benchmark::kMillisecond);

// LSCE on the beam (no target in issue 5; for comparison with pLSCF): impulse
// responses 0 .. 1000 Hz, automatic window, same orders.
void BM_BeamChartLsce(benchmark::State& state) {
  runStabilization<LsceOptions>(state, beam(), 65.0, 1000.0, lsceStabilization);
}
BENCHMARK(BM_BeamChartLsce)->Arg(60)->Arg(120)->Unit(benchmark::kMillisecond);

void BM_Synthetic100x20000_OneRef(benchmark::State& state) {
  static const FrfMatrix frf = synthetic(1);
  runStabilization(state, frf, 0.1, 2000.0);
}
BENCHMARK(BM_Synthetic100x20000_OneRef)->Arg(30)->Arg(60)->Arg(120)->Unit(benchmark::kMillisecond);

// Scaling with the number of lines: the same 100 FRFs fitted over 0.1 Hz ..
// range(0) x 0.1 Hz (5,000 / 10,000 / 20,000 lines), orders to 60.
void BM_Synthetic100_OneRef_Lines(benchmark::State& state) {
  static const FrfMatrix frf = synthetic(1);
  runStabilization<PlscfOptions>(state, frf, 0.1, 0.1 * static_cast<double>(state.range(0)),
                                 [](const FrfMatrix& f, PlscfOptions o) {
                                   o.maxOrder = 60;  // range(0) is the line count here
                                   return plscfStabilization(f, o);
                                 });
}
BENCHMARK(BM_Synthetic100_OneRef_Lines)->Arg(5000)->Arg(10000)->Arg(20000)->Unit(benchmark::kMillisecond);

// Scaling with the number of FRFs: the first range(0) responses (25 / 50 /
// 100) of the same set, 20,000 lines, orders to 60.
void BM_Synthetic_OneRef_Frfs(benchmark::State& state) {
  static const FrfMatrix all = synthetic(1);
  const auto no = static_cast<Eigen::Index>(state.range(0));
  FrfMatrix frf;
  frf.frequencyHz = all.frequencyHz;
  frf.responses.assign(all.responses.begin(), all.responses.begin() + no);
  frf.references = all.references;
  frf.type = all.type;
  frf.h.push_back(all.h[0].leftCols(no));
  runStabilization<PlscfOptions>(state, frf, 0.1, 2000.0, [](const FrfMatrix& f, PlscfOptions o) {
    o.maxOrder = 60;  // range(0) is the FRF count here
    return plscfStabilization(f, o);
  });
}
BENCHMARK(BM_Synthetic_OneRef_Frfs)->Arg(25)->Arg(50)->Arg(100)->Unit(benchmark::kMillisecond);

void BM_Synthetic100x20000_ThreeRefs(benchmark::State& state) {
  static const FrfMatrix frf = synthetic(3);
  runStabilization(state, frf, 0.1, 2000.0);
}
BENCHMARK(BM_Synthetic100x20000_ThreeRefs)->Arg(40)->Arg(120)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace mozzi::core::modal
