// Shapes spread over a mesh: measured DOFs land in global axes through each
// node's displacement system, slaves follow their masters, free nodes along a
// trace line are interpolated linearly by arc length (the harmonic
// interpolant on a chain), unreachable nodes stay still. Expected values are
// worked by hand in the comments.
#include "core/geometry/mode_shape.h"

#include "core/stiffness/screw_axis.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mozzi::core::geometry {
namespace {

using io::MeshDocument;
constexpr double kTol = 1e-12;  // a few roundings of O(1) numbers

Dof dof(int node, Direction d, bool negative = false) {
  return Dof{node, d, negative};
}

io::StoredNode node(int label, Vector3 p, int dcs = 0, int ddcs = 0) {
  io::StoredNode n;
  n.label = label;
  n.position = p;
  n.definitionCs = dcs;
  n.displacementCs = ddcs;
  return n;
}

// Nodes 1..5 on the x axis at 0, 1, 3, 6, 10 m; lines 1-2-3-4-5; node 9 alone.
MeshDocument chain() {
  MeshDocument d;
  const double x[] = {0, 1, 3, 6, 10};
  for (int i = 0; i < 5; ++i) d.mesh.nodes.push_back(node(i + 1, Vector3(x[i], 0, 0)));
  d.mesh.nodes.push_back(node(9, Vector3(0, 5, 0)));
  for (int i = 1; i < 5; ++i) d.mesh.lines.push_back({i, i + 1});
  return d;
}

TEST(ModeShape, FreeNodesOnAChainAreLinearInArcLength) {
  const MeshDocument d = chain();
  // z = 1 at x = 0 and z = 3 + 2i at x = 10: linear in x between them.
  ComplexVector values(2);
  values << Complex(1.0, 0.0), Complex(3.0, 2.0);
  auto f = shapeField(d, {dof(1, Direction::Z), dof(5, Direction::Z)}, values);
  ASSERT_TRUE(f.ok()) << f.error().describe();
  const double x[] = {0, 1, 3, 6, 10};
  for (int i = 0; i < 5; ++i) {
    const Complex expected = values[0] + (values[1] - values[0]) * (x[i] / 10.0);
    EXPECT_LT(std::abs(f->u(i, 2) - expected), kTol) << "node " << i + 1;
    EXPECT_EQ(f->u(i, 0), Complex(0.0, 0.0));
  }
  EXPECT_EQ(f->measuredNodes, 2);
  EXPECT_EQ(f->interpolatedNodes, 3);
  EXPECT_EQ(f->stillNodes, 1);  // node 9 has no line
  EXPECT_EQ(f->source[5], NodeSource::Still);
  EXPECT_EQ(f->u.row(5).norm(), 0.0);

  FieldOptions off;
  off.interpolate = false;
  auto g = shapeField(d, {dof(1, Direction::Z), dof(5, Direction::Z)}, values, off);
  ASSERT_TRUE(g.ok());
  EXPECT_EQ(g->stillNodes, 4);
}

TEST(ModeShape, DisplacementSystemsTurnLocalDirectionsIntoGlobalOnes) {
  MeshDocument d;
  io::StoredCoordinateSystem turned;  // local x along global y
  turned.label = 1;
  turned.rotation << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  io::StoredCoordinateSystem cyl;  // radial, tangential, axial about global z
  cyl.label = 2;
  cyl.kind = io::StoredCoordinateSystem::Kind::Cylindrical;
  d.mesh.coordinateSystems = {turned, cyl};
  d.mesh.nodes = {node(1, Vector3(0, 0, 0), 0, 1), node(2, Vector3(0, 2, 0), 0, 2), node(3, Vector3(1, 0, 0))};
  ComplexVector v(4);
  v << 2.0, 3.0, 5.0, 7.0;
  auto f =
      shapeField(d, {dof(1, Direction::X), dof(2, Direction::X), dof(2, Direction::Y), dof(3, Direction::Y, true)}, v);
  ASSERT_TRUE(f.ok()) << f.error().describe();
  // Node 1: local +X = global +Y.
  EXPECT_LT((f->u.row(0) - Eigen::RowVector3cd(0, 2, 0)).norm(), kTol);
  // Node 2 at phi = 90 deg: radial = +Y, tangential = -X.
  EXPECT_LT((f->u.row(1) - Eigen::RowVector3cd(-5, 3, 0)).norm(), kTol);
  // Node 3: -Y measured 7 means +Y = -7.
  EXPECT_LT((f->u.row(2) - Eigen::RowVector3cd(0, -7, 0)).norm(), kTol);
}

TEST(ModeShape, SlavesFollowTheirMastersBeforeInterpolation) {
  MeshDocument d = chain();
  // Node 3 z = 0.5 z1 + 0.5 z5 (a rigid link, say); rotations are not drawn.
  d.slaves = {{dof(3, Direction::Z), {{dof(1, Direction::Z), 0.5}, {dof(5, Direction::Z, true), -0.5}}}};
  ComplexVector v(3);
  v << 2.0, 4.0, 99.0;
  auto f = shapeField(d, {dof(1, Direction::Z), dof(5, Direction::Z), dof(5, Direction::RX)}, v);
  ASSERT_TRUE(f.ok());
  EXPECT_LT(std::abs(f->u(2, 2) - Complex(3.0, 0.0)), kTol);  // 0.5*2 + (-0.5)*(-4)
  EXPECT_EQ(f->source[2], NodeSource::Slaved);
  EXPECT_EQ(f->slavedNodes, 1);
  EXPECT_EQ(f->ignoredDofs, 1);  // the rotation
  // Node 2 between 1 (z 2, x 0) and 3 (z 3, x 3) at x = 1: 2 + 1/3.
  EXPECT_LT(std::abs(f->u(1, 2) - Complex(2.0 + 1.0 / 3.0, 0.0)), kTol);
}

TEST(ModeShape, SizeMismatchAndNonFiniteValuesAreNamed) {
  const MeshDocument d = chain();
  ComplexVector one(1);
  one << 1.0;
  EXPECT_FALSE(shapeField(d, {dof(1, Direction::Z), dof(2, Direction::Z)}, one).ok());
  one << Complex(std::nan(""), 0.0);
  auto r = shapeField(d, {dof(1, Direction::Z)}, one);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().where.find("1:+Z"), std::string::npos);
}

