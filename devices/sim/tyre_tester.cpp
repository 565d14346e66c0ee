// Simulated Mototiremeter (thesis §1.8, §1.9, §5.1): rotating disk, yaw and
// camber servos, three load cells, rate gyro. The tyre is the first-order
// form of the ring model (appendix 1, last FRF): the slip angle the patch
// feels, alpha, lags the enforced yaw psi as
//   sigma d(alpha)/dt + V alpha = V psi - a d(psi)/dt,
// which gives F/psi = C (V - i w a) / (V + i w sigma) in the linear range
// (core/tire/relaxation_length.h, eq. 1), and the forces come from a Magic
// Formula of that slip and the camber (core/tire/magic_formula.h) whose slope
// at the origin is the cornering stiffness C and whose camber thrust is
// F_z pVy3 gamma. sigma defaults to the thesis prediction of eq. 48 for the
// chosen tyre (Table 16 ring, Table 17 contact half-length at the pressure).
#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "core/tire/magic_formula.h"
#include "core/tire/relaxation_prediction.h"
#include "core/tire/ring_model.h"
#include "core/tire/thesis_tyres.h"
#include "devices/mcc_usb1608fsplus/usb1608fsplus_protocol.h"
#include "devices/sim/sim_device.h"
#include "devices/sim/specimen_catalogue.h"

namespace mozzi::devices::sim {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kRollingResistance = 0.015;  // assumed f_r: M_y = -f_r F_z r

core::Result<std::vector<double>> parseFrequencies(const std::string& text) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    char* end = nullptr;
    const double f = std::strtod(item.c_str(), &end);
    while (end && *end == ' ') ++end;
    if (end == item.c_str() || (end && *end != '\0') || !std::isfinite(f) || f <= 0.0 || f > 20.0)
      return core::makeError(core::ErrorCode::InvalidArgument, "'" + item + "' is not a frequency in (0, 20] Hz",
                             "parameter yaw.frequencies_hz");
    out.push_back(f);
  }
  if (out.empty())
    return core::makeError(core::ErrorCode::InvalidArgument, "no frequency given", "parameter yaw.frequencies_hz");
  return out;
}

const core::tire::ThesisTyre* thesisTyre(const std::string& key) {
  const auto keys = tyreSpecimenKeys();
  for (std::size_t i = 0; i < keys.size() && i < core::tire::thesisTyres().size(); ++i)
    if (keys[i] == key) return &core::tire::thesisTyres()[i];
  return nullptr;
}

std::size_t mfIndex(const std::string& name) {
  const auto& names = core::tire::mfLateralNames();
  return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

}  // namespace

double tyreHalfLengthAt(const std::string& tyreKey, double pressurePa) {
  const auto* t = thesisTyre(tyreKey);
  return t ? core::tire::table17HalfLength(*t, pressurePa) : 0.0;
}

