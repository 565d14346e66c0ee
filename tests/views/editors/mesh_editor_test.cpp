// The mesh editor driven as a user does: edits through the toolbar's actions
// and the table cells, each undone and redone, the node table compared with
// the table expected by hand; a click in the 3-D view selects the node under
// it; an edit that orphans measured data asks first and names the data;
// export and import give the same mesh; a template replaces the mesh and undo
// brings the old one back. Screenshot: mesh_editor.png.
#include "views/editors/mesh_editor.h"

#include <vtkRenderer.h>
#include <QAbstractItemModel>
#include <QApplication>
#include <QDir>
#include <QItemSelectionModel>
#include <QTableView>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include "core/io/csv/csv_exchange.h"
#include "core/io/uff_import.h"
#include "views/scene/scene_view.h"

using mozzi::core::Dof;
using mozzi::core::Vector3;
using mozzi::core::io::MeshDocument;
using mozzi::views::MeshEditor;

namespace {

Dof dofZ(int node) {
  return Dof{node, mozzi::core::Direction::Z, false};
}

// A 3 x 2 grid of nodes 1..6 at 100 mm spacing, lines along x, Z measured at 1..3.
MeshDocument grid() {
  MeshDocument d;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      mozzi::core::io::StoredNode n;
      n.label = 1 + i + 3 * j;
      n.position = Vector3(0.1 * i, 0.1 * j, 0.0);
      d.mesh.nodes.push_back(n);
    }
  d.mesh.lines = {{1, 2}, {2, 3}, {4, 5}, {5, 6}};
  d.measurementDofs = {dofZ(1), dofZ(2), dofZ(3)};
  return d;
}

// The node table as text: "label | x | y | z | cs | dcs | DOFs" per row.
QStringList nodeRows(MeshEditor& editor) {
  auto* table = editor.findChild<QTableView*>(QStringLiteral("meshNodeTable"));
  QStringList rows;
  auto* model = table->model();
  for (int r = 0; r < model->rowCount(); ++r) {
    QStringList cells;
    for (int c = 0; c < model->columnCount(); ++c) cells << model->index(r, c).data().toString();
    rows << cells.join(QStringLiteral(" | "));
  }
  return rows;
}

void saveScreenshot(QWidget& w, const QString& name) {
  const QString folder = qEnvironmentVariable("MOZZI_SCREENSHOT_DIR", QDir::tempPath());
  QDir().mkpath(folder);
  const QString path = QDir(folder).filePath(name);
  QVERIFY(w.grab().save(path));
  qInfo("screenshot: %s", qPrintable(path));
}

}  // namespace

class MeshEditorTest : public QObject {
  Q_OBJECT
 private slots:
  void editsUndoAndRedoGiveTheExpectedTable();
  void editingCellsGoesThroughTheUndoStack();
  void clickingANodeInTheSceneSelectsIt();
  void orphaningMeasuredDataAsksAndNamesIt();
  void exportThenImportGivesTheSameMesh();
  void templateReplacesTheMeshAndUndoBringsItBack();
};

void MeshEditorTest::editsUndoAndRedoGiveTheExpectedTable() {
  MeshEditor editor;
  editor.resize(1280, 800);
  editor.show();
  QVERIFY(QTest::qWaitForWindowExposed(&editor));
  QTRY_VERIFY(editor.scene()->isReady());  // the 3-D window is a native child: exposed a moment later
  editor.setDocument(grid());
  const QStringList start = nodeRows(editor);
  QCOMPARE(start.size(), 6);
  QCOMPARE(start[0], QStringLiteral("1 | 0.000 | 0.000 | 0.000 | 0 | 0 | +Z"));

  QVERIFY(editor.addNode(Vector3(0.2, 0.2, 0.05)));  // node 7
  QCOMPARE(editor.selectedNodes(), std::vector<int>{7});
  QVERIFY(editor.setNodeDofs(7, QStringLiteral("+X +Z")));
  editor.selectNodes({6, 7});
  QVERIFY(editor.addLineFromSelection());
  QVERIFY(editor.moveSelection(Vector3(0.0123, 0.0, 0.0)));  // nodes 6 and 7 by 12.3 mm
  QVERIFY(editor.snapSelection(0.01));                       // back onto the 10 mm grid
  QVERIFY(editor.renumberNode(7, 70));
  editor.selectNodes({4});
  QVERIFY(editor.deleteSelection());  // node 4 and its line 4-5
  QCOMPARE(editor.undoStack()->count(), 7);

  const QStringList expected = {
      QStringLiteral("1 | 0.000 | 0.000 | 0.000 | 0 | 0 | +Z"),
      QStringLiteral("2 | 100.000 | 0.000 | 0.000 | 0 | 0 | +Z"),
      QStringLiteral("3 | 200.000 | 0.000 | 0.000 | 0 | 0 | +Z"),
      QStringLiteral("5 | 100.000 | 100.000 | 0.000 | 0 | 0 | "),
      QStringLiteral("6 | 210.000 | 100.000 | 0.000 | 0 | 0 | "),  // 212.3 snapped to 210
      QStringLiteral("70 | 210.000 | 200.000 | 50.000 | 0 | 0 | +X +Z"),
  };
  QCOMPARE(nodeRows(editor), expected);
  const auto& doc = editor.document();
  QCOMPARE(doc.mesh.lines.size(), std::size_t{4});  // 1-2, 2-3, 5-6, 6-70
  QCOMPARE(doc.mesh.lines.back().nodeB, 70);
  QCOMPARE(editor.scene()->meshPointCount(), 6);
  QCOMPARE(editor.scene()->meshLineCount(), 4);

  // Undo everything: the grid again, exactly; redo everything: the table above.
  for (int i = 0; i < 7; ++i) editor.undoStack()->undo();
  QVERIFY(mozzi::core::io::sameDocument(editor.document(), grid()));
  QCOMPARE(nodeRows(editor), start);
  QCOMPARE(editor.scene()->meshLineCount(), 4);
  for (int i = 0; i < 7; ++i) editor.undoStack()->redo();
  QCOMPARE(nodeRows(editor), expected);
  QCOMPARE(editor.undoStack()->undoText(), QStringLiteral("delete node 4"));

  editor.selectNodes({2, 3, 70});
  editor.fitView();
  saveScreenshot(editor, QStringLiteral("mesh_editor.png"));
}

