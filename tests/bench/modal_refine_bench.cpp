// The modal refinement as a kernel (issue 19: "a refinement that costs about
// as much as one LSFD"): on the 20-mode synthetic set (synthetic_frfs.h),
// band 50-950 Hz (10 modes), starting from the LSFD model of the poles the
// automatic selection of the pLSCF diagram (orders to 60) picked:
//   BM_Lsfd_*          LSFD at those poles (residues, lower/upper residuals)
//   BM_VarproEval_*    one variable-projection evaluation with the
//                      Golub-Pereyra normal equations ([Q, E]^T Y)
//   BM_VarproKaufman_* one evaluation as the refinement's trials make it:
//                      gradient and J_K^T J_K (Q^T Y, then Y X^T on the modes' rows)
//   BM_Refine_*        the whole refinement with standard errors, every line
//   BM_RefineThinned_*/N  the refinement on at most N lines, those carrying
//                      the modes (RefineOptions::maxLines), with the LSFD over
//                      the band at the refined poles
//   BM_RefineStage_*   the stage as identify runs it (refineSelection with
//                      the default options, kRefineLinesCarryingModes)
// Counters: iterations and evaluations of the refinement, and its largest
// relative frequency and damping errors against the generating modes; for
// the thinned ones also the lines fitted, the largest differences from the
// all-lines fit in its standard errors and the largest standard error ratio.
// Figures and commands: docs/performance/commands.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/modal/identification.h"
#include "core/modal/lsfd.h"
#include "core/modal/refine.h"
#include "core/modal/varpro.h"
#include "synthetic_frfs.h"

