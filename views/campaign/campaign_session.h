#pragma once
// The thin Qt adapter over the campaign engine (devices/campaign/
// campaign_engine.h; WORKBENCH.md "Engines are Qt-free; pages present them").
// It owns the engine while a campaign runs, observes it on the engine thread
// and hands what the page needs to the GUI thread without ever blocking it:
// - events (state, verdict, committed hit, running FRF, progress, errors, end)
//   are copied (their payloads are shared_ptrs to const data) and re-emitted
//   as signals in the GUI thread through queued calls;
// - the live blocks are kept in a short buffer under a mutex held only to
//   push or copy shared_ptrs; the page's refresh timer takes a snapshot.
// It computes nothing: every number comes from the engine.

#include <QObject>
#include <QString>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>

#include "devices/campaign/campaign_engine.h"

namespace mozzi {
namespace views {

class ProjectModel;

// What the traces show: the last seconds of the live stream since the arm.
struct LiveSnapshot {
  double sampleRateHz = 0.0;
  std::int64_t firstSample = 0;  // of the first block kept (since the arm)
  std::vector<std::shared_ptr<const core::Matrix>> blocks;
  bool triggered = false;
  std::uint64_t generation = 0;  // grows with every block
};

class CampaignSession : public QObject {
  Q_OBJECT
 public:
  explicit CampaignSession(ProjectModel* model, QObject* parent = nullptr);
  ~CampaignSession() override;  // stop()

  // Opens campaign `campaignId` of the model's project on `station` and
  // starts the engine. Errors (no project, no such campaign, no definition)
  // leave the session stopped.
  core::Result<void> start(qint64 campaignId, std::unique_ptr<devices::campaign::Station> station,
                           devices::campaign::EngineOptions options = {});
  // Stops the engine (a pending, undecided hit is not committed). Idempotent.
  void stop();
  bool isRunning() const { return static_cast<bool>(engine_); }
  qint64 campaignId() const { return campaignId_; }
  const devices::campaign::CampaignEngine* engine() const { return engine_.get(); }

  // Commands, queued to the engine; nothing happens when stopped.
  void arm();
  void disarm();
  void accept();
  void reject(const QString& reason = QString());
  void redo(int position, const QString& reason = QString());
  void skip(int position, const QString& reason);

  // The live stream kept for the traces (about `seconds` of it), copied
  // under a short lock; `generation` tells whether anything came since.
  LiveSnapshot liveSnapshot() const;
  void setLiveWindow(double seconds);

 signals:
  void stateChanged(devices::campaign::EngineState state, const QString& message);
  void verdictReady(const devices::campaign::HitVerdictEvent& verdict);
  void hitCommitted(const devices::campaign::CommittedHitEvent& hit);
  void runningFrf(const devices::campaign::RunningFrfEvent& frf);
  void progressChanged(const devices::campaign::EngineProgress& progress);
  void engineError(const QString& message);
  void finished(const devices::campaign::FinishedEvent& finished);
  void stopped();

 private:
  class Observer;
  void pushLive(const devices::campaign::LiveBlock& block);

  ProjectModel* model_;
  qint64 campaignId_ = 0;
  std::unique_ptr<Observer> observer_;
  std::unique_ptr<devices::campaign::CampaignEngine> engine_;

  mutable std::mutex liveMutex_;
  std::deque<std::shared_ptr<const core::Matrix>> live_;
  std::int64_t liveFirst_ = 0;
  std::int64_t liveScans_ = 0;
  double liveRate_ = 0.0;
  bool liveTriggered_ = false;
  std::uint64_t liveGeneration_ = 0;
  double liveWindowS_ = 2.0;
};

}  // namespace views
}  // namespace mozzi
