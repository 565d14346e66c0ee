// The rig test page: construction, the controls, the specimen and test lists.
// Its other parts: rig_test_setup.cpp (the set-up panel), rig_test_run.cpp
// (running a sequence), rig_test_plots.cpp (plots, results, stored tests).

#include "views/rigs/rig_test_page.h"

#include <qwt_interval_symbol.h>
#include <qwt_legend.h>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_grid.h>
#include <qwt_plot_intervalcurve.h>
#include <qwt_symbol.h>
#include <qwt_text.h>
#include <qwt_text_label.h>
#include <QComboBox>
#include <QCoreApplication>
#include <QEvent>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QShortcut>
#include <QSplitter>
#include <QStyle>
#include <QTabWidget>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <mutex>
#include <nlohmann/json.hpp>
#include <variant>

#include "core/io/project_store.h"
#include "core/tire/magic_formula.h"
#include "devices/rigtests/rig_sequence.h"
#include "devices/rigtests/sequence_parameters.h"
#include "devices/rigtests/stiffness_results.h"
#include "devices/rigtests/stiffness_tests.h"
#include "devices/rigtests/tyre_tests.h"
#include "devices/rigtests/virtual_rigs.h"
#include "devices/sim/sim_drivers.h"
#include "devices/sim/specimen_catalogue.h"
#include "views/common/job_runner.h"
#include "views/panels/parameter_form.h"
#include "views/plots/interactive_plot.h"
#include "views/plots/plot_export.h"
#include "views/scene/plate_sketch.h"

#include "views/rigs/rig_test_page_internal.h"

