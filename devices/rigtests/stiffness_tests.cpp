#include "devices/rigtests/stiffness_tests.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

#include "core/io/project_store.h"
#include "core/signal/sine_fit.h"
#include "devices/rigtests/session.h"
#include "devices/rigtests/test_store.h"
#include "devices/sim/specimen_models.h"

namespace mozzi::devices::rigtests {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr const char* kWhere = "stiffness rig test";

core::Error refuse(const std::string& what) {
  return core::makeError(core::ErrorCode::InvalidArgument, what, kWhere);
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

constexpr double kMinSpacingM = 0.005;  // lasers closer than this, or this near one line, are refused

std::string mm(double m) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f", m * 1e3);
  return buf;
}

core::Error geometryError(const std::string& what, const std::string& key) {
  return core::makeError(core::ErrorCode::InvalidArgument, what, key);
}

core::Result<void> checkSetup(const StiffnessRigSetup& setup) {
  if (setup.lasers.size() < 3) return refuse("the set-up has " + number(setup.lasers.size()) + " lasers; at least 3");
  if (setup.laserPoints.size() != setup.lasers.size())
    return refuse("the set-up has " + number(setup.lasers.size()) + " lasers but " + number(setup.laserPoints.size()) +
                  " plate points");
  if (!(setup.sampleRateHz > 0)) return refuse("sample rate " + number(setup.sampleRateHz) + " Hz: must be > 0");
  if (setup.bendAxis.has_value() != setup.torsAxis.has_value())
    return refuse("give both the bending and the torsion axis, or neither");
  return checkPlateGeometry(setup);
}

std::string hz(double f) {
  std::ostringstream s;
  s << f << " Hz";
  return s.str();
}

// Where the actuator's set-point goes: a function generator, or the DAQ
// device when it drives the actuator itself (it declares "mode").
enum class ActuatorPath { FunctionGenerator, Daq };

bool declares(const Device& dev, const std::string& key) {
  for (const auto& p : dev.capabilities().parameters)
    if (p.key == key) return true;
  return false;
}

core::Result<ActuatorPath> actuatorPath(const Device& daq, const Device* actuator) {
  if (actuator) {
    if (!declares(*actuator, "mode") || !declares(*actuator, "sine.frequency"))
      return refuse("the actuator device " + actuator->descriptor().label() +
                    " declares no set-point parameters (mode, sine.frequency): is it a function generator?");
    return ActuatorPath::FunctionGenerator;
  }
  if (!declares(daq, "mode"))
    return refuse("no actuator: the DAQ device " + daq.descriptor().label() +
                  " does not drive one and no function generator was given");
  return ActuatorPath::Daq;
}

// Records are stored load cell first, then the lasers in set-up order.
struct Columns {
  int force = -1;
  std::vector<int> lasers;
  std::vector<int> all() const {
    std::vector<int> c{force};
    c.insert(c.end(), lasers.begin(), lasers.end());
    return c;
  }
};

core::Result<Columns> columnsOf(const StreamHeader& header, const StiffnessRigSetup& setup) {
  Columns c;
  c.force = detail::channelIndex(header, setup.loadCell.name);
  if (c.force < 0) return refuse("the stream has no channel '" + setup.loadCell.name + "'");
  for (const auto& l : setup.lasers) {
    const int k = detail::channelIndex(header, l.name);
    if (k < 0) return refuse("the stream has no channel '" + l.name + "'");
    c.lasers.push_back(k);
  }
  return c;
}

// w(load point) = weights . lasers: the least-squares plane through the
// lasers evaluated at the load point (plate_motion.h), for the live plot.
core::Vector loadPointWeights(const StiffnessRigSetup& setup) {
  const Eigen::Index n = static_cast<Eigen::Index>(setup.laserPoints.size());
  core::Matrix a(n, 3);
  for (Eigen::Index i = 0; i < n; ++i)
    a.row(i) << 1.0, setup.laserPoints[static_cast<std::size_t>(i)].x(),
        setup.laserPoints[static_cast<std::size_t>(i)].y();
  const core::Matrix pinv = (a.transpose() * a).inverse() * a.transpose();  // 3 x n
  const Eigen::RowVector3d at(1.0, setup.loadPoint.x(), setup.loadPoint.y());
  return (at * pinv).transpose();
}

std::vector<ChannelConfig> channelsOf(const StiffnessRigSetup& setup) {
  std::vector<ChannelConfig> c{setup.loadCell};
  c.insert(c.end(), setup.lasers.begin(), setup.lasers.end());
  return c;
}

// Stores the set-up and the test row (status Running); returns their ids.
struct Stored {
  std::optional<std::int64_t> setupId, testId;
  std::string name;
  std::vector<std::string> labels;  // of the planned steps
};

core::Result<Stored> storeStart(const StoreTarget& target, const StiffnessRigSetup& setup, const Device& daq,
                                const Device* actuator, bool dynamic, const nlohmann::json& plan,
                                const ParameterMap& daqParameters) {
  Stored s;
  for (const auto& st : plan.at("steps")) s.labels.push_back(st.at("label").get<std::string>());
  if (!target.store) {
    s.name = target.testName;
    return s;
  }
  auto& store = *target.store;
  auto name = detail::uniqueTestName(store, target.specimenId, false, target.testName, dynamic ? "dynamic" : "static");
  if (!name) return name.error();
  s.name = *name;
  core::io::StoredRigSetup rs;
  rs.specimenId = target.specimenId;
  rs.name = setup.rigName + " set-up of " + *name;
  rs.rigKind = dynamic ? "dynamic-stiffness" : "static-stiffness";
  rs.driver = daq.descriptor().driver + (actuator ? " + " + actuator->descriptor().driver : "");
  nlohmann::json geometry;
  geometry["plate_axes"] = "u = x, v = z, w = y (thesis §1.2): lasers and load cell along +w";
  geometry["load_point_m"] = {setup.loadPoint.x(), setup.loadPoint.y()};
  geometry["laser_points_m"] = nlohmann::json::array();
  for (const auto& p : setup.laserPoints) geometry["laser_points_m"].push_back({p.x(), p.y()});
  auto axisJson = [](const core::stiffness::PlateAxis& a) {
    return nlohmann::json{{"point_m", {a.point.x(), a.point.y()}}, {"direction", {a.direction.x(), a.direction.y()}}};
  };
  if (!setup.plateOutline.empty()) {
    geometry["plate_outline_m"] = nlohmann::json::array();
    for (const auto& p : setup.plateOutline) geometry["plate_outline_m"].push_back({p.x(), p.y()});
  }
  if (setup.constrainedEnd) geometry["constrained_end_m"] = {setup.constrainedEnd->x(), setup.constrainedEnd->y()};
  if (setup.bendAxis) geometry["bending_axis"] = axisJson(*setup.bendAxis);
  if (setup.torsAxis) geometry["torsion_axis"] = axisJson(*setup.torsAxis);
  geometry["record_columns"] = nlohmann::json::array();
  for (const auto& c : channelsOf(setup)) geometry["record_columns"].push_back(c.name);
  rs.axisMapJson = geometry.dump();
  nlohmann::json params;
  params["daq"] = detail::parametersJson(daqParameters);
  params["sample_rate_hz"] = setup.sampleRateHz;
  rs.parametersJson = params.dump();
  rs.transducers = detail::transducersOf(channelsOf(setup));
  auto setupId = store.addRigSetup(rs);
  if (!setupId) return setupId.error();
  s.setupId = *setupId;
  core::io::StoredRigTest t;
  t.specimenId = target.specimenId;
  t.rigSetupId = *setupId;
  t.kind = dynamic ? core::io::StoredRigTest::Kind::Dynamic : core::io::StoredRigTest::Kind::Static;
  t.name = *name;
  t.parametersJson = plan.dump();
  t.status = TestStatus::Running;
  t.statusNote = cutShortNote(0, s.labels);
  auto id = store.addRigTest(t);
  if (!id) return id.error();
  s.testId = *id;
  return s;
}

// A store failure during the test does not stop it; it is said in the note.
void storeStep(const StoreTarget& target, const Stored& stored, int step, double fs, const Eigen::MatrixXf& record,
               const std::vector<Quantity>& results, std::string& storeErrors) {
  if (!target.store || !stored.testId) return;
  auto r = target.store->commitRigTestStep(*stored.testId, step, fs, record, detail::rigResults(results, step),
                                           cutShortNote(step + 1, stored.labels));
  detail::collectStoreError(r, storeErrors);
}

void storeEnd(const StoreTarget& target, const Stored& stored, Outcome& out, std::string& storeErrors) {
  detail::reportStoreErrors(storeErrors, out);
  if (!target.store || !stored.testId) return;
  auto r = target.store->finishRigTest(*stored.testId, out.status, out.note, detail::rigResults(out.results, {}));
  detail::reportFinalWrite(r, out);
}

Quantity q(const char* key, const char* label, double v, const char* unit, double u = 0.0) {
  return Quantity{key, label, v, unit, std::isfinite(u) ? std::abs(u) : 0.0};
}

// First-order propagation of k_tw, the axis inclination and its offset into
// the decomposition, by central differences.
void decomposeInto(const core::stiffness::StaticTwistResult& tw, const StiffnessRigSetup& setup,
                   std::vector<Quantity>& out, std::optional<core::stiffness::Decomposition>& keep, std::string& note) {
  using core::stiffness::PlateAxis;
  auto run = [&](double kTw, double dBeta, double dOffset) {
    PlateAxis a = tw.axis.axis;
    const double c = std::cos(dBeta), s = std::sin(dBeta);
    a.direction = core::Vector2(c * a.direction.x() + s * a.direction.y(), -s * a.direction.x() + c * a.direction.y());
    const core::Vector2 normal(a.direction.y(), -a.direction.x());
    a.point += dOffset * normal;
    return core::stiffness::decomposeStiffness(kTw, a, *setup.bendAxis, *setup.torsAxis, setup.loadPoint);
  };
  auto d = run(tw.twistStiffness, 0.0, 0.0);
  if (!d) {
    note = "decomposition: " + d.error().message;
    return;
  }
  keep = *d;
  double vb = 0.0, vt = 0.0;
  const double steps[3][3] = {
      {tw.twistStiffnessSigma, 0, 0}, {0, tw.axis.axis.betaSigma, 0}, {0, 0, tw.axis.axis.offsetSigma}};
  for (const auto& st : steps) {
    auto p = run(tw.twistStiffness + st[0], st[1], st[2]);
    auto m = run(tw.twistStiffness - st[0], -st[1], -st[2]);
    if (p && m) {
      vb += std::pow(0.5 * (p->bendStiffness - m->bendStiffness), 2);
      vt += std::pow(0.5 * (p->torsStiffness - m->torsStiffness), 2);
    }
  }
  out.push_back(q("k_bend", "bending stiffness", d->bendStiffness, "N m/rad", std::sqrt(vb)));
  out.push_back(q("k_tors", "torsion stiffness", d->torsStiffness, "N m/rad", std::sqrt(vt)));
  out.push_back(q("a_bend", "bending arm", setup.bendAxis->signedArm(setup.loadPoint), "m"));
  out.push_back(q("a_tors", "torsion arm", setup.torsAxis->signedArm(setup.loadPoint), "m"));
  if (d->lowConfidence) note = "decomposition: " + d->note;
}

void progress(const Callbacks& cb, int step, int steps, double fraction, const std::string& message) {
  if (cb.progress) cb.progress(Progress{step, steps, std::clamp(fraction, 0.0, 1.0), message});
}

void log(const Callbacks& cb, const std::string& line) {
  if (cb.log) cb.log(line);
}

// Names of the channels whose overloads a session reported.
std::string overloadedNames(const detail::SessionData& data) {
  std::set<int> channels;
  for (const auto& o : data.overloads) channels.insert(o.channel);
  std::string s;
  for (int c : channels)
    s += (s.empty() ? "" : ", ") + (c < static_cast<int>(data.header.channels.size())
                                        ? data.header.channels[static_cast<std::size_t>(c)].name
                                        : std::to_string(c));
  return s;
}

}  // namespace

