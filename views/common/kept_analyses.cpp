#include "views/common/kept_analyses.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QSignalBlocker>

#include "views/common/project_model.h"

namespace mozzi {
namespace views {

int fillKeptAnalyses(QComboBox* box, const ProjectModel* project, const std::string& kind) {
  const qint64 previous = box->currentData().toLongLong();
  const QSignalBlocker block(box);
  box->clear();
  if (project && project->store()) {
    if (auto analyses = project->store()->analysisInfos())  // the listing: no result JSON read
      for (const auto& a : *analyses)
        if (a.kind == kind)
          box->addItem(QCoreApplication::translate("KeptAnalyses", "%1 (analysis %2)")
                           .arg(QString::fromStdString(a.name))
                           .arg(a.id),
                       QVariant::fromValue<qint64>(a.id));
  }
  const int at = box->findData(QVariant::fromValue<qint64>(previous));
  box->setCurrentIndex(at >= 0 ? at : box->count() - 1);
  box->setEnabled(box->count() > 0);
  return box->count();
}

std::vector<qint64> keptAnalysisIds(const QComboBox* box) {
  std::vector<qint64> ids;
  for (int i = 0; i < box->count(); ++i) ids.push_back(box->itemData(i).toLongLong());
  return ids;
}

}  // namespace views
}  // namespace mozzi
