#include "devices/rigtests/fork_model_inputs.h"

#include <cstdio>

namespace mozzi::devices::rigtests {

namespace {

// Ranges as `mozzi-cli fork`'s option table (app/cli/commands/fork.cpp).
// Where the CLI takes any number above 0, the lower bound here is a small
// positive one: the form shows a field's decimals from its bounds and default
// (views/panels/parameter_form), so a measured 22.298577 Hz stays 22.298577
// and not 22.30.
ParameterSpec real(const char* key, const char* label, const char* unit, double min, double max, double value,
                   const char* help) {
  return ParameterSpec{key, label, ParameterType::Real, unit, min, max, {}, value, help};
}

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

std::vector<ParameterSpec> lumpedForkParameterSpecs() {
  return {
      real("fork.k", "Static bending stiffness", "N m/rad", 0.0, 1e9, 28e3,
           "from the static test and its decomposition (Table 10: 28 kNm/rad)"),
      real("fork.l1", "Static axis arm L1", "m", -10.0, 10.0, 0.670,
           "where the static twist axis meets the fork axis, from the contact point (Table 12: 0.670 m)"),
      real("fork.l2", "Dynamic axis arm L2", "m", -10.0, 10.0, 0.846,
           "where the modal twist axis meets the fork axis, from the contact point (Table 12: 0.846 m)"),
      real("fork.wheel_centre", "Wheel centre height", "m", -10.0, 10.0, 0.265,
           "wheel centre above the contact point (0.670 - 0.405 m, §4.2)"),
      real("fork.mass", "Vibrating mass", "kg", 1e-4, 1000.0, 11.0, "wheel and unsprung mass (8 + 3 kg, §4.2)"),
      real("fork.wheel_inertia", "Wheel inertia", "kg m^2", 0.0, 100.0, 0.278,
           "the wheel's diametrical moment of inertia (0.278 kgm^2, §4.2)"),
      real("fork.frequency", "Measured lateral mode", "Hz", 1e-4, 1e4, 22.3,
           "natural frequency of the lateral mode with the wheel (Table 11: 22.3 Hz)"),
      real("fork.zeta", "Viscous damping ratio", "", 1e-6, 1.0, 0.024, "of that mode, as a fraction (Table 11: 2.4 %)"),
  };
}

core::stiffness::ForkLumpedInput lumpedForkInput(const ParameterMap& v) {
  core::stiffness::ForkLumpedInput in;
  in.staticBendStiffness = parameterReal(v, "fork.k", 0.0);
  in.staticAxisArm = parameterReal(v, "fork.l1", 0.0);
  in.dynamicAxisArm = parameterReal(v, "fork.l2", 0.0);
  in.wheelCentreHeight = parameterReal(v, "fork.wheel_centre", 0.0);
  in.vibratingMass = parameterReal(v, "fork.mass", 0.0);
  in.wheelInertia = parameterReal(v, "fork.wheel_inertia", 0.0);
  in.measuredFrequencyHz = parameterReal(v, "fork.frequency", 0.0);
  in.zeta = parameterReal(v, "fork.zeta", 0.0);
  return in;
}

std::vector<std::string> lumpedForkCliArguments(const core::stiffness::ForkLumpedInput& in) {
  return {"--k",
          number(in.staticBendStiffness),
          "--l1",
          number(in.staticAxisArm),
          "--l2",
          number(in.dynamicAxisArm),
          "--wheel-centre",
          number(in.wheelCentreHeight),
          "--mass",
          number(in.vibratingMass),
          "--wheel-inertia",
          number(in.wheelInertia),
          "--freq",
          number(in.measuredFrequencyHz),
          "--zeta",
          number(in.zeta)};
}

std::vector<ParameterSpec> bicycleForkParameterSpecs() {
  return {
      real("bicycle.fork_mass", "Fork mass", "kg", 1e-4, 100.0, 0.393,
           "m_fork (Table 21: carbon 0.393, steel 1.336 kg)"),
      real("bicycle.wheel_mass", "Wheel mass", "kg", 1e-4, 100.0, 1.334, "m_F (Table 21)"),
      real("bicycle.wheel_radius", "Wheel radius", "m", 1e-4, 2.0, 0.350, "r_F (Table 21)"),
      real("bicycle.hub_mass", "Hub mass", "kg", 1e-4, 100.0, 0.094, "the fake hub of the fork-alone test (Table 21)"),
      real("bicycle.hub_radius", "Hub radius", "m", 1e-5, 1.0, 0.004, "Table 21"),
      real("bicycle.hub_length", "Hub length", "m", 1e-4, 1.0, 0.225, "Table 21"),
      real("bicycle.tip_distance", "Blade-tip distance d", "m", 1e-4, 5.0, 0.060,
           "blade tips to the steering axis (eq. 52; not printed, 0.060 m assumed)"),
      real("bicycle.max_bend_arm", "Largest bending arm", "m", 1e-4, 5.0, 0.460,
           "h_W range upper end: the lower jaw fixing point (§6.5: 0.460 m)"),
      real("bicycle.f_tors_wheel", "Torsion mode with wheel", "Hz", 1e-4, 1e4, 19.3, "Table 20, carbon fork"),
      real("bicycle.eta_tors_wheel", "Torsion loss factor with wheel", "", 1e-6, 2.0, 0.1004,
           "hysteretic eta = 2 zeta (Table 20: 10.04 %)"),
      real("bicycle.f_tors_alone", "Torsion mode, fork alone", "Hz", 1e-4, 1e4, 191.2, "Table 19, carbon fork"),
      real("bicycle.f_tors_alone2", "Second torsion mode, fork alone", "Hz", 0.0, 1e4, 0.0,
           "0 when the fork alone shows one torsion mode (steel fork: 230.1 Hz, eq. 54)"),
      real("bicycle.f_bend_wheel", "Lateral mode with wheel", "Hz", 1e-4, 1e4, 21.3, "Table 20, carbon fork"),
      real("bicycle.eta_bend_wheel", "Lateral loss factor with wheel", "", 1e-6, 2.0, 0.0424,
           "hysteretic eta = 2 zeta (Table 20: 4.24 %)"),
      real("bicycle.f_bend_alone", "Lateral mode, fork alone", "Hz", 1e-4, 1e4, 64.0, "Table 19, carbon fork"),
  };
}

BicycleForkInput bicycleForkInput(const ParameterMap& v) {
  BicycleForkInput in;
  auto& p = in.parameters;
  p.forkMass = parameterReal(v, "bicycle.fork_mass", 0.0);
  p.wheelMass = parameterReal(v, "bicycle.wheel_mass", 0.0);
  p.wheelRadius = parameterReal(v, "bicycle.wheel_radius", 0.0);
  p.hubMass = parameterReal(v, "bicycle.hub_mass", 0.0);
  p.hubRadius = parameterReal(v, "bicycle.hub_radius", 0.0);
  p.hubLength = parameterReal(v, "bicycle.hub_length", 0.0);
  p.tipDistance = parameterReal(v, "bicycle.tip_distance", 0.0);
  p.maxBendArm = parameterReal(v, "bicycle.max_bend_arm", 0.460);
  in.torsionWithWheelHz = parameterReal(v, "bicycle.f_tors_wheel", 0.0);
  in.torsionWithWheelEta = parameterReal(v, "bicycle.eta_tors_wheel", 0.0);
  in.torsionAloneHz = parameterReal(v, "bicycle.f_tors_alone", 0.0);
  in.torsionAlone2Hz = parameterReal(v, "bicycle.f_tors_alone2", 0.0);
  in.bendingWithWheelHz = parameterReal(v, "bicycle.f_bend_wheel", 0.0);
  in.bendingWithWheelEta = parameterReal(v, "bicycle.eta_bend_wheel", 0.0);
  in.bendingAloneHz = parameterReal(v, "bicycle.f_bend_alone", 0.0);
  return in;
}

std::vector<std::string> bicycleForkCliArguments(const BicycleForkInput& in) {
  const auto& p = in.parameters;
  std::vector<std::string> a{"--fork-mass",      number(p.forkMass),
                             "--wheel-mass",     number(p.wheelMass),
                             "--wheel-radius",   number(p.wheelRadius),
                             "--hub-mass",       number(p.hubMass),
                             "--hub-radius",     number(p.hubRadius),
                             "--hub-length",     number(p.hubLength),
                             "--tip-distance",   number(p.tipDistance),
                             "--max-bend-arm",   number(p.maxBendArm),
                             "--f-tors-wheel",   number(in.torsionWithWheelHz),
                             "--eta-tors-wheel", number(in.torsionWithWheelEta),
                             "--f-tors-alone",   number(in.torsionAloneHz),
                             "--f-bend-wheel",   number(in.bendingWithWheelHz),
                             "--eta-bend-wheel", number(in.bendingWithWheelEta),
                             "--f-bend-alone",   number(in.bendingAloneHz)};
  if (in.torsionAlone2Hz > 0) {
    a.push_back("--f-tors-alone2");
    a.push_back(number(in.torsionAlone2Hz));
  }
  return a;
}

nlohmann::json lumpedModelsJson(const core::stiffness::ForkLumpedModels& models) {
  auto one = [](const core::stiffness::LumpedModel& m) {
    return nlohmann::json{{"stiffness_Nm_per_rad", m.stiffness},
                          {"arm_m", m.arm},
                          {"inertia_kgm2", m.inertia},
                          {"pure_moment_kgm2", m.pureMoment},
                          {"frequency_Hz", m.frequencyHz},
                          {"damping_Nms_per_rad", m.damping},
                          {"zeta", m.zeta}};
  };
  return {{"model1", one(models.model1)}, {"model2", one(models.model2)}, {"model3", one(models.model3)}};
}

nlohmann::json lumpedInputJson(const core::stiffness::ForkLumpedInput& in) {
  return {{"static_bend_stiffness_Nm_per_rad", in.staticBendStiffness},
          {"static_axis_arm_L1_m", in.staticAxisArm},
          {"dynamic_axis_arm_L2_m", in.dynamicAxisArm},
          {"wheel_centre_height_m", in.wheelCentreHeight},
          {"vibrating_mass_kg", in.vibratingMass},
          {"wheel_inertia_kgm2", in.wheelInertia},
          {"measured_frequency_Hz", in.measuredFrequencyHz},
          {"zeta", in.zeta}};
}

}  // namespace mozzi::devices::rigtests
