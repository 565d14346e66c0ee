#include "views/editors/mesh_editor.h"

#include <QAbstractTableModel>
#include <QAction>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QItemSelectionModel>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSplitter>
#include <QTabWidget>
#include <QTableView>
#include <QToolBar>
#include <QToolButton>
#include <QUndoCommand>
#include <QUndoStack>
#include <QVBoxLayout>
#include <algorithm>
#include <set>

#include "core/geometry/mesh_placement.h"
#include "core/io/csv/csv_exchange.h"
#include "core/io/uff_import.h"
#include "views/editors/mesh_table_model.h"
#include "views/scene/scene_view.h"

namespace mozzi {
namespace views {

namespace geo = core::geometry;
using core::io::MeshDocument;
using core::io::StoredCoordinateSystem;

namespace {

using mesh_editor::kMm;

QString fromCore(const core::Error& e) {
  return QString::fromStdString(e.message) +
         (e.where.empty() ? QString() : QStringLiteral(" (") + QString::fromStdString(e.where) + QStringLiteral(")"));
}
}  // namespace

// One undoable edit: the planned MeshEdit and its inverse.
class MeshEditCommand : public QUndoCommand {
 public:
  MeshEditCommand(MeshEditor* editor, geo::MeshEdit edit)
      : editor_(editor), forward_(std::move(edit)), backward_(geo::inverse(forward_)) {
    setText(QString::fromStdString(forward_.description));
  }
  void redo() override { run(forward_); }
  void undo() override { run(backward_); }

 private:
  void run(const geo::MeshEdit& edit) {
    MeshDocument doc = editor_->document_;
    if (auto r = geo::apply(doc, edit); !r) {
      editor_->report(MeshEditor::tr("Cannot apply the edit: %1").arg(fromCore(r.error())));
      return;
    }
    editor_->applyDocument(doc, false);
  }
  MeshEditor* editor_;
  geo::MeshEdit forward_;
  geo::MeshEdit backward_;
};

MeshEditor::MeshEditor(QWidget* parent) : QWidget(parent) {
  undo_ = new QUndoStack(this);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);

  buildToolbar(layout);

  auto* splitter = new QSplitter(Qt::Horizontal, this);
  layout->addWidget(splitter, 1);
  tabs_ = new QTabWidget(splitter);
  tabs_->setObjectName(QStringLiteral("meshTabs"));
  auto makeTable = [this](MeshTableModel::Kind kind, const char* name, MeshTableModel*& model) {
    auto* view = new QTableView(tabs_);
    view->setObjectName(QString::fromLatin1(name));
    model = new MeshTableModel(kind, this);
    view->setModel(model);
    view->setSelectionBehavior(QAbstractItemView::SelectRows);
    view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    view->horizontalHeader()->setStretchLastSection(true);
    view->verticalHeader()->setDefaultSectionSize(view->fontMetrics().height() + 6);
    view->setAlternatingRowColors(true);
    tabs_->addTab(view, QString());
    return view;
  };
  nodeTable_ = makeTable(MeshTableModel::Kind::Nodes, "meshNodeTable", nodeModel_);
  lineTable_ = makeTable(MeshTableModel::Kind::Lines, "meshLineTable", lineModel_);
  faceTable_ = makeTable(MeshTableModel::Kind::Faces, "meshFaceTable", faceModel_);
  systemTable_ = makeTable(MeshTableModel::Kind::Systems, "meshSystemTable", systemModel_);
  auto* slavePage = new QWidget(tabs_);
  auto* slaveLayout = new QVBoxLayout(slavePage);
  slaveList_ = new QListWidget(slavePage);
  slaveList_->setObjectName(QStringLiteral("meshSlaveList"));
  slaveEdit_ = new QLineEdit(slavePage);
  slaveEdit_->setObjectName(QStringLiteral("meshSlaveEdit"));
  auto* slaveButtons = new QHBoxLayout;
  auto* setSlave = new QPushButton(slavePage);
  setSlave->setObjectName(QStringLiteral("meshSetSlaveButton"));
  auto* removeSlave = new QPushButton(slavePage);
  removeSlave->setObjectName(QStringLiteral("meshRemoveSlaveButton"));
  slaveButtons->addWidget(setSlave);
  slaveButtons->addWidget(removeSlave);
  slaveButtons->addStretch(1);
  slaveLayout->addWidget(slaveList_, 1);
  slaveLayout->addWidget(slaveEdit_);
  slaveLayout->addLayout(slaveButtons);
  tabs_->addTab(slavePage, QString());
  connect(setSlave, &QPushButton::clicked, this, [this] { setSlaveRule(slaveEdit_->text()); });
  connect(slaveEdit_, &QLineEdit::returnPressed, this, [this] { setSlaveRule(slaveEdit_->text()); });
  connect(removeSlave, &QPushButton::clicked, this, [this] { removeSlaveRule(slaveList_->currentRow()); });

