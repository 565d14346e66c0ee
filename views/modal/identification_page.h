#pragma once
// The identification page (issue 18): an FRF set, a band, a method (pLSCF,
// LSCE, peak picking, circle fit) and the maximum order; the run goes off the
// GUI thread (JobRunner: progress, cancel). The stabilization diagram over the
// sum or CMIF shows the automatic selection as a start; a click on a pole adds
// or removes it and the modal table (f, zeta, eta, standard errors, MPC, MPD,
// complexity), the synthesised FRFs over the measured ones with the residual
// per FRF, and the MAC / AutoMAC grids follow at once (a tab not shown when
// it is shown; budget 50 ms on 100 FRFs x 20,000 lines). Two chosen poles that
// are one mode (closer than the resolution, or the same shape) raise a
// warning. Save stores the selection, refined as the CLI refines, as a modal
// result of the project. Opened on a set, before any run, the diagram shows
// the set's sum (or CMIF) and, when the project keeps a modal result
// identified from the set, its modes as the selection with their synthesis,
// then the stabilization diagram of its band behind them (a job).
// All numbers come from core through identification_backend.h.

#include <QWidget>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "core/common/frf_matrix.h"
#include "core/io/project_records.h"
#include "core/modal/pole_selection.h"
#include "views/common/page_registry.h"
#include "views/modal/identification_backend.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTabWidget;
class QTableWidget;
class QTableWidgetItem;

namespace mozzi {
namespace views {

class InteractivePlot;
class JobRunner;
class MacPlot;
class ProjectModel;
class StabilizationPlot;

class IdentificationPage : public QWidget {
  Q_OBJECT
 public:
  // Opens the FRF set ctx.item.id (when ctx.item is an FRF set).
  explicit IdentificationPage(const PageContext& ctx);
  ~IdentificationPage() override;

  // --- what a user sets and does (tests drive these as the widgets do) ---
  bool setFrfSet(qint64 frfSetId);
  qint64 frfSetId() const { return frfSetId_; }
  // Time constant of the set's exponential window [s] (0: none), removed from the damping.
  double windowTauS() const { return windowTauS_; }
  void setBand(double lowHz, double highHz);
  void setMethod(identification::Method method);
  void setMaxOrder(int order);
  void setBackdrop(identification::Backdrop backdrop);
  void setRefine(bool on);
  void run();
  void cancel();
  bool isRunning() const;
  // Adds the diagram pole if it is not chosen, else removes it (a click).
  void togglePole(int diagramIndex);
  // Back to the automatic selection.
  void resetSelection();
  // Refines the chosen poles (job) and stores them as a modal result; emits saved().
  void save(const QString& name = QString());

  // --- what it shows ---
  StabilizationPlot* diagramPlot() const { return diagram_; }
  QTableWidget* modalTable() const { return table_; }
  QTableWidget* residualTable() const { return residuals_; }
  InteractivePlot* synthesisPlot() const { return synthesis_; }
  MacPlot* autoMacPlot() const { return autoMac_; }
  MacPlot* macPlot() const { return mac_; }
  const std::vector<core::modal::ModalTableRow>& tableRows() const { return rows_; }
  const std::vector<core::modal::SelectionWarning>& warnings() const { return warnings_; }
  QString statusText() const;
  QString warningText() const;
  // Poles of the current selection (diagram order of choosing).
  std::vector<core::Complex> chosenPoles() const;
  const identification::Outcome* outcome() const { return outcome_ ? &*outcome_ : nullptr; }
  // The kept identification shown until a run replaces it: the project's
  // latest modal result of this set (null when none). Its modes are the
  // selection: the poles of their f and zeta (with the set's exponential
  // window's decay put back, as measured), fitted to the set over its band.
  const core::io::ModalResultInfo* keptResult() const { return kept_ ? &kept_->info : nullptr; }
  // Milliseconds: result delivered -> diagram drawn; click -> table and
  // synthesis shown. Wall time, and the GUI thread's CPU time (what the work
  // costs, whatever else the machine runs).
  double lastDiagramDrawMs() const { return diagramMs_; }
  double lastSelectionUpdateMs() const { return selectionMs_; }
  double lastDiagramDrawCpuMs() const { return diagramCpuMs_; }
  double lastSelectionUpdateCpuMs() const { return selectionCpuMs_; }

