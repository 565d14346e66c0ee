#include "views/campaign/campaign_session.h"

#include <QMetaObject>
#include <QPointer>

#include "views/common/project_model.h"

namespace mozzi {
namespace views {

namespace cp = devices::campaign;

// Runs on the engine thread: copies and queues, never waits for the GUI.
class CampaignSession::Observer final : public cp::CampaignObserver {
 public:
  Observer(CampaignSession* session, ProjectModel* model, qint64 campaignId)
      : session_(session), model_(model), campaignId_(campaignId) {}

  void onState(cp::EngineState state, const std::string& message) override {
    const QString text = QString::fromStdString(message);
    post([state, text](CampaignSession* s) { emit s->stateChanged(state, text); });
  }
  void onLiveBlock(const cp::LiveBlock& block) override { session_->pushLive(block); }
  void onVerdict(const cp::HitVerdictEvent& verdict) override {
    post([verdict](CampaignSession* s) { emit s->verdictReady(verdict); });
  }
  void onHitCommitted(const cp::CommittedHitEvent& hit) override {
    // The engine wrote the hit through the store: observers of the project
    // hear of it (queued to the GUI thread by the model).
    model_->notifyChanged(RecordKind::Hit, campaignId_);
    post([hit](CampaignSession* s) { emit s->hitCommitted(hit); });
  }
  void onRunningFrf(const cp::RunningFrfEvent& frf) override {
    post([frf](CampaignSession* s) { emit s->runningFrf(frf); });
  }
  void onProgress(const cp::EngineProgress& progress) override {
    post([progress](CampaignSession* s) { emit s->progressChanged(progress); });
  }
  void onError(const core::Error& error) override {
    const QString text = QString::fromStdString(error.describe());
    post([text](CampaignSession* s) { emit s->engineError(text); });
  }
  void onFinished(const cp::FinishedEvent& finished) override {
    model_->notifyChanged(RecordKind::FrfSet, finished.frfSetId);
    model_->notifyChanged(RecordKind::Campaign, 0);
    post([finished](CampaignSession* s) { emit s->finished(finished); });
  }

 private:
  template <typename F>
  void post(F&& f) {
    // Dropped by Qt when the session is gone before the call is delivered.
    CampaignSession* s = session_;
    QMetaObject::invokeMethod(
        s, [s, f = std::forward<F>(f)] { f(s); }, Qt::QueuedConnection);
  }

  CampaignSession* session_;
  ProjectModel* model_;
  qint64 campaignId_;
};

CampaignSession::CampaignSession(ProjectModel* model, QObject* parent) : QObject(parent), model_(model) {
  connect(model_, &ProjectModel::aboutToClose, this, &CampaignSession::stop);
}

CampaignSession::~CampaignSession() {
  stop();
}

core::Result<void> CampaignSession::start(qint64 campaignId, std::unique_ptr<cp::Station> station,
                                          cp::EngineOptions options) {
  stop();
  core::io::ProjectStore* store = model_->store();
  if (!store) return core::makeError(core::ErrorCode::InvalidArgument, "no project is open", "campaign");
  auto engine = cp::CampaignEngine::open(*store, campaignId, std::move(station), std::move(options));
  if (!engine) return engine.error();
  campaignId_ = campaignId;
  {
    std::lock_guard<std::mutex> lock(liveMutex_);
    live_.clear();
    liveScans_ = 0;
    liveGeneration_ = 0;
    liveWindowS_ = std::max(0.5, (*engine)->definition().acquisition.recordSeconds);
  }
  observer_ = std::make_unique<Observer>(this, model_, campaignId);
  engine_ = std::move(engine).value();
  engine_->addObserver(observer_.get());
  engine_->start();
  return {};
}

void CampaignSession::stop() {
  if (!engine_) return;
  engine_->stop();  // joins the engine thread: no observer call after this
  engine_.reset();
  observer_.reset();
  emit stopped();
}

void CampaignSession::arm() {
  if (engine_) engine_->arm();
}
void CampaignSession::disarm() {
  if (engine_) engine_->disarm();
}
void CampaignSession::accept() {
  if (engine_) engine_->accept();
}
void CampaignSession::reject(const QString& reason) {
  if (engine_) engine_->reject(reason.toStdString());
}
void CampaignSession::redo(int position, const QString& reason) {
  if (engine_) engine_->redo(position, reason.toStdString());
}
void CampaignSession::skip(int position, const QString& reason) {
  if (engine_) engine_->skip(position, reason.toStdString());
}

void CampaignSession::setLiveWindow(double seconds) {
  std::lock_guard<std::mutex> lock(liveMutex_);
  liveWindowS_ = seconds;
}

void CampaignSession::pushLive(const cp::LiveBlock& block) {
  if (!block.values) return;
  std::lock_guard<std::mutex> lock(liveMutex_);
  if (block.firstSample == 0 || block.firstSample < liveFirst_ + liveScans_ - 1) {  // a new arm
    live_.clear();
    liveScans_ = 0;
    liveFirst_ = block.firstSample;
  }
  if (live_.empty()) liveFirst_ = block.firstSample;
  live_.push_back(block.values);
  liveScans_ += block.values->rows();
  liveRate_ = block.sampleRateHz;
  liveTriggered_ = block.triggered;
  const auto keep = static_cast<std::int64_t>(liveWindowS_ * std::max(1.0, liveRate_));
  while (live_.size() > 1 && liveScans_ - live_.front()->rows() >= keep) {
    liveScans_ -= live_.front()->rows();
    liveFirst_ += live_.front()->rows();
    live_.pop_front();
  }
  ++liveGeneration_;
}

LiveSnapshot CampaignSession::liveSnapshot() const {
  std::lock_guard<std::mutex> lock(liveMutex_);
  LiveSnapshot s;
  s.sampleRateHz = liveRate_;
  s.firstSample = liveFirst_;
  s.blocks.assign(live_.begin(), live_.end());
  s.triggered = liveTriggered_;
  s.generation = liveGeneration_;
  return s;
}

}  // namespace views
}  // namespace mozzi
