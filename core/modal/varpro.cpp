#include "core/modal/varpro.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace mozzi::core::modal {

namespace {
constexpr double kTwoPi = 2.0 * M_PI;

Complex iOmegaPower(double omega, int n) {
  Complex f(1.0, 0.0);
  for (int p = 0; p < n; ++p) f *= Complex(0.0, omega);
  for (int p = 0; p < -n; ++p) f /= Complex(0.0, omega);
  return f;
}

// Columns: basis column of mode r, part c (0: fn (a + b), 1: i fn (a - b));
// derivative column of mode r, parameter t (0: f, 1: zeta), part c.
inline Eigen::Index basisCol(int r, int c) {
  return 2 * r + c;
}
inline Eigen::Index derivCol(int r, int t, int c) {
  return 4 * r + 2 * t + c;
}
}  // namespace

Result<ModalVarpro> ModalVarpro::create(const FrfMatrix& frf, std::vector<LineSegment> segments, int modes,
                                        bool lowerResidual, bool upperResidual, bool derivatives) {
  const std::string where = "variable projection";
  if (modes < 1) return makeError(ErrorCode::InvalidArgument, "no modes", where);
  ModalVarpro v;
  v.frf_ = &frf;
  v.nm_ = modes;
  v.lower_ = lowerResidual;
  v.upper_ = upperResidual;
  v.no_ = frf.responseCount();
  v.ni_ = frf.referenceCount();
  v.m_ = v.no_ * v.ni_;
  v.p_ = 2 * modes + (lowerResidual ? 2 : 0) + (upperResidual ? 2 : 0);
  for (const auto& s : segments) {
    if (s.count <= 0 || s.first < 0 || s.first + s.count > frf.lineCount()) {
      return makeError(ErrorCode::InvalidArgument, "line segment outside the FRFs", where);
    }
    v.segmentRow_.push_back(2 * v.nf_);
    v.nf_ += s.count;
  }
  v.segments_ = std::move(segments);
  if (2 * v.nf_ <= v.p_ + 2 * modes) {
    return makeError(ErrorCode::InvalidArgument,
                     std::to_string(v.nf_) + " lines are too few for " + std::to_string(v.p_) +
                         " real unknowns per FRF and " + std::to_string(2 * modes) + " pole parameters",
                     where + ", band");
  }
  const int n = frfTypeOrder(frf.type);
  v.modeTerms_.resize(static_cast<std::size_t>(modes));
  v.omega_.resize(v.nf_);
  v.fn_.resize(v.nf_);
  v.fl_.resize(v.nf_);
  Eigen::Index k = 0;
  for (const auto& s : v.segments_) {
    for (Eigen::Index q = 0; q < s.count; ++q, ++k) {
      const double w = kTwoPi * frf.frequencyHz[s.first + q];
      if (!(w > 0.0)) return makeError(ErrorCode::InvalidArgument, "a line at 0 Hz or below", where);
      v.omega_[k] = w;
      v.fn_[k] = iOmegaPower(w, n);
      v.fl_[k] = iOmegaPower(w, n - 2);
    }
  }
  v.yNorm2_ = 0.0;
  for (std::size_t s = 0; s < v.segments_.size(); ++s)
    for (Eigen::Index i = 0; i < v.ni_; ++i) v.yNorm2_ += v.ySegment(s, i).squaredNorm();
  if (!(v.yNorm2_ > 0.0) || !std::isfinite(v.yNorm2_)) {
    return makeError(ErrorCode::InvalidArgument, "FRFs are zero (or not finite) on the lines", where);
  }
  const Eigen::Index rows = 2 * v.nf_, nd = derivatives ? 4 * modes : 0;
  v.withDerivatives_ = derivatives;
  v.a_.resize(rows, v.p_ + nd);
  v.r_.resize(v.p_, v.p_);
  v.rTmp_.resize(v.p_, v.p_);
  v.gram_.resize(v.p_, v.p_);
  // Sized by a factorisation, not by LLT(size): that constructor leaves the
  // status unset, and moving it in is a load of an invalid enum (UBSan).
  v.llt_.compute(Matrix::Identity(v.p_, v.p_));
  v.hWork_.resize(v.p_ + nd);
  // Blocks of at most about 4 MB of model values (Q Z, rows x no): few
  // matrix products (each sets up its own packing), none of the data's size.
  const Eigen::Index blockRows = std::min<Eigen::Index>(
      rows, std::max<Eigen::Index>(256, (Eigen::Index{1} << 19) / std::max<Eigen::Index>(1, v.no_)));
  v.blockWork_.resize(blockRows, v.no_);
  v.w_.resize(v.p_ + nd, v.m_);
  v.x_.resize(v.p_, v.m_);
  v.colNorm_.resize(v.p_);
  if (derivatives) {
    v.qtE_.resize(v.p_, nd);
    v.epe_.resize(nd, nd);
    v.g_.resize(v.p_, v.p_);
    v.b_.resize(v.p_, v.m_ * 2 * modes);
    v.grad_.resize(2 * modes);
    v.jtjGp_.resize(2 * modes, 2 * modes);
    v.jtjK_.resize(2 * modes, 2 * modes);
    v.rx_.resize(std::min<Eigen::Index>(rows, 1024), 2 * modes);  // a block of rows
    v.zx_.resize(v.p_, 2 * modes);
    v.ezx_.resize(nd, 2 * modes);
  }
  return v;
}

