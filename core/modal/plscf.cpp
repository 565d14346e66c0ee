#include "core/modal/plscf.h"

#include <fftw3.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <string>
#include <utility>

#include "core/io/output_file.h"
#include "core/modal/lsfd.h"
#include "core/modal/mode_merging.h"
#include "core/modal/shape_tools.h"
#include "core/modal/stabilization.h"
#include "core/signal/fft.h"

namespace mozzi::core::modal {

namespace {

constexpr double kTwoPi = 2.0 * M_PI;

std::string hz(double f) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g Hz", f);
  return buf;
}

// Smallest N >= n whose prime factors are 2, 3, 5 and 7 (fast FFT sizes).
long niceFftSize(long n) {
  for (long m = std::max(1L, n);; ++m) {
    long r = m;
    for (long p : {2L, 3L, 5L, 7L}) {
      while (r % p == 0) r /= p;
    }
    if (r == 1) return m;
  }
}

struct FftwFree {
  void operator()(fftw_complex* p) const { fftw_free(p); }
};

// The series of the lag sums, without a copy of the data (the band of 100
// FRFs x 20,000 lines is 14 MB): column 0 is 1, column 1 + o ni + a is
// H_oa / rms read from the FRF matrix, the last ni^2 columns are
// sum_o conj(H_oa) H_ob / rms^2 (computed here, nf x ni^2).
class Series {
  using Column = Eigen::VectorBlock<const ComplexMatrix::ConstColXpr>;
  Column data(Eigen::Index a, Eigen::Index o) const {
    return frf_.h[static_cast<std::size_t>(a)].col(o).segment(k0_, nf_);
  }

 public:
  Series(const FrfMatrix& frf, Eigen::Index k0, Eigen::Index nf, double rms)
      : frf_(frf), k0_(k0), nf_(nf), no_(frf.responseCount()), ni_(frf.referenceCount()), rms_(rms) {
    cross_.resize(nf, ni_ * ni_);
    for (Eigen::Index a = 0; a < ni_; ++a) {
      for (Eigen::Index b = 0; b < ni_; ++b) {
        auto acc = cross_.col(a * ni_ + b);
        acc.setZero();
        for (Eigen::Index o = 0; o < no_; ++o) {
          acc += (data(a, o).conjugate().array() * data(b, o).array()).matrix();
        }
        acc /= rms * rms;
      }
    }
  }
  Eigen::Index rows() const { return nf_; }
  Eigen::Index cols() const { return 1 + no_ * ni_ + ni_ * ni_; }
  // Column s as (first value, scale): nullptr for the column of ones.
  std::pair<const Complex*, double> column(Eigen::Index s) const {
    if (s == 0) return {nullptr, 1.0};
    if (s <= no_ * ni_) return {data((s - 1) % ni_, (s - 1) / ni_).data(), 1.0 / rms_};
    return {cross_.col(s - 1 - no_ * ni_).data(), 1.0};
  }

