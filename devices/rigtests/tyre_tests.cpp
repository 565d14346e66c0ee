#include "devices/rigtests/tyre_tests.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "core/io/project_store.h"
#include "core/tire/relaxation_length.h"
#include "core/tire/steady_state.h"
#include "devices/rigtests/session.h"
#include "devices/rigtests/test_store.h"
#include "devices/sim/sim_drivers.h"

namespace mozzi::devices::rigtests {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr const char* kWhere = "tyre tester test";

core::Error refuse(const std::string& what) {
  return core::makeError(core::ErrorCode::InvalidArgument, what, kWhere);
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string signedDeg(double v) {
  std::ostringstream s;
  s << (v > 0 ? "+" : "") << v << " deg";
  return s.str();
}

core::Result<void> checkSpeed(double kmh) {
  if (!std::isfinite(kmh) || kmh <= 0) return refuse("disk speed " + number(kmh) + " km/h: must be > 0");
  if (kmh > kMachineMaxSpeedKmh)
    return refuse("disk speed " + number(kmh) + " km/h exceeds the machine's limit of " + number(kMachineMaxSpeedKmh) +
                  " km/h (thesis §1.8)");
  return {};
}

// A side-slip (yaw) set-point against the machine's and the working limit.
core::Result<void> checkSlip(const TyreRigSetup& setup, const std::string& what, double deg) {
  if (!std::isfinite(deg)) return refuse(what + " is not a number");
  if (std::abs(deg) > kMachineMaxSlipDeg + 1e-9)
    return refuse(what + " " + number(deg) + " deg exceeds the machine's side-slip limit of +/-" +
                  number(kMachineMaxSlipDeg) + " deg (thesis §1.8, appendix 2)");
  if (std::abs(deg) > setup.slipLimitDeg + 1e-9)
    return refuse(what + " " + number(deg) + " deg exceeds the working side-slip limit of +/-" +
                  number(setup.slipLimitDeg) + " deg (thesis §1.8: against oscillations of the arm); raise it up to " +
                  "the machine's +/-" + number(kMachineMaxSlipDeg) + " deg if the tyre and load allow");
  return {};
}

core::Result<void> checkCamber(const TyreRigSetup& setup, const std::string& what, double deg) {
  if (!std::isfinite(deg)) return refuse(what + " is not a number");
  if (std::abs(deg) > kMachineMaxCamberDeg + 1e-9)
    return refuse(what + " " + number(deg) + " deg exceeds the machine's camber limit of +/-" +
                  number(kMachineMaxCamberDeg) + " deg (thesis appendix 2)");
  if (std::abs(deg) > setup.camberLimitDeg + 1e-9)
    return refuse(what + " " + number(deg) + " deg exceeds the working camber limit of +/-" +
                  number(setup.camberLimitDeg) + " deg (thesis §1.8: against oscillations of the arm); raise it up " +
                  "to the machine's +/-" + number(kMachineMaxCamberDeg) + " deg if the tyre and load allow");
  return {};
}

core::Result<void> checkSetup(const TyreRigSetup& setup) {
  if (!(setup.sampleRateHz > 0)) return refuse("sample rate " + number(setup.sampleRateHz) + " Hz: must be > 0");
  if (!(setup.slipLimitDeg >= 0) || setup.slipLimitDeg > kMachineMaxSlipDeg)
    return refuse("working side-slip limit " + number(setup.slipLimitDeg) + " deg: between 0 and the machine's " +
                  number(kMachineMaxSlipDeg) + " deg");
  if (!(setup.camberLimitDeg >= 0) || setup.camberLimitDeg > kMachineMaxCamberDeg)
    return refuse("working camber limit " + number(setup.camberLimitDeg) + " deg: between 0 and the machine's " +
                  number(kMachineMaxCamberDeg) + " deg");
  if (!(setup.verticalLoadN > 0)) return refuse("vertical load " + number(setup.verticalLoadN) + " N: must be > 0");
  return {};
}

std::vector<ChannelConfig> channelsOf(const TyreRigSetup& s) {
  return {s.yawRate, s.lateralForce, s.aligningMoment, s.spinMoment, s.yawAngle, s.camberAngle};
}

// Record columns in set-up order (the stream orders channels by input).
core::Result<std::vector<int>> columnsOf(const StreamHeader& header, const TyreRigSetup& setup) {
  std::vector<int> c;
  for (const auto& ch : channelsOf(setup)) {
    const int k = detail::channelIndex(header, ch.name);
    if (k < 0) return refuse("the stream has no channel '" + ch.name + "'");
    c.push_back(k);
  }
  return c;
}

ParameterMap withLimits(const TyreRigSetup& setup) {
  ParameterMap p = setup.daqParameters;
  p["servo.yaw_limit_deg"] = setup.slipLimitDeg;
  p["servo.camber_limit_deg"] = setup.camberLimitDeg;
  return p;
}

struct Stored {
  std::optional<std::int64_t> setupId, testId;
  std::string name;
  std::vector<std::string> labels;  // of the planned steps
};

core::Result<Stored> storeStart(const StoreTarget& target, const TyreRigSetup& setup, const Device& daq,
                                const std::string& kind, double speedMps, const nlohmann::json& plan) {
  Stored s;
  for (const auto& st : plan.at("steps")) s.labels.push_back(st.at("label").get<std::string>());
  s.name = target.testName;
  if (!target.store) return s;
  auto& store = *target.store;
  auto name = detail::uniqueTestName(store, target.specimenId, true, target.testName, kind);
  if (!name) return name.error();
  s.name = *name;
  core::io::StoredRigSetup rs;
  rs.specimenId = target.specimenId;
  rs.name = setup.rigName + " set-up of " + *name;
  rs.rigKind = "tyre-disk";
  rs.driver = daq.descriptor().driver;
  nlohmann::json axes;
  axes["record_columns"] = nlohmann::json::array();
  for (const auto& c : channelsOf(setup)) axes["record_columns"].push_back(c.name);
  axes["limits_deg"] = {{"machine_slip", kMachineMaxSlipDeg},
                        {"machine_camber", kMachineMaxCamberDeg},
                        {"working_slip", setup.slipLimitDeg},
                        {"working_camber", setup.camberLimitDeg}};
  rs.axisMapJson = axes.dump();
  nlohmann::json params;
  params["daq"] = detail::parametersJson(withLimits(setup));
  params["sample_rate_hz"] = setup.sampleRateHz;
  rs.parametersJson = params.dump();
  rs.transducers = detail::transducersOf(channelsOf(setup));
  auto setupId = store.addRigSetup(rs);
  if (!setupId) return setupId.error();
  s.setupId = *setupId;
  core::io::StoredTyreTest t;
  t.specimenId = target.specimenId;
  t.rigSetupId = *setupId;
  t.name = *name;
  t.kind = kind;
  t.inflationPressurePa = setup.pressurePa;
  t.verticalLoadN = setup.verticalLoadN;
  t.speedMps = speedMps;
  t.status = TestStatus::Running;
  t.statusNote = cutShortNote(0, s.labels);
  t.parametersJson = plan.dump();
  auto id = store.addTyreTest(t);
  if (!id) return id.error();
  s.testId = *id;
  return s;
}

void storeStep(const StoreTarget& target, const Stored& stored, int step, double fs, const Eigen::MatrixXf& record,
               const std::vector<core::io::StoredTyreTest::Point>& points, const std::vector<Quantity>& results,
               std::string& storeErrors) {
  if (!target.store || !stored.testId) return;
  auto r =
      target.store->commitTyreTestStep(*stored.testId, step, fs, record, points, detail::tyreParameters(results, step),
                                       cutShortNote(step + 1, stored.labels));
  detail::collectStoreError(r, storeErrors);
}

void storeEnd(const StoreTarget& target, const Stored& stored, Outcome& out, std::string& storeErrors) {
  detail::reportStoreErrors(storeErrors, out);
  if (!target.store || !stored.testId) return;
  auto r = target.store->finishTyreTest(*stored.testId, out.status, out.note, detail::tyreParameters(out.results, {}));
  detail::reportFinalWrite(r, out);
}

Quantity q(const std::string& key, const std::string& label, double v, const char* unit, double u = 0.0) {
  return Quantity{key, label, v, unit, std::isfinite(u) ? std::abs(u) : 0.0};
}

void progress(const Callbacks& cb, int step, int steps, double fraction, const std::string& message) {
  if (cb.progress) cb.progress(Progress{step, steps, std::clamp(fraction, 0.0, 1.0), message});
}

void log(const Callbacks& cb, const std::string& line) {
  if (cb.log) cb.log(line);
}

std::string hz(double f) {
  std::ostringstream s;
  s << f << " Hz";
  return s.str();
}

}  // namespace

core::Result<void> checkRelaxationSettings(const TyreRigSetup& setup, const RelaxationSettings& s) {
  if (auto r = checkSetup(setup); !r) return r;
  if (auto r = checkSpeed(s.speedKmh); !r) return r;
  if (!(s.yawAmplitudeDeg > 0)) return refuse("yaw amplitude " + number(s.yawAmplitudeDeg) + " deg: must be > 0");
  if (auto r = checkSlip(setup, "yaw amplitude", s.yawAmplitudeDeg); !r) return r;
  if (s.frequenciesHz.empty()) return refuse("no yaw frequency given");
  for (double f : s.frequenciesHz)
    if (!std::isfinite(f) || f <= 0 || f > 20.0 || f > setup.sampleRateHz / 20)
      return refuse("yaw frequency " + number(f) + " Hz: between 0 and 20 Hz and below a twentieth of the " +
                    number(setup.sampleRateHz) + " Hz sample rate");
  if (s.cycles < 3 || s.cycles > 1000) return refuse("cycles per frequency " + number(s.cycles) + ": 3 to 1000");
  if (s.settleCycles < 0 || s.cycles - s.settleCycles < 2)
    return refuse("settling cycles " + number(s.settleCycles) + ": leave at least 2 of the " + number(s.cycles) +
                  " cycles for the fit");
  if (!(setup.halfLengthM >= 0)) return refuse("contact half-length " + number(setup.halfLengthM) + " m: >= 0");
  return {};
}

core::Result<void> checkSteadyStateSettings(const TyreRigSetup& setup, const SteadyStateSettings& s) {
  if (auto r = checkSetup(setup); !r) return r;
  if (auto r = checkSpeed(s.speedKmh); !r) return r;
  if (s.slipDeg.empty() && s.camberDeg.empty()) return refuse("no side-slip nor camber set-point given");
  for (double a : s.slipDeg)
    if (auto r = checkSlip(setup, "side-slip set-point", a); !r) return r;
  for (double g : s.camberDeg)
    if (auto r = checkCamber(setup, "camber set-point", g); !r) return r;
  if (!(s.settleS >= 0) || !(s.holdS > 0) || s.holdS * setup.sampleRateHz < 10)
    return refuse("settling must be >= 0 s and the hold at least 10 samples");
  return {};
}

core::Result<RelaxationOutcome> runRelaxationTest(Device& daq, const TyreRigSetup& setup,
                                                  const RelaxationSettings& settings, const StoreTarget& target,
                                                  const Callbacks& callbacks, const CancelFlag* cancel) {
  if (auto r = checkRelaxationSettings(setup, settings); !r) return r.error();
  const double fs = setup.sampleRateHz;
  const double speed = settings.speedKmh / 3.6;
  std::vector<std::string> labels;
  std::ostringstream list;
  double totalS = 0.0;
  nlohmann::json plan;
  plan["test"] = "relaxation";
  plan["speed_m_s"] = speed;
  plan["yaw_amplitude_rad"] = settings.yawAmplitudeDeg * kDeg;
  plan["cycles"] = settings.cycles;
  plan["settle_cycles"] = settings.settleCycles;
  plan["half_length_m"] = setup.halfLengthM;
  plan["steps"] = nlohmann::json::array();
  std::vector<std::int64_t> stepStart;  // planned first scan of each step
  for (std::size_t k = 0; k < settings.frequenciesHz.size(); ++k) {
    const double f = settings.frequenciesHz[k];
    list << (k ? "," : "") << f;
    labels.push_back(hz(f));
    stepStart.push_back(static_cast<std::int64_t>(std::llround(totalS * fs)));
    totalS += settings.cycles / f;
    plan["steps"].push_back({{"label", hz(f)}, {"frequency_hz", f}});
  }
  detail::SessionPlan sp;
  sp.step = 0;
  sp.stepLabel = labels.front();
  sp.daqConfig.sampleRateHz = fs;
  sp.daqConfig.channels = channelsOf(setup);
  sp.daqConfig.scanCount = detail::scansFor(totalS, fs);
  sp.daqConfig.parameters = withLimits(setup);
  sp.daqConfig.parameters["mode"] = std::string("harmonic-yaw");
  sp.daqConfig.parameters["disk.speed_kmh"] = settings.speedKmh;
  sp.daqConfig.parameters["yaw.amplitude_deg"] = settings.yawAmplitudeDeg;
  sp.daqConfig.parameters["yaw.frequencies_hz"] = list.str();
  sp.daqConfig.parameters["yaw.cycles"] = static_cast<std::int64_t>(settings.cycles);

  auto stored = storeStart(target, setup, daq, "relaxation", speed, plan);
  if (!stored) return stored.error();
  RelaxationOutcome out;
  out.testId = stored->testId;
  out.rigSetupId = stored->setupId;
  out.testName = stored->name;
  std::string storeErrors;

  core::tire::HarmonicYawSettings hy;
  hy.speed = speed;
  hy.halfLength = setup.halfLengthM;
  hy.bandLowHz = settings.bandLowHz;
  hy.bandHighHz = settings.bandHighHz;
  std::vector<core::tire::HarmonicYawRecord> fitted;  // the committed steps' fit windows
  int nextStep = 0;
  std::vector<int> cols;
  const int steps = static_cast<int>(labels.size());

  // Commits step k = [start of k, end) and reports it.
  auto finishStep = [&](const detail::SessionData& d, Eigen::Index end) {
    const int k = nextStep++;
    const double f = settings.frequenciesHz[static_cast<std::size_t>(k)];
    const Eigen::Index start = static_cast<Eigen::Index>(stepStart[static_cast<std::size_t>(k)]);
    StepReport report{k, labels[static_cast<std::size_t>(k)], false, "", {}};
    report.results.push_back(q("frequency", "yaw frequency", f, "Hz"));
    const Eigen::Index skip = static_cast<Eigen::Index>(std::llround(settings.settleCycles * fs / f));
    if (cols.size() == 6 && end - start - skip > 8) {
      core::tire::HarmonicYawRecord rec;
      rec.excitationFrequencyHz = f;
      rec.sampleRateHz = fs;
      rec.yawRate = d.values.col(cols[0]).segment(start + skip, end - start - skip);
      rec.lateralForce = d.values.col(cols[1]).segment(start + skip, end - start - skip);
      core::tire::HarmonicYawSettings one = hy;
      one.bandLowHz = 0.0;
      one.bandHighHz = 1e9;
      auto r = core::tire::relaxationFromHarmonicYaw({rec}, one);
      if (r && !r->points.empty()) {
        const auto& p = r->points.front();
        report.results.push_back(
            q("phase_lag", "lag of F_y behind the yaw angle", p.phaseLagRad, "rad", p.phaseLagStdError));
        report.results.push_back(q("yaw_amplitude", "yaw amplitude", p.yawAmplitude, "rad"));
        report.results.push_back(q("force_amplitude", "lateral force amplitude", p.forceAmplitude, "N"));
        report.results.push_back(q("relaxation_length_m", "relaxation length", p.sigma, "m", p.sigmaStdError));
        report.ok = true;
        fitted.push_back(rec);
      } else {
        report.note = r ? "no point" : r.error().message;
      }
    } else {
      report.note = "too short a record to fit";
    }
    storeStep(target, *stored, k, fs,
              detail::recordOf(d.values.middleRows(start, end - start), end - start,
                               cols.size() == 6 ? cols : std::vector<int>{}),
              {}, report.results, storeErrors);
    out.steps.push_back(report);
    if (callbacks.step) callbacks.step(report);
  };
  detail::SessionHooks hooks;
  hooks.block = [&](const detail::SessionData& d, Eigen::Index, Eigen::Index) {
    if (cols.empty()) {
      if (auto c = columnsOf(d.header, setup)) cols = *c;
    }
    // A step is complete once the data reach the start of the next one.
    while (nextStep + 1 < steps && d.rows >= stepStart[static_cast<std::size_t>(nextStep + 1)])
      finishStep(d, static_cast<Eigen::Index>(stepStart[static_cast<std::size_t>(nextStep + 1)]));
    const double t = static_cast<double>(d.rows) / fs;
    progress(callbacks, nextStep, steps, t / totalS, labels[static_cast<std::size_t>(nextStep)]);
  };
  log(callbacks, "relaxation test: yaw +/-" + number(settings.yawAmplitudeDeg) + " deg at " + list.str() + " Hz, " +
                     number(settings.cycles) + " cycles each, " + number(settings.speedKmh) + " km/h");
  progress(callbacks, 0, steps, 0.0, labels.front());
  auto session = detail::runSession(daq, nullptr, sp, callbacks, cancel, hooks);
  if (!session) {
    out.status = TestStatus::Failed;
    out.note = "the tester refused the test: " + session.error().describe();
    storeEnd(target, *stored, out, storeErrors);
    return session.error();
  }
  if (cols.empty()) {
    if (auto c = columnsOf(session->header, setup)) cols = *c;
  }
  const bool complete =
      session->end.reason == EndReason::Completed && !session->cancelled && session->scans() >= sp.daqConfig.scanCount;
  if (complete) {
    finishStep(*session, session->scans());
  } else {
    const std::string cause = session->cancelled ? "cancelled" : detail::endCause(session->end);
    const int failed = nextStep;
    // The partial step's record is kept, without a result.
    const Eigen::Index start = static_cast<Eigen::Index>(stepStart[static_cast<std::size_t>(failed)]);
    if (session->scans() > start && cols.size() == 6)
      storeStep(
          target, *stored, failed, fs,
          detail::recordOf(session->values.middleRows(start, session->scans() - start), session->scans() - start, cols),
          {}, {q("frequency", "yaw frequency", settings.frequenciesHz[static_cast<std::size_t>(failed)], "Hz")},
          storeErrors);
    out.status = TestStatus::Interrupted;
    out.note = missingStepsNote(cause, failed, labels);
  }
  if (!session->overruns.empty() && out.status == TestStatus::Complete) {
    out.status = TestStatus::Failed;
    out.note = "the acquisition lost data (overrun): repeat the test";
  }
  if (!fitted.empty()) {
    auto mean = core::tire::relaxationFromHarmonicYaw(fitted, hy);
    if (mean) {
      out.results.push_back(
          q("relaxation_length_m",
            "relaxation length, mean over " + number(hy.bandLowHz) + " to " + number(hy.bandHighHz) + " Hz (§5.4)",
            mean->meanSigma, "m", mean->meanSigmaStdError));
      out.results.push_back(
          q("relaxation_length_scatter_m", "scatter of the relaxation length in the band", mean->bandScatter, "m"));
      out.results.push_back(q("points_in_band", "frequencies in the band", mean->pointsInBand, ""));
    } else if (out.status == TestStatus::Complete) {
      out.note = mean.error().message;
    }
  }
  out.results.push_back(q("speed", "disk speed", speed, "m/s"));
  out.results.push_back(q("half_length", "contact half-length a (Table 17)", setup.halfLengthM, "m"));
  progress(callbacks, steps, steps, 1.0, "done");
  storeEnd(target, *stored, out, storeErrors);
  log(callbacks, std::string("relaxation test ") + core::io::testStatusName(out.status) +
                     (out.note.empty() ? "" : ": " + out.note));
  return out;
}

core::Result<SteadyStateOutcome> runSteadyStateTest(Device& daq, const TyreRigSetup& setup,
                                                    const SteadyStateSettings& settings, const StoreTarget& target,
                                                    const Callbacks& callbacks, const CancelFlag* cancel) {
  if (auto r = checkSteadyStateSettings(setup, settings); !r) return r.error();
  const double fs = setup.sampleRateHz;
  const double speed = settings.speedKmh / 3.6;
  struct SetPoint {
    double slipDeg, camberDeg;
    bool slipSweep;
  };
  std::vector<SetPoint> points;
  std::vector<std::string> labels;
  nlohmann::json plan;
  plan["test"] = "steady-state";
  plan["speed_m_s"] = speed;
  plan["settle_s"] = settings.settleS;
  plan["hold_s"] = settings.holdS;
  plan["steps"] = nlohmann::json::array();
  for (double a : settings.slipDeg) {
    points.push_back({a, 0.0, true});
    labels.push_back("slip " + signedDeg(a));
  }
  for (double g : settings.camberDeg) {
    points.push_back({0.0, g, false});
    labels.push_back("camber " + signedDeg(g));
  }
  for (std::size_t k = 0; k < points.size(); ++k)
    plan["steps"].push_back(
        {{"label", labels[k]}, {"slip_rad", points[k].slipDeg * kDeg}, {"camber_rad", points[k].camberDeg * kDeg}});
  auto stored = storeStart(target, setup, daq, "steady-state", speed, plan);
  if (!stored) return stored.error();
  SteadyStateOutcome out;
  out.testId = stored->testId;
  out.rigSetupId = stored->setupId;
  out.testName = stored->name;
  std::string storeErrors;
  const int steps = static_cast<int>(points.size());
  const std::int64_t settleScans = detail::scansFor(settings.settleS, fs);
  const std::int64_t holdScans = detail::scansFor(settings.holdS, fs);
  log(callbacks, "steady-state test: " + number(settings.slipDeg.size()) + " side-slip and " +
                     number(settings.camberDeg.size()) + " camber set-points at " + number(settings.speedKmh) +
                     " km/h");
  for (int k = 0; k < steps; ++k) {
    const auto& p = points[static_cast<std::size_t>(k)];
    if (cancel && cancel->cancelled()) {
      out.status = TestStatus::Interrupted;
      out.note = missingStepsNote("cancelled", k, labels);
      break;
    }
    detail::SessionPlan sp;
    sp.step = k;
    sp.stepLabel = labels[static_cast<std::size_t>(k)];
    sp.daqConfig.sampleRateHz = fs;
    sp.daqConfig.channels = channelsOf(setup);
    sp.daqConfig.scanCount = settleScans + holdScans;
    sp.daqConfig.parameters = withLimits(setup);
    sp.daqConfig.parameters["mode"] = std::string("steady-state");
    sp.daqConfig.parameters["disk.speed_kmh"] = settings.speedKmh;
    sp.daqConfig.parameters["sweep.slip_deg"] = p.slipDeg;
    sp.daqConfig.parameters["sweep.camber_deg"] = p.camberDeg;
    detail::SessionHooks hooks;
    hooks.block = [&](const detail::SessionData& d, Eigen::Index, Eigen::Index) {
      const double within = static_cast<double>(d.rows) / static_cast<double>(sp.daqConfig.scanCount);
      progress(callbacks, k, steps, (k + within) / steps,
               sp.stepLabel + (d.rows < settleScans ? ": settling" : ": holding"));
    };
    auto session = detail::runSession(daq, nullptr, sp, callbacks, cancel, hooks);
    if (!session) {
      out.status = k == 0 ? TestStatus::Failed : TestStatus::Interrupted;
      out.note = missingStepsNote("the tester refused the step (" + session.error().describe() + ")", k, labels);
      if (k == 0) {
        storeEnd(target, *stored, out, storeErrors);
        return session.error();
      }
      break;
    }
    auto cols = columnsOf(session->header, setup);
    const Eigen::Index rows = session->scans();
    const bool complete =
        session->end.reason == EndReason::Completed && !session->cancelled && rows >= sp.daqConfig.scanCount && cols;
    StepReport report{k, sp.stepLabel, false, "", {}};
    std::vector<core::io::StoredTyreTest::Point> stepPoints;
    if (complete && session->overloads.empty() && session->overruns.empty()) {
      auto mean = [&](int col, double* se) {
        const core::Vector x = session->values.col(col).segment(settleScans, holdScans);
        const double m = x.mean();
        const double sd = holdScans > 1 ? std::sqrt((x.array() - m).square().sum() / (holdScans - 1)) : 0.0;
        if (se) *se = sd / std::sqrt(static_cast<double>(holdScans));  // white noise: s / sqrt(n)
        return m;
      };
      SteadyStatePoint pt;
      pt.slipSweep = p.slipSweep;
      pt.slipRad = p.slipDeg * kDeg;
      pt.camberRad = p.camberDeg * kDeg;
      pt.force = mean((*cols)[1], &pt.forceSe);
      pt.torque = mean((*cols)[2], &pt.torqueSe);
      pt.spinMoment = mean((*cols)[3], nullptr);
      double slipSe = 0, camberSe = 0;
      const double slipMeasured = mean((*cols)[4], &slipSe), camberMeasured = mean((*cols)[5], &camberSe);
      out.points.push_back(pt);
      report.ok = true;
      auto& r = report.results;
      r.push_back(q("slip", "side-slip set-point", pt.slipRad, "rad"));
      r.push_back(q("camber", "camber set-point", pt.camberRad, "rad"));
      r.push_back(q("slip_measured", "side-slip angle measured (yaw servo)", slipMeasured, "rad", slipSe));
      r.push_back(q("camber_measured", "camber angle measured (camber servo)", camberMeasured, "rad", camberSe));
      r.push_back(q("lateral_force", "lateral force F_y", pt.force, "N", pt.forceSe));
      r.push_back(q("aligning_moment", "yaw torque M_z", pt.torque, "N m", pt.torqueSe));
      r.push_back(q("spin_moment", "moment about the spin axis M_y", pt.spinMoment, "N m"));
      // Mx is not measured by the tester: the point's overturning moment stays 0.
      stepPoints.push_back({pt.slipRad, pt.camberRad, pt.force, pt.torque, 0.0});
    } else if (complete) {
      report.note = !session->overloads.empty() ? "a load cell reached the end of its range; the record is stored"
                                                : "the acquisition lost data (overrun); the record is stored";
    }
    if (cols && rows > 0)
      storeStep(target, *stored, k, fs, detail::recordOf(session->values, rows, *cols), stepPoints, report.results,
                storeErrors);
    if (!complete) {
      const std::string cause = session->cancelled ? "cancelled" : detail::endCause(session->end);
      out.status = TestStatus::Interrupted;
      out.note = missingStepsNote(cause, k, labels);
      report.note = cause + "; the partial record is stored";
      out.steps.push_back(report);
      if (callbacks.step) callbacks.step(report);
      break;
    }
    out.steps.push_back(report);
    if (callbacks.step) callbacks.step(report);
  }

  // Characteristics from what was measured (also for an interrupted test:
  // each sweep is characterised when it has enough points).
  std::string notes;
  auto addNote = [&](const std::string& n) { notes += (notes.empty() ? "" : "; ") + n; };
  auto sweep = [&](bool slip) {
    std::vector<SteadyStatePoint> s;
    for (const auto& p : out.points)
      if (p.slipSweep == slip) s.push_back(p);
    std::sort(s.begin(), s.end(), [slip](const SteadyStatePoint& a, const SteadyStatePoint& b) {
      return slip ? a.slipRad < b.slipRad : a.camberRad < b.camberRad;
    });
    core::tire::SteadyStateSweep sw;
    const auto n = static_cast<Eigen::Index>(s.size());
    sw.angle.resize(n);
    sw.force.resize(n);
    sw.torque.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const auto& p = s[static_cast<std::size_t>(i)];
      sw.angle(i) = slip ? p.slipRad : p.camberRad;
      sw.force(i) = p.force;
      sw.torque(i) = p.torque;
    }
    sw.verticalLoad = setup.verticalLoadN;
    sw.pressure = setup.pressurePa;
    sw.speed = speed;
    return sw;
  };
  if (!settings.slipDeg.empty()) {
    auto ch = core::tire::characteriseSweep(sweep(true), settings.slipWindowDeg * kDeg, 3);
    if (ch) {
      out.results.push_back(q("cornering_stiffness", "cornering stiffness dF_y/dalpha", ch->forceSlope.slope, "N/rad",
                              ch->forceSlope.slopeStdError));
      out.results.push_back(q("aligning_stiffness", "self-aligning torque stiffness dM_z/dalpha", ch->torqueSlope.slope,
                              "N m/rad", ch->torqueSlope.slopeStdError));
      out.results.push_back(q("normalised_cornering_stiffness", "cornering stiffness / F_z", ch->normalisedForceSlope,
                              "1/rad", ch->forceSlope.slopeStdError / setup.verticalLoadN));
    } else {
      addNote("side-slip characteristics: " + ch.error().message);
    }
  }
  if (!settings.camberDeg.empty()) {
    auto ch = core::tire::characteriseSweep(sweep(false), settings.camberWindowDeg * kDeg, 1);
    if (ch) {
      out.results.push_back(q("camber_stiffness", "camber stiffness dF_y/dgamma", ch->forceSlope.slope, "N/rad",
                              ch->forceSlope.slopeStdError));
      out.results.push_back(q("twisting_torque_stiffness", "twisting torque stiffness dM_z/dgamma",
                              ch->torqueSlope.slope, "N m/rad", ch->torqueSlope.slopeStdError));
    } else {
      addNote("camber characteristics: " + ch.error().message);
    }
  }
  if (settings.fitMagicFormula && out.points.size() >= 8) {
    std::vector<core::tire::SteadyStatePoint> data;
    for (const auto& p : out.points)
      data.push_back({p.slipRad, p.camberRad, setup.verticalLoadN, setup.pressurePa, p.force, p.torque});
    const core::tire::MfConstants c{setup.verticalLoadN, setup.pressurePa, setup.unloadedRadiusM};
    core::tire::MfFitOptions opt;
    // Sweeps along the two axes do not separate the combined slip-camber
    // terms: hold them (camber enters through the vertical shift pVy3).
    opt.fixed = {"pDy3", "pKy3", "pEy4", "pHy3"};
    auto lat = core::tire::fitMfLateral(data, c, opt);
    if (lat) {
      out.lateral = *lat;
      const auto& names = core::tire::mfLateralNames();
      for (std::size_t i = 0; i < names.size(); ++i)
        if (lat->free[i])
          out.results.push_back(q("mf_" + names[i], "Magic Formula " + names[i], lat->value[i], "", lat->stdError[i]));
      out.results.push_back(q("mf_lateral_rms", "Magic Formula F_y rms residual", lat->rmsResidual, "N"));
      core::tire::MfFitOptions aopt;
      aopt.fixed = {"qBz4", "qBz5", "qDz3", "qDz4", "qEz5", "qHz3", "qHz4", "qDz9"};
      core::tire::MfLateralCoefficients lv;
      std::copy(lat->value.begin(), lat->value.end(), lv.begin());
      auto al = core::tire::fitMfAligning(data, c, lv, aopt);
      if (!al) {
        // The residual torque's shape (qBz9, qBz10) and the curvature's
        // asymmetry (qEz4) are not seen when the residual torque is nil: hold
        // them and fit again, saying so.
        aopt.fixed.insert({"qBz9", "qBz10", "qEz4"});
        al = core::tire::fitMfAligning(data, c, lv, aopt);
        if (al) addNote("Magic Formula M_z: qBz9, qBz10, qEz4 held (the data do not separate them)");
      }
      if (al) {
        out.aligning = *al;
        const auto& an = core::tire::mfAligningNames();
        for (std::size_t i = 0; i < an.size(); ++i)
          if (al->free[i])
            out.results.push_back(q("mf_" + an[i], "Magic Formula " + an[i], al->value[i], "", al->stdError[i]));
        out.results.push_back(q("mf_aligning_rms", "Magic Formula M_z rms residual", al->rmsResidual, "N m"));
      } else {
        addNote("Magic Formula M_z: " + al.error().message);
      }
    } else {
      addNote("Magic Formula F_y: " + lat.error().message);
    }
  }
  if (!notes.empty()) out.note += (out.note.empty() ? "" : "; ") + notes;
  out.results.push_back(q("speed", "disk speed", speed, "m/s"));
  out.results.push_back(q("vertical_load", "vertical load F_z", setup.verticalLoadN, "N"));
  progress(callbacks, steps, steps, 1.0, "done");
  storeEnd(target, *stored, out, storeErrors);
  log(callbacks, std::string("steady-state test ") + core::io::testStatusName(out.status) +
                     (out.note.empty() ? "" : ": " + out.note));
  return out;
}

