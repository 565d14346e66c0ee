// The mesh editor and mode animation pages on a real project, through the
// ProjectModel: an edit is written to the project (and heard as
// meshChanged), undo writes the old mesh back, the orphan question names the
// FRF set stored on the specimen, and the animation page shows the stored
// modes on the stored mesh.
#include "views/editors/mesh_editor_page.h"

#include <QApplication>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include "views/common/project_model.h"
#include "views/editors/mesh_editor.h"
#include "views/scene/mode_animation_page.h"
#include "views/scene/mode_animation_view.h"
#include "views/scene/scene_view.h"

using namespace mozzi;

namespace {
core::Dof dofZ(int node) {
  return core::Dof{node, core::Direction::Z, false};
}
}  // namespace

class MeshEditorPageTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    QVERIFY(model_.create(dir_.filePath(QStringLiteral("p.mozzi"))).ok());
    auto id = model_.addSpecimen(QStringLiteral("Fork A"), QStringLiteral("fork"));
    QVERIFY(id.ok());
    specimen_ = *id;
    core::io::StoredMesh mesh;
    for (int k = 1; k <= 4; ++k) {
      core::io::StoredNode n;
      n.label = k;
      n.position = core::Vector3(0, 0, 0.1 * k);
      mesh.nodes.push_back(n);
    }
    mesh.lines = {{1, 2}, {2, 3}, {3, 4}};
    QVERIFY(model_.setMesh(specimen_, mesh).ok());
    core::FrfMatrix frf;
    frf.frequencyHz = core::Vector::LinSpaced(50, 1.0, 50.0);
    frf.responses = {dofZ(2), dofZ(4)};
    frf.references = {dofZ(4)};
    frf.h = {core::ComplexMatrix::Constant(50, 2, core::Complex(1.0, 0.5))};
    core::io::FrfSetInfo info;
    info.specimenId = specimen_;
    info.name = "fork-a hammer";
    auto set = model_.addFrfSet(info, frf);
    QVERIFY(set.ok());
    frfSet_ = *set;
    core::io::ModalTable table;
    table.dofs = {dofZ(2), dofZ(4)};
    table.modes = {{41.5, 0.01, core::ComplexVector::Constant(2, 1.0)},
                   {97.0, 0.02, (core::ComplexVector(2) << 1.0, -1.0).finished()}};
    core::io::ModalResultInfo result;
    result.specimenId = specimen_;
    result.frfSetId = frfSet_;
    result.name = "PolyMAX";
    auto r = model_.addModalResult(result, table);
    QVERIFY(r.ok());
    result_ = *r;
  }

  void editsAreSavedAndUndoSavesTheOldMesh() {
    views::MeshEditorPage page(&model_, specimen_);
    auto* editor = page.editor();
    // The DOFs the FRF set names are the measurement DOFs shown.
    QCOMPARE(editor->document().measurementDofs, (std::vector<core::Dof>{dofZ(2), dofZ(4)}));
    QString asked;
    editor->setConfirmHandler([&](const QString&, const QString& text) {
      asked = text;
      return true;
    });
    QSignalSpy changed(&model_, &views::ProjectModel::meshChanged);
    editor->selectNodes({4});
    QVERIFY(editor->deleteSelection());
    QVERIFY2(asked.contains(QStringLiteral("FRF set %1 'fork-a hammer' (4:+Z)").arg(frfSet_)), qPrintable(asked));
    QVERIFY(asked.contains(QStringLiteral("modal result %1 'PolyMAX' (4:+Z)").arg(result_)));
    QCOMPARE(changed.count(), 1);
    QCOMPARE(model_.store()->mesh(specimen_)->nodes.size(), std::size_t{3});
    editor->undoStack()->undo();
    QCOMPARE(model_.store()->mesh(specimen_)->nodes.size(), std::size_t{4});
    QCOMPARE(model_.store()->mesh(specimen_)->lines.size(), std::size_t{3});
    // A change by someone else reloads the page.
    auto mesh = *model_.store()->mesh(specimen_);
    mesh.nodes[0].position.x() = 0.05;
    QVERIFY(model_.setMesh(specimen_, mesh).ok());
    QCOMPARE(editor->document().mesh.nodes[0].position.x(), 0.05);
    QCOMPARE(editor->undoStack()->count(), 0);
  }

  void animationPageShowsTheStoredModes() {
    views::ModeAnimationPage page(&model_, result_);
    auto* view = page.view();
    QCOMPARE(view->shapes().size(), std::size_t{2});
    QVERIFY(view->field());
    QCOMPARE(view->field()->measuredNodes, 2);
    QCOMPARE(view->scene()->meshPointCount(), 4);
    QVERIFY(view->showOds(10.2));  // the result's FRF set gives the ODS
    QVERIFY(view->compareWith(1));
    QVERIFY(std::abs(*view->mac()) < 1e-12);  // (1, 1) against (1, -1)
  }

 private:
  QTemporaryDir dir_;
  views::ProjectModel model_;
  qint64 specimen_ = 0;
  qint64 frfSet_ = 0;
  qint64 result_ = 0;
};

int main(int argc, char** argv) {
  views::SceneView::prepareSurfaceFormat();
  QApplication app(argc, argv);
  MeshEditorPageTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "mesh_editor_page_test.moc"
