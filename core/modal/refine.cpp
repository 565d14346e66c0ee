#include "core/modal/refine.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/modal/varpro.h"

namespace mozzi::core::modal {

namespace {

// Lines of the band the fit uses (refine.h: the lines carrying the modes when
// the band holds more than maxLines).
std::vector<LineSegment> fitLines(const FrfMatrix& frf, Eigen::Index k0, Eigen::Index nf, const Vector& theta,
                                  Eigen::Index maxLines) {
  if (maxLines <= 0 || nf <= maxLines) return {LineSegment{k0, nf}};
  // Each mode's window: 8 half-power half-widths (zeta f) on either side,
  // narrowed (by factors 1.25) while the windows take more than 3/4 of the
  // budget, down to 3 half-widths (98.6% of an isolated mode's information
  // on (f, zeta): the integral of |dH/d sigma|^2, 1 / (1 + x^2)^2 over
  // |x| < 3); at least 10 lines on either side. The rest of the budget goes
  // to blocks of 16 lines spread over the band (residues, residual terms).
  constexpr double kMostHalfWidths = 8.0, kFewestHalfWidths = 3.0, kModesShare = 0.75;
  constexpr Eigen::Index kMinHalfLines = 10, kBlock = 16;
  std::vector<char> keep(static_cast<std::size_t>(nf), 0);
  const double* f = frf.frequencyHz.data() + k0;
  auto markModes = [&](double halfWidths) {
    std::fill(keep.begin(), keep.end(), 0);
    for (Eigen::Index r = 0; r < theta.size() / 2; ++r) {
      const double fr = theta[2 * r], half = halfWidths * theta[2 * r + 1] * fr;
      const Eigen::Index c = std::lower_bound(f, f + nf, fr) - f;
      const Eigen::Index lo = std::min(std::lower_bound(f, f + nf, fr - half) - f, c - kMinHalfLines);
      const Eigen::Index hi = std::max(std::upper_bound(f, f + nf, fr + half) - f, c + kMinHalfLines);
      // edges on a grid of kBlock lines: poles a little apart (the start and
      // the solution) mostly give the same lines
      const Eigen::Index first = std::max<Eigen::Index>(lo >= 0 ? lo / kBlock * kBlock : 0, 0);
      const Eigen::Index last = std::min((hi + kBlock - 1) / kBlock * kBlock, nf);
      for (Eigen::Index k = first; k < last; ++k) keep[static_cast<std::size_t>(k)] = 1;
    }
    return static_cast<Eigen::Index>(std::count(keep.begin(), keep.end(), 1));
  };
  double halfWidths = kMostHalfWidths;
  Eigen::Index marked = markModes(halfWidths);
  while (static_cast<double>(marked) > kModesShare * static_cast<double>(maxLines) && halfWidths > kFewestHalfWidths) {
    halfWidths = std::max(kFewestHalfWidths, halfWidths / 1.25);
    marked = markModes(halfWidths);
  }
  const Eigen::Index rest = nf - marked, budget = maxLines - marked;
  if (budget >= rest) return {LineSegment{k0, nf}};
  if (budget >= kBlock) {
    // blocks of kBlock lines every `stride` lines over the whole band, the
    // stride a whole number (so that windows a line wider or narrower, poles
    // a little apart, seldom move the blocks) and lengthened until the
    // blocks stay within the budget
    const std::vector<char> modes = keep;
    for (Eigen::Index stride = (kBlock * rest + budget - 1) / budget;; ++stride) {
      keep = modes;
      for (Eigen::Index b = (stride - kBlock) / 2; b < nf; b += stride) {
        for (Eigen::Index k = b; k < std::min(b + kBlock, nf); ++k) keep[static_cast<std::size_t>(k)] = 1;
      }
      if (std::count(keep.begin(), keep.end(), 1) <= maxLines) break;
    }
  }
  std::vector<LineSegment> out;
  for (Eigen::Index k = 0; k < nf;) {
    if (!keep[static_cast<std::size_t>(k)]) {
      ++k;
      continue;
    }
    Eigen::Index e = k;
    while (e < nf && keep[static_cast<std::size_t>(e)]) ++e;
    out.push_back(LineSegment{k0 + k, e - k});
    k = e;
  }
  return out;
}

// Levenberg-Marquardt on the projected functional of `vp` from theta, where
// vp was just evaluated with Derivatives::Kaufman; on return theta is the
// solution and vp holds its evaluation with J_K^T J_K. `linear`: the linear
// parameters (p m). Counts iterations and evaluations into `out`.
Result<void> levenbergMarquardt(ModalVarpro& vpRef, Vector& theta, Eigen::Index linear, const RefineOptions& opt,
                                RefineResult& out) {
  const std::string where = "modal refinement";
  ModalVarpro* vp = &vpRef;
  const int nm = static_cast<int>(theta.size() / 2);
  const Eigen::Index np = theta.size();
  const double yn2 = vp->dataNorm2();
  double ssr = vp->ssr();
  Matrix h = vp->kaufman();
  Vector g = vp->gradient();
  bool atTheta = true;  // vp holds the evaluation at theta

  // Levenberg-Marquardt with Marquardt's diagonal scaling and Nielsen's damping update.
  double mu = 1e-3, nu = 2.0;
  Matrix lhs(np, np);
  Vector delta(np), trial(np);
  Eigen::LDLT<Matrix> ldlt(np);
  // SSR comes from ||Y||^2 - ||Q^T Y||^2: differences below this are rounding.
  const double ssrResolution = 1e-13 * yn2;
  // Converged when the full Gauss-Newton step would lower SSR by less than
  // 1e-6 s^2 (s^2 = SSR / (N - P)): the step is then below 1e-3 standard
  // errors in every direction (delta^T J^T J delta = 2 x the decrease).
  const double dof = static_cast<double>(2 * vp->lineCount() * vp->frfCount() - (np + linear));
  Vector gnStep(np);
  // The last step: Gauss-Newton converges linearly here (the residual is
  // noise), each step's predicted decrease a factor `rate` of the one
  // before (about 1e-4 on the benchmark sets). When the decrease after this
  // step is predicted 10 x below the stop threshold, the trial is evaluated
  // without the gradient (Derivatives::Covariance: no pass of E over the
  // data), and accepted it is the solution; J_K^T J_K, X and SSR are then
  // still those of the solution. Rejected, the iteration goes on as before.
  double lastDecrease = 0.0;  // Gauss-Newton decrease predicted at the previous accepted point
  bool finalTrial = false, shortcutFailed = false;
  for (int it = 0; it < opt.maxIterations; ++it) {
    if (opt.progress && !opt.progress(out.iterations, std::sqrt(ssr / yn2))) {
      return makeError(ErrorCode::Cancelled, "refinement cancelled", where);
    }
    ldlt.compute(h);
    finalTrial = false;
    if (ldlt.info() == Eigen::Success) {
      gnStep = ldlt.solve(-g);
      const double decrease = -g.dot(gnStep), threshold = 1e-6 * ssr / dof;  // -g.step = decrease of SSR
      if (gnStep.allFinite() && decrease <= threshold) break;
      if (gnStep.allFinite() && !shortcutFailed && lastDecrease > 0.0) {
        const double rate = decrease / lastDecrease;
        finalTrial = rate <= 0.1 && decrease * rate <= 0.1 * threshold;
      }
      if (gnStep.allFinite()) lastDecrease = decrease;
    }
    ++out.iterations;
    lhs = h;
    lhs.diagonal() += mu * h.diagonal().cwiseMax(1e-300);
    ldlt.compute(lhs);
    delta = ldlt.solve(-g);
    if (ldlt.info() != Eigen::Success || !delta.allFinite()) {
      mu *= nu;
      nu *= 2.0;
      continue;
    }
    trial = theta + delta;
    for (int r = 0; r < nm; ++r) {  // stay admissible: f > 0, 0 < zeta < 1
      trial[2 * r] = std::max(trial[2 * r], 0.5 * theta[2 * r]);
      trial[2 * r + 1] = std::clamp(trial[2 * r + 1], std::max(1e-7, 0.1 * theta[2 * r + 1]), 0.99);
    }
    delta = trial - theta;
    bool small = true;
    for (int r = 0; r < nm; ++r) {
      small = small && std::abs(delta[2 * r]) <= 1e-11 * theta[2 * r] &&
              std::abs(delta[2 * r + 1]) <= 1e-9 * theta[2 * r + 1];
    }
    if (small) break;
    const double predicted = -g.dot(delta) - 0.5 * delta.dot(h * delta);  // of SSR / 2
    ++out.evaluations;
    atTheta = false;
    if (!vp->evaluate(trial, finalTrial ? ModalVarpro::Derivatives::Covariance : ModalVarpro::Derivatives::Kaufman)) {
      shortcutFailed = shortcutFailed || finalTrial;
      mu *= nu;
      nu *= 2.0;
      continue;
    }
    const double actual = 0.5 * (ssr - vp->ssr());
    const double rho = predicted > 0.0 ? actual / predicted : -1.0;
    if (rho > 0.0 && finalTrial) {
      theta = trial;
      atTheta = true;
      ssr = vp->ssr();
      break;
    }
    shortcutFailed = shortcutFailed || finalTrial;
    if (rho > 0.0) {
      theta = trial;
      h = vp->kaufman();
      g = vp->gradient();
      atTheta = true;
      const double old = ssr;
      ssr = vp->ssr();
      mu *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * rho - 1.0, 3));
      nu = 2.0;
      if (old - ssr <= std::max(1e-12 * old, ssrResolution)) break;
    } else {
      if (predicted <= ssrResolution) break;  // no decrease left to see
      mu *= nu;
      nu *= 2.0;
    }
  }
  if (!atTheta) {
    if (!vp->evaluate(theta, ModalVarpro::Derivatives::Covariance)) {
      return makeError(ErrorCode::NumericalFailure, "LSFD fails at the solution", where);
    }
    ++out.evaluations;
  }

