#include "devices/sim/specimen_models.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <optional>

namespace mozzi::devices::sim {

namespace {
constexpr double kPi = 3.14159265358979323846;

// Out-of-band completion modes: a specimen with fewer tabulated modes than
// the three accelerometers of the hammer station gets stiff modes at 2.5 x
// its highest frequency (5% damping) so every DOF has a physical response;
// they lie above the band an identification looks at.
constexpr double kCompletionFrequencyFactor = 2.5;
constexpr double kCompletionZeta = 0.05;
constexpr Eigen::Index kMinDofs = 3;

// Generic shapes on n DOFs: entries of magnitude 0.4..1 with mixed signs from a
// fixed linear congruential sequence (the same on every platform), columns of
// unit length; the first well-conditioned draw is kept, so every mode is seen
// at every DOF and no DOF is a node.
core::Matrix genericShapes(Eigen::Index n) {
  std::uint64_t state = 0x2545F4914F6CDD1DULL + static_cast<std::uint64_t>(n);
  auto next = [&state] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;  // [0, 1)
  };
  core::Matrix v(n, n);
  for (int attempt = 0; attempt < 1000; ++attempt) {
    for (Eigen::Index r = 0; r < n; ++r)
      for (Eigen::Index j = 0; j < n; ++j) v(j, r) = (next() < 0.5 ? -1.0 : 1.0) * (0.4 + 0.6 * next());
    for (Eigen::Index r = 0; r < n; ++r) {
      if (v(0, r) < 0) v.col(r) *= -1.0;  // positive at the driving point
      v.col(r).normalize();
    }
    Eigen::JacobiSVD<core::Matrix> svd(v);
    const double cond = svd.singularValues()(0) / svd.singularValues()(n - 1);
    if (cond < 8.0) break;
  }
  return v;
}

core::Dof meshDof(Eigen::Index j) {
  static const char* dirs[] = {"+Z", "+Y", "+X"};
  return *core::parseDof(std::to_string(j + 1) + ":" + dirs[j % 3]);
}
}  // namespace

core::signal::LinearMdof ModalSpecimen::toMdof() const {
  const core::Matrix inv = shapes.inverse();
  const Eigen::Index n = static_cast<Eigen::Index>(frequencyHz.size());
  core::Vector w2(n), c(n);
  for (Eigen::Index r = 0; r < n; ++r) {
    const double w = 2.0 * kPi * frequencyHz[static_cast<std::size_t>(r)];
    w2(r) = w * w;
    c(r) = 2.0 * zeta[static_cast<std::size_t>(r)] * w;
  }
  core::signal::LinearMdof sys;
  sys.mass = inv.transpose() * inv;
  sys.stiffness = inv.transpose() * w2.asDiagonal() * inv;
  sys.damping = inv.transpose() * c.asDiagonal() * inv;
  // Symmetrise the round-off of the products.
  sys.mass = 0.5 * (sys.mass + sys.mass.transpose()).eval();
  sys.stiffness = 0.5 * (sys.stiffness + sys.stiffness.transpose()).eval();
  sys.damping = 0.5 * (sys.damping + sys.damping.transpose()).eval();
  return sys;
}

std::vector<std::string> modalSpecimenKeys() {
  return specimenKeys();
}