namespace mozzi {
namespace views {

namespace rig_page {

core::Result<rt::Outcome> runOnSimulatedRig(JobProgress& progress, RigHandOver& handOver,
                                            const std::shared_ptr<core::io::ProjectStore>& store,
                                            const std::string& specimenKey, bool tyre, const SequenceRun& run) {
  auto who = rt::resolveSpecimen(*store, specimenKey);
  if (!who) return who.error();
  {
    std::lock_guard<std::mutex> lock(handOver.mutex);
    handOver.specimenAdded = who->created;
  }
  auto driver = tyre ? devices::sim::makeTyreTesterDriver() : devices::sim::makeStiffnessRigDriver();
  auto device = driver->create(devices::DeviceDescriptor{driver->name(), "", 0, 0, "", "sim:0"});
  if (!device) return device.error();
  rt::Callbacks cb;
  cb.live = [&](const rt::LiveReadout& r) {
    if (progress.cancelled()) handOver.cancel.cancel();  // the status bar's Cancel
    std::lock_guard<std::mutex> lock(handOver.mutex);
    handOver.live.push_back(r);
  };
  cb.progress = [&](const rt::Progress& p) {
    progress.report(p.fraction, p.message);
    if (progress.cancelled()) handOver.cancel.cancel();
    std::lock_guard<std::mutex> lock(handOver.mutex);
    handOver.progress = p;
  };
  cb.step = [&](const rt::StepReport& s) {
    std::lock_guard<std::mutex> lock(handOver.mutex);
    handOver.events.emplace_back(s);
  };
  cb.log = [&](const std::string& line) {
    std::lock_guard<std::mutex> lock(handOver.mutex);
    handOver.events.emplace_back(line);
  };
  auto out = run(**device, rt::StoreTarget{store.get(), who->specimenId, ""}, cb, &handOver.cancel);
  if (out) {
    std::lock_guard<std::mutex> lock(handOver.mutex);
    handOver.outcome = *out;
  }
  return out;
}

namespace {

// The results' names in words (the sequences' keys, devices/rigtests).
struct KeyLabel {
  const char* key;
  const char* label;
};
const KeyLabel kResultLabels[] = {
    {"k_lat", QT_TRANSLATE_NOOP("RigResults", "lateral stiffness k_lat")},
    {"a_tw", QT_TRANSLATE_NOOP("RigResults", "twist arm a_tw")},
    {"k_tw", QT_TRANSLATE_NOOP("RigResults", "twist stiffness k_tw")},
    {"axis_inclination", QT_TRANSLATE_NOOP("RigResults", "twist axis inclination from the plate's v axis")},
    {"axis_point_u", QT_TRANSLATE_NOOP("RigResults", "twist axis foot from the load point, u")},
    {"axis_point_v", QT_TRANSLATE_NOOP("RigResults", "twist axis foot from the load point, v")},
    {"peak_force", QT_TRANSLATE_NOOP("RigResults", "peak force measured")},
    {"k_lat_positive", QT_TRANSLATE_NOOP("RigResults", "lateral stiffness, positive load")},
    {"k_lat_negative", QT_TRANSLATE_NOOP("RigResults", "lateral stiffness, negative load")},
    {"plane_rms_residual", QT_TRANSLATE_NOOP("RigResults", "rms residual of the laser plane")},
    {"k_bend", QT_TRANSLATE_NOOP("RigResults", "bending stiffness")},
    {"k_tors", QT_TRANSLATE_NOOP("RigResults", "torsion stiffness")},
    {"a_bend", QT_TRANSLATE_NOOP("RigResults", "bending arm")},
    {"a_tors", QT_TRANSLATE_NOOP("RigResults", "torsion arm")},
    {"frequency", QT_TRANSLATE_NOOP("RigResults", "frequency")},
    {"force_amplitude", QT_TRANSLATE_NOOP("RigResults", "force amplitude")},
    {"steps_with_axis", QT_TRANSLATE_NOOP("RigResults", "frequencies with a twist axis")},
    {"phase_lag", QT_TRANSLATE_NOOP("RigResults", "lag of F_y behind the yaw angle")},
    {"yaw_amplitude", QT_TRANSLATE_NOOP("RigResults", "yaw amplitude")},
    {"relaxation_length_m", QT_TRANSLATE_NOOP("RigResults", "relaxation length")},
    {"relaxation_length_scatter_m", QT_TRANSLATE_NOOP("RigResults", "scatter of the relaxation length in the band")},
    {"points_in_band", QT_TRANSLATE_NOOP("RigResults", "frequencies in the band")},
    {"speed", QT_TRANSLATE_NOOP("RigResults", "disk speed")},
    {"half_length", QT_TRANSLATE_NOOP("RigResults", "contact half-length a (Table 17)")},
    {"slip", QT_TRANSLATE_NOOP("RigResults", "side-slip set-point")},
    {"camber", QT_TRANSLATE_NOOP("RigResults", "camber set-point")},
    {"slip_measured", QT_TRANSLATE_NOOP("RigResults", "side-slip angle measured")},
    {"camber_measured", QT_TRANSLATE_NOOP("RigResults", "camber angle measured")},
    {"lateral_force", QT_TRANSLATE_NOOP("RigResults", "lateral force F_y")},
    {"aligning_moment", QT_TRANSLATE_NOOP("RigResults", "yaw torque M_z")},
    {"spin_moment", QT_TRANSLATE_NOOP("RigResults", "moment about the spin axis M_y")},
    {"cornering_stiffness", QT_TRANSLATE_NOOP("RigResults", "cornering stiffness dF_y/dalpha")},
    {"aligning_stiffness", QT_TRANSLATE_NOOP("RigResults", "self-aligning torque stiffness dM_z/dalpha")},
    {"normalised_cornering_stiffness", QT_TRANSLATE_NOOP("RigResults", "cornering stiffness / F_z")},
    {"camber_stiffness", QT_TRANSLATE_NOOP("RigResults", "camber stiffness dF_y/dgamma")},
    {"twisting_torque_stiffness", QT_TRANSLATE_NOOP("RigResults", "twisting torque stiffness dM_z/dgamma")},
    {"mf_lateral_rms", QT_TRANSLATE_NOOP("RigResults", "Magic Formula F_y rms residual")},
    {"mf_aligning_rms", QT_TRANSLATE_NOOP("RigResults", "Magic Formula M_z rms residual")},
    {"vertical_load", QT_TRANSLATE_NOOP("RigResults", "vertical load F_z")},
};

}  // namespace

QString resultLabel(const std::string& key) {
  for (const auto& k : kResultLabels)
    if (key == k.key) return QCoreApplication::translate("RigResults", k.label);
  // laser_<n>_amplitude, laser_<n>_phase, mf_<coefficient>
  const QString q = qs(key);
  if (q.startsWith(QLatin1String("laser_")) && q.endsWith(QLatin1String("_amplitude")))
    return QCoreApplication::translate("RigResults", "laser %1 amplitude").arg(q.section(QLatin1Char('_'), 1, 1));
  if (q.startsWith(QLatin1String("laser_")) && q.endsWith(QLatin1String("_phase")))
    return QCoreApplication::translate("RigResults", "laser %1 phase from the force")
        .arg(q.section(QLatin1Char('_'), 1, 1));
  if (q.startsWith(QLatin1String("mf_")))
    return QCoreApplication::translate("RigResults", "Magic Formula %1").arg(q.mid(3));
  return q;
}

QwtPlotCurve* addCurve(QwtPlot* plot, const QColor& colour, int yAxis) {
  auto* c = new QwtPlotCurve();
  c->setPen(QPen(colour, 1.5));
  c->setRenderHint(QwtPlotItem::RenderAntialiased, true);
  c->setYAxis(yAxis);
  c->setLegendAttribute(QwtPlotCurve::LegendShowLine, true);
  c->setLegendAttribute(QwtPlotCurve::LegendShowSymbol, true);
  c->attach(plot);
  return c;
}

void setAxisText(QwtPlot* plot, int axis, const QString& text) {
  QwtText title(text);
  // A vertical axis's title on one line; a horizontal one may wrap (it
  // only grows downwards, under the tick labels).
  const bool horizontal = axis == QwtPlot::xBottom || axis == QwtPlot::xTop;
  title.setRenderFlags(horizontal ? Qt::AlignCenter | Qt::TextWordWrap : Qt::AlignCenter);
  title.setFont(plot->font());
  plot->setAxisTitle(axis, title);
}

QwtPlot* makePlot(QWidget* parent) {
  auto* plot = new QwtPlot(parent);
  plot->setCanvasBackground(Qt::white);
  auto* grid = new QwtPlotGrid();
  grid->setMajorPen(QPen(QColor(220, 220, 220), 0.0, Qt::DotLine));
  grid->attach(plot);
  plot->insertLegend(new QwtLegend(), QwtPlot::BottomLegend);
  plot->setMinimumSize(kPlotMinWidth, kPlotMinHeight);
  // Titles at the text's size (bold): Qwt's larger default wrapped over
  // three lines in a third of the plots' width.
  QFont title = plot->font();
  title.setBold(true);
  plot->titleLabel()->setFont(title);
  installPlotExportAction(plot);
  return plot;
}

}  // namespace rig_page

using rig_page::kControlsMaxChars;
using rig_page::kControlsMinChars;
using rig_page::kRedrawMs;
using rig_page::makePlot;
using rig_page::qs;
using rig_page::setAxisText;

RigTestPage::RigTestPage(Rig rig, const PageContext& ctx)
    : QWidget(ctx.parent), rig_(rig), model_(ctx.model), jobs_(ctx.jobs), log_(ctx.log) {
  buildUi();
  fillSpecimens();
  fillTests();
  rebuildSetupForm();
  rebuildTestForm();
  resetPlots();
  retranslate();
  connect(model_, &ProjectModel::aboutToClose, this, &RigTestPage::stop);
  if (ctx.item.kind == (rig_ == Rig::Stiffness ? RecordKind::RigTest : RecordKind::TyreTest))
    showStoredTest(ctx.item.id);
  else
    showLatestStored(true);  // the project's latest test of the specimen, plotted on open
  connect(model_, &ProjectModel::projectChanged, this, [this] {
    if (isRunning()) return;
    resetPlots();
    showLatestStored(true);
  });
}

RigTestPage::~RigTestPage() {
  if (handOver_) handOver_->cancel.cancel();  // the job delivers nothing to a destroyed page
}

// The run controls on the left: specimen and test, the rig's and the test's
// forms, Run and Stop, progress and status, in a scroll area.
QWidget* RigTestPage::buildControls() {
  auto* left = new QWidget;
  auto* leftLayout = new QVBoxLayout(left);
  setupBox_ = new QGroupBox;
  auto* setupForm = new QFormLayout(setupBox_);
  specimen_ = new QComboBox;
  specimen_->setObjectName(QStringLiteral("specimen"));
  test_ = new QComboBox;
  test_->setObjectName(QStringLiteral("test"));
  specimenLabel_ = new QLabel;
  testLabel_ = new QLabel;
  setupForm->addRow(specimenLabel_, specimen_);
  setupForm->addRow(testLabel_, test_);
  setupInfo_ = new QLabel;
  setupInfo_->setObjectName(QStringLiteral("setup"));
  setupInfo_->setWordWrap(true);
  setupForm->addRow(setupInfo_);
  leftLayout->addWidget(setupBox_);

  rigBox_ = new QGroupBox;
  auto* rigLayout = new QVBoxLayout(rigBox_);
  rigForm_ = new ParameterForm(devices::rigtests::simulatedRigParameters(rig_ == Rig::Tyre));
  rigForm_->setObjectName(QStringLiteral("rigForm"));
  rigLayout->addWidget(rigForm_);
  leftLayout->addWidget(rigBox_);

  testBoxGroup_ = new QGroupBox;
  auto* testLayout = new QVBoxLayout(testBoxGroup_);
  testForm_ = new ParameterForm;
  testForm_->setObjectName(QStringLiteral("testForm"));
  testLayout->addWidget(testForm_);
  leftLayout->addWidget(testBoxGroup_);

  auto* buttons = new QHBoxLayout;
  run_ = new QPushButton;
  run_->setObjectName(QStringLiteral("run"));
  stop_ = new QPushButton;
  stop_->setObjectName(QStringLiteral("stop"));
  stop_->setEnabled(false);
  buttons->addWidget(run_);
  buttons->addWidget(stop_);
  leftLayout->addLayout(buttons);
  progress_ = new QProgressBar;
  progress_->setRange(0, 1000);
  progress_->setValue(0);
  leftLayout->addWidget(progress_);
  status_ = new QLabel;
  status_->setObjectName(QStringLiteral("status"));
  status_->setWordWrap(true);
  status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  leftLayout->addWidget(status_);
  leftLayout->addStretch(1);

  // The controls scroll on their own (both ways) rather than widen the page
  // past the tab area: at 1280x800 with the project dock open the page has
  // about 950 pixels, the plots need most of them.
  auto* scroll = new QScrollArea;
  scroll->setObjectName(QStringLiteral("controls"));
  scroll->setWidget(left);
  scroll->setWidgetResizable(true);
  scroll->setMinimumWidth(fontMetrics().averageCharWidth() * kControlsMinChars);
  return scroll;
}

void RigTestPage::buildUi() {
  auto* scroll = buildControls();

  readout_ = new QLabel;
  readout_->setObjectName(QStringLiteral("readout"));
  readout_->setWordWrap(true);
  QFont big = readout_->font();
  big.setPointSizeF(big.pointSizeF() * 1.15);
  readout_->setFont(big);
  livePlot_ = makePlot(this);
  livePlot_->setObjectName(QStringLiteral("livePlot"));
  livePlot_->enableAxis(QwtPlot::yRight, true);
  resultPlot_ = makePlot(this);
  resultPlot_->setObjectName(QStringLiteral("resultPlot"));
  axisPlot_ = makePlot(this);
  axisPlot_->setObjectName(QStringLiteral("axisPlot"));
  axisPlot_->enableAxis(QwtPlot::yRight, true);
  auto* plots = new QSplitter(Qt::Horizontal);
  plots->addWidget(livePlot_);
  plots->addWidget(resultPlot_);
  plots->addWidget(axisPlot_);

  resultsBox_ = new QGroupBox;
  auto* resultsLayout = new QVBoxLayout(resultsBox_);
  headline_ = new QLabel;
  headline_->setObjectName(QStringLiteral("headline"));
  headline_->setWordWrap(false);  // its few lines always fit; the table gives way
  QFont bold = headline_->font();
  bold.setBold(true);
  bold.setPointSizeF(bold.pointSizeF() * 1.15);
  headline_->setFont(bold);
  headline_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  results_ = new QTableWidget(0, 5);
  results_->setObjectName(QStringLiteral("results"));
  results_->verticalHeader()->hide();
  results_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  results_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
  resultsLayout->addWidget(headline_);
  resultsLayout->addWidget(results_);
  logView_ = new QPlainTextEdit;
  logView_->setObjectName(QStringLiteral("log"));
  logView_->setReadOnly(true);
  logView_->setMaximumBlockCount(2000);
  logView_->hide();  // shown when a run starts: until then the results take its room
  auto* bottom = new QSplitter(Qt::Horizontal);
  bottom->addWidget(resultsBox_);
  bottom->addWidget(logView_);
  bottom->setStretchFactor(0, 3);
  bottom->setStretchFactor(1, 1);

  auto* right = new QWidget;
  auto* rightLayout = new QVBoxLayout(right);
  rightLayout->setContentsMargins(0, 0, 0, 0);
  rightLayout->addWidget(readout_);
  plotTabs_ = new QTabWidget;
  plotTabs_->setObjectName(QStringLiteral("plotTabs"));
  plotTabs_->setDocumentMode(true);
  plotTabs_->addTab(plots, QString());
  if (rig_ == Rig::Stiffness) {
    plotTabs_->addTab(buildSetupView(), QString());
  } else {
    plotTabs_->tabBar()->hide();
  }
  auto* vertical = new QSplitter(Qt::Vertical);
  vertical->addWidget(plotTabs_);
  vertical->addWidget(bottom);
  vertical->setStretchFactor(0, 3);
  vertical->setStretchFactor(1, 2);
  rightLayout->addWidget(vertical, 1);

  // Controls and plots side by side, the split movable; the controls start
  // as wide as their form (at most kControlsMaxChars), the plots take the rest.
  auto* split = new QSplitter(Qt::Horizontal);
  split->setObjectName(QStringLiteral("controlsSplit"));
  split->setChildrenCollapsible(false);
  split->addWidget(scroll);
  split->addWidget(right);
  split->setStretchFactor(0, 0);
  split->setStretchFactor(1, 1);
  controlsSplit_ = split;  // sized in the first showEvent(), when its width is known
  auto* layout = new QHBoxLayout(this);
  layout->addWidget(split);

  timer_ = new QTimer(this);
  timer_->setInterval(kRedrawMs);
  connect(timer_, &QTimer::timeout, this, &RigTestPage::drain);
  connect(run_, &QPushButton::clicked, this, &RigTestPage::start);
  connect(stop_, &QPushButton::clicked, this, &RigTestPage::stop);
  auto* runKey = new QShortcut(QKeySequence(Qt::Key_F5), this);
  runKey->setContext(Qt::WidgetWithChildrenShortcut);
  connect(runKey, &QShortcut::activated, this, &RigTestPage::start);
  auto* stopKey = new QShortcut(QKeySequence(Qt::Key_Escape), this);
  stopKey->setContext(Qt::WidgetWithChildrenShortcut);
  connect(stopKey, &QShortcut::activated, this, &RigTestPage::stop);
  connect(rigForm_, &ParameterForm::valuesChanged, this, [this] { showSetup(); });
  if (setupForm_) connect(setupForm_, &ParameterForm::valuesChanged, this, [this] { drawSetup(); });
  // A specimen or a test picked: its latest stored result, if the project has one.
  connect(specimen_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] {
    rebuildSetupForm();
    rebuildTestForm();
    if (isRunning() || showingStored_) return;
    resetPlots();
    showLatestStored(false);
  });
  connect(test_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] {
    rebuildTestForm();
    if (isRunning()) return;
    resetPlots();
    showLatestStored(false);
  });
}