 signals:
  void finished(bool ok);
  void selectionChanged();
  void saved(qint64 modalResultId);
  void saveFailed(const QString& why);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  struct Chosen {
    core::Complex pole;
    core::ComplexVector shape;
    int diagramIndex = -1;
  };
  void retranslate();
  void reloadSets();
  // The set's sum or CMIF on the diagram before a run.
  void showBackdrop();
  // The latest modal result of the set as the selection (kept_, chosen_).
  void loadKept();
  // The stabilization diagram of the kept result's band (pLSCF or LSCE, no
  // refinement; a job) drawn behind its modes, each ringed on its pole: the
  // page opens on what was identified and what it was chosen from.
  void drawDiagramBehindKept();
  void cancelKeptDiagram();
  void showDiagramBehindKept(qint64 keptId, core::Result<identification::Outcome> result);
  // outcome_'s diagram over its backdrop.
  void showOutcomeDiagram();
  // The Over box changed: the backdrop before a run or behind the kept result.
  void changeBackdrop();
  // outcome_'s automatic selection, each on its representative pole.
  void takeAutomaticSelection();
  // Band of the fit behind the selection: the run's, else the kept result's.
  std::optional<std::pair<double, double>> selectionBand() const;
  void onFinished(core::Result<identification::Outcome> result);
  void updateSelection();
  // Save enabled with a selection the project does not keep yet.
  void updateSaveButton();
  void showTable();
  void showSynthesis();  // identification_synthesis.cpp
  // A right-aligned, read-only table cell.
  static QTableWidgetItem* cell(const QString& text);
  void showMac();
  // The synthesis and MAC tabs: the one shown now, the other when shown.
  void showTabs();
  void setStatus(const QString& text, bool error);
  // Keeps `model` with the standard errors of its refinement (one per mode).
  void storeModel(const core::modal::ModalModel& model, const QString& name, const std::vector<double>& frequencyStdHz,
                  const std::vector<double>& zetaStd);

  ProjectModel* model_ = nullptr;
  JobRunner* jobs_ = nullptr;
  std::function<void(const QString&)> log_;
  qint64 frfSetId_ = 0;
  qint64 specimenId_ = 0;
  // Exponential window of the campaign that measured the set [s], 0: none;
  // its decay is removed from the table and the saved modes, as the CLI does.
  double windowTauS_ = 0.0;
  std::shared_ptr<const core::FrfMatrix> frf_;
  std::optional<identification::Outcome> outcome_;
  struct Kept {
    core::io::ModalResultInfo info;
    core::io::ModalTable table;
  };
  std::optional<Kept> kept_;
  std::vector<Chosen> chosen_;
  std::vector<Chosen> automatic_;
  // The pole-click fit over the run's band (made when first needed, dropped
  // with the run or the set): what does not depend on the poles done once.
  std::optional<identification::SelectionFitter> fitter_;
  std::optional<identification::Fit> fit_;
  // A tab not shown is brought up to date when it is shown, not at each click.
  bool synthesisStale_ = false, macStale_ = false;
  // Standard errors belong to the automatic selection's refinement; shown
  // while the selection is that one.
  bool selectionIsAutomatic_ = false;
  // The selection is the kept identification's, unchanged: saving it would
  // store a copy of what the project keeps.
  bool selectionIsKept_ = false;
  std::vector<core::modal::ModalTableRow> rows_;
  std::vector<core::modal::SelectionWarning> warnings_;
  int jobId_ = 0;
  int keptDiagramJob_ = 0;
  double diagramMs_ = 0.0, selectionMs_ = 0.0, diagramCpuMs_ = 0.0, selectionCpuMs_ = 0.0;

  QLabel* setLabel_ = nullptr;
  QComboBox* setBox_ = nullptr;
  QLabel* bandLabel_ = nullptr;
  QDoubleSpinBox* lowBox_ = nullptr;
  QDoubleSpinBox* highBox_ = nullptr;
  QLabel* methodLabel_ = nullptr;
  QComboBox* methodBox_ = nullptr;
  QLabel* orderLabel_ = nullptr;
  QSpinBox* orderBox_ = nullptr;
  QLabel* backdropLabel_ = nullptr;
  QComboBox* backdropBox_ = nullptr;
  QCheckBox* refineBox_ = nullptr;
  QPushButton* runButton_ = nullptr;
  QPushButton* cancelButton_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QLabel* status_ = nullptr;
  QLabel* warning_ = nullptr;
  StabilizationPlot* diagram_ = nullptr;
  QTableWidget* table_ = nullptr;
  QPushButton* autoButton_ = nullptr;
  QLineEdit* nameEdit_ = nullptr;
  QPushButton* saveButton_ = nullptr;
  QTabWidget* tabs_ = nullptr;
  QComboBox* synthesisFrfBox_ = nullptr;
  InteractivePlot* synthesis_ = nullptr;
  QTableWidget* residuals_ = nullptr;
  MacPlot* autoMac_ = nullptr;
  MacPlot* mac_ = nullptr;
  QLabel* autoMacLabel_ = nullptr;
  QLabel* macLabel_ = nullptr;
};

}  // namespace views
}  // namespace mozzi
