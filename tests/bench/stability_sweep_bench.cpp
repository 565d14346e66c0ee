// The Stability page's sweep (issue 22): eigenvalues at 10,000 speeds with the
// modes tracked, named and their critical speeds refined (core::stability::
// sweepSpeeds, what the page and `mozzi-cli stability` run), on each model the
// page offers. Issue target: 50 ms or less. docs/performance/stability.md has
// the figures, the command and the ratio to the CLI.
#include <benchmark/benchmark.h>

#include <string>

#include "core/stability/benchmark_bicycle.h"
#include "core/stability/compliant_fork_bicycle.h"
#include "core/stability/mode_tracking.h"
#include "core/stability/motorcycle.h"

namespace st = mozzi::core::stability;

namespace {

constexpr int kSpeeds = 10000;

void sweep(benchmark::State& state, const st::StabilitySystem& system, double from, double to) {
  const auto speeds = st::speedGrid(from, to, (to - from) / (kSpeeds - 1));
  if (!speeds) {
    state.SkipWithError(speeds.error().describe().c_str());
    return;
  }
  for (auto _ : state) {
    auto s = st::sweepSpeeds(system, *speeds);
    if (!s) state.SkipWithError(s.error().describe().c_str());
    benchmark::DoNotOptimize(s);
  }
  state.counters["speeds"] = static_cast<double>(speeds->size());
}

std::optional<st::SharpParameters> sharp() {
  auto p = st::loadSharpParameters(std::string(MOZZI_SHARED_DATA_DIR) + "/motorcycle/sharp1971-parameters.csv");
  if (!p) return std::nullopt;
  return *p;
}

void BM_SweepBenchmarkBicycle(benchmark::State& state) {
  sweep(state, st::bicycleSystem(*st::benchmarkModel(st::meijaard2007Parameters())), 0.0, 10.0);
}
BENCHMARK(BM_SweepBenchmarkBicycle)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

void BM_SweepForkBendingBicycle(benchmark::State& state) {
  const auto m = st::forkBendingModel(st::meijaard2007Parameters(), st::thesisSteelForkBending());
  sweep(state, st::bicycleSystem(*m), 0.0, 10.0);
}
BENCHMARK(BM_SweepForkBendingBicycle)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

void BM_SweepMotorcycle(benchmark::State& state) {
  const auto p = sharp();
  if (!p) return state.SkipWithError("no Sharp (1971) parameters");
  std::optional<st::LumpedForkModel> fork;
  if (state.range(0) > 0) fork = *st::thesisLumpedForkModel(static_cast<int>(state.range(0)));
  const auto m = st::MotorcycleModel::build(*p, fork);
  if (!m) return state.SkipWithError(m.error().describe().c_str());
  sweep(state, m->system(), 1.0, 60.0);
}
// 0: rigid fork; 1, 2, 3: the lumped fork models of thesis Table 12.
BENCHMARK(BM_SweepMotorcycle)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

}  // namespace
