#include "devices/rigtests/stiffness_results.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <nlohmann/json.hpp>

namespace mozzi::devices::rigtests {

namespace {

std::optional<core::Vector2> vec2(const nlohmann::json& j) {
  if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number()) return std::nullopt;
  return core::Vector2(j[0].get<double>(), j[1].get<double>());
}

std::optional<core::stiffness::PlateAxis> axisOf(const nlohmann::json& geometry, const char* key) {
  if (!geometry.contains(key) || !geometry[key].is_object()) return std::nullopt;
  const auto point = vec2(geometry[key].value("point_m", nlohmann::json()));
  const auto direction = vec2(geometry[key].value("direction", nlohmann::json()));
  if (!point || !direction || !(direction->norm() > 0.0)) return std::nullopt;
  core::stiffness::PlateAxis a;
  a.point = *point;
  a.direction = direction->normalized();
  a.beta = std::atan2(a.direction(0), a.direction(1));
  return a;
}

// The axis a step or the whole test stored: foot (axis_point_u, axis_point_v)
// and inclination beta from the plate's v axis, with their uncertainties.
std::optional<core::stiffness::PlateAxis> storedAxis(const std::map<std::string, StoredQuantity>& r) {
  const auto u = r.find("axis_point_u"), v = r.find("axis_point_v"), beta = r.find("axis_inclination");
  if (u == r.end() || v == r.end() || beta == r.end()) return std::nullopt;
  auto a = core::stiffness::plateAxisAt(core::Vector2(u->second.value, v->second.value), beta->second.value);
  a.betaSigma = beta->second.uncertainty;
  a.offsetSigma = u->second.uncertainty;
  return a;
}

}  // namespace

const StoredQuantity* StiffnessTestView::result(const std::string& key) const {
  const auto it = results.find(key);
  return it == results.end() ? nullptr : &it->second;
}

std::vector<core::stiffness::AxisAtFrequency> StiffnessTestView::dynamicAxes() const {
  std::vector<core::stiffness::AxisAtFrequency> out;
  for (const auto& s : steps)
    if (s.axis) out.push_back({s.frequencyHz, *s.axis});
  return out;
}

core::Result<StiffnessTestView> readStiffnessTest(const core::io::ProjectStore& store, std::int64_t testId) {
  auto test = store.rigTest(testId);
  if (!test) return test.error();
  StiffnessTestView v;
  v.testId = test->id;
  v.specimenId = test->specimenId;
  v.name = test->name;
  v.dynamic = test->kind == core::io::StoredRigTest::Kind::Dynamic;
  v.status = test->status;
  v.statusNote = test->statusNote;
  const std::string where = "rig test " + std::to_string(testId);
  if (!test->rigSetupId)
    return core::makeError(core::ErrorCode::NotFound, "the test has no rig set-up, so no plate geometry", where);
  auto setup = store.rigSetup(*test->rigSetupId);
  if (!setup) return setup.error();
  const auto geometry = nlohmann::json::parse(setup->axisMapJson, nullptr, false);
  const auto load = geometry.is_object() ? vec2(geometry.value("load_point_m", nlohmann::json())) : std::nullopt;
  if (!load || !geometry.contains("laser_points_m") || !geometry["laser_points_m"].is_array())
    return core::makeError(core::ErrorCode::Corrupt,
                           "the rig set-up has no plate geometry (load_point_m, laser_points_m)", where);
  v.loadPoint = *load;
  for (const auto& p : geometry["laser_points_m"]) {
    const auto q = vec2(p);
    if (!q) return core::makeError(core::ErrorCode::Corrupt, "a laser point is not [u, v]", where);
    v.laserPoints.push_back(*q);
  }
  if (geometry.contains("plate_outline_m") && geometry["plate_outline_m"].is_array())
    for (const auto& p : geometry["plate_outline_m"])
      if (const auto q = vec2(p)) v.plateOutline.push_back(*q);
  v.constrainedEnd = vec2(geometry.value("constrained_end_m", nlohmann::json()));
  v.bendAxis = axisOf(geometry, "bending_axis");
  v.torsAxis = axisOf(geometry, "torsion_axis");
  const auto params = nlohmann::json::parse(setup->parametersJson, nullptr, false);
  if (params.is_object() && params.contains("daq") && params["daq"].is_object() &&
      params["daq"].value("specimen", nlohmann::json()).is_string())
    v.specimenKey = params["daq"]["specimen"].get<std::string>();

  std::map<int, std::map<std::string, StoredQuantity>> bySteps;
  for (const auto& r : test->results) {
    const StoredQuantity q{r.value, r.uncertainty, r.unit};
    if (r.step)
      bySteps[*r.step][r.quantity] = q;
    else
      v.results[r.quantity] = q;
  }
  if (!v.dynamic) v.axis = storedAxis(v.results);
  for (const auto& [step, results] : bySteps) {
    const auto f = results.find("frequency");
    if (f == results.end()) continue;
    StiffnessTestView::Step s;
    s.step = step;
    s.frequencyHz = f->second.value;
    s.results = results;
    s.axis = storedAxis(results);
    const auto n = static_cast<Eigen::Index>(v.laserPoints.size());
    core::ComplexVector y(n);
    bool all = n > 0;
    for (Eigen::Index i = 0; i < n && all; ++i) {
      const std::string key = "laser_" + std::to_string(i + 1);
      const auto a = results.find(key + "_amplitude"), ph = results.find(key + "_phase");
      all = a != results.end() && ph != results.end();
      if (all) y(i) = std::polar(a->second.value, ph->second.value);
    }
    if (all) s.laserPhasors = y;
    v.steps.push_back(std::move(s));
  }
  return v;
}