core::Result<TyreRigSetup> simulatedTyreSetup(const std::string& tyreKey, double pressureBar, std::uint64_t seed,
                                              bool realtime) {
  ParameterMap p;
  p["tyre"] = tyreKey;
  p["tyre.pressure_bar"] = pressureBar;
  p["sim.seed"] = static_cast<std::int64_t>(seed);
  p["sim.realtime"] = realtime;
  auto sim = sim::tyreTesterSetup(p);
  if (!sim) return sim.error();
  TyreRigSetup s;
  s.rigName = "Simulated Mototiremeter";
  auto channel = [](int input, const char* name, core::signal::TransducerKind kind, double mvPerUnit, const char* unit,
                    const char* model) {
    ChannelConfig c;
    c.input = input;
    c.name = name;
    c.rangeCode = 0;  // +/-10 V
    c.transducer = core::signal::Transducer{kind, model, "", mvPerUnit, unit, false};
    return c;
  };
  using K = core::signal::TransducerKind;
  // Scales chosen so the thesis's ranges fit +/-10 V: 10 rad/s, 5000 N, 100 N m, 1 rad.
  s.yawRate = channel(0, "yaw rate", K::AngularRate, 1000.0, "rad/s", "rate gyro");
  s.lateralForce = channel(1, "Fy", K::Force, 2.0, "N", "arm load cell F_y");
  s.aligningMoment = channel(2, "Mz", K::Other, 100.0, "N m", "load cell M_z");
  s.spinMoment = channel(3, "My", K::Other, 100.0, "N m", "load cell M_y");
  s.yawAngle = channel(4, "yaw angle", K::Other, 10000.0, "rad", "yaw servo encoder");
  s.camberAngle = channel(5, "camber angle", K::Other, 10000.0, "rad", "camber servo encoder");
  s.daqParameters = p;
  s.verticalLoadN = sim->load;
  s.pressurePa = sim->pressurePa;
  s.halfLengthM = sim->halfLength;
  s.unloadedRadiusM = sim->outerRadius;
  return s;
}

}  // namespace mozzi::devices::rigtests
