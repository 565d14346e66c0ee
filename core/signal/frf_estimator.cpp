#include "core/signal/frf_estimator.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <string>

#include <Eigen/Eigenvalues>

#include "core/common/enum_names.h"
#include "core/common/text.h"

namespace mozzi::core::signal {

namespace {
constexpr auto kEstimatorNames =
    enumTable<FrfEstimator>({{FrfEstimator::H1, "H1"}, {FrfEstimator::H2, "H2"}, {FrfEstimator::Hv, "Hv"}}, "H1");
}  // namespace

const char* frfEstimatorName(FrfEstimator estimator) {
  return kEstimatorNames.of(estimator);
}

Result<FrfEstimator> parseFrfEstimator(std::string_view text) {
  return parseEnum(kEstimatorNames, text, "FRF estimator", "estimator", NameCase::Ignore);
}

FrfOptions FrfOptions::hammer(FrfEstimator estimator, std::optional<double> forceWidthS, double forceTaperS,
                              std::optional<double> exponentialTauS) {
  FrfOptions o;
  o.estimator = estimator;
  const double tau = exponentialTauS.value_or(0.0);
  if (forceWidthS) {
    o.referenceWindow.kind = WindowKind::Force;
    o.referenceWindow.forceWidthS = *forceWidthS;
    o.referenceWindow.forceTaperS = forceTaperS;
  }
  o.referenceWindow.exponentialTauS = tau;
  if (exponentialTauS) {
    o.responseWindow.kind = WindowKind::Exponential;
    o.responseWindow.exponentialTauS = tau;
  }
  return o;
}

double FrfOptions::exponentialTauS() const {
  return responseWindow.exponentialTauS > 0.0 ? responseWindow.exponentialTauS : 0.0;
}

namespace {
std::string channelWhere(const TimeRecord& r, Eigen::Index c) {
  const auto& ch = r.channels[static_cast<std::size_t>(c)];
  return "channel " + std::to_string(c) + (ch.name.empty() ? std::string() : " '" + ch.name + "'") + " (" +
         formatDof(ch.dof) + ")";
}

bool isRectangular(const WindowSpec& w) {
  return w.kind == WindowKind::Rectangular && w.exponentialTauS == 0.0;
}
}  // namespace

Result<FrfType> responseFrfType(const TimeRecord& record, Eigen::Index referenceChannel) {
  return responseFrfType(record, std::vector<Eigen::Index>{referenceChannel});
}

Result<FrfType> responseFrfType(const TimeRecord& record, const std::vector<Eigen::Index>& referenceChannels) {
  std::optional<FrfType> type;
  for (Eigen::Index c = 0; c < record.channelCount(); ++c) {
    if (std::find(referenceChannels.begin(), referenceChannels.end(), c) != referenceChannels.end()) continue;
    FrfType t;
    switch (record.channels[static_cast<std::size_t>(c)].transducer.kind) {
      case TransducerKind::Acceleration: t = FrfType::Accelerance; break;
      case TransducerKind::Velocity: t = FrfType::Mobility; break;
      case TransducerKind::Displacement: t = FrfType::Receptance; break;
      default:
        return makeError(ErrorCode::Unsupported,
                         std::string("response transducer of kind '") +
                             transducerKindName(record.channels[static_cast<std::size_t>(c)].transducer.kind) +
                             "' has no FRF type (use acceleration, velocity or displacement)",
                         channelWhere(record, c));
    }
    if (type && *type != t) {
      return makeError(ErrorCode::Unsupported, "responses of different kinds cannot share one FRF matrix",
                       channelWhere(record, c));
    }
    type = t;
  }
  if (!type) return makeError(ErrorCode::InvalidArgument, "record has no response channel", "time record");
  return *type;
}

namespace {
// The references of `options` for `layout`, checked: in range, no repeats.
Result<std::vector<Eigen::Index>> pickReferences(const TimeRecord& layout, const FrfOptions& options) {
  std::vector<Eigen::Index> refs = options.referenceChannels;
  if (refs.empty() && options.referenceChannel) refs.push_back(*options.referenceChannel);
  if (refs.empty()) {
    for (Eigen::Index c = 0; c < layout.channelCount(); ++c) {
      if (layout.channels[static_cast<std::size_t>(c)].transducer.kind == TransducerKind::Force) refs.push_back(c);
    }
    if (refs.empty()) return findForceChannel(layout).error();  // its "no force channel" message
  }
  for (std::size_t i = 0; i < refs.size(); ++i) {
    if (refs[i] < 0 || refs[i] >= layout.channelCount()) {
      return makeError(ErrorCode::InvalidArgument,
                       "reference channel " + std::to_string(refs[i]) + " does not exist (record has " +
                           std::to_string(layout.channelCount()) + " channels)",
                       "FRF options");
    }
    if (std::find(refs.begin(), refs.begin() + static_cast<std::ptrdiff_t>(i), refs[i]) !=
        refs.begin() + static_cast<std::ptrdiff_t>(i)) {
      return makeError(ErrorCode::InvalidArgument, "reference channel " + std::to_string(refs[i]) + " is named twice",
                       "FRF options");
    }
  }
  return refs;
}

// The window of `spec`, shared with other averagers of the same layout: the
// last few are kept, since a campaign creates one averager per measurement
// point with the same windows and an exponential window costs an exp() per
// sample (as long as a 65536-sample block's four FFTs).
Result<std::shared_ptr<const Vector>> sharedWindow(const WindowSpec& spec, Eigen::Index n, double fs,
                                                   Eigen::Index origin) {
  struct Entry {
    WindowSpec spec;
    Eigen::Index n, origin;
    double fs;
    std::shared_ptr<const Vector> window;
  };
  constexpr std::size_t kKept = 4;
  static std::mutex mutex;
  static auto* cache = new std::vector<Entry>();  // never destroyed (used until exit)
  const auto same = [&](const Entry& e) {
    return e.n == n && e.origin == origin && e.fs == fs && e.spec.kind == spec.kind &&
           e.spec.forceWidthS == spec.forceWidthS && e.spec.forceTaperS == spec.forceTaperS &&
           e.spec.exponentialTauS == spec.exponentialTauS;
  };
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (auto it = std::find_if(cache->begin(), cache->end(), same); it != cache->end()) return it->window;
  }
  auto w = makeWindow(spec, n, fs, origin);
  if (!w) return w.error();
  auto shared = std::make_shared<const Vector>(std::move(*w));
  std::lock_guard<std::mutex> lock(mutex);
  if (cache->size() == kKept) cache->erase(cache->begin());
  cache->push_back(Entry{spec, n, origin, fs, shared});
  return shared;
}

// Per-thread scratch for add(): one windowed input block and the spectra of
// every channel of a hit. Kept between calls and averagers (it only grows), so
// an averager created per estimate does not page-fault fresh buffers.
struct Workspace {
  AlignedBuffer<double> in;
  AlignedBuffer<std::complex<double>> spectra;
};

Workspace& workspace(Eigen::Index n, std::size_t spectraSize) {
  thread_local Workspace ws;
  if (ws.in.size() < static_cast<std::size_t>(n)) ws.in = AlignedBuffer<double>(static_cast<std::size_t>(n));
  if (ws.spectra.size() < spectraSize) ws.spectra = AlignedBuffer<std::complex<double>>(spectraSize);
  return ws;
}

// Spectrum stride: a whole number of 64-byte lines (FFTW's SIMD alignment for
// every spectrum) plus one, so that the spectra streamed side by side in
// accumulate() do not sit at the same offset modulo 4 KiB (cache-set aliasing).
Eigen::Index spectrumStride(Eigen::Index nf) {
  return (nf + 3) / 4 * 4 + 4;
}

// dst = x (.* w), in cache-sized chunks so that the sum of squares, the
// finiteness and zero-force check, reads the chunk back from L1. Returns
// sum dst^2: finite exactly when every sample is (NaN and inf propagate, and a
// finite sum of squares bounds every spectral product of the block).
double windowInto(const double* x, const double* w, double* dst, Eigen::Index n) {
  constexpr Eigen::Index kChunk = 2048;
  double sumSq = 0.0;
  for (Eigen::Index i0 = 0; i0 < n; i0 += kChunk) {
    const Eigen::Index len = std::min(kChunk, n - i0);
    Eigen::Map<Vector> d(dst + i0, len);
    if (w != nullptr) {
      d = Eigen::Map<const Vector>(x + i0, len).cwiseProduct(Eigen::Map<const Vector>(w + i0, len));
    } else {
      std::memcpy(dst + i0, x + i0, sizeof(double) * static_cast<std::size_t>(len));  // libc's widest copy
    }
    sumSq += d.squaredNorm();
  }
  return sumSq;
}

// acc_k += |s_k|^2 and acc_k += conj(a_k) b_k on interleaved (re, im) data:
// plain loops the compiler vectorises (std::complex operators would go through
// the NaN-recovering __muldc3 without -ffast-math; inputs are finite here).
// The first hit assigns instead (Add = false): the accumulators are neither
// zeroed beforehand nor read back, one pass less over megabytes per estimate.
template <bool Add>
void addAbs2(const double* __restrict s, double* __restrict acc, Eigen::Index len) {
  for (Eigen::Index k = 0; k < len; ++k) {
    const double v = s[2 * k] * s[2 * k] + s[2 * k + 1] * s[2 * k + 1];
    acc[k] = Add ? acc[k] + v : v;
  }
}

template <bool Add>
void addConjProduct(const double* __restrict a, const double* __restrict b, double* __restrict acc, Eigen::Index len) {
  for (Eigen::Index k = 0; k < len; ++k) {
    const double ar = a[2 * k], ai = a[2 * k + 1], br = b[2 * k], bi = b[2 * k + 1];
    const double re = ar * br + ai * bi, im = ar * bi - ai * br;
    acc[2 * k] = Add ? acc[2 * k] + re : re;
    acc[2 * k + 1] = Add ? acc[2 * k + 1] + im : im;
  }
}
}  // namespace

