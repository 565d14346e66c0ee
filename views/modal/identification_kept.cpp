// The Identification page before a run (identification_page.h): the set's
// backdrop on the diagram, and the project's kept modal result of the set as
// the selection, with the stabilization diagram of its band behind it.
#include <qwt_plot.h>
#include <QComboBox>
#include <QPushButton>
#include <QSpinBox>
#include <algorithm>

#include "core/io/project_store.h"
#include "core/modal/modal_model.h"
#include "core/modal/plscf.h"
#include "core/signal/window.h"
#include "views/common/job_runner.h"
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
                       kind == identification::Backdrop::Cmif ? tr("CMIF 1 [dB]") : tr("sum of |H| [dB]"));
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
  selectionIsKept_ = true;
}

void IdentificationPage::updateSaveButton() {
  saveButton_->setEnabled(outcome_ && fit_ && !chosen_.empty() && !selectionIsKept_);
  saveButton_->setToolTip(
      selectionIsKept_ ? tr("These are the kept modes, in the project already: click poles or run to save other ones")
                       : tr("Refine the chosen poles and store them as a modal result of the project"));
}

void IdentificationPage::drawDiagramBehindKept() {
  cancelKeptDiagram();
  if (!kept_ || !frf_ || outcome_ || isRunning()) return;  // a run has replaced it or will
  // The kept result's own method (a selection saved from it is that method's);
  // peak picking and circle fit draw no diagram.
  using identification::Method;
  Method method = Method::Plscf;
  if (kept_->info.method == identification::storedMethodName(Method::Lsce)) {
    method = Method::Lsce;
  } else if (kept_->info.method != identification::storedMethodName(Method::Plscf)) {
    return;
  }
  setMethod(method);  // the box shows it, as the band boxes show the kept band
  identification::Options opt;
  opt.method = method;
  opt.bandLowHz = kept_->info.bandLowHz;
  opt.bandHighHz = kept_->info.bandHighHz;
  // As the CLI's default order: capped at what a narrow band's lines support.
  opt.maxOrder =
      method == Method::Plscf
          ? std::min(orderBox_->value(), std::max(8, md::plscfOrderLimit(*frf_, opt.bandLowHz, opt.bandHighHz)))
          : orderBox_->value();
  opt.backdrop = static_cast<identification::Backdrop>(backdropBox_->currentIndex());
  opt.refine = false;  // the diagram only: the kept modes are the selection
  auto frf = frf_;
  const qint64 keptId = kept_->info.id;
  auto job = std::make_shared<int>(0);
  *job = jobs_->run<identification::Outcome>(
      this, tr("Stabilization diagram"), [frf, opt](JobProgress& p) { return identification::identify(*frf, opt, p); },
      [this, keptId, job](core::Result<identification::Outcome> r) {
        if (keptDiagramJob_ != *job) return;  // a job cancelled since (another took its place)
        keptDiagramJob_ = 0;
        showDiagramBehindKept(keptId, std::move(r));
      });
  keptDiagramJob_ = *job;
}

void IdentificationPage::cancelKeptDiagram() {
  if (keptDiagramJob_) jobs_->cancel(keptDiagramJob_);
  keptDiagramJob_ = 0;
}

void IdentificationPage::showDiagramBehindKept(qint64 keptId, core::Result<identification::Outcome> result) {
  // Dropped when a run has replaced the kept result or another set is shown.
  if (!kept_ || kept_->info.id != keptId || outcome_ || isRunning()) return;
  if (!result) {
    if (log_ && result.error().code != core::ErrorCode::Cancelled) {
      log_(tr("No stabilization diagram for the kept band of FRF set %1: %2")
               .arg(frfSetId_)
               .arg(QString::fromStdString(result.error().describe())));
    }
    return;
  }
  outcome_ = std::move(result).value();
  showOutcomeDiagram();
  takeAutomaticSelection();
  // Each kept mode ringed on the diagram's pole that represents it (a click
  // there removes it; its shape makes the same-mode warning work); the kept
  // pole itself stays the selection.
  const double tolerance = identification::estimatorOptions(outcome_->options).clusterFrequencyTolerance;
  for (Chosen& c : chosen_) {
    if (!outcome_->diagram) continue;
    c.diagramIndex = md::representativePole(*outcome_->diagram, c.pole, tolerance);
    if (c.diagramIndex >= 0 && c.shape.size() == 0)
      c.shape = outcome_->diagram->poles[static_cast<std::size_t>(c.diagramIndex)].shape;
  }
  updateSelection();
}

void IdentificationPage::showOutcomeDiagram() {
  diagram_->setDiagram(
      outcome_->diagram, std::make_shared<const core::Vector>(frf_->frequencyHz), outcome_->backdropDb,
      outcome_->options.backdrop == identification::Backdrop::Cmif ? tr("CMIF 1 [dB]") : tr("sum of |H| [dB]"));
}

void IdentificationPage::changeBackdrop() {
  if (!frf_) return;
  const auto kind = static_cast<identification::Backdrop>(backdropBox_->currentIndex());
  if (keptDiagramJob_) {
    drawDiagramBehindKept();  // again, over the new curve
  } else if (kept_ && outcome_ && outcome_->options.backdrop != kind) {
    // The diagram behind the kept result: the chosen curve under it, the selection kept.
    auto db = identification::backdropDb(*frf_, kind);
    if (!db) return;
    outcome_->backdropDb = std::move(db);
    outcome_->options.backdrop = kind;
    showOutcomeDiagram();
    updateSelection();
    return;
  }
  if (outcome_) return;  // after a run the choice is for the next one
  showBackdrop();
  if (kept_) diagram_->setAxisScale(QwtPlot::xBottom, kept_->info.bandLowHz, kept_->info.bandHighHz);
  updateSelection();
}

void IdentificationPage::takeAutomaticSelection() {
  automatic_.clear();
  if (!outcome_) return;
  const md::PlscfOptions est = identification::estimatorOptions(outcome_->options);
  for (const auto& s : outcome_->automatic) {
    Chosen c;
    c.pole = s.pole;
    c.shape = s.shape;
    if (outcome_->diagram) {
      c.diagramIndex = md::representativePole(*outcome_->diagram, s.pole, est.clusterFrequencyTolerance);
      if (c.diagramIndex >= 0 && c.shape.size() == 0)
        c.shape = outcome_->diagram->poles[static_cast<std::size_t>(c.diagramIndex)].shape;
    }
    automatic_.push_back(c);
  }
}

std::optional<std::pair<double, double>> IdentificationPage::selectionBand() const {
  if (outcome_) return std::pair{outcome_->options.bandLowHz, outcome_->options.bandHighHz};
  if (kept_) return std::pair{kept_->info.bandLowHz, kept_->info.bandHighHz};
  return std::nullopt;
}

}  // namespace views
}  // namespace mozzi
