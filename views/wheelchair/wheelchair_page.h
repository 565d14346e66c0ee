#pragma once
// The Wheelchair page (issue 22; thesis §7.2 to §7.4, Figures 57 to 60): the
// trajectory of the chair's centre of mass and the rear wheels' slip angles in
// a slalom or a steady-turning manoeuvre, computed by core's five-DOF model
// (core/stability/wheelchair_model.h) as `mozzi-cli wheelchair` computes them,
// for one chair or for the thesis's stiffness studies (the rear cornering or
// aligning stiffness at 0.5, 1 and 2 times its value, one curve each). The
// chair and the manoeuvre come from a form built from a ParameterSpec list
// (views/panels/parameter_form); the simulation runs on the job runner
// (core/stability/wheelchair_record.h runWheelchairStudy). With a project
// open, every simulation is kept as an analysis of kind "wheelchair", which
// the page lists and re-shows, as the project report reads it.

#include <QWidget>
#include <optional>
#include <string>
#include <vector>

#include "core/stability/wheelchair_model.h"
#include "core/stability/wheelchair_record.h"
#include "devices/common/parameters.h"

class QComboBox;
class QLabel;
class QPushButton;
class QwtPlot;

namespace mozzi {
namespace views {

class JobRunner;
class ParameterForm;
class ProjectModel;

// The form's parameters (keys "manoeuvre", "study", "speed", "torque",
// "frequency", "duration", "ramp", "chair.*"), defaults those of the CLI.
const std::vector<devices::ParameterSpec>& wheelchairParameterSpecs();

class WheelchairPage : public QWidget {
  Q_OBJECT
 public:
  struct Run {
    double factor = 1.0;  // the studied stiffness's factor (1 without a study)
    std::vector<core::stability::WheelchairState> history;
  };

  WheelchairPage(QWidget* parent, JobRunner* jobs);

  ParameterForm* form() const { return form_; }
  // Simulates with the form's values (on the job runner when there is one);
  // with a project open the result is kept in it.
  void run();
  // On opening: the last kept result, else a sweep with the page's defaults
  // that is not kept.
  void openShowing();
  void setProjectModel(ProjectModel* model);
  // The wheelchair analyses the project keeps (ids in the list's order), and
  // one of them shown again.
  std::vector<qint64> storedResults() const;
  bool showStored(qint64 analysisId);
  void showRecord(const core::stability::WheelchairRecord& record);
  qint64 lastStoredId() const { return lastStoredId_; }  // 0: the last run was not kept
  const std::optional<core::stability::WheelchairRecord>& record() const { return record_; }

  // For tests and the log.
  const std::vector<Run>& runs() const { return runs_; }
  QString summaryText() const;
  QwtPlot* trajectoryPlot() const { return trajectory_; }
  QwtPlot* slipRightPlot() const { return slipRight_; }
  QwtPlot* slipLeftPlot() const { return slipLeft_; }

 signals:
  void finished(bool ok);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  struct Outcome {
    core::stability::WheelchairRecord record;
    std::string json;  // result_json, when kept
  };
  void present(core::Result<Outcome> result, bool keepIt);
  QString keep(const Outcome& outcome);
  void refreshStored();
  void start(bool keepResult);
  void retranslate();

  JobRunner* jobs_ = nullptr;
  std::vector<Run> runs_;
  std::optional<core::stability::WheelchairRecord> record_;
  ProjectModel* project_ = nullptr;
  qint64 lastStoredId_ = 0;
  QLabel* storedLabel_ = nullptr;
  QComboBox* stored_ = nullptr;
  QPushButton* showStored_ = nullptr;
  ParameterForm* form_ = nullptr;
  QPushButton* runButton_ = nullptr;
  QLabel* summary_ = nullptr;
  QwtPlot* trajectory_ = nullptr;
  QwtPlot* slipRight_ = nullptr;
  QwtPlot* slipLeft_ = nullptr;
};

}  // namespace views
}  // namespace mozzi
