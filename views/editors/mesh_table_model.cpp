// The mesh editor's tables (views/editors/mesh_table_model.h).

#include "views/editors/mesh_table_model.h"

#include <QStringList>
#include <vector>

#include "core/geometry/mesh_edit.h"
#include "views/editors/mesh_editor.h"

namespace mozzi {
namespace views {

namespace geo = core::geometry;
using core::io::StoredCoordinateSystem;
using mesh_editor::csKindName;
using mesh_editor::kMm;

namespace mesh_editor {
QString csKindName(StoredCoordinateSystem::Kind kind) {
  switch (kind) {
    case StoredCoordinateSystem::Kind::Cartesian: return MeshEditor::tr("cartesian");
    case StoredCoordinateSystem::Kind::Cylindrical: return MeshEditor::tr("cylindrical");
    case StoredCoordinateSystem::Kind::Spherical: return MeshEditor::tr("spherical");
  }
  return {};
}
}  // namespace mesh_editor

MeshTableModel::MeshTableModel(Kind kind, MeshEditor* editor)
    : QAbstractTableModel(editor), kind_(kind), editor_(editor) {}

void MeshTableModel::reset() {
  beginResetModel();
  endResetModel();
}

int MeshTableModel::rowCount(const QModelIndex& parent) const {
  if (parent.isValid()) return 0;
  const auto& mesh = editor_->document().mesh;
  switch (kind_) {
    case Kind::Nodes: return static_cast<int>(mesh.nodes.size());
    case Kind::Lines: return static_cast<int>(mesh.lines.size());
    case Kind::Faces: return static_cast<int>(mesh.faces.size());
    case Kind::Systems: return static_cast<int>(mesh.coordinateSystems.size());
  }
  return 0;
}

int MeshTableModel::columnCount(const QModelIndex& parent) const {
  if (parent.isValid()) return 0;
  switch (kind_) {
    case Kind::Nodes: return 7;
    case Kind::Lines: return 2;
    case Kind::Faces: return 4;
    case Kind::Systems: return 7;
  }
  return 0;
}

QVariant MeshTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation == Qt::Vertical) {
    return role == Qt::DisplayRole ? QVariant(section + 1) : QVariant();
  }
  if (role == Qt::ToolTipRole && kind_ == Kind::Nodes && section >= 1 && section <= 3) {
    return MeshEditor::tr(
        "Coordinates in the node's definition system; in a cylindrical system r [mm], "
        "theta [deg], z [mm], in a spherical one r [mm], theta [deg], phi [deg]");
  }
  if (role != Qt::DisplayRole) return {};
  switch (kind_) {
    case Kind::Nodes: {
      const QString titles[] = {MeshEditor::tr("Node"),         MeshEditor::tr("X [mm]"),  MeshEditor::tr("Y [mm]"),
                                MeshEditor::tr("Z [mm]"),       MeshEditor::tr("Def. CS"), MeshEditor::tr("Disp. CS"),
                                MeshEditor::tr("Measured DOFs")};
      return titles[section];
    }
    case Kind::Lines: return section == 0 ? MeshEditor::tr("Node A") : MeshEditor::tr("Node B");
    case Kind::Faces: {
      const QString titles[] = {MeshEditor::tr("Node A"), MeshEditor::tr("Node B"), MeshEditor::tr("Node C"),
                                MeshEditor::tr("Node D")};
      return titles[section];
    }
    case Kind::Systems: {
      const QString titles[] = {MeshEditor::tr("CS"),
                                MeshEditor::tr("Name"),
                                MeshEditor::tr("Type"),
                                MeshEditor::tr("Origin X [mm]"),
                                MeshEditor::tr("Origin Y [mm]"),
                                MeshEditor::tr("Origin Z [mm]"),
                                MeshEditor::tr("Axes x | y | z")};
      return titles[section];
    }
  }
  return {};
}

Qt::ItemFlags MeshTableModel::flags(const QModelIndex& index) const {
  Qt::ItemFlags f = QAbstractTableModel::flags(index);
  if (kind_ == Kind::Nodes || (kind_ == Kind::Systems && index.column() >= 1 && index.column() <= 5)) {
    f |= Qt::ItemIsEditable;
  }
  return f;
}

