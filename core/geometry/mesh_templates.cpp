#include "core/geometry/mesh_templates.h"

#include <cmath>
#include <initializer_list>

namespace mozzi::core::geometry {

const NodeGroup* MeshTemplate::group(const std::string& groupName) const {
  for (const auto& g : groups)
    if (g.name == groupName) return &g;
  return nullptr;
}

const io::StoredNode* MeshTemplate::node(int label) const {
  for (const auto& n : mesh.nodes)
    if (n.label == label) return &n;
  return nullptr;
}

namespace {

constexpr double kPi = 3.14159265358979323846;

// Builds one template: nodes, trace lines, faces, groups and DOFs.
class Builder {
 public:
  Builder(std::string key, std::string name, std::string source, std::string notes) {
    t_.key = std::move(key);
    t_.name = std::move(name);
    t_.source = std::move(source);
    t_.notes = std::move(notes);
    t_.approximateCoordinates = true;
  }
  // A variant of `base` (the frame with its engine, the fork with its wheel):
  // its nodes, lines, faces and groups, to which the variant adds, and its
  // notes followed by `moreNotes`. The DOFs come from take().
  Builder(const MeshTemplate& base, std::string key, std::string name, std::string source, const std::string& moreNotes)
      : Builder(std::move(key), std::move(name), std::move(source), base.notes + moreNotes) {
    t_.mesh = base.mesh;
    t_.groups = base.groups;
  }
  Builder& node(int label, double x, double y, double z) {
    io::StoredNode n;
    n.label = label;
    n.position = Vector3(x, y, z);
    t_.mesh.nodes.push_back(n);
    return *this;
  }
  // A polyline through the nodes in order.
  Builder& lines(std::initializer_list<int> chain) {
    const int* prev = nullptr;
    for (const int& n : chain) {
      if (prev) t_.mesh.lines.push_back(io::StoredLine{*prev, n});
      prev = &n;
    }
    return *this;
  }
  Builder& face(int a, int b, int c, int d = 0) {
    t_.mesh.faces.push_back(io::StoredFace{a, b, c, d});
    return *this;
  }
  Builder& group(const std::string& name, std::vector<int> nodes) {
    t_.groups.push_back(NodeGroup{name, std::move(nodes)});
    return *this;
  }
  // `count` nodes labelled from `first` on a circle of radius r [m] in the x-y
  // plane, from the lowest point (-r, 0, 0) going forward and up, joined by a
  // closed line (a wheel rim, a tyre belt); their labels.
  std::vector<int> ring(int first, int count, double r) {
    std::vector<int> labels;
    for (int k = 0; k < count; ++k) {
      const double a = k * 2.0 * kPi / count;
      node(first + k, -r * std::cos(a), r * std::sin(a), 0.0);
      labels.push_back(first + k);
    }
    for (int k = 0; k < count; ++k) t_.mesh.lines.push_back(io::StoredLine{labels[k], labels[(k + 1) % count]});
    return labels;
  }
  // The template, measured in the given directions at every node (DOFs in node order).
  MeshTemplate take(std::initializer_list<Direction> dirs) {
    for (const auto& n : t_.mesh.nodes)
      for (Direction d : dirs) t_.measurementDofs.push_back(Dof{n.label, d, false});
    return std::move(t_);
  }
  const MeshTemplate& peek() const { return t_; }