void MeshEditorTest::editingCellsGoesThroughTheUndoStack() {
  MeshEditor editor;
  editor.setDocument(grid());
  auto* model = editor.findChild<QTableView*>(QStringLiteral("meshNodeTable"))->model();
  QVERIFY(model->setData(model->index(1, 3), 25.0));                  // z of node 2 = 25 mm
  QVERIFY(model->setData(model->index(1, 6), QStringLiteral("-Y")));  // DOFs of node 2
  QVERIFY(model->setData(model->index(2, 0), 33));                    // renumber node 3
  QVERIFY(!model->setData(model->index(0, 0), 2));                    // 2 exists: refused
  QVERIFY(editor.lastMessage().contains(QStringLiteral("node 2 already exists")));
  QCOMPARE(model->index(1, 3).data().toString(), QStringLiteral("25.000"));
  QCOMPARE(editor.document().mesh.nodes[1].position.z(), 0.025);
  QCOMPARE(model->index(1, 6).data().toString(), QStringLiteral("-Y"));
  QCOMPARE(model->index(2, 0).data().toInt(), 33);
  QCOMPARE(editor.undoStack()->count(), 3);
  editor.undoStack()->setIndex(0);
  QVERIFY(mozzi::core::io::sameDocument(editor.document(), grid()));
}

