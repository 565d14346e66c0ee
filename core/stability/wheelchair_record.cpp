#include "core/stability/wheelchair_record.h"

#include <nlohmann/json.hpp>

#include "core/io/project_store.h"

namespace mozzi::core::stability {

namespace {

using Json = nlohmann::json;

// The history's columns: key and member, in the order of `mozzi-cli
// wheelchair slalom --out`.
const std::vector<std::pair<const char*, double WheelchairState::*>>& historyColumns() {
  static const std::vector<std::pair<const char*, double WheelchairState::*>> columns = {
      {"t_s", &WheelchairState::t},
      {"x_m", &WheelchairState::x},
      {"y_m", &WheelchairState::y},
      {"psi_rad", &WheelchairState::psi},
      {"u_m_s", &WheelchairState::u},
      {"v_m_s", &WheelchairState::v},
      {"r_rad_s", &WheelchairState::r},
      {"caster_right_rad", &WheelchairState::deltaRight},
      {"caster_left_rad", &WheelchairState::deltaLeft},
      {"slip_right_rad", &WheelchairState::slipRight},
      {"slip_left_rad", &WheelchairState::slipLeft},
      {"torque_right_nm", &WheelchairState::torqueRight},
      {"torque_left_nm", &WheelchairState::torqueLeft}};
  return columns;
}

const std::vector<std::pair<const char*, double WheelchairParameters::*>>& chairFields() {
  static const std::vector<std::pair<const char*, double WheelchairParameters::*>> fields = {
      {"mass_kg", &WheelchairParameters::mass},
      {"yaw_inertia_kgm2", &WheelchairParameters::yawInertia},
      {"rear_axle_behind_m", &WheelchairParameters::rearAxleBehindCoM},
      {"caster_ahead_m", &WheelchairParameters::casterAheadOfCoM},
      {"rear_half_track_m", &WheelchairParameters::rearHalfTrack},
      {"caster_half_track_m", &WheelchairParameters::casterHalfTrack},
      {"caster_trail_m", &WheelchairParameters::casterTrail},
      {"rear_wheel_radius_m", &WheelchairParameters::rearWheelRadius},
      {"rear_wheel_spin_inertia_kgm2", &WheelchairParameters::rearWheelSpinInertia},
      {"rear_cornering_stiffness_N_per_rad", &WheelchairParameters::rearCorneringStiffness},
      {"rear_aligning_stiffness_Nm_per_rad", &WheelchairParameters::rearAligningStiffness},
      {"caster_cornering_stiffness_N_per_rad", &WheelchairParameters::casterCorneringStiffness},
      {"caster_aligning_stiffness_Nm_per_rad", &WheelchairParameters::casterAligningStiffness}};
  return fields;
}

const std::vector<std::pair<const char*, double WheelchairStudy::*>>& studyNumbers() {
  static const std::vector<std::pair<const char*, double WheelchairStudy::*>> fields = {
      {"speed_m_s", &WheelchairStudy::speed},
      {"torque_nm", &WheelchairStudy::torque},
      {"frequency_hz", &WheelchairStudy::frequency},
      {"duration_s", &WheelchairStudy::duration},
      {"ramp_s", &WheelchairStudy::ramp}};
  return fields;
}

Error missing(const std::string& what, const std::string& where) {
  return makeError(ErrorCode::InvalidArgument, "no " + what, where);
}

}  // namespace

std::vector<double> studyFactors(const std::string& study) {
  return study == "none" ? std::vector<double>{1.0} : std::vector<double>{0.5, 1.0, 2.0};
}

Result<WheelchairRecord> runWheelchairStudy(const WheelchairStudy& s) {
  if (s.manoeuvre != "slalom" && s.manoeuvre != "steady turning")
    return makeError(ErrorCode::InvalidArgument, "'" + s.manoeuvre + "' is neither slalom nor steady turning",
                     "manoeuvre");
  if (s.study != "none" && s.study != "cornering stiffness" && s.study != "aligning stiffness")
    return makeError(ErrorCode::InvalidArgument, "'" + s.study + "' is not a stiffness study", "study");
  WheelchairRecord out;
  out.study = s;
  for (double factor : studyFactors(s.study)) {
    WheelchairParameters p = s.chair;
    if (s.study == "cornering stiffness") p.rearCorneringStiffness *= factor;  // thesis Figures 57, 58
    if (s.study == "aligning stiffness") p.rearAligningStiffness *= factor;    // thesis Figures 59, 60
    WheelchairRun run{factor, {}};
    if (s.manoeuvre == "slalom") {
      MOZZI_TRY_ASSIGN(auto r, runSlalom(p, s.speed, s.torque, s.frequency, s.duration));
      run.history = std::move(r.history);
    } else {
      MOZZI_TRY_ASSIGN(auto r, simulate(p, steadyTurningManoeuvre(s.speed, s.torque, s.ramp, s.duration)));
      run.history = std::move(r);
    }
    out.runs.push_back(std::move(run));
  }
  return out;
}

std::string wheelchairRecordJson(const WheelchairRecord& r) {
  Json j;
  j["format"] = "mozzi-wheelchair-1";
  j["manoeuvre"] = r.study.manoeuvre;
  j["study"] = r.study.study;
  for (const auto& [key, member] : studyNumbers()) j[key] = r.study.*member;
  Json chair = Json::object();
  for (const auto& [key, member] : chairFields()) chair[key] = r.study.chair.*member;
  j["chair"] = chair;
  j["runs"] = Json::array();
  for (const auto& run : r.runs) {
    Json history = Json::object();
    for (const auto& [key, member] : historyColumns()) {
      Json column = Json::array();
      for (const auto& s : run.history) column.push_back(s.*member);
      history[key] = std::move(column);
    }
    j["runs"].push_back({{"factor", run.factor}, {"history", std::move(history)}});
  }
  return j.dump();
}

Result<WheelchairRecord> wheelchairRecordFromJson(const std::string& text) {
  const std::string where = "wheelchair record";
  const Json j = Json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object())
    return makeError(ErrorCode::InvalidArgument, "the result is not a JSON object", where);
  WheelchairRecord r;
  for (const char* key : {"manoeuvre", "study"})
    if (!j.contains(key) || !j.at(key).is_string()) return missing(std::string("text '") + key + "'", where);
  r.study.manoeuvre = j.at("manoeuvre").get<std::string>();
  r.study.study = j.at("study").get<std::string>();
  for (const auto& [key, member] : studyNumbers()) {
    if (!j.contains(key) || !j.at(key).is_number()) return missing(std::string("number '") + key + "'", where);
    r.study.*member = j.at(key).get<double>();
  }
  if (!j.contains("chair") || !j.at("chair").is_object()) return missing("'chair'", where);
  for (const auto& [key, member] : chairFields()) {
    const Json& chair = j.at("chair");
    if (!chair.contains(key) || !chair.at(key).is_number())
      return missing(std::string("number '") + key + "'", where + ", chair");
    r.study.chair.*member = chair.at(key).get<double>();
  }
  if (!j.contains("runs") || !j.at("runs").is_array() || j.at("runs").empty()) return missing("'runs'", where);
  for (std::size_t k = 0; k < j.at("runs").size(); ++k) {
    const Json& run = j.at("runs").at(k);
    const std::string at = where + ", runs[" + std::to_string(k) + "]";
    if (!run.contains("factor") || !run.at("factor").is_number()) return missing("number 'factor'", at);
    if (!run.contains("history") || !run.at("history").is_object()) return missing("'history'", at);
    const Json& h = run.at("history");
    WheelchairRun out{run.at("factor").get<double>(), {}};
    std::size_t length = 0;
    bool first = true;
    for (const auto& [key, member] : historyColumns()) {
      if (!h.contains(key) || !h.at(key).is_array()) return missing(std::string("column '") + key + "'", at);
      const Json& column = h.at(key);
      if (first) {
        length = column.size();
        out.history.resize(length);
        first = false;
      } else if (column.size() != length) {
        return makeError(ErrorCode::InvalidArgument, std::string("column '") + key + "' differs in length", at);
      }
      for (std::size_t i = 0; i < length; ++i) {
        if (!column.at(i).is_number())
          return makeError(ErrorCode::InvalidArgument, "not a number", at + ", " + key + "[" + std::to_string(i) + "]");
        out.history[i].*member = column.at(i).get<double>();
      }
    }
    r.runs.push_back(std::move(out));
  }
  return r;
}

