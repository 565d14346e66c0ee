#pragma once
// The mesh editor on a specimen of the open project: reads the specimen's mesh
// and the data measured on it through the ProjectModel, writes the mesh back
// after every edit, undo and redo (ProjectModel::setMesh, so every other page
// hears meshChanged), and reloads when someone else changes the mesh.
//
// The project stores the geometry only: the measurement DOFs shown are those
// the specimen's hits, FRF sets and modal results name on the mesh's nodes, and
// slave rules live as long as the page (export the mesh CSV to keep them).

#include <QWidget>

#include "core/geometry/mesh_edit.h"

namespace mozzi {
namespace views {

class MeshEditor;
class ProjectModel;

class MeshEditorPage : public QWidget {
  Q_OBJECT
 public:
  MeshEditorPage(ProjectModel* model, qint64 specimenId, QWidget* parent = nullptr);
  MeshEditor* editor() const { return editor_; }
  qint64 specimenId() const { return specimenId_; }
  // Re-reads the mesh and the measured data from the project (drops the undo history).
  void reload();

  // What the project holds on this specimen's DOFs (hits per campaign, FRF
  // sets, modal results), for the orphan question.
  static std::vector<core::geometry::MeasuredData> measuredData(ProjectModel* model, qint64 specimenId);

 signals:
  void message(const QString& text);

 private:
  void save();

  ProjectModel* model_;
  qint64 specimenId_;
  MeshEditor* editor_ = nullptr;
  bool saving_ = false;
};

}  // namespace views
}  // namespace mozzi
