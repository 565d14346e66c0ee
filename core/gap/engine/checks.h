#pragma once
// Checks after the candidate fits (GAP.md steps 6 and 7): the flip probability
// between the top two by simulating from each fitted alternative, and the
// held-out improvement on folds not used for fitting.

#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "core/common/result.h"
#include "core/gap/engine/fit.h"

namespace mozzi::core::gap::engine {

// A fitted model: which candidate (-1: baseline), its scaled parameters and
// the optimum u (theta then phi).
struct FittedAlternative {
  int candidate = -1;
  std::vector<Scaled> phi;
  Eigen::VectorXd u;
};

// How plausible a flip of the top two is, from `samples` simulations of each
// fitted alternative (a ranked first, with an observed margin
// D = LR_a - LR_b >= 0): the larger of
//   P_a(LR_b > LR_a)        were a the truth, b would win this often, and
//   P_b(LR_a - LR_b >= D)   were b the truth, a would look this much better
//                           this often (a parametric-bootstrap Cox test).
// Both are small only when the data separate the two.
Result<double> flipProbability(const GapProblem& problem, const std::vector<Scaled>& theta, const FittedAlternative& a,
                               const FittedAlternative& b, double observedMargin, int samples, unsigned long long seed,
                               const std::function<bool()>& keepGoing);

// The baseline's part of the held-out check: per fold f, SS_baseline(f), the
// squared whitened residual on f after fitting on all the other folds. The
// same for every effect, so computed once per problem (folds on every core).
struct HeldOutBaseline {
  std::vector<int> foldIds;  // empty: a single fold, no check
  std::vector<double> sumOfSquares;
};
Result<HeldOutBaseline> heldOutBaseline(const GapProblem& problem, const std::vector<Scaled>& theta,
                                        const Eigen::VectorXd& uBaseline);

// 1 - sum_f SS_effect(f) / sum_f SS_baseline(f), SS_effect(f) as above with
// the effect; NaN when the problem has a single fold.
Result<double> heldOutImprovement(const GapProblem& problem, const std::vector<Scaled>& theta,
                                  const Eigen::VectorXd& uBaseline, const FittedAlternative& effect,
                                  const HeldOutBaseline& baseline);

// Profile-likelihood interval of effect parameter j (Venzon and Moolgavkar
// 1988): the values x with 2 (min NLL given phi_j = x  -  NLL at the optimum)
// <= `level` (3.84 for 95%), theta and the other effect parameters refitted at
// every x. Stepped outwards from the optimum in multiples of `stdError`, then
// bisected; an end stops at the parameter's bound when the level is not
// reached within it.
Result<std::pair<double, double>> profileInterval(const GapProblem& problem, const std::vector<Scaled>& theta,
                                                  const FittedAlternative& effect, int j, double stdError,
                                                  double level);

}  // namespace mozzi::core::gap::engine
