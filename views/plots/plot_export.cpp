#include "views/plots/plot_export.h"

#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_renderer.h>
#include <qwt_text.h>
#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QSaveFile>
#include <QSettings>
#include <QStringList>
#include <QTextStream>
#include <functional>
#include <vector>

namespace mozzi {
namespace views {

namespace {

const char* const kSettingsFolder = "files/lastExportFolder";

// The translation context of the helper's messages.
class PlotExport {
  Q_DECLARE_TR_FUNCTIONS(mozzi::views::PlotExport)
};

std::vector<const QwtPlotCurve*> visibleCurves(const QwtPlot* plot) {
  std::vector<const QwtPlotCurve*> curves;
  for (const QwtPlotItem* item : plot->itemList(QwtPlotItem::Rtti_PlotCurve)) {
    if (item->isVisible()) curves.push_back(static_cast<const QwtPlotCurve*>(item));
  }
  return curves;
}

}  // namespace

QString csvField(const QString& text) {
  if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"')) && !text.contains(QLatin1Char('\n')))
    return text;
  QString quoted = text;
  quoted.replace(QLatin1Char('"'), QStringLiteral("\"\""));
  return QLatin1Char('"') + quoted + QLatin1Char('"');
}

QString plotCsv(const QwtPlot* plot) {
  const auto curves = visibleCurves(plot);
  QStringList header;
  size_t rows = 0;
  for (size_t c = 0; c < curves.size(); ++c) {
    const QwtPlotCurve* curve = curves[c];
    QString name = curve->title().text();
    if (name.isEmpty()) name = PlotExport::tr("curve %1").arg(c + 1);
    QString x = plot->axisTitle(curve->xAxis()).text();
    QString y = plot->axisTitle(curve->yAxis()).text();
    if (x.isEmpty()) x = QStringLiteral("x");  // an untitled axis still names its column
    if (y.isEmpty()) y = QStringLiteral("y");
    header << csvField(name + QStringLiteral(": ") + x) << csvField(name + QStringLiteral(": ") + y);
    rows = std::max(rows, curve->dataSize());
  }
  QString out;
  QTextStream stream(&out);
  stream << header.join(QLatin1Char(',')) << '\n';
  for (size_t r = 0; r < rows; ++r) {
    QStringList cells;
    for (const QwtPlotCurve* curve : curves) {
      if (r < curve->dataSize()) {
        const QPointF p = curve->sample(r);
        cells << QString::number(p.x(), 'g', 17) << QString::number(p.y(), 'g', 17);
      } else {
        cells << QString() << QString();
      }
    }
    stream << cells.join(QLatin1Char(',')) << '\n';
  }
  return out;
}

QString exportPlot(QwtPlot* plot, const QString& path, const PlotExportOptions& options) {
  if (!plot) return PlotExport::tr("There is no plot to export.");
  const QString suffix = QFileInfo(path).suffix().toLower();
  const QString where = QDir::toNativeSeparators(path);
  if (suffix == QLatin1String("csv")) {
    if (visibleCurves(plot).empty())
      return PlotExport::tr("The plot shows no curve: nothing to write to %1.").arg(where);
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
      return PlotExport::tr("Cannot write %1: %2").arg(where, file.errorString());
    }
    file.write(plotCsv(plot).toUtf8());
    if (!file.commit()) return PlotExport::tr("Cannot write %1: %2").arg(where, file.errorString());
    return {};
  }
  if (suffix != QLatin1String("png") && suffix != QLatin1String("svg") && suffix != QLatin1String("pdf")) {
    return PlotExport::tr("Cannot export to %1: use a .png, .svg, .pdf or .csv file name.").arg(where);
  }
  // QwtPlotRenderer reports no error: check the folder first and the file after.
  const QFileInfo info(path);
  if (!info.absoluteDir().exists()) return PlotExport::tr("Cannot write %1: the folder does not exist.").arg(where);
  QFile::remove(path);
  QSizeF sizeMm = options.sizeMm;
  if (sizeMm.isEmpty()) sizeMm = QSizeF(plot->width(), plot->height()) * 25.4 / 96.0;
  QwtPlotRenderer renderer;
  const int dpi = suffix == QLatin1String("png") ? options.pngDpi : 85;  // vector formats: dpi sets only line widths
  renderer.renderDocument(plot, path, suffix, sizeMm, dpi);
  if (!QFileInfo(path).exists() || QFileInfo(path).size() == 0) {
    return PlotExport::tr("Cannot write %1 (the folder may be read-only).").arg(where);
  }
  return {};
}

QAction* installPlotExportAction(QwtPlot* plot) {
  auto* action = new QAction(plot);
  action->setObjectName(QStringLiteral("plotExportAction"));
  const auto retranslate = [action] {
    action->setText(PlotExport::tr("Export Plot..."));
    action->setStatusTip(PlotExport::tr("Save this plot as PNG, SVG or PDF, or its curves as CSV"));
  };
  retranslate();
  plot->addAction(action);
  plot->setContextMenuPolicy(Qt::ActionsContextMenu);
  QObject::connect(action, &QAction::triggered, plot, [plot] {
    QSettings settings;
    QString folder = settings.value(QLatin1String(kSettingsFolder)).toString();
    if (folder.isEmpty()) folder = QDir::homePath();
    QString base = plot->objectName().isEmpty() ? QStringLiteral("plot") : plot->objectName();
    QString selected;
    const QString path = QFileDialog::getSaveFileName(
        plot, PlotExport::tr("Export Plot"), QDir(folder).filePath(base + QStringLiteral(".png")),
        PlotExport::tr("PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf);;CSV data (*.csv)"), &selected);
    if (path.isEmpty()) return;
    settings.setValue(QLatin1String(kSettingsFolder), QFileInfo(path).absolutePath());
    const QString error = exportPlot(plot, path);
    if (!error.isEmpty()) QMessageBox::warning(plot, PlotExport::tr("Export Plot"), error);
  });
  // The action's text follows the language: a filter on the plot sees LanguageChange.
  struct LanguageFilter : QObject {
    std::function<void()> onChange;
    bool eventFilter(QObject* watched, QEvent* event) override {
      if (event->type() == QEvent::LanguageChange) onChange();
      return QObject::eventFilter(watched, event);
    }
  };
  auto* filter = new LanguageFilter;
  filter->setParent(action);
  filter->onChange = retranslate;
  plot->installEventFilter(filter);
  return action;
}

}  // namespace views
}  // namespace mozzi