 private:
  const FrfMatrix& frf_;
  Eigen::Index k0_, nf_, no_, ni_;
  double rms_;
  ComplexMatrix cross_;
};

// Lag sums sum_k z_k^d x_k(k) for d = -n..n of several series x (columns of
// `series`, nf x ns), z_k = exp(i 2 pi f_k dt). Returns (2n+1) x ns, row d + n.
// On an even grid f_k = f_0 + k df with dt = 1/(N df), one inverse FFT per
// series gives every lag at once (O(N log N) instead of O(nf n)). Otherwise a
// direct sum.
ComplexMatrix lagSums(const Series& series, const Vector& f, double dt, long fftSize, bool evenGrid, int n) {
  const Eigen::Index nf = series.rows(), ns = series.cols();
  ComplexMatrix out(2 * n + 1, ns);
  if (evenGrid) {
    const long N = fftSize;
    // Chunks of series through one plan: a 16 N buffer instead of ns N (200 MB
    // for 100 outputs x 3 references, whose page faults cost more than the FFTs).
    const Eigen::Index chunk = std::min<Eigen::Index>(ns, 16);
    std::unique_ptr<fftw_complex[], FftwFree> buf(
        static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * static_cast<std::size_t>(N * chunk))));
    int sizes[1] = {static_cast<int>(N)};
    // Planned under RealFft's planner lock (FFTW's planner is not thread-safe).
    fftw_plan plan = signal::withFftwPlanner([&] {
      return fftw_plan_many_dft(1, sizes, static_cast<int>(chunk), buf.get(), nullptr, 1, static_cast<int>(N),
                                buf.get(), nullptr, 1, static_cast<int>(N), FFTW_BACKWARD, FFTW_ESTIMATE);
    });
    for (Eigen::Index s0 = 0; s0 < ns; s0 += chunk) {
      const Eigen::Index cs = std::min(chunk, ns - s0);
      for (Eigen::Index c = 0; c < chunk; ++c) {
        fftw_complex* col = buf.get() + c * N;
        const Eigen::Index filled = c < cs ? nf : 0;
        if (filled > 0) {
          const auto [x, scale] = series.column(s0 + c);
          for (Eigen::Index k = 0; k < filled; ++k) {
            col[k][0] = x ? scale * x[k].real() : 1.0;
            col[k][1] = x ? scale * x[k].imag() : 0.0;
          }
        }
        std::fill(reinterpret_cast<double*>(col + filled), reinterpret_cast<double*>(col + N), 0.0);
      }
      fftw_execute(plan);
      // Backward FFT: Y[d] = sum_k x_k exp(+i 2 pi k d / N); shift by f_0: exp(i 2 pi f_0 dt d).
      for (int d = -n; d <= n; ++d) {
        const Complex shift = std::polar(1.0, kTwoPi * f[0] * dt * d);
        const long idx = d >= 0 ? d : N + d;
        for (Eigen::Index c = 0; c < cs; ++c) {
          const fftw_complex& y = buf[static_cast<std::size_t>(c * N + idx)];
          out(d + n, s0 + c) = shift * Complex(y[0], y[1]);
        }
      }
    }
    signal::withFftwPlanner([&] { fftw_destroy_plan(plan); });
    return out;
  }
  out.setZero();
  ComplexVector row(ns);
  for (Eigen::Index k = 0; k < nf; ++k) {
    for (Eigen::Index s = 0; s < ns; ++s) {
      const auto [x, scale] = series.column(s);
      row[s] = x ? scale * x[k] : Complex(1.0, 0.0);
    }
    const Complex z = std::polar(1.0, kTwoPi * f[k] * dt);
    Complex zp(1.0, 0.0);  // z^d for d >= 0
    for (int d = 0; d <= n; ++d) {
      out.row(d + n) += zp * row.transpose();
      if (d > 0) out.row(n - d) += std::conj(zp) * row.transpose();
      zp *= z;
    }
  }
  return out;
}

}  // namespace

int plscfOrderLimit(const FrfMatrix& frf, double bandLowHz, double bandHighHz) {
  Eigen::Index nf = 0;
  for (Eigen::Index k = 0; k < frf.lineCount(); ++k)
    if (frf.frequencyHz[k] >= bandLowHz && frf.frequencyHz[k] <= bandHighHz) ++nf;
  return static_cast<int>(nf / 2 - 1);
}

char poleStatusSymbol(PoleStatus status) {
  switch (status) {
    case PoleStatus::New: return 'o';
    case PoleStatus::Frequency: return 'f';
    case PoleStatus::FrequencyDamping: return 'd';
    case PoleStatus::FrequencyVector: return 'v';
    case PoleStatus::Stable: return 's';
  }
  return '?';
}