std::optional<core::ComplexVector> laserPhasorsOf(const std::vector<Quantity>& results, std::size_t lasers) {
  core::ComplexVector y(static_cast<Eigen::Index>(lasers));
  for (std::size_t i = 0; i < lasers; ++i) {
    const std::string key = "laser_" + std::to_string(i + 1);
    const Quantity* a = findQuantity(results, key + "_amplitude");
    const Quantity* ph = findQuantity(results, key + "_phase");
    if (!a || !ph) return std::nullopt;
    y(static_cast<Eigen::Index>(i)) = std::polar(a->value, ph->value);
  }
  return y;
}

core::Result<std::vector<core::Vector2>> fittedSineLoop(const std::vector<core::Vector2>& laserPoints,
                                                        const core::Vector2& loadPoint, double forceAmplitude,
                                                        const core::ComplexVector& laserPhasors, int samples) {
  constexpr const char* kWhere = "fitted sine loop";
  if (static_cast<Eigen::Index>(laserPoints.size()) != laserPhasors.size())
    return core::makeError(
        core::ErrorCode::InvalidArgument,
        std::to_string(laserPoints.size()) + " laser points but " + std::to_string(laserPhasors.size()) + " phasors",
        kWhere);
  if (!(forceAmplitude > 0.0))
    return core::makeError(core::ErrorCode::InvalidArgument, "the force amplitude is not > 0", kWhere);
  std::vector<double> re, im;
  for (Eigen::Index i = 0; i < laserPhasors.size(); ++i) {
    re.push_back(laserPhasors(i).real());
    im.push_back(laserPhasors(i).imag());
  }
  auto pr = core::stiffness::fitPlane(laserPoints, re);
  if (!pr) return pr.error();
  auto pi = core::stiffness::fitPlane(laserPoints, im);
  if (!pi) return pi.error();
  const std::complex<double> x(pr->evaluate(loadPoint), pi->evaluate(loadPoint));
  constexpr double kTwoPi = 6.283185307179586;
  const int n = std::max(samples, 4);
  std::vector<core::Vector2> loop;
  loop.reserve(static_cast<std::size_t>(n) + 1);
  for (int k = 0; k <= n; ++k) {
    const double theta = kTwoPi * k / n;
    loop.emplace_back((x * std::polar(1.0, theta)).real(), forceAmplitude * std::cos(theta));
  }
  return loop;
}

}  // namespace mozzi::devices::rigtests
