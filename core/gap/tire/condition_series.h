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
  bool residuals(const ModelPoint& at, double* r) const override;
  std::vector<int> folds() const override;
  std::unique_ptr<GapProblem> simulated(const ModelPoint& at, std::mt19937_64& rng) const override;
  GapMetrics metrics(const ModelPoint& at) const override;

  // The prediction at every point, in the points' unit; NaN where the model
  // cannot be evaluated (residuals() then returns false).
  virtual std::vector<double> predict(const ModelPoint& at) const = 0;
  const std::vector<ConditionPoint>& points() const { return points_; }

 protected:
  // residualName: what the metrics' `overall` measures ("relaxation_residual").
  ConditionSeriesProblem(std::vector<ConditionPoint> points, std::string residualName)
      : points_(std::move(points)), residualName_(std::move(residualName)) {}
  // The same problem with other measured values (same layout).
  virtual std::unique_ptr<GapProblem> withPoints(std::vector<ConditionPoint> points) const = 0;
  // Extra named figures per point for the metrics rows; empty for none.
  virtual std::vector<std::vector<std::pair<std::string, double>>> details(const ModelPoint& at) const;

  std::vector<ConditionPoint> points_;

 private:
  std::string residualName_;
};

// A condition-series problem from its two files (the tyre and stability
// loaders): the model file's text parsed by parseModel(text); the measured
// file's rows parsed by parseRows(text, measuredPath) and kept where
// conditionOf(row) (pressure, speed) lies in [lo, hi], an InvalidArgument
// naming the file when none is; then Problem::create(model, rows).
template <class Problem, class Row, class ParseModel, class ParseRows, class ConditionOf>
Result<std::unique_ptr<GapProblem>> loadConditionSeriesProblem(const std::string& modelPath, ParseModel parseModel,
                                                               const std::string& measuredPath, ParseRows parseRows,
                                                               ConditionOf conditionOf, double lo, double hi,
                                                               const std::string& conditionName) {
  MOZZI_TRY_ASSIGN(const std::string modelText, readTextFile(modelPath));
  MOZZI_TRY_ASSIGN(auto model, parseModel(modelText));
  MOZZI_TRY_ASSIGN(const std::string measuredText, readTextFile(measuredPath));
  MOZZI_TRY_ASSIGN(const std::vector<Row> rows, parseRows(measuredText, measuredPath));
  std::vector<Row> kept;
  for (const Row& row : rows)
    if (conditionOf(row) >= lo && conditionOf(row) <= hi) kept.push_back(row);
  if (kept.empty()) {
    return makeError(ErrorCode::InvalidArgument, "no measured " + conditionName + " inside the selected range",
                     measuredPath);
  }
  MOZZI_TRY_ASSIGN(auto problem, Problem::create(std::move(model), std::move(kept)));
  return std::unique_ptr<GapProblem>(std::move(problem));
}

}  // namespace mozzi::core::gap
