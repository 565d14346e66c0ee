#pragma once
// Scalar measurements against an operating condition (tyre relaxation length
// against inflation pressure, stability-mode frequency against speed, a fork's
// frequency and static stiffness): the parts the tyre, stability and fork gap
// problems share — whitened residuals, the "where" table per condition with
// Holm-corrected flags (shared/GAP.md step 2), the parametric-bootstrap copy
// of the data, and a GapProblem base that needs only the prediction.

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "core/common/result.h"
#include "core/gap/gap_problem.h"

namespace mozzi::core::gap {

// One measured value at one condition.
struct ConditionPoint {
  std::string label;  // "2 bar", "weave 12.0 m/s"
  double x = 0.0;     // the condition's abscissa in its display unit (bar, m/s)
  double measured = 0.0;
  double sigma = 0.0;  // standard uncertainty, > 0
  int fold = 0;        // held-out group
};

// The whole file as text (IoError naming the path).
Result<std::string> readTextFile(const std::string& path);

// r_j = (predicted_j - measured_j) / sigma_j. False when a prediction is not finite.
bool whitenedResiduals(const std::vector<ConditionPoint>& points, const std::vector<double>& predicted, double* r);

// Per-condition rows: value = relative error [%], z = (predicted - measured) /
// sigma, flagged by Holm's step-down procedure at level alpha over the rows of
// each kind (engine/statistics.h); details "measured", "predicted",
// "uncertainty" plus any extra per-row figures. overall = root mean square of
// the relative errors (dimensionless, so rows in different units combine).
GapMetrics conditionMetrics(const std::vector<ConditionPoint>& points, const std::vector<double>& predicted,
                            const std::string& residualName,
                            const std::vector<std::vector<std::pair<std::string, double>>>& extraDetails = {},
                            double alpha = 0.05);

// measured_j <- predicted_j + N(0, sigma_j).
std::vector<ConditionPoint> simulatedPoints(const std::vector<ConditionPoint>& points,
                                            const std::vector<double>& predicted, std::mt19937_64& rng);

// A gap problem whose data are ConditionPoints: residuals, folds (the points'
// own), the bootstrap copy and the metrics follow from predict().
class ConditionSeriesProblem : public GapProblem {
 public:
  int residualCount() const override { return static_cast<int>(points_.size()); }
  bool residuals(const double* theta, int candidate, const double* phi, double* r) const override;
  std::vector<int> folds() const override;
  std::unique_ptr<GapProblem> simulated(const double* theta, int candidate, const double* phi,
                                        std::mt19937_64& rng) const override;
  GapMetrics metrics(const double* theta, int candidate, const double* phi) const override;

  // The prediction at every point, in the points' unit; NaN where the model
  // cannot be evaluated (residuals() then returns false).
  virtual std::vector<double> predict(const double* theta, int candidate, const double* phi) const = 0;
  const std::vector<ConditionPoint>& points() const { return points_; }

 protected:
  explicit ConditionSeriesProblem(std::vector<ConditionPoint> points) : points_(std::move(points)) {}
  // The same problem with other measured values (same layout).
  virtual std::unique_ptr<GapProblem> withPoints(std::vector<ConditionPoint> points) const = 0;
  virtual std::string residualName() const = 0;
  // Extra named figures per point for the metrics rows; empty for none.
  virtual std::vector<std::vector<std::pair<std::string, double>>> details(const double* theta, int candidate,
                                                                           const double* phi) const;

  std::vector<ConditionPoint> points_;
};

}  // namespace mozzi::core::gap
