#include "views/panels/project_overview.h"

#include <QDir>
#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QTimer>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>

#include "views/common/project_model.h"

namespace mozzi {
namespace views {

namespace {

// The job a page serves (WORKBENCH.md, "The three jobs"); setting up a
// specimen comes before the technician's job at the rig.
enum class Job { Setup, Rig, Review };
constexpr Job kJobs[] = {Job::Setup, Job::Rig, Job::Review};

Job jobOf(const QString& pageId) {
  if (pageId == QLatin1String("hammer-station") || pageId == QLatin1String("stiffness-rig") ||
      pageId == QLatin1String("tyre-tester"))
    return Job::Rig;
  if (pageId == QLatin1String("scene") || pageId == QLatin1String("mesh-editor")) return Job::Setup;
  return Job::Review;
}

// Specimens table columns.
enum Column {
  kName,
  kKind,
  kMeshNodes,
  kCampaigns,
  kFrfSets,
  kModalResults,
  kRigTests,
  kTyreTests,
  kAnalyses,
  kDescription,
  kColumnCount
};

constexpr int kEntryRole = Qt::UserRole + 1;  // index into entries_ on a start-list row

QTableWidgetItem* countItem(std::size_t count) {
  auto* item = new QTableWidgetItem(count ? QString::number(count) : QString());
  item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
  return item;
}

}  // namespace

ProjectOverview::ProjectOverview(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  title_ = new QLabel(this);
  title_->setObjectName(QStringLiteral("overviewTitle"));
  QFont big = title_->font();
  big.setPointSizeF(big.pointSizeF() * 1.6);
  big.setBold(true);
  title_->setFont(big);
  details_ = new QLabel(this);
  details_->setObjectName(QStringLiteral("overviewDetails"));
  details_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  details_->setWordWrap(true);

  QFont heading = font();
  heading.setBold(true);
  heading.setPointSizeF(heading.pointSizeF() * 1.15);
  startHeading_ = new QLabel(this);
  startHeading_->setFont(heading);
  start_ = new QTreeWidget(this);
  start_->setObjectName(QStringLiteral("overviewStart"));
  start_->setColumnCount(3);
  start_->setRootIsDecorated(false);
  start_->setUniformRowHeights(true);
  start_->setSelectionBehavior(QAbstractItemView::SelectRows);
  start_->header()->setStretchLastSection(true);
  start_->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
  connect(start_, &QTreeWidget::itemActivated, this, [this] { openCurrentStartItem(); });
  connect(start_, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* current) {
    const QVariant index = current ? current->data(0, kEntryRole) : QVariant();
    open_->setEnabled(index.isValid() && entries_[index.toUInt()].available);
  });
  open_ = new QPushButton(this);
  open_->setObjectName(QStringLiteral("overviewOpen"));
  open_->setEnabled(false);
  connect(open_, &QPushButton::clicked, this, [this] { openCurrentStartItem(); });
  reportHint_ = new QLabel(this);
  reportHint_->setWordWrap(true);
  auto* openRow = new QHBoxLayout;
  openRow->addWidget(open_);
  openRow->addWidget(reportHint_, 1);

  specimensHeading_ = new QLabel(this);
  specimensHeading_->setFont(heading);
  specimens_ = new QTableWidget(0, kColumnCount, this);
  specimens_->setObjectName(QStringLiteral("overviewSpecimens"));
  specimens_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  specimens_->setSelectionBehavior(QAbstractItemView::SelectRows);
  specimens_->horizontalHeader()->setStretchLastSection(true);
  specimens_->verticalHeader()->setVisible(false);
  // One line a row (the style's default is nearly two): more specimens above the fold.
  specimens_->verticalHeader()->setDefaultSectionSize(fontMetrics().lineSpacing() + 8);
  specimens_->setMinimumHeight(fontMetrics().lineSpacing() * 12);

