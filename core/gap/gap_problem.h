#pragma once
// The sim-to-real gap as a statistical problem (design: shared/GAP.md).
//
// A GapProblem holds a model, measured data and its noise model, and evaluates
// whitened residuals r_j = (prediction_j - measured_j) / sigma_j for
//  - the model's own uncertain parameters theta (calibrated first, with bounds
//    and optional Gaussian priors: "calibrate before you blame"), and
//  - optionally one candidate effect k of the catalogue with its parameters phi_k
//    (the "augmentation" of the model; phi_k at `Parameter::nominal` means the
//    effect is absent).
// The engine (diagnosis.h) does not know whether the residuals come from FRFs,
// modes, tyre relaxation lengths or stability-mode frequencies: structural,
// tyre and stability problems are implementations of this interface.

#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/common/result.h"

namespace mozzi::core::gap {

struct Parameter {
  std::string name;      // "k_scale", "added_mass", "eta"
  std::string unit;      // SI unit, "" for dimensionless
  double nominal = 0.0;  // start value; for an effect, the "absent" value
  double lower = 0.0;    // bounds (Ceres parameter bounds)
  double upper = 0.0;
  double priorSigma = 0.0;  // > 0: Gaussian prior N(nominal, priorSigma) as a residual block
};

// One candidate of the catalogue at one location.
struct Candidate {
  Candidate() = default;
  // (A constructor rather than aggregate initialisation, so the problems'
  // catalogues name the three defining fields and leave `equivalent` empty.)
  Candidate(std::string effect_, std::vector<std::string> location_, std::vector<Parameter> parameters_)
      : effect(std::move(effect_)), location(std::move(location_)), parameters(std::move(parameters_)) {}

  std::string effect;                 // catalogue name, e.g. "mass_loading"
  std::vector<std::string> location;  // DOF labels in the model's own format; empty when global
  std::vector<Parameter> parameters;  // the effect's size(s)
  // Locations of the other candidates of the same effect that act on the data
  // exactly as this one (GapProblem::effectShape): the diagnosis fits this
  // one for the family (core/gap/engine/families.h); empty when alone.
  std::vector<std::vector<std::string>> equivalent;
};

// " at 5+X", " at 4+X-5+X"; "" when global.
inline std::string locationSuffix(const std::vector<std::string>& location) {
  std::string s;
  for (std::size_t i = 0; i < location.size(); ++i) s += (i ? "-" : " at ") + location[i];
  return s;
}

// "mass_loading at 5+X", "element_stiffness at 4+X-5+X", "exponential_window".
inline std::string label(const Candidate& c) {
  return c.effect + locationSuffix(c.location);
}

// label() with its equivalent locations: "residual_mode at 1+Y (equivalent at
// 2+Y)", "residual_mode at 1+Y (and 24 equivalent locations)".
inline std::string familyLabel(const Candidate& c) {
  std::string s = label(c);
  if (c.equivalent.size() == 1) {
    const std::string other = locationSuffix(c.equivalent[0]);
    s += " (equivalent" + (other.empty() ? std::string() : other) + ")";
  } else if (c.equivalent.size() > 1) {
    s += " (and " + std::to_string(c.equivalent.size()) + " equivalent locations)";
  }
  return s;
}

// A labelled gap figure for "where" tables and before/after comparisons.
struct GapEntry {
  std::string kind;   // "band", "dof", "mode", "condition", "overall", "prediction" (downstream figures, never flagged)
  std::string label;  // "100-200 Hz", "21+Z", "mode 3", "2.0 bar"
  double value = 0.0;    // the gap in the row's own measure (relative residual, % error...)
  double z = 0.0;        // value in units of its measurement uncertainty (0 when not applicable)
  bool flagged = false;  // significant after Holm correction over the rows of its kind
  // z is a chi-square excess (residual beyond noise): only a large positive z
  // is a gap, so the Holm test is one-sided; otherwise two-sided.
  bool oneSided = false;
  // Named extra figures: "frequency_error_pct", "zeta_error_pct", "mac",
  // "measured", "predicted", ...
  std::vector<std::pair<std::string, double>> details;
};

struct GapMetrics {
  std::string residualName = "frf_residual";  // what `overall` measures
  double overall = 0.0;                       // e.g. relative FRF residual norm
  std::vector<GapEntry> entries;
};

// Measured against predicted along one abscissa (frequency, pressure, speed),
// for the "before / after" overlay of the workbench view and the report.
struct OverlayCurve {
  std::string label;   // "21+Z / 1+Z", "relaxation length"
  std::string xLabel;  // "Frequency [Hz]", "Pressure [bar]"
  std::string yLabel;  // "|H| [m/s^2/N]", "sigma [m]"
  bool logY = false;   // plot y on a logarithmic axis (FRF magnitudes)
  std::vector<double> x;
  std::vector<double> measured;
  std::vector<double> predicted;
};

// The measurement noise behind the whitening (GAP.md step 0), as reported.
struct NoiseEntry {
  std::string label;      // what it applies to: "4+X / 1+X" (one FRF), "mode 2", "all"
  std::string band;       // "10-120 Hz"; empty = the whole fitted band
  double relative = 0.0;  // relative sigma per real/imaginary component (fraction of |H|)
  double floor = 0.0;     // additive sigma per component, in the data's own unit
  std::string unit;       // unit of `floor`
  int lines = 0;          // lines the figures were fitted on (0: not fitted)
};

struct NoiseModel {
  // "estimated" (fitted from the data being diagnosed), "coherence", "replicates"
  // (scatter of repeated hits), "stated" (given by the user), "floors" (fixed
  // sigma floors of GAP.md step 0).
  std::string source = "stated";
  // Fitted from the same data: the bootstrap refits it on every simulated data
  // set, and the goodness of fit is judged against the bootstrap's own
  // chi-square distribution (the noise estimate's error included).
  bool estimated = false;
  std::string description;  // one sentence: the model and how it was obtained
  std::vector<NoiseEntry> entries;
  // Variance the noise estimate's own error adds to the chi-square of all
  // residuals: sum over the groups fitted separately (FRFs) of
  // n_g^2 var(log sigma_g^2). The bootstrap refits the level only; this
  // covers the shape (floor against relative part) too. 0 when not estimated.
  double chiSquareVariance = 0.0;
};

// Where a GapProblem is evaluated: calibration parameters theta (in the order
// of calibrationParameters()) and, when candidate >= 0, that candidate effect
// of candidates() with its parameters phi; candidate -1 and phi null for the
// calibrated model alone.
struct ModelPoint {
  const double* theta = nullptr;
  int candidate = -1;
  const double* phi = nullptr;
};

class GapProblem {
 public:
  virtual ~GapProblem() = default;