  scene_ = new SceneView(splitter);
  scene_->setObjectName(QStringLiteral("meshEditorScene"));
  splitter->setChildrenCollapsible(false);
  scene_->setMinimumWidth(240);
  splitter->setStretchFactor(0, 2);
  splitter->setStretchFactor(1, 3);
  splitter->setSizes({400, 600});  // tables : view = 2 : 3 whatever the window size
  status_ = new QLabel(this);
  status_->setObjectName(QStringLiteral("meshEditorStatus"));
  status_->setWordWrap(true);
  layout->addWidget(status_);

  connect(nodeTable_->selectionModel(), &QItemSelectionModel::selectionChanged, this, [this] { syncSceneSelection(); });
  connect(scene_, &SceneView::nodeClicked, this, &MeshEditor::onNodeClicked);
  connect(undo_, &QUndoStack::indexChanged, this, [this] { emit documentChanged(); });
  confirm_ = [this](const QString& title, const QString& text) {
    return QMessageBox::question(this, title, text, QMessageBox::Yes | QMessageBox::No, QMessageBox::No) ==
           QMessageBox::Yes;
  };
  retranslate();
  refresh(true);
}

// The toolbar: templates, import and export, undo and redo, node, line, face
// and coordinate-system edits, the snap grid, the view.
void MeshEditor::buildToolbar(QVBoxLayout* layout) {
  toolbar_ = new QToolBar(this);
  toolbar_->setObjectName(QStringLiteral("meshEditorToolbar"));
  toolbar_->setToolButtonStyle(Qt::ToolButtonTextOnly);
  layout->addWidget(toolbar_);
  auto addAction = [this](const char* name, auto slot) {
    auto* action = toolbar_->addAction(QString());
    action->setObjectName(QString::fromLatin1(name));
    connect(action, &QAction::triggered, this, slot);
    return action;
  };
  templateAction_ = toolbar_->addAction(QString());
  templateAction_->setObjectName(QStringLiteral("meshTemplateAction"));
  templateAction_->setMenu(new QMenu(this));
  if (auto* button = qobject_cast<QToolButton*>(toolbar_->widgetForAction(templateAction_))) {
    button->setPopupMode(QToolButton::InstantPopup);
  }
  importAction_ = addAction("meshImportAction", [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Import a mesh"), QString(),
                                                      tr("Meshes (*.uff *.unv *.csv);;All files (*)"));
    if (!path.isEmpty()) importFile(path);
  });
  exportAction_ = addAction("meshExportAction", [this] {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export the mesh"), QString(),
                                                      tr("Universal file (*.uff);;Mesh CSV (*.csv)"));
    if (!path.isEmpty()) exportFile(path);
  });
  toolbar_->addSeparator();
  // Fixed button texts; what would be undone or redone is in the tooltip.
  undoAction_ = addAction("meshUndoAction", [this] { undo_->undo(); });
  undoAction_->setShortcut(QKeySequence::Undo);
  undoAction_->setEnabled(false);
  redoAction_ = addAction("meshRedoAction", [this] { undo_->redo(); });
  redoAction_->setShortcut(QKeySequence::Redo);
  redoAction_->setEnabled(false);
  connect(undo_, &QUndoStack::canUndoChanged, undoAction_, &QAction::setEnabled);
  connect(undo_, &QUndoStack::canRedoChanged, redoAction_, &QAction::setEnabled);
  connect(undo_, &QUndoStack::undoTextChanged, this,
          [this](const QString& text) { undoAction_->setToolTip(tr("Undo %1").arg(text)); });
  connect(undo_, &QUndoStack::redoTextChanged, this,
          [this](const QString& text) { redoAction_->setToolTip(tr("Redo %1").arg(text)); });
  toolbar_->addSeparator();
  addNodeAction_ = addAction("meshAddNodeAction", [this] {
    // New node beside the selection (or at the origin), 10 mm along x.
    core::Vector3 at = core::Vector3::Zero();
    const auto sel = selectedNodes();
    if (!sel.empty()) {
      if (const auto index = geo::nodeIndex(document_, sel.back())) {
        const auto& n = document_.mesh.nodes[*index];
        if (n.definitionCs == 0) at = n.position + core::Vector3(0.01, 0.0, 0.0);
      }
    }
    addNode(at);
  });
  deleteAction_ = addAction("meshDeleteAction", [this] { deleteSelection(); });
  deleteAction_->setShortcut(QKeySequence::Delete);
  deleteAction_->setShortcutContext(Qt::WidgetWithChildrenShortcut);
  renumberAction_ = addAction("meshRenumberAction", [this] {
    const auto sel = selectedNodes();
    if (sel.size() != 1) {
      report(tr("Select one node to renumber."));
      return;
    }
    bool ok = false;
    const int to = QInputDialog::getInt(this, tr("Renumber node"), tr("New number of node %1:").arg(sel.front()),
                                        geo::nextFreeLabel(document_), 1, 2147483647, 1, &ok);
    if (ok) renumberNode(sel.front(), to);
  });
  renumberAllAction_ = addAction("meshRenumberAllAction", [this] { renumberAll(1, 1); });
  snapAction_ = addAction("meshSnapAction", [this] { snapSelection(gridSpin_->value() / kMm); });
  gridSpin_ = new QDoubleSpinBox(this);
  gridSpin_->setObjectName(QStringLiteral("meshGridSpin"));
  gridSpin_->setRange(0.001, 10000.0);
  gridSpin_->setDecimals(3);
  gridSpin_->setValue(10.0);
  gridSpin_->setSuffix(QStringLiteral(" mm"));
  toolbar_->addWidget(gridSpin_);
  toolbar_->addSeparator();
  addLineAction_ = addAction("meshAddLineAction", [this] { addLineFromSelection(); });
  addFaceAction_ = addAction("meshAddFaceAction", [this] { addFaceFromSelection(); });
  addSystemAction_ = addAction("meshAddSystemAction", [this] { addCoordinateSystem(); });
  toolbar_->addSeparator();
  fitAction_ = addAction("meshFitAction", [this] { fitView(); });
  labelsAction_ = toolbar_->addAction(QString());
  labelsAction_->setObjectName(QStringLiteral("meshLabelsAction"));
  labelsAction_->setCheckable(true);
  labelsAction_->setChecked(true);
  connect(labelsAction_, &QAction::toggled, this, [this](bool on) { scene_->setLabelsVisible(on); });
}

