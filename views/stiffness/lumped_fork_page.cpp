#include "views/stiffness/lumped_fork_page.h"

#include <qwt_legend.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_marker.h>
#include <qwt_scale_draw.h>
#include <qwt_symbol.h>
#include <qwt_text.h>
#include <QComboBox>
#include <QEvent>
#include <QFont>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/io/project_store.h"
#include "core/stiffness/fork_models.h"
#include "devices/rigtests/fork_model_inputs.h"
#include "views/common/job_runner.h"
#include "views/common/project_model.h"
#include "views/panels/parameter_form.h"
#include "views/plots/interactive_plot.h"

namespace mozzi {
namespace views {

namespace st = core::stiffness;
namespace rt = devices::rigtests;

// What one computation gives (worker thread -> GUI thread).
struct LumpedForkOutcome {
  st::ForkLumpedInput lumpedInput;
  core::Result<st::ForkLumpedModels> lumped = core::Error{};
  rt::BicycleForkInput bicycleInput;
  core::Result<st::BicycleTorsion> torsion = core::Error{};
  core::Result<st::BicycleBending> bending = core::Error{};
  // §6.5's two stiffness curves k(h) = (2 pi f)^2 I_bend(h), eq. 57 to 59.
  std::vector<double> h, kWithWheel, kAlone;
};

namespace {

QString qs(const std::string& s) {
  return QString::fromStdString(s);
}

// Six significant digits: what `mozzi-cli fork` prints (std::ostream's default).
QString printed(double v) {
  return QString::number(v, 'g', 6);
}

QTableWidgetItem* numberItem(double v, bool computed) {
  auto* item = new QTableWidgetItem(printed(v));
  item->setData(Qt::UserRole, v);
  item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
  if (computed) {
    QFont f = item->font();
    f.setBold(true);
    item->setFont(f);
  }
  return item;
}

QTableWidget* makeTable(QWidget* parent, const char* name) {
  auto* t = new QTableWidget(parent);
  t->setObjectName(QLatin1String(name));
  t->setEditTriggers(QAbstractItemView::NoEditTriggers);
  t->setSelectionMode(QAbstractItemView::ContiguousSelection);
  t->setWordWrap(false);
  // As tall as its rows (the plot takes the rest).
  t->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
  t->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Maximum);
  return t;
}

InteractivePlot* makePlot(QWidget* parent, const char* name) {
  auto* p = new InteractivePlot(parent);
  p->setObjectName(QLatin1String(name));
  p->setMinimumSize(280, 160);
  p->insertLegend(new QwtLegend, QwtPlot::TopLegend);
  return p;
}

const QColor kMeasuredColour(20, 20, 20);
const QColor kModelColours[3] = {QColor(40, 90, 170), QColor(200, 30, 30), QColor(230, 120, 0)};

LumpedForkOutcome computeOutcome(const st::ForkLumpedInput& lumped, const rt::BicycleForkInput& bicycle) {
  LumpedForkOutcome o;
  o.lumpedInput = lumped;
  o.bicycleInput = bicycle;
  o.lumped = st::forkLumpedModels(lumped);
  const auto& p = bicycle.parameters;
  o.torsion = st::bicycleForkTorsion(p, bicycle.torsionWithWheelHz, bicycle.torsionWithWheelEta, bicycle.torsionAloneHz,
                                     bicycle.torsionAlone2Hz);
  o.bending =
      st::bicycleForkBending(p, bicycle.bendingWithWheelHz, bicycle.bendingWithWheelEta, bicycle.bendingAloneHz);
  if (p.maxBendArm > 0 && std::isfinite(p.maxBendArm)) {
    const int n = 200;
    for (int i = 0; i <= n; ++i) {
      const double h = p.maxBendArm * i / n;
      o.h.push_back(h);
      o.kWithWheel.push_back(st::modalStiffness(bicycle.bendingWithWheelHz, st::bendInertiaWithWheel(p, h)));
      o.kAlone.push_back(st::modalStiffness(bicycle.bendingAloneHz, st::bendInertiaForkAlone(p, h)));
    }
  }
  return o;
}

}  // namespace

LumpedForkPage::LumpedForkPage(const PageContext& ctx) : QWidget(ctx.parent), model_(ctx.model), jobs_(ctx.jobs) {
  buildUi();
  retranslate();
  reload();
  connect(model_, &ProjectModel::projectChanged, this, &LumpedForkPage::reload);
  connect(model_, &ProjectModel::specimensChanged, this, &LumpedForkPage::reload);
  connect(model_, &ProjectModel::modalResultsChanged, this, &LumpedForkPage::reload);
  compute();  // the thesis's inputs at once: worth a look on opening
}

LumpedForkPage::~LumpedForkPage() = default;

void LumpedForkPage::buildUi() {
  auto* layout = new QVBoxLayout(this);
  auto* bar = new QHBoxLayout;
  specimenLabel_ = new QLabel(this);
  specimen_ = new QComboBox(this);
  specimen_->setObjectName(QStringLiteral("lumpedForkSpecimen"));
  specimen_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  compute_ = new QPushButton(this);
  compute_->setObjectName(QStringLiteral("lumpedForkCompute"));
  bar->addWidget(specimenLabel_);
  bar->addWidget(specimen_);
  bar->addStretch(1);
  bar->addWidget(compute_);
  layout->addLayout(bar);

  tabs_ = new QTabWidget(this);
  tabs_->setObjectName(QStringLiteral("lumpedForkTabs"));
  tabs_->setDocumentMode(true);
  layout->addWidget(tabs_, 1);

  // --- motorcycle fork: form | modes and models
  auto* moto = new QSplitter(Qt::Horizontal, tabs_);
  auto* formScroll = new QScrollArea(moto);
  formScroll->setWidgetResizable(true);
  lumpedForm_ = new ParameterForm(rt::lumpedForkParameterSpecs(), formScroll);
  lumpedForm_->setObjectName(QStringLiteral("lumpedForkForm"));
  formScroll->setWidget(lumpedForm_);
  auto* right = new QWidget(moto);
  auto* rl = new QVBoxLayout(right);
  rl->setContentsMargins(0, 0, 0, 0);
  auto* modalBar = new QHBoxLayout;
  modalLabel_ = new QLabel(right);
  modal_ = new QComboBox(right);
  modal_->setObjectName(QStringLiteral("lumpedForkModalResult"));
  useMode_ = new QPushButton(right);
  useMode_->setObjectName(QStringLiteral("lumpedForkUseMode"));
  modalBar->addWidget(modalLabel_);
  modalBar->addWidget(modal_, 1);
  modalBar->addWidget(useMode_);
  rl->addLayout(modalBar);
  modes_ = makeTable(right, "lumpedForkModes");
  modes_->setSelectionBehavior(QAbstractItemView::SelectRows);
  modes_->setSelectionMode(QAbstractItemView::SingleSelection);
  rl->addWidget(modes_);
  models_ = makeTable(right, "lumpedForkModels");
  rl->addWidget(models_);
  legend_ = new QLabel(right);
  legend_->setWordWrap(true);
  rl->addWidget(legend_);
  auto* keepBar = new QHBoxLayout;
  keepLumped_ = new QPushButton(right);
  keepLumped_->setObjectName(QStringLiteral("lumpedForkKeep"));
  keepBar->addStretch(1);
  keepBar->addWidget(keepLumped_);
  rl->addLayout(keepBar);
  ladder_ = makePlot(right, "lumpedForkLadder");
  ladder_->enableAxis(QwtPlot::yLeft, false);
  rl->addWidget(ladder_, 1);
  moto->addWidget(formScroll);
  moto->addWidget(right);
  moto->setStretchFactor(1, 1);
  tabs_->addTab(moto, QString());

  // --- bicycle fork: form | results and curves
  auto* bike = new QSplitter(Qt::Horizontal, tabs_);
  auto* bikeScroll = new QScrollArea(bike);
  bikeScroll->setWidgetResizable(true);
  bicycleForm_ = new ParameterForm(rt::bicycleForkParameterSpecs(), bikeScroll);
  bicycleForm_->setObjectName(QStringLiteral("bicycleForkForm"));
  bikeScroll->setWidget(bicycleForm_);
  auto* bright = new QWidget(bike);
  auto* bl = new QVBoxLayout(bright);
  bl->setContentsMargins(0, 0, 0, 0);
  bicycle_ = makeTable(bright, "bicycleForkResults");
  bl->addWidget(bicycle_);
  bicycleNote_ = new QLabel(bright);
  bicycleNote_->setWordWrap(true);
  bl->addWidget(bicycleNote_);
  auto* bkeep = new QHBoxLayout;
  keepBicycle_ = new QPushButton(bright);
  keepBicycle_->setObjectName(QStringLiteral("bicycleForkKeep"));
  bkeep->addStretch(1);
  bkeep->addWidget(keepBicycle_);
  bl->addLayout(bkeep);
  curves_ = makePlot(bright, "bicycleForkCurves");
  bl->addWidget(curves_, 1);
  bike->addWidget(bikeScroll);
  bike->addWidget(bright);
  bike->setStretchFactor(1, 1);
  tabs_->addTab(bike, QString());

  statusLabel_ = new QLabel(this);
  statusLabel_->setObjectName(QStringLiteral("lumpedForkStatus"));
  statusLabel_->setWordWrap(true);
  layout->addWidget(statusLabel_);

  connect(compute_, &QPushButton::clicked, this, &LumpedForkPage::compute);
  connect(modal_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] { fillModes(); });
  connect(useMode_, &QPushButton::clicked, this, [this] {
    const int row = modes_->currentRow();
    if (useMeasuredMode(row < 0 ? 0 : row)) compute();
  });
  // The specimen to keep for follows the tab: a motorcycle fork or a bicycle fork.
  connect(tabs_, &QTabWidget::currentChanged, this, [this](int tab) {
    const QString wanted = tab == 1 ? QStringLiteral("bicycle-fork") : QStringLiteral("fork");
    if (specimen_->currentData(Qt::UserRole + 1).toString() == wanted) return;
    const int i = specimen_->findData(wanted, Qt::UserRole + 1);
    if (i >= 0) specimen_->setCurrentIndex(i);
  });
  connect(keepLumped_, &QPushButton::clicked, this, [this] { keepLumpedModels(); });
  connect(keepBicycle_, &QPushButton::clicked, this, [this] { keepBicycleFork(); });
}

