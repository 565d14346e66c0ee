#include "views/tyre/relaxation_page.h"

#include <qwt_column_symbol.h>
#include <qwt_interval_symbol.h>
#include <qwt_legend.h>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_intervalcurve.h>
#include <qwt_plot_multi_barchart.h>
#include <qwt_symbol.h>
#include <qwt_text.h>
#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>

#include "core/common/text.h"
#include "core/io/project_store.h"
#include "views/common/job_runner.h"
#include "views/common/project_model.h"
#include "views/plots/interactive_plot.h"

namespace mozzi {
namespace views {

namespace tire = core::tire;

namespace {

// One colour per inflation pressure series (measured points and their
// prediction line share it).
QColor seriesColour(int i) {
  static const QColor colours[] = {QColor(31, 119, 180),  QColor(214, 39, 40),  QColor(44, 160, 44),
                                   QColor(148, 103, 189), QColor(255, 127, 14), QColor(140, 86, 75)};
  return colours[i % 6];
}

// Figure 43's segments, bottom to top: contact patch, camber, lateral, C-, S-shaped
// (and the modes k >= 4 when the ring has them).
QVector<double> contributions(const tire::RelaxationPrediction& p, bool higher) {
  QVector<double> v{p.contactPatch, p.camber, p.lateral, p.cShaped, p.sShaped};
  if (higher) v.append(p.higherModes);
  return v;
}

QString number(double v, int digits) {
  return QString::fromStdString(core::formatNumber(v, digits));
}

QString bar(double pa) {
  return number(pa / 1e5, 3);
}

}  // namespace

RelaxationPage::RelaxationPage(const PageContext& ctx) : QWidget(ctx.parent), model_(ctx.model), jobs_(ctx.jobs) {
  tyreLabel_ = new QLabel(this);
  tyre_ = new QComboBox(this);
  tyre_->setObjectName(QStringLiteral("relaxationTyre"));
  tyre_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  keep_ = new QPushButton(this);
  keep_->setObjectName(QStringLiteral("relaxationKeep"));
  keep_->setEnabled(false);
  status_ = new QLabel(this);
  status_->setObjectName(QStringLiteral("relaxationStatus"));
  status_->setWordWrap(true);
  status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  inputs_ = new QLabel(this);
  inputs_->setObjectName(QStringLiteral("relaxationInputs"));
  inputs_->setWordWrap(true);
  inputs_->setTextInteractionFlags(Qt::TextSelectableByMouse);

  auto* f = new InteractivePlot(this);
  f->setObjectName(QStringLiteral("relaxationFrequency"));
  frequency_ = f;
  auto* p = new InteractivePlot(this);
  p->setObjectName(QStringLiteral("relaxationPressure"));
  p->setCursorOnClick(false);
  pressure_ = p;
  frequency_->insertLegend(new QwtLegend, QwtPlot::RightLegend);
  pressure_->insertLegend(new QwtLegend, QwtPlot::RightLegend);
  for (QwtPlot* plot : {frequency_, pressure_}) plot->setMinimumSize(320, 180);

  ringTitle_ = new QLabel(this);
  ring_ = new QTableWidget(0, 7, this);
  ring_->setObjectName(QStringLiteral("relaxationRingModes"));
  ring_->verticalHeader()->setVisible(false);
  ring_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  ring_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  ring_->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
  ring_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);

  auto* bar = new QHBoxLayout;
  bar->addWidget(tyreLabel_);
  bar->addWidget(tyre_);
  bar->addStretch(1);
  bar->addWidget(keep_);
  auto* plots = new QSplitter(Qt::Vertical, this);
  plots->addWidget(frequency_);
  plots->addWidget(pressure_);
  auto* ringBox = new QWidget(this);
  auto* ringLayout = new QVBoxLayout(ringBox);
  ringLayout->setContentsMargins(0, 0, 0, 0);
  ringLayout->addWidget(ringTitle_);
  ringLayout->addWidget(ring_);
  ringLayout->addWidget(inputs_);
  ringLayout->addStretch(1);
  auto* split = new QSplitter(Qt::Horizontal, this);
  split->addWidget(plots);
  split->addWidget(ringBox);
  split->setStretchFactor(0, 3);
  split->setStretchFactor(1, 2);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(bar);
  layout->addWidget(status_);
  layout->addWidget(split, 1);