MeshEditor::~MeshEditor() = default;

void MeshEditor::setDocument(const MeshDocument& document) {
  undo_->clear();
  document_ = document;
  refresh(true);
}

void MeshEditor::applyDocument(const MeshDocument& document, bool resetCamera) {
  document_ = document;
  refresh(resetCamera);
}

void MeshEditor::refresh(bool resetCamera) {
  const auto keep = selectedNodes();
  syncing_ = true;
  nodeModel_->reset();
  lineModel_->reset();
  faceModel_->reset();
  systemModel_->reset();
  slaveList_->clear();
  for (const auto& s : document_.slaves) slaveList_->addItem(QString::fromStdString(geo::formatSlaveRule(s)));
  auto positions = geo::globalNodePositions(document_.mesh);
  if (positions) {
    scene_->showMesh(document_.mesh, *positions, resetCamera);
  } else {
    scene_->clearMesh();
    report(tr("Cannot place the mesh: %1").arg(fromCore(positions.error())));
  }
  scene_->setLabelsVisible(labelsAction_->isChecked() && document_.mesh.nodes.size() <= 2000);
  syncing_ = false;
  selectNodes(keep);
  status_->setText(tr("%1 nodes, %2 lines, %3 faces, %4 coordinate systems, %5 measurement DOFs, %6 slave rules")
                       .arg(document_.mesh.nodes.size())
                       .arg(document_.mesh.lines.size())
                       .arg(document_.mesh.faces.size())
                       .arg(document_.mesh.coordinateSystems.size())
                       .arg(document_.measurementDofs.size())
                       .arg(document_.slaves.size()));
}

