#include "views/rigs/rig_test_page.h"

#include <qwt_interval_symbol.h>
#include <qwt_legend.h>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_grid.h>
#include <qwt_plot_intervalcurve.h>
#include <qwt_symbol.h>
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

namespace mozzi {
namespace views {

namespace rt = devices::rigtests;

// What the sequence's thread hands to the GUI thread (rig_test_page.h).
struct RigHandOver {
  std::mutex mutex;
  std::vector<rt::LiveReadout> live;
  // Step reports and log lines in the order they came (the log view shows both).
  std::vector<std::variant<rt::StepReport, std::string>> events;
  std::optional<rt::Progress> progress;
  std::optional<rt::Outcome> outcome;  // kept even when the job ends cancelled
  bool specimenAdded = false;
  rt::CancelFlag cancel;
};

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kRedrawMs = 40;              // 25 Hz
constexpr double kPlotRateHz = 250.0;      // live curves keep at most this many points per second
constexpr double kTyreTimeWindowS = 10.0;  // seconds of the tyre tester's time traces shown
constexpr double kSineTimeWindowS = 2.0;   // seconds of the stiffness rig's sine traces shown

QString qs(const std::string& s) {
  return QString::fromStdString(s);
}

// Runs one sequence on a simulated rig: resolves the specimen (adds it to the
// project when it is not there), creates the device, follows the sequence
// with the hand-over buffer. Worker thread.
using SequenceRun = std::function<core::Result<rt::Outcome>(devices::Device&, const rt::StoreTarget&,
                                                            const rt::Callbacks&, const rt::CancelFlag*)>;

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

// Angles in degrees, everything else as stored (SI).
struct Shown {
  double value, uncertainty;
  QString unit;
};
Shown shown(double value, double uncertainty, const std::string& unit) {
  if (unit == "rad") return {value * 180.0 / kPi, uncertainty * 180.0 / kPi, QStringLiteral("deg")};
  if (unit == "rad/s") return {value * 180.0 / kPi, uncertainty * 180.0 / kPi, QStringLiteral("deg/s")};
  if (unit == "m") return {value * 1e3, uncertainty * 1e3, QStringLiteral("mm")};
  return {value, uncertainty, qs(unit)};
}

QString number(double v) {
  return QString::number(v, 'g', 5);
}

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

QwtPlotCurve* addCurve(QwtPlot* plot, const QColor& colour, int yAxis = QwtPlot::yLeft) {
  auto* c = new QwtPlotCurve();
  c->setPen(QPen(colour, 1.5));
  c->setRenderHint(QwtPlotItem::RenderAntialiased, true);
  c->setYAxis(yAxis);
  c->setLegendAttribute(QwtPlotCurve::LegendShowLine, true);
  c->setLegendAttribute(QwtPlotCurve::LegendShowSymbol, true);
  c->attach(plot);
  return c;
}

QwtPlot* makePlot(QWidget* parent) {
  auto* plot = new QwtPlot(parent);
  plot->setCanvasBackground(Qt::white);
  auto* grid = new QwtPlotGrid();
  grid->setMajorPen(QPen(QColor(220, 220, 220), 0.0, Qt::DotLine));
  grid->attach(plot);
  plot->insertLegend(new QwtLegend(), QwtPlot::BottomLegend);
  plot->setMinimumSize(280, 220);
  installPlotExportAction(plot);
  return plot;
}

void trimFront(QVector<QPointF>& v, double fromX) {
  int n = 0;
  while (n < v.size() && v[n].x() < fromX) ++n;
  if (n > 0) v.remove(0, n);
}

}  // namespace

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
}

RigTestPage::~RigTestPage() {
  if (handOver_) handOver_->cancel.cancel();  // the job delivers nothing to a destroyed page
}

void RigTestPage::buildUi() {
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

  auto* scroll = new QScrollArea;
  scroll->setWidget(left);
  scroll->setWidgetResizable(true);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  scroll->setMinimumWidth(left->sizeHint().width() + 24);
  scroll->setMaximumWidth(std::max(460, left->sizeHint().width() + 24));

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
    // The set-up view: the plate, the lasers, the load point and the
    // constrained end over the specimen's silhouette, as the form says.
    // The form beside the picture, so the run controls on the left stay in view.
    setupFormBox_ = new QGroupBox;
    auto* setupLayout = new QVBoxLayout(setupFormBox_);
    setupForm_ = new ParameterForm;
    setupForm_->setObjectName(QStringLiteral("setupForm"));
    setupLayout->addWidget(setupForm_);
    setupLayout->addStretch(1);
    auto* formScroll = new QScrollArea;
    formScroll->setWidget(setupFormBox_);
    formScroll->setWidgetResizable(true);
    formScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setupScroll_ = formScroll;
    auto* view = new QWidget;
    auto* viewRow = new QHBoxLayout(view);
    viewRow->setContentsMargins(0, 0, 0, 0);
    viewRow->addWidget(formScroll);
    auto* viewLayout = new QVBoxLayout;
    viewRow->addLayout(viewLayout, 1);
    setupPlot_ = new InteractivePlot;
    setupPlot_->setObjectName(QStringLiteral("setupPlot"));
    setupPlot_->setCanvasBackground(Qt::white);
    setupPlot_->setCursorOnClick(false);
    setupPlot_->setMinimumSize(280, 220);
    installPlotExportAction(setupPlot_);
    setupExtent_ = new QwtPlotCurve;
    setupExtent_->setStyle(QwtPlotCurve::NoCurve);
    setupExtent_->setItemAttribute(QwtPlotItem::Legend, false);
    setupExtent_->attach(setupPlot_);
    sketch_ = std::make_unique<PlateSketch>(setupPlot_);
    setupPlot_->setEqualAspect(true);
    geometry_ = new QLabel;
    geometry_->setObjectName(QStringLiteral("geometry"));
    geometry_->setWordWrap(true);
    geometry_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    setupNote_ = new QLabel;
    setupNote_->setObjectName(QStringLiteral("setupNote"));
    setupNote_->setWordWrap(true);
    viewLayout->addWidget(setupPlot_, 1);
    viewLayout->addWidget(geometry_);
    viewLayout->addWidget(setupNote_);
    plotTabs_->addTab(view, QString());
  } else {
    plotTabs_->tabBar()->hide();
  }
  auto* vertical = new QSplitter(Qt::Vertical);
  vertical->addWidget(plotTabs_);
  vertical->addWidget(bottom);
  vertical->setStretchFactor(0, 3);
  vertical->setStretchFactor(1, 2);
  rightLayout->addWidget(vertical, 1);

  auto* layout = new QHBoxLayout(this);
  layout->addWidget(scroll);
  layout->addWidget(right, 1);

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
  connect(specimen_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] {
    rebuildSetupForm();
    rebuildTestForm();
  });
  connect(test_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] {
    rebuildTestForm();
    if (!isRunning()) resetPlots();
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
    setupPlot_->setAxisTitle(QwtPlot::xBottom, tr("u [m] (plate plane)"));
    setupPlot_->setAxisTitle(QwtPlot::yLeft, tr("v [m]"));
    drawSetup();
  }
  resultsBox_->setTitle(tr("Result stored in the project"));
  run_->setText(tr("Run (F5)"));
  run_->setToolTip(tr("Check the settings against the machine's limits and run the test"));
  stop_->setText(tr("Stop (Esc)"));
  stop_->setToolTip(tr("Stop the test: the finished steps stay in the project"));
  results_->setHorizontalHeaderLabels({tr("Step"), tr("Quantity"), tr("Value"), tr("Std. uncertainty"), tr("Unit")});
  fillTests();
  if (status_->text().isEmpty()) setStatus(tr("Ready. Pick a test and press Run."));
  showSetup();
  if (!isRunning()) resetPlots();
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

