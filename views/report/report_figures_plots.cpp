// The plot figures of a report (report_figures.h): FRF overlay and coherence
// (views/plots FrfPlot), the stabilization diagram (views/plots
// StabilizationPlot over the identification page's back end), the gap overlay
// of a stored diagnosis and the steady-state tyre chart (InteractivePlot, the
// plot adapter every page draws on).
#include <qwt_legend.h>
#include <qwt_plot_curve.h>
#include <qwt_symbol.h>
#include <QCoreApplication>
#include <QPen>
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/modal/plscf.h"
#include "views/common/job_runner.h"
#include "views/modal/identification_backend.h"
#include "views/plots/frf_plot.h"
#include "views/plots/interactive_plot.h"
#include "views/plots/stabilization_plot.h"
#include "views/report/report_figures.h"

namespace mozzi {
namespace views {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("ReportFigures", text);
}

bool fail(QString* error, const QString& why) {
  if (error) *error = why;
  return false;
}

bool frfPlot(const FigureRequest& r, FigureDrawing& out, QString* error, FrfPlot::View view) {
  auto frf = r.store.frfSet(r.figure.recordId);
  if (!frf) return fail(error, QString::fromStdString(frf.error().describe()));
  if (view == FrfPlot::View::Coherence && frf->coherence.empty())
    return fail(error, tr("the FRF set has no coherence"));
  auto plot = std::make_unique<FrfPlot>();
  plot->resize(1000, 700);
  plot->setFrfs(std::make_shared<const core::FrfMatrix>(std::move(*frf)));
  plot->setView(view);
  plot->setFilter(core::FrfFilter{});  // every FRF of the set
  plot->autoscale();
  QwtPlot* main = plot->mainPlot();
  // On screen the coherence plot below carries the frequency axis; the
  // figure is the main plot alone, so it carries it.
  main->enableAxis(QwtPlot::xBottom, true);
  out.plot = main;
  out.keep.push_back(std::move(plot));
  return true;
}

std::vector<double> numbers(const nlohmann::json& j, const char* key) {
  std::vector<double> v;
  if (j.contains(key) && j[key].is_array())
    for (const auto& x : j[key]) v.push_back(x.is_number() ? x.get<double>() : std::nan(""));
  return v;
}

QwtPlotCurve* addCurve(QwtPlot* plot, const QString& title, const std::vector<double>& x, const std::vector<double>& y,
                       const QPen& pen) {
  auto* curve = new QwtPlotCurve(title);
  curve->setRenderHint(QwtPlotItem::RenderAntialiased);
  curve->setPen(pen);
  curve->setSamples(x.data(), y.data(), static_cast<int>(std::min(x.size(), y.size())));
  curve->attach(plot);
  return curve;
}

}  // namespace

bool renderFrfOverlay(const FigureRequest& r, FigureDrawing& out, QString* error) {
  return frfPlot(r, out, error, FrfPlot::View::Magnitude);
}

bool renderFrfCoherence(const FigureRequest& r, FigureDrawing& out, QString* error) {
  return frfPlot(r, out, error, FrfPlot::View::Coherence);
}

// The first overlay curve of a stored diagnosis (core::report::analysisFromDiagnosis):
// measured, model before and model after, as the Model vs Test page draws them.
bool renderGapOverlay(const FigureRequest& r, FigureDrawing& out, QString* error) {
  if (r.figure.recordId == 0) return fail(error, tr("the diagnosis is not stored in the project"));
  auto analysis = r.store.analysis(r.figure.recordId);
  if (!analysis) return fail(error, QString::fromStdString(analysis.error().describe()));
  const auto json = nlohmann::json::parse(analysis->resultJson, nullptr, false);
  if (!json.is_object() || !json.contains("overlay") || !json["overlay"].is_array() || json["overlay"].empty())
    return fail(error, tr("the stored diagnosis holds no overlay curves"));
  const auto& c = json["overlay"][0];
  auto plot = std::make_unique<InteractivePlot>();
  plot->resize(1000, 600);
  const auto x = numbers(c, "x");
  const bool logY = c.value("log_y", false);
  plot->setLogY(logY);
  plot->setAxisTitle(QwtPlot::xBottom, QString::fromStdString(c.value("x_label", std::string())));
  plot->setAxisTitle(QwtPlot::yLeft, QString::fromStdString(c.value("y_label", std::string())));
  plot->setTitle(QString::fromStdString(c.value("label", std::string())));
  addCurve(plot.get(), tr("measured"), x, numbers(c, "measured"), QPen(Qt::black, 0));
  addCurve(plot.get(), tr("model"), x, numbers(c, "before"), QPen(QColor(0x1f, 0x77, 0xb4), 0, Qt::DashLine));
  if (c.contains("after"))
    addCurve(plot.get(), tr("after: %1").arg(QString::fromStdString(c.value("after_label", std::string()))), x,
             numbers(c, "after"), QPen(QColor(0xd6, 0x27, 0x28), 0));
  plot->insertLegend(new QwtLegend(plot.get()), QwtPlot::TopLegend);
  plot->autoscale();
  out.plot = plot.get();
  out.keep.push_back(std::move(plot));
  return true;
}