TEST(ModeShape, PeakMagnitudeIsTheLargestOverACycle) {
  NodeDisplacements u(3, 3);
  u << Complex(1, 0), Complex(0, 2), Complex(0.5, 0.5),  //
      Complex(3, 0), Complex(0, 0), Complex(0, 0),       //
      Complex(1, 1), Complex(-1, 1), Complex(0, 0);
  const Vector peak = peakMagnitudes(u);
  for (Eigen::Index i = 0; i < u.rows(); ++i) {
    double brute = 0.0;  // max over 20000 phases of |Re u sin + Im u cos|
    for (int k = 0; k < 20000; ++k) {
      const double t = 2 * M_PI * k / 20000;
      brute = std::max(brute, (u.row(i).real() * std::sin(t) + u.row(i).imag() * std::cos(t)).norm());
    }
    // Sampling misses the peak by at most |u| (1 - cos(pi/20000)) ~ 1e-8 |u|.
    EXPECT_NEAR(peak[i], brute, 1e-7) << "node row " << i;
  }
  EXPECT_DOUBLE_EQ(peak[1], 3.0);
}

TEST(ModeShape, MacOverSharedDofsHonoursSigns) {
  const std::vector<Dof> a = {dof(1, Direction::Z), dof(2, Direction::Z), dof(3, Direction::Z)};
  const std::vector<Dof> b = {dof(3, Direction::Z), dof(2, Direction::Z, true), dof(7, Direction::Z)};
  ComplexVector va(3), vb(3);
  va << 1.0, 2.0, 3.0;
  vb << Complex(0, 6.0), Complex(0, -4.0), 5.0;  // = 2i x a on the shared DOFs, node 2 read as -Z
  auto m = macOnCommonDofs(a, va, b, vb);
  ASSERT_TRUE(m.ok());
  EXPECT_EQ(m->commonDofs, 2);
  EXPECT_NEAR(m->mac, 1.0, 1e-15);
  vb << 2.0, 3.0, 0.0;  // shared part (a2, a3) = (2, 3) against (-3, 2): orthogonal
  EXPECT_NEAR(macOnCommonDofs(a, va, b, vb)->mac, 0.0, 1e-15);
  auto none = macOnCommonDofs({dof(1, Direction::X)}, va.head(1), {dof(1, Direction::Y)}, vb.head(1));
  ASSERT_FALSE(none.ok());
}

