#include "views/wheelchair/wheelchair_page.h"

#include <qwt_legend.h>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>
#include <cmath>

#include "core/common/text.h"
#include "views/common/job_runner.h"
#include "views/common/kept_analyses.h"
#include "views/common/project_model.h"
#include "views/panels/parameter_form.h"
#include "views/plots/interactive_plot.h"

namespace mozzi {
namespace views {

namespace st = core::stability;
using devices::ParameterMap;
using devices::ParameterSpec;
using devices::ParameterType;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

ParameterSpec real(const char* key, const char* label, const char* unit, double min, double max, double value,
                   const char* help) {
  return ParameterSpec{key, label, ParameterType::Real, unit, min, max, {}, value, help};
}

ParameterSpec choice(const char* key, const char* label, std::vector<std::string> choices, const char* help) {
  const std::string first = choices.front();
  return ParameterSpec{key,   label, ParameterType::Choice, "", std::nullopt, std::nullopt, std::move(choices),
                       first, help};
}

// The chair of the form: WheelchairParameters with the CLI's chair options.
st::WheelchairParameters chairOf(const ParameterMap& v) {
  st::WheelchairParameters p;
  p.mass = devices::parameterReal(v, "chair.mass", p.mass);
  p.yawInertia = devices::parameterReal(v, "chair.yaw_inertia", p.yawInertia);
  p.rearAxleBehindCoM = devices::parameterReal(v, "chair.rear_axle_behind", p.rearAxleBehindCoM);
  p.casterAheadOfCoM = devices::parameterReal(v, "chair.caster_ahead", p.casterAheadOfCoM);
  p.rearHalfTrack = devices::parameterReal(v, "chair.half_track", p.rearHalfTrack);
  p.rearCorneringStiffness = devices::parameterReal(v, "chair.cornering_stiffness", p.rearCorneringStiffness);
  p.rearAligningStiffness = devices::parameterReal(v, "chair.aligning_stiffness", p.rearAligningStiffness);
  return p;
}

// The form's study: the manoeuvre and chair as `mozzi-cli wheelchair` takes them.
st::WheelchairStudy studyOf(const ParameterMap& v) {
  st::WheelchairStudy s;
  s.manoeuvre = devices::parameterText(v, "manoeuvre", "slalom");
  s.study = devices::parameterText(v, "study", "none");
  s.speed = devices::parameterReal(v, "speed", 4.0 / 3.6);
  s.torque = devices::parameterReal(v, "torque", 10.0);
  s.frequency = devices::parameterReal(v, "frequency", 0.25);
  s.duration = devices::parameterReal(v, "duration", 20.0);
  s.ramp = devices::parameterReal(v, "ramp", 1.0);
  s.chair = chairOf(v);
  return s;
}

QColor runColour(std::size_t i) {
  static const QColor colours[] = {QColor(31, 119, 180), QColor(0, 0, 0), QColor(214, 39, 40)};
  return colours[i % 3];
}

QString number(double v, int digits) {
  return QString::fromStdString(core::formatNumber(v, digits));
}

}  // namespace

const std::vector<ParameterSpec>& wheelchairParameterSpecs() {
  static const st::WheelchairParameters d;
  static const std::vector<ParameterSpec> specs = {
      choice("manoeuvre", "Manoeuvre", {"slalom", "steady turning"},
             "slalom: T_R - T_L = torque cos(2 pi f t); steady turning: the torque ramped up, then held (§7.3)"),
      choice("study", "Stiffness study", {"cornering stiffness", "aligning stiffness", "none"},
             "the rear tyres' cornering or aligning stiffness at 0.5, 1 and 2 times its value (Figures 57 to 60)"),
      real("speed", "Forward speed", "m/s", 0.05, 10.0, 4.0 / 3.6, "held constant (§7.3); 4 km/h by default"),
      real("torque", "Differential torque", "N m", -1000.0, 1000.0, 10.0,
           "T_R - T_L: the slalom's amplitude or the steady turn's held value"),
      real("frequency", "Slalom frequency", "Hz", 0.01, st::kMaxSlalomFrequencyHz, 0.25,
           "a manual slalom is below 1 Hz"),
      real("duration", "Duration", "s", 0.5, 600.0, 20.0, "simulated time"),
      real("ramp", "Torque ramp", "s", 0.0, 60.0, 1.0, "steady turning: time to reach the held torque"),
      real("chair.mass", "Mass", "kg", 1.0, 1000.0, d.mass, "chair, user and rear wheels (assumed: 110 kg)"),
      real("chair.yaw_inertia", "Yaw inertia", "kg m^2", 0.01, 1000.0, d.yawInertia, "about the centre of mass"),
      real("chair.rear_axle_behind", "Rear axle behind CoM", "m", 0.0, 2.0, d.rearAxleBehindCoM,
           "b: distance of the rear axle behind the centre of mass (assumed)"),
      real("chair.caster_ahead", "Casters ahead of CoM", "m", 0.0, 2.0, d.casterAheadOfCoM,
           "a_f: distance of the caster pivots ahead of the centre of mass (assumed)"),
      real("chair.half_track", "Rear half-track", "m", 0.01, 2.0, d.rearHalfTrack,
           "w: half the distance between the rear wheels (assumed)"),
      real("chair.cornering_stiffness", "Rear cornering stiffness", "N/rad", 1.0, 1e6, d.rearCorneringStiffness,
           "per rear tyre (10 F_z/rad at 400 N, §7.1)"),
      real("chair.aligning_stiffness", "Rear aligning stiffness", "N m/rad", 0.0, 1e5, d.rearAligningStiffness,
           "per rear tyre (7.5 mm pneumatic trail)"),
  };
  return specs;
}

WheelchairPage::WheelchairPage(QWidget* parent, JobRunner* jobs) : QWidget(parent), jobs_(jobs) {
  form_ = new ParameterForm(wheelchairParameterSpecs(), this);
  form_->setObjectName(QStringLiteral("wheelchairForm"));
  runButton_ = new QPushButton(this);
  runButton_->setObjectName(QStringLiteral("wheelchairRun"));
  summary_ = new QLabel(this);
  summary_->setObjectName(QStringLiteral("wheelchairSummary"));
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);  // one short line per run, never wrapped away
  auto plot = [this](const char* name) {
    auto* p = new InteractivePlot(this);
    p->setObjectName(QString::fromLatin1(name));
    p->setMinimumSize(280, 160);
    return p;
  };
  trajectory_ = plot("wheelchairTrajectory");
  slipRight_ = plot("wheelchairSlipRight");
  slipLeft_ = plot("wheelchairSlipLeft");
  trajectory_->insertLegend(new QwtLegend, QwtPlot::RightLegend);
  storedLabel_ = new QLabel(this);
  stored_ = new QComboBox(this);
  stored_->setObjectName(QStringLiteral("wheelchairStored"));
  showStored_ = new QPushButton(this);
  showStored_->setObjectName(QStringLiteral("wheelchairShowStored"));

