#include "views/common/project_tree.h"

#include <QApplication>
#include <QDir>
#include <QEvent>
#include <QFileInfo>
#include <QHeaderView>
#include <QPainter>
#include <QStyledItemDelegate>
#include <QTreeWidgetItemIterator>

#include <algorithm>
#include <map>

namespace mozzi {
namespace views {

namespace {

constexpr int kRoleKind = Qt::UserRole + 1;
constexpr int kRoleId = Qt::UserRole + 2;
constexpr int kRoleSpecimen = Qt::UserRole + 3;
constexpr int kRoleProperties = Qt::UserRole + 4;  // QStringList: name, value, name, value, ...
constexpr int kRoleAnalysisKind = Qt::UserRole + 5;

QString text(const std::string& s) {
  return QString::fromStdString(s);
}

// What a stored analysis is, in the user's words (its kind as stored otherwise).
QString analysisKindText(const std::string& kind) {
  if (kind == "stability") return ProjectTree::tr("stability sweep");
  if (kind == "wheelchair") return ProjectTree::tr("wheelchair manoeuvre");
  if (kind == "gap-diagnosis") return ProjectTree::tr("gap diagnosis");
  return text(kind);
}

// The group row of the stored analyses of one kind.
QString analysisGroupText(const std::string& kind) {
  if (kind == "stability") return ProjectTree::tr("Stability sweeps");
  if (kind == "wheelchair") return ProjectTree::tr("Wheelchair manoeuvres");
  if (kind == "gap-diagnosis") return ProjectTree::tr("Gap diagnoses");
  return text(kind);
}

// The first column's names wrapped at spaces to the column's width, the row
// as tall as they need (the view would keep rows one line high and cut the
// names). A word longer than the column is cut in the middle.
class WrappingDelegate : public QStyledItemDelegate {
 public:
  explicit WrappingDelegate(QTreeView* view) : QStyledItemDelegate(view), view_(view) {}
  QSize sizeHint(const QStyleOptionViewItem& option, const QModelIndex& index) const override {
    QSize size = QStyledItemDelegate::sizeHint(option, index);
    if (index.column() != 0) return size;
    int depth = view_->rootIsDecorated() ? 1 : 0;
    for (QModelIndex up = index.parent(); up.isValid(); up = up.parent()) ++depth;
    const QRect need =
        textBounds(option.fontMetrics, view_->columnWidth(0) - view_->indentation() * depth, index.data().toString());
    size.setHeight(std::max(size.height(), need.height() + 2));
    return size;
  }
  void paint(QPainter* painter, const QStyleOptionViewItem& option, const QModelIndex& index) const override {
    if (index.column() != 0) {
      QStyledItemDelegate::paint(painter, option, index);
      return;
    }
    QStyleOptionViewItem opt = option;
    initStyleOption(&opt, index);
    const QString text = opt.text;
    opt.text.clear();  // the background, selection and focus as the style draws them; the text below
    const QWidget* widget = opt.widget;
    QStyle* style = widget ? widget->style() : QApplication::style();
    style->drawControl(QStyle::CE_ItemViewItem, &opt, painter, widget);
    const QRect room = textRoom(opt.rect);
    QStringList lines;
    for (const QString& line : wrapped(opt.fontMetrics, room.width(), text)) lines << line;
    painter->save();
    painter->setPen(opt.palette.color(opt.state & QStyle::State_Selected ? QPalette::HighlightedText : QPalette::Text));
    painter->setFont(opt.font);
    const int h = opt.fontMetrics.height() * static_cast<int>(lines.size());
    int y = room.top() + (room.height() - h) / 2;
    for (const QString& line : lines) {
      painter->drawText(QRect(room.left(), y, room.width(), opt.fontMetrics.height()), Qt::AlignLeft | Qt::AlignVCenter,
                        line);
      y += opt.fontMetrics.height();
    }
    painter->restore();
  }

