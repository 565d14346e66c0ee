#include "views/campaign/hammer_station_page.h"

#include <qwt_legend.h>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_grid.h>
#include <qwt_text.h>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QFont>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QProgressBar>
#include <QSplitter>
#include <QStackedWidget>
#include <QTableWidget>
#include <QTime>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>
#include <initializer_list>

#include "core/geometry/mode_shape.h"
#include "devices/campaign/campaign_store.h"
#include "devices/common/driver.h"
#include "views/campaign/campaign_session.h"
#include "views/campaign/campaign_wizard.h"
#include "views/common/dof_text.h"
#include "views/plots/frf_plot.h"
#include "views/plots/interactive_plot.h"
#include "views/plots/plot_export.h"
#include "views/plots/vector_series.h"
#include "views/scene/scene_view.h"

namespace mozzi {
namespace views {

namespace cp = devices::campaign;

namespace {

constexpr int kRefreshMs = 40;                   // 25 Hz traces
constexpr int kSpecimenRole = Qt::UserRole + 1;  // campaign list: the campaign's specimen

QString stateName(cp::EngineState state) {
  switch (state) {
    case cp::EngineState::Idle: return HammerStationPage::tr("Idle: press A to arm");
    case cp::EngineState::Armed: return HammerStationPage::tr("Armed: hit the point");
    case cp::EngineState::Recording: return HammerStationPage::tr("Recording the hit");
    case cp::EngineState::VerdictPending: return HammerStationPage::tr("Verdict: Space accepts, Backspace rejects");
    case cp::EngineState::PointDone: return HammerStationPage::tr("Point done");
    case cp::EngineState::WaitingForDevice: return HammerStationPage::tr("Waiting for the device");
    case cp::EngineState::Finished: return HammerStationPage::tr("Campaign finished");
  }
  return QString();
}

// Axis titles in the page's normal font (Qwt's default is large and bold:
// too big for the traces at 1280x800).
void setAxisText(QwtPlot* plot, int axis, const QString& text) {
  QwtText title(text);
  // On one line: wrapped at a word break, a unit splits ("Response [m/" over "s^2]").
  title.setRenderFlags(Qt::AlignCenter);
  QFont f = plot->font();
  f.setBold(false);
  title.setFont(f);
  plot->setAxisTitle(axis, title);
}

std::shared_ptr<const core::Vector> column(const std::vector<std::shared_ptr<const core::Matrix>>& blocks,
                                           Eigen::Index channel) {
  Eigen::Index n = 0;
  for (const auto& b : blocks) n += b->rows();
  auto out = std::make_shared<core::Vector>(n);
  Eigen::Index k = 0;
  for (const auto& b : blocks) {
    if (channel < b->cols())
      out->segment(k, b->rows()) = b->col(channel);
    else
      out->segment(k, b->rows()).setZero();
    k += b->rows();
  }
  return out;
}

}  // namespace

HammerStationPage::HammerStationPage(const PageContext& ctx) : QWidget(ctx.parent), ctx_(ctx) {
  session_ = new CampaignSession(ctx.model, this);

  // --- top: campaign, start/stop, station -------------------------------------
  auto* top = new QHBoxLayout;
  campaigns_ = new QComboBox(this);
  campaigns_->setObjectName(QStringLiteral("hammerCampaigns"));
  campaigns_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  campaigns_->setMinimumContentsLength(24);
  top->addWidget(campaigns_, 1);
  autoArm_ = new QCheckBox(this);
  autoArm_->setObjectName(QStringLiteral("hammerAutoArm"));
  autoArm_->setChecked(true);
  autoArm_->setFocusPolicy(Qt::NoFocus);

  auto addAction = [this](const QString& name, const char* text, const QKeySequence& key, auto slot) {
    auto* a = new QAction(this);
    a->setObjectName(name);
    a->setShortcut(key);
    a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    QWidget::addAction(a);
    connect(a, &QAction::triggered, this, slot);
    auto* b = new QToolButton(this);
    b->setObjectName(name + QStringLiteral("Button"));
    b->setDefaultAction(a);
    b->setToolButtonStyle(Qt::ToolButtonTextOnly);
    b->setFocusPolicy(Qt::NoFocus);
    b->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    actions_.push_back(ActionEntry{name, a, b, text});
    return b;
  };
  top->addWidget(addAction(QStringLiteral("newCampaign"), QT_TR_NOOP("New Campaign..."),
                           QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_N), [this] { newCampaign(); }));
  top->addWidget(
      addAction(QStringLiteral("start"), QT_TR_NOOP("Start"), QKeySequence(Qt::Key_F5), [this] { startCampaign(); }));
  top->addWidget(addAction(QStringLiteral("stop"), QT_TR_NOOP("Stop"), QKeySequence(Qt::SHIFT | Qt::Key_F5),
                           [this] { stopCampaign(); }));
  top->addWidget(autoArm_);

