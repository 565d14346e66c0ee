#include "devices/sim/sim_drivers.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <complex>
#include <mutex>
#include <random>
#include <thread>

#include "core/signal/hit_synthesis.h"
#include "core/tire/tire_csv.h"
#include "devices/funcgen/funcgen_driver.h"
#include "devices/mcc_usb1608fsplus/usb1608fsplus_protocol.h"
#include "devices/sim/sim_device.h"
#include "devices/sim/specimen_models.h"

namespace mozzi::devices::sim {

double hammerPulseWidthS(double hammerMassKg, double tipStiffnessNPerM) {
  return 3.14159265358979323846 * std::sqrt(hammerMassKg / tipStiffnessNPerM);
}

double actuatorSineAmplitude(double amplitudeAt1HzN, double frequencyHz) {
  return amplitudeAt1HzN * (1.0 - 0.8 * std::log(frequencyHz) / std::log(45.0));
}

namespace {

// ---------------------------------------------------------------- hammer station

struct Tip {
  const char* name;
  double stiffness;  // N/m
};
// Contact stiffnesses chosen to give the usual contact times of a 0.16 kg
// hammer (PCB 086C03): steel ~0.3 ms, plastic ~1 ms, rubber ~3 ms.
constexpr Tip kTips[] = {{"steel", 1.6e7}, {"plastic", 1.6e6}, {"rubber", 1.6e5}};
constexpr double kHammerMassKg = 0.16;
// Hammer + 7 accelerometers: the 8 inputs of the MCC USB-1608FS-Plus.
constexpr int kAccelerometers = 7;

// Comma-separated DOF labels, blanks ignored: "12:+Y, 13:+Z".
std::vector<std::string> splitLabels(const std::string& text) {
  std::vector<std::string> out;
  std::string cur;
  auto flush = [&] {
    const auto b = cur.find_first_not_of(" \t");
    const auto e = cur.find_last_not_of(" \t");
    if (b != std::string::npos) out.push_back(cur.substr(b, e - b + 1));
    cur.clear();
  };
  for (char c : text) {
    if (c == ',')
      flush();
    else
      cur += c;
  }
  flush();
  return out;
}

class HammerModel final : public SignalModel {
 public:
  core::Result<void> prepare(const AcquisitionConfig& config) override {
    auto spec = modalSpecimen(parameterText(config.parameters, "specimen", "fork-a-without-wheel"));
    if (!spec) return spec.error();
    specimen_ = *spec;
    // Hammer point: "hammer.point", or the specimen's driving point.
    DofRow drive{specimen_.excitedDof, 1.0};
    const std::string point = parameterText(config.parameters, "hammer.point", "");
    if (!splitLabels(point).empty()) {
      const auto labels = splitLabels(point);
      if (labels.size() != 1)
        return core::makeError(core::ErrorCode::InvalidArgument,
                               "hammer.point takes one DOF label, not \"" + point + "\"", "parameter hammer.point");
      auto row = specimen_.findDof(labels.front());
      if (!row) return core::makeError(row.error().code, "hammer.point: " + row.error().message, row.error().where);
      drive = *row;
    }
    driven_ = specimen_.drivenSystem(drive.row, drive.sign);
    // Accelerometer DOFs: "response.dofs", or the first DOFs of the mesh.
    responses_.clear();
    const auto labels = splitLabels(parameterText(config.parameters, "response.dofs", ""));
    if (labels.size() > static_cast<std::size_t>(kAccelerometers))
      return core::makeError(core::ErrorCode::InvalidArgument,
                             std::to_string(labels.size()) + " response DOFs for " + std::to_string(kAccelerometers) +
                                 " accelerometer inputs",
                             "parameter response.dofs");
    for (const auto& label : labels) {
      auto row = specimen_.findDof(label);
      if (!row) return core::makeError(row.error().code, "response.dofs: " + row.error().message, row.error().where);
      responses_.push_back(*row);
    }
    if (labels.empty())
      for (Eigen::Index j = 0; j < std::min<Eigen::Index>(kAccelerometers, specimen_.shapes.rows()); ++j)
        responses_.push_back(DofRow{j, 1.0});
    fs_ = config.sampleRateHz;
    interval_ = std::max<std::int64_t>(
        16, static_cast<std::int64_t>(std::llround(parameterReal(config.parameters, "hammer.interval_s", 4.0) * fs_)));
    const std::string tip = parameterText(config.parameters, "hammer.tip", "plastic");
    double k = kTips[1].stiffness;
    for (const auto& t : kTips)
      if (tip == t.name) k = t.stiffness;
    pulseWidth_ = hammerPulseWidthS(kHammerMassKg, k);
    peak_ = parameterReal(config.parameters, "hammer.peak_force", 200.0);
    forceNoise_ = parameterReal(config.parameters, "noise.force_rms", 0.05);
    responseNoise_ = parameterReal(config.parameters, "noise.response_rms", 0.002);
    // An ADC toggles its last code: half a code rms of input noise on each
    // accelerometer input, in that channel's units (its range and sensitivity).
    // Without it a DOF the hit cannot move (a node of every mode excited
    // there) would read exactly zero, which only a broken cable does.
    inputNoise_.assign(1 + kAccelerometers, responseNoise_);
    for (const auto& ch : config.channels) {
      if (ch.input < 1 || ch.input > kAccelerometers) continue;
      const double voltsPerUnit = ch.transducer.sensitivityMvPerUnit / 1000.0 * ch.conditionerGain;
      for (const auto& r : mcc::ranges())
        if (r.code == ch.rangeCode && voltsPerUnit > 0.0) {
          const double codeUnits = (r.maxVolts - r.minVolts) / 65536.0 / voltsPerUnit;
          inputNoise_[static_cast<std::size_t>(ch.input)] = std::max(responseNoise_, 0.5 * codeUnits);
        }
    }
    pDouble_ = parameterReal(config.parameters, "fault.double_hit_probability", 0.0);
    pOverload_ = parameterReal(config.parameters, "fault.overload_probability", 0.0);
    overloadFactor_ = parameterReal(config.parameters, "fault.overload_factor", 30.0);
    seed_ = static_cast<std::uint64_t>(parameterInteger(config.parameters, "sim.seed", 1));
    // Quiet time before each hit: 0.25 s, or 15% of the interval when longer, so a
    // record as long as the interval has its 10% pre-trigger before the first hit.
    const double quietS = std::max(0.25, 0.15 * static_cast<double>(interval_) / fs_);
    preHit_ = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::llround(quietS * fs_)));
    segmentIndex_ = -1;
    return {};
  }

