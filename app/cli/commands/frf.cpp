// mozzi-cli frf HITS.uff: impact-hammer FRFs from time records (thesis §1.4,
// §1.6, §5.2). Reads UFF 58 time responses (function type 1), one hit per load
// case (record 6), checks every hit, averages the accepted ones with H1, H2 or
// Hv, writes FRFs and coherence as UFF 58 (function type 4 and 6) and prints a
// summary. With several force channels (or several --reference DOFs) the load
// cases are blocks of a multiple-input test (shakers) and the FRF matrix comes
// from H1 = Gyf Gff^-1 with multiple coherence (core/signal/frf_estimator.h).
// Documented in docs/cli/frf.md.
#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <limits>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <sstream>
#include <thread>
#include <utility>

#include "app/cli/args.h"
#include "app/cli/command.h"
#include "app/cli/output.h"
#include "core/common/thread_start.h"
#include "core/io/uff/uff.h"
#include "core/io/uff_hits.h"
#include "core/signal/frf_estimator.h"
#include "core/signal/hit_quality.h"

namespace mozzi::cli {
namespace {

namespace sg = core::signal;
namespace uff = core::io::uff;

constexpr const char* kUsage =
    "Usage: mozzi-cli frf HITS.uff --estimator H1|H2|Hv [--force-window S] [--exp-window TAU]\n"
    "                 [--reference NODE:DIR[,NODE:DIR...]] [--max-condition C] [--out FRF.uff] [--json]\n";

std::string fmt(double v, const char* f = "%.4g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// The force channels of a hit (core/io/uff_hits.h applied --reference): the references.
std::vector<Eigen::Index> forceChannels(const sg::TimeRecord& r) {
  std::vector<Eigen::Index> refs;
  for (Eigen::Index c = 0; c < r.channelCount(); ++c) {
    if (r.channels[static_cast<std::size_t>(c)].transducer.kind == sg::TransducerKind::Force) refs.push_back(c);
  }
  return refs;
}

std::string dofList(const std::vector<core::Dof>& dofs) {
  std::string s;
  for (std::size_t i = 0; i < dofs.size(); ++i) s += (i ? ", " : "") + core::formatDof(dofs[i]);
  return s;
}

// The averaging of the accepted hits on a second thread while the calling
// thread reads and checks the next ones: the user waits for wall time, and
// reading plus checking a hit costs about what its four FFTs and the
// accumulation cost (issue 19). Up to two hits in flight (UffHitReader keeps
// a hit valid while the next two are read), so that neither thread waits for
// the other after every hit: with one, each hand-over cost the averaging
// thread a wake-up of 0.25-0.6 ms on the reference machine. Hits are averaged
// one at a time in the order handed over, so the sums are those of the
// sequential loop whatever the timing. A hit the averaging thread has not
// started yet when the caller needs its slot (a loaded machine that has not
// scheduled it) is averaged by the caller itself rather than waited for; on
// a single core every hit is.
class AveragingThread {
 public:
  // `options` is read when the first hit is averaged, and must outlive this.
  explicit AveragingThread(const sg::FrfOptions& options) : options_(options) {
    if (std::thread::hardware_concurrency() >= 2) thread_ = core::PairedThread([this] { run(); });
  }
  ~AveragingThread() {
    if (!thread_.joinable()) return;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    changed_.notify_all();
    thread_.join();
  }
  AveragingThread(const AveragingThread&) = delete;
  AveragingThread& operator=(const AveragingThread&) = delete;

  // Plans the FFT of length n on the averaging thread (FFTW's planning of
  // 65,536 samples takes 2 ms), while the first hit is read.
  void prepare(Eigen::Index n) {
    if (!thread_.joinable()) return;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      planLength_ = n;
    }
    changed_.notify_all();
  }
  // Completes every hit in flight that the reader's next call `read` may
  // overwrite: UffHitReader keeps a hit until the third call after the one
  // that returned it starts, and a rejected hit is read but never handed
  // over, so counting hand-overs is not enough.
  void beforeRead(int read) {
    std::unique_lock<std::mutex> lock(mutex_);
    completeWhile(lock, [&] { return oldestRead() <= read - 3; });
  }
  // Completes hits until at most one is in flight, then hands `hit` over,
  // returned by the reader's call `read`; false once a hit has failed.
  bool submit(const core::io::UffHit& hit, int read) {
    std::unique_lock<std::mutex> lock(mutex_);
    completeWhile(lock, [&] { return inFlight() > 1; });
    if (error_) return false;
    pending_.push_back(Pending{&hit, read});
    if (!thread_.joinable()) completeWhile(lock, [&] { return inFlight() > 0; });
    lock.unlock();
    changed_.notify_all();
    return true;
  }
  // Completes every hit in flight; the first failure, "load case N: reason".
  const std::optional<std::string>& finish() {
    std::unique_lock<std::mutex> lock(mutex_);
    completeWhile(lock, [&] { return inFlight() > 0; });
    return error_;
  }
  // The average, after finish() returned no failure.
  sg::SpectralAverager& averager() { return *averager_; }

 private:
  // A hit handed over and the reader's call that returned it.
  struct Pending {
    const core::io::UffHit* hit;
    int read;
  };
  std::size_t inFlight() const { return pending_.size() + (averaging_ ? 1 : 0); }
  // The reader's call that returned the oldest hit in flight.
  int oldestRead() const {
    return averaging_ ? averagingRead_ : pending_.empty() ? std::numeric_limits<int>::max() : pending_.front().read;
  }
  // While `unfinished()`: waits while a hit is being averaged, and averages
  // the oldest waiting hit here when none is.
  template <class Unfinished>
  void completeWhile(std::unique_lock<std::mutex>& lock, Unfinished unfinished) {
    while (unfinished()) {
      if (averaging_) {
        changed_.wait(lock);
        continue;
      }
      averageOldest(lock);
    }
  }
  void run() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      changed_.wait(lock, [this] { return stop_ || planLength_ > 0 || (!averaging_ && !pending_.empty()); });
      if (planLength_ > 0) {
        const Eigen::Index n = std::exchange(planLength_, 0);
        lock.unlock();
        (void)sg::RealFft::forLength(n);  // kept in its cache; a failure is reported where it is used
        lock.lock();
        continue;
      }
      if (averaging_ || pending_.empty()) return;  // stopped with nothing left to take
      averageOldest(lock);
    }
  }
  // Takes the oldest waiting hit and averages it outside the lock; the
  // averager is never on two threads at once (averaging_). error_ is only
  // touched under the lock: the caller reads it while a hit may be averaged.
  void averageOldest(std::unique_lock<std::mutex>& lock) {
    const Pending oldest = pending_.front();
    pending_.pop_front();
    if (error_) {  // after a failure the rest are dropped
      changed_.notify_all();
      return;
    }
    averaging_ = true;
    averagingRead_ = oldest.read;
    lock.unlock();
    std::optional<std::string> failure = average(*oldest.hit);
    lock.lock();
    averaging_ = false;
    if (failure) error_ = std::move(failure);
    changed_.notify_all();
  }
  // "load case N: reason" when the hit cannot be averaged.
  std::optional<std::string> average(const core::io::UffHit& hit) {
    if (!averager_) {
      auto a = sg::SpectralAverager::create(hit.record, options_);
      if (!a) return "load case " + std::to_string(hit.loadCase) + ": " + a.error().describe();
      averager_.emplace(std::move(*a));
    }
    if (auto ok = averager_->add(hit.record); !ok) {
      return "load case " + std::to_string(hit.loadCase) + ": " + ok.error().describe();
    }
    return std::nullopt;
  }