Result<SpectralAverager> SpectralAverager::create(const TimeRecord& layout, const FrfOptions& options) {
  if (auto ok = layout.validate(); !ok) return ok.error();
  SpectralAverager a;
  a.options_ = options;
  a.n_ = layout.sampleCount();
  a.sampleRateHz_ = layout.sampleRateHz;
  a.preTrigger_ = layout.preTriggerSamples;
  for (const auto& ch : layout.channels) a.dofs_.push_back(ch.dof);
  auto refs = pickReferences(layout, options);
  if (!refs) return refs.error();
  a.references_ = std::move(*refs);
  for (Eigen::Index c = 0; c < layout.channelCount(); ++c) {
    if (std::find(a.references_.begin(), a.references_.end(), c) == a.references_.end()) a.responses_.push_back(c);
  }
  auto type = responseFrfType(layout, a.references_);
  if (!type) return type.error();
  a.type_ = *type;
  if (a.references_.size() > 1 && options.estimator != FrfEstimator::H1) {
    return makeError(ErrorCode::Unsupported,
                     std::string(frfEstimatorName(options.estimator)) + " takes one reference; with " +
                         std::to_string(a.references_.size()) + " references use H1 (H = Gyf Gff^-1)",
                     "FRF options");
  }
  auto fft = RealFft::forLength(a.n_);
  if (!fft) return fft.error();
  a.fft_ = *fft;
  a.refRect_ = isRectangular(options.referenceWindow);
  a.respRect_ = isRectangular(options.responseWindow);
  if (!a.refRect_) {  // rectangular windows are applied by copying, no vector needed
    auto wr = sharedWindow(options.referenceWindow, a.n_, a.sampleRateHz_, a.preTrigger_);
    if (!wr) return wr.error();
    a.refWindow_ = std::move(*wr);
  }
  if (!a.respRect_) {
    auto wx = sharedWindow(options.responseWindow, a.n_, a.sampleRateHz_, a.preTrigger_);
    if (!wx) return wx.error();
    a.respWindow_ = std::move(*wx);
  }
  const Eigen::Index nf = a.fft_->lineCount();
  a.frequencyHz_ =
      Vector::LinSpaced(nf, 0.0, static_cast<double>(nf - 1)) * (a.sampleRateHz_ / static_cast<double>(a.n_));
  const auto nr = static_cast<Eigen::Index>(a.references_.size());
  const auto no = static_cast<Eigen::Index>(a.responses_.size());
  for (Eigen::Index i = 0; i < nr; ++i) {
    for (Eigen::Index j = i + 1; j < nr; ++j) a.pairs_.emplace_back(i, j);
  }
  for (Eigen::Index i = 0; i < nr; ++i) {
    for (Eigen::Index o = 0; o < no; ++o) a.pairs_.emplace_back(i, nr + o);
  }
  a.nf_ = nf;
  a.autoCount_ = nr + no;
  a.crossOffset_ = (nf * a.autoCount_ + 7) / 8 * 8;
  a.acc_ = PooledBuffer(static_cast<std::size_t>(a.crossOffset_ + 2 * nf * static_cast<Eigen::Index>(a.pairs_.size())),
                        PooledBuffer::Init::Uninitialised);  // the first hit assigns
  return a;
}