  void generate(std::int64_t first, Eigen::Index n, const std::vector<int>& inputs, core::Matrix& out,
                FaultCounters& counters) override {
    for (Eigen::Index s = 0; s < n; ++s) {
      const std::int64_t k = first + s;
      const std::int64_t seg = k / interval_;
      if (seg != segmentIndex_) makeSegment(seg, counters);
      const Eigen::Index row = static_cast<Eigen::Index>(k - seg * interval_);
      for (std::size_t c = 0; c < inputs.size(); ++c) {
        const int in = inputs[c];
        out(s, static_cast<Eigen::Index>(c)) = in < segment_.cols() ? segment_(row, in) : 0.0;
      }
    }
  }

 private:
  void makeSegment(std::int64_t seg, FaultCounters& counters) {
    // Faults of hit `seg` from its own generator: the same hits whatever the block size.
    std::mt19937_64 rng(seed_ * 1000003u + static_cast<std::uint64_t>(seg));
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const bool isDouble = u(rng) < pDouble_;
    const bool isOverload = u(rng) < pOverload_;
    core::signal::HammerHitSpec spec;
    spec.sampleRateHz = fs_;
    spec.sampleCount = static_cast<Eigen::Index>(interval_);
    spec.preTriggerSamples = static_cast<Eigen::Index>(preHit_);
    spec.oversampling = 8;
    spec.peakForceN = peak_ * (isOverload ? overloadFactor_ : 1.0) * (0.9 + 0.2 * u(rng));  // the hand varies +/-10%
    spec.pulseWidthS = pulseWidth_;
    spec.excitedDof = 0;  // coordinate 0 of the driven system is the hammer point
    spec.forceNoiseRms = forceNoise_;
    spec.responseNoiseRms = 0.0;  // added below, per accelerometer, after the map to the mesh DOFs
    spec.seed = seed_ * 7777u + static_cast<std::uint64_t>(seg) + 1u;
    if (isDouble) {
      spec.secondHitDelayS = 4.0 * pulseWidth_ + 0.004;  // a rebound a few ms after the first contact
      spec.secondHitFraction = 0.5;
    }
    const Eigen::Index ns = static_cast<Eigen::Index>(interval_);
    segment_ = core::Matrix::Zero(ns, 1 + kAccelerometers);
    auto rec = core::signal::synthesizeHammerHit(driven_.system, spec);
    if (rec) {
      // Accelerations of the driven coordinates y -> accelerometer DOFs: x = output * y.
      segment_.col(0) = rec->samples.col(0);
      const Eigen::Index m = driven_.output.cols();
      for (std::size_t a = 0; a < responses_.size(); ++a) {
        const core::Vector map = responses_[a].sign * driven_.output.row(responses_[a].row).transpose();
        segment_.col(static_cast<Eigen::Index>(a + 1)) = rec->samples.middleCols(1, m) * map;
      }
    }
    std::mt19937_64 noiseRng(seed_ * 104729u + static_cast<std::uint64_t>(seg) + 3u);
    std::normal_distribution<double> normal(0.0, 1.0);
    for (Eigen::Index c = 1; c <= kAccelerometers; ++c)
      for (Eigen::Index k = 0; k < ns; ++k)
        segment_(k, c) += inputNoise_[static_cast<std::size_t>(c)] * normal(noiseRng);
    segmentIndex_ = seg;
    ++counters.hits;
    if (isDouble) ++counters.doubleHits;
    if (isOverload) ++counters.overloadHits;
  }

