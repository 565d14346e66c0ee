#pragma once
// The stiffness-rig page (Motostiffmeter, thesis §1.1 to §1.3) and the
// tyre-tester page (Mototiremeter, §1.8, §1.9): pick a specimen, the test
// sequence and its settings (forms built from the sequences' and the
// simulated rig's ParameterSpec lists), run it on the simulated rig through
// devices/rigtests off the GUI thread (views::JobRunner), follow it on live
// readouts and Qwt plots redrawn at 25 Hz, stop it, and read the result the
// sequence stored in the project (results table, fitted line on the plot).
//
// The page computes nothing: the sequence (devices/rigtests) runs the test,
// fits and stores; the page shows what it sends (live blocks, step reports)
// and then what the project holds. The sequence's callbacks run on the job's
// worker thread; they only append to a locked hand-over buffer that a GUI
// timer drains every 40 ms (never more than one redraw per tick, whatever the
// data rate: a simulated rig out of real time delivers much faster).

#include <QElapsedTimer>
#include <QPointF>
#include <QString>
#include <QVector>
#include <QWidget>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "devices/common/parameters.h"
#include "views/common/page_registry.h"

class QComboBox;
class QLabel;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QSplitter;
class QTabWidget;
class QTableWidget;
class QTimer;
class QwtPlot;
class QwtPlotCurve;
class QwtPlotIntervalCurve;
class QGroupBox;

namespace mozzi {
namespace devices::rigtests {
struct LiveReadout;
struct StepReport;
struct Quantity;
struct Outcome;
}  // namespace devices::rigtests

namespace views {

class InteractivePlot;
class ParameterForm;
class PlateSketch;
struct RigHandOver;

class RigTestPage : public QWidget {
  Q_OBJECT
 public:
  enum class Rig { Stiffness, Tyre };

  RigTestPage(Rig rig, const PageContext& ctx);
  ~RigTestPage() override;

  Rig rig() const { return rig_; }

  // The controls, for tests and for the user guide's figures.
  QComboBox* specimenBox() const { return specimen_; }
  QComboBox* testBox() const { return test_; }
  ParameterForm* rigForm() const { return rigForm_; }
  ParameterForm* testForm() const { return testForm_; }
  // Stiffness rig: the set-up form (plate, lasers, load point, constrained
  // end; devices/rigtests stiffnessSetupParameters), its picture over the
  // specimen's silhouette (the drawing the Twist Axes page uses) and the
  // result of the geometry check ("" when the set-up is fine). Null for the
  // tyre tester.
  ParameterForm* setupForm() const { return setupForm_; }
  QwtPlot* setupPlot() const;
  PlateSketch* setupSketch() const { return sketch_.get(); }
  QString geometryText() const;
  // The tabs over the plots: the measurement's plots, and the set-up view.
  QTabWidget* plotTabs() const { return plotTabs_; }
  QPushButton* runButton() const { return run_; }
  QPushButton* stopButton() const { return stop_; }
  QTableWidget* resultsTable() const { return results_; }
  QwtPlot* livePlot() const { return livePlot_; }
  QwtPlot* resultPlot() const { return resultPlot_; }
  // Sine sweep: the dynamic twist axis against frequency (inclination [deg]
  // on the left axis, twist arm a_tw [mm] on the right, each with its
  // one-sigma bars), filled as frequencies complete and from a stored test.
  QwtPlot* axisPlot() const { return axisPlot_; }
  QString statusText() const;
  QString readoutText() const;
  // The rig's set-up for the chosen specimen (plate points, load point; tyre
  // load, contact half-length and limits).
  QString setupText() const;

  // Selects a specimen by catalogue key ("fork-a-with-wheel") and a test by
  // id ("static", "dynamic", "relaxation", "steady-state"); false if absent.
  bool selectSpecimen(const QString& key);
  bool selectTest(const QString& id);

  bool isRunning() const { return jobId_ != 0; }
  // The test the last run stored (rig_test.id or tyre_test.id).
  std::optional<qint64> lastTestId() const { return lastTestId_; }
  // Live plot redraws since the run started (the 25 Hz timer's) and their
  // mean rate between the first and the last one [Hz] (0 before two).
  int redrawCount() const { return redraws_; }
  double redrawRateHz() const;

  // Shows a stored test of this page's kind (its results from the project).
  void showStoredTest(qint64 testId);

 public slots:
  // Checks the settings (the error is shown, nothing moves) and starts the run.
  void start();
  // Asks the sequence to stop: it keeps the steps committed and stores the
  // test as interrupted.
  void stop();

 signals:
  // The run ended (ok: the sequence completed the test).
  void finished(bool ok);

 protected:
  void changeEvent(QEvent* event) override;
  void showEvent(QShowEvent* event) override;

