// Eigenvalues of the 3-DOF bicycle model (thesis appendix 3, eq. 65, steel fork
// bending) at 10,000 speeds; issue target: under 50 ms. Also the 2-DOF
// benchmark and the tracked sweep (eigenvectors, naming, Brent refinement).
#include <benchmark/benchmark.h>

#include "core/stability/compliant_fork_bicycle.h"
#include "core/stability/mode_tracking.h"

namespace st = mozzi::core::stability;

namespace {

void eigenvaluesAtSpeeds(benchmark::State& state, const st::BicycleModel& model) {
  const int count = static_cast<int>(state.range(0));
  for (auto _ : state) {
    double sum = 0.0;
    for (int i = 0; i < count; ++i) {
      const double v = 10.0 * i / count;
      auto ev = model.eigenvalues(v);
      if (!ev) state.SkipWithError(ev.error().describe().c_str());
      sum += ev->real().maxCoeff();
    }
    benchmark::DoNotOptimize(sum);
  }
  state.counters["speeds"] = count;
}

void BM_Bicycle3DofEigenvalues(benchmark::State& state) {
  const auto model = st::forkBendingModel(st::meijaard2007Parameters(), st::thesisSteelForkBending());
  eigenvaluesAtSpeeds(state, *model);
}
BENCHMARK(BM_Bicycle3DofEigenvalues)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_Bicycle2DofEigenvalues(benchmark::State& state) {
  const auto model = st::benchmarkModel(st::meijaard2007Parameters());
  eigenvaluesAtSpeeds(state, *model);
}
BENCHMARK(BM_Bicycle2DofEigenvalues)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_Bicycle3DofTrackedSweep(benchmark::State& state) {
  const auto model = st::forkBendingModel(st::meijaard2007Parameters(), st::thesisSteelForkBending());
  const auto system = st::bicycleSystem(*model);
  const auto speeds = st::speedGrid(0.0, 10.0, 10.0 / static_cast<double>(state.range(0)));
  for (auto _ : state) {
    auto sweep = st::sweepSpeeds(system, *speeds);
    benchmark::DoNotOptimize(sweep);
  }
}
BENCHMARK(BM_Bicycle3DofTrackedSweep)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
