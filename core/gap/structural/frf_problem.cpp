#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "core/common/text.h"
#include "core/gap/structural/frf_noise.h"
#include "core/gap/structural/structural_core.h"
#include "core/gap/structural/structural_problem.h"
#include "core/modal/sdof.h"
#include "core/modal/shape_tools.h"
#include "core/signal/frf_estimator.h"

// The FRF problem of structural_problem.h: measured FRFs against the
// structural model, whitened by the noise model of StructuralOptions.

namespace mozzi::core::gap::structural {

using detail::CandidateDef;
using detail::ChannelMap;
using detail::Effect;
using detail::hzLabel;
using detail::mapDof;
using detail::ModalSystem;
using detail::nominalTheta;
using detail::StructuralCore;
using detail::times;

namespace {

std::vector<std::pair<double, double>> octaveBands(double lo, double hi) {
  std::vector<std::pair<double, double>> bands;
  if (!(hi > lo)) return bands;
  double start = std::max(lo, 1e-3);
  // Octaves anchored at 1 kHz / 2^n (nominal octave edges times sqrt 2).
  double edge = 1000.0 / std::sqrt(2.0);
  while (edge > start) edge /= 2;
  while (edge * 2 <= start) edge *= 2;
  while (edge < hi) {
    bands.emplace_back(std::max(edge, lo), std::min(edge * 2, hi));
    edge *= 2;
  }
  return bands;
}

using NoiseSource = StructuralOptions::NoiseSource;

// Estimate the noise from the residual against the nominal model rather than
// from the FRF itself: the difference kernel then sees the (small) curvature
// of the model error instead of the FRF's own, which lowers its bias where the
// line spacing is coarse against the peaks (docs/gap.md, "Noise from the data").
constexpr bool kNoiseFromNominalResidual = true;
// Relative sigma assumed for an FRF whose own lines cannot give one (fewer than
// 16 usable lines, or all exactly zero): the floor stated in the report.
constexpr double kFallbackRelative = 0.01;
// With coherence, the H1 random error never below 0.1% per component (a
// coherence of exactly 1, e.g. simulated data, would give an infinite weight).
constexpr double kCoherenceFloor = 0.001;

const char* frfUnit(FrfType type) {
  return type == FrfType::Receptance ? "m/N" : type == FrfType::Mobility ? "m/s/N" : "m/s^2/N";
}

// The noise behind the whitening of an FRF problem: absolute sigma per line and
// component, and how it was obtained.
struct FrfNoise {
  NoiseSource source = NoiseSource::Stated;
  std::vector<Matrix> sigma;  // per reference: nf x no, per real/imaginary component
  Matrix logVariance;         // ni x no: variance of log sigma^2 of each FRF (0 unless estimated)
  NoiseModel report;
  // Estimated noise: the fit per FRF (reference-major) and the curve its
  // differences were taken of (the nominal model's FRFs), kept so that a
  // simulated data set refits the level only (frf_noise.h, rescaleFrfNoise).
  std::vector<FrfNoiseFit> fits;
  std::shared_ptr<const std::vector<ComplexMatrix>> reference;
  std::string referenceName = "the nominal model";  // what `reference` is, for the report
  // Coherence: the relative H1 error per line (per reference, nf x no); the
  // sigma follows from it and the FRF read, on simulated data too.
  std::vector<Matrix> coherenceRelative;
};

// Sigma from the coherence's relative errors r (Bendat & Piersol eq. 9.65).
// The error is relative to the true |H|, which the reading overstates on
// average by 1 + 2 r^2 (its own noise) and, where the noise dominates (r > 1),
// scatters down to zero: |H|^2 is taken as the larger of the line's own and
// the median over five lines, so a reading that happens to fall near zero
// does not get a near-zero sigma.
std::vector<Matrix> coherenceSigma(const FrfMatrix& data, const std::vector<Matrix>& rel, double tiny) {
  const Eigen::Index nf = data.lineCount(), no = data.responseCount();
  std::vector<Matrix> out;
  for (std::size_t i = 0; i < data.h.size(); ++i) {
    Matrix s(nf, no);
    for (Eigen::Index o = 0; o < no; ++o) {
      const ComplexVector h = data.h[i].col(o);
      for (Eigen::Index k = 0; k < nf; ++k) {
        std::array<double, 5> near{};
        int count = 0;
        for (Eigen::Index j = std::max<Eigen::Index>(0, k - 2); j <= std::min(nf - 1, k + 2); ++j)
          near[static_cast<std::size_t>(count++)] = std::norm(h[j]);
        std::nth_element(near.begin(), near.begin() + count / 2, near.begin() + count);
        const double mag2 = std::max(std::norm(h[k]), near[static_cast<std::size_t>(count / 2)]);
        const double r = rel[i](k, o);
        s(k, o) = std::max(r * std::sqrt(mag2 / (1.0 + 2.0 * r * r)), tiny);
      }
    }
    out.push_back(std::move(s));
  }
  return out;
}

class FrfProblem final : public GapProblem {
 public:
  FrfProblem(std::shared_ptr<const StructuralCore> core, FrfMatrix measured, std::vector<ChannelMap> resp,
             std::vector<ChannelMap> refs, FrfNoise noise, StructuralOptions options)
      : core_(std::move(core)),
        data_(std::move(measured)),
        resp_(std::move(resp)),
        refs_(std::move(refs)),
        noise_(std::move(noise)),
        options_(std::move(options)) {
    for (const auto& c : resp_) respDofs_.push_back(c.dof);
    for (const auto& c : refs_) refDofs_.push_back(c.dof);
    // Rows to evaluate: responses, then the DOFs misaligned channels lean to.
    evalDofs_ = respDofs_;
    misRow_.assign(core_->defs.size(), -1);
    for (std::size_t c = 0; c < core_->defs.size(); ++c) {
      if (core_->defs[c].effect != Effect::Misalignment) continue;
      misRow_[c] = static_cast<Eigen::Index>(evalDofs_.size());
      evalDofs_.push_back(core_->defs[c].other);
    }
    if (noise_.sigma.empty()) {
      if (noise_.source == NoiseSource::Coherence) {
        noise_.sigma = coherenceSigma(data_, noise_.coherenceRelative, tinySigma());
      } else {
        estimateNoise();
      }
    }
  }

