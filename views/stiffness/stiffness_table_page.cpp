#include "views/stiffness/stiffness_table_page.h"

#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QTextStream>
#include <QVBoxLayout>
#include <cmath>

#include "core/io/project_store.h"
#include "devices/rigtests/stiffness_tables.h"
#include "views/common/project_model.h"
#include "views/plots/plot_export.h"

namespace mozzi {
namespace views {

namespace rt = devices::rigtests;

namespace {

constexpr double kPi = 3.14159265358979323846;

QString qs(const std::string& s) {
  return QString::fromStdString(s);
}

// Display units of the thesis's tables: kN/m, m, kNm/rad, degrees.
struct DisplayUnit {
  double scale;
  const char* unit;
  int decimals;
};
DisplayUnit displayUnit(const std::string& si) {
  if (si == "N/m") return {1e-3, "kN/m", 2};
  if (si == "N m/rad") return {1e-3, "kNm/rad", 2};
  if (si == "rad") return {180.0 / kPi, "°", 2};
  return {1.0, "m", 4};
}

// The rows' labels, for lupdate (the English texts are devices/rigtests/stiffness_tables.cpp's).
const char* const kRowLabels[] = {
    QT_TRANSLATE_NOOP("StiffnessTablePage", "Lateral stiffness"),
    QT_TRANSLATE_NOOP("StiffnessTablePage", "Twist arm"),
    QT_TRANSLATE_NOOP("StiffnessTablePage", "Twist stiffness"),
    QT_TRANSLATE_NOOP("StiffnessTablePage", "Bending arm"),
    QT_TRANSLATE_NOOP("StiffnessTablePage", "Bending stiffness"),
    QT_TRANSLATE_NOOP("StiffnessTablePage", "Torsion arm"),
    QT_TRANSLATE_NOOP("StiffnessTablePage", "Torsion stiffness"),
    QT_TRANSLATE_NOOP("StiffnessTablePage", "Inclination of the twist axis"),
};

QString rowLabel(const rt::StiffnessRowSpec& row) {
  for (const char* l : kRowLabels)
    if (qstrcmp(l, row.label) == 0) return QCoreApplication::translate("StiffnessTablePage", l);
  return QString::fromLatin1(row.label);
}

QString constraintText(const std::string& c) {
  static const char* const kConstraints[] = {QT_TRANSLATE_NOOP("StiffnessTablePage", "front-constrained"),
                                             QT_TRANSLATE_NOOP("StiffnessTablePage", "rear-constrained"),
                                             QT_TRANSLATE_NOOP("StiffnessTablePage", "steering head locked")};
  for (const char* k : kConstraints)
    if (c == k) return QCoreApplication::translate("StiffnessTablePage", k);
  return qs(c);
}

enum class ColumnKind { Measured, Thesis, Deviation };

// Which test and what a table column shows (kept on the header item).
constexpr int kTestRole = Qt::UserRole;
constexpr int kKindRole = Qt::UserRole + 1;

}  // namespace

StiffnessTablePage::StiffnessTablePage(const PageContext& ctx) : QWidget(ctx.parent), model_(ctx.model) {
  buildUi();
  retranslate();
  reload();
  connect(model_, &ProjectModel::rigTestsChanged, this, &StiffnessTablePage::reload);
  connect(model_, &ProjectModel::specimensChanged, this, &StiffnessTablePage::reload);
  connect(model_, &ProjectModel::projectChanged, this, &StiffnessTablePage::reload);
}

StiffnessTablePage::~StiffnessTablePage() = default;

void StiffnessTablePage::buildUi() {
  auto* layout = new QVBoxLayout(this);
  auto* bar = new QHBoxLayout;
  thesis_ = new QCheckBox(this);
  thesis_->setObjectName(QStringLiteral("stiffnessThesisBox"));
  thesis_->setChecked(true);
  copy_ = new QPushButton(this);
  copy_->setObjectName(QStringLiteral("stiffnessCopyButton"));
  export_ = new QPushButton(this);
  export_->setObjectName(QStringLiteral("stiffnessExportButton"));
  bar->addWidget(thesis_);
  bar->addStretch(1);
  bar->addWidget(copy_);
  bar->addWidget(export_);
  layout->addLayout(bar);
  table_ = new QTableWidget(this);
  table_->setObjectName(QStringLiteral("stiffnessTable"));
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionMode(QAbstractItemView::ContiguousSelection);
  table_->horizontalHeader()->setDefaultAlignment(Qt::AlignCenter);
  table_->setWordWrap(false);
  // As tall as its rows: the notes right below it.
  table_->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
  table_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Maximum);
  layout->addWidget(table_);
  sources_ = new QLabel(this);
  sources_->setObjectName(QStringLiteral("stiffnessSources"));
  sources_->setWordWrap(true);
  sources_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(sources_);
  status_ = new QLabel(this);
  status_->setObjectName(QStringLiteral("stiffnessStatus"));
  status_->setWordWrap(true);
  layout->addWidget(status_);
  layout->addStretch(1);
  connect(thesis_, &QCheckBox::toggled, this, [this] { fill(); });
  connect(copy_, &QPushButton::clicked, this, &StiffnessTablePage::copyCsv);
  connect(export_, &QPushButton::clicked, this, &StiffnessTablePage::askExport);
}

void StiffnessTablePage::retranslate() {
  thesis_->setText(tr("Thesis values beside the measured ones"));
  thesis_->setToolTip(
      tr("Where a specimen is one of the thesis's, its printed values (Tables 3 to 5, 7, 9, 10, "
         "13) and the difference from the measured ones"));
  copy_->setText(tr("Copy as CSV"));
  export_->setText(tr("Export CSV..."));
}

void StiffnessTablePage::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) {
    retranslate();
    fill();
  }
  QWidget::changeEvent(event);
}