  connect(tyre_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int) { recompute(); });
  connect(keep_, &QPushButton::clicked, this, [this] { keepInProject(); });
  connect(model_, &ProjectModel::projectChanged, this, [this] { fillSpecimens(); });
  connect(model_, &ProjectModel::specimensChanged, this, [this] { fillSpecimens(); });
  connect(model_, &ProjectModel::tyreTestsChanged, this, [this] { recompute(); });
  retranslate();
  if (ctx.item.kind == RecordKind::Specimen) wanted_ = ctx.item.id;
  fillSpecimens();
  if (ctx.item.kind == RecordKind::TyreTest) showTyreTest(ctx.item.id);
}

qint64 RelaxationPage::specimenId() const {
  return tyre_->currentIndex() >= 0 ? tyre_->currentData().toLongLong() : 0;
}

QString RelaxationPage::statusText() const {
  return status_->text();
}

// The project's tyres: specimens of kind "tyre" or named after a thesis tyre.
void RelaxationPage::fillSpecimens() {
  const qint64 keep = wanted_ ? wanted_ : specimenId();
  const QSignalBlocker block(tyre_);
  tyre_->clear();
  if (model_->store()) {
    if (auto summary = model_->summary()) {
      for (const auto& s : summary->specimens)
        if (s.kind == "tyre" || tire::findThesisTyre(s.name))
          tyre_->addItem(QString::fromStdString(s.name), QVariant::fromValue<qlonglong>(s.id));
    }
  }
  const int at = tyre_->findData(QVariant::fromValue<qlonglong>(keep));
  tyre_->setCurrentIndex(at >= 0 ? at : (tyre_->count() ? 0 : -1));
  if (at >= 0) wanted_ = 0;
  recompute();
}

void RelaxationPage::showSpecimen(qint64 id) {
  const int at = tyre_->findData(QVariant::fromValue<qlonglong>(id));
  if (at < 0) {
    wanted_ = id;
    fillSpecimens();
    return;
  }
  if (at == tyre_->currentIndex())
    recompute();
  else
    tyre_->setCurrentIndex(at);  // recomputes
}

void RelaxationPage::showTyreTest(qint64 tyreTestId) {
  if (!model_->store()) return;
  auto tests = model_->store()->tyreTests();
  if (!tests) return;
  for (const auto& t : *tests)
    if (t.id == tyreTestId) showSpecimen(t.specimenId);
}

void RelaxationPage::recompute() {
  const qint64 id = specimenId();
  keep_->setEnabled(false);
  if (!model_->store() || id == 0) {
    showProblem(tr("The project holds no tyre specimen."));
    return;
  }
  status_->setText(tr("Reading the relaxation tests and predicting (thesis eq. 48)..."));
  auto store = model_->storeHandle();
  auto work = [store, id](JobProgress&) { return tire::relaxationOverview(*store, id); };
  if (!jobs_) {
    JobProgress progress;
    present(work(progress));
    return;
  }
  jobs_->run<tire::RelaxationOverview>(this, tr("Tyre relaxation"), work,
                                       [this, id](core::Result<tire::RelaxationOverview> r) {
                                         if (id == specimenId()) present(std::move(r));  // a newer choice wins
                                       });
}

void RelaxationPage::present(core::Result<tire::RelaxationOverview> result) {
  if (!result) {
    showProblem(tr("Cannot show the relaxation length: %1").arg(QString::fromStdString(result.error().describe())));
    return;
  }
  overview_ = std::move(result).value();
  showOverview();
  keep_->setEnabled(!model_->isReadOnly());
  emit finished(true);
}

void RelaxationPage::clearPlots() {
  frequency_->detachItems(QwtPlotItem::Rtti_PlotCurve, true);
  frequency_->detachItems(QwtPlotItem::Rtti_PlotIntervalCurve, true);
  pressure_->detachItems(QwtPlotItem::Rtti_PlotMultiBarChart, true);
  pressure_->detachItems(QwtPlotItem::Rtti_PlotCurve, true);
}

