#include "views/report/stability_figures.h"

#include <qwt_plot.h>
#include <QCoreApplication>

#include "core/stability/stability_record.h"
#include "core/stability/wheelchair_record.h"
#include "views/stability/stability_page.h"
#include "views/wheelchair/wheelchair_page.h"

namespace mozzi {
namespace views {

bool isStabilityFigure(const std::string& view) {
  return view == "stability-real" || view == "stability-imaginary" || view == "wheelchair-trajectory";
}

QwtPlot* stabilityFigurePlot(const core::report::Figure& figure, const core::io::ProjectStore& store,
                             std::unique_ptr<QWidget>& owner, QString* error) {
  auto fail = [error](const core::Error& e) -> QwtPlot* {
    if (error) *error = QString::fromStdString(e.describe());
    return nullptr;
  };
  if (figure.view == "wheelchair-trajectory") {
    auto stored = core::stability::storedWheelchairRecord(store, figure.recordId);
    if (!stored) return fail(stored.error());
    auto page = std::make_unique<WheelchairPage>(nullptr, nullptr);
    page->resize(1280, 800);
    page->showRecord(std::move(stored->record));
    QwtPlot* plot = page->trajectoryPlot();
    owner = std::move(page);
    return plot;
  }
  if (!isStabilityFigure(figure.view)) {
    if (error)
      *error = QCoreApplication::translate("ReportWriter", "the %1 view does not render in a project report")
                   .arg(QString::fromStdString(figure.view));
    return nullptr;
  }
  auto stored = core::stability::storedStabilityRecord(store, figure.recordId);
  if (!stored) return fail(stored.error());
  auto page = std::make_unique<StabilityPage>(nullptr, nullptr);
  page->resize(1280, 800);
  page->showRecord(std::move(stored->record));
  QwtPlot* plot = figure.view == "stability-real" ? page->realPlot() : page->imaginaryPlot();
  owner = std::move(page);
  return plot;
}

}  // namespace views
}  // namespace mozzi