void StiffnessTablePage::setThesisShown(bool shown) {
  thesis_->setChecked(shown);
}

void StiffnessTablePage::reload() {
  columns_.clear();
  skipped_.clear();
  readError_.clear();
  if (auto* store = model_->store()) {
    auto cols = rt::stiffnessColumns(*store, &skipped_);
    if (cols) {
      columns_ = std::move(cols).value();
    } else {
      readError_ = qs(cols.error().describe());
    }
  }
  fill();
}

void StiffnessTablePage::fill() {
  const auto& rows = rt::stiffnessRows();
  const bool withThesis = thesis_->isChecked();
  table_->clear();
  table_->setRowCount(static_cast<int>(rows.size()));
  int count = 0;
  for (const auto& c : columns_) count += 1 + ((withThesis && !c.thesis.empty()) ? 2 : 0);
  table_->setColumnCount(count);
  for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
    const DisplayUnit u = displayUnit(rows[r].unit);
    table_->setVerticalHeaderItem(
        r, new QTableWidgetItem(QStringLiteral("%1 [%2]").arg(rowLabel(rows[r]), QString::fromUtf8(u.unit))));
  }
  int col = 0;
  QStringList sources;
  for (const auto& c : columns_) {
    QString title = qs(c.specimenName);
    if (!c.constraint.empty()) title += QStringLiteral("\n") + constraintText(c.constraint);
    title += QStringLiteral("\n") + qs(c.testName);
    if (c.status != core::io::TestStatus::Complete)
      title += QStringLiteral(" (%1)").arg(qs(core::io::testStatusName(c.status)));
    const bool thesis = withThesis && !c.thesis.empty();
    auto header = [&](const QString& text, ColumnKind kind) {
      auto* h = new QTableWidgetItem(text);
      h->setData(kTestRole, QVariant::fromValue<qlonglong>(c.testId));
      h->setData(kKindRole, static_cast<int>(kind));
      table_->setHorizontalHeaderItem(col, h);
    };
    header(title + QStringLiteral("\n") + tr("measured"), ColumnKind::Measured);
    for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
      const auto it = c.measured.find(rows[r].key);
      auto* item = new QTableWidgetItem;
      item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      if (it == c.measured.end()) {
        item->setText(QStringLiteral("-"));
      } else {
        const DisplayUnit u = displayUnit(rows[r].unit);
        const auto& q = it->second;
        QString text = QString::number(q.value * u.scale, 'f', u.decimals);
        if (q.uncertainty > 0) text += QStringLiteral(" ± %1").arg(QString::number(q.uncertainty * u.scale, 'g', 2));
        item->setText(text);
        item->setData(Qt::UserRole, q.value);
        item->setData(Qt::UserRole + 1, q.uncertainty);
        item->setToolTip(
            tr("%1 %2, one standard deviation %3 %2 (as stored)")
                .arg(QString::number(q.value, 'g', 10), qs(q.unit), QString::number(q.uncertainty, 'g', 3)));
      }
      table_->setItem(r, col, item);
    }
    ++col;
    if (!thesis) continue;
    header(title + QStringLiteral("\n") + tr("thesis"), ColumnKind::Thesis);
    for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
      const auto it = c.thesis.find(rows[r].key);
      auto* item = new QTableWidgetItem;
      item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      item->setForeground(palette().color(QPalette::Disabled, QPalette::Text).darker(130));
      if (it == c.thesis.end()) {
        item->setText(QStringLiteral("-"));
      } else {
        const DisplayUnit u = displayUnit(rows[r].unit);
        item->setText(QString::number(it->second * u.scale, 'g', 4));
        item->setData(Qt::UserRole, it->second);
      }
      table_->setItem(r, col, item);
    }
    ++col;
    header(title + QStringLiteral("\n") + tr("difference"), ColumnKind::Deviation);
    for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
      const auto d = rt::thesisDeviation(c, rows[r].key);
      // +0.0 rather than -0.0 for a difference that rounds to nothing.
      const double shown = d ? std::round(1000.0 * *d) / 10.0 + 0.0 : 0.0;
      auto* item =
          new QTableWidgetItem(d ? QStringLiteral("%1 %").arg(QString::number(shown, 'f', 1)) : QStringLiteral("-"));
      item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      if (d) item->setData(Qt::UserRole, *d);
      table_->setItem(r, col, item);
    }
    ++col;
    sources << tr("%1: %2").arg(qs(c.specimenName), qs(c.thesisSource));
  }
  table_->resizeColumnsToContents();
  table_->resizeRowsToContents();
  sources_->setText(sources.isEmpty() ? QString()
                                      : tr("Thesis values as printed (misprinted units corrected, "
                                           "docs/validation/stiffness.md) from %1.")
                                            .arg(sources.join(QStringLiteral("; "))));
  sources_->setVisible(!sources.isEmpty());
  QString status;
  if (!model_->store()) {
    status = tr("No project is open.");
  } else if (!readError_.isEmpty()) {
    status = tr("Could not read the rig tests: %1").arg(readError_);
  } else if (columns_.empty()) {
    status = tr("The project holds no static stiffness test: run one on the Stiffness Rig page.");
  } else {
    status =
        tr("%n static test(s); sine sweeps are on the Twist Axes page.", nullptr, static_cast<int>(columns_.size()));
  }
  for (const auto& s : skipped_) status += QStringLiteral("\n") + tr("Not shown: %1").arg(qs(s));
  status_->setText(status);
  copy_->setEnabled(!columns_.empty());
  export_->setEnabled(!columns_.empty());
}

