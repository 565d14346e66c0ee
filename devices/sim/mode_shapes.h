#pragma once
// Mode shapes of the virtual specimens over their measurement meshes (internal
// to devices/sim; specimen_models.h is the public face). Each tabulated mode
// is a displacement field over the node coordinates that follows the thesis's
// description of it, built from a few physical shape functions:
//   - cantilever bending: u = e psi(xi), xi the distance from the clamp along
//     the component over its length, psi = xi^2 (3 - xi) / 2 (the static
//     deflection under a tip load, psi(1) = 1) and its rigid extension beyond
//     the tip (wheels, tails); its twist axis then crosses the component at one
//     third of its length from the clamp, as §3.1 finds for swing-arm A;
//   - torsion: a rotation theta(xi) about the component's torsion axis,
//     u = theta (d x (p - a)), so the two sides of the axis move in opposition;
//   - rigid wheel motion: translation and rotation of the whole rim;
//   - ring modes of the tyre belt: u_z = cos(k phi) (thesis eq. 42).
// The clamp of the rig is not rigid: a clamped node moves 3% of what a free
// tip does (the ninth point of the bicycle forks was added "to check the
// stiffness of the locking system", chapter 6), so no DOF is an exact node.
// Every specimen with a 3-D mesh also gets three out-of-band completion modes
// (one per axis, above 2.5 x its highest tabulated frequency) so that every
// DOF of the mesh responds.

#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/result.h"
#include "core/geometry/mesh_templates.h"
#include "devices/sim/specimen_catalogue.h"

namespace mozzi::devices::sim {

struct SpatialShapes {
  // dofs x modes over the template's measurement DOFs: the tabulated modes in
  // catalogue order, then the completion modes; each column scaled to a
  // largest component of 1 and positive at the driving point.
  core::Matrix shapes;
  std::vector<std::string> descriptions;  // per column
  std::size_t tabulatedModes = 0;
  Eigen::Index drivingDof = 0;  // row of the thesis's hammer / static load point
};

// The template of a catalogue specimen ("" when it has none).
std::string templateKeyFor(const SpecimenEntry& entry);

core::Result<SpatialShapes> spatialShapes(const SpecimenEntry& entry, const core::geometry::MeshTemplate& mesh);

}  // namespace mozzi::devices::sim
