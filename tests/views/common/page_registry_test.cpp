// The page table and the tabs built from it: the right page opens for a
// project item (the first registered that opens it), a singleton has one tab
// and follows the selection, other pages get one tab per item titled with the
// record's name, bad entries are refused, item tabs close with the project,
// and the project tree hands out the items its rows stand for.
#include "views/common/page_registry.h"

#include <QApplication>
#include <QLabel>
#include <QScrollArea>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTreeWidgetItemIterator>
#include <QtTest>

#include "views/common/job_runner.h"
#include "views/common/page_tabs.h"
#include "views/common/project_tree.h"

using mozzi::views::JobRunner;
using mozzi::views::PageContext;
using mozzi::views::PageMenu;
using mozzi::views::PageRegistry;
using mozzi::views::PageSpec;
using mozzi::views::PageTabs;
using mozzi::views::ProjectItem;
using mozzi::views::ProjectModel;
using mozzi::views::RecordKind;

namespace {

// A page that says what it was opened on and what it was last shown.
struct Probe {
  int created = 0;
  QList<ProjectItem> shown;
};

PageSpec labelPage(const QString& id, const char* title, bool singleton, std::function<bool(const ProjectItem&)> opens,
                   Probe* probe) {
  PageSpec spec;
  spec.id = id;
  spec.title = title;
  spec.opensItem = std::move(opens);
  spec.singleton = singleton;
  spec.create = [probe, id](const PageContext& ctx) -> QWidget* {
    ++probe->created;
    auto* label = new QLabel(QStringLiteral("%1 on %2").arg(id).arg(ctx.item.id), ctx.parent);
    if (!ctx.model || !ctx.jobs) qFatal("a page got no model or job runner");
    return label;
  };
  if (singleton) {
    spec.showItem = [probe](QWidget*, const PageContext& ctx) { probe->shown << ctx.item; };
  }
  return spec;
}

}  // namespace

class PageRegistryTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    model_.setMozziVersion(QStringLiteral("test"));
    QVERIFY(model_.create(QDir(dir_.path()).filePath(QStringLiteral("pages.mozzi"))).ok());
    auto sp = model_.addSpecimen(QStringLiteral("Swing-arm B"), QStringLiteral("swing-arm"));
    QVERIFY(sp.ok());
    specimen_ = *sp;
    mozzi::core::FrfMatrix frf;
    frf.frequencyHz = mozzi::core::Vector::LinSpaced(4, 1.0, 4.0);
    frf.responses = {{1, mozzi::core::Direction::Z, false}};
    frf.references = {{1, mozzi::core::Direction::Z, true}};
    frf.h.emplace_back(mozzi::core::ComplexMatrix::Ones(4, 1));
    for (const char* name : {"hammer run 1", "hammer run 2"}) {
      mozzi::core::io::FrfSetInfo info;
      info.specimenId = specimen_;
      info.name = name;
      auto id = model_.addFrfSet(info, frf);
      QVERIFY(id.ok());
      sets_ << *id;
    }

    QVERIFY(registry_.add(labelPage(
        QStringLiteral("mesh"), "Mesh", true, [](const ProjectItem& i) { return i.kind == RecordKind::Specimen; },
        &mesh_)));
    QVERIFY(registry_.add(labelPage(
        QStringLiteral("frf"), "FRF", false, [](const ProjectItem& i) { return i.kind == RecordKind::FrfSet; },
        &frf_)));
    QVERIFY(registry_.add(labelPage(
        QStringLiteral("bode"), "Bode", false, [](const ProjectItem& i) { return i.kind == RecordKind::FrfSet; },
        &bode_)));
    auto menuPage = labelPage(QStringLiteral("tool"), "Tool", true, nullptr, &tool_);
    menuPage.menu = PageMenu::Tools;
    QVERIFY(registry_.add(menuPage));
  }

  void refusesBadEntries() {
    PageRegistry registry;
    PageSpec spec = labelPage(QStringLiteral("x"), "X", false, nullptr, &tool_);
    QVERIFY(registry.add(spec));
    QVERIFY(!registry.add(spec));  // id taken
    spec.id.clear();
    QVERIFY(!registry.add(spec));
    spec.id = QStringLiteral("y");
    spec.create = nullptr;
    QVERIFY(!registry.add(spec));
    spec = labelPage(QStringLiteral("z"), nullptr, false, nullptr, &tool_);
    QVERIFY(!registry.add(spec));
    QCOMPARE(registry.pages().size(), size_t(1));
  }

  void pagesForAnItemInTableOrder() {
    const auto forSet = registry_.pagesFor({RecordKind::FrfSet, sets_[0], specimen_});
    QCOMPARE(forSet.size(), size_t(2));
    QCOMPARE(forSet[0]->id, QStringLiteral("frf"));
    QCOMPARE(forSet[1]->id, QStringLiteral("bode"));
    const auto forSpecimen = registry_.pagesFor({RecordKind::Specimen, specimen_, specimen_});
    QCOMPARE(forSpecimen.size(), size_t(1));
    QCOMPARE(forSpecimen[0]->id, QStringLiteral("mesh"));
    QVERIFY(registry_.pagesFor({RecordKind::TyreTest, 1, 0}).empty());
    QVERIFY(registry_.pagesFor({}).empty());  // a menu page is not an item's page
    QVERIFY(registry_.find(QStringLiteral("tool")));
    QVERIFY(!registry_.find(QStringLiteral("nope")));
    QCOMPARE(PageRegistry::title(*registry_.find(QStringLiteral("frf"))), QStringLiteral("FRF"));
  }

  void tabsOpenTheRightPageOncePerItem() {
    JobRunner jobs;
    PageTabs tabs(&registry_, &model_, &jobs);
    const ProjectItem set0{RecordKind::FrfSet, sets_[0], specimen_};
    const ProjectItem set1{RecordKind::FrfSet, sets_[1], specimen_};

    QWidget* a = tabs.openItem(set0);
    QVERIFY(a);
    QCOMPARE(tabs.specOf(a)->id, QStringLiteral("frf"));  // the default page of an FRF set
    QCOMPARE(tabs.itemOf(a), set0);
    QCOMPARE(tabs.tabText(tabs.indexOfPage(a)), QStringLiteral("FRF: hammer run 1"));
    // Pages sit in scroll areas: a page cannot push the window past the screen.
    QVERIFY(qobject_cast<QScrollArea*>(tabs.widget(tabs.indexOfPage(a))));
    QCOMPARE(tabs.openItem(set0), a);  // raised, not opened again
    QCOMPARE(tabs.count(), 1);
    QWidget* b = tabs.openItem(set1);
    QVERIFY(b && b != a);
    QCOMPARE(tabs.tabText(tabs.indexOfPage(b)), QStringLiteral("FRF: hammer run 2"));
    QWidget* c = tabs.openPage(QStringLiteral("bode"), set0);  // "Open in Bode"
    QVERIFY(c && c != a);
    QCOMPARE(tabs.currentPage(), c);
    QCOMPARE(tabs.count(), 3);
    QCOMPARE(frf_.created, 2);

    // A page does not open what it does not claim; unknown pages open nothing.
    QVERIFY(!tabs.openPage(QStringLiteral("frf"), {RecordKind::Specimen, specimen_, specimen_}));
    QVERIFY(!tabs.openPage(QStringLiteral("nope")));
    QVERIFY(!tabs.openItem({RecordKind::TyreTest, 1, 0}));

    // A singleton: one tab; opening it on another item shows that item in it.
    QWidget* tool = tabs.openPage(QStringLiteral("tool"));
    QVERIFY(tool);
    QCOMPARE(tabs.openPage(QStringLiteral("tool")), tool);
    QCOMPARE(tool_.created, 1);
    QWidget* mesh = tabs.openItem({RecordKind::Specimen, specimen_, specimen_});
    QVERIFY(mesh);
    QCOMPARE(mesh_.shown.size(), 1);
    QCOMPARE(tabs.tabText(tabs.indexOfPage(mesh)), QStringLiteral("Mesh"));
    // It follows the tree's selection when it opens the selected item.
    tabs.followSelection({RecordKind::Specimen, 4242, 4242});
    QCOMPARE(mesh_.shown.size(), 2);
    QCOMPARE(mesh_.shown.last().id, qint64(4242));
    tabs.followSelection(set1);  // not a specimen: not shown
    QCOMPARE(mesh_.shown.size(), 2);
    QCOMPARE(tabs.openItem({RecordKind::Specimen, specimen_, specimen_}), mesh);
    QCOMPARE(mesh_.created, 1);

    // A new project closes the item tabs (their records belong to the old one).
    const int before = tabs.count();
    emit model_.projectChanged();
    QCOMPARE(tabs.count(), before - 3);
    QVERIFY(tabs.findPage(QStringLiteral("tool")));
    QVERIFY(!tabs.findPage(QStringLiteral("frf"), set0));
  }

  void treeRowsCarryTheirItems() {
    mozzi::views::ProjectTree tree(&model_);
    QSignalSpy open(&tree, &mozzi::views::ProjectTree::openRequested);
    QTreeWidgetItem* setRow = nullptr;
    QTreeWidgetItem* specimenRow = nullptr;
    for (QTreeWidgetItemIterator it(&tree); *it; ++it) {
      const ProjectItem item = mozzi::views::ProjectTree::itemOf(*it);
      if (item.kind == RecordKind::FrfSet && item.id == sets_[1]) setRow = *it;
      if (item.kind == RecordKind::Specimen) specimenRow = *it;
    }
    QVERIFY(setRow && specimenRow);
    QCOMPARE(setRow->text(0), QStringLiteral("hammer run 2"));
    QCOMPARE(mozzi::views::ProjectTree::itemOf(setRow).specimenId, specimen_);
    emit tree.itemActivated(setRow, 0);
    QCOMPARE(open.count(), 1);
    QCOMPARE(open.first().first().value<ProjectItem>(), (ProjectItem{RecordKind::FrfSet, sets_[1], specimen_}));

    QSignalSpy selection(&tree, &mozzi::views::ProjectTree::currentProjectItemChanged);
    QVERIFY(tree.selectItem({RecordKind::Specimen, specimen_, specimen_}));
    QCOMPARE(selection.count(), 1);
    const auto props = tree.currentProperties();
    QCOMPARE(props.value(0).second, QStringLiteral("Swing-arm B"));
    QCOMPARE(props.value(3).second, QStringLiteral("none"));  // no mesh yet
    // A new record rebuilds the tree and keeps the selection.
    QVERIFY(model_.addSpecimen(QStringLiteral("Fork B"), QStringLiteral("fork")).ok());
    QCOMPARE(tree.currentProjectItem().id, specimen_);
    QCOMPARE(selection.count(), 1);
  }

 private:
  QTemporaryDir dir_;
  ProjectModel model_;
  PageRegistry registry_;
  qint64 specimen_ = 0;
  QList<qint64> sets_;
  Probe mesh_, frf_, bode_, tool_;
};

QTEST_MAIN(PageRegistryTest)
#include "page_registry_test.moc"