  std::string dataKind() const override { return "frf"; }
  std::vector<Parameter> calibrationParameters() const override { return core_->calibration; }
  std::vector<Candidate> candidates() const override {
    std::vector<Candidate> out;
    for (const auto& d : core_->defs) out.push_back(d.candidate);
    return out;
  }
  int residualCount() const override {
    return static_cast<int>(2 * data_.lineCount() * data_.responseCount() * data_.referenceCount());
  }

  // A residual mode adds term(s) u_o u_i to FRF (o, i) (StructuralCore::
  // Receptance::at), with u its deflection shape, normalised to max |u| = 1
  // over all DOFs, and term(s) the same function of its sizes for every
  // residual mode of the problem (one band top). So its shape is the products
  // u_o u_i (channel signs included) over the measured pairs: u and -u give
  // the same products and the same FRFs, and a candidate whose u differed at
  // the measured DOFs by a factor c would need its sizes divided by c^2, so
  // the products keep that scale and such candidates are never merged. What u
  // does at DOFs nobody measured reaches no residual, metric or overlay.
  std::vector<double> effectShape(int candidate) const override {
    if (candidate < 0 || candidate >= static_cast<int>(core_->defs.size())) return {};
    const CandidateDef& def = core_->defs[static_cast<std::size_t>(candidate)];
    if (def.effect != Effect::ResidualMode) return {};
    std::vector<double> out;
    out.reserve(resp_.size() * refs_.size());
    for (const auto& o : resp_)
      for (const auto& i : refs_) out.push_back(def.shape[o.dof] * o.sign * def.shape[i.dof] * i.sign);
    return out;
  }
  NoiseModel noiseModel() const override { return noise_.report; }

  bool residuals(const ModelPoint& at, double* r) const override {
    return residualsFor(at.theta, comboOf(at.candidate), at.phi, r);
  }

  bool combinable(const std::vector<int>& combo) const override {
    for (std::size_t a = 0; a < combo.size(); ++a) {
      if (combo[a] < 0 || combo[a] >= static_cast<int>(core_->defs.size())) return false;
      const CandidateDef& da = core_->defs[static_cast<std::size_t>(combo[a])];
      for (std::size_t b = a + 1; b < combo.size(); ++b) {
        if (combo[a] == combo[b]) return false;
        const CandidateDef& db = core_->defs[static_cast<std::size_t>(combo[b])];
        // One loss factor, one window, one tilt per channel: the same global
        // effect twice is one effect.
        if (da.effect == db.effect && (da.effect == Effect::Hysteretic || da.effect == Effect::Window)) return false;
        if (da.effect == Effect::Misalignment && db.effect == Effect::Misalignment && da.dof == db.dof) return false;
      }
    }
    return true;
  }
  bool combinedResiduals(const double* theta, const std::vector<int>& combo, const double* phi,
                         double* r) const override {
    return residualsFor(theta, combo, phi, r);
  }
  GapMetrics combinedMetrics(const double* theta, const std::vector<int>& combo, const double* phi) const override {
    return metricsFor(theta, combo, phi);
  }
  std::vector<OverlayCurve> combinedOverlay(const double* theta, const std::vector<int>& combo,
                                            const double* phi) const override {
    return overlayFor(theta, combo, phi);
  }

  std::vector<int> folds() const override {
    std::vector<int> f;
    const Eigen::Index nf = data_.lineCount();
    const int nfold = std::max(1, options_.folds);
    f.reserve(static_cast<std::size_t>(residualCount()));
    for (Eigen::Index i = 0; i < data_.referenceCount(); ++i)
      for (Eigen::Index o = 0; o < data_.responseCount(); ++o)
        for (Eigen::Index k = 0; k < nf; ++k) {
          const int fold = static_cast<int>((k * nfold) / std::max<Eigen::Index>(nf, 1));
          f.push_back(fold);
          f.push_back(fold);
        }
    return f;
  }

