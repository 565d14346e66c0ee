#include "devices/campaign/campaign_engine.h"

#include <algorithm>

namespace mozzi::devices::campaign {

using core::ErrorCode;

const char* engineStateName(EngineState state) {
  switch (state) {
    case EngineState::Idle: return "idle";
    case EngineState::Armed: return "armed";
    case EngineState::Recording: return "recording";
    case EngineState::VerdictPending: return "verdict pending";
    case EngineState::PointDone: return "point done";
    case EngineState::WaitingForDevice: return "waiting for device";
    case EngineState::Finished: return "finished";
  }
  return "idle";
}

core::Result<std::unique_ptr<CampaignEngine>> CampaignEngine::open(core::io::ProjectStore& store,
                                                                   std::int64_t campaignId,
                                                                   std::unique_ptr<Station> station,
                                                                   EngineOptions options) {
  if (!station) return core::makeError(ErrorCode::InvalidArgument, "no station for the campaign", "campaign engine");
  if (store.isReadOnly())
    return core::makeError(ErrorCode::Locked, "the project is open read-only: " + store.readOnlyReason(), store.path());
  auto loaded = loadCampaign(store, campaignId);
  if (!loaded) return loaded.error();
  return std::unique_ptr<CampaignEngine>(
      new CampaignEngine(store, std::move(*loaded), std::move(station), std::move(options)));
}

CampaignEngine::CampaignEngine(core::io::ProjectStore& store, LoadedCampaign loaded, std::unique_ptr<Station> station,
                               EngineOptions options)
    : store_(store),
      loaded_(std::move(loaded)),
      station_(std::move(station)),
      options_(std::move(options)),
      average_(loaded_.definition) {
  progress_.campaignId = loaded_.campaign.id;
  progress_.campaignName = loaded_.campaign.name;
  progress_.hitsPerPoint = loaded_.definition.hitsPerPoint;
  progress_.schedule = loaded_.schedule.progress();
  progress_.points = loaded_.schedule.points();
  progress_.device = station_->label();
  if (loaded_.frfSetCurrent) progress_.frfSetId = loaded_.frfSetId;
}

CampaignEngine::~CampaignEngine() {
  stop();
}

void CampaignEngine::addObserver(CampaignObserver* observer) {
  if (observer) observers_.push_back(observer);
}

void CampaignEngine::start() {
  std::lock_guard<std::mutex> l(mutex_);
  if (thread_.joinable() || stopping_) return;
  thread_ = std::thread([this] { run(); });
}

void CampaignEngine::stop() {
  {
    std::lock_guard<std::mutex> l(mutex_);
    if (!thread_.joinable()) return;
    stopping_ = true;
    queue_.push_back(Command{Command::Stop, -1, {}});
  }
  cv_.notify_all();
  deviceRoom_.notify_all();
  thread_.join();
}

void CampaignEngine::post(Command command) {
  {
    std::lock_guard<std::mutex> l(mutex_);
    queue_.push_back(std::move(command));
  }
  cv_.notify_all();
}

void CampaignEngine::arm() {
  post(Command{Command::Arm, -1, {}});
}
void CampaignEngine::disarm() {
  post(Command{Command::Disarm, -1, {}});
}
void CampaignEngine::accept() {
  post(Command{Command::Accept, -1, {}});
}
void CampaignEngine::reject(const std::string& reason) {
  post(Command{Command::Reject, -1, reason});
}
void CampaignEngine::redo(int position, const std::string& reason) {
  post(Command{Command::Redo, position, reason});
}
void CampaignEngine::skip(const std::string& reason) {
  post(Command{Command::Skip, -1, reason});
}
void CampaignEngine::skip(int position, const std::string& reason) {
  post(Command{Command::Skip, position, reason});
}

EngineState CampaignEngine::state() const {
  std::lock_guard<std::mutex> l(mutex_);
  return state_;
}

EngineProgress CampaignEngine::progress() const {
  std::lock_guard<std::mutex> l(mutex_);
  return progress_;
}

std::optional<HitVerdictEvent> CampaignEngine::pendingVerdict() const {
  std::lock_guard<std::mutex> l(mutex_);
  return pending_;
}

bool CampaignEngine::waitFor(const std::function<bool(EngineState)>& predicate,
                             std::chrono::milliseconds timeout) const {
  // The predicate runs unlocked: it may ask the engine (progress(),
  // pendingVerdict(), ...), which takes the same mutex. A change while it runs
  // is seen at the next look, at most kLook later.
  constexpr auto kLook = std::chrono::milliseconds(20);
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  std::unique_lock<std::mutex> l(mutex_);
  for (;;) {
    const EngineState now = state_;
    l.unlock();
    if (predicate(now)) return true;
    l.lock();
    const auto t = std::chrono::steady_clock::now();
    if (t >= deadline) return false;
    cv_.wait_until(l, std::min(deadline, t + kLook));
  }
}

bool CampaignEngine::waitUntilFinished(std::chrono::milliseconds timeout) const {
  return waitFor([](EngineState s) { return s == EngineState::Finished; }, timeout);
}

// Called on the device's acquisition thread: queue the event for the engine
// thread. Data blocks wait for room (so a simulated station faster than real
// time cannot fill the memory); events of an ended session are dropped.
void CampaignEngine::onDeviceEvent(std::uint64_t session, StreamEvent&& event) {
  std::unique_lock<std::mutex> l(mutex_);
  if (std::holds_alternative<DataBlock>(event)) {
    deviceRoom_.wait(l, [&] {
      return stopping_ || session != session_ || queuedDeviceMessages_ < std::max(1, options_.queuedBlocks);
    });
  }
  if (stopping_ || session != session_) return;
  ++queuedDeviceMessages_;
  queue_.push_back(DeviceMessage{session, std::move(event)});
  l.unlock();
  cv_.notify_all();
}

void CampaignEngine::setState(EngineState s, const std::string& message) {
  {
    std::lock_guard<std::mutex> l(mutex_);
    state_ = s;
    progress_.state = s;
  }
  cv_.notify_all();
  for (auto* o : observers_) o->onState(s, message);
}

void CampaignEngine::error(ErrorCode code, const std::string& message, const std::string& where) {
  const core::Error e =
      core::makeError(code, message, where.empty() ? "campaign '" + loaded_.campaign.name + "'" : where);
  for (auto* o : observers_) o->onError(e);
}

void CampaignEngine::publishProgress() {
  EngineProgress p;
  {
    std::lock_guard<std::mutex> l(mutex_);
    progress_.current = current_;
    progress_.schedule = loaded_.schedule.progress();
    progress_.points = loaded_.schedule.points();
    progress_.state = state_;
    p = progress_;
  }
  for (auto* o : observers_) o->onProgress(p);
}

void CampaignEngine::run() {
  if (loaded_.schedule.progress().complete()) {
    finish();
  } else {
    if (connect()) enterPoint();
  }
  for (;;) {
    Message m;
    {
      std::unique_lock<std::mutex> l(mutex_);
      const bool waiting = state_ == EngineState::WaitingForDevice;
      const auto ready = [&] { return !queue_.empty(); };
      if (waiting)
        cv_.wait_until(l, nextReconnect_, ready);
      else
        cv_.wait(l, ready);
      if (queue_.empty()) {
        l.unlock();
        if (connect()) enterPoint();
        continue;
      }
      m = std::move(queue_.front());
      queue_.pop_front();
      if (std::holds_alternative<DeviceMessage>(m)) {
        --queuedDeviceMessages_;
        deviceRoom_.notify_all();
      }
    }
    if (auto* c = std::get_if<Command>(&m)) {
      if (c->kind == Command::Stop) break;
      handle(*c);
    } else {
      handleDevice(std::get<DeviceMessage>(m));
    }
  }
  endSession();
  station_->disconnect();
  device_ = nullptr;
}

// Connects the station when there is no device; false (WaitingForDevice,
// next try scheduled) when it is absent.
bool CampaignEngine::connect() {
  if (device_) return true;
  auto d = station_->connect();
  if (!d) {
    nextReconnect_ = std::chrono::steady_clock::now() + options_.reconnectInterval;
    if (state() != EngineState::WaitingForDevice)
      setState(EngineState::WaitingForDevice, "waiting for " + station_->label() + ": " + d.error().message);
    return false;
  }
  device_ = *d;
  return true;
}

void CampaignEngine::enterPoint() {
  current_ = loaded_.schedule.next();
  consecutiveRejections_ = 0;
  if (!current_) {
    finish();
    return;
  }
  if (auto r = rebuildPointAverage(store_, loaded_, *current_, average_); !r) {
    error(r.error().code, "cannot rebuild the point's average: " + r.error().message, r.error().where);
    average_.reset();
  }
  publishProgress();
  if (average_.hits() > 0) {
    auto f = average_.frf();
    if (f) {
      RunningFrfEvent e{*current_, loaded_.schedule.point(*current_).dof, average_.hits(),
                        std::make_shared<const core::FrfMatrix>(std::move(*f))};
      for (auto* o : observers_) o->onRunningFrf(e);
    }
  }
  setState(EngineState::Idle, "next point " + core::formatDof(loaded_.schedule.point(*current_).dof));
  if (options_.autoArm) doArm();
}

void CampaignEngine::handle(const Command& c) {
  const EngineState s = state();
  switch (c.kind) {
    case Command::Arm:
      if (s != EngineState::Idle)
        return error(ErrorCode::InvalidArgument, std::string("cannot arm while ") + engineStateName(s));
      consecutiveRejections_ = 0;
      return doArm();
    case Command::Disarm:
      if (s != EngineState::Armed && s != EngineState::Recording) return;
      endSession();
      return setState(EngineState::Idle, "disarmed");
    case Command::Accept:
    case Command::Reject:
      if (s != EngineState::VerdictPending)
        return error(ErrorCode::InvalidArgument, "no hit is waiting for a decision");
      return decide(c.kind == Command::Accept, c.reason);
    case Command::Skip: {
      if (s == EngineState::VerdictPending || s == EngineState::Recording)
        return error(ErrorCode::InvalidArgument, "decide the hit first, then skip");
      const int position = c.position >= 0 ? c.position : current_.value_or(-1);
      if (position < 0 || position >= static_cast<int>(loaded_.schedule.points().size()))
        return error(ErrorCode::InvalidArgument, "no such point to skip");
      if (c.reason.empty()) return error(ErrorCode::InvalidArgument, "a skip needs a reason");
      if (auto r = store_.setCampaignPointSkipped(loaded_.campaign.id, position, true, c.reason); !r)
        return error(r.error().code, "cannot store the skip: " + r.error().message, r.error().where);
      loaded_.schedule.setSkipped(position, true, c.reason);
      if (current_ && *current_ == position) {
        endSession();
        if (s == EngineState::WaitingForDevice) return publishProgress();
        return enterPoint();
      }
      return publishProgress();
    }
    case Command::Redo: {
      if (s == EngineState::VerdictPending || s == EngineState::Recording)
        return error(ErrorCode::InvalidArgument, "decide the hit first, then redo");
      if (c.position < 0 || c.position >= static_cast<int>(loaded_.schedule.points().size()))
        return error(ErrorCode::InvalidArgument, "no such point to redo");
      const std::string reason = "redone" + (c.reason.empty() ? std::string() : ": " + c.reason);
      auto n = store_.redoCampaignPoint(loaded_.campaign.id, c.position, reason);
      if (!n) return error(n.error().code, "cannot redo the point: " + n.error().message, n.error().where);
      endSession();
      // Reload the hits (their acceptance changed) and measure the point next.
      auto reloaded = loadCampaign(store_, loaded_.campaign.id);
      if (!reloaded) return error(reloaded.error().code, reloaded.error().message, reloaded.error().where);
      loaded_ = std::move(*reloaded);
      {
        std::lock_guard<std::mutex> l(mutex_);
        progress_.frfSetId.reset();
      }
      if (s == EngineState::WaitingForDevice) return publishProgress();
      if (s == EngineState::Finished && !connect()) return;
      return enterPoint();
    }
    case Command::Stop: return;
  }
}

void CampaignEngine::doArm() {
  if (!current_) return;
  if (!connect()) return;
  const auto& def = loaded_.definition;
  const auto& point = loaded_.schedule.point(*current_);
  ParameterMap overrides = options_.deviceOverrides;
  // A simulated station is told where the hammer hits and where the
  // accelerometers sit (when it declares those parameters), and gets the
  // hit's own seed.
  const auto caps = device_->capabilities();
  auto declares = [&](const char* key) {
    return std::any_of(caps.parameters.begin(), caps.parameters.end(),
                       [&](const ParameterSpec& p) { return p.key == key; });
  };
  const int fc = def.forceChannel();
  if (declares("hammer.point"))
    overrides["hammer.point"] = core::formatDof(def.channelDof(static_cast<std::size_t>(fc), point.dof));
  if (declares("response.dofs")) {
    std::vector<std::pair<int, std::string>> byInput;
    for (std::size_t c = 0; c < def.channels.size(); ++c)
      if (static_cast<int>(c) != fc)
        byInput.emplace_back(def.channels[c].input, core::formatDof(def.channelDof(c, point.dof)));
    std::sort(byInput.begin(), byInput.end());
    std::string dofs;
    for (const auto& [in, label] : byInput) dofs += (dofs.empty() ? "" : ",") + label;
    overrides["response.dofs"] = dofs;
  }
  if (declares("sim.seed"))
    overrides["sim.seed"] = static_cast<std::int64_t>(hitSeed(def.seed, *current_, point.attempts));
  auto applied = device_->configure(acquisitionConfigFor(def, point.dof, overrides));
  if (!applied) {
    if (device_->state() == DeviceState::Closed) return deviceLost(applied.error().message);
    return error(applied.error().code, "the device refused the configuration: " + applied.error().message,
                 applied.error().where);
  }
  SoftwareTriggerConfig tc;
  tc.channel = fc;
  tc.level = def.acquisition.triggerLevel;
  tc.slope = TriggerSlope::Rising;
  tc.recordScans = def.recordScans();
  tc.preTriggerFraction = def.acquisition.preTriggerFraction;
  auto chains = chainsFor(device_->capabilities(), *applied);
  for (const auto& ch : chains) tc.fullScale.push_back(ch.fullScaleEngineering());
  auto trig = SoftwareTrigger::create(tc, static_cast<int>(def.channels.size()));
  if (!trig) return error(trig.error().code, trig.error().message, trig.error().where);
  trigger_ = std::move(*trig);
  header_.reset();
  armedScans_ = 0;
  std::uint64_t session;
  {
    std::lock_guard<std::mutex> l(mutex_);
    session = ++session_;
  }
  auto started = device_->start([this, session](StreamEvent&& e) { onDeviceEvent(session, std::move(e)); });
  if (!started) {
    {
      std::lock_guard<std::mutex> l(mutex_);
      session_ = 0;
    }
    return deviceLost(started.error().message);
  }
  setState(EngineState::Armed, "armed at " + core::formatDof(point.dof));
}

void CampaignEngine::endSession() {
  {
    std::lock_guard<std::mutex> l(mutex_);
    session_ = 0;
    // Drop what the ended session queued.
    for (auto it = queue_.begin(); it != queue_.end();) {
      if (std::holds_alternative<DeviceMessage>(*it)) {
        it = queue_.erase(it);
        --queuedDeviceMessages_;
      } else {
        ++it;
      }
    }
  }
  deviceRoom_.notify_all();
  if (device_) device_->stop();
  trigger_.reset();
}

void CampaignEngine::deviceLost(const std::string& message) {
  endSession();
  station_->disconnect();
  device_ = nullptr;
  error(ErrorCode::IoError, message + "; the hit in flight was discarded, nothing committed is lost",
        station_->label());
  nextReconnect_ = std::chrono::steady_clock::now() + options_.reconnectInterval;
  setState(EngineState::WaitingForDevice, "waiting for " + station_->label());
}

void CampaignEngine::handleDevice(DeviceMessage& m) {
  {
    std::lock_guard<std::mutex> l(mutex_);
    if (m.session != session_) return;
  }
  const EngineState s = state();
  if (s != EngineState::Armed && s != EngineState::Recording) return;
  if (auto* h = std::get_if<StreamHeader>(&m.event)) {
    header_ = *h;
    return;
  }
  if (auto* b = std::get_if<DataBlock>(&m.event)) {
    if (!trigger_) return;
    auto records = trigger_->feed(b->firstSample, b->values);
    armedScans_ = b->firstSample + b->scanCount();
    const bool triggered = trigger_->triggersAccepted() > 0;
    LiveBlock live{current_.value_or(0), b->firstSample, header_ ? header_->sampleRateHz : 0.0,
                   std::make_shared<const core::Matrix>(std::move(b->values)), triggered};
    for (auto* o : observers_) o->onLiveBlock(live);
    if (!records.empty()) return recordComplete(std::move(records.front()));
    if (triggered && s == EngineState::Armed) setState(EngineState::Recording, "trigger");
    if (options_.maxArmedSeconds > 0.0 && header_ && !triggered &&
        static_cast<double>(armedScans_) > options_.maxArmedSeconds * header_->sampleRateHz) {
      // No hit within the armed time: start a fresh session.
      endSession();
      setState(EngineState::Idle, "no hit within " + std::to_string(options_.maxArmedSeconds) + " s");
      if (options_.autoArm) doArm();
    }
    return;
  }
  if (auto* o = std::get_if<OverrunEvent>(&m.event)) {
    if (s == EngineState::Recording) {
      // Samples of the hit were lost: discard it and arm again.
      endSession();
      error(ErrorCode::IoError, "data lost during the hit (" + o->detail + "); hit discarded, hit again");
      setState(EngineState::Idle, "hit discarded");
      if (options_.autoArm) doArm();
    }
    return;
  }
  if (auto* e = std::get_if<StreamEnd>(&m.event)) {
    if (e->reason == EndReason::Stopped) return;
    if (e->reason == EndReason::Completed) {
      endSession();
      setState(EngineState::Idle, "the acquisition ended before a complete hit");
      if (options_.autoArm) doArm();
      return;
    }
    return deviceLost(std::string("the device stopped (") + endReasonName(e->reason) + "): " + e->message);
  }
}

void CampaignEngine::recordComplete(TriggeredRecord&& record) {
  const double fs = header_ ? header_->sampleRateHz : loaded_.definition.acquisition.sampleRateHz;
  std::vector<double> fullScale;
  if (header_)
    for (const auto& ch : header_->channels) fullScale.push_back(ch.fullScale);
  endSession();
  const auto& point = loaded_.schedule.point(*current_);
  // The hit as it will be stored (float32): verdict and average see exactly that.
  Eigen::MatrixXf stored = storedSamples(record.samples);
  auto tr = std::make_shared<core::signal::TimeRecord>(
      timeRecordFor(loaded_.definition, point.dof, fs, fullScale, samplesFromStored(stored)));
  tr->preTriggerSamples = record.preTriggerScans;
  auto verdict = judgeHit(loaded_.definition, *tr, &average_);
  if (!verdict) {
    error(verdict.error().code, "cannot check the hit: " + verdict.error().message, verdict.error().where);
    setState(EngineState::Idle, "hit discarded");
    if (options_.autoArm) doArm();
    return;
  }
  HitVerdictEvent ev{*current_, point.dof, point.attempts, std::move(*verdict), tr, !options_.autoDecide};
  {
    std::lock_guard<std::mutex> l(mutex_);
    pending_ = ev;
    pendingSamples_ = std::move(stored);
  }
  setState(EngineState::VerdictPending, ev.verdict.text());
  for (auto* o : observers_) o->onVerdict(ev);
  if (options_.autoDecide) decide(ev.verdict.passed, {});
}

void CampaignEngine::decide(bool accept, const std::string& extraReason) {
  HitVerdictEvent ev;
  {
    std::lock_guard<std::mutex> l(mutex_);
    if (!pending_) return;
    ev = *pending_;
  }
  core::io::StoredHit hit;
  hit.campaignId = loaded_.campaign.id;
  hit.sequence = loaded_.nextSequence;
  hit.point = ev.point;
  hit.sampleRateHz = ev.record->sampleRateHz;
  {
    std::lock_guard<std::mutex> l(mutex_);
    hit.samples = pendingSamples_;
  }
  for (const auto& ch : ev.record->channels) {
    core::io::StoredHitChannel c;
    c.dof = ch.dof;
    c.quantity = core::signal::transducerKindName(ch.transducer.kind);
    c.unit = ch.transducer.unit;
    hit.channels.push_back(std::move(c));
  }
  hit.accepted = accept;
  hit.qualityFlags = ev.verdict.flags;
  std::vector<std::string> reasons = ev.verdict.reasons;
  if (!accept && ev.verdict.passed) hit.qualityFlags |= core::io::kHitManualReject;
  if (!accept && !extraReason.empty()) reasons.push_back(extraReason);
  if (!accept && reasons.empty()) reasons.push_back("rejected by the technician");
  if (accept && !ev.verdict.passed) reasons.insert(reasons.begin(), "accepted by the technician despite");
  for (std::size_t i = 0; i < reasons.size(); ++i) hit.qualityReasons += (i ? "; " : "") + reasons[i];
  const auto t0 = std::chrono::steady_clock::now();
  auto id = store_.commitHit(hit);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!id) {
    // Keep the hit pending: accept() or reject() again retries the commit.
    return error(id.error().code, "the hit could not be saved: " + id.error().message, id.error().where);
  }
  {
    std::lock_guard<std::mutex> l(mutex_);
    pending_.reset();
    pendingSamples_.resize(0, 0);
  }
  ++loaded_.nextSequence;
  core::io::HitInfo info;
  info.id = *id;
  info.sequence = hit.sequence;
  info.point = hit.point;
  info.sampleRateHz = hit.sampleRateHz;
  info.channelCount = static_cast<int>(hit.channelCount());
  info.sampleCount = hit.sampleCount();
  info.accepted = accept;
  info.qualityFlags = hit.qualityFlags;
  info.qualityReasons = hit.qualityReasons;
  loaded_.hits.push_back(info);
  loaded_.schedule.recordHit(ev.position, accept);
  CommittedHitEvent c{ev.position, ev.point, *id, hit.sequence, accept, hit.qualityFlags, hit.qualityReasons, seconds};
  for (auto* o : observers_) o->onHitCommitted(c);
  if (accept) {
    if (auto a = average_.add(*ev.record); !a) {
      error(a.error().code, "the hit was saved but cannot be averaged: " + a.error().message, a.error().where);
    } else if (auto f = average_.frf(); f) {
      RunningFrfEvent e{ev.position, ev.point, average_.hits(), std::make_shared<const core::FrfMatrix>(std::move(*f))};
      for (auto* o : observers_) o->onRunningFrf(e);
    }
  }
  // Idle time between hits: copy the WAL into the database so that no commit
  // pays for SQLite's auto-checkpoint (docs/performance/project.md).
  if (options_.checkpointBetweenHits) (void)store_.checkpoint();
  publishProgress();
  if (loaded_.schedule.point(ev.position).done) {
    setState(EngineState::PointDone, "point " + core::formatDof(ev.point) + " done");
    return enterPoint();
  }
  consecutiveRejections_ = accept ? 0 : consecutiveRejections_ + 1;
  setState(EngineState::Idle, accept ? "accepted" : "rejected");
  if (options_.autoArm && options_.maxConsecutiveRejections > 0 &&
      consecutiveRejections_ >= options_.maxConsecutiveRejections) {
    return error(ErrorCode::NumericalFailure, std::to_string(consecutiveRejections_) + " hits in a row rejected at " +
                                                  core::formatDof(ev.point) + " (last: " + hit.qualityReasons +
                                                  "); check the set-up, then arm again");
  }
  if (options_.autoArm) doArm();
}

void CampaignEngine::finish() {
  current_.reset();
  endSession();
  if (!loaded_.finished()) {
    if (loaded_.schedule.progress().pointsDone == 0) {
      error(ErrorCode::InvalidArgument, "every point was skipped: no FRF to store");
    } else {
      auto id = storeCampaignFrf(store_, loaded_);
      if (!id) {
        error(id.error().code, "cannot store the campaign's FRFs: " + id.error().message, id.error().where);
        publishProgress();
        return setState(EngineState::Idle, "the FRFs could not be stored");
      }
      loaded_.frfSetId = *id;
      loaded_.frfSetCurrent = true;
    }
  }
  {
    std::lock_guard<std::mutex> l(mutex_);
    progress_.frfSetId = loaded_.frfSetId;
  }
  publishProgress();
  FinishedEvent f{loaded_.campaign.id, loaded_.frfSetId.value_or(0), loaded_.schedule.progress()};
  setState(EngineState::Finished, "campaign finished");
  for (auto* o : observers_) o->onFinished(f);
}

}  // namespace mozzi::devices::campaign
