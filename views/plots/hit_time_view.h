#pragma once
// Time view of the stored hits behind a campaign's FRF set (issue 18): the
// force and one response of a hit as the project holds them, with the windows
// the FRFs were computed with drawn over them (the force window scaled to the
// force's peak, the exponential window to the response's), so an engineer can
// see that the force window holds the whole pulse and that the response has
// decayed before the record ends. The windows come from core
// (core/signal/window.h) through the campaign's own FRF options
// (CampaignDefinition::frfOptions), the samples from the project.

#include <QWidget>
#include <cstdint>
#include <vector>

#include "core/common/result.h"
#include "core/io/project_store.h"
#include "devices/campaign/campaign_definition.h"

class QComboBox;
class QLabel;
class QwtPlot;
class QwtPlotCurve;

namespace mozzi {
namespace views {

class HitTimeView : public QWidget {
  Q_OBJECT
 public:
  explicit HitTimeView(QWidget* parent = nullptr);

  // The hits tied to FRF set `frfSetId` and their campaign's windows. Errors:
  // a set without hits (imported, synthesised) or whose campaign is unreadable.
  core::Result<void> setFrfSet(const core::io::ProjectStore& store, std::int64_t frfSetId);
  int hitCount() const { return static_cast<int>(hitIds_.size()); }
  // Shows hit `index` of the set (0-based, in stored order) and response
  // channel `response` (an index among the hit's non-force channels).
  bool showHit(int index, int response = 0);
  QwtPlot* plot() const { return plot_; }
  QString hitText() const;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void redraw();

  // The store the set was read from. The view lives on an item page, which
  // PageTabs closes when the project changes, so it never outlives the store.
  const core::io::ProjectStore* store_ = nullptr;
  std::vector<std::int64_t> hitIds_;
  devices::campaign::CampaignDefinition definition_;
  core::io::StoredHit hit_;
  bool haveHit_ = false;

  QComboBox* hitBox_ = nullptr;
  QComboBox* responseBox_ = nullptr;
  QLabel* hitLabel_ = nullptr;
  QLabel* responseLabel_ = nullptr;
  QLabel* status_ = nullptr;
  QwtPlot* plot_ = nullptr;  // an InteractivePlot
  QwtPlotCurve* force_ = nullptr;
  QwtPlotCurve* response_ = nullptr;
  QwtPlotCurve* forceWindow_ = nullptr;
  QwtPlotCurve* responseWindow_ = nullptr;
};

}  // namespace views
}  // namespace mozzi
