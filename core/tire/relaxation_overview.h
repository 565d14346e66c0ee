#pragma once
// What the Tyre Relaxation page shows (thesis §5.4, Figure 43), gathered from a
// project without a widget: a tyre specimen's stored relaxation tests (the
// relaxation length at each yaw frequency and the band mean, as the tyre
// tester stored them, devices/rigtests/tyre_tests.h), the ring model of its
// thesis tyre (Table 16, eq. 45-47) and the eq. 48 prediction with its
// contributions at the Table 17 pressures and at each tested pressure.
//
// Inputs of eq. 48 and where they come from:
//   ring C_k        Table 16 of the specimen's thesis tyre (matched by size in
//                   the specimen's name), tyre mass and damping assumed
//                   (thesis_tyres.h);
//   a               a test's stored contact half-length; Table 17 for the bars;
//   F_z             a test's vertical load; the thesis test load for the bars;
//   C_bFalpha       a stored steady-state test of the same specimen at that
//                   pressure (its cornering stiffness) when there is one, else
//                   the assumed C/F_z of thesis_tyres.h times F_z;
//   lambda, alpha   assumed friction, 1.5 deg (§5.4).

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/common/result.h"
#include "core/tire/relaxation_prediction.h"
#include "core/tire/ring_model.h"
#include "core/tire/thesis_tyres.h"

namespace mozzi::core::io {
class ProjectStore;
struct StoredTyreTest;
}  // namespace mozzi::core::io

namespace mozzi::core::tire {

// The thesis tyre whose size ("120/70 R17") appears in `text` (a specimen
// name, or a size as typed), ignoring spaces, '/' and '-'; nullptr if none.
const ThesisTyre* findThesisTyre(const std::string& text);

struct MeasuredRelaxationPoint {
  int step = 0;
  double frequencyHz = 0.0;
  double sigma = 0.0;          // [m]
  double sigmaStdError = 0.0;  // [m]
};

struct MeasuredRelaxation {
  std::int64_t testId = 0;
  std::string name;
  double pressurePa = 0.0;
  double verticalLoadN = 0.0;
  double speedMps = 0.0;
  double halfLengthM = 0.0;                     // the stored "half_length" (Table 17 at the pressure)
  std::vector<MeasuredRelaxationPoint> points;  // the steps with a stored relaxation length, by step
  std::optional<double> bandMean;               // the test's result: mean over the band (§5.4) [m]
  double bandMeanStdError = 0.0;
};

// The stored results of one relaxation test. Error when the test is not a
// relaxation test or holds neither a point nor a band mean.
Result<MeasuredRelaxation> measuredRelaxation(const io::StoredTyreTest& test);

enum class CorneringSource { SteadyStateTest, Assumed };

struct PredictionCase {
  double pressurePa = 0.0;
  ContactPatchInputs contact;
  CorneringSource corneringSource = CorneringSource::Assumed;
  std::int64_t corneringTestId = 0;  // the steady-state test, when SteadyStateTest
  RelaxationPrediction prediction;   // eq. 48 to 50
};

struct RelaxationOverview {
  std::int64_t specimenId = 0;
  std::string specimenName;
  ThesisTyre tyre;
  RingModel ring;                             // Table 16, eq. 45 to 47
  std::vector<MeasuredRelaxation> tests;      // by pressure, then id
  std::vector<PredictionCase> table17;        // the Figure 43 bars, one per Table 17 pressure
  std::vector<PredictionCase> atTests;        // one per entry of `tests`, same order
  std::vector<std::int64_t> unreadableTests;  // relaxation tests with nothing to show
};

// Errors: the specimen is unknown, stands for no thesis tyre, or the store
// cannot be read; a prediction that cannot be made (eq. 49, m <= 0).
Result<RelaxationOverview> relaxationOverview(const io::ProjectStore& store, std::int64_t specimenId);

// A ring model as JSON (ring mass and radius, each mode's k, name, frequency,
// zeta, m_k, C_k, c_k): `mozzi-cli tire ring --json` and the analysis below.
nlohmann::json ringModelJson(const RingModel& ring);

// The overview as an analysis record's result_json (kind "relaxation-prediction"):
// the tyre, the ring modes, each prediction case with its contributions [m] and
// the cornering stiffness's source, the measured band means.
std::string relaxationOverviewJson(const RelaxationOverview& overview);

}  // namespace mozzi::core::tire
