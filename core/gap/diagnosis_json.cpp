#include "core/gap/diagnosis_json.h"

#include <algorithm>
#include <cmath>

namespace mozzi::core::gap {

namespace {

// JSON has no NaN or infinity: a figure that is not available is null.
nlohmann::json number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

nlohmann::json entryToJson(const GapEntry& e) {
  nlohmann::json j{
      {"kind", e.kind}, {"label", e.label}, {"value", number(e.value)}, {"z", number(e.z)}, {"flagged", e.flagged}};
  for (const auto& [name, value] : e.details) j[name] = number(value);
  return j;
}

// "band" -> "bands": the groups the issue names (bands, dofs, modes, conditions).
nlohmann::json groupByKind(const std::vector<GapEntry>& entries) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& e : entries) j[e.kind + "s"].push_back(entryToJson(e));
  return j;
}

nlohmann::json named(const std::vector<Parameter>& defs, const std::vector<double>& values) {
  nlohmann::json j = nlohmann::json::object();
  for (std::size_t i = 0; i < defs.size() && i < values.size(); ++i) j[defs[i].name] = number(values[i]);
  return j;
}

nlohmann::json effectToJson(const RankedEffect& e, double threshold) {
  nlohmann::json j{
      {"effect", e.candidate.effect},
      {"location", e.candidate.location},
      {"parameters", named(e.candidate.parameters, e.parameters)},
      {"units", nlohmann::json::object()},
      {"std_errors", e.stdErrors.empty() ? nlohmann::json(nullptr) : named(e.candidate.parameters, e.stdErrors)},
      {"identifiable", e.identifiable},
      {"criterion",
       {{"likelihood_ratio", number(e.likelihoodRatio)},
        {"threshold", number(threshold)},
        {"aicc", e.fitted ? number(e.aicc) : nlohmann::json(nullptr)},
        {"held_out_improvement", number(e.heldOutImprovement)},
        {"chi_square", e.fitted ? number(e.chiSquare) : nlohmann::json(nullptr)},
        {"fit_p_value", e.fitted ? number(e.fitPValue) : nlohmann::json(nullptr)},
        {"projected_signature", number(e.projectedSignature)}}},
      {"smallest_detectable", named(e.candidate.parameters, e.smallestDetectable)},
      {"calibration", e.theta},
      {"gap_after",
       e.gapAfter.entries.empty() && e.gapAfter.overall == 0.0 ? nlohmann::json(nullptr) : metricsToJson(e.gapAfter)},
      {"shrink_pct",
       e.gapAfter.entries.empty() && e.gapAfter.overall == 0.0 ? nlohmann::json(nullptr) : number(e.shrinkPct)}};
  for (const auto& p : e.candidate.parameters) j["units"][p.name] = p.unit;
  if (!e.candidate.equivalent.empty()) j["equivalent_locations"] = e.candidate.equivalent;
  // Wald 95% interval (size +- 1.96 se), clipped to the parameter's bounds.
  nlohmann::json interval = nullptr;
  if (e.stdErrors.size() == e.parameters.size() && e.parameters.size() == e.candidate.parameters.size()) {
    interval = nlohmann::json::object();
    for (std::size_t i = 0; i < e.parameters.size(); ++i) {
      const Parameter& p = e.candidate.parameters[i];
      interval[p.name] = {number(std::max(p.lower, e.parameters[i] - 1.959964 * e.stdErrors[i])),
                          number(std::min(p.upper, e.parameters[i] + 1.959964 * e.stdErrors[i]))};
    }
  }
  j["interval_95"] = interval;
  nlohmann::json profile = nullptr;
  if (e.profileInterval.size() == e.candidate.parameters.size() && !e.profileInterval.empty()) {
    profile = nlohmann::json::object();
    for (std::size_t i = 0; i < e.profileInterval.size(); ++i) {
      profile[e.candidate.parameters[i].name] = {number(e.profileInterval[i].first),
                                                 number(e.profileInterval[i].second)};
    }
  }
  j["profile_interval_95"] = profile;
  if (!e.note.empty()) j["note"] = e.note;
  return j;
}

nlohmann::json noiseToJson(const NoiseModel& n) {
  nlohmann::json entries = nlohmann::json::array();
  for (const auto& e : n.entries) {
    entries.push_back({{"label", e.label},
                       {"band", e.band.empty() ? nlohmann::json(nullptr) : nlohmann::json(e.band)},
                       {"relative", number(e.relative)},
                       {"floor", number(e.floor)},
                       {"unit", e.unit},
                       {"lines", e.lines}});
  }
  return {{"source", n.source}, {"estimated", n.estimated}, {"description", n.description}, {"entries", entries}};
}

