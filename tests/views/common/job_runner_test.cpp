// JobRunner: the work runs off the GUI thread; its result, its error and its
// progress arrive in the GUI thread; cancel reaches the worker and the job ends
// with a Cancelled error; a job whose receiver was destroyed delivers nothing
// (and is cancelled); the status-bar widget follows the running jobs.
#include "views/common/job_runner.h"

#include <QAbstractButton>
#include <QApplication>
#include <QSignalSpy>
#include <QThread>
#include <QtTest>

#include <atomic>
#include <memory>
#include <thread>

#include "views/common/job_status_widget.h"

using mozzi::core::ErrorCode;
using mozzi::core::Result;
using mozzi::views::JobProgress;
using mozzi::views::JobRunner;

class JobRunnerTest : public QObject {
  Q_OBJECT

 private slots:
  void deliversTheResultInTheGuiThread() {
    JobRunner jobs;
    QThread* gui = QThread::currentThread();
    std::atomic<QThread*> workerThread{nullptr};
    std::optional<int> value;
    QThread* doneIn = nullptr;
    QSignalSpy finished(&jobs, &JobRunner::jobFinished);
    const int id = jobs.run<int>(
        QStringLiteral("sum"),
        [&](JobProgress&) -> Result<int> {
          workerThread = QThread::currentThread();
          int sum = 0;
          for (int i = 1; i <= 100; ++i) sum += i;
          return sum;
        },
        [&](Result<int> r) {
          doneIn = QThread::currentThread();
          QVERIFY(r.ok());
          value = *r;
        });
    QVERIFY(id > 0);
    QVERIFY(jobs.isRunning(id));
    QCOMPARE(jobs.title(id), QStringLiteral("sum"));
    QVERIFY(finished.wait(5000));
    QCOMPARE(value, std::optional<int>(5050));
    QCOMPARE(doneIn, gui);
    QVERIFY(workerThread.load() != gui);
    QCOMPARE(finished.first().at(0).toInt(), id);
    QCOMPARE(finished.first().at(1).toBool(), true);
    QVERIFY(!jobs.isRunning());
  }

  void deliversTheError() {
    JobRunner jobs;
    std::optional<mozzi::core::Error> error;
    QSignalSpy finished(&jobs, &JobRunner::jobFinished);
    jobs.run<double>(
        QStringLiteral("fit"),
        [](JobProgress&) -> Result<double> {
          return mozzi::core::makeError(ErrorCode::NumericalFailure, "singular fit", "mode 3");
        },
        [&](Result<double> r) {
          QVERIFY(!r.ok());
          error = r.error();
        });
    QVERIFY(finished.wait(5000));
    QVERIFY(error.has_value());
    QCOMPARE(error->code, ErrorCode::NumericalFailure);
    QCOMPARE(QString::fromStdString(error->where), QStringLiteral("mode 3"));
    QCOMPARE(finished.first().at(1).toBool(), false);
  }

  // Progress: the receiver sees fractions in order, the last one reported
  // among them, each with its step; never more events than reports.
  void deliversProgress() {
    JobRunner jobs;
    QList<double> fractions;
    QStringList steps;
    QSignalSpy progress(&jobs, &JobRunner::jobProgress);
    QSignalSpy finished(&jobs, &JobRunner::jobFinished);
    std::atomic<bool> go{false};
    jobs.run<int>(
        this, QStringLiteral("steps"),
        [&](JobProgress& p) -> Result<int> {
          for (int i = 1; i <= 4; ++i) {
            p.report(0.25 * i, "step " + std::to_string(i));
            // Let the GUI thread see each report before the next one.
            while (!go.exchange(false)) std::this_thread::yield();
          }
          return 4;
        },
        [](Result<int>) {},
        [&](double f, const QString& step) {
          fractions << f;
          steps << step;
          go = true;
        });
    QVERIFY(finished.wait(5000));
    QCOMPARE(fractions, (QList<double>{0.25, 0.5, 0.75, 1.0}));
    QCOMPARE(steps.last(), QStringLiteral("step 4"));
    QCOMPARE(progress.count(), 4);
    // Clamped to [0, 1].
    JobProgress standalone;
    standalone.report(1.7, "over");
    QCOMPARE(standalone.fraction(), 1.0);
    standalone.report(-3.0);
    QCOMPARE(standalone.fraction(), 0.0);
    QCOMPARE(standalone.step(), std::string("over"));
  }

