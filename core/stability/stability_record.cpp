#include "core/stability/stability_record.h"

#include <cstdio>

#include "core/io/project_store.h"

namespace mozzi::core::stability {

namespace {

using Json = nlohmann::json;

bool isCrossing(const std::string& kind) {
  return kind == "stabilises" || kind == "destabilises";
}

Result<double> numberAt(const Json& j, const char* key, const std::string& where) {
  if (!j.is_object() || !j.contains(key) || !j.at(key).is_number())
    return makeError(ErrorCode::InvalidArgument, std::string("no number '") + key + "'", where);
  return j.at(key).get<double>();
}

Result<std::string> textAt(const Json& j, const char* key, const std::string& where) {
  if (!j.is_object() || !j.contains(key) || !j.at(key).is_string())
    return makeError(ErrorCode::InvalidArgument, std::string("no text '") + key + "'", where);
  return j.at(key).get<std::string>();
}

std::string optionalText(const Json& j, const char* key) {
  return j.contains(key) && j.at(key).is_string() ? j.at(key).get<std::string>() : std::string();
}

}  // namespace

Json sweepJson(const std::string& model, const StabilitySweep& sweep) {
  Json j;
  j["model"] = model;
  j["speeds"] = Json::array();
  for (const auto& p : sweep.points) {
    Json modes = Json::array();
    for (const auto& r : p.roots) modes.push_back({{"name", r.name}, {"re", r.lambda.real()}, {"im", r.lambda.imag()}});
    j["speeds"].push_back({{"v", p.v}, {"modes", modes}});
  }
  Json critical = Json::object();
  for (const char* name : {"weave", "capsize", "wobble"}) critical[name] = nullptr;
  for (const auto& e : sweep.events) {
    if (!isCrossing(e.kind)) continue;
    if (critical.contains(e.mode) && !critical[e.mode].is_null()) continue;
    critical[e.mode] = e.v;
  }
  j["critical_speeds"] = critical;
  j["events"] = Json::array();
  for (const auto& e : sweep.events) {
    Json ev = {{"mode", e.mode}, {"v", e.v}, {"kind", e.kind}};
    if (e.kind == "pair born" || e.kind == "pair splits") ev["lambda"] = e.lambda;
    if (isCrossing(e.kind)) ev["im"] = e.frequency;
    j["events"].push_back(ev);
  }
  return j;
}

Result<StabilitySweep> sweepFromJson(const Json& j) {
  const std::string where = "stability sweep";
  if (!j.is_object() || !j.contains("speeds") || !j.at("speeds").is_array())
    return makeError(ErrorCode::InvalidArgument, "no 'speeds' array", where);
  StabilitySweep s;
  for (std::size_t k = 0; k < j.at("speeds").size(); ++k) {
    const Json& p = j.at("speeds").at(k);
    const std::string at = where + ", speeds[" + std::to_string(k) + "]";
    MOZZI_TRY_ASSIGN(const double v, numberAt(p, "v", at));
    if (!p.contains("modes") || !p.at("modes").is_array())
      return makeError(ErrorCode::InvalidArgument, "no 'modes' array", at);
    SpeedPoint point;
    point.v = v;
    for (const Json& m : p.at("modes")) {
      MOZZI_TRY_ASSIGN(std::string name, textAt(m, "name", at));
      MOZZI_TRY_ASSIGN(const double re, numberAt(m, "re", at));
      MOZZI_TRY_ASSIGN(const double im, numberAt(m, "im", at));
      Root r;
      r.lambda = Complex(re, im);
      r.name = std::move(name);
      point.roots.push_back(std::move(r));
    }
    s.points.push_back(std::move(point));
  }
  if (j.contains("events") && j.at("events").is_array()) {
    for (std::size_t k = 0; k < j.at("events").size(); ++k) {
      const Json& e = j.at("events").at(k);
      const std::string at = where + ", events[" + std::to_string(k) + "]";
      MOZZI_TRY_ASSIGN(std::string mode, textAt(e, "mode", at));
      MOZZI_TRY_ASSIGN(std::string kind, textAt(e, "kind", at));
      MOZZI_TRY_ASSIGN(const double v, numberAt(e, "v", at));
      ModeEvent event{std::move(mode), v, std::move(kind), 0.0, 0.0};
      if (e.contains("lambda") && e.at("lambda").is_number()) event.lambda = e.at("lambda").get<double>();
      if (e.contains("im") && e.at("im").is_number()) event.frequency = e.at("im").get<double>();
      s.events.push_back(std::move(event));
    }
  }
  return s;
}

std::string stabilityRecordJson(const StabilityRecord& r) {
  Json j;
  j["format"] = "mozzi-stability-1";
  j["vehicle"] = r.vehicle;
  j["model"] = r.model;
  j["fork"] = r.fork;
  j["fork_source"] = r.forkSource;
  j["parameters_file"] = r.parametersFile;
  j["speed_grid"] = {{"from_m_s", r.from}, {"to_m_s", r.to}, {"step_m_s", r.step}};
  j["sweep"] = sweepJson(r.model, r.sweep);
  if (r.rigidSweep) j["rigid_sweep"] = sweepJson(r.model + ", rigid fork", *r.rigidSweep);
  return j.dump();
}

Result<StabilityRecord> stabilityRecordFromJson(const std::string& text) {
  const std::string where = "stability record";
  const Json j = Json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object())
    return makeError(ErrorCode::InvalidArgument, "the result is not a JSON object", where);
  StabilityRecord r;
  MOZZI_TRY_ASSIGN(r.vehicle, textAt(j, "vehicle", where));
  MOZZI_TRY_ASSIGN(r.model, textAt(j, "model", where));
  if (r.vehicle != "bicycle" && r.vehicle != "motorcycle")
    return makeError(ErrorCode::InvalidArgument, "vehicle '" + r.vehicle + "' is neither bicycle nor motorcycle",
                     where);
  r.fork = optionalText(j, "fork");
  r.forkSource = optionalText(j, "fork_source");
  r.parametersFile = optionalText(j, "parameters_file");
  if (j.contains("speed_grid")) {
    const Json& g = j.at("speed_grid");
    MOZZI_TRY_ASSIGN(r.from, numberAt(g, "from_m_s", where + ", speed_grid"));
    MOZZI_TRY_ASSIGN(r.to, numberAt(g, "to_m_s", where + ", speed_grid"));
    MOZZI_TRY_ASSIGN(r.step, numberAt(g, "step_m_s", where + ", speed_grid"));
  }
  if (!j.contains("sweep")) return makeError(ErrorCode::InvalidArgument, "no 'sweep'", where);
  MOZZI_TRY_ASSIGN(r.sweep, sweepFromJson(j.at("sweep")));
  if (r.sweep.points.empty()) return makeError(ErrorCode::InvalidArgument, "the sweep has no speeds", where);
  if (j.contains("rigid_sweep")) {
    MOZZI_TRY_ASSIGN(r.rigidSweep, sweepFromJson(j.at("rigid_sweep")));
  }
  return r;
}