void RigTestPage::retranslate() {
  const bool stiff = rig_ == Rig::Stiffness;
  setupBox_->setTitle(stiff ? tr("Stiffness rig (simulated Motostiffmeter)")
                            : tr("Tyre tester (simulated Mototiremeter)"));
  specimenLabel_->setText(stiff ? tr("Specimen") : tr("Tyre"));
  testLabel_->setText(tr("Test"));
  rigBox_->setTitle(tr("Simulated rig"));
  testBoxGroup_->setTitle(tr("Test settings"));
  if (setupFormBox_) setupFormBox_->setTitle(tr("Set-up: plate, lasers, load point (mm)"));
  plotTabs_->setTabText(0, tr("Measurement"));
  if (setupPlot_) {
    plotTabs_->setTabText(1, tr("Set-up view"));
    setupPlot_->setTitle(tr("Set-up over the specimen"));
    setAxisText(setupPlot_, QwtPlot::xBottom, tr("u [m] (plate plane)"));
    setAxisText(setupPlot_, QwtPlot::yLeft, tr("v [m]"));
    drawSetup();
  }
  resultsBox_->setTitle(tr("Result stored in the project"));
  run_->setText(tr("Run (F5)"));
  run_->setToolTip(tr("Check the settings against the machine's limits and run the test"));
  stop_->setText(tr("Stop (Esc)"));
  stop_->setToolTip(tr("Stop the test: the finished steps stay in the project"));
  results_->setHorizontalHeaderLabels({tr("Step"), tr("Quantity"), tr("Value"), tr("Std. uncertainty"), tr("Unit")});
  fillTests();
  if (statusSource_)
    setStatus(statusSource_, statusError_);  // said again in the new language
  else
    setStatus([] { return tr("Ready. Pick a test and press Run."); });
  showSetup();
  // The plots' titles in the new language; a stored test shown keeps its
  // curves and its results table is written again (step and quantity names).
  resetPlots(false);
  if (!isRunning() && lastTestId_ && model_->store()) showStoredTest(*lastTestId_);
}

