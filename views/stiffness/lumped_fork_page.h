#pragma once
// Lumped fork models (issue 22; thesis §4.2, Table 12) and bicycle-fork
// stiffness and damping (§6.4, §6.5).
//
// Motorcycle fork: the inputs of Table 12 in a form built from
// devices/rigtests/fork_model_inputs.h's parameter specs (defaults: the
// thesis's enduro fork), the measured modes of a modal result of the project
// beside the three models' natural frequencies (a table and a frequency
// ladder), and the fitted parameters k_i, L_i, J_i, the pure moment, f_n,
// c_i, zeta_i of models 1 to 3 — what core::stiffness::forkLumpedModels
// computes and `mozzi-cli fork lumped` prints, to its printed digits (six
// significant). Bicycle fork: the torsion stiffness with the wheel and alone,
// the bending arm h_W where the two stiffness curves of eq. 57 to 59 meet, the
// bending stiffness and both dampings (core::stiffness::bicycleForkTorsion,
// bicycleForkBending; `mozzi-cli fork bicycle`), with the two curves plotted.
//
// The computation runs on the window's JobRunner; "Keep in project" stores the
// result as a project model of kind "lumped" (the JSON keys of
// `mozzi-cli fork ... --json`) and an analysis of kind "lumped-fork" or
// "bicycle-fork" naming it, which the project report shows with the stiffness
// results.

#include <QString>
#include <QWidget>
#include <memory>
#include <optional>

#include "views/common/page_registry.h"

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;
class QTabWidget;
class QwtPlotCurve;

namespace mozzi {
namespace views {

class InteractivePlot;
class ParameterForm;
struct LumpedForkOutcome;

class LumpedForkPage : public QWidget {
  Q_OBJECT
 public:
  explicit LumpedForkPage(const PageContext& ctx);
  ~LumpedForkPage() override;

  // Computes both the motorcycle models and the bicycle fork from the forms,
  // on the job runner; computed() follows.
  void compute();
  // Takes the frequency and damping ratio of mode `index` of the shown modal
  // result into the motorcycle form.
  bool useMeasuredMode(int index);
  // Stores the motorcycle models (or the bicycle fork's results) as a model of
  // kind "lumped" for the chosen specimen, with an analysis naming it (and the
  // modal result whose modes are shown); the model's id, or 0 (the reason in
  // statusText()).
  qint64 keepLumpedModels();
  qint64 keepBicycleFork();
  // Re-reads the project's specimens and modal results.
  void reload();

  // For tests and the user guide.
  ParameterForm* lumpedForm() const { return lumpedForm_; }
  ParameterForm* bicycleForm() const { return bicycleForm_; }
  QComboBox* specimenBox() const { return specimen_; }
  QComboBox* modalResultBox() const { return modal_; }
  QTableWidget* modelTable() const { return models_; }
  QTableWidget* modeTable() const { return modes_; }
  QTableWidget* bicycleTable() const { return bicycle_; }
  InteractivePlot* ladderPlot() const { return ladder_; }
  InteractivePlot* curvesPlot() const { return curves_; }
  QString statusText() const;
  bool isComputing() const { return computing_; }

 signals:
  void computed(bool ok);
  void message(const QString& text);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void buildUi();
  void retranslate();
  void fillModes();
  void present();
  void presentModels();
  void presentModes();
  void presentBicycle();
  qint64 keep(const QString& name, const std::string& analysisKind, const std::string& json, qint64 modalResultId);

  ProjectModel* model_ = nullptr;
  JobRunner* jobs_ = nullptr;
  std::unique_ptr<LumpedForkOutcome> outcome_;
  bool computing_ = false;
  QString status_;
  QComboBox* specimen_ = nullptr;
  QComboBox* modal_ = nullptr;
  ParameterForm* lumpedForm_ = nullptr;
  ParameterForm* bicycleForm_ = nullptr;
  QTableWidget* models_ = nullptr;
  QTableWidget* modes_ = nullptr;
  QTableWidget* bicycle_ = nullptr;
  InteractivePlot* ladder_ = nullptr;
  InteractivePlot* curves_ = nullptr;
  QPushButton* compute_ = nullptr;
  QPushButton* useMode_ = nullptr;
  QPushButton* keepLumped_ = nullptr;
  QPushButton* keepBicycle_ = nullptr;
  QLabel* specimenLabel_ = nullptr;
  QLabel* modalLabel_ = nullptr;
  QLabel* statusLabel_ = nullptr;
  QLabel* legend_ = nullptr;
  QLabel* bicycleNote_ = nullptr;
  QTabWidget* tabs_ = nullptr;
};

}  // namespace views
}  // namespace mozzi
