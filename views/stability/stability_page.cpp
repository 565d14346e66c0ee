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

#include "core/common/text.h"
#include "core/stability/benchmark_bicycle.h"
#include "core/stability/compliant_fork_bicycle.h"
#include "core/stability/motorcycle.h"
#include "views/common/job_runner.h"
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

// The vehicle's system: the bicycle from the built-in or a file's parameters,
// the motorcycle from a file (Sharp 1971 format); rigid: the same vehicle
// with its fork rigid.
core::Result<st::StabilitySystem> systemOf(Model model, const std::string& file, bool rigid,
                                           const std::optional<st::KeptFork>& kept) {
  if (StabilityPage::isMotorcycle(model)) {
    if (file.empty())
      return core::makeError(core::ErrorCode::InvalidArgument,
                             "the motorcycle needs a parameter file (Sharp 1971 format, docs/cli/stability.md)",
                             "parameters");
    auto p = st::loadSharpParameters(file);
    if (!p) return p.error();
    std::optional<st::LumpedForkModel> fork;
    if (!rigid && model != Model::Motorcycle) {
      const int index = static_cast<int>(model) - static_cast<int>(Model::Motorcycle);  // 1 to 3
      if (kept) {
        const auto& m = kept->lumped.at(static_cast<std::size_t>(index - 1));
        if (!m)
          return core::makeError(core::ErrorCode::InvalidArgument,
                                 "the kept fork '" + kept->name + "' has no model " + std::to_string(index), "fork");
        fork = *m;
      } else {
        auto f = st::thesisLumpedForkModel(index);
        if (!f) return f.error();
        fork = *f;
      }
    }
    auto m = st::MotorcycleModel::build(*p, fork);
    if (!m) return m.error();
    return m->system();
  }
  st::BenchmarkParameters p = st::meijaard2007Parameters();
  if (!file.empty()) {
    auto loaded = st::loadBenchmarkParameters(file);
    if (!loaded) return loaded.error();
    p = *loaded;
  }
  if (rigid || model == Model::Benchmark) {
    auto m = st::benchmarkModel(p);
    if (!m) return m.error();
    return st::bicycleSystem(*m);
  }
  const char* missing = model == Model::ForkBending ? "bending" : "torsion";
  if (kept && ((model == Model::ForkBending && !kept->bending) || (model == Model::ForkTorsion && !kept->torsion)))
    return core::makeError(core::ErrorCode::InvalidArgument,
                           "the kept fork '" + kept->name + "' has no " + missing + " stiffness", "fork");
  auto m = model == Model::ForkBending ? st::forkBendingModel(p, kept ? *kept->bending : st::thesisSteelForkBending())
                                       : st::forkTorsionModel(p, kept ? *kept->torsion : st::thesisSteelForkTorsion());
  if (!m) return m.error();
  return st::bicycleSystem(*m);
}

core::Result<st::StabilitySweep> sweepOf(Model model, const std::string& file, bool rigid,
                                         const std::optional<st::KeptFork>& kept, const std::vector<double>& speeds) {
  auto system = systemOf(model, file, rigid, kept);
  if (!system) return system.error();
  return st::sweepSpeeds(*system, speeds);
}

// The workbench's plot (grid, cursor, zoom, pan, export).
InteractivePlot* makePlot(QWidget* parent, const char* objectName) {
  auto* plot = new InteractivePlot(parent);
  plot->setObjectName(QString::fromLatin1(objectName));
  return plot;
}

}  // namespace

struct StabilityPage::Sweeps {
  st::StabilitySweep main;
  std::optional<st::StabilitySweep> rigid;
};