Eigen::Map<const Matrix, 0, Eigen::OuterStride<>> ModalVarpro::ySegment(std::size_t s, Eigen::Index i) const {
  const ComplexMatrix& h = frf_->h[static_cast<std::size_t>(i)];
  const LineSegment& seg = segments_[s];
  return Eigen::Map<const Matrix, 0, Eigen::OuterStride<>>(reinterpret_cast<const double*>(h.data() + seg.first),
                                                           2 * seg.count, no_, Eigen::OuterStride<>(2 * h.rows()));
}

bool ModalVarpro::fillBasis(const Eigen::Ref<const Vector>& theta, bool withDerivatives) {
  for (int r = 0; r < nm_; ++r) {
    const double f = theta[2 * r], z = theta[2 * r + 1];
    if (!(f > 0.0) || !(z > 0.0) || !(z < 1.0) || !std::isfinite(f)) return false;
  }
  const Complex i1(0.0, 1.0);
  // Per mode, once (the same expressions as per line: the same numbers).
  modeTerms_.resize(static_cast<std::size_t>(nm_));
  for (int r = 0; r < nm_; ++r) {
    const double f = theta[2 * r], z = theta[2 * r + 1];
    const double wn = kTwoPi * f, s = std::sqrt(1.0 - z * z);
    // d lambda / d f = lambda / f = 2 pi (-zeta + i s); d lambda / d zeta = wn (-1 - i zeta / s)
    modeTerms_[static_cast<std::size_t>(r)] = {wn,
                                               s,
                                               z * wn,
                                               wn * s,  // lambda = -sigma + i wd
                                               Complex(-kTwoPi * z, kTwoPi * s),
                                               Complex(-wn, -wn * z / s)};
  }
  for (Eigen::Index k = 0; k < nf_; ++k) {
    const double w = omega_[k];
    const Complex fn = fn_[k];
    const Eigen::Index row = 2 * k;
    for (int r = 0; r < nm_; ++r) {
      const auto& m = modeTerms_[static_cast<std::size_t>(r)];
      const double sigma = m.sigma, wd = m.wd;
      // a = 1/(i w - lambda) = 1/(sigma + i (w - wd)), b = 1/(sigma + i (w + wd))
      const double d1 = w - wd, d2 = w + wd;
      const double n1 = 1.0 / (sigma * sigma + d1 * d1), n2 = 1.0 / (sigma * sigma + d2 * d2);
      const Complex a(sigma * n1, -d1 * n1), b(sigma * n2, -d2 * n2);
      const Complex c1 = fn * (a + b), c2 = i1 * fn * (a - b);
      a_(row, basisCol(r, 0)) = c1.real();
      a_(row + 1, basisCol(r, 0)) = c1.imag();
      a_(row, basisCol(r, 1)) = c2.real();
      a_(row + 1, basisCol(r, 1)) = c2.imag();
      if (!withDerivatives) continue;
      const Complex dl[2] = {m.dlf, m.dlz};
      const Complex a2 = a * a, b2 = b * b;
      for (int t = 0; t < 2; ++t) {
        // da = a^2 dlambda, db = b^2 conj(dlambda)
        const Complex da = a2 * dl[t], db = b2 * std::conj(dl[t]);
        const Complex e1 = fn * (da + db), e2 = i1 * fn * (da - db);
        a_(row, p_ + derivCol(r, t, 0)) = e1.real();
        a_(row + 1, p_ + derivCol(r, t, 0)) = e1.imag();
        a_(row, p_ + derivCol(r, t, 1)) = e2.real();
        a_(row + 1, p_ + derivCol(r, t, 1)) = e2.imag();
      }
    }
    Eigen::Index c = 2 * nm_;
    auto put = [&](Complex g) {
      a_(row, c) = g.real();
      a_(row + 1, c) = g.imag();
      a_(row, c + 1) = -g.imag();  // i g
      a_(row + 1, c + 1) = g.real();
      c += 2;
    };
    if (upper_) put(fn);
    if (lower_) put(fl_[k]);
  }
  return true;
}

