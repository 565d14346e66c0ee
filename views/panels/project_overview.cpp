#include "views/panels/project_overview.h"

#include <QDir>
#include <QEvent>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

#include "views/common/project_model.h"

namespace mozzi {
namespace views {

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
  specimens_ = new QTableWidget(0, 3, this);
  specimens_->setObjectName(QStringLiteral("overviewSpecimens"));
  specimens_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  specimens_->setSelectionBehavior(QAbstractItemView::SelectRows);
  specimens_->horizontalHeader()->setStretchLastSection(true);
  specimens_->verticalHeader()->setVisible(false);
  layout->addWidget(title_);
  layout->addWidget(details_);
  layout->addWidget(specimens_, 1);
  retranslate();
}

void ProjectOverview::setModel(ProjectModel* model) {
  if (model_) disconnect(model_, nullptr, this, nullptr);
  model_ = model;
  if (model_) {
    connect(model_, &ProjectModel::projectChanged, this, &ProjectOverview::refresh);
    connect(model_, &ProjectModel::specimensChanged, this, &ProjectOverview::refresh);
  }
  refresh();
}

void ProjectOverview::refresh() {
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
}

void ProjectOverview::showSummary(const QString& path, const core::io::ProjectSummary& summary, bool readOnly,
                                  const QString& readOnlyReason) {
  path_ = path;
  summary_ = summary;
  readOnly_ = readOnly;
  readOnlyReason_ = readOnlyReason;
  hasProject_ = true;
  specimens_->setRowCount(static_cast<int>(summary.specimens.size()));
  int row = 0;
  for (const auto& sp : summary.specimens) {
    specimens_->setItem(row, 0, new QTableWidgetItem(QString::fromStdString(sp.name)));
    specimens_->setItem(row, 1, new QTableWidgetItem(QString::fromStdString(sp.kind)));
    specimens_->setItem(row, 2, new QTableWidgetItem(QString::fromStdString(sp.description)));
    ++row;
  }
  specimens_->resizeColumnsToContents();
  retranslate();
}

void ProjectOverview::clear() {
  hasProject_ = false;
  specimens_->setRowCount(0);
  retranslate();
}

int ProjectOverview::specimenRows() const {
  return specimens_->rowCount();
}

void ProjectOverview::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void ProjectOverview::retranslate() {
  specimens_->setHorizontalHeaderLabels({tr("Specimen"), tr("Kind"), tr("Description")});
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