StabilityPage::StabilityPage(QWidget* parent, JobRunner* jobs) : QWidget(parent), jobs_(jobs) {
  modelLabel_ = new QLabel(this);
  model_ = new QComboBox(this);
  model_->setObjectName(QStringLiteral("stabilityModel"));
  for (int i = 0; i < 7; ++i) model_->addItem(QString());
  forkLabel_ = new QLabel(this);
  fork_ = new QComboBox(this);
  fork_->setObjectName(QStringLiteral("stabilityFork"));
  fork_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  compare_ = new QCheckBox(this);
  compare_->setObjectName(QStringLiteral("stabilityCompareRigid"));
  paramsLabel_ = new QLabel(this);
  paramsFile_ = new QLabel(this);
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
  params->addWidget(forkLabel_);
  params->addWidget(fork_);
  params->addWidget(compare_);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(bar);
  layout->addLayout(params);
  layout->addWidget(summary_);
  layout->addWidget(real_, 1);
  layout->addWidget(imaginary_, 1);
  connect(runButton_, &QPushButton::clicked, this, &StabilityPage::run);
  connect(model_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int) { modelChanged(); });
  connect(paramsButton_, &QPushButton::clicked, this, &StabilityPage::chooseParameterFile);
  connect(paramsClear_, &QPushButton::clicked, this, [this] { setParameterFile(QString()); });
  retranslate();
  modelChanged();
}