bool ModalVarpro::orthogonalize(const Eigen::Ref<const Vector>& theta) {
  auto q = a_.leftCols(p_);
  colNorm_ = q.colwise().norm().transpose();
  for (Eigen::Index c = 0; c < p_; ++c) {
    if (!(colNorm_[c] > 0.0) || !std::isfinite(colNorm_[c])) return false;
  }
  // CholeskyQR2 (Fukaya, Nakatsukasa, Yanagisawa and Yamamoto, 2014) on the
  // column-equilibrated basis: two passes of Q <- Q U^-1 with U^T U = Q^T Q
  // give Q orthonormal to rounding while the scaled basis is conditioned
  // better than about 1e7; all of it matrix-matrix products.
  q.array().rowwise() /= colNorm_.transpose().array();
  r_.setIdentity();
  bool ok = true;
  for (int pass = 0; pass < 2 && ok; ++pass) {
    gram_.setZero();
    gram_.selfadjointView<Eigen::Lower>().rankUpdate(q.transpose());
    llt_.compute(gram_);
    ok = llt_.info() == Eigen::Success;
    if (!ok) break;
    llt_.matrixU().solveInPlace<Eigen::OnTheRight>(q);
    rTmp_.noalias() = llt_.matrixU() * r_;
    r_ = rTmp_;
  }
  // |R_cc| of the equilibrated basis is the sine of the angle between column
  // c and the span of the columns before it.
  for (Eigen::Index c = 0; ok && c < p_; ++c) ok = std::abs(r_(c, c)) > 1e-6;
  if (ok) {
    r_.array().rowwise() *= colNorm_.transpose().array();  // Phi = Q R
    return true;
  }
  // Nearly dependent columns (two close poles): Householder QR, the basis
  // filled again (the passes above overwrote it).
  fillBasis(theta, false);
  if (qr_.rows() != q.rows()) qr_ = Eigen::HouseholderQR<Matrix>(q.rows(), p_);
  qr_.compute(q);
  const auto& qrm = qr_.matrixQR();
  for (Eigen::Index c = 0; c < p_; ++c) {
    if (!(std::abs(qrm(c, c)) > 1e-11 * colNorm_[c])) return false;
  }
  r_ = qrm.topLeftCorner(p_, p_).triangularView<Eigen::Upper>();
  q.setIdentity();
  qr_.householderQ().applyThisOnTheLeft(q, hWork_);
  return true;
}