  // The text's width in a cell of `cellWidth` pixels: a margin each side.
  static constexpr int kMargin = 4;
  static QRect textRoom(const QRect& cell) { return cell.adjusted(kMargin, 0, -kMargin, 0); }
  // `text` in lines no wider than `width`: broken at spaces, a word too long cut in the middle.
  static std::vector<QString> wrapped(const QFontMetrics& fm, int width, const QString& text) {
    std::vector<QString> lines;
    QString line;
    for (const QString& word : text.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
      const QString longer = line.isEmpty() ? word : line + QLatin1Char(' ') + word;
      if (line.isEmpty() || fm.horizontalAdvance(longer) <= width) {
        line = longer;
      } else {
        lines.push_back(fm.elidedText(line, Qt::ElideMiddle, width));
        line = word;
      }
    }
    if (!line.isEmpty() || lines.empty()) lines.push_back(fm.elidedText(line, Qt::ElideMiddle, width));
    return lines;
  }
  static QRect textBounds(const QFontMetrics& fm, int cellWidth, const QString& text) {
    const int width = std::max(20, textRoom(QRect(0, 0, cellWidth, 1)).width());
    return QRect(0, 0, width, fm.height() * static_cast<int>(wrapped(fm, width, text).size()));
  }

 private:
  QTreeView* view_;
};

}  // namespace

ProjectTree::ProjectTree(ProjectModel* model, QWidget* parent) : QTreeWidget(parent), model_(model) {
  qRegisterMetaType<mozzi::views::ProjectItem>("mozzi::views::ProjectItem");
  setObjectName(QStringLiteral("projectTree"));
  setColumnCount(2);
  header()->setStretchLastSection(false);
  header()->setSectionResizeMode(0, QHeaderView::Stretch);
  header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
  // In the dock's 260 pixels a long name ("Tyre 110/70-16 high-wheel scooter
  // (front)") wraps onto more lines rather than being cut where names differ
  // (WrappingDelegate); the whole name is in the tooltip as well. Indented by
  // a little more than a branch arrow.
  setUniformRowHeights(false);
  setItemDelegate(new WrappingDelegate(this));
  setIndentation(fontMetrics().height());
  // Wrapped rows take their height for the new width (the view keeps row heights until laid out again).
  connect(header(), &QHeaderView::sectionResized, this, [this](int section) {
    if (section == 0) scheduleDelayedItemsLayout();
  });
  setContextMenuPolicy(Qt::CustomContextMenu);
  connect(this, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* current) {
    if (!rebuilding_) emit currentProjectItemChanged(itemOf(current));
  });
  connect(this, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* row) {
    const ProjectItem item = itemOf(row);
    if (item.kind != RecordKind::None) emit openRequested(item);
  });
  connect(model_, &ProjectModel::projectChanged, this, [this] {
    projectReplaced_ = true;  // the same ids now name other records
    refresh();
  });
  connect(model_, &ProjectModel::recordsChanged, this, [this](RecordKind kind) {
    if (kind != RecordKind::Hit) refresh();  // hits are not listed; a campaign commits one every few seconds
  });
  refresh();
}

ProjectItem ProjectTree::itemOf(const QTreeWidgetItem* row) {
  if (!row) return {};
  return ProjectItem{static_cast<RecordKind>(row->data(0, kRoleKind).toInt()), row->data(0, kRoleId).toLongLong(),
                     row->data(0, kRoleSpecimen).toLongLong(), row->data(0, kRoleAnalysisKind).toString()};
}

QTreeWidgetItem* ProjectTree::addRow(QTreeWidgetItem* parent, const QStringList& texts, const ProjectItem& item) {
  auto* row = parent ? new QTreeWidgetItem(parent, texts) : new QTreeWidgetItem(this, texts);
  row->setToolTip(0, texts.value(0));  // long names are cut in a narrow dock
  row->setData(0, kRoleKind, static_cast<int>(item.kind));
  row->setData(0, kRoleId, QVariant::fromValue<qlonglong>(item.id));
  row->setData(0, kRoleSpecimen, QVariant::fromValue<qlonglong>(item.specimenId));
  if (!item.analysisKind.isEmpty()) row->setData(0, kRoleAnalysisKind, item.analysisKind);
  return row;
}

bool ProjectTree::selectItem(const ProjectItem& item) {
  for (QTreeWidgetItemIterator it(this); *it; ++it) {
    const ProjectItem row = itemOf(*it);
    if (row.kind == item.kind && row.id == item.id) {
      setCurrentItem(*it);
      return true;
    }
  }
  return false;
}

