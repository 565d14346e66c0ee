#pragma once
// The campaign engine (thesis §1.4, §1.6; issue 15): a state machine that
// runs an impact campaign point by point on its own thread, for the CLI and,
// through a thin Qt adapter, the workbench's hammer-station page.
//
//   Idle --arm--> Armed --trigger--> Recording --record complete--> VerdictPending
//   VerdictPending --accept/reject (caller, or the rules when autoDecide)--> commit
//   commit --point has its hits--> PointDone --> Idle at the next point
//          --no point left--> FRF set stored --> Finished
//   Armed/Recording --disarm--> Idle (hit in flight discarded)
//   any device loss --> WaitingForDevice (hit in flight discarded, message)
//          --device back--> Idle (Armed again with autoArm)
//
// Guarantees:
// - Every decided hit, accepted or rejected (flagged, with its reasons), is
//   committed to the project before the next arm: arm() is handled on the
//   engine thread after the commit has returned, and a failed commit keeps
//   the hit pending (accept() again retries) instead of arming.
// - Resume: open() on a campaign of the project continues at the first
//   point neither done nor skipped, with every accepted hit (the point's
//   running average is rebuilt from the stored hits).
// - Same station, same seed, same hits: a simulated station gets a seed per
//   hit from (campaign seed, point, attempt at the point) (hitSeed).
//
// Threading: commands (arm, disarm, accept, reject, redo, skip, stop) may be
// called from any thread; they are queued and return at once. Every
// observer callback runs on the engine thread, in order; a callback must not
// block for long (it delays acquisition) and must not call the engine's
// blocking waits. A Qt adapter copies what it needs and re-emits it as a
// queued signal to the GUI thread. The payloads hold shared_ptrs to const
// data, cheap to copy across threads. state(), progress() and
// pendingVerdict() are thread-safe snapshots.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include "core/common/frf_matrix.h"
#include "core/io/project_store.h"
#include "devices/campaign/campaign_store.h"
#include "devices/campaign/hit_pipeline.h"
#include "devices/campaign/station.h"
#include "devices/common/trigger.h"

namespace mozzi::devices::campaign {

enum class EngineState { Idle, Armed, Recording, VerdictPending, PointDone, WaitingForDevice, Finished };
const char* engineStateName(EngineState state);  // "idle", "armed", ...

// A block of the live stream while armed, for the traces (one per device
// block: about 50 ms of data, i.e. 20 updates a second or more).
struct LiveBlock {
  int position = 0;              // point being measured
  std::int64_t firstSample = 0;  // since the arm
  double sampleRateHz = 0.0;
  std::shared_ptr<const core::Matrix> values;  // scans x channels [EU], channels in definition order
  bool triggered = false;                      // the hit's trigger has fired (Recording)
};

struct HitVerdictEvent {
  int position = 0;
  core::Dof point;
  int attempt = 0;  // 0-based attempt number at the point
  HitVerdict verdict;
  std::shared_ptr<const core::signal::TimeRecord> record;  // the hit as it will be stored
  bool awaitingDecision = true;                            // false with autoDecide (decided at once)
};

struct CommittedHitEvent {
  int position = 0;
  core::Dof point;
  std::int64_t hitId = 0;
  int sequence = 0;
  bool accepted = false;
  std::uint32_t flags = 0;  // core::io::HitQualityFlag bits
  std::string reasons;
  double commitSeconds = 0.0;  // wall time of the commit
};

struct RunningFrfEvent {
  int position = 0;
  core::Dof point;
  int hits = 0;                                // accepted hits in the average
  std::shared_ptr<const core::FrfMatrix> frf;  // stored band, with coherence
};

struct EngineProgress {
  std::int64_t campaignId = 0;
  std::string campaignName;
  EngineState state = EngineState::Idle;
  std::optional<int> current;  // point being measured
  int hitsPerPoint = 0;
  ScheduleProgress schedule;
  std::vector<PointStatus> points;
  std::optional<std::int64_t> frfSetId;  // once finished
  std::string device;                    // station label
};

struct FinishedEvent {
  std::int64_t campaignId = 0;
  std::int64_t frfSetId = 0;
  ScheduleProgress schedule;
};

class CampaignObserver {
 public:
  virtual ~CampaignObserver() = default;
  virtual void onState(EngineState state, const std::string& message) {
    (void)state;
    (void)message;
  }
  virtual void onLiveBlock(const LiveBlock& block) { (void)block; }
  virtual void onVerdict(const HitVerdictEvent& verdict) { (void)verdict; }
  virtual void onHitCommitted(const CommittedHitEvent& hit) { (void)hit; }
  virtual void onRunningFrf(const RunningFrfEvent& frf) { (void)frf; }
  virtual void onProgress(const EngineProgress& progress) { (void)progress; }
  // Device lost, commit failed, command refused in this state, ...: the
  // engine goes on (or waits for the device); `error.message` says what.
  virtual void onError(const core::Error& error) { (void)error; }
  virtual void onFinished(const FinishedEvent& finished) { (void)finished; }
};

struct EngineOptions {
  bool autoDecide = false;       // accept hits that pass the rules and reject the others, without a caller
  bool autoArm = false;          // arm at once when a point is ready (after each decision, at each new point)
  ParameterMap deviceOverrides;  // applied over the definition's rig parameters (e.g. sim.realtime = false)
  std::chrono::milliseconds reconnectInterval{500};  // while WaitingForDevice
  // A session armed this long (stream time) without a complete hit is
  // restarted (0 = never). Bounds a simulated station running faster than
  // real time.
  double maxArmedSeconds = 0.0;
  int queuedBlocks = 64;  // device blocks buffered between the device thread and the engine
  // With autoArm: after this many rejected hits in a row at one point the
  // engine stops arming and reports it (the set-up needs a look), 0 = never.
  int maxConsecutiveRejections = 20;
  // Passive WAL checkpoint after each decided hit (so that no commit pays
  // for SQLite's auto-checkpoint); off for bulk runs (the demo project).
  bool checkpointBetweenHits = true;
};

class CampaignEngine {
 public:
  // Loads campaign `campaignId` of `store` (which must outlive the engine and
  // may be used by other threads meanwhile: it locks itself) for a run on
  // `station`. Nothing runs until start().
  static core::Result<std::unique_ptr<CampaignEngine>> open(core::io::ProjectStore& store, std::int64_t campaignId,
                                                            std::unique_ptr<Station> station,
                                                            EngineOptions options = {});
  ~CampaignEngine();  // stop()
  CampaignEngine(const CampaignEngine&) = delete;
  CampaignEngine& operator=(const CampaignEngine&) = delete;