core::Result<TyreTesterSetup> tyreTesterSetup(const ParameterMap& parameters) {
  const std::string key = parameterText(parameters, "tyre", "tyre-120-70-r17");
  const auto* t = thesisTyre(key);
  if (!t) return core::makeError(core::ErrorCode::NotFound, "no such thesis tyre", "tyre " + key);
  TyreTesterSetup s;
  s.tyre = key;
  s.pressurePa = parameterReal(parameters, "tyre.pressure_bar", 2.0) * 1e5;
  s.load = parameterReal(parameters, "tyre.load", 0.0);
  if (s.load <= 0.0) s.load = t->testLoad;
  s.speed = parameterReal(parameters, "disk.speed_kmh", 5.0) / 3.6;
  s.halfLength = tyreHalfLengthAt(key, s.pressurePa);
  s.corneringStiffness = parameterReal(parameters, "tyre.cornering_stiffness", 0.0);
  if (s.corneringStiffness <= 0.0) s.corneringStiffness = core::tire::kAssumedNormalisedCorneringStiffness * s.load;
  s.camberStiffness = parameterReal(parameters, "tyre.camber_stiffness", 0.0);
  if (s.camberStiffness <= 0.0) s.camberStiffness = kAssumedNormalisedCamberStiffness * s.load;
  s.relaxationLength = parameterReal(parameters, "tyre.relaxation_length", 0.0);
  if (s.relaxationLength <= 0.0) {
    // Eq. 48 with the Table 16 ring (nominal pressure) and Table 17's a.
    std::vector<core::tire::RingStiffnessInput> in = {{0, t->lateralStiffness, core::tire::kAssumedDampingRatio},
                                                      {1, t->camberStiffness, core::tire::kAssumedDampingRatio},
                                                      {2, t->cShapedStiffness, core::tire::kAssumedDampingRatio},
                                                      {3, t->sShapedStiffness, core::tire::kAssumedDampingRatio}};
    auto ring = core::tire::ringModelFromStiffness(in, core::tire::RingModelSettings{t->tyreMass, 0.8, t->outerRadius});
    if (!ring) return ring.error();
    core::tire::ContactPatchInputs cp;
    cp.halfLength = s.halfLength;
    cp.corneringStiffness = s.corneringStiffness;
    cp.verticalLoad = s.load;
    cp.friction = core::tire::kAssumedFriction;
    auto pred = core::tire::predictRelaxationLength(*ring, cp);
    if (!pred) return pred.error();
    s.relaxationLength = pred->total();
  }
  s.outerRadius = t->outerRadius;
  return s;
}

namespace {

class TyreModel final : public SignalModel {
 public:
  core::Result<void> prepare(const AcquisitionConfig& config) override {
    auto setup = tyreTesterSetup(config.parameters);
    if (!setup) return setup.error();
    s_ = *setup;
    fs_ = config.sampleRateHz;
    const std::string mode = parameterText(config.parameters, "mode", "harmonic-yaw");
    mode_ = mode == "slip-sweep"     ? Mode::SlipSweep
            : mode == "camber-sweep" ? Mode::CamberSweep
            : mode == "steady-state" ? Mode::Steady
                                     : Mode::HarmonicYaw;
    const double yawLimit = parameterReal(config.parameters, "servo.yaw_limit_deg", 6.0) * kDeg;
    const double camberLimit = parameterReal(config.parameters, "servo.camber_limit_deg", 45.0) * kDeg;
    amplitude_ = parameterReal(config.parameters, "yaw.amplitude_deg", 1.5) * kDeg;
    slipMax_ = parameterReal(config.parameters, "sweep.slip_max_deg", 6.0) * kDeg;
    camberMax_ = parameterReal(config.parameters, "sweep.camber_max_deg", 45.0) * kDeg;
    fixedCamber_ = parameterReal(config.parameters, "sweep.camber_deg", 0.0) * kDeg;
    fixedSlip_ = parameterReal(config.parameters, "sweep.slip_deg", 0.0) * kDeg;
    period_ = parameterReal(config.parameters, "sweep.period_s", 60.0);
    const char* where = "simulated tyre tester";
    auto beyond = [&](double angle, double limit, const char* what) -> core::Result<void> {
      if (std::abs(angle) > limit + 1e-12)
        return core::makeError(core::ErrorCode::InvalidArgument,
                               std::string(what) +
                                   " exceeds the servo limit (raise servo.*_limit_deg up to the "
                                   "machine's 10 deg yaw, 55 deg camber, §1.8, appendix 2)",
                               where);
      return {};
    };
    if (mode_ == Mode::HarmonicYaw) {
      if (auto r = beyond(amplitude_, yawLimit, "the yaw amplitude"); !r) return r;
    } else if (mode_ == Mode::SlipSweep) {
      if (auto r = beyond(slipMax_, yawLimit, "the slip sweep"); !r) return r;
      if (auto r = beyond(fixedCamber_, camberLimit, "the camber"); !r) return r;
    } else if (mode_ == Mode::CamberSweep) {
      if (auto r = beyond(camberMax_, camberLimit, "the camber sweep"); !r) return r;
      if (auto r = beyond(fixedSlip_, yawLimit, "the slip angle"); !r) return r;
    } else {
      if (auto r = beyond(fixedSlip_, yawLimit, "the slip angle"); !r) return r;
      if (auto r = beyond(fixedCamber_, camberLimit, "the camber"); !r) return r;
    }
    auto freqs = parseFrequencies(parameterText(config.parameters, "yaw.frequencies_hz", "0.42,0.84,1.26,1.68,2.10"));
    if (!freqs) return freqs.error();
    const auto cycles = parameterInteger(config.parameters, "yaw.cycles", 10);
    steps_.clear();
    double t = 0.0;
    for (double f : *freqs) {
      steps_.push_back({t, f});
      t += static_cast<double>(cycles) / f;
    }
    programEnd_ = t;
    // Magic Formula with F_z0 = F_z: K_ya = pKy1 F_z sin(2 atan(1/pKy2)) = C.
    constants_ = core::tire::MfConstants{s_.load, 2e5, s_.outerRadius};
    lateral_ = core::tire::mfLateralDefaults();
    lateral_[mfIndex("pKy1")] =
        s_.corneringStiffness / (s_.load * std::sin(2.0 * std::atan(1.0 / lateral_[mfIndex("pKy2")])));
    lateral_[mfIndex("pVy3")] = s_.camberStiffness / s_.load;
    aligning_ = core::tire::mfAligningDefaults();
    forceNoise_ = parameterReal(config.parameters, "noise.force_rms", 2.0);
    gyroNoise_ = parameterReal(config.parameters, "noise.gyro_rms", 0.002);
    momentNoise_ = parameterReal(config.parameters, "noise.moment_rms", 0.05);
    rng_.seed(static_cast<std::uint64_t>(parameterInteger(config.parameters, "sim.seed", 1)) + 4242u);
    alpha_ = 0.0;
    nextScan_ = 0;
    return {};
  }