namespace {

// The estimator on the FRFs as given (stabilizationOnFewerReferences picks the orientation).
Result<StabilizationDiagram> plscfStabilizationAsGiven(const FrfMatrix& frf, const PlscfOptions& opt) {
  const std::string where = "pLSCF";
  if (auto ok = frf.validate(); !ok) return ok.error();
  auto orderList = stabilizationOrders(opt, where);
  if (!orderList) return orderList.error();
  const std::vector<int>& orders = *orderList;
  const Eigen::Index nfAll = frf.lineCount();
  Eigen::Index k0 = 0;
  while (k0 < nfAll && frf.frequencyHz[k0] < opt.bandLowHz) ++k0;
  Eigen::Index k1 = k0;
  while (k1 < nfAll && frf.frequencyHz[k1] <= opt.bandHighHz) ++k1;
  const Eigen::Index nf = k1 - k0;
  const int n = orders.back();
  if (n > plscfOrderLimit(frf, opt.bandLowHz, opt.bandHighHz)) {
    return makeError(ErrorCode::InvalidArgument,
                     "band " + hz(opt.bandLowHz) + " .. " + hz(opt.bandHighHz) + " holds " + std::to_string(nf) +
                         " lines; order " + std::to_string(n) + " needs at least " + std::to_string(2 * (n + 1)),
                     where + ", band");
  }
  const Eigen::Index no = frf.responseCount(), ni = frf.referenceCount();
  const Vector f = frf.frequencyHz.segment(k0, nf);

  // Scale the data to unit RMS so the normal equations are well scaled.
  double ss = 0.0;
  for (Eigen::Index i = 0; i < ni; ++i) ss += frf.h[static_cast<std::size_t>(i)].middleRows(k0, nf).squaredNorm();
  const double rms = std::sqrt(ss / static_cast<double>(nf * no * ni));
  if (!(rms > 0.0)) return makeError(ErrorCode::InvalidArgument, "FRFs are zero in the band", where);

  // Grid: even spacing allows the FFT lag sums; dt = 1/(N df) <= 1/(2 f_high).
  const double df = (f[nf - 1] - f[0]) / static_cast<double>(nf - 1);
  bool even = true;
  for (Eigen::Index k = 0; k < nf && even; ++k) even = std::abs(f[k] - (f[0] + df * k)) <= 1e-6 * df;
  long fftSize = 0;
  double dt = 1.0 / (2.0 * f[nf - 1]);
  if (even) {
    fftSize = niceFftSize(
        std::max<long>({static_cast<long>(std::ceil(2.0 * f[nf - 1] / df)) + 1, static_cast<long>(nf), 2L * n + 2}));
    dt = 1.0 / (static_cast<double>(fftSize) * df);
  }

  // Series: [1 | H_oa (o major) | sum_o conj(H_oa) H_ob], read from the FRFs.
  const Series series(frf, k0, nf, rms);
  const ComplexMatrix lags = lagSums(series, f, dt, fftSize, even, n);
  auto lag = [&](int d, Eigen::Index s) { return lags(d + n, s); };

  // Toeplitz blocks (lag l - j): R(j,l) = Re r, S_o(j, l ni + a) = -Re s_oa, T = Re t_ab.
  const Eigen::Index n1 = n + 1, nb = n1 * ni;
  Matrix rmat(n1, n1);
  for (Eigen::Index j = 0; j < n1; ++j)
    for (Eigen::Index l = 0; l < n1; ++l) rmat(j, l) = lag(static_cast<int>(l - j), 0).real();
  Matrix tmat(nb, nb);
  for (Eigen::Index j = 0; j < n1; ++j)
    for (Eigen::Index l = 0; l < n1; ++l)
      for (Eigen::Index a = 0; a < ni; ++a)
        for (Eigen::Index b = 0; b < ni; ++b)
          tmat(j * ni + a, l * ni + b) = lag(static_cast<int>(l - j), 1 + no * ni + a * ni + b).real();
  // S^T stacked over outputs: st(o nb + l ni + a, j) = S_o(j, l ni + a).
  Matrix st(no * nb, n1);
  for (Eigen::Index o = 0; o < no; ++o)
    for (Eigen::Index l = 0; l < n1; ++l)
      for (Eigen::Index a = 0; a < ni; ++a)
        for (Eigen::Index j = 0; j < n1; ++j)
          st(o * nb + l * ni + a, j) = -lag(static_cast<int>(l - j), 1 + o * ni + a).real();

  // R is the Gram matrix of the numerator basis; for a narrow band far from
  // 0 Hz it is numerically singular (the basis is redundant). A ridge of
  // 1e-10 of its diagonal keeps the Cholesky defined and changes the
  // well-conditioned cases only at rounding level.
  rmat.diagonal().array() += 1e-10 * rmat.diagonal().mean();
  Eigen::LLT<Matrix> rllt(rmat);
  if (rllt.info() != Eigen::Success) {
    return makeError(ErrorCode::NumericalFailure, "basis matrix R is not positive definite (too few lines?)", where);
  }
  const Matrix lmat = rllt.matrixL();
  // W^T = S^T L^-T (W_o = L^-1 S_o); column j is row j of every W_o.
  Matrix wt = st;
  lmat.transpose().triangularView<Eigen::Upper>().solveInPlace<Eigen::OnTheRight>(wt);

  StabilizationDiagram diag;
  diag.orders = orders;
  diag.bandLowHz = opt.bandLowHz;
  diag.bandHighHz = opt.bandHighHz;
  diag.samplingTime = dt;
  diag.resolutionHz = frequencyResolutionHz(frf.frequencyHz, opt.bandLowHz, opt.bandHighHz);

  Matrix g = Matrix::Zero(nb, nb);  // running sum_{j<=m} sum_o w_oj^T w_oj (lower triangle)
  std::size_t nextOrder = 0;
  std::vector<StabilizationPole> previous;
  MatrixPolynomialRoots roots;
  Matrix alpha, beta;
  ComplexVector zpow;
  for (Eigen::Index j = 0; j < n1 && nextOrder < orders.size(); ++j) {
    Eigen::Map<const Matrix> wj(wt.col(j).data(), nb, no);  // wj(c, o) = W_o(j, c)
    g.selfadjointView<Eigen::Lower>().rankUpdate(wj);
    const int m = static_cast<int>(j);
    if (m != orders[nextOrder]) continue;
    ++nextOrder;
    const std::string at = where + ", order " + std::to_string(m);
    if (opt.orderProgress && !opt.orderProgress(m)) return makeError(ErrorCode::Cancelled, "cancelled", at);
    const Eigen::Index mb = static_cast<Eigen::Index>(m) * ni, mb1 = mb + ni;
    // M_m = T_m - G_m (leading (m+1) ni block), symmetric.
    Matrix mm = tmat.topLeftCorner(mb1, mb1);
    mm.triangularView<Eigen::Lower>() -= g.topLeftCorner(mb1, mb1);
    mm = mm.selfadjointView<Eigen::Lower>();
    Eigen::LDLT<Matrix> ldlt(mm.topLeftCorner(mb, mb));
    if (ldlt.info() != Eigen::Success) {
      return makeError(ErrorCode::NumericalFailure, "reduced normal equations are singular", at);
    }
    alpha.resize(mb1, ni);  // [alpha_0; ...; alpha_{m-1}; I]
    alpha.topRows(mb) = -ldlt.solve(mm.topRightCorner(mb, ni));
    alpha.bottomRows(ni).setIdentity();
    if (!alpha.allFinite()) {
      return makeError(ErrorCode::NumericalFailure, "denominator coefficients are not finite", at);
    }
    auto zr = roots.solve(alpha, ni, at);
    if (!zr) return zr.error();
    // Numerator per output: beta_o = -R_m^-1 S_o,m alpha = -L_m^-T (W_o,m alpha).
    beta.resize(m + 1, no * ni);
    for (Eigen::Index o = 0; o < no; ++o) {
      beta.middleCols(o * ni, ni) = wt.block(o * nb, 0, mb1, m + 1).transpose() * alpha;
    }
    lmat.topLeftCorner(m + 1, m + 1).transpose().triangularView<Eigen::Upper>().solveInPlace(beta);
    beta = -beta;
    // Shape_o = B_o(z) v = sum_q z^q beta_oq v.
    auto shape = [&](Complex z, const ComplexVector& v) {
      zpow.resize(m + 1);
      zpow[0] = 1.0;
      for (int q = 1; q <= m; ++q) zpow[q] = zpow[q - 1] * z;
      const Vector re = beta.transpose() * zpow.real(), im = beta.transpose() * zpow.imag();  // (o a)
      ComplexVector s(no);
      for (Eigen::Index o = 0; o < no; ++o) {
        Complex acc(0.0, 0.0);
        for (Eigen::Index a = 0; a < ni; ++a) acc += Complex(re[o * ni + a], im[o * ni + a]) * v[a];
        s[o] = acc;
      }
      return s;
    };
    appendOrderPoles(m, alpha, ni, *zr, dt, shape, opt, previous, diag);
  }
  return diag;
}

}  // namespace

