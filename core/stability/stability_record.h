#pragma once
// Stability results the project keeps (issue 22): a sweep of the eigenvalues
// against speed (mode_tracking.h) with what it was computed from, stored as an
// analysis of kind "stability" whose result_json is written and read here, so
// the Stability page, `mozzi-cli stability --project` and the project report
// (core/report/stability_report.cpp) show the same record. Format:
// docs/formats.md, "Stored stability and wheelchair results".
//
// The sweep's JSON is the object `mozzi-cli stability --json` prints (model,
// speeds with the named modes' eigenvalues, critical_speeds, events); the
// eigenvector shapes and track indices are not kept (the plots do not use
// them). Numbers are written with the shortest text that reads back to the
// same double, so a stored sweep reloads identically.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/common/result.h"
#include "core/io/project_records.h"
#include "core/stability/kept_forks.h"
#include "core/stability/mode_tracking.h"
#include "core/stability/stored_result.h"

namespace mozzi::core::stability {

inline constexpr const char* kStabilityAnalysisKind = "stability";

struct StabilityRecord {
  std::string vehicle;                      // "bicycle" or "motorcycle"
  std::string model;                        // what was swept, as `mozzi-cli stability` names it
  std::string fork;                         // "rigid", "bending", "torsion", "model 1", "model 2", "model 3"
  std::string forkSource;                   // "thesis", "kept analysis N", "command line"
  std::string parametersFile;               // empty: the built-in parameters
  double from = 0.0, to = 0.0, step = 0.0;  // the requested speed grid [m/s]
  StabilitySweep sweep;
  std::optional<StabilitySweep> rigidSweep;  // the same vehicle with a rigid fork, when compared
};

// What to sweep (the Stability page's choices; the demo project's steps).
struct StabilityRequest {
  std::string vehicle = "bicycle";  // "bicycle" or "motorcycle"
  // bicycle: "rigid", "bending" (§6.5), "torsion" (§6.4); motorcycle: "rigid",
  // "model 1", "model 2", "model 3" (thesis Table 12)
  std::string fork = "rigid";
  std::optional<KeptFork> kept;  // the project's fork instead of the thesis's
  std::string parametersFile;    // empty: built in (Meijaard et al. 2007; Sharp 1971)
  double from = 0.0, to = 10.0, step = 0.05;
  bool compareRigid = false;  // also sweep the vehicle with a rigid fork
};

// The request's system (rigid: the same vehicle with a rigid fork) and its
// description, as `mozzi-cli stability` names the model.
Result<StabilitySystem> stabilitySystem(const StabilityRequest& request, bool rigid, std::string* model = nullptr);
// Sweeps the request (stability_request.cpp). Errors name the bad choice.
Result<StabilityRecord> computeStabilityRecord(const StabilityRequest& request);

// The `mozzi-cli stability --json` object of one sweep.
nlohmann::json sweepJson(const std::string& model, const StabilitySweep& sweep);
// Reads it back (roots without shapes, track -1). Errors name the key.
Result<StabilitySweep> sweepFromJson(const nlohmann::json& j);

std::string stabilityRecordJson(const StabilityRecord& record);
Result<StabilityRecord> stabilityRecordFromJson(const std::string& json);

// A critical speed as `mozzi-cli stability` prints it (fixed, 6 decimals), and
// the crossing's imaginary part (fixed, 3 decimals).
std::string criticalSpeedText(double v);
std::string crossingFrequencyText(double imaginary);

// The specimen a vehicle's result is kept under when none is chosen: the first
// specimen of kind "bicycle-fork" (bicycle) or "fork" (motorcycle), else the
// project's first specimen. NotFound when the project has no specimen.
Result<std::int64_t> defaultStabilitySpecimen(const io::ProjectStore& store, const std::string& vehicle);
// The id of the specimen named `name`; NotFound naming it otherwise.
Result<std::int64_t> specimenNamed(const io::ProjectStore& store, const std::string& name);

// The analysis row (kind "stability") holding `record`, under a free name.
Result<io::StoredAnalysis> stabilityAnalysis(const io::ProjectStore& store, std::int64_t specimenId,
                                             const std::string& name, const StabilityRecord& record);
// Adds it; returns the analysis id.
Result<std::int64_t> storeStabilityRecord(io::ProjectStore& store, std::int64_t specimenId, const std::string& name,
                                          const StabilityRecord& record);

using StoredStability = StoredResult<StabilityRecord>;

// Every readable stability analysis, in id order; unreadable ids in
// `unreadable` when given.
Result<std::vector<StoredStability>> storedStabilityRecords(const io::ProjectStore& store,
                                                            std::vector<std::int64_t>* unreadable = nullptr);
// One by id; NotFound when it is not a stability analysis.
Result<StoredStability> storedStabilityRecord(const io::ProjectStore& store, std::int64_t analysisId);

}  // namespace mozzi::core::stability