  // Prediction plus noise drawn with the whitening sigma of this problem. A
  // noise model estimated from the data is estimated again from the simulated
  // data, one from the coherence re-derived from the simulated reading (the
  // bootstrap then carries their own error); a replicate or stated one is kept.
  std::unique_ptr<GapProblem> simulated(const ModelPoint& at, std::mt19937_64& rng) const override {
    std::vector<ComplexMatrix> h;
    FrfMatrix sim = data_;
    if (!predict(at.theta, comboOf(at.candidate), at.phi, h)) h = data_.h;
    std::normal_distribution<double> nd(0.0, 1.0);
    const Eigen::Index nf = data_.lineCount(), no = data_.responseCount();
    const double tiny = tinySigma();
    for (std::size_t i = 0; i < h.size(); ++i)
      for (Eigen::Index o = 0; o < no; ++o)
        for (Eigen::Index k = 0; k < nf; ++k) {
          const double s = simulationSigma(i, k, o, std::norm(h[i](k, o)), tiny);
          const double re = nd(rng), im = nd(rng);
          sim.h[i](k, o) = h[i](k, o) + Complex(s * re, s * im);
        }
    FrfNoise noise = noise_;
    // Estimated: its level refitted from the simulated lines, against the
    // simulated truth (the best reference there is, as for the measurement
    // after withNoiseReference); coherence: the sigma re-derived from the
    // simulated reading (the same relative errors).
    if (noise.source == NoiseSource::Estimated) {
      noise.reference = std::make_shared<const std::vector<ComplexMatrix>>(h);
    }
    if (noise.source == NoiseSource::Estimated || noise.source == NoiseSource::Coherence) noise.sigma.clear();
    return std::make_unique<FrfProblem>(core_, std::move(sim), resp_, refs_, std::move(noise), options_);
  }

  // Sigma of the noise drawn around a simulated truth of magnitude^2 `mag2`:
  // the part of the noise model that is relative follows the simulated FRF,
  // not the measured one, exactly as the simulated problem whitens it. (With
  // the measured |H| a peak the effect moved would put large noise where the
  // baseline has none and whiten it with a small sigma: a null chi-square
  // many times its degrees of freedom, and no residual read as beyond noise.)
  double simulationSigma(std::size_t i, Eigen::Index k, Eigen::Index o, double mag2, double tiny) const {
    const auto ii = static_cast<Eigen::Index>(i);
    if (noise_.source == NoiseSource::Estimated && !noise_.fits.empty()) {
      const FrfNoiseFit& fit = noise_.fits[static_cast<std::size_t>(ii * data_.responseCount() + o)];
      return std::max(fit.ok ? fit.sigma(k, mag2) : kFallbackRelative * std::sqrt(mag2), tiny);
    }
    if (noise_.source == NoiseSource::Coherence && i < noise_.coherenceRelative.size()) {
      return std::max(noise_.coherenceRelative[i](k, o) * std::sqrt(mag2), tiny);
    }
    return noise_.sigma[i](k, o);
  }

  std::unique_ptr<GapProblem> withNoiseReference(const double* theta, const std::vector<int>& combo,
                                                 const double* phi) const override {
    if (noise_.source != NoiseSource::Estimated) return nullptr;
    auto ref = std::make_shared<std::vector<ComplexMatrix>>();
    if (!predict(theta, combo, phi, *ref)) return nullptr;
    FrfNoise noise;
    noise.source = NoiseSource::Estimated;
    noise.reference = std::move(ref);
    noise.referenceName = "the calibrated model with";
    const auto all = candidates();
    for (std::size_t c = 0; c < combo.size(); ++c)
      noise.referenceName += (c ? " and " : " ") + label(all[static_cast<std::size_t>(combo[c])]);
    return std::make_unique<FrfProblem>(core_, data_, resp_, refs_, std::move(noise), options_);
  }

  GapMetrics metrics(const ModelPoint& at) const override {
    return metricsFor(at.theta, comboOf(at.candidate), at.phi);
  }
  std::vector<OverlayCurve> overlay(const ModelPoint& at) const override {
    return overlayFor(at.theta, comboOf(at.candidate), at.phi);
  }

  // Predicted FRFs in the measured layout and type: h[i] is nf x no.
  bool predict(const double* theta, const std::vector<int>& combo, const double* phi,
               std::vector<ComplexMatrix>& h) const {
    ModalSystem sys;
    if (!core_->solve(theta, combo, phi, sys)) return false;
    const Eigen::Index nf = data_.lineCount(), no = data_.responseCount(), ni = data_.referenceCount();
    h.resize(static_cast<std::size_t>(ni));
    for (auto& m : h)
      if (m.rows() != nf || m.cols() != no) m.resize(nf, no);
    const int order = frfTypeOrder(data_.type);
    const std::vector<int>& rows = sys.tilts.empty() ? respDofs_ : evalDofs_;
    StructuralCore::Receptance receptance(sys, rows, refDofs_);
    ComplexMatrix x(static_cast<Eigen::Index>(rows.size()), ni);
    for (Eigen::Index k = 0; k < nf; ++k) {
      const Complex s(sys.decay, 2 * M_PI * data_.frequencyHz[k]);
      receptance.at(s, x);
      Complex factor(1.0, 0.0);
      for (int n = 0; n < order; ++n) factor = times(factor, s);
      for (Eigen::Index i = 0; i < ni; ++i) {
        for (Eigen::Index o = 0; o < no; ++o) {
          Complex v = x(o, i);
          for (const auto& tilt : sys.tilts) {
            if (respDofs_[static_cast<std::size_t>(o)] != tilt.def->dof) continue;
            v = std::cos(tilt.angle) * x(o, i) +
                std::sin(tilt.angle) * x(misRow_[static_cast<std::size_t>(tilt.candidate)], i);
          }
          h[static_cast<std::size_t>(i)](k, o) =
              times(factor, v) * (resp_[static_cast<std::size_t>(o)].sign * refs_[static_cast<std::size_t>(i)].sign);
        }
      }
    }
    for (const auto& m : h)
      if (!m.allFinite()) return false;
    return true;
  }

