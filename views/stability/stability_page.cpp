#include "views/stability/stability_page.h"

#include <qwt_legend.h>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_marker.h>
#include <qwt_symbol.h>
#include <qwt_text.h>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QMap>
#include <QPushButton>
#include <QVBoxLayout>
#include <algorithm>

#include "core/common/text.h"
#include "core/stability/benchmark_bicycle.h"
#include "core/stability/compliant_fork_bicycle.h"
#include "views/common/job_runner.h"
#include "views/plots/interactive_plot.h"

namespace mozzi {
namespace views {

namespace st = core::stability;

namespace {

// One colour per mode name, the same on both plots.
QColor modeColour(const std::string& name) {
  static const QMap<QString, QColor> known{{QStringLiteral("weave"), QColor(31, 119, 180)},
                                           {QStringLiteral("capsize"), QColor(214, 39, 40)},
                                           {QStringLiteral("castering"), QColor(44, 160, 44)},
                                           {QStringLiteral("fork bending"), QColor(148, 103, 189)},
                                           {QStringLiteral("fork torsion"), QColor(140, 86, 75)}};
  return known.value(QString::fromStdString(name), QColor(127, 127, 127));
}

core::Result<st::StabilitySweep> sweepOf(StabilityPage::Model model, const std::vector<double>& speeds) {
  const st::BenchmarkParameters p = st::meijaard2007Parameters();
  core::Result<st::BicycleModel> m =
      model == StabilityPage::Model::ForkBending   ? st::forkBendingModel(p, st::thesisSteelForkBending())
      : model == StabilityPage::Model::ForkTorsion ? st::forkTorsionModel(p, st::thesisSteelForkTorsion())
                                                   : st::benchmarkModel(p);
  if (!m) return m.error();
  return st::sweepSpeeds(st::bicycleSystem(*m), speeds);
}

// The workbench's plot (grid, cursor, zoom, pan, export).
InteractivePlot* makePlot(QWidget* parent, const char* objectName) {
  auto* plot = new InteractivePlot(parent);
  plot->setObjectName(QString::fromLatin1(objectName));
  return plot;
}

}  // namespace

StabilityPage::StabilityPage(QWidget* parent, JobRunner* jobs) : QWidget(parent), jobs_(jobs) {
  modelLabel_ = new QLabel(this);
  model_ = new QComboBox(this);
  model_->setObjectName(QStringLiteral("stabilityModel"));
  for (int i = 0; i < 3; ++i) model_->addItem(QString());
  speedsLabel_ = new QLabel(this);
  auto spin = [this](const char* name, double value) {
    auto* s = new QDoubleSpinBox(this);
    s->setObjectName(QString::fromLatin1(name));
    s->setRange(0.0, 100.0);
    s->setDecimals(2);
    s->setSuffix(QStringLiteral(" m/s"));
    s->setValue(value);
    return s;
  };
  from_ = spin("stabilityFrom", 0.0);
  to_ = spin("stabilityTo", 10.0);
  step_ = spin("stabilityStep", 0.05);
  step_->setRange(0.01, 10.0);
  runButton_ = new QPushButton(this);
  runButton_->setObjectName(QStringLiteral("stabilityRun"));
  summary_ = new QLabel(this);
  summary_->setObjectName(QStringLiteral("stabilitySummary"));
  summary_->setWordWrap(true);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  real_ = makePlot(this, "stabilityReal");
  imaginary_ = makePlot(this, "stabilityImaginary");
  real_->insertLegend(new QwtLegend, QwtPlot::TopLegend);  // one legend: the colours are the same below
  for (QwtPlot* plot : {real_, imaginary_}) plot->setMinimumSize(300, 160);

  auto* bar = new QHBoxLayout;
  bar->addWidget(modelLabel_);
  bar->addWidget(model_, 1);
  bar->addWidget(speedsLabel_);
  bar->addWidget(from_);
  bar->addWidget(to_);
  bar->addWidget(step_);
  bar->addWidget(runButton_);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(bar);
  layout->addWidget(summary_);
  layout->addWidget(real_, 1);
  layout->addWidget(imaginary_, 1);
  connect(runButton_, &QPushButton::clicked, this, &StabilityPage::run);
  retranslate();
}

void StabilityPage::setModel(Model model) {
  model_->setCurrentIndex(static_cast<int>(model));
}

void StabilityPage::setSpeedRange(double fromMps, double toMps, double stepMps) {
  from_->setValue(fromMps);
  to_->setValue(toMps);
  step_->setValue(stepMps);
}

void StabilityPage::run() {
  auto speeds = st::speedGrid(from_->value(), to_->value(), step_->value());
  if (!speeds) {
    present(speeds.error());
    return;
  }
  const Model model = static_cast<Model>(model_->currentIndex());
  runButton_->setEnabled(false);
  summary_->setText(tr("Computing the eigenvalues against speed..."));
  if (!jobs_) {
    present(sweepOf(model, *speeds));
    return;
  }
  const std::vector<double> grid = *speeds;
  jobs_->run<st::StabilitySweep>(
      this, tr("Stability against speed"), [model, grid](JobProgress&) { return sweepOf(model, grid); },
      [this](core::Result<st::StabilitySweep> result) { present(std::move(result)); });
}

void StabilityPage::present(core::Result<st::StabilitySweep> result) {
  runButton_->setEnabled(true);
  for (QwtPlot* plot : {real_, imaginary_}) plot->detachItems(QwtPlotItem::Rtti_PlotCurve, true);
  for (QwtPlotMarker* m : markers_) {  // ours only: the plots' cursors stay
    m->detach();
    delete m;
  }
  markers_.clear();
  if (!result) {
    sweep_.reset();
    summary_->setText(tr("Cannot compute: %1").arg(QString::fromStdString(result.error().describe())));
    real_->replot();
    imaginary_->replot();
    emit finished(false);
    return;
  }
  sweep_ = std::move(result).value();
  // One curve per mode name and plot: points (the tracks cross and pair up,
  // so lines between named samples would join different roots).
  QMap<QString, QVector<QPointF>> re, im;
  for (const auto& point : sweep_->points)
    for (const auto& root : point.roots) {
      const QString name = QString::fromStdString(root.name);
      re[name].append(QPointF(point.v, root.lambda.real()));
      if (root.lambda.imag() > 0.0) im[name].append(QPointF(point.v, root.lambda.imag()));
    }
  auto addCurves = [](QwtPlot* plot, const QMap<QString, QVector<QPointF>>& data) {
    for (auto it = data.begin(); it != data.end(); ++it) {
      auto* c = new QwtPlotCurve(it.key());
      const QColor colour = modeColour(it.key().toStdString());
      c->setStyle(QwtPlotCurve::NoCurve);
      c->setSymbol(new QwtSymbol(QwtSymbol::Ellipse, QBrush(colour), QPen(colour), QSize(4, 4)));
      c->setSamples(it.value());
      c->setLegendAttribute(QwtPlotCurve::LegendShowSymbol, true);
      c->attach(plot);
    }
  };
  addCurves(real_, re);
  addCurves(imaginary_, im);
  for (QwtPlotItem* item : imaginary_->itemList(QwtPlotItem::Rtti_PlotCurve))
    item->setItemAttribute(QwtPlotItem::Legend, false);
  auto* zero = new QwtPlotMarker;
  zero->setLineStyle(QwtPlotMarker::HLine);
  zero->setYValue(0.0);
  zero->setLinePen(QColor(0, 0, 0), 1.0);
  zero->attach(real_);
  markers_.push_back(zero);
  QStringList lines;
  for (const auto& e : sweep_->events) {
    if (e.kind != "stabilises" && e.kind != "destabilises") continue;
    const QString text = tr("%1 %2 at %3 m/s")
                             .arg(QString::fromStdString(e.mode), QString::fromStdString(e.kind))
                             .arg(QString::fromStdString(core::formatNumber(e.v, 5)));
    lines << text;
    for (QwtPlot* plot : {real_, imaginary_}) {
      auto* m = new QwtPlotMarker;
      m->setLineStyle(QwtPlotMarker::VLine);
      m->setXValue(e.v);
      m->setLinePen(modeColour(e.mode), 1.0, Qt::DashLine);
      if (plot == real_) {
        QwtText label(tr("%1 %2 m/s")
                          .arg(QString::fromStdString(e.mode))
                          .arg(QString::fromStdString(core::formatNumber(e.v, 5))));
        label.setColor(modeColour(e.mode));
        m->setLabel(label);
        // Alternately at the top and the bottom: close speeds keep their labels apart.
        m->setLabelAlignment(Qt::AlignRight | (lines.size() % 2 ? Qt::AlignTop : Qt::AlignBottom));
      }
      m->attach(plot);
      markers_.push_back(m);
    }
  }
  // Re from -15 1/s up: the question is the sign near zero; castering and
  // the fork modes reach far below and would flatten the weave and capsize.
  double reMax = 1.0;
  for (const auto& curve : re)
    for (const auto& p : curve) reMax = std::max(reMax, p.y());
  real_->setAxisScale(QwtPlot::yLeft, -15.0, std::min(reMax * 1.1, 15.0));
  real_->setAxisScale(QwtPlot::xBottom, sweep_->points.front().v, sweep_->points.back().v);
  imaginary_->setAxisScale(QwtPlot::xBottom, sweep_->points.front().v, sweep_->points.back().v);
  summary_->setText(lines.isEmpty() ? tr("No real part crosses zero in this speed range.")
                                    : tr("Critical speeds: %1").arg(lines.join(QStringLiteral("; "))));
  alignLeftAxes({real_, imaginary_});  // one speed axis: the canvases line up
  real_->replot();
  imaginary_->replot();
  emit finished(true);
}

QString StabilityPage::summaryText() const {
  return summary_->text();
}

void StabilityPage::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void StabilityPage::retranslate() {
  modelLabel_->setText(tr("Model:"));
  model_->setItemText(0, tr("Benchmark bicycle (Meijaard et al. 2007)"));
  model_->setItemText(1, tr("Benchmark bicycle, steel fork in bending (thesis §6.5)"));
  model_->setItemText(2, tr("Benchmark bicycle, steel fork in torsion (thesis §6.4)"));
  speedsLabel_->setText(tr("Speeds from, to, step:"));
  runButton_->setText(tr("Compute"));
  real_->setTitle(tr("Real part of the eigenvalues"));
  real_->setAxisTitle(QwtPlot::xBottom, tr("Speed [m/s]"));
  real_->setAxisTitle(QwtPlot::yLeft, tr("Re λ [1/s]"));
  imaginary_->setTitle(tr("Imaginary part (oscillating modes)"));
  imaginary_->setAxisTitle(QwtPlot::xBottom, tr("Speed [m/s]"));
  imaginary_->setAxisTitle(QwtPlot::yLeft, tr("Im λ [rad/s]"));
}

}  // namespace views
}  // namespace mozzi