void MeshEditor::fitView() {
  scene_->resetCamera();
}

void MeshEditor::setTemplates(std::vector<Template> templates) {
  templates_ = std::move(templates);
  QMenu* menu = templateAction_->menu();
  menu->clear();
  for (const auto& t : templates_) {
    QAction* a = menu->addAction(t.title);
    a->setObjectName(QStringLiteral("meshTemplate_") + t.key);
    const QString key = t.key;
    connect(a, &QAction::triggered, this, [this, key] { startFromTemplate(key); });
  }
  templateAction_->setEnabled(!templates_.empty());
}

bool MeshEditor::confirmOrphans(const MeshDocument& after) {
  if (measured_.empty()) return true;
  const auto orphans = geo::orphanedBy(document_, after, measured_);
  if (orphans.empty()) return true;
  const QString text = tr("This edit takes away nodes that measured data refers to:\n\n%1\n\n"
                          "The data stays in the project but can no longer be drawn on this mesh. Go ahead?")
                           .arg(QString::fromStdString(geo::describeOrphans(orphans)));
  return confirm_ ? confirm_(tr("Measured data on these nodes"), text) : false;
}

bool MeshEditor::pushEdit(const core::Result<geo::MeshEdit>& planned) {
  if (!planned) {
    report(tr("Cannot edit the mesh: %1").arg(fromCore(planned.error())));
    return false;
  }
  if (planned->empty()) return true;  // nothing changes
  MeshDocument after = document_;
  if (auto r = geo::apply(after, *planned); !r) {
    report(tr("Cannot edit the mesh: %1").arg(fromCore(r.error())));
    return false;
  }
  if (!confirmOrphans(after)) {
    report(tr("Edit cancelled: measured data refers to these nodes."));
    return false;
  }
  undo_->push(new MeshEditCommand(this, *planned));
  lastMessage_.clear();
  return true;
}

bool MeshEditor::addNode(const core::Vector3& position, int label) {
  core::io::StoredNode node;
  node.label = label;
  node.position = position;
  const int newLabel = label == 0 ? geo::nextFreeLabel(document_) : label;
  if (!pushEdit(geo::planAddNode(document_, node))) return false;
  selectNodes({newLabel});
  return true;
}

bool MeshEditor::deleteSelection() {
  if (tabs_->currentWidget() == lineTable_ && !selectedLines().empty()) {
    return pushEdit(geo::planDeleteLines(document_, selectedLines()));
  }
  if (tabs_->currentWidget() == faceTable_ && !selectedFaces().empty()) {
    return pushEdit(geo::planDeleteFaces(document_, selectedFaces()));
  }
  if (tabs_->currentWidget() == systemTable_) {
    const auto rows = systemTable_->selectionModel()->selectedRows();
    if (rows.size() != 1) {
      report(tr("Select one coordinate system to delete."));
      return false;
    }
    return pushEdit(geo::planDeleteCoordinateSystem(
        document_, document_.mesh.coordinateSystems[static_cast<std::size_t>(rows.front().row())].label));
  }
  const auto nodes = selectedNodes();
  if (nodes.empty()) {
    report(tr("Select the nodes to delete."));
    return false;
  }
  return pushEdit(geo::planDeleteNodes(document_, nodes));
}

