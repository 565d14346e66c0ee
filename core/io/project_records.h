#pragma once
// Storage-level records of the project file (.mozzi). These mirror the SQLite
// tables one to one and carry no behaviour; signal processing, modal
// identification and the GUI convert them to and from their own types. Units
// are SI throughout (DESIGN.md): m, s, N, Pa, rad, Hz; samples are in the SI
// unit of the channel's quantity (N for force, m/s^2 for acceleration, ...).

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/common/dof.h"
#include "core/common/eigen_types.h"
#include "core/common/frf_matrix.h"

namespace mozzi::core::io {

// --- mesh ----------------------------------------------------------------------

// A coordinate system of the mesh (UFF 2420 / 18): x_global = origin + R x_local.
struct StoredCoordinateSystem {
  std::int64_t id = 0;
  int label = 0;  // UFF coordinate-system number, unique per specimen
  std::string name;
  enum class Kind { Cartesian = 0, Cylindrical = 1, Spherical = 2 } kind = Kind::Cartesian;
  Vector3 origin = Vector3::Zero();        // [m] in the global system
  Matrix3 rotation = Matrix3::Identity();  // columns are the local axes in global coordinates
};

struct StoredNode {
  std::int64_t id = 0;
  int label = 0;                       // node number used by DOF labels ("21:+Z")
  int definitionCs = 0;                // coordinate-system label the position is given in (0 = global)
  int displacementCs = 0;              // coordinate-system label the DOF directions refer to (0 = global)
  Vector3 position = Vector3::Zero();  // [m]
};

struct StoredLine {
  int nodeA = 0;  // node labels
  int nodeB = 0;
};

// A triangle (nodeD == 0) or quadrilateral face, node labels counter-clockwise.
struct StoredFace {
  int nodeA = 0, nodeB = 0, nodeC = 0, nodeD = 0;
};

struct StoredMesh {
  std::vector<StoredCoordinateSystem> coordinateSystems;
  std::vector<StoredNode> nodes;
  std::vector<StoredLine> lines;
  std::vector<StoredFace> faces;
};

// --- rig set-up ------------------------------------------------------------------

struct StoredTransducer {
  std::int64_t id = 0;
  int channel = 0;           // acquisition channel, 0-based
  std::string quantity;      // "force", "acceleration", "displacement", "velocity", "strain", ...
  std::string unit;          // SI unit of the measured quantity, e.g. "N", "m/s^2"
  double sensitivity = 1.0;  // [V per SI unit], > 0
  std::string model;
  std::string serial;
  std::optional<Dof> dof;  // where it measures, when fixed for the set-up
};

struct StoredRigSetup {
  std::int64_t id = 0;
  std::int64_t specimenId = 0;
  std::string name;
  std::string rigKind;                // "impact-hammer", "static-stiffness", "dynamic-stiffness", "tyre-drum", ...
  std::string driver;                 // device driver name, "sim:frame-a" for a simulated rig
  std::string axisMapJson = "{}";     // how the rig's sensor axes map onto the mesh axes
  std::string parametersJson = "{}";  // driver parameters at the time of the test
  std::vector<StoredTransducer> transducers;
};

// --- campaigns and hits ----------------------------------------------------------

struct StoredCampaign {
  std::int64_t id = 0;
  std::int64_t specimenId = 0;
  std::optional<std::int64_t> rigSetupId;
  std::string name;
  std::string kind = "roving-hammer";  // "roving-hammer", "roving-accelerometer", "shaker", "other"
  std::string notes;
  std::string startedUtc;           // filled by the store
  std::string settingsJson = "{}";  // the campaign definition (devices/campaign), "{}" when none
};

// One point of a campaign's roving schedule (position = order of roving).
struct StoredCampaignPoint {
  int position = 0;
  Dof dof;
  bool skipped = false;
  std::string skipReason;  // the technician's words
};

// Why a hit may be rejected; bits of StoredHit::qualityFlags.
enum HitQualityFlag : std::uint32_t {
  kHitOverload = 1u << 0,      // a channel reached the converter's range
  kHitDoubleHit = 1u << 1,     // a second impact in the force window
  kHitTruncated = 1u << 2,     // the response has not decayed by the end of the record
  kHitLowSignal = 1u << 3,     // force or response near the noise floor
  kHitLowCoherence = 1u << 4,  // coherence of the running average dropped
  kHitManualReject = 1u << 5,  // the technician rejected it
};

struct StoredHitChannel {
  std::optional<Dof> dof;  // DOF this channel measured in this hit (roving sensors move)
  std::string quantity;    // "force", "acceleration", ...
  std::string unit;        // SI unit of the samples
};

// One impact (or one block of a shaker run) with its raw time data.
struct StoredHit {
  std::int64_t id = 0;
  std::int64_t campaignId = 0;
  int sequence = 0;                        // hit number within the campaign, unique
  Dof point;                               // measurement point of the hit (the roving DOF)
  std::string recordedUtc;                 // ISO 8601; filled with the commit time when empty
  double sampleRateHz = 0.0;               // > 0
  Eigen::MatrixXf samples;                 // sampleCount x channelCount, SI units, column = channel
  std::vector<StoredHitChannel> channels;  // empty, or one per column of samples
  bool accepted = true;
  std::uint32_t qualityFlags = 0;  // HitQualityFlag bits
  std::string qualityReasons;      // the reasons in words, as shown to the technician