  layout->addWidget(title_);
  layout->addWidget(details_);
  layout->addSpacing(fontMetrics().lineSpacing() / 2);
  layout->addWidget(startHeading_);
  layout->addWidget(start_);
  layout->addLayout(openRow);
  layout->addSpacing(fontMetrics().lineSpacing() / 2);
  layout->addWidget(specimensHeading_);
  layout->addWidget(specimens_, 1);
  retranslate();
}

void ProjectOverview::setModel(ProjectModel* model) {
  if (model_) disconnect(model_, nullptr, this, nullptr);
  model_ = model;
  if (model_) {
    connect(model_, &ProjectModel::projectChanged, this, &ProjectOverview::refresh);
    // Records added or removed change the counts and the start list; hits do
    // not (a campaign commits one every few seconds), and a burst of changes
    // (a rig test's steps) costs one refresh, when the page is next shown.
    connect(model_, &ProjectModel::recordsChanged, this, [this](RecordKind kind) {
      if (kind == RecordKind::Hit || kind == RecordKind::Project) return;
      stale_ = true;
      if (isVisible())
        QTimer::singleShot(0, this, [this] {
          if (stale_) refresh();
        });
    });
  }
  refresh();
}

void ProjectOverview::setPages(const PageRegistry* registry,
                               std::function<QWidget*(const QString&, const ProjectItem&)> openPage) {
  registry_ = registry;
  openPage_ = std::move(openPage);
  refresh();
}

void ProjectOverview::refresh() {
  stale_ = false;
  if (!model_ || !model_->isOpen()) {
    clear();
    return;
  }
  auto summary = model_->summary();
  if (!summary) {
    clear();
    return;
  }
  showSummary(model_->path(), *summary, model_->isReadOnly(), model_->readOnlyReason());
  showContents(model_->contents());
}

void ProjectOverview::showSummary(const QString& path, const core::io::ProjectSummary& summary, bool readOnly,
                                  const QString& readOnlyReason) {
  path_ = path;
  summary_ = summary;
  readOnly_ = readOnly;
  readOnlyReason_ = readOnlyReason;
  hasProject_ = true;
  fillSpecimenTable();
  retranslate();
}

void ProjectOverview::showContents(const std::vector<core::io::SpecimenContents>& contents) {
  contents_ = contents;
  fillSpecimenTable();
  buildStartEntries();
  fillStartList();
}

void ProjectOverview::fillSpecimenTable() {
  specimens_->setRowCount(static_cast<int>(summary_.specimens.size()));
  int row = 0;
  for (const auto& sp : summary_.specimens) {
    specimens_->setItem(row, kName, new QTableWidgetItem(QString::fromStdString(sp.name)));
    specimens_->setItem(row, kKind, new QTableWidgetItem(QString::fromStdString(sp.kind)));
    specimens_->setItem(row, kDescription, new QTableWidgetItem(QString::fromStdString(sp.description)));
    const core::io::SpecimenContents* held = nullptr;
    for (const auto& c : contents_)
      if (c.specimenId == sp.id) held = &c;
    const core::io::SpecimenContents none;
    const auto& c = held ? *held : none;
    specimens_->setItem(row, kMeshNodes, countItem(static_cast<std::size_t>(c.meshNodes)));
    specimens_->setItem(row, kCampaigns, countItem(c.campaigns.size()));
    specimens_->setItem(row, kFrfSets, countItem(c.frfSets.size()));
    specimens_->setItem(row, kModalResults, countItem(c.modalResults.size()));
    specimens_->setItem(row, kRigTests, countItem(c.staticRigTests.size() + c.dynamicRigTests.size()));
    specimens_->setItem(row, kTyreTests, countItem(c.tyreTests.size()));
    specimens_->setItem(row, kAnalyses, countItem(c.analyses.size()));
    ++row;
  }
  specimens_->resizeColumnsToContents();
}

// Every page but this one, on the first record of the project it opens. The
// records are tried richest first (a modal result before the FRF set it came
// from, a static test before a sweep), so each page opens on something worth
// seeing.
void ProjectOverview::buildStartEntries() {
  entries_.clear();
  if (!registry_ || !hasProject_) return;
  std::vector<ProjectItem> candidates;
  auto add = [&](RecordKind kind, const std::vector<std::int64_t> core::io::SpecimenContents::*ids) {
    for (const auto& c : contents_)
      for (std::int64_t id : c.*ids) candidates.push_back(ProjectItem{kind, id, c.specimenId});
  };
  add(RecordKind::ModalResult, &core::io::SpecimenContents::modalResults);
  add(RecordKind::FrfSet, &core::io::SpecimenContents::frfSets);
  add(RecordKind::Campaign, &core::io::SpecimenContents::campaigns);
  add(RecordKind::RigTest, &core::io::SpecimenContents::staticRigTests);
  add(RecordKind::RigTest, &core::io::SpecimenContents::dynamicRigTests);
  add(RecordKind::TyreTest, &core::io::SpecimenContents::tyreTests);
  // Analyses carry their kind, so that the page of that kind claims them (the
  // oldest of each kind first, as the store lists them).
  std::vector<core::io::AnalysisInfo> analyses;
  for (const auto& c : contents_) analyses.insert(analyses.end(), c.analyses.begin(), c.analyses.end());
  std::sort(analyses.begin(), analyses.end(), [](const auto& x, const auto& y) { return x.id < y.id; });
  for (const auto& a : analyses)
    candidates.push_back(ProjectItem{RecordKind::Analysis, a.id, a.specimenId, QString::fromStdString(a.kind)});
  for (const auto& c : contents_)
    if (c.meshNodes > 0) candidates.push_back(ProjectItem{RecordKind::Mesh, c.specimenId, c.specimenId});
  for (const auto& c : contents_) candidates.push_back(ProjectItem{RecordKind::Specimen, c.specimenId, c.specimenId});

  for (const PageSpec& spec : registry_->pages()) {
    if (spec.id == QLatin1String("overview")) continue;
    StartEntry entry;
    entry.pageId = spec.id;
    if (spec.opensItem) {
      for (const auto& candidate : candidates) {
        if (!spec.opensItem(candidate)) continue;
        entry.item = candidate;
        entry.available = true;
        break;
      }
    }
    if (!entry.available) entry.available = spec.menu != PageMenu::None;
    entries_.push_back(entry);
  }
}

QString ProjectOverview::whereText(const StartEntry& entry) const {
  if (!entry.available) return tr("needs a record this project does not hold yet");
  if (entry.item.kind == RecordKind::None) return tr("opens on its own (Pages or Tools menu)");
  QString specimen;
  for (const auto& c : contents_)
    if (c.specimenId == entry.item.specimenId) specimen = QString::fromStdString(c.name);
  if (entry.item.kind == RecordKind::Specimen) return specimen;
  if (entry.item.kind == RecordKind::Mesh) {
    for (const auto& c : contents_)
      if (c.specimenId == entry.item.specimenId) return tr("%1: mesh of %n nodes", nullptr, c.meshNodes).arg(specimen);
  }
  const QString record = model_ ? model_->recordName(entry.item.kind, entry.item.id) : QString();
  return record.isEmpty() ? specimen : tr("%1: %2").arg(specimen, record);
}

void ProjectOverview::fillStartList() {
  start_->clear();
  if (!registry_) return;
  QFont bold = start_->font();
  bold.setBold(true);
  for (Job job : kJobs) {
    QString group;
    switch (job) {
      case Job::Setup: group = tr("Setting up a specimen"); break;
      case Job::Rig: group = tr("At the rig"); break;
      case Job::Review: group = tr("Reviewing results"); break;
    }
    auto* header = new QTreeWidgetItem(start_, {group});
    header->setFirstColumnSpanned(true);
    header->setFont(0, bold);
    header->setFlags(Qt::ItemIsEnabled);
    for (std::size_t i = 0; i < entries_.size(); ++i) {
      const StartEntry& entry = entries_[i];
      if (jobOf(entry.pageId) != job) continue;
      const PageSpec* spec = registry_->find(entry.pageId);
      if (!spec) continue;
      auto* row = new QTreeWidgetItem(start_, {QStringLiteral("    ") + PageRegistry::title(*spec),
                                               PageRegistry::summary(*spec), whereText(entry)});
      row->setData(0, kEntryRole, static_cast<uint>(i));
      row->setToolTip(1, PageRegistry::summary(*spec));
      if (!entry.available) row->setFlags(Qt::NoItemFlags);
    }
  }
  start_->resizeColumnToContents(0);
  // The summaries are long: give them a readable share and let the record column take the rest.
  start_->resizeColumnToContents(1);
  start_->setColumnWidth(1, qMin(start_->columnWidth(1), fontMetrics().averageCharWidth() * 70));
  const int rows = start_->topLevelItemCount();
  const int height =
      start_->header()->sizeHint().height() + rows * qMax(1, start_->sizeHintForRow(0)) + 2 * start_->frameWidth() + 2;
  start_->setFixedHeight(rows ? height : start_->header()->sizeHint().height() * 3);
}

QWidget* ProjectOverview::openStartEntry(int index) {
  if (index < 0 || index >= static_cast<int>(entries_.size()) || !openPage_) return nullptr;
  const StartEntry& entry = entries_[static_cast<std::size_t>(index)];
  if (!entry.available) return nullptr;
  return openPage_(entry.pageId, entry.item);
}

void ProjectOverview::openCurrentStartItem() {
  QTreeWidgetItem* current = start_->currentItem();
  if (!current) return;
  const QVariant index = current->data(0, kEntryRole);
  if (index.isValid()) openStartEntry(index.toInt());
}

void ProjectOverview::clear() {
  hasProject_ = false;
  summary_ = {};
  contents_.clear();
  entries_.clear();
  specimens_->setRowCount(0);
  start_->clear();
  retranslate();
}

int ProjectOverview::specimenRows() const {
  return specimens_->rowCount();
}

void ProjectOverview::showEvent(QShowEvent* event) {
  if (stale_) refresh();
  QWidget::showEvent(event);
}

void ProjectOverview::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) {
    retranslate();
    fillStartList();
  }
  QWidget::changeEvent(event);
}

