#pragma once
// Bounded least-squares fits of a GapProblem's whitened residuals (GAP.md steps
// 1 and 4) in scaled coordinates: every parameter x = nominal + scale * u with
// scale = its bound span (or prior sigma when unbounded), so numerical
// derivatives, multistarts and tolerances are relative to the bounds.

#include <Eigen/Dense>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/common/result.h"
#include "core/gap/gap_problem.h"

namespace mozzi::core::gap::engine {

// One fitted parameter's coordinate map and box in u.
struct Scaled {
  Parameter def;
  double scale = 1.0;
  double uLower = 0.0, uUpper = 0.0;  // may be +-inf
  bool fixed = false;                 // lower == upper == nominal
  double toX(double u) const { return def.nominal + scale * u; }
  double toU(double x) const { return (x - def.nominal) / scale; }
};

Result<Scaled> scaleParameter(const Parameter& p, const std::string& where);

// The residual model of one fit: calibration theta plus (candidate >= 0) that
// candidate's phi, over all residual rows or a subset (held-out folds).
class Model {
 public:
  Model(const GapProblem& problem, std::vector<Scaled> theta, int candidate, std::vector<Scaled> phi,
        std::vector<int> rows = {});

  int thetaCount() const { return static_cast<int>(theta_.size()); }
  int parameterCount() const { return static_cast<int>(theta_.size() + phi_.size()); }
  int residualCount() const { return rows_.empty() ? problem_.residualCount() : static_cast<int>(rows_.size()); }
  int candidate() const { return candidate_; }
  const std::vector<Scaled>& theta() const { return theta_; }
  const std::vector<Scaled>& phi() const { return phi_; }
  const Scaled& parameter(int i) const { return i < thetaCount() ? theta_[i] : phi_[i - thetaCount()]; }
  const GapProblem& problem() const { return problem_; }

  // Data residuals at u (theta then phi, scaled); false when not evaluable.
  bool residuals(const double* u, double* r) const;
  // Central differences with step h in u (one-sided at a bound) for the
  // columns [first, first + count); false when a side cannot be evaluated.
  // Given the residuals r0 at u, forward differences instead (backward at the
  // upper bound): one evaluation per column instead of two.
  bool jacobian(const Eigen::VectorXd& u, int first, int count, double h, Eigen::MatrixXd& jac,
                const Eigen::VectorXd* r0 = nullptr) const;
  // Prior residuals (x - nominal) / priorSigma of the parameters that have one.
  int priorCount() const;
  void priorResiduals(const double* u, double* r) const;
  void priorJacobian(Eigen::MatrixXd& jac) const;  // priorCount x parameterCount

  std::vector<double> thetaX(const Eigen::VectorXd& u) const;
  std::vector<double> phiX(const Eigen::VectorXd& u) const;

 private:
  const GapProblem& problem_;
  std::vector<Scaled> theta_;
  int candidate_;
  std::vector<Scaled> phi_;
  std::vector<int> rows_;
  mutable std::vector<double> theta_buf_, phi_buf_, full_buf_;
};

struct FitOptions {
  int maxIterations = 100;
  // With several starts, each runs at most this many iterations and only the
  // best is then polished to maxIterations (0: every start runs to the end).
  int startIterations = 0;
  double functionTolerance = 1e-10;
  bool covariance = false;  // std errors via ceres::Covariance at the optimum
};

struct FitResult {
  bool ok = false;
  Eigen::VectorXd u;       // optimum in scaled coordinates
  double nll = 0.0;        // 0.5 |r|^2 + 0.5 |prior|^2 (Gaussian NLL up to a constant)
  double chiSquare = 0.0;  // |r|^2 of the data residuals alone
  int starts = 0, feasibleStarts = 0;
  // Covariance (when asked): standard errors in the parameters' own units, or
  // empty with `rankDeficient` and the singular values / null direction of the
  // whitened Jacobian (data and priors) in scaled coordinates.
  std::vector<double> stdErrors;
  bool rankDeficient = false;
  Eigen::VectorXd singularValues;
  Eigen::VectorXd nullDirection;
};

// Multistart bounded Levenberg-Marquardt fit (Ceres, one parameter block per
// parameter, priors as residual blocks). Every start is tried; the lowest NLL
// wins. Starts are clipped to the box.
FitResult fitModel(const Model& model, const std::vector<Eigen::VectorXd>& starts, const FitOptions& options);

// Uniform draw in the box (normal with sd 1 in u on an unbounded side).
Eigen::VectorXd randomStart(const Model& model, std::mt19937_64& rng);
Eigen::VectorXd clipToBox(const Model& model, Eigen::VectorXd u);

// Starts from a grid along parameters [first, first + count) of u: each free
// one in turn at u + t (bound - u), t = 1/64 ... 1 towards either bound, the
// rest where u has them; every local minimum of the data cost along the grid
// is a start, the `maxStarts` lowest returned. An effect size that moves a
// resonance past a few lines has a local minimum at nominal that a local fit
// never leaves (a clamp spring at half its stiffness); beside another effect
// fitted alone, which has absorbed part of it, the right basin need not even
// be lower than nominal, so minima count, not only points below u; `below`
// keeps only minima whose data cost is lower than it.
std::vector<Eigen::VectorXd> gridStarts(const Model& model, Eigen::Index first, Eigen::Index count,
                                        const Eigen::VectorXd& u, int maxStarts,
                                        double below = std::numeric_limits<double>::infinity());

// Sum of squared data residuals of `model` at u (prior rows aside); +inf
// where the model cannot be evaluated. `r` is the work buffer.
double dataCost(const Model& model, const Eigen::VectorXd& u, Eigen::VectorXd& r);

}  // namespace mozzi::core::gap::engine
