#pragma once
// Auto and cross spectra averaged over hits, the H1, H2 and Hv FRF estimators
// and the ordinary coherence (thesis §1.6 and §5.2: "the FRF [is] the ratio
// between the cross spectrum of input signal force and output signal and the
// auto spectrum of input signal", i.e. H1; eq. 20).
//
// One reference (the hammer force) or several (shakers driven by independent
// signals, MIMO), any number of responses. With one reference and F_k the
// DFT of the windowed force and X_k that of a windowed response, per hit:
//   G_ff = c_k |F_k|^2, G_xx = c_k |X_k|^2, G_fx = c_k conj(F_k) X_k
// with the one-sided energy-spectral-density scaling c_k = 2 / fs^2 (1 / fs^2
// at DC and Nyquist) [EU^2 s / Hz], averaged over the hits. Then
//   H1 = G_fx / G_ff                      (unbiased by output noise)
//   H2 = G_xx / G_xf,  G_xf = conj(G_fx)  (unbiased by input noise)
//   Hv = (G_xx - G_ff + sqrt((G_ff - G_xx)^2 + 4 |G_fx|^2)) / (2 G_xf)
//        (total least squares with equal weights; H1 <= |Hv| <= H2)
//   gamma^2 = |G_fx|^2 / (G_ff G_xx)      (ordinary coherence, = H1 / H2)
//
// Several references measured simultaneously (forces f, R of them; responses
// y): per line the input cross-spectral matrix Gff = E[f f^H] (R x R,
// Hermitian) and Gyf = E[y f^H] (no x R) give
//   H1 = Gyf Gff^-1                                  (no x R, per line)
//   gamma^2_o = H1_o Gyf_o^H / G_yoyo = Gyf_o Gff^-1 Gyf_o^H / G_yoyo
// the multiple coherence of output o with all references (the multiple-input
// form of eq. 20; thesis §1.6 names tests "with many shakers at the same
// time"; Bendat & Piersol, Random Data, ch. 7). Gff must be
// invertible at every line: correlated references (one signal driving two
// shakers, a stinger cross-talk, fewer averages than references) make it
// singular. The check uses the condition number of the normalised matrix
// D^-1/2 Gff D^-1/2 (D its diagonal), so it measures correlation, not a level
// difference between the forces; for two references it is (1+g)/(1-g) with
// g = |gamma_12| the coherence amplitude between them.

#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "core/common/frf_matrix.h"
#include "core/signal/fft.h"
#include "core/signal/pooled_buffer.h"
#include "core/signal/time_record.h"
#include "core/signal/window.h"

namespace mozzi::core::signal {

enum class FrfEstimator { H1, H2, Hv };

const char* frfEstimatorName(FrfEstimator estimator);           // "H1", "H2", "Hv"
Result<FrfEstimator> parseFrfEstimator(std::string_view text);  // case-insensitive

struct FrfOptions {
  FrfEstimator estimator = FrfEstimator::H1;
  // References: referenceChannels when not empty (several: multiple-input H1),
  // else referenceChannel, else every Force channel of the record.
  std::optional<Eigen::Index> referenceChannel;
  std::vector<Eigen::Index> referenceChannels;
  // Largest condition number of the normalised Gff accepted at a line with
  // several references (100: coherence amplitude between two references up to
  // 0.98); above it the estimate is an error naming the lines.
  double maxReferenceConditionNumber = 100.0;
  WindowSpec referenceWindow;  // applied to the reference (force) channel
  WindowSpec responseWindow;   // applied to every response channel

  // Hammer set-up: force window of the given width (and taper) on the force,
  // exponential window of time constant tau on every channel (force included,
  // so that H keeps the meaning of an FRF whose poles moved by -1/tau).
  static FrfOptions hammer(FrfEstimator estimator, std::optional<double> forceWidthS, double forceTaperS,
                           std::optional<double> exponentialTauS);
  // Time constant of the exponential window, 0 when none (for the damping correction).
  double exponentialTauS() const;
};

// FRF type implied by the response transducers: acceleration -> accelerance,
// velocity -> mobility, displacement -> receptance. Mixed kinds or other kinds
// are an error naming the channel.
Result<FrfType> responseFrfType(const TimeRecord& record, Eigen::Index referenceChannel);
Result<FrfType> responseFrfType(const TimeRecord& record, const std::vector<Eigen::Index>& referenceChannels);

class SpectralAverager {
 public:
  // Sets up windows, FFT plan and accumulators from the layout of `layout`
  // (length, sample rate, pre-trigger, channels); no data is added.
  static Result<SpectralAverager> create(const TimeRecord& layout, const FrfOptions& options);

  // Adds one hit (or one block of a random test). It must have the layout's
  // length, sample rate, pre-trigger and channel DOFs; NaN samples and an
  // all-zero windowed reference are errors, and a failed hit leaves the
  // average untouched. Windowing and FFTs go through a per-thread workspace
  // (kept between calls, so creating an averager per estimate allocates only
  // the accumulators); one averager must not be fed from two threads at once.
  Result<void> add(const TimeRecord& hit);