QList<QPair<QString, QString>> ProjectTree::currentProperties() const {
  QList<QPair<QString, QString>> rows;
  const QTreeWidgetItem* row = currentItem();
  if (!row) return rows;
  const QStringList props = row->data(0, kRoleProperties).toStringList();
  if (props.isEmpty()) {
    rows << qMakePair(tr("Item"), row->text(0));
    if (!row->text(1).isEmpty()) rows << qMakePair(tr("Count"), row->text(1));
    return rows;
  }
  for (int i = 0; i + 1 < props.size(); i += 2) rows << qMakePair(props[i], props[i + 1]);
  const ProjectItem item = itemOf(row);
  if (item.kind == RecordKind::Specimen && model_->store()) {
    QString mesh = tr("none");
    if (auto m = model_->store()->mesh(item.id); m && !m->nodes.empty()) {
      mesh = tr("%1 nodes, %2 lines").arg(m->nodes.size()).arg(m->lines.size());
    }
    rows << qMakePair(tr("Mesh"), mesh);
  }
  return rows;
}

void ProjectTree::refresh() {
  const ProjectItem selected = currentProjectItem();
  rebuilding_ = true;
  clear();
  setHeaderLabels({tr("Item"), tr("Count")});
  core::io::ProjectStore* store = model_->store();
  auto summary = model_->summary();
  if (!store || !summary) {
    rebuilding_ = false;
    if (selected.kind != RecordKind::None || projectReplaced_) emit currentProjectItemChanged({});
    projectReplaced_ = false;
    return;
  }
  const QString path = model_->path();
  auto* root = addRow(nullptr, {QFileInfo(path).completeBaseName()}, {RecordKind::Project, 0, 0});
  root->setData(
      0, kRoleProperties,
      QStringList{tr("File"), QDir::toNativeSeparators(path), tr("Access"),
                  model_->isReadOnly() ? tr("read-only: %1").arg(model_->readOnlyReason()) : tr("read-write")});

  auto* specimens = addRow(root, {tr("Specimens"), QString::number(summary->specimens.size())}, {});
  for (const auto& sp : summary->specimens) {
    auto* row = addRow(specimens, {text(sp.name)}, {RecordKind::Specimen, sp.id, sp.id});
    // The mesh row is added when the specimen is selected (a mesh can be large).
    row->setData(
        0, kRoleProperties,
        QStringList{tr("Name"), text(sp.name), tr("Kind"), text(sp.kind), tr("Description"), text(sp.description)});
    if (auto campaigns = store->campaigns(sp.id); campaigns && !campaigns->empty()) {
      for (const auto& c : *campaigns) {
        auto* crow = addRow(row, {text(c.name)}, {RecordKind::Campaign, c.id, sp.id});
        crow->setData(0, kRoleProperties,
                      QStringList{tr("Name"), text(c.name), tr("Kind"), text(c.kind), tr("Notes"), text(c.notes)});
      }
    }
  }
  if (auto sets = store->frfSets(); sets && !sets->empty()) {
    auto* group = addRow(root, {tr("FRF sets"), QString::number(sets->size())}, {});
    for (const auto& set : *sets) {
      auto* row = addRow(group, {text(set.name), QString::number(set.responseCount * set.referenceCount)},
                         {RecordKind::FrfSet, set.id, set.specimenId});
      row->setData(0, kRoleProperties,
                   QStringList{tr("Name"), text(set.name), tr("Source"), text(set.source), tr("Frequency lines"),
                               QString::number(set.lineCount), tr("Response/reference pairs"),
                               QString::number(set.responseCount * set.referenceCount)});
    }
    expandItem(group);
  }
  if (auto results = store->modalResults(); results && !results->empty()) {
    auto* group = addRow(root, {tr("Modal results"), QString::number(results->size())}, {});
    for (const auto& result : *results) {
      auto* row = addRow(group, {text(result.name), QString::number(result.modeCount)},
                         {RecordKind::ModalResult, result.id, result.specimenId});
      row->setData(0, kRoleProperties,
                   QStringList{tr("Name"), text(result.name), tr("Method"), text(result.method), tr("Band"),
                               tr("%1 - %2 Hz").arg(result.bandLowHz, 0, 'f', 1).arg(result.bandHighHz, 0, 'f', 1),
                               tr("Modes"), QString::number(result.modeCount)});
    }
    expandItem(group);
  }
  // Rig and tyre tests (devices/rigtests, the stiffness-rig and tyre-tester pages).
  const auto statusText = [this](core::io::TestStatus status) {
    switch (status) {
      case core::io::TestStatus::Running: return tr("running");
      case core::io::TestStatus::Complete: return tr("complete");
      case core::io::TestStatus::Interrupted: return tr("interrupted");
      case core::io::TestStatus::Failed: return tr("failed");
    }
    return QString();
  };
  const auto addTests = [&](const QString& title, RecordKind kind, const std::vector<core::io::TestInfo>& tests) {
    auto* group = addRow(root, {title, QString::number(tests.size())}, {});
    for (const auto& t : tests) {
      auto* row = addRow(group, {text(t.name), statusText(t.status)}, {kind, t.id, t.specimenId});
      row->setData(0, kRoleProperties,
                   QStringList{tr("Name"), text(t.name), tr("Specimen"), text(t.specimenName), tr("Kind"), text(t.kind),
                               tr("Status"), statusText(t.status), tr("Note"), text(t.statusNote), tr("Recorded (UTC)"),
                               text(t.recordedUtc), tr("Steps recorded"), QString::number(t.recordCount), tr("Results"),
                               QString::number(t.resultCount)});
    }
    expandItem(group);
  };
  if (auto tests = store->rigTests(); tests && !tests->empty()) addTests(tr("Rig tests"), RecordKind::RigTest, *tests);
  if (auto tests = store->tyreTests(); tests && !tests->empty())
    addTests(tr("Tyre tests"), RecordKind::TyreTest, *tests);
  // Stored analyses (stability sweeps, wheelchair manoeuvres, gap diagnoses),
  // from the model's listing (no result read), grouped by kind so that the
  // second column stays a count: double-clicked, each opens on the page of its kind.
  std::vector<core::io::AnalysisInfo> analyses;
  for (const auto& c : model_->contents()) analyses.insert(analyses.end(), c.analyses.begin(), c.analyses.end());
  if (!analyses.empty()) {
    std::stable_sort(analyses.begin(), analyses.end(), [](const auto& x, const auto& y) { return x.id < y.id; });
    auto* group = addRow(root, {tr("Analyses"), QString::number(analyses.size())}, {});
    std::map<std::string, QTreeWidgetItem*> kinds;  // kind -> its row, in order of the first analysis of each
    for (const auto& a : analyses) {
      QTreeWidgetItem*& kindRow = kinds[a.kind];
      if (!kindRow) kindRow = addRow(group, {analysisGroupText(a.kind), QString()}, {});
      kindRow->setText(1, QString::number(kindRow->childCount() + 1));
      auto* row = addRow(kindRow, {text(a.name)}, {RecordKind::Analysis, a.id, a.specimenId, text(a.kind)});
      row->setToolTip(0, tr("%1 (%2)").arg(text(a.name), analysisKindText(a.kind)));
      row->setData(0, kRoleProperties,
                   QStringList{tr("Name"), text(a.name), tr("Kind"), analysisKindText(a.kind), tr("Analysis id"),
                               QString::number(a.id)});
    }
    expandItem(group);
    for (const auto& [kind, kindRow] : kinds) expandItem(kindRow);
  }
  auto* data = addRow(root, {tr("Data")}, {});
  for (const auto& count : summary->counts) {
    if (count.table == "specimen") continue;
    addRow(data, {text(count.table), QString::number(count.rows)}, {});
  }
  expandItem(root);
  expandItem(specimens);
  if (selected.kind == RecordKind::None || !selectItem(selected)) setCurrentItem(root);
  rebuilding_ = false;
  // Observers hear of the selection only when it moved to another record.
  if (currentProjectItem() != selected || projectReplaced_) emit currentProjectItemChanged(currentProjectItem());
  projectReplaced_ = false;
}

QStringList ProjectTree::shownLines(const QTreeWidgetItem* row) const {
  QStringList out;
  if (!row) return out;
  int depth = rootIsDecorated() ? 1 : 0;
  for (const QTreeWidgetItem* up = row->parent(); up; up = up->parent()) ++depth;
  const int cell = columnWidth(0) - indentation() * depth;
  const QRect room = WrappingDelegate::textRoom(QRect(0, 0, cell, 1));
  for (const QString& line : WrappingDelegate::wrapped(fontMetrics(), std::max(20, room.width()), row->text(0)))
    out << line;
  return out;
}

QSize ProjectTree::sizeHint() const {
  return QSize(fontMetrics().averageCharWidth() * 36, QTreeWidget::sizeHint().height());
}

void ProjectTree::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) {
    refresh();
    emit retranslated();
  }
  QTreeWidget::changeEvent(event);
}

}  // namespace views
}  // namespace mozzi
