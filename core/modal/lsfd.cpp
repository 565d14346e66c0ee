#include "core/modal/lsfd.h"

#include <Eigen/Dense>
#include <cmath>
#include <string>

namespace mozzi::core::modal {

namespace {
constexpr double kTwoPi = 2.0 * M_PI;

Complex iOmegaPower(double omega, int n) {
  Complex f(1.0, 0.0);
  if (n >= 0) {
    for (int p = 0; p < n; ++p) f *= Complex(0.0, omega);
  } else {
    for (int p = 0; p < -n; ++p) f /= Complex(0.0, omega);
  }
  return f;
}

struct BandLines {
  Eigen::Index k0 = 0, nf = 0;
};

BandLines bandLines(const FrfMatrix& frf, double lo, double hi, bool skipDc) {
  BandLines b;
  Eigen::Index k = 0;
  while (k < frf.lineCount() && (frf.frequencyHz[k] < lo || (skipDc && frf.frequencyHz[k] == 0.0))) ++k;
  b.k0 = k;
  while (k < frf.lineCount() && frf.frequencyHz[k] <= hi) ++k;
  b.nf = k - b.k0;
  return b;
}
}  // namespace

Result<ModalModel> lsfd(const FrfMatrix& frf, const std::vector<Complex>& poles, const LsfdOptions& opt) {
  const std::string where = "LSFD";
  if (auto ok = frf.validate(); !ok) return ok.error();
  if (poles.empty()) return makeError(ErrorCode::InvalidArgument, "no poles to fit residues for", where);
  for (std::size_t r = 0; r < poles.size(); ++r) {
    if (!(poles[r].imag() > 0.0) || !(poles[r].real() < 0.0) || !std::isfinite(std::abs(poles[r]))) {
      return makeError(ErrorCode::InvalidArgument, "pole must be finite with Re < 0 and Im > 0",
                       where + ", pole " + std::to_string(r + 1));
    }
  }
  const int n = frfTypeOrder(frf.type);
  const BandLines b = bandLines(frf, opt.bandLowHz, opt.bandHighHz, true);
  const Eigen::Index nm = static_cast<Eigen::Index>(poles.size());
  const Eigen::Index p = 2 * nm + (opt.upperResidual ? 2 : 0) + (opt.lowerResidual ? 2 : 0);
  if (2 * b.nf < 2 * p) {
    return makeError(ErrorCode::InvalidArgument,
                     "band holds " + std::to_string(b.nf) + " lines (DC excluded) for " + std::to_string(p) +
                         " real unknowns per FRF",
                     where + ", band");
  }
  // Real basis [Re g; Im g] (2 nf x p), see header for the columns.
  Matrix basis(2 * b.nf, p);
  for (Eigen::Index k = 0; k < b.nf; ++k) {
    const double w = kTwoPi * frf.frequencyHz[b.k0 + k];
    const Complex iw(0.0, w), fn = iOmegaPower(w, n);
    Eigen::Index c = 0;
    auto put = [&](Complex g) {
      basis(k, c) = g.real();
      basis(b.nf + k, c) = g.imag();
      ++c;
    };
    for (const Complex& lam : poles) {
      const Complex a = 1.0 / (iw - lam), bb = 1.0 / (iw - std::conj(lam));
      put(fn * (a + bb));                      // Re R
      put(fn * Complex(0.0, 1.0) * (a - bb));  // Im R
    }
    if (opt.upperResidual) {
      put(fn);
      put(fn * Complex(0.0, 1.0));
    }
    if (opt.lowerResidual) {
      const Complex fl = iOmegaPower(w, n - 2);
      put(fl);
      put(fl * Complex(0.0, 1.0));
    }
  }
  Vector scale = basis.colwise().norm().transpose();
  for (Eigen::Index c = 0; c < p; ++c) {
    if (!(scale[c] > 0.0)) return makeError(ErrorCode::NumericalFailure, "basis column is zero", where);
    basis.col(c) /= scale[c];
  }
  Eigen::ColPivHouseholderQR<Matrix> qr(basis);
  if (qr.rank() < p) {
    return makeError(ErrorCode::NumericalFailure,
                     "basis is rank deficient (rank " + std::to_string(qr.rank()) + " of " + std::to_string(p) +
                         "): duplicate poles or too narrow a band",
                     where);
  }
  const Eigen::Index no = frf.responseCount(), ni = frf.referenceCount();
  Matrix rhs(2 * b.nf, no * ni);
  for (Eigen::Index i = 0; i < ni; ++i) {
    const auto blk = frf.h[static_cast<std::size_t>(i)].middleRows(b.k0, b.nf);
    rhs.block(0, i * no, b.nf, no) = blk.real();
    rhs.block(b.nf, i * no, b.nf, no) = blk.imag();
  }
  Matrix x = qr.solve(rhs);
  for (Eigen::Index c = 0; c < p; ++c) x.row(c) /= scale[c];

  ModalModel model;
  model.responses = frf.responses;
  model.references = frf.references;
  for (Eigen::Index r = 0; r < nm; ++r) {
    Mode md;
    md.pole = poles[static_cast<std::size_t>(r)];
    md.residue.resize(no, ni);
    for (Eigen::Index i = 0; i < ni; ++i)
      for (Eigen::Index o = 0; o < no; ++o) md.residue(o, i) = Complex(x(2 * r, i * no + o), x(2 * r + 1, i * no + o));
    model.modes.push_back(std::move(md));
  }
  Eigen::Index c = 2 * nm;
  auto residual = [&](ComplexMatrix& out) {
    out.resize(no, ni);
    for (Eigen::Index i = 0; i < ni; ++i)
      for (Eigen::Index o = 0; o < no; ++o) out(o, i) = Complex(x(c, i * no + o), x(c + 1, i * no + o));
    c += 2;
  };
  if (opt.upperResidual) residual(model.upperResidual);
  if (opt.lowerResidual) residual(model.lowerResidual);
  return model;
}

Result<double> relativeFitError(const FrfMatrix& frf, const ModalModel& model, double lo, double hi) {
  if (auto ok = frf.validate(); !ok) return ok.error();
  if (auto ok = model.validate(); !ok) return ok.error();
  if (model.responseCount() != frf.responseCount() || model.referenceCount() != frf.referenceCount()) {
    return makeError(ErrorCode::InvalidArgument, "model and FRFs have different DOF counts", "fit error");
  }
  const BandLines b = bandLines(frf, lo, hi, true);
  if (b.nf == 0) return makeError(ErrorCode::InvalidArgument, "band holds no line", "fit error");
  double num = 0.0, den = 0.0;
  for (Eigen::Index i = 0; i < frf.referenceCount(); ++i) {
    for (Eigen::Index o = 0; o < frf.responseCount(); ++o) {
      for (Eigen::Index k = b.k0; k < b.k0 + b.nf; ++k) {
        const Complex hm = frf.h[static_cast<std::size_t>(i)](k, o);
        num += std::norm(hm - synthesize(model, o, i, kTwoPi * frf.frequencyHz[k], frf.type));
        den += std::norm(hm);
      }
    }
  }
  if (!(den > 0.0)) return makeError(ErrorCode::InvalidArgument, "FRFs are zero in the band", "fit error");
  return std::sqrt(num / den);
}

}  // namespace mozzi::core::modal