  return {};
}

}  // namespace

Result<RefineResult> refineModalModel(const FrfMatrix& frf, const ModalModel& initial, const RefineOptions& opt) {
  const std::string where = "modal refinement";
  MOZZI_TRY(frf.validate());
  MOZZI_TRY(initial.validate());
  if (initial.modes.empty()) return makeError(ErrorCode::InvalidArgument, "no modes to refine", where);
  Eigen::Index k0 = 0;
  while (k0 < frf.lineCount() && (frf.frequencyHz[k0] < opt.bandLowHz || frf.frequencyHz[k0] == 0.0)) ++k0;
  Eigen::Index k = k0;
  while (k < frf.lineCount() && frf.frequencyHz[k] <= opt.bandHighHz) ++k;
  const Eigen::Index nf = k - k0;
  const int nm = static_cast<int>(initial.modes.size());
  const Eigen::Index m = frf.responseCount() * frf.referenceCount();
  const Eigen::Index p = 2 * nm + (opt.lowerResidual ? 2 : 0) + (opt.upperResidual ? 2 : 0);
  if (2 * nf * m <= 2 * nm + p * m) {
    return makeError(
        ErrorCode::InvalidArgument,
        "band holds " + std::to_string(nf) + " lines, too few for " + std::to_string(2 * nm + p * m) + " parameters",
        where + ", band");
  }
  Vector theta(2 * nm);
  for (int r = 0; r < nm; ++r) {
    theta[2 * r] = initial.modes[static_cast<std::size_t>(r)].frequencyHz();
    theta[2 * r + 1] = initial.modes[static_cast<std::size_t>(r)].zeta();
  }
  auto vp =
      ModalVarpro::create(frf, fitLines(frf, k0, nf, theta, opt.maxLines), nm, opt.lowerResidual, opt.upperResidual);
  if (!vp) return makeError(vp.error().code, vp.error().message, where + ", band");
  RefineResult out;
  out.bandLines = nf;
  if (!vp->evaluate(theta, ModalVarpro::Derivatives::Kaufman)) {
    return makeError(ErrorCode::NumericalFailure, "LSFD fails for the initial poles (rank-deficient basis)", where);
  }
  ++out.evaluations;
  {
    std::vector<Complex> start;
    for (const Mode& md : initial.modes) start.push_back(md.pole);
    out.startModel = modalModelFromLinear(*vp, frf, start);
    for (int r = 0; r < nm; ++r) {
      out.startModel.modes[static_cast<std::size_t>(r)].participation =
          initial.modes[static_cast<std::size_t>(r)].participation;
    }
  }
  const double yn2 = vp->dataNorm2();
  out.initialRelativeError = std::sqrt(vp->ssr() / yn2);
  MOZZI_TRY(levenbergMarquardt(*vp, theta, p * m, opt, out));
  // Thinned: the lines are those of the start's poles; chosen again around
  // the refined poles, and the fit repeated from there on them when they
  // differ, so that the lines, and the result, depend on the solution, not
  // on the start (a re-selection of the same modes in the diagram gives the
  // same refined modes).
  if (vp->lineCount() < nf) {
    auto again = fitLines(frf, k0, nf, theta, opt.maxLines);
    const auto& used = vp->segments();
    const bool same = again.size() == used.size() && std::equal(again.begin(), again.end(), used.begin(),
                                                                [](const LineSegment& x, const LineSegment& y) {
                                                                  return x.first == y.first && x.count == y.count;
                                                                });
    if (!same) {
      vp = ModalVarpro::create(frf, std::move(again), nm, opt.lowerResidual, opt.upperResidual);
      if (!vp) return makeError(vp.error().code, vp.error().message, where + ", band");
      if (!vp->evaluate(theta, ModalVarpro::Derivatives::Kaufman)) {
        return makeError(ErrorCode::NumericalFailure, "LSFD fails on the lines of the refined poles", where);
      }
      ++out.evaluations;
      MOZZI_TRY(levenbergMarquardt(*vp, theta, p * m, opt, out));
    }
  }
  out.fittedLines = vp->lineCount();
  const double dof = static_cast<double>(2 * vp->lineCount() * m - (2 * nm + p * m));
  const Eigen::Index np = 2 * nm;

  // Model: poles from theta, residues and residual terms from X.
  std::vector<Complex> poles;
  for (int r = 0; r < nm; ++r) poles.push_back(poleFromFrequencyDamping(theta[2 * r], theta[2 * r + 1]));
  out.model = modalModelFromLinear(*vp, frf, poles);
  for (int r = 0; r < nm; ++r) {
    out.model.modes[static_cast<std::size_t>(r)].participation =
        initial.modes[static_cast<std::size_t>(r)].participation;
  }

  // SSR = ||Y||^2 - ||Z||^2 loses about log10(||Y||^2 / SSR) of its 16
  // digits; the explicit residual (one more pass over the data) only where
  // fewer than 10 would be left (an almost exact fit).
  const auto accurateSsr = [](ModalVarpro& v) { return v.ssr() > 1e-6 * v.dataNorm2() ? v.ssr() : v.explicitSsr(); };
  const double finalSsr = accurateSsr(*vp);
  out.finalRelativeError = std::sqrt(finalSsr / vp->dataNorm2());
  // s^2 of the standard errors: the noise variance, estimated over every
  // line the fit used, or, when thinned, over every line of the band by the
  // LSFD there at the refined poles (one LSFD), which also gives the model's
  // residues and residual terms over the whole band. The lines carrying the
  // modes hold the misfit of the peaks (measured FRFs: leakage, the model
  // error at resonance) and few of the lines where the data is fitted to
  // the noise, so their own s^2 would grow as the fit is thinned (5 x the
  // band's standard errors on the ModeLAB beam at 2,000 of 47,873 lines);
  // with the band's s^2 the standard errors are those of the thinned fit's
  // information, on the same noise estimate as the all-lines fit's
  // (Refine.ThinnedStandardErrorsWithinAQuarterOfTheScatterOf200Realisations).
  double s2 = finalSsr / dof;
  if (vp->lineCount() < nf) {
    auto band = ModalVarpro::create(frf, {LineSegment{k0, nf}}, nm, opt.lowerResidual, opt.upperResidual, false);
    if (!band || !band->evaluate(theta, ModalVarpro::Derivatives::None)) {
      return makeError(ErrorCode::NumericalFailure, "LSFD over the band fails at the refined poles", where);
    }
    ModalModel whole = modalModelFromLinear(*band, frf, poles);
    for (int r = 0; r < nm; ++r) {
      whole.modes[static_cast<std::size_t>(r)].participation = initial.modes[static_cast<std::size_t>(r)].participation;
    }
    out.model = std::move(whole);
    s2 = accurateSsr(*band) / static_cast<double>(2 * nf * m - (np + p * m));
  }
  const Matrix& jtj = vp->kaufman();
  Eigen::LDLT<Matrix> cov(jtj);
  if (cov.info() != Eigen::Success || !(cov.vectorD().minCoeff() > 0.0)) {
    return makeError(ErrorCode::NumericalFailure, "J^T J is singular: a frequency or damping is not identifiable",
                     where);
  }
  const Matrix inv = cov.solve(Matrix::Identity(np, np));
  for (int r = 0; r < nm; ++r) {
    out.frequencyStdHz.push_back(std::sqrt(s2 * inv(2 * r, 2 * r)));
    out.zetaStd.push_back(std::sqrt(s2 * inv(2 * r + 1, 2 * r + 1)));
  }
  return out;
}

}  // namespace mozzi::core::modal