 private:
  MeshTemplate t_;
};

constexpr std::initializer_list<Direction> kTriaxial = {Direction::X, Direction::Y, Direction::Z};

// ---------------------------------------------------------------- reference plate

const char* kPlateNotes =
    "Axes of thesis eq. 3-4: the plate lies in the x-z plane, y is its normal (the direction the lasers and the "
    "mono-axial accelerometers read). ";

MeshTemplate plate3() {
  // Eq. 3: L1 = (x0, 0, -z0), L2 = (0, 0, -z0), L3 = (0, 0, 0); the thesis
  // prints no x0, z0: 200 mm and 150 mm assumed (the plate of the static model).
  Builder b("stiffness-plate-3", "Stiffness-rig reference plate, 3 sensor points",
            "thesis §1.2 eq. 3-4, §1.4 eq. 9, Figures 3 and 5",
            std::string(kPlateNotes) +
                "Nodes 1, 2, 3 are L1, L2, L3 (A1, A2, A3 of eq. 9 for the accelerometers); x0 = 0.20 m and z0 = "
                "0.15 m are assumed (not printed), so the layout is approximate. Point 3 is the origin.");
  b.node(1, 0.20, 0.0, -0.15).node(2, 0.0, 0.0, -0.15).node(3, 0.0, 0.0, 0.0);
  b.lines({1, 2, 3, 1}).face(1, 2, 3);
  b.group("sensors", {1, 2, 3});
  return b.take({Direction::Y});
}

MeshTemplate plate4() {
  // The four lasers of §1.2 ("a fourth laser sensor has been added") at the
  // points of the simulated stiffness rig (devices/sim staticSpecimen: a
  // 200 mm x 150 mm plate around the load point): (u, v) -> (x, z).
  Builder b("stiffness-plate-4", "Stiffness-rig reference plate, 4 sensor points", "thesis §1.2, Figure 3",
            std::string(kPlateNotes) +
                "Nodes 1-4 are the four lasers at (x, z) = (-0.10, -0.075), (0.10, -0.075), (0.10, 0.075), (-0.10, "
                "0.075) m around the load point at the origin, the layout of the simulated Motostiffmeter; the "
                "thesis prints no plate dimensions, so the layout is approximate.");
  b.node(1, -0.10, 0.0, -0.075).node(2, 0.10, 0.0, -0.075).node(3, 0.10, 0.0, 0.075).node(4, -0.10, 0.0, 0.075);
  b.lines({1, 2, 3, 4, 1}).face(1, 2, 3, 4);
  b.group("sensors", {1, 2, 3, 4});
  return b.take({Direction::Y});
}

// ---------------------------------------------------------------- motorcycle frames

const char* kFrameAxes =
    "Axes of the thesis's accelerometer (§2.1): x up, y forward (travelling direction), z = x cross y, lateral "
    "(left); origin at the middle of the swing-arm pivot axis. ";

// The tubular frame skeleton of frames A and B (steel, enduro and motocross,
// §2.1, Figure 12): steering head, two upper rails, double cradle, swing-arm
// pivot plates and the rear subframe; typical dimensions of a 250-450 cc
// enduro frame (head about 0.7 m ahead of and 0.35-0.52 m above the pivot).
void frameSkeleton(Builder& b) {
  b.node(1, 0.52, 0.62, 0.0)     // steering head, top
      .node(2, 0.34, 0.70, 0.0)  // steering head, bottom
      .node(3, 0.47, 0.46, 0.06)
      .node(4, 0.47, 0.46, -0.06)  // upper rails, front
      .node(5, 0.42, 0.16, 0.11)
      .node(6, 0.42, 0.16, -0.11)  // upper rails, rear (above the pivot plates)
      .node(7, 0.0, 0.0, 0.12)
      .node(8, 0.0, 0.0, -0.12)  // swing-arm pivot, left and right
      .node(9, -0.20, 0.06, 0.10)
      .node(10, -0.20, 0.06, -0.10)  // cradle, rear bottom
      .node(11, -0.22, 0.46, 0.08)
      .node(12, -0.22, 0.46, -0.08)  // cradle, front bottom
      .node(13, 0.08, 0.64, 0.05)
      .node(14, 0.08, 0.64, -0.05)  // down tubes
      .node(15, 0.42, -0.10, 0.10)
      .node(16, 0.42, -0.10, -0.10)  // subframe, front
      .node(17, 0.50, -0.45, 0.09)
      .node(18, 0.50, -0.45, -0.09)  // subframe, rear
      .node(19, 0.20, -0.25, 0.10)
      .node(20, 0.20, -0.25, -0.10);  // subframe stays
  b.lines({1, 2}).lines({1, 3, 5, 7}).lines({1, 4, 6, 8}).lines({2, 13, 11}).lines({2, 14, 12});
  b.lines({5, 15, 17, 19, 7}).lines({6, 16, 18, 20, 8});
  b.lines({3, 4}).lines({5, 6}).lines({7, 8}).lines({15, 16}).lines({17, 18});
  b.group("steering head", {1, 2}).group("swing-arm pivot", {7, 8}).group("subframe", {15, 16, 17, 18, 19, 20});
}

MeshTemplate frame20() {
  Builder b("motorcycle-frame-20", "Motorcycle frame, 20 points (frame A)", "thesis §2.1, Figures 12, 13",
            std::string(kFrameAxes) +
                "20 points as measured on frame A: steering head (1, 2), upper rails (3-6), swing-arm pivot (7, 8), "
                "double cradle (9-14), rear subframe (15-20). Positions are approximate, drawn from Figure 12 and "
                "typical enduro-frame dimensions; the thesis prints no coordinates.");
  frameSkeleton(b);
  b.lines({7, 9, 11}).lines({8, 10, 12}).lines({9, 10}).lines({11, 12});
  b.group("upper", {1, 3, 4, 5, 6}).group("lower", {9, 10, 11, 12, 13, 14});
  return b.take(kTriaxial);
}

MeshTemplate frame26() {
  Builder b("motorcycle-frame-26", "Motorcycle frame, 26 points (frame B)", "thesis §2.1, Figures 12, 14",
            std::string(kFrameAxes) +
                "26 points as measured on frame B: the skeleton of the 20-point frame (same labels 1-20) plus the "
                "thick square upper tube (21), the middle of the lower tubes (22, 23) and the long tail for the "
                "saddle and exhaust (24-26). Positions are approximate, drawn from Figure 12 and typical "
                "dimensions; the thesis prints no coordinates.");
  frameSkeleton(b);
  b.node(21, 0.50, 0.36, 0.0)  // square upper tube
      .node(22, -0.21, 0.26, 0.09)
      .node(23, -0.21, 0.26, -0.09)  // lower tubes, middle
      .node(24, 0.54, -0.70, 0.08)
      .node(25, 0.54, -0.70, -0.08)  // tail
      .node(26, 0.56, -0.90, 0.0);   // tail end
  b.lines({1, 21, 5}).lines({21, 6}).lines({7, 9, 22, 11}).lines({8, 10, 23, 12}).lines({9, 10}).lines({11, 12});
  b.lines({22, 23}).lines({17, 24, 26, 25, 18});
  b.group("upper", {1, 3, 4, 5, 6, 21}).group("lower", {9, 10, 11, 12, 13, 14, 22, 23}).group("tail", {24, 25, 26});
  return b.take(kTriaxial);
}

// Frame C (§2.2): aluminium, "metal plates instead of tubes", two long
// lateral beams almost parallel from the pivot to the steering head.
void frameCSkeleton(Builder& b) {
  b.node(1, 0.52, 0.64, 0.0)     // steering head, top
      .node(2, 0.36, 0.70, 0.0)  // steering head, bottom
      .node(3, 0.46, 0.52, 0.12)
      .node(4, 0.46, 0.52, -0.12)  // lateral beams, front
      .node(5, 0.41, 0.32, 0.15)
      .node(6, 0.41, 0.32, -0.15)  // lateral beams, middle
      .node(7, 0.35, 0.12, 0.14)
      .node(8, 0.35, 0.12, -0.14)  // lateral beams, rear
      .node(9, 0.0, 0.0, 0.12)
      .node(10, 0.0, 0.0, -0.12)  // swing-arm pivot
      .node(11, -0.16, 0.03, 0.11)
      .node(12, -0.16, 0.03, -0.11)  // pivot plates, bottom
      .node(13, 0.12, 0.56, 0.10)
      .node(14, 0.12, 0.56, -0.10)  // front engine mounts
      .node(15, 0.28, 0.60, 0.10)
      .node(16, 0.28, 0.60, -0.10)  // beam lower flanges, front
      .node(17, 0.42, -0.08, 0.10)
      .node(18, 0.42, -0.08, -0.10)  // subframe, front
      .node(19, 0.48, -0.40, 0.09)
      .node(20, 0.48, -0.40, -0.09)  // subframe, rear
      .node(21, 0.36, 0.10, 0.0)     // upper cross member
      .node(22, -0.16, 0.03, 0.0);   // lower cross member
  b.lines({1, 2}).lines({1, 3, 5, 7, 9, 11}).lines({1, 4, 6, 8, 10, 12}).lines({2, 16, 13}).lines({2, 15, 14});
  b.lines({16, 5}).lines({15, 6}).lines({7, 21, 8}).lines({11, 22, 12}).lines({7, 17, 19}).lines({8, 18, 20});
  b.lines({17, 18}).lines({19, 20});
  b.group("steering head", {1, 2}).group("swing-arm pivot", {9, 10}).group("upper", {1, 3, 4, 5, 6, 7, 8, 21});
  b.group("lower", {11, 12, 13, 14, 22}).group("subframe", {17, 18, 19, 20});
}

MeshTemplate frame22() {
  Builder b("motorcycle-frame-22", "Motorcycle frame, 22 points (frame C)", "thesis §2.2, Figure 19",
            std::string(kFrameAxes) +
                "22 points as measured on frame C: steering head (1, 2), the two lateral beams (3-8), swing-arm pivot "
                "(9, 10), pivot plates and cross members (11, 12, 21, 22), engine mounts and beam flanges (13-16), "
                "subframe (17-20). Positions are approximate, drawn from Figure 19 and typical dimensions of a sport "
                "twin-beam frame; the thesis prints no coordinates.");
  frameCSkeleton(b);
  return b.take(kTriaxial);
}

MeshTemplate frame22Engine10() {
  Builder b(frame22(), "motorcycle-frame-22-engine-10", "Motorcycle frame with engine, 22 + 10 points (frame C)",
            "thesis §2.2, Figure 19",
            " With the engine: 10 more points on it (101-110: the crankcase corners and the cylinder head), "
            "an in-line engine of about 0.4 m x 0.4 m x 0.26 m hung in the cradle; approximate.");
  b.node(101, -0.24, 0.10, 0.13)
      .node(102, -0.24, 0.10, -0.13)
      .node(103, -0.24, 0.50, 0.13)
      .node(104, -0.24, 0.50, -0.13)
      .node(105, 0.06, 0.10, 0.13)
      .node(106, 0.06, 0.10, -0.13)
      .node(107, 0.06, 0.50, 0.13)
      .node(108, 0.06, 0.50, -0.13)
      .node(109, 0.28, 0.44, 0.08)
      .node(110, 0.28, 0.44, -0.08);
  b.lines({101, 103, 107, 105, 101}).lines({102, 104, 108, 106, 102}).lines({101, 102}).lines({103, 104});
  b.lines({105, 106}).lines({107, 108}).lines({107, 109, 110, 108}).lines({107, 13}).lines({108, 14});
  b.lines({105, 11}).lines({106, 12});
  b.group("engine", {101, 102, 103, 104, 105, 106, 107, 108, 109, 110});
  return b.take(kTriaxial);
}

// ---------------------------------------------------------------- swing-arms

const char* kSwingArmAxes =
    "Axes of the thesis's accelerometer (§3.1): x up, y along the stems from the pivot towards the rear hub, z = x "
    "cross y, lateral (to the right of the rider, since y points rearwards); origin at the middle of the pivot "
    "axis. ";

MeshTemplate swingArm6() {
  Builder b("swing-arm-6", "Swing-arm, 6 points (swing-arm A)", "thesis §3.1, Figures 22-24",
            std::string(kSwingArmAxes) +
                "6 points on the two stems of swing-arm A: at the pivot (1, 2), half-way (3, 4) and at the axle "
                "plates (5, 6); odd labels on the left stem. The thesis's hammer point 100, the rear hub, lies "
                "between nodes 5 and 6. Pivot-to-axle length 0.58 m (enduro), stems 0.22-0.24 m apart: typical "
                "dimensions, approximate.");
  b.node(1, 0.0, 0.0, -0.12).node(2, 0.0, 0.0, 0.12);
  b.node(3, 0.0, 0.29, -0.115).node(4, 0.0, 0.29, 0.115);
  b.node(5, 0.0, 0.58, -0.11).node(6, 0.0, 0.58, 0.11);
  b.lines({1, 3, 5}).lines({2, 4, 6}).lines({1, 2}).lines({3, 4});
  b.group("swing-arm pivot", {1, 2}).group("left stem", {1, 3, 5}).group("right stem", {2, 4, 6});
  b.group("axle", {5, 6});
  return b.take(kTriaxial);
}

MeshTemplate swingArm18() {
  Builder b("swing-arm-18", "Swing-arm, 18 points (swing-arm B)", "thesis §3.2, Figures 25, 26",
            std::string(kSwingArmAxes) +
                "18 points on the three-dimensional swing-arm B: the upper and lower edges of each box-section stem "
                "at the pivot, half-way and at the axle (1-12), and the bracing above the stems that makes the "
                "triangle of Figure 26 (13-18); odd labels on the left. The hub lies between the axle nodes. "
                "Pivot-to-axle length 0.54 m, stems 0.08 m deep: typical sport swing-arm dimensions, approximate.");
  const double ys[] = {0.0, 0.27, 0.54};
  const double halfWidth[] = {0.13, 0.125, 0.12};
  int label = 1;
  for (int s = 0; s < 3; ++s) {
    b.node(label, 0.04, ys[s], -halfWidth[s]).node(label + 1, 0.04, ys[s], halfWidth[s]);        // upper edge L, R
    b.node(label + 2, -0.04, ys[s], -halfWidth[s]).node(label + 3, -0.04, ys[s], halfWidth[s]);  // lower edge L, R
    label += 4;
  }
  b.node(13, 0.14, 0.12, -0.125).node(14, 0.14, 0.12, 0.125);  // bracing, front
  b.node(15, 0.20, 0.27, -0.12).node(16, 0.20, 0.27, 0.12);    // bracing, top
  b.node(17, 0.10, 0.42, -0.12).node(18, 0.10, 0.42, 0.12);    // bracing, rear
  b.lines({1, 5, 9}).lines({3, 7, 11}).lines({2, 6, 10}).lines({4, 8, 12});
  b.lines({1, 3}).lines({5, 7}).lines({9, 11}).lines({2, 4}).lines({6, 8}).lines({10, 12});
  b.lines({1, 2}).lines({3, 4}).lines({1, 13, 15, 17, 9}).lines({2, 14, 16, 18, 10}).lines({15, 16});
  b.face(1, 5, 7, 3).face(5, 9, 11, 7).face(2, 4, 8, 6).face(6, 8, 12, 10);
  b.group("swing-arm pivot", {1, 2, 3, 4});
  b.group("left stem", {1, 3, 5, 7, 9, 11, 13, 15, 17}).group("right stem", {2, 4, 6, 8, 10, 12, 14, 16, 18});
  b.group("axle", {9, 10, 11, 12});
  return b.take(kTriaxial);
}

// ---------------------------------------------------------------- motorcycle forks

const char* kForkAxes =
    "Axes of the thesis's accelerometer (chapter 4): x along the stems (up, from the wheel axle to the steering "
    "head), y normal to the fork plane (longitudinal, forward), z = x cross y, lateral (left); origin at the wheel "
    "axle. ";

// Ten points on the fork: the steering stem at the upper and lower clamps
// (1, 2; 30 mm behind the legs, the clamp offset), and four stations on each
// leg from the lower clamp to the fork foot (odd: left).
void forkPoints(Builder& b) {
  const double legX[] = {0.66, 0.44, 0.22, 0.0};
  b.node(1, 0.86, -0.03, 0.0).node(2, 0.66, -0.03, 0.0);
  int label = 3;
  for (double x : legX) {
    b.node(label, x, 0.0, 0.105).node(label + 1, x, 0.0, -0.105);
    label += 2;
  }
  b.lines({1, 2}).lines({1, 3}).lines({1, 4}).lines({2, 3}).lines({2, 4}).lines({3, 5, 7, 9}).lines({4, 6, 8, 10});
  b.lines({9, 10});
  b.group("steering head", {1, 2}).group("left leg", {3, 5, 7, 9}).group("right leg", {4, 6, 8, 10});
  b.group("fork feet", {9, 10});
}

MeshTemplate fork10() {
  Builder b("motorcycle-fork-10", "Motorcycle front fork, 10 points", "thesis chapter 4, §4.1, Figures 27, 32",
            std::string(kForkAxes) +
                "Fork: steering stem at the upper and lower clamps (1, 2), four stations on each leg from the lower "
                "clamp to the fork foot (odd labels left, 3-10). Leg length 0.66 m below the lower clamp, legs 0.21 m "
                "apart, clamp offset 0.03 m: typical enduro-fork dimensions (fork A), approximate; the thesis prints "
                "no coordinates.");
  forkPoints(b);
  return b.take(kTriaxial);
}

MeshTemplate fork10Wheel8() {
  Builder b(fork10(), "motorcycle-fork-10-wheel-8", "Motorcycle front fork with wheel, 10 + 8 points",
            "thesis chapter 4, §4.1, Figures 27, 28, 32",
            " Wheel: 8 points on the rim, 45 degrees apart in the x-y plane, radius 0.34 m (a 21-inch enduro "
            "wheel; the super-sport 17-inch wheel of fork B is a little smaller), node 11 the lowest point "
            "(where the static load and the hammer were applied), 12-18 going forward and up.");
  b.group("wheel", b.ring(11, 8, 0.34)).group("wheel lowest point", {11});
  return b.take(kTriaxial);
}

// ---------------------------------------------------------------- tyre

MeshTemplate tyre6() {
  Builder b("tyre-6", "Tyre, 6 points on the belt", "thesis §5.2, §5.3, Figures 37, 38",
            "Axes: x up, y forward, z = x cross y along the wheel axle (lateral); origin at the wheel centre. 6 points "
            "equidistant on the belt, 60 degrees apart, node 100 the lowest point (the accelerometer of §5.2) and "
            "101-105 going forward and up. Radius 0.30 m, a typical 17-inch tyre (approximate); the ring modes y = y0 "
            "cos(k phi) "
            "(eq. 42) depend on the angle only, so the template serves every tyre of the catalogue. The rim is "
            "fixed to the rig; the belt's lateral DOFs are measured.");
  b.group("belt", b.ring(100, 6, 0.30)).group("point 100", {100});
  return b.take({Direction::Z});
}

// ---------------------------------------------------------------- bicycle

MeshTemplate bicycle9Fork12() {
  Builder b("bicycle-9-12", "Bicycle, 9 frame + 12 fork points", "thesis §6.1, Figures 44, 46",
            "Axes of the thesis's accelerometer (§6.1): x up, y forward, z = x cross y, lateral (left); origin at the "
            "rear hub. Frame (9 points): rear hub 100 (the hammer point of §6.1), chain stay (1), crank set (2), "
            "seat stay (3), seat cluster (4), top tube (5), head tube top and bottom (6, 7), down tube (8). Fork "
            "(12 points): six on each blade from the crown to the dropout (11-16 left, 17-22 right). Geometry of a "
            "typical road bicycle: wheelbase 1.0 m, head angle 72 degrees, fork offset 45 mm; approximate.");
  b.node(100, 0.0, 0.0, 0.0)
      .node(1, -0.035, 0.21, 0.0)
      .node(2, -0.07, 0.41, 0.0)
      .node(3, 0.27, 0.12, 0.0)
      .node(4, 0.52, 0.23, 0.0)
      .node(5, 0.49, 0.52, 0.0)
      .node(6, 0.45, 0.807, 0.0)
      .node(7, 0.30, 0.856, 0.0)
      .node(8, 0.12, 0.63, 0.0);
  for (int s = 0; s < 6; ++s) {
    const double f = s / 5.0;  // crown -> dropout
    const double x = 0.28 * (1.0 - f), y = 0.862 + 0.138 * f;
    b.node(11 + s, x, y, 0.05).node(17 + s, x, y, -0.05);
  }
  b.lines({100, 1, 2, 4, 3, 100}).lines({4, 5, 6, 7, 8, 2});
  b.lines({7, 11, 12, 13, 14, 15, 16}).lines({7, 17, 18, 19, 20, 21, 22}).lines({16, 22});
  b.group("frame", {100, 1, 2, 3, 4, 5, 6, 7, 8}).group("rear hub", {100});
  b.group("fork", {11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22});
  b.group("left blade", {11, 12, 13, 14, 15, 16}).group("right blade", {17, 18, 19, 20, 21, 22});
  return b.take(kTriaxial);
}

// ---------------------------------------------------------------- bicycle forks

const char* kBicycleForkNotes =
    "Axes: x along the steerer (up), y normal to the fork plane (forward), z = x cross y, lateral (left), as for the "
    "motorcycle forks (chapter 4) and §6.2 (blades in z for the lateral mode, in y for the longitudinal one); origin "
    "at the hub. Fork (9 points, chapter 6 introduction): four equidistant points on each blade from the crown to "
    "the dropout (1-4 left, 5-8 right) and a ninth on the steerer close to the fixation (9). Blade length 0.37 m, "
    "dropouts 0.10 m apart, rake 45 mm (the steerer axis 45 mm behind the hub): typical road-fork dimensions, "
    "approximate.";

void bicycleForkPoints(Builder& b) {
  for (int s = 0; s < 4; ++s) {
    const double f = s / 3.0;  // crown -> dropout
    const double x = 0.37 * (1.0 - f), y = -0.035 * (1.0 - f) * (1.0 - f);
    b.node(1 + s, x, y, 0.05).node(5 + s, x, y, -0.05);
  }
  b.node(9, 0.50, -0.045, 0.0);
  b.lines({9, 1, 2, 3, 4}).lines({9, 5, 6, 7, 8}).lines({4, 8});
  b.group("steerer", {9}).group("left blade", {1, 2, 3, 4}).group("right blade", {5, 6, 7, 8});
  b.group("dropouts", {4, 8});
}

MeshTemplate bicycleFork9() {
  Builder b("bicycle-fork-9", "Bicycle fork, 9 points", "thesis chapter 6 introduction, §6.2, §6.3, Figures 48, 49",
            std::string(kBicycleForkNotes) + " Without the wheel a fake hub joins the dropouts.");
  bicycleForkPoints(b);
  return b.take(kTriaxial);
}

MeshTemplate bicycleFork9Wheel8() {
  Builder b("bicycle-fork-9-wheel-8", "Bicycle fork with wheel, 9 + 8 points",
            "thesis chapter 6 introduction, §6.2, §6.3, Figures 48, 50; Table 21",
            std::string(kBicycleForkNotes) +
                " Wheel: 8 equidistant points on the rim, radius 0.35 m (Table 21), node 10 the lowest point, "
                "11-17 going forward and up.");
  bicycleForkPoints(b);
  b.group("wheel", b.ring(10, 8, 0.35));  // radius: Table 21
  return b.take(kTriaxial);
}

std::vector<MeshTemplate> buildTemplates() {
  return {plate3(),     plate4(), frame20(),      frame26(), frame22(),        frame22Engine10(), swingArm6(),
          swingArm18(), fork10(), fork10Wheel8(), tyre6(),   bicycle9Fork12(), bicycleFork9(),    bicycleFork9Wheel8()};
}

}  // namespace

const std::vector<MeshTemplate>& meshTemplates() {
  static const std::vector<MeshTemplate> templates = buildTemplates();
  return templates;
}

const MeshTemplate* findMeshTemplate(const std::string& key) {
  for (const auto& t : meshTemplates())
    if (t.key == key) return &t;
  return nullptr;
}

}  // namespace mozzi::core::geometry