void LumpedForkPage::retranslate() {
  specimenLabel_->setText(tr("Keep for specimen:"));
  compute_->setText(tr("Compute"));
  compute_->setToolTip(tr("Fit the three lumped models and the bicycle fork from the forms"));
  modalLabel_->setText(tr("Measured modes:"));
  useMode_->setText(tr("Use the selected mode"));
  useMode_->setToolTip(tr("Take the selected mode's frequency and damping ratio as the measured lateral mode"));
  keepLumped_->setText(tr("Keep the models in the project"));
  keepBicycle_->setText(tr("Keep in the project"));
  legend_->setText(
      tr("Bold: computed by the model; the other values come from the inputs (the dotted entries of "
         "thesis Table 12). Values to six significant digits, as mozzi-cli fork prints them."));
  bicycleNote_->setText(
      tr("h_W is where the bending stiffness computed with the wheel (eq. 58) equals the one of "
         "the fork alone (eq. 59); c = zeta c_c with zeta = eta / 2 (eq. 55, 56, 60)."));
  tabs_->setTabText(0, tr("Motorcycle fork (§4.2, Table 12)"));
  tabs_->setTabText(1, tr("Bicycle fork (§6.4, §6.5)"));
  ladder_->setAxisTitle(QwtPlot::xBottom, tr("Frequency [Hz]"));
  curves_->setAxisTitle(QwtPlot::xBottom, tr("Bending arm h_W from the blade tips [m]"));
  curves_->setAxisTitle(QwtPlot::yLeft, tr("k_β(h_W) [Nm/rad]"));
}