  void generate(std::int64_t first, Eigen::Index n, const std::vector<int>& inputs, core::Matrix& out,
                FaultCounters&) override {
    std::normal_distribution<double> noise(0.0, 1.0);
    while (nextScan_ < first) advance();  // scans lost to an injected overrun still pass on the disk
    for (Eigen::Index s = 0; s < n; ++s) {
      const double t = static_cast<double>(nextScan_) / fs_;
      const double psi = yaw(t), gamma = camber(t);
      const double fy = core::tire::mfLateralForce(lateral_, constants_, alpha_, gamma, s_.load, s_.pressurePa);
      const double mz =
          core::tire::mfAligningTorque(aligning_, lateral_, constants_, alpha_, gamma, s_.load, s_.pressurePa);
      for (std::size_t c = 0; c < inputs.size(); ++c) {
        double v = 0.0;
        switch (inputs[c]) {
          case 0: v = yawRate(t) + gyroNoise_ * noise(rng_); break;
          case 1: v = fy + forceNoise_ * noise(rng_); break;
          case 2: v = mz + momentNoise_ * noise(rng_); break;
          case 3: v = -kRollingResistance * s_.load * s_.outerRadius + momentNoise_ * noise(rng_); break;
          case 4: v = psi; break;
          case 5: v = gamma; break;
          default: break;
        }
        out(s, static_cast<Eigen::Index>(c)) = v;
      }
      advance();
    }
  }

  void marks(std::int64_t first, Eigen::Index n, std::vector<TriggerEvent>& out) override {
    if (mode_ != Mode::HarmonicYaw) return;
    for (const auto& st : steps_) {
      const auto k = static_cast<std::int64_t>(std::llround(st.start * fs_));
      if (k >= first && k < first + n) out.push_back(TriggerEvent{k, 0, st.frequency});
    }
  }