void ProjectOverview::retranslate() {
  specimens_->setHorizontalHeaderLabels({tr("Specimen"), tr("Kind"), tr("Mesh nodes"), tr("Campaigns"), tr("FRF sets"),
                                         tr("Modal results"), tr("Rig tests"), tr("Tyre tests"), tr("Analyses"),
                                         tr("Description")});
  start_->setHeaderLabels({tr("Page"), tr("What it shows"), tr("Opens on")});
  startHeading_->setText(tr("Start here: double-click a page to open it on this project's data"));
  open_->setText(tr("&Open Page"));
  reportHint_->setText(tr("To leave with a document: File > Export > Report..."));
  specimensHeading_->setText(tr("Specimens and what each holds"));
  startHeading_->setVisible(hasProject_ && registry_);
  start_->setVisible(hasProject_ && registry_);
  open_->setVisible(hasProject_ && registry_);
  reportHint_->setVisible(hasProject_);
  specimensHeading_->setVisible(hasProject_);
  if (!hasProject_) {
    title_->setText(tr("No project open"));
    details_->setText(
        tr("Create a project with File > New, open one with File > Open, "
           "or try the demo with Tools > Create Demo Project."));
    return;
  }
  title_->setText(QFileInfo(path_).completeBaseName());
  QString text = tr("File: %1\nSchema version %2, created %3 by Mozzi %4")
                     .arg(QDir::toNativeSeparators(path_))
                     .arg(summary_.schemaVersion)
                     .arg(QString::fromStdString(summary_.createdUtc), QString::fromStdString(summary_.mozziVersion));
  if (readOnly_) text += QLatin1Char('\n') + tr("Opened read-only: %1").arg(readOnlyReason_);
  details_->setText(text);
}

}  // namespace views
}  // namespace mozzi
