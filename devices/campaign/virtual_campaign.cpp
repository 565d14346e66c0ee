#include "devices/campaign/virtual_campaign.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "devices/mcc_usb1608fsplus/usb1608fsplus_protocol.h"
#include "devices/sim/sim_drivers.h"
#include "devices/sim/specimen_catalogue.h"
#include "devices/sim/specimen_models.h"

namespace mozzi::devices::campaign {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kHammerMvPerN = 2.25;           // PCB 086C03 (thesis §1.6)
constexpr double kAccelerometerMvPerMs2 = 10.0;  // PCB M352C65 (thesis §1.4)

// Peak |q''| of q'' + 2 zeta w q' + w^2 q = f(t), f a half-sine of unit peak
// and width T, from rest, over the pulse and two periods after it (the peak
// of an underdamped oscillator's free decay comes in its first period). RK4
// at T/40 or period/80, whichever is finer.
double modalPeakAcceleration(double frequencyHz, double zeta, double T) {
  const double w = 2 * kPi * frequencyHz;
  const double dt = std::min(T / 40.0, 1.0 / (80.0 * frequencyHz));
  const double end = T + 2.0 / frequencyHz;
  auto force = [&](double t) { return t >= 0.0 && t <= T ? std::sin(kPi * t / T) : 0.0; };
  auto acc = [&](double t, double q, double v) { return force(t) - 2 * zeta * w * v - w * w * q; };
  double q = 0, v = 0, peak = 0;
  for (double t = 0; t < end; t += dt) {
    const double a1 = acc(t, q, v);
    const double q2 = q + 0.5 * dt * v, v2 = v + 0.5 * dt * a1;
    const double a2 = acc(t + 0.5 * dt, q2, v2);
    const double q3 = q + 0.5 * dt * v2, v3 = v + 0.5 * dt * a2;
    const double a3 = acc(t + 0.5 * dt, q3, v3);
    const double q4 = q + dt * v3, v4 = v + dt * a3;
    const double a4 = acc(t + dt, q4, v4);
    q += dt / 6 * (v + 2 * v2 + 2 * v3 + v4);
    v += dt / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
    peak = std::max(peak, std::abs(a1));
  }
  return peak;
}

// The smallest range of the station's DAQ (the USB-1608FS-Plus ranges the
// simulated inputs have) holding `volts` twice over.
std::uint8_t rangeFor(double volts) {
  std::uint8_t best = 0;
  for (const auto& r : mcc::ranges())
    if (r.maxVolts >= 2.0 * volts && r.maxVolts < mcc::ranges()[best].maxVolts) best = r.code;
  return best;
}

std::string constraintText(const std::string& key, ConstraintKind& kind) {
  kind = ConstraintKind::OnRig;
  if (key.find("front-constrained") != std::string::npos)
    return "front-constrained: steering head held on the rig (thesis §2.1)";
  if (key.find("rear-constrained") != std::string::npos)
    return "rear-constrained: swing-arm pivot held on the rig (thesis §2.1)";
  if (key.rfind("fork", 0) == 0) return "steering tube clamped on the rig (thesis §4.1, §4.3)";
  if (key.rfind("swing-arm", 0) == 0) return "pivot clamped on the rig (thesis ch. 3)";
  if (key.rfind("tyre", 0) == 0) return "rim held on the hub (thesis §5.2)";
  if (key.rfind("bicycle-", 0) == 0 && key.find("fork") != std::string::npos)
    return "steering tube clamped (thesis §6.2, §6.3)";
  kind = ConstraintKind::FreeFree;
  return "suspended on elastic cords (thesis §6.1)";
}

}  // namespace

double peakAccelerationBound(const core::Matrix& shapes, const std::vector<double>& frequencyHz,
                             const std::vector<double>& zeta, Eigen::Index i, Eigen::Index j, double peakForceN,
                             double pulseWidthS) {
  double a = 0.0;
  for (Eigen::Index r = 0; r < shapes.cols(); ++r)
    a += std::abs(shapes(i, r) * shapes(j, r)) * modalPeakAcceleration(frequencyHz[static_cast<std::size_t>(r)],
                                                                       zeta[static_cast<std::size_t>(r)], pulseWidthS);
  return peakForceN * a;
}