void LumpedForkPage::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) {
    retranslate();
    fillModes();
    present();
  }
  QWidget::changeEvent(event);
}

void LumpedForkPage::reload() {
  const qint64 keptSpecimen = specimen_->currentData().toLongLong();
  const qint64 keptResult = modal_->currentData().toLongLong();
  QSignalBlocker b1(specimen_), b2(modal_);
  specimen_->clear();
  modal_->clear();
  auto* store = model_->store();
  if (store) {
    auto summary = store->summary();
    int preferred = -1;
    if (summary) {
      for (const auto& s : summary->specimens) {
        specimen_->addItem(qs(s.name), QVariant::fromValue<qlonglong>(s.id));
        specimen_->setItemData(specimen_->count() - 1, qs(s.kind), Qt::UserRole + 1);
        // The thesis's fork with its wheel (Table 12's specimen) first, else any fork.
        const bool fork = s.kind == "fork";
        if (fork && preferred < 0) preferred = specimen_->count() - 1;
        if (fork && s.name.find("with wheel") != std::string::npos &&
            (preferred < 0 || specimen_->itemText(preferred).indexOf(QLatin1String("with wheel")) < 0))
          preferred = specimen_->count() - 1;
      }
    }
    const int kept = specimen_->findData(QVariant::fromValue<qlonglong>(keptSpecimen));
    specimen_->setCurrentIndex(kept >= 0 ? kept : std::max(preferred, 0));
    auto results = store->modalResults();
    if (results) {
      const qint64 specimen = specimen_->currentData().toLongLong();
      int first = -1;
      for (const auto& r : *results) {
        QString owner;
        if (summary)
          for (const auto& s : summary->specimens)
            if (s.id == r.specimenId) owner = qs(s.name);
        modal_->addItem(tr("%1: %2 (%n mode(s))", nullptr, r.modeCount).arg(owner, qs(r.name)),
                        QVariant::fromValue<qlonglong>(r.id));
        if (r.specimenId == specimen && first < 0) first = modal_->count() - 1;
      }
      const int keptIndex = modal_->findData(QVariant::fromValue<qlonglong>(keptResult));
      modal_->setCurrentIndex(keptIndex >= 0 ? keptIndex : std::max(first, 0));
    }
  }
  keepLumped_->setEnabled(store && !model_->isReadOnly() && specimen_->count() > 0);
  keepBicycle_->setEnabled(keepLumped_->isEnabled());
  fillModes();
}

