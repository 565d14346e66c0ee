#include "views/stability/stability_page.h"

#include <qwt_legend.h>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_marker.h>
#include <qwt_symbol.h>
#include <qwt_text.h>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMap>
#include <QPushButton>
#include <QVBoxLayout>
#include <algorithm>
#include <limits>

#include "core/common/text.h"
#include "core/stability/benchmark_bicycle.h"
#include "core/stability/compliant_fork_bicycle.h"
#include "core/stability/motorcycle.h"
#include "views/common/job_runner.h"
#include "views/common/kept_analyses.h"
#include "views/common/project_model.h"
#include "views/plots/interactive_plot.h"

namespace mozzi {
namespace views {

namespace st = core::stability;

namespace {

// One colour per mode name, the same on both plots.
QColor modeColour(const std::string& name) {
  static const QMap<QString, QColor> known{
      {QStringLiteral("weave"), QColor(31, 119, 180)},       {QStringLiteral("capsize"), QColor(214, 39, 40)},
      {QStringLiteral("castering"), QColor(44, 160, 44)},    {QStringLiteral("fork bending"), QColor(148, 103, 189)},
      {QStringLiteral("fork torsion"), QColor(140, 86, 75)}, {QStringLiteral("wobble"), QColor(255, 127, 14)},
      {QStringLiteral("tyre lag"), QColor(23, 190, 207)}};
  return known.value(QString::fromStdString(name), QColor(127, 127, 127));
}

using Model = StabilityPage::Model;

// The width a combo box asks for, in characters (its entries are longer).
constexpr int kComboMinChars = 22;

// The fork of each Model entry, as core::stability::StabilityRequest names it.
const char* const kForks[] = {"rigid", "bending", "torsion", "rigid", "model 1", "model 2", "model 3"};

// The workbench's plot (grid, cursor, zoom, pan, export).
InteractivePlot* makePlot(QWidget* parent, const char* objectName) {
  auto* plot = new InteractivePlot(parent);
  plot->setObjectName(QString::fromLatin1(objectName));
  return plot;
}

}  // namespace

// The record and its result_json, serialised on the job runner's thread.
struct StabilityPage::Sweeps {
  st::StabilityRecord record;
  std::string json;
};

StabilityPage::StabilityPage(QWidget* parent, JobRunner* jobs) : QWidget(parent), jobs_(jobs) {
  modelLabel_ = new QLabel(this);
  model_ = new QComboBox(this);
  model_->setObjectName(QStringLiteral("stabilityModel"));
  for (int i = 0; i < 7; ++i) model_->addItem(QString());
  // Combo boxes as wide as the row gives them, not as their longest entry
  // (a kept fork's name, a model's reference): the page fits 1280x800 with
  // the project dock open; the full text is in the drop-down list.
  model_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  model_->setMinimumContentsLength(kComboMinChars);
  forkLabel_ = new QLabel(this);
  fork_ = new QComboBox(this);
  fork_->setObjectName(QStringLiteral("stabilityFork"));
  fork_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  fork_->setMinimumContentsLength(kComboMinChars);
  compare_ = new QCheckBox(this);
  compare_->setObjectName(QStringLiteral("stabilityCompareRigid"));
  paramsLabel_ = new QLabel(this);
  paramsFile_ = new QLabel(this);  // a long file name wraps rather than widen the page
  paramsFile_->setWordWrap(true);
  paramsFile_->setObjectName(QStringLiteral("stabilityParameterFile"));
  paramsFile_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  paramsButton_ = new QPushButton(this);
  paramsButton_->setObjectName(QStringLiteral("stabilityChooseParameters"));
  paramsClear_ = new QPushButton(this);
  paramsClear_->setObjectName(QStringLiteral("stabilityBuiltInParameters"));
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
  storedLabel_ = new QLabel(this);
  stored_ = new QComboBox(this);
  stored_->setObjectName(QStringLiteral("stabilityStored"));
  stored_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  stored_->setMinimumContentsLength(kComboMinChars);
  showStored_ = new QPushButton(this);
  showStored_->setObjectName(QStringLiteral("stabilityShowStored"));
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
  auto* params = new QHBoxLayout;
  params->addWidget(paramsLabel_);
  params->addWidget(paramsFile_, 1);
  params->addWidget(paramsButton_);
  params->addWidget(paramsClear_);
  auto* forkRow = new QHBoxLayout;  // the fork on a row of its own: one row was wider than the tab area
  forkRow->addWidget(forkLabel_);
  forkRow->addWidget(fork_, 1);
  forkRow->addWidget(compare_);
  auto* kept = new QHBoxLayout;
  kept->addWidget(storedLabel_);
  kept->addWidget(stored_, 1);
  kept->addWidget(showStored_);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(bar);
  layout->addLayout(params);
  layout->addLayout(forkRow);
  layout->addLayout(kept);
  layout->addWidget(summary_);
  layout->addWidget(real_, 3);  // the sign of the real part is the verdict: the larger plot
  layout->addWidget(imaginary_, 2);
  connect(runButton_, &QPushButton::clicked, this, &StabilityPage::run);
  connect(model_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int) { modelChanged(); });
  connect(paramsButton_, &QPushButton::clicked, this, &StabilityPage::chooseParameterFile);
  connect(paramsClear_, &QPushButton::clicked, this, [this] { setParameterFile(QString()); });
  connect(showStored_, &QPushButton::clicked, this, [this] {
    if (stored_->count() > 0) showStored(stored_->currentData().toLongLong());
  });
  retranslate();
  refreshStored();
  modelChanged();
}

// The bicycle and the motorcycle have their own speed ranges (the tyre lag
// of the motorcycle divides by the speed: from 1 m/s).
void StabilityPage::modelChanged() {
  const Model model = static_cast<Model>(model_->currentIndex());
  compare_->setEnabled(hasCompliantFork(model));
  refreshForks();
  setParameterFile(parameterFile_);
  if (isMotorcycle(model) != isMotorcycle(shownFamily_)) {
    if (isMotorcycle(model))
      setSpeedRange(1.0, 60.0, 0.25);
    else
      setSpeedRange(0.0, 10.0, 0.05);
  }
  shownFamily_ = model;
}

void StabilityPage::setParameterFile(const QString& path) {
  parameterFile_ = path;
  const bool motorcycle = isMotorcycle(static_cast<Model>(model_->currentIndex()));
  paramsFile_->setText(path.isEmpty() ? (motorcycle ? tr("built-in (Sharp 1971 standard machine)")
                                                    : tr("built-in (benchmark bicycle, Meijaard et al. 2007)"))
                                      : QFileInfo(path).fileName());
  paramsFile_->setToolTip(path);
  paramsClear_->setEnabled(!path.isEmpty());
}

void StabilityPage::chooseParameterFile() {
  const QString path =
      QFileDialog::getOpenFileName(this, tr("Vehicle parameter file"), QFileInfo(parameterFile_).path(),
                                   tr("Parameter files (*.csv);;All files (*)"));
  if (!path.isEmpty()) setParameterFile(path);
}

void StabilityPage::setProjectModel(ProjectModel* model) {
  project_ = model;
  if (project_) {
    connect(project_, &ProjectModel::analysesChanged, this, &StabilityPage::refreshForks);
    connect(project_, &ProjectModel::projectChanged, this, &StabilityPage::refreshForks);
    connect(project_, &ProjectModel::analysesChanged, this, &StabilityPage::refreshStored);
    connect(project_, &ProjectModel::projectChanged, this, &StabilityPage::refreshStored);
  }
  refreshForks();
  refreshStored();
}

// The Fork choice: the thesis's fork, then the project's kept forks of the
// shown vehicle (motorcycle or bicycle); item data = 1 + index in kept_.
void StabilityPage::refreshForks() {
  kept_.clear();
  if (project_ && project_->store()) {
    if (auto forks = st::keptForks(*project_->store())) kept_ = std::move(*forks);
  }
  const Model model = static_cast<Model>(model_->currentIndex());
  const int previous = fork_->currentData().toInt();
  const QSignalBlocker block(fork_);
  fork_->clear();
  fork_->addItem(isMotorcycle(model) ? tr("thesis (Table 12)") : tr("thesis steel fork (§6.4, §6.5)"), 0);
  for (std::size_t i = 0; i < kept_.size(); ++i)
    if (kept_[i].motorcycle == isMotorcycle(model))
      fork_->addItem(tr("kept: %1 (analysis %2)").arg(QString::fromStdString(kept_[i].name)).arg(kept_[i].analysisId),
                     static_cast<int>(i + 1));
  const int at = fork_->findData(previous);
  fork_->setCurrentIndex(at >= 0 ? at : 0);
  fork_->setEnabled(hasCompliantFork(model) && fork_->count() > 1);
}

bool StabilityPage::setForkChoice(int index) {
  if (index < 0 || index >= fork_->count()) return false;
  fork_->setCurrentIndex(index);
  return true;
}

int StabilityPage::forkChoiceCount() const {
  return fork_->count();
}

void StabilityPage::setCompareRigid(bool on) {
  compare_->setChecked(on);
}

void StabilityPage::setModel(Model model) {
  model_->setCurrentIndex(static_cast<int>(model));
}

void StabilityPage::setSpeedRange(double fromMps, double toMps, double stepMps) {
  from_->setValue(fromMps);
  to_->setValue(toMps);
  step_->setValue(stepMps);
}

st::StabilityRequest StabilityPage::request() const {
  const Model model = static_cast<Model>(model_->currentIndex());
  st::StabilityRequest r;
  r.vehicle = isMotorcycle(model) ? "motorcycle" : "bicycle";
  r.fork = kForks[static_cast<int>(model)];
  r.parametersFile = parameterFile_.toStdString();
  r.from = from_->value();
  r.to = to_->value();
  r.step = step_->value();
  r.compareRigid = compare_->isChecked() && hasCompliantFork(model);
  const int keptIndex = fork_->currentData().toInt();
  if (keptIndex > 0 && hasCompliantFork(model)) r.kept = kept_.at(static_cast<std::size_t>(keptIndex - 1));
  return r;
}

void StabilityPage::run() {
  start(true);
}

void StabilityPage::openShowing() {
  const auto ids = storedResults();
  if (ids.empty() || !showStored(ids.back())) start(false);
}

void StabilityPage::start(bool keepResult) {
  if (auto speeds = st::speedGrid(from_->value(), to_->value(), step_->value()); !speeds) {
    present(speeds.error(), true);
    return;
  }
  runButton_->setEnabled(false);
  summary_->setText(tr("Computing the eigenvalues against speed..."));
  const bool keep = keepResult && project_ && project_->store();
  auto work = [request = request(), keep](JobProgress&) -> core::Result<Sweeps> {
    auto record = st::computeStabilityRecord(request);
    if (!record) return record.error();
    Sweeps out{std::move(*record), {}};
    if (keep) out.json = st::stabilityRecordJson(out.record);
    return out;
  };
  if (!jobs_) {
    JobProgress progress;
    present(work(progress), keep);
    return;
  }
  jobs_->run<Sweeps>(this, tr("Stability against speed"), work,
                     [this, keep](core::Result<Sweeps> result) { present(std::move(result), keep); });
}

// Keeps the sweep as an analysis of kind "stability" under the kept fork's
// specimen or the vehicle's default one (core/stability/stability_record.h).
QString StabilityPage::keep(const Sweeps& sweeps) {
  lastStoredId_ = 0;
  if (!project_ || !project_->store()) return {};
  const st::StabilityRequest r = request();
  auto specimen = r.kept ? core::Result<std::int64_t>(r.kept->specimenId)
                         : st::defaultStabilitySpecimen(*project_->store(), sweeps.record.vehicle);
  if (!specimen) return tr("Not kept: %1").arg(QString::fromStdString(specimen.error().describe()));
  auto name = st::freeAnalysisName(*project_->store(), *specimen, sweeps.record.model);
  if (!name) return tr("Not kept: %1").arg(QString::fromStdString(name.error().describe()));
  core::io::StoredAnalysis a;
  a.specimenId = *specimen;
  a.kind = st::kStabilityAnalysisKind;
  a.name = *name;
  a.resultJson = sweeps.json.empty() ? st::stabilityRecordJson(sweeps.record) : sweeps.json;
  auto id = project_->addAnalysis(a);
  if (!id) return tr("Not kept: %1").arg(QString::fromStdString(id.error().describe()));
  lastStoredId_ = *id;
  return tr("Kept in the project as analysis %1.").arg(*id);
}

void StabilityPage::refreshStored() {
  showStored_->setEnabled(fillKeptAnalyses(stored_, project_, st::kStabilityAnalysisKind) > 0);
}

std::vector<qint64> StabilityPage::storedResults() const {
  return keptAnalysisIds(stored_);
}

bool StabilityPage::showStored(qint64 analysisId) {
  if (!project_ || !project_->store()) return false;
  auto stored = st::storedStabilityRecord(*project_->store(), analysisId);
  if (!stored) {
    present(stored.error(), false, true);
    return false;
  }
  const int at = stored_->findData(QVariant::fromValue<qint64>(analysisId));
  if (at >= 0) stored_->setCurrentIndex(at);
  showRecord(std::move(stored->record));
  return true;
}

void StabilityPage::showRecord(st::StabilityRecord record) {
  // The controls say what the record is: its vehicle and fork, its speeds
  // and parameter file (a kept fork's choice stays as it is).
  for (int m = 0; m < 7; ++m)
    if (isMotorcycle(static_cast<Model>(m)) == (record.vehicle == "motorcycle") && record.fork == kForks[m]) {
      setModel(static_cast<Model>(m));
      break;
    }
  if (record.step > 0.0) setSpeedRange(record.from, record.to, record.step);
  setParameterFile(QString::fromStdString(record.parametersFile));
  compare_->setChecked(record.rigidSweep.has_value());
  present(Sweeps{std::move(record), {}}, false, true);
}

std::optional<st::StabilityRecord> StabilityPage::record() const {
  if (!record_ || !sweep_) return std::nullopt;
  st::StabilityRecord r = *record_;
  r.sweep = *sweep_;
  r.rigidSweep = rigidSweep_;
  return r;
}

void StabilityPage::present(core::Result<Sweeps> result, bool keepIt, bool fromStore) {
  runButton_->setEnabled(true);
  for (QwtPlot* plot : {real_, imaginary_}) plot->detachItems(QwtPlotItem::Rtti_PlotCurve, true);
  for (QwtPlotMarker* m : markers_) {  // ours only: the plots' cursors stay
    m->detach();
    delete m;
  }
  markers_.clear();
  if (!result) {
    record_.reset();
    sweep_.reset();
    rigidSweep_.reset();
    summary_->setText(tr("Cannot compute: %1").arg(QString::fromStdString(result.error().describe())));
    real_->replot();
    imaginary_->replot();
    emit finished(false);
    return;
  }
  const QString kept = keepIt ? keep(*result) : QString();
  // The sweeps moved, not copied (10,000 speeds redraw within a frame); the
  // rest of the record kept beside them.
  sweep_ = std::move(result->record.sweep);
  rigidSweep_ = std::move(result->record.rigidSweep);
  result->record.sweep = {};
  result->record.rigidSweep.reset();
  record_ = std::move(result->record);
  auto* zero = new QwtPlotMarker;
  zero->setLineStyle(QwtPlotMarker::HLine);
  zero->setYValue(0.0);
  zero->setLinePen(QColor(0, 0, 0), 1.0);
  zero->attach(real_);
  markers_.push_back(zero);
  QStringList lines, rigidLines;
  // Re from -15 1/s up: the question is the sign near zero; castering and
  // the fork modes reach far below and would flatten the weave and capsize.
  double reMax = std::max(1.0, drawSweep(*sweep_, false, lines));
  if (rigidSweep_) reMax = std::max(reMax, drawSweep(*rigidSweep_, true, rigidLines));
  for (QwtPlotItem* item : imaginary_->itemList(QwtPlotItem::Rtti_PlotCurve))
    item->setItemAttribute(QwtPlotItem::Legend, false);
  real_->setAxisScale(QwtPlot::yLeft, -15.0, std::min(reMax * 1.1, 15.0));
  real_->setAxisScale(QwtPlot::xBottom, sweep_->points.front().v, sweep_->points.back().v);
  imaginary_->setAxisScale(QwtPlot::xBottom, sweep_->points.front().v, sweep_->points.back().v);
  QString text = lines.isEmpty() ? tr("No real part crosses zero in this speed range.")
                                 : tr("Critical speeds: %1").arg(lines.join(QStringLiteral("; ")));
  if (rigidSweep_)
    text +=
        QStringLiteral(". ") + (rigidLines.isEmpty() ? tr("Rigid fork: no real part crosses zero.")
                                                     : tr("Rigid fork: %1").arg(rigidLines.join(QStringLiteral("; "))));
  if (fromStore) text = tr("Stored: %1. %2").arg(QString::fromStdString(record_->model), text);
  if (!kept.isEmpty()) text += QLatin1Char(' ') + kept;
  summary_->setText(text);
  alignLeftAxes({real_, imaginary_});  // one speed axis: the canvases line up
  real_->replot();
  imaginary_->replot();
  emit finished(true);
}

// One sweep's curves and critical-speed markers. The rigid-fork sweep of a
// comparison: open symbols, dotted markers, names "... (rigid fork)".
double StabilityPage::drawSweep(const st::StabilitySweep& sweep, bool rigid, QStringList& lines) {
  // One curve per mode name and plot: points (the tracks cross and pair up,
  // so lines between named samples would join different roots). Grouped by
  // the name as core spells it, the QString made once per track: 10,000
  // speeds of a dozen roots redraw within a frame.
  struct Track {
    const std::string* name;
    QVector<QPointF> re, im;
  };
  std::vector<Track> tracks;
  double reMax = -std::numeric_limits<double>::infinity();
  for (const auto& point : sweep.points)
    for (size_t k = 0; k < point.roots.size(); ++k) {
      const auto& root = point.roots[k];
      // Roots keep their order from speed to speed: the k-th track is the first guess.
      size_t t = k < tracks.size() && *tracks[k].name == root.name ? k : 0;
      while (t < tracks.size() && *tracks[t].name != root.name) ++t;
      if (t == tracks.size()) {
        tracks.push_back({&root.name, {}, {}});
        tracks.back().re.reserve(static_cast<int>(sweep.points.size()));
      }
      tracks[t].re.append(QPointF(point.v, root.lambda.real()));
      if (root.lambda.imag() > 0.0) tracks[t].im.append(QPointF(point.v, root.lambda.imag()));
      reMax = std::max(reMax, root.lambda.real());
    }
  QMap<QString, const Track*> byName;  // the legend in alphabetical order, as before
  for (const Track& t : tracks) byName.insert(QString::fromStdString(*t.name), &t);
  auto addCurves = [this, rigid, &byName](QwtPlot* plot, QVector<QPointF> Track::*samples) {
    for (auto it = byName.begin(); it != byName.end(); ++it) {
      if ((it.value()->*samples).isEmpty()) continue;
      auto* c = new QwtPlotCurve(rigid ? tr("%1 (rigid fork)").arg(it.key()) : it.key());
      const QColor colour = modeColour(*it.value()->name);
      c->setStyle(QwtPlotCurve::NoCurve);
      // Points on the same pixel drawn once: 10,000 speeds redraw within a frame.
      c->setPaintAttribute(QwtPlotCurve::FilterPoints, true);
      c->setSymbol(rigid ? new QwtSymbol(QwtSymbol::Ellipse, QBrush(Qt::NoBrush), QPen(colour, 1.0), QSize(6, 6))
                         : new QwtSymbol(QwtSymbol::Ellipse, QBrush(colour), QPen(colour), QSize(4, 4)));
      c->setSamples(it.value()->*samples);
      c->setLegendAttribute(QwtPlotCurve::LegendShowSymbol, true);
      c->setZ(rigid ? 19 : 20);  // the compliant fork's points over the rigid one's
      c->attach(plot);
    }
  };
  addCurves(real_, &Track::re);
  addCurves(imaginary_, &Track::im);
  for (const auto& e : sweep.events) {
    if (e.kind != "stabilises" && e.kind != "destabilises") continue;
    const QString text = tr("%1 %2 at %3 m/s")
                             .arg(QString::fromStdString(e.mode), QString::fromStdString(e.kind))
                             .arg(QString::fromStdString(core::formatNumber(e.v, 5)));
    lines << text;
    for (QwtPlot* plot : {real_, imaginary_}) {
      auto* m = new QwtPlotMarker;
      m->setLineStyle(QwtPlotMarker::VLine);
      m->setXValue(e.v);
      m->setLinePen(modeColour(e.mode), 1.0, rigid ? Qt::DotLine : Qt::DashLine);
      if (plot == real_) {
        // The rigid fork's speeds are listed above the plots; on the canvas
        // only the number, mid-height, so both sets of labels stay readable.
        const QString speed = QString::fromStdString(core::formatNumber(e.v, 5));
        QwtText label(rigid ? tr("rigid: %1").arg(speed) : tr("%1 %2 m/s").arg(QString::fromStdString(e.mode), speed));
        label.setColor(modeColour(e.mode));
        m->setLabel(label);
        // Near the right end the label goes left of its line; close speeds
        // alternate top and bottom so their labels keep apart.
        const double span = sweep.points.back().v - sweep.points.front().v;
        const bool nearEnd = e.v > sweep.points.back().v - 0.2 * span;
        const Qt::Alignment vertical = rigid ? Qt::AlignVCenter : (lines.size() % 2 ? Qt::AlignTop : Qt::AlignBottom);
        m->setLabelAlignment((nearEnd ? Qt::AlignLeft : Qt::AlignRight) | vertical);
      }
      m->setTitle(rigid ? QStringLiteral("rigid") : QStringLiteral("compliant"));
      m->attach(plot);
      markers_.push_back(m);
    }
  }
  return reMax;
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
  model_->setItemText(3, tr("Motorcycle (Sharp 1971), rigid fork"));
  model_->setItemText(4, tr("Motorcycle, lumped fork model 1 (thesis Table 12)"));
  model_->setItemText(5, tr("Motorcycle, lumped fork model 2 (thesis Table 12)"));
  model_->setItemText(6, tr("Motorcycle, lumped fork model 3 (thesis Table 12)"));
  compare_->setText(tr("Compare with the rigid fork"));
  forkLabel_->setText(tr("Fork:"));
  fork_->setToolTip(tr("The thesis's fork, or one the project keeps (Lumped Fork page)"));
  refreshForks();
  compare_->setToolTip(tr("Sweep the same vehicle with a rigid fork too and draw it with open symbols"));
  paramsLabel_->setText(tr("Parameters:"));
  paramsButton_->setText(tr("From file..."));
  paramsButton_->setToolTip(
      tr("A bicycle (Meijaard et al. 2007) or motorcycle (Sharp 1971) parameter file, as "
         "mozzi-cli stability --params reads"));
  paramsClear_->setText(tr("Built-in"));
  setParameterFile(parameterFile_);
  speedsLabel_->setText(tr("Speeds from, to, step:"));
  runButton_->setText(tr("Compute"));
  storedLabel_->setText(tr("Kept results:"));
  stored_->setToolTip(tr("Stability sweeps the project keeps (this page, mozzi-cli stability --project)"));
  showStored_->setText(tr("Show"));
  real_->setTitle(tr("Real part of the eigenvalues"));
  real_->setAxisTitle(QwtPlot::xBottom, tr("Speed [m/s]"));
  real_->setAxisTitle(QwtPlot::yLeft, tr("Re λ [1/s]"));
  imaginary_->setTitle(tr("Imaginary part (oscillating modes)"));
  imaginary_->setAxisTitle(QwtPlot::xBottom, tr("Speed [m/s]"));
  imaginary_->setAxisTitle(QwtPlot::yLeft, tr("Im λ [rad/s]"));
}

}  // namespace views
}  // namespace mozzi
