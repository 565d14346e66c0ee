// The rig test page's set-up panel: the rig's set-up for the chosen specimen,
// the stiffness rig's set-up form and its sketch over the specimen's outline.

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

#include "views/rigs/rig_test_page_internal.h"

namespace mozzi {
namespace views {

using rig_page::number;
using rig_page::qs;

// The stiffness rig's set-up tab: the plate, the lasers, the load point and the
// constrained end over the specimen's silhouette, as the form says. The form
// beside the picture, so the run controls on the left stay in view.
QWidget* RigTestPage::buildSetupView() {
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
  setupPlot_->setMinimumSize(rig_page::kPlotMinWidth, rig_page::kPlotMinHeight);
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
  return view;
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

}  // namespace views
}  // namespace mozzi