  // Forgets every hit, keeps layout, windows and plan (next measurement point).
  void reset();

  int hitCount() const { return hits_; }
  Eigen::Index referenceChannel() const { return references_.front(); }
  const std::vector<Eigen::Index>& referenceChannels() const { return references_; }
  Eigen::Index referenceCount() const { return static_cast<Eigen::Index>(references_.size()); }
  const std::vector<Eigen::Index>& responseChannels() const { return responses_; }
  const Vector& frequencyHz() const { return frequencyHz_; }

  // Averaged spectra with the ESD scaling above (nf, nf x no, nf x no), of the
  // first reference.
  Vector gff() const;
  Matrix gxx() const;
  ComplexMatrix gfx() const;
  // Input cross-spectral matrix Gff = E[f f^H] at line k (R x R, ESD scaling).
  ComplexMatrix referenceSpectralMatrix(Eigen::Index line) const;
  // Condition number of the normalised Gff per line (1 for one reference,
  // +inf where a reference has no power or Gff is singular).
  Vector referenceConditionNumber() const;

  // FRFs of the estimator with coherence, type from the response transducers.
  // One reference: H1, H2 or Hv with the ordinary coherence. Several: H1 only
  // (H = Gyf Gff^-1), and every coherence block holds the multiple coherence
  // of each output (the same for each reference: with several inputs acting
  // the ordinary coherence of one of them is not a quality measure).
  // Errors: no hits; a reference's auto spectrum zero at a line; with several
  // references, Gff ill-conditioned at some line (the error names the lines).
  Result<FrfMatrix> frf(FrfEstimator estimator) const;
  Result<FrfMatrix> frf() const { return frf(options_.estimator); }

 private:
  SpectralAverager() = default;
  Result<FrfMatrix> frfSingleReference(FrfEstimator estimator, FrfMatrix m) const;
  Result<FrfMatrix> frfMultipleReference(FrfMatrix m) const;
  // Index of the cross accumulator sum conj(S_a) S_b, a < b (channels in
  // accumulation order: references, then responses).
  Eigen::Index crossIndex(Eigen::Index a, Eigen::Index b) const;
  void rawReferenceMatrix(Eigen::Index line, ComplexMatrix& g) const;  // unscaled sums, into g
  void accumulate(const std::complex<double>* spectra, Eigen::Index stride);
  template <bool Add>
  void accumulateBlocks(const std::complex<double>* spectra, Eigen::Index stride);

  FrfOptions options_;
  std::shared_ptr<const RealFft> fft_;
  Eigen::Index n_ = 0;
  double sampleRateHz_ = 0.0;
  Eigen::Index preTrigger_ = 0;
  std::vector<Dof> dofs_;
  std::vector<Eigen::Index> references_;
  std::vector<Eigen::Index> responses_;
  FrfType type_ = FrfType::Accelerance;
  Vector frequencyHz_;
  std::shared_ptr<const Vector> refWindow_, respWindow_;  // shared, read-only (see sharedWindow)
  bool refRect_ = true, respRect_ = true;
  // Raw sums over hits (scaled on output; not defined while hits_ == 0), one column per channel or pair so
  // that each is a contiguous stream: autos()(k, a) = sum |S_a|^2 and
  // cross()(k, p) = sum conj(S_a) S_b for the pairs (a, b) in pairs_: every
  // reference pair a < b < R, then every (reference, response).
  // Both live in one pooled block (pooled_buffer.h): autos first, cross from
  // crossOffset_ doubles on (a whole number of cache lines).
  Eigen::Map<Matrix> autos() { return {acc_.data(), nf_, autoCount_}; }
  Eigen::Map<const Matrix> autos() const { return {acc_.data(), nf_, autoCount_}; }
  Eigen::Map<ComplexMatrix> cross() {
    return {reinterpret_cast<Complex*>(acc_.data() + crossOffset_), nf_, static_cast<Eigen::Index>(pairs_.size())};
  }
  Eigen::Map<const ComplexMatrix> cross() const {
    return {reinterpret_cast<const Complex*>(acc_.data() + crossOffset_), nf_,
            static_cast<Eigen::Index>(pairs_.size())};
  }
  PooledBuffer acc_;
  Eigen::Index nf_ = 0, autoCount_ = 0, crossOffset_ = 0;
  std::vector<std::pair<Eigen::Index, Eigen::Index>> pairs_;
  int hits_ = 0;
};

// The lines of `frf` with fLo <= f <= fHi (FRFs and coherence), e.g. to drop
// the DC line before a conversion that divides by omega (FrfMatrix::convertedTo)
// or to keep the usable band. Error when no line is left.
Result<FrfMatrix> selectBand(const FrfMatrix& frf, double fLoHz, double fHiHz);

// All hits through one SpectralAverager.
Result<FrfMatrix> estimateFrf(const std::vector<TimeRecord>& hits, const FrfOptions& options);

}  // namespace mozzi::core::signal