Result<StabilizationDiagram> plscfStabilization(const FrfMatrix& frf, const PlscfOptions& opt) {
  return stabilizationOnFewerReferences(
      frf, [&](const FrfMatrix& oriented) { return plscfStabilizationAsGiven(oriented, opt); });
}

Result<std::vector<SelectedPole>> selectPoles(const StabilizationDiagram& diagram, const PlscfOptions& opt) {
  struct Cluster {
    std::vector<const StabilizationPole*> members;
    double meanHz = 0.0;
    const StabilizationPole* seed = nullptr;
  };
  std::vector<const StabilizationPole*> stable;
  for (const auto& p : diagram.poles) {
    if (p.status == PoleStatus::Stable) stable.push_back(&p);
  }
  std::sort(stable.begin(), stable.end(), [](auto* a, auto* b) { return a->frequencyHz < b->frequencyHz; });
  std::vector<Cluster> clusters;
  for (const auto* p : stable) {
    Cluster* best = nullptr;
    for (auto& c : clusters) {
      if (std::abs(p->frequencyHz - c.meanHz) > opt.clusterFrequencyTolerance * c.meanHz) continue;
      const double vmac = opt.criteria.vector == StabilityVector::Participation
                              ? mac(p->participation, c.seed->participation)
                              : mac(p->shape, c.seed->shape);
      if (vmac < opt.criteria.macThreshold) continue;
      if (!best || std::abs(p->frequencyHz - c.meanHz) < std::abs(p->frequencyHz - best->meanHz)) best = &c;
    }
    if (!best) {
      clusters.push_back(Cluster{{p}, p->frequencyHz, p});
    } else {
      best->members.push_back(p);
      best->meanHz += (p->frequencyHz - best->meanHz) / static_cast<double>(best->members.size());
    }
  }
  const int needed =
      std::max(opt.minClusterSize,
               static_cast<int>(std::ceil(opt.minClusterFraction * static_cast<double>(diagram.orders.size()))));
  std::vector<SelectedPole> out;
  for (auto& c : clusters) {
    // One pole per order: the one nearest the cluster mean.
    std::sort(c.members.begin(), c.members.end(), [&](auto* a, auto* b) {
      if (a->order != b->order) return a->order < b->order;
      return std::abs(a->frequencyHz - c.meanHz) < std::abs(b->frequencyHz - c.meanHz);
    });
    c.members.erase(
        std::unique(c.members.begin(), c.members.end(), [](auto* a, auto* b) { return a->order == b->order; }),
        c.members.end());
    if (static_cast<int>(c.members.size()) < needed) continue;
    // Representative: medians over the upper half of the cluster's orders (low
    // orders carry the bias of an under-parameterised model).
    std::vector<double> fs, zs;
    for (std::size_t q = c.members.size() / 2; q < c.members.size(); ++q) {
      const auto* p = c.members[q];
      fs.push_back(p->frequencyHz);
      zs.push_back(p->zeta);
    }
    auto median = [](std::vector<double> v) {
      std::sort(v.begin(), v.end());
      const std::size_t h = v.size() / 2;
      return v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
    };
    auto stdev = [](const std::vector<double>& v) {
      double mu = 0.0, s2 = 0.0;
      for (double x : v) mu += x;
      mu /= static_cast<double>(v.size());
      for (double x : v) s2 += (x - mu) * (x - mu);
      return std::sqrt(s2 / static_cast<double>(std::max<std::size_t>(1, v.size() - 1)));
    };
    SelectedPole s;
    s.pole = poleFromFrequencyDamping(median(fs), median(zs));
    s.participation = c.members.back()->participation;
    s.clusterSize = static_cast<int>(c.members.size());
    s.frequencySpreadHz = stdev(fs);  // over the upper half used for the estimate
    s.zetaSpread = stdev(zs);
    s.shape = c.members.back()->shape;
    out.push_back(std::move(s));
  }
  std::sort(out.begin(), out.end(),
            [](const SelectedPole& a, const SelectedPole& b) { return std::abs(a.pole) < std::abs(b.pole); });
  mergeSameModes(out, opt, diagram.resolutionHz);
  if (out.empty()) {
    return makeError(ErrorCode::NotFound,
                     "no stable mode in band " + hz(diagram.bandLowHz) + " .. " + hz(diagram.bandHighHz) +
                         ": no pole "
                         "stayed stable (frequency, damping and vector) over " +
                         std::to_string(needed) + " orders; the band holds no identifiable mode or the FRFs are noise",
                     "automatic pole selection");
  }
  return out;
}

