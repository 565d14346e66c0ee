#include "devices/rigtests/sequence_parameters.h"

#include <cctype>
#include <cstdio>

#include "core/tire/tire_csv.h"
#include "devices/sim/sim_drivers.h"

namespace mozzi::devices::rigtests {

namespace {

std::string listText(const std::vector<double>& values) {
  std::string out;
  for (double v : values) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    out += (out.empty() ? "" : ", ") + std::string(buf);
  }
  return out;
}

ParameterSpec real(const char* key, const char* label, const char* unit, double min, double max, double value,
                   const char* help) {
  return ParameterSpec{key, label, ParameterType::Real, unit, min, max, {}, value, help};
}

ParameterSpec integer(const char* key, const char* label, double min, double max, std::int64_t value,
                      const char* help) {
  return ParameterSpec{key, label, ParameterType::Integer, "", min, max, {}, value, help};
}

ParameterSpec text(const char* key, const char* label, const char* unit, const std::string& value, const char* help) {
  return ParameterSpec{key, label, ParameterType::Text, unit, std::nullopt, std::nullopt, {}, value, help};
}

// The values checked against their specs (types, ranges), defaults completed.
core::Result<ParameterMap> applied(const std::vector<ParameterSpec>& specs, const ParameterMap& values) {
  return applyParameters(specs, values);
}

}  // namespace

core::Result<std::vector<double>> parseNumberList(const std::string& text, const std::string& key) {
  std::string compact;
  for (char c : text)
    if (!std::isspace(static_cast<unsigned char>(c))) compact += c;
  if (compact.empty())
    return core::makeError(core::ErrorCode::InvalidArgument, "the list is empty: give numbers separated by commas",
                           key);
  auto tuples = core::tire::parseNumberTuples(compact, 1, key);
  if (!tuples) return tuples.error();
  std::vector<double> out;
  for (const auto& t : *tuples) out.push_back(t.front());
  return out;
}

std::vector<ParameterSpec> staticTestParameters(double peakForceN) {
  const StaticTestSettings d;
  return {real("static.peak_force", "Peak force", "N", 1.0, kActuatorMaxForceN, peakForceN,
               "F of the ramp 0 -> +F -> -F -> 0 (the thesis uses 300 N, fork B 500 N; §1.2)"),
          real("static.period", "Ramp duration", "s", 1.0, 600.0, d.periodS,
               "time of the whole ramp; slow, so the specimen's inertia plays no part (§1.2)")};
}

core::Result<StaticTestSettings> staticSettingsFrom(const ParameterMap& values) {
  auto v = applied(staticTestParameters(), values);
  if (!v) return v.error();
  StaticTestSettings s;
  s.peakForceN = parameterReal(*v, "static.peak_force", s.peakForceN);
  s.periodS = parameterReal(*v, "static.period", s.periodS);
  return s;
}

std::vector<ParameterSpec> dynamicTestParameters(double amplitudeN) {
  const DynamicTestSettings d;
  return {text("dynamic.frequencies", "Frequencies", "Hz", listText(d.frequenciesHz),
               "sine frequencies in the actuator's band of 1 to 45 Hz, separated by commas (§1.3)"),
          real("dynamic.amplitude", "Force amplitude", "N", 1.0, kActuatorMaxForceN, amplitudeN,
               "sine set-point; the actuator's force falls with frequency (§1.1)"),
          real("dynamic.settle_cycles", "Settling cycles", "", 0.0, 1000.0, d.settleCycles,
               "cycles discarded after the soft start (at least 1 s)"),
          real("dynamic.record_cycles", "Recorded cycles", "", 1.0, 1000.0, d.recordCycles,
               "whole cycles fitted with a sine per channel (at least 1 s)")};
}

core::Result<DynamicTestSettings> dynamicSettingsFrom(const ParameterMap& values) {
  auto v = applied(dynamicTestParameters(), values);
  if (!v) return v.error();
  DynamicTestSettings s;
  auto f = parseNumberList(parameterText(*v, "dynamic.frequencies", ""), "dynamic.frequencies");
  if (!f) return f.error();
  s.frequenciesHz = *f;
  s.amplitudeN = parameterReal(*v, "dynamic.amplitude", s.amplitudeN);
  s.settleCycles = parameterReal(*v, "dynamic.settle_cycles", s.settleCycles);
  s.recordCycles = parameterReal(*v, "dynamic.record_cycles", s.recordCycles);
  return s;
}

