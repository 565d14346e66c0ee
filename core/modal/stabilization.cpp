#include "core/modal/stabilization.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/common/text.h"
#include "core/modal/shape_tools.h"

namespace mozzi::core::modal {

namespace {

constexpr double kTwoPi = 2.0 * M_PI;

// 1 / d without the NaN/Inf bookkeeping of the C99 complex division (__divdc3,
// a third of the root finding's time); d is never zero or infinite here.
inline Complex reciprocal(Complex d) {
  const double s = 1.0 / (d.real() * d.real() + d.imag() * d.imag());
  return {d.real() * s, -d.imag() * s};
}

}  // namespace

bool MatrixPolynomialRoots::aberth(const Matrix& alpha, Eigen::Index ni) {
  const Eigen::Index m = alpha.rows() / ni - 1, nr = m * ni;
  const auto n = static_cast<std::size_t>(nr);
  roots_.assign(n, Complex(0.0, 0.0));
  done_.assign(n, 0);
  const std::size_t reuse = std::min(n, warm_.size());
  std::copy(warm_.begin(), warm_.begin() + static_cast<std::ptrdiff_t>(reuse), roots_.begin());
  for (std::size_t i = reuse; i < n; ++i) {
    const double t = kTwoPi * (static_cast<double>(i - reuse) + 0.37) / static_cast<double>(n - reuse) + 0.1;
    roots_[i] = std::polar(1.05, t);
  }
  if (ni > 1) {
    a_.resize(ni, ni);
    da_.resize(ni, ni);
  }
  Eigen::PartialPivLU<ComplexMatrix> lu(ni);
  // Newton ratio det A / (det A)' at z.
  auto newton = [&](Complex z) -> Complex {
    if (ni == 1) {
      Complex pz(1.0, 0.0), dp(0.0, 0.0);
      for (Eigen::Index j = m - 1; j >= 0; --j) {
        dp = dp * z + pz;
        pz = pz * z + alpha(j, 0);
      }
      return pz * reciprocal(dp);
    }
    a_.setIdentity();
    da_.setZero();
    for (Eigen::Index j = m - 1; j >= 0; --j) {
      da_ = da_ * z + a_;
      a_ = a_ * z + alpha.block(j * ni, 0, ni, ni).cast<Complex>();
    }
    lu.compute(a_);
    x_ = lu.solve(da_);
    return reciprocal(x_.trace());  // (det A)' / det A = tr(A^-1 A')
  };
  for (int sweep = 0; sweep < 50; ++sweep) {
    bool all = true;
    for (std::size_t i = 0; i < n; ++i) {
      if (done_[i]) continue;
      Complex& z = roots_[i];
      const Complex ratio = newton(z);
      if (ratio == Complex(0.0, 0.0)) {
        done_[i] = 1;
        continue;
      }
      Complex sum(0.0, 0.0);
      for (std::size_t j = 0; j < n; ++j) {
        if (j != i) sum += reciprocal(z - roots_[j]);
      }
      const Complex w = ratio * reciprocal(1.0 - ratio * sum);
      if (!std::isfinite(w.real()) || !std::isfinite(w.imag())) return false;
      z -= w;
      // Relative step; the roots are not better conditioned than this at order 100+.
      if (std::abs(w) < 1e-11 * std::max(1.0, std::abs(z))) {
        done_[i] = 1;
      } else {
        all = false;
      }
    }
    if (all) return true;
  }
  return false;
}

Result<ComplexVector> MatrixPolynomialRoots::solve(const Matrix& alpha, Eigen::Index ni, const std::string& where) {
  const Eigen::Index m = alpha.rows() / ni - 1, mb = m * ni;
  if (aberth(alpha, ni)) {
    warm_ = roots_;
    return ComplexVector(Eigen::Map<const ComplexVector>(roots_.data(), mb));
  }
  warm_.clear();
  ComplexVector zr(mb);
  if (ni == 1) {
    // Companion in upper Hessenberg form (first row -a_{m-1} .. -a_0, ones
    // below the diagonal): straight to the real Schur iteration.
    Matrix hess = Matrix::Zero(mb, mb);
    for (Eigen::Index j = 0; j < mb; ++j) hess(0, j) = -alpha(mb - 1 - j, 0);
    if (mb > 1) hess.diagonal(-1).setOnes();
    Eigen::RealSchur<Matrix> schur(mb);
    schur.computeFromHessenberg(hess, Matrix(), false);
    if (schur.info() != Eigen::Success) {
      return makeError(ErrorCode::NumericalFailure, "companion eigenproblem did not converge", where);
    }
    const Matrix& t = schur.matrixT();
    for (Eigen::Index q = 0; q < mb;) {
      if (q + 1 < mb && t(q + 1, q) != 0.0) {
        // 2 x 2 block [a b; c d]: eigenvalues (a + d)/2 +- sqrt(((a - d)/2)^2 + b c).
        const double p0 = 0.5 * (t(q, q) + t(q + 1, q + 1));
        const Complex disc = std::sqrt(
            Complex(0.25 * (t(q, q) - t(q + 1, q + 1)) * (t(q, q) - t(q + 1, q + 1)) + t(q, q + 1) * t(q + 1, q)));
        zr[q] = p0 + disc;
        zr[q + 1] = p0 - disc;
        q += 2;
      } else {
        zr[q] = t(q, q);
        ++q;
      }
    }
    return zr;
  }
  // Block companion: bottom block row -alpha_j (z^m l = -sum_j alpha_j z^j l).
  Matrix comp = Matrix::Zero(mb, mb);
  if (m > 1) comp.topRightCorner(mb - ni, mb - ni).setIdentity();
  for (Eigen::Index j = 0; j < m; ++j) comp.block(mb - ni, j * ni, ni, ni) = -alpha.block(j * ni, 0, ni, ni);
  Eigen::EigenSolver<Matrix> es(comp, false);
  if (es.info() != Eigen::Success) {
    return makeError(ErrorCode::NumericalFailure, "companion eigenproblem did not converge", where);
  }
  return ComplexVector(es.eigenvalues());
}

void appendOrderPoles(int order, const Matrix& alpha, Eigen::Index ni, const ComplexVector& zr, double dt,
                      const PoleShapeFunction& shape, const PlscfOptions& opt, std::vector<StabilizationPole>& previous,
                      StabilizationDiagram& diag) {
  const Eigen::Index m = alpha.rows() / ni - 1;
  std::vector<StabilizationPole> current;
  for (Eigen::Index r = 0; r < zr.size(); ++r) {
    const Complex z = zr[r];
    if (std::abs(z) == 0.0) continue;
    const Complex lambda = std::log(z) / dt;
    if (lambda.imag() <= 0.0) continue;
    const double fr = poleFrequencyHz(lambda), zeta = poleZeta(lambda);
    if (fr < opt.bandLowHz || fr > opt.bandHighHz || !(zeta > 0.0) || zeta > opt.criteria.maxZeta) continue;
    StabilizationPole p;
    p.order = order;
    p.pole = lambda;
    p.frequencyHz = fr;
    p.zeta = zeta;
    // H ~ (N(z_r) v) w^T / (z - z_r): v, the right null vector of A(z_r),
    // builds the shape; w (w^T A(z_r) = 0) is the participation vector. From
    // A = U S V^H: v = last column of V, w = conj(last column of U).
    ComplexVector v = ComplexVector::Ones(1);
    if (ni > 1) {
      ComplexMatrix az = ComplexMatrix::Zero(ni, ni);
      Complex zp(1.0, 0.0);
      for (Eigen::Index q = 0; q <= m; ++q) {
        az += zp * alpha.block(q * ni, 0, ni, ni).cast<Complex>();
        zp *= z;
      }
      Eigen::JacobiSVD<ComplexMatrix> svd(az, Eigen::ComputeFullU | Eigen::ComputeFullV);
      v = svd.matrixV().col(ni - 1);
      p.participation = svd.matrixU().col(ni - 1).conjugate();
      Eigen::Index imax = 0;
      p.participation.cwiseAbs().maxCoeff(&imax);
      p.participation /= p.participation[imax];
    } else {
      p.participation = v;
    }
    p.shape = shape(z, v);
    // Stability against the previous evaluated order: nearest pole in frequency.
    p.status = PoleStatus::New;
    const StabilizationPole* best = nullptr;
    for (const auto& q : previous) {
      if (!best || std::abs(q.frequencyHz - fr) < std::abs(best->frequencyHz - fr)) best = &q;
    }
    if (best && std::abs(best->frequencyHz - fr) <= opt.criteria.frequencyTolerance * best->frequencyHz) {
      const bool dampOk = std::abs(best->zeta - zeta) <= opt.criteria.dampingTolerance * best->zeta;
      const double vmac = opt.criteria.vector == StabilityVector::Participation
                              ? mac(p.participation, best->participation)
                              : mac(p.shape, best->shape);
      const bool vecOk = vmac >= opt.criteria.macThreshold;
      p.status = dampOk && vecOk ? PoleStatus::Stable
                 : dampOk        ? PoleStatus::FrequencyDamping
                 : vecOk         ? PoleStatus::FrequencyVector
                                 : PoleStatus::Frequency;
    }
    current.push_back(std::move(p));
  }
  std::sort(current.begin(), current.end(),
            [](const StabilizationPole& a, const StabilizationPole& b) { return a.frequencyHz < b.frequencyHz; });
  diag.poles.insert(diag.poles.end(), current.begin(), current.end());
  previous = std::move(current);
}

Result<std::vector<int>> stabilizationOrders(const PlscfOptions& opt, const std::string& where) {
  if (!(opt.bandLowHz >= 0.0) || !(opt.bandHighHz > opt.bandLowHz)) {
    return makeError(ErrorCode::InvalidArgument,
                     "band must satisfy 0 <= low < high (got " + formatNumber(opt.bandLowHz, 6) + " .. " +
                         formatNumber(opt.bandHighHz, 6) + " Hz)",
                     where + ", band");
  }
  if (opt.minOrder < 1 || opt.maxOrder < opt.minOrder || opt.orderStep < 1) {
    return makeError(ErrorCode::InvalidArgument,
                     "order range must satisfy 1 <= min <= max and step >= 1 (got " + std::to_string(opt.minOrder) +
                         ".." + std::to_string(opt.maxOrder) + " step " + std::to_string(opt.orderStep) + ")",
                     where + ", orders");
  }
  std::vector<int> orders;
  for (int m = opt.minOrder; m <= opt.maxOrder; m += opt.orderStep) orders.push_back(m);
  if (static_cast<int>(orders.size()) < opt.minClusterSize + 1) {
    return makeError(ErrorCode::InvalidArgument,
                     "order range " + std::to_string(opt.minOrder) + ".." + std::to_string(opt.maxOrder) + " gives " +
                         std::to_string(orders.size()) + " orders; judging stability needs at least " +
                         std::to_string(opt.minClusterSize + 1),
                     where + ", orders");
  }
  return orders;
}

Result<StabilizationDiagram> stabilizationOnFewerReferences(const FrfMatrix& frf,
                                                            const StabilizationEstimator& estimate) {
  if (frf.referenceCount() <= frf.responseCount()) return estimate(frf);
  // Errors name the DOFs in the caller's orientation.
  MOZZI_TRY(frf.validate());
  auto diagram = estimate(frf.transposed());
  if (!diagram) return diagram;
  for (auto& p : diagram->poles) std::swap(p.participation, p.shape);
  return diagram;
}

}  // namespace mozzi::core::modal