  // --- verdict row --------------------------------------------------------------
  verdict_ = new QLabel(this);
  verdict_->setObjectName(QStringLiteral("hammerVerdict"));
  QFont big = verdict_->font();
  big.setPointSizeF(big.pointSizeF() * 2.4);
  big.setBold(true);
  verdict_->setFont(big);
  verdict_->setAlignment(Qt::AlignCenter);
  verdict_->setWordWrap(true);
  // Fixed heights: a new verdict must not relayout the page (and so re-render
  // every plot) while a campaign runs.
  verdict_->setFixedHeight(QFontMetrics(big).lineSpacing() * 2 + 12);
  verdict_->setAutoFillBackground(true);
  verdictDetail_ = new QLabel(this);
  verdictDetail_->setObjectName(QStringLiteral("hammerVerdictDetail"));
  verdictDetail_->setAlignment(Qt::AlignCenter);
  verdictDetail_->setWordWrap(true);
  verdictDetail_->setFixedHeight(QFontMetrics(font()).lineSpacing() * 2 + 4);
  trigger_ = new QLabel(this);
  trigger_->setObjectName(QStringLiteral("hammerTrigger"));
  trigger_->setAlignment(Qt::AlignCenter);
  trigger_->setMinimumWidth(QFontMetrics(font()).horizontalAdvance(QStringLiteral("TRIGGERED")) + 24);
  trigger_->setAutoFillBackground(true);
  stateLabel_ = new QLabel(this);
  stateLabel_->setObjectName(QStringLiteral("hammerState"));
  stateLabel_->setWordWrap(true);
  stateLabel_->setFixedHeight(QFontMetrics(font()).lineSpacing() * 2 + 4);
  station_ = new QLabel(this);
  station_->setObjectName(QStringLiteral("hammerStation"));
  station_->setWordWrap(true);
  station_->setFixedHeight(QFontMetrics(font()).lineSpacing() * 2 + 4);
  banner_ = new QLabel(this);
  banner_->setObjectName(QStringLiteral("hammerBanner"));
  banner_->setWordWrap(true);
  banner_->setStyleSheet(QStringLiteral("QLabel { background: #fde2c8; color: #5a2d00; padding: 4px; }"));
  banner_->hide();

  auto* status = new QVBoxLayout;
  auto* lampRow = new QHBoxLayout;
  lampRow->addWidget(trigger_);
  lampRow->addWidget(stateLabel_, 1);
  status->addLayout(lampRow);
  status->addWidget(station_);
  auto* verdictBox = new QVBoxLayout;
  verdictBox->addWidget(verdict_);
  verdictBox->addWidget(verdictDetail_);
  auto* verdictRow = new QHBoxLayout;
  verdictRow->addLayout(verdictBox, 3);
  verdictRow->addLayout(status, 1);

  // --- left: traces and the point's running FRF ---------------------------------
  auto* left = new QWidget(this);
  auto* leftLayout = new QVBoxLayout(left);
  leftLayout->setContentsMargins(0, 0, 0, 0);
  auto* traceBar = new QHBoxLayout;
  pointTitle_ = new QLabel(left);
  pointTitle_->setObjectName(QStringLiteral("hammerPointTitle"));
  QFont bold = pointTitle_->font();
  bold.setBold(true);
  pointTitle_->setFont(bold);
  responseLabel_ = new QLabel(left);
  responseChannel_ = new QComboBox(left);
  responseChannel_->setObjectName(QStringLiteral("hammerResponseChannel"));
  responseChannel_->setFocusPolicy(Qt::NoFocus);
  traceBar->addWidget(pointTitle_, 1);
  traceBar->addWidget(responseLabel_);
  traceBar->addWidget(responseChannel_);
  leftLayout->addLayout(traceBar);
  traces_ = new QwtPlot(left);
  traces_->setObjectName(QStringLiteral("hammerTraces"));
  traces_->setCanvasBackground(Qt::white);
  traces_->enableAxis(QwtPlot::yRight, true);
  traces_->setMinimumHeight(190);
  auto* grid = new QwtPlotGrid;
  grid->setMajorPen(QColor(0, 0, 0, 40), 0.0, Qt::DotLine);
  grid->attach(traces_);
  forceCurve_ = new QwtPlotCurve;
  forceCurve_->setPen(QColor(29, 53, 87), 1.2);
  forceCurve_->attach(traces_);
  responseCurve_ = new QwtPlotCurve;
  responseCurve_->setPen(QColor(230, 57, 70), 1.0);
  responseCurve_->setYAxis(QwtPlot::yRight);
  responseCurve_->attach(traces_);
  traces_->insertLegend(new QwtLegend, QwtPlot::TopLegend);
  installPlotExportAction(traces_);
  frf_ = new FrfPlot(left);
  frf_->setObjectName(QStringLiteral("hammerFrf"));
  frf_->setView(FrfPlot::View::Magnitude);  // magnitude and coherence: what decides whether a point is good
  // The page's normal font for the FRF's axis titles too (FrfPlot sets
  // their text later; Qwt keeps the font).
  for (QwtPlot* plot : std::initializer_list<QwtPlot*>{frf_->magnitudePlot(), frf_->coherencePlot()})
    for (int axis : {QwtPlot::yLeft, QwtPlot::xBottom}) setAxisText(plot, axis, plot->axisTitle(axis).text());
  frf_->setMinimumHeight(220);
  leftLayout->addWidget(traces_, 2);
  // The FRF and a hint in one stack: switching between them does not
  // relayout the page.
  frfHint_ = new QLabel(left);
  frfHint_->setObjectName(QStringLiteral("hammerFrfHint"));
  frfHint_->setAlignment(Qt::AlignCenter);
  frfHint_->setWordWrap(true);
  frfStack_ = new QStackedWidget(left);
  frfStack_->addWidget(frfHint_);
  frfStack_->addWidget(frf_);
  leftLayout->addWidget(frfStack_, 3);
  frfStack_->setMinimumHeight(280);  // magnitude and coherence readable at 1280x800

