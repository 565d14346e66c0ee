#include "core/geometry/mesh_edit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <set>
#include <type_traits>

namespace mozzi::core::geometry {
namespace {

using io::MeshDocument;
using io::SlavedDof;
using io::StoredCoordinateSystem;
using io::StoredFace;
using io::StoredLine;
using io::StoredNode;

bool equal(const StoredCoordinateSystem& a, const StoredCoordinateSystem& b) {
  return io::sameCoordinateSystem(a, b);
}
bool equal(const StoredNode& a, const StoredNode& b) {
  return io::sameNode(a, b);
}
bool equal(const StoredLine& a, const StoredLine& b) {
  return io::sameLine(a, b);
}
bool equal(const StoredFace& a, const StoredFace& b) {
  return io::sameFace(a, b);
}
bool equal(const Dof& a, const Dof& b) {
  return a == b;
}
bool equal(const SlavedDof& a, const SlavedDof& b) {
  return a == b;
}

std::vector<StoredCoordinateSystem>& list(MeshDocument& d, const ListChange<StoredCoordinateSystem>&) {
  return d.mesh.coordinateSystems;
}
std::vector<StoredNode>& list(MeshDocument& d, const ListChange<StoredNode>&) {
  return d.mesh.nodes;
}
std::vector<StoredLine>& list(MeshDocument& d, const ListChange<StoredLine>&) {
  return d.mesh.lines;
}
std::vector<StoredFace>& list(MeshDocument& d, const ListChange<StoredFace>&) {
  return d.mesh.faces;
}
std::vector<Dof>& list(MeshDocument& d, const ListChange<Dof>&) {
  return d.measurementDofs;
}
std::vector<SlavedDof>& list(MeshDocument& d, const ListChange<SlavedDof>&) {
  return d.slaves;
}

const char* listName(const ListChange<StoredCoordinateSystem>&) {
  return "coordinate system";
}
const char* listName(const ListChange<StoredNode>&) {
  return "node";
}
const char* listName(const ListChange<StoredLine>&) {
  return "line";
}
const char* listName(const ListChange<StoredFace>&) {
  return "face";
}
const char* listName(const ListChange<Dof>&) {
  return "measurement DOF";
}
const char* listName(const ListChange<SlavedDof>&) {
  return "slave rule";
}

template <class T>
Result<void> applyOne(MeshDocument& d, const ListChange<T>& op) {
  auto& items = list(d, op);
  const std::string where = std::string(listName(op)) + " " + std::to_string(op.index + 1);
  if (!op.before && !op.after) return makeError(ErrorCode::InvalidArgument, "empty edit", where);
  if (!op.before) {
    if (op.index > items.size()) return makeError(ErrorCode::InvalidArgument, "insert past the end", where);
    items.insert(items.begin() + static_cast<std::ptrdiff_t>(op.index), *op.after);
    return {};
  }
  if (op.index >= items.size()) return makeError(ErrorCode::InvalidArgument, "no such item", where);
  if (!equal(items[op.index], *op.before)) {
    return makeError(ErrorCode::InvalidArgument, "the document changed since the edit was planned", where);
  }
  if (!op.after) {
    items.erase(items.begin() + static_cast<std::ptrdiff_t>(op.index));
  } else {
    items[op.index] = *op.after;
  }
  return {};
}

template <class T>
EditOp set(std::size_t index, const T& before, const T& after) {
  return ListChange<T>{index, before, after};
}
template <class T>
EditOp removal(std::size_t index, const T& before) {
  return ListChange<T>{index, before, std::nullopt};
}
template <class T>
EditOp insertion(std::size_t index, const T& after) {
  return ListChange<T>{index, std::nullopt, after};
}

Error notFound(int label) {
  return makeError(ErrorCode::NotFound, "the mesh has no node " + std::to_string(label),
                   "node " + std::to_string(label));
}

const StoredCoordinateSystem* findCs(const MeshDocument& d, int label) {
  for (const auto& cs : d.mesh.coordinateSystems)
    if (cs.label == label) return &cs;
  return nullptr;
}

Result<void> checkSystems(const MeshDocument& d, const StoredNode& node) {
  for (int cs : {node.definitionCs, node.displacementCs}) {
    if (cs != 0 && !findCs(d, cs)) {
      return makeError(ErrorCode::NotFound,
                       "node " + std::to_string(node.label) + " names coordinate system " + std::to_string(cs) +
                           ", which the mesh does not have",
                       "node " + std::to_string(node.label));
    }
  }
  if (!node.position.allFinite()) {
    return makeError(ErrorCode::InvalidArgument, "coordinates must be finite", "node " + std::to_string(node.label));
  }
  return {};
}

bool dofNamesNode(const Dof& dof, const std::set<int>& labels) {
  return labels.count(dof.node) > 0;
}

bool slaveNamesNode(const SlavedDof& s, const std::set<int>& labels) {
  if (labels.count(s.slave.node)) return true;
  for (const auto& m : s.masters)
    if (labels.count(m.first.node)) return true;
  return false;
}

int mapLabel(int label, const std::map<int, int>& map) {
  const auto it = map.find(label);
  return it == map.end() ? label : it->second;
}

// The set ops that relabel nodes by `map` (old -> new) everywhere.
MeshEdit relabel(const MeshDocument& d, const std::map<int, int>& map, std::string description) {
  MeshEdit e;
  e.description = std::move(description);
  for (std::size_t i = 0; i < d.mesh.nodes.size(); ++i) {
    StoredNode n = d.mesh.nodes[i];
    n.label = mapLabel(n.label, map);
    if (n.label != d.mesh.nodes[i].label) e.ops.push_back(set(i, d.mesh.nodes[i], n));
  }
  for (std::size_t i = 0; i < d.mesh.lines.size(); ++i) {
    StoredLine l = d.mesh.lines[i];
    l.nodeA = mapLabel(l.nodeA, map);
    l.nodeB = mapLabel(l.nodeB, map);
    if (!io::sameLine(l, d.mesh.lines[i])) e.ops.push_back(set(i, d.mesh.lines[i], l));
  }
  for (std::size_t i = 0; i < d.mesh.faces.size(); ++i) {
    StoredFace f = d.mesh.faces[i];
    f.nodeA = mapLabel(f.nodeA, map);
    f.nodeB = mapLabel(f.nodeB, map);
    f.nodeC = mapLabel(f.nodeC, map);
    if (f.nodeD != 0) f.nodeD = mapLabel(f.nodeD, map);
    if (!io::sameFace(f, d.mesh.faces[i])) e.ops.push_back(set(i, d.mesh.faces[i], f));
  }
  for (std::size_t i = 0; i < d.measurementDofs.size(); ++i) {
    Dof dof = d.measurementDofs[i];
    dof.node = mapLabel(dof.node, map);
    if (dof != d.measurementDofs[i]) e.ops.push_back(set(i, d.measurementDofs[i], dof));
  }
  for (std::size_t i = 0; i < d.slaves.size(); ++i) {
    SlavedDof s = d.slaves[i];
    s.slave.node = mapLabel(s.slave.node, map);
    for (auto& m : s.masters) m.first.node = mapLabel(m.first.node, map);
    if (!(s == d.slaves[i])) e.ops.push_back(set(i, d.slaves[i], s));
  }
  return e;
}

// Removal ops, highest index first, for the items of `items` that `doomed` picks.
template <class T, class Pred>
void removeWhere(const std::vector<T>& items, Pred doomed, std::vector<EditOp>& ops) {
  for (std::size_t i = items.size(); i-- > 0;)
    if (doomed(items[i])) ops.push_back(removal(i, items[i]));
}

std::set<int> nodeLabels(const MeshDocument& d) {
  std::set<int> labels;
  for (const auto& n : d.mesh.nodes) labels.insert(n.label);
  return labels;
}

Result<void> checkSlaveRules(const MeshDocument& d) {
  const std::set<int> labels = nodeLabels(d);
  std::map<Dof, const SlavedDof*> bySlave;
  for (const auto& s : d.slaves) {
    const std::string where = "slave " + formatDof(s.slave);
    if (!labels.count(s.slave.node)) return makeError(ErrorCode::NotFound, "the slave node is not in the mesh", where);
    if (std::find(d.measurementDofs.begin(), d.measurementDofs.end(), s.slave) != d.measurementDofs.end()) {
      return makeError(ErrorCode::InvalidArgument, "a measured DOF cannot be a slave", where);
    }
    if (s.masters.empty()) return makeError(ErrorCode::InvalidArgument, "a slave needs at least one master", where);
    for (const auto& m : s.masters) {
      if (!labels.count(m.first.node)) {
        return makeError(ErrorCode::NotFound, "master " + formatDof(m.first) + " is not on a node of the mesh", where);
      }
      if (!std::isfinite(m.second)) return makeError(ErrorCode::InvalidArgument, "weights must be finite", where);
      if (m.first == s.slave) return makeError(ErrorCode::InvalidArgument, "a DOF cannot be its own master", where);
    }
    if (!bySlave.emplace(s.slave, &s).second) {
      return makeError(ErrorCode::InvalidArgument, "two rules for the same slave", where);
    }
  }
  // Cycle check: depth-first over slave -> master edges among slaves.
  std::map<Dof, int> state;  // 0 unseen, 1 on the path, 2 done
  std::function<Result<void>(const Dof&)> visit = [&](const Dof& dof) -> Result<void> {
    const auto it = bySlave.find(dof);
    if (it == bySlave.end()) return {};
    int& st = state[dof];
    if (st == 1) return makeError(ErrorCode::InvalidArgument, "slave rules form a cycle", "slave " + formatDof(dof));
    if (st == 2) return {};
    st = 1;
    for (const auto& m : it->second->masters) MOZZI_TRY(visit(m.first));
    state[dof] = 2;
    return {};
  };
  for (const auto& s : d.slaves) MOZZI_TRY(visit(s.slave));
  return {};
}

// Deletes the rows at `indices` (0-based, repeats ignored) of a list of the
// mesh (lines, faces), the last first so that each removal's index holds when
// the ops run in order; an index past the end is an error naming it 1-based.
template <class Row>
Result<MeshEdit> planDeleteRows(const std::vector<Row>& rows, std::vector<std::size_t> indices, const char* noun) {
  std::sort(indices.begin(), indices.end());
  indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
  MeshEdit e;
  e.description = "delete " + std::to_string(indices.size()) + " " + noun + "(s)";
  for (auto it = indices.rbegin(); it != indices.rend(); ++it) {
    if (*it >= rows.size()) {
      return makeError(ErrorCode::NotFound, std::string("no such ") + noun, noun + (" " + std::to_string(*it + 1)));
    }
    e.ops.push_back(removal(*it, rows[*it]));
  }
  return e;
}

}  // namespace

// GCC 12 at -O3 reports the optionals copied here as maybe-uninitialized
// (a known false positive with std::optional of aggregates); they are copies
// of engaged or disengaged optionals, never read uninitialised.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
MeshEdit inverse(const MeshEdit& edit) {
  MeshEdit out;
  out.description = edit.description;
  out.ops.reserve(edit.ops.size());
  for (auto it = edit.ops.rbegin(); it != edit.ops.rend(); ++it) {
    out.ops.push_back(std::visit(
        [](const auto& op) -> EditOp {
          using Change = std::decay_t<decltype(op)>;
          return Change{op.index, op.after, op.before};
        },
        *it));
  }
  return out;
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

Result<void> apply(MeshDocument& document, const MeshEdit& edit) {
  MeshDocument work = document;
  for (std::size_t i = 0; i < edit.ops.size(); ++i) {
    auto r = std::visit([&](const auto& op) { return applyOne(work, op); }, edit.ops[i]);
    if (!r) {
      Error e = r.error();
      e.message = "cannot " + edit.description + ": " + e.message;
      return e;
    }
  }
  document = std::move(work);
  return {};
}

std::optional<std::size_t> nodeIndex(const MeshDocument& document, int label) {
  for (std::size_t i = 0; i < document.mesh.nodes.size(); ++i)
    if (document.mesh.nodes[i].label == label) return i;
  return std::nullopt;
}

int nextFreeLabel(const MeshDocument& document) {
  int top = 0;
  for (const auto& n : document.mesh.nodes) top = std::max(top, n.label);
  return top + 1;
}

Result<MeshEdit> planAddNode(const MeshDocument& document, StoredNode node) {
  if (node.label == 0) node.label = nextFreeLabel(document);
  if (node.label < 0) return makeError(ErrorCode::InvalidArgument, "node labels are positive", "new node");
  if (nodeIndex(document, node.label)) {
    return makeError(ErrorCode::InvalidArgument, "node " + std::to_string(node.label) + " already exists",
                     "node " + std::to_string(node.label));
  }
  MOZZI_TRY(checkSystems(document, node));
  node.id = 0;
  MeshEdit e;
  e.description = "add node " + std::to_string(node.label);
  e.ops.push_back(insertion(document.mesh.nodes.size(), node));
  return e;
}

Result<MeshEdit> planSetNode(const MeshDocument& document, int label, const StoredNode& node) {
  const auto index = nodeIndex(document, label);
  if (!index) return notFound(label);
  if (node.label != label) {
    return makeError(ErrorCode::InvalidArgument, "changing a label is a renumber", "node " + std::to_string(label));
  }
  MOZZI_TRY(checkSystems(document, node));
  MeshEdit e;
  e.description = "edit node " + std::to_string(label);
  StoredNode after = node;
  after.id = document.mesh.nodes[*index].id;
  if (!io::sameNode(after, document.mesh.nodes[*index]))
    e.ops.push_back(set(*index, document.mesh.nodes[*index], after));
  return e;
}

Result<MeshEdit> planMoveNodes(const MeshDocument& document, const std::vector<int>& labels, const Vector3& delta) {
  if (!delta.allFinite()) return makeError(ErrorCode::InvalidArgument, "the move must be finite", "move");
  MeshEdit e;
  e.description = labels.size() == 1 ? "move node " + std::to_string(labels.front())
                                     : "move " + std::to_string(labels.size()) + " nodes";
  std::set<int> seen;
  for (int label : labels) {
    if (!seen.insert(label).second) continue;
    const auto index = nodeIndex(document, label);
    if (!index) return notFound(label);
    const StoredNode& before = document.mesh.nodes[*index];
    if (before.definitionCs != 0) {
      const auto* cs = findCs(document, before.definitionCs);
      if (cs && cs->kind != StoredCoordinateSystem::Kind::Cartesian) {
        return makeError(ErrorCode::Unsupported,
                         "moving by a distance needs a cartesian definition system; edit the coordinates instead",
                         "node " + std::to_string(label));
      }
    }
    StoredNode after = before;
    after.position += delta;
    e.ops.push_back(set(*index, before, after));
  }
  return e;
}

Result<MeshEdit> planDeleteNodes(const MeshDocument& document, const std::vector<int>& labels) {
  std::set<int> doomed;
  for (int label : labels) {
    if (!nodeIndex(document, label)) return notFound(label);
    doomed.insert(label);
  }
  MeshEdit e;
  e.description = doomed.size() == 1 ? "delete node " + std::to_string(*doomed.begin())
                                     : "delete " + std::to_string(doomed.size()) + " nodes";
  removeWhere(
      document.slaves, [&](const SlavedDof& s) { return slaveNamesNode(s, doomed); }, e.ops);
  removeWhere(
      document.measurementDofs, [&](const Dof& d) { return dofNamesNode(d, doomed); }, e.ops);
  removeWhere(
      document.mesh.faces,
      [&](const StoredFace& f) {
        return doomed.count(f.nodeA) || doomed.count(f.nodeB) || doomed.count(f.nodeC) ||
               (f.nodeD != 0 && doomed.count(f.nodeD));
      },
      e.ops);
  removeWhere(
      document.mesh.lines, [&](const StoredLine& l) { return doomed.count(l.nodeA) || doomed.count(l.nodeB); }, e.ops);
  removeWhere(
      document.mesh.nodes, [&](const StoredNode& n) { return doomed.count(n.label) > 0; }, e.ops);
  return e;
}

Result<MeshEdit> planRenumber(const MeshDocument& document, int from, int to) {
  if (!nodeIndex(document, from)) return notFound(from);
  if (to <= 0) return makeError(ErrorCode::InvalidArgument, "node labels are positive", "node " + std::to_string(to));
  if (from == to) return MeshEdit{"renumber node " + std::to_string(from), {}};
  if (nodeIndex(document, to)) {
    return makeError(ErrorCode::InvalidArgument, "node " + std::to_string(to) + " already exists",
                     "renumber node " + std::to_string(from));
  }
  return relabel(document, {{from, to}}, "renumber node " + std::to_string(from) + " to " + std::to_string(to));
}

Result<MeshEdit> planRenumberAll(const MeshDocument& document, int first, int step) {
  if (first <= 0 || step <= 0) {
    return makeError(ErrorCode::InvalidArgument, "the first label and the step must be positive", "renumber");
  }
  const long long last = first + static_cast<long long>(step) * static_cast<long long>(document.mesh.nodes.size());
  if (last > 2147483647LL) return makeError(ErrorCode::InvalidArgument, "labels would exceed 2^31 - 1", "renumber");
  std::map<int, int> map;
  int label = first;
  for (const auto& n : document.mesh.nodes) {
    map[n.label] = label;
    label += step;
  }
  return relabel(document, map, "renumber all nodes from " + std::to_string(first));
}

Result<MeshEdit> planSnapToGrid(const MeshDocument& document, const std::vector<int>& labels, double grid) {
  if (!(grid > 0.0) || !std::isfinite(grid)) {
    return makeError(ErrorCode::InvalidArgument, "the grid spacing must be positive", "snap to grid");
  }
  auto snap = [grid](double v) { return std::round(v / grid) * grid; };
  MeshEdit e;
  e.description = "snap " + std::to_string(labels.size()) + " node(s) to the grid";
  std::set<int> seen;
  for (int label : labels) {
    if (!seen.insert(label).second) continue;
    const auto index = nodeIndex(document, label);
    if (!index) return notFound(label);
    const StoredNode& before = document.mesh.nodes[*index];
    StoredNode after = before;
    const auto* cs = before.definitionCs == 0 ? nullptr : findCs(document, before.definitionCs);
    const auto kind = cs ? cs->kind : StoredCoordinateSystem::Kind::Cartesian;
    after.position[0] = snap(before.position[0]);  // x or r
    if (kind == StoredCoordinateSystem::Kind::Cartesian) after.position[1] = snap(before.position[1]);
    if (kind != StoredCoordinateSystem::Kind::Spherical) after.position[2] = snap(before.position[2]);  // z
    if (!io::sameNode(before, after)) e.ops.push_back(set(*index, before, after));
  }
  return e;
}

Result<MeshEdit> planAddLine(const MeshDocument& document, int nodeA, int nodeB) {
  if (!nodeIndex(document, nodeA)) return notFound(nodeA);
  if (!nodeIndex(document, nodeB)) return notFound(nodeB);
  const std::string where = "line " + std::to_string(nodeA) + "-" + std::to_string(nodeB);
  if (nodeA == nodeB) return makeError(ErrorCode::InvalidArgument, "a line joins two different nodes", where);
  for (const auto& l : document.mesh.lines) {
    if ((l.nodeA == nodeA && l.nodeB == nodeB) || (l.nodeA == nodeB && l.nodeB == nodeA)) {
      return makeError(ErrorCode::InvalidArgument, "the mesh already has this line", where);
    }
  }
  MeshEdit e;
  e.description = "add " + where;
  e.ops.push_back(insertion(document.mesh.lines.size(), StoredLine{nodeA, nodeB}));
  return e;
}

Result<MeshEdit> planDeleteLines(const MeshDocument& document, std::vector<std::size_t> indices) {
  return planDeleteRows(document.mesh.lines, std::move(indices), "line");
}

Result<MeshEdit> planAddFace(const MeshDocument& document, const StoredFace& face) {
  std::vector<int> nodes = {face.nodeA, face.nodeB, face.nodeC};
  if (face.nodeD != 0) nodes.push_back(face.nodeD);
  for (int n : nodes)
    if (!nodeIndex(document, n)) return notFound(n);
  std::set<int> distinct(nodes.begin(), nodes.end());
  if (distinct.size() != nodes.size()) {
    return makeError(ErrorCode::InvalidArgument, "a face needs distinct nodes", "new face");
  }
  MeshEdit e;
  e.description = nodes.size() == 3 ? "add triangle" : "add quadrilateral";
  e.ops.push_back(insertion(document.mesh.faces.size(), face));
  return e;
}

Result<MeshEdit> planDeleteFaces(const MeshDocument& document, std::vector<std::size_t> indices) {
  return planDeleteRows(document.mesh.faces, std::move(indices), "face");
}

Result<MeshEdit> planSetNodeDofs(const MeshDocument& document, int label, const std::vector<Dof>& dofs) {
  if (!nodeIndex(document, label)) return notFound(label);
  std::set<Dof> wanted;
  for (const auto& d : dofs) {
    if (d.node != label) {
      return makeError(ErrorCode::InvalidArgument, "DOF " + formatDof(d) + " is not on node " + std::to_string(label),
                       "node " + std::to_string(label));
    }
    Dof flipped = d;
    flipped.negative = !d.negative;
    if (!wanted.insert(d).second || wanted.count(flipped)) {
      return makeError(ErrorCode::InvalidArgument, "direction " + formatDof(d) + " given twice",
                       "node " + std::to_string(label));
    }
  }
  for (const auto& s : document.slaves) {
    if (wanted.count(s.slave)) {
      return makeError(ErrorCode::InvalidArgument, formatDof(s.slave) + " is slaved; remove its rule first",
                       "node " + std::to_string(label));
    }
  }
  MeshEdit e;
  e.description = "set the measurement DOFs of node " + std::to_string(label);
  std::set<Dof> kept;
  removeWhere(
      document.measurementDofs,
      [&](const Dof& d) {
        if (d.node != label) return false;
        if (wanted.count(d)) {
          kept.insert(d);
          return false;
        }
        return true;
      },
      e.ops);
  const std::size_t removed = e.ops.size();
  std::size_t end = document.measurementDofs.size() - removed;
  for (const auto& d : dofs) {
    if (kept.count(d)) continue;
    e.ops.push_back(insertion(end++, d));
  }
  return e;
}

Result<MeshEdit> planAddCoordinateSystem(const MeshDocument& document, StoredCoordinateSystem cs) {
  if (cs.label == 0) {
    int top = 0;
    for (const auto& c : document.mesh.coordinateSystems) top = std::max(top, c.label);
    cs.label = top + 1;
  }
  const std::string where = "coordinate system " + std::to_string(cs.label);
  if (cs.label < 0) return makeError(ErrorCode::InvalidArgument, "labels are positive (0 is global)", where);
  if (findCs(document, cs.label)) return makeError(ErrorCode::InvalidArgument, "the label is in use", where);
  if (!cs.origin.allFinite() || !cs.rotation.allFinite()) {
    return makeError(ErrorCode::InvalidArgument, "origin and axes must be finite", where);
  }
  cs.id = 0;
  MeshEdit e;
  e.description = "add " + where;
  e.ops.push_back(insertion(document.mesh.coordinateSystems.size(), cs));
  return e;
}

Result<MeshEdit> planSetCoordinateSystem(const MeshDocument& document, int label, const StoredCoordinateSystem& cs) {
  const std::string where = "coordinate system " + std::to_string(label);
  for (std::size_t i = 0; i < document.mesh.coordinateSystems.size(); ++i) {
    const auto& before = document.mesh.coordinateSystems[i];
    if (before.label != label) continue;
    if (cs.label != label) return makeError(ErrorCode::InvalidArgument, "the label cannot change", where);
    if (!cs.origin.allFinite() || !cs.rotation.allFinite()) {
      return makeError(ErrorCode::InvalidArgument, "origin and axes must be finite", where);
    }
    MeshEdit e;
    e.description = "edit " + where;
    StoredCoordinateSystem after = cs;
    after.id = before.id;
    if (!io::sameCoordinateSystem(before, after)) e.ops.push_back(set(i, before, after));
    return e;
  }
  return makeError(ErrorCode::NotFound, "the mesh has no such coordinate system", where);
}

Result<MeshEdit> planDeleteCoordinateSystem(const MeshDocument& document, int label) {
  const std::string where = "coordinate system " + std::to_string(label);
  for (const auto& n : document.mesh.nodes) {
    if (n.definitionCs == label || n.displacementCs == label) {
      return makeError(ErrorCode::InvalidArgument, "node " + std::to_string(n.label) + " uses it", where);
    }
  }
  MeshEdit e;
  e.description = "delete " + where;
  removeWhere(
      document.mesh.coordinateSystems, [&](const StoredCoordinateSystem& c) { return c.label == label; }, e.ops);
  if (e.ops.empty()) return makeError(ErrorCode::NotFound, "the mesh has no such coordinate system", where);
  return e;
}

Result<MeshEdit> planSetSlave(const MeshDocument& document, const SlavedDof& rule) {
  MeshDocument trial = document;
  MeshEdit e;
  e.description = "slave " + formatDof(rule.slave);
  bool replaced = false;
  for (std::size_t i = 0; i < document.slaves.size(); ++i) {
    if (document.slaves[i].slave == rule.slave) {
      if (document.slaves[i] == rule) return e;
      e.ops.push_back(set(i, document.slaves[i], rule));
      trial.slaves[i] = rule;
      replaced = true;
    }
  }
  if (!replaced) {
    e.ops.push_back(insertion(document.slaves.size(), rule));
    trial.slaves.push_back(rule);
  }
  MOZZI_TRY(checkSlaveRules(trial));
  return e;
}

Result<MeshEdit> planRemoveSlave(const MeshDocument& document, const Dof& slave) {
  MeshEdit e;
  e.description = "remove the rule of " + formatDof(slave);
  removeWhere(
      document.slaves, [&](const SlavedDof& s) { return s.slave == slave; }, e.ops);
  if (e.ops.empty()) return makeError(ErrorCode::NotFound, "no rule for this DOF", "slave " + formatDof(slave));
  return e;
}

MeshEdit planReplace(const MeshDocument& document, const MeshDocument& replacement, const std::string& description) {
  MeshEdit e;
  e.description = description;
  auto all = [](const auto&) { return true; };
  removeWhere(document.slaves, all, e.ops);
  removeWhere(document.measurementDofs, all, e.ops);
  removeWhere(document.mesh.faces, all, e.ops);
  removeWhere(document.mesh.lines, all, e.ops);
  removeWhere(document.mesh.nodes, all, e.ops);
  removeWhere(document.mesh.coordinateSystems, all, e.ops);
  auto insertAll = [&e](const auto& items) {
    for (std::size_t i = 0; i < items.size(); ++i) e.ops.push_back(insertion(i, items[i]));
  };
  insertAll(replacement.mesh.coordinateSystems);
  insertAll(replacement.mesh.nodes);
  insertAll(replacement.mesh.lines);
  insertAll(replacement.mesh.faces);
  insertAll(replacement.measurementDofs);
  insertAll(replacement.slaves);
  return e;
}

Result<void> validate(const MeshDocument& document) {
  std::set<int> systems;
  for (const auto& cs : document.mesh.coordinateSystems) {
    const std::string where = "coordinate system " + std::to_string(cs.label);
    if (cs.label <= 0) return makeError(ErrorCode::InvalidArgument, "labels are positive (0 is global)", where);
    if (!systems.insert(cs.label).second) return makeError(ErrorCode::InvalidArgument, "label used twice", where);
    if (!cs.origin.allFinite() || !cs.rotation.allFinite()) {
      return makeError(ErrorCode::InvalidArgument, "origin and axes must be finite", where);
    }
  }
  std::set<int> labels;
  for (const auto& n : document.mesh.nodes) {
    const std::string where = "node " + std::to_string(n.label);
    if (n.label <= 0) return makeError(ErrorCode::InvalidArgument, "node labels are positive", where);
    if (!labels.insert(n.label).second) return makeError(ErrorCode::InvalidArgument, "label used twice", where);
    MOZZI_TRY(checkSystems(document, n));
  }
  for (std::size_t i = 0; i < document.mesh.lines.size(); ++i) {
    const auto& l = document.mesh.lines[i];
    const std::string where =
        "line " + std::to_string(i + 1) + " (" + std::to_string(l.nodeA) + "-" + std::to_string(l.nodeB) + ")";
    if (!labels.count(l.nodeA) || !labels.count(l.nodeB)) {
      return makeError(ErrorCode::NotFound, "names a node the mesh does not have", where);
    }
    if (l.nodeA == l.nodeB) return makeError(ErrorCode::InvalidArgument, "joins a node to itself", where);
  }
  for (std::size_t i = 0; i < document.mesh.faces.size(); ++i) {
    const auto& f = document.mesh.faces[i];
    const std::string where = "face " + std::to_string(i + 1);
    std::vector<int> nodes = {f.nodeA, f.nodeB, f.nodeC};
    if (f.nodeD != 0) nodes.push_back(f.nodeD);
    for (int n : nodes)
      if (!labels.count(n)) {
        return makeError(ErrorCode::NotFound, "names node " + std::to_string(n) + ", which the mesh does not have",
                         where);
      }
    if (std::set<int>(nodes.begin(), nodes.end()).size() != nodes.size()) {
      return makeError(ErrorCode::InvalidArgument, "repeats a node", where);
    }
  }
  std::set<Dof> dofs;
  for (const auto& d : document.measurementDofs) {
    const std::string where = "measurement DOF " + formatDof(d);
    if (!labels.count(d.node)) return makeError(ErrorCode::NotFound, "names a node the mesh does not have", where);
    if (!dofs.insert(d).second) return makeError(ErrorCode::InvalidArgument, "listed twice", where);
  }
  return checkSlaveRules(document);
}

std::vector<Orphan> orphanedBy(const MeshDocument& before, const MeshDocument& after,
                               const std::vector<MeasuredData>& data) {
  const std::set<int> had = nodeLabels(before);
  const std::set<int> has = nodeLabels(after);
  std::vector<Orphan> out;
  for (const auto& item : data) {
    Orphan o;
    o.name = item.name;
    std::set<Dof> seen;
    for (const auto& d : item.dofs)
      if (had.count(d.node) && !has.count(d.node) && seen.insert(d).second) o.dofs.push_back(d);
    if (!o.dofs.empty()) out.push_back(std::move(o));
  }
  return out;
}

std::string describeOrphans(const std::vector<Orphan>& orphans) {
  std::string text;
  for (const auto& o : orphans) {
    if (!text.empty()) text += '\n';
    text += o.name + " (";
    const std::size_t shown = std::min<std::size_t>(o.dofs.size(), 4);
    for (std::size_t i = 0; i < shown; ++i) {
      if (i > 0) text += ", ";
      text += formatDof(o.dofs[i]);
    }
    if (o.dofs.size() > shown) text += " and " + std::to_string(o.dofs.size() - shown) + " more";
    text += ")";
  }
  return text;
}

}  // namespace mozzi::core::geometry