QVariant MeshTableModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || (role != Qt::DisplayRole && role != Qt::EditRole)) return {};
  const auto& doc = editor_->document();
  const auto& mesh = doc.mesh;
  const int r = index.row(), c = index.column();
  const bool edit = role == Qt::EditRole;
  switch (kind_) {
    case Kind::Nodes: {
      const auto& n = mesh.nodes[static_cast<std::size_t>(r)];
      if (c == 0) return n.label;
      if (c >= 1 && c <= 3) {
        const double v = n.position[c - 1] * lengthScale(n.definitionCs, c - 1);
        return edit ? QVariant(v) : QVariant(QString::number(v, 'f', 3));
      }
      if (c == 4) return n.definitionCs;
      if (c == 5) return n.displacementCs;
      std::vector<core::Dof> dofs;
      for (const auto& d : doc.measurementDofs)
        if (d.node == n.label) dofs.push_back(d);
      return QString::fromStdString(geo::formatNodeDofs(dofs));
    }
    case Kind::Lines: {
      const auto& l = mesh.lines[static_cast<std::size_t>(r)];
      return c == 0 ? l.nodeA : l.nodeB;
    }
    case Kind::Faces: {
      const auto& f = mesh.faces[static_cast<std::size_t>(r)];
      const int v[] = {f.nodeA, f.nodeB, f.nodeC, f.nodeD};
      return c == 3 && v[3] == 0 ? QVariant(QString()) : QVariant(v[c]);
    }
    case Kind::Systems: {
      const auto& cs = mesh.coordinateSystems[static_cast<std::size_t>(r)];
      if (c == 0) return cs.label;
      if (c == 1) return QString::fromStdString(cs.name);
      if (c == 2) return edit ? QVariant(static_cast<int>(cs.kind)) : QVariant(csKindName(cs.kind));
      if (c >= 3 && c <= 5) {
        const double v = cs.origin[c - 3] * kMm;
        return edit ? QVariant(v) : QVariant(QString::number(v, 'f', 3));
      }
      QStringList axes;
      for (int k = 0; k < 3; ++k) {
        axes << QStringLiteral("(%1, %2, %3)")
                    .arg(cs.rotation(0, k), 0, 'f', 3)
                    .arg(cs.rotation(1, k), 0, 'f', 3)
                    .arg(cs.rotation(2, k), 0, 'f', 3);
      }
      return axes.join(QStringLiteral(" | "));
    }
  }
  return {};
}

bool MeshTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
  if (!index.isValid() || role != Qt::EditRole) return false;
  const auto& doc = editor_->document();
  const int r = index.row(), c = index.column();
  bool ok = true;
  if (kind_ == Kind::Nodes) {
    const auto node = doc.mesh.nodes[static_cast<std::size_t>(r)];
    if (c == 0) {
      const int to = value.toInt(&ok);
      return ok && editor_->renumberNode(node.label, to);
    }
    if (c == 6) return editor_->setNodeDofs(node.label, value.toString());
    auto after = node;
    if (c >= 1 && c <= 3) {
      const double v = value.toDouble(&ok);
      if (!ok) return false;
      after.position[c - 1] = v / lengthScale(node.definitionCs, c - 1);
    } else {
      const int cs = value.toInt(&ok);
      if (!ok) return false;
      (c == 4 ? after.definitionCs : after.displacementCs) = cs;
    }
    return editor_->pushEdit(geo::planSetNode(doc, node.label, after));
  }
  if (kind_ == Kind::Systems) {
    auto cs = doc.mesh.coordinateSystems[static_cast<std::size_t>(r)];
    const int label = cs.label;
    if (c == 1) {
      cs.name = value.toString().toStdString();
    } else if (c == 2) {
      const int kind = value.toInt(&ok);
      if (!ok || kind < 0 || kind > 2) return false;
      cs.kind = static_cast<StoredCoordinateSystem::Kind>(kind);
    } else if (c >= 3 && c <= 5) {
      const double v = value.toDouble(&ok);
      if (!ok) return false;
      cs.origin[c - 3] = v / kMm;
    } else {
      return false;
    }
    return editor_->pushEdit(geo::planSetCoordinateSystem(doc, label, cs));
  }
  return false;
}

double MeshTableModel::lengthScale(int cs, int axis) const {
  if (cs == 0) return kMm;
  for (const auto& s : editor_->document().mesh.coordinateSystems) {
    if (s.label != cs) continue;
    if (s.kind == StoredCoordinateSystem::Kind::Cylindrical && axis == 1) return 1.0;
    if (s.kind == StoredCoordinateSystem::Kind::Spherical && axis >= 1) return 1.0;
  }
  return kMm;
}

}  // namespace views
}  // namespace mozzi
