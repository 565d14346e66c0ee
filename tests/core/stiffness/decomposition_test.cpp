// Stiffness decomposition (thesis §1.7 eq. 22-27; §4 eq. 33-36): forward
// synthesis from known bending and torsion stiffness, the fork variant as a
// special case, directed axes, and singular or non-physical input.
#include "core/stiffness/decomposition.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mozzi::core::stiffness {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Forward model: load F at a point with arms a_b, a_t about the bending and
// torsion axes (angles beta_b, beta_t). theta_b = F a_b / k_b, theta_t = F a_t / k_t
// (eq. 23); the twist rotation vector is their sum (eq. 25, 26) and the load
// point displacement is theta_b a_b + theta_t a_t (eq. 22). From these the
// static axis angle beta, theta_tw, a_tw = x / theta_tw and k_tw = F a_tw / theta_tw.
DecompositionInput synthesise(double kb, double kt, double ab, double at, double bb, double bt) {
  const double F = 1.0;
  const double thb = F * ab / kb, tht = F * at / kt;
  const double cx = thb * std::cos(bb) + tht * std::cos(bt);
  const double sx = thb * std::sin(bb) + tht * std::sin(bt);
  const double thtw = std::hypot(cx, sx);
  const double x = thb * ab + tht * at;
  DecompositionInput in;
  in.twistBeta = std::atan2(sx, cx);
  in.twistArm = x / thtw;
  in.twistStiffness = F * in.twistArm / thtw;
  in.bendArm = ab;
  in.bendBeta = bb;
  in.torsArm = at;
  in.torsBeta = bt;
  return in;
}

TEST(Decomposition, RecoversKnownBendingAndTorsionStiffness) {
  // Frame-like: bending axis near perpendicular to the frame, torsion along it.
  const auto in = synthesise(52.1e3, 22.0e3, 0.556, 0.032, 0.1, 0.1 + kPi / 2 + 0.2);
  const auto r = decomposeStiffness(in);
  ASSERT_TRUE(r.ok()) << r.error().describe();
  EXPECT_NEAR(r->bendStiffness, 52.1e3, 1e-9 * 52.1e3);
  EXPECT_NEAR(r->torsStiffness, 22.0e3, 1e-9 * 22.0e3);
  EXPECT_NEAR(r->balanceResidual, 0.0, 1e-12);
  EXPECT_NEAR(r->rotationResidual, 0.0, 1e-12);  // exact synthesis: eq. 25/26 magnitude also holds
}

// The fork variant (eq. 35/36) is the general system with beta_bend = 0,
// beta_tors = 90 deg and beta = alpha.
TEST(Decomposition, ForkVariantIsTheGeneralCaseWithPerpendicularAxes) {
  ForkDecompositionInput f{22.33e3, 0.452, 0.528, 0.083, 41.2 * kPi / 180};
  const auto a = decomposeForkStiffness(f);
  DecompositionInput g{f.twistStiffness, f.twistArm, f.alpha, f.bendArm, 0.0, f.torsArm, kPi / 2};
  const auto b = decomposeStiffness(g);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_NEAR(a->bendStiffness, b->bendStiffness, 1e-9 * b->bendStiffness);
  EXPECT_NEAR(a->torsStiffness, b->torsStiffness, 1e-9 * b->torsStiffness);
  // eq. 36 holds: tan(alpha) = a_t k_b / (k_t a_b)
  EXPECT_NEAR(std::tan(f.alpha), f.torsArm * a->bendStiffness / (a->torsStiffness * f.bendArm), 1e-12);
  EXPECT_NEAR(a->balanceResidual, 0.0, 1e-12);
}