  // Observers are added before start() and must outlive the engine's thread.
  void addObserver(CampaignObserver* observer);
  // Starts the engine thread: connects the station, rebuilds the current
  // point's average, reports progress; Idle (or Armed with autoArm), or
  // Finished when nothing is left (the FRF set is stored if it was missing).
  void start();
  // Stops the thread (disarms; a pending, undecided hit is not committed).
  // Idempotent; called by the destructor.
  void stop();

  // Commands (thread-safe, queued; refused with onError in a state where
  // they make no sense).
  void arm();
  void disarm();
  void accept();                                // the pending hit, accepted (also when it failed a rule)
  void reject(const std::string& reason = {});  // the pending hit, rejected with the rules' reasons (+ reason)
  void redo(int position, const std::string& reason = {});  // the point's accepted hits set aside; measure it again
  void skip(const std::string& reason);                     // the current point
  void skip(int position, const std::string& reason);

  // Snapshots (thread-safe).
  EngineState state() const;
  EngineProgress progress() const;
  std::optional<HitVerdictEvent> pendingVerdict() const;
  const CampaignDefinition& definition() const { return loaded_.definition; }

  // Blocks until `predicate(state)` holds or the timeout; true when it held.
  // The predicate is called without the engine's lock: it may call the engine.
  bool waitFor(const std::function<bool(EngineState)>& predicate, std::chrono::milliseconds timeout) const;
  bool waitUntilFinished(std::chrono::milliseconds timeout) const;

 private:
  struct Command {
    enum Kind { Arm, Disarm, Accept, Reject, Redo, Skip, Stop } kind;
    int position = -1;
    std::string reason;
  };
  struct DeviceMessage {
    std::uint64_t session = 0;
    StreamEvent event;
  };
  using Message = std::variant<Command, DeviceMessage>;

  CampaignEngine(core::io::ProjectStore& store, LoadedCampaign loaded, std::unique_ptr<Station> station,
                 EngineOptions options);

  void post(Command command);
  void onDeviceEvent(std::uint64_t session, StreamEvent&& event);
  void run();
  void handle(const Command& c);
  void handleDevice(DeviceMessage& m);
  void setState(EngineState s, const std::string& message = {});
  void error(core::ErrorCode code, const std::string& message, const std::string& where = {});
  void publishProgress();

  bool connect();
  void doArm();
  void endSession();  // stops the device session; later events of it are dropped
  void deviceLost(const std::string& message);
  void recordComplete(TriggeredRecord&& record);
  void decide(bool accept, const std::string& extraReason);
  void enterPoint();  // at schedule.next(): rebuild the average, Idle or arm, or finish
  void finish();

  core::io::ProjectStore& store_;
  LoadedCampaign loaded_;
  std::unique_ptr<Station> station_;
  EngineOptions options_;
  std::vector<CampaignObserver*> observers_;

  // Engine-thread state.
  Device* device_ = nullptr;
  std::optional<int> current_;
  PointAverage average_;
  std::optional<SoftwareTrigger> trigger_;
  std::optional<StreamHeader> header_;
  std::int64_t armedScans_ = 0;
  int consecutiveRejections_ = 0;
  std::chrono::steady_clock::time_point nextReconnect_;

  // Shared state.
  mutable std::mutex mutex_;
  mutable std::condition_variable cv_;  // queue changes and state changes
  std::condition_variable deviceRoom_;  // room in the queue for device blocks
  std::deque<Message> queue_;
  int queuedDeviceMessages_ = 0;
  std::uint64_t session_ = 0;  // current device session (0 = none)
  EngineState state_ = EngineState::Idle;
  EngineProgress progress_;
  std::optional<HitVerdictEvent> pending_;
  Eigen::MatrixXf pendingSamples_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace mozzi::devices::campaign
