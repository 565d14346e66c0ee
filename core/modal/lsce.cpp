#include "core/modal/lsce.h"

#include <fftw3.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/common/text.h"
#include "core/modal/mode_merging.h"
#include "core/modal/stabilization.h"
#include "core/signal/fft.h"

namespace mozzi::core::modal {

namespace {

struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};

std::string hz(double f) {
  return formatNumber(f, 6) + " Hz";
}

// Impulse responses of every FRF on the baseband grid 0 .. K df: columns
// o ni + a, the first `keep` samples of the length-2K real inverse FFT.
struct ImpulseResponses {
  Matrix h;         // keep x (no ni)
  double dt = 0.0;  // 1 / (2 K df)
  long period = 0;  // 2K samples
};

Result<ImpulseResponses> impulseResponses(const FrfMatrix& frf, const LsceOptions& opt, const std::string& where) {
  const Eigen::Index nfAll = frf.lineCount();
  if (nfAll < 2) return makeError(ErrorCode::InvalidArgument, "needs at least two lines", where);
  const Vector& f = frf.frequencyHz;
  const double df = f[1] - f[0];
  Eigen::Index top = 0;  // last line <= band high
  while (top + 1 < nfAll && f[top + 1] <= opt.bandHighHz) ++top;
  for (Eigen::Index k = 0; k <= top; ++k) {
    if (std::abs(f[k] - (f[0] + df * static_cast<double>(k))) > 1e-6 * df) {
      return makeError(ErrorCode::InvalidArgument,
                       "LSCE needs an even frequency grid (line " + std::to_string(k + 1) + " at " + hz(f[k]) +
                           " breaks the spacing " + hz(df) + "); pLSCF fits uneven grids",
                       where + ", frequency grid");
    }
  }
  const double firstLine = f[0] / df;
  const auto k0 = static_cast<Eigen::Index>(std::llround(firstLine));
  const long kTop = static_cast<long>(k0 + top);  // index of the band's top line on the 0 Hz grid
  const double fN = df * static_cast<double>(kTop);
  if (std::abs(firstLine - static_cast<double>(k0)) > 1e-6 || f[0] > std::min(opt.bandLowHz, 0.05 * fN) + 1e-9 * df) {
    return makeError(ErrorCode::InvalidArgument,
                     "LSCE needs baseband FRFs from 0 Hz on a grid aligned with 0 Hz (first line " + hz(f[0]) +
                         ", spacing " + hz(df) + "; missing low lines are zero-filled only up to min(band low, 5% of " +
                         hz(fN) + ")); use pLSCF for a zoom band",
                     where + ", frequency grid");
  }
  if (kTop < 4) {
    return makeError(ErrorCode::InvalidArgument,
                     "band up to " + hz(opt.bandHighHz) + " holds " + std::to_string(top + 1) +
                         " lines; LSCE needs the band from 0 Hz",
                     where + ", band");
  }
  const Eigen::Index no = frf.responseCount(), ni = frf.referenceCount();
  ImpulseResponses out;
  out.period = 2 * kTop;
  out.dt = 1.0 / (static_cast<double>(out.period) * df);
  const long half = kTop;
  std::unique_ptr<fftw_complex[], FftwFree> in(
      static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * static_cast<std::size_t>(kTop + 1))));
  std::unique_ptr<double[], FftwFree> time(
      static_cast<double*>(fftw_malloc(sizeof(double) * static_cast<std::size_t>(out.period))));
  // Planned under RealFft's planner lock (FFTW's planner is not thread-safe).
  fftw_plan plan = signal::withFftwPlanner(
      [&] { return fftw_plan_dft_c2r_1d(static_cast<int>(out.period), in.get(), time.get(), FFTW_ESTIMATE); });
  out.h.resize(half, no * ni);
  for (Eigen::Index a = 0; a < ni; ++a) {
    for (Eigen::Index o = 0; o < no; ++o) {
      for (long k = 0; k <= kTop; ++k) {
        const Complex v = k < k0 ? Complex(0.0, 0.0) : frf.h[static_cast<std::size_t>(a)](k - k0, o);
        in[k][0] = v.real();
        in[k][1] = v.imag();
      }
      fftw_execute_dft_c2r(plan, in.get(), time.get());
      out.h.col(o * ni + a) = Eigen::Map<const Vector>(time.get(), half);
    }
  }
  signal::withFftwPlanner([&] { fftw_destroy_plan(plan); });
  return out;
}