  ModalSpecimen specimen_;
  DrivenSystem driven_;
  std::vector<DofRow> responses_;
  double fs_ = 0.0, pulseWidth_ = 0.0, peak_ = 0.0, forceNoise_ = 0.0, responseNoise_ = 0.0;
  std::vector<double> inputNoise_;  // per input: response noise, at least half an ADC code
  double pDouble_ = 0.0, pOverload_ = 0.0, overloadFactor_ = 30.0;
  std::int64_t interval_ = 1, preHit_ = 1;
  std::uint64_t seed_ = 1;
  std::int64_t segmentIndex_ = -1;
  core::Matrix segment_;
};

Capabilities hammerCapabilities() {
  Capabilities caps;
  caps.model = "Simulated impact hammer station";
  caps.inputs = {simInput("hammer", true)};
  for (int a = 1; a <= kAccelerometers; ++a) caps.inputs.push_back(simInput("acc " + std::to_string(a), true));
  caps.rates = RateSpec{1.0, 51200.0, 204800.0, 0.0, true};
  caps.triggers = {TriggerKind::Immediate, TriggerKind::Software};
  caps.fifoSamples = mcc::kFifoSamples;
  caps.parameters = commonSimParameters();
  std::vector<ParameterSpec> own = {
      ParameterSpec{
          "specimen", "Specimen", ParameterType::Choice, "", std::nullopt, std::nullopt, modalSpecimenKeys(),
          std::string("fork-a-without-wheel"),
          "virtual specimen with thesis modal parameters (Tables 6, 8, 11, 14, 16, 18, 19, 20; frames §2.1, §2.2)"},
      ParameterSpec{"hammer.point",
                    "Hammer point",
                    ParameterType::Text,
                    "",
                    std::nullopt,
                    std::nullopt,
                    {},
                    std::string(""),
                    "DOF label of the mesh the hammer strikes, e.g. 12:+Y (-Y: struck the other way); empty = the "
                    "specimen's driving point (the thesis's hammer point)"},
      ParameterSpec{"response.dofs",
                    "Accelerometer DOFs",
                    ParameterType::Text,
                    "",
                    std::nullopt,
                    std::nullopt,
                    {},
                    std::string(""),
                    "comma-separated DOF labels of the mesh for acc 1..7 in order; empty = the first DOFs of the "
                    "mesh; inputs without a DOF read noise only"},
      ParameterSpec{"hammer.tip",
                    "Hammer tip",
                    ParameterType::Choice,
                    "",
                    std::nullopt,
                    std::nullopt,
                    {"steel", "plastic", "rubber"},
                    std::string("plastic"),
                    "contact time pi sqrt(m/k): steel 0.3 ms, plastic 1 ms, rubber 3 ms"},
      ParameterSpec{"hammer.peak_force",
                    "Peak force",
                    ParameterType::Real,
                    "N",
                    1.0,
                    4000.0,
                    {},
                    200.0,
                    "nominal peak of a hit (+/-10%)"},
      ParameterSpec{"hammer.interval_s",
                    "Time between hits",
                    ParameterType::Real,
                    "s",
                    0.05,
                    60.0,
                    {},
                    4.0,
                    "one hit every so many seconds"},
      ParameterSpec{"noise.force_rms",
                    "Force noise",
                    ParameterType::Real,
                    "N",
                    0.0,
                    100.0,
                    {},
                    0.05,
                    "white noise RMS on the hammer"},
      ParameterSpec{"noise.response_rms",
                    "Response noise",
                    ParameterType::Real,
                    "m/s^2",
                    0.0,
                    100.0,
                    {},
                    0.002,
                    "white noise RMS on each accelerometer"},
      ParameterSpec{"fault.double_hit_probability",
                    "Double-hit probability",
                    ParameterType::Real,
                    "",
                    0.0,
                    1.0,
                    {},
                    0.0,
                    "a hit rebounds (second contact at half the peak) with this probability"},
      ParameterSpec{"fault.overload_probability",
                    "Overload probability",
                    ParameterType::Real,
                    "",
                    0.0,
                    1.0,
                    {},
                    0.0,
                    "a hit is struck this many times harder than nominal with this probability"},
      ParameterSpec{"fault.overload_factor",
                    "Overload factor",
                    ParameterType::Real,
                    "",
                    1.0,
                    1000.0,
                    {},
                    30.0,
                    "peak multiplier of an overloaded hit"},
  };
  caps.parameters.insert(caps.parameters.end(), own.begin(), own.end());
  return caps;
}