core::Result<ModalSpecimen> modalSpecimen(const std::string& key) {
  const SpecimenEntry* e = findSpecimen(key);
  if (!e) return core::makeError(core::ErrorCode::NotFound, "no such virtual specimen", "specimen " + key);
  if (e->modes.empty())
    return core::makeError(core::ErrorCode::InvalidArgument, "the specimen has no modal data", "specimen " + key);
  ModalSpecimen m;
  m.key = e->key;
  m.name = e->name;
  m.source = e->modalSource;
  double fMax = 0.0;
  for (std::size_t r = 0; r < e->modes.size(); ++r) {
    m.frequencyHz.push_back(e->modes[r].frequencyHz);
    m.zeta.push_back(e->zeta(r));
    fMax = std::max(fMax, e->modes[r].frequencyHz);
  }
  const Eigen::Index n = std::max<Eigen::Index>(kMinDofs, static_cast<Eigen::Index>(e->modes.size()));
  for (Eigen::Index r = static_cast<Eigen::Index>(e->modes.size()); r < n; ++r) {
    m.frequencyHz.push_back(kCompletionFrequencyFactor * fMax * (1.0 + 0.1 * static_cast<double>(r)));
    m.zeta.push_back(kCompletionZeta);
  }
  const core::Matrix v = genericShapes(n);
  core::Vector modalMass(n);
  if (e->statics) {
    // Equal modal masses with sum_r v_0r^2 / (m w_r^2) = 1 / k_lat.
    double s = 0.0;
    for (Eigen::Index r = 0; r < n; ++r) {
      const double w = 2.0 * kPi * m.frequencyHz[static_cast<std::size_t>(r)];
      s += v(0, r) * v(0, r) / (w * w);
    }
    modalMass.setConstant(e->statics->lateralStiffness * s);
  } else {
    const double fallback = e->modalMass.empty() ? 1.0 : e->modalMass.back();
    for (Eigen::Index r = 0; r < n; ++r)
      modalMass(r) =
          r < static_cast<Eigen::Index>(e->modalMass.size()) ? e->modalMass[static_cast<std::size_t>(r)] : fallback;
  }
  m.shapes.resize(n, n);
  for (Eigen::Index r = 0; r < n; ++r) m.shapes.col(r) = v.col(r) / std::sqrt(modalMass(r));
  for (Eigen::Index j = 0; j < n; ++j) m.dofs.push_back(meshDof(j));
  m.excitedDof = 0;
  return m;
}

double ModalSpecimen::staticCompliance(Eigen::Index i, Eigen::Index j) const {
  double s = 0.0;
  for (Eigen::Index r = 0; r < shapes.cols(); ++r) {
    const double w = 2.0 * kPi * frequencyHz[static_cast<std::size_t>(r)];
    s += shapes(i, r) * shapes(j, r) / (w * w);
  }
  return s;
}

double StaticSpecimen::displacementAt(const core::Vector2& p, double forceN) const {
  // Axis through the point at distance a_tw from the load point, normal to the
  // direction; signedArm(p) = (p - q) x d as in core/stiffness/plate_motion.h.
  const core::Vector2 normal(axisDirection.y(), -axisDirection.x());  // arm(load) = +a_tw
  const core::Vector2 q = loadPoint - twistArm * normal;
  const double arm = (p.x() - q.x()) * axisDirection.y() - (p.y() - q.y()) * axisDirection.x();
  const double rotation = forceN / (lateralStiffness * twistArm);  // [rad], eq. 29-30
  return rotation * arm;
}

std::complex<double> StaticSpecimen::receptance(const core::Vector2& p, double frequencyHz) const {
  if (modes.empty()) return displacementAt(p, 1.0);
  std::complex<double> w = 0.0;
  for (const auto& m : modes) {
    const double arm = (p.x() - m.point.x()) * m.direction.y() - (p.y() - m.point.y()) * m.direction.x();
    const double r = frequencyHz / m.frequencyHz;
    w += m.rotationPerN * arm / std::complex<double>(1.0 - r * r, 2.0 * m.zeta * r);
  }
  return w;
}

