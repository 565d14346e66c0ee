#pragma once
// Edits of a measurement mesh as data: every edit the mesh editor offers (add,
// move, delete, renumber, snap, lines, faces, DOFs, coordinate systems, slave
// rules, replace from a template or a file) is planned here as a MeshEdit, a
// list of primitive list changes, each with an exact inverse. The editor's undo
// stack applies an edit and its inverse; nothing here knows about Qt.
//
// Planning checks the edit against the document (labels exist, stay unique,
// a line joins two different nodes, ...) and returns an error naming the item;
// apply() then cannot fail on a document in the state the plan was made for.

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/common/result.h"
#include "core/io/mesh_document.h"

namespace mozzi::core::geometry {

// One item of one list inserted (before empty), removed (after empty) or
// replaced (both set) at `index`.
template <class T>
struct ListChange {
  std::size_t index = 0;
  std::optional<T> before;
  std::optional<T> after;
};

using EditOp =
    std::variant<ListChange<io::StoredCoordinateSystem>, ListChange<io::StoredNode>, ListChange<io::StoredLine>,
                 ListChange<io::StoredFace>, ListChange<Dof>, ListChange<io::SlavedDof>>;

struct MeshEdit {
  std::string description;  // "delete 3 nodes", for the undo history
  std::vector<EditOp> ops;  // applied in order
  bool empty() const { return ops.empty(); }
};

// The edit that undoes `edit` (ops reversed, before and after swapped).
MeshEdit inverse(const MeshEdit& edit);
// Applies the ops in order. An op whose index is out of range or whose
// `before` does not match the document is an error (the document is then left
// as it was before the call).
Result<void> apply(io::MeshDocument& document, const MeshEdit& edit);

// --- planning --------------------------------------------------------------------

// Index of the node with `label` in document.mesh.nodes, or nullopt.
std::optional<std::size_t> nodeIndex(const io::MeshDocument& document, int label);
// The smallest label above every label in use (1 for an empty mesh).
int nextFreeLabel(const io::MeshDocument& document);

// Adds a node (label 0: the next free label). The label must be new and the
// coordinate systems must exist.
Result<MeshEdit> planAddNode(const io::MeshDocument& document, io::StoredNode node);
// Replaces node `label` by `node` (coordinates, systems; a different label is a
// renumber and is refused here: use planRenumber).
Result<MeshEdit> planSetNode(const io::MeshDocument& document, int label, const io::StoredNode& node);
// Moves nodes by `delta` [m] in their definition system (cartesian systems only).
Result<MeshEdit> planMoveNodes(const io::MeshDocument& document, const std::vector<int>& labels, const Vector3& delta);
// Deletes nodes and everything that names them: lines, faces, measurement
// DOFs, slave rules in which they are slave or master.
Result<MeshEdit> planDeleteNodes(const io::MeshDocument& document, const std::vector<int>& labels);
// Gives node `from` the label `to` (unused), in lines, faces, DOFs and slaves too.
Result<MeshEdit> planRenumber(const io::MeshDocument& document, int from, int to);
// Labels first, first + step, ... in the current node order.
Result<MeshEdit> planRenumberAll(const io::MeshDocument& document, int first, int step);
// Rounds each coordinate to the nearest multiple of `grid` [m] (> 0) in the
// node's definition system; in cylindrical and spherical systems only the
// lengths (r, z; r) are rounded, angles are kept.
Result<MeshEdit> planSnapToGrid(const io::MeshDocument& document, const std::vector<int>& labels, double grid);

Result<MeshEdit> planAddLine(const io::MeshDocument& document, int nodeA, int nodeB);
Result<MeshEdit> planDeleteLines(const io::MeshDocument& document, std::vector<std::size_t> indices);
// Triangle (nodeD == 0) or quadrilateral of distinct existing nodes.
Result<MeshEdit> planAddFace(const io::MeshDocument& document, const io::StoredFace& face);
Result<MeshEdit> planDeleteFaces(const io::MeshDocument& document, std::vector<std::size_t> indices);

// Sets node `label`'s measurement DOFs to `dofs` (each naming that node, no
// duplicates); the node's other DOFs in the list keep their place.
Result<MeshEdit> planSetNodeDofs(const io::MeshDocument& document, int label, const std::vector<Dof>& dofs);

Result<MeshEdit> planAddCoordinateSystem(const io::MeshDocument& document, io::StoredCoordinateSystem cs);
Result<MeshEdit> planSetCoordinateSystem(const io::MeshDocument& document, int label,
                                         const io::StoredCoordinateSystem& cs);
// Refused while a node is defined or measured in the system (names the node).
Result<MeshEdit> planDeleteCoordinateSystem(const io::MeshDocument& document, int label);

// Adds or replaces the rule for `rule.slave` (slave node must exist, masters
// must exist, the slave must not be a measurement DOF, no cycle).
Result<MeshEdit> planSetSlave(const io::MeshDocument& document, const io::SlavedDof& rule);
Result<MeshEdit> planRemoveSlave(const io::MeshDocument& document, const Dof& slave);

// Replaces the whole document (start from a template, import a file).
MeshEdit planReplace(const io::MeshDocument& document, const io::MeshDocument& replacement,
                     const std::string& description);

// Checks a document as a whole: unique labels, systems exist, lines and faces
// name existing distinct nodes, DOFs name existing nodes, slaves valid. The
// error names the first offender.
Result<void> validate(const io::MeshDocument& document);

// --- text forms the editor's table cells use ----------------------------------------

// A node's measurement directions: "+X +Z", "X, Y, -Z", "" (none). Tokens are
// separated by blanks or commas; each is a direction with an optional sign.
Result<std::vector<Dof>> parseNodeDofs(int node, std::string_view text);
std::string formatNodeDofs(const std::vector<Dof>& dofs);  // "+X +Z"
// "5:+Z = 0.5 4:+Z + 0.5 6:+Z": slave, '=', then terms "[+|-][weight [*]] DOF"
// (weight 1 when omitted). Errors name the offending term.
Result<io::SlavedDof> parseSlaveRule(std::string_view text);
std::string formatSlaveRule(const io::SlavedDof& rule);

// --- measured data -----------------------------------------------------------------

// DOFs that a stored record refers to ("campaign 'Fork A' hits", "FRF set 3
// 'fork-a.uff'", "modal result 2 'PolyMAX'").
struct MeasuredData {
  std::string name;
  std::vector<Dof> dofs;
};

struct Orphan {
  std::string name;       // MeasuredData::name
  std::vector<Dof> dofs;  // its DOFs on nodes the edit removes or renumbers
};

// The measured data that would lose its nodes: DOFs whose node is in `before`
// and not in `after`. Empty when the edit is harmless.
std::vector<Orphan> orphanedBy(const io::MeshDocument& before, const io::MeshDocument& after,
                               const std::vector<MeasuredData>& data);
// "FRF set 'x' (21:+Z, 22:+Z and 3 more)"; one line per orphan.
std::string describeOrphans(const std::vector<Orphan>& orphans);

}  // namespace mozzi::core::geometry