  Eigen::Index sampleCount() const { return samples.rows(); }
  Eigen::Index channelCount() const { return samples.cols(); }
};

// A hit without its samples, for lists.
struct HitInfo {
  std::int64_t id = 0;
  int sequence = 0;
  Dof point;
  std::string recordedUtc;
  double sampleRateHz = 0.0;
  int channelCount = 0;
  std::int64_t sampleCount = 0;
  bool accepted = true;
  std::uint32_t qualityFlags = 0;
  std::string qualityReasons;
  std::int64_t storedBytes = 0;  // size of the sample blob in the file
};

// --- FRFs and modal results -------------------------------------------------------

struct FrfSetInfo {
  std::int64_t id = 0;
  std::int64_t specimenId = 0;
  std::optional<std::int64_t> campaignId;
  std::string name;
  std::string source;     // "measured", "imported from X.uff", "synthesised from modal result 3", ...
  std::string estimator;  // "H1", "H2", "Hv" or empty
  FrfType type = FrfType::Accelerance;
  std::int64_t lineCount = 0;
  int responseCount = 0;
  int referenceCount = 0;
};

struct StoredMode {
  StoredMode() = default;
  // Most makers know no standard errors (UFF 55, CSV, peak picking).
  StoredMode(double frequencyHz, double dampingRatio, ComplexVector shape = {})
      : frequencyHz(frequencyHz), dampingRatio(dampingRatio), shape(std::move(shape)) {}