namespace {

core::Vector2 directionAt(double beta) {  // from the v axis towards u
  return core::Vector2(std::sin(beta), std::cos(beta));
}

PlateMode plateMode(const char* name, double beta, double arm, double rotationPerN, const CatalogueMode& m,
                    double zeta) {
  PlateMode out;
  out.name = name;
  out.direction = directionAt(beta);
  const core::Vector2 normal(out.direction.y(), -out.direction.x());  // signedArm(load point) = +arm
  out.point = -arm * normal;
  out.arm = arm;
  out.rotationPerN = rotationPerN;
  out.frequencyHz = m.frequencyHz;
  out.zeta = zeta;
  return out;
}

// The modes of the specimen's modal table that stand for bending and torsion.
std::optional<std::size_t> findMode(const SpecimenEntry& e, std::initializer_list<const char*> shapes) {
  for (std::size_t r = 0; r < e.modes.size(); ++r)
    for (const char* s : shapes)
      if (e.modes[r].shape == s) return r;
  return std::nullopt;
}

void addPlateModes(const SpecimenEntry& e, StaticSpecimen& s) {
  const StaticProperties& st = *e.statics;
  const double beta = std::atan2(s.axisDirection.x(), s.axisDirection.y());
  const double thetaS = 1.0 / (st.lateralStiffness * st.twistArm);  // [rad/N]
  const auto bend = findMode(e, {"Lateral", "Bending"});
  const auto tors = findMode(e, {"Torsional", "Wheel"});
  if (st.bendArm > 0 && st.torsArm > 0 && st.bendStiffness > 0 && st.torsStiffness > 0 && bend && tors) {
    const double thetaB = st.bendArm / st.bendStiffness, thetaT = st.torsArm / st.torsStiffness;
    // Angles of the triangle theta_s = theta_b + theta_t (law of cosines,
    // clamped where the printed numbers do not close it).
    auto angle = [](double a, double b, double opposite) {
      return std::acos(std::clamp((a * a + b * b - opposite * opposite) / (2 * a * b), -1.0, 1.0));
    };
    const double betaB = beta + angle(thetaS, thetaB, thetaT);
    const double betaT = beta - angle(thetaS, thetaT, thetaB);
    // Magnitudes that sum to theta_s exactly along these directions (the
    // printed ones where the triangle closes).
    Eigen::Matrix2d d;
    d.col(0) = directionAt(betaB);
    d.col(1) = directionAt(betaT);
    const core::Vector2 th = d.fullPivLu().solve(thetaS * s.axisDirection);
    // Eq. 22 at the load point: theta_b a_b + theta_t a_t = theta_s a_tw.
    const double armB = (thetaS * st.twistArm - th(1) * st.torsArm) / th(0);
    s.modes.push_back(plateMode("bending", betaB, armB, th(0), e.modes[*bend], e.zeta(*bend)));
    s.modes.push_back(plateMode("torsion", betaT, st.torsArm, th(1), e.modes[*tors], e.zeta(*tors)));
  } else if (!e.modes.empty()) {
    s.modes.push_back(plateMode("lateral", beta, st.twistArm, thetaS, e.modes[0], e.zeta(0)));
  }
}

}  // namespace

core::Result<StaticSpecimen> staticSpecimen(const std::string& key) {
  const SpecimenEntry* e = findSpecimen(key);
  if (!e) return core::makeError(core::ErrorCode::NotFound, "no such virtual specimen", "specimen " + key);
  if (!e->statics)
    return core::makeError(core::ErrorCode::NotFound, "the thesis has no static test of this specimen",
                           "specimen " + key);
  StaticSpecimen s;
  s.key = e->key;
  s.name = e->name;
  s.source = e->staticSource;
  s.lateralStiffness = e->statics->lateralStiffness;
  s.twistArm = e->statics->twistArm;
  s.testForceN = e->statics->testForceN;
  s.loadPoint = core::Vector2(0.0, 0.0);
  const double beta = e->statics->inclinationDeg * kPi / 180.0;  // from the v axis towards u
  s.axisDirection = core::Vector2(std::sin(beta), std::cos(beta));
  s.laserPoints = {core::Vector2(-0.10, -0.075), core::Vector2(0.10, -0.075), core::Vector2(0.10, 0.075),
                   core::Vector2(-0.10, 0.075)};
  addPlateModes(*e, s);
  return s;
}

}  // namespace mozzi::devices::sim