core::Result<CampaignDefinition> virtualSpecimenCampaign(const std::string& key, const VirtualCampaignOptions& o) {
  auto spec = sim::modalSpecimen(key);
  if (!spec)
    return core::makeError(core::ErrorCode::NotFound,
                           "no virtual specimen '" + key + "' (mozzi-cli rig list prints the keys)", "--specimen");
  if (o.accelerometers < 1 || o.accelerometers > 7)
    return core::makeError(core::ErrorCode::InvalidArgument, "1 to 7 accelerometers", "accelerometers");
  CampaignDefinition d;
  d.specimenKey = key;
  d.points = spec->dofs;
  d.constraint.description = constraintText(key, d.constraint.kind);
  d.excitation = ExcitationKind::RovingHammer;
  d.hitsPerPoint = o.hitsPerPoint;
  d.seed = o.seed;
  d.driver = "sim-hammer";
  d.acquisition.sampleRateHz = o.sampleRateHz;
  d.acquisition.recordSeconds = o.recordSeconds;
  d.acquisition.preTriggerFraction = 0.1;
  d.rules.minCoherence = o.minCoherence;

  // Fixed accelerometers: for each mode in turn the DOF where it moves most
  // (not taken yet), so that every mode is seen; the rest spread evenly.
  const Eigen::Index n = spec->shapes.rows();
  const int count = std::min<int>(o.accelerometers, static_cast<int>(n));
  std::vector<Eigen::Index> rows;
  std::set<Eigen::Index> taken;
  for (Eigen::Index r = 0; r < spec->shapes.cols() && static_cast<int>(rows.size()) < count; ++r) {
    Eigen::Index best = -1;
    for (Eigen::Index i = 0; i < n; ++i)
      if (!taken.count(i) && (best < 0 || std::abs(spec->shapes(i, r)) > std::abs(spec->shapes(best, r)))) best = i;
    if (best >= 0) {
      rows.push_back(best);
      taken.insert(best);
    }
  }
  for (Eigen::Index k = 0; static_cast<int>(rows.size()) < count && k < n; ++k) {
    const Eigen::Index i = (k * n) / count % n;
    if (taken.insert(i).second) rows.push_back(i);
  }
  // Without the station's response.dofs parameter, accelerometer input k
  // measures specimen DOF k-1 (the station's fixed wiring): keep that order.
  const bool wired = [] {
    auto drv = sim::makeHammerStationDriver();
    auto dev = drv->create(DeviceDescriptor{"sim-hammer", "", 0, 0, "", "sim:0"});
    if (!dev) return true;
    for (const auto& p : (*dev)->capabilities().parameters)
      if (p.key == "response.dofs") return false;
    return true;
  }();
  if (wired) {
    rows.clear();
    for (Eigen::Index i = 0; i < count; ++i) rows.push_back(i);
  }

  // Ranges as after a test hit: twice the largest peak over every hammer point.
  const double pulse = sim::hammerPulseWidthS(0.16, 1.6e6);  // plastic tip, the station's default
  // Each accelerometer's largest peak over every hammer point for a 1 N hit
  // (the bound is linear in the force).
  std::vector<double> peakPerNewton(rows.size(), 0.0);
  for (std::size_t k = 0; k < rows.size(); ++k)
    for (Eigen::Index j = 0; j < n; ++j)
      peakPerNewton[k] = std::max(
          peakPerNewton[k], peakAccelerationBound(spec->shapes, spec->frequencyHz, spec->zeta, rows[k], j, 1.0, pulse));
  const double largestPerNewton =
      peakPerNewton.empty() ? 0.0 : *std::max_element(peakPerNewton.begin(), peakPerNewton.end());
  // A light specimen (a bicycle fork) would clip the accelerometers even on
  // the DAQ's widest range at the nominal force: the technician hits softer,
  // until twice the largest peak fits that range.
  double widestVolts = 0.0;
  for (const auto& r : mcc::ranges()) widestVolts = std::max(widestVolts, r.maxVolts);
  double peakForce = o.peakForceN;
  const double nominalVolts = largestPerNewton * 1.1 * peakForce * kAccelerometerMvPerMs2 / 1000.0;
  if (2.0 * nominalVolts > widestVolts) peakForce *= widestVolts / (2.0 * nominalVolts);
  const double hitPeak = 1.1 * peakForce;         // the hand varies +/-10%
  d.acquisition.triggerLevel = 0.05 * peakForce;  // far above the 0.05 N force noise
  d.rules.minPeakForceN = 0.25 * peakForce;
  ChannelAssignment hammer;
  hammer.input = 0;
  hammer.name = "hammer";
  hammer.transducer =
      core::signal::Transducer{core::signal::TransducerKind::Force, "PCB 086C03", "SIM-H1", kHammerMvPerN, "N", true};
  hammer.calibrationDate = "2026-01-15";
  hammer.rangeCode = rangeFor(hitPeak * kHammerMvPerN / 1000.0);
  hammer.roving = true;
  d.channels.push_back(hammer);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const double peak = peakPerNewton[k] * hitPeak;
    ChannelAssignment a;
    a.input = static_cast<int>(k) + 1;
    a.dof = spec->dofs[static_cast<std::size_t>(rows[k])];
    a.name = "acc " + core::formatDof(a.dof);
    a.transducer = core::signal::Transducer{core::signal::TransducerKind::Acceleration,
                                            "PCB M352C65",
                                            "SIM-A" + std::to_string(k + 1),
                                            kAccelerometerMvPerMs2,
                                            "m/s^2",
                                            true};
    a.calibrationDate = "2026-01-15";
    a.rangeCode = rangeFor(peak * kAccelerometerMvPerMs2 / 1000.0);
    d.channels.push_back(a);
  }
  d.deviceParameters["specimen"] = key;
  d.deviceParameters["hammer.peak_force"] = peakForce;
  // One hit per session: the quiet time before it, max(0.25 s, 15% of the
  // interval), holds the 10% pre-trigger; 0.4 s after the record is spare.
  d.deviceParameters["hammer.interval_s"] = o.recordSeconds + 0.4;
  d.deviceParameters["fault.double_hit_probability"] = o.doubleHitProbability;
  d.deviceParameters["fault.overload_probability"] = o.overloadProbability;
  if (auto v = d.validate(); !v) return v.error();
  return d;
}

}  // namespace mozzi::devices::campaign
