// ProjectModel: every mutator writes through the store and emits the signal
// of its kind of record (and recordsChanged) with the right id; notifyChanged
// from a worker thread reaches GUI-thread receivers queued, in the GUI thread;
// failed opens leave the open project untouched; a job's store handle outlives
// close(); an FRF set is read once and shared until the project changes.
#include "views/common/project_model.h"

#include <QApplication>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QThread>
#include <QtTest>

#include <thread>

using mozzi::views::ProjectModel;
using mozzi::views::RecordKind;
namespace io = mozzi::core::io;

namespace {

mozzi::core::FrfMatrix smallFrf() {
  mozzi::core::FrfMatrix frf;
  frf.frequencyHz = mozzi::core::Vector::LinSpaced(8, 1.0, 8.0);
  frf.responses = {{1, mozzi::core::Direction::Z, false}};
  frf.references = {{1, mozzi::core::Direction::Z, true}};
  frf.h.emplace_back(mozzi::core::ComplexMatrix::Constant(8, 1, mozzi::core::Complex(1.0, -0.5)));
  return frf;
}

// The (kind, id) pairs recordsChanged carried, in order.
QList<QPair<RecordKind, qint64>> records(const QSignalSpy& spy) {
  QList<QPair<RecordKind, qint64>> out;
  for (const auto& args : spy) out << qMakePair(args.at(0).value<RecordKind>(), args.at(1).toLongLong());
  return out;
}

}  // namespace

class ProjectModelTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    QVERIFY(dir_.isValid());
    model_ = std::make_unique<ProjectModel>();
    model_->setMozziVersion(QStringLiteral("test"));
    QVERIFY(model_->create(path(QStringLiteral("p%1.mozzi").arg(++serial_))).ok());
  }
  void cleanup() { model_.reset(); }

  void closedModelRefusesWrites() {
    ProjectModel closed;
    QVERIFY(!closed.isOpen());
    QVERIFY(closed.store() == nullptr);
    QVERIFY(closed.path().isEmpty());
    auto id = closed.addSpecimen(QStringLiteral("Frame A"), QStringLiteral("frame"));
    QVERIFY(!id.ok());
    QCOMPARE(id.error().code, mozzi::core::ErrorCode::NotFound);
  }

  void eachMutatorEmitsItsSignal() {
    QSignalSpy all(model_.get(), &ProjectModel::recordsChanged);
    QSignalSpy specimens(model_.get(), &ProjectModel::specimensChanged);
    QSignalSpy meshes(model_.get(), &ProjectModel::meshChanged);
    QSignalSpy campaigns(model_.get(), &ProjectModel::campaignsChanged);
    QSignalSpy hits(model_.get(), &ProjectModel::hitsChanged);
    QSignalSpy frfSets(model_.get(), &ProjectModel::frfSetsChanged);
    QSignalSpy modal(model_.get(), &ProjectModel::modalResultsChanged);
    QSignalSpy rigTests(model_.get(), &ProjectModel::rigTestsChanged);
    QSignalSpy tyreTests(model_.get(), &ProjectModel::tyreTestsChanged);
    QSignalSpy models(model_.get(), &ProjectModel::modelsChanged);
    QSignalSpy analyses(model_.get(), &ProjectModel::analysesChanged);

    auto sp = model_->addSpecimen(QStringLiteral("Fork A"), QStringLiteral("fork"), QStringLiteral("thesis §5"));
    QVERIFY(sp.ok());
    QCOMPARE(specimens.count(), 1);
    QCOMPARE(model_->recordName(RecordKind::Specimen, *sp), QStringLiteral("Fork A"));

    io::StoredMesh mesh;
    mesh.nodes = {{0, 1, 0, 0, mozzi::core::Vector3(0, 0, 0)}, {0, 2, 0, 0, mozzi::core::Vector3(1, 0, 0)}};
    mesh.lines = {{1, 2}};
    QVERIFY(model_->setMesh(*sp, mesh).ok());
    QCOMPARE(meshes.count(), 1);
    QCOMPARE(meshes.first().first().toLongLong(), *sp);

    io::StoredCampaign campaign;
    campaign.specimenId = *sp;
    campaign.name = "roving hammer";
    auto c = model_->addCampaign(campaign);
    QVERIFY(c.ok());
    QCOMPARE(campaigns.count(), 1);
    QCOMPARE(campaigns.first().first().toLongLong(), *sp);

    io::StoredHit hit;
    hit.campaignId = *c;
    hit.sequence = 1;
    hit.point = {1, mozzi::core::Direction::Z, false};
    hit.sampleRateHz = 1024.0;
    hit.samples = Eigen::MatrixXf::Ones(16, 2);
    QVERIFY(model_->commitHit(hit).ok());
    QCOMPARE(hits.count(), 1);
    QCOMPARE(hits.first().first().toLongLong(), *c);

    io::FrfSetInfo info;
    info.specimenId = *sp;
    info.name = "run 1";
    auto set = model_->addFrfSet(info, smallFrf());
    QVERIFY(set.ok());
    QCOMPARE(frfSets.count(), 1);
    QCOMPARE(model_->recordName(RecordKind::FrfSet, *set), QStringLiteral("run 1"));

    io::ModalResultInfo modalInfo;
    modalInfo.specimenId = *sp;
    modalInfo.name = "LSCE 0-200 Hz";
    io::ModalTable table;
    table.modes = {{42.0, 0.01, {}}};
    auto result = model_->addModalResult(modalInfo, table);
    QVERIFY(result.ok());
    QCOMPARE(modal.count(), 1);

    io::StoredRigTest rig;
    rig.specimenId = *sp;
    rig.name = "static";
    auto rigId = model_->addRigTest(rig);
    QVERIFY(rigId.ok());
    QCOMPARE(rigTests.count(), 1);
    io::StoredTyreTest tyre;
    tyre.specimenId = *sp;
    tyre.name = "relaxation";
    auto tyreId = model_->addTyreTest(tyre);
    QVERIFY(tyreId.ok());
    QCOMPARE(tyreTests.count(), 1);
    io::StoredModel m;
    m.specimenId = *sp;
    m.name = "fork model 2";
    m.kind = "lumped";
    auto modelId = model_->addModel(m);
    QVERIFY2(modelId.ok(), modelId.ok() ? "" : modelId.error().describe().c_str());
    QCOMPARE(models.count(), 1);
    io::StoredAnalysis a;
    a.specimenId = *sp;
    a.name = "gap";
    auto analysisId = model_->addAnalysis(a);
    QVERIFY(analysisId.ok());
    QCOMPARE(analyses.count(), 1);

    const QList<QPair<RecordKind, qint64>> expected{{RecordKind::Specimen, *sp},   {RecordKind::Mesh, *sp},
                                                    {RecordKind::Campaign, *sp},   {RecordKind::Hit, *c},
                                                    {RecordKind::FrfSet, *set},    {RecordKind::ModalResult, *result},
                                                    {RecordKind::RigTest, *rigId}, {RecordKind::TyreTest, *tyreId},
                                                    {RecordKind::Model, *modelId}, {RecordKind::Analysis, *analysisId}};
    QCOMPARE(records(all), expected);

    // Deleting the specimen takes everything it owned: every list is told.
    all.clear();
    QVERIFY(model_->deleteSpecimen(*sp).ok());
    QCOMPARE(specimens.count(), 2);
    QCOMPARE(frfSets.count(), 2);
    QCOMPARE(modal.count(), 2);
    QCOMPARE(analyses.count(), 2);
    QCOMPARE(all.count(), 9);
    QVERIFY(model_->store()->summary()->specimens.empty());
  }

  void frfSetIsReadOnceUntilTheProjectChanges() {
    auto sp = model_->addSpecimen(QStringLiteral("Fork A"), QStringLiteral("fork"));
    QVERIFY(sp.ok());
    io::FrfSetInfo info;
    info.specimenId = *sp;
    std::vector<qint64> ids;
    for (int k = 0; k < 4; ++k) {
      info.name = "run " + std::to_string(k + 1);
      auto set = model_->addFrfSet(info, smallFrf());
      QVERIFY(set.ok());
      ids.push_back(*set);
    }
    auto first = model_->frfSet(ids[0]);
    QVERIFY(first.ok());
    // As stored: the values smallFrf() wrote.
    QCOMPARE((*first)->lineCount(), Eigen::Index(8));
    QCOMPARE((*first)->h[0](3, 0), mozzi::core::Complex(1.0, -0.5));
    auto again = model_->frfSet(ids[0]);
    QVERIFY(again.ok());
    QCOMPARE(again->get(), first->get());  // shared, not read again
    // Three more sets read: the first drops out of the kept ones and is read again.
    for (int k = 1; k < 4; ++k) QVERIFY(model_->frfSet(ids[static_cast<std::size_t>(k)]).ok());
    QCOMPARE(ProjectModel::kFrfSetsKept, std::size_t(3));
    auto reread = model_->frfSet(ids[0]);
    QVERIFY(reread.ok());
    QVERIFY(reread->get() != first->get());
    QCOMPARE((*reread)->h[0], (*first)->h[0]);
    // A change drops them all: the deleted specimen's sets are gone, not served from memory.
    auto kept = model_->frfSet(ids[3]);
    QVERIFY(kept.ok());
    QVERIFY(model_->deleteSpecimen(*sp).ok());
    auto gone = model_->frfSet(ids[3]);
    QVERIFY(!gone.ok());
    QCOMPARE(gone.error().code, mozzi::core::ErrorCode::NotFound);
    model_->close();
    QVERIFY(!model_->frfSet(ids[0]).ok());
  }

  void failedWritesEmitNothing() {
    QSignalSpy all(model_.get(), &ProjectModel::recordsChanged);
    QVERIFY(!model_->setMesh(999, io::StoredMesh{}).ok());
    io::StoredCampaign orphan;
    orphan.specimenId = 999;
    QVERIFY(!model_->addCampaign(orphan).ok());
    QVERIFY(!model_->importUff(path(QStringLiteral("missing.uff")), 1).ok());
    QCOMPARE(all.count(), 0);
  }

  void notifyFromAWorkerArrivesQueuedInTheGuiThread() {
    QThread* gui = QThread::currentThread();
    QThread* seenIn = nullptr;
    qint64 seenId = 0;
    connect(model_.get(), &ProjectModel::hitsChanged, this, [&](qint64 campaignId) {
      seenIn = QThread::currentThread();
      seenId = campaignId;
    });
    QSignalSpy hits(model_.get(), &ProjectModel::hitsChanged);
    QSignalSpy all(model_.get(), &ProjectModel::recordsChanged);
    std::thread worker([this] {
      // An engine would have written through store() here.
      model_->notifyChanged(RecordKind::Hit, 77);
    });
    worker.join();
    QCOMPARE(hits.count(), 0);  // queued: nothing until the GUI thread runs its events
    QVERIFY(hits.wait(5000));
    QCOMPARE(seenId, qint64(77));
    QCOMPARE(seenIn, gui);
    QCOMPARE(records(all), (QList<QPair<RecordKind, qint64>>{{RecordKind::Hit, 77}}));

    // From the GUI thread the signal is emitted before notifyChanged returns.
    model_->notifyChanged(RecordKind::FrfSet, 3);
    QCOMPARE(all.count(), 2);
    disconnect(model_.get(), &ProjectModel::hitsChanged, this, nullptr);
  }

  void failedOpenLeavesTheProjectOpen() {
    const QString before = model_->path();
    QSignalSpy changed(model_.get(), &ProjectModel::projectChanged);
    auto r = model_->open(path(QStringLiteral("no-such.mozzi")));
    QVERIFY(!r.ok());
    QVERIFY(model_->isOpen());
    QCOMPARE(model_->path(), before);
    QVERIFY(!model_->create(before).ok());  // exists: refused
    QCOMPARE(model_->path(), before);
    QCOMPARE(changed.count(), 0);
    QVERIFY(model_->addSpecimen(QStringLiteral("still writable"), QStringLiteral("frame")).ok());
  }

  void openCloseAndSaveAsSignalTheProject() {
    QSignalSpy changed(model_.get(), &ProjectModel::projectChanged);
    QSignalSpy closing(model_.get(), &ProjectModel::aboutToClose);
    const QString copy = path(QStringLiteral("copy%1.mozzi").arg(serial_));
    QVERIFY(model_->saveAs(copy).ok());
    QCOMPARE(model_->path(), copy);
    QCOMPARE(changed.count(), 1);
    QCOMPARE(closing.count(), 1);
    // A job holding the store keeps it usable after the user closed the project.
    auto handle = model_->storeHandle();
    model_->close();
    QVERIFY(!model_->isOpen());
    QCOMPARE(changed.count(), 2);
    QCOMPARE(closing.count(), 2);
    QVERIFY(handle->summary().ok());
  }

  void integrityCheckOfTheOpenProject() {
    QVERIFY(model_->checkIntegrity().ok());
    QVERIFY(model_->addSpecimen(QStringLiteral("Frame B"), QStringLiteral("frame")).ok());  // still writable
    ProjectModel closed;
    QVERIFY(!closed.checkIntegrity().ok());
  }

  void demoProjectOpens() {
    QVERIFY(model_->createDemo(path(QStringLiteral("demo%1.mozzi").arg(serial_))).ok());
    QVERIFY(model_->isOpen());
    QVERIFY(!model_->isReadOnly());
    auto summary = model_->summary();
    QVERIFY(summary.ok());
    QVERIFY(!summary->specimens.empty());
  }

 private:
  QString path(const QString& name) const { return QDir(dir_.path()).filePath(name); }
  QTemporaryDir dir_;
  std::unique_ptr<ProjectModel> model_;
  int serial_ = 0;
};

QTEST_MAIN(ProjectModelTest)
#include "project_model_test.moc"