  // --- right: progress over the mesh, actions, log --------------------------------
  auto* right = new QWidget(this);
  auto* rightLayout = new QVBoxLayout(right);
  rightLayout->setContentsMargins(0, 0, 0, 0);
  progressLabel_ = new QLabel(right);
  progressLabel_->setObjectName(QStringLiteral("hammerProgressText"));
  progressLabel_->setWordWrap(true);
  progressLabel_->setFixedHeight(QFontMetrics(font()).lineSpacing() * 2 + 4);
  progress_ = new QProgressBar(right);
  progress_->setObjectName(QStringLiteral("hammerProgress"));
  progress_->setRange(0, 1000);
  progress_->setValue(0);
  points_ = new QTableWidget(0, 4, right);
  points_->setObjectName(QStringLiteral("hammerPoints"));
  points_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  points_->setSelectionBehavior(QAbstractItemView::SelectRows);
  points_->setSelectionMode(QAbstractItemView::SingleSelection);
  points_->verticalHeader()->setVisible(false);
  points_->horizontalHeader()->setStretchLastSection(true);
  for (int c = 0; c < 3; ++c) points_->horizontalHeader()->setSectionResizeMode(c, QHeaderView::ResizeToContents);
  points_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  points_->setWordWrap(false);
  points_->setTextElideMode(Qt::ElideRight);
  points_->setFocusPolicy(Qt::NoFocus);
  points_->setMinimumHeight(140);
  // The mesh above the table: the point to hit next is marked on it, the
  // arrow giving the hammer's direction.
  scene_ = new SceneView(right);
  scene_->setObjectName(QStringLiteral("hammerScene"));
  scene_->setMinimumHeight(170);
  scene_->setLabelsVisible(true);
  auto* meshAndPoints = new QSplitter(Qt::Vertical, right);
  meshAndPoints->setObjectName(QStringLiteral("hammerMeshSplit"));
  meshAndPoints->addWidget(scene_);
  meshAndPoints->addWidget(points_);
  meshAndPoints->setStretchFactor(0, 3);
  meshAndPoints->setStretchFactor(1, 2);
  meshAndPoints->setChildrenCollapsible(false);
  rightLayout->addWidget(progressLabel_);
  rightLayout->addWidget(progress_);
  rightLayout->addWidget(meshAndPoints, 3);

  auto* buttons = new QGridLayout;
  buttons->addWidget(
      addAction(QStringLiteral("arm"), QT_TR_NOOP("Arm"), QKeySequence(Qt::Key_A), [this] { session_->arm(); }), 0, 0);
  buttons->addWidget(addAction(QStringLiteral("disarm"), QT_TR_NOOP("Disarm"), QKeySequence(Qt::Key_Escape),
                               [this] { session_->disarm(); }),
                     0, 1);
  buttons->addWidget(addAction(QStringLiteral("accept"), QT_TR_NOOP("Accept"), QKeySequence(Qt::Key_Space),
                               [this] { session_->accept(); }),
                     1, 0);
  buttons->addWidget(addAction(QStringLiteral("reject"), QT_TR_NOOP("Reject"), QKeySequence(Qt::Key_Backspace),
                               [this] { session_->reject(); }),
                     1, 1);
  buttons->addWidget(
      addAction(QStringLiteral("redo"), QT_TR_NOOP("Redo Point"), QKeySequence(Qt::Key_R), [this] { doRedo(); }), 2, 0);
  buttons->addWidget(
      addAction(QStringLiteral("skip"), QT_TR_NOOP("Skip Point"), QKeySequence(Qt::Key_S), [this] { doSkip(); }), 2, 1);
  for (auto& e : actions_) {
    if (e.name == QLatin1String("accept") || e.name == QLatin1String("reject")) {
      QFont f = e.button->font();
      f.setPointSizeF(f.pointSizeF() * 1.4);
      f.setBold(true);
      e.button->setFont(f);
    }
  }
  skipReason_ = new QLineEdit(right);
  skipReason_->setObjectName(QStringLiteral("hammerSkipReason"));
  skipReason_->setClearButtonEnabled(true);
  connect(skipReason_, &QLineEdit::returnPressed, this, [this] { doSkip(); });
  rightLayout->addLayout(buttons);
  rightLayout->addWidget(skipReason_);
  log_ = new QListWidget(right);
  log_->setObjectName(QStringLiteral("hammerLog"));
  log_->setFocusPolicy(Qt::NoFocus);
  log_->setMinimumHeight(60);
  log_->setWordWrap(true);
  log_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  rightLayout->addWidget(log_, 1);