  auto* scroll = new QScrollArea(this);
  scroll->setWidget(form_);
  scroll->setWidgetResizable(true);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  scroll->setMinimumWidth(form_->sizeHint().width() + 24);
  auto* left = new QVBoxLayout;
  left->addWidget(scroll, 1);
  left->addWidget(runButton_);
  left->addWidget(storedLabel_);
  left->addWidget(stored_);
  left->addWidget(showStored_);
  auto* slips = new QHBoxLayout;
  slips->addWidget(slipRight_);
  slips->addWidget(slipLeft_);
  auto* right = new QVBoxLayout;
  right->addWidget(summary_);
  right->addWidget(trajectory_, 3);
  right->addLayout(slips, 2);
  auto* layout = new QHBoxLayout(this);
  layout->addLayout(left);
  layout->addLayout(right, 1);
  connect(runButton_, &QPushButton::clicked, this, &WheelchairPage::run);
  connect(showStored_, &QPushButton::clicked, this, [this] {
    if (stored_->count() > 0) showStored(stored_->currentData().toLongLong());
  });
  retranslate();
  refreshStored();
}

void WheelchairPage::run() {
  start(true);
}

void WheelchairPage::openShowing() {
  const auto ids = storedResults();
  if (ids.empty() || !showStored(ids.back())) start(false);
}