// The measured modes of the chosen modal result (a table; the model columns
// are filled by presentModes()).
void LumpedForkPage::fillModes() {
  modes_->clear();
  modes_->setRowCount(0);
  modes_->setColumnCount(5);
  auto* store = model_->store();
  const qint64 id = modal_->currentData().toLongLong();
  if (store && id > 0) {
    auto table = store->modalResult(id);
    if (table) {
      modes_->setRowCount(static_cast<int>(table->modes.size()));
      for (int i = 0; i < modes_->rowCount(); ++i) {
        const auto& m = table->modes[static_cast<std::size_t>(i)];
        modes_->setItem(i, 0, numberItem(m.frequencyHz, false));
        modes_->setItem(i, 1, numberItem(m.dampingRatio, false));
      }
    }
  }
  useMode_->setEnabled(modes_->rowCount() > 0);
  presentModes();
}

bool LumpedForkPage::useMeasuredMode(int index) {
  if (index < 0 || index >= modes_->rowCount()) return false;
  const double f = modes_->item(index, 0)->data(Qt::UserRole).toDouble();
  const double zeta = modes_->item(index, 1)->data(Qt::UserRole).toDouble();
  auto r = lumpedForm_->setValues({{"fork.frequency", f}, {"fork.zeta", zeta}});
  modes_->selectRow(index);
  return r.ok();
}

void LumpedForkPage::compute() {
  const st::ForkLumpedInput lumped = rt::lumpedForkInput(lumpedForm_->values());
  const rt::BicycleForkInput bicycle = rt::bicycleForkInput(bicycleForm_->values());
  computing_ = true;
  compute_->setEnabled(false);
  status_ = tr("Computing the lumped models...");
  statusLabel_->setText(status_);
  auto done = [this](core::Result<LumpedForkOutcome> r) {
    computing_ = false;
    compute_->setEnabled(true);
    if (r) {
      outcome_ = std::make_unique<LumpedForkOutcome>(std::move(r).value());
    } else {
      outcome_.reset();
      status_ = tr("The computation stopped: %1").arg(qs(r.error().describe()));
    }
    present();
    emit computed(static_cast<bool>(outcome_));
  };
  auto work = [lumped, bicycle](JobProgress&) -> core::Result<LumpedForkOutcome> {
    return computeOutcome(lumped, bicycle);
  };
  if (!jobs_) {
    done(work(*std::make_unique<JobProgress>()));
    return;
  }
  jobs_->run<LumpedForkOutcome>(this, tr("Lumped fork models"), work, done);
}

void LumpedForkPage::present() {
  presentModels();
  presentModes();
  presentBicycle();
  if (!outcome_) {
    statusLabel_->setText(status_);
    return;
  }
  QStringList problems;
  if (!outcome_->lumped) problems << tr("Lumped models: %1").arg(qs(outcome_->lumped.error().message));
  if (!outcome_->torsion) problems << tr("Bicycle fork torsion: %1").arg(qs(outcome_->torsion.error().message));
  if (!outcome_->bending) problems << tr("Bicycle fork bending: %1").arg(qs(outcome_->bending.error().message));
  status_ = problems.isEmpty() ? tr("Computed.") : problems.join(QLatin1Char('\n'));
  statusLabel_->setText(status_);
}