Eigen::Index SpectralAverager::crossIndex(Eigen::Index a, Eigen::Index b) const {
  const auto nr = static_cast<Eigen::Index>(references_.size());
  if (b < nr) return a * (2 * nr - a - 1) / 2 + (b - a - 1);  // reference pairs, row by row
  return nr * (nr - 1) / 2 + a * static_cast<Eigen::Index>(responses_.size()) + (b - nr);
}

Result<void> SpectralAverager::add(const TimeRecord& hit) {
  const std::string where = "hit " + std::to_string(hits_ + 1);
  if (!std::isfinite(hit.sampleRateHz) || hit.sampleRateHz <= 0.0) {
    return makeError(ErrorCode::InvalidArgument, "sample rate must be finite and positive", where);
  }
  if (hit.sampleRateHz != sampleRateHz_) {
    return makeError(ErrorCode::InvalidArgument,
                     "sample rate " + std::to_string(hit.sampleRateHz) + " Hz differs from the first hit's " +
                         std::to_string(sampleRateHz_) + " Hz",
                     where);
  }
  if (hit.channelCount() != static_cast<Eigen::Index>(dofs_.size()) || hit.samples.cols() != hit.channelCount()) {
    return makeError(ErrorCode::InvalidArgument, "channel layout differs from the first hit (mismatched lengths)",
                     where);
  }
  if (hit.sampleCount() != n_) {
    return makeError(ErrorCode::InvalidArgument,
                     "hit has " + std::to_string(hit.sampleCount()) + " samples, the first hit " + std::to_string(n_) +
                         " (mismatched lengths)",
                     where);
  }
  if (hit.preTriggerSamples != preTrigger_) {
    return makeError(ErrorCode::InvalidArgument, "pre-trigger length differs from the first hit", where);
  }
  for (std::size_t c = 0; c < dofs_.size(); ++c) {
    if (hit.channels[c].dof != dofs_[c]) {
      return makeError(
          ErrorCode::InvalidArgument,
          "channel DOF " + formatDof(hit.channels[c].dof) + " differs from the first hit's " + formatDof(dofs_[c]),
          where + ", channel " + std::to_string(c));
    }
  }
  // Stage 1: each channel windowed straight into the FFT input (one pass) or,
  // with a rectangular window, read once for the check and transformed from
  // the record's column itself (that pass brings it into L2 for the FFT),
  // checked, transformed into its slot of the workspace. Nothing is accumulated before every
  // channel passed, so a bad hit leaves the average untouched.
  const Eigen::Index nf = fft_->lineCount();
  const Eigen::Index stride = spectrumStride(nf);
  const std::size_t nr = references_.size();
  const std::size_t channels = nr + responses_.size();
  Workspace& ws = workspace(n_, static_cast<std::size_t>(stride) * channels);
  for (std::size_t j = 0; j < channels; ++j) {
    const bool isRef = j < nr;
    const Eigen::Index c = isRef ? references_[j] : responses_[j - nr];
    const double* x = hit.samples.col(c).data();
    const double* w = isRef ? (refRect_ ? nullptr : refWindow_->data()) : (respRect_ ? nullptr : respWindow_->data());
    // A rectangular window needs no copy: the FFT reads the column itself
    // (RealFft::forward copies only when its alignment differs from the plan's).
    const double sumSq =
        w != nullptr ? windowInto(x, w, ws.in.data(), n_) : Eigen::Map<const Vector>(x, n_).squaredNorm();
    if (!std::isfinite(sumSq)) {
      for (Eigen::Index i = 0; i < n_; ++i) {
        if (!std::isfinite(x[i])) {
          return makeError(ErrorCode::InvalidArgument, "sample is NaN or infinite",
                           where + ", " + channelWhere(hit, c) + ", sample " + std::to_string(i));
        }
      }
      return makeError(ErrorCode::NumericalFailure, "samples too large: their sum of squares overflows",
                       where + ", " + channelWhere(hit, c));
    }
    if (isRef && !(sumSq > 0.0)) {
      return makeError(ErrorCode::InvalidArgument, "force is zero (after the force window): no excitation to divide by",
                       where + ", " + channelWhere(hit, c));
    }
    fft_->forward(w != nullptr ? ws.in.data() : x, ws.spectra.data() + static_cast<Eigen::Index>(j) * stride);
  }
  accumulate(ws.spectra.data(), stride);
  ++hits_;
  return {};
}

