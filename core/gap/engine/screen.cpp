#include "core/gap/engine/screen.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/text.h"

namespace mozzi::core::gap::engine {

namespace {

// Signature step in u (fraction of the bound span): large enough that the
// residual change is far above rounding, small enough to stay linear.
constexpr double kSignatureStep = 1e-4;
// Below this many noise standard deviations over the whole admissible range an
// effect cannot be seen with these data (whitened residuals: noise scale 1).
constexpr double kNoiseScale = 1.0;
// sigma_min(P S) / sigma_min(S) below this: calibration absorbs the signature
// (structural non-identifiability rather than a small effect).
constexpr double kAbsorbed = 1e-6;

// min |a + B d|^2 over the box lo <= d <= hi by cyclic coordinate descent on the
// convex quadratic (H = B'B, g = B'a); returns the improvement |a|^2 - min.
double boxQuadratic(const Eigen::MatrixXd& h, const Eigen::VectorXd& g, const std::vector<Scaled>& phi,
                    Eigen::VectorXd& d) {
  const Eigen::Index q = g.size();
  d = Eigen::VectorXd::Zero(q);
  for (int sweep = 0; sweep < (q == 1 ? 1 : 200); ++sweep) {
    double change = 0.0;
    for (Eigen::Index j = 0; j < q; ++j) {
      if (!(h(j, j) > 0.0) || phi[static_cast<std::size_t>(j)].fixed) continue;
      const double rest = g[j] + h.row(j).dot(d) - h(j, j) * d[j];
      const double dj =
          std::clamp(-rest / h(j, j), phi[static_cast<std::size_t>(j)].uLower, phi[static_cast<std::size_t>(j)].uUpper);
      change = std::max(change, std::abs(dj - d[j]));
      d[j] = dj;
    }
    if (change < 1e-14) break;
  }
  return -(2.0 * g.dot(d) + d.dot(h * d));
}

}  // namespace

bool Screen::augmentedResiduals(const Model& baseline, const Eigen::VectorXd& u, Eigen::VectorXd& r) {
  const int n = baseline.residualCount();
  r.resize(n + baseline.priorCount());
  if (!baseline.residuals(u.data(), r.data())) return false;
  baseline.priorResiduals(u.data(), r.data() + n);
  return true;
}

double Screen::linearRatio(int c, const Eigen::VectorXd& r, Eigen::VectorXd* step) const {
  const ScreenedCandidate& sc = candidates[static_cast<std::size_t>(c)];
  // B lies in range(P), so B'(P r) = B' r: no projection of r needed.
  const Eigen::VectorXd g = sc.projected.transpose() * r;
  Eigen::VectorXd d;
  const double lr = boxQuadratic(sc.gram, g, sc.phi, d);
  if (step) *step = d;
  return std::max(lr, 0.0);
}

Result<Screen> screenCandidates(const Model& baseline, const Eigen::VectorXd& u0,
                                const std::vector<std::pair<int, std::vector<Scaled>>>& phi) {
  const std::string where = "linear screen";
  Screen screen;
  const int n = baseline.residualCount();
  const int p = baseline.parameterCount();
  Eigen::MatrixXd jd, jp;
  if (!baseline.jacobian(u0, 0, p, kSignatureStep, jd)) {
    return makeError(ErrorCode::NumericalFailure, "the model cannot be evaluated next to the calibrated baseline",
                     where);
  }
  baseline.priorJacobian(jp);
  const int m = n + static_cast<int>(jp.rows());
  screen.augmentedRows = m;
  Eigen::MatrixXd jac(m, p);
  jac << jd, jp;
  if (p > 0) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(jac);
    screen.thetaRank = static_cast<int>(qr.rank());
    screen.basis = qr.householderQ() * Eigen::MatrixXd::Identity(m, screen.thetaRank);
  } else {
    screen.basis = Eigen::MatrixXd(m, 0);  // nothing to project out
  }
  const std::vector<Scaled>& theta = baseline.theta();