TEST(ModeShape, OdsTakesTheNearestLine) {
  FrfMatrix frf;
  frf.frequencyHz = Vector::LinSpaced(11, 0.0, 100.0);  // 10 Hz lines
  frf.responses = {dof(1, Direction::Z), dof(2, Direction::Z)};
  frf.references = {dof(1, Direction::Z)};
  ComplexMatrix h(11, 2);
  for (int k = 0; k < 11; ++k) h.row(k) << Complex(k, 0), Complex(0, -k);
  frf.h = {h};
  auto ods = operatingDeflectionShape(frf, 34.0);
  ASSERT_TRUE(ods.ok());
  EXPECT_EQ(ods->line, 3);
  EXPECT_EQ(ods->lineHz, 30.0);
  EXPECT_EQ(ods->values[1], Complex(0, -3));
  EXPECT_EQ(operatingDeflectionShape(frf, 35.0)->line, 3);  // a tie takes the lower line
  EXPECT_EQ(operatingDeflectionShape(frf, 1e9)->line, 10);
  EXPECT_EQ(operatingDeflectionShape(frf, -5.0)->line, 0);
  EXPECT_FALSE(operatingDeflectionShape(frf, 50.0, 1).ok());
}

// A roving hammer read by one accelerometer: 4 hammer points, 1 response. The
// set's shapes lie along the references; the ODS is the row of the response
// over them (reciprocity, H_{o,i} = H_{i,o}), driven at the accelerometer's DOF.
TEST(ModeShape, OdsOfARovingHammerSetIsTheRowOverTheHammerPoints) {
  FrfMatrix frf;
  frf.frequencyHz = Vector::LinSpaced(11, 0.0, 100.0);
  frf.responses = {dof(9, Direction::Y)};
  for (int n = 1; n <= 4; ++n) frf.references.push_back(dof(n, Direction::Z, n == 3));
  for (int i = 0; i < 4; ++i) {
    ComplexMatrix h(11, 1);
    for (int k = 0; k < 11; ++k) h(k, 0) = Complex(k * (i + 1), -i);
    frf.h.push_back(h);
  }
  auto ods = operatingDeflectionShape(frf, 71.0);
  ASSERT_TRUE(ods.ok());
  EXPECT_TRUE(ods->alongReferences);
  EXPECT_EQ(ods->line, 7);
  EXPECT_EQ(ods->drivenAt, dof(9, Direction::Y));
  ASSERT_EQ(ods->dofs.size(), 4u);
  EXPECT_EQ(ods->dofs[2], dof(3, Direction::Z, true));  // the hammer's DOF, sign kept
  ASSERT_EQ(ods->values.size(), 4);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(ods->values[i], Complex(7 * (i + 1), -i));
  EXPECT_FALSE(operatingDeflectionShape(frf, 71.0, 1).ok());  // one response only
  // The same set transposed (the hammer fixed, four accelerometers) gives the
  // same shape as a column.
  auto column = operatingDeflectionShape(frf.transposed(), 71.0);
  ASSERT_TRUE(column.ok());
  EXPECT_FALSE(column->alongReferences);
  EXPECT_EQ(column->dofs, ods->dofs);
  EXPECT_EQ(column->drivenAt, ods->drivenAt);
  EXPECT_EQ((column->values - ods->values).norm(), 0.0);
}