void WheelchairPage::start(bool keepResult) {
  if (form_->hasProblems()) {
    summary_->setText(tr("Correct the marked values first."));
    emit finished(false);
    return;
  }
  const st::WheelchairStudy study = studyOf(form_->values());
  runButton_->setEnabled(false);
  summary_->setText(tr("Simulating the manoeuvre..."));
  const bool keep = keepResult && project_ && project_->store();
  // The record and its result_json, serialised on the job runner's thread.
  auto work = [study, keep](JobProgress&) -> core::Result<Outcome> {
    auto record = st::runWheelchairStudy(study);
    if (!record) return record.error();
    Outcome out{std::move(*record), {}};
    if (keep) out.json = st::wheelchairRecordJson(out.record);
    return out;
  };
  if (!jobs_) {
    JobProgress progress;
    present(work(progress), keep);
    return;
  }
  jobs_->run<Outcome>(this, tr("Wheelchair manoeuvre"), work,
                      [this, keep](core::Result<Outcome> result) { present(std::move(result), keep); });
}

void WheelchairPage::setProjectModel(ProjectModel* model) {
  project_ = model;
  if (project_) {
    connect(project_, &ProjectModel::analysesChanged, this, &WheelchairPage::refreshStored);
    connect(project_, &ProjectModel::projectChanged, this, &WheelchairPage::refreshStored);
  }
  refreshStored();
}

// Keeps the runs as an analysis of kind "wheelchair" under the project's
// wheelchair-tyre specimen (core/stability/wheelchair_record.h).
QString WheelchairPage::keep(const Outcome& outcome) {
  lastStoredId_ = 0;
  if (!project_ || !project_->store()) return {};
  auto specimen = st::defaultWheelchairSpecimen(*project_->store());
  if (!specimen) return tr("Not kept: %1").arg(QString::fromStdString(specimen.error().describe()));
  const std::string base = outcome.record.study.manoeuvre +
                           (outcome.record.study.study == "none" ? "" : ", " + outcome.record.study.study + " study");
  auto a = st::wheelchairAnalysis(*project_->store(), *specimen, base, st::WheelchairRecord{});
  if (!a) return tr("Not kept: %1").arg(QString::fromStdString(a.error().describe()));
  a->resultJson = outcome.json.empty() ? st::wheelchairRecordJson(outcome.record) : outcome.json;
  auto id = project_->addAnalysis(*a);
  if (!id) return tr("Not kept: %1").arg(QString::fromStdString(id.error().describe()));
  lastStoredId_ = *id;
  return tr("Kept in the project as analysis %1.").arg(*id);
}

void WheelchairPage::refreshStored() {
  showStored_->setEnabled(fillKeptAnalyses(stored_, project_, st::kWheelchairAnalysisKind) > 0);
}

std::vector<qint64> WheelchairPage::storedResults() const {
  return keptAnalysisIds(stored_);
}

bool WheelchairPage::showStored(qint64 analysisId) {
  if (!project_ || !project_->store()) return false;
  auto stored = st::storedWheelchairRecord(*project_->store(), analysisId);
  if (!stored) {
    present(stored.error(), false);
    return false;
  }
  const int at = stored_->findData(QVariant::fromValue<qint64>(analysisId));
  if (at >= 0) stored_->setCurrentIndex(at);
  showRecord(stored->record);
  return true;
}

void WheelchairPage::showRecord(const st::WheelchairRecord& record) {
  // The form says what the record is (a value outside the form's range is
  // clamped and marked there; the plots show the record as kept).
  const st::WheelchairStudy& s = record.study;
  (void)form_->setValues({{"manoeuvre", s.manoeuvre},
                          {"study", s.study},
                          {"speed", s.speed},
                          {"torque", s.torque},
                          {"frequency", s.frequency},
                          {"duration", s.duration},
                          {"ramp", s.ramp},
                          {"chair.mass", s.chair.mass},
                          {"chair.yaw_inertia", s.chair.yawInertia},
                          {"chair.rear_axle_behind", s.chair.rearAxleBehindCoM},
                          {"chair.caster_ahead", s.chair.casterAheadOfCoM},
                          {"chair.half_track", s.chair.rearHalfTrack},
                          {"chair.cornering_stiffness", s.chair.rearCorneringStiffness},
                          {"chair.aligning_stiffness", s.chair.rearAligningStiffness}});
  present(Outcome{record, {}}, false);
}