// The bicycle and the motorcycle have their own speed ranges (the tyre lag
// of the motorcycle divides by the speed: from 1 m/s).
void StabilityPage::modelChanged() {
  const Model model = static_cast<Model>(model_->currentIndex());
  compare_->setEnabled(hasCompliantFork(model));
  refreshForks();
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
  paramsFile_->setText(path.isEmpty() ? tr("built-in (benchmark bicycle, Meijaard et al. 2007)")
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
  }
  refreshForks();
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

void StabilityPage::run() {
  auto speeds = st::speedGrid(from_->value(), to_->value(), step_->value());
  if (!speeds) {
    present(speeds.error());
    return;
  }
  const Model model = static_cast<Model>(model_->currentIndex());
  const bool compare = compare_->isChecked() && hasCompliantFork(model);
  const std::string file = parameterFile_.toStdString();
  std::optional<st::KeptFork> kept;
  const int keptIndex = fork_->currentData().toInt();
  if (keptIndex > 0 && hasCompliantFork(model)) kept = kept_.at(static_cast<std::size_t>(keptIndex - 1));
  runButton_->setEnabled(false);
  summary_->setText(tr("Computing the eigenvalues against speed..."));
  const std::vector<double> grid = *speeds;
  auto work = [model, compare, file, kept, grid](JobProgress&) -> core::Result<Sweeps> {
    auto main = sweepOf(model, file, false, kept, grid);
    if (!main) return main.error();
    Sweeps out{std::move(main).value(), std::nullopt};
    if (compare) {
      auto rigid = sweepOf(model, file, true, std::nullopt, grid);
      if (!rigid) return rigid.error();
      out.rigid = std::move(rigid).value();
    }
    return out;
  };
  if (!jobs_) {
    JobProgress progress;
    present(work(progress));
    return;
  }
  jobs_->run<Sweeps>(this, tr("Stability against speed"), work,
                     [this](core::Result<Sweeps> result) { present(std::move(result)); });
}

void StabilityPage::present(core::Result<Sweeps> result) {
  runButton_->setEnabled(true);
  for (QwtPlot* plot : {real_, imaginary_}) plot->detachItems(QwtPlotItem::Rtti_PlotCurve, true);
  for (QwtPlotMarker* m : markers_) {  // ours only: the plots' cursors stay
    m->detach();
    delete m;
  }
  markers_.clear();
  if (!result) {
    sweep_.reset();
    rigidSweep_.reset();
    summary_->setText(tr("Cannot compute: %1").arg(QString::fromStdString(result.error().describe())));
    real_->replot();
    imaginary_->replot();
    emit finished(false);
    return;
  }
  sweep_ = std::move(result->main);
  rigidSweep_ = std::move(result->rigid);
  auto* zero = new QwtPlotMarker;
  zero->setLineStyle(QwtPlotMarker::HLine);
  zero->setYValue(0.0);
  zero->setLinePen(QColor(0, 0, 0), 1.0);
  zero->attach(real_);
  markers_.push_back(zero);
  QStringList lines, rigidLines;
  drawSweep(*sweep_, false, lines);
  if (rigidSweep_) drawSweep(*rigidSweep_, true, rigidLines);
  for (QwtPlotItem* item : imaginary_->itemList(QwtPlotItem::Rtti_PlotCurve))
    item->setItemAttribute(QwtPlotItem::Legend, false);
  // Re from -15 1/s up: the question is the sign near zero; castering and
  // the fork modes reach far below and would flatten the weave and capsize.
  double reMax = 1.0;
  for (QwtPlotItem* item : real_->itemList(QwtPlotItem::Rtti_PlotCurve)) {
    const auto* c = static_cast<QwtPlotCurve*>(item);
    for (size_t i = 0; i < c->dataSize(); ++i) reMax = std::max(reMax, c->sample(static_cast<int>(i)).y());
  }
  real_->setAxisScale(QwtPlot::yLeft, -15.0, std::min(reMax * 1.1, 15.0));
  real_->setAxisScale(QwtPlot::xBottom, sweep_->points.front().v, sweep_->points.back().v);
  imaginary_->setAxisScale(QwtPlot::xBottom, sweep_->points.front().v, sweep_->points.back().v);
  QString text = lines.isEmpty() ? tr("No real part crosses zero in this speed range.")
                                 : tr("Critical speeds: %1").arg(lines.join(QStringLiteral("; ")));
  if (rigidSweep_)
    text +=
        QStringLiteral(". ") + (rigidLines.isEmpty() ? tr("Rigid fork: no real part crosses zero.")
                                                     : tr("Rigid fork: %1").arg(rigidLines.join(QStringLiteral("; "))));
  summary_->setText(text);
  alignLeftAxes({real_, imaginary_});  // one speed axis: the canvases line up
  real_->replot();
  imaginary_->replot();
  emit finished(true);
}

// One sweep's curves and critical-speed markers. The rigid-fork sweep of a
// comparison: open symbols, dotted markers, names "... (rigid fork)".
void StabilityPage::drawSweep(const st::StabilitySweep& sweep, bool rigid, QStringList& lines) {
  // One curve per mode name and plot: points (the tracks cross and pair up,
  // so lines between named samples would join different roots).
  QMap<QString, QVector<QPointF>> re, im;
  for (const auto& point : sweep.points)
    for (const auto& root : point.roots) {
      const QString name = QString::fromStdString(root.name);
      re[name].append(QPointF(point.v, root.lambda.real()));
      if (root.lambda.imag() > 0.0) im[name].append(QPointF(point.v, root.lambda.imag()));
    }
  auto addCurves = [this, rigid](QwtPlot* plot, const QMap<QString, QVector<QPointF>>& data) {
    for (auto it = data.begin(); it != data.end(); ++it) {
      auto* c = new QwtPlotCurve(rigid ? tr("%1 (rigid fork)").arg(it.key()) : it.key());
      const QColor colour = modeColour(it.key().toStdString());
      c->setStyle(QwtPlotCurve::NoCurve);
      c->setSymbol(rigid ? new QwtSymbol(QwtSymbol::Ellipse, QBrush(Qt::NoBrush), QPen(colour, 1.0), QSize(6, 6))
                         : new QwtSymbol(QwtSymbol::Ellipse, QBrush(colour), QPen(colour), QSize(4, 4)));
      c->setSamples(it.value());
      c->setLegendAttribute(QwtPlotCurve::LegendShowSymbol, true);
      c->setZ(rigid ? 19 : 20);  // the compliant fork's points over the rigid one's
      c->attach(plot);
    }
  };
  addCurves(real_, re);
  addCurves(imaginary_, im);
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
  real_->setTitle(tr("Real part of the eigenvalues"));
  real_->setAxisTitle(QwtPlot::xBottom, tr("Speed [m/s]"));
  real_->setAxisTitle(QwtPlot::yLeft, tr("Re λ [1/s]"));
  imaginary_->setTitle(tr("Imaginary part (oscillating modes)"));
  imaginary_->setAxisTitle(QwtPlot::xBottom, tr("Speed [m/s]"));
  imaginary_->setAxisTitle(QwtPlot::yLeft, tr("Im λ [rad/s]"));
}

}  // namespace views
}  // namespace mozzi