 private:
  enum class Mode { HarmonicYaw, SlipSweep, CamberSweep, Steady };
  struct Step {
    double start;
    double frequency;
  };

  // Triangle 0 -> +max -> -max -> 0 over one period, and its slope.
  double triangle(double t, double max) const {
    const double x = std::fmod(t / period_, 1.0);
    if (x < 0.25) return max * 4.0 * x;
    if (x < 0.75) return max * (2.0 - 4.0 * x);
    return max * (4.0 * x - 4.0);
  }
  double triangleRate(double t, double max) const {
    const double x = std::fmod(t / period_, 1.0);
    return (x < 0.25 || x >= 0.75 ? 4.0 : -4.0) * max / period_;
  }
  const Step* stepAt(double t) const {
    if (t >= programEnd_) return nullptr;
    const Step* cur = nullptr;
    for (const auto& st : steps_)
      if (t >= st.start) cur = &st;
    return cur;
  }

  double yaw(double t) const {
    switch (mode_) {
      case Mode::HarmonicYaw: {
        const Step* st = stepAt(t);
        return st ? amplitude_ * std::sin(2.0 * kPi * st->frequency * (t - st->start)) : 0.0;
      }
      case Mode::SlipSweep: return triangle(t, slipMax_);
      case Mode::CamberSweep:
      case Mode::Steady: return fixedSlip_;
    }
    return 0.0;
  }
  double yawRate(double t) const {
    switch (mode_) {
      case Mode::HarmonicYaw: {
        const Step* st = stepAt(t);
        const double w = st ? 2.0 * kPi * st->frequency : 0.0;
        return st ? amplitude_ * w * std::cos(w * (t - st->start)) : 0.0;
      }
      case Mode::SlipSweep: return triangleRate(t, slipMax_);
      case Mode::CamberSweep:
      case Mode::Steady: return 0.0;
    }
    return 0.0;
  }
  double camber(double t) const { return mode_ == Mode::CamberSweep ? triangle(t, camberMax_) : fixedCamber_; }

  // d(alpha)/dt = (V psi - a psi' - V alpha) / sigma
  double slope(double t, double alpha) const {
    return (s_.speed * yaw(t) - s_.halfLength * yawRate(t) - s_.speed * alpha) / s_.relaxationLength;
  }

