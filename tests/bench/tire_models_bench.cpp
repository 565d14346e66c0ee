// Throughput of the tyre identification steps: harmonic-yaw relaxation length
// (5 frequencies x 10 cycles at 200 Hz, thesis §5.1), appendix-1 FRF over 1000
// frequencies, a Magic Formula lateral fit (189 points, 3 loads x 3 cambers x 21 slips),
// and the wheelchair slalom of `mozzi-cli wheelchair slalom` (20 s, 0.25 Hz).
#include <benchmark/benchmark.h>

#include <cmath>
#include <complex>
#include <random>

#include "core/stability/wheelchair_model.h"
#include "core/tire/magic_formula.h"
#include "core/tire/relaxation_length.h"
#include "core/tire/relaxation_prediction.h"
#include "core/tire/ring_model.h"

namespace {

namespace tr = mozzi::core::tire;
constexpr double kPi = 3.14159265358979323846;

std::vector<tr::HarmonicYawRecord> yawRecords() {
  std::vector<tr::HarmonicYawRecord> recs;
  std::mt19937 rng(1);
  std::normal_distribution<double> g(0.0, 1.0);
  const double V = 5.0 / 3.6, a = 0.07, sigma = 0.15, psi0 = 1.5 * kPi / 180;
  for (double f : {0.42, 0.84, 1.26, 1.68, 2.10}) {
    const double w = 2 * kPi * f;
    const std::complex<double> h = 19500.0 * std::complex<double>(V, -w * a) / std::complex<double>(V, w * sigma);
    tr::HarmonicYawRecord r;
    r.excitationFrequencyHz = f;
    r.sampleRateHz = 200.0;
    const auto n = static_cast<Eigen::Index>(std::round(10 * 200.0 / f));
    r.yawRate.resize(n);
    r.lateralForce.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) / 200.0;
      r.yawRate[i] = psi0 * w * std::cos(w * t) + 0.01 * g(rng);
      r.lateralForce[i] = std::abs(h) * psi0 * std::sin(w * t + std::arg(h)) + 10 * g(rng);
    }
    recs.push_back(r);
  }
  return recs;
}

void BM_RelaxationFromHarmonicYaw(benchmark::State& state) {
  const auto recs = yawRecords();
  tr::HarmonicYawSettings s;
  s.halfLength = 0.07;
  for (auto _ : state) benchmark::DoNotOptimize(tr::relaxationFromHarmonicYaw(recs, s));
}
BENCHMARK(BM_RelaxationFromHarmonicYaw)->Unit(benchmark::kMicrosecond);

void BM_RingFrfFull(benchmark::State& state) {
  auto ring = tr::identifyRingModel({{0, 103, 0.03}, {1, 85, 0.03}, {2, 183, 0.03}, {3, 311, 0.03}}, {3.5, 0.8, 0.28});
  const tr::RingFrfInputs in{5.0 / 3.6, 0.06, 0.053, 19500.0, 0.015};
  const mozzi::core::Vector w = mozzi::core::Vector::LinSpaced(1000, 0.1, 2 * kPi * 5.0);
  for (auto _ : state) benchmark::DoNotOptimize(tr::impliedRelaxationLength(*ring, in, w, tr::RingFrfVariant::Full));
}
BENCHMARK(BM_RingFrfFull)->Unit(benchmark::kMicrosecond);

void BM_MagicFormulaLateralFit(benchmark::State& state) {
  const tr::MfConstants c;
  tr::MfLateralCoefficients p = tr::mfLateralDefaults();
  p[1] = 1.1, p[8] = 14.0, p[16] = 0.8;
  std::vector<tr::SteadyStatePoint> d;
  std::mt19937 rng(3);
  std::normal_distribution<double> g(0.0, 5.0);
  for (double fz : {1000.0, 1500.0, 2000.0})
    for (double gam : {0.0, 0.05, 0.1})
      for (int i = -10; i <= 10; ++i) {
        const double a = i * kPi / 180;
        d.push_back({a, gam, fz, 2e5, tr::mfLateralForce(p, c, a, gam, fz, 2e5) + g(rng), 0.0});
      }
  for (auto _ : state) benchmark::DoNotOptimize(tr::fitMfLateral(d, c));
}
BENCHMARK(BM_MagicFormulaLateralFit)->Unit(benchmark::kMillisecond);

void BM_WheelchairSlalom(benchmark::State& state) {
  const mozzi::core::stability::WheelchairParameters p;
  for (auto _ : state) benchmark::DoNotOptimize(mozzi::core::stability::runSlalom(p, 4.0 / 3.6, 10.0, 0.25, 20.0));
}
BENCHMARK(BM_WheelchairSlalom)->Unit(benchmark::kMillisecond);

}  // namespace
