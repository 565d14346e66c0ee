#pragma once
// The measurement-mesh editor: tables of nodes (with their measurement DOFs),
// trace lines, faces, coordinate systems and slave rules beside the 3-D view,
// kept in sync (select in one, see it in the other). Every edit is planned by
// core::geometry (mesh_edit.h) and pushed on a QUndoStack, so undo and redo
// cover all of them. An edit that would take nodes away from measured data
// (hits, FRFs, mode shapes that name them) asks first and names the data.
//
// The editor holds the document; whoever opens it (a page on the project)
// gives it the mesh and the measured data, and saves on documentChanged().

#include <QWidget>
#include <functional>
#include <vector>

#include "core/common/result.h"
#include "core/geometry/mesh_edit.h"
#include "core/io/mesh_document.h"

class QAction;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QTabWidget;
class QTableView;
class QToolBar;
class QUndoStack;
class QVBoxLayout;

namespace mozzi {
namespace views {

class SceneView;
class MeshTableModel;

class MeshEditor : public QWidget {
  Q_OBJECT
 public:
  explicit MeshEditor(QWidget* parent = nullptr);
  ~MeshEditor() override;

  // Loads a document (from the project, a template, a file) without undo
  // history; the 3-D view is reset to show it.
  void setDocument(const core::io::MeshDocument& document);
  const core::io::MeshDocument& document() const { return document_; }
  QUndoStack* undoStack() const { return undo_; }
  SceneView* scene() const { return scene_; }

  // The data that refers to this mesh's DOFs (for the orphan question).
  void setMeasuredData(std::vector<core::geometry::MeasuredData> data) { measured_ = std::move(data); }
  // Asks the user; returns true to go ahead. The default shows a question box;
  // tests install their own.
  using ConfirmHandler = std::function<bool(const QString& title, const QString& text)>;
  void setConfirmHandler(ConfirmHandler handler) { confirm_ = std::move(handler); }

  // Templates offered by "Start from template".
  struct Template {
    QString key;
    QString title;
    std::function<core::Result<core::io::MeshDocument>()> make;
  };
  void setTemplates(std::vector<Template> templates);

  // --- actions (the toolbar's, callable by a page or a test) ------------------
  // Each plans the edit, asks about orphans, pushes it; false (with the reason
  // in lastMessage()) when refused or declined.
  bool addNode(const core::Vector3& position, int label = 0);
  bool deleteSelection();
  bool renumberNode(int from, int to);
  bool renumberAll(int first = 1, int step = 1);
  bool snapSelection(double gridMetres);
  bool moveSelection(const core::Vector3& deltaMetres);
  bool addLineFromSelection();
  bool addFaceFromSelection();
  bool setNodeDofs(int label, const QString& directions);
  bool setSlaveRule(const QString& rule);
  bool removeSlaveRule(int index);
  bool addCoordinateSystem();
  bool startFromTemplate(const QString& key);
  bool importFile(const QString& path);
  bool exportFile(const QString& path);
  // Pushes any planned edit (the tables use it).
  bool pushEdit(const core::Result<core::geometry::MeshEdit>& planned);
  QString lastMessage() const { return lastMessage_; }

  void selectNodes(const std::vector<int>& labels);
  // Frames the whole mesh in the 3-D view (edits keep the view as it is).
  void fitView();
  std::vector<int> selectedNodes() const;
  std::vector<std::size_t> selectedLines() const;
  std::vector<std::size_t> selectedFaces() const;

 signals:
  // After every edit, undo and redo (not after setDocument).
  void documentChanged();
  // A status line for the user (errors and notes).
  void message(const QString& text);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  friend class MeshEditCommand;
  void buildToolbar(QVBoxLayout* layout);                                        // from the constructor
  void applyDocument(const core::io::MeshDocument& document, bool resetCamera);  // from the undo commands
  void refresh(bool resetCamera);
  void syncSceneSelection();
  void onNodeClicked(int label, Qt::KeyboardModifiers modifiers);
  void report(const QString& text);
  void retranslate();
  bool confirmOrphans(const core::io::MeshDocument& after);

  core::io::MeshDocument document_;
  std::vector<core::geometry::MeasuredData> measured_;
  std::vector<Template> templates_;
  ConfirmHandler confirm_;
  QString lastMessage_;

  QUndoStack* undo_ = nullptr;
  SceneView* scene_ = nullptr;
  QToolBar* toolbar_ = nullptr;
  QTabWidget* tabs_ = nullptr;
  QTableView* nodeTable_ = nullptr;
  QTableView* lineTable_ = nullptr;
  QTableView* faceTable_ = nullptr;
  QTableView* systemTable_ = nullptr;
  MeshTableModel* nodeModel_ = nullptr;
  MeshTableModel* lineModel_ = nullptr;
  MeshTableModel* faceModel_ = nullptr;
  MeshTableModel* systemModel_ = nullptr;
  QListWidget* slaveList_ = nullptr;
  QLineEdit* slaveEdit_ = nullptr;
  QDoubleSpinBox* gridSpin_ = nullptr;
  QLabel* status_ = nullptr;
  QAction* templateAction_ = nullptr;
  QAction* importAction_ = nullptr;
  QAction* exportAction_ = nullptr;
  QAction* undoAction_ = nullptr;
  QAction* redoAction_ = nullptr;
  QAction* addNodeAction_ = nullptr;
  QAction* deleteAction_ = nullptr;
  QAction* renumberAction_ = nullptr;
  QAction* renumberAllAction_ = nullptr;
  QAction* snapAction_ = nullptr;
  QAction* addLineAction_ = nullptr;
  QAction* addFaceAction_ = nullptr;
  QAction* addSystemAction_ = nullptr;
  QAction* labelsAction_ = nullptr;
  QAction* fitAction_ = nullptr;
  bool syncing_ = false;
};

}  // namespace views
}  // namespace mozzi
