#pragma once
// The Wheelchair page (issue 22; thesis §7.2 to §7.4, Figures 57 to 60): the
// trajectory of the chair's centre of mass and the rear wheels' slip angles in
// a slalom or a steady-turning manoeuvre, computed by core's five-DOF model
// (core/stability/wheelchair_model.h) as `mozzi-cli wheelchair` computes them,
// for one chair or for the thesis's stiffness studies (the rear cornering or
// aligning stiffness at 0.5, 1 and 2 times its value, one curve each). The
// chair and the manoeuvre come from a form built from a ParameterSpec list
// (views/panels/parameter_form); the simulation runs on the job runner.

#include <QWidget>
#include <vector>

#include "core/stability/wheelchair_model.h"
#include "devices/common/parameters.h"

class QLabel;
class QPushButton;
class QwtPlot;

namespace mozzi {
namespace views {

class JobRunner;
class ParameterForm;

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
  // Simulates with the form's values (on the job runner when there is one).
  void run();

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
  void present(core::Result<std::vector<Run>> result, const devices::ParameterMap& values);
  void retranslate();

  JobRunner* jobs_ = nullptr;
  std::vector<Run> runs_;
  ParameterForm* form_ = nullptr;
  QPushButton* runButton_ = nullptr;
  QLabel* summary_ = nullptr;
  QwtPlot* trajectory_ = nullptr;
  QwtPlot* slipRight_ = nullptr;
  QwtPlot* slipLeft_ = nullptr;
};

}  // namespace views
}  // namespace mozzi
