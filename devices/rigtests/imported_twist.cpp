#include "devices/rigtests/imported_twist.h"

#include <cmath>
#include <complex>
#include <nlohmann/json.hpp>

#include "core/common/text.h"
#include "core/stiffness/dynamic_twist.h"
#include "devices/rigtests/test_store.h"

namespace mozzi::devices::rigtests {

namespace st = core::stiffness;

namespace {

StiffnessTestView geometryOf(const st::PlateCsv& csv, const std::string& name, bool dynamic) {
  StiffnessTestView v;
  v.name = name;
  v.dynamic = dynamic;
  v.loadPoint = csv.hasLoad ? csv.load : core::Vector2::Zero();
  v.laserPoints = csv.sensors;
  return v;
}

void putAxis(std::map<std::string, StoredQuantity>& r, const st::PlateAxis& a) {
  r["axis_inclination"] = {a.beta, a.betaSigma, "rad"};
  r["axis_point_u"] = {a.point(0), a.offsetSigma, "m"};
  r["axis_point_v"] = {a.point(1), a.offsetSigma, "m"};
}

}  // namespace

core::Result<StiffnessTestView> staticViewFromCsv(const st::PlateCsv& csv, const std::string& name) {
  auto res = st::staticTwistFromCsv(csv);
  if (!res) {
    core::Error e = res.error();
    // A computation's error (zero load, collinear lasers) names the data row.
    if (e.where.rfind(csv.source, 0) != 0) e.where = csv.where() + (e.where.empty() ? "" : ": " + e.where);
    return e;
  }
  StiffnessTestView v = geometryOf(csv, name, false);
  v.results["k_lat"] = {res->lateralStiffness, res->lateralStiffnessSe, "N/m"};
  v.results["a_tw"] = {res->twistArm, res->twistArmSigma, "m"};
  v.results["k_tw"] = {res->twistStiffness, res->twistStiffnessSigma, "N m/rad"};
  putAxis(v.results, res->axis.axis);
  v.axis = res->axis.axis;
  if (res->lowConfidence) v.statusNote = res->note;
  return v;
}

core::Result<StiffnessTestView> dynamicViewFromCsv(const st::PlateCsv& csv, const std::string& name,
                                                   std::string* note) {
  auto sweep = st::sweepFromCsv(csv);
  if (!sweep) return sweep.error();
  if (!csv.hasLoad) return core::makeError(core::ErrorCode::ParseError, "no 'load,u,v' row", csv.source);
  auto axes = st::dynamicTwistSweep(csv.sensors, *sweep, csv.load);
  if (!axes) {
    core::Error e = axes.error();
    e.where = csv.source + (e.where.empty() ? "" : ": " + e.where);
    return e;
  }
  StiffnessTestView v = geometryOf(csv, name, true);
  std::string problems;
  int withAxis = 0;
  for (std::size_t k = 0; k < axes->size(); ++k) {
    const auto& s = (*axes)[k];
    const auto& p = (*sweep)[k];
    StiffnessTestView::Step step;
    step.step = static_cast<int>(k);
    step.frequencyHz = s.frequencyHz;
    step.results["frequency"] = {s.frequencyHz, 0.0, "Hz"};
    step.laserPhasors.resize(p.amplitude.size());
    for (Eigen::Index i = 0; i < p.amplitude.size(); ++i) step.laserPhasors(i) = std::polar(p.amplitude(i), p.phase(i));
    if (s.axis) {
      const auto& a = s.axis->axis.axis;
      step.axis = a;
      putAxis(step.results, a);
      // The arm is the load point's distance from the axis (its foot from the load point).
      step.results["a_tw"] = {(v.loadPoint - a.point).norm(), a.offsetSigma, "m"};
      if (p.forceAmplitude > 0.0) {
        step.results["k_lat"] = {s.dynamicLateralStiffness, 0.0, "N/m"};
        step.results["k_tw"] = {s.dynamicTwistStiffness, 0.0, "N m/rad"};
      }
      ++withAxis;
    } else {
      problems += (problems.empty() ? "" : "; ") + core::formatNumber(s.frequencyHz) + " Hz (" + csv.where(k) +
                  "): " + s.axis.error().message;
    }
    v.steps.push_back(std::move(step));
  }
  if (withAxis == 0)
    return core::makeError(core::ErrorCode::NumericalFailure, "no frequency gives a twist axis: " + problems,
                           csv.source);
  if (note) *note = problems;
  return v;
}

core::Result<std::int64_t> storeImportedTest(core::io::ProjectStore& store, std::int64_t specimenId,
                                             const StiffnessTestView& view, const std::string& sourcePath) {
  auto name = detail::uniqueTestName(store, specimenId, false, view.name, view.dynamic ? "dynamic" : "static");
  if (!name) return name.error();
  core::io::StoredRigSetup rs;
  rs.specimenId = specimenId;
  rs.name = "imported " + *name;
  rs.rigKind = "imported-csv";
  rs.driver = "csv";
  nlohmann::json geometry;
  geometry["plate_axes"] = "u = x, v = z, w = y (thesis §1.2): as the imported file gives them";
  geometry["load_point_m"] = {view.loadPoint.x(), view.loadPoint.y()};
  geometry["laser_points_m"] = nlohmann::json::array();
  for (const auto& p : view.laserPoints) geometry["laser_points_m"].push_back({p.x(), p.y()});
  rs.axisMapJson = geometry.dump();
  rs.parametersJson = nlohmann::json{{"source", sourcePath}}.dump();
  auto setupId = store.addRigSetup(rs);
  if (!setupId) return setupId.error();
  core::io::StoredRigTest t;
  t.specimenId = specimenId;
  t.rigSetupId = *setupId;
  t.kind = view.dynamic ? core::io::StoredRigTest::Kind::Dynamic : core::io::StoredRigTest::Kind::Static;
  t.name = *name;
  t.parametersJson = nlohmann::json{{"imported_from", sourcePath}}.dump();
  t.status = core::io::TestStatus::Complete;
  t.statusNote = view.statusNote;
  auto put = [&t](const std::map<std::string, StoredQuantity>& results, std::optional<int> step) {
    for (const auto& [key, q] : results) t.results.push_back({key, q.value, q.unit, q.uncertainty, step});
  };
  put(view.results, std::nullopt);
  for (const auto& s : view.steps) {
    put(s.results, s.step);
    for (Eigen::Index i = 0; i < s.laserPhasors.size(); ++i) {
      const std::string key = "laser_" + std::to_string(i + 1);
      t.results.push_back({key + "_amplitude", std::abs(s.laserPhasors(i)), "m", 0.0, s.step});
      t.results.push_back({key + "_phase", std::arg(s.laserPhasors(i)), "rad", 0.0, s.step});
    }
  }
  return store.addRigTest(t);
}

}  // namespace mozzi::devices::rigtests