// ---------------------------------------------------------------- stiffness rig

// The set-point line from the simulated function generator to the simulated
// rig (one simulated bench per process): what the generator was set to, and
// whether its output is on.
struct SimulatedSetPoint {
  std::mutex mutex;
  bool programmed = false;
  bool sine = false;
  double frequencyHz = 0.0, amplitudeN = 0.0, maxForceN = 0.0, periodS = 20.0;
  std::atomic<bool> on{false};
  FunctionGeneratorSimCounters counters;
};

SimulatedSetPoint& setPointLine() {
  static SimulatedSetPoint line;
  return line;
}

constexpr double kLoadCellFullScaleN = 200.0 * 9.80665;  // +/-200 kg (§1.1)
constexpr double kLaserRangeM = 0.020;                   // 20 mm (§1.1)
constexpr double kLaserResolutionM = 4e-6;               // 4 um (§1.1)

class StiffnessModel final : public SignalModel {
 public:
  core::Result<void> prepare(const AcquisitionConfig& config) override {
    auto spec = staticSpecimen(parameterText(config.parameters, "specimen", "frame-a-front-constrained"));
    if (!spec) return spec.error();
    specimen_ = *spec;
    fs_ = config.sampleRateHz;
    sine_ = parameterText(config.parameters, "mode", "static-ramp") == "sine";
    maxForce_ = parameterReal(config.parameters, "static.max_force", 0.0);
    if (maxForce_ <= 0.0) maxForce_ = specimen_.testForceN;  // the thesis's ramp for this specimen
    period_ = parameterReal(config.parameters, "static.period_s", 20.0);
    sineHz_ = parameterReal(config.parameters, "sine.frequency", 10.0);
    sineAmp_ = actuatorSineAmplitude(parameterReal(config.parameters, "sine.amplitude_1hz", 1000.0), sineHz_);
    fromGenerator_ = parameterText(config.parameters, "actuator.source", "internal") == "sim-funcgen";
    if (fromGenerator_) {
      // The actuator follows the simulated function generator's set-point.
      auto& line = setPointLine();
      std::lock_guard<std::mutex> lock(line.mutex);
      if (!line.programmed)
        return core::makeError(core::ErrorCode::InvalidArgument,
                               "the simulated function generator has not been set: configure it first",
                               "actuator.source");
      sine_ = line.sine;
      sineHz_ = line.frequencyHz;
      sineAmp_ = actuatorSineAmplitude(line.amplitudeN, sineHz_);
      maxForce_ = line.maxForceN;
      period_ = line.periodS;
    }
    forceNoise_ = parameterReal(config.parameters, "noise.force_rms", 0.5);
    // Where the set-up puts the lasers and the load point (plate
    // coordinates [m]); empty: the specimen's own layout.
    lasers_ = specimen_.laserPoints;
    load_ = specimen_.loadPoint;
    const std::string lasers = parameterText(config.parameters, "lasers.points", "");
    if (!lasers.empty()) {
      auto t = core::tire::parseNumberTuples(lasers, 2, "lasers.points");
      if (!t) return t.error();
      if (t->size() != specimen_.laserPoints.size())
        return core::makeError(core::ErrorCode::InvalidArgument,
                               "give " + std::to_string(specimen_.laserPoints.size()) + " points u:v, one per laser",
                               "lasers.points");
      for (std::size_t i = 0; i < t->size(); ++i) lasers_[i] = core::Vector2((*t)[i][0], (*t)[i][1]);
    }
    const std::string load = parameterText(config.parameters, "load.point", "");
    if (!load.empty()) {
      auto t = core::tire::parseNumberTuples(load, 2, "load.point");
      if (!t) return t.error();
      if (t->size() != 1) return core::makeError(core::ErrorCode::InvalidArgument, "give one point u:v", "load.point");
      load_ = core::Vector2(t->front()[0], t->front()[1]);
    }
    receptance_.clear();
    for (const auto& p : lasers_) receptance_.push_back(specimen_.receptance(p, load_, sineHz_));
    rng_.seed(static_cast<std::uint64_t>(parameterInteger(config.parameters, "sim.seed", 1)) + 99u);
    return {};
  }