bool StiffnessTablePage::showRigTest(qint64 testId) {
  for (int c = 0; c < table_->columnCount(); ++c) {
    if (testOfColumn(c) != testId) continue;
    table_->selectColumn(c);
    table_->scrollToItem(table_->item(0, c));
    return true;
  }
  return false;
}

QString StiffnessTablePage::statusText() const {
  return status_->text();
}

qint64 StiffnessTablePage::testOfColumn(int column) const {
  const auto* h = table_->horizontalHeaderItem(column);
  if (!h || h->data(kKindRole).toInt() != static_cast<int>(ColumnKind::Measured)) return 0;
  return h->data(kTestRole).toLongLong();
}

QString StiffnessTablePage::csv() const {
  const auto& rows = rt::stiffnessRows();
  const bool withThesis = thesis_->isChecked();
  QStringList header{csvField(tr("quantity")), csvField(tr("unit"))};
  for (const auto& c : columns_) {
    QString title = qs(c.specimenName);
    if (!c.constraint.empty()) title += QStringLiteral(", ") + constraintText(c.constraint);
    title += QStringLiteral(" / ") + qs(c.testName);
    header << csvField(title + QStringLiteral(": ") + tr("measured"))
           << csvField(title + QStringLiteral(": ") + tr("standard deviation"));
    if (withThesis && !c.thesis.empty()) header << csvField(title + QStringLiteral(": ") + tr("thesis"));
  }
  QStringList lines{header.join(QLatin1Char(','))};
  for (const auto& row : rows) {
    const DisplayUnit u = displayUnit(row.unit);
    QStringList line{csvField(rowLabel(row)), csvField(QString::fromUtf8(u.unit))};
    for (const auto& c : columns_) {
      const auto m = c.measured.find(row.key);
      line << (m == c.measured.end() ? QString() : QString::number(m->second.value * u.scale, 'g', 12))
           << (m == c.measured.end() ? QString() : QString::number(m->second.uncertainty * u.scale, 'g', 6));
      if (withThesis && !c.thesis.empty()) {
        const auto t = c.thesis.find(row.key);
        line << (t == c.thesis.end() ? QString() : QString::number(t->second * u.scale, 'g', 12));
      }
    }
    lines << line.join(QLatin1Char(','));
  }
  return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

QString StiffnessTablePage::exportCsv(const QString& path) const {
  QFile file(path);
  if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text))
    return tr("Cannot write %1: %2").arg(path, file.errorString());
  QTextStream out(&file);
  out.setCodec("UTF-8");
  out << csv();
  out.flush();
  if (file.error() != QFileDevice::NoError) return tr("Cannot write %1: %2").arg(path, file.errorString());
  return {};
}

void StiffnessTablePage::copyCsv() {
  QApplication::clipboard()->setText(csv());
  emit message(tr("Stiffness tables copied as CSV."));
}

void StiffnessTablePage::askExport() {
  const QString path =
      QFileDialog::getSaveFileName(this, tr("Export the stiffness tables"), QString(), tr("CSV data (*.csv)"));
  if (path.isEmpty()) return;
  const QString problem = exportCsv(path);
  emit message(problem.isEmpty() ? tr("Stiffness tables written to %1.").arg(path) : problem);
}

}  // namespace views
}  // namespace mozzi
