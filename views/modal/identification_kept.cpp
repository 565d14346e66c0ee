// The Identification page before a run (identification_page.h): the set's
// backdrop on the diagram, and the project's kept modal result of the set as
// the selection.
#include <qwt_plot.h>
#include <QComboBox>
#include <QSpinBox>

#include "core/io/project_store.h"
#include "core/modal/modal_model.h"
#include "core/signal/window.h"
#include "views/common/project_model.h"
#include "views/modal/identification_page.h"
#include "views/plots/stabilization_plot.h"

namespace mozzi {
namespace views {

namespace md = core::modal;

void IdentificationPage::showBackdrop() {
  if (!frf_) return;
  const auto kind = static_cast<identification::Backdrop>(backdropBox_->currentIndex());
  auto db = identification::backdropDb(*frf_, kind);
  // From the first line above 0 Hz (an accelerance or a mobility is zero there).
  Eigen::Index a = 0;
  while (a < frf_->lineCount() && !(frf_->frequencyHz[a] > 0.0)) ++a;
  const Eigen::Index n = frf_->lineCount() - a;
  std::shared_ptr<const core::Vector> f, v;
  if (db && n > 1) {
    f = std::make_shared<const core::Vector>(frf_->frequencyHz.segment(a, n));
    v = std::make_shared<const core::Vector>(db->segment(a, n));
  }
  diagram_->setDiagram(nullptr, f, v,
                       kind == identification::Backdrop::Cmif ? tr("CMIF 1 [dB]") : tr("|sum of FRFs| [dB]"));
  // The orders the run will fill.
  diagram_->setAxisScale(QwtPlot::yLeft, 0.0, orderBox_->value() + 2.0);
  diagram_->replot();
}

void IdentificationPage::loadKept() {
  core::io::ProjectStore* store = model_->store();
  if (!store) return;
  auto results = store->modalResults();
  if (!results) return;
  const core::io::ModalResultInfo* latest = nullptr;
  for (const auto& r : *results) {
    if (r.frfSetId && *r.frfSetId == frfSetId_ && (!latest || r.id > latest->id)) latest = &r;
  }
  if (!latest) return;
  auto table = store->modalResult(latest->id);
  if (!table || table->modes.empty()) return;
  std::vector<Chosen> poles;
  for (const auto& m : table->modes) {
    // As measured: the window's decay put back (the stored modes have it removed).
    core::signal::PoleEstimate p{m.frequencyHz, m.dampingRatio};
    if (windowTauS_ > 0.0) {
      auto w = core::signal::applyExponentialWindowDamping(p, windowTauS_);
      if (!w) return;
      p = *w;
    }
    poles.push_back(Chosen{md::poleFromFrequencyDamping(p.naturalFrequencyHz, p.zeta), core::ComplexVector(), -1});
  }
  kept_ = Kept{*latest, std::move(table).value()};
  chosen_ = std::move(poles);
  selectionIsAutomatic_ = false;
}

std::optional<std::pair<double, double>> IdentificationPage::selectionBand() const {
  if (outcome_) return std::pair{outcome_->options.bandLowHz, outcome_->options.bandHighHz};
  if (kept_) return std::pair{kept_->info.bandLowHz, kept_->info.bandHighHz};
  return std::nullopt;
}

}  // namespace views
}  // namespace mozzi
