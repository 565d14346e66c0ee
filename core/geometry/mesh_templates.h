#pragma once
// Measurement meshes of the thesis set-ups, ready to store as a specimen's mesh
// (io::StoredMesh) and to drive a campaign: the points the thesis measured on
// motorcycle frames (§2.1: 20 points on frame A, 26 on frame B; §2.2: 22 on
// frame C plus 10 on its engine), swing-arms (§3.1: 6, §3.2: 18), front forks
// (chapter 4: 10 on the fork and 8 on the wheel), tyres (§5.2, Figure 37: 6 on
// the belt), bicycles (§6.1, Figure 44: 9 on the frame, 12 on the fork),
// bicycle forks (chapter 6 introduction: 9 points, 8 more on the wheel) and the
// reference plate of the stiffness rig (§1.2-1.4, Figures 3 and 5: 3 or 4
// sensor points).
//
// Coordinates. The thesis prints no coordinates, only the point counts, the
// figures and a few dimensions (wheel radius, fork masses, Table 21); every
// template is drawn from those and typical dimensions of the component, so
// approximateCoordinates is true and `notes` says what is assumed. Nodes are
// in metres in the thesis's own measurement axes, the ones its tri-axial
// accelerometer was oriented along, so a DOF label reads as in the thesis:
//   frames, swing-arms, bicycles, tyres: x up, y forward (swing-arms: along the
//     stems, towards the hub), z = x cross y, lateral (§2.1, §3.1, §6.1);
//   forks and bicycle forks: x along the stems (up), y longitudinal (normal to
//     the fork plane), z = x cross y, lateral (chapter 4);
//   reference plate: the plate in the x-z plane, y its normal (eq. 3-4).
// So lateral is +Z everywhere except on the plate, where the sensors read +Y.
//
// Measurement DOFs: +X, +Y, +Z at every node where the thesis moved a
// tri-axial accelerometer (frames, swing-arms, forks, bicycles, bicycle
// forks); +Z (lateral) on the tyre belt, where the ring modes are lateral
// (§5.3); +Y (the plate normal) on the plate's sensor points. Node labels are
// unique per template; the "with wheel" and "with engine" templates extend the
// plain ones with the same labels for the shared nodes.

#include <string>
#include <vector>

#include "core/common/dof.h"
#include "core/io/project_records.h"

namespace mozzi::core::geometry {

// A named set of nodes ("steering head", "left leg", "wheel", ...): the places
// a constraint or a description refers to.
struct NodeGroup {
  std::string name;
  std::vector<int> nodes;  // node labels
};

struct MeshTemplate {
  std::string key;     // "motorcycle-fork-10-wheel-8"
  std::string name;    // "Motorcycle front fork with wheel (10 + 8 points)"
  std::string source;  // thesis section and figure
  bool approximateCoordinates = true;
  std::string notes;  // axes, where the dimensions come from, what is approximate
  io::StoredMesh mesh;
  std::vector<Dof> measurementDofs;  // in node order, X before Y before Z
  std::vector<NodeGroup> groups;

  const NodeGroup* group(const std::string& name) const;  // nullptr if absent
  const io::StoredNode* node(int label) const;            // nullptr if absent
};

// Every template, in thesis order (plate, frames, swing-arms, forks, tyre,
// bicycle, bicycle forks).
const std::vector<MeshTemplate>& meshTemplates();
const MeshTemplate* findMeshTemplate(const std::string& key);

}  // namespace mozzi::core::geometry
