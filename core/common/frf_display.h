#pragma once
// What an FRF plot shows, computed without a widget (WORKBENCH.md "What is
// drawn is testable"): the value of an FRF in each representation an engineer
// asks for, which FRFs of a set a filter picks, their sum, and the mode
// nearest to a cursor. The plots in views/plots only draw these vectors.

#include <optional>
#include <string>
#include <vector>

#include "core/common/dof.h"
#include "core/common/eigen_types.h"
#include "core/common/frf_matrix.h"
#include "core/common/result.h"

namespace mozzi::core {

enum class FrfView {
  MagnitudeLinear,  // |H| on a linear axis
  MagnitudeLog,     // |H| on a logarithmic axis (same values)
  MagnitudeDb,      // 20 log10 |H| [dB re 1 unit of the FRF]
  PhaseWrapped,     // arg H [deg] in (-180, 180]
  PhaseUnwrapped,   // arg H [deg], successive lines within 180 deg
  Real,             // Re H
  Imaginary,        // Im H
  Nyquist,          // Im H against Re H (frequency is the curve parameter)
  Coherence,        // ordinary coherence [0, 1]
};

const char* frfViewName(FrfView view);  // "magnitude (dB)", ... (for CSV and logs)
bool frfViewIsLogarithmic(FrfView view);

// y values of H in `view` (Nyquist: Im H; its x is Re H). Coherence is not a
// function of H: use the set's coherence column.
Vector frfViewValues(const ComplexVectorRef& h, FrfView view);

// One FRF of a set: H_{response, reference}.
struct FrfPick {
  Eigen::Index response = 0;
  Eigen::Index reference = 0;
  friend bool operator==(const FrfPick& a, const FrfPick& b) {
    return a.response == b.response && a.reference == b.reference;
  }
};

// FRFs of a set chosen by response DOF, reference DOF and mesh point (node of
// the response or of the reference); an empty criterion matches everything.
struct FrfFilter {
  std::optional<Dof> response;
  std::optional<Dof> reference;
  std::optional<int> node;
};
std::vector<FrfPick> pickFrfs(const FrfMatrix& frf, const FrfFilter& filter);

// Complex sum over the picked FRFs (the FRF plot's *Sum*, a curve with a
// phase). Errors: no FRF picked, an index out of range.
Result<ComplexVector> frfSum(const FrfMatrix& frf, const std::vector<FrfPick>& picks);

// Sum of the magnitudes |H| over the picked FRFs: the guide to where a set's
// modes are (the stabilization diagram's backdrop, Mode Animation's guide).
// Unlike the complex sum, no mode cancels in it: the FRFs of an
// antisymmetric mode at mirrored points have opposite signs and drop out of
// the complex sum (on the demo frame's roving-hammer set its third mode,
// 77 Hz, stands 14 dB lower there). Errors as frfSum.
Result<Vector> frfMagnitudeSum(const FrfMatrix& frf, const std::vector<FrfPick>& picks);

// Sub-set of the picked FRFs as an FrfMatrix (for the CMIF of a selection):
// the responses and references the picks use, with H zero where a pair of them
// was not picked. Errors as frfSum.
Result<FrfMatrix> frfSubset(const FrfMatrix& frf, const std::vector<FrfPick>& picks);

// Index of the mode nearest to frequencyHz among modeFrequenciesHz (any
// order); -1 when there is none.
int nearestMode(const std::vector<double>& modeFrequenciesHz, double frequencyHz);

}  // namespace mozzi::core