  // What kind of data this is ("frf", "modes", "relaxation", "stability").
  virtual std::string dataKind() const = 0;
  virtual std::vector<Parameter> calibrationParameters() const = 0;
  virtual std::vector<Candidate> candidates() const = 0;
  virtual int residualCount() const = 0;

  // What candidate `candidate` adds to the whitened residuals' model, as a
  // vector the engine compares between candidates of the same effect: equal
  // vectors (to 1e-9 of their largest entry, core/gap/engine/families.h) must
  // mean equal residuals at equal parameters everywhere, so the problem
  // normalises away whatever sign or scale its effect does not see and keeps
  // whatever it does. Equal candidates are fitted once, as a family. Empty
  // (the default) when the problem does not compare this candidate.
  virtual std::vector<double> effectShape(int candidate) const {
    (void)candidate;
    return {};
  }

  // Whitened residuals at `at`. Returns false where the model cannot be
  // evaluated (e.g. a singular matrix): the fitter treats it as infeasible.
  virtual bool residuals(const ModelPoint& at, double* r) const = 0;

  // Group of each residual for held-out checks (frequency bands, conditions);
  // all zero when the data cannot be split.
  virtual std::vector<int> folds() const { return std::vector<int>(static_cast<size_t>(residualCount()), 0); }

  // The same problem with the measured data replaced by the prediction at
  // `at` plus noise drawn from the problem's noise model: the parametric
  // bootstrap and the ambiguity check simulate from it.
  virtual std::unique_ptr<GapProblem> simulated(const ModelPoint& at, std::mt19937_64& rng) const = 0;

  // The gap as a user reads it (step 2 of GAP.md), at `at`.
  virtual GapMetrics metrics(const ModelPoint& at) const = 0;

  // The noise model behind the whitened residuals.
  virtual NoiseModel noiseModel() const { return {}; }

  // A noise model estimated from the data sees, besides the noise, whatever
  // of the model error its estimator cannot tell from noise (a resonance the
  // nominal model puts elsewhere reads as scatter). The same problem with that
  // noise estimated again from the residual against the model with the
  // candidates `combo` applied at (theta, phi), nearer the data; null when the
  // noise is not estimated from the data (the default).
  virtual std::unique_ptr<GapProblem> withNoiseReference(const double* theta, const std::vector<int>& combo,
                                                         const double* phi) const {
    (void)theta;
    (void)combo;
    (void)phi;
    return nullptr;
  }

  // Two (or more) effects at once (GAP.md step 4, "pairs"): the residuals,
  // metrics and overlay with the candidates in `combo` all applied, their
  // parameters concatenated in phi in the order of `combo`. Problems that
  // cannot combine a set return false from combinable() (the default).
  virtual bool combinable(const std::vector<int>& combo) const {
    (void)combo;
    return false;
  }
  virtual bool combinedResiduals(const double* theta, const std::vector<int>& combo, const double* phi,
                                 double* r) const {
    if (combo.size() == 1) return residuals({theta, combo[0], phi}, r);
    return false;
  }
  virtual GapMetrics combinedMetrics(const double* theta, const std::vector<int>& combo, const double* phi) const {
    if (combo.size() == 1) return metrics({theta, combo[0], phi});
    return {};
  }
  virtual std::vector<OverlayCurve> combinedOverlay(const double* theta, const std::vector<int>& combo,
                                                    const double* phi) const {
    if (combo.size() == 1) return overlay({theta, combo[0], phi});
    return {};
  }

  // Curves for the overlay (one per measured FRF, mode set or condition
  // series); empty when the problem has nothing to plot.
  virtual std::vector<OverlayCurve> overlay(const ModelPoint& at) const {
    (void)at;
    return {};
  }
};

}  // namespace mozzi::core::gap
