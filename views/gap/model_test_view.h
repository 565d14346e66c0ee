#pragma once
// "Model vs test": the workbench face of the sim-to-real gap diagnosis
// (core/gap, shared/GAP.md). Choose a model file and a test file, run the
// diagnosis off the GUI thread, read the gap by band, DOF, mode or condition,
// the ranked candidate effects with sizes and standard errors, the verdict, and
// the measured/model overlay before and after the best effect; export it all as
// a report (HTML with the figures, plus the JSON the CLI writes). With a
// project open it also lists the diagnoses the project keeps and shows one as
// it was stored (verdict, ranking, gap, overlay) without running anything.

#include <QString>
#include <QWidget>
#include <map>
#include <memory>
#include <optional>

#include "core/gap/diagnosis.h"
#include "core/gap/gap_problem.h"
#include "views/gap/stored_diagnosis.h"
#include "views/plots/interactive_plot.h"

class QCheckBox;
class QComboBox;
class QHBoxLayout;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTabWidget;
class QTableWidget;
class QTextBrowser;
class QwtPlot;
class QwtPlotCurve;

namespace mozzi {
namespace views {

class JobRunner;
class ProjectModel;

class ModelTestView : public QWidget {
  Q_OBJECT
 public:
  // Runs the diagnosis on `jobs` (the window's runner); without one the view
  // keeps a runner of its own.
  explicit ModelTestView(QWidget* parent = nullptr, JobRunner* jobs = nullptr);
  ~ModelTestView() override;

  // What the buttons do; the GUI tests call these directly.
  void setModelPath(const QString& path);
  void setTestPath(const QString& path);
  void setBand(double lowHz, double highHz);  // 0, 0 = the whole measured band
  void setBootstrapSamples(int samples);
  void setMultistarts(int starts);
  // Ticks exactly the named candidate effects (after loadInputs()).
  void setEffects(const QStringList& names);
  // Reads both files and lists the candidate effects; false (and a message in
  // the status line) when a file cannot be used.
  bool loadInputs();
  // Starts the diagnosis as a job of the JobRunner; false when inputs are missing or
  // a run is under way. finished() is emitted when it ends (ok or not).
  bool run();
  void cancel();
  bool isRunning() const;
  // The open project: its kept gap diagnoses are listed ("Kept diagnoses")
  // and follow its changes.
  void setProjectModel(ProjectModel* model);
  // Shows a kept diagnosis (analysis id) as stored; false, with the reason in
  // the status line, when it is not a readable gap diagnosis.
  bool showStored(qint64 analysisId);
  // Shows the newest kept diagnosis, if the project keeps one.
  bool showNewestStored();
  QComboBox* storedChoice() const { return stored_; }
  // The kept diagnosis shown (nullopt while a run's diagnosis, or none, is shown).
  const std::optional<StoredDiagnosis>& storedDiagnosis() const { return storedDiagnosis_; }

  // Writes the report: HTML at `path`, the JSON beside it (same name, .json).
  bool exportReport(const QString& path, QString* error = nullptr) const;

  const std::optional<core::gap::Diagnosis>& diagnosis() const { return diagnosis_; }
  QString statusText() const;
  QString verdictText() const;
  QTableWidget* rankingTable() const { return ranking_; }
  QTabWidget* whereTabs() const { return whereTabs_; }
  InteractivePlot* overlayPlot() const { return overlayPlot_; }
  int overlayCurveCount() const;
  // Selects the overlay curve (FRF or series) shown; false when out of range.
  bool showOverlay(int index);