void RigTestPage::showEvent(QShowEvent* event) {
  QWidget::showEvent(event);
  if (controlsSized_) return;
  // As wide as the filled form needs beside its scroll bar, within bounds;
  // sizes that add up to the splitter's width (others are scaled to it).
  auto* controls = static_cast<QScrollArea*>(controlsSplit_->widget(0));
  const int width = std::clamp(controls->widget()->minimumSizeHint().width() +
                                   style()->pixelMetric(QStyle::PM_ScrollBarExtent) + 2 * controls->frameWidth() + 4,
                               fontMetrics().averageCharWidth() * kControlsMinChars,
                               fontMetrics().averageCharWidth() * kControlsMaxChars);
  const int rest = controlsSplit_->width() - controlsSplit_->handleWidth() - width;
  if (rest <= 0) return;
  controlsSplit_->setSizes({width, rest});
  controlsSized_ = true;
}

void RigTestPage::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void RigTestPage::fillSpecimens() {
  const QSignalBlocker block(specimen_);
  specimen_->clear();
  for (const auto& e : devices::sim::specimenCatalogue()) {
    const bool fits = rig_ == Rig::Stiffness ? e.statics.has_value() : e.kind == "tyre";
    if (fits) specimen_->addItem(qs(e.name), qs(e.key));
  }
  const int preferred = specimen_->findData(rig_ == Rig::Stiffness ? QStringLiteral("fork-a-with-wheel")
                                                                   : QStringLiteral("tyre-120-70-r17"));
  if (preferred >= 0) specimen_->setCurrentIndex(preferred);
}