void SpectralAverager::accumulate(const std::complex<double>* spectra, Eigen::Index stride) {
  if (hits_ == 0) {
    accumulateBlocks<false>(spectra, stride);
  } else {
    accumulateBlocks<true>(spectra, stride);
  }
}

template <bool Add>
void SpectralAverager::accumulateBlocks(const std::complex<double>* spectra, Eigen::Index stride) {
  // Stage 2: one sweep over the lines in blocks that fit L1, every auto and
  // cross product of a block done while its spectra are cached; each
  // accumulator column is a contiguous stream read and written once per hit.
  constexpr Eigen::Index kBlock = 512;
  const auto spec = [&](Eigen::Index a, Eigen::Index k0) {
    return reinterpret_cast<const double*>(spectra + a * stride + k0);
  };
  auto au = autos();
  auto cr = cross();
  for (Eigen::Index k0 = 0; k0 < nf_; k0 += kBlock) {
    const Eigen::Index len = std::min(kBlock, nf_ - k0);
    for (Eigen::Index a = 0; a < autoCount_; ++a) addAbs2<Add>(spec(a, k0), au.col(a).data() + k0, len);
    for (std::size_t p = 0; p < pairs_.size(); ++p) {
      addConjProduct<Add>(spec(pairs_[p].first, k0), spec(pairs_[p].second, k0),
                          reinterpret_cast<double*>(cr.col(static_cast<Eigen::Index>(p)).data() + k0), len);
    }
  }
}

