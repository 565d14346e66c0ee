#pragma once
// Approximate outlines of the tested components (frames A, B, C, swing-arms A
// and B, forks A and B, the bicycle forks), for drawing twist axes over them in
// the plane of the component (thesis Figures 15 to 18, 20, 21, 28 to 30). The
// outlines are data (resources/silhouettes/silhouettes.json, whose metadata
// says they are approximate and where each dimension comes from); this file
// reads them and places a component in the plate coordinates of a rig test.
//
// Component coordinates: the component's plane [m], x forward (direction of
// travel), z up; forks: x forward across the fork, z along the stems.
// Placement in plate coordinates (plate_motion.h; the simulated rig puts the
// load point at the plate origin): u = uSign (x - x_load), v = z - z_load.

#include <optional>
#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/result.h"

namespace mozzi::core::stiffness {

struct SilhouetteComponent {
  std::string key;                             // "frame-a"
  std::string name;                            // "Frame A (steel, enduro)"
  std::string source;                          // where the dimensions come from
  std::vector<std::vector<Vector2>> polygons;  // closed outlines (circles already as polygons) [m]
  struct NamedPoint {
    std::string name;  // "steering head", "swing-arm pivot", "wheel contact point"
    Vector2 at = Vector2::Zero();
  };
  std::vector<NamedPoint> points;
  std::optional<Vector2> centreOfGravity;  // only where the thesis marks one
  std::string centreOfGravityNote;
  const NamedPoint* point(const std::string& name) const;
};

struct SilhouettePlacement {
  std::string specimenKey;              // devices/sim/specimen_catalogue.h key, "frame-a-front-constrained"
  std::vector<std::string> components;  // drawn together ("frame-c", "engine-c")
  std::string loadPoint;                // a named point of the first component
  std::string constrainedEnd;           // a named point of the first component
  double uSign = 1.0;                   // +1: u along +x, -1: u along -x
};

struct SilhouetteCatalogue {
  std::string format;  // "mozzi-silhouettes 1"
  bool approximate = true;
  std::string note;         // what the outlines are and are not
  std::string coordinates;  // the coordinate convention, in words
  std::vector<SilhouetteComponent> components;
  std::vector<SilhouettePlacement> placements;
  const SilhouetteComponent* component(const std::string& key) const;
  const SilhouettePlacement* placement(const std::string& specimenKey) const;
};

// Reads the catalogue. Errors name the entry: not JSON, a missing or wrong
// field, a polygon of fewer than 3 points, a circle without a positive radius,
// a placement naming an unknown component or point.
Result<SilhouetteCatalogue> parseSilhouettes(const std::string& json);

// A component placed in the plate coordinates of a test.
struct PlacedSilhouette {
  std::string specimenKey;
  std::string name;
  std::string source;
  bool approximate = true;
  std::vector<std::vector<Vector2>> polygons;  // [m], plate coordinates
  Vector2 loadPoint = Vector2::Zero();
  std::string loadPointName;
  Vector2 constrainedEnd = Vector2::Zero();
  std::string constrainedEndName;
  std::optional<Vector2> centreOfGravity;
  std::string centreOfGravityNote;
};

// Places the specimen's silhouette so its load point lands on `loadPoint`
// (the rig set-up's, plate coordinates). Error when the catalogue has no
// placement for the key.
Result<PlacedSilhouette> placeSilhouette(const SilhouetteCatalogue& catalogue, const std::string& specimenKey,
                                         const Vector2& loadPoint);

}  // namespace mozzi::core::stiffness