  // One sample period of RK4, in sub-steps of at most 1/20 of the time
  // constant sigma / V.
  void advance() {
    const double dt = 1.0 / fs_;
    const double tau = s_.relaxationLength / s_.speed;
    const int sub = std::max(1, static_cast<int>(std::ceil(dt / (tau / 20.0))));
    const double h = dt / sub;
    double t = static_cast<double>(nextScan_) * dt;
    for (int i = 0; i < sub; ++i, t += h) {
      const double k1 = slope(t, alpha_);
      const double k2 = slope(t + h / 2, alpha_ + h / 2 * k1);
      const double k3 = slope(t + h / 2, alpha_ + h / 2 * k2);
      const double k4 = slope(t + h, alpha_ + h * k3);
      alpha_ += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    ++nextScan_;
  }

  TyreTesterSetup s_;
  Mode mode_ = Mode::HarmonicYaw;
  double fs_ = 0.0, amplitude_ = 0.0, slipMax_ = 0.0, camberMax_ = 0.0, fixedCamber_ = 0.0, fixedSlip_ = 0.0;
  double period_ = 60.0, programEnd_ = 0.0;
  std::vector<Step> steps_;
  core::tire::MfConstants constants_;
  core::tire::MfLateralCoefficients lateral_{};
  core::tire::MfAligningCoefficients aligning_{};
  double forceNoise_ = 0.0, gyroNoise_ = 0.0, momentNoise_ = 0.0;
  std::mt19937_64 rng_;
  double alpha_ = 0.0;  // lagged slip angle [rad]
  std::int64_t nextScan_ = 0;
};

Capabilities tyreTesterCapabilities() {
  Capabilities caps;
  caps.model = "Simulated Mototiremeter (rotating-disk tyre tester)";
  caps.inputs = {simInput("yaw rate gyro", false),      simInput("lateral force Fy", false),
                 simInput("aligning moment Mz", false), simInput("spin-axis moment My", false),
                 simInput("yaw angle (servo)", false),  simInput("camber angle (servo)", false)};
  caps.outputs = {OutputSpec{"yaw servo", "deg", -kTyreTesterMaxYawDeg, kTyreTesterMaxYawDeg},
                  OutputSpec{"camber servo", "deg", -kTyreTesterMaxCamberDeg, kTyreTesterMaxCamberDeg},
                  OutputSpec{"disk speed", "km/h", 0.0, kTyreTesterMaxSpeedKmh}};
  caps.rates = RateSpec{1.0, 10000.0, 60000.0, 0.0, true};
  caps.triggers = {TriggerKind::Immediate};
  caps.fifoSamples = mcc::kFifoSamples;
  caps.parameters = commonSimParameters();
  std::vector<ParameterSpec> own = {
      ParameterSpec{"tyre", "Tyre", ParameterType::Choice, "", std::nullopt, std::nullopt, tyreSpecimenKeys(),
                    std::string("tyre-120-70-r17"), "one of the six thesis tyres (chapter 5, Tables 15-17)"},
      ParameterSpec{"tyre.pressure_bar",
                    "Inflation pressure",
                    ParameterType::Real,
                    "bar",
                    0.5,
                    4.0,
                    {},
                    2.0,
                    "selects the contact half-length of Table 17 (interpolated)"},
      ParameterSpec{"tyre.load",
                    "Vertical load",
                    ParameterType::Real,
                    "N",
                    0.0,
                    3000.0,
                    {},
                    0.0,
                    "0 = the thesis test load (1500 N; 1000 N for the 12 inch tyres, §5.4)"},
      ParameterSpec{"tyre.cornering_stiffness",
                    "Cornering stiffness",
                    ParameterType::Real,
                    "N/rad",
                    0.0,
                    1e6,
                    {},
                    0.0,
                    "0 = 13 F_z /rad (assumed, core/tire/thesis_tyres.h)"},
      ParameterSpec{"tyre.camber_stiffness",
                    "Camber stiffness",
                    ParameterType::Real,
                    "N/rad",
                    0.0,
                    1e6,
                    {},
                    0.0,
                    "0 = 0.9 F_z /rad (assumed)"},
      ParameterSpec{"tyre.relaxation_length",
                    "Relaxation length",
                    ParameterType::Real,
                    "m",
                    0.0,
                    2.0,
                    {},
                    0.0,
                    "0 = the thesis prediction of eq. 48 for this tyre and pressure"},
      ParameterSpec{"disk.speed_kmh",
                    "Disk speed",
                    ParameterType::Real,
                    "km/h",
                    0.5,
                    50.0,
                    {},
                    5.0,
                    "forward speed of the track under the tyre; the thesis tests ran at 5 km/h (§1.9)"},
      ParameterSpec{"mode",
                    "Test",
                    ParameterType::Choice,
                    "",
                    std::nullopt,
                    std::nullopt,
                    {"harmonic-yaw", "slip-sweep", "camber-sweep", "steady-state"},
                    std::string("harmonic-yaw"),
                    "harmonic yaw for the relaxation length (§1.9), a side-slip or camber sweep, or one held "
                    "steady-state set-point (sweep.slip_deg, sweep.camber_deg; appendix 2)"},
      ParameterSpec{"yaw.amplitude_deg",
                    "Yaw amplitude",
                    ParameterType::Real,
                    "deg",
                    0.1,
                    10.0,
                    {},
                    1.5,
                    "harmonic yaw amplitude (§5.1: 1.5 deg)"},
      ParameterSpec{"yaw.frequencies_hz",
                    "Yaw frequencies",
                    ParameterType::Text,
                    "Hz",
                    std::nullopt,
                    std::nullopt,
                    {},
                    std::string("0.42,0.84,1.26,1.68,2.10"),
                    "the step-increasing frequencies of §5.1; a trigger mark starts each"},
      ParameterSpec{"yaw.cycles",
                    "Cycles per frequency",
                    ParameterType::Integer,
                    "",
                    1.0,
                    1000.0,
                    {},
                    std::int64_t{10},
                    "about 10 cycles at each frequency (§5.1)"},
      ParameterSpec{"servo.yaw_limit_deg",
                    "Yaw servo limit",
                    ParameterType::Real,
                    "deg",
                    0.0,
                    10.0,
                    {},
                    6.0,
                    "the machine reaches 10 deg; 6 deg by default against arm oscillations (§1.8)"},
      ParameterSpec{"servo.camber_limit_deg",
                    "Camber servo limit",
                    ParameterType::Real,
                    "deg",
                    0.0,
                    kTyreTesterMaxCamberDeg,
                    {},
                    45.0,
                    "the machine reaches 55 deg (appendix 2; §1.8 prints 54); 45 deg by default (§1.8)"},
      ParameterSpec{"sweep.slip_max_deg",
                    "Slip sweep amplitude",
                    ParameterType::Real,
                    "deg",
                    0.1,
                    10.0,
                    {},
                    6.0,
                    "side-slip triangle 0 -> +max -> -max -> 0"},
      ParameterSpec{"sweep.camber_max_deg",
                    "Camber sweep amplitude",
                    ParameterType::Real,
                    "deg",
                    0.1,
                    kTyreTesterMaxCamberDeg,
                    {},
                    45.0,
                    "camber triangle 0 -> +max -> -max -> 0"},
      ParameterSpec{"sweep.period_s",
                    "Sweep period",
                    ParameterType::Real,
                    "s",
                    1.0,
                    3600.0,
                    {},
                    60.0,
                    "slow enough to be quasi-static (sigma/V is about 0.1 s at 5 km/h)"},
      ParameterSpec{"sweep.camber_deg",
                    "Camber during a slip sweep",
                    ParameterType::Real,
                    "deg",
                    -kTyreTesterMaxCamberDeg,
                    kTyreTesterMaxCamberDeg,
                    {},
                    0.0,
                    "also the held camber of a steady-state set-point"},
      ParameterSpec{"sweep.slip_deg",
                    "Slip during a camber sweep",
                    ParameterType::Real,
                    "deg",
                    -kTyreTesterMaxYawDeg,
                    kTyreTesterMaxYawDeg,
                    {},
                    0.0,
                    "also the held side-slip of a steady-state set-point"},
      ParameterSpec{"noise.force_rms", "Load-cell noise", ParameterType::Real, "N", 0.0, 100.0, {}, 2.0, ""},
      ParameterSpec{"noise.gyro_rms", "Gyro noise", ParameterType::Real, "rad/s", 0.0, 1.0, {}, 0.002, ""},
      ParameterSpec{"noise.moment_rms", "Moment noise", ParameterType::Real, "N m", 0.0, 100.0, {}, 0.05, ""},
  };
  caps.parameters.insert(caps.parameters.end(), own.begin(), own.end());
  return caps;
}

}  // namespace

std::unique_ptr<Driver> makeTyreTesterDriver() {
  return makeSimDriver(
      "sim-tyre-tester",
      "Simulated Mototiremeter: rotating disk, yaw and camber servos, load cells, rate gyro (thesis §1.8, §1.9)",
      "Simulated Mototiremeter", &tyreTesterCapabilities,
      +[]() -> std::unique_ptr<SignalModel> { return std::make_unique<TyreModel>(); });
}

}  // namespace mozzi::devices::sim