// Fit window length from `first`: up to where the block-averaged energy of
// the responses falls below three times the noise floor (median block energy
// of the second quarter of the period), at least `minimum`.
Eigen::Index autoWindow(const Matrix& h, Eigen::Index first, Eigen::Index minimum) {
  const Eigen::Index n = h.rows();
  const Eigen::Index block = std::max<Eigen::Index>(16, n / 512);
  std::vector<double> energy;
  for (Eigen::Index b = 0; (b + 1) * block <= n; ++b) energy.push_back(h.middleRows(b * block, block).squaredNorm());
  const auto nb = static_cast<Eigen::Index>(energy.size());
  if (nb < 4) return n - first;
  std::vector<double> tail(energy.begin() + nb / 2, energy.end());
  std::nth_element(tail.begin(), tail.begin() + static_cast<std::ptrdiff_t>(tail.size() / 2), tail.end());
  const double floor = tail[tail.size() / 2];
  Eigen::Index end = n;
  for (Eigen::Index b = first / block + 1; b < nb; ++b) {
    if (energy[static_cast<std::size_t>(b)] < 3.0 * floor) {
      end = b * block;
      break;
    }
  }
  return std::min(n - first, std::max(end - first, minimum));
}

// The estimator on the FRFs as given (stabilizationOnFewerReferences picks the orientation).
Result<StabilizationDiagram> lsceStabilizationAsGiven(const FrfMatrix& frf, const LsceOptions& opt) {
  const std::string where = "LSCE";
  if (auto ok = frf.validate(); !ok) return ok.error();
  auto orderList = stabilizationOrders(opt, where);
  if (!orderList) return orderList.error();
  const std::vector<int>& orders = *orderList;
  auto irf = impulseResponses(frf, opt, where);
  if (!irf) return irf.error();
  const Eigen::Index no = frf.responseCount(), ni = frf.referenceCount();
  const Eigen::Index pmax = orders.back();
  const Eigen::Index half = irf->h.rows();
  const Eigen::Index s0 = opt.firstSample;
  // At least pmax + max(pmax, 2 pmax ni / no) samples: every lag available and
  // twice as many equations as unknowns.
  const Eigen::Index need = pmax + std::max<Eigen::Index>(pmax, (2 * pmax * ni + no - 1) / no);
  if (s0 < 0 || opt.sampleCount < 0 || half - s0 < need) {
    return makeError(ErrorCode::InvalidArgument,
                     "band up to " + hz(opt.bandHighHz) + " gives " + std::to_string(half) +
                         " causal impulse-response samples; order " + std::to_string(pmax) + " from sample " +
                         std::to_string(s0) + " needs at least " + std::to_string(s0 + need) +
                         " (finer frequency spacing or a lower order)",
                     where + ", samples");
  }
  const Eigen::Index ns = opt.sampleCount > 0 ? std::clamp<Eigen::Index>(opt.sampleCount, need, half - s0)
                                              : autoWindow(irf->h, s0, std::min(half - s0, 4 * need));
  const Matrix& h = irf->h;
  const double rms = h.middleRows(s0, ns).norm() / std::sqrt(static_cast<double>(ns * no * ni));
  if (!(rms > 0.0)) return makeError(ErrorCode::InvalidArgument, "impulse responses are zero", where);

  // Gram blocks C(i, j) = sum_o sum_{k=kb}^{ke} h_o(k - i)^T h_o(k - j), lags
  // 0 (target) .. pmax. First block row directly, the rest by the shift
  // recursion C(i+1, j+1) = C(i, j) + h(kb-1-i)^T h(kb-1-j) - h(ke-i)^T h(ke-j).
  const Eigen::Index kb = s0 + pmax, ke = s0 + ns - 1, nk = ke - kb + 1;
  const Eigen::Index nl = pmax + 1, dim = nl * ni;
  Matrix gram(dim, dim);
  auto col = [&](Eigen::Index o, Eigen::Index a) { return h.col(o * ni + a); };
  for (Eigen::Index j = 0; j < nl; ++j) {
    for (Eigen::Index a = 0; a < ni; ++a) {
      for (Eigen::Index b = 0; b < ni; ++b) {
        double acc = 0.0;
        for (Eigen::Index o = 0; o < no; ++o) acc += col(o, a).segment(kb, nk).dot(col(o, b).segment(kb - j, nk));
        gram(a, j * ni + b) = acc;
        gram(j * ni + b, a) = acc;
      }
    }
  }
  for (Eigen::Index i = 0; i + 1 < nl; ++i) {
    for (Eigen::Index j = i; j + 1 < nl; ++j) {
      for (Eigen::Index a = 0; a < ni; ++a) {
        for (Eigen::Index b = 0; b < ni; ++b) {
          double acc = gram(i * ni + a, j * ni + b);
          for (Eigen::Index o = 0; o < no; ++o) {
            acc += col(o, a)[kb - 1 - i] * col(o, b)[kb - 1 - j] - col(o, a)[ke - i] * col(o, b)[ke - j];
          }
          gram((i + 1) * ni + a, (j + 1) * ni + b) = acc;
          gram((j + 1) * ni + b, (i + 1) * ni + a) = acc;
        }
      }
    }
  }
  gram /= rms * rms;

  // Regressors: lags 1..pmax (leading blocks nest by order); target: lag 0.
  const Eigen::Index nx = pmax * ni;
  Matrix gxx = gram.bottomRightCorner(nx, nx);
  // Beyond the signal subspace the Gram matrix is singular up to the noise;
  // a ridge of 1e-10 of its diagonal keeps the Cholesky factor defined.
  gxx.diagonal().array() += 1e-10 * gxx.diagonal().mean();
  Eigen::LLT<Matrix> llt(gxx);
  if (llt.info() != Eigen::Success) {
    return makeError(ErrorCode::NumericalFailure, "normal equations of the AR model are not positive definite", where);
  }
  const Matrix lmat = llt.matrixL();
  Matrix c = gram.bottomLeftCorner(nx, ni);
  lmat.triangularView<Eigen::Lower>().solveInPlace(c);  // L^-1 Gxy, nested in the order

  StabilizationDiagram diag;
  diag.orders = orders;
  diag.bandLowHz = opt.bandLowHz;
  diag.bandHighHz = opt.bandHighHz;
  diag.samplingTime = irf->dt;
  diag.resolutionHz = frequencyResolutionHz(frf.frequencyHz, opt.bandLowHz, opt.bandHighHz);
  std::vector<StabilizationPole> previous;
  MatrixPolynomialRoots roots;
  Matrix theta, alpha;
  std::vector<Matrix> numer(static_cast<std::size_t>(no));  // Prony numerators n_k (p x ni) per output
  for (const int p : orders) {
    const std::string at = where + ", order " + std::to_string(p);
    if (opt.orderProgress && !opt.orderProgress(p)) return makeError(ErrorCode::Cancelled, "cancelled", at);
    const Eigen::Index pb = p * ni;
    theta = lmat.topLeftCorner(pb, pb).transpose().triangularView<Eigen::Upper>().solve(c.topRows(pb));
    if (!theta.allFinite()) return makeError(ErrorCode::NumericalFailure, "AR coefficients are not finite", at);
    // A(z) = z^p I - sum_j z^{p-j} theta_j: block q (q < p) is -theta_{p-q}.
    alpha.resize(pb + ni, ni);
    for (Eigen::Index q = 0; q < p; ++q) alpha.middleRows(q * ni, ni) = -theta.middleRows((p - 1 - q) * ni, ni);
    alpha.bottomRows(ni).setIdentity();
    auto zr = roots.solve(alpha, ni, at);
    if (!zr) return zr.error();
    // Prony numerator of g(k) = h(s0 + k): n_k = g(k) - sum_{i=1}^{k} g(k - i) theta_i, k < p;
    // near the pole the z-transform of g is N(1/z_r) v_r u_r^T / (...), so
    // N_o(1/z_r) v_r is the shape up to a factor common to all outputs.
    for (Eigen::Index o = 0; o < no; ++o) {
      Matrix& nm = numer[static_cast<std::size_t>(o)];
      nm.resize(p, ni);
      for (Eigen::Index k = 0; k < p; ++k) {
        for (Eigen::Index a = 0; a < ni; ++a) nm(k, a) = col(o, a)[s0 + k];
        for (Eigen::Index i = 1; i <= k; ++i) {
          for (Eigen::Index a = 0; a < ni; ++a) {
            double g = col(o, a)[s0 + k - i];
            for (Eigen::Index b = 0; b < ni; ++b) nm(k, b) -= g * theta((i - 1) * ni + a, b);
          }
        }
      }
    }
    auto shape = [&](Complex z, const ComplexVector& v) {
      const Complex w = 1.0 / z;
      ComplexVector s(no);
      for (Eigen::Index o = 0; o < no; ++o) {
        const Matrix& nm = numer[static_cast<std::size_t>(o)];
        Complex acc(0.0, 0.0);
        for (Eigen::Index a = 0; a < ni; ++a) {
          Complex horner(0.0, 0.0);
          for (Eigen::Index k = p - 1; k >= 0; --k) horner = horner * w + nm(k, a);
          acc += horner * v[a];
        }
        s[o] = acc;
      }
      return s;
    };
    appendOrderPoles(p, alpha, ni, *zr, irf->dt, shape, opt, previous, diag);
  }
  return diag;
}

}  // namespace

Result<StabilizationDiagram> lsceStabilization(const FrfMatrix& frf, const LsceOptions& opt) {
  return stabilizationOnFewerReferences(
      frf, [&](const FrfMatrix& oriented) { return lsceStabilizationAsGiven(oriented, opt); });
}

Result<PlscfResult> identifyLsce(const FrfMatrix& frf, const LsceOptions& options) {
  auto diagram = lsceStabilization(frf, options);
  if (!diagram) return diagram.error();
  return modalModelFromDiagram(frf, std::move(diagram).value(), options);
}

}  // namespace mozzi::core::modal
