#pragma once
// One physical mode, one pole: the rule that keeps identification honest on
// real data (issue 18). An estimator can return two poles for one sharp
// resonance - on a real three-FRF roving-hammer set at 1 Hz resolution pLSCF
// gave 958.42 and 958.58 Hz, both stable over many orders - because a mode
// narrower than a spectral line is fitted about equally well by a pair. Two
// poles are taken for the same mode when
//   1. they are closer than the frequency resolution of the FRFs (the data
//      holds no information that separates them), or
//   2. their shapes are the same (MAC >= macThreshold, the vector-stability
//      level of the diagram) and they are within the diagram's frequency
//      tolerance of each other (a repeated shape far away in frequency is a
//      different mode seen through too few DOFs: spatial aliasing).
// The automatic selection (selectPoles) keeps one pole per group: the one
// backed by the most orders. A user who selects both in the diagram is warned
// (the page names the pair, their separation and MAC).

#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/modal/plscf.h"

namespace mozzi::core::modal {

// Frequency resolution of a set of lines in [lowHz, highHz]: the median line
// spacing (robust to a missing line or an uneven export). 0 with fewer than
// two lines in the band.
double frequencyResolutionHz(const VectorRef& frequencyHz, double lowHz, double highHz);

struct SameModeCriteria {
  double resolutionHz = 0.0;         // 1: poles closer than this are one mode
  double macThreshold = 0.98;        // 2: shapes at least this alike ...
  double frequencyTolerance = 0.01;  // ... within this relative distance
};

// From the diagram's options (stability criteria) and the FRFs' resolution.
SameModeCriteria sameModeCriteria(const PlscfOptions& options, double resolutionHz);

enum class SameModeReason {
  Distinct = 0,
  WithinResolution,  // closer than the frequency resolution
  SameShape,         // MAC near 1 within the frequency tolerance
};

struct ModeCandidate {
  double frequencyHz = 0.0;
  ComplexVector shape;  // over the outputs; empty: only the resolution rule applies
};

struct SameModePair {
  std::size_t first = 0, second = 0;  // indices into the candidates, first < second
  double separationHz = 0.0;
  double mac = 0.0;  // 0 when a shape is missing
  SameModeReason reason = SameModeReason::Distinct;
};

// Whether two candidates are one mode, and why (fills separationHz and mac).
SameModePair compareModes(const ModeCandidate& a, const ModeCandidate& b, const SameModeCriteria& criteria);

// Every pair of candidates that are one mode.
std::vector<SameModePair> findSameModes(const std::vector<ModeCandidate>& candidates, const SameModeCriteria& criteria);

// Groups of candidates that are one mode (connected through the pairs), and
// one kept per group: the one with the largest `support` (orders backing it),
// ties to the smaller index. Returns the kept indices, ascending.
std::vector<std::size_t> keepOnePerMode(const std::vector<ModeCandidate>& candidates, const std::vector<int>& support,
                                        const SameModeCriteria& criteria);

// The automatic selection's last step: merges selected poles that are one
// mode (keeping the one whose cluster holds the most orders). Uses
// SelectedPole::shape; `resolutionHz` from the fitted FRFs.
void mergeSameModes(std::vector<SelectedPole>& selected, const PlscfOptions& options, double resolutionHz);

// "958.42 Hz and 958.58 Hz are 0.16 Hz apart, closer than the frequency
// resolution (1 Hz): one mode" / "... have the same shape (MAC 0.998)".
std::string describeSameMode(const SameModePair& pair, const std::vector<ModeCandidate>& candidates,
                             const SameModeCriteria& criteria);

}  // namespace mozzi::core::modal