void RigTestPage::fillTests() {
  const QString current = testId();
  const QSignalBlocker block(test_);
  test_->clear();
  if (rig_ == Rig::Stiffness) {
    test_->addItem(tr("Static ramp"), QStringLiteral("static"));
    test_->setItemData(0, tr("A slow force ramp: k_lat, the twist axis, a_tw and k_tw"), Qt::ToolTipRole);
    test_->addItem(tr("Sine sweep"), QStringLiteral("dynamic"));
    test_->setItemData(1, tr("A sine per frequency: the dynamic twist axis and stiffness"), Qt::ToolTipRole);
  } else {
    test_->addItem(tr("Harmonic yaw"), QStringLiteral("relaxation"));
    test_->setItemData(0, tr("Yaw oscillations at a list of frequencies: the relaxation length"), Qt::ToolTipRole);
    test_->addItem(tr("Steady-state sweeps"), QStringLiteral("steady-state"));
    test_->setItemData(1, tr("Side-slip and camber sweeps: the characteristics and the Magic Formula"),
                       Qt::ToolTipRole);
  }
  const int i = test_->findData(current);
  if (i >= 0) test_->setCurrentIndex(i);
}

bool RigTestPage::selectSpecimen(const QString& key) {
  const int i = specimen_->findData(key);
  if (i < 0) return false;
  specimen_->setCurrentIndex(i);
  return true;
}