// Directed axes: flipping the direction of an axis flips its signed arm and
// its angle by pi; the stiffnesses do not change.
TEST(Decomposition, DirectedAxesAreInvariantToOrientation) {
  const Vector2 load(0.0, -0.6);
  auto axis = [](Vector2 q, double beta) {
    PlateAxis a;
    a.point = q;
    a.direction = Vector2(std::sin(beta), std::cos(beta));
    return a;
  };
  const PlateAxis bend = axis(Vector2(0.0, -0.05), kPi / 2 + 0.05);
  const PlateAxis tors = axis(Vector2(0.04, 0.0), 0.02);
  const double ab = bend.signedArm(load), at = tors.signedArm(load);
  const auto in = synthesise(50e3, 10e3, ab, at, std::atan2(bend.direction(0), bend.direction(1)),
                             std::atan2(tors.direction(0), tors.direction(1)));
  // Twist axis as a directed line through the point at signed distance a_tw.
  PlateAxis tw = axis(Vector2::Zero(), in.twistBeta);
  const Vector2 nrm(tw.direction(1), -tw.direction(0));  // signedArm grows along this
  tw.point = load - in.twistArm * nrm;
  ASSERT_NEAR(tw.signedArm(load), in.twistArm, 1e-12);
  const auto r1 = decomposeStiffness(in.twistStiffness, tw, bend, tors, load);
  PlateAxis torsFlipped = tors;
  torsFlipped.direction = -tors.direction;
  PlateAxis twFlipped = tw;
  twFlipped.direction = -tw.direction;
  const auto r2 = decomposeStiffness(in.twistStiffness, twFlipped, bend, torsFlipped, load);
  ASSERT_TRUE(r1.ok()) << r1.error().describe();
  ASSERT_TRUE(r2.ok()) << r2.error().describe();
  EXPECT_NEAR(r1->bendStiffness, 50e3, 1e-6 * 50e3);
  EXPECT_NEAR(r1->torsStiffness, 10e3, 1e-6 * 10e3);
  EXPECT_NEAR(r2->bendStiffness, 50e3, 1e-6 * 50e3);
  EXPECT_NEAR(r2->torsStiffness, 10e3, 1e-6 * 10e3);
}

TEST(Decomposition, SingularAndNonPhysicalInputAreErrors) {
  // Singular 2x2 system: a_b sin(bt - b) = a_t sin(bb - b).
  DecompositionInput p{15e3, 0.5, 0.0, 0.6, 0.5, 0.6 * std::sin(1.0) / std::sin(0.5), 1.0};
  auto r = decomposeStiffness(p);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("singular"), std::string::npos);
  // Parallel bending and torsion axes: eq. 27 forces A = -B, one stiffness negative.
  r = decomposeStiffness(DecompositionInput{15e3, 0.5, 0.3, 0.6, 0.1, 0.06, 0.1});
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("non-physical"), std::string::npos);
  // Static axis parallel to the bending axis: torsion not identifiable.
  DecompositionInput q{15e3, 0.5, 0.2, 0.6, 0.2, 0.06, 1.7};
  r = decomposeStiffness(q);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("not identifiable"), std::string::npos);
  // Static axis outside the angle between the two: a negative stiffness.
  DecompositionInput s{15e3, 0.5, -0.3, 0.6, 0.0, 0.06, kPi / 2};
  r = decomposeStiffness(s);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("non-physical"), std::string::npos);
  // Zero stiffness or arm.
  EXPECT_FALSE(decomposeStiffness(DecompositionInput{0.0, 0.5, 0.3, 0.6, 0.0, 0.06, 1.5}).ok());
  EXPECT_FALSE(decomposeStiffness(DecompositionInput{1e4, 0.5, 0.3, 0.0, 0.0, 0.06, 1.5}).ok());
  // Fork variant: alpha 0 or 90 deg.
  EXPECT_FALSE(decomposeForkStiffness({15e3, 0.5, 0.67, 0.066, 0.0}).ok());
  EXPECT_FALSE(decomposeForkStiffness({15e3, 0.5, 0.67, 0.066, kPi / 2}).ok());
}

}  // namespace
}  // namespace mozzi::core::stiffness