  // The actuator's soft start of a sine: the amplitude rises linearly over
  // this time (the transient a test lets settle before it records).
  static constexpr double kSineSoftStartS = 0.5;

  double envelope(double t) const { return std::min(1.0, t / kSineSoftStartS); }

  // Actuator force at time t: triangle 0 -> +F -> -F -> 0 over one period, or
  // the sine of the set frequency and its amplitude.
  double force(double t) const {
    if (fromGenerator_ && !setPointLine().on.load()) return 0.0;  // the generator's output is off
    if (sine_) return sineAmp_ * envelope(t) * std::sin(2.0 * 3.14159265358979323846 * sineHz_ * t);
    if (fromGenerator_) {  // the generator's RAMP at 50% symmetry: -F -> +F -> -F
      const double x = std::fmod(t / period_, 1.0);
      return x < 0.5 ? maxForce_ * (4.0 * x - 1.0) : maxForce_ * (3.0 - 4.0 * x);
    }
    const double x = std::fmod(t / period_, 1.0);
    if (x < 0.25) return maxForce_ * 4.0 * x;
    if (x < 0.75) return maxForce_ * (2.0 - 4.0 * x);
    return maxForce_ * (4.0 * x - 4.0);
  }

  void generate(std::int64_t first, Eigen::Index n, const std::vector<int>& inputs, core::Matrix& out,
                FaultCounters&) override {
    std::normal_distribution<double> noise(0.0, 1.0);
    for (Eigen::Index s = 0; s < n; ++s) {
      const double t = static_cast<double>(first + s) / fs_;
      const double f = force(t);
      for (std::size_t c = 0; c < inputs.size(); ++c) {
        const int in = inputs[c];
        double v = 0.0;
        if (in == 0) {
          v = f + forceNoise_ * noise(rng_);
        } else {
          // Quasi-static response to the slow ramp; the steady response of the
          // plate modes to a sine (StaticSpecimen::receptance: bending and
          // torsion oscillators, thesis §1.3, §1.7), scaled by the soft start.
          // Each laser quantises to its 4 um resolution and saturates at the
          // ends of its 20 mm range.
          const auto& p = lasers_[static_cast<std::size_t>(in - 1)];
          double w = 0.0;
          if (sine_) {
            const std::complex<double> h = receptance_[static_cast<std::size_t>(in - 1)];
            w = sineAmp_ * envelope(t) * std::abs(h) *
                std::sin(2.0 * 3.14159265358979323846 * sineHz_ * t + std::arg(h));
          } else {
            w = specimen_.displacementAt(p, load_, f);
          }
          v = std::clamp(kLaserResolutionM * std::round(w / kLaserResolutionM), -kLaserRangeM / 2, kLaserRangeM / 2);
        }
        out(s, static_cast<Eigen::Index>(c)) = v;
      }
    }
  }