namespace {
// c_k = 2 / fs^2, 1 / fs^2 at DC and (even n) Nyquist; divided by the hit count.
Vector esdScale(Eigen::Index nf, Eigen::Index n, double fs, int hits) {
  Vector s = Vector::Constant(nf, 2.0 / (fs * fs * hits));
  s[0] = 1.0 / (fs * fs * hits);
  if (n % 2 == 0) s[nf - 1] = 1.0 / (fs * fs * hits);
  return s;
}

std::string hz(double f) {
  return formatNumber(f, 6) + " Hz";
}
}  // namespace

void SpectralAverager::reset() {
  hits_ = 0;  // the next hit overwrites the accumulators
}

Vector SpectralAverager::gff() const {
  if (hits_ == 0) return Vector::Zero(autos().rows());
  return autos().col(0).cwiseProduct(esdScale(autos().rows(), n_, sampleRateHz_, hits_));
}

Matrix SpectralAverager::gxx() const {
  const auto no = static_cast<Eigen::Index>(responses_.size());
  if (hits_ == 0) return Matrix::Zero(autos().rows(), no);
  return esdScale(autos().rows(), n_, sampleRateHz_, hits_).asDiagonal() * autos().rightCols(no);
}

ComplexMatrix SpectralAverager::gfx() const {
  const auto nr = static_cast<Eigen::Index>(references_.size());
  const auto no = static_cast<Eigen::Index>(responses_.size());
  if (hits_ == 0) return ComplexMatrix::Zero(autos().rows(), no);
  const Eigen::Index first = crossIndex(0, nr);  // reference 0 with response 0, responses follow
  return esdScale(autos().rows(), n_, sampleRateHz_, hits_).cast<Complex>().asDiagonal() *
         cross().middleCols(first, no);
}

void SpectralAverager::rawReferenceMatrix(Eigen::Index line, ComplexMatrix& g) const {
  const auto nr = static_cast<Eigen::Index>(references_.size());
  g.resize(nr, nr);
  for (Eigen::Index i = 0; i < nr; ++i) {
    g(i, i) = autos()(line, i);
    for (Eigen::Index j = i + 1; j < nr; ++j) {
      // cross() holds sum conj(f_i) f_j = E[f_j conj(f_i)] = Gff(j, i)
      g(j, i) = cross()(line, crossIndex(i, j));
      g(i, j) = std::conj(g(j, i));
    }
  }
}

ComplexMatrix SpectralAverager::referenceSpectralMatrix(Eigen::Index line) const {
  const auto nr = static_cast<Eigen::Index>(references_.size());
  if (hits_ == 0 || line < 0 || line >= nf_) return ComplexMatrix::Zero(nr, nr);
  ComplexMatrix g;
  rawReferenceMatrix(line, g);
  return esdScale(nf_, n_, sampleRateHz_, hits_)[line] * g;
}

namespace {
// Condition number of D^-1/2 G D^-1/2 (D = diag G) for Hermitian G and G^-1
// when it is finite; +inf when a diagonal entry is not positive or the
// normalised matrix is singular. Two references (the usual two-shaker test)
// in closed form: with c = G10 / sqrt(G00 G11) the normalised eigenvalues are
// 1 +- |c|; more through the eigen decomposition. Buffers are kept between
// lines (no allocation per line).
struct NormalisedInput {
  Vector invSqrtDiag, invL;
  Eigen::SelfAdjointEigenSolver<ComplexMatrix> eig;
  ComplexMatrix normalised, inverse;
  double condition = 1.0;

