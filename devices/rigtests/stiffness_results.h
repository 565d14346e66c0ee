#pragma once
// Reading back what the stiffness-rig sequences (stiffness_tests.h) stored:
// the plate geometry of the rig set-up (load point, laser points, the
// specimen's bending and torsion axes), the whole-test results (k_lat, k_tw,
// a_tw, the static twist axis with its uncertainties) and, for a sine sweep,
// each frequency's dynamic twist axis and laser phasors. The twist-axes page
// and the CLI read tests through this one place, which knows the result keys
// the sequences write.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/result.h"
#include "core/io/project_store.h"
#include "core/stiffness/plate_motion.h"
#include "core/stiffness/twist_geometry.h"
#include "devices/rigtests/rig_sequence.h"

namespace mozzi::devices::rigtests {

struct StoredQuantity {
  double value = 0.0;
  double uncertainty = 0.0;  // one standard deviation, 0 when unknown
  std::string unit;          // SI, as stored
};

struct StiffnessTestView {
  std::int64_t testId = 0;
  std::int64_t specimenId = 0;
  std::string name;
  bool dynamic = false;
  core::io::TestStatus status = core::io::TestStatus::Complete;
  std::string statusNote;
  // The virtual specimen's catalogue key when the test ran on the simulated
  // rig (the set-up's DAQ parameter "specimen"); empty otherwise.
  std::string specimenKey;
  // Plate geometry of the set-up (u = x, v = z, thesis §1.2) [m].
  core::Vector2 loadPoint = core::Vector2::Zero();
  std::vector<core::Vector2> laserPoints;
  std::optional<core::stiffness::PlateAxis> bendAxis, torsAxis;
  // The plate's outline and the constrained end when the set-up gave them.
  std::vector<core::Vector2> plateOutline;
  std::optional<core::Vector2> constrainedEnd;
  // Whole-test results by key ("k_lat", "a_tw", "k_tw", "axis_inclination", ...).
  std::map<std::string, StoredQuantity> results;
  // Static test: the twist axis (point, beta, betaSigma, offsetSigma).
  std::optional<core::stiffness::PlateAxis> axis;
  // Sine sweep: one entry per step that stored a frequency, ascending step.
  struct Step {
    int step = 0;
    double frequencyHz = 0.0;
    std::map<std::string, StoredQuantity> results;
    std::optional<core::stiffness::PlateAxis> axis;  // none when the step gave no axis
    // Laser displacement phasors relative to the force [m] (amplitude e^{i phase}),
    // empty when the step stored no sine fits.
    core::ComplexVector laserPhasors;
  };
  std::vector<Step> steps;

  const StoredQuantity* result(const std::string& key) const;
  // The dynamic axes of the steps that have one, for core::stiffness::dynamicAxisPath.
  std::vector<core::stiffness::AxisAtFrequency> dynamicAxes() const;
};

// Reads rig test `testId` (static or dynamic) and its set-up. Errors: no such
// test, a set-up without the plate geometry the sequences write.
core::Result<StiffnessTestView> readStiffnessTest(const core::io::ProjectStore& store, std::int64_t testId);

// The laser phasors relative to the force [m] of one frequency's results
// (laser_<n>_amplitude, laser_<n>_phase, n = 1..lasers, as the dynamic test
// reports and stores them); nullopt when a laser's fit is missing.
std::optional<core::ComplexVector> laserPhasorsOf(const std::vector<Quantity>& results, std::size_t lasers);

// The force-displacement loop that one frequency's sine fits describe, to draw
// over the measured loop (thesis §1.3): over one cycle theta in [0, 2 pi],
// F = |F| cos(theta) and x = Re(X e^{i theta}) at the load point, with
// X = w0 + gu u + i (...) the planes fitted to the real and to the imaginary
// parts of the laser phasors (core/stiffness/plate_motion.h fitPlane)
// evaluated at the load point. Points are (x [m], F [N]), `samples` + 1 of
// them (closed). Errors: sizes differ, fewer than 3 lasers, a plane that
// cannot be fitted (collinear lasers), a force amplitude not > 0.
core::Result<std::vector<core::Vector2>> fittedSineLoop(const std::vector<core::Vector2>& laserPoints,
                                                        const core::Vector2& loadPoint, double forceAmplitude,
                                                        const core::ComplexVector& laserPhasors, int samples = 120);

}  // namespace mozzi::devices::rigtests
