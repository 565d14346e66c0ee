#pragma once
// Stability against speed (issue 22; thesis §4.2 Figure 33, §6.6 Figures 51
// and 52; Meijaard et al. 2007 Figure 3): the real and imaginary parts of the
// eigenvalues of a bicycle model over a speed range, each mode tracked and
// named by core (core/stability/mode_tracking.h), the critical speeds (a real
// part crossing zero) marked on both plots and listed. Models: the benchmark
// bicycle of Meijaard et al. (2007) and the same bicycle with the thesis's
// compliant steel fork in bending (§6.5) or torsion (§6.4); the motorcycle in
// the structure of Sharp (1971) with a rigid fork or the lumped fork models 1
// to 3 of thesis §4.2 (Table 12, Figure 33). Parameters: built in (the
// benchmark bicycle) or from a parameter file (core/stability/parameter_file:
// the bicycle's or Sharp's CSV, as `mozzi-cli stability --params` reads).
// "Compare with the rigid fork" sweeps the same vehicle with a rigid fork too
// and draws both on one plot (rigid: open symbols, dotted markers). The
// sweeps run on the job runner; the page computes nothing itself. With a
// project open, every sweep is kept as an analysis of kind "stability"
// (core/stability/stability_record.h), which the page lists and re-shows, as
// `mozzi-cli stability --project` and the project report read it.

#include <QString>
#include <QStringList>
#include <QWidget>
#include <optional>
#include <vector>

#include "core/stability/kept_forks.h"
#include "core/stability/mode_tracking.h"
#include "core/stability/stability_record.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QwtPlot;
class QwtPlotMarker;

namespace mozzi {
namespace views {

class JobRunner;
class ProjectModel;

class StabilityPage : public QWidget {
  Q_OBJECT
 public:
  enum class Model {
    Benchmark = 0,
    ForkBending,
    ForkTorsion,
    Motorcycle,  // Sharp (1971) structure, rigid fork
    MotorcycleFork1,
    MotorcycleFork2,
    MotorcycleFork3
  };
  static bool isMotorcycle(Model m) { return m >= Model::Motorcycle; }
  static bool hasCompliantFork(Model m) { return m != Model::Benchmark && m != Model::Motorcycle; }

  StabilityPage(QWidget* parent, JobRunner* jobs);

  void setModel(Model model);
  void setSpeedRange(double fromMps, double toMps, double stepMps);
  // A parameter file (empty: the built-in benchmark bicycle; the motorcycle needs one).
  void setParameterFile(const QString& path);
  QString parameterFile() const { return parameterFile_; }
  // Also sweep the rigid-fork vehicle and draw it on the same plots.
  void setCompareRigid(bool on);
  // The project whose kept forks (Lumped Fork page: analyses "lumped-fork",
  // "bicycle-fork") the Fork choice offers beside the thesis's.
  void setProjectModel(ProjectModel* model);
  // 0: the thesis's fork; i > 0: the i-th kept fork the choice lists.
  bool setForkChoice(int index);
  int forkChoiceCount() const;
  // Starts the sweep (on the job runner when there is one, else at once);
  // with a project open the result is kept in it.
  void run();
  // On opening: the last kept result, else a sweep with the page's defaults
  // that is not kept.
  void openShowing();
  // The stability analyses the project keeps (ids, in the list's order), and
  // one of them shown again (false and the error in the summary if unreadable).
  std::vector<qint64> storedResults() const;
  bool showStored(qint64 analysisId);
  // Draws a record (a stored one, or the report's figure).
  void showRecord(core::stability::StabilityRecord record);
  qint64 lastStoredId() const { return lastStoredId_; }  // 0: the last sweep was not kept
  // The record shown (a copy: for tests and the log).
  std::optional<core::stability::StabilityRecord> record() const;
  // For tests and the log.
  const std::optional<core::stability::StabilitySweep>& sweep() const { return sweep_; }
  const std::optional<core::stability::StabilitySweep>& rigidSweep() const { return rigidSweep_; }
  QString summaryText() const;
  QwtPlot* realPlot() const { return real_; }
  QwtPlot* imaginaryPlot() const { return imaginary_; }

 signals:
  void finished(bool ok);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  struct Sweeps;
  void present(core::Result<Sweeps> sweeps, bool keepIt, bool fromStore = false);
  core::stability::StabilityRequest request() const;
  QString keep(const Sweeps& sweeps);
  void refreshStored();
  void start(bool keepResult);
  void modelChanged();
  void refreshForks();
  void chooseParameterFile();
  // Returns the largest real part it drew.
  double drawSweep(const core::stability::StabilitySweep& sweep, bool rigid, QStringList& lines);

  JobRunner* jobs_ = nullptr;
  std::optional<core::stability::StabilityRecord> record_;  // without its sweeps: sweep_, rigidSweep_
  qint64 lastStoredId_ = 0;
  std::optional<core::stability::StabilitySweep> sweep_;
  std::optional<core::stability::StabilitySweep> rigidSweep_;
  QString parameterFile_;
  ProjectModel* project_ = nullptr;
  std::vector<core::stability::KeptFork> kept_;  // the project's, all families
  Model shownFamily_ = Model::Benchmark;         // the family whose speed range is shown
  QComboBox* model_ = nullptr;
  QDoubleSpinBox* from_ = nullptr;
  QDoubleSpinBox* to_ = nullptr;
  QDoubleSpinBox* step_ = nullptr;
  QPushButton* runButton_ = nullptr;
  QCheckBox* compare_ = nullptr;
  QLabel* forkLabel_ = nullptr;
  QComboBox* fork_ = nullptr;
  QLabel* paramsLabel_ = nullptr;
  QLabel* paramsFile_ = nullptr;
  QPushButton* paramsButton_ = nullptr;
  QPushButton* paramsClear_ = nullptr;
  QLabel* modelLabel_ = nullptr;
  QLabel* speedsLabel_ = nullptr;
  QLabel* summary_ = nullptr;
  QLabel* storedLabel_ = nullptr;
  QComboBox* stored_ = nullptr;
  QPushButton* showStored_ = nullptr;
  QwtPlot* real_ = nullptr;
  QwtPlot* imaginary_ = nullptr;
  std::vector<QwtPlotMarker*> markers_;  // the zero line and the critical speeds
};

}  // namespace views
}  // namespace mozzi
