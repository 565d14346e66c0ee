#pragma once
// FRF viewer: the FRFs of a set, one or an overlay chosen by response DOF,
// reference DOF and mesh point, in every representation an engineer asks for
// (Bode with magnitude linear, log or dB and phase wrapped or unwrapped; real
// and imaginary parts; Nyquist; coherence), with the sum and the CMIF of the
// shown FRFs, a cursor whose readout names the frequency, the values and the
// nearest identified mode, and zoom, pan and autoscale (InteractivePlot).
// The numbers come from core (frf_display.h, plot_math.h, shape_tools.h).

#include <QWidget>
#include <memory>
#include <optional>
#include <vector>

#include "core/common/frf_display.h"
#include "core/common/frf_matrix.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QwtPlot;

namespace mozzi {
namespace views {

class DecimatingCurve;
class InteractivePlot;

class FrfPlot : public QWidget {
  Q_OBJECT
 public:
  enum class View { Bode = 0, Magnitude, Phase, RealImaginary, Nyquist, Coherence };
  enum class MagnitudeScale { Decibel = 0, Linear, Logarithmic };

  explicit FrfPlot(QWidget* parent = nullptr);
  ~FrfPlot() override;

  void setFrfs(std::shared_ptr<const core::FrfMatrix> frfs);
  // Natural frequencies [Hz] of identified modes, for the cursor readout.
  void setModeFrequencies(std::vector<double> frequenciesHz);

  void setView(View view);
  View view() const { return view_; }
  void setMagnitudeScale(MagnitudeScale scale);
  void setUnwrapPhase(bool on);
  void setLogFrequency(bool on);
  void setShowSum(bool on);
  void setShowCmif(bool on);
  // Filter of the overlay (empty criteria: all); the combo boxes show it.
  void setFilter(const core::FrfFilter& filter);
  // Shows H_{response, reference} alone; false if either index is out of range.
  bool showPair(int response, int reference);
  int pairCount() const;
  int currentResponse() const;
  int currentReference() const;
  const std::vector<core::FrfPick>& shownPicks() const { return picks_; }

  // Plots: main (magnitude, phase, real part, Nyquist or coherence by view),
  // secondary (phase in Bode, imaginary part), coherence (Bode and magnitude,
  // when the set has coherence). Hidden plots hold no curves.
  InteractivePlot* mainPlot() const { return main_; }
  InteractivePlot* secondaryPlot() const { return secondary_; }
  InteractivePlot* coherencePlot() const { return coherence_; }
  QwtPlot* magnitudePlot() const;  // main plot in Bode (compatibility with the first viewer)
  QwtPlot* phasePlot() const;
  // Samples of the first curve of the main plot (0 when nothing is shown).
  size_t shownSamples() const;
  // Cursor at frequency f on every plot; the readout follows.
  void setCursorFrequency(double frequencyHz);
  QString readoutText() const;
  void autoscale();
  // Frequency range of every stacked plot (y refit to it); not in Nyquist.
  void setFrequencyRange(double lowHz, double highHz);

 protected:
  void changeEvent(QEvent* event) override;
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void retranslate();
  // Views with the magnitude on top and the coherence under it (Bode, Magnitude).
  bool stacksCoherence() const { return view_ == View::Bode || view_ == View::Magnitude; }
  void rebuildChoices();
  void applyChoices();
  void redraw(bool keepX);
  void updateReadout();
  void syncX(InteractivePlot* from, double lower, double upper);
  QString curveTitle(const core::FrfPick& pick) const;
  QString magnitudeTitle() const;
  QString unitText() const;                      // "m/N", ... by FRF type
  QString typeText() const;                      // "receptance", ...
  QString partTitle(const QString& part) const;  // "Re H [m/N]"

  std::shared_ptr<const core::FrfMatrix> frfs_;
  std::shared_ptr<const core::Vector> frequency_;
  std::vector<core::FrfPick> picks_;
  core::FrfFilter filter_;
  std::vector<double> modesHz_;
  View view_ = View::Bode;
  MagnitudeScale magnitudeScale_ = MagnitudeScale::Decibel;
  bool unwrap_ = false, logFrequency_ = false, showSum_ = false, showCmif_ = false, syncing_ = false;
  std::optional<double> cursorHz_;

  QComboBox* viewBox_ = nullptr;
  QComboBox* scaleBox_ = nullptr;
  QComboBox* responseBox_ = nullptr;
  QComboBox* referenceBox_ = nullptr;
  QComboBox* pointBox_ = nullptr;
  QCheckBox* unwrapBox_ = nullptr;
  QCheckBox* logFrequencyBox_ = nullptr;
  QCheckBox* sumBox_ = nullptr;
  QCheckBox* cmifBox_ = nullptr;
  QPushButton* autoscaleButton_ = nullptr;
  QLabel* readout_ = nullptr;
  QLabel* viewLabel_ = nullptr;
  QLabel* showLabel_ = nullptr;
  InteractivePlot* main_ = nullptr;
  InteractivePlot* secondary_ = nullptr;
  InteractivePlot* coherence_ = nullptr;
};

}  // namespace views
}  // namespace mozzi