 private:
  StaticSpecimen specimen_;
  std::vector<core::Vector2> lasers_;  // plate points of lasers 1.. [m]
  core::Vector2 load_ = core::Vector2::Zero();
  std::vector<std::complex<double>> receptance_;  // per laser at the sine frequency [m/N]
  double fs_ = 0.0, maxForce_ = 0.0, period_ = 20.0, sineHz_ = 10.0, sineAmp_ = 0.0, forceNoise_ = 0.0;
  bool sine_ = false;
  bool fromGenerator_ = false;
  std::mt19937_64 rng_;
};

Capabilities stiffnessCapabilities() {
  Capabilities caps;
  caps.model = "Simulated Motostiffmeter";
  caps.inputs = {simInput("load cell", false), simInput("laser 1", false), simInput("laser 2", false),
                 simInput("laser 3", false), simInput("laser 4", false)};
  caps.outputs = {OutputSpec{"actuator force set-point", "N", -5000.0, 5000.0}};
  caps.rates = RateSpec{1.0, 10000.0, 50000.0, 0.0, true};
  caps.triggers = {TriggerKind::Immediate};
  caps.fifoSamples = mcc::kFifoSamples;
  caps.parameters = commonSimParameters();
  std::vector<ParameterSpec> own = {
      ParameterSpec{"specimen", "Specimen", ParameterType::Choice, "", std::nullopt, std::nullopt, staticSpecimenKeys(),
                    std::string("frame-a-front-constrained"),
                    "virtual specimen with thesis static stiffness and twist axis (Tables 3, 4, 5, 7, 9, 10, 13)"},
      ParameterSpec{"mode",
                    "Actuator mode",
                    ParameterType::Choice,
                    "",
                    std::nullopt,
                    std::nullopt,
                    {"static-ramp", "sine"},
                    std::string("static-ramp"),
                    "slow triangular ramp or sine excitation (§1.1)"},
      ParameterSpec{"static.max_force",
                    "Ramp peak force",
                    ParameterType::Real,
                    "N",
                    0.0,
                    5000.0,
                    {},
                    0.0,
                    "up to 5000 N (§1.1); 0 = the thesis's range for the specimen (±300 N, fork B ±500 N, swing-arms "
                    "1000 N assumed)"},
      ParameterSpec{
          "static.period_s", "Ramp period", ParameterType::Real, "s", 1.0, 3600.0, {}, 20.0, "0 -> +F -> -F -> 0"},
      ParameterSpec{"sine.frequency",
                    "Sine frequency",
                    ParameterType::Real,
                    "Hz",
                    1.0,
                    45.0,
                    {},
                    10.0,
                    "dynamic excitation up to 45 Hz (§1.1)"},
      ParameterSpec{"sine.amplitude_1hz",
                    "Sine amplitude at 1 Hz",
                    ParameterType::Real,
                    "N",
                    1.0,
                    5000.0,
                    {},
                    1000.0,
                    "falls logarithmically with frequency to 20% at 45 Hz"},
      ParameterSpec{"actuator.source",
                    "Actuator set-point from",
                    ParameterType::Choice,
                    "",
                    std::nullopt,
                    std::nullopt,
                    {"internal", "sim-funcgen"},
                    std::string("internal"),
                    "internal: the rig's own drive (mode, static.*, sine.*); sim-funcgen: the simulated function "
                    "generator (§1.1)"},
      ParameterSpec{"lasers.points",
                    "Laser positions",
                    ParameterType::Text,
                    "m",
                    std::nullopt,
                    std::nullopt,
                    {},
                    std::string(),
                    "plate points u:v of lasers 1 to 4, separated by commas; empty = the specimen's plate layout"},
      ParameterSpec{"load.point",
                    "Load point",
                    ParameterType::Text,
                    "m",
                    std::nullopt,
                    std::nullopt,
                    {},
                    std::string(),
                    "plate point u:v where the actuator loads; empty = the specimen's load point"},
      ParameterSpec{"noise.force_rms",
                    "Load-cell noise",
                    ParameterType::Real,
                    "N",
                    0.0,
                    100.0,
                    {},
                    0.5,
                    "white noise RMS on the load cell"},
  };
  caps.parameters.insert(caps.parameters.end(), own.begin(), own.end());
  return caps;
}

}  // namespace