bool MeshEditor::renumberNode(int from, int to) {
  if (!pushEdit(geo::planRenumber(document_, from, to))) return false;
  selectNodes({to});
  return true;
}

bool MeshEditor::renumberAll(int first, int step) {
  return pushEdit(geo::planRenumberAll(document_, first, step));
}

bool MeshEditor::snapSelection(double gridMetres) {
  auto nodes = selectedNodes();
  if (nodes.empty()) {
    for (const auto& n : document_.mesh.nodes) nodes.push_back(n.label);  // nothing selected: the whole mesh
  }
  return pushEdit(geo::planSnapToGrid(document_, nodes, gridMetres));
}

bool MeshEditor::moveSelection(const core::Vector3& deltaMetres) {
  return pushEdit(geo::planMoveNodes(document_, selectedNodes(), deltaMetres));
}

bool MeshEditor::addLineFromSelection() {
  const auto nodes = selectedNodes();
  if (nodes.size() < 2) {
    report(tr("Select two or more nodes: lines join them in the order selected."));
    return false;
  }
  // A chain through the selected nodes, one undo step.
  geo::MeshEdit chain;
  chain.description = "add lines";
  MeshDocument work = document_;
  for (std::size_t i = 1; i < nodes.size(); ++i) {
    auto step = geo::planAddLine(work, nodes[i - 1], nodes[i]);
    if (!step) return pushEdit(step);
    (void)geo::apply(work, *step);
    chain.ops.insert(chain.ops.end(), step->ops.begin(), step->ops.end());
  }
  return pushEdit(chain);
}

bool MeshEditor::addFaceFromSelection() {
  const auto nodes = selectedNodes();
  if (nodes.size() != 3 && nodes.size() != 4) {
    report(tr("Select three or four nodes, counter-clockwise, for a face."));
    return false;
  }
  core::io::StoredFace face{nodes[0], nodes[1], nodes[2], nodes.size() == 4 ? nodes[3] : 0};
  return pushEdit(geo::planAddFace(document_, face));
}

bool MeshEditor::setNodeDofs(int label, const QString& directions) {
  auto dofs = geo::parseNodeDofs(label, directions.toStdString());
  if (!dofs) {
    report(tr("Cannot set the DOFs: %1").arg(fromCore(dofs.error())));
    return false;
  }
  return pushEdit(geo::planSetNodeDofs(document_, label, *dofs));
}

bool MeshEditor::setSlaveRule(const QString& rule) {
  auto parsed = geo::parseSlaveRule(rule.toStdString());
  if (!parsed) {
    report(tr("Cannot read the rule: %1").arg(fromCore(parsed.error())));
    return false;
  }
  if (!pushEdit(geo::planSetSlave(document_, *parsed))) return false;
  slaveEdit_->clear();
  return true;
}

bool MeshEditor::removeSlaveRule(int index) {
  if (index < 0 || index >= static_cast<int>(document_.slaves.size())) {
    report(tr("Select a rule to remove."));
    return false;
  }
  return pushEdit(geo::planRemoveSlave(document_, document_.slaves[static_cast<std::size_t>(index)].slave));
}

bool MeshEditor::addCoordinateSystem() {
  StoredCoordinateSystem cs;
  cs.name = tr("System").toStdString();
  return pushEdit(geo::planAddCoordinateSystem(document_, cs));
}

bool MeshEditor::startFromTemplate(const QString& key) {
  for (const auto& t : templates_) {
    if (t.key != key) continue;
    auto doc = t.make();
    if (!doc) {
      report(tr("Cannot build the template: %1").arg(fromCore(doc.error())));
      return false;
    }
    if (!pushEdit(geo::planReplace(document_, *doc, "start from template " + key.toStdString()))) return false;
    refresh(true);
    return true;
  }
  report(tr("No template named %1.").arg(key));
  return false;
}

