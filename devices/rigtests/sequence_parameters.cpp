#include "devices/rigtests/sequence_parameters.h"

#include <algorithm>
#include <cctype>
#include <cmath>
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

namespace {}  // namespace

std::vector<ParameterSpec> stiffnessSetupParameters(const StiffnessRigSetup& base,
                                                    const std::optional<core::Vector2>& constrainedEnd) {
  // Plate size: the outline the set-up has, else the lasers' spread with a
  // 10 mm margin on every side (the simulated rig's 200 x 150 mm layout,
  // docs/devices.md, on a 220 x 170 mm plate).
  double width = 200.0, height = 150.0;
  const auto& around = base.plateOutline.size() >= 3 ? base.plateOutline : base.laserPoints;
  if (!around.empty()) {
    core::Vector2 lo = around.front(), hi = lo;
    for (const auto& p : around) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    // centred on the load point: wide enough for the farthest spot
    const double margin = base.plateOutline.size() >= 3 ? 0.0 : 0.010;
    width = 2e3 * (std::max(std::abs(hi.x() - base.loadPoint.x()), std::abs(lo.x() - base.loadPoint.x())) + margin);
    height = 2e3 * (std::max(std::abs(hi.y() - base.loadPoint.y()), std::abs(lo.y() - base.loadPoint.y())) + margin);
  }
  auto coordinate = [](std::string key, std::string label, double valueM, const char* help) {
    return ParameterSpec{
        std::move(key), std::move(label), ParameterType::Real, "mm", -2000.0, 2000.0, {}, valueM * 1e3, help};
  };
  std::vector<ParameterSpec> out{
      real("setup.plate_width", "Plate width (u)", "mm", 20.0, 2000.0, width,
           "the reference plate along u, centred on the load point where it is fixed to the specimen (§1.2)"),
      real("setup.plate_height", "Plate height (v)", "mm", 20.0, 2000.0, height,
           "the reference plate along v, centred on the load point where it is fixed to the specimen (§1.2)")};
  static const char* const kLaserU[] = {"Laser 1 u", "Laser 2 u", "Laser 3 u", "Laser 4 u"};
  static const char* const kLaserV[] = {"Laser 1 v", "Laser 2 v", "Laser 3 v", "Laser 4 v"};
  for (std::size_t i = 0; i < base.laserPoints.size() && i < 4; ++i) {
    out.push_back(coordinate(laserFieldKey(i, "u"), kLaserU[i], base.laserPoints[i].x(),
                             "where the laser's spot is on the plate, u = x (§1.2)"));
    out.push_back(coordinate(laserFieldKey(i, "v"), kLaserV[i], base.laserPoints[i].y(),
                             "where the laser's spot is on the plate, v = z (§1.2)"));
  }
  out.push_back(coordinate("setup.load_u", "Load point u", base.loadPoint.x(),
                           "where the actuator loads the specimen through the load cell (§1.1)"));
  out.push_back(coordinate("setup.load_v", "Load point v", base.loadPoint.y(),
                           "where the actuator loads the specimen through the load cell (§1.1)"));
  const core::Vector2 locked = constrainedEnd.value_or(base.constrainedEnd.value_or(core::Vector2(0.0, 0.6)));
  out.push_back(coordinate("setup.constrained_u", "Constrained end u", locked.x(),
                           "where the specimen is locked to the rig's frame (§1.2)"));
  out.push_back(coordinate("setup.constrained_v", "Constrained end v", locked.y(),
                           "where the specimen is locked to the rig's frame (§1.2)"));
  return out;
}

core::Result<StiffnessRigSetup> stiffnessSetupFrom(const StiffnessRigSetup& base, const ParameterMap& values) {
  auto v = applied(stiffnessSetupParameters(base, std::nullopt), values);
  if (!v) return v.error();
  StiffnessRigSetup s = base;
  auto point = [&](const std::string& u, const std::string& w) {
    return core::Vector2(parameterReal(*v, u, 0.0) * 1e-3, parameterReal(*v, w, 0.0) * 1e-3);
  };
  for (std::size_t i = 0; i < s.laserPoints.size() && i < 4; ++i)
    s.laserPoints[i] = point(laserFieldKey(i, "u"), laserFieldKey(i, "v"));
  s.loadPoint = point("setup.load_u", "setup.load_v");
  s.constrainedEnd = point("setup.constrained_u", "setup.constrained_v");
  const core::Vector2 c = s.loadPoint;
  const double hw = 0.5e-3 * parameterReal(*v, "setup.plate_width", 200.0);
  const double hh = 0.5e-3 * parameterReal(*v, "setup.plate_height", 150.0);
  s.plateOutline = {c + core::Vector2(-hw, -hh), c + core::Vector2(hw, -hh), c + core::Vector2(hw, hh),
                    c + core::Vector2(-hw, hh)};
  if (s.daqParameters.count("specimen")) {
    std::string lasers;
    char buf[64];
    for (const auto& p : s.laserPoints) {
      std::snprintf(buf, sizeof buf, "%.9g:%.9g", p.x(), p.y());
      lasers += (lasers.empty() ? "" : ",") + std::string(buf);
    }
    s.daqParameters["lasers.points"] = lasers;
    std::snprintf(buf, sizeof buf, "%.9g:%.9g", s.loadPoint.x(), s.loadPoint.y());
    s.daqParameters["load.point"] = std::string(buf);
  }
  return s;
}

ParameterSpec actuatorParameter(const std::vector<std::string>& choices) {
  return ParameterSpec{"setup.actuator",
                       "Actuator set-point",
                       ParameterType::Choice,
                       "",
                       std::nullopt,
                       std::nullopt,
                       choices,
                       choices.empty() ? std::string(kActuatorRigDrive) : choices.front(),
                       "sim-stiffness: the rig's own drive; sim-funcgen / usbtmc-funcgen: a function generator gives "
                       "the actuator controller its set-point (§1.1)"};
}

core::Result<std::unique_ptr<Device>> actuatorFor(const std::string& choice, StiffnessRigSetup& setup) {
  if (choice == kActuatorRigDrive) return std::unique_ptr<Device>();
  if (choice == kActuatorSimGenerator) {
    auto d = sim::makeFunctionGeneratorSimDriver();
    auto dev = d->create(DeviceDescriptor{d->name(), "", 0, 0, "", "sim:0"});
    if (!dev) return dev.error();
    setup.daqParameters["actuator.source"] = std::string(kActuatorSimGenerator);
    return std::move(dev).value();
  }
  if (choice == kActuatorUsbtmcGenerator) {
    Driver* d = builtinDrivers().find(kActuatorUsbtmcGenerator);
    if (!d)
      return core::makeError(core::ErrorCode::NotFound, "the usbtmc-funcgen driver is not built in", "setup.actuator");
    auto found = d->scan();
    if (!found) return found.error();
    if (found->empty())
      return core::makeError(core::ErrorCode::NotFound,
                             "no USBTMC function generator found (docs/hardware.md: permissions, cable)",
                             "setup.actuator");
    return d->create(found->front());
  }
  return core::makeError(core::ErrorCode::InvalidArgument,
                         "'" + choice +
                             "' is not an actuator set-point source (sim-stiffness, sim-funcgen, "
                             "usbtmc-funcgen)",
                         "setup.actuator");
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
