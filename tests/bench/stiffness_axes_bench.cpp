// Cost of the stiffness identification steps a technician triggers at the rig:
// one static twist axis, a +-300 N static ramp, a 3-D screw axis and a 1..45 Hz
// dynamic sweep. Inputs are built once per benchmark, outside the timed loop.
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/stiffness/dynamic_twist.h"
#include "core/stiffness/plate_motion.h"
#include "core/stiffness/screw_axis.h"

namespace {

namespace st = mozzi::core::stiffness;
using mozzi::core::Vector2;

const std::vector<Vector2> kLayout{{0.2, -0.3}, {0, -0.3}, {0, 0}, {0.2, 0}};

double rigid(const Vector2& p, double theta) {
  return theta * (-(p(1) + 0.1)) + 1e-5 * p(0);
}

void BM_StaticTwistAxis4Lasers(benchmark::State& state) {
  std::vector<double> w;
  for (const auto& p : kLayout) w.push_back(rigid(p, 1e-3));
  for (auto _ : state) {
    auto r = st::staticTwistAxis(kLayout, w, Vector2(0.1, -0.7));
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_StaticTwistAxis4Lasers);

void BM_StaticRamp(benchmark::State& state) {
  const auto n = static_cast<Eigen::Index>(state.range(0));
  mozzi::core::Vector f(n);
  mozzi::core::Matrix d(n, 4);
  for (Eigen::Index k = 0; k < n; ++k) {
    f(k) = -300.0 + 600.0 * static_cast<double>(k) / static_cast<double>(n - 1);
    for (int i = 0; i < 4; ++i) d(k, i) = rigid(kLayout[static_cast<std::size_t>(i)], f(k) / 167e3 / 0.551);
  }
  for (auto _ : state) {
    auto r = st::staticTwistTest(kLayout, f, d, Vector2(0.1, -0.651));
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations() * n);
}
BENCHMARK(BM_StaticRamp)->Arg(61)->Arg(1000);

void BM_ScrewAxis(benchmark::State& state) {
  const auto n = static_cast<Eigen::Index>(state.range(0));
  mozzi::core::Matrix p(n, 3), d(n, 3);
  const Eigen::Vector3d w(0.001, 0.002, 0.01), dO(5e-4, -2e-4, 3e-4);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double t = static_cast<double>(i);
    p.row(i) << 0.3 * std::cos(t), 0.2 * std::sin(1.7 * t), 0.1 * t / static_cast<double>(n);
    const Eigen::Vector3d pi = p.row(i).transpose();
    d.row(i) = (dO + w.cross(pi)).transpose();
  }
  for (auto _ : state) {
    auto r = st::screwAxis(p, d);
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_ScrewAxis)->Arg(3)->Arg(30);

// The Mode Animation page's Mozzi axis: the rigid twist fitted to a complex
// mode's readings, n nodes measured along x, y and z (3n readings), what the
// page computes on the GUI thread each time a mode is chosen.
void BM_ModeScrewAxisReadings(benchmark::State& state) {
  const auto n = static_cast<Eigen::Index>(state.range(0));
  mozzi::core::Matrix p(3 * n, 3), e(3 * n, 3);
  mozzi::core::ComplexVector v(3 * n);
  const Eigen::Vector3d w(0.001, 0.002, 0.01), dO(5e-4, -2e-4, 3e-4);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double t = static_cast<double>(i);
    const Eigen::Vector3d pi(0.3 * std::cos(t), 0.2 * std::sin(1.7 * t), 0.1 * t / static_cast<double>(n));
    const Eigen::Vector3d d = dO + w.cross(pi);
    for (int k = 0; k < 3; ++k) {
      p.row(3 * i + k) = pi.transpose();
      e.row(3 * i + k) = Eigen::Vector3d::Unit(k).transpose();
      v(3 * i + k) = d(k) * std::polar(1.0, 0.4);
    }
  }
  for (auto _ : state) {
    auto r = st::screwAxisFromReadingPhasors(p, e, v);
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations() * 3 * n);
}
BENCHMARK(BM_ModeScrewAxisReadings)->Arg(30)->Arg(20000)->Unit(benchmark::kMillisecond);

void BM_DynamicSweep1To45Hz(benchmark::State& state) {
  std::vector<st::SweepPoint> sweep;
  for (int f = 1; f <= 45; ++f) {
    st::SweepPoint s;
    s.frequencyHz = f;
    s.amplitude.resize(4);
    s.phase.resize(4);
    for (int i = 0; i < 4; ++i) {
      const double a = rigid(kLayout[static_cast<std::size_t>(i)], 1e-3 * (1 + 0.01 * f));
      s.amplitude(i) = std::abs(a);
      s.phase(i) = (a >= 0 ? 0.0 : 3.141592653589793) + 0.002 * f * i;
    }
    s.forceAmplitude = 100.0;
    sweep.push_back(s);
  }
  for (auto _ : state) {
    auto r = st::dynamicTwistSweep(kLayout, sweep, Vector2(0.1, -0.651));
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_DynamicSweep1To45Hz);

}  // namespace