  double frequencyHz = 0.0;   // undamped natural frequency [Hz]
  double dampingRatio = 0.0;  // viscous ratio zeta (DESIGN.md), not the loss factor
  ComplexVector shape;        // one entry per ModalTable::dofs, unscaled unless stated
  // Standard errors of frequencyHz and dampingRatio from the identification's
  // refinement (schema 5); empty when the method gives none or the result was
  // kept before schema 5.
  std::optional<double> frequencyStdHz;
  std::optional<double> dampingRatioStd;
};

// Modal parameters of one identification (also the CSV modal table).
struct ModalTable {
  std::vector<Dof> dofs;  // DOFs of the mode shapes (may be empty: frequencies only)
  std::vector<StoredMode> modes;
};

struct ModalResultInfo {
  std::int64_t id = 0;
  std::int64_t specimenId = 0;
  std::optional<std::int64_t> frfSetId;
  std::string name;
  std::string method;  // "LSCE", "PolyMAX", "circle fit", ...
  double bandLowHz = 0.0;
  double bandHighHz = 0.0;
  int modeCount = 0;
};

// --- rig tests, tyre tests, models, analyses ---------------------------------------

// State of a rig or tyre test run step by step (schema 3): Running while its
// steps are being committed (a Running test nobody is running was cut short by
// a crash), then Complete, Interrupted (unplug, cancel: the committed steps
// stay) or Failed.
enum class TestStatus { Running, Complete, Interrupted, Failed };

// A static or dynamic stiffness test on a rig; its records are time data of the
// same layout as hits, its results are named quantities with units.
struct StoredRigTest {
  std::int64_t id = 0;
  std::int64_t specimenId = 0;
  std::optional<std::int64_t> rigSetupId;
  enum class Kind { Static, Dynamic } kind = Kind::Static;
  std::string name;
  std::string parametersJson = "{}";  // load steps, preload, excitation frequency, ...
  struct Result {
    std::string quantity;  // "lateral stiffness", "torsional stiffness", "twist axis height", ...
    double value = 0.0;
    std::string unit;           // SI: "N/m", "N m/rad", "m"
    double uncertainty = 0.0;   // one standard deviation, same unit; 0 when unknown
    std::optional<int> step{};  // the step (record) it comes from; none: the whole test
  };
  std::vector<Result> results;
  TestStatus status = TestStatus::Complete;
  std::string statusNote;   // what is missing, why it stopped; empty when complete
  std::string recordedUtc;  // filled by the store
};

struct StoredTyreTest {
  std::int64_t id = 0;
  std::int64_t specimenId = 0;
  std::optional<std::int64_t> rigSetupId;
  std::string name;
  std::string kind;                  // "cornering", "camber", "relaxation", "twisting torque", ...
  double inflationPressurePa = 0.0;  // [Pa]
  double verticalLoadN = 0.0;        // [N]
  double speedMps = 0.0;             // [m/s]
  struct Point {
    double slipAngleRad = 0.0;         // [rad]
    double camberRad = 0.0;            // [rad]
    double lateralForceN = 0.0;        // Fy [N]
    double aligningMomentNm = 0.0;     // Mz [N m]
    double overturningMomentNm = 0.0;  // Mx [N m]
  };
  std::vector<Point> points;
  struct Parameter {
    std::string name;  // "cornering stiffness", "relaxation length", ...
    double value = 0.0;
    std::string unit;  // SI
    double uncertainty = 0.0;
    std::optional<int> step{};  // the step (record) it comes from; none: the whole test
  };
  std::vector<Parameter> parameters;
  TestStatus status = TestStatus::Complete;
  std::string statusNote;
  std::string parametersJson = "{}";  // set-points, frequencies, limits, seed
  std::string recordedUtc;            // filled by the store
};

// A rig or tyre test without its data, for lists (project info, project tree).
struct TestInfo {
  std::int64_t id = 0;
  std::int64_t specimenId = 0;
  std::string specimenName;
  std::string kind;  // rig tests: "static", "dynamic"; tyre tests: as stored ("relaxation", ...)
  std::string name;
  TestStatus status = TestStatus::Complete;
  std::string statusNote;
  std::string recordedUtc;
  int recordCount = 0;  // raw records (steps committed)
  int resultCount = 0;  // results (rig) or parameters (tyre)
};

struct StoredModel {
  std::int64_t id = 0;
  std::int64_t specimenId = 0;
  std::string name;
  std::string kind;  // "spatial", "modal", "lumped", "stability"
  std::string source;
  std::string parametersJson = "{}";
};

// A sim-to-real gap diagnosis (or another analysis) of a model against a test.
struct StoredAnalysis {
  std::int64_t id = 0;
  std::int64_t specimenId = 0;
  std::optional<std::int64_t> modelId;
  std::optional<std::int64_t> frfSetId;
  std::optional<std::int64_t> modalResultId;
  std::optional<std::int64_t> rigTestId;
  std::optional<std::int64_t> tyreTestId;
  std::string kind = "gap-diagnosis";
  std::string name;
  std::string resultJson = "{}";
  struct Finding {
    double bandLowHz = 0.0, bandHighHz = 0.0;  // where model and test disagree [Hz]
    std::optional<int> modeIndex;
    std::optional<Dof> dof;
    std::string condition;  // operating condition, e.g. "inflation 200 kPa"
    std::string effect;     // best explaining effect from the catalogue, or "cannot tell apart"
    double size = 0.0;      // fitted size of the effect, in `unit`
    std::string unit;
    double uncertainty = 0.0;
    double remainingGap = 0.0;  // fraction of the gap left once the effect is added, [0, 1]
  };
  std::vector<Finding> findings;
};

// A stored analysis without its result and findings, for lists (project
// contents, project tree): read without touching result_json.
struct AnalysisInfo {
  std::int64_t id = 0;
  std::int64_t specimenId = 0;
  std::string kind;  // "gap-diagnosis", "stability", "wheelchair", ...
  std::string name;
};

}  // namespace mozzi::core::io