namespace mozzi::core::modal {
namespace {

constexpr double kLowHz = 50.0, kHighHz = 950.0;

struct Case {
  FrfMatrix frf;
  ModalModel start;  // LSFD model of the automatically selected poles
  std::vector<Complex> poles;
};

Case dataset(int no, int nf, double df) {
  Case c;
  c.frf = bench::syntheticFrfs(no, nf, df);
  IdentificationOptions opt;
  opt.estimator.bandLowHz = kLowHz;
  opt.estimator.bandHighHz = kHighHz;
  opt.estimator.maxOrder = 60;
  opt.refine = false;
  auto id = identifyModes(c.frf, opt);
  if (id) {
    c.start = id->lsfdModel;
    for (const auto& m : c.start.modes) c.poles.push_back(m.pole);
  }
  return c;
}
const Case& large() {
  static const Case c = dataset(100, 20000, 0.1);  // 100 FRFs x 20,000 lines, 9,000 in the band
  return c;
}
const Case& small() {
  static const Case c = dataset(10, 5000, 0.2);  // 10 FRFs x 5,000 lines, 4,500 in the band
  return c;
}

void runLsfd(benchmark::State& state, const Case& c) {
  if (c.poles.empty()) {
    state.SkipWithError("no poles selected");
    return;
  }
  LsfdOptions opt;
  opt.bandLowHz = kLowHz;
  opt.bandHighHz = kHighHz;
  for (auto _ : state) {
    auto m = lsfd(c.frf, c.poles, opt);
    if (!m) {
      state.SkipWithError(m.error().describe().c_str());
      return;
    }
    benchmark::DoNotOptimize(m->modes.data());
  }
  state.counters["modes"] = static_cast<double>(c.poles.size());
}

void runEvaluation(benchmark::State& state, const Case& c,
                   ModalVarpro::Derivatives what = ModalVarpro::Derivatives::Full) {
  Eigen::Index k0 = 0, k = 0;
  while (k0 < c.frf.lineCount() && c.frf.frequencyHz[k0] < kLowHz) ++k0;
  k = k0;
  while (k < c.frf.lineCount() && c.frf.frequencyHz[k] <= kHighHz) ++k;
  const int nm = static_cast<int>(c.poles.size());
  auto vp = ModalVarpro::create(c.frf, {LineSegment{k0, k - k0}}, nm, true, true);
  if (!vp || nm == 0) {
    state.SkipWithError("variable projection not created");
    return;
  }
  Vector theta(2 * nm);
  for (int r = 0; r < nm; ++r) {
    theta[2 * r] = poleFrequencyHz(c.poles[static_cast<std::size_t>(r)]);
    theta[2 * r + 1] = poleZeta(c.poles[static_cast<std::size_t>(r)]);
  }
  for (auto _ : state) {
    if (!vp->evaluate(theta, what)) {
      state.SkipWithError("evaluation failed");
      return;
    }
    benchmark::DoNotOptimize(vp->ssr());
  }
  state.counters["lines"] = static_cast<double>(k - k0);
}

void runRefine(benchmark::State& state, const Case& c) {
  if (c.poles.empty()) {
    state.SkipWithError("no poles selected");
    return;
  }
  RefineOptions opt;
  opt.bandLowHz = kLowHz;
  opt.bandHighHz = kHighHz;
  RefineResult last;
  for (auto _ : state) {
    auto r = refineModalModel(c.frf, c.start, opt);
    if (!r) {
      state.SkipWithError(r.error().describe().c_str());
      return;
    }
    last = std::move(r).value();
  }
  double fErr = 0.0, zErr = 0.0;
  for (const auto& m : last.model.modes) {
    const int r = static_cast<int>(std::lround((m.frequencyHz() - 80.0) / 90.0));
    fErr = std::max(fErr, std::abs(m.frequencyHz() - bench::syntheticFrequencyHz(r)) / bench::syntheticFrequencyHz(r));
    zErr = std::max(zErr, std::abs(m.zeta() - bench::syntheticZeta(r)) / bench::syntheticZeta(r));
  }
  state.counters["iterations"] = last.iterations;
  state.counters["evaluations"] = last.evaluations;
  state.counters["f_rel_err"] = fErr;
  state.counters["zeta_rel_err"] = zErr;
}

// The all-lines refinement of a case, the reference of the thinned ones.
const RefineResult& allLines(const Case& c) {
  static std::vector<std::pair<const Case*, RefineResult>> kept;
  for (const auto& k : kept)
    if (k.first == &c) return k.second;
  RefineOptions opt;
  opt.bandLowHz = kLowHz;
  opt.bandHighHz = kHighHz;
  auto r = refineModalModel(c.frf, c.start, opt);
  kept.emplace_back(&c, r ? std::move(r).value() : RefineResult{});
  return kept.back().second;
}

// Counters of a thinned fit against the all-lines one and the truth:
// largest |f_thin - f_all| / std_all (and of zeta), largest std_thin / std_all.
void compareWithAllLines(benchmark::State& state, const Case& c, const RefineResult& thin) {
  const RefineResult& all = allLines(c);
  double df = 0.0, dz = 0.0, sf = 0.0, sz = 0.0, fErr = 0.0, zErr = 0.0;
  for (std::size_t r = 0; r < thin.model.modes.size() && r < all.model.modes.size(); ++r) {
    const Mode &a = all.model.modes[r], &b = thin.model.modes[r];
    df = std::max(df, std::abs(a.frequencyHz() - b.frequencyHz()) / all.frequencyStdHz[r]);
    dz = std::max(dz, std::abs(a.zeta() - b.zeta()) / all.zetaStd[r]);
    sf = std::max(sf, thin.frequencyStdHz[r] / all.frequencyStdHz[r]);
    sz = std::max(sz, thin.zetaStd[r] / all.zetaStd[r]);
    const int k = static_cast<int>(std::lround((b.frequencyHz() - 80.0) / 90.0));
    fErr = std::max(fErr, std::abs(b.frequencyHz() - bench::syntheticFrequencyHz(k)) / bench::syntheticFrequencyHz(k));
    zErr = std::max(zErr, std::abs(b.zeta() - bench::syntheticZeta(k)) / bench::syntheticZeta(k));
  }
  state.counters["lines"] = static_cast<double>(thin.fittedLines);
  state.counters["df_per_std"] = df;
  state.counters["dzeta_per_std"] = dz;
  state.counters["f_std_ratio"] = sf;
  state.counters["zeta_std_ratio"] = sz;
  state.counters["f_rel_err"] = fErr;
  state.counters["zeta_rel_err"] = zErr;
  state.counters["iterations"] = thin.iterations;
}

// The refinement on at most state.range(0) lines (RefineOptions::maxLines).
void runRefineThinned(benchmark::State& state, const Case& c) {
  if (c.poles.empty()) {
    state.SkipWithError("no poles selected");
    return;
  }
  RefineOptions opt;
  opt.bandLowHz = kLowHz;
  opt.bandHighHz = kHighHz;
  opt.maxLines = state.range(0);
  RefineResult last;
  for (auto _ : state) {
    auto r = refineModalModel(c.frf, c.start, opt);
    if (!r) {
      state.SkipWithError(r.error().describe().c_str());
      return;
    }
    last = std::move(r).value();
  }
  compareWithAllLines(state, c, last);
}

// The whole refinement stage as identify runs it (refineSelection with the
// default IdentificationOptions: thinned fit, then the LSFD over the band at
// the refined poles when thinned).
void runRefineStage(benchmark::State& state, const Case& c) {
  if (c.poles.empty()) {
    state.SkipWithError("no poles selected");
    return;
  }
  IdentificationOptions opt;
  opt.estimator.bandLowHz = kLowHz;
  opt.estimator.bandHighHz = kHighHz;
  RefineResult last;
  for (auto _ : state) {
    auto r = refineSelection(c.frf, c.start, opt);
    if (!r) {
      state.SkipWithError(r.error().describe().c_str());
      return;
    }
    last = std::move(r).value();
  }
  compareWithAllLines(state, c, last);
}

void BM_Lsfd_100x20000(benchmark::State& state) {
  runLsfd(state, large());
}
BENCHMARK(BM_Lsfd_100x20000)->Unit(benchmark::kMillisecond);
void BM_VarproEval_100x20000(benchmark::State& state) {
  runEvaluation(state, large());
}
BENCHMARK(BM_VarproEval_100x20000)->Unit(benchmark::kMillisecond);
void BM_VarproKaufman_100x20000(benchmark::State& state) {
  runEvaluation(state, large(), ModalVarpro::Derivatives::Kaufman);
}
BENCHMARK(BM_VarproKaufman_100x20000)->Unit(benchmark::kMillisecond);
void BM_Refine_100x20000(benchmark::State& state) {
  runRefine(state, large());
}
BENCHMARK(BM_Refine_100x20000)->Unit(benchmark::kMillisecond);

void BM_RefineThinned_100x20000(benchmark::State& state) {
  runRefineThinned(state, large());
}
BENCHMARK(BM_RefineThinned_100x20000)->Unit(benchmark::kMillisecond)->Arg(1000)->Arg(2000)->Arg(3000);
void BM_RefineStage_100x20000(benchmark::State& state) {
  runRefineStage(state, large());
}
BENCHMARK(BM_RefineStage_100x20000)->Unit(benchmark::kMillisecond);

void BM_Lsfd_10x5000(benchmark::State& state) {
  runLsfd(state, small());
}
BENCHMARK(BM_Lsfd_10x5000)->Unit(benchmark::kMillisecond);
void BM_VarproEval_10x5000(benchmark::State& state) {
  runEvaluation(state, small());
}
BENCHMARK(BM_VarproEval_10x5000)->Unit(benchmark::kMillisecond);
void BM_VarproKaufman_10x5000(benchmark::State& state) {
  runEvaluation(state, small(), ModalVarpro::Derivatives::Kaufman);
}
BENCHMARK(BM_VarproKaufman_10x5000)->Unit(benchmark::kMillisecond);
void BM_Refine_10x5000(benchmark::State& state) {
  runRefine(state, small());
}
BENCHMARK(BM_Refine_10x5000)->Unit(benchmark::kMillisecond);

void BM_RefineThinned_10x5000(benchmark::State& state) {
  runRefineThinned(state, small());
}
BENCHMARK(BM_RefineThinned_10x5000)->Unit(benchmark::kMillisecond)->Arg(1000)->Arg(2000)->Arg(3000);
void BM_RefineStage_10x5000(benchmark::State& state) {
  runRefineStage(state, small());
}
BENCHMARK(BM_RefineStage_10x5000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace mozzi::core::modal
