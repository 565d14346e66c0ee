#pragma once
// FRF viewer: magnitude [dB], phase [deg] and coherence against frequency for
// one response/reference pair of a core::FrfMatrix, chosen from a list.

#include <QWidget>
#include <memory>

#include "core/common/frf_matrix.h"

class QComboBox;
class QCheckBox;
class QwtPlot;
class QwtPlotCurve;

namespace mozzi {
namespace views {

class FrfPlot : public QWidget {
  Q_OBJECT
 public:
  explicit FrfPlot(QWidget* parent = nullptr);
  ~FrfPlot() override;

  void setFrfs(std::shared_ptr<const core::FrfMatrix> frfs);
  // Shows H_{response, reference}; false if either index is out of range.
  bool showPair(int response, int reference);
  int pairCount() const;
  int currentResponse() const { return response_; }
  int currentReference() const { return reference_; }

  QwtPlot* magnitudePlot() const { return magnitude_; }
  QwtPlot* phasePlot() const { return phase_; }
  QwtPlot* coherencePlot() const { return coherence_; }
  // Samples in the magnitude curve (0 when nothing is shown).
  size_t shownSamples() const;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void rebuildPairList();

  std::shared_ptr<const core::FrfMatrix> frfs_;
  std::shared_ptr<const core::Vector> frequency_;
  int response_ = -1;
  int reference_ = -1;
  QComboBox* pairs_ = nullptr;
  QCheckBox* unwrap_ = nullptr;
  QwtPlot* magnitude_ = nullptr;
  QwtPlot* phase_ = nullptr;
  QwtPlot* coherence_ = nullptr;
  QwtPlotCurve* magnitudeCurve_ = nullptr;
  QwtPlotCurve* phaseCurve_ = nullptr;
  QwtPlotCurve* coherenceCurve_ = nullptr;
};

}  // namespace views
}  // namespace mozzi
