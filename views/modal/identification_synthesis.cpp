// The Identification page's Synthesis tab (identification_page.h): the
// synthesised FRF over the measured one, and every FRF's residual, level and
// misfit.
#include <QComboBox>
#include <QTableWidget>
#include <algorithm>
#include <cmath>

#include "views/modal/identification_page.h"
#include "views/plots/decimating_curve.h"
#include "views/plots/interactive_plot.h"

namespace mozzi {
namespace views {

void IdentificationPage::showSynthesis() {
  synthesisStale_ = false;
  synthesis_->detachItems(QwtPlotItem::Rtti_PlotCurve, true);
  residuals_->setRowCount(0);
  // A fit over the data (not the single-mode methods' estimate) has a residual.
  core::ComplexVector synthesised;
  const int pick = std::max(0, synthesisFrfBox_->currentIndex());
  const Eigen::Index no = frf_ ? frf_->responseCount() : 1;
  const Eigen::Index o = pick % no, i = frf_ ? std::min<Eigen::Index>(pick / no, frf_->referenceCount() - 1) : 0;
  if (!frf_ || !fit_ || fit_->residual.size() == 0 || !fitter_ || !fitter_->synthesis(o, i, synthesised)) {
    synthesis_->replot();
    return;
  }
  // Only the FRF shown is synthesised, on the band's lines.
  const auto& x = fitter_->frequencyHz();
  auto db = [](const core::ComplexVectorRef& h) {
    core::Vector v(h.size());
    for (Eigen::Index k = 0; k < h.size(); ++k) v[k] = 20.0 * std::log10(std::max(std::abs(h[k]), 1e-300));
    return std::make_shared<const core::Vector>(std::move(v));
  };
  auto* measured = new DecimatingCurve(tr("measured"));
  measured->setPen(QColor(31, 119, 180), 1.5);
  measured->setVectors(x, db(fitter_->measured(o, i)));
  measured->attach(synthesis_);
  auto* synth = new DecimatingCurve(tr("synthesised"));
  synth->setPen(QColor(214, 39, 40), 1.5, Qt::DashLine);
  synth->setVectors(x, db(synthesised));
  synth->attach(synthesis_);
  synthesis_->autoscale();
  // Residual per FRF, its level and the misfit's, worst misfit first; each FRF
  // named as in the FRF box.
  const auto rows = identification::residualsWorstFirst(*fitter_, fit_->residual);
  residuals_->setRowCount(static_cast<int>(rows.size()));
  for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
    const auto& row = rows[static_cast<std::size_t>(r)];
    auto* name = new QTableWidgetItem(synthesisFrfBox_->itemText(static_cast<int>(row.reference * no + row.response)));
    name->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    residuals_->setItem(r, 0, name);
    residuals_->setItem(r, 1, cell(QString::number(100.0 * row.residual, 'f', 2)));
    const auto db = [](double v) {
      if (!std::isfinite(v)) return QStringLiteral("-");
      const double tenths = std::round(10.0 * v) / 10.0;
      return QString::number(tenths == 0.0 ? 0.0 : tenths, 'f', 1);  // no "-0.0"
    };
    residuals_->setItem(r, 2, cell(db(row.levelDb)));
    residuals_->setItem(r, 3, cell(db(row.misfitDb)));
  }
}

}  // namespace views
}  // namespace mozzi