void WheelchairPage::present(core::Result<Outcome> result, bool keepIt) {
  runButton_->setEnabled(true);
  for (QwtPlot* p : {trajectory_, slipRight_, slipLeft_}) p->detachItems(QwtPlotItem::Rtti_PlotCurve, true);
  if (!result) {
    runs_.clear();
    record_.reset();
    summary_->setText(tr("Cannot simulate: %1").arg(QString::fromStdString(result.error().describe())));
    for (QwtPlot* p : {trajectory_, slipRight_, slipLeft_}) p->replot();
    emit finished(false);
    return;
  }
  const QString kept = keepIt ? keep(*result) : QString();
  record_ = std::move(result->record);
  runs_.clear();
  for (const auto& r : record_->runs) runs_.push_back(Run{r.factor, r.history});
  const std::string study = record_->study.study;
  const bool slalom = record_->study.manoeuvre == "slalom";
  const double frequency = record_->study.frequency;
  QStringList lines;
  for (std::size_t i = 0; i < runs_.size(); ++i) {
    const Run& run = runs_[i];
    const QString name = study == "none"                  ? tr("chair")
                         : study == "cornering stiffness" ? tr("C_α × %1").arg(number(run.factor, 3))
                                                          : tr("C_M × %1").arg(number(run.factor, 3));
    QVector<QPointF> path, right, left;
    for (const auto& s : run.history) {
      path.append(QPointF(s.x, s.y));
      right.append(QPointF(s.t, s.slipRight / kDeg));
      left.append(QPointF(s.t, s.slipLeft / kDeg));
    }
    const QPen pen(runColour(i), 2.0, i == 1 || runs_.size() == 1 ? Qt::SolidLine : Qt::DashLine);
    auto add = [&](QwtPlot* plot, const QVector<QPointF>& data, bool legend) {
      auto* c = new QwtPlotCurve(name);
      c->setPen(pen);
      c->setSamples(data);
      c->setItemAttribute(QwtPlotItem::Legend, legend);
      c->attach(plot);
    };
    add(trajectory_, path, true);
    add(slipRight_, right, false);
    add(slipLeft_, left, false);
    // What the thesis reads off each run.
    if (slalom) {
      auto s = st::summariseSlalom(run.history, 2.0 / frequency, frequency);
      if (s)
        lines << tr("%1: lateral amplitude %2 m, rear slip amplitude right %3°, left %4°")
                     .arg(name, number(s->lateralAmplitude, 4), number(s->slipAmplitudeRight / kDeg, 4),
                          number(s->slipAmplitudeLeft / kDeg, 4));
    } else if (!run.history.empty()) {
      const auto& end = run.history.back();
      const double radius = std::abs(end.r) > 0.0 ? std::hypot(end.u, end.v) / std::abs(end.r) : 0.0;
      lines << tr("%1: radius %2 m at the end, rear slip right %3°, left %4°")
                   .arg(name, number(radius, 4), number(end.slipRight / kDeg, 4), number(end.slipLeft / kDeg, 4));
    }
  }
  if (!kept.isEmpty()) lines << kept;
  summary_->setText(lines.join(QLatin1Char('\n')));
  // A turn is drawn to scale (its circle round); a slalom's sideways sway
  // would vanish at equal scales, so its axes fit the path.
  static_cast<InteractivePlot*>(trajectory_)->setEqualAspect(!slalom);
  for (QwtPlot* p : {trajectory_, slipRight_, slipLeft_}) static_cast<InteractivePlot*>(p)->autoscale();
  emit finished(true);
}

QString WheelchairPage::summaryText() const {
  return summary_->text();
}

void WheelchairPage::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void WheelchairPage::retranslate() {
  runButton_->setText(tr("Simulate"));
  storedLabel_->setText(tr("Kept results:"));
  stored_->setToolTip(tr("Manoeuvres the project keeps (this page, mozzi-cli wheelchair slalom --project)"));
  showStored_->setText(tr("Show"));
  trajectory_->setTitle(tr("Trajectory of the centre of mass (thesis Figures 57 to 60)"));
  trajectory_->setAxisTitle(QwtPlot::xBottom, tr("x [m]"));
  trajectory_->setAxisTitle(QwtPlot::yLeft, tr("y [m]"));
  slipRight_->setTitle(tr("Right rear wheel slip angle"));
  slipLeft_->setTitle(tr("Left rear wheel slip angle"));
  for (QwtPlot* p : {slipRight_, slipLeft_}) {
    p->setAxisTitle(QwtPlot::xBottom, tr("t [s]"));
    p->setAxisTitle(QwtPlot::yLeft, tr("α [deg]"));
  }
}

}  // namespace views
}  // namespace mozzi