bool ModalVarpro::evaluate(const Eigen::Ref<const Vector>& theta, Derivatives what) {
  derivatives_ = false;
  const bool anyDerivatives = what != Derivatives::None, full = what == Derivatives::Full;
  if (anyDerivatives && !withDerivatives_) return false;
  if (theta.size() != 2 * nm_ || !fillBasis(theta, anyDerivatives)) return false;
  // A = [Phi, E] now; Phi is replaced by Q below (E stays).
  if (!orthogonalize(theta)) return false;
  const Eigen::Index nd = 4 * nm_, cols = full ? p_ + nd : p_;
  if (anyDerivatives) qtE_.noalias() = a_.leftCols(p_).transpose() * a_.rightCols(nd);  // Q^T E
  // [Z; E^T Y] = [Q, E]^T Y (Z = Q^T Y without the gradient): the one pass over the data.
  auto w = w_.topRows(cols);
  w.setZero();
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    const auto aRows = a_.block(segmentRow_[s], 0, 2 * segments_[s].count, cols);
    for (Eigen::Index i = 0; i < ni_; ++i) w.middleCols(i * no_, no_).noalias() += aRows.transpose() * ySegment(s, i);
  }
  const auto z = w_.topRows(p_);
  ssr_ = std::max(0.0, yNorm2_ - z.squaredNorm());
  x_ = z;
  r_.triangularView<Eigen::Upper>().solveInPlace(x_);
  if (!x_.allFinite()) return false;
  if (!anyDerivatives) return true;

  // E^T P E = E^T E - (Q^T E)^T (Q^T E): P E is never formed (it cost one
  // more product of the size of Q^T E); by rank updates.
  epe_.setZero();
  epe_.selfadjointView<Eigen::Lower>().rankUpdate(a_.rightCols(nd).transpose());
  epe_.selfadjointView<Eigen::Lower>().rankUpdate(qtE_.transpose(), -1.0);
  epe_.triangularView<Eigen::StrictlyUpper>() = epe_.transpose();
  g_.noalias() = x_ * x_.transpose();
  for (int r = 0; r < nm_; ++r) {
    for (int t = 0; t < 2; ++t) {
      const int j = 2 * r + t;
      for (int r2 = 0; r2 < nm_; ++r2) {
        for (int t2 = 0; t2 < 2; ++t2) {
          double v = 0.0;
          for (int c = 0; c < 2; ++c)
            for (int c2 = 0; c2 < 2; ++c2)
              v += epe_(derivCol(r, t, c), derivCol(r2, t2, c2)) * g_(basisCol(r, c), basisCol(r2, c2));
          jtjK_(j, 2 * r2 + t2) = v;
        }
      }
    }
  }
  if (what == Derivatives::Covariance) {
    derivatives_ = true;
    return true;
  }
  if (what == Derivatives::Kaufman) {
    // g_j = -sum_c E_(j,c)^T (R X_m^T)_(2r+c), R X_m^T = Y X_m^T - Q Z X_m^T;
    // E^T Q Z X_m^T = (Q^T E)^T (Z X_m^T): Q is not applied to the data's size.
    // Y X_m^T in blocks of rows (rx_: one block), each block's dot products
    // with E taken while it is in cache (a 2 nf x 2 nm buffer raised
    // identify's peak by 2.3 MB).
    const Eigen::Index nx = 2 * nm_, block = rx_.rows();
    const auto xm = x_.topRows(nx);
    zx_.noalias() = z * xm.transpose();
    ezx_.noalias() = qtE_.transpose() * zx_;
    for (int j = 0; j < nx; ++j) {
      const int r = j / 2, t = j % 2;
      grad_[j] = ezx_(derivCol(r, t, 0), basisCol(r, 0)) + ezx_(derivCol(r, t, 1), basisCol(r, 1));
    }
    for (std::size_t s = 0; s < segments_.size(); ++s) {
      const Eigen::Index rows = 2 * segments_[s].count;
      for (Eigen::Index r0 = 0; r0 < rows; r0 += block) {
        const Eigen::Index b = std::min(block, rows - r0);
        auto rx = rx_.topRows(b);
        rx.setZero();
        for (Eigen::Index i = 0; i < ni_; ++i)
          rx.noalias() += ySegment(s, i).middleRows(r0, b) * xm.middleCols(i * no_, no_).transpose();
        const auto e = a_.block(segmentRow_[s] + r0, p_, b, nd);
        for (int j = 0; j < nx; ++j) {
          const int r = j / 2, t = j % 2;
          grad_[j] -= e.col(derivCol(r, t, 0)).dot(rx.col(basisCol(r, 0))) +
                      e.col(derivCol(r, t, 1)).dot(rx.col(basisCol(r, 1)));
        }
      }
    }
    derivatives_ = true;
    return true;
  }
  // F = E^T R = E^T (Y - Q Z) = E^T Y - (Q^T E)^T Z.
  auto f = w_.bottomRows(nd);
  f.noalias() -= qtE_.transpose() * z;
  for (int r = 0; r < nm_; ++r) {
    for (int t = 0; t < 2; ++t) {
      grad_[2 * r + t] = -(f.row(derivCol(r, t, 0)).dot(x_.row(basisCol(r, 0))) +
                           f.row(derivCol(r, t, 1)).dot(x_.row(basisCol(r, 1))));
    }
  }
  // B_j = T^-T D_j^T R: D_j^T R has rows 2r, 2r+1 = F rows of (r, t); T^T is
  // lower triangular, so rows above 2r stay zero.
  const auto tLower = r_.transpose().triangularView<Eigen::Lower>();  // T^T
  for (int r = 0; r < nm_; ++r) {
    for (int t = 0; t < 2; ++t) {
      const int j = 2 * r + t;
      auto bj = b_.middleCols(j * m_, m_);
      bj.setZero();
      bj.row(basisCol(r, 0)) = f.row(derivCol(r, t, 0));
      bj.row(basisCol(r, 1)) = f.row(derivCol(r, t, 1));
      tLower.solveInPlace(bj);
    }
  }
  for (int j = 0; j < 2 * nm_; ++j) {
    for (int l = 0; l <= j; ++l) {
      const double extra = b_.middleCols(j * m_, m_).cwiseProduct(b_.middleCols(l * m_, m_)).sum();
      jtjGp_(j, l) = jtjK_(j, l) + extra;
      jtjGp_(l, j) = jtjGp_(j, l);
    }
  }
  derivatives_ = true;
  return true;
}