void LumpedForkPage::presentModels() {
  models_->clear();
  const QStringList rows{tr("Bending stiffness k_i [Nm/rad]"),
                         tr("Bending arm L_i [m]"),
                         tr("Vibrating inertia J_i [kgm²]"),
                         tr("Pure moment of inertia [kgm²]"),
                         tr("Natural frequency f_n [Hz]"),
                         tr("Damping coefficient c_i [Nms/rad]"),
                         tr("Viscous damping ζ_i")};
  models_->setRowCount(rows.size());
  models_->setColumnCount(3);
  models_->setVerticalHeaderLabels(rows);
  models_->setHorizontalHeaderLabels({tr("Model 1"), tr("Model 2"), tr("Model 3")});
  if (!outcome_ || !outcome_->lumped) return;
  const auto& r = *outcome_->lumped;
  // Which entries each model computes (the undotted cells of Table 12).
  const st::LumpedModel* ms[3] = {&r.model1, &r.model2, &r.model3};
  const bool computedK[3] = {false, true, false}, computedJ[3] = {false, false, true},
             computedF[3] = {true, false, false};
  for (int c = 0; c < 3; ++c) {
    const auto& m = *ms[c];
    models_->setItem(0, c, numberItem(m.stiffness, computedK[c]));
    models_->setItem(1, c, numberItem(m.arm, false));
    models_->setItem(2, c, numberItem(m.inertia, computedJ[c] || c == 0 || c == 1));
    models_->setItem(3, c, numberItem(m.pureMoment, c == 2));
    models_->setItem(4, c, numberItem(m.frequencyHz, computedF[c]));
    models_->setItem(5, c, numberItem(m.damping, true));
    models_->setItem(6, c, numberItem(m.zeta, false));
  }
  models_->resizeColumnsToContents();
}

void LumpedForkPage::presentModes() {
  const int n = modes_->rowCount();
  modes_->setColumnCount(5);
  modes_->setHorizontalHeaderLabels(
      {tr("f [Hz]"), tr("ζ"), tr("Model 1 f_n - f"), tr("Model 2 f_n - f"), tr("Model 3 f_n - f")});
  const st::ForkLumpedModels* r = (outcome_ && outcome_->lumped) ? &*outcome_->lumped : nullptr;
  for (int i = 0; i < n; ++i) {
    const double f = modes_->item(i, 0)->data(Qt::UserRole).toDouble();
    for (int c = 0; c < 3; ++c) {
      if (!r) {
        modes_->setItem(i, 2 + c, new QTableWidgetItem(QStringLiteral("-")));
        continue;
      }
      const double fn = (c == 0 ? r->model1 : c == 1 ? r->model2 : r->model3).frequencyHz;
      auto* item = new QTableWidgetItem(
          QStringLiteral("%1 Hz (%2 %)")
              .arg(QString::number(fn - f, 'f', 2), QString::number(100.0 * (fn - f) / f, 'f', 1)));
      item->setData(Qt::UserRole, fn - f);
      item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      modes_->setItem(i, 2 + c, item);
    }
  }
  modes_->resizeColumnsToContents();

  // The frequency ladder: the measured modes on the top rung, each model's
  // natural frequency on its own rung below.
  ladder_->detachItems(QwtPlotItem::Rtti_PlotCurve, true);
  ladder_->detachItems(QwtPlotItem::Rtti_PlotMarker, true);
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  auto rung = [&](const QString& title, const QVector<QPointF>& pts, const QColor& colour, QwtSymbol::Style s) {
    auto* c = new QwtPlotCurve(title);
    c->setStyle(QwtPlotCurve::NoCurve);
    c->setSymbol(new QwtSymbol(s, QBrush(colour), QPen(colour, 1.5), QSize(11, 11)));
    c->setSamples(pts);
    c->attach(ladder_);
    bool above = true;  // neighbours' labels alternate above and below their point
    for (const QPointF& p : pts) {
      lo = std::min(lo, p.x());
      hi = std::max(hi, p.x());
      auto* label = new QwtPlotMarker;
      label->setValue(p);
      QwtText t(QString::number(p.x(), 'f', 1));
      t.setColor(colour);
      label->setLabel(t);
      label->setLabelAlignment((above ? Qt::AlignTop : Qt::AlignBottom) | Qt::AlignHCenter);
      above = !above;
      label->setItemAttribute(QwtPlotItem::AutoScale, false);
      label->attach(ladder_);
    }
  };
  QVector<QPointF> measured;
  for (int i = 0; i < n; ++i) measured.append(QPointF(modes_->item(i, 0)->data(Qt::UserRole).toDouble(), 4.0));
  if (!measured.isEmpty()) rung(tr("Measured modes"), measured, kMeasuredColour, QwtSymbol::Diamond);
  if (r) {
    const st::LumpedModel* ms[3] = {&r->model1, &r->model2, &r->model3};
    for (int c = 0; c < 3; ++c)
      rung(tr("Model %1").arg(c + 1), {QPointF(ms[c]->frequencyHz, 3.0 - c)}, kModelColours[c], QwtSymbol::Ellipse);
    auto* target = new QwtPlotMarker;
    target->setLineStyle(QwtPlotMarker::VLine);
    target->setLinePen(QColor(120, 120, 120), 1.0, Qt::DashLine);
    target->setXValue(outcome_->lumpedInput.measuredFrequencyHz);
    target->setItemAttribute(QwtPlotItem::AutoScale, false);
    target->attach(ladder_);
  }
  ladder_->autoscale();
  if (lo <= hi) {  // every point and its label inside the view
    const double pad = 0.08 * (hi - lo) + 1.0;
    ladder_->setAxisScale(QwtPlot::xBottom, std::max(0.0, lo - pad), hi + pad);
  }
  ladder_->setAxisScale(QwtPlot::yLeft, 0.3, 4.8);
  ladder_->replot();
}

