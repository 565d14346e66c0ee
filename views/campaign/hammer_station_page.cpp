// The hammer-station page: its widgets, and the campaign controls (start,
// stop, new campaign, skip and redo). The session's events, the traces and the
// verdict: hammer_station_events.cpp.

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
#include "views/campaign/hammer_station_internal.h"
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

}  // namespace

using hammer_station::setAxisText;

HammerStationPage::HammerStationPage(const PageContext& ctx) : QWidget(ctx.parent), ctx_(ctx) {
  session_ = new CampaignSession(ctx.model, this);
  auto* top = buildTopBar();
  auto* verdictRow = buildVerdictRow();
  auto* left = buildTracePanel();
  auto* right = buildProgressPanel();

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

  wire();

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

// An action with its key, on a text button; retranslate() names both.
QToolButton* HammerStationPage::addActionButton(const QString& name, const char* text, const QKeySequence& key,
                                                const std::function<void()>& slot) {
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
}

// --- top: campaign, start/stop, station -------------------------------------
QHBoxLayout* HammerStationPage::buildTopBar() {
  auto* top = new QHBoxLayout;
  campaigns_ = new QComboBox(this);
  campaigns_->setObjectName(QStringLiteral("hammerCampaigns"));
  campaigns_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  // 16 characters: with the four actions beside it the bar fits 1280x800
  // with the project dock open (24 made the page wider than the tab area).
  campaigns_->setMinimumContentsLength(16);
  top->addWidget(campaigns_, 1);
  autoArm_ = new QCheckBox(this);
  autoArm_->setObjectName(QStringLiteral("hammerAutoArm"));
  autoArm_->setChecked(true);
  autoArm_->setFocusPolicy(Qt::NoFocus);

  top->addWidget(addActionButton(QStringLiteral("newCampaign"), QT_TR_NOOP("New Campaign..."),
                                 QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_N), [this] { newCampaign(); }));
  top->addWidget(addActionButton(QStringLiteral("start"), QT_TR_NOOP("Start"), QKeySequence(Qt::Key_F5),
                                 [this] { startCampaign(); }));
  top->addWidget(addActionButton(QStringLiteral("stop"), QT_TR_NOOP("Stop"), QKeySequence(Qt::SHIFT | Qt::Key_F5),
                                 [this] { stopCampaign(); }));
  top->addWidget(autoArm_);
  return top;
}

// --- verdict row --------------------------------------------------------------
// The technician's actions beside the verdict they answer (arming, the
// hit's decision, the point), so that the page fits a 1280x800 window: in the
// progress column they took the page to 928 px in a 606 px tab.
QGridLayout* HammerStationPage::buildActionGrid() {
  auto* buttons = new QGridLayout;
  buttons->addWidget(
      addActionButton(QStringLiteral("arm"), QT_TR_NOOP("Arm"), QKeySequence(Qt::Key_A), [this] { session_->arm(); }),
      0, 0);
  buttons->addWidget(addActionButton(QStringLiteral("disarm"), QT_TR_NOOP("Disarm"), QKeySequence(Qt::Key_Escape),
                                     [this] { session_->disarm(); }),
                     1, 0);
  buttons->addWidget(addActionButton(QStringLiteral("accept"), QT_TR_NOOP("Accept"), QKeySequence(Qt::Key_Space),
                                     [this] { session_->accept(); }),
                     0, 1);
  buttons->addWidget(addActionButton(QStringLiteral("reject"), QT_TR_NOOP("Reject"), QKeySequence(Qt::Key_Backspace),
                                     [this] { session_->reject(); }),
                     1, 1);
  buttons->addWidget(
      addActionButton(QStringLiteral("redo"), QT_TR_NOOP("Redo Point"), QKeySequence(Qt::Key_R), [this] { doRedo(); }),
      0, 2);
  buttons->addWidget(
      addActionButton(QStringLiteral("skip"), QT_TR_NOOP("Skip Point"), QKeySequence(Qt::Key_S), [this] { doSkip(); }),
      1, 2);
  for (auto& e : actions_) {
    if (e.name == QLatin1String("accept") || e.name == QLatin1String("reject")) {
      QFont f = e.button->font();
      f.setPointSizeF(f.pointSizeF() * 1.4);
      f.setBold(true);
      e.button->setFont(f);
    }
  }
  skipReason_ = new QLineEdit(this);
  skipReason_->setObjectName(QStringLiteral("hammerSkipReason"));
  skipReason_->setClearButtonEnabled(true);
  connect(skipReason_, &QLineEdit::returnPressed, this, [this] { doSkip(); });
  buttons->addWidget(skipReason_, 2, 0, 1, 3);
  return buttons;
}

