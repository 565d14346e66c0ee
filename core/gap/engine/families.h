#pragma once
// Candidates that act on the data exactly alike (GapProblem::effectShape):
// one residual_mode per reference DOF gives a family of equal candidates
// wherever the model's quasi-static deflection under a load there is the same
// at the measured DOFs (the demo's fork: every Y reference excites one and the
// same shape). The diagnosis fits, screens and bootstraps one representative
// per family and reports the others as its equivalent locations.

#include <vector>

#include "core/gap/gap_problem.h"

namespace mozzi::core::gap::engine {

// Relative tolerance on the largest entry of two effect shapes.
constexpr double kEqualShapeTolerance = 1e-9;

// True when two effect shapes are the same vector to `kEqualShapeTolerance`
// of the larger's largest entry (both non-empty, of one length, not zero).
bool equalShapes(const std::vector<double>& a, const std::vector<double>& b);

// Families among `indices` (into candidates): candidates of one effect, with
// parameters of the same names, units, nominal values and priors, and equal
// effect shapes. Each family lists its members in the order of `indices`,
// the first its representative; families in the order of their first members.
// A candidate without an effect shape is a family of its own.
std::vector<std::vector<int>> equalEffectFamilies(const GapProblem& problem, const std::vector<Candidate>& candidates,
                                                  const std::vector<int>& indices);

// The representative of a family as the diagnosis fits it: the first
// member with the others' locations in `equivalent` and each parameter's
// bounds the union of the members' (equal shapes at equal sizes give equal
// residuals, so the family's admissible sizes are those of any member).
Candidate familyCandidate(const std::vector<Candidate>& candidates, const std::vector<int>& family);

}  // namespace mozzi::core::gap::engine