 private:
  static std::vector<int> comboOf(int candidate) {
    return candidate < 0 ? std::vector<int>{} : std::vector<int>{candidate};
  }

  bool residualsFor(const double* theta, const std::vector<int>& combo, const double* phi, double* r) const {
    thread_local std::vector<ComplexMatrix> h;  // reused: one allocation per thread, not per evaluation
    if (!predict(theta, combo, phi, h)) return false;
    std::size_t j = 0;
    const Eigen::Index nf = data_.lineCount();
    for (std::size_t i = 0; i < h.size(); ++i) {
      for (Eigen::Index o = 0; o < data_.responseCount(); ++o) {
        for (Eigen::Index k = 0; k < nf; ++k) {
          const Complex d = h[i](k, o) - data_.h[i](k, o);
          const double s = noise_.sigma[i](k, o);
          r[j++] = d.real() / s;
          r[j++] = d.imag() / s;
        }
      }
    }
    // (Vectorised, without an early exit: a non-finite entry is the rare case.)
    return Eigen::Map<const Eigen::VectorXd>(r, static_cast<Eigen::Index>(j)).allFinite();
  }

  GapMetrics metricsFor(const double* theta, const std::vector<int>& combo, const double* phi) const;
  std::vector<OverlayCurve> overlayFor(const double* theta, const std::vector<int>& combo, const double* phi) const;

  // The smallest sigma of any line: 1e-12 of the largest |H| of the whole set,
  // so a line (or a whole uncoupled FRF) that reads exactly zero never gets an
  // infinite weight (a weakly coupled cross FRF at low frequency can lie 1e-7
  // below its peak, well above this).
  double tinySigma() const {
    double peak = 0.0;
    for (const auto& m : data_.h) peak = std::max(peak, m.cwiseAbs().maxCoeff());
    return 1e-12 * peak + 1e-300;
  }

  std::string frfLabel(Eigen::Index i, Eigen::Index o) const {
    return core_->label(respDofs_[static_cast<std::size_t>(o)]) + " / " +
           core_->label(refDofs_[static_cast<std::size_t>(i)]);
  }

  // Noise per FRF (and band) from the data's own lines (frf_noise.h). With
  // fits from an earlier estimate (a simulated data set), only their level is
  // refitted.
  void estimateNoise() {
    const Eigen::Index nf = data_.lineCount(), no = data_.responseCount(), ni = data_.referenceCount();
    const bool rescale = noise_.fits.size() == static_cast<std::size_t>(ni * no);
    if (!rescale && !noise_.reference && kNoiseFromNominalResidual) {
      std::vector<double> nominal;
      for (const auto& p : core_->model.parameters) nominal.push_back(p.nominal);
      auto ref = std::make_shared<std::vector<ComplexMatrix>>();
      if (predict(nominal.data(), {}, nullptr, *ref)) noise_.reference = std::move(ref);
    }
    const int nfold = std::max(1, options_.folds);
    std::vector<Eigen::Index> edges;
    for (int b = 0; b <= nfold; ++b) edges.push_back(static_cast<Eigen::Index>((nf * b) / nfold));
    const double tiny = tinySigma();
    noise_.source = NoiseSource::Estimated;
    noise_.sigma.assign(static_cast<std::size_t>(ni), Matrix(nf, no));
    noise_.logVariance = Matrix::Zero(ni, no);
    noise_.report = NoiseModel{};
    noise_.report.source = "estimated";
    noise_.report.estimated = true;
    std::vector<FrfNoiseFit> fits;
    int fallbacks = 0;
    for (Eigen::Index i = 0; i < ni; ++i)
      for (Eigen::Index o = 0; o < no; ++o) {
        const ComplexVector h = data_.h[static_cast<std::size_t>(i)].col(o);
        const Vector mag2 = h.cwiseAbs2();
        const ComplexVector y =
            noise_.reference ? ComplexVector(h - (*noise_.reference)[static_cast<std::size_t>(i)].col(o)) : h;
        const FrfNoiseFit fit = rescale
                                    ? rescaleFrfNoise(noise_.fits[static_cast<std::size_t>(i * no + o)], y, mag2, edges)
                                    : estimateFrfNoise(y, mag2, edges);
        fits.push_back(fit);
        NoiseEntry entry;
        entry.label = frfLabel(i, o);
        entry.unit = frfUnit(data_.type);
        if (fit.ok) {
          entry.relative = fit.relative;
          entry.floor = fit.floor;
          entry.lines = fit.lines;
          noise_.logVariance(i, o) = fit.logVariance;
        } else {
          ++fallbacks;
          entry.relative = kFallbackRelative;
          entry.floor = 0.0;
        }
        for (Eigen::Index k = 0; k < nf; ++k) {
          const double s = fit.ok ? fit.sigma(k, mag2[k]) : kFallbackRelative * std::sqrt(mag2[k]);
          noise_.sigma[static_cast<std::size_t>(i)](k, o) = std::max(s, tiny);
        }
        noise_.report.entries.push_back(entry);
        for (const auto& b : fit.bands) {
          if (b.scale == 1.0 || b.last <= b.first) continue;
          NoiseEntry e = entry;
          e.band = hzLabel(data_.frequencyHz[b.first], data_.frequencyHz[b.last - 1]);
          e.relative *= std::sqrt(b.scale);
          e.floor *= std::sqrt(b.scale);
          e.lines = b.lines;
          noise_.report.entries.push_back(e);
        }
      }
    noise_.fits = std::move(fits);
    for (Eigen::Index i = 0; i < ni; ++i)
      for (Eigen::Index o = 0; o < no; ++o)
        noise_.report.chiSquareVariance += 4.0 * static_cast<double>(nf * nf) * noise_.logVariance(i, o);
    std::ostringstream d;
    d << "Estimated from the data (no coherence given): per FRF a relative part and an additive floor, fitted "
         "robustly to the scatter of third differences of neighbouring lines"
      << (noise_.reference ? " of the residual against " + noise_.referenceName : std::string())
      << ", with a level of its own for a band where the data show one; its level is refitted on every simulated "
         "data set of the bootstrap.";
    if (fallbacks > 0) {
      d << " " << fallbacks
        << " FRF(s) had too few usable lines (or read exactly zero): " << formatNumber(100 * kFallbackRelative, 2)
        << "% relative assumed there.";
    }
    noise_.report.description = d.str();
  }