 private:
  void buildUi();
  QWidget* buildControls();   // the run controls (rig_test_page.cpp)
  QWidget* buildSetupView();  // the stiffness rig's set-up tab (rig_test_setup.cpp)
  void retranslate();
  void fillSpecimens();
  void fillTests();
  void rebuildTestForm();
  void showSetup();
  void rebuildSetupForm();
  void drawSetup();
  // The set-up form's geometry values (without the actuator choice).
  devices::ParameterMap geometryValues() const;
  void drain();
  void onLive(const devices::rigtests::LiveReadout& r);
  void onStep(const devices::rigtests::StepReport& s);
  // One stored result or parameter of a test, as showStoredTest() lists it.
  struct StoredRow {
    std::optional<int> step;
    std::string key;
    double value, uncertainty;
    std::string unit;
  };
  void drawStoredFits(qint64 testId, const std::vector<StoredRow>& rows, double tyreLoadN, double tyrePressurePa);
  void onJobFinished(const core::Result<devices::rigtests::Outcome>& result);
  void onDone(bool ok, const std::function<QString()>& message);
  // Sine sweep: one frequency's axis point and its sine-fit loop (results of
  // a step report or of the stored step).
  void addAxisPoint(const std::vector<devices::rigtests::Quantity>& results);
  void clearAxisPlot();
  // Empties the curves (clearData) and sets the plots' titles and styles for
  // the selected test; without clearData only titles and styles (a language change).
  void resetPlots(bool clearData = true);
  // The latest test the project holds for the selected specimen (of the
  // selected test's kind, or of any kind), shown as showStoredTest() does.
  std::optional<qint64> latestStoredTest(bool anyKind) const;
  void showLatestStored(bool anyKind);
  void replot();
  // The status line, kept as how to say it: a language change says it again.
  void setStatus(std::function<QString()> text, bool error = false);
  void setRunning(bool running);
  QString testId() const;
  QString specimenKey() const;

  Rig rig_;
  ProjectModel* model_;
  JobRunner* jobs_;
  std::function<void(const QString&)> log_;

  QGroupBox* setupBox_ = nullptr;
  QGroupBox* rigBox_ = nullptr;
  QGroupBox* testBoxGroup_ = nullptr;
  QGroupBox* resultsBox_ = nullptr;
  QLabel* specimenLabel_ = nullptr;
  QLabel* testLabel_ = nullptr;
  QComboBox* specimen_ = nullptr;
  QComboBox* test_ = nullptr;
  ParameterForm* rigForm_ = nullptr;
  ParameterForm* testForm_ = nullptr;
  ParameterForm* setupForm_ = nullptr;
  QGroupBox* setupFormBox_ = nullptr;
  QWidget* setupScroll_ = nullptr;  // the form's scroll area, as wide as the form
  QTabWidget* plotTabs_ = nullptr;
  QSplitter* controlsSplit_ = nullptr;  // the controls | the plots
  bool controlsSized_ = false;          // the split set once, when first shown
  InteractivePlot* setupPlot_ = nullptr;
  QwtPlotCurve* setupExtent_ = nullptr;  // draws nothing: the points the set-up view must hold
  std::unique_ptr<PlateSketch> sketch_;
  QLabel* geometry_ = nullptr;
  QLabel* setupNote_ = nullptr;
  QPushButton* run_ = nullptr;
  QPushButton* stop_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QLabel* status_ = nullptr;
  std::function<QString()> statusSource_;
  bool statusError_ = false;
  bool showingStored_ = false;  // in showStoredTest(): its test selection shows nothing else
  QLabel* readout_ = nullptr;
  QLabel* setupInfo_ = nullptr;
  QwtPlot* livePlot_ = nullptr;
  QwtPlot* resultPlot_ = nullptr;
  QwtPlot* axisPlot_ = nullptr;
  QTableWidget* results_ = nullptr;
  QPlainTextEdit* logView_ = nullptr;
  QLabel* headline_ = nullptr;
  QTimer* timer_ = nullptr;

  // Live curves: live plot (time traces, two axes), result plot (two curves
  // plus a fitted line).
  QwtPlotCurve* timeLeft_ = nullptr;
  QwtPlotCurve* timeRight_ = nullptr;
  QwtPlotCurve* xyLive_ = nullptr;
  QwtPlotCurve* xySecond_ = nullptr;
  QwtPlotCurve* fitLine_ = nullptr;
  QwtPlotCurve* fitLine2_ = nullptr;
  QwtPlotCurve* mfSlip_ = nullptr;    // the stored Magic Formula over the side-slip sweep
  QwtPlotCurve* mfCamber_ = nullptr;  // ... and over the camber sweep
  QwtPlotCurve* sineFit_ = nullptr;   // sine sweep: the loop the last frequency's sine fits describe
  QwtPlotCurve* inclination_ = nullptr;
  QwtPlotCurve* arm_ = nullptr;
  QwtPlotIntervalCurve* inclinationBars_ = nullptr;
  QwtPlotIntervalCurve* armBars_ = nullptr;
  QVector<QPointF> timeLeftData_, timeRightData_, xyData_, xySecondData_;
  // Sine sweep: (f [Hz], inclination [deg]) and (f, a_tw [mm]); their sigmas as (f, sigma).
  QVector<QPointF> inclinationData_, armData_, inclinationSigma_, armSigma_;
  double timeWindowS_ = 0.0;  // 0: keep the whole step
  int liveStep_ = -1;
  bool dirty_ = false;
  int redraws_ = 0;
  qint64 firstRedrawMs_ = -1, lastRedrawMs_ = -1;
  QElapsedTimer clock_;

  std::shared_ptr<RigHandOver> handOver_;
  int jobId_ = 0;
  std::optional<qint64> lastTestId_;
  QString runningTest_;
  // Plate geometry of the running (or shown) stiffness test, for the sine-fit loop.
  std::vector<std::pair<double, double>> laserPoints_;
  std::pair<double, double> loadPoint_{0.0, 0.0};
  std::vector<std::string> roles_;  // tyre tester: channel names of F_y, M_z, yaw angle, camber angle
};

}  // namespace views
}  // namespace mozzi