bool MeshEditor::importFile(const QString& path) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  MeshDocument doc;
  if (suffix == QLatin1String("csv")) {
    auto read = core::io::csv::importMeshCsv(path.toStdString());
    if (!read) {
      report(tr("Cannot import %1: %2").arg(path, fromCore(read.error())));
      return false;
    }
    doc = std::move(read).value();
  } else {
    auto read = core::io::importMeshUff(path.toStdString());
    if (!read) {
      report(tr("Cannot import %1: %2").arg(path, fromCore(read.error())));
      return false;
    }
    doc.mesh = std::move(read).value();
    if (doc.mesh.nodes.empty()) {
      report(tr("%1 holds no nodes (datasets 15 or 2411).").arg(path));
      return false;
    }
  }
  if (auto valid = geo::validate(doc); !valid) {
    report(tr("Cannot import %1: %2").arg(path, fromCore(valid.error())));
    return false;
  }
  if (!pushEdit(geo::planReplace(document_, doc, "import " + QFileInfo(path).fileName().toStdString()))) return false;
  refresh(true);
  return true;
}

bool MeshEditor::exportFile(const QString& path) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (suffix == QLatin1String("csv")) {
    if (auto r = core::io::csv::exportMeshCsv(document_, path.toStdString()); !r) {
      report(tr("Cannot export: %1").arg(fromCore(r.error())));
      return false;
    }
    report(tr("Mesh written to %1.").arg(path));
    return true;
  }
  core::io::MeshUffOptions options;
  options.doublePrecision = true;
  auto written = core::io::exportMeshUff(document_.mesh, path.toStdString(), options);
  if (!written) {
    report(tr("Cannot export: %1").arg(fromCore(written.error())));
    return false;
  }
  QString text = tr("Mesh written to %1 (datasets 164, 2420, 2411, 82).").arg(path);
  if (written->facesLeftOut > 0 || !document_.measurementDofs.empty() || !document_.slaves.empty()) {
    text += QLatin1Char(' ') + tr("Faces, measurement DOFs and slave rules have no dataset there; "
                                  "export to CSV to keep them.");
  }
  report(text);
  return true;
}

void MeshEditor::selectNodes(const std::vector<int>& labels) {
  syncing_ = true;
  auto* selection = nodeTable_->selectionModel();
  selection->clearSelection();
  QItemSelection rows;
  const std::set<int> wanted(labels.begin(), labels.end());
  int last = -1;
  for (std::size_t i = 0; i < document_.mesh.nodes.size(); ++i) {
    if (!wanted.count(document_.mesh.nodes[i].label)) continue;
    const QModelIndex index = nodeModel_->index(static_cast<int>(i), 0);
    rows.select(index, index);
    last = static_cast<int>(i);
  }
  selection->select(rows, QItemSelectionModel::Select | QItemSelectionModel::Rows);
  if (last >= 0) nodeTable_->scrollTo(nodeModel_->index(last, 0));
  syncing_ = false;
  // Keep the order the caller gave (lines and faces follow it).
  std::vector<int> present;
  for (int l : labels)
    if (geo::nodeIndex(document_, l)) present.push_back(l);
  scene_->setSelectedNodes(present);
}

std::vector<int> MeshEditor::selectedNodes() const {
  // The scene keeps the click order; the table's selection decides membership.
  std::set<int> inTable;
  for (const auto& index : nodeTable_->selectionModel()->selectedRows()) {
    const std::size_t row = static_cast<std::size_t>(index.row());
    if (row < document_.mesh.nodes.size()) inTable.insert(document_.mesh.nodes[row].label);
  }
  std::vector<int> out;
  for (int l : scene_->selectedNodes())
    if (inTable.erase(l)) out.push_back(l);
  for (const auto& n : document_.mesh.nodes)
    if (inTable.count(n.label)) out.push_back(n.label);
  return out;
}