  auto* split = new QSplitter(Qt::Horizontal, this);
  split->addWidget(left);
  split->addWidget(right);
  split->setStretchFactor(0, 3);
  split->setStretchFactor(1, 2);
  split->setChildrenCollapsible(false);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(top);
  layout->addWidget(banner_);
  layout->addLayout(verdictRow);
  layout->addWidget(split, 1);
  setFocusPolicy(Qt::StrongFocus);

  // --- wiring ------------------------------------------------------------------
  connect(session_, &CampaignSession::verdictReady, this, &HammerStationPage::onVerdict);
  connect(session_, &CampaignSession::hitCommitted, this, &HammerStationPage::onCommitted);
  connect(session_, &CampaignSession::runningFrf, this, &HammerStationPage::onRunningFrf);
  connect(session_, &CampaignSession::progressChanged, this, &HammerStationPage::onProgress);
  connect(session_, &CampaignSession::stateChanged, this, &HammerStationPage::onState);
  connect(session_, &CampaignSession::finished, this, &HammerStationPage::onFinished);
  connect(session_, &CampaignSession::engineError, this, [this](const QString& message) {
    showBanner(message);
    log(message);
  });
  connect(session_, &CampaignSession::stopped, this, [this] {
    state_.reset();
    updateActions();
  });
  connect(ctx_.model, &ProjectModel::projectChanged, this, [this] {
    sceneMesh_.reset();  // another project: its specimen ids name other meshes
    reloadCampaigns();
    updateActions();
  });
  connect(ctx_.model, &ProjectModel::campaignsChanged, this, [this] { reloadCampaigns(); });
  connect(ctx_.model, &ProjectModel::meshChanged, this, [this](qint64 specimenId) {
    if (specimenId == sceneSpecimen_ || specimenId == 0) {
      sceneMesh_.reset();
      showSpecimenMesh();
    }
  });
  connect(campaigns_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] {
    updateActions();
    showSpecimenMesh();
  });
  connect(points_, &QTableWidget::itemSelectionChanged, this, [this] { updateActions(); });
  connect(responseChannel_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] {
    shownGeneration_ = 0;
    retranslate();
  });

  refresh_ = new QTimer(this);
  refresh_->setInterval(kRefreshMs);
  connect(refresh_, &QTimer::timeout, this, &HammerStationPage::refreshTraces);
  refresh_->start();

  reloadCampaigns();
  if (ctx.item.kind == RecordKind::Campaign) showCampaign(ctx.item.id);
  setVerdict(QString(), QString(), QString());
  retranslate();
  updateActions();
}

HammerStationPage::~HammerStationPage() {
  session_->stop();
}

QAction* HammerStationPage::action(const QString& name) const {
  for (const auto& e : actions_)
    if (e.name == name) return e.action;
  return nullptr;
}

qint64 HammerStationPage::selectedCampaign() const {
  return campaigns_->currentData().toLongLong();
}

QString HammerStationPage::verdictText() const {
  return verdict_->text();
}
QString HammerStationPage::stateText() const {
  return stateLabel_->text();
}
QString HammerStationPage::bannerText() const {
  return banner_->isVisible() ? banner_->text() : QString();
}

void HammerStationPage::reloadCampaigns() {
  const qint64 keep = selectedCampaign();
  const QSignalBlocker block(campaigns_);
  campaigns_->clear();
  core::io::ProjectStore* store = ctx_.model->store();
  if (store) {
    auto summary = store->summary();
    if (summary) {
      for (const auto& specimen : summary->specimens) {
        auto list = store->campaigns(specimen.id);
        if (!list) continue;
        for (const auto& c : *list) {
          campaigns_->addItem(tr("%1 (%2)").arg(QString::fromStdString(c.name), QString::fromStdString(specimen.name)),
                              QVariant::fromValue<qlonglong>(c.id));
          campaigns_->setItemData(campaigns_->count() - 1, QVariant::fromValue<qlonglong>(specimen.id), kSpecimenRole);
        }
      }
    }
  }
  const int index = campaigns_->findData(QVariant::fromValue<qlonglong>(keep));
  if (index >= 0) campaigns_->setCurrentIndex(index);
  updateActions();
  showSpecimenMesh();
}

void HammerStationPage::showSpecimenMesh() {
  const qint64 specimen = campaigns_->currentData(kSpecimenRole).toLongLong();
  if (specimen == sceneSpecimen_ && sceneMesh_) return;
  sceneSpecimen_ = specimen;
  sceneMesh_.reset();
  // A specimen without a mesh clears the view: the table alone shows the points.
  views::ShownMesh shown = views::showStoredMesh(*scene_, ctx_.model->store(), specimen);
  if (!shown.mesh) return;
  sceneMesh_.emplace();
  sceneMesh_->mesh = std::move(*shown.mesh);
  updateHitMarker();
}