  explicit NormalisedInput(Eigen::Index r) : invSqrtDiag(r), invL(r), eig(r), normalised(r, r), inverse(r, r) {}

  void compute(const ComplexMatrix& g) {
    const Eigen::Index r = g.rows();
    constexpr double kInf = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < r; ++i) {
      const double d = g(i, i).real();
      if (!(d > 0.0)) {
        condition = kInf;
        return;
      }
      invSqrtDiag[i] = 1.0 / std::sqrt(d);
    }
    if (r == 2) {
      const double a = g(0, 0).real(), d = g(1, 1).real();
      const Complex b = g(1, 0);
      const double c = std::sqrt(std::norm(b)) * invSqrtDiag[0] * invSqrtDiag[1];  // (std::abs goes through hypot)
      condition = c < 1.0 ? (1.0 + c) / (1.0 - c) : kInf;
      const double det = a * d - std::norm(b);
      if (!(det > 0.0)) condition = kInf;
      if (condition == kInf) return;
      inverse(0, 0) = d / det;
      inverse(1, 1) = a / det;
      inverse(1, 0) = -b / det;
      inverse(0, 1) = -std::conj(b) / det;
      return;
    }
    normalised.noalias() = invSqrtDiag.asDiagonal() * g * invSqrtDiag.asDiagonal();
    eig.compute(normalised);
    const Vector& l = eig.eigenvalues();  // ascending
    condition = l[0] > 0.0 ? l[r - 1] / l[0] : kInf;
    if (condition == kInf) return;
    // G^-1 = D V L^-1 V^H D (D = diag^-1/2, V L V^H the normalised matrix)
    invL = l.cwiseInverse();
    const auto& v = eig.eigenvectors();
    normalised.noalias() = v * invL.asDiagonal() * v.adjoint();
    inverse.noalias() = invSqrtDiag.asDiagonal() * normalised * invSqrtDiag.asDiagonal();
  }
};
}  // namespace

Vector SpectralAverager::referenceConditionNumber() const {
  const Eigen::Index nf = autos().rows();
  Vector cond = Vector::Ones(nf);
  if (references_.size() < 2 || hits_ == 0) return cond;
  NormalisedInput ni(static_cast<Eigen::Index>(references_.size()));
  ComplexMatrix g;
  for (Eigen::Index k = 0; k < nf; ++k) {
    rawReferenceMatrix(k, g);  // the condition number does not depend on the scale
    ni.compute(g);
    cond[k] = ni.condition;
  }
  return cond;
}

Result<FrfMatrix> SpectralAverager::frf(FrfEstimator estimator) const {
  const std::string where = std::string(frfEstimatorName(estimator)) + " estimate";
  if (hits_ == 0) return makeError(ErrorCode::InvalidArgument, "no hits were averaged", where);
  FrfMatrix m;
  m.frequencyHz = frequencyHz_;
  for (auto c : references_) m.references.push_back(dofs_[static_cast<std::size_t>(c)]);
  for (auto c : responses_) m.responses.push_back(dofs_[static_cast<std::size_t>(c)]);
  m.type = type_;
  if (references_.size() == 1) return frfSingleReference(estimator, std::move(m));
  if (estimator != FrfEstimator::H1) {
    return makeError(ErrorCode::Unsupported,
                     std::string(frfEstimatorName(estimator)) + " takes one reference; with " +
                         std::to_string(references_.size()) + " references use H1 (H = Gyf Gff^-1)",
                     where);
  }
  return frfMultipleReference(std::move(m));
}