std::vector<std::size_t> MeshEditor::selectedLines() const {
  std::vector<std::size_t> out;
  for (const auto& index : lineTable_->selectionModel()->selectedRows())
    out.push_back(static_cast<std::size_t>(index.row()));
  return out;
}

std::vector<std::size_t> MeshEditor::selectedFaces() const {
  std::vector<std::size_t> out;
  for (const auto& index : faceTable_->selectionModel()->selectedRows())
    out.push_back(static_cast<std::size_t>(index.row()));
  return out;
}

void MeshEditor::syncSceneSelection() {
  if (syncing_) return;
  scene_->setSelectedNodes(selectedNodes());
}

void MeshEditor::onNodeClicked(int label, Qt::KeyboardModifiers modifiers) {
  std::vector<int> labels;
  if (modifiers & (Qt::ControlModifier | Qt::ShiftModifier)) {
    labels = selectedNodes();
    const auto it = std::find(labels.begin(), labels.end(), label);
    if (it != labels.end()) {
      labels.erase(it);
    } else {
      labels.push_back(label);
    }
  } else {
    labels = {label};
  }
  tabs_->setCurrentWidget(nodeTable_);
  selectNodes(labels);
}

void MeshEditor::report(const QString& text) {
  lastMessage_ = text;
  emit message(text);
  status_->setToolTip(text);
  status_->setText(text);
}

void MeshEditor::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void MeshEditor::retranslate() {
  templateAction_->setText(tr("Start from template"));
  templateAction_->setToolTip(tr("Replace the mesh by a template of the component (undoable)"));
  importAction_->setText(tr("Import…"));
  importAction_->setToolTip(tr("Read a mesh from a universal file (15/2411, 18/2420, 82) or a mesh CSV"));
  exportAction_->setText(tr("Export…"));
  exportAction_->setToolTip(tr("Write the mesh as a universal file or a mesh CSV"));
  undoAction_->setText(tr("Undo"));
  redoAction_->setText(tr("Redo"));
  addNodeAction_->setText(tr("Add node"));
  deleteAction_->setText(tr("Delete"));
  deleteAction_->setToolTip(
      tr("Delete the selected nodes (with their lines, faces and DOFs), lines, faces or "
         "coordinate system (Del)"));
  renumberAction_->setText(tr("Renumber…"));
  renumberAllAction_->setText(tr("Renumber all"));
  renumberAllAction_->setToolTip(tr("Number the nodes 1, 2, 3, … in table order"));
  snapAction_->setText(tr("Snap to grid"));
  snapAction_->setToolTip(tr("Round the selected nodes' coordinates (all nodes when none is selected) to the grid"));
  gridSpin_->setToolTip(tr("Grid spacing"));
  addLineAction_->setText(tr("Add lines"));
  addLineAction_->setToolTip(tr("Join the selected nodes by trace lines in the order they were picked"));
  addFaceAction_->setText(tr("Add face"));
  addSystemAction_->setText(tr("Add CS"));
  addSystemAction_->setToolTip(tr("Add a cartesian coordinate system at the origin"));
  labelsAction_->setText(tr("Labels"));
  fitAction_->setText(tr("Fit view"));
  fitAction_->setToolTip(tr("Show the whole mesh"));
  tabs_->setTabText(0, tr("Nodes"));
  tabs_->setTabText(1, tr("Lines"));
  tabs_->setTabText(2, tr("Faces"));
  tabs_->setTabText(3, tr("Coordinate systems"));
  tabs_->setTabText(4, tr("Slaved DOFs"));
  slaveEdit_->setPlaceholderText(tr("e.g. 5:+Z = 0.5 4:+Z + 0.5 6:+Z"));
  if (auto* b = findChild<QPushButton*>(QStringLiteral("meshSetSlaveButton"))) b->setText(tr("Set rule"));
  if (auto* b = findChild<QPushButton*>(QStringLiteral("meshRemoveSlaveButton"))) b->setText(tr("Remove rule"));
  nodeModel_->reset();
  systemModel_->reset();
}

}  // namespace views
}  // namespace mozzi
