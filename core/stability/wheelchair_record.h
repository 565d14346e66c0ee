#pragma once
// Wheelchair manoeuvres the project keeps (issue 22; thesis §7.2 to §7.4,
// Figures 57 to 60): the manoeuvre, the chair, the stiffness study and the
// time history of each run (one per stiffness factor), stored as an analysis
// of kind "wheelchair" whose result_json is written and read here, so the
// Wheelchair page, `mozzi-cli wheelchair slalom --project` and the project
// report (core/report/stability_report.cpp) show the same record. Format:
// docs/formats.md, "Stored stability and wheelchair results".

#include <cstdint>
#include <string>
#include <vector>

#include "core/common/result.h"
#include "core/io/project_records.h"
#include "core/stability/stored_result.h"
#include "core/stability/wheelchair_model.h"

namespace mozzi::core::stability {

inline constexpr const char* kWheelchairAnalysisKind = "wheelchair";

struct WheelchairStudy {
  std::string manoeuvre = "slalom";  // "slalom" or "steady turning"
  std::string study = "none";        // "none", "cornering stiffness", "aligning stiffness"
  double speed = 4.0 / 3.6;          // [m/s]
  double torque = 10.0;              // T_R - T_L: slalom amplitude or held value [N m]
  double frequency = 0.25;           // slalom [Hz]
  double duration = 20.0;            // [s]
  double ramp = 1.0;                 // steady turning: torque ramp [s]
  WheelchairParameters chair;
};

struct WheelchairRun {
  double factor = 1.0;  // the studied stiffness's factor (1 without a study)
  std::vector<WheelchairState> history;
};

struct WheelchairRecord {
  WheelchairStudy study;
  std::vector<WheelchairRun> runs;
};

// The stiffness factors of a study: {1} without one, else {0.5, 1, 2} (§7.3, §7.4).
std::vector<double> studyFactors(const std::string& study);

// Every run of the study: the slalom through runSlalom (as `mozzi-cli
// wheelchair slalom`), steady turning through simulate with the torque ramped.
// Errors: an unknown manoeuvre or study, and those of the model.
Result<WheelchairRecord> runWheelchairStudy(const WheelchairStudy& study);

std::string wheelchairRecordJson(const WheelchairRecord& record);
Result<WheelchairRecord> wheelchairRecordFromJson(const std::string& json);

// The analysis row (kind "wheelchair") under a free name (stored_result.h).
Result<io::StoredAnalysis> wheelchairAnalysis(const io::ProjectStore& store, std::int64_t specimenId,
                                              const std::string& name, const WheelchairRecord& record);
Result<std::int64_t> storeWheelchairRecord(io::ProjectStore& store, std::int64_t specimenId, const std::string& name,
                                           const WheelchairRecord& record);
// The first specimen of kind "wheelchair-tyre", else the project's first;
// NotFound when the project has none.
Result<std::int64_t> defaultWheelchairSpecimen(const io::ProjectStore& store);

using StoredWheelchair = StoredResult<WheelchairRecord>;

Result<std::vector<StoredWheelchair>> storedWheelchairRecords(const io::ProjectStore& store,
                                                              std::vector<std::int64_t>* unreadable = nullptr);
Result<StoredWheelchair> storedWheelchairRecord(const io::ProjectStore& store, std::int64_t analysisId);

}  // namespace mozzi::core::stability