void RelaxationPage::showProblem(const QString& text) {
  overview_.reset();
  clearPlots();
  ring_->setRowCount(0);
  inputs_->clear();
  status_->setText(text);
  frequency_->replot();
  pressure_->replot();
  emit finished(false);
}

void RelaxationPage::showOverview() {
  clearPlots();
  drawFrequency();
  drawPressure();
  fillRingTable();
  const auto& o = *overview_;
  QStringList status;
  if (o.tests.empty())
    status << tr("No relaxation test of this tyre in the project: the prediction alone.");
  else
    status << tr("%n relaxation test(s) of tyre %1.", nullptr, static_cast<int>(o.tests.size()))
                  .arg(QString::fromStdString(o.tyre.size));
  if (!o.unreadableTests.empty())
    status << tr("%n relaxation test(s) hold no result and are not drawn.", nullptr,
                 static_cast<int>(o.unreadableTests.size()));
  for (std::size_t i = 0; i < o.tests.size(); ++i) {
    const auto& t = o.tests[i];
    const double predicted = o.atTests[i].prediction.total();
    if (t.bandMean)
      status << tr("%1 bar: measured %2 m, predicted %3 m (%4%).")
                    .arg(bar(t.pressurePa), number(*t.bandMean, 4), number(predicted, 4))
                    .arg(number(100.0 * (predicted - *t.bandMean) / *t.bandMean, 3));
  }
  status_->setText(status.join(QLatin1Char(' ')));
  int measured = 0;
  for (const auto& c : o.table17) measured += c.corneringSource == tire::CorneringSource::SteadyStateTest;
  inputs_->setText(
      tr("Inputs of eq. 48: ring stiffness from thesis Table 16 (nominal pressure); contact half-length a from "
         "Table 17 for the bars and as each test stored it for the lines; F_z %1 N; cornering stiffness from the "
         "project's steady-state test at %n of the 7 Table 17 pressures, elsewhere assumed %2 F_z; friction %3 "
         "and slip angle 1.5° assumed (§5.4). Tyre mass %4 kg and damping ratio %5 assumed (eq. 45 to 47).",
         nullptr, measured)
          .arg(number(o.tyre.testLoad, 5), number(tire::kAssumedNormalisedCorneringStiffness, 3),
               number(tire::kAssumedFriction, 3), number(o.tyre.tyreMass, 3), number(tire::kAssumedDampingRatio, 3)));
}