// Lateral force and aligning moment of a steady-state tyre test against slip
// angle (thesis Figures 53 to 56): the measured points.
bool renderTyreSteadyState(const FigureRequest& r, FigureDrawing& out, QString* error) {
  auto test = r.store.tyreTest(r.figure.recordId);
  if (!test) return fail(error, QString::fromStdString(test.error().describe()));
  if (test->points.empty()) return fail(error, tr("the tyre test has no measured points"));
  std::vector<double> slip, fy, mz;
  for (const auto& p : test->points) {
    slip.push_back(p.slipAngleRad * 180.0 / M_PI);
    fy.push_back(p.lateralForceN);
    mz.push_back(p.aligningMomentNm);
  }
  auto plot = std::make_unique<InteractivePlot>();
  plot->resize(1000, 600);
  plot->enableAxis(QwtPlot::yRight, true);
  plot->setAxisTitle(QwtPlot::xBottom, tr("Slip angle [deg]"));
  plot->setAxisTitle(QwtPlot::yLeft, tr("Lateral force Fy [N]"));
  plot->setAxisTitle(QwtPlot::yRight, tr("Aligning moment Mz [N m]"));
  auto* f = addCurve(plot.get(), tr("Fy"), slip, fy, QPen(QColor(0x1f, 0x77, 0xb4), 0));
  f->setSymbol(new QwtSymbol(QwtSymbol::Ellipse, QBrush(QColor(0x1f, 0x77, 0xb4)), QPen(Qt::NoPen), QSize(5, 5)));
  auto* m = addCurve(plot.get(), tr("Mz"), slip, mz, QPen(QColor(0xd6, 0x27, 0x28), 0, Qt::DashLine));
  m->setSymbol(new QwtSymbol(QwtSymbol::Rect, QBrush(QColor(0xd6, 0x27, 0x28)), QPen(Qt::NoPen), QSize(5, 5)));
  m->setYAxis(QwtPlot::yRight);
  plot->insertLegend(new QwtLegend(plot.get()), QwtPlot::TopLegend);
  plot->setAxisAutoScale(QwtPlot::yRight, true);
  plot->autoscale();
  out.plot = plot.get();
  out.keep.push_back(std::move(plot));
  return true;
}

// The diagram of a stored modal result: the identification page's run on its
// FRF set over its band (the stored modes ringed at their frequencies).
bool renderStabilization(const FigureRequest& r, FigureDrawing& out, QString* error) {
  auto results = r.store.modalResults();
  if (!results) return fail(error, QString::fromStdString(results.error().describe()));
  const core::io::ModalResultInfo* info = nullptr;
  for (const auto& m : *results)
    if (m.id == r.figure.recordId) info = &m;
  if (!info || !info->frfSetId) return fail(error, tr("the modal result names no FRF set"));
  auto frf = r.store.frfSet(*info->frfSetId);
  if (!frf) return fail(error, QString::fromStdString(frf.error().describe()));
  auto modes = r.store.modalResult(info->id);
  if (!modes) return fail(error, QString::fromStdString(modes.error().describe()));
  identification::Options options;
  options.method =
      info->method.find("LSCE") != std::string::npos ? identification::Method::Lsce : identification::Method::Plscf;
  options.bandLowHz = info->bandLowHz;
  options.bandHighHz = info->bandHighHz;
  // As the identification ran (the demo, the page's default): order 60,
  // capped at what the band's lines support.
  options.maxOrder = std::min(60, std::max(8, core::modal::plscfOrderLimit(*frf, info->bandLowHz, info->bandHighHz)));
  options.refine = false;  // the diagram only
  JobProgress progress;
  auto outcome = identification::identify(*frf, options, progress);
  if (!outcome) return fail(error, QString::fromStdString(outcome.error().describe()));
  if (!outcome->diagram) return fail(error, tr("the method draws no stabilization diagram"));
  auto plot = std::make_unique<StabilizationPlot>();
  plot->resize(1000, 700);
  plot->setDiagram(outcome->diagram, std::make_shared<const core::Vector>(frf->frequencyHz), outcome->backdropDb,
                   tr("sum of |H| [dB]"));
  std::vector<double> frequencies;
  for (const auto& m : modes->modes) frequencies.push_back(m.frequencyHz);
  plot->setSelection({}, frequencies);
  plot->setAxisScale(QwtPlot::xBottom, info->bandLowHz, info->bandHighHz);
  plot->replot();
  out.plot = plot.get();
  out.keep.push_back(std::move(plot));
  return true;
}

}  // namespace views
}  // namespace mozzi
