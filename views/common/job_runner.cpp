#include "views/common/job_runner.h"

#include <QRunnable>
#include <QThread>
#include <algorithm>
#include <cmath>

namespace mozzi {
namespace views {

void JobProgress::report(double fraction, std::string step) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    fraction_ = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 1.0) : fraction_;
    if (!step.empty()) step_ = std::move(step);
  }
  if (onReport_) onReport_();
}

double JobProgress::fraction() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return fraction_;
}

std::string JobProgress::step() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return step_;
}

std::function<bool(double, const std::string&)> JobProgress::callback() {
  return [this](double fraction, const std::string& step) {
    report(fraction, step);
    return !cancelled();
  };
}

JobRunner::JobRunner(QObject* parent) : QObject(parent) {
  // Core computations are CPU-bound: one worker per core, the rest queue.
  pool_.setMaxThreadCount(std::max(1, QThread::idealThreadCount()));
}

JobRunner::~JobRunner() {
  cancelAll();
  pool_.waitForDone();
}

int JobRunner::startJob(const QString& title, QObject* context, Progress onProgress,
                        std::function<void(int, JobProgress&)> body) {
  const int id = nextId_++;
  auto job = std::make_shared<Job>();
  job->title = title;
  job->context = context ? context : this;
  job->onProgress = std::move(onProgress);
  // report() on the worker wakes the GUI thread at most once per pending
  // delivery, so a chatty worker cannot flood the event queue.
  Job* raw = job.get();
  job->progress = std::make_shared<JobProgress>([this, id, raw] {
    if (!raw->progressPosted.exchange(true)) {
      QMetaObject::invokeMethod(
          this, [this, id] { deliverProgress(id); }, Qt::QueuedConnection);
    }
  });
  jobs_.insert(id, job);
  // A page closed mid-computation stops its job; nothing is delivered to it.
  if (context && context != this) connect(context, &QObject::destroyed, this, [this, id] { cancel(id); });
  // The runnable owns the progress object (and through its callback the job
  // state it touches) until the worker returns.
  auto progress = job->progress;
  auto keep = job;
  QRunnable* runnable = QRunnable::create([body = std::move(body), progress, keep, id] { body(id, *progress); });
  emit jobStarted(id, title);
  pool_.start(runnable);
  return id;
}

void JobRunner::deliverProgress(int jobId) {
  const auto it = jobs_.constFind(jobId);
  if (it == jobs_.constEnd()) return;
  const std::shared_ptr<Job> job = it.value();
  job->progressPosted.store(false);
  const double fraction = job->progress->fraction();
  const QString step = QString::fromStdString(job->progress->step());
  emit jobProgress(jobId, fraction, step);
  if (job->context && job->onProgress) job->onProgress(fraction, step);
}

bool JobRunner::finishJob(int jobId) {
  const std::shared_ptr<Job> job = jobs_.take(jobId);
  return job && job->context;
}

void JobRunner::cancel(int jobId) {
  if (const auto it = jobs_.constFind(jobId); it != jobs_.constEnd()) it.value()->progress->cancel();
}

void JobRunner::cancelAll() {
  for (const auto& job : qAsConst(jobs_)) job->progress->cancel();
}

QList<int> JobRunner::runningJobs() const {
  QList<int> ids = jobs_.keys();
  std::sort(ids.begin(), ids.end());
  return ids;
}

QString JobRunner::title(int jobId) const {
  const auto job = jobs_.value(jobId);
  return job ? job->title : QString();
}

double JobRunner::fraction(int jobId) const {
  const auto job = jobs_.value(jobId);
  return job ? job->progress->fraction() : 0.0;
}

QString JobRunner::step(int jobId) const {
  const auto job = jobs_.value(jobId);
  return job ? QString::fromStdString(job->progress->step()) : QString();
}

bool JobRunner::waitForDone(int msecs) {
  return pool_.waitForDone(msecs);
}

}  // namespace views
}  // namespace mozzi