QHBoxLayout* HammerStationPage::buildVerdictRow() {
  verdict_ = new QLabel(this);
  verdict_->setObjectName(QStringLiteral("hammerVerdict"));
  QFont big = verdict_->font();
  big.setPointSizeF(big.pointSizeF() * 2.1);
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
  verdictDetail_->setFixedHeight(QFontMetrics(font()).lineSpacing() * 3 + 4);  // a rejection's measures and keys
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

  // The lamp above the state: beside it the state had a third of its column
  // and took three lines in two.
  auto* status = new QVBoxLayout;
  status->addWidget(trigger_);
  status->addWidget(stateLabel_);
  status->addWidget(station_);
  auto* verdictBox = new QVBoxLayout;
  verdictBox->addWidget(verdict_);
  verdictBox->addWidget(verdictDetail_);
  auto* verdictRow = new QHBoxLayout;
  // 3:2:3: at 1280x800 with the project dock open the state ("Not started:
  // choose a campaign, press F5") needs a quarter of the row for two lines.
  verdictRow->addLayout(verdictBox, 3);
  verdictRow->addLayout(status, 2);
  verdictRow->addLayout(buildActionGrid(), 3);
  return verdictRow;
}

// --- left: traces and the point's running FRF ---------------------------------
QWidget* HammerStationPage::buildTracePanel() {
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
  traces_->setMinimumHeight(160);
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
  frf_->setMinimumHeight(190);
  leftLayout->addWidget(traces_, 1);
  // The FRF and a hint in one stack: switching between them does not
  // relayout the page.
  frfHint_ = new QLabel(left);
  frfHint_->setObjectName(QStringLiteral("hammerFrfHint"));
  frfHint_->setAlignment(Qt::AlignCenter);
  frfHint_->setWordWrap(true);
  frfStack_ = new QStackedWidget(left);
  frfStack_->addWidget(frfHint_);
  frfStack_->addWidget(frf_);
  leftLayout->addWidget(frfStack_, 1);
  frfStack_->setMinimumHeight(200);  // magnitude and coherence readable at 1280x800
  return left;
}

// --- right: progress over the mesh, actions, log --------------------------------
QWidget* HammerStationPage::buildProgressPanel() {
  auto* right = new QWidget(this);
  auto* rightLayout = new QVBoxLayout(right);
  rightLayout->setContentsMargins(0, 0, 0, 0);
  progressLabel_ = new QLabel(right);
  progressLabel_->setObjectName(QStringLiteral("hammerProgressText"));
  progressLabel_->setWordWrap(true);
  // Three lines: the column is narrow at 1280x800 ("...: 0 done, 0 skipped;
  // 0 hits accepted, 0 rejected" took three and lost the last).
  progressLabel_->setFixedHeight(QFontMetrics(font()).lineSpacing() * 3 + 4);
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
  points_->setMinimumHeight(100);
  // The mesh above the table: the point to hit next is marked on it, the
  // arrow giving the hammer's direction.
  scene_ = new SceneView(right);
  scene_->setObjectName(QStringLiteral("hammerScene"));
  scene_->setMinimumHeight(130);
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

  log_ = new QListWidget(right);
  log_->setObjectName(QStringLiteral("hammerLog"));
  log_->setFocusPolicy(Qt::NoFocus);
  log_->setMinimumHeight(60);
  log_->setWordWrap(true);
  log_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  rightLayout->addWidget(log_, 1);
  return right;
}

// --- wiring: the session's events and the model's changes ----------------------
void HammerStationPage::wire() {
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
QString HammerStationPage::verdictDetailText() const {
  return verdictDetail_->text();
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
  forceUnit_ = QString::fromStdString(def.channels[static_cast<std::size_t>(forceChannel_)].transducer.unit);
  setAxisText(traces_, QwtPlot::yLeft, tr("Force [%1]").arg(forceUnit_));
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

}  // namespace views
}  // namespace mozzi