std::vector<ParameterSpec> relaxationTestParameters() {
  const RelaxationSettings d;
  return {real("relaxation.speed", "Disk speed", "km/h", 0.5, kMachineMaxSpeedKmh, d.speedKmh,
               "speed of the rotating disk (the thesis runs the yaw test at 5 km/h, §1.9)"),
          text("relaxation.frequencies", "Yaw frequencies", "Hz", listText(d.frequenciesHz),
               "harmonic yaw frequencies, separated by commas (§5.1: 0.42 to 2.10 Hz)"),
          real("relaxation.yaw_amplitude", "Yaw amplitude", "deg", 0.1, kMachineMaxSlipDeg, d.yawAmplitudeDeg,
               "amplitude of the side-slip oscillation (§1.9: 1.5 deg)"),
          integer("relaxation.cycles", "Cycles per frequency", 2, 200, d.cycles,
                  "yaw cycles recorded at each frequency (§5.1: about 10)"),
          integer("relaxation.settle_cycles", "Settling cycles", 0, 50, d.settleCycles,
                  "cycles dropped at the start of each frequency (the lag's transient)")};
}

core::Result<RelaxationSettings> relaxationSettingsFrom(const ParameterMap& values) {
  auto v = applied(relaxationTestParameters(), values);
  if (!v) return v.error();
  RelaxationSettings s;
  s.speedKmh = parameterReal(*v, "relaxation.speed", s.speedKmh);
  auto f = parseNumberList(parameterText(*v, "relaxation.frequencies", ""), "relaxation.frequencies");
  if (!f) return f.error();
  s.frequenciesHz = *f;
  s.yawAmplitudeDeg = parameterReal(*v, "relaxation.yaw_amplitude", s.yawAmplitudeDeg);
  s.cycles = static_cast<int>(parameterInteger(*v, "relaxation.cycles", s.cycles));
  s.settleCycles = static_cast<int>(parameterInteger(*v, "relaxation.settle_cycles", s.settleCycles));
  return s;
}

std::vector<ParameterSpec> steadyStateTestParameters() {
  const SteadyStateSettings d;
  return {real("steady.speed", "Disk speed", "km/h", 0.5, kMachineMaxSpeedKmh, d.speedKmh,
               "speed of the rotating disk (appendix 2)"),
          text("steady.slip", "Side-slip set-points", "deg", listText(d.slipDeg),
               "the side-slip sweep at zero camber, separated by commas (machine limit +/-10 deg)"),
          text("steady.camber", "Camber set-points", "deg", listText(d.camberDeg),
               "the camber sweep at zero side-slip, separated by commas (machine limit +/-55 deg)"),
          real("steady.settle", "Settling time", "s", 0.0, 60.0, d.settleS,
               "wait after each set-point before averaging (appendix 2 holds 10 s)"),
          real("steady.hold", "Averaging time", "s", 0.1, 120.0, d.holdS, "forces and moments averaged per set-point"),
          ParameterSpec{"steady.magic_formula",
                        "Magic Formula fit",
                        ParameterType::Bool,
                        "",
                        std::nullopt,
                        std::nullopt,
                        {},
                        d.fitMagicFormula,
                        "fit the Magic Formula to F_y and M_z at the end"}};
}

core::Result<SteadyStateSettings> steadyStateSettingsFrom(const ParameterMap& values) {
  auto v = applied(steadyStateTestParameters(), values);
  if (!v) return v.error();
  SteadyStateSettings s;
  s.speedKmh = parameterReal(*v, "steady.speed", s.speedKmh);
  auto slip = parseNumberList(parameterText(*v, "steady.slip", ""), "steady.slip");
  if (!slip) return slip.error();
  s.slipDeg = *slip;
  auto camber = parseNumberList(parameterText(*v, "steady.camber", ""), "steady.camber");
  if (!camber) return camber.error();
  s.camberDeg = *camber;
  s.settleS = parameterReal(*v, "steady.settle", s.settleS);
  s.holdS = parameterReal(*v, "steady.hold", s.holdS);
  s.fitMagicFormula = parameterBool(*v, "steady.magic_formula", s.fitMagicFormula);
  return s;
}

std::vector<ParameterSpec> simulatedRigParameters(bool tyreTester) {
  // The simulated device's own declarations (labels, ranges, help), not copies.
  auto driver = tyreTester ? sim::makeTyreTesterDriver() : sim::makeStiffnessRigDriver();
  auto device = driver->create(DeviceDescriptor{driver->name(), "", 0, 0, "", "sim:0"});
  std::vector<ParameterSpec> out;
  if (!device) return out;
  for (const auto& spec : (*device)->capabilities().parameters)
    if (spec.key == "sim.seed" || spec.key == "sim.realtime" || (tyreTester && spec.key == "tyre.pressure_bar"))
      out.push_back(spec);
  return out;
}

}  // namespace mozzi::devices::rigtests