void ModalVarpro::modelValues(std::vector<ComplexMatrix>& out) const {
  out.resize(static_cast<std::size_t>(ni_));
  for (Eigen::Index i = 0; i < ni_; ++i) {
    ComplexMatrix& h = out[static_cast<std::size_t>(i)];
    h.resize(nf_, no_);
    // Phi X = Q Z
    Eigen::Map<Matrix>(reinterpret_cast<double*>(h.data()), 2 * nf_, no_).noalias() =
        a_.leftCols(p_) * w_.topRows(p_).middleCols(i * no_, no_);
  }
}

void ModalVarpro::modelValues(Eigen::Index response, Eigen::Index reference, ComplexVector& out) const {
  out.resize(nf_);
  // Phi x_c = Q z_c
  Eigen::Map<Vector>(reinterpret_cast<double*>(out.data()), 2 * nf_).noalias() =
      a_.leftCols(p_) * w_.topRows(p_).col(reference * no_ + response);
}

double ModalVarpro::explicitSsr() {
  Vector perFrf;
  explicitSsrPerFrf(perFrf);
  return perFrf.sum();
}

void ModalVarpro::explicitSsrPerFrf(Vector& out) {
  out.setZero(m_);
  const auto q = a_.leftCols(p_);
  const auto z = w_.topRows(p_);
  const Eigen::Index block = blockWork_.rows();
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    const Eigen::Index rows = 2 * segments_[s].count;
    for (Eigen::Index i = 0; i < ni_; ++i) {
      const auto y = ySegment(s, i);
      const auto zi = z.middleCols(i * no_, no_);
      for (Eigen::Index r0 = 0; r0 < rows; r0 += block) {
        // R = Y - Q Z on rows r0 .. r0 + b of the segment (the product
        // subtracted in place), then |R|^2 per column.
        const Eigen::Index b = std::min(block, rows - r0);
        auto work = blockWork_.topRows(b);
        work = y.middleRows(r0, b);
        work.noalias() -= q.middleRows(segmentRow_[s] + r0, b) * zi;
        out.segment(i * no_, no_) += work.colwise().squaredNorm().transpose();
      }
    }
  }
}

