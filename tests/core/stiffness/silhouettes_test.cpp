// The shipped silhouettes (resources/silhouettes/silhouettes.json) parse, say
// they are approximate and where their dimensions come from, cover the
// components the issue names, and place the component with its load point on
// the rig's load point; malformed files are refused with the entry named.
#include "core/stiffness/silhouettes.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace mozzi::core::stiffness {
namespace {

std::string shipped() {
  std::ifstream in(std::string(MOZZI_SOURCE_DIR) + "/resources/silhouettes/silhouettes.json");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Silhouettes, ShippedFileIsApproximateAndSourced) {
  auto cat = parseSilhouettes(shipped());
  ASSERT_TRUE(cat.ok()) << cat.error().describe();
  EXPECT_TRUE(cat->approximate);
  EXPECT_NE(cat->note.find("Approximate"), std::string::npos);
  for (const auto& c : cat->components) {
    EXPECT_FALSE(c.source.empty()) << c.key;
    EXPECT_FALSE(c.polygons.empty()) << c.key;
    if (c.centreOfGravity) {
      EXPECT_NE(c.centreOfGravityNote.find("estimated"), std::string::npos) << c.key;
    }
  }
  // Frames A, B, C, swing-arms A and B, forks A and B, the bicycle forks.
  for (const char* key : {"frame-a-front-constrained", "frame-a-rear-constrained", "frame-b-front-constrained",
                          "frame-b-rear-constrained", "frame-c-without-engine", "frame-c-with-engine", "swing-arm-a",
                          "swing-arm-b", "fork-a-with-wheel", "fork-a-without-wheel", "fork-b-with-wheel",
                          "fork-b-without-wheel", "bicycle-fork-carbon-with-wheel", "bicycle-fork-carbon-without-wheel",
                          "bicycle-fork-steel-with-wheel", "bicycle-fork-steel-without-wheel"})
    EXPECT_NE(cat->placement(key), nullptr) << key;
}

TEST(Silhouettes, PlacementPutsTheLoadPointOnTheRigs) {
  auto cat = parseSilhouettes(shipped());
  ASSERT_TRUE(cat.ok());
  // Frame A front-constrained: load at the swing-arm pivot (0, 0) of the
  // component, steering head at (0.60, 0.36); u = -(x - 0), v = z - 0, shifted
  // to a load point at (0.01, -0.02).
  auto placed = placeSilhouette(*cat, "frame-a-front-constrained", Vector2(0.01, -0.02));
  ASSERT_TRUE(placed.ok()) << placed.error().describe();
  EXPECT_EQ(placed->loadPointName, "swing-arm pivot");
  EXPECT_EQ(placed->constrainedEndName, "steering head");
  EXPECT_NEAR(placed->constrainedEnd(0), 0.01 - 0.60, 1e-12);
  EXPECT_NEAR(placed->constrainedEnd(1), -0.02 + 0.36, 1e-12);
  ASSERT_TRUE(placed->centreOfGravity.has_value());
  EXPECT_NEAR((*placed->centreOfGravity)(0), 0.01 - 0.30, 1e-12);
  // Its first polygon starts at the pivot, i.e. at the load point.
  EXPECT_NEAR(placed->polygons.front().front()(0), 0.01, 1e-12);
  EXPECT_NEAR(placed->polygons.front().front()(1), -0.02, 1e-12);
  // Fork A with wheel: fork and wheel (two circles of 72 sides), no centre of gravity.
  auto fork = placeSilhouette(*cat, "fork-a-with-wheel", Vector2::Zero());
  ASSERT_TRUE(fork.ok());
  EXPECT_EQ(fork->polygons.size(), 6u + 2u);
  EXPECT_EQ(fork->polygons.back().size(), 72u);
  EXPECT_FALSE(fork->centreOfGravity.has_value());
  EXPECT_GT(fork->constrainedEnd(1), 1.0);  // the steering head at the top
  EXPECT_FALSE(placeSilhouette(*cat, "tyre-120-70-r17", Vector2::Zero()).ok());
}

TEST(Silhouettes, MalformedFilesAreRefusedWithTheEntryNamed) {
  EXPECT_FALSE(parseSilhouettes("not json").ok());
  const std::string head =
      R"({"format": "mozzi-silhouettes 1", "approximate": true, "note": "n", "coordinates": "c", "components": )";
  auto twoPoints = parseSilhouettes(
      head + R"({"x": {"name": "X", "source": "s", "polygons": [[[0, 0], [1, 0]]]}}, "specimens": {}})");
  ASSERT_FALSE(twoPoints.ok());
  EXPECT_NE(twoPoints.error().where.find("component x"), std::string::npos) << twoPoints.error().describe();
  auto unknown = parseSilhouettes(
      head + R"({"x": {"name": "X", "source": "s", "polygons": [[[0, 0], [1, 0], [1, 1]]], "points": {"a": [0, 0]}}},
             "specimens": {"k": {"components": ["y"], "load_point": "a", "constrained_end": "a"}}})");
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.error().where.find("specimen k"), std::string::npos);
  auto noApprox = parseSilhouettes(
      R"({"format": "mozzi-silhouettes 1", "note": "n", "coordinates": "c", "components": {}, "specimens": {}})");
  EXPECT_FALSE(noApprox.ok());
  auto badRadius = parseSilhouettes(
      head + R"({"x": {"name": "X", "source": "s", "circles": [{"centre": [0, 0], "radius": -1}]}}, "specimens": {}})");
  EXPECT_FALSE(badRadius.ok());
}

}  // namespace
}  // namespace mozzi::core::stiffness