std::unique_ptr<Driver> makeHammerStationDriver() {
  return makeSimDriver(
      "sim-hammer", "Simulated impact hammer station (virtual specimens, thesis §1.4, §1.6)",
      "Simulated impact hammer station", &hammerCapabilities,
      +[]() -> std::unique_ptr<SignalModel> { return std::make_unique<HammerModel>(); });
}

std::unique_ptr<Driver> makeStiffnessRigDriver() {
  return makeSimDriver(
      "sim-stiffness", "Simulated Motostiffmeter: actuator, load cell, four lasers (thesis §1.1)",
      "Simulated Motostiffmeter", &stiffnessCapabilities,
      +[]() -> std::unique_ptr<SignalModel> { return std::make_unique<StiffnessModel>(); });
}

namespace {

// 33522B into high impedance (docs/hardware.md): 2 mVpp..20 Vpp, 10 V peak.
constexpr double kGeneratorMinVpp = 0.002, kGeneratorMaxVpp = 20.0, kGeneratorMaxPeakV = 10.0;

class FunctionGeneratorSim final : public Device {
 public:
  explicit FunctionGeneratorSim(DeviceDescriptor d) : d_(std::move(d)) {}
  ~FunctionGeneratorSim() override { close(); }
  const DeviceDescriptor& descriptor() const override { return d_; }
  core::Result<void> open() override {
    setPointLine().on.store(false);  // the output is off on open, as the real driver's
    state_ = DeviceState::Open;
    return {};
  }
  void close() override {
    if (state_ == DeviceState::Running) stop();
    if (state_ != DeviceState::Closed) setPointLine().on.store(false);
    state_ = DeviceState::Closed;
  }
  Capabilities capabilities() const override {
    Capabilities caps;
    caps.model = "Simulated function generator (33522B-like)";
    caps.outputs = {OutputSpec{"actuator force set-point", "N", -5000.0, 5000.0},
                    OutputSpec{"CH1 voltage", "V", -kGeneratorMaxPeakV, kGeneratorMaxPeakV},
                    OutputSpec{"CH2 voltage", "V", -kGeneratorMaxPeakV, kGeneratorMaxPeakV}};
    caps.triggers = {TriggerKind::Immediate};
    caps.parameters = funcgen::setPointParameters(2);  // usbtmc-funcgen's, for a two-channel generator
    return caps;
  }
  core::Result<AcquisitionConfig> configure(const AcquisitionConfig& requested) override {
    if (state_ == DeviceState::Closed)
      return core::makeError(core::ErrorCode::InvalidArgument, "the device is not open", d_.label());
    if (state_ == DeviceState::Running)
      return core::makeError(core::ErrorCode::InvalidArgument, "stop the output before configuring", d_.label());
    if (!requested.channels.empty())
      return core::makeError(core::ErrorCode::InvalidArgument, "a function generator has no inputs", d_.label());
    auto applied = applyParameters(capabilities().parameters, requested.parameters);
    if (!applied) return applied.error();
    const bool sine = parameterText(*applied, "mode", "static-ramp") == "sine";
    const double k = parameterReal(*applied, "actuator.newtons_per_volt", 500.0);
    const double forceN =
        sine ? parameterReal(*applied, "sine.amplitude", 1000.0) : parameterReal(*applied, "static.max_force", 1000.0);
    const double vpp = 2.0 * forceN / k;
    const char* key = sine ? "sine.amplitude" : "static.max_force";
    // Refused before anything is set, naming the parameter and the limit.
    if (vpp > kGeneratorMaxVpp || vpp / 2.0 > kGeneratorMaxPeakV)
      return core::makeError(core::ErrorCode::InvalidArgument,
                             std::to_string(forceN) + " N at " + std::to_string(k) + " N/V is " + std::to_string(vpp) +
                                 " Vpp: the generator gives at most 20 Vpp (10 V peak) into high impedance",
                             key);
    if (vpp < kGeneratorMinVpp)
      return core::makeError(core::ErrorCode::InvalidArgument,
                             std::to_string(vpp) + " Vpp is below the generator's 2 mVpp", key);
    auto& line = setPointLine();
    {
      std::lock_guard<std::mutex> lock(line.mutex);
      line.programmed = true;
      line.sine = sine;
      line.frequencyHz = parameterReal(*applied, "sine.frequency", 10.0);
      line.amplitudeN = parameterReal(*applied, "sine.amplitude", 1000.0);
      line.maxForceN = parameterReal(*applied, "static.max_force", 1000.0);
      line.periodS = parameterReal(*applied, "static.period_s", 20.0);
      ++line.counters.configured;
      line.counters.lastMode = sine ? "sine" : "static-ramp";
      line.counters.lastFrequencyHz = sine ? line.frequencyHz : 1.0 / line.periodS;
      line.counters.lastAmplitudeN = forceN;
      line.counters.lastAmplitudeVpp = vpp;
    }
    AcquisitionConfig out = requested;
    out.parameters = *applied;
    state_ = DeviceState::Configured;
    return out;
  }
  core::Result<void> start(StreamSink sink) override {
    if (state_ != DeviceState::Configured)
      return core::makeError(core::ErrorCode::InvalidArgument, "configure the generator first", d_.label());
    sink_ = std::move(sink);
    auto& line = setPointLine();
    {
      std::lock_guard<std::mutex> lock(line.mutex);
      ++line.counters.started;
    }
    line.on.store(true);
    state_ = DeviceState::Running;
    sink_(StreamEvent(StreamHeader{}));
    return {};
  }
  void stop() override {
    if (state_ != DeviceState::Running) return;
    setPointLine().on.store(false);
    state_ = DeviceState::Configured;
    sink_(StreamEvent(StreamEnd{EndReason::Stopped, 0, "output off"}));
  }
  DeviceState state() const override { return state_; }

