#pragma once
// Private to the mesh editor (mesh_editor.cpp, mesh_table_model.cpp): the
// model behind its node, line, face and coordinate-system tables.

#include <QAbstractTableModel>
#include <QString>

#include "core/io/project_records.h"

namespace mozzi {
namespace views {

class MeshEditor;

namespace mesh_editor {
inline constexpr double kMm = 1000.0;  // display lengths in millimetres
QString csKindName(core::io::StoredCoordinateSystem::Kind kind);
}  // namespace mesh_editor

// The tables: one model class, one kind of row per instance. Reads the
// editor's document; edits go through the editor's undo stack.
class MeshTableModel : public QAbstractTableModel {
 public:
  enum class Kind { Nodes, Lines, Faces, Systems };
  MeshTableModel(Kind kind, MeshEditor* editor);

  void reset();

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;

  QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

  Qt::ItemFlags flags(const QModelIndex& index) const override;

  QVariant data(const QModelIndex& index, int role) const override;

  bool setData(const QModelIndex& index, const QVariant& value, int role) override;

 private:
  // Display factor of coordinate `axis` of a node defined in system `cs`:
  // lengths in mm, angles of cylindrical and spherical systems in degrees as stored.
  double lengthScale(int cs, int axis) const;

  Kind kind_;
  MeshEditor* editor_;
};

}  // namespace views
}  // namespace mozzi