// Relaxation length against frequency: measured points with their standard
// errors, one series per pressure, and eq. 48 at that pressure (frequency-free
// in the first-order model) as a dashed line over the measured range.
void RelaxationPage::drawFrequency() {
  const auto& o = *overview_;
  double fMin = 0.42, fMax = 2.10;  // §5.1's yaw frequencies when nothing is measured
  bool any = false;
  for (const auto& t : o.tests)
    for (const auto& pt : t.points) {
      fMin = any ? std::min(fMin, pt.frequencyHz) : pt.frequencyHz;
      fMax = any ? std::max(fMax, pt.frequencyHz) : pt.frequencyHz;
      any = true;
    }
  const double pad = std::max(0.1, 0.08 * (fMax - fMin));
  for (std::size_t i = 0; i < o.tests.size(); ++i) {
    const auto& t = o.tests[i];
    const QColor colour = seriesColour(static_cast<int>(i));
    QVector<QPointF> points;
    QVector<QwtIntervalSample> errors;
    for (const auto& pt : t.points) {
      points.append(QPointF(pt.frequencyHz, pt.sigma));
      errors.append(QwtIntervalSample(pt.frequencyHz, pt.sigma - pt.sigmaStdError, pt.sigma + pt.sigmaStdError));
    }
    auto* curve = new QwtPlotCurve(tr("measured, %1 bar").arg(bar(t.pressurePa)));
    curve->setStyle(QwtPlotCurve::NoCurve);
    curve->setSymbol(new QwtSymbol(QwtSymbol::Ellipse, QBrush(colour), QPen(colour), QSize(8, 8)));
    curve->setLegendAttribute(QwtPlotCurve::LegendShowSymbol, true);
    curve->setSamples(points);
    curve->attach(frequency_);
    auto* bars = new QwtPlotIntervalCurve(tr("standard error"));
    bars->setStyle(QwtPlotIntervalCurve::NoCurve);
    auto* symbol = new QwtIntervalSymbol(QwtIntervalSymbol::Bar);
    symbol->setWidth(8);
    symbol->setPen(QPen(colour, 1.5));
    bars->setSymbol(symbol);
    bars->setSamples(errors);
    bars->setItemAttribute(QwtPlotItem::Legend, false);
    bars->attach(frequency_);
    const double predicted = o.atTests[i].prediction.total();
    auto* line = new QwtPlotCurve(tr("predicted (eq. 48), %1 bar").arg(bar(t.pressurePa)));
    line->setPen(QPen(colour, 2.0, Qt::DashLine));
    line->setSamples(QVector<QPointF>{{fMin - pad, predicted}, {fMax + pad, predicted}});
    line->attach(frequency_);
  }
  frequency_->setAxisScale(QwtPlot::xBottom, std::max(0.0, fMin - pad), fMax + pad);
  static_cast<InteractivePlot*>(frequency_)->autoscaleY();
  double top = 0.0;
  for (const auto& t : o.tests) {
    for (const auto& pt : t.points) top = std::max(top, pt.sigma + pt.sigmaStdError);
  }
  for (const auto& c : o.atTests) top = std::max(top, c.prediction.total());
  frequency_->setAxisScale(QwtPlot::yLeft, 0.0, top > 0.0 ? 1.15 * top : 0.3);  // lengths from zero
  frequency_->replot();
}

// Figure 43: the prediction at the Table 17 pressures as stacked bars of its
// contributions, and the measured band means (the thesis's dashed red line).
void RelaxationPage::drawPressure() {
  const auto& o = *overview_;
  bool higher = false;
  for (const auto& c : o.table17) higher = higher || c.prediction.higherModes > 0.0;
  auto* chart = new QwtPlotMultiBarChart(tr("predicted (eq. 48)"));
  chart->setStyle(QwtPlotMultiBarChart::Stacked);
  chart->setLayoutPolicy(QwtPlotAbstractBarChart::ScaleSamplesToAxes);
  chart->setLayoutHint(0.18);  // bar width in bar: 0.5 and 0.75 bar stay apart
  QList<QwtText> titles{tr("contact patch a m"), tr("camber mode"), tr("lateral mode"), tr("C-shaped mode"),
                        tr("S-shaped mode")};
  if (higher) titles << tr("modes k ≥ 4");
  chart->setBarTitles(titles);
  const QColor fills[] = {QColor(80, 80, 80),    QColor(190, 190, 190), QColor(135, 135, 135),
                          QColor(250, 250, 250), QColor(20, 20, 20),    QColor(120, 160, 200)};
  for (int k = 0; k < titles.size(); ++k) {
    auto* symbol = new QwtColumnSymbol(QwtColumnSymbol::Box);
    symbol->setLineWidth(1);
    symbol->setFrameStyle(QwtColumnSymbol::Plain);
    QPalette palette(fills[k]);
    palette.setColor(QPalette::Dark, QColor(0, 0, 0));
    symbol->setPalette(palette);
    chart->setSymbol(k, symbol);
  }
  QVector<QwtSetSample> samples;
  double top = 0.0;
  for (const auto& c : o.table17) {
    samples.append(QwtSetSample(c.pressurePa / 1e5, contributions(c.prediction, higher)));
    top = std::max(top, c.prediction.total());
  }
  chart->setSamples(samples);
  chart->attach(pressure_);
  if (!o.tests.empty()) {
    QVector<QPointF> means;
    for (const auto& t : o.tests)
      if (t.bandMean) {
        means.append(QPointF(t.pressurePa / 1e5, *t.bandMean));
        top = std::max(top, *t.bandMean);
      }
    auto* measured = new QwtPlotCurve(tr("measured (band mean)"));
    measured->setPen(QPen(QColor(214, 39, 40), 2.0, Qt::DashLine));
    measured->setSymbol(
        new QwtSymbol(QwtSymbol::Diamond, QBrush(QColor(214, 39, 40)), QPen(QColor(214, 39, 40)), QSize(10, 10)));
    measured->setLegendAttribute(QwtPlotCurve::LegendShowSymbol, true);
    measured->setSamples(means);
    measured->setZ(chart->z() + 1);
    measured->attach(pressure_);
  }
  pressure_->setAxisScale(QwtPlot::xBottom, 0.25, 4.25);
  pressure_->setAxisScale(QwtPlot::yLeft, 0.0, top > 0.0 ? 1.1 * top : 0.3);
  pressure_->replot();
}