std::string criticalSpeedText(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.6f", v);
  return text;
}

std::string crossingFrequencyText(double imaginary) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3f", imaginary);
  return text;
}

Result<std::int64_t> defaultStabilitySpecimen(const io::ProjectStore& store, const std::string& vehicle) {
  return defaultSpecimenOfKind(store, vehicle == "motorcycle" ? "fork" : "bicycle-fork");
}

Result<std::int64_t> specimenNamed(const io::ProjectStore& store, const std::string& name) {
  MOZZI_TRY_ASSIGN(const auto summary, store.summary());
  for (const auto& s : summary.specimens)
    if (s.name == name) return s.id;
  return makeError(ErrorCode::NotFound, "no specimen named '" + name + "'", store.path());
}

Result<io::StoredAnalysis> stabilityAnalysis(const io::ProjectStore& store, std::int64_t specimenId,
                                             const std::string& name, const StabilityRecord& record) {
  return resultAnalysis(store, specimenId, name, kStabilityAnalysisKind, "stability result name",
                        stabilityRecordJson(record));
}

Result<std::int64_t> storeStabilityRecord(io::ProjectStore& store, std::int64_t specimenId, const std::string& name,
                                          const StabilityRecord& record) {
  MOZZI_TRY_ASSIGN(const io::StoredAnalysis a, stabilityAnalysis(store, specimenId, name, record));
  return store.addAnalysis(a);
}

Result<std::vector<StoredStability>> storedStabilityRecords(const io::ProjectStore& store,
                                                            std::vector<std::int64_t>* unreadable) {
  return storedResults<StabilityRecord>(store, kStabilityAnalysisKind, stabilityRecordFromJson, unreadable);
}

Result<StoredStability> storedStabilityRecord(const io::ProjectStore& store, std::int64_t analysisId) {
  return storedResult<StabilityRecord>(store, analysisId, kStabilityAnalysisKind, "stability result",
                                       stabilityRecordFromJson);
}

}  // namespace mozzi::core::stability
