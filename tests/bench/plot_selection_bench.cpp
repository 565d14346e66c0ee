// The numbers behind the workbench's FRF and identification pages on the
// issue 18 budget set, 100 FRFs x 20,000 lines (results and commands:
// docs/performance/workbench-plots.md):
//  - one frame of the overlay: min/max decimation of 100 curves into 1,280
//    (and 2,560, QT_SCALE_FACTOR=2) pixel columns; budget 33 ms per frame;
//  - a pole click: LSFD for the chosen poles, synthesis on the band and the
//    residual per FRF: LSFD then synthesis (before session 5), core's one-QR
//    fitSelectedPoles (session 5), SelectionFitter with the synthesis of the
//    FRF shown only (session 6, the page's); budget 50 ms;
//  - the stabilization backdrop: |sum| and the CMIF of the set.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "core/common/frf_display.h"
#include "core/common/plot_math.h"
#include "core/modal/identification.h"
#include "core/modal/lsfd.h"
#include "core/modal/modal_model.h"
#include "core/modal/pole_selection.h"
#include "core/modal/shape_tools.h"

namespace mozzi::core {
namespace {

constexpr double kModesHz[5] = {120.0, 260.0, 410.0, 640.0, 870.0};

const FrfMatrix& set100x20000() {
  static const FrfMatrix frf = [] {
    FrfMatrix f;
    const int n = 20000, no = 100;
    f.frequencyHz = Vector::LinSpaced(n, 0.05, 1000.0);
    f.references = {Dof{1, Direction::Z}};
    f.type = FrfType::Accelerance;
    f.h.emplace_back(n, no);
    std::mt19937 rng(18);
    std::normal_distribution<double> nd(0.0, 1.0);
    for (int o = 0; o < no; ++o) {
      f.responses.push_back(Dof{o + 2, Direction::Z});
      for (int k = 0; k < n; ++k) {
        const double w = 2 * M_PI * f.frequencyHz[k];
        Complex h(0.0, 0.0);
        for (int r = 0; r < 5; ++r) {
          const double wr = 2 * M_PI * kModesHz[r];
          h += -w * w * std::sin(0.37 * (r + 1) * (o + 1)) / Complex(wr * wr - w * w, 2 * 0.01 * wr * w);
        }
        f.h[0](k, o) = h * (1.0 + 0.01 * Complex(nd(rng), nd(rng)));
      }
    }
    return f;
  }();
  return frf;
}

void BM_OverlayFrameDecimation(benchmark::State& state) {
  const FrfMatrix& f = set100x20000();
  std::vector<Vector> db;
  for (Eigen::Index o = 0; o < f.responseCount(); ++o) db.push_back(magnitudeDb(f.h[0].col(o)));
  const int columns = static_cast<int>(state.range(0));
  double lo = 100.0, hi = 900.0;
  std::size_t points = 0;
  for (auto _ : state) {
    // A zoom step: a new range every frame.
    lo += 0.5;
    hi -= 0.5;
    if (hi - lo < 50.0) lo = 100.0, hi = 900.0;
    const auto starts = pixelColumnStarts(f.frequencyHz, lo, hi, columns);
    for (const auto& y : db) points += static_cast<std::size_t>(decimateMinMax(f.frequencyHz, y, starts).x.size());
    benchmark::DoNotOptimize(points);
  }
  state.counters["points_per_curve"] = static_cast<double>(points) / (100.0 * static_cast<double>(state.iterations()));
}
BENCHMARK(BM_OverlayFrameDecimation)->Arg(1280)->Arg(2560)->Unit(benchmark::kMillisecond);

void BM_PoleClickRefit(benchmark::State& state) {
  const FrfMatrix& f = set100x20000();
  std::vector<Complex> poles;
  for (double fn : kModesHz) poles.push_back(modal::poleFromFrequencyDamping(fn, 0.01));
  const double lo = 50.0, hi = 950.0;
  for (auto _ : state) {
    modal::LsfdOptions o;
    o.bandLowHz = lo;
    o.bandHighHz = hi;
    auto model = modal::lsfd(f, poles, o);
    Eigen::Index a = 0, b = f.lineCount();
    while (a < b && f.frequencyHz[a] < lo) ++a;
    while (b > a && f.frequencyHz[b - 1] > hi) --b;
    FrfMatrix band;
    band.frequencyHz = f.frequencyHz.segment(a, b - a);
    band.responses = f.responses;
    band.references = f.references;
    band.type = f.type;
    band.h = {f.h[0].middleRows(a, b - a)};
    auto synth = modal::synthesizeFrf(*model, band.frequencyHz, f.type);
    auto residual = modal::residualPerFrf(band, *synth, lo, hi);
    auto rows = modal::modalTableRows(*model);
    benchmark::DoNotOptimize(residual);
    benchmark::DoNotOptimize(rows);
  }
}
BENCHMARK(BM_PoleClickRefit)->Unit(benchmark::kMillisecond);

// The poles a click alternates between: all five modes, and four (the third
// removed), in the band of the page's run.
std::pair<std::vector<Complex>, std::vector<Complex>> clickedPoles() {
  std::vector<Complex> five, four;
  for (double fn : kModesHz) five.push_back(modal::poleFromFrequencyDamping(fn, 0.01));
  four = five;
  four.erase(four.begin() + 2);
  return {five, four};
}
modal::LsfdOptions clickBand() {
  modal::LsfdOptions o;
  o.bandLowHz = 50.0;
  o.bandHighHz = 950.0;
  return o;
}

// The pole click as the page did it until session 6: core's one-QR fit with
// the synthesis of every FRF (fitSelectedPoles), the measured FRFs copied
// onto the band, residualPerFrf over both. Clicks alternate four and five modes.
void BM_PoleClickFitSelectedPoles(benchmark::State& state) {
  const FrfMatrix& f = set100x20000();
  const auto [five, four] = clickedPoles();
  const modal::LsfdOptions o = clickBand();
  bool odd = false;
  for (auto _ : state) {
    odd = !odd;
    auto fit = modal::fitSelectedPoles(f, odd ? four : five, o);
    const Eigen::Index n = fit->synthesis.lineCount();
    Eigen::Index a = 0;
    while (a < f.lineCount() && f.frequencyHz[a] < fit->synthesis.frequencyHz[0]) ++a;
    FrfMatrix measured;
    measured.frequencyHz = f.frequencyHz.segment(a, n);
    measured.responses = f.responses;
    measured.references = f.references;
    measured.type = f.type;
    for (const auto& h : f.h) measured.h.push_back(h.middleRows(a, n));
    auto residual = modal::residualPerFrf(measured, fit->synthesis, o.bandLowHz, o.bandHighHz);
    benchmark::DoNotOptimize(residual);
  }
}
BENCHMARK(BM_PoleClickFitSelectedPoles)->Unit(benchmark::kMillisecond);

// The pole click as the page does it (session 6): SelectionFitter made once
// for the band, then per click the fit (LSFD, residual per FRF) and the
// synthesis of the one FRF shown. Clicks alternate four and five modes.
void BM_PoleClickSelectionFitter(benchmark::State& state) {
  const FrfMatrix& f = set100x20000();
  const auto [five, four] = clickedPoles();
  const modal::LsfdOptions o = clickBand();
  auto fitter = modal::SelectionFitter::create(f, o);
  ComplexVector shown;
  bool odd = false;
  for (auto _ : state) {
    odd = !odd;
    auto fit = fitter->fit(odd ? four : five);
    fitter->synthesis(7, 0, shown);
    benchmark::DoNotOptimize(fit);
    benchmark::DoNotOptimize(shown.data());
  }
}
BENCHMARK(BM_PoleClickSelectionFitter)->Unit(benchmark::kMillisecond);

void BM_StabilizationBackdrop(benchmark::State& state) {
  const FrfMatrix& f = set100x20000();
  const bool cmifBackdrop = state.range(0) == 1;
  for (auto _ : state) {
    if (cmifBackdrop) {
      auto sv = modal::cmif(f);
      benchmark::DoNotOptimize(sv);
    } else {
      auto sum = frfSum(f, pickFrfs(f, {}));
      benchmark::DoNotOptimize(sum);
    }
  }
}
BENCHMARK(BM_StabilizationBackdrop)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace mozzi::core
