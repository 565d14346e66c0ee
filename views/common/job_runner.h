#pragma once
// Long work off the GUI thread, always with progress and cancel (WORKBENCH.md;
// the shape of KDAB/hotspot's JobTracker): run() starts a core computation on
// a worker thread and returns a job id; progress, then exactly one result or
// error, arrive queued in the GUI thread. A job whose receiver (the `context`
// object, usually the page) was destroyed delivers nothing. The window owns
// one JobRunner and hands it to every page; its status-bar widget lists the
// jobs under way with a cancel button.
//
//   jobs->run<core::gap::Diagnosis>(this, tr("Model vs test"),
//       [problem](JobProgress& p) { return core::gap::diagnose(*problem, opts(p)); },
//       [this](core::Result<core::gap::Diagnosis> r) { show(std::move(r)); },
//       [this](double f, const QString& step) { bar->setValue(f * 1000); });

#include <QHash>
#include <QMetaObject>
#include <QObject>
#include <QPointer>
#include <QString>
#include <QThreadPool>
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include "core/common/result.h"

namespace mozzi {
namespace views {

// What a worker sees of its job: no Qt in its interface, safe from any thread.
class JobProgress {
 public:
  JobProgress() = default;
  // `onReport` runs (on the reporting thread) after each report(); the
  // JobRunner uses it to wake the GUI thread.
  explicit JobProgress(std::function<void()> onReport) : onReport_(std::move(onReport)) {}
  JobProgress(const JobProgress&) = delete;
  JobProgress& operator=(const JobProgress&) = delete;

  // fraction in [0, 1] (clamped); step: what is being done, in words.
  void report(double fraction, std::string step = {});
  // True once cancel() was called: the worker should return soon (an error
  // with ErrorCode::Cancelled is the usual answer; the runner delivers one anyway).
  bool cancelled() const { return cancelled_.load(); }
  void cancel() { cancelled_.store(true); }

  double fraction() const;
  std::string step() const;

  // For core's callbacks of the form bool(fraction, step) that return
  // "go on": reports and answers !cancelled(). The object must outlive it.
  std::function<bool(double, const std::string&)> callback();

 private:
  std::atomic<bool> cancelled_{false};
  mutable std::mutex mutex_;
  double fraction_ = 0.0;
  std::string step_;
  std::function<void()> onReport_;
};

class JobRunner : public QObject {
  Q_OBJECT
 public:
  template <class T>
  using Work = std::function<core::Result<T>(JobProgress&)>;
  template <class T>
  using Done = std::function<void(core::Result<T>)>;
  using Progress = std::function<void(double fraction, const QString& step)>;

  explicit JobRunner(QObject* parent = nullptr);
  // Cancels every job and waits for the workers.
  ~JobRunner() override;

  // Starts `work` on a worker thread; returns the job id (> 0). `done` runs in
  // the GUI thread with the work's result (an ErrorCode::Cancelled error when
  // the job was cancelled), `progress` (optional) with the latest report,
  // both only while `context` lives. `context` lives in the GUI thread.
  template <class T>
  int run(QObject* context, const QString& title, Work<T> work, Done<T> done, Progress progress = {});
  // The same with this runner as the context (for callers that outlive it).
  template <class T>
  int run(const QString& title, Work<T> work, Done<T> done, Progress progress = {}) {
    return run<T>(this, title, std::move(work), std::move(done), std::move(progress));
  }

  // Asks a job to stop (its worker sees JobProgress::cancelled()).
  void cancel(int jobId);
  void cancelAll();
  bool isRunning(int jobId) const { return jobs_.contains(jobId); }
  bool isRunning() const { return !jobs_.isEmpty(); }
  QList<int> runningJobs() const;
  QString title(int jobId) const;
  double fraction(int jobId) const;
  QString step(int jobId) const;
  // Blocks until every worker has returned (shutdown, tests); results still
  // arrive through the event loop afterwards.
  bool waitForDone(int msecs = -1);

 signals:
  void jobStarted(int jobId, const QString& title);
  void jobProgress(int jobId, double fraction, const QString& step);
  // After the job's `done` (ok: the work returned a value and was not cancelled).
  void jobFinished(int jobId, bool ok);

 private:
  struct Job {
    QString title;
    std::shared_ptr<JobProgress> progress;
    QPointer<QObject> context;
    Progress onProgress;
    std::atomic<bool> progressPosted{false};
  };
  int startJob(const QString& title, QObject* context, Progress onProgress,
               std::function<void(int jobId, JobProgress&)> body);
  void deliverProgress(int jobId);
  // GUI thread: forgets the job; true when its context still lives.
  bool finishJob(int jobId);

  QThreadPool pool_;
  QHash<int, std::shared_ptr<Job>> jobs_;  // GUI thread only
  int nextId_ = 1;
};

template <class T>
int JobRunner::run(QObject* context, const QString& title, Work<T> work, Done<T> done, Progress progress) {
  // The worker computes, then posts the result to this runner (which outlives
  // every worker); the runner hands it on only if the context still lives.
  auto body = [this, work = std::move(work), done = std::move(done)](int jobId, JobProgress& p) {
    auto result = std::make_shared<core::Result<T>>(work(p));
    if (p.cancelled() && result->ok()) {
      *result = core::Result<T>(core::makeError(core::ErrorCode::Cancelled, "cancelled by the user"));
    }
    QMetaObject::invokeMethod(
        this,
        [this, jobId, result, done] {
          const bool ok = result->ok();
          if (finishJob(jobId) && done) done(std::move(*result));
          emit jobFinished(jobId, ok);
        },
        Qt::QueuedConnection);
  };
  return startJob(title, context, std::move(progress), std::move(body));
}

}  // namespace views
}  // namespace mozzi
