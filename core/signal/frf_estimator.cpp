#include "core/signal/frf_estimator.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

namespace mozzi::core::signal {

const char* frfEstimatorName(FrfEstimator estimator) {
  switch (estimator) {
    case FrfEstimator::H1: return "H1";
    case FrfEstimator::H2: return "H2";
    case FrfEstimator::Hv: return "Hv";
  }
  return "H1";
}

Result<FrfEstimator> parseFrfEstimator(std::string_view text) {
  std::string t(text);
  std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (t == "h1") return FrfEstimator::H1;
  if (t == "h2") return FrfEstimator::H2;
  if (t == "hv") return FrfEstimator::Hv;
  return makeError(ErrorCode::ParseError, "unknown FRF estimator '" + std::string(text) + "' (expected H1, H2 or Hv)",
                   "estimator");
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

bool isRectangular(const WindowSpec& w) { return w.kind == WindowKind::Rectangular && w.exponentialTauS == 0.0; }
}  // namespace

Result<FrfType> responseFrfType(const TimeRecord& record, Eigen::Index referenceChannel) {
  std::optional<FrfType> type;
  for (Eigen::Index c = 0; c < record.channelCount(); ++c) {
    if (c == referenceChannel) continue;
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

Result<SpectralAverager> SpectralAverager::create(const TimeRecord& layout, const FrfOptions& options) {
  if (auto ok = layout.validate(); !ok) return ok.error();
  SpectralAverager a;
  a.options_ = options;
  a.n_ = layout.sampleCount();
  a.sampleRateHz_ = layout.sampleRateHz;
  a.preTrigger_ = layout.preTriggerSamples;
  for (const auto& ch : layout.channels) a.dofs_.push_back(ch.dof);
  if (options.referenceChannel) {
    if (*options.referenceChannel < 0 || *options.referenceChannel >= layout.channelCount()) {
      return makeError(ErrorCode::InvalidArgument,
                       "reference channel " + std::to_string(*options.referenceChannel) + " does not exist (record has " +
                           std::to_string(layout.channelCount()) + " channels)",
                       "FRF options");
    }
    a.reference_ = *options.referenceChannel;
  } else {
    auto ref = findForceChannel(layout);
    if (!ref) return ref.error();
    a.reference_ = *ref;
  }
  for (Eigen::Index c = 0; c < layout.channelCount(); ++c) {
    if (c != a.reference_) a.responses_.push_back(c);
  }
  auto type = responseFrfType(layout, a.reference_);
  if (!type) return type.error();
  a.type_ = *type;
  auto fft = RealFft::forLength(a.n_);
  if (!fft) return fft.error();
  a.fft_ = *fft;
  a.refRect_ = isRectangular(options.referenceWindow);
  a.respRect_ = isRectangular(options.responseWindow);
  if (!a.refRect_) {  // rectangular windows are applied by copying, no vector needed
    auto wr = makeWindow(options.referenceWindow, a.n_, a.sampleRateHz_, a.preTrigger_);
    if (!wr) return wr.error();
    a.refWindow_ = std::move(*wr);
  }
  if (!a.respRect_) {
    auto wx = makeWindow(options.responseWindow, a.n_, a.sampleRateHz_, a.preTrigger_);
    if (!wx) return wx.error();
    a.respWindow_ = std::move(*wx);
  }
  const Eigen::Index nf = a.fft_->lineCount();
  a.frequencyHz_ = Vector::LinSpaced(nf, 0.0, static_cast<double>(nf - 1)) * (a.sampleRateHz_ / static_cast<double>(a.n_));
  const auto no = static_cast<Eigen::Index>(a.responses_.size());
  a.sff_ = Vector::Zero(nf);
  a.sxx_ = Matrix::Zero(nf, no);
  a.sfx_ = ComplexMatrix::Zero(nf, no);
  a.in_ = std::make_shared<AlignedBuffer<double>>(static_cast<std::size_t>(a.n_) * (a.responses_.size() + 1));
  a.fSpec_ = std::make_shared<AlignedBuffer<std::complex<double>>>(static_cast<std::size_t>(nf));
  a.xSpec_ = std::make_shared<AlignedBuffer<std::complex<double>>>(static_cast<std::size_t>(nf));
  return a;
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
    return makeError(ErrorCode::InvalidArgument, "channel layout differs from the first hit (mismatched lengths)", where);
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
      return makeError(ErrorCode::InvalidArgument,
                       "channel DOF " + formatDof(hit.channels[c].dof) + " differs from the first hit's " +
                           formatDof(dofs_[c]),
                       where + ", channel " + std::to_string(c));
    }
  }
  const Eigen::Index nf = fft_->lineCount();
  // Stage 1: every channel (windowed) into its aligned input block and checked
  // finite before anything is accumulated, so a bad hit leaves the average
  // untouched. The sum of a block is finite exactly when its samples are
  // (NaN and inf propagate even through zero window weights).
  std::vector<Eigen::Index> order{reference_};
  order.insert(order.end(), responses_.begin(), responses_.end());
  for (std::size_t j = 0; j < order.size(); ++j) {
    const Eigen::Index c = order[j];
    const bool isRef = j == 0;
    const double* x = hit.samples.col(c).data();
    double* in = in_->data() + j * static_cast<std::size_t>(n_);
    if (isRef ? refRect_ : respRect_) {
      std::copy(x, x + n_, in);
    } else {
      const double* wp = isRef ? refWindow_.data() : respWindow_.data();
      for (Eigen::Index i = 0; i < n_; ++i) in[i] = x[i] * wp[i];
    }
    if (!std::isfinite(Eigen::Map<const Vector>(in, n_).sum())) {
      for (Eigen::Index i = 0; i < n_; ++i) {
        if (!std::isfinite(x[i])) {
          return makeError(ErrorCode::InvalidArgument, "sample is NaN or infinite",
                           where + ", " + channelWhere(hit, c) + ", sample " + std::to_string(i));
        }
      }
      return makeError(ErrorCode::NumericalFailure, "samples too large: their sum overflows", where + ", " + channelWhere(hit, c));
    }
  }
  std::complex<double>* f = fSpec_->data();
  fft_->forward(in_->data(), f);
  const Eigen::Map<const ComplexVector> fv(f, nf);
  if (!(fv.squaredNorm() > 0.0)) {
    return makeError(ErrorCode::InvalidArgument, "force is zero (after the force window): no excitation to divide by",
                     where + ", " + channelWhere(hit, reference_));
  }
  // Stage 2: each response transformed and accumulated at once, while its
  // spectrum is still in cache, with Eigen's packet math (SIMD complex
  // products without std::complex's NaN-recovery path; inputs are finite).
  sff_.array() += fv.real().array().square() + fv.imag().array().square();  // |F|^2
  const Eigen::Map<const ComplexVector> xv(xSpec_->data(), nf);
  for (std::size_t o = 0; o < responses_.size(); ++o) {
    fft_->forward(in_->data() + (o + 1) * static_cast<std::size_t>(n_), xSpec_->data());
    sfx_.col(static_cast<Eigen::Index>(o)).array() += fv.conjugate().array() * xv.array();  // conj(F) X
    sxx_.col(static_cast<Eigen::Index>(o)).array() += xv.real().array().square() + xv.imag().array().square();  // |X|^2
  }
  ++hits_;
  return {};
}

namespace {
// c_k = 2 / fs^2, 1 / fs^2 at DC and (even n) Nyquist; divided by the hit count.
Vector esdScale(Eigen::Index nf, Eigen::Index n, double fs, int hits) {
  Vector s = Vector::Constant(nf, 2.0 / (fs * fs * hits));
  s[0] = 1.0 / (fs * fs * hits);
  if (n % 2 == 0) s[nf - 1] = 1.0 / (fs * fs * hits);
  return s;
}
}  // namespace

void SpectralAverager::reset() {
  sff_.setZero();
  sxx_.setZero();
  sfx_.setZero();
  hits_ = 0;
}

Vector SpectralAverager::gff() const {
  if (hits_ == 0) return Vector::Zero(sff_.size());
  return sff_.cwiseProduct(esdScale(sff_.size(), n_, sampleRateHz_, hits_));
}

Matrix SpectralAverager::gxx() const {
  if (hits_ == 0) return Matrix::Zero(sxx_.rows(), sxx_.cols());
  return esdScale(sxx_.rows(), n_, sampleRateHz_, hits_).asDiagonal() * sxx_;
}

ComplexMatrix SpectralAverager::gfx() const {
  if (hits_ == 0) return ComplexMatrix::Zero(sfx_.rows(), sfx_.cols());
  return esdScale(sfx_.rows(), n_, sampleRateHz_, hits_).cast<Complex>().asDiagonal() * sfx_;
}

Result<FrfMatrix> SpectralAverager::frf(FrfEstimator estimator) const {
  const std::string where = std::string(frfEstimatorName(estimator)) + " estimate";
  if (hits_ == 0) return makeError(ErrorCode::InvalidArgument, "no hits were averaged", where);
  const Eigen::Index nf = sff_.size();
  const auto no = static_cast<Eigen::Index>(responses_.size());
  FrfMatrix m;
  m.frequencyHz = frequencyHz_;
  m.references = {dofs_[static_cast<std::size_t>(reference_)]};
  for (auto c : responses_) m.responses.push_back(dofs_[static_cast<std::size_t>(c)]);
  m.type = type_;
  ComplexMatrix h(nf, no);
  Matrix coh(nf, no);
  // The scale c_k cancels in every ratio below, so the raw sums are used.
  for (Eigen::Index k = 0; k < nf; ++k) {
    const double gff = sff_[k];
    if (!(gff > 0.0)) {
      return makeError(ErrorCode::NumericalFailure,
                       "force auto spectrum is zero at " + std::to_string(frequencyHz_[k]) + " Hz; H cannot be formed",
                       where + ", line " + std::to_string(k));
    }
    for (Eigen::Index o = 0; o < no; ++o) {
      const Complex gfx = sfx_(k, o);
      const double gxx = sxx_(k, o);
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
  m.h = {std::move(h)};
  m.coherence = {std::move(coh)};
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