Result<PlscfResult> modalModelFromDiagram(const FrfMatrix& frf, StabilizationDiagram diagram,
                                          const PlscfOptions& options) {
  auto selected = selectPoles(diagram, options);
  if (!selected) return selected.error();
  std::vector<Complex> poles;
  for (const auto& s : *selected) poles.push_back(s.pole);
  LsfdOptions lo;
  lo.bandLowHz = options.bandLowHz;
  lo.bandHighHz = options.bandHighHz;
  auto model = lsfd(frf, poles, lo);
  if (!model) return model.error();
  for (std::size_t r = 0; r < poles.size(); ++r) model->modes[r].participation = (*selected)[r].participation;
  PlscfResult out;
  out.diagram = std::move(diagram);
  out.selected = std::move(selected).value();
  out.model = std::move(model).value();
  return out;
}

Result<PlscfResult> identifyPlscf(const FrfMatrix& frf, const PlscfOptions& options) {
  auto diagram = plscfStabilization(frf, options);
  if (!diagram) return diagram.error();
  return modalModelFromDiagram(frf, std::move(diagram).value(), options);
}

Result<void> writeStabilizationCsv(const StabilizationDiagram& diagram, const std::string& path) {
  // Through the output helper: temporary file, checked flush + fsync + close, rename.
  return io::writeOutputFile(path, [&](std::ostream& os) -> Result<void> {
    os << "order,frequency_hz,zeta,status\n";
    char buf[128];
    for (const auto& p : diagram.poles) {
      std::snprintf(buf, sizeof buf, "%d,%.9g,%.9g,%c\n", p.order, p.frequencyHz, p.zeta, poleStatusSymbol(p.status));
      os << buf;
    }
    return {};
  });
}

}  // namespace mozzi::core::modal