void MeshEditorTest::clickingANodeInTheSceneSelectsIt() {
  MeshEditor editor;
  editor.resize(1280, 800);
  editor.show();
  QVERIFY(QTest::qWaitForWindowExposed(&editor));
  QTRY_VERIFY(editor.scene()->isReady());  // the 3-D window is a native child: exposed a moment later
  editor.setDocument(grid());
  auto* scene = editor.scene();
  auto* vtk = scene->findChild<QWidget*>(QStringLiteral("sceneVtkWidget"));
  QVERIFY(vtk);
  scene->render();
  // Where node 5 (0.1, 0.1, 0) is drawn, in widget pixels.
  vtkRenderer* renderer = scene->renderer();
  renderer->SetWorldPoint(0.1, 0.1, 0.0, 1.0);
  renderer->WorldToDisplay();
  double display[3];
  renderer->GetDisplayPoint(display);
  const double ratio = vtk->devicePixelRatioF();
  const QPoint at(qRound(display[0] / ratio), qRound((vtk->height() * ratio - 1 - display[1]) / ratio));
  QCOMPARE(scene->nodeAt(at), std::optional<int>(5));
  QTest::mouseClick(vtk, Qt::LeftButton, Qt::NoModifier, at);
  QCOMPARE(editor.selectedNodes(), std::vector<int>{5});
  QCOMPARE(scene->selectedNodes(), std::vector<int>{5});
  // Ctrl-click adds node 1; selecting in the table shows in the scene.
  renderer->SetWorldPoint(0.0, 0.0, 0.0, 1.0);
  renderer->WorldToDisplay();
  renderer->GetDisplayPoint(display);
  const QPoint at1(qRound(display[0] / ratio), qRound((vtk->height() * ratio - 1 - display[1]) / ratio));
  QTest::mouseClick(vtk, Qt::LeftButton, Qt::ControlModifier, at1);
  QCOMPARE(editor.selectedNodes(), (std::vector<int>{5, 1}));
  auto* table = editor.findChild<QTableView*>(QStringLiteral("meshNodeTable"));
  table->selectionModel()->select(table->model()->index(2, 0),
                                  QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
  QCOMPARE(scene->selectedNodes(), std::vector<int>{3});
}

void MeshEditorTest::orphaningMeasuredDataAsksAndNamesIt() {
  MeshEditor editor;
  editor.setDocument(grid());
  editor.setMeasuredData({{"FRF set 2 'frame-a hammer'", {dofZ(2), dofZ(3)}}});
  QString asked;
  bool answer = false;
  editor.setConfirmHandler([&](const QString&, const QString& text) {
    asked = text;
    return answer;
  });
  editor.selectNodes({3});
  QVERIFY(!editor.deleteSelection());  // declined
  QVERIFY2(asked.contains(QStringLiteral("FRF set 2 'frame-a hammer' (3:+Z)")), qPrintable(asked));
  QCOMPARE(editor.document().mesh.nodes.size(), std::size_t{6});
  QCOMPARE(editor.undoStack()->count(), 0);
  asked.clear();
  QVERIFY(editor.moveSelection(Vector3(0, 0, 0.01)));  // moving orphans nothing: no question
  QVERIFY(asked.isEmpty());
  answer = true;
  QVERIFY(editor.renumberNode(2, 20));  // renumbering does orphan: asked, accepted
  QVERIFY(asked.contains(QStringLiteral("(2:+Z)")));
  QVERIFY(!mozzi::core::geometry::nodeIndex(editor.document(), 2));
}

void MeshEditorTest::exportThenImportGivesTheSameMesh() {
  QTemporaryDir dir;
  MeshEditor editor;
  MeshDocument d = grid();
  mozzi::core::io::StoredCoordinateSystem cs;
  cs.label = 2;
  cs.name = "rotated";
  cs.rotation << 0, 0, 1, 0, 1, 0, -1, 0, 0;
  cs.origin = Vector3(1.0 / 3.0, 0, 0);
  d.mesh.coordinateSystems = {cs};
  d.mesh.nodes[5].definitionCs = 2;
  d.mesh.nodes[5].position = Vector3(0.1 / 3.0, 2.0 / 7.0, -0.05);
  d.mesh.faces = {{1, 2, 5, 4}};
  d.slaves = {{dofZ(5), {{dofZ(2), 0.5}, {dofZ(3), 0.5}}}};
  editor.setDocument(d);
  const QString csvPath = dir.filePath(QStringLiteral("grid.csv"));
  const QString uffPath = dir.filePath(QStringLiteral("grid.uff"));
  QVERIFY(editor.exportFile(csvPath));
  QVERIFY(editor.exportFile(uffPath));
  QVERIFY(editor.lastMessage().contains(QStringLiteral("export to CSV to keep them")));

  MeshEditor fromCsv;
  QVERIFY(fromCsv.importFile(csvPath));
  QVERIFY(mozzi::core::io::sameDocument(fromCsv.document(), d));
  MeshEditor fromUff;
  QVERIFY(fromUff.importFile(uffPath));
  mozzi::core::io::StoredMesh geometry = d.mesh;
  geometry.faces.clear();
  QVERIFY(mozzi::core::io::sameMesh(fromUff.document().mesh, geometry));
  // A vendor file imports as it does in the project import (36 nodes, 30 segments).
  MeshEditor vendor;
  QVERIFY(vendor.importFile(QStringLiteral(MOZZI_SHARED_DATA_DIR "/uff/TestLab 161 164 18 15 82.uff")));
  QCOMPARE(vendor.document().mesh.nodes.size(), std::size_t{36});
  QCOMPARE(vendor.scene()->meshLineCount(), 30);
  // A broken file leaves the mesh untouched and says why.
  QFile bad(dir.filePath(QStringLiteral("bad.csv")));
  QVERIFY(bad.open(QIODevice::WriteOnly));
  bad.write("node,x [m],y [m],z [m]\n1,0,0,oops\n");
  bad.close();
  QVERIFY(!vendor.importFile(bad.fileName()));
  QVERIFY2(vendor.lastMessage().contains(QStringLiteral("bad.csv:2, column 4")), qPrintable(vendor.lastMessage()));
  QCOMPARE(vendor.document().mesh.nodes.size(), std::size_t{36});
}

void MeshEditorTest::templateReplacesTheMeshAndUndoBringsItBack() {
  MeshEditor editor;
  editor.setDocument(grid());
  MeshDocument ladder;
  for (int i = 0; i < 4; ++i) {
    mozzi::core::io::StoredNode n;
    n.label = 101 + i;
    n.position = Vector3(0, 0, 0.2 * i);
    ladder.mesh.nodes.push_back(n);
  }
  ladder.mesh.lines = {{101, 102}, {102, 103}, {103, 104}};
  editor.setTemplates({{QStringLiteral("ladder"), QStringLiteral("Ladder"),
                        [ladder]() -> mozzi::core::Result<MeshDocument> { return ladder; }}});
  QVERIFY(editor.startFromTemplate(QStringLiteral("ladder")));
  QVERIFY(mozzi::core::io::sameDocument(editor.document(), ladder));
  QCOMPARE(editor.scene()->meshLineCount(), 3);
  editor.undoStack()->undo();
  QVERIFY(mozzi::core::io::sameDocument(editor.document(), grid()));
  QVERIFY(!editor.startFromTemplate(QStringLiteral("nope")));
}

int main(int argc, char** argv) {
  mozzi::views::SceneView::prepareSurfaceFormat();
  QApplication app(argc, argv);
  MeshEditorTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "mesh_editor_test.moc"
