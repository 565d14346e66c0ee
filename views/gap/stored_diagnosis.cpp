#include "views/gap/stored_diagnosis.h"

#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>

namespace mozzi::views {

namespace {

using Json = nlohmann::json;

// JSON writes a figure that is not available as null (diagnosis_json.cpp).
double numberOr(const Json& j, const char* key, double fallback = 0.0) {
  if (!j.is_object() || !j.contains(key) || !j[key].is_number()) return fallback;
  return j[key].get<double>();
}

std::string textOr(const Json& j, const char* key) {
  if (!j.is_object() || !j.contains(key) || !j[key].is_string()) return {};
  return j[key].get<std::string>();
}

std::vector<double> numbers(const Json& j, const char* key) {
  std::vector<double> out;
  if (!j.contains(key) || !j[key].is_array()) return out;
  for (const auto& v : j[key])
    out.push_back(v.is_number() ? v.get<double>() : std::numeric_limits<double>::quiet_NaN());
  return out;
}

// metricsToJson's groups ("bands", "dofs", ...) back into entries; the
// figures beyond kind, label, value, z and flagged are the entry's details.
core::gap::GapMetrics metricsFrom(const Json& j) {
  core::gap::GapMetrics m;
  if (!j.is_object()) return m;
  m.residualName = textOr(j, "residual_name");
  if (m.residualName.empty()) m.residualName = "frf_residual";
  m.overall = numberOr(j, "overall");
  for (const auto& [group, rows] : j.items()) {
    if (!rows.is_array()) continue;
    for (const auto& row : rows) {
      if (!row.is_object()) continue;
      core::gap::GapEntry e;
      e.kind = textOr(row, "kind");
      e.label = textOr(row, "label");
      e.value = numberOr(row, "value");
      e.z = numberOr(row, "z");
      e.flagged = row.value("flagged", false);
      for (const auto& [name, value] : row.items())
        if (value.is_number() && name != "value" && name != "z") e.details.emplace_back(name, value.get<double>());
      m.entries.push_back(std::move(e));
    }
  }
  return m;
}

StoredDiagnosis::RankedEffect effectFrom(const Json& j) {
  StoredDiagnosis::RankedEffect e;
  e.effect = textOr(j, "effect");
  if (j.contains("location") && j["location"].is_array())
    for (const auto& part : j["location"])
      if (part.is_string()) e.location.push_back(part.get<std::string>());
  if (j.contains("equivalent_locations") && j["equivalent_locations"].is_array()) {
    for (const auto& other : j["equivalent_locations"]) {
      if (!other.is_array()) continue;
      std::vector<std::string> at;
      for (const auto& part : other)
        if (part.is_string()) at.push_back(part.get<std::string>());
      if (!at.empty()) e.equivalent.push_back(std::move(at));
    }
  }
  const Json& errors = j.contains("std_errors") ? j["std_errors"] : Json();
  const Json& units = j.contains("units") ? j["units"] : Json();
  if (j.contains("parameters") && j["parameters"].is_object()) {
    for (const auto& [name, value] : j["parameters"].items()) {
      StoredDiagnosis::Parameter p;
      p.name = name;
      p.value = value.is_number() ? value.get<double>() : std::numeric_limits<double>::quiet_NaN();
      p.stdError = numberOr(errors, name.c_str(), -1.0);
      p.unit = textOr(units, name.c_str());
      e.parameters.push_back(std::move(p));
    }
  }
  e.identifiable = j.value("identifiable", true);
  const Json& criterion = j.contains("criterion") ? j["criterion"] : Json();
  // As diagnosis_json.cpp writes them: a figure null is NaN (e.g. no held-out
  // fit for a candidate below the threshold), a shrink null is 0 (no gap after).
  constexpr double kNotAvailable = std::numeric_limits<double>::quiet_NaN();
  e.likelihoodRatio = numberOr(criterion, "likelihood_ratio", kNotAvailable);
  e.heldOutImprovement = numberOr(criterion, "held_out_improvement", kNotAvailable);
  e.shrinkPct = numberOr(j, "shrink_pct", 0.0);
  if (j.contains("gap_after")) e.gapAfter = numberOr(j["gap_after"], "overall");
  return e;
}

}  // namespace

core::Result<StoredDiagnosis> parseStoredDiagnosis(const std::string& resultJson) {
  const Json j = Json::parse(resultJson, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object() || !j.contains("verdict") || !j["verdict"].is_string())
    return core::makeError(core::ErrorCode::InvalidArgument, "the analysis holds no gap diagnosis (no verdict)",
                           "kept gap diagnosis");
  StoredDiagnosis d;
  d.verdict = j["verdict"].get<std::string>();
  d.explanation = textOr(j, "explanation");
  if (j.contains("threshold")) d.threshold = numberOr(j["threshold"], "likelihood_ratio");
  if (j.contains("gap_before")) d.gapBefore = metricsFrom(j["gap_before"]);
  if (j.contains("ranking") && j["ranking"].is_array())
    for (const auto& row : j["ranking"]) d.ranking.push_back(effectFrom(row));
  if (j.contains("verdict_set") && j["verdict_set"].is_array()) {
    for (const auto& index : j["verdict_set"]) {
      if (!index.is_number_integer()) continue;
      const int r = index.get<int>();
      if (r < 0 || r >= static_cast<int>(d.ranking.size())) continue;
      d.ranking[static_cast<std::size_t>(r)].inVerdict = true;
      if (d.best < 0) d.best = r;
    }
  }
  // A verdict of two effects fitted together (diagnosis_json.cpp pairToJson).
  d.pair = j.contains("two_effects") && j["two_effects"].is_object() && j["two_effects"].value("significant", false) &&
           std::count_if(d.ranking.begin(), d.ranking.end(), [](const auto& r) { return r.inVerdict; }) == 2;
  if (d.pair) d.pairHeldOutImprovement = numberOr(j["two_effects"], "held_out_improvement", d.pairHeldOutImprovement);
  if (j.contains("overlay") && j["overlay"].is_array()) {
    for (const auto& c : j["overlay"]) {
      core::gap::OverlayCurve before;
      before.label = textOr(c, "label");
      before.xLabel = textOr(c, "x_label");
      before.yLabel = textOr(c, "y_label");
      before.logY = c.value("log_y", false);
      before.x = numbers(c, "x");
      before.measured = numbers(c, "measured");
      before.predicted = numbers(c, "before");
      core::gap::OverlayCurve after = before;
      after.predicted = numbers(c, "after");
      if (d.afterLabel.empty()) d.afterLabel = textOr(c, "after_label");
      d.before.push_back(std::move(before));
      d.after.push_back(std::move(after));
    }
  }
  return d;
}

}  // namespace mozzi::views
