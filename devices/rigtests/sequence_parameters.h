#pragma once
// The settings of the rig test sequences as ParameterSpec lists, so that one
// form builder (views/panels/parameter_form.h) shows them and a new setting
// appears in the workbench without GUI code (WORKBENCH.md "Forms from
// declarations"), and the map a form returns back as the sequence's settings.
// Lists of frequencies and set-points are Text parameters of comma-separated
// numbers ("1, 2, 5, 10"). Angles are in degrees and speeds in km/h, as the
// operator sets them at the machine (§1.8, §1.9). The conversions check the
// form of each value (the error names the key); the sequences' check*Settings
// then check the values against the machine's limits.

#include <memory>
#include <string>
#include <vector>

#include "core/common/result.h"
#include "devices/common/driver.h"
#include "devices/common/parameters.h"
#include "devices/rigtests/stiffness_tests.h"
#include "devices/rigtests/tyre_tests.h"

namespace mozzi::devices::rigtests {

// Stiffness rig. `peakForceN`: the default peak force (the specimen's test force).
std::vector<ParameterSpec> staticTestParameters(double peakForceN = 300.0);
core::Result<StaticTestSettings> staticSettingsFrom(const ParameterMap& values);
std::vector<ParameterSpec> dynamicTestParameters(double amplitudeN = 300.0);
core::Result<DynamicTestSettings> dynamicSettingsFrom(const ParameterMap& values);

// The stiffness rig's set-up as a form (thesis §1.2, Fig. 3): the plate's
// size, the plate coordinates (u, v) of the four lasers, of the load point and
// of the constrained end, in mm as the technician measures them on the rig.
// Defaults from `base` (the simulated rig's layout for the specimen) and
// `constrainedEnd` (where the specimen is locked, e.g. from its silhouette).
// Keys: setup.plate_width, setup.plate_height, setup.laser<n>_u,
// setup.laser<n>_v (n = 1..lasers), setup.load_u, setup.load_v,
// setup.constrained_u, setup.constrained_v.
std::vector<ParameterSpec> stiffnessSetupParameters(const StiffnessRigSetup& base,
                                                    const std::optional<core::Vector2>& constrainedEnd);
// `base` with the form's geometry: laser and load points, the plate outline
// (the width x height rectangle centred on the load point), the
// constrained end; for the simulated rig (base.daqParameters names a
// "specimen") the same points go to the device (lasers.points, load.point),
// so it measures where the set-up says. The geometry is not checked here
// (checkPlateGeometry in stiffness_tests.h, which the tests run before
// anything moves): a form shows what was entered, then says what is wrong.
core::Result<StiffnessRigSetup> stiffnessSetupFrom(const StiffnessRigSetup& base, const ParameterMap& values);

// Where the actuator's set-point comes from (thesis §1.1; docs/hardware.md):
// "sim-stiffness", the simulated rig's own drive; "sim-funcgen", the
// simulated function generator, which the simulated rig then follows;
// "usbtmc-funcgen", the first USBTMC function generator found. A Choice
// parameter "setup.actuator" of these (`choices`, the first the default).
inline constexpr const char* kActuatorRigDrive = "sim-stiffness";
inline constexpr const char* kActuatorSimGenerator = "sim-funcgen";
inline constexpr const char* kActuatorUsbtmcGenerator = "usbtmc-funcgen";
ParameterSpec actuatorParameter(const std::vector<std::string>& choices);
// The actuator device for a choice: null for the rig's own drive; the
// simulated generator with the set-up's simulated rig told to follow it
// (daqParameters["actuator.source"]); the first device usbtmc-funcgen finds.
// The sequence opens, configures, starts and closes it. Errors: an unknown
// choice, no USBTMC generator found (naming "setup.actuator").
core::Result<std::unique_ptr<Device>> actuatorFor(const std::string& choice, StiffnessRigSetup& setup);

// Tyre tester.
std::vector<ParameterSpec> relaxationTestParameters();
core::Result<RelaxationSettings> relaxationSettingsFrom(const ParameterMap& values);
std::vector<ParameterSpec> steadyStateTestParameters();
core::Result<SteadyStateSettings> steadyStateSettingsFrom(const ParameterMap& values);

// The simulated rigs' own settings a front end offers, as the simulated
// devices declare them: "sim.seed" (noise seed), "sim.realtime" (paced like
// the real rig), and for the tyre tester "tyre.pressure_bar" (Table 17's
// half-length at that pressure). Empty if the driver cannot be created.
std::vector<ParameterSpec> simulatedRigParameters(bool tyreTester);

// "1, 2, 5": the numbers of a list parameter; the error names `key`.
core::Result<std::vector<double>> parseNumberList(const std::string& text, const std::string& key);

}  // namespace mozzi::devices::rigtests