  std::shared_ptr<const StructuralCore> core_;
  FrfMatrix data_;
  std::vector<ChannelMap> resp_, refs_;
  std::vector<int> respDofs_, refDofs_, evalDofs_;
  std::vector<Eigen::Index> misRow_;  // per candidate: row of the DOF a misaligned channel leans to, -1 otherwise
  FrfNoise noise_;
  StructuralOptions options_;
};

GapMetrics FrfProblem::metricsFor(const double* theta, const std::vector<int>& combo, const double* phi) const {
  GapMetrics out;
  out.residualName = "frf_residual";
  std::vector<ComplexMatrix> h;
  if (!predict(theta, combo, phi, h)) {
    out.overall = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  const Eigen::Index nf = data_.lineCount(), no = data_.responseCount(), ni = data_.referenceCount();
  // Per (line, response) sums over references: squared relative error, the
  // same expected from noise alone (lines with a nonzero reading), chi2.
  Matrix rel2 = Matrix::Zero(nf, no), chi2 = Matrix::Zero(nf, no), noise2 = Matrix::Zero(nf, no),
         cells = Matrix::Zero(nf, no);
  for (Eigen::Index i = 0; i < ni; ++i)
    for (Eigen::Index o = 0; o < no; ++o)
      for (Eigen::Index k = 0; k < nf; ++k) {
        const Complex meas = data_.h[static_cast<std::size_t>(i)](k, o);
        const Complex d = h[static_cast<std::size_t>(i)](k, o) - meas;
        const double s = noise_.sigma[static_cast<std::size_t>(i)](k, o);
        chi2(k, o) += std::norm(d) / (s * s);
        if (std::norm(meas) > 0) {
          rel2(k, o) += std::norm(d) / std::norm(meas);
          noise2(k, o) += 2 * s * s / std::norm(meas);  // expected |dH / H|^2 from noise alone (two components)
          cells(k, o) += 1;
        }
      }
  auto row = [&](const std::string& kind, const std::string& label, Eigen::Index k0, Eigen::Index k1, Eigen::Index o0,
                 Eigen::Index o1) {
    GapEntry e;
    e.kind = kind;
    e.label = label;
    e.oneSided = true;
    const double count = cells.block(k0, o0, k1 - k0, o1 - o0).sum();
    const double r2 = rel2.block(k0, o0, k1 - k0, o1 - o0).sum();
    const double c2 = chi2.block(k0, o0, k1 - k0, o1 - o0).sum();
    const double n2 = noise2.block(k0, o0, k1 - k0, o1 - o0).sum();
    // The gap is the relative FRF residual in excess of the noise:
    // sqrt(max(0, mean |dH/H|^2 - mean 2 sigma^2 / |H|^2)); 0 for a model that
    // fits within noise, so the shrink measures what an effect explains.
    e.value = count > 0 ? std::sqrt(std::max(0.0, r2 - n2) / count) : 0.0;
    // z of the chi-square sum against its expectation n: variance 2 n, plus,
    // for a noise level estimated from the data, (n_f)^2 var(log sigma_f^2)
    // per FRF f (the whole row scales with the estimate).
    const double n = static_cast<double>(2 * (k1 - k0) * (o1 - o0) * ni);
    double var = 2 * n;
    const double perFrf = static_cast<double>(2 * (k1 - k0));
    for (Eigen::Index i = 0; i < ni; ++i)
      for (Eigen::Index o = o0; o < o1; ++o) var += perFrf * perFrf * noise_.logVariance(i, o);
    e.z = n > 0 ? (c2 - n) / std::sqrt(var) : 0.0;
    e.details = {{"raw_residual", count > 0 ? std::sqrt(r2 / count) : 0.0},
                 {"noise_floor", count > 0 ? std::sqrt(n2 / count) : 0.0},
                 {"chi2_per_residual", n > 0 ? c2 / n : 0.0},
                 {"lines", static_cast<double>(k1 - k0)}};
    return e;
  };
  out.overall = row("overall", "all", 0, nf, 0, no).value;
  const double flo = data_.frequencyHz[0], fhi = data_.frequencyHz[nf - 1];
  auto bands = options_.reportBands.empty() ? octaveBands(flo, fhi) : options_.reportBands;
  for (const auto& b : bands) {
    Eigen::Index k0 = 0, k1 = nf;
    while (k0 < nf && data_.frequencyHz[k0] < b.first) ++k0;
    k1 = k0;
    while (k1 < nf && data_.frequencyHz[k1] <= b.second) ++k1;
    if (k1 <= k0) continue;
    out.entries.push_back(row("band", hzLabel(b.first, b.second), k0, k1, 0, no));
  }
  for (Eigen::Index o = 0; o < no; ++o) {
    out.entries.push_back(row("dof", core_->label(respDofs_[static_cast<std::size_t>(o)]), 0, nf, o, o + 1));
  }
  // Per model mode in the band: the residual over its half-power neighbourhood
  // (at least +/- 2 lines), and the measured mode from a circle fit between
  // the neighbouring predicted modes (frequency and damping errors, MAC).
  ModalSystem sys;
  if (core_->solve(theta, combo, phi, sys)) {
    const Eigen::Index nq = sys.w2.size();
    std::vector<double> fr(static_cast<std::size_t>(nq)), zr(static_cast<std::size_t>(nq));
    for (Eigen::Index r = 0; r < nq; ++r) {
      const double w = std::sqrt(sys.w2[r]);
      double zeta = w > 0 ? sys.cdiag[r] / (2 * w) + sys.eta / 2 : 0.0;
      Complex lambda = modal::poleFromFrequencyDamping(w / (2 * M_PI), std::min(zeta, 0.99)) - sys.decay;
      fr[static_cast<std::size_t>(r)] = modal::poleFrequencyHz(lambda);
      zr[static_cast<std::size_t>(r)] = modal::poleZeta(lambda);
    }
    for (Eigen::Index r = 0; r < nq; ++r) {
      const double f = fr[static_cast<std::size_t>(r)], z = zr[static_cast<std::size_t>(r)];
      if (f < flo || f > fhi) continue;
      const double half = std::max(z * f, 1e-9);
      Eigen::Index k0 = 0;
      while (k0 < nf && data_.frequencyHz[k0] < f - half) ++k0;
      Eigen::Index k1 = k0;
      while (k1 < nf && data_.frequencyHz[k1] <= f + half) ++k1;
      k0 = std::max<Eigen::Index>(0, std::min(k0, k1) - 2);
      k1 = std::min(nf, k1 + 2);
      GapEntry e = row("mode", "mode " + std::to_string(r + 1) + " (" + formatNumber(f, 4) + " Hz)", k0, k1, 0, no);
      e.details.push_back({"predicted_hz", f});
      e.details.push_back({"predicted_zeta", z});
      const double lo = r > 0 ? std::sqrt(f * fr[static_cast<std::size_t>(r - 1)]) : flo;
      const double hi = r + 1 < nq ? std::sqrt(f * fr[static_cast<std::size_t>(r + 1)]) : fhi;
      auto fit = modal::circleFit(data_, 0, std::max(lo, flo), std::min(hi, fhi));
      if (fit && fit->frequencyHz > 0) {
        e.details.push_back({"measured_hz", fit->frequencyHz});
        e.details.push_back({"measured_zeta", fit->zeta});
        e.details.push_back({"frequency_error_pct", 100 * (f - fit->frequencyHz) / fit->frequencyHz});
        if (fit->zeta > 0) e.details.push_back({"zeta_error_pct", 100 * (z - fit->zeta) / fit->zeta});
        ComplexVector model(no);
        for (Eigen::Index o = 0; o < no; ++o)
          model[o] = sys.a(respDofs_[static_cast<std::size_t>(o)], r) * resp_[static_cast<std::size_t>(o)].sign;
        if (fit->residue.size() == no) e.details.push_back({"mac", modal::mac(model, fit->residue)});
      }
      out.entries.push_back(e);
    }
  }
  return out;
}

std::vector<OverlayCurve> FrfProblem::overlayFor(const double* theta, const std::vector<int>& combo,
                                                 const double* phi) const {
  std::vector<OverlayCurve> curves;
  std::vector<ComplexMatrix> h;
  if (!predict(theta, combo, phi, h)) return curves;
  for (Eigen::Index i = 0; i < data_.referenceCount(); ++i)
    for (Eigen::Index o = 0; o < data_.responseCount(); ++o) {
      OverlayCurve c;
      c.label = frfLabel(i, o);
      c.xLabel = "Frequency [Hz]";
      c.yLabel = std::string("|H| [") + frfUnit(data_.type) + "]";
      c.logY = true;
      for (Eigen::Index k = 0; k < data_.lineCount(); ++k) {
        c.x.push_back(data_.frequencyHz[k]);
        c.measured.push_back(std::abs(data_.h[static_cast<std::size_t>(i)](k, o)));
        c.predicted.push_back(std::abs(h[static_cast<std::size_t>(i)](k, o)));
      }
      curves.push_back(std::move(c));
    }
  return curves;
}

// The noise model of the measured set `data` (already cut to the fitted band
// from bandLow): stated, from the coherence or from replicates; an estimated
// one is left empty here (the problem estimates it from its own lines).
Result<FrfNoise> initialNoise(const StructuralModel& model, const FrfMatrix& data, const std::vector<ChannelMap>& resp,
                              const std::vector<ChannelMap>& refs, const StructuralOptions& options, double bandLow) {
  const Eigen::Index nf = data.lineCount();
  const Eigen::Index no = data.responseCount(), ni = data.referenceCount();
  NoiseSource source = options.noise;
  if (source == NoiseSource::Auto) {
    source = !data.coherence.empty()       ? NoiseSource::Coherence
             : !options.replicates.empty() ? NoiseSource::Replicates
                                           : NoiseSource::Estimated;
  }
  if (source == NoiseSource::Coherence && data.coherence.empty()) {
    return makeError(ErrorCode::InvalidArgument, "the noise model 'coherence' needs coherence in the test file",
                     "--noise");
  }
  if (source == NoiseSource::Replicates && options.replicates.size() < 2) {
    return makeError(ErrorCode::InvalidArgument, "the noise model 'replicates' needs at least two repeated FRF sets",
                     "--noise");
  }
  FrfNoise noise;
  noise.source = source;
  noise.logVariance = Matrix::Zero(ni, no);
  double peak = 0.0;
  for (const auto& m : data.h) peak = std::max(peak, m.cwiseAbs().maxCoeff());
  const double tiny = 1e-12 * peak + 1e-300;
  const char* unit = frfUnit(data.type);
  auto label = [&](Eigen::Index i, Eigen::Index o) {
    return model.labels[static_cast<std::size_t>(resp[static_cast<std::size_t>(o)].dof)] + " / " +
           model.labels[static_cast<std::size_t>(refs[static_cast<std::size_t>(i)].dof)];
  };
  if (source == NoiseSource::Stated) {
    noise.report.source = "stated";
    noise.report.description = "Stated by the user: sigma^2 = (" + formatNumber(options.relativeFloor, 3) +
                               " |H|)^2 + (" + formatNumber(options.additiveFloor, 3) + " " + unit +
                               ")^2 per real and imaginary component, on every line.";
    noise.report.entries.push_back({"all", "", options.relativeFloor, options.additiveFloor, unit, 0});
    for (Eigen::Index i = 0; i < ni; ++i) {
      Matrix s(nf, no);
      for (Eigen::Index o = 0; o < no; ++o)
        for (Eigen::Index k = 0; k < nf; ++k)
          s(k, o) = std::max(std::hypot(options.relativeFloor * std::abs(data.h[static_cast<std::size_t>(i)](k, o)),
                                        options.additiveFloor),
                             tiny);
      noise.sigma.push_back(s);
    }
  } else if (source == NoiseSource::Coherence) {
    // The normalised random error of an H1 estimate from n_avg averages with
    // coherence g: sqrt(1 - g^2) / (g sqrt(2 n_avg)) (Bendat & Piersol,
    // "Random data", eq. 9.65), per component, never below 0.1%.
    if (options.averages < 1) return makeError(ErrorCode::InvalidArgument, "averages must be at least 1", "--averages");
    noise.report.source = "coherence";
    noise.report.description = "From the coherence in the file (H1 random error, Bendat & Piersol eq. 9.65, " +
                               std::to_string(options.averages) + " averages), at least " +
                               formatNumber(100 * kCoherenceFloor, 2) + "% per component.";
    noise.report.estimated = true;  // read from the same data: its |H| is noisy too
    for (Eigen::Index i = 0; i < ni; ++i) {
      Matrix rel(nf, no);
      for (Eigen::Index o = 0; o < no; ++o) {
        double sum = 0;
        for (Eigen::Index k = 0; k < nf; ++k) {
          const double g2 = std::clamp(data.coherence[static_cast<std::size_t>(i)](k, o), 1e-6, 1.0);
          rel(k, o) = std::max(kCoherenceFloor, std::sqrt((1 - g2) / (2.0 * options.averages * g2)));
          sum += rel(k, o);
        }
        noise.report.entries.push_back({label(i, o), "", sum / static_cast<double>(nf), 0.0, unit, 0});
      }
      noise.coherenceRelative.push_back(rel);
    }
    noise.sigma = coherenceSigma(data, noise.coherenceRelative, tiny);
  } else if (source == NoiseSource::Replicates) {
    noise.report.source = "replicates";
    noise.report.description = "From the scatter of " + std::to_string(options.replicates.size()) +
                               " repeated FRF sets (hits): the variance of their mean per line, smoothed by a "
                               "relative part and an additive floor per FRF.";
    std::vector<FrfMatrix> reps;
    for (std::size_t r = 0; r < options.replicates.size(); ++r) {
      auto b = signal::selectBand(options.replicates[r], bandLow, options.bandHighHz);
      if (!b.ok() || b->lineCount() != nf || b->responseCount() != no || b->referenceCount() != ni ||
          b->responses != data.responses || b->references != data.references) {
        return makeError(ErrorCode::InvalidArgument, "does not have the layout of the measured FRF set",
                         "repeated FRF set " + std::to_string(r + 1));
      }
      reps.push_back(std::move(b).value());
    }
    const int nfold = std::max(1, options.folds);
    std::vector<Eigen::Index> edges;
    for (int b = 0; b <= nfold; ++b) edges.push_back(static_cast<Eigen::Index>((nf * b) / nfold));
    for (Eigen::Index i = 0; i < ni; ++i) {
      Matrix s(nf, no);
      for (Eigen::Index o = 0; o < no; ++o) {
        std::vector<ComplexVector> hits;
        for (const auto& r : reps) hits.push_back(r.h[static_cast<std::size_t>(i)].col(o));
        const FrfNoiseFit fit = replicateFrfNoise(hits, edges);
        for (Eigen::Index k = 0; k < nf; ++k) {
          const double m2 = std::norm(data.h[static_cast<std::size_t>(i)](k, o));
          s(k, o) = std::max(fit.ok ? fit.sigma(k, m2) : kFallbackRelative * std::sqrt(m2), tiny);
        }
        noise.report.entries.push_back(
            {label(i, o), "", fit.ok ? fit.relative : kFallbackRelative, fit.ok ? fit.floor : 0.0, unit, fit.lines});
      }
      noise.sigma.push_back(s);
    }
  }
  return noise;
}

}  // namespace

Result<std::unique_ptr<GapProblem>> makeFrfProblem(const StructuralModel& model, const FrfMatrix& measured,
                                                   const StructuralOptions& options) {
  MOZZI_TRY(measured.validate());
  if (measured.lineCount() == 0 || measured.responseCount() == 0 || measured.referenceCount() == 0) {
    return makeError(ErrorCode::InvalidArgument, "the measured FRF set is empty", "measured FRFs");
  }
  std::vector<ChannelMap> resp, refs;
  for (const auto& d : measured.responses) {
    MOZZI_TRY_ASSIGN(const ChannelMap c, mapDof(model, d, "response"));
    resp.push_back(c);
  }
  for (const auto& d : measured.references) {
    MOZZI_TRY_ASSIGN(const ChannelMap c, mapDof(model, d, "reference"));
    refs.push_back(c);
  }
  if (options.noise == NoiseSource::Stated && !(options.relativeFloor > 0) && !(options.additiveFloor > 0)) {
    return makeError(ErrorCode::InvalidArgument, "a stated noise needs a positive relative or additive sigma",
                     "noise floor");
  }
  if (!(options.relativeFloor >= 0) || !(options.additiveFloor >= 0) || !std::isfinite(options.relativeFloor) ||
      !std::isfinite(options.additiveFloor)) {
    return makeError(ErrorCode::InvalidArgument, "noise floors must be finite and not negative", "noise floor");
  }
  // The fitted band: lines inside [lo, hi] and above 0 Hz (the type
  // conversion and the lower residual divide by s).
  const double bandLow = std::max(options.bandLowHz, std::nextafter(0.0, 1.0));
  auto banded = signal::selectBand(measured, bandLow, options.bandHighHz);
  if (!banded.ok() || banded->lineCount() < 4) {
    return makeError(ErrorCode::InvalidArgument,
                     "fewer than 4 frequency lines in the band " + hzLabel(options.bandLowHz, options.bandHighHz),
                     "--band");
  }
  FrfMatrix data = std::move(banded).value();
  const Eigen::Index nf = data.lineCount();
  MOZZI_TRY_ASSIGN(FrfNoise noise, initialNoise(model, data, resp, refs, options, bandLow));
  // Estimated: left empty here, the problem estimates it from its own lines.
  auto core = std::make_shared<StructuralCore>(model);
  std::vector<int> measuredDofs, responseDofs;
  for (const auto& c : resp) {
    measuredDofs.push_back(c.dof);
    responseDofs.push_back(c.dof);
  }
  for (const auto& c : refs) measuredDofs.push_back(c.dof);
  ModalSystem nominal;
  const auto theta = nominalTheta(model);
  if (!core->solve({theta.data(), -1, nullptr}, nominal)) {
    return makeError(ErrorCode::NumericalFailure, "the model cannot be solved at its nominal parameters", model.name);
  }
  std::vector<int> referenceDofs;
  for (const auto& c : refs) referenceDofs.push_back(c.dof);
  core->buildCandidates(measuredDofs, responseDofs, referenceDofs, true, data.frequencyHz[nf - 1], nominal.w2);
  data.coherence.clear();  // used only for the noise model above
  return std::unique_ptr<GapProblem>(std::make_unique<FrfProblem>(std::move(core), std::move(data), std::move(resp),
                                                                  std::move(refs), std::move(noise), options));
}

}  // namespace mozzi::core::gap::structural