nlohmann::json pairToJson(const Diagnosis& d) {
  if (!d.pairFitted) return nullptr;
  const EffectPair& p = d.pair;
  nlohmann::json effects = nlohmann::json::array();
  for (const auto& e : p.effects) {
    nlohmann::json j{
        {"effect", e.candidate.effect},
        {"location", e.candidate.location},
        {"parameters", named(e.candidate.parameters, e.parameters)},
        {"units", nlohmann::json::object()},
        {"std_errors", e.stdErrors.empty() ? nlohmann::json(nullptr) : named(e.candidate.parameters, e.stdErrors)}};
    for (const auto& q : e.candidate.parameters) j["units"][q.name] = q.unit;
    if (!e.candidate.equivalent.empty()) j["equivalent_locations"] = e.candidate.equivalent;
    effects.push_back(j);
  }
  if (effects.empty()) return {{"pairs_fitted", p.pairsFitted}, {"effects", effects}};
  return {{"pairs_fitted", p.pairsFitted},
          {"effects", effects},
          {"significant", p.significant},
          {"likelihood_ratio", number(p.likelihoodRatio)},
          {"likelihood_ratio_each", {number(p.eachRatio[0]), number(p.eachRatio[1])}},
          {"threshold", number(d.threshold)},
          {"chi_square", number(p.chiSquare)},
          {"fit_p_value", number(p.fitPValue)},
          {"held_out_improvement", number(p.heldOutImprovement)},
          {"calibration", p.theta},
          {"gap_before", number(d.gapBefore.overall)},
          {"gap_after_one", number(p.gapAfterOne.overall)},
          {"gap_after_both", number(p.gapAfterBoth.overall)},
          {"shrink_one_pct", number(p.shrinkOnePct)},
          {"shrink_both_pct", number(p.shrinkBothPct)},
          {"gap_after_both_detail", metricsToJson(p.gapAfterBoth)}};
}

}  // namespace

nlohmann::json metricsToJson(const GapMetrics& metrics) {
  nlohmann::json j = groupByKind(metrics.entries);
  j[metrics.residualName] = number(metrics.overall);
  j["residual_name"] = metrics.residualName;
  j["overall"] = number(metrics.overall);
  return j;
}

nlohmann::json diagnosisToJson(const Diagnosis& d) {
  nlohmann::json ranking = nlohmann::json::array();
  for (const auto& e : d.ranking) ranking.push_back(effectToJson(e, d.threshold));
  nlohmann::json best(nullptr);
  if (!d.verdictSet.empty())
    best = effectToJson(d.ranking[static_cast<std::size_t>(d.verdictSet.front())], d.threshold);
  nlohmann::json calibration = nlohmann::json::object();
  for (std::size_t i = 0; i < d.calibration.size() && i < d.calibrated.size(); ++i) {
    calibration[d.calibration[i].name] = {{"value", number(d.calibrated[i])},
                                          {"nominal", number(d.calibration[i].nominal)},
                                          {"unit", d.calibration[i].unit}};
  }
  return nlohmann::json{{"data_kind", d.dataKind},
                        {"calibration", calibration},
                        {"goodness_of_fit",
                         {{"chi_square", number(d.chiSquare)},
                          {"dof", d.dof},
                          {"p_value", number(d.fitPValue)},
                          {"method", d.fitFromBootstrap ? "bootstrap" : "chi_square"},
                          {"null_mean", d.fitFromBootstrap ? number(d.nullChiSquareMean) : nlohmann::json(nullptr)},
                          {"null_sd", d.fitFromBootstrap ? number(d.nullChiSquareSd) : nlohmann::json(nullptr)}}},
                        {"noise_model", noiseToJson(d.noise)},
                        {"two_effects", pairToJson(d)},
                        {"gap_before", metricsToJson(d.gapBefore)},
                        {"where", groupByKind(d.where)},
                        {"verdict", verdictName(d.verdict)},
                        {"verdict_set", d.verdictSet},
                        {"threshold",
                         {{"likelihood_ratio", number(d.threshold)},
                          {"bootstrap_samples", d.bootstrapSamples},
                          {"method", d.thresholdLinearised ? "linearised" : "full_refit"}}},
                        {"flip_probability", d.flipProbability >= 0.0 ? number(d.flipProbability) : nullptr},
                        {"separating_measurement", d.separatingMeasurement},
                        {"ranking", ranking},
                        {"best", best},
                        {"explanation", d.explanation}};
}

}  // namespace mozzi::core::gap
