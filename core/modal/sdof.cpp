#include "core/modal/sdof.h"

#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <vector>

namespace mozzi::core::modal {

namespace {
constexpr double kTwoPi = 2.0 * M_PI;

struct Band {
  Eigen::Index k0 = 0, nf = 0;
};

Result<Band> band(const FrfMatrix& frf, Eigen::Index reference, double lo, double hi, const char* who) {
  MOZZI_TRY(frf.validate());
  if (reference < 0 || reference >= frf.referenceCount()) {
    return makeError(ErrorCode::NotFound, "reference index out of range", who);
  }
  Band b;
  while (b.k0 < frf.lineCount() && (frf.frequencyHz[b.k0] < lo || frf.frequencyHz[b.k0] == 0.0)) ++b.k0;
  Eigen::Index k = b.k0;
  while (k < frf.lineCount() && frf.frequencyHz[k] <= hi) ++k;
  b.nf = k - b.k0;
  if (b.nf < 5) {
    return makeError(ErrorCode::InvalidArgument,
                     "band holds " + std::to_string(b.nf) + " lines above 0 Hz; a single-mode fit needs at least 5",
                     who);
  }
  return b;
}

// FRF of `reference` converted to (i omega)^target / (i omega)^type.
Complex as(const FrfMatrix& frf, Eigen::Index i, Eigen::Index k, Eigen::Index o, FrfType target) {
  return frf.h[static_cast<std::size_t>(i)](k, o) * frfConversionFactor(frf.type, target, kTwoPi * frf.frequencyHz[k]);
}
}  // namespace

Result<SdofEstimate> peakPicking(const FrfMatrix& frf, Eigen::Index reference, double lo, double hi) {
  const char* who = "peak picking";
  MOZZI_TRY_ASSIGN(auto b, band(frf, reference, lo, hi, who));
  const auto& h = frf.h[static_cast<std::size_t>(reference)];
  Vector power = h.middleRows(b.k0, b.nf).cwiseAbs2().rowwise().sum();
  Eigen::Index kp = 0;
  power.maxCoeff(&kp);
  if (kp == 0 || kp == b.nf - 1) {
    return makeError(ErrorCode::NotFound, "the largest response is on the band edge: the band holds no resonance peak",
                     who);
  }
  const Vector& f = frf.frequencyHz;
  const Eigen::Index K = b.k0 + kp;
  // Parabolic interpolation of the peak over lines K-1, K, K+1.
  const double y0 = power[kp - 1], y1 = power[kp], y2 = power[kp + 1];
  const double den = y0 - 2 * y1 + y2;
  const double delta = den != 0.0 ? 0.5 * (y0 - y2) / den : 0.0;
  const double fr = f[K] + delta * 0.5 * (f[K + 1] - f[K - 1]);
  // Half-power points on the strongest response.
  Eigen::Index o = 0;
  h.row(K).cwiseAbs().maxCoeff(&o);
  const double half = std::abs(h(K, o)) / std::sqrt(2.0);
  auto cross = [&](int dir) -> double {
    for (Eigen::Index k = K; k + dir >= b.k0 && k + dir < b.k0 + b.nf; k += dir) {
      const double a0 = std::abs(h(k, o)), a1 = std::abs(h(k + dir, o));
      if (a1 <= half) return f[k] + (f[k + dir] - f[k]) * (a0 - half) / (a0 - a1);
    }
    return -1.0;
  };
  const double f1 = cross(-1), f2 = cross(+1);
  if (f1 < 0.0 || f2 < 0.0) {
    return makeError(ErrorCode::InvalidArgument, "a half-power point lies outside the band; widen the band", who);
  }
  SdofEstimate est;
  est.frequencyHz = fr;
  est.zeta = (f2 * f2 - f1 * f1) / (4.0 * fr * fr);
  const double wr = kTwoPi * fr, wd = wr * std::sqrt(1 - est.zeta * est.zeta);
  est.residue.resize(frf.responseCount());
  for (Eigen::Index q = 0; q < frf.responseCount(); ++q) {
    // Receptance at resonance: H = A / (2 i zeta wr^2) -> A = 2 i zeta wr^2 H.
    const Complex hr = as(frf, reference, K, q, FrfType::Receptance);
    const Complex a = Complex(0.0, 2.0 * est.zeta * wr * wr) * hr;
    est.residue[q] = a / Complex(0.0, 2.0 * wd);
  }
  return est;
}

Result<SdofEstimate> circleFit(const FrfMatrix& frf, Eigen::Index reference, double lo, double hi) {
  const char* who = "circle fit";
  MOZZI_TRY_ASSIGN(const Band b, band(frf, reference, lo, hi, who));
  const Eigen::Index nf = b.nf, no = frf.responseCount();
  Vector w(nf);
  for (Eigen::Index k = 0; k < nf; ++k) w[k] = kTwoPi * frf.frequencyHz[b.k0 + k];
  double sumWeights = 0.0, sumF = 0.0, sumZ = 0.0;
  std::vector<Complex> centres(static_cast<std::size_t>(no));
  std::vector<double> radii(static_cast<std::size_t>(no));
  for (Eigen::Index o = 0; o < no; ++o) {
    ComplexVector y(nf);
    for (Eigen::Index k = 0; k < nf; ++k) y[k] = as(frf, reference, b.k0 + k, o, FrfType::Mobility);
    // Kasa fit: x^2 + y^2 + D x + E y + F = 0 in least squares.
    Matrix a(nf, 3);
    Vector rhs(nf);
    for (Eigen::Index k = 0; k < nf; ++k) {
      a(k, 0) = y[k].real();
      a(k, 1) = y[k].imag();
      a(k, 2) = 1.0;
      rhs[k] = -std::norm(y[k]);
    }
    const Vector s = a.colPivHouseholderQr().solve(rhs);
    const Complex c(-0.5 * s[0], -0.5 * s[1]);
    const double r2 = std::norm(c) - s[2];
    if (!(r2 > 0.0) || !s.allFinite()) continue;
    const double radius = std::sqrt(r2);
    centres[static_cast<std::size_t>(o)] = c;
    radii[static_cast<std::size_t>(o)] = radius;
    // Angle of each point around the centre (unwrapped); sweep rate d theta / d(w^2).
    Vector theta(nf);
    for (Eigen::Index k = 0; k < nf; ++k) theta[k] = std::arg(y[k] - c);
    for (Eigen::Index k = 1; k < nf; ++k) {
      while (theta[k] - theta[k - 1] > M_PI) theta[k] -= 2 * M_PI;
      while (theta[k] - theta[k - 1] < -M_PI) theta[k] += 2 * M_PI;
    }
    Eigen::Index kr = 0;
    double best = -1.0;
    for (Eigen::Index k = 0; k + 1 < nf; ++k) {
      const double rate = std::abs(theta[k + 1] - theta[k]) / (w[k + 1] * w[k + 1] - w[k] * w[k]);
      if (rate > best) {
        best = rate;
        kr = k;
      }
    }
    // The resonance point is the far end of the diameter through the origin:
    // its angle about the centre is arg(c) (branch nearest the fastest sweep).
    // Interpolate omega^2 linearly in angle to that point.
    const double guess = 0.5 * (theta[kr] + theta[kr + 1]);
    double thetaR = std::arg(c);
    thetaR += 2 * M_PI * std::round((guess - thetaR) / (2 * M_PI));
    double wr = std::sqrt(0.5 * (w[kr] * w[kr] + w[kr + 1] * w[kr + 1]));
    for (Eigen::Index q = std::max<Eigen::Index>(0, kr - 2); q + 1 < std::min<Eigen::Index>(nf, kr + 3); ++q) {
      const double t0 = theta[q] - thetaR, t1 = theta[q + 1] - thetaR;
      if (t0 == t1 || t0 * t1 > 0.0) continue;
      const double u = t0 / (t0 - t1);
      wr = std::sqrt(w[q] * w[q] + u * (w[q + 1] * w[q + 1] - w[q] * w[q]));
      break;
    }
    // Damping from pairs (a below, b above): angles swept from resonance.
    double zs = 0.0;
    int nz = 0;
    for (Eigen::Index ia = 0; ia <= kr; ++ia) {
      for (Eigen::Index ib = kr + 1; ib < nf; ++ib) {
        const double ta = std::abs(theta[ia] - thetaR), tb = std::abs(theta[ib] - thetaR);
        if (ta < 0.3 || tb < 0.3 || ta > 2.6 || tb > 2.6) continue;  // 17 .. 150 deg: well-conditioned pairs
        const double wa = w[ia], wb = w[ib];
        const double z = (wb * wb - wa * wa) / (2.0 * wr * (wa * std::tan(ta / 2) + wb * std::tan(tb / 2)));
        zs += z;
        ++nz;
      }
    }
    if (nz == 0) continue;
    const double weight = radius;
    sumWeights += weight;
    sumF += weight * wr / kTwoPi;
    sumZ += weight * zs / nz;
  }
  if (!(sumWeights > 0.0)) {
    return makeError(ErrorCode::NotFound,
                     "no response traced a usable circle in the band (no mode, or band too narrow)", who);
  }
  SdofEstimate est;
  est.frequencyHz = sumF / sumWeights;
  est.zeta = sumZ / sumWeights;
  const double wr = kTwoPi * est.frequencyHz, wd = wr * std::sqrt(1 - est.zeta * est.zeta);
  est.residue = ComplexVector::Zero(no);
  for (Eigen::Index o = 0; o < no; ++o) {
    const double d = 2.0 * radii[static_cast<std::size_t>(o)];
    if (!(d > 0.0)) continue;
    // Mobility at resonance = A / (2 zeta wr): the diameter through the centre
    // from the origin-side point gives |A| and its phase.
    const Complex c = centres[static_cast<std::size_t>(o)];
    // Mobility at resonance = A / (2 zeta wr) is the far end of the diameter
    // from the origin, 2 c (the modal circle passes through the origin up to
    // residual terms).
    const Complex a = 2.0 * est.zeta * wr * (2.0 * c);
    est.residue[o] = a / Complex(0.0, 2.0 * wd);
  }
  return est;
}

}  // namespace mozzi::core::modal
