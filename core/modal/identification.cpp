#include "core/modal/identification.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <string>

#include "core/common/enum_names.h"
#include "core/modal/varpro.h"

namespace mozzi::core::modal {

namespace {
constexpr EnumEntry<IdentificationStage, const char*> kStageEntries[] = {
    {IdentificationStage::Diagram, "stabilization diagram"},
    {IdentificationStage::Selection, "pole selection"},
    {IdentificationStage::Lsfd, "LSFD"},
    {IdentificationStage::Refinement, "refinement"}};
constexpr auto kStageNames = enumTable(kStageEntries, "identification");
}  // namespace

// 2,000 lines: measured on the two benchmark sets of modal_refine_bench and
// the ModeLAB beam (docs/performance/commands.md, fifth pass), the whole
// refinement stage (thinned fit and the LSFD over the band) in LSFDs of the
// band, and the largest ratio of the thinned fit's standard errors to the
// all-lines fit's, at 1,000 / 2,000 / 3,000 lines:
//   beam (9 x 47,873 lines, 4 modes 1-2 lines wide)    1.18 / 1.32 / 1.51 LSFD, 1.07 / 1.06 / 1.05
//   10 x 4,501 lines (10 modes, 0.4-12 Hz half-widths) 4.3 / 4.5 / 10.4, 1.15 / 1.13 / 1.06
//   100 x 9,000 lines: the modes' windows of 3 half-widths hold 3,344 lines: 2.9, 1.17 at every budget
// (all lines: 9.6, 8.6, 6.9 LSFDs). Below 2,000 the beam gains little and
// the small set loses standard error; above it the cost grows with the lines
// for a few % of standard error (at 3,000 the small set's lines also moved
// with the solution: a second fit).
const Eigen::Index kRefineLinesCarryingModes = 2000;

const char* identificationStageName(IdentificationStage stage) {
  return kStageNames.of(stage);
}

namespace {

using Report = std::function<bool(IdentificationStage, double)>;

// LSFD for out.selected (participation factors carried over) and, when
// options.refine, the refinement: the part of the pipeline after the selection.
Result<void> fitSelection(const FrfMatrix& frf, const IdentificationOptions& options, const Report& report,
                          IdentificationResult& out) {
  const std::string where = "identification";
  const LsceOptions& est = options.estimator;
  if (!report(IdentificationStage::Lsfd, 0.0)) return makeError(ErrorCode::Cancelled, "cancelled", where);
  std::vector<Complex> poles;
  for (const auto& s : out.selected) poles.push_back(s.pole);
  LsfdOptions lo2;
  lo2.bandLowHz = est.bandLowHz;
  lo2.bandHighHz = est.bandHighHz;
  auto bandLsfd = [&]() -> Result<void> {
    MOZZI_TRY_ASSIGN(auto model, lsfd(frf, poles, lo2));
    for (std::size_t r = 0; r < poles.size(); ++r) model.modes[r].participation = out.selected[r].participation;
    out.lsfdModel = std::move(model);
    return {};
  };
  if (!options.refine) return bandLsfd();

  // The refinement's first evaluation is the LSFD at the selected poles: it
  // is out.lsfdModel (on the fitted lines when thinned), not computed twice.
  ModalModel start;
  start.responses = frf.responses;
  start.references = frf.references;
  for (const auto& s : out.selected) {
    Mode md;
    md.pole = s.pole;
    md.residue = ComplexMatrix::Zero(frf.responseCount(), frf.referenceCount());
    md.participation = s.participation;
    start.modes.push_back(std::move(md));
  }
  auto refined = refineSelection(frf, start, options,
                                 [&](const IdentificationProgress& p) { return report(p.stage, p.fraction); });
  if (!refined) {
    if (refined.error().code == ErrorCode::Cancelled) return refined.error();
    // The LSFD's own error where it fails too (rank-deficient basis, band).
    MOZZI_TRY(bandLsfd());
    return refined.error();
  }
  out.lsfdModel = std::move(refined->startModel);
  refined->startModel = ModalModel{};
  out.refined = std::move(refined).value();
  return {};
}

}  // namespace

Result<RefineResult> refineSelection(const FrfMatrix& frf, const ModalModel& start,
                                     const IdentificationOptions& options, const IdentificationCallback& progress) {
  RefineOptions ro;
  ro.bandLowHz = options.estimator.bandLowHz;
  ro.bandHighHz = options.estimator.bandHighHz;
  ro.maxIterations = options.maxRefineIterations;
  ro.maxLines = options.refineMaxLines;
  ro.progress = [&](int iteration, double) {
    return !progress ||
           progress(IdentificationProgress{
               IdentificationStage::Refinement,
               static_cast<double>(iteration) / static_cast<double>(std::max(1, options.maxRefineIterations))});
  };
  return refineModalModel(frf, start, ro);
}

Result<IdentificationResult> identifyModes(const FrfMatrix& frf, const IdentificationOptions& options,
                                           const IdentificationCallback& progress) {
  const std::string where = "identification";
  auto report = [&](IdentificationStage stage, double fraction) {
    return !progress || progress(IdentificationProgress{stage, fraction});
  };
  LsceOptions est = options.estimator;
  const int lo = est.minOrder, hi = std::max(est.maxOrder, est.minOrder + 1);
  est.orderProgress = [&](int order) {
    return report(IdentificationStage::Diagram,
                  std::clamp(static_cast<double>(order - lo) / static_cast<double>(hi - lo), 0.0, 1.0));
  };
  if (!report(IdentificationStage::Diagram, 0.0)) return makeError(ErrorCode::Cancelled, "cancelled", where);
  IdentificationResult out;
  MOZZI_TRY_ASSIGN(out.diagram, options.method == IdentificationMethod::Lsce ? lsceStabilization(frf, est)
                                                                             : plscfStabilization(frf, est));
  if (!report(IdentificationStage::Selection, 0.0)) return makeError(ErrorCode::Cancelled, "cancelled", where);
  MOZZI_TRY_ASSIGN(out.selected, selectPoles(out.diagram, est));

  MOZZI_TRY(fitSelection(frf, options, report, out));
  return out;
}

Result<IdentificationResult> reselectModes(const FrfMatrix& frf, StabilizationDiagram diagram,
                                           const std::vector<std::size_t>& diagramPoles,
                                           const IdentificationOptions& options,
                                           const IdentificationCallback& progress) {
  const std::string where = "pole re-selection";
  if (diagramPoles.empty()) return makeError(ErrorCode::InvalidArgument, "no poles selected", where);
  std::set<std::size_t> seen;
  IdentificationResult out;
  for (const std::size_t i : diagramPoles) {
    if (i >= diagram.poles.size()) {
      return makeError(
          ErrorCode::InvalidArgument,
          "pole " + std::to_string(i) + " is not in the diagram (" + std::to_string(diagram.poles.size()) + " poles)",
          where);
    }
    if (!seen.insert(i).second) {
      return makeError(ErrorCode::InvalidArgument, "pole " + std::to_string(i) + " selected twice", where);
    }
    const StabilizationPole& p = diagram.poles[i];
    SelectedPole s;
    s.pole = p.pole;
    s.participation = p.participation;
    s.clusterSize = 1;
    out.selected.push_back(std::move(s));
  }
  // In frequency order, as the automatic selection gives them.
  std::sort(out.selected.begin(), out.selected.end(),
            [](const SelectedPole& a, const SelectedPole& b) { return a.pole.imag() < b.pole.imag(); });
  out.diagram = std::move(diagram);
  auto report = [&](IdentificationStage stage, double fraction) {
    return !progress || progress(IdentificationProgress{stage, fraction});
  };
  MOZZI_TRY(fitSelection(frf, options, report, out));
  return out;
}

Result<SelectionFit> fitSelectedPoles(const FrfMatrix& frf, const std::vector<Complex>& poles,
                                      const LsfdOptions& band) {
  MOZZI_TRY_ASSIGN(auto fitter, SelectionFitter::create(frf, band));
  MOZZI_TRY_ASSIGN(auto fit, fitter.fit(poles));
  SelectionFit out;
  out.model = std::move(fit.model);
  out.relativeError = fit.relativeError;
  out.synthesis.frequencyHz = frf.frequencyHz.segment(fitter.firstLine(), fitter.lineCount());
  out.synthesis.responses = frf.responses;
  out.synthesis.references = frf.references;
  out.synthesis.type = frf.type;
  fitter.synthesis(out.synthesis.h);
  return out;
}

namespace {
// Mode counts whose workspaces a SelectionFitter keeps: a click adds or
// removes one mode, so the counts alternate; each holds 2 nf x (2 nm + 4)
// doubles of basis (4 MB for 18,000 lines and five modes) and up to 4 MB of
// block workspace.
constexpr std::size_t kKeptWorkspaces = 3;
}  // namespace

Result<SelectionFitter> SelectionFitter::create(const FrfMatrix& frf, const LsfdOptions& band) {
  MOZZI_TRY(frf.validate());
  SelectionFitter f;
  f.frf_ = &frf;
  f.band_ = band;
  Eigen::Index k0 = 0;
  while (k0 < frf.lineCount() && (frf.frequencyHz[k0] < band.bandLowHz || frf.frequencyHz[k0] == 0.0)) ++k0;
  Eigen::Index k = k0;
  while (k < frf.lineCount() && frf.frequencyHz[k] <= band.bandHighHz) ++k;
  f.first_ = k0;
  f.count_ = k - k0;
  const Eigen::Index no = frf.responseCount(), ni = frf.referenceCount();
  f.norm2_.resize(no, ni);
  for (Eigen::Index i = 0; i < ni; ++i)
    for (Eigen::Index o = 0; o < no; ++o)
      f.norm2_(o, i) = frf.h[static_cast<std::size_t>(i)].col(o).segment(k0, f.count_).squaredNorm();
  return f;
}

Result<PoleSetFit> SelectionFitter::fit(const std::vector<Complex>& poles) {
  const std::string where = "pole selection fit";
  lastValid_ = false;
  if (poles.empty()) return makeError(ErrorCode::InvalidArgument, "no poles selected", where);
  const int nm = static_cast<int>(poles.size());
  Vector theta(2 * nm);
  for (int r = 0; r < nm; ++r) {
    const Complex l = poles[static_cast<std::size_t>(r)];
    if (!(l.imag() > 0.0) || !(l.real() < 0.0) || !std::isfinite(std::abs(l))) {
      return makeError(ErrorCode::InvalidArgument, "pole must be finite with Re < 0 and Im > 0",
                       where + ", pole " + std::to_string(r + 1));
    }
    theta[2 * r] = poleFrequencyHz(l);
    theta[2 * r + 1] = poleZeta(l);
  }
  // The workspace of this mode count, moved to the back (created when new).
  auto it =
      std::find_if(workspaces_.begin(), workspaces_.end(), [nm](const ModalVarpro& v) { return v.modeCount() == nm; });
  if (it != workspaces_.end()) {
    std::rotate(it, it + 1, workspaces_.end());
  } else {
    auto vp =
        ModalVarpro::create(*frf_, {LineSegment{first_, count_}}, nm, band_.lowerResidual, band_.upperResidual, false);
    if (!vp) return makeError(vp.error().code, vp.error().message, where + ", band");
    if (workspaces_.size() >= kKeptWorkspaces) workspaces_.erase(workspaces_.begin());
    workspaces_.push_back(std::move(vp).value());
  }
  ModalVarpro& vp = workspaces_.back();
  if (!vp.evaluate(theta, false)) {
    return makeError(ErrorCode::NumericalFailure, "basis is rank deficient: duplicate poles or too narrow a band",
                     where);
  }
  // |H - H_model|^2 per FRF from the explicit residual: Q Z subtracted from
  // the data, not ||Z||^2 from ||Y||^2 (that loses most digits, or all, on
  // an almost exact fit).
  Vector ssr;
  vp.explicitSsrPerFrf(ssr);
  PoleSetFit out;
  out.model = modalModelFromLinear(vp, *frf_, poles);
  const Eigen::Index no = norm2_.rows(), ni = norm2_.cols();
  out.residual.resize(no, ni);
  for (Eigen::Index i = 0; i < ni; ++i) {
    for (Eigen::Index o = 0; o < no; ++o) {
      const double den = norm2_(o, i);
      out.residual(o, i) = den > 0.0 ? std::sqrt(ssr[i * no + o] / den) : 0.0;
    }
  }
  out.relativeError = std::sqrt(ssr.sum() / vp.dataNorm2());
  lastValid_ = true;
  return out;
}

bool SelectionFitter::synthesis(Eigen::Index response, Eigen::Index reference, ComplexVector& out) const {
  if (!lastValid_ || response < 0 || response >= norm2_.rows() || reference < 0 || reference >= norm2_.cols())
    return false;
  workspaces_.back().modelValues(response, reference, out);
  return true;
}

bool SelectionFitter::synthesis(std::vector<ComplexMatrix>& out) const {
  if (!lastValid_) return false;
  workspaces_.back().modelValues(out);
  return true;
}

}  // namespace mozzi::core::modal
