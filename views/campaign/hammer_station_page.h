#pragma once
// The hammer-station page (issue 15, WORKBENCH.md job 1): where a technician
// works through an impact campaign with the keyboard. It presents the
// campaign engine (devices/campaign/campaign_engine.h) through
// CampaignSession and computes nothing itself:
// - station status, engine state, a trigger lamp;
// - live force and response traces refreshed by a 25 Hz timer from the
//   session's live buffer (and the hit's record once it is complete);
// - the verdict with its reasons in large text, and an audible cue;
// - Arm (A), Disarm (Esc), Accept (Space), Reject (Backspace), Redo (R),
//   Skip with a reason (S), Start (F5), Stop (Shift+F5), New campaign
//   (Ctrl+Shift+N): every action has its key on its button;
// - progress over the mesh: the specimen's mesh with the point to hit next
//   marked (the arrow is the hammer's direction), and the points in roving
//   order with their hits and status, the point being measured highlighted;
// - the running FRF and coherence of the current point.

#include <QPointer>
#include <QString>
#include <QStringList>
#include <QWidget>
#include <functional>
#include <optional>

#include "core/io/mesh_document.h"
#include "devices/campaign/campaign_engine.h"
#include "views/common/page_registry.h"

class QAction;
class QCheckBox;
class QComboBox;
class QGridLayout;
class QHBoxLayout;
class QKeySequence;
class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QStackedWidget;
class QTableWidget;
class QTimer;
class QToolButton;
class QwtPlot;
class QwtPlotCurve;

namespace mozzi {
namespace views {

class CampaignSession;
class CampaignWizard;
class FrfPlot;
class SceneView;

class HammerStationPage : public QWidget {
  Q_OBJECT
 public:
  explicit HammerStationPage(const PageContext& ctx);
  ~HammerStationPage() override;

  // Shows campaign `campaignId` in the campaign list (not started).
  void showCampaign(qint64 campaignId);
  // Starts the selected campaign on its station (sim-hammer runs in real
  // time). False, with the reason in the banner, when it cannot.
  bool startCampaign();
  void stopCampaign();
  // Opens the new-campaign wizard (not modal); the campaign it creates is
  // selected when it finishes.
  CampaignWizard* newCampaign();

  // For tests and the status bar.
  CampaignSession* session() const { return session_; }
  qint64 selectedCampaign() const;
  QString verdictText() const;
  QString verdictDetailText() const;  // the line under the headline
  QString stateText() const;
  QString bannerText() const;
  std::optional<devices::campaign::EngineState> engineState() const { return state_; }
  std::optional<int> currentPoint() const { return current_; }
  int traceRefreshes() const { return traceRefreshes_; }
  QAction* action(const QString& name) const;  // "arm", "disarm", "accept", "reject", "redo", "skip", ...
  QTableWidget* pointTable() const { return points_; }
  FrfPlot* frfPlot() const { return frf_; }
  QwtPlot* tracePlot() const { return traces_; }
  QLineEdit* skipReasonEdit() const { return skipReason_; }
  SceneView* scene() const { return scene_; }

 protected:
  void changeEvent(QEvent* event) override;

 private:
  // The constructor's parts, called in this order (hammer_station_page.cpp).
  QToolButton* addActionButton(const QString& name, const char* text, const QKeySequence& key,
                               const std::function<void()>& slot);
  QHBoxLayout* buildTopBar();
  QHBoxLayout* buildVerdictRow();
  QGridLayout* buildActionGrid();
  QWidget* buildTracePanel();
  QWidget* buildProgressPanel();
  void wire();

  void retranslate();
  void reloadCampaigns();
  void updateActions();
  void refreshTraces();
  void showRecordTraces(const core::signal::TimeRecord& record);
  void setVerdict(const QString& headline, const QString& detail, const QString& colour);
  void showBanner(const QString& text);
  void log(const QString& text);
  int selectedPoint() const;

  void onState(devices::campaign::EngineState state, const QString& message);
  void onVerdict(const devices::campaign::HitVerdictEvent& verdict);
  void onCommitted(const devices::campaign::CommittedHitEvent& hit);
  void onRunningFrf(const devices::campaign::RunningFrfEvent& frf);
  void onProgress(const devices::campaign::EngineProgress& progress);
  void onFinished(const devices::campaign::FinishedEvent& finished);
  void doSkip();
  void showSpecimenMesh();  // of the selected campaign
  void updateHitMarker();   // on the current point
  void doRedo();

  PageContext ctx_;
  CampaignSession* session_ = nullptr;
  QPointer<CampaignWizard> wizard_;

  QComboBox* campaigns_ = nullptr;
  QCheckBox* autoArm_ = nullptr;
  QLabel* station_ = nullptr;
  QLabel* stateLabel_ = nullptr;
  QLabel* trigger_ = nullptr;
  QLabel* verdict_ = nullptr;
  QLabel* verdictDetail_ = nullptr;
  QLabel* banner_ = nullptr;
  QLabel* pointTitle_ = nullptr;
  QLabel* responseLabel_ = nullptr;
  QComboBox* responseChannel_ = nullptr;
  QwtPlot* traces_ = nullptr;
  QwtPlotCurve* forceCurve_ = nullptr;
  QwtPlotCurve* responseCurve_ = nullptr;
  FrfPlot* frf_ = nullptr;
  QLabel* frfHint_ = nullptr;
  QStackedWidget* frfStack_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QLabel* progressLabel_ = nullptr;
  QTableWidget* points_ = nullptr;
  SceneView* scene_ = nullptr;
  qint64 sceneSpecimen_ = 0;
  std::optional<core::io::MeshDocument> sceneMesh_;  // shown, for the DOF directions
  QLineEdit* skipReason_ = nullptr;
  QListWidget* log_ = nullptr;
  QTimer* refresh_ = nullptr;

  struct ActionEntry {
    QString name;
    QAction* action;
    QToolButton* button;
    const char* text;
  };
  std::vector<ActionEntry> actions_;

  std::optional<devices::campaign::EngineState> state_;
  std::optional<int> current_;
  std::optional<devices::campaign::EngineProgress> lastProgress_;
  std::uint64_t shownGeneration_ = 0;
  bool showingRecord_ = false;
  // What the language-dependent texts are built from (retranslate): the force
  // channel's unit and the station's device, empty until a campaign runs.
  QString forceUnit_ = QStringLiteral("N");
  QString stationDevice_;
  int traceRefreshes_ = 0;
  int forceChannel_ = 0;
  std::vector<int> responseChannels_;
  QStringList responseUnits_;
  QString verdictHeadline_;
};

}  // namespace views
}  // namespace mozzi