Result<FrfMatrix> SpectralAverager::frfSingleReference(FrfEstimator estimator, FrfMatrix m) const {
  const std::string where = std::string(frfEstimatorName(estimator)) + " estimate";
  const Eigen::Index nf = autos().rows();
  const auto no = static_cast<Eigen::Index>(responses_.size());
  ComplexMatrix h(nf, no);
  Matrix coh(nf, no);
  const auto au = autos();
  const auto cr = cross();
  // The scale c_k cancels in every ratio below, so the raw sums are used.
  if (estimator == FrfEstimator::H1 && au.col(0).minCoeff() > 0.0) {
    // H1 = G_fx / G_ff and gamma^2 = |G_fx|^2 / (G_ff G_xx) as whole columns
    // (vectorised; the per-line loop below is for H2, Hv and the error)
    const Eigen::ArrayXd invGff = au.col(0).array().inverse();
    for (Eigen::Index o = 0; o < no; ++o) {
      const auto gfx = cr.col(o).array();  // pair (0, 1 + o) is column o with one reference
      const auto gxx = au.col(1 + o).array();
      h.col(o).array() = gfx * invGff.cast<Complex>();
      coh.col(o).array() = (gxx > 0.0).select((gfx.abs2() * invGff / gxx).min(1.0).max(0.0), 0.0);
    }
    m.h.push_back(std::move(h));  // (a braced list would copy the blocks)
    m.coherence.push_back(std::move(coh));
    return m;
  }
  for (Eigen::Index k = 0; k < nf; ++k) {
    const double gff = au(k, 0);
    if (!(gff > 0.0)) {
      return makeError(ErrorCode::NumericalFailure,
                       "force auto spectrum is zero at " + std::to_string(frequencyHz_[k]) + " Hz; H cannot be formed",
                       where + ", line " + std::to_string(k));
    }
    for (Eigen::Index o = 0; o < no; ++o) {
      const Complex gfx = cr(k, o);  // pair (0, 1 + o) is column o with one reference
      const double gxx = au(k, 1 + o);
      const double g2 = gfx.real() * gfx.real() + gfx.imag() * gfx.imag();  // |G_fx|^2 (std::norm goes through hypot)
      // gamma^2 = |G_fx|^2 / (G_ff G_xx); 0 when the response is exactly zero
      coh(k, o) = gxx > 0.0 ? std::clamp(g2 / (gff * gxx), 0.0, 1.0) : 0.0;
      if (estimator == FrfEstimator::H1) {
        h(k, o) = Complex(gfx.real() / gff, gfx.imag() / gff);  // H1 = G_fx / G_ff
        continue;
      }
      if (!(g2 > 0.0)) {
        return makeError(ErrorCode::NumericalFailure,
                         "cross spectrum is zero at " + std::to_string(frequencyHz_[k]) + " Hz; " +
                             frfEstimatorName(estimator) + " divides by it",
                         where + ", response " + formatDof(m.responses[static_cast<std::size_t>(o)]) + ", line " +
                             std::to_string(k));
      }
      const Complex gxf = std::conj(gfx);
      if (estimator == FrfEstimator::H2) {
        h(k, o) = gxx / gxf;  // H2 = G_xx / G_xf
      } else {
        // Hv = (G_xx - G_ff + sqrt((G_ff - G_xx)^2 + 4 |G_fx|^2)) / (2 G_xf)
        const double d = gff - gxx;
        h(k, o) = (gxx - gff + std::sqrt(d * d + 4.0 * g2)) / (2.0 * gxf);
      }
    }
  }
  m.h.push_back(std::move(h));  // (a braced list would copy the blocks)
  m.coherence.push_back(std::move(coh));
  return m;
}

