#include "core/modal/lsfd.h"

#include <cmath>
#include <string>

#include "core/modal/varpro.h"

namespace mozzi::core::modal {

namespace {
constexpr double kTwoPi = 2.0 * M_PI;

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
  MOZZI_TRY(frf.validate());
  if (poles.empty()) return makeError(ErrorCode::InvalidArgument, "no poles to fit residues for", where);
  for (std::size_t r = 0; r < poles.size(); ++r) {
    if (!(poles[r].imag() > 0.0) || !(poles[r].real() < 0.0) || !std::isfinite(std::abs(poles[r]))) {
      return makeError(ErrorCode::InvalidArgument, "pole must be finite with Re < 0 and Im > 0",
                       where + ", pole " + std::to_string(r + 1));
    }
  }
  const BandLines b = bandLines(frf, opt.bandLowHz, opt.bandHighHz, true);
  const Eigen::Index nm = static_cast<Eigen::Index>(poles.size());
  const Eigen::Index p = 2 * nm + (opt.upperResidual ? 2 : 0) + (opt.lowerResidual ? 2 : 0);
  if (2 * b.nf < 2 * p) {
    return makeError(ErrorCode::InvalidArgument,
                     "band holds " + std::to_string(b.nf) + " lines (DC excluded) for " + std::to_string(p) +
                         " real unknowns per FRF",
                     where + ", band");
  }
  // The basis, its QR and the solution for every FRF: the variable-projection
  // evaluation of refine.h at fixed poles (varpro.h), one implementation.
  auto vp = ModalVarpro::create(frf, {LineSegment{b.k0, b.nf}}, static_cast<int>(nm), opt.lowerResidual,
                                opt.upperResidual, false);
  if (!vp) return makeError(vp.error().code, vp.error().message, where + ", band");
  Vector theta(2 * nm);
  for (Eigen::Index r = 0; r < nm; ++r) {
    theta[2 * r] = poleFrequencyHz(poles[static_cast<std::size_t>(r)]);
    theta[2 * r + 1] = poleZeta(poles[static_cast<std::size_t>(r)]);
  }
  if (!vp->evaluate(theta, false)) {
    return makeError(
        ErrorCode::NumericalFailure,
        "basis is rank deficient: duplicate poles or too narrow a band for " + std::to_string(nm) + " poles", where);
  }
  return modalModelFromLinear(*vp, frf, poles);
}

Result<double> relativeFitError(const FrfMatrix& frf, const ModalModel& model, double lo, double hi) {
  MOZZI_TRY(frf.validate());
  MOZZI_TRY(model.validate());
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
