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

// Fraction of simulations in which the other alternative fits better than the
// one the data were simulated from; `samples` simulations from each side.
Result<double> flipProbability(const GapProblem& problem, const std::vector<Scaled>& theta, const FittedAlternative& a,
                               const FittedAlternative& b, int samples, unsigned long long seed,
                               const std::function<bool()>& keepGoing);

// 1 - sum_f SS_effect(f) / sum_f SS_baseline(f), where SS(f) is the squared
// whitened residual on fold f after fitting on all the other folds; NaN when
// the problem has a single fold.
Result<double> heldOutImprovement(const GapProblem& problem, const std::vector<Scaled>& theta,
                                  const Eigen::VectorXd& uBaseline, const FittedAlternative& effect);

}  // namespace mozzi::core::gap::engine