 signals:
  void finished(bool ok);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void browseModel();
  void browseTest();
  void onProgress(double fraction, const QString& step);
  void onFinished(core::Result<core::gap::Diagnosis> result);
  void showDiagnosis();
  QHBoxLayout* makeKeptRow();
  QHBoxLayout* makeOptionsRow();
  void refreshStored();
  void showVerdict(const QString& verdict, const QString& effects);
  void showDiagnosisText();
  // "residual_mode at 9+Z" (the effect alone when it has no location), with a
  // family of equivalent locations "residual_mode at 9+Z (equivalent at
  // 10+Z)", "residual_mode at 9+Z (and 24 equivalent locations)".
  static QString effectText(const std::string& effect, const std::vector<std::string>& location,
                            const std::vector<std::vector<std::string>>& equivalent);
  // The "after" legend of the overlay, in the page's language: of the
  // diagnosis run here, of the stored one.
  QString liveAfterLabel() const;
  static QString storedAfterLabel(const StoredDiagnosis& diagnosis);
  void showStoredText();
  // What the band boxes and the candidate list describe: the next run, or the
  // kept diagnosis shown (with or without a frequency band of its own).
  enum class Setup { NextRun, KeptBand, KeptNoBand };
  // Fills the band and the candidate list from the kept diagnosis shown.
  void showStoredSetup();
  // Enables and words the band boxes and the candidate list for `setup`.
  void setSetup(Setup setup);
  // One checkable row per effect, its locations in the tooltip; effects in
  // `unticked` start unticked.
  void fillEffects(const std::map<std::string, std::vector<std::string>>& locations, const QStringList& unticked);
  // "Locations: a; b; ..." with at most a screenful, each entry elided.
  static QString locationsTip(const std::vector<std::string>& locations);
  void fillWhere(const core::gap::GapMetrics* gap);
  void fillRanking();
  void fillRankingRows(const std::vector<StoredDiagnosis::RankedEffect>& rows, double threshold);
  void computeOverlays();
  void setStatus(const QString& text);
  QString htmlReport() const;

  QLabel* storedLabel_ = nullptr;
  QComboBox* stored_ = nullptr;
  QPushButton* showStored_ = nullptr;
  QLineEdit* modelPath_ = nullptr;
  QLineEdit* testPath_ = nullptr;
  QPushButton* browseModel_ = nullptr;
  QPushButton* browseTest_ = nullptr;
  QLabel* modelLabel_ = nullptr;
  QLabel* testLabel_ = nullptr;
  QLabel* bandLabel_ = nullptr;
  QDoubleSpinBox* bandLow_ = nullptr;
  QDoubleSpinBox* bandHigh_ = nullptr;
  QLabel* bootstrapLabel_ = nullptr;
  QSpinBox* bootstrap_ = nullptr;
  QLabel* multistartsLabel_ = nullptr;
  QSpinBox* multistarts_ = nullptr;
  QLabel* effectsLabel_ = nullptr;
  QListWidget* effects_ = nullptr;
  QPushButton* load_ = nullptr;
  QPushButton* run_ = nullptr;
  QPushButton* cancel_ = nullptr;
  QPushButton* export_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QLabel* status_ = nullptr;
  QLabel* verdict_ = nullptr;
  QTextBrowser* explanation_ = nullptr;
  QTabWidget* results_ = nullptr;
  QTabWidget* whereTabs_ = nullptr;
  QTableWidget* ranking_ = nullptr;
  QComboBox* overlayChoice_ = nullptr;
  InteractivePlot* overlayPlot_ = nullptr;
  QwtPlotCurve* measuredCurve_ = nullptr;
  QwtPlotCurve* beforeCurve_ = nullptr;
  QwtPlotCurve* afterCurve_ = nullptr;

  std::shared_ptr<const core::gap::GapProblem> problem_;    // loaded from the current inputs
  std::shared_ptr<const core::gap::GapProblem> running_;    // the one under diagnosis
  std::shared_ptr<const core::gap::GapProblem> diagnosed_;  // the one the shown diagnosis is of
  std::optional<core::gap::Diagnosis> diagnosis_;
  std::vector<core::gap::OverlayCurve> before_;
  std::vector<core::gap::OverlayCurve> after_;
  QString afterLabel_;
  ProjectModel* project_ = nullptr;
  std::optional<StoredDiagnosis> storedDiagnosis_;
  qint64 storedId_ = 0;
  Setup setup_ = Setup::NextRun;

  JobRunner* jobs_ = nullptr;
  int jobId_ = 0;  // the diagnosis under way (0: none)
};

}  // namespace views
}  // namespace mozzi
