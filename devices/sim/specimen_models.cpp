#include "devices/sim/specimen_models.h"

#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <optional>

#include "core/geometry/mesh_templates.h"
#include "devices/sim/mode_shapes.h"

namespace mozzi::devices::sim {

namespace {
constexpr double kPi = 3.14159265358979323846;

// Out-of-band completion modes (mode_shapes.h) at 2.5, 2.75 and 3 x the
// highest tabulated frequency, 5% damping: above the band an identification
// looks at, they give every DOF of the mesh a physical response.
constexpr double kCompletionFrequencyFactor = 2.5;
constexpr double kCompletionZeta = 0.05;
// Their modal mass is 10 times the tabulated modes' (they stand for stiffer,
// heavier higher modes; an accelerance grows with w^2, and they must not
// dominate the accelerometers' range at the driving point).
constexpr double kCompletionMassFactor = 10.0;
}  // namespace

core::Result<DofRow> ModalSpecimen::findDof(const core::Dof& dof) const {
  for (std::size_t j = 0; j < dofs.size(); ++j) {
    const core::Dof& d = dofs[j];
    if (d.node == dof.node && d.direction == dof.direction)
      return DofRow{static_cast<Eigen::Index>(j), d.negative == dof.negative ? 1.0 : -1.0};
  }
  return core::makeError(core::ErrorCode::NotFound,
                         "DOF " + core::formatDof(dof) + " is not on the mesh " + meshTemplate + " of the specimen",
                         "specimen " + key);
}

core::Result<DofRow> ModalSpecimen::findDof(const std::string& label) const {
  auto dof = core::parseDof(label);
  if (!dof)
    return core::makeError(core::ErrorCode::ParseError, "\"" + label + "\" is not a DOF label (e.g. 12:+Y)",
                           "specimen " + key);
  return findDof(*dof);
}

core::signal::LinearMdof ModalSpecimen::modalSystem() const {
  const Eigen::Index n = shapes.cols();
  core::signal::LinearMdof sys;
  sys.mass = core::Matrix::Identity(n, n);
  sys.stiffness = core::Matrix::Zero(n, n);
  sys.damping = core::Matrix::Zero(n, n);
  for (Eigen::Index r = 0; r < n; ++r) {
    const double w = 2.0 * kPi * frequencyHz[static_cast<std::size_t>(r)];
    sys.stiffness(r, r) = w * w;
    sys.damping(r, r) = 2.0 * zeta[static_cast<std::size_t>(r)] * w;
  }
  return sys;
}

DrivenSystem ModalSpecimen::drivenSystem(Eigen::Index drive, double sign) const {
  const Eigen::Index n = shapes.cols();
  DrivenSystem d;
  const core::Vector phi = sign * shapes.row(drive).transpose();  // phi_e
  const double norm = phi.norm();
  if (!(norm > 1e-12 * std::max(1.0, shapes.cwiseAbs().maxCoeff()))) {
    d.system = modalSystem();
    d.output = core::Matrix::Zero(shapes.rows(), n);
    d.excited = false;
    return d;
  }
  // T^-1 = [phi_e / |phi_e|^2, Q / |phi_e|], Q: orthonormal complement of phi_e.
  core::Matrix tInv(n, n);
  tInv.col(0) = phi / (norm * norm);
  if (n > 1) {
    Eigen::HouseholderQR<core::Matrix> qr(phi);
    const core::Matrix full = qr.householderQ();
    tInv.rightCols(n - 1) = full.rightCols(n - 1) / norm;
  }
  core::Vector w2(n), c(n);
  for (Eigen::Index r = 0; r < n; ++r) {
    const double w = 2.0 * kPi * frequencyHz[static_cast<std::size_t>(r)];
    w2(r) = w * w;
    c(r) = 2.0 * zeta[static_cast<std::size_t>(r)] * w;
  }
  d.system.mass = tInv.transpose() * tInv;
  d.system.stiffness = tInv.transpose() * w2.asDiagonal() * tInv;
  d.system.damping = tInv.transpose() * c.asDiagonal() * tInv;
  // Symmetrise the round-off of the products.
  d.system.mass = 0.5 * (d.system.mass + d.system.mass.transpose()).eval();
  d.system.stiffness = 0.5 * (d.system.stiffness + d.system.stiffness.transpose()).eval();
  d.system.damping = 0.5 * (d.system.damping + d.system.damping.transpose()).eval();
  d.output = shapes * tInv;
  return d;
}

std::complex<double> ModalSpecimen::receptance(Eigen::Index i, Eigen::Index j, double omega) const {
  std::complex<double> h(0.0, 0.0);
  for (Eigen::Index r = 0; r < shapes.cols(); ++r) {
    const double w = 2.0 * kPi * frequencyHz[static_cast<std::size_t>(r)];
    const std::complex<double> den(w * w - omega * omega, 2.0 * zeta[static_cast<std::size_t>(r)] * w * omega);
    h += shapes(i, r) * shapes(j, r) / den;
  }
  return h;
}

double ModalSpecimen::staticCompliance(Eigen::Index i, Eigen::Index j) const {
  double s = 0.0;
  for (Eigen::Index r = 0; r < shapes.cols(); ++r) {
    const double w = 2.0 * kPi * frequencyHz[static_cast<std::size_t>(r)];
    s += shapes(i, r) * shapes(j, r) / (w * w);
  }
  return s;
}

std::string meshTemplateKey(const std::string& specimenKey) {
  const SpecimenEntry* e = findSpecimen(specimenKey);
  return e ? templateKeyFor(*e) : std::string();
}

std::vector<std::string> modalSpecimenKeys() {
  return specimenKeys();
}

core::Result<ModalSpecimen> modalSpecimen(const std::string& key) {
  const SpecimenEntry* e = findSpecimen(key);
  if (!e) return core::makeError(core::ErrorCode::NotFound, "no such virtual specimen", "specimen " + key);
  if (e->modes.empty())
    return core::makeError(core::ErrorCode::InvalidArgument, "the specimen has no modal data", "specimen " + key);
  const std::string templateKey = templateKeyFor(*e);
  const auto* mesh = core::geometry::findMeshTemplate(templateKey);
  if (!mesh)
    return core::makeError(core::ErrorCode::NotFound, "no measurement mesh for this specimen", "specimen " + key);
  auto spatial = spatialShapes(*e, *mesh);
  if (!spatial) return spatial.error();

  ModalSpecimen m;
  m.key = e->key;
  m.name = e->name;
  m.source = e->modalSource;
  m.meshTemplate = templateKey;
  m.dofs = mesh->measurementDofs;
  m.excitedDof = spatial->drivingDof;
  m.modeShapes = spatial->descriptions;
  m.tabulatedModes = spatial->tabulatedModes;
  double fMax = 0.0;
  for (std::size_t r = 0; r < e->modes.size(); ++r) {
    m.frequencyHz.push_back(e->modes[r].frequencyHz);
    m.zeta.push_back(e->zeta(r));
    fMax = std::max(fMax, e->modes[r].frequencyHz);
  }
  const Eigen::Index n = spatial->shapes.cols();
  for (Eigen::Index r = static_cast<Eigen::Index>(e->modes.size()); r < n; ++r) {
    const double k = static_cast<double>(r - static_cast<Eigen::Index>(e->modes.size()));
    m.frequencyHz.push_back(kCompletionFrequencyFactor * fMax * (1.0 + 0.1 * k));
    m.zeta.push_back(kCompletionZeta);
  }
  const core::Matrix& v = spatial->shapes;
  const Eigen::Index drive = spatial->drivingDof;
  const Eigen::Index nTab = static_cast<Eigen::Index>(e->modes.size());
  core::Vector modalMass(n);
  if (e->statics) {
    // Equal modal masses m (10 m for the completion modes) with
    // sum_r v_er^2 / (m_r w_r^2) = 1 / k_lat.
    double s = 0.0;
    for (Eigen::Index r = 0; r < n; ++r) {
      const double w = 2.0 * kPi * m.frequencyHz[static_cast<std::size_t>(r)];
      s += v(drive, r) * v(drive, r) / (w * w) / (r < nTab ? 1.0 : kCompletionMassFactor);
    }
    for (Eigen::Index r = 0; r < n; ++r)
      modalMass(r) = e->statics->lateralStiffness * s * (r < nTab ? 1.0 : kCompletionMassFactor);
  } else {
    double largest = 0.0;
    for (Eigen::Index r = 0; r < nTab; ++r) {
      modalMass(r) = r < static_cast<Eigen::Index>(e->modalMass.size())
                         ? e->modalMass[static_cast<std::size_t>(r)]
                         : (e->modalMass.empty() ? 1.0 : e->modalMass.back());
      largest = std::max(largest, modalMass(r));
    }
    for (Eigen::Index r = nTab; r < n; ++r) modalMass(r) = kCompletionMassFactor * largest;
  }
  m.shapes.resize(v.rows(), n);
  for (Eigen::Index r = 0; r < n; ++r) m.shapes.col(r) = v.col(r) / std::sqrt(modalMass(r));
  return m;
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

double StaticSpecimen::displacementAt(const core::Vector2& p, const core::Vector2& q, double forceN) const {
  // displacementAt(q, 1) k_lat = signedArm(q) / a_tw: 1 at the load point.
  return displacementAt(p, forceN) * displacementAt(q, 1.0) * lateralStiffness;
}

std::complex<double> StaticSpecimen::receptance(const core::Vector2& p, const core::Vector2& q,
                                                double frequencyHz) const {
  if (modes.empty()) return displacementAt(p, q, 1.0);
  std::complex<double> w = 0.0;
  for (const auto& m : modes) {
    auto armOf = [&](const core::Vector2& x) {
      return (x.x() - m.point.x()) * m.direction.y() - (x.y() - m.point.y()) * m.direction.x();
    };
    const double r = frequencyHz / m.frequencyHz;
    w += m.rotationPerN * (armOf(q) / m.arm) * armOf(p) / std::complex<double>(1.0 - r * r, 2.0 * m.zeta * r);
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