// A rigid screw motion about a known axis, measured as a mode on a mesh whose
// nodes report in a turned cartesian and in a cylindrical displacement system
// and with some negative DOFs: the readings give back the screw axis of the
// motion (thesis §1.5; notes.md closed forms), whatever the node systems.
// Motion: rotation w = theta u about the axis through q with direction u, and
// a slide h theta along it: d(p) = w x (p - q) + h w. Exact data: round-off.
TEST(ModeShape, ReadingsOfARigidScrewGiveItsAxisBack) {
  const Vector3 u = Vector3(0.3, -0.2, 1.0).normalized(), q(0.05, 0.12, 0.0);
  const double theta = 2e-3, h = 0.04;  // [rad], [m/rad]
  const Vector3 w = theta * u;
  MeshDocument d;
  io::StoredCoordinateSystem turned;
  turned.label = 1;
  turned.rotation = Eigen::AngleAxisd(0.6, Vector3(1, 1, 0).normalized()).toRotationMatrix();
  io::StoredCoordinateSystem cyl;
  cyl.label = 2;
  cyl.kind = io::StoredCoordinateSystem::Kind::Cylindrical;
  cyl.origin = Vector3(0.1, 0.0, 0.0);
  d.mesh.coordinateSystems = {turned, cyl};
  const Vector3 at[] = {{0, 0, 0}, {0.4, 0, 0}, {0.4, 0.3, 0.1}, {0, 0.3, -0.2}, {0.2, 0.15, 0.3}};
  std::vector<Dof> dofs;
  std::vector<Complex> values;
  const Complex mode = std::polar(1.0, 0.4);  // a complex mode with a common phase
  for (int i = 0; i < 5; ++i) {
    const int cs = i % 3;  // global, turned, cylindrical
    d.mesh.nodes.push_back(node(i + 1, at[i], 0, cs));
    const Vector3 disp = w.cross(at[i] - q) + h * w;
    // Local axes of the node's displacement system, in global coordinates.
    Matrix3 axes = Matrix3::Identity();
    if (cs == 1) axes = turned.rotation;
    if (cs == 2) {
      const double phi = std::atan2(at[i].y() - cyl.origin.y(), at[i].x() - cyl.origin.x());
      axes.col(0) = Vector3(std::cos(phi), std::sin(phi), 0);
      axes.col(1) = Vector3(-std::sin(phi), std::cos(phi), 0);
      axes.col(2) = Vector3::UnitZ();
    }
    for (int k = 0; k < 3; ++k) {
      const bool negative = (i + k) % 2 == 1;
      const double local = axes.col(k).dot(disp);
      dofs.push_back(dof(i + 1, static_cast<Direction>(k + 1), negative));
      values.push_back((negative ? -local : local) * mode);
    }
  }
  dofs.push_back(dof(3, Direction::RZ));  // a rotation: left out
  values.emplace_back(5.0, 0.0);
  dofs.push_back(dof(42, Direction::X));  // a node the mesh lacks: left out
  values.emplace_back(7.0, 0.0);
  const ComplexVector v = Eigen::Map<const ComplexVector>(values.data(), static_cast<Eigen::Index>(values.size()));
  auto r = shapeReadings(d, dofs, v);
  ASSERT_TRUE(r.ok()) << r.error().describe();
  ASSERT_EQ(r->values.size(), 15);
  auto s = stiffness::screwAxisFromReadingPhasors(r->points, r->directions, r->values);
  ASSERT_TRUE(s.ok()) << s.error().describe();
  EXPECT_NEAR(std::abs(s->direction.dot(u)), 1.0, 1e-12);
  EXPECT_LT(s->distance(q), 1e-12);  // the axis passes through q
  EXPECT_NEAR(s->pitch, h, 1e-12);   // the pitch is the motion's, whatever the phase and the sign
  EXPECT_LT(s->phaseResidual, 1e-12);
  EXPECT_FALSE(shapeReadings(d, dofs, v.head(3)).ok());  // sizes differ
}

}  // namespace
}  // namespace mozzi::core::geometry