bool RigTestPage::selectTest(const QString& id) {
  const int i = test_->findData(id);
  if (i < 0) return false;
  test_->setCurrentIndex(i);
  return true;
}

QString RigTestPage::testId() const {
  return test_->currentData().toString();
}

QString RigTestPage::specimenKey() const {
  return specimen_->currentData().toString();
}

void RigTestPage::rebuildTestForm() {
  showSetup();
  const auto* entry = devices::sim::findSpecimen(specimenKey().toStdString());
  const double force = entry && entry->statics ? entry->statics->testForceN : 300.0;
  const QString id = testId();
  if (id == QLatin1String("static"))
    testForm_->setSpecs(rt::staticTestParameters(force));
  else if (id == QLatin1String("dynamic"))
    testForm_->setSpecs(rt::dynamicTestParameters(force));
  else if (id == QLatin1String("relaxation"))
    testForm_->setSpecs(rt::relaxationTestParameters());
  else
    testForm_->setSpecs(rt::steadyStateTestParameters());
}

QString RigTestPage::statusText() const {
  return status_->text();
}

QString RigTestPage::readoutText() const {
  return readout_->text();
}

void RigTestPage::setStatus(std::function<QString()> text, bool error) {
  statusSource_ = std::move(text);
  statusError_ = error;
  status_->setText(statusSource_ ? statusSource_() : QString());
  status_->setStyleSheet(error ? QStringLiteral("color: #b00020; font-weight: bold;") : QString());
}

void RigTestPage::setRunning(bool running) {
  run_->setEnabled(!running);
  stop_->setEnabled(running);
  specimen_->setEnabled(!running);
  test_->setEnabled(!running);
  rigForm_->setEnabled(!running);
  testForm_->setEnabled(!running);
  if (setupForm_) setupForm_->setEnabled(!running);
}

}  // namespace views
}  // namespace mozzi