QString RigTestPage::setupText() const {
  return setupInfo_->text();
}

void RigTestPage::showSetup() {
  const std::string key = specimenKey().toStdString();
  const auto values = rigForm_->values();
  const auto mm = [](double m) { return QString::number(m * 1e3, 'f', 0); };
  if (rig_ == Rig::Stiffness) {
    auto setup = rt::simulatedStiffnessSetup(key, 1, false);
    if (!setup) {
      setupInfo_->setText(qs(setup.error().describe()));
      return;
    }
    if (setupForm_ && !setupForm_->specs().empty())
      if (auto edited = rt::stiffnessSetupFrom(*setup, geometryValues())) setup = std::move(edited);
    QStringList points;
    for (const auto& p : setup->laserPoints) points << QStringLiteral("(%1, %2)").arg(mm(p.x()), mm(p.y()));
    setupInfo_->setText(
        tr("Plate (u, v) [mm]: %n laser(s) at %1; load point at (%2, %3); the other end locked.", nullptr,
           static_cast<int>(points.size()))
            .arg(points.join(QStringLiteral(", ")), mm(setup->loadPoint.x()), mm(setup->loadPoint.y())));
  } else {
    auto setup = rt::simulatedTyreSetup(key, devices::parameterReal(values, "tyre.pressure_bar", 2.0), 1, false);
    if (!setup) {
      setupInfo_->setText(qs(setup.error().describe()));
      return;
    }
    setupInfo_->setText(tr("Load F_z %1 N; contact half-length a %2 mm (Table 17); working limits side-slip "
                           "±%3°, camber ±%4° (machine ±%5°, ±%6°, disk up to %7 km/h).")
                            .arg(setup->verticalLoadN, 0, 'f', 0)
                            .arg(mm(setup->halfLengthM))
                            .arg(setup->slipLimitDeg)
                            .arg(setup->camberLimitDeg)
                            .arg(rt::kMachineMaxSlipDeg)
                            .arg(rt::kMachineMaxCamberDeg)
                            .arg(rt::kMachineMaxSpeedKmh));
  }
}

void RigTestPage::rebuildSetupForm() {
  if (!setupForm_) return;
  const std::string key = specimenKey().toStdString();
  auto base = rt::simulatedStiffnessSetup(key, 1, false);
  if (!base) {
    setupForm_->setSpecs({});
    drawSetup();
    return;
  }
  // The constrained end where the specimen's silhouette has it.
  std::optional<core::Vector2> locked;
  if (const auto& catalogue = silhouetteCatalogue())
    if (auto placed = core::stiffness::placeSilhouette(*catalogue, key, base->loadPoint))
      locked = placed->constrainedEnd;
  {
    const QSignalBlocker block(setupForm_);
    // The geometry, then where the actuator's set-point comes from (the
    // simulated rig's own drive or the simulated function generator).
    auto specs = rt::stiffnessSetupParameters(*base, locked);
    specs.push_back(rt::actuatorParameter({rt::kActuatorRigDrive, rt::kActuatorSimGenerator}));
    setupForm_->setSpecs(specs);
  }
  // As wide as the form's widest row (labels and spin boxes), whatever the font.
  setupFormBox_->layout()->activate();
  const QFontMetrics fm(setupForm_->font());
  const int rowWidth = fm.horizontalAdvance(QCoreApplication::translate("Parameters", "Constrained end u")) +
                       fm.horizontalAdvance(QStringLiteral("-2000.00 mm")) + fm.height() * 6;
  setupScroll_->setMinimumWidth(std::max(setupFormBox_->sizeHint().width(), rowWidth) + 24);
  drawSetup();
}

devices::ParameterMap RigTestPage::geometryValues() const {
  auto values = setupForm_->values();
  values.erase("setup.actuator");
  return values;
}

QwtPlot* RigTestPage::setupPlot() const {
  return setupPlot_;
}

QString RigTestPage::geometryText() const {
  return geometry_ ? geometry_->text() : QString();
}