  void cancelReachesTheWorker() {
    JobRunner jobs;
    std::atomic<bool> started{false};
    std::optional<mozzi::core::Error> error;
    QSignalSpy finished(&jobs, &JobRunner::jobFinished);
    const int id = jobs.run<int>(
        QStringLiteral("endless"),
        [&](JobProgress& p) -> Result<int> {
          started = true;
          while (!p.cancelled()) QThread::msleep(1);
          return 1;  // a worker that ignores its own cancellation still ends as cancelled
        },
        [&](Result<int> r) {
          QVERIFY(!r.ok());
          error = r.error();
        });
    QTRY_VERIFY_WITH_TIMEOUT(started.load(), 5000);
    jobs.cancel(id);
    QVERIFY(finished.wait(5000));
    QVERIFY(error.has_value());
    QCOMPARE(error->code, ErrorCode::Cancelled);

    // The core-callback adapter answers "stop" once cancelled.
    JobProgress p;
    auto callback = p.callback();
    QVERIFY(callback(0.1, "a"));
    p.cancel();
    QVERIFY(!callback(0.2, "b"));
    QCOMPARE(p.fraction(), 0.2);
  }

  void deadReceiverGetsNothing() {
    JobRunner jobs;
    auto receiver = std::make_unique<QObject>();
    std::atomic<bool> release{false};
    std::atomic<bool> sawCancel{false};
    bool delivered = false;
    bool progressed = false;
    QSignalSpy finished(&jobs, &JobRunner::jobFinished);
    jobs.run<int>(
        receiver.get(), QStringLiteral("orphan"),
        [&](JobProgress& p) -> Result<int> {
          while (!release.load()) QThread::msleep(1);
          sawCancel = p.cancelled();
          p.report(0.5, "half");
          return 42;
        },
        [&](Result<int>) { delivered = true; }, [&](double, const QString&) { progressed = true; });
    receiver.reset();  // the page closes while its job runs
    release = true;
    QVERIFY(finished.wait(5000));
    QCoreApplication::processEvents();
    QVERIFY(!delivered);
    QVERIFY(!progressed);
    QVERIFY(sawCancel.load());  // the job was told to stop when its receiver died
    QVERIFY(!jobs.isRunning());
  }

  void runnerDestroyedWhileAJobRunsWaitsAndDeliversNothing() {
    bool delivered = false;
    std::atomic<bool> sawCancel{false};
    {
      JobRunner jobs;
      jobs.run<int>(
          QStringLiteral("long"),
          [&](JobProgress& p) -> Result<int> {
            while (!p.cancelled()) QThread::msleep(1);
            sawCancel = true;
            return 0;
          },
          [&](Result<int>) { delivered = true; });
    }  // ~JobRunner cancels and waits
    QVERIFY(sawCancel.load());
    QCoreApplication::processEvents();
    QVERIFY(!delivered);
  }

  void statusWidgetShowsTheRunningJob() {
    JobRunner jobs;
    mozzi::views::JobStatusWidget status(&jobs);
    QCOMPARE(status.shownJob(), 0);
    std::atomic<bool> release{false};
    QSignalSpy finished(&jobs, &JobRunner::jobFinished);
    auto wait = [&](JobProgress& p) -> Result<int> {
      while (!release.load() && !p.cancelled()) QThread::msleep(1);
      return 0;
    };
    const int a = jobs.run<int>(QStringLiteral("Identify modes"), wait, [](Result<int>) {});
    QCOMPARE(status.shownJob(), a);
    QCOMPARE(status.text(), QStringLiteral("Identify modes"));
    const int b = jobs.run<int>(QStringLiteral("Diagnose gap"), wait, [](Result<int>) {});
    QCOMPARE(status.shownJob(), b);
    QCOMPARE(status.text(), QStringLiteral("Diagnose gap (+1 more)"));
    // Its Cancel button cancels the job it shows.
    auto* cancel = status.findChild<QAbstractButton*>(QStringLiteral("jobCancel"));
    QVERIFY(cancel);
    cancel->click();
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 5000);
    QCOMPARE(finished.first().at(0).toInt(), b);
    QCOMPARE(status.shownJob(), a);
    release = true;
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 5000);
    QCOMPARE(status.shownJob(), 0);
  }
};

QTEST_MAIN(JobRunnerTest)
#include "job_runner_test.moc"