Result<FrfMatrix> SpectralAverager::frfMultipleReference(FrfMatrix m) const {
  const std::string where = "multiple-reference H1 estimate";
  const Eigen::Index nf = autos().rows();
  const auto nr = static_cast<Eigen::Index>(references_.size());
  const auto no = static_cast<Eigen::Index>(responses_.size());
  std::vector<ComplexMatrix> h(static_cast<std::size_t>(nr), ComplexMatrix(nf, no));
  Matrix coh(nf, no);
  NormalisedInput ni(nr);
  ComplexMatrix gyf(no, nr), hk(no, nr);
  std::vector<Eigen::Index> badLines;
  double worst = 0.0;
  Eigen::Index worstLine = 0;
  // Raw sums again: the scale c_k is common to Gff, Gyf and Gyy at a line.
  ComplexMatrix g;
  for (Eigen::Index k = 0; k < nf; ++k) {
    rawReferenceMatrix(k, g);
    for (Eigen::Index i = 0; i < nr; ++i) {
      if (!(autos()(k, i) > 0.0)) {
        return makeError(ErrorCode::NumericalFailure,
                         "auto spectrum of reference " + formatDof(m.references[static_cast<std::size_t>(i)]) +
                             " is zero at " + hz(frequencyHz_[k]) + "; H cannot be formed",
                         where + ", line " + std::to_string(k));
      }
    }
    ni.compute(g);
    if (!(ni.condition <= options_.maxReferenceConditionNumber)) {
      badLines.push_back(k);
      if (!(ni.condition <= worst)) {
        worst = ni.condition;
        worstLine = k;
      }
      continue;
    }
    for (Eigen::Index i = 0; i < nr; ++i) {
      for (Eigen::Index o = 0; o < no; ++o) gyf(o, i) = cross()(k, crossIndex(i, nr + o));  // E[y_o conj(f_i)]
    }
    // H = Gyf Gff^-1, well defined since the condition was checked
    hk.noalias() = gyf * ni.inverse;
    for (Eigen::Index o = 0; o < no; ++o) {
      // gamma^2_o = H_o Gyf_o^H / G_yoyo (real: a Hermitian form)
      const double gyy = autos()(k, nr + o);
      const double num = (hk.row(o) * gyf.row(o).adjoint()).value().real();
      coh(k, o) = gyy > 0.0 ? std::clamp(num / gyy, 0.0, 1.0) : 0.0;
      for (Eigen::Index i = 0; i < nr; ++i) h[static_cast<std::size_t>(i)](k, o) = hk(o, i);
    }
  }
  if (!badLines.empty()) {
    // consecutive lines as ranges "40 Hz to 60 Hz", at most six of them
    std::string lines;
    int ranges = 0;
    for (std::size_t b = 0; b < badLines.size() && ranges < 6; ++ranges) {
      std::size_t e = b;
      while (e + 1 < badLines.size() && badLines[e + 1] == badLines[e] + 1) ++e;
      lines += (ranges ? ", " : "") + hz(frequencyHz_[badLines[b]]);
      if (e > b) lines += " to " + hz(frequencyHz_[badLines[e]]);
      b = e + 1;
      if (ranges == 5 && b < badLines.size()) lines += ", ...";
    }
    return makeError(ErrorCode::NumericalFailure,
                     "the references are correlated: their cross-spectral matrix Gff is ill-conditioned at " +
                         std::to_string(badLines.size()) + " of " + std::to_string(nf) + " lines (" + lines +
                         "; worst condition number " + formatNumber(worst, 3) + " at " + hz(frequencyHz_[worstLine]) +
                         ", limit " + formatNumber(options_.maxReferenceConditionNumber, 3) +
                         "), so the forces cannot be separated. Drive the references with independent signals, "
                         "average more blocks than there are references, or use one reference",
                     where);
  }
  m.h = std::move(h);
  m.coherence.assign(static_cast<std::size_t>(nr), coh);
  return m;
}

Result<FrfMatrix> selectBand(const FrfMatrix& frf, double fLoHz, double fHiHz) {
  std::vector<Eigen::Index> keep;
  for (Eigen::Index k = 0; k < frf.lineCount(); ++k) {
    if (frf.frequencyHz[k] >= fLoHz && frf.frequencyHz[k] <= fHiHz) keep.push_back(k);
  }
  if (keep.empty()) {
    return makeError(ErrorCode::InvalidArgument,
                     "no frequency line between " + std::to_string(fLoHz) + " and " + std::to_string(fHiHz) + " Hz",
                     "FRF band selection");
  }
  FrfMatrix out;
  out.responses = frf.responses;
  out.references = frf.references;
  out.type = frf.type;
  const auto m = static_cast<Eigen::Index>(keep.size());
  out.frequencyHz.resize(m);
  for (Eigen::Index r = 0; r < m; ++r) out.frequencyHz[r] = frf.frequencyHz[keep[static_cast<std::size_t>(r)]];
  for (const auto& block : frf.h) {
    ComplexMatrix b(m, block.cols());
    for (Eigen::Index r = 0; r < m; ++r) b.row(r) = block.row(keep[static_cast<std::size_t>(r)]);
    out.h.push_back(std::move(b));
  }
  for (const auto& block : frf.coherence) {
    Matrix b(m, block.cols());
    for (Eigen::Index r = 0; r < m; ++r) b.row(r) = block.row(keep[static_cast<std::size_t>(r)]);
    out.coherence.push_back(std::move(b));
  }
  return out;
}

Result<FrfMatrix> estimateFrf(const std::vector<TimeRecord>& hits, const FrfOptions& options) {
  if (hits.empty()) return makeError(ErrorCode::InvalidArgument, "no hits given", "FRF estimate");
  auto avg = SpectralAverager::create(hits.front(), options);
  if (!avg) return avg.error();
  for (const auto& hit : hits) {
    if (auto ok = avg->add(hit); !ok) return ok.error();
  }
  return avg->frf();
}

}  // namespace mozzi::core::signal