void RigTestPage::drawSetup() {
  if (!setupPlot_) return;
  const std::string key = specimenKey().toStdString();
  for (const auto& spec : setupForm_->specs())
    if (QWidget* e = setupForm_->editor(spec.key)) e->setStyleSheet(QString());
  auto base = rt::simulatedStiffnessSetup(key, 1, false);
  std::optional<core::stiffness::PlacedSilhouette> placed;
  QString note;
  if (base) {
    // The specimen stays where it is: its silhouette placed at the specimen's own load point.
    if (const auto& catalogue = silhouetteCatalogue()) {
      auto p = core::stiffness::placeSilhouette(*catalogue, key, base->loadPoint);
      if (p)
        placed = std::move(p).value();
      else
        note = tr("No outline drawn: %1").arg(qs(p.error().describe()));
    } else {
      note = tr("No outline drawn: %1").arg(qs(catalogue.error().describe()));
    }
  }
  PlateSketchInput input;
  input.silhouette = placed ? &*placed : nullptr;
  QString problem;
  if (base && !setupForm_->specs().empty()) {
    auto setup = rt::stiffnessSetupFrom(*base, geometryValues());
    if (setup) {
      input.laserPoints = setup->laserPoints;
      input.loadPoint = setup->loadPoint;
      input.plateOutline = setup->plateOutline;
      input.constrainedEnd = setup->constrainedEnd;
      if (auto ok = rt::checkPlateGeometry(*setup); !ok) {
        // Name the field in the form's words and mark it.
        QString field = qs(ok.error().where);
        for (const auto& spec : setupForm_->specs())
          if (spec.key == ok.error().where) {
            field = QCoreApplication::translate("Parameters", spec.label.c_str());
            if (QWidget* e = setupForm_->editor(spec.key))
              e->setStyleSheet(QStringLiteral("background-color: #ffd6d6;"));
          }
        problem = tr("Set-up not valid, field '%1': %2").arg(field, qs(ok.error().message));
      }
    } else {
      problem = tr("Set-up not valid: %1").arg(qs(setup.error().describe()));
    }
  } else if (!base) {
    problem = qs(base.error().describe());
  }
  sketch_->draw(input);
  QVector<QPointF> extent;
  for (const auto& p : sketch_->extent()) extent.append(QPointF(p.x(), p.y()));
  setupExtent_->setSamples(extent);
  setupPlot_->autoscale();
  setupPlot_->replot();
  geometry_->setText(problem);
  geometry_->setStyleSheet(problem.isEmpty() ? QString() : QStringLiteral("color: #b00020; font-weight: bold;"));
  setupNote_->setText(placed ? tr("Outline: %1, approximate (not to scale of a drawing).").arg(qs(placed->name))
                             : note);
  showSetup();
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

void RigTestPage::setStatus(const QString& text, bool error) {
  status_->setText(text);
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

void RigTestPage::resetPlots() {
  const bool stiff = rig_ == Rig::Stiffness;
  const QString id = testId();
  timeLeftData_.clear();
  timeRightData_.clear();
  xyData_.clear();
  xySecondData_.clear();
  liveStep_ = -1;
  if (!timeLeft_) {  // the curves are made once; a reset empties and re-titles them
    timeLeft_ = addCurve(livePlot_, QColor(31, 119, 180));
    timeRight_ = addCurve(livePlot_, QColor(214, 39, 40), QwtPlot::yRight);
    xyLive_ = addCurve(resultPlot_, QColor(31, 119, 180));
    xySecond_ = addCurve(resultPlot_, QColor(44, 160, 44));
    fitLine_ = addCurve(resultPlot_, QColor(0, 0, 0));
    fitLine2_ = addCurve(resultPlot_, QColor(120, 120, 120));
    fitLine_->setPen(QPen(Qt::black, 1.5, Qt::DashLine));
    fitLine2_->setPen(QPen(QColor(120, 120, 120), 1.5, Qt::DashLine));
    mfSlip_ = addCurve(resultPlot_, QColor(148, 103, 189));
    mfCamber_ = addCurve(resultPlot_, QColor(140, 86, 75));
    mfSlip_->setPen(QPen(QColor(148, 103, 189), 2.0));
    mfCamber_->setPen(QPen(QColor(140, 86, 75), 2.0));
    timeLeft_->setPen(QPen(QColor(31, 119, 180), 3.0));  // wide: an in-phase trace on the right axis covers it
    sineFit_ = addCurve(resultPlot_, Qt::black);
    sineFit_->setPen(QPen(Qt::black, 1.5, Qt::DashLine));
    const QColor incColour(31, 119, 180), armColour(214, 39, 40);
    inclination_ = addCurve(axisPlot_, incColour);
    inclination_->setSymbol(new QwtSymbol(QwtSymbol::Ellipse, QBrush(incColour), QPen(incColour), QSize(7, 7)));
    arm_ = addCurve(axisPlot_, armColour, QwtPlot::yRight);
    arm_->setSymbol(new QwtSymbol(QwtSymbol::Rect, QBrush(armColour), QPen(armColour), QSize(7, 7)));
    auto bars = [this](const QColor& colour, int yAxis) {
      auto* c = new QwtPlotIntervalCurve();
      c->setStyle(QwtPlotIntervalCurve::NoCurve);
      auto* symbol = new QwtIntervalSymbol(QwtIntervalSymbol::Bar);
      symbol->setWidth(8);
      symbol->setPen(QPen(colour, 1.2));
      c->setSymbol(symbol);
      c->setYAxis(yAxis);
      c->setItemAttribute(QwtPlotItem::Legend, false);
      c->attach(axisPlot_);
      return c;
    };
    inclinationBars_ = bars(incColour, QwtPlot::yLeft);
    armBars_ = bars(armColour, QwtPlot::yRight);
  }
  clearAxisPlot();
  const bool sine = stiff && id == QLatin1String("dynamic");
  axisPlot_->setVisible(sine);
  sineFit_->setSamples(QVector<QPointF>());
  sineFit_->setVisible(sine);
  sineFit_->setItemAttribute(QwtPlotItem::Legend, sine);
  const bool steady = id == QLatin1String("steady-state");
  for (QwtPlotCurve* c : {xyLive_, xySecond_}) {
    // Steady state: one point per set-point; otherwise a line through the scans.
    c->setStyle(steady ? QwtPlotCurve::NoCurve : QwtPlotCurve::Lines);
    const QColor colour = c->pen().color();
    c->setSymbol(steady ? new QwtSymbol(QwtSymbol::Ellipse, QBrush(colour), QPen(colour), QSize(7, 7)) : nullptr);
  }
  for (QwtPlotCurve* c : {timeLeft_, timeRight_, xyLive_, xySecond_, fitLine_, fitLine2_, mfSlip_, mfCamber_})
    c->setSamples(QVector<QPointF>());
  // Which curves this test draws (and lists in the legend).
  const bool second = !stiff && steady;
  const bool fit = stiff ? id == QLatin1String("static") : steady;
  const std::pair<QwtPlotCurve*, bool> used[] = {
      {xySecond_, second}, {fitLine_, fit}, {fitLine2_, second}, {mfSlip_, second}, {mfCamber_, second}};
  for (const auto& [c, on] : used) {
    c->setVisible(on);
    c->setItemAttribute(QwtPlotItem::Legend, on);
  }
  // A measured line under a stored fit is drawn wide and light, so both show where they agree.
  const bool under = (fit && !steady) || sine;  // a stored line or a sine-fit loop drawn over it
  xyLive_->setPen(QPen(under ? QColor(120, 170, 220) : QColor(31, 119, 180), under ? 5.0 : 1.5));
  livePlot_->setAxisTitle(QwtPlot::xBottom, tr("Time [s]"));
  if (stiff) {
    timeWindowS_ = id == QLatin1String("dynamic") ? kSineTimeWindowS : 0.0;
    livePlot_->setTitle(tr("Load cell and load-point displacement"));
    livePlot_->setAxisTitle(QwtPlot::yLeft, tr("Force [N]"));
    livePlot_->setAxisTitle(QwtPlot::yRight, tr("Displacement [mm]"));
    timeLeft_->setTitle(tr("load cell [N]"));
    timeRight_->setTitle(tr("load-point displacement [mm]"));
    resultPlot_->setTitle(tr("Force vs load-point displacement"));
    resultPlot_->setAxisTitle(QwtPlot::xBottom, tr("Load-point displacement [mm]"));
    resultPlot_->setAxisTitle(QwtPlot::yLeft, tr("Force [N]"));
    xyLive_->setTitle(id == QLatin1String("dynamic") ? tr("current frequency") : tr("measured"));
    fitLine_->setTitle(tr("F = k_lat x (stored k_lat)"));
    sineFit_->setTitle(tr("sine fit, last frequency"));
    axisPlot_->setTitle(tr("Dynamic twist axis against frequency"));
    axisPlot_->setAxisTitle(QwtPlot::xBottom, tr("Frequency [Hz]"));
    axisPlot_->setAxisTitle(QwtPlot::yLeft, tr("Inclination [deg]"));
    axisPlot_->setAxisTitle(QwtPlot::yRight, tr("Twist arm a_tw [mm]"));
    inclination_->setTitle(tr("inclination ± 1σ"));
    arm_->setTitle(tr("a_tw ± 1σ"));
  } else {
    timeWindowS_ = kTyreTimeWindowS;
    livePlot_->setTitle(tr("Lateral force and aligning moment"));
    livePlot_->setAxisTitle(QwtPlot::yLeft, tr("F_y [N]"));
    livePlot_->setAxisTitle(QwtPlot::yRight, tr("M_z [N m]"));
    timeLeft_->setTitle(tr("F_y [N]"));
    timeRight_->setTitle(tr("M_z [N m]"));
    resultPlot_->setAxisTitle(QwtPlot::yLeft, tr("F_y [N]"));
    if (steady) {
      resultPlot_->setTitle(tr("Steady-state characteristic"));
      resultPlot_->setAxisTitle(QwtPlot::xBottom, tr("Side-slip, camber [deg]"));
      xyLive_->setTitle(tr("F_y vs side-slip"));
      xySecond_->setTitle(tr("F_y vs camber"));
      fitLine_->setTitle(tr("cornering stiffness (stored)"));
      fitLine2_->setTitle(tr("camber stiffness (stored)"));
      mfSlip_->setTitle(tr("Magic Formula vs side-slip"));
      mfCamber_->setTitle(tr("Magic Formula vs camber"));
    } else {
      resultPlot_->setTitle(tr("Lateral force vs yaw angle"));
      resultPlot_->setAxisTitle(QwtPlot::xBottom, tr("Yaw angle [deg]"));
      xyLive_->setTitle(tr("current frequency"));
    }
  }
  livePlot_->setAxisAutoScale(QwtPlot::xBottom);
  livePlot_->setAxisAutoScale(QwtPlot::yLeft);
  livePlot_->setAxisAutoScale(QwtPlot::yRight);
  resultPlot_->setAxisAutoScale(QwtPlot::xBottom);
  resultPlot_->setAxisAutoScale(QwtPlot::yLeft);
  livePlot_->updateLegend();
  resultPlot_->updateLegend();
  livePlot_->replot();
  resultPlot_->replot();
}

void RigTestPage::start() {
  if (isRunning()) return;
  core::io::ProjectStore* store = model_->store();
  if (!store) {
    setStatus(tr("Open or create a project first: the test is stored in it."), true);
    return;
  }
  if (model_->isReadOnly()) {
    setStatus(tr("The project is open read-only (%1): the test could not be stored.").arg(model_->readOnlyReason()),
              true);
    return;
  }
  if (testForm_->hasProblems() || rigForm_->hasProblems()) {
    setStatus(tr("Correct the settings marked in the form first."), true);
    return;
  }
  const std::string key = specimenKey().toStdString();
  const auto rigValues = rigForm_->values();
  const auto seed = static_cast<std::uint64_t>(devices::parameterInteger(rigValues, "sim.seed", 1));
  const bool realtime = devices::parameterBool(rigValues, "sim.realtime", true);
  const QString id = testId();
  auto refuse = [this](const core::Error& e) {
    setStatus(tr("Not started: %1").arg(qs(e.describe())), true);
    if (log_) log_(tr("Rig test not started: %1").arg(qs(e.describe())));
  };

  auto handOver = std::make_shared<RigHandOver>();
  auto storeHandle = model_->storeHandle();
  const bool tyre = rig_ == Rig::Tyre;
  SequenceRun run;
  roles_.clear();
  if (!tyre) {
    auto setup = rt::simulatedStiffnessSetup(key, seed, realtime);
    if (!setup) return refuse(setup.error());
    std::shared_ptr<devices::Device> actuator;
    if (!setupForm_->specs().empty()) {
      setup = rt::stiffnessSetupFrom(*setup, geometryValues());
      if (!setup) return refuse(setup.error());
      auto device = rt::actuatorFor(
          devices::parameterText(setupForm_->values(), "setup.actuator", rt::kActuatorRigDrive), *setup);
      if (!device) return refuse(device.error());
      actuator = std::shared_ptr<devices::Device>(std::move(device).value());
      if (auto ok = rt::checkPlateGeometry(*setup); !ok) {
        drawSetup();  // marks the field
        plotTabs_->setCurrentIndex(1);
        setStatus(tr("Not started: %1").arg(geometry_->text()), true);
        if (log_) log_(tr("Rig test not started: %1").arg(geometry_->text()));
        return;
      }
    }
    laserPoints_.clear();
    for (const auto& p : setup->laserPoints) laserPoints_.emplace_back(p.x(), p.y());
    loadPoint_ = {setup->loadPoint.x(), setup->loadPoint.y()};
    if (id == QLatin1String("static")) {
      auto st = rt::staticSettingsFrom(testForm_->values());
      if (!st) return refuse(st.error());
      if (auto ok = rt::checkStaticSettings(*setup, *st); !ok) return refuse(ok.error());
      run = [setup = *setup, st = *st, actuator](devices::Device& d, const rt::StoreTarget& t, const rt::Callbacks& cb,
                                                 const rt::CancelFlag* c) -> core::Result<rt::Outcome> {
        auto o = rt::runStaticStiffnessTest(d, actuator.get(), setup, st, t, cb, c);
        if (!o) return o.error();
        return rt::Outcome(*o);
      };
    } else {
      auto st = rt::dynamicSettingsFrom(testForm_->values());
      if (!st) return refuse(st.error());
      if (auto ok = rt::checkDynamicSettings(*setup, *st); !ok) return refuse(ok.error());
      run = [setup = *setup, st = *st, actuator](devices::Device& d, const rt::StoreTarget& t, const rt::Callbacks& cb,
                                                 const rt::CancelFlag* c) -> core::Result<rt::Outcome> {
        auto o = rt::runDynamicStiffnessTest(d, actuator.get(), setup, st, t, cb, c);
        if (!o) return o.error();
        return rt::Outcome(*o);
      };
    }
  } else {
    const double pressure = devices::parameterReal(rigValues, "tyre.pressure_bar", 2.0);
    auto setup = rt::simulatedTyreSetup(key, pressure, seed, realtime);
    if (!setup) return refuse(setup.error());
    roles_ = {setup->lateralForce.name, setup->aligningMoment.name, setup->yawAngle.name, setup->camberAngle.name};
    if (id == QLatin1String("relaxation")) {
      auto st = rt::relaxationSettingsFrom(testForm_->values());
      if (!st) return refuse(st.error());
      if (auto ok = rt::checkRelaxationSettings(*setup, *st); !ok) return refuse(ok.error());
      run = [setup = *setup, st = *st](devices::Device& d, const rt::StoreTarget& t, const rt::Callbacks& cb,
                                       const rt::CancelFlag* c) -> core::Result<rt::Outcome> {
        auto o = rt::runRelaxationTest(d, setup, st, t, cb, c);
        if (!o) return o.error();
        return rt::Outcome(*o);
      };
    } else {
      auto st = rt::steadyStateSettingsFrom(testForm_->values());
      if (!st) return refuse(st.error());
      if (auto ok = rt::checkSteadyStateSettings(*setup, *st); !ok) return refuse(ok.error());
      run = [setup = *setup, st = *st](devices::Device& d, const rt::StoreTarget& t, const rt::Callbacks& cb,
                                       const rt::CancelFlag* c) -> core::Result<rt::Outcome> {
        auto o = rt::runSteadyStateTest(d, setup, st, t, cb, c);
        if (!o) return o.error();
        return rt::Outcome(*o);
      };
    }
  }

  handOver_ = handOver;
  runningTest_ = test_->currentText();
  lastTestId_.reset();
  redraws_ = 0;
  firstRedrawMs_ = lastRedrawMs_ = -1;
  clock_.start();
  resetPlots();
  plotTabs_->setCurrentIndex(0);
  results_->setRowCount(0);
  headline_->clear();
  progress_->setValue(0);
  setRunning(true);
  setStatus(tr("Running: %1 on %2").arg(runningTest_, specimen_->currentText()));
  if (log_) log_(tr("Rig test started: %1 on %2").arg(runningTest_, specimen_->currentText()));
  jobId_ = jobs_->run<rt::Outcome>(
      this, tr("%1 on %2").arg(runningTest_, specimen_->currentText()),
      [handOver, storeHandle, key, tyre, run](JobProgress& p) {
        return runOnSimulatedRig(p, *handOver, storeHandle, key, tyre, run);
      },
      [this](core::Result<rt::Outcome> result) {
        jobId_ = 0;
        timer_->stop();
        drain();
        std::optional<rt::Outcome> outcome;
        QString error;
        if (result) {
          outcome = *result;
        } else {
          error = qs(result.error().describe());
          std::lock_guard<std::mutex> lock(handOver_->mutex);
          outcome = handOver_->outcome;
        }
        bool added = false;
        {
          std::lock_guard<std::mutex> lock(handOver_->mutex);
          added = handOver_->specimenAdded;
        }
        if (added) model_->notifyChanged(RecordKind::Specimen);
        bool ok = false;
        QString message;
        if (outcome) {
          ok = outcome->status == core::io::TestStatus::Complete;
          if (outcome->testId) {
            lastTestId_ = *outcome->testId;
            model_->notifyChanged(rig_ == Rig::Stiffness ? RecordKind::RigTest : RecordKind::TyreTest,
                                  *outcome->testId);
            showStoredTest(*outcome->testId);
          }
          const QString name = qs(outcome->testName);
          switch (outcome->status) {
            case core::io::TestStatus::Complete: message = tr("Complete: stored as '%1'.").arg(name); break;
            case core::io::TestStatus::Interrupted:
              message = tr("Interrupted: stored as '%1' with the finished steps (%2).").arg(name, qs(outcome->note));
              break;
            default: message = tr("Failed: %1").arg(qs(outcome->note)); break;
          }
        } else {
          message = tr("Failed: %1").arg(error);
        }
        onDone(ok, message);
      },
      [this](double fraction, const QString&) { progress_->setValue(static_cast<int>(fraction * 1000)); });
  timer_->start();
}

void RigTestPage::stop() {
  if (!isRunning() || !handOver_) return;
  handOver_->cancel.cancel();
  setStatus(tr("Stopping: the sequence keeps the finished steps..."));
}

void RigTestPage::onDone(bool ok, const QString& message) {
  setRunning(false);
  if (ok) progress_->setValue(1000);
  setStatus(message, !ok);
  if (log_) log_(tr("Rig test: %1").arg(message));
  emit finished(ok);
}

void RigTestPage::drain() {
  if (!handOver_) return;
  std::vector<rt::LiveReadout> live;
  std::vector<std::variant<rt::StepReport, std::string>> events;
  {
    std::lock_guard<std::mutex> lock(handOver_->mutex);
    live.swap(handOver_->live);
    events.swap(handOver_->events);
  }
  for (const auto& r : live) onLive(r);
  bool stepped = false;
  for (const auto& e : events) {
    if (const auto* step = std::get_if<rt::StepReport>(&e)) {
      onStep(*step);
      stepped = true;
    } else {
      logView_->appendPlainText(qs(std::get<std::string>(e)));
    }
  }
  if (stepped)  // the running test's committed steps are in the project now
    model_->notifyChanged(rig_ == Rig::Stiffness ? RecordKind::RigTest : RecordKind::TyreTest);
  if (!live.empty() || stepped || dirty_) replot();
}

void RigTestPage::onLive(const rt::LiveReadout& r) {
  const Eigen::Index rows = r.block.rows();
  if (rows == 0 || r.sampleRateHz <= 0) return;
  const bool stiff = rig_ == Rig::Stiffness;
  if (r.step != liveStep_) {
    // A new step: a sine or a yaw frequency starts its own loop; the static
    // ramp is one step; a steady-state set-point keeps the traces running.
    if (liveStep_ >= 0 && testId() != QLatin1String("steady-state")) {
      timeLeftData_.clear();
      timeRightData_.clear();
      xyData_.clear();
      if (sineFit_) sineFit_->setSamples(QVector<QPointF>());  // the fit of the frequency before
    }
    liveStep_ = r.step;
  }
  auto column = [&](const std::string& name) {
    for (std::size_t c = 0; c < r.channels.size(); ++c)
      if (r.channels[c] == name) return static_cast<Eigen::Index>(c);
    return Eigen::Index{-1};
  };
  const int stride = std::max(1, static_cast<int>(std::lround(r.sampleRateHz / kPlotRateHz)));
  const double dt = 1.0 / r.sampleRateHz;
  // Time of the steady-state traces runs on over the set-points.
  const double offset = (!stiff && testId() == QLatin1String("steady-state") && !timeLeftData_.isEmpty() &&
                         r.time - (rows - 1) * dt < timeLeftData_.last().x() - 1e-9)
                            ? timeLeftData_.last().x() + dt - (r.time - (rows - 1) * dt)
                            : 0.0;
  Eigen::Index left = 0, right = -1, xCol = -1;
  if (stiff) {
    left = 0;  // the load cell
  } else if (roles_.size() == 4) {
    left = column(roles_[0]);
    right = column(roles_[1]);
    xCol = column(roles_[2]);
  }
  for (Eigen::Index i = 0; i < rows; i += stride) {
    const double t = r.time - static_cast<double>(rows - 1 - i) * dt + offset;
    if (left >= 0) timeLeftData_.append(QPointF(t, r.block(i, left)));
    if (stiff && r.derived.size() == rows) {
      const double x = r.derived(i) * 1e3;
      timeRightData_.append(QPointF(t, x));
      xyData_.append(QPointF(x, r.block(i, 0)));
    } else if (!stiff) {
      if (right >= 0) timeRightData_.append(QPointF(t, r.block(i, right)));
      if (xCol >= 0 && left >= 0 && testId() == QLatin1String("relaxation"))
        xyData_.append(QPointF(r.block(i, xCol) * 180.0 / kPi, r.block(i, left)));
    }
  }
  if (timeWindowS_ > 0 && !timeLeftData_.isEmpty()) {
    const double from = timeLeftData_.last().x() - timeWindowS_;
    trimFront(timeLeftData_, from);
    trimFront(timeRightData_, from);
    if (stiff) {
      // The force-displacement loop of the last window only (a settled sine).
      while (xyData_.size() > timeLeftData_.size()) xyData_.remove(0);
    }
  }
  // Readouts: the block's last scan, every channel.
  QStringList parts;
  parts << tr("%1 at %2 s").arg(qs(r.stepLabel)).arg(r.time, 0, 'f', 2);
  for (std::size_t c = 0; c < r.channels.size() && c < static_cast<std::size_t>(r.block.cols()); ++c) {
    const auto s = shown(r.block(rows - 1, static_cast<Eigen::Index>(c)), 0.0, c < r.units.size() ? r.units[c] : "");
    parts << QStringLiteral("%1 %2 %3").arg(qs(r.channels[c]), QString::number(s.value, 'f', 3), s.unit);
  }
  if (stiff && r.derived.size() == rows)
    parts << tr("load point %1 mm").arg(QString::number(r.derived(rows - 1) * 1e3, 'f', 4));
  readout_->setText(parts.join(QStringLiteral("   |   ")));
  dirty_ = true;
}

void RigTestPage::onStep(const rt::StepReport& s) {
  logView_->appendPlainText(
      s.ok ? tr("Step %1 (%2) committed.").arg(s.step).arg(qs(s.label))
           : tr("Step %1 (%2) kept without a result: %3").arg(s.step).arg(qs(s.label), qs(s.note)));
  if (rig_ == Rig::Stiffness && testId() == QLatin1String("dynamic") && s.ok) addAxisPoint(s.results);
  if (rig_ != Rig::Tyre || testId() != QLatin1String("steady-state")) return;
  const auto* slip = rt::findQuantity(s.results, "slip");
  const auto* camber = rt::findQuantity(s.results, "camber");
  const auto* fy = rt::findQuantity(s.results, "lateral_force");
  if (!slip || !camber || !fy) return;
  // The slip sweep runs at zero camber, the camber sweep at zero side-slip.
  const bool slipSweep = QString::fromStdString(s.label).startsWith(QLatin1String("slip"));
  if (slipSweep)
    xyData_.append(QPointF(slip->value * 180.0 / kPi, fy->value));
  else
    xySecondData_.append(QPointF(camber->value * 180.0 / kPi, fy->value));
  dirty_ = true;
}

void RigTestPage::clearAxisPlot() {
  inclinationData_.clear();
  armData_.clear();
  inclinationSigma_.clear();
  armSigma_.clear();
  if (!inclination_) return;
  inclination_->setSamples(QVector<QPointF>());
  arm_->setSamples(QVector<QPointF>());
  inclinationBars_->setSamples(QVector<QwtIntervalSample>());
  armBars_->setSamples(QVector<QwtIntervalSample>());
}

void RigTestPage::addAxisPoint(const std::vector<rt::Quantity>& results) {
  const auto* f = rt::findQuantity(results, "frequency");
  const auto* beta = rt::findQuantity(results, "axis_inclination");
  const auto* arm = rt::findQuantity(results, "a_tw");
  if (!f) return;
  // As stored (rad, m), shown in degrees and millimetres.
  if (beta) {
    inclinationData_.append(QPointF(f->value, beta->value * 180.0 / kPi));
    inclinationSigma_.append(QPointF(f->value, beta->uncertainty * 180.0 / kPi));
  }
  if (arm) {
    armData_.append(QPointF(f->value, arm->value * 1e3));
    armSigma_.append(QPointF(f->value, arm->uncertainty * 1e3));
  }
  auto bars = [](const QVector<QPointF>& data, const QVector<QPointF>& sigma) {
    QVector<QwtIntervalSample> out;
    for (int i = 0; i < data.size() && i < sigma.size(); ++i)
      out.append(QwtIntervalSample(data[i].x(), data[i].y() - sigma[i].y(), data[i].y() + sigma[i].y()));
    return out;
  };
  inclination_->setSamples(inclinationData_);
  arm_->setSamples(armData_);
  inclinationBars_->setSamples(bars(inclinationData_, inclinationSigma_));
  armBars_->setSamples(bars(armData_, armSigma_));
  // The loop the sine fits of this frequency describe, over the measured one.
  const auto* force = rt::findQuantity(results, "force_amplitude");
  const auto phasors = rt::laserPhasorsOf(results, laserPoints_.size());
  if (force && phasors) {
    std::vector<core::Vector2> lasers;
    for (const auto& [u, v] : laserPoints_) lasers.emplace_back(u, v);
    auto loop = rt::fittedSineLoop(lasers, core::Vector2(loadPoint_.first, loadPoint_.second), force->value, *phasors);
    QVector<QPointF> samples;
    if (loop)
      for (const auto& p : *loop) samples.append(QPointF(p.x() * 1e3, p.y()));
    sineFit_->setSamples(samples);
  }
  dirty_ = true;
}

void RigTestPage::replot() {
  timeLeft_->setSamples(timeLeftData_);
  timeRight_->setSamples(timeRightData_);
  xyLive_->setSamples(xyData_);
  xySecond_->setSamples(xySecondData_);
  livePlot_->replot();
  resultPlot_->replot();
  axisPlot_->replot();
  dirty_ = false;
  if (isRunning()) {
    ++redraws_;
    const qint64 now = clock_.elapsed();
    if (firstRedrawMs_ < 0) firstRedrawMs_ = now;
    lastRedrawMs_ = now;
  }
}

double RigTestPage::redrawRateHz() const {
  if (redraws_ < 2 || lastRedrawMs_ <= firstRedrawMs_) return 0.0;
  return (redraws_ - 1) * 1000.0 / static_cast<double>(lastRedrawMs_ - firstRedrawMs_);
}

void RigTestPage::showStoredTest(qint64 id) {
  core::io::ProjectStore* store = model_->store();
  if (!store) return;
  struct Row {
    std::optional<int> step;
    std::string key;
    double value, uncertainty;
    std::string unit;
  };
  std::vector<Row> rows;
  std::vector<core::io::StoredTyreTest::Point> storedPoints;
  double tyreLoadN = 0.0, tyrePressurePa = 0.0;
  std::string parametersJson, name, note;
  core::io::TestStatus status = core::io::TestStatus::Complete;
  if (rig_ == Rig::Stiffness) {
    auto t = store->rigTest(id);
    if (!t) {
      setStatus(tr("Cannot read the rig test: %1").arg(qs(t.error().describe())), true);
      return;
    }
    for (const auto& r : t->results) rows.push_back({r.step, r.quantity, r.value, r.uncertainty, r.unit});
    parametersJson = t->parametersJson;
    name = t->name;
    status = t->status;
    note = t->statusNote;
  } else {
    auto t = store->tyreTest(id);
    if (!t) {
      setStatus(tr("Cannot read the tyre test: %1").arg(qs(t.error().describe())), true);
      return;
    }
    for (const auto& r : t->parameters) rows.push_back({r.step, r.name, r.value, r.uncertainty, r.unit});
    storedPoints = t->points;
    tyreLoadN = t->verticalLoadN;
    tyrePressurePa = t->inflationPressurePa;
    parametersJson = t->parametersJson;
    name = t->name;
    status = t->status;
    note = t->statusNote;
  }
  // Step labels from the plan the sequence stored ("steps": [{"label": ...}]).
  std::vector<QString> labels;
  const auto plan = nlohmann::json::parse(parametersJson, nullptr, false);
  // A test opened from the project tree: its kind's plots, its stored points.
  if (!isRunning() && plan.is_object() && plan.contains("test") && plan["test"].is_string()) {
    const QString kind = qs(plan["test"].get<std::string>());
    if (kind != testId()) selectTest(kind);
  }
  if (!isRunning() && rig_ == Rig::Tyre && testId() == QLatin1String("steady-state") && xyData_.isEmpty() &&
      xySecondData_.isEmpty()) {
    // Each point to its sweep by the plan's step of the same set-point (the
    // point at zero slip and zero camber is in both sweeps, once each); a
    // plan without steps: the slip sweep runs at zero camber.
    struct PlanStep {
      double slip, camber;
      bool slipSweep, used;
    };
    std::vector<PlanStep> planSteps;
    if (plan.is_object() && plan.contains("steps") && plan["steps"].is_array())
      for (const auto& st : plan["steps"])
        if (st.is_object() && st.value("slip_rad", nlohmann::json()).is_number() &&
            st.value("camber_rad", nlohmann::json()).is_number() && st.value("label", nlohmann::json()).is_string())
          planSteps.push_back({st["slip_rad"].get<double>(), st["camber_rad"].get<double>(),
                               st["label"].get<std::string>().rfind("slip", 0) == 0, false});
    for (const auto& p : storedPoints) {
      bool slipSweep = p.camberRad == 0.0;
      for (auto& st : planSteps)
        if (!st.used && std::abs(st.slip - p.slipAngleRad) <= 1e-12 && std::abs(st.camber - p.camberRad) <= 1e-12) {
          st.used = true;
          slipSweep = st.slipSweep;
          break;
        }
      if (slipSweep)
        xyData_.append(QPointF(p.slipAngleRad * 180.0 / kPi, p.lateralForceN));
      else
        xySecondData_.append(QPointF(p.camberRad * 180.0 / kPi, p.lateralForceN));
    }
  }
  if (plan.is_object() && plan.contains("steps") && plan["steps"].is_array())
    for (const auto& st : plan["steps"])
      labels.push_back(st.is_object() && st.contains("label") && st["label"].is_string()
                           ? qs(st["label"].get<std::string>())
                           : QString());
  std::stable_sort(rows.begin(), rows.end(),
                   [](const Row& a, const Row& b) { return a.step.value_or(-1) < b.step.value_or(-1); });
  results_->setRowCount(static_cast<int>(rows.size()));
  const std::string headlineKeys[] = {
      "k_lat", "k_tw", "axis_inclination", "relaxation_length_m", "cornering_stiffness", "camber_stiffness"};
  QStringList headline, stepHeadline;
  for (int i = 0; i < static_cast<int>(rows.size()); ++i) {
    const Row& r = rows[static_cast<std::size_t>(i)];
    const auto s = shown(r.value, r.uncertainty, r.unit);
    QString step = tr("whole test");
    if (r.step) {
      const auto k = static_cast<std::size_t>(*r.step);
      step = k < labels.size() && !labels[k].isEmpty() ? QStringLiteral("%1: %2").arg(*r.step).arg(labels[k])
                                                       : QString::number(*r.step);
    }
    const QString items[] = {step, resultLabel(r.key), number(s.value),
                             r.uncertainty > 0 ? number(s.uncertainty) : QStringLiteral("-"), s.unit};
    for (int c = 0; c < 5; ++c) {
      auto* item = new QTableWidgetItem(items[c]);
      if (c == 2 || c == 3) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      item->setData(Qt::UserRole, qs(r.key));
      item->setToolTip(items[c]);  // a long quantity's name is elided in its column
      results_->setItem(i, c, item);
    }
    if (!r.step)
      for (const auto& k : headlineKeys)
        if (r.key == k)
          headline << QStringLiteral("%1 = %2 ± %3 %4")
                          .arg(resultLabel(r.key), number(s.value), number(s.uncertainty), s.unit);
    if (r.step && r.key == "k_lat")  // a sine sweep: the dynamic stiffness per frequency
      stepHeadline << QStringLiteral("%1: %2 = %3 ± %4 %5")
                          .arg(step, resultLabel(r.key), number(s.value), number(s.uncertainty), s.unit);
  }
  results_->resizeColumnsToContents();
  results_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
  QString word;
  switch (status) {
    case core::io::TestStatus::Running: word = tr("running"); break;
    case core::io::TestStatus::Complete: word = tr("complete"); break;
    case core::io::TestStatus::Interrupted: word = tr("interrupted"); break;
    case core::io::TestStatus::Failed: word = tr("failed"); break;
  }
  QString head = tr("'%1' (%2)").arg(qs(name), word);
  headline_->setToolTip(qs(note));  // the status line shows it too
  if (headline.isEmpty()) headline = stepHeadline.mid(0, 4);
  if (!headline.isEmpty()) head += QStringLiteral("\n") + headline.join(QStringLiteral("\n"));
  headline_->setText(head);

  // The stored stiffness over what was measured (plots show what the numbers say).
  auto find = [&](const char* key) -> const Row* {
    for (const auto& r : rows)
      if (!r.step && r.key == key) return &r;
    return nullptr;
  };
  fitLine_->setSamples(QVector<QPointF>());
  fitLine2_->setSamples(QVector<QPointF>());
  if (rig_ == Rig::Stiffness && testId() == QLatin1String("dynamic")) {
    // The dynamic twist axis of every stored frequency, and the sine-fit
    // loop of the last one, from what the project holds.
    clearAxisPlot();
    sineFit_->setSamples(QVector<QPointF>());
    auto view = rt::readStiffnessTest(*store, id);
    if (view) {
      laserPoints_.clear();
      for (const auto& p : view->laserPoints) laserPoints_.emplace_back(p.x(), p.y());
      loadPoint_ = {view->loadPoint.x(), view->loadPoint.y()};
      for (const auto& st : view->steps) {
        std::vector<rt::Quantity> results;
        for (const auto& [key, q] : st.results)
          results.push_back(rt::Quantity{key, "", q.value, q.unit, q.uncertainty});
        addAxisPoint(results);
      }
    } else {
      setStatus(tr("Cannot read the rig test's twist axes: %1").arg(qs(view.error().describe())), true);
    }
  }
  if (rig_ == Rig::Stiffness) {
    if (const Row* k = find("k_lat"); k && !xyData_.isEmpty() && testId() == QLatin1String("static")) {
      double lo = xyData_.first().x(), hi = lo;
      for (const auto& p : xyData_) {
        lo = std::min(lo, p.x());
        hi = std::max(hi, p.x());
      }
      fitLine_->setSamples(QVector<QPointF>{{lo, k->value * lo * 1e-3}, {hi, k->value * hi * 1e-3}});
    }
  } else if (testId() == QLatin1String("steady-state")) {
    // Over the window the sequence fits the slope in (SteadyStateSettings).
    auto line = [](QwtPlotCurve* c, const QVector<QPointF>& data, double slopePerRad, double windowDeg) {
      if (data.isEmpty()) return;
      double lo = 0, hi = 0;
      for (const auto& p : data) {
        lo = std::min(lo, std::max(p.x(), -windowDeg));
        hi = std::max(hi, std::min(p.x(), windowDeg));
      }
      c->setSamples(QVector<QPointF>{{lo, slopePerRad * lo * kPi / 180.0}, {hi, slopePerRad * hi * kPi / 180.0}});
    };
    const rt::SteadyStateSettings defaults;
    if (const Row* c = find("cornering_stiffness")) line(fitLine_, xyData_, c->value, defaults.slipWindowDeg);
    if (const Row* c = find("camber_stiffness")) line(fitLine2_, xySecondData_, c->value, defaults.camberWindowDeg);
    // The stored Magic Formula over each sweep: the fitted coefficients, the
    // held ones at the values the fit started from (its defaults), at the
    // test's load and pressure (core/tire/magic_formula.h).
    mfSlip_->setSamples(QVector<QPointF>());
    mfCamber_->setSamples(QVector<QPointF>());
    core::tire::MfLateralCoefficients mf = core::tire::mfLateralDefaults();
    bool fitted = false;
    const auto& names = core::tire::mfLateralNames();
    for (std::size_t i = 0; i < names.size(); ++i)
      if (const Row* r = find(("mf_" + names[i]).c_str())) {
        mf[i] = r->value;
        fitted = true;
      }
    if (fitted && tyreLoadN > 0.0 && tyrePressurePa > 0.0) {
      const core::tire::MfConstants constants{tyreLoadN, tyrePressurePa, 0.3};  // R0 enters M_z only
      auto curve = [&](QwtPlotCurve* c, const QVector<QPointF>& data, bool slip) {
        if (data.size() < 2) return;
        double lo = data.first().x(), hi = lo;
        for (const auto& p : data) {
          lo = std::min(lo, p.x());
          hi = std::max(hi, p.x());
        }
        QVector<QPointF> samples;
        constexpr int kSamples = 200;
        for (int k = 0; k <= kSamples; ++k) {
          const double deg = lo + (hi - lo) * k / kSamples, rad = deg * kPi / 180.0;
          samples.append(QPointF(deg, core::tire::mfLateralForce(mf, constants, slip ? rad : 0.0, slip ? 0.0 : rad,
                                                                 tyreLoadN, tyrePressurePa)));
        }
        c->setSamples(samples);
      };
      curve(mfSlip_, xyData_, true);
      curve(mfCamber_, xySecondData_, false);
    }
  }
  lastTestId_ = id;
  replot();
}

}  // namespace views
}  // namespace mozzi