  for (const auto& [index, scaled] : phi) {
    ScreenedCandidate sc;
    sc.index = index;
    sc.phi = scaled;
    const int q = static_cast<int>(scaled.size());
    Model joint(baseline.problem(), theta, index, scaled);
    Eigen::VectorXd uj = Eigen::VectorXd::Zero(p + q);
    uj.head(p) = u0;
    Eigen::MatrixXd s;
    if (q == 0 || !joint.jacobian(uj, p, q, kSignatureStep, s)) {
      sc.reason = q == 0 ? "the effect has no parameters" : "the model with this effect cannot be evaluated";
      screen.candidates.push_back(std::move(sc));
      continue;
    }
    Eigen::MatrixXd sAug = Eigen::MatrixXd::Zero(m, q);
    sAug.topRows(n) = s;
    // B = P S = S - Q (Q' S)
    sc.projected = sAug - screen.basis * (screen.basis.transpose() * sAug);
    sc.gram = sc.projected.transpose() * sc.projected;
    Eigen::VectorXd span(q);
    for (int j = 0; j < q; ++j) {
      const Scaled& ph = scaled[static_cast<std::size_t>(j)];
      span[j] = ph.fixed ? 0.0 : std::max(std::min(ph.uUpper, 1.0), std::min(-ph.uLower, 1.0));
      sc.projectedNorm.push_back(sc.projected.col(j).norm());
    }
    // Over the free parameters only (a fixed one moves nothing by design).
    std::vector<int> free;
    for (int j = 0; j < q; ++j) {
      if (!scaled[static_cast<std::size_t>(j)].fixed) free.push_back(j);
    }
    const auto nf = static_cast<Eigen::Index>(free.size());
    Eigen::MatrixXd bFree(m, nf), sFree(m, nf);
    for (Eigen::Index j = 0; j < nf; ++j) {
      bFree.col(j) = sc.projected.col(free[static_cast<std::size_t>(j)]) * span[free[static_cast<std::size_t>(j)]];
      sFree.col(j) = sAug.col(free[static_cast<std::size_t>(j)]) * span[free[static_cast<std::size_t>(j)]];
    }
    sc.sigmaMin = nf > 0 ? Eigen::JacobiSVD<Eigen::MatrixXd>(bFree).singularValues()[nf - 1] : 0.0;
    const double sMin = nf > 0 ? Eigen::JacobiSVD<Eigen::MatrixXd>(sFree).singularValues()[nf - 1] : 0.0;
    sc.absorbedFraction = sMin > 0.0 ? 1.0 - sc.sigmaMin / sMin : 1.0;

    Eigen::MatrixXd both(m, p + q);
    both << jac, sAug;
    const Eigen::JacobiSVD<Eigen::MatrixXd> svdJoint(both, Eigen::ComputeThinV);
    sc.jointSingularValues = svdJoint.singularValues();
    sc.nullDirection = svdJoint.matrixV().col(svdJoint.matrixV().cols() - 1);

    if (!(sMin > 0.0) || sc.sigmaMin <= kAbsorbed * sMin) {
      sc.reason = sMin > 0.0 ? "calibration absorbs its signature (what is left after projecting out theta is " +
                                   formatNumber(sc.sigmaMin / sMin, 2) + " of it)"
                             : "its parameters do not change the residuals";
    } else if (sc.sigmaMin < kNoiseScale) {
      sc.reason = "even the largest size within its bounds moves the residuals by " + formatNumber(sc.sigmaMin, 2) +
                  " noise standard deviations after calibration";
    } else {
      sc.identifiable = true;
    }
    if (sc.identifiable) {
      Eigen::HouseholderQR<Eigen::MatrixXd> qb(bFree);
      sc.basis = qb.householderQ() * Eigen::MatrixXd::Identity(m, nf);
    }
    screen.candidates.push_back(std::move(sc));
  }

  const auto k = static_cast<Eigen::Index>(screen.candidates.size());
  screen.confusability = Eigen::MatrixXd::Constant(k, k, std::numeric_limits<double>::quiet_NaN());
  for (Eigen::Index a = 0; a < k; ++a) {
    for (Eigen::Index b = a; b < k; ++b) {
      const auto& ca = screen.candidates[static_cast<std::size_t>(a)];
      const auto& cb = screen.candidates[static_cast<std::size_t>(b)];
      if (!ca.identifiable || !cb.identifiable) continue;
      // cosine of the smallest principal angle between the two ranges
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd(ca.basis.transpose() * cb.basis);
      screen.confusability(a, b) = screen.confusability(b, a) = std::min(1.0, svd.singularValues()[0]);
    }
  }
  return screen;
}

}  // namespace mozzi::core::gap::engine