void LumpedForkPage::presentBicycle() {
  bicycle_->clear();
  const QStringList rows{tr("Torsion inertia with wheel [kgm²]"),
                         tr("Torsion inertia, fork alone [kgm²]"),
                         tr("Torsion stiffness with wheel [Nm/rad]"),
                         tr("Torsion stiffness, fork alone [Nm/rad]"),
                         tr("Torsion damping [Nms/rad]"),
                         tr("Bending arm h_W [m]"),
                         tr("Bending stiffness [Nm/rad]"),
                         tr("Bending inertia with wheel [kgm²]"),
                         tr("Bending damping [Nms/rad]")};
  bicycle_->setRowCount(rows.size());
  bicycle_->setColumnCount(1);
  bicycle_->setVerticalHeaderLabels(rows);
  bicycle_->setHorizontalHeaderLabels({tr("Value")});
  curves_->detachItems(QwtPlotItem::Rtti_PlotCurve, true);
  curves_->detachItems(QwtPlotItem::Rtti_PlotMarker, true);
  if (!outcome_) {
    curves_->replot();
    return;
  }
  if (outcome_->torsion) {
    const auto& t = *outcome_->torsion;
    const double v[] = {t.inertiaWithWheel, t.inertiaAlone, t.stiffnessWithWheel, t.stiffnessAlone, t.damping};
    for (int i = 0; i < 5; ++i) bicycle_->setItem(i, 0, numberItem(v[i], i >= 2));
  }
  if (outcome_->bending) {
    const auto& b = *outcome_->bending;
    const double v[] = {b.bendArm, b.stiffness, b.inertiaWithWheel, b.damping};
    for (int i = 0; i < 4; ++i) bicycle_->setItem(5 + i, 0, numberItem(v[i], i != 2));
  }
  bicycle_->resizeColumnsToContents();
  auto curve = [this](const QString& title, const std::vector<double>& y, const QColor& colour) {
    auto* c = new QwtPlotCurve(title);
    c->setPen(QPen(colour, 2.0));
    c->setRenderHint(QwtPlotItem::RenderAntialiased, true);
    QVector<QPointF> pts;
    for (std::size_t i = 0; i < y.size(); ++i) pts.append(QPointF(outcome_->h[i], y[i]));
    c->setSamples(pts);
    c->attach(curves_);
  };
  curve(tr("with the wheel (eq. 58)"), outcome_->kWithWheel, kModelColours[0]);
  curve(tr("fork alone (eq. 59)"), outcome_->kAlone, kModelColours[1]);
  if (outcome_->bending) {
    auto* m = new QwtPlotMarker;
    m->setValue(outcome_->bending->bendArm, outcome_->bending->stiffness);
    m->setSymbol(new QwtSymbol(QwtSymbol::Ellipse, QBrush(kMeasuredColour), QPen(kMeasuredColour), QSize(9, 9)));
    QwtText t(tr("h_W = %1 m, k = %2 Nm/rad")
                  .arg(printed(outcome_->bending->bendArm), printed(outcome_->bending->stiffness)));
    m->setLabel(t);
    m->setLabelAlignment(Qt::AlignLeft | Qt::AlignTop);
    m->attach(curves_);
  }
  curves_->autoscale();
  curves_->replot();
}