  const sg::FrfOptions& options_;
  std::optional<sg::SpectralAverager> averager_;
  std::optional<std::string> error_;
  std::mutex mutex_;
  std::condition_variable changed_;  // any of the state below changed
  std::deque<Pending> pending_;      // handed over, not taken yet, oldest first
  bool averaging_ = false;           // a thread is averaging a hit
  int averagingRead_ = 0;            // the reader's call that returned that hit
  Eigen::Index planLength_ = 0;
  bool stop_ = false;
  core::PairedThread thread_;  // last: started once the members above exist
};

// The option table: a hammer pulse lasts well under a second; the force
// window must also cover at least one sample (checked against the file).
const OptionSpec kSpec{{"--estimator", "--reference", "--out"},
                       {"--json"},
                       {{"--force-window", aboveTo(0, 10, "s"), "force window width (at least one sample)"},
                        {"--exp-window", aboveTo(0, 1000, "s"), "exponential window time constant tau"},
                        {"--max-condition", closed(1, 1e12, ""), "largest condition number of Gff"}},
                       {"--out"}};

int frfCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const auto parsed = ParsedArgs::parse(args, kSpec);
  if (!parsed && exitCodeFor(parsed.error()) == kExitFailure) {
    err << "mozzi-cli frf: " << parsed.error().describe() << "\n";
    return kExitFailure;
  }
  if (!parsed || parsed->positional().size() != 1 || !parsed->value("--estimator")) {
    err << "mozzi-cli frf: "
        << (!parsed                            ? parsed.error().describe()
            : parsed->positional().size() != 1 ? std::string("expected one input file")
                                               : "--estimator is required")
        << "\n"
        << kUsage;
    return kExitUsage;
  }
  const std::string path = parsed->positional()[0];
  auto estimator = sg::parseFrfEstimator(*parsed->value("--estimator"));
  auto forceWidth = parsed->number("--force-window");
  auto tau = parsed->number("--exp-window");
  auto maxCondition = parsed->number("--max-condition");
  std::vector<core::Dof> references;
  if (auto ref = parsed->value("--reference")) {
    std::stringstream list(*ref);
    for (std::string item; std::getline(list, item, ',');) {
      auto dof = core::parseDof(item);
      if (!dof) {
        err << "mozzi-cli frf: --reference: " << dof.error().describe() << "\n" << kUsage;
        return kExitUsage;
      }
      if (std::find(references.begin(), references.end(), *dof) != references.end()) {
        err << "mozzi-cli frf: --reference names " << core::formatDof(*dof) << " twice\n" << kUsage;
        return kExitUsage;
      }
      references.push_back(*dof);
    }
  }
  if (!estimator || !forceWidth || !tau || !maxCondition) {
    err << "mozzi-cli frf: "
        << (!estimator    ? estimator.error().describe()
            : !forceWidth ? forceWidth.error().describe()
            : !tau        ? tau.error().describe()
                          : maxCondition.error().describe())
        << "\n"
        << kUsage;
    return kExitUsage;
  }
  if (references.size() > 1 && *estimator != sg::FrfEstimator::H1) {
    err << "mozzi-cli frf: " << sg::frfEstimatorName(*estimator)
        << " takes one reference; with several --reference DOFs use --estimator H1\n"
        << kUsage;
    return kExitUsage;
  }

  if (int rc = refuseOutputsOntoInputs(*parsed, kSpec, {path}, "frf", err); rc != kExitOk) return rc;

  // Hits stream from the file one at a time, read straight into reused
  // sample matrices (core/io/uff_hits.h): memory is four hits, not the file.
  auto hitReader = core::io::UffHitReader::open(path, references);
  if (!hitReader) {
    err << "mozzi-cli frf: " << hitReader.error().describe() << "\n";
    return kExitFailure;
  }

  // Force window: the given width, tapered over a quarter of it.
  sg::FrfOptions options = sg::FrfOptions::hammer(*estimator, *forceWidth, forceWidth->value_or(0.0) * 0.25, *tau);
  if (maxCondition->has_value()) options.maxReferenceConditionNumber = **maxCondition;
  // Several references: the load cases are blocks of a shaker (random) test,
  // not hammer hits, so only the overload check of the hit assessment applies.
  bool multiReference = false;
  AveragingThread averaging(options);
  hitReader->onFirstLength([&averaging](Eigen::Index n) { averaging.prepare(n); });
  // An error of this thread is reported after the hits handed over before it
  // are averaged: if one of those failed, its error comes first, as in a
  // loop that averages each hit before reading the next.
  const auto fail = [&](const std::string& message) {
    const auto& earlier = averaging.finish();
    err << "mozzi-cli frf: " << (earlier ? *earlier : message) << "\n";
    return kExitFailure;
  };
  nlohmann::json jsonHits = nlohmann::json::array();
  std::ostringstream text;
  int accepted = 0, rejected = 0;
  double band10 = 0.0, band20 = 0.0;
  bool haveBand = false;
  int reads = 0;  // calls of hitReader->next()
  for (bool firstHit = true;; firstHit = false) {
    averaging.beforeRead(++reads);
    auto nextHit = hitReader->next();
    if (!nextHit) return fail(nextHit.error().describe());
    if (!*nextHit) break;
    const core::io::UffHit& hit = **nextHit;
    if (firstHit) {
      if (forceWidth->has_value()) {
        // A window narrower than one sample keeps at most the sample at t = 0:
        // the FRF would be noise with coherence near 0.
        const double rate = hit.record.sampleRateHz;
        if (**forceWidth * rate < 1.0) {
          return fail("option --force-window = " + fmt(**forceWidth) + " s is shorter than one sample of " + path +
                      " (1/" + fmt(rate) + " Hz = " + fmt(1.0 / rate) + " s)");
        }
      }
      options.referenceChannels = forceChannels(hit.record);
      multiReference = options.referenceChannels.size() > 1;
    }
    sg::HitQualityOptions qo;
    if (!options.referenceChannels.empty()) qo.referenceChannel = options.referenceChannels.front();
    auto q = sg::assessHit(hit.record, qo);
    if (!q) return fail("load case " + std::to_string(hit.loadCase) + ": " + q.error().describe());
    if (multiReference) {
      q->accepted = true;
      q->reasons.clear();
      for (const auto& ch : q->channels) {
        if (ch.clipped) {
          q->accepted = false;
          q->reasons.push_back("overload on " + ch.name + " (" + std::to_string(ch.clippedSamples) + " samples)");
        }
      }
    }
    nlohmann::json jh{{"load_case", hit.loadCase}, {"accepted", q->accepted}, {"reasons", q->reasons}};
    if (!multiReference) {
      jh["pulse_width_s"] = q->pulseWidthS;
      jh["peak_force"] = q->peakForce;
      if (q->usableBand10dBHz) jh["usable_band_10db_hz"] = *q->usableBand10dBHz;
      if (q->usableBand20dBHz) jh["usable_band_20db_hz"] = *q->usableBand20dBHz;
    }
    jsonHits.push_back(jh);
    text << "  " << (multiReference ? "block " : "hit ") << hit.loadCase << ": " << q->verdictText() << "\n";
    if (!q->accepted) {
      ++rejected;
      continue;
    }
    if (!averaging.submit(hit, reads)) return fail("");  // an earlier hit failed: its error
    ++accepted;
    // usable band of the average: the narrowest accepted hit's (a shaker
    // test's band is the excitation's, unknown here: up to Nyquist)
    const double nyquist = 0.5 * hit.record.sampleRateHz;
    const double b10 = multiReference ? nyquist : q->usableBand10dBHz.value_or(nyquist);
    const double b20 = multiReference ? nyquist : q->usableBand20dBHz.value_or(nyquist);
    band10 = haveBand ? std::min(band10, b10) : b10;
    band20 = haveBand ? std::min(band20, b20) : b20;
    haveBand = true;
  }
  if (const auto& failed = averaging.finish()) {
    err << "mozzi-cli frf: " << *failed << "\n";
    return kExitFailure;
  }
  if (accepted == 0) {
    err << "mozzi-cli frf: every " << (multiReference ? "block" : "hit") << " was rejected\n" << text.str();
    return kExitFailure;
  }
  sg::SpectralAverager& averager = averaging.averager();
  auto frf = averager.frf();
  if (!frf) {
    err << "mozzi-cli frf: " << frf.error().describe() << "\n";
    return kExitFailure;
  }
  // minimum (multiple) coherence over (0, f_10] per response; below Nyquist
  // with several references (the Nyquist line of a real signal carries no phase)
  const char* cohName = multiReference ? "multiple coherence" : "coherence";
  nlohmann::json jsonCoh = nlohmann::json::array();
  double minCoh = 1.0;
  for (Eigen::Index o = 0; o < frf->responseCount(); ++o) {
    double m = 1.0;
    for (Eigen::Index k = 1; k < frf->lineCount() && frf->frequencyHz[k] <= band10; ++k) {
      if (multiReference && k == frf->lineCount() - 1) break;
      m = std::min(m, frf->coherence[0](k, o));
    }
    minCoh = std::min(minCoh, m);
    jsonCoh.push_back(
        {{"response", core::formatDof(frf->responses[static_cast<std::size_t>(o)])}, {"min_coherence", m}});
  }
  double worstCondition = 1.0, worstConditionHz = 0.0;
  if (multiReference) {
    const core::Vector cond = averager.referenceConditionNumber();
    Eigen::Index k = 0;
    worstCondition = cond.maxCoeff(&k);
    worstConditionHz = frf->frequencyHz[k];
  }
  if (auto outPath = parsed->value("--out")) {
    auto records = uff::fromFrfMatrix(*frf);
    if (!records) {
      err << "mozzi-cli frf: " << records.error().describe() << "\n";
      return kExitFailure;
    }
    uff::UffFile outFile;
    for (auto& r : *records) outFile.datasets.push_back(uff::makeDataset(std::move(r)));
    if (auto ok = uff::writeFile(*outPath, outFile); !ok) {
      err << "mozzi-cli frf: " << ok.error().describe() << "\n";
      return kExitFailure;
    }
  }
  const double tauS = options.exponentialTauS();
  if (parsed->flag("--json")) {
    nlohmann::json refs = nlohmann::json::array();
    for (const auto& d : frf->references) refs.push_back(core::formatDof(d));
    nlohmann::json j{{"file", path},
                     {"estimator", sg::frfEstimatorName(*estimator)},
                     {"frf_type", core::frfTypeName(frf->type)},
                     {"reference", core::formatDof(frf->references[0])},
                     {"references", refs},
                     {"coherence_kind", multiReference ? "multiple" : "ordinary"},
                     {"hits_accepted", accepted},
                     {"hits_rejected", rejected},
                     {"hits", jsonHits},
                     {"usable_band_10db_hz", band10},
                     {"usable_band_20db_hz", band20},
                     {"min_coherence_in_band", minCoh},
                     {"coherence", jsonCoh},
                     {"lines", frf->lineCount()},
                     {"frequency_step_hz", frf->frequencyHz[1] - frf->frequencyHz[0]}};
    if (multiReference) {
      j["max_reference_condition_number"] = worstCondition;
      j["max_reference_condition_hz"] = worstConditionHz;
    }
    if (tauS > 0.0) j["exponential_window"] = {{"tau_s", tauS}, {"added_decay_rate_per_s", 1.0 / tauS}};
    out << j.dump(2) << "\n";
    return kExitOk;
  }
  out << "FRF " << sg::frfEstimatorName(*estimator) << " (" << core::frfTypeName(frf->type) << ") from " << path
      << (multiReference ? ", references " : ", reference ") << dofList(frf->references) << "\n"
      << (multiReference ? "blocks: " : "hits: ") << accepted << " accepted, " << rejected << " rejected\n"
      << text.str();
  if (multiReference) {
    out << "reference conditioning: worst condition number of the normalised Gff " << fmt(worstCondition) << " at "
        << fmt(worstConditionHz, "%.1f") << " Hz (limit " << fmt(options.maxReferenceConditionNumber) << ")\n"
        << "minimum multiple coherence below Nyquist: " << fmt(minCoh, "%.4f") << "\n";
  } else {
    out << "usable band: 10 dB down at " << fmt(band10, "%.1f") << " Hz, 20 dB down at " << fmt(band20, "%.1f")
        << " Hz\n"
        << "minimum " << cohName << " up to " << fmt(band10, "%.1f") << " Hz: " << fmt(minCoh, "%.4f") << "\n";
  }
  if (tauS > 0.0) {
    out << "exponential window tau = " << fmt(tauS) << " s adds " << fmt(1.0 / tauS)
        << " 1/s to every pole's decay: subtract it from identified zeta*omega_n\n";
  }
  return kExitOk;
}

const CommandRegistrar kRegistrar({"frf",
                                   "HITS.uff --estimator H1|H2|Hv [--force-window S] [--exp-window TAU] "
                                   "[--reference NODE:DIR[,NODE:DIR...]] [--max-condition C] [--out FRF.uff] [--json]",
                                   "Hammer FRFs with coherence from UFF 58 time records, hit by hit checked; "
                                   "several references: multiple-input H1 (shakers)",
                                   frfCommand, &kSpec});

}  // namespace
}  // namespace mozzi::cli
