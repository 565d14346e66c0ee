#pragma once
// Stability against speed (issue 22; thesis §4.2 Figure 33, §6.6 Figures 51
// and 52; Meijaard et al. 2007 Figure 3): the real and imaginary parts of the
// eigenvalues of a bicycle model over a speed range, each mode tracked and
// named by core (core/stability/mode_tracking.h), the critical speeds (a real
// part crossing zero) marked on both plots and listed. Models: the benchmark
// bicycle of Meijaard et al. (2007) and the same bicycle with the thesis's
// compliant steel fork in bending (§6.5) or torsion (§6.4). The sweep runs on
// the job runner; the page computes nothing itself.

#include <QWidget>
#include <optional>
#include <vector>

#include "core/stability/mode_tracking.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QwtPlot;
class QwtPlotMarker;

namespace mozzi {
namespace views {

class JobRunner;

class StabilityPage : public QWidget {
  Q_OBJECT
 public:
  enum class Model { Benchmark = 0, ForkBending, ForkTorsion };

  StabilityPage(QWidget* parent, JobRunner* jobs);

  void setModel(Model model);
  void setSpeedRange(double fromMps, double toMps, double stepMps);
  // Starts the sweep (on the job runner when there is one, else at once).
  void run();
  // For tests and the log.
  const std::optional<core::stability::StabilitySweep>& sweep() const { return sweep_; }
  QString summaryText() const;
  QwtPlot* realPlot() const { return real_; }
  QwtPlot* imaginaryPlot() const { return imaginary_; }

 signals:
  void finished(bool ok);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void present(core::Result<core::stability::StabilitySweep> sweep);

  JobRunner* jobs_ = nullptr;
  std::optional<core::stability::StabilitySweep> sweep_;
  QComboBox* model_ = nullptr;
  QDoubleSpinBox* from_ = nullptr;
  QDoubleSpinBox* to_ = nullptr;
  QDoubleSpinBox* step_ = nullptr;
  QPushButton* runButton_ = nullptr;
  QLabel* modelLabel_ = nullptr;
  QLabel* speedsLabel_ = nullptr;
  QLabel* summary_ = nullptr;
  QwtPlot* real_ = nullptr;
  QwtPlot* imaginary_ = nullptr;
  std::vector<QwtPlotMarker*> markers_;  // the zero line and the critical speeds
};

}  // namespace views
}  // namespace mozzi
