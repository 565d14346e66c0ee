#pragma once
// The structural sim-to-real gap problems (shared/GAP.md, issue 10):
//  - measured FRFs (UFF 58, any FRF type) against a structural model, and
//  - identified modes (frequency, damping, shapes; UFF 55) against the model,
// with the structural catalogue of candidate effects:
//   mass_loading        added mass dm [kg] at a measured DOF
//   boundary_stiffness  a grounded spring of the model scaled by s
//   element_stiffness   a spring between two DOFs scaled by s
//   residual_mode       an out-of-band mode excited from reference DOF d: upper
//                       residual U [m/N], its curvature V [m/N] (the omega^2
//                       growth of a mode above the band, at the band's top
//                       omega_t) and lower residual L [1/kg]:
//                       (U - V s^2 / omega_t^2 + L / s^2) u u^T along the static
//                       deflection u under a load at d, max |u| = 1 (FRFs
//                       only: an out-of-band mode moves no in-band mode)
//   hysteretic_damping  structural damping i eta K added (loss factor eta,
//                       equal on every mode; with a "damping" calibration
//                       parameter the fit can trade viscous for structural)
//   exponential_window  every pole's decay + a = 1/tau [1/s]: the FRF at
//                       s = i omega + a
//   sensor_misalignment response channel at o reads cos(a) x_o + sin(a) x_p,
//                       p another DOF of the same node and kind (tilt a in
//                       degrees)
//
// Receptance of the augmented model, in the generalised coordinates of
// model_file.h (x = T q): H(s) = T (K_q (1 + i eta) + s C_q + s^2 M_q)^-1 T^T,
// evaluated through the undamped modes of (K_q, M_q); mobility and accelerance
// multiply by s and s^2.

#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/gap/gap_problem.h"
#include "core/gap/structural/model_file.h"
#include "core/io/uff/uff.h"

namespace mozzi::core::gap::structural {

struct StructuralOptions {
  // Only lines in [bandLowHz, bandHighHz] are fitted (FRF data) / only modes in
  // the band are paired (mode data).
  double bandLowHz = 0.0;
  double bandHighHz = std::numeric_limits<double>::infinity();
  // Bands of the "where" table; empty = octave bands over the data.
  std::vector<std::pair<double, double>> reportBands;
  // FRF noise (issue 16, docs/gap.md "Noise from the data"), per real and
  // imaginary component: sigma^2 = (relative |H|)^2 + floor^2.
  //  - Estimated: relative part and additive floor fitted per FRF (and per
  //    band where the data show a different level) from the data's own lines
  //    (frf_noise.h); re-estimated on every simulated data set.
  //  - Coherence: the normalised random error of an H1 estimate from n_avg
  //    averages with coherence g, sqrt(1 - g^2) / (g sqrt(2 n_avg)) (Bendat &
  //    Piersol, "Random data", eq. 9.65), at least 0.1%.
  //  - Replicates: the scatter of repeated hits (`replicates`, same layout as
  //    the measured set, which is their mean), smoothed by the same model.
  //  - Stated: relativeFloor and additiveFloor as given.
  //  - Auto: coherence when the file has it, else replicates when given, else
  //    estimated.
  enum class NoiseSource { Auto, Estimated, Coherence, Replicates, Stated };
  NoiseSource noise = NoiseSource::Auto;
  double relativeFloor = 0.01;  // Stated: relative sigma per component
  double additiveFloor = 0.0;   // Stated: additive sigma per component, in the FRF's unit
  int averages = 10;            // Coherence: averages behind the estimate
  std::vector<FrfMatrix> replicates;
  // Mode data (GAP.md step 0): relative sigma floors of frequency and damping;
  // shape components relative to the largest measured component.
  double frequencySigmaFloor = 0.002;
  double dampingSigmaFloor = 0.15;
  double shapeSigma = 0.03;
  double macPairing = 0.6;  // MAC below this: unpaired
  // Held-out groups: the fitted lines (or modes) are split into this many
  // contiguous frequency bands.
  int folds = 4;
};

// The effect enumeration behind Candidate::effect.
const std::vector<std::string>& structuralEffectNames();

Result<std::unique_ptr<GapProblem>> makeFrfProblem(const StructuralModel& model, const FrfMatrix& measured,
                                                   const StructuralOptions& options = {});

// Measured modes: ModalData as read from UFF 55 (any normalisation; shapes are
// compared through MAC and a least-squares scale factor).
Result<std::unique_ptr<GapProblem>> makeModesProblem(const StructuralModel& model, const io::uff::ModalData& measured,
                                                     const StructuralOptions& options = {});

}  // namespace mozzi::core::gap::structural
