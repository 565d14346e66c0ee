#pragma once
// Two effects at once (issue 16, GAP.md step 4 "pairs if allowed"): when the
// best single effect leaves a significant residual, the best few singles are
// fitted jointly with every other candidate the problem can combine them with.
//
// A pair is presented to the fitting engine as a problem of its own
// (ComboProblem) whose one candidate is the pair, so fits, covariance, held-out
// checks and metrics run unchanged.

#include <Eigen/Dense>
#include <functional>
#include <memory>
#include <vector>

#include "core/common/result.h"
#include "core/gap/engine/fit.h"
#include "core/gap/gap_problem.h"

namespace mozzi::core::gap::engine {

// `base` with the candidates in `combo` applied together as its candidate 0.
class ComboProblem final : public GapProblem {
 public:
  ComboProblem(const GapProblem& base, std::vector<int> combo);

  std::string dataKind() const override { return base_.dataKind(); }
  std::vector<Parameter> calibrationParameters() const override { return base_.calibrationParameters(); }
  std::vector<Candidate> candidates() const override { return {combined_}; }
  int residualCount() const override { return base_.residualCount(); }
  bool residuals(const ModelPoint& at, double* r) const override;
  std::vector<int> folds() const override { return base_.folds(); }
  // Simulation from the baseline only (pairs are not bootstrapped).
  std::unique_ptr<GapProblem> simulated(const ModelPoint& at, std::mt19937_64& rng) const override;
  GapMetrics metrics(const ModelPoint& at) const override;
  std::vector<OverlayCurve> overlay(const ModelPoint& at) const override;
  NoiseModel noiseModel() const override { return base_.noiseModel(); }

 private:
  const GapProblem& base_;
  std::vector<int> combo_;
  Candidate combined_;
};

// One candidate's single fit as the pair search starts from it.
struct SingleFit {
  int candidate = -1;       // index into problem.candidates()
  std::vector<Scaled> phi;  // its scaled parameters
  Eigen::VectorXd u;        // optimum (theta then phi)
  double nll = 0.0;
};

struct PairFit {
  int a = -1, b = -1;       // candidates (a: the leader)
  std::vector<Scaled> phi;  // phi_a then phi_b
  Eigen::VectorXd u;        // optimum (theta then phi_a then phi_b)
  double nll = 0.0;
  double chiSquare = 0.0;
  bool ok = false;
};

// A pair already fitted (under another noise model) and its optimum u.
struct PairStart {
  int a = -1, b = -1;
  Eigen::VectorXd u;
};

// Fits every combinable pair (leader, other) with the leaders the first
// `leaders` entries of `singles` (best first) and the others all of them;
// starts: the leader's optimum with the other absent, and with the other's
// own single optimum, and the local minima of a grid along the other's sizes
// (pairs.cpp, gridStarts). With `known` pairs only those are fitted, each
// from its own optimum. Results sorted by NLL, best first.
Result<std::vector<PairFit>> fitPairs(const GapProblem& problem, const std::vector<Scaled>& theta,
                                      const std::vector<SingleFit>& singles, int leaders,
                                      const std::vector<PairStart>& known,
                                      const std::function<bool(double)>& keepGoing);

}  // namespace mozzi::core::gap::engine