void HammerStationPage::updateHitMarker() {
  const std::optional<int> current = lastProgress_ ? lastProgress_->current : std::nullopt;
  if (!sceneMesh_ || !current || *current < 0 || *current >= static_cast<int>(lastProgress_->points.size())) {
    scene_->setHitMarker(std::nullopt);
    return;
  }
  const core::Dof dof = lastProgress_->points[static_cast<std::size_t>(*current)].dof;
  // The DOF's direction in global axes: the shape of a unit value at that DOF
  // alone (core/geometry/mode_shape.h resolves the node's displacement system).
  core::Vector3 strike = core::Vector3::Zero();
  core::geometry::FieldOptions alone;
  alone.interpolate = false;
  auto field = core::geometry::shapeField(*sceneMesh_, {dof}, core::ComplexVector::Ones(1), alone);
  if (field) {
    const auto& nodes = sceneMesh_->mesh.nodes;
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (nodes[i].label == dof.node) strike = field->u.row(static_cast<Eigen::Index>(i)).real().transpose();
  }
  // The point's DOF beside the marker, as the point table names it.
  scene_->setHitMarker(dof.node, strike, tr("Next: %1").arg(dofText(dof)));
}

void HammerStationPage::showCampaign(qint64 campaignId) {
  reloadCampaigns();
  const int index = campaigns_->findData(QVariant::fromValue<qlonglong>(campaignId));
  if (index >= 0) campaigns_->setCurrentIndex(index);
  updateActions();
}

bool HammerStationPage::startCampaign() {
  const qint64 id = selectedCampaign();
  core::io::ProjectStore* store = ctx_.model->store();
  if (!store || id == 0) {
    showBanner(tr("Choose a campaign first, or make one with New Campaign (Ctrl+Shift+N)."));
    return false;
  }
  if (session_->isRunning() && session_->campaignId() == id) return true;
  auto loaded = cp::loadCampaign(*store, id);
  if (!loaded) {
    showBanner(tr("Cannot open the campaign: %1").arg(QString::fromStdString(loaded.error().describe())));
    return false;
  }
  const cp::CampaignDefinition& def = loaded->definition;
  cp::EngineOptions options;
  options.autoArm = autoArm_->isChecked();
  auto station = cp::makeDriverStation(devices::builtinDrivers(), def.driver, def.deviceSerial);
  auto started = session_->start(id, std::move(station), options);
  if (!started) {
    showBanner(tr("Cannot start the campaign: %1").arg(QString::fromStdString(started.error().describe())));
    return false;
  }
  banner_->hide();
  forceChannel_ = std::max(0, def.forceChannel());
  const QSignalBlocker block(responseChannel_);
  responseChannel_->clear();
  responseChannels_.clear();
  responseUnits_.clear();
  for (std::size_t c = 0; c < def.channels.size(); ++c) {
    if (static_cast<int>(c) == forceChannel_) continue;
    responseChannels_.push_back(static_cast<int>(c));
    responseChannel_->addItem(QString::fromStdString(def.channels[c].name));
    responseUnits_ << QString::fromStdString(def.channels[c].transducer.unit);
  }
  setAxisText(traces_, QwtPlot::yLeft,
              tr("Force [%1]")
                  .arg(QString::fromStdString(def.channels[static_cast<std::size_t>(forceChannel_)].transducer.unit)));
  frf_->setFrfs(nullptr);
  frfStack_->setCurrentWidget(frfHint_);
  showingRecord_ = false;
  log(tr("Campaign started on %1").arg(QString::fromStdString(def.driver)));
  retranslate();
  updateActions();
  setFocus();  // the keys act on the page, not on a field that had the focus
  return true;
}

void HammerStationPage::stopCampaign() {
  if (!session_->isRunning()) return;
  session_->stop();
  log(tr("Campaign stopped; every decided hit is in the project"));
  stateLabel_->setText(tr("Stopped"));
  updateActions();
}

CampaignWizard* HammerStationPage::newCampaign() {
  if (wizard_) {
    wizard_->raise();
    return wizard_;
  }
  if (!ctx_.model->store()) {
    showBanner(tr("Open or create a project first."));
    return nullptr;
  }
  wizard_ = new CampaignWizard(ctx_.model, this);
  wizard_->setAttribute(Qt::WA_DeleteOnClose);
  connect(wizard_, &CampaignWizard::campaignCreated, this, [this](qint64 id) {
    showCampaign(id);
    log(tr("New campaign %1 created").arg(campaigns_->currentText()));
  });
  wizard_->show();
  return wizard_;
}

int HammerStationPage::selectedPoint() const {
  const auto rows = points_->selectionModel() ? points_->selectionModel()->selectedRows() : QModelIndexList();
  if (!rows.isEmpty()) return rows.first().row();
  return current_.value_or(-1);
}

void HammerStationPage::doSkip() {
  if (!session_->isRunning() || !current_) return;
  const QString reason = skipReason_->text().trimmed();
  if (reason.isEmpty()) {
    showBanner(tr("Type why the point is skipped in the reason box, then press Enter."));
    skipReason_->setFocus();
    return;
  }
  session_->skip(*current_, reason);
  log(tr("Point %1 skipped: %2").arg(*current_ + 1).arg(reason));
  skipReason_->clear();
  setFocus();
}