std::string laserFieldKey(std::size_t index, const char* axis) {
  return "setup.laser" + std::to_string(index + 1) + "_" + axis;
}

core::Result<void> checkPlateGeometry(const StiffnessRigSetup& setup) {
  const auto& l = setup.laserPoints;
  auto at = [](const core::Vector2& p) { return "(" + mm(p.x()) + ", " + mm(p.y()) + ") mm"; };
  for (std::size_t i = 0; i < l.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if ((l[i] - l[j]).norm() < kMinSpacingM)
        return geometryError("laser " + std::to_string(i + 1) + " at " + at(l[i]) + " is less than 5 mm from laser " +
                                 std::to_string(j + 1) + ": each laser needs its own spot",
                             laserFieldKey(i, "u"));
  if (l.size() >= 3) {
    // Distance of each laser from the line through the others (their
    // principal direction); all within 5 mm: the lasers lie on one line.
    double worst = 0.0;
    std::size_t worstLaser = l.size() - 1;
    for (std::size_t k = 0; k < l.size(); ++k) {
      core::Vector2 c = core::Vector2::Zero();
      for (std::size_t i = 0; i < l.size(); ++i)
        if (i != k) c += l[i];
      c /= static_cast<double>(l.size() - 1);
      Eigen::Matrix2d s = Eigen::Matrix2d::Zero();
      for (std::size_t i = 0; i < l.size(); ++i)
        if (i != k) s += (l[i] - c) * (l[i] - c).transpose();
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(s);
      const core::Vector2 along = eig.eigenvectors().col(1);
      const core::Vector2 d = l[k] - c;
      const double off = std::abs(d.x() * along.y() - d.y() * along.x());
      if (off > worst) {
        worst = off;
        worstLaser = k;
      }
    }
    if (worst < kMinSpacingM)
      return geometryError("the lasers lie on one line (laser " + std::to_string(worstLaser + 1) + " is " + mm(worst) +
                               " mm off the line through the others): the twist axis needs the plate's "
                               "plane; move laser " +
                               std::to_string(worstLaser + 1) + " off the line",
                           laserFieldKey(worstLaser, "u"));
  }
  if (setup.plateOutline.size() >= 3) {
    core::Vector2 lo = setup.plateOutline.front(), hi = lo;
    for (const auto& p : setup.plateOutline) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    const double eps = 1e-9;
    auto on = [&](const core::Vector2& p) {
      return p.x() >= lo.x() - eps && p.x() <= hi.x() + eps && p.y() >= lo.y() - eps && p.y() <= hi.y() + eps;
    };
    for (std::size_t i = 0; i < l.size(); ++i)
      if (!on(l[i]))
        return geometryError("laser " + std::to_string(i + 1) + " at " + at(l[i]) + " is off the " +
                                 mm(hi.x() - lo.x()) + " x " + mm(hi.y() - lo.y()) + " mm plate",
                             laserFieldKey(i, "u"));
    if (setup.constrainedEnd && on(*setup.constrainedEnd))
      return geometryError("the constrained end at " + at(*setup.constrainedEnd) +
                               " is on the plate: the plate is at the loaded end, the other end is locked",
                           "setup.constrained_u");
  }
  if (setup.constrainedEnd && (*setup.constrainedEnd - setup.loadPoint).norm() < kMinSpacingM)
    return geometryError("the constrained end is at the load point: the load acts at the free end",
                         "setup.constrained_u");
  return {};
}

core::Result<void> checkStaticSettings(const StiffnessRigSetup& setup, const StaticTestSettings& s) {
  if (auto r = checkSetup(setup); !r) return r;
  if (!(s.peakForceN > 0) || !std::isfinite(s.peakForceN))
    return refuse("peak force " + number(s.peakForceN) + " N: must be > 0");
  if (s.peakForceN > kActuatorMaxForceN)
    return refuse("peak force " + number(s.peakForceN) + " N exceeds the actuator's limit of " +
                  number(kActuatorMaxForceN) + " N (thesis §1.1)");
  if (s.peakForceN > setup.loadCellFullScaleN)
    return refuse("peak force " + number(s.peakForceN) + " N exceeds the load cell's range of " +
                  number(setup.loadCellFullScaleN) + " N (+/-200 kg, thesis §1.1)");
  if (!(s.periodS >= 1.0) || !std::isfinite(s.periodS))
    return refuse("ramp period " + number(s.periodS) + " s: at least 1 s (a slowly varying force, §1.2)");
  if (s.periodS * setup.sampleRateHz < 40)
    return refuse("the ramp would have " + number(s.periodS * setup.sampleRateHz) +
                  " samples; at least 40 (raise the period or the rate)");
  return {};
}

core::Result<void> checkDynamicSettings(const StiffnessRigSetup& setup, const DynamicTestSettings& s) {
  if (auto r = checkSetup(setup); !r) return r;
  if (s.frequenciesHz.empty()) return refuse("no frequency given");
  for (double f : s.frequenciesHz) {
    if (!std::isfinite(f) || f < kActuatorMinFrequencyHz || f > kActuatorMaxFrequencyHz)
      return refuse("frequency " + number(f) + " Hz is outside the actuator's band of " +
                    number(kActuatorMinFrequencyHz) + " to " + number(kActuatorMaxFrequencyHz) + " Hz (thesis §1.1)");
    if (f > setup.sampleRateHz / 20)
      return refuse("frequency " + number(f) + " Hz is above a twentieth of the " + number(setup.sampleRateHz) +
                    " Hz sample rate");
  }
  if (!(s.amplitudeN > 0) || !std::isfinite(s.amplitudeN))
    return refuse("sine amplitude " + number(s.amplitudeN) + " N: must be > 0");
  if (s.amplitudeN > kActuatorMaxForceN)
    return refuse("sine amplitude " + number(s.amplitudeN) + " N exceeds the actuator's limit of " +
                  number(kActuatorMaxForceN) + " N (thesis §1.1)");
  if (s.amplitudeN > setup.loadCellFullScaleN)
    return refuse("sine amplitude " + number(s.amplitudeN) + " N exceeds the load cell's range of " +
                  number(setup.loadCellFullScaleN) + " N (+/-200 kg, thesis §1.1)");
  if (!(s.settleCycles >= 0) || !(s.minSettleS >= 0) || !(s.recordCycles >= 2) || !(s.minRecordS > 0))
    return refuse("settling must be >= 0 and the record at least 2 cycles");
  return {};
}

core::Result<StaticOutcome> runStaticStiffnessTest(Device& daq, Device* actuator, const StiffnessRigSetup& setup,
                                                   const StaticTestSettings& settings, const StoreTarget& target,
                                                   const Callbacks& callbacks, const CancelFlag* cancel) {
  // Everything is checked before a device is touched.
  if (auto r = checkStaticSettings(setup, settings); !r) return r.error();
  auto path = actuatorPath(daq, actuator);
  if (!path) return path.error();

  detail::SessionPlan plan;
  plan.step = 0;
  plan.stepLabel = "ramp +/-" + number(settings.peakForceN) + " N";
  plan.daqConfig.sampleRateHz = setup.sampleRateHz;
  plan.daqConfig.channels = channelsOf(setup);
  plan.daqConfig.scanCount = detail::scansFor(settings.periodS, setup.sampleRateHz);
  plan.daqConfig.parameters = setup.daqParameters;
  ParameterMap act{{"mode", std::string("static-ramp")},
                   {"static.max_force", settings.peakForceN},
                   {"static.period_s", settings.periodS}};
  if (*path == ActuatorPath::FunctionGenerator) {
    plan.actuatorConfig = AcquisitionConfig{};
    plan.actuatorConfig->parameters = act;
  } else {
    for (auto& [k, v] : act) plan.daqConfig.parameters[k] = v;
  }

  nlohmann::json planJson;
  planJson["test"] = "static";
  planJson["peak_force_n"] = settings.peakForceN;
  planJson["period_s"] = settings.periodS;
  planJson["sample_rate_hz"] = setup.sampleRateHz;
  planJson["steps"] = nlohmann::json::array();
  planJson["steps"].push_back({{"label", plan.stepLabel}});
  auto stored = storeStart(target, setup, daq, actuator, false, planJson, plan.daqConfig.parameters);
  if (!stored) return stored.error();

  StaticOutcome out;
  out.testId = stored->testId;
  out.rigSetupId = stored->setupId;
  out.testName = stored->name;
  std::string storeErrors;
  log(callbacks, "static test: ramp 0 -> +" + number(settings.peakForceN) + " -> -" + number(settings.peakForceN) +
                     " -> 0 N over " + number(settings.periodS) + " s");

  const core::Vector weights = loadPointWeights(setup);
  std::vector<int> laserCols;
  detail::SessionHooks hooks;
  hooks.derivedLabel = "load-point displacement [m]";
  const std::int64_t total = plan.daqConfig.scanCount;
  hooks.block = [&](const detail::SessionData& d, Eigen::Index, Eigen::Index) {
    if (laserCols.empty()) {
      if (auto c = columnsOf(d.header, setup)) laserCols = c->lasers;
    }
    progress(callbacks, 0, 1, static_cast<double>(d.rows) / static_cast<double>(total), plan.stepLabel);
  };
  hooks.derived = [&](const core::Matrix& block) {
    core::Vector w = core::Vector::Zero(block.rows());
    if (laserCols.size() == static_cast<std::size_t>(weights.size()))
      for (std::size_t i = 0; i < laserCols.size(); ++i)
        w += weights(static_cast<Eigen::Index>(i)) * block.col(laserCols[i]);
    return w;
  };
  progress(callbacks, 0, 1, 0.0, plan.stepLabel);
  auto session = detail::runSession(daq, actuator, plan, callbacks, cancel, hooks);
  if (!session) {
    out.status = TestStatus::Failed;
    out.note = "the rig refused the test: " + session.error().describe();
    storeEnd(target, *stored, out, storeErrors);
    return session.error();
  }
  auto cols = columnsOf(session->header, setup);
  const Eigen::Index rows = session->scans();
  const double fs = session->header.sampleRateHz;
  if (cols && rows > 0)
    storeStep(target, *stored, 0, fs, detail::recordOf(session->values, rows, cols->all()), {}, storeErrors);
  StepReport report{0, plan.stepLabel, false, "", {}};
  const bool complete = session->end.reason == EndReason::Completed && !session->cancelled && rows >= total;
  if (!complete) {
    out.status = TestStatus::Interrupted;
    const std::string cause = session->cancelled ? "cancelled" : detail::endCause(session->end);
    out.note = cause + " after " + number(static_cast<double>(rows) / fs) + " s of the " + number(settings.periodS) +
               " s ramp; the partial record is stored (step 0), no result was computed";
    report.note = out.note;
  } else if (!cols) {
    out.status = TestStatus::Failed;
    out.note = cols.error().message;
  } else if (!session->overloads.empty() || !session->overruns.empty()) {
    out.status = TestStatus::Failed;
    out.note = !session->overloads.empty()
                   ? overloadedNames(*session) + " reached the end of its range: lower the peak force"
                   : "the acquisition lost data (overrun): repeat the test";
    report.note = out.note;
  } else {
    const core::Vector force = session->values.col(cols->force);
    core::Matrix disp(rows, static_cast<Eigen::Index>(cols->lasers.size()));
    for (std::size_t i = 0; i < cols->lasers.size(); ++i)
      disp.col(static_cast<Eigen::Index>(i)) = session->values.col(cols->lasers[i]);
    auto tw = core::stiffness::staticTwistTest(setup.laserPoints, force, disp, setup.loadPoint);
    if (!tw) {
      out.status = TestStatus::Failed;
      out.note = "static twist test: " + tw.error().message;
      report.note = out.note;
    } else {
      out.twist = *tw;
      auto& r = out.results;
      r.push_back(q("k_lat", "lateral stiffness", tw->lateralStiffness, "N/m", tw->lateralStiffnessSe));
      r.push_back(q("a_tw", "twist arm", tw->twistArm, "m", tw->twistArmSigma));
      r.push_back(q("k_tw", "twist stiffness", tw->twistStiffness, "N m/rad", tw->twistStiffnessSigma));
      r.push_back(q("axis_inclination", "twist axis inclination from the plate's v axis", tw->axis.axis.beta, "rad",
                    tw->axis.axis.betaSigma));
      r.push_back(q("axis_point_u", "twist axis foot from the load point, u", tw->axis.axis.point.x(), "m",
                    tw->axis.axis.offsetSigma));
      r.push_back(q("axis_point_v", "twist axis foot from the load point, v", tw->axis.axis.point.y(), "m",
                    tw->axis.axis.offsetSigma));
      r.push_back(q("peak_force", "peak force measured", force.cwiseAbs().maxCoeff(), "N"));
      if (tw->positiveBranchStiffness > 0)
        r.push_back(q("k_lat_positive", "lateral stiffness, positive load", tw->positiveBranchStiffness, "N/m"));
      if (tw->negativeBranchStiffness > 0)
        r.push_back(q("k_lat_negative", "lateral stiffness, negative load", tw->negativeBranchStiffness, "N/m"));
      r.push_back(q("plane_rms_residual", "rms residual of the laser plane", tw->axis.plane.rmsResidual, "m"));
      std::string dnote;
      if (setup.bendAxis && setup.torsAxis) decomposeInto(*tw, setup, r, out.decomposition, dnote);
      std::string notes = tw->note;
      if (!dnote.empty()) notes += (notes.empty() ? "" : "; ") + dnote;
      if (!tw->linear) notes += std::string(notes.empty() ? "" : "; ") + "the two load branches differ (non-linear)";
      out.note = notes;
      report.ok = true;
      report.results = r;
      report.note = notes;
    }
  }
  out.steps.push_back(report);
  if (callbacks.step) callbacks.step(report);
  progress(callbacks, 1, 1, 1.0, "done");
  storeEnd(target, *stored, out, storeErrors);
  log(callbacks,
      std::string("static test ") + core::io::testStatusName(out.status) + (out.note.empty() ? "" : ": " + out.note));
  return out;
}

core::Result<DynamicOutcome> runDynamicStiffnessTest(Device& daq, Device* actuator, const StiffnessRigSetup& setup,
                                                     const DynamicTestSettings& settings, const StoreTarget& target,
                                                     const Callbacks& callbacks, const CancelFlag* cancel) {
  if (auto r = checkDynamicSettings(setup, settings); !r) return r.error();
  auto path = actuatorPath(daq, actuator);
  if (!path) return path.error();

  std::vector<std::string> labels;
  nlohmann::json planJson;
  planJson["test"] = "dynamic";
  planJson["amplitude_n"] = settings.amplitudeN;
  planJson["sample_rate_hz"] = setup.sampleRateHz;
  planJson["steps"] = nlohmann::json::array();
  struct StepTiming {
    double f, settleS, recordS;
  };
  std::vector<StepTiming> timing;
  double totalS = 0.0;
  for (double f : settings.frequenciesHz) {
    const double settle = std::max(settings.settleCycles / f, settings.minSettleS);
    const double cycles = std::ceil(std::max(settings.recordCycles, settings.minRecordS * f) - 1e-9);
    timing.push_back({f, settle, cycles / f});
    totalS += settle + cycles / f;
    labels.push_back(hz(f));
    planJson["steps"].push_back(
        {{"label", hz(f)}, {"frequency_hz", f}, {"settle_s", settle}, {"record_s", cycles / f}});
  }
  auto stored = storeStart(target, setup, daq, actuator, true, planJson, setup.daqParameters);
  if (!stored) return stored.error();

  DynamicOutcome out;
  out.testId = stored->testId;
  out.rigSetupId = stored->setupId;
  out.testName = stored->name;
  std::string storeErrors;
  const core::Vector weights = loadPointWeights(setup);
  double doneS = 0.0;
  int ok = 0;
  for (std::size_t k = 0; k < timing.size(); ++k) {
    const auto& st = timing[k];
    const int step = static_cast<int>(k);
    if (cancel && cancel->cancelled()) {
      out.status = TestStatus::Interrupted;
      out.note = missingStepsNote("cancelled", step, labels);
      break;
    }
    detail::SessionPlan plan;
    plan.step = step;
    plan.stepLabel = labels[k];
    plan.daqConfig.sampleRateHz = setup.sampleRateHz;
    plan.daqConfig.channels = channelsOf(setup);
    const std::int64_t settleScans = detail::scansFor(st.settleS, setup.sampleRateHz);
    const std::int64_t recordScans = detail::scansFor(st.recordS, setup.sampleRateHz);
    plan.daqConfig.scanCount = settleScans + recordScans;
    plan.daqConfig.parameters = setup.daqParameters;
    if (*path == ActuatorPath::FunctionGenerator) {
      plan.actuatorConfig = AcquisitionConfig{};
      plan.actuatorConfig->parameters = ParameterMap{
          {"mode", std::string("sine")}, {"sine.frequency", st.f}, {"sine.amplitude", settings.amplitudeN}};
    } else {
      plan.daqConfig.parameters["mode"] = std::string("sine");
      plan.daqConfig.parameters["sine.frequency"] = st.f;
      plan.daqConfig.parameters["sine.amplitude_1hz"] = settings.amplitudeN;
    }
    std::vector<int> laserCols;
    detail::SessionHooks hooks;
    hooks.derivedLabel = "load-point displacement [m]";
    hooks.block = [&](const detail::SessionData& d, Eigen::Index, Eigen::Index) {
      if (laserCols.empty()) {
        if (auto c = columnsOf(d.header, setup)) laserCols = c->lasers;
      }
      const double t = static_cast<double>(d.rows) / setup.sampleRateHz;
      progress(callbacks, step, static_cast<int>(timing.size()), (doneS + t) / totalS,
               labels[k] + (t < st.settleS ? ": settling" : ": recording"));
    };
    hooks.derived = [&](const core::Matrix& block) {
      core::Vector w = core::Vector::Zero(block.rows());
      if (laserCols.size() == static_cast<std::size_t>(weights.size()))
        for (std::size_t i = 0; i < laserCols.size(); ++i)
          w += weights(static_cast<Eigen::Index>(i)) * block.col(laserCols[i]);
      return w;
    };
    log(callbacks, "dynamic test: " + labels[k] + ", " + number(settings.amplitudeN) + " N set-point");
    auto session = detail::runSession(daq, actuator, plan, callbacks, cancel, hooks);
    if (!session) {
      out.status = step == 0 ? TestStatus::Failed : TestStatus::Interrupted;
      out.note = missingStepsNote("the rig refused the step (" + session.error().describe() + ")", step, labels);
      if (step == 0) {
        storeEnd(target, *stored, out, storeErrors);
        return session.error();
      }
      break;
    }
    doneS += st.settleS + st.recordS;
    auto cols = columnsOf(session->header, setup);
    const Eigen::Index rows = session->scans();
    const double fs = session->header.sampleRateHz;
    const bool complete =
        session->end.reason == EndReason::Completed && !session->cancelled && rows >= plan.daqConfig.scanCount && cols;
    StepReport report{step, labels[k], false, "", {}};
    DynamicStep ds;
    ds.frequencyHz = st.f;
    if (complete && session->overloads.empty() && session->overruns.empty()) {
      // Sine fits of the record after settling, phases at the record's start.
      const Eigen::Index from = static_cast<Eigen::Index>(settleScans);
      const Eigen::Index n = rows - from;
      auto fit = [&](int col) {
        return core::signal::fitSineKnownFrequency(session->values.col(col).segment(from, n), fs, st.f);
      };
      auto ff = fit(cols->force);
      core::stiffness::SweepPoint sp;
      sp.frequencyHz = st.f;
      sp.amplitude.resize(static_cast<Eigen::Index>(cols->lasers.size()));
      sp.phase.resize(sp.amplitude.size());
      bool fitted = ff.ok();
      std::vector<Quantity>& r = report.results;
      r.push_back(q("frequency", "excitation frequency", st.f, "Hz"));
      if (ff) {
        sp.forceAmplitude = ff->amplitude;
        sp.forcePhase = ff->phaseRad;
        r.push_back(q("force_amplitude", "force amplitude", ff->amplitude, "N", ff->amplitudeStdError));
      }
      for (std::size_t i = 0; i < cols->lasers.size() && fitted; ++i) {
        auto lf = fit(cols->lasers[i]);
        if (!lf) {
          fitted = false;
          report.note = "sine fit of " + setup.lasers[i].name + ": " + lf.error().message;
          break;
        }
        sp.amplitude(static_cast<Eigen::Index>(i)) = lf->amplitude;
        sp.phase(static_cast<Eigen::Index>(i)) = core::signal::wrapPhase(lf->phaseRad - sp.forcePhase);
        const std::string n1 = "laser_" + std::to_string(i + 1);
        r.push_back(Quantity{n1 + "_amplitude", setup.lasers[i].name + " amplitude", lf->amplitude, "m",
                             lf->amplitudeStdError});
        r.push_back(Quantity{n1 + "_phase", setup.lasers[i].name + " phase from the force",
                             sp.phase(static_cast<Eigen::Index>(i)), "rad",
                             std::hypot(lf->phaseStdError, ff ? ff->phaseStdError : 0.0)});
      }
      if (!ff) report.note = "sine fit of the load cell: " + ff.error().message;
      sp.forcePhase = 0.0;  // laser phases are relative to the force
      if (fitted) {
        auto sweep = core::stiffness::dynamicTwistSweep(setup.laserPoints, {sp}, setup.loadPoint);
        if (sweep && !sweep->empty() && sweep->front().axis.ok()) {
          const auto& sa = sweep->front();
          const auto& pa = *sa.axis;
          const auto& ax = pa.axis.axis;
          // x_lat = plane at the load point; its variance from the plane fit.
          const auto& plane = pa.axis.plane;
          const core::Vector3 e(1.0, setup.loadPoint.x(), setup.loadPoint.y());
          const double xLat = std::abs(plane.evaluate(setup.loadPoint));
          const double sx = std::sqrt(std::max(0.0, e.dot(plane.covariance * e)));
          const double relK = std::hypot(ff->amplitudeStdError / ff->amplitude, xLat > 0 ? sx / xLat : 0.0);
          r.push_back(q("axis_inclination", "dynamic twist axis inclination from the plate's v axis", ax.beta, "rad",
                        ax.betaSigma));
          r.push_back(
              q("axis_point_u", "dynamic twist axis foot from the load point, u", ax.point.x(), "m", ax.offsetSigma));
          r.push_back(
              q("axis_point_v", "dynamic twist axis foot from the load point, v", ax.point.y(), "m", ax.offsetSigma));
          r.push_back(q("a_tw", "dynamic twist arm", sa.twistArm, "m", ax.offsetSigma));
          r.push_back(q("k_lat", "dynamic lateral stiffness", sa.dynamicLateralStiffness, "N/m",
                        relK * sa.dynamicLateralStiffness));
          r.push_back(
              q("k_tw", "dynamic twist stiffness", sa.dynamicTwistStiffness, "N m/rad",
                std::hypot(relK, sa.twistArm > 0 ? 2 * ax.offsetSigma / sa.twistArm : 0.0) * sa.dynamicTwistStiffness));
          report.ok = true;
          report.note = std::string(core::stiffness::phasorAxisCaseName(pa.method)) + " axis" +
                        (pa.note.empty() ? "" : "; " + pa.note);
          ds.axis = sa;
          ++ok;
        } else {
          report.note = "no twist axis: " +
                        (sweep ? (sweep->empty() ? std::string("empty sweep") : sweep->front().axis.error().message)
                               : sweep.error().message);
        }
      }
    } else if (complete) {
      report.note = !session->overloads.empty() ? overloadedNames(*session) +
                                                      " reached the end of its range (near a resonance?): lower the "
                                                      "amplitude; the record is stored"
                                                : "the acquisition lost data (overrun); the record is stored";
    }
    if (cols && rows > 0)
      storeStep(target, *stored, step, fs, detail::recordOf(session->values, rows, cols->all()), report.results,
                storeErrors);
    out.sweep.push_back(ds);
    if (!complete) {
      const std::string cause = session->cancelled ? "cancelled" : detail::endCause(session->end);
      out.status = TestStatus::Interrupted;
      out.note = missingStepsNote(cause, step, labels);
      report.note = cause + "; the partial record is stored";
      out.steps.push_back(report);
      if (callbacks.step) callbacks.step(report);
      break;
    }
    out.steps.push_back(report);
    if (callbacks.step) callbacks.step(report);
  }
  out.results.push_back(q("steps_with_axis", "frequencies with a twist axis", ok, ""));
  if (out.status == TestStatus::Complete && ok < static_cast<int>(timing.size()))
    out.note = std::to_string(static_cast<int>(timing.size()) - ok) + " of " + std::to_string(timing.size()) +
               " frequencies gave no twist axis (see their notes)";
  progress(callbacks, static_cast<int>(timing.size()), static_cast<int>(timing.size()), 1.0, "done");
  storeEnd(target, *stored, out, storeErrors);
  log(callbacks,
      std::string("dynamic test ") + core::io::testStatusName(out.status) + (out.note.empty() ? "" : ": " + out.note));
  return out;
}

core::Result<StiffnessRigSetup> simulatedStiffnessSetup(const std::string& specimenKey, std::uint64_t seed,
                                                        bool realtime) {
  auto spec = sim::staticSpecimen(specimenKey);
  if (!spec) return spec.error();
  StiffnessRigSetup s;
  s.rigName = "Simulated Motostiffmeter";
  s.loadCell.input = 0;
  s.loadCell.name = "load cell";
  s.loadCell.rangeCode = 0;  // +/-10 V
  s.loadCell.transducer = core::signal::Transducer{
      core::signal::TransducerKind::Force, "load cell +/-200 kg", "", 10000.0 / (200 * 9.80665), "N", false};
  for (int i = 1; i <= static_cast<int>(spec->laserPoints.size()); ++i) {
    ChannelConfig l;
    l.input = i;
    l.name = "laser " + std::to_string(i);
    l.rangeCode = 0;  // +/-10 V = +/-10 mm: the laser's 20 mm range
    l.transducer = core::signal::Transducer{
        core::signal::TransducerKind::Displacement, "laser 20 mm, 4 um", "", 1e6, "m", false};  // 1 V/mm
    s.lasers.push_back(l);
  }
  s.laserPoints = spec->laserPoints;
  s.loadPoint = spec->loadPoint;
  s.daqParameters["specimen"] = specimenKey;
  s.daqParameters["sim.seed"] = static_cast<std::int64_t>(seed);
  s.daqParameters["sim.realtime"] = realtime;
  if (spec->hasAxes()) {
    auto axis = [](const sim::PlateMode& m) {
      core::stiffness::PlateAxis a;
      a.point = m.point;
      a.direction = m.direction;
      a.beta = std::atan2(m.direction.x(), m.direction.y());
      return a;
    };
    s.bendAxis = axis(spec->modes[0]);
    s.torsAxis = axis(spec->modes[1]);
  }
  return s;
}

}  // namespace mozzi::devices::rigtests
