#include "devices/sim/specimen_models.h"

#include <Eigen/LU>
#include <cmath>

namespace mozzi::devices::sim {

namespace {
constexpr double kPi = 3.14159265358979323846;

core::Dof dof(const char* text) { return *core::parseDof(text); }

// Plausible mass-normalised shapes for three DOFs of a reference plate
// (lateral at point 1, longitudinal at point 2, lateral at point 3): every
// mode is seen at the hammer point, none is a node, the matrix is well
// conditioned. Magnitudes ~ 1/sqrt(modal mass of a few kg).
core::Matrix plateShapes() {
  core::Matrix phi(3, 3);
  phi << 0.60, 0.30, 0.45,
         0.25, 0.65, 0.10,
         0.55, 0.20, -0.50;
  return phi;
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

ModalSpecimen forkAWithoutWheel() {
  return ModalSpecimen{"fork-a-without-wheel", "Fork A (enduro) without wheel", "thesis Table 11 (left)",
                       {38.6, 41.2, 67.1}, {0.022, 0.018, 0.036}, plateShapes(),
                       {dof("1:+Y"), dof("2:+X"), dof("3:+Y")}, 0};
}

ModalSpecimen forkAWithWheel() {
  return ModalSpecimen{"fork-a-with-wheel", "Fork A (enduro) with wheel", "thesis Table 11 (right)",
                       {22.3, 23.5, 67.2}, {0.024, 0.014, 0.059}, plateShapes(),
                       {dof("1:+Y"), dof("2:+X"), dof("3:+Y")}, 0};
}

ModalSpecimen frameAFrontConstrainedModal() {
  return ModalSpecimen{"frame-a-front-constrained", "Frame A, front-constrained", "thesis §2.1 (damping 2% assumed)",
                       {26.5, 56.8, 77.0}, {0.02, 0.02, 0.02}, plateShapes(),
                       {dof("1:+Z"), dof("2:+Y"), dof("3:+Z")}, 0};
}

std::vector<std::string> modalSpecimenKeys() { return {"fork-a-without-wheel", "fork-a-with-wheel", "frame-a-front-constrained"}; }

core::Result<ModalSpecimen> modalSpecimen(const std::string& key) {
  if (key == "fork-a-without-wheel") return forkAWithoutWheel();
  if (key == "fork-a-with-wheel") return forkAWithWheel();
  if (key == "frame-a-front-constrained") return frameAFrontConstrainedModal();
  return core::makeError(core::ErrorCode::NotFound, "no modal model for this specimen", "specimen " + key);
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

StaticSpecimen frameAFrontConstrainedStatic() {
  StaticSpecimen s;
  s.key = "frame-a-front-constrained";
  s.name = "Frame A, front-constrained";
  s.source = "thesis Table 3";
  s.lateralStiffness = 167e3;
  s.twistArm = 0.551;
  s.loadPoint = core::Vector2(0.0, 0.0);
  // Twist axis inclined 30 degrees in the plate plane (the layout of Fig. 15
  // is not tabulated; the inclination does not enter Table 3).
  s.axisDirection = core::Vector2(std::sin(kPi / 6), std::cos(kPi / 6));
  // Four lasers on a 200 mm x 150 mm reference plate around the load point.
  s.laserPoints = {core::Vector2(-0.10, -0.075), core::Vector2(0.10, -0.075), core::Vector2(0.10, 0.075), core::Vector2(-0.10, 0.075)};
  return s;
}

std::vector<std::string> staticSpecimenKeys() { return {"frame-a-front-constrained"}; }

core::Result<StaticSpecimen> staticSpecimen(const std::string& key) {
  if (key == "frame-a-front-constrained") return frameAFrontConstrainedStatic();
  return core::makeError(core::ErrorCode::NotFound, "no static model for this specimen", "specimen " + key);
}

}  // namespace mozzi::devices::sim