void RelaxationPage::fillRingTable() {
  const auto& ring = overview_->ring;
  ring_->setRowCount(static_cast<int>(ring.modes.size()));
  int row = 0;
  for (const auto& m : ring.modes) {
    const QStringList cells{
        QString::number(m.k),           QString::fromStdString(m.name), number(m.naturalFrequencyHz, 4),
        number(m.dampingRatio, 3),      number(m.modalMass, 4),         number(m.modalStiffness / 1e3, 5),
        number(m.dampingCoefficient, 4)};
    for (int c = 0; c < cells.size(); ++c) {
      auto* item = new QTableWidgetItem(cells[c]);
      item->setTextAlignment(c == 1 ? int(Qt::AlignLeft | Qt::AlignVCenter) : int(Qt::AlignRight | Qt::AlignVCenter));
      ring_->setItem(row, c, item);
    }
    ++row;
  }
  // The whole table in view: its columns set the pane's width.
  ring_->resizeColumnsToContents();
  ring_->setMinimumWidth(ring_->horizontalHeader()->length() + 2 * ring_->frameWidth());
}

qint64 RelaxationPage::keepInProject() {
  if (!overview_ || !model_->store()) return 0;
  core::io::StoredAnalysis a;
  a.specimenId = overview_->specimenId;
  a.kind = "relaxation-prediction";
  a.name = "relaxation length, thesis eq. 48, " + overview_->tyre.size;
  if (!overview_->tests.empty()) a.tyreTestId = overview_->tests.front().testId;
  a.resultJson = tire::relaxationOverviewJson(*overview_);
  auto id = model_->addAnalysis(a);
  if (!id) {
    status_->setText(tr("Could not keep the prediction: %1").arg(QString::fromStdString(id.error().describe())));
    return 0;
  }
  emit message(tr("Relaxation prediction of %1 kept in the project (analysis %2)")
                   .arg(QString::fromStdString(overview_->specimenName))
                   .arg(*id));
  return *id;
}

void RelaxationPage::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void RelaxationPage::retranslate() {
  tyreLabel_->setText(tr("Tyre:"));
  keep_->setText(tr("Keep in project"));
  keep_->setToolTip(tr("Store the prediction and its inputs as an analysis of the project"));
  frequency_->setTitle(tr("Relaxation length against yaw frequency"));
  frequency_->setAxisTitle(QwtPlot::xBottom, tr("Frequency [Hz]"));
  frequency_->setAxisTitle(QwtPlot::yLeft, tr("σ [m]"));
  pressure_->setTitle(tr("Relaxation length against pressure (thesis Figure 43)"));
  pressure_->setAxisTitle(QwtPlot::xBottom, tr("Inflation pressure [bar]"));
  pressure_->setAxisTitle(QwtPlot::yLeft, tr("σ [m]"));
  ringTitle_->setText(tr("Rigid-ring modes (thesis Table 16, eq. 45 to 47)"));
  ring_->setHorizontalHeaderLabels(
      {tr("k"), tr("mode"), tr("f [Hz]"), tr("ζ"), tr("m_k [kg]"), tr("C_k [kN/m]"), tr("c_k [N s/m]")});
  if (overview_) showOverview();
}

}  // namespace views
}  // namespace mozzi