Result<io::StoredAnalysis> wheelchairAnalysis(const io::ProjectStore& store, std::int64_t specimenId,
                                              const std::string& name, const WheelchairRecord& record) {
  return resultAnalysis(store, specimenId, name, kWheelchairAnalysisKind, "wheelchair result name",
                        wheelchairRecordJson(record));
}

Result<std::int64_t> storeWheelchairRecord(io::ProjectStore& store, std::int64_t specimenId, const std::string& name,
                                           const WheelchairRecord& record) {
  MOZZI_TRY_ASSIGN(const io::StoredAnalysis a, wheelchairAnalysis(store, specimenId, name, record));
  return store.addAnalysis(a);
}

Result<std::int64_t> defaultWheelchairSpecimen(const io::ProjectStore& store) {
  return defaultSpecimenOfKind(store, "wheelchair-tyre");
}

Result<std::vector<StoredWheelchair>> storedWheelchairRecords(const io::ProjectStore& store,
                                                              std::vector<std::int64_t>* unreadable) {
  return storedResults<WheelchairRecord>(store, kWheelchairAnalysisKind, wheelchairRecordFromJson, unreadable);
}

Result<StoredWheelchair> storedWheelchairRecord(const io::ProjectStore& store, std::int64_t analysisId) {
  return storedResult<WheelchairRecord>(store, analysisId, kWheelchairAnalysisKind, "wheelchair result",
                                        wheelchairRecordFromJson);
}

}  // namespace mozzi::core::stability