void ModalVarpro::denseResidual(const Eigen::Ref<const Vector>& theta, Vector& r, Matrix* jGp, Matrix* jK) {
  // Phi and E before evaluate() overwrites Phi with Q.
  Matrix phi, e;
  if (fillBasis(theta, true)) {
    phi = a_.leftCols(p_);
    e = a_.rightCols(4 * nm_);
  }
  const bool ok = evaluate(theta, true);
  const Eigen::Index rows = 2 * nf_;
  r.resize(rows * m_);
  if (!ok) {
    r.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  // Dense Y, residual R = Y - Phi X.
  Matrix y(rows, m_);
  for (std::size_t s = 0; s < segments_.size(); ++s)
    for (Eigen::Index i = 0; i < ni_; ++i)
      y.block(segmentRow_[s], i * no_, 2 * segments_[s].count, no_) = ySegment(s, i);
  const Matrix res = y - phi * x_;
  for (Eigen::Index c = 0; c < m_; ++c) r.segment(c * rows, rows) = res.col(c);
  if (!jGp && !jK) return;
  const Matrix q = a_.leftCols(p_);
  const auto tLower = r_.transpose().triangularView<Eigen::Lower>();  // T^T
  if (jGp) jGp->resize(rows * m_, 2 * nm_);
  if (jK) jK->resize(rows * m_, 2 * nm_);
  for (int md = 0; md < nm_; ++md) {
    for (int t = 0; t < 2; ++t) {
      const int j = 2 * md + t;
      Matrix dj = Matrix::Zero(rows, p_);
      dj.col(basisCol(md, 0)) = e.col(derivCol(md, t, 0));
      dj.col(basisCol(md, 1)) = e.col(derivCol(md, t, 1));
      const Matrix djx = dj * x_;
      const Matrix kauf = -(djx - q * (q.transpose() * djx));
      Matrix bj = dj.transpose() * res;
      tLower.solveInPlace(bj);
      const Matrix gp = kauf - q * bj;
      for (Eigen::Index c = 0; c < m_; ++c) {
        if (jK) jK->block(c * rows, j, rows, 1) = kauf.col(c);
        if (jGp) jGp->block(c * rows, j, rows, 1) = gp.col(c);
      }
    }
  }
}

ModalModel modalModelFromLinear(const ModalVarpro& vp, const FrfMatrix& frf, const std::vector<Complex>& poles) {
  const Matrix& x = vp.linear();
  const Eigen::Index no = frf.responseCount(), ni = frf.referenceCount();
  ModalModel model;
  model.responses = frf.responses;
  model.references = frf.references;
  for (std::size_t r = 0; r < poles.size(); ++r) {
    Mode md;
    md.pole = poles[r];
    md.residue.resize(no, ni);
    const Eigen::Index row = 2 * static_cast<Eigen::Index>(r);
    for (Eigen::Index i = 0; i < ni; ++i)
      for (Eigen::Index o = 0; o < no; ++o) md.residue(o, i) = Complex(x(row, i * no + o), x(row + 1, i * no + o));
    model.modes.push_back(std::move(md));
  }
  Eigen::Index c = 2 * static_cast<Eigen::Index>(poles.size());
  auto residual = [&](ComplexMatrix& out) {
    out.resize(no, ni);
    for (Eigen::Index i = 0; i < ni; ++i)
      for (Eigen::Index o = 0; o < no; ++o) out(o, i) = Complex(x(c, i * no + o), x(c + 1, i * no + o));
    c += 2;
  };
  if (vp.upperResidual()) residual(model.upperResidual);
  if (vp.lowerResidual()) residual(model.lowerResidual);
  return model;
}

}  // namespace mozzi::core::modal
