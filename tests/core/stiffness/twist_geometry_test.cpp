// Geometry of twist axes in the plate plane (core/stiffness/twist_geometry.h):
// a rigid plate turning about a known axis gives that axis back, clipped,
// crossed and traced; expected values are closed forms written here, not
// calls to the code under test.
#include "core/stiffness/twist_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "core/stiffness/dynamic_twist.h"

namespace mozzi::core::stiffness {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kExact = 1e-12;  // round-off on metre-sized numbers

// The simulated rig's plate: four lasers on 200 mm x 150 mm around the load point at the origin.
std::vector<Vector2> lasers() {
  return {Vector2(-0.10, -0.075), Vector2(0.10, -0.075), Vector2(0.10, 0.075), Vector2(-0.10, 0.075)};
}

// w(p) = theta (p - q) x d for a rotation theta about the line through q along d.
double turn(const Vector2& p, const Vector2& q, const Vector2& d, double theta) {
  return theta * ((p(0) - q(0)) * d(1) - (p(1) - q(1)) * d(0));
}

double distanceFromLine(const Vector2& p, const Vector2& q, const Vector2& d) {
  return std::abs((p(0) - q(0)) * d(1) - (p(1) - q(1)) * d(0)) / d.norm();
}

TEST(TwistGeometry, RigidPlateGivesBackItsAxis) {
  const double beta = 0.4;  // rad from v towards u
  const Vector2 d(std::sin(beta), std::cos(beta));
  const Vector2 q(-0.30, 0.20);  // a point of the axis
  std::vector<double> w;
  for (const auto& p : lasers()) w.push_back(turn(p, q, d, 2e-4));
  auto axis = staticTwistAxis(lasers(), w, Vector2::Zero());
  ASSERT_TRUE(axis.ok()) << axis.error().describe();
  // The stored form (point, inclination) back into an axis.
  const PlateAxis a = plateAxisAt(axis->axis.point, axis->axis.beta);
  EXPECT_NEAR(a.beta, beta, kExact);
  // Foot of the perpendicular from the load point (origin): q - (q . d) d.
  const Vector2 foot = q - q.dot(d) * d;
  EXPECT_NEAR(footOf(a, Vector2::Zero())(0), foot(0), kExact);
  EXPECT_NEAR(footOf(a, Vector2::Zero())(1), foot(1), kExact);
  // Clipped to a region, both ends lie on the known line and span its chord.
  PlaneBox box;
  box.include(Vector2(-1.0, -0.5));
  box.include(Vector2(0.5, 1.0));
  auto seg = clipAxis(a, box);
  ASSERT_TRUE(seg.ok()) << seg.error().describe();
  EXPECT_LT(distanceFromLine(seg->from, q, d), kExact);
  EXPECT_LT(distanceFromLine(seg->to, q, d), kExact);
  EXPECT_NEAR(std::atan2(seg->to(0) - seg->from(0), seg->to(1) - seg->from(1)), beta, kExact);
  // The line u = q_u + (v - q_v) tan(beta) leaves the box through v = -0.5 and v = 1.0.
  EXPECT_NEAR(seg->from(1), -0.5, kExact);
  EXPECT_NEAR(seg->from(0), q(0) + (-0.5 - q(1)) * std::tan(beta), kExact);
  EXPECT_NEAR(seg->to(1), 1.0, kExact);
  EXPECT_NEAR(seg->to(0), q(0) + (1.0 - q(1)) * std::tan(beta), kExact);
}

TEST(TwistGeometry, ClipsToTheBoxOrSaysItMisses) {
  PlaneBox unit;
  unit.include(Vector2(0, 0));
  unit.include(Vector2(1, 1));
  auto diag = clipAxis(plateAxisAt(Vector2(0.5, 0.5), kPi / 4), unit);
  ASSERT_TRUE(diag.ok());
  EXPECT_NEAR(diag->from(0), 0.0, kExact);
  EXPECT_NEAR(diag->from(1), 0.0, kExact);
  EXPECT_NEAR(diag->to(0), 1.0, kExact);
  EXPECT_NEAR(diag->to(1), 1.0, kExact);
  auto across = clipAxis(plateAxisAt(Vector2(0.3, 0.25), kPi / 2), unit);  // along +u at v = 0.25
  ASSERT_TRUE(across.ok());
  EXPECT_NEAR(across->from(0), 0.0, kExact);
  EXPECT_NEAR(across->to(0), 1.0, kExact);
  EXPECT_NEAR(across->from(1), 0.25, kExact);
  EXPECT_FALSE(clipAxis(plateAxisAt(Vector2(2.0, 0.0), 0.0), unit).ok());  // u = 2, outside
  EXPECT_FALSE(clipAxis(plateAxisAt(Vector2(0.5, 0.5), 0.0), PlaneBox{}).ok());
}

TEST(TwistGeometry, AxesCrossWhereTheLinesMeet) {
  // v = u and v = 1 - u meet at (0.5, 0.5).
  auto x = axisIntersection(plateAxisAt(Vector2(0, 0), kPi / 4), plateAxisAt(Vector2(0, 1), -kPi / 4));
  ASSERT_TRUE(x.ok());
  EXPECT_NEAR((*x)(0), 0.5, kExact);
  EXPECT_NEAR((*x)(1), 0.5, kExact);
  auto parallel = axisIntersection(plateAxisAt(Vector2(0, 0), 0.3), plateAxisAt(Vector2(1, 0), 0.3));
  ASSERT_FALSE(parallel.ok());
  EXPECT_NE(parallel.error().message.find("parallel"), std::string::npos);
}

TEST(TwistGeometry, CrossingsOfAnOutlineInOrderAlongTheAxis) {
  const std::vector<Vector2> square{Vector2(0, 0), Vector2(1, 0), Vector2(1, 1), Vector2(0, 1)};
  auto up = axisCrossings(plateAxisAt(Vector2(0.25, 5.0), 0.0), square);  // u = 0.25, towards +v
  ASSERT_EQ(up.size(), 2u);
  EXPECT_NEAR(up[0](0), 0.25, kExact);
  EXPECT_NEAR(up[0](1), 0.0, kExact);
  EXPECT_NEAR(up[1](1), 1.0, kExact);
  // Through a vertex: the corner counts once.
  auto corner = axisCrossings(plateAxisAt(Vector2(0, 0), kPi / 4), square);
  EXPECT_EQ(corner.size(), 2u);
  EXPECT_TRUE(axisCrossings(plateAxisAt(Vector2(3, 0), 0.0), square).empty());
}

// A plate turning about a bending and a torsion axis, each an undamped
// single-degree-of-freedom response to the sine force (the virtual
// specimens' model, devices/sim/specimen_models.h): the displacement field
// is the plane w = g0 + gu u + gv v with
//   g(f) = sum_r theta_r r_r(f) (d_rv, -d_ru),  g0(f) = -sum_r theta_r r_r(f) (q_r x d_r),
//   r_r(f) = 1 / (1 - (f/f_r)^2),
// whose zero line is the dynamic axis: foot from the origin -g0 g / |g|^2.
TEST(TwistGeometry, DynamicAxisPathFollowsTheTwoModeModel) {
  struct Mode {
    Vector2 q, d;
    double theta, fn;
  };
  const Mode modes[] = {{Vector2(-0.06, 0.67), Vector2(0.996, 0.09).normalized(), 2.4e-5, 22.3},
                        {Vector2(-0.066, 0.0), Vector2(0.035, 1.0).normalized(), 2.2e-5, 67.2}};
  const double freqs[] = {15.0, 1.0, 5.0, 10.0};  // unsorted on purpose
  std::vector<AxisAtFrequency> axes;
  for (double f : freqs) {
    ComplexVector y(4);
    for (int i = 0; i < 4; ++i) {
      double w = 0.0;
      for (const auto& m : modes) w += turn(lasers()[i], m.q, m.d, m.theta) / (1.0 - (f / m.fn) * (f / m.fn));
      y(i) = std::polar(std::abs(w), w >= 0 ? 0.0 : kPi);
    }
    auto pa = phasorTwistAxis(lasers(), y, Vector2::Zero());
    ASSERT_TRUE(pa.ok()) << pa.error().describe();
    axes.push_back({f, pa->axis.axis});
  }
  auto path = dynamicAxisPath(axes, Vector2::Zero());
  ASSERT_TRUE(path.ok()) << path.error().describe();
  ASSERT_EQ(path->points.size(), 4u);
  const double sorted[] = {1.0, 5.0, 10.0, 15.0};
  for (std::size_t k = 0; k < 4; ++k) {
    const double f = sorted[k];
    EXPECT_EQ(path->points[k].frequencyHz, f);
    double g0 = 0.0;
    Vector2 g = Vector2::Zero();
    for (const auto& m : modes) {
      const double s = m.theta / (1.0 - (f / m.fn) * (f / m.fn));
      g += s * Vector2(m.d(1), -m.d(0));
      g0 -= s * (m.q(0) * m.d(1) - m.q(1) * m.d(0));
    }
    const Vector2 foot = -g0 * g / g.squaredNorm();
    EXPECT_NEAR(path->points[k].foot(0), foot(0), 1e-9) << f << " Hz";
    EXPECT_NEAR(path->points[k].foot(1), foot(1), 1e-9) << f << " Hz";
    EXPECT_NEAR(path->points[k].arm, foot.norm(), 1e-9) << f << " Hz";
  }
  // The axis turns towards the bending axis as 22.3 Hz nears: its foot moves.
  EXPECT_GT((path->points[3].foot - path->points[0].foot).norm(), 0.01);
  EXPECT_EQ(path->nearest(11.0), 2u);
  EXPECT_EQ(path->nearest(-3.0), 0u);
  EXPECT_EQ(path->nearest(99.0), 3u);
  // Bad input.
  EXPECT_FALSE(dynamicAxisPath({}, Vector2::Zero()).ok());
  EXPECT_FALSE(dynamicAxisPath({axes[0], axes[0]}, Vector2::Zero()).ok());
}

}  // namespace
}  // namespace mozzi::core::stiffness
