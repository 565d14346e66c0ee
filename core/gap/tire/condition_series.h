#pragma once
// Scalar measurements against an operating condition (tyre relaxation length
// against inflation pressure, stability-mode frequency against speed, a fork's
// frequency and static stiffness): the parts the tyre, stability and fork gap
// problems share — a small numeric CSV reader, whitened residuals, the "where"
// table per condition with Holm-corrected flags (shared/GAP.md step 2) and the
// parametric-bootstrap copy of the data.

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

// Header row of names, comma separated, '#' comments, every cell a finite
// number except in the columns named in textColumns (kept as text, non-empty;
// their numeric cell is 0). Errors name the file and line.
struct NumericTable {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  std::vector<std::vector<std::string>> text;  // per row, the cells of the text columns in textColumns order
  std::vector<int> lines;                      // file line of each row
  int column(const std::string& name) const;
};
Result<NumericTable> readNumericCsv(const std::string& text, const std::string& source,
                                    const std::vector<std::string>& required,
                                    const std::vector<std::string>& textColumns = {});
// The whole file as text (IoError naming the path).
Result<std::string> readTextFile(const std::string& path);

// r_j = (predicted_j - measured_j) / sigma_j. False when a prediction is not finite.
bool whitenedResiduals(const std::vector<ConditionPoint>& points, const std::vector<double>& predicted, double* r);

// Per-condition rows: value = relative error [%], z = (predicted - measured) /
// sigma, flagged by Holm's step-down procedure at level alpha over the rows;
// details "measured", "predicted", "uncertainty" plus any extra per-row figures.
// overall = |predicted - measured| / |measured| (relative residual norm).
GapMetrics conditionMetrics(const std::vector<ConditionPoint>& points, const std::vector<double>& predicted,
                            const std::string& residualName,
                            const std::vector<std::vector<std::pair<std::string, double>>>& extraDetails = {},
                            double alpha = 0.05);

// Holm (1979) step-down over the entries' |z| (two-sided normal p-values).
void holmFlags(std::vector<GapEntry>& entries, double alpha);

// measured_j <- predicted_j + N(0, sigma_j).
std::vector<ConditionPoint> simulatedPoints(const std::vector<ConditionPoint>& points,
                                            const std::vector<double>& predicted, std::mt19937_64& rng);

}  // namespace mozzi::core::gap
