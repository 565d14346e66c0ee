#pragma once
// Stabilization diagram: every candidate pole at (frequency, order) with the
// symbol of its status (stable, frequency and damping stable, frequency and
// vector stable, frequency stable, new), the sum or CMIF of the FRFs behind
// it on the right axis [dB], the selected modes ringed with a dashed line at
// their frequency. A left click on a pole emits poleClicked(index into
// diagram.poles). Zoom, pan, cursor and export as every InteractivePlot.

#include <memory>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/modal/plscf.h"
#include "views/plots/interactive_plot.h"

class QwtPlotCurve;

namespace mozzi {
namespace views {

class DecimatingCurve;

class StabilizationPlot : public InteractivePlot {
  Q_OBJECT
 public:
  explicit StabilizationPlot(QWidget* parent = nullptr);

  // The diagram, and the backdrop: |sum| or the first CMIF value on the
  // frequency lines, drawn in dB on the right axis. Title names it. Without a
  // diagram (before a run) the backdrop alone spans the frequency axis.
  void setDiagram(std::shared_ptr<const core::modal::StabilizationDiagram> diagram,
                  std::shared_ptr<const core::Vector> frequencyHz, std::shared_ptr<const core::Vector> backdropDb,
                  const QString& backdropTitle);
  // Diagram poles drawn as selected (ringed), and lines at the selected modes' frequencies.
  void setSelection(const std::vector<int>& poleIndices, const std::vector<double>& modeFrequenciesHz);
  const std::vector<int>& selection() const { return selected_; }
  // Pixel position (canvas coordinates) of diagram pole i; for tests.
  QPoint polePixel(int index) const;
  // Points in the status curves (for tests and the time budget).
  int drawnPoleCount() const;
  // The backdrop curve (its samples: frequency [Hz], value [dB]).
  const DecimatingCurve* backdropCurve() const { return backdrop_; }
  // Frequencies [Hz] of the dashed lines at the selected modes.
  std::vector<double> modeLineFrequencies() const;

 signals:
  void poleClicked(int index);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void onClicked(QPointF plotPoint, QPoint pixel);

  std::shared_ptr<const core::modal::StabilizationDiagram> diagram_;
  std::vector<int> selected_;
  std::vector<QwtPlotCurve*> statusCurves_;  // one per PoleStatus
  QwtPlotCurve* selectedCurve_ = nullptr;
  DecimatingCurve* backdrop_ = nullptr;
  std::vector<class QwtPlotMarker*> modeLines_;
  QString backdropTitle_;
};

}  // namespace views
}  // namespace mozzi