QString LumpedForkPage::statusText() const {
  return status_;
}

// A model of kind "lumped" with the inputs and the results, and an analysis
// of kind `analysisKind` ("lumped-fork", "bicycle-fork") naming it and the
// measured modes, whose result_json the project report shows with the
// stiffness results (core/report/project_report.cpp).
qint64 LumpedForkPage::keep(const QString& name, const std::string& analysisKind, const std::string& json,
                            qint64 modalResultId) {
  const qint64 specimen = specimen_->currentData().toLongLong();
  if (!model_->store() || specimen == 0) {
    status_ = tr("No specimen to keep the model for.");
    statusLabel_->setText(status_);
    return 0;
  }
  core::io::StoredModel m;
  m.specimenId = specimen;
  m.name = name.toStdString();
  m.kind = "lumped";
  m.parametersJson = json;
  m.source = "Mozzi Lumped Fork page (core::stiffness::fork_models; thesis §4.2, §6.4, §6.5)";
  auto id = model_->addModel(m);
  if (id) {
    core::io::StoredAnalysis a;
    a.specimenId = specimen;
    a.modelId = *id;
    if (modalResultId > 0) a.modalResultId = modalResultId;
    a.kind = analysisKind;
    a.name = m.name;
    a.resultJson = json;
    auto kept = model_->addAnalysis(a);
    if (!kept) {
      status_ = tr("Could not keep the model: %1").arg(qs(kept.error().describe()));
      statusLabel_->setText(status_);
      emit message(status_);
      return 0;
    }
  }
  status_ = id ? tr("Kept as model %1 of %2.").arg(*id).arg(specimen_->currentText())
               : tr("Could not keep the model: %1").arg(qs(id.error().describe()));
  statusLabel_->setText(status_);
  emit message(status_);
  return id ? *id : 0;
}

qint64 LumpedForkPage::keepLumpedModels() {
  if (!outcome_ || !outcome_->lumped) return 0;
  nlohmann::json j{{"fork", "motorcycle"},
                   {"inputs", rt::lumpedInputJson(outcome_->lumpedInput)},
                   {"models", rt::lumpedModelsJson(*outcome_->lumped)}};
  const qint64 result = modal_->currentData().toLongLong();
  if (result > 0) j["measured_modal_result_id"] = result;
  return keep(tr("Lumped fork models 1 to 3"), "lumped-fork", j.dump(), result);
}

qint64 LumpedForkPage::keepBicycleFork() {
  if (!outcome_ || !outcome_->torsion || !outcome_->bending) return 0;
  const auto& t = *outcome_->torsion;
  const auto& b = *outcome_->bending;
  const auto args = rt::bicycleForkCliArguments(outcome_->bicycleInput);
  nlohmann::json inputs = nlohmann::json::object();
  for (std::size_t i = 0; i + 1 < args.size(); i += 2) inputs[args[i].substr(2)] = std::stod(args[i + 1]);
  nlohmann::json j{{"fork", "bicycle"},
                   {"inputs", inputs},
                   {"torsion",
                    {{"inertia_with_wheel_kgm2", t.inertiaWithWheel},
                     {"inertia_alone_kgm2", t.inertiaAlone},
                     {"stiffness_with_wheel_Nm_per_rad", t.stiffnessWithWheel},
                     {"stiffness_alone_Nm_per_rad", t.stiffnessAlone},
                     {"damping_Nms_per_rad", t.damping}}},
                   {"bending",
                    {{"bend_arm_hW_m", b.bendArm},
                     {"stiffness_Nm_per_rad", b.stiffness},
                     {"inertia_with_wheel_kgm2", b.inertiaWithWheel},
                     {"damping_Nms_per_rad", b.damping}}}};
  return keep(tr("Bicycle fork stiffness and damping"), "bicycle-fork", j.dump(), 0);
}

}  // namespace views
}  // namespace mozzi
