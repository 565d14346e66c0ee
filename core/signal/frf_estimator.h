#pragma once
// Auto and cross spectra averaged over hits, the H1, H2 and Hv FRF estimators
// and the ordinary coherence (thesis §1.6 and §5.2: "the FRF [is] the ratio
// between the cross spectrum of input signal force and output signal and the
// auto spectrum of input signal", i.e. H1; eq. 20).
//
// Single reference (the hammer force), any number of responses. With F_k the
// DFT of the windowed force and X_k that of a windowed response, per hit:
//   G_ff = c_k |F_k|^2, G_xx = c_k |X_k|^2, G_fx = c_k conj(F_k) X_k
// with the one-sided energy-spectral-density scaling c_k = 2 / fs^2 (1 / fs^2
// at DC and Nyquist) [EU^2 s / Hz], averaged over the hits. Then
//   H1 = G_fx / G_ff                      (unbiased by output noise)
//   H2 = G_xx / G_xf,  G_xf = conj(G_fx)  (unbiased by input noise)
//   Hv = (G_xx - G_ff + sqrt((G_ff - G_xx)^2 + 4 |G_fx|^2)) / (2 G_xf)
//        (total least squares with equal weights; H1 <= |Hv| <= H2)
//   gamma^2 = |G_fx|^2 / (G_ff G_xx)      (ordinary coherence, = H1 / H2)

#include <optional>
#include <string_view>
#include <vector>

#include "core/common/frf_matrix.h"
#include "core/signal/fft.h"
#include "core/signal/time_record.h"
#include "core/signal/window.h"

namespace mozzi::core::signal {

enum class FrfEstimator { H1, H2, Hv };

const char* frfEstimatorName(FrfEstimator estimator);           // "H1", "H2", "Hv"
Result<FrfEstimator> parseFrfEstimator(std::string_view text);  // case-insensitive

struct FrfOptions {
  FrfEstimator estimator = FrfEstimator::H1;
  std::optional<Eigen::Index> referenceChannel;  // default: the one Force channel
  WindowSpec referenceWindow;                    // applied to the reference (force) channel
  WindowSpec responseWindow;                     // applied to every response channel

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

class SpectralAverager {
 public:
  // Sets up windows, FFT plan and accumulators from the layout of `layout`
  // (length, sample rate, pre-trigger, channels); no data is added.
  static Result<SpectralAverager> create(const TimeRecord& layout, const FrfOptions& options);

  // Adds one hit. It must have the layout's length, sample rate, pre-trigger and
  // channel DOFs; NaN samples and an all-zero windowed force are errors.
  Result<void> add(const TimeRecord& hit);

  // Forgets every hit, keeps layout, windows and plan (next measurement point).
  void reset();

  int hitCount() const { return hits_; }
  Eigen::Index referenceChannel() const { return reference_; }
  const std::vector<Eigen::Index>& responseChannels() const { return responses_; }
  const Vector& frequencyHz() const { return frequencyHz_; }

  // Averaged spectra with the ESD scaling above (nf, nf x no, nf x no).
  Vector gff() const;
  Matrix gxx() const;
  ComplexMatrix gfx() const;

  // FRFs of the estimator with coherence, one reference, type from the
  // response transducers. Error with no hits or where G_ff = 0.
  Result<FrfMatrix> frf(FrfEstimator estimator) const;
  Result<FrfMatrix> frf() const { return frf(options_.estimator); }

 private:
  SpectralAverager() = default;
  FrfOptions options_;
  std::shared_ptr<const RealFft> fft_;
  Eigen::Index n_ = 0;
  double sampleRateHz_ = 0.0;
  Eigen::Index preTrigger_ = 0;
  std::vector<Dof> dofs_;
  Eigen::Index reference_ = 0;
  std::vector<Eigen::Index> responses_;
  FrfType type_ = FrfType::Accelerance;
  Vector frequencyHz_;
  Vector refWindow_, respWindow_;
  bool refRect_ = true, respRect_ = true;
  // raw sums of conj(F) X etc. over hits (scaled on output)
  Vector sff_;
  Matrix sxx_;
  ComplexMatrix sfx_;
  int hits_ = 0;
  std::shared_ptr<AlignedBuffer<double>> in_;  // n per channel (reference first), back to back
  std::shared_ptr<AlignedBuffer<std::complex<double>>> fSpec_;
  std::shared_ptr<AlignedBuffer<std::complex<double>>> xSpec_;  // one response spectrum at a time
};

// The lines of `frf` with fLo <= f <= fHi (FRFs and coherence), e.g. to drop
// the DC line before a conversion that divides by omega (FrfMatrix::convertedTo)
// or to keep the usable band. Error when no line is left.
Result<FrfMatrix> selectBand(const FrfMatrix& frf, double fLoHz, double fHiHz);

// All hits through one SpectralAverager.
Result<FrfMatrix> estimateFrf(const std::vector<TimeRecord>& hits, const FrfOptions& options);

}  // namespace mozzi::core::signal