void HammerStationPage::doRedo() {
  if (!session_->isRunning()) return;
  const int point = selectedPoint();
  if (point < 0) return;
  session_->redo(point, skipReason_->text().trimmed());
  log(tr("Point %1 to be measured again").arg(point + 1));
  skipReason_->clear();
}

void HammerStationPage::updateActions() {
  const bool running = session_->isRunning();
  const bool open = ctx_.model->store() != nullptr;
  const auto s = state_.value_or(cp::EngineState::Finished);
  const auto enable = [this](const char* name, bool on) {
    if (QAction* a = action(QLatin1String(name))) a->setEnabled(on);
  };
  enable("newCampaign", open && !running);
  enable("start", open && !running && selectedCampaign() != 0);
  enable("stop", running);
  enable("arm", running && (s == cp::EngineState::Idle || s == cp::EngineState::PointDone));
  enable("disarm", running && (s == cp::EngineState::Armed || s == cp::EngineState::Recording));
  enable("accept", running && s == cp::EngineState::VerdictPending);
  enable("reject", running && s == cp::EngineState::VerdictPending);
  enable("redo",
         running && s != cp::EngineState::Recording && s != cp::EngineState::VerdictPending && selectedPoint() >= 0);
  enable("skip", running && current_.has_value() &&
                     (s == cp::EngineState::Idle || s == cp::EngineState::Armed || s == cp::EngineState::PointDone));
  campaigns_->setEnabled(!running);
  autoArm_->setEnabled(!running);
}

void HammerStationPage::showBanner(const QString& text) {
  banner_->setText(text);
  banner_->show();
}

