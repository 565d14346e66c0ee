#include "devices/sim/mode_shapes.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>

namespace mozzi::devices::sim {

namespace {

using core::Vector3;

constexpr double kPi = 3.14159265358979323846;

// A clamped node moves this fraction of a free tip (the jaws are not rigid).
constexpr double kClampCompliance = 0.03;
// Principal bending axes of the fork legs and blades inclined by 15 degrees
// to the measurement axes (assumed): the lateral and longitudinal modes each
// carry a sin(15 deg) = 26% component in the other direction, as the thesis's
// FRFs show (§4.1: the lateral excitation of fork A shows both the lateral and
// the longitudinal peak in y and z).
constexpr double kBendingAxisTilt = 15.0 * kPi / 180.0;
// Frame A's longitudinal mode (56.8 Hz, "y axis, not displayed", §2.1) was
// identified from lateral hits at the pivot: 25% lateral participation assumed.
constexpr double kFrameLongitudinalLateral = 0.25;
// Fork legs and blades react to the wheel's own mode with 5% of its motion
// ("the points of the fork ... are almost fixed", §4.1).
constexpr double kWheelModeReaction = 0.05;

using Field = std::function<Vector3(const Vector3& p, int label)>;

// Static cantilever deflection under a tip load, psi(1) = 1, psi'(1) = 3/2;
// beyond the tip a rigid extension.
double psi(double xi) {
  if (xi <= 0.0) return 0.0;
  if (xi <= 1.0) return 0.5 * xi * xi * (3.0 - xi);
  return 1.0 + 1.5 * (xi - 1.0);
}
constexpr double kPsiTipSlope = 1.5;

// Motion of a point that is clamp-compliance plus (1 - c) of the free motion.
double clampWeight(double s) {
  return kClampCompliance + (1.0 - kClampCompliance) * s;
}

double clamp01(double xi) {
  return std::min(1.0, std::max(0.0, xi));
}

Vector3 unitX() {
  return Vector3::UnitX();
}
Vector3 unitY() {
  return Vector3::UnitY();
}
Vector3 unitZ() {
  return Vector3::UnitZ();
}

bool inGroup(const core::geometry::MeshTemplate& t, const std::string& group, int label) {
  const auto* g = t.group(group);
  return g && std::find(g->nodes.begin(), g->nodes.end(), label) != g->nodes.end();
}

struct ModeField {
  Field field;
  std::string description;
};

// What a specimen's shapes are built from.
struct Layout {
  std::vector<ModeField> modes;  // one per catalogue mode, in catalogue order
  Field clamp;                   // weight of the completion modes (1 = free)
  core::Dof drive;
  bool completion = true;
};

core::Dof lateralAt(int node) {
  return core::Dof{node, core::Direction::Z, false};
}

// Bending of a cantilever along -x from the clamp at x = xc (forks): the legs
// move e psi(xi), a wheel hung at the axle (origin) moves rigidly with the tip:
// u = e psi(1) + omega x p, omega = -(psi'(1) / L) (x_hat x e).
Field forkBending(const core::geometry::MeshTemplate& t, double xc, const Vector3& e) {
  const double length = xc;
  return [&t, xc, length, e](const Vector3& p, int label) -> Vector3 {
    if (inGroup(t, "wheel", label)) {
      const Vector3 omega = -(kPsiTipSlope / length) * unitX().cross(e);
      const Vector3 rigid = e + omega.cross(p);
      return kClampCompliance * e + (1.0 - kClampCompliance) * rigid;
    }
    return e * clampWeight(psi((xc - p.x()) / length));
  };
}

// Rotation theta(xi) about the axis through `a` along `d`.
Field twist(const Vector3& a, const Vector3& d, std::function<double(const Vector3&, int)> theta) {
  const Vector3 dn = d.normalized();
  return [a, dn, theta](const Vector3& p, int label) -> Vector3 { return theta(p, label) * dn.cross(p - a); };
}

// ---------------------------------------------------------------- frames (§2.1, §2.2)

Layout frameLayout(const SpecimenEntry& e, const core::geometry::MeshTemplate& t) {
  Layout l;
  const bool rear = e.key.find("rear-constrained") != std::string::npos;
  const bool frameB = e.key.rfind("frame-b", 0) == 0;
  // Steering head about 0.66 m ahead of the pivot on every frame template.
  const double yHead = 0.66, length = 0.66;
  // Distance from the clamp over the head-to-pivot length. Rear-constrained,
  // the bending runs forward from the pivot (the tail behind it hardly takes
  // part), while torsion twists the tail too (frame B: "the lower part of the
  // frame and the tail move in opposition", §2.1).
  auto xi = [rear, yHead, length](const Vector3& p) {
    return rear ? std::max(0.0, p.y()) / length : (yHead - p.y()) / length;
  };
  auto xiTwist = [rear, yHead, length](const Vector3& p) {
    return rear ? std::abs(p.y()) / length : (yHead - p.y()) / length;
  };
  // Hammer on the swing-arm pivot (front-constrained) or the steering head
  // (rear-constrained), §2.1; lateral, as the static force (§2.1).
  const auto* pivot = t.group("swing-arm pivot");
  l.drive = lateralAt(rear ? 2 : (pivot ? pivot->nodes.front() : 7));
  // Torsion axes: frames A and C twist about a longitudinal axis half-way
  // between the upper rails and the cradle ("the points of the upper part and
  // the points of the lower part of the frame move in opposition", §2.1);
  // frame B about an axis along its thick upper tube, descending to the rear,
  // so that the tube is almost motionless while the lower part and the tail
  // move in opposition (§2.1).
  Vector3 axisPoint(0.15, 0.0, 0.0), axisDir = unitY();
  if (frameB) {
    axisPoint = Vector3(0.50, 0.60, 0.0);
    axisDir = Vector3(-0.2, -0.6, 0.0);
  }
  l.clamp = [xi](const Vector3& p, int) { return Vector3::Constant(clampWeight(clamp01(xi(p)))); };
  for (const auto& m : e.modes) {
    if (m.shape == "Lateral") {
      l.modes.push_back({[xi](const Vector3& p, int) -> Vector3 { return unitZ() * clampWeight(psi(xi(p))); },
                         "lateral bending (z), largest at the loaded end"});
    } else if (m.shape == "Longitudinal") {
      l.modes.push_back({[xi](const Vector3& p, int) -> Vector3 {
                           return (unitY() + kFrameLongitudinalLateral * unitZ()) * clampWeight(psi(xi(p)));
                         },
                         "longitudinal (y) bending with 25% lateral"});
    } else {
      l.modes.push_back(
          {twist(axisPoint, axisDir, [xiTwist](const Vector3& p, int) { return clampWeight(clamp01(xiTwist(p))); }),
           frameB ? "torsion about the upper tube: lower part and tail in opposition"
                  : "torsion: upper and lower parts in opposition"});
    }
  }
  return l;
}

// ---------------------------------------------------------------- swing-arms (chapter 3)

Layout swingArmLayout(const SpecimenEntry& e, const core::geometry::MeshTemplate& t) {
  Layout l;
  const auto* axle = t.group("axle");
  double yAxle = 0.0;
  for (int n : axle->nodes) yAxle = std::max(yAxle, t.node(n)->position.y());
  // Hammer at the rear hub (point 100, §3.1), between the axle nodes: the
  // left axle node (the lower edge on swing-arm B), lateral.
  l.drive = lateralAt(t.key == "swing-arm-6" ? 5 : 11);
  // Torsion axis along the stems, at the tabulated torsion arm above the hub
  // (Tables 7, 9: 0.025 m, 0.026 m): the stems move vertically in opposition
  // and the hub laterally by a_tors theta.
  const double torsArm = e.statics ? e.statics->torsArm : 0.025;
  auto xi = [yAxle](const Vector3& p) { return p.y() / yAxle; };
  l.clamp = [xi](const Vector3& p, int) { return Vector3::Constant(clampWeight(clamp01(xi(p)))); };
  for (const auto& m : e.modes) {
    if (m.shape == "Bending")
      l.modes.push_back({[xi](const Vector3& p, int) -> Vector3 { return unitZ() * clampWeight(psi(xi(p))); },
                         "lateral bending (z), the rear hub moves most"});
    else
      l.modes.push_back({twist(Vector3(torsArm, 0.0, 0.0), unitY(),
                               [xi](const Vector3& p, int) { return clampWeight(clamp01(xi(p))); }),
                         "torsion about the stems' axis: left and right stems in opposition"});
  }
  return l;
}

// ---------------------------------------------------------------- forks (chapter 4, §6.2, §6.3)

struct ForkGeometry {
  double crownX;       // clamp (lower triple clamp / crown) height above the axle
  Vector3 steerPoint;  // a point of the steering axis
  int driveWithout;    // fork-foot / dropout node
  int driveWithWheel;  // wheel node hit
};

Layout forkLayout(const SpecimenEntry& e, const core::geometry::MeshTemplate& t, const ForkGeometry& g) {
  Layout l;
  const bool wheel = t.group("wheel") != nullptr;
  l.drive = lateralAt(wheel ? g.driveWithWheel : g.driveWithout);
  const Vector3 eLat = std::cos(kBendingAxisTilt) * unitZ() + std::sin(kBendingAxisTilt) * unitY();
  const Vector3 eLon = std::cos(kBendingAxisTilt) * unitY() - std::sin(kBendingAxisTilt) * unitZ();
  const double xc = g.crownX;
  auto xi = [xc](const Vector3& p) { return (xc - p.x()) / xc; };
  l.clamp = [&t, xi](const Vector3& p, int label) {
    return Vector3::Constant(inGroup(t, "wheel", label) ? 1.0 : clampWeight(clamp01(xi(p))));
  };
  const Vector3 steer = g.steerPoint;
  for (const auto& m : e.modes) {
    const std::string& s = m.shape;
    if (s == "Lateral") {
      l.modes.push_back({forkBending(t, xc, eLat), wheel ? "lateral bending (z), the wheel follows rigidly"
                                                         : "lateral bending (z), legs in phase"});
    } else if (s == "Longitudinal") {
      l.modes.push_back({forkBending(t, xc, eLon), wheel ? "longitudinal bending (y), the wheel follows rigidly"
                                                         : "longitudinal bending (y), legs in phase"});
    } else if (s == "Wheel" || s == "Wheel diametrical") {
      // The wheel rotates about its horizontal diameter (the y axis through
      // the axle), §4.1 and §6.2; the fork reacts a little.
      l.modes.push_back({[&t, xi](const Vector3& p, int label) -> Vector3 {
                           if (inGroup(t, "wheel", label)) return unitY().cross(p);
                           return -kWheelModeReaction * unitZ() * psi(clamp01(xi(p)));
                         },
                         "wheel rotating about its horizontal diameter, fork almost still"});
    } else {
      // Torsion about the steering axis: the legs/blades move in opposition in
      // y (and laterally by the offset of the axis). "First torsional" of the
      // bicycle forks is localised at the lower tips (§6.3: theta ~ xi^3),
      // "Second torsional" involves the whole blade (theta ~ sin(pi xi / 2));
      // with the wheel, the wheel turns rigidly with the blade tips (§6.2).
      std::function<double(double)> profile = [](double x) { return x; };
      std::string what = "torsion about the steering axis: legs in opposition (y)";
      if (s == "First torsional") {
        profile = [](double x) { return x * x * x; };
        what = "first torsion about the steering axis, localised at the tips: blades in opposition (y)";
      } else if (s == "Second torsional") {
        profile = [](double x) { return std::sin(0.5 * kPi * x); };
        what = "second torsion about the steering axis, the whole blade: blades in opposition (y)";
      } else if (wheel) {
        what = "torsion about the steering axis, the wheel turning rigidly with the blades";
      }
      l.modes.push_back({twist(steer, unitX(),
                               [&t, xi, profile](const Vector3& p, int label) {
                                 return inGroup(t, "wheel", label) ? 1.0 : clampWeight(profile(clamp01(xi(p))));
                               }),
                         what});
    }
  }
  return l;
}

// ---------------------------------------------------------------- tyres (§5.2, §5.3)

Layout tyreLayout(const SpecimenEntry& e) {
  Layout l;
  l.drive = lateralAt(100);  // the accelerometer at point 100, §5.2
  l.completion = false;      // lateral DOFs only; the k = 0 mode moves them all
  for (const auto& m : e.modes) {
    int k = 0;
    if (m.shape == "camber") k = 1;
    if (m.shape == "C-shaped") k = 2;
    if (m.shape == "S-shaped") k = 3;
    l.modes.push_back({[k](const Vector3& p, int) -> Vector3 {
                         const double phi = std::atan2(p.y(), -p.x());  // from the lowest point
                         return unitZ() * std::cos(k * phi);
                       },
                       "ring mode k = " + std::to_string(k) + ": u_z = cos(" + std::to_string(k) + " phi)"});
  }
  return l;
}

// ---------------------------------------------------------------- bicycles (§6.1)

// First free-free bending mode of a uniform beam on [0, 1] (beta L = 4.730),
// nodes at 0.224 and 0.776, ends at 2 (scaled later).
double freeFree1(double s) {
  const double b = 4.730040745, sigma = 0.982502215;
  const double x = b * s;
  return std::cosh(x) + std::cos(x) - sigma * (std::sinh(x) + std::sin(x));
}

Layout bicycleLayout(const SpecimenEntry& e, const core::geometry::MeshTemplate& t) {
  Layout l;
  l.drive = lateralAt(100);                                       // out-of-plane hit on the rear hub, point 100 (§6.1)
  l.clamp = [](const Vector3&, int) { return Vector3::Ones(); };  // hung on soft ropes
  auto isFork = [&t](int label) { return inGroup(t, "fork", label); };
  // Blade coordinate from the crown (0) to the dropout (1).
  auto bladeXi = [](const Vector3& p) { return clamp01((0.28 - p.x()) / 0.28); };
  const Vector3 steerPoint(0.0, 0.953, 0.0), steerDir(0.951, -0.309, 0.0);
  const double headY = 0.83;  // head tube
  for (const auto& m : e.modes) {
    const std::string& s = m.shape;
    Field f;
    std::string what;
    if (s == "Tire dominated - Yaw") {
      // Rigid yaw of the rear frame about a vertical axis mid-frame and a steer
      // rotation of the front frame about the steering axis.
      f = [isFork, steerPoint, steerDir](const Vector3& p, int label) -> Vector3 {
        Vector3 u = unitX().cross(p - Vector3(0.0, 0.45, 0.0));
        if (isFork(label)) u += 1.5 * steerDir.normalized().cross(p - steerPoint);
        return u;
      };
      what = "rigid yaw of the rear frame and steer of the front frame";
    } else if (s == "Tire dominated - Roll") {
      f = [](const Vector3& p, int) -> Vector3 { return unitY().cross(p - Vector3(0.45, 0.0, 0.0)); };
      what = "rigid roll about a nodal line near the top tube";
    } else if (s == "Torsion") {
      // Fork tips in phase with the crank set, in opposition with the stays.
      f = [isFork, bladeXi](const Vector3& p, int label) -> Vector3 {
        const double theta = (p.y() - 0.3) / 0.7;
        double uz = theta * (0.6 - p.x());
        if (isFork(label)) uz += 0.5 * psi(bladeXi(p));
        return unitZ() * uz;
      };
      what = "frame torsion with fork lateral bending: fork tips with the crank set, against the stays";
    } else if (s == "First bending") {
      f = [headY](const Vector3& p, int) -> Vector3 {
        return unitZ() * freeFree1(std::min(1.0, std::max(0.0, p.y() / headY)));
      };
      what = "first free-free lateral bending: antinodes at rear hub, seat tube, head tube";
    } else if (s == "Fork lateral") {
      f = [isFork, bladeXi](const Vector3& p, int label) -> Vector3 {
        if (isFork(label)) return unitZ() * psi(bladeXi(p));
        return unitZ() * (p.y() - 0.55);  // head and saddle in opposition
      };
      what = "fork lateral bending, head and saddle in opposition";
    } else if (s == "Second bending") {
      f = [isFork](const Vector3& p, int label) -> Vector3 {
        if (isFork(label) || p.y() >= 0.8) return Vector3::Zero();
        return unitZ() * (1.0 - p.y() / 0.8) * std::cos(kPi * p.y() / 0.41);
      };
      what = "second bending: rear hub against the crank set, fork and head still";
    } else {
      // The rear triangle sways: the seat tube most at the top, the stays
      // (and the hub where they meet) with it, the front still.
      f = [isFork](const Vector3& p, int label) -> Vector3 {
        if (isFork(label) || p.y() >= 0.6) return Vector3::Zero();
        return unitZ() * (0.5 + 0.5 * std::sin(kPi * (p.x() + 0.07) / 1.2)) * (1.0 - p.y() / 0.6);
      };
      what = "seat tube and rear triangle (stays) lateral";
    }
    l.modes.push_back({f, what});
  }
  return l;
}

}  // namespace

std::string templateKeyFor(const SpecimenEntry& e) {
  const std::string& k = e.key;
  auto starts = [&k](const char* p) { return k.rfind(p, 0) == 0; };
  auto has = [&k](const char* p) { return k.find(p) != std::string::npos; };
  if (starts("frame-a")) return "motorcycle-frame-20";
  if (starts("frame-b")) return "motorcycle-frame-26";
  if (k == "frame-c-with-engine") return "motorcycle-frame-22-engine-10";
  if (starts("frame-c")) return "motorcycle-frame-22";
  if (k == "swing-arm-a") return "swing-arm-6";
  if (k == "swing-arm-b") return "swing-arm-18";
  if (starts("fork-")) return has("with-wheel") ? "motorcycle-fork-10-wheel-8" : "motorcycle-fork-10";
  if (e.kind == "tyre") return "tyre-6";
  if (starts("bicycle-fork-")) return has("with-wheel") ? "bicycle-fork-9-wheel-8" : "bicycle-fork-9";
  if (e.kind == "bicycle") return "bicycle-9-12";
  return "";
}

core::Result<SpatialShapes> spatialShapes(const SpecimenEntry& e, const core::geometry::MeshTemplate& t) {
  const std::string where = "specimen " + e.key + " on mesh " + t.key;
  Layout l;
  if (e.kind == "frame")
    l = frameLayout(e, t);
  else if (e.kind == "swing-arm")
    l = swingArmLayout(e, t);
  else if (e.kind == "fork")
    l = forkLayout(e, t, ForkGeometry{0.66, Vector3(0.0, -0.03, 0.0), 9, 11});
  else if (e.kind == "bicycle-fork")
    l = forkLayout(e, t, ForkGeometry{0.37, Vector3(0.0, -0.045, 0.0), 4, 11});
  else if (e.kind == "tyre")
    l = tyreLayout(e);
  else if (e.kind == "bicycle")
    l = bicycleLayout(e, t);
  else
    return core::makeError(core::ErrorCode::Unsupported, "no mode shapes for this kind of specimen", where);

  const auto& dofs = t.measurementDofs;
  const Eigen::Index nd = static_cast<Eigen::Index>(dofs.size());
  SpatialShapes out;
  out.drivingDof = -1;
  for (Eigen::Index j = 0; j < nd; ++j)
    if (dofs[static_cast<std::size_t>(j)] == l.drive) out.drivingDof = j;
  if (out.drivingDof < 0)
    return core::makeError(core::ErrorCode::InvalidArgument,
                           "the driving point " + core::formatDof(l.drive) + " is not a DOF of the mesh", where);

  std::vector<Field> fields;
  for (const auto& m : l.modes) {
    fields.push_back(m.field);
    out.descriptions.push_back(m.description);
  }
  out.tabulatedModes = l.modes.size();
  if (l.completion) {
    // Completion modes: every DOF along one axis, weighted by the clamp and
    // by 1 + 0.5 cos(2 pi s) along the mesh's longest extent s, so they are
    // independent of the bending modes and never vanish on a free node.
    Vector3 lo = Vector3::Constant(1e9), hi = Vector3::Constant(-1e9);
    for (const auto& n : t.mesh.nodes) {
      lo = lo.cwiseMin(n.position);
      hi = hi.cwiseMax(n.position);
    }
    Eigen::Index axis = 0;
    (hi - lo).maxCoeff(&axis);
    const double span = std::max(1e-6, hi(axis) - lo(axis));
    const double start = lo(axis);
    const Field clamp = l.clamp;
    const char* names[] = {"x", "y", "z"};
    for (int c = 0; c < 3; ++c) {
      const Vector3 dir = Vector3::Unit(c);
      fields.push_back([clamp, dir, axis, span, start](const Vector3& p, int label) -> Vector3 {
        const double along = (p(axis) - start) / span;
        return dir * clamp(p, label).x() * (1.0 + 0.5 * std::cos(2.0 * kPi * along));
      });
      out.descriptions.push_back(std::string("out-of-band completion mode (") + names[c] + ")");
    }
  }

  const Eigen::Index nm = static_cast<Eigen::Index>(fields.size());
  out.shapes.resize(nd, nm);
  for (Eigen::Index r = 0; r < nm; ++r) {
    for (Eigen::Index j = 0; j < nd; ++j) {
      const core::Dof& d = dofs[static_cast<std::size_t>(j)];
      const auto* node = t.node(d.node);
      const Vector3 u = fields[static_cast<std::size_t>(r)](node->position, d.node);
      const int axis = static_cast<int>(d.direction) - 1;  // translations only in the templates
      out.shapes(j, r) = (d.negative ? -1.0 : 1.0) * u(axis);
    }
    const double big = out.shapes.col(r).cwiseAbs().maxCoeff();
    if (!(big > 0.0))
      return core::makeError(core::ErrorCode::NumericalFailure,
                             "mode " + std::to_string(r + 1) + " (" + out.descriptions[static_cast<std::size_t>(r)] +
                                 ") does not move the mesh",
                             where);
    out.shapes.col(r) /= big;
    if (out.shapes(out.drivingDof, r) < 0.0) out.shapes.col(r) *= -1.0;
  }
  return out;
}

}  // namespace mozzi::devices::sim