 private:
  DeviceDescriptor d_;
  DeviceState state_ = DeviceState::Closed;
  StreamSink sink_;
};

class FunctionGeneratorSimDriver final : public Driver {
 public:
  std::string name() const override { return "sim-funcgen"; }
  std::string description() const override {
    return "Simulated function generator giving the simulated Motostiffmeter its set-point (thesis §1.1)";
  }
  bool simulated() const override { return true; }
  core::Result<std::vector<DeviceDescriptor>> scan() override {
    return std::vector<DeviceDescriptor>{
        DeviceDescriptor{name(), "Simulated function generator (33522B-like)", 0, 0, "", "sim:0"}};
  }
  core::Result<std::unique_ptr<Device>> create(const DeviceDescriptor& descriptor) override {
    DeviceDescriptor d = descriptor;
    if (d.model.empty()) d.model = "Simulated function generator (33522B-like)";
    return std::unique_ptr<Device>(std::make_unique<FunctionGeneratorSim>(d));
  }
};

}  // namespace

std::unique_ptr<Driver> makeFunctionGeneratorSimDriver() {
  return std::make_unique<FunctionGeneratorSimDriver>();
}

FunctionGeneratorSimCounters functionGeneratorSimCounters() {
  auto& line = setPointLine();
  std::lock_guard<std::mutex> lock(line.mutex);
  return line.counters;
}

}  // namespace mozzi::devices::sim