void HammerStationPage::log(const QString& text) {
  log_->addItem(QStringLiteral("%1  %2").arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss")), text));
  while (log_->count() > 500) delete log_->takeItem(0);
  log_->scrollToBottom();
  if (ctx_.log) ctx_.log(tr("Hammer station: %1").arg(text));
}

void HammerStationPage::setVerdict(const QString& headline, const QString& detail, const QString& colour) {
  verdictHeadline_ = headline;
  verdict_->setText(headline.isEmpty() ? QStringLiteral(" ") : headline);
  verdictDetail_->setText(detail);
  QPalette p = verdict_->palette();
  p.setColor(QPalette::Window, colour.isEmpty() ? palette().color(QPalette::Window) : QColor(colour));
  p.setColor(QPalette::WindowText, colour.isEmpty() ? palette().color(QPalette::WindowText) : QColor(Qt::white));
  verdict_->setPalette(p);
}

void HammerStationPage::refreshTraces() {
  // The trigger lamp follows the engine's state and the live stream.
  const LiveSnapshot live = session_->liveSnapshot();
  const bool triggered =
      state_ && (*state_ == cp::EngineState::Recording || (*state_ == cp::EngineState::Armed && live.triggered));
  const bool armed = state_ && *state_ == cp::EngineState::Armed;
  QPalette p = trigger_->palette();
  p.setColor(QPalette::Window, triggered ? QColor(214, 40, 40) : armed ? QColor(244, 162, 97) : QColor(200, 200, 200));
  p.setColor(QPalette::WindowText, triggered ? Qt::white : Qt::black);
  trigger_->setPalette(p);
  trigger_->setText(triggered ? tr("TRIGGERED") : armed ? tr("ARMED") : tr("TRIGGER"));

  if (showingRecord_ || live.generation == shownGeneration_ || live.blocks.empty() || live.sampleRateHz <= 0.0) return;
  shownGeneration_ = live.generation;
  const auto force = column(live.blocks, forceChannel_);
  const int r = responseChannel_->currentIndex();
  const int responseColumn = r >= 0 && r < static_cast<int>(responseChannels_.size()) ? responseChannels_[r] : -1;
  auto time = std::make_shared<core::Vector>(force->size());
  for (Eigen::Index i = 0; i < time->size(); ++i)
    (*time)[i] = static_cast<double>(live.firstSample + i) / live.sampleRateHz;
  forceCurve_->setData(new VectorSeries(time, force));
  if (responseColumn >= 0) responseCurve_->setData(new VectorSeries(time, column(live.blocks, responseColumn)));
  setAxisText(traces_, QwtPlot::xBottom, tr("Time since arming [s]"));
  traces_->replot();
  ++traceRefreshes_;
}

void HammerStationPage::showRecordTraces(const core::signal::TimeRecord& record) {
  if (record.sampleRateHz <= 0.0 || record.samples.rows() == 0) return;
  showingRecord_ = true;
  const Eigen::Index n = record.samples.rows();
  auto time = std::make_shared<core::Vector>(n);
  for (Eigen::Index i = 0; i < n; ++i) (*time)[i] = static_cast<double>(i) / record.sampleRateHz;
  auto force = std::make_shared<core::Vector>(
      record.samples.col(std::min<Eigen::Index>(forceChannel_, record.samples.cols() - 1)));
  forceCurve_->setData(new VectorSeries(time, force));
  const int r = responseChannel_->currentIndex();
  if (r >= 0 && r < static_cast<int>(responseChannels_.size()) && responseChannels_[r] < record.samples.cols())
    responseCurve_->setData(
        new VectorSeries(time, std::make_shared<core::Vector>(record.samples.col(responseChannels_[r]))));
  setAxisText(traces_, QwtPlot::xBottom, tr("Time in the hit's record [s]"));
  traces_->replot();
  ++traceRefreshes_;
}

void HammerStationPage::onState(cp::EngineState state, const QString& message) {
  const bool newArm = state == cp::EngineState::Armed && state_ != cp::EngineState::Armed;
  state_ = state;
  stateLabel_->setText(stateName(state));
  if (newArm) {
    showingRecord_ = false;
    shownGeneration_ = 0;
    setVerdict(tr("ARMED"), tr("Hit point %1").arg(current_ ? QString::number(*current_ + 1) : QString()),
               QStringLiteral("#b86f00"));
  }
  if (state == cp::EngineState::WaitingForDevice) {
    showBanner(message.isEmpty() ? tr("The device went away; the campaign goes on when it is back.") : message);
    QApplication::beep();
  }
  if (!message.isEmpty() && state != cp::EngineState::WaitingForDevice) log(message);
  updateActions();
}

void HammerStationPage::onVerdict(const cp::HitVerdictEvent& v) {
  if (v.record) showRecordTraces(*v.record);
  QStringList details;
  details << tr("Point %1 (%2), hit attempt %3").arg(v.position + 1).arg(dofText(v.point)).arg(v.attempt + 1);
  for (const auto& note : v.verdict.notes) details << QString::fromStdString(note);
  if (v.verdict.meanCoherence) details << tr("mean coherence %1").arg(*v.verdict.meanCoherence, 0, 'f', 3);
  if (v.verdict.passed) {
    setVerdict(tr("GOOD HIT — Space accepts"), details.join(QStringLiteral("; ")), QStringLiteral("#2a7f3f"));
    QApplication::beep();
  } else {
    QStringList reasons;
    for (const auto& reason : v.verdict.reasons) reasons << QString::fromStdString(reason);
    setVerdict(tr("REJECT: %1").arg(reasons.join(QStringLiteral(", "))),
               tr("Backspace rejects, Space keeps it anyway. %1").arg(details.join(QStringLiteral("; "))),
               QStringLiteral("#b3261e"));
    QApplication::beep();
    QTimer::singleShot(180, this, [] { QApplication::beep(); });  // two beeps: look at the screen
  }
  updateActions();
}

void HammerStationPage::onCommitted(const cp::CommittedHitEvent& hit) {
  const QString reasons = QString::fromStdString(hit.reasons);
  if (hit.accepted) {
    setVerdict(tr("ACCEPTED"),
               tr("Hit %1 stored at point %2 (%3)").arg(hit.hitId).arg(hit.position + 1).arg(dofText(hit.point)),
               QStringLiteral("#2a7f3f"));
    log(tr("Point %1: hit %2 accepted").arg(hit.position + 1).arg(hit.hitId));
  } else {
    setVerdict(tr("REJECTED"), reasons, QStringLiteral("#6d6d6d"));
    log(tr("Point %1: hit %2 rejected (%3)").arg(hit.position + 1).arg(hit.hitId).arg(reasons));
  }
}

void HammerStationPage::onRunningFrf(const cp::RunningFrfEvent& e) {
  if (!e.frf) return;
  const int response = std::max(0, frf_->currentResponse());
  const int reference = std::max(0, frf_->currentReference());
  frf_->setFrfs(e.frf);
  frfStack_->setCurrentWidget(frf_);
  frf_->showPair(response, reference);
  // Short axis titles: the FRF shares the column with the traces.
  setAxisText(frf_->magnitudePlot(), QwtPlot::yLeft, tr("|H| [dB]"));
  setAxisText(frf_->coherencePlot(), QwtPlot::yLeft, tr("Coh."));
  pointTitle_->setText(tr("Point %1 (%2): running FRF of %n accepted hit(s)", nullptr, e.hits)
                           .arg(e.position + 1)
                           .arg(dofText(e.point)));
}

void HammerStationPage::onProgress(const cp::EngineProgress& p) {
  const bool pointChanged = p.current != current_;
  lastProgress_ = p;
  current_ = p.current;
  if (pointChanged) updateHitMarker();
  state_ = p.state;
  station_->setText(tr("Station: %1").arg(QString::fromStdString(p.device)));
  const auto& s = p.schedule;
  progress_->setValue(static_cast<int>(std::lround(s.fraction() * 1000.0)));
  progress_->setFormat(tr("%1 of %2 points").arg(s.pointsDone + s.pointsSkipped).arg(s.pointCount));
  progressLabel_->setText(tr("%1: %2 done, %3 skipped; %4 hits accepted, %5 rejected")
                              .arg(QString::fromStdString(p.campaignName))
                              .arg(s.pointsDone)
                              .arg(s.pointsSkipped)
                              .arg(s.acceptedHits)
                              .arg(s.rejectedHits));
  if (points_->rowCount() != static_cast<int>(p.points.size())) points_->setRowCount(static_cast<int>(p.points.size()));
  for (const auto& pt : p.points) {
    const int row = pt.position;
    if (row < 0 || row >= points_->rowCount()) continue;
    const bool current = p.current && *p.current == row;
    QString status;
    QColor background;
    if (pt.skipped) {
      status = tr("skipped: %1").arg(QString::fromStdString(pt.skipReason));
      background = QColor(225, 225, 225);
    } else if (pt.done) {
      status = tr("done");
      background = QColor(214, 240, 219);
    } else if (current) {
      status = tr("measuring now");
      background = QColor(255, 221, 87);
    } else {
      status = pt.attempts > 0 ? tr("started") : tr("to do");
    }
    const QStringList cells = {QString::number(row + 1), dofText(pt.dof),
                               tr("%1 / %2").arg(pt.accepted).arg(p.hitsPerPoint), status};
    for (int c = 0; c < cells.size(); ++c) {
      QTableWidgetItem* item = points_->item(row, c);
      if (!item) {
        item = new QTableWidgetItem;
        points_->setItem(row, c, item);
      }
      item->setText(cells[c]);
      item->setBackground(background.isValid() ? QBrush(background) : QBrush());
      QFont f = item->font();
      f.setBold(current);
      item->setFont(f);
      if (c == 3 && pt.attempts > pt.accepted)
        item->setToolTip(tr("%n attempt(s) at this point", nullptr, pt.attempts));
    }
  }
  if (pointChanged && p.current) {
    points_->scrollToItem(points_->item(*p.current, 0), QAbstractItemView::PositionAtCenter);
    if (!showingRecord_) {
      frf_->setFrfs(nullptr);
      frfStack_->setCurrentWidget(frfHint_);
    }
    pointTitle_->setText(tr("Point %1 (%2)").arg(*p.current + 1).arg(dofText(p.points[*p.current].dof)));
  }
  updateActions();
}

void HammerStationPage::onFinished(const cp::FinishedEvent& f) {
  setVerdict(tr("CAMPAIGN COMPLETE"),
             tr("%1 points measured, %2 skipped; FRF set %3 stored with its hits")
                 .arg(f.schedule.pointsDone)
                 .arg(f.schedule.pointsSkipped)
                 .arg(f.frfSetId),
             QStringLiteral("#1d3557"));
  log(tr("Campaign finished: FRF set %1").arg(f.frfSetId));
  QApplication::beep();
  updateActions();
}

void HammerStationPage::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void HammerStationPage::retranslate() {
  for (auto& e : actions_) {
    const QString key = e.action->shortcut().toString(QKeySequence::NativeText);
    e.action->setText(tr("%1 (%2)").arg(tr(e.text), key));
    e.action->setToolTip(e.action->text());
  }
  if (scene_ && sceneMesh_) updateHitMarker();  // the marker's "Next: ..." in the new language
  autoArm_->setText(tr("Arm again after each decision"));
  autoArm_->setToolTip(tr("Applies when the campaign starts"));
  responseLabel_->setText(tr("Response:"));
  skipReason_->setPlaceholderText(tr("Reason for Skip or Redo"));
  skipReason_->setToolTip(tr("Type the reason, then S skips the current point or R measures the selected point again"));
  points_->setHorizontalHeaderLabels({tr("Point"), tr("DOF"), tr("Hits"), tr("Status")});
  traces_->setTitle(QString());
  forceCurve_->setTitle(tr("Force"));
  responseCurve_->setTitle(responseChannel_->currentText().isEmpty() ? tr("Response")
                                                                     : responseChannel_->currentText());
  {
    const int r = responseChannel_->currentIndex();
    const QString unit = r >= 0 && r < responseUnits_.size() ? responseUnits_[r] : tr("EU");
    // The unit alone: the legend names the response, and "Response [m/s^2]"
    // is longer than the traces are high at 1280x800.
    setAxisText(traces_, QwtPlot::yRight, tr("[%1]", "right axis of the hit traces: the response's unit").arg(unit));
  }
  if (traces_->axisTitle(QwtPlot::yLeft).isEmpty()) setAxisText(traces_, QwtPlot::yLeft, tr("Force [N]"));
  if (traces_->axisTitle(QwtPlot::xBottom).isEmpty())
    setAxisText(traces_, QwtPlot::xBottom, tr("Time since arming [s]"));
  if (!state_) stateLabel_->setText(session_->isRunning() ? QString() : tr("Not started: choose a campaign, press F5"));
  if (station_->text().isEmpty()) station_->setText(tr("Station: not connected"));
  frfHint_->setText(tr("The running FRF and coherence of the point appear after its first accepted hit."));
  if (pointTitle_->text().isEmpty()) pointTitle_->setText(tr("No point yet"));
  if (verdictHeadline_.isEmpty()) verdictDetail_->setText(tr("The verdict of each hit appears here."));
}

}  // namespace views
}  // namespace mozzi
