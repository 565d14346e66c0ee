#include "core/gap/tire/condition_series.h"

#include "core/gap/engine/statistics.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace mozzi::core::gap {

Result<std::string> readTextFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return makeError(ErrorCode::IoError, "cannot open file", path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool whitenedResiduals(const std::vector<ConditionPoint>& points, const std::vector<double>& predicted, double* r) {
  for (std::size_t j = 0; j < points.size(); ++j) {
    if (!std::isfinite(predicted[j])) return false;
    r[j] = (predicted[j] - points[j].measured) / points[j].sigma;
  }
  return true;
}

GapMetrics conditionMetrics(const std::vector<ConditionPoint>& points, const std::vector<double>& predicted,
                            const std::string& residualName,
                            const std::vector<std::vector<std::pair<std::string, double>>>& extraDetails,
                            double alpha) {
  GapMetrics m;
  m.residualName = residualName;
  double sumRel2 = 0.0;
  for (std::size_t j = 0; j < points.size(); ++j) {
    const auto& pt = points[j];
    const double d = predicted[j] - pt.measured;
    if (pt.measured != 0.0) sumRel2 += (d / pt.measured) * (d / pt.measured);
    GapEntry e;
    e.kind = "condition";
    e.label = pt.label;
    e.value = pt.measured != 0.0 ? 100.0 * d / std::abs(pt.measured) : 0.0;
    e.z = d / pt.sigma;
    e.details = {{"measured", pt.measured}, {"predicted", predicted[j]}, {"uncertainty", pt.sigma}};
    if (j < extraDetails.size()) e.details.insert(e.details.end(), extraDetails[j].begin(), extraDetails[j].end());
    m.entries.push_back(std::move(e));
  }
  applyHolmFlags(m, alpha);
  m.overall = points.empty() ? 0.0 : std::sqrt(sumRel2 / static_cast<double>(points.size()));
  return m;
}

std::vector<ConditionPoint> simulatedPoints(const std::vector<ConditionPoint>& points,
                                            const std::vector<double>& predicted, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<ConditionPoint> out = points;
  for (std::size_t j = 0; j < out.size(); ++j) out[j].measured = predicted[j] + out[j].sigma * noise(rng);
  return out;
}

bool ConditionSeriesProblem::residuals(const ModelPoint& at, double* r) const {
  return whitenedResiduals(points_, predict(at), r);
}

std::vector<int> ConditionSeriesProblem::folds() const {
  std::vector<int> f;
  for (const auto& p : points_) f.push_back(p.fold);
  return f;
}

std::unique_ptr<GapProblem> ConditionSeriesProblem::simulated(const ModelPoint& at, std::mt19937_64& rng) const {
  return withPoints(simulatedPoints(points_, predict(at), rng));
}

GapMetrics ConditionSeriesProblem::metrics(const ModelPoint& at) const {
  return conditionMetrics(points_, predict(at), residualName_, details(at));
}

std::vector<std::vector<std::pair<std::string, double>>> ConditionSeriesProblem::details(const ModelPoint&) const {
  return {};
}

}  // namespace mozzi::core::gap
