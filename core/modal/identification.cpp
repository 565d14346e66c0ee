#include "core/modal/identification.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <string>

#include "core/modal/varpro.h"

namespace mozzi::core::modal {

const char* identificationStageName(IdentificationStage stage) {
  switch (stage) {
    case IdentificationStage::Diagram: return "stabilization diagram";
    case IdentificationStage::Selection: return "pole selection";
    case IdentificationStage::Lsfd: return "LSFD";
    case IdentificationStage::Refinement: return "refinement";
  }
  return "identification";
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
  auto model = lsfd(frf, poles, lo2);
  if (!model) return model.error();
  for (std::size_t r = 0; r < poles.size(); ++r) model->modes[r].participation = out.selected[r].participation;
  out.lsfdModel = std::move(model).value();

  if (options.refine) {
    RefineOptions ro;
    ro.bandLowHz = est.bandLowHz;
    ro.bandHighHz = est.bandHighHz;
    ro.maxIterations = options.maxRefineIterations;
    ro.maxLines = options.refineMaxLines;
    ro.progress = [&](int iteration, double) {
      return report(IdentificationStage::Refinement,
                    static_cast<double>(iteration) / static_cast<double>(std::max(1, options.maxRefineIterations)));
    };
    auto refined = refineModalModel(frf, out.lsfdModel, ro);
    if (!refined) return refined.error();
    out.refined = std::move(refined).value();
  }
  return {};
}

}  // namespace

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
  auto diagram =
      options.method == IdentificationMethod::Lsce ? lsceStabilization(frf, est) : plscfStabilization(frf, est);
  if (!diagram) return diagram.error();

  IdentificationResult out;
  if (!report(IdentificationStage::Selection, 0.0)) return makeError(ErrorCode::Cancelled, "cancelled", where);
  auto selected = selectPoles(*diagram, est);
  if (!selected) return selected.error();
  out.diagram = std::move(diagram).value();
  out.selected = std::move(selected).value();

  if (auto ok = fitSelection(frf, options, report, out); !ok) return ok.error();
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
  if (auto ok = fitSelection(frf, options, report, out); !ok) return ok.error();
  return out;
}

Result<SelectionFit> fitSelectedPoles(const FrfMatrix& frf, const std::vector<Complex>& poles,
                                      const LsfdOptions& band) {
  const std::string where = "pole selection fit";
  if (auto ok = frf.validate(); !ok) return ok.error();
  if (poles.empty()) return makeError(ErrorCode::InvalidArgument, "no poles selected", where);
  Eigen::Index k0 = 0;
  while (k0 < frf.lineCount() && (frf.frequencyHz[k0] < band.bandLowHz || frf.frequencyHz[k0] == 0.0)) ++k0;
  Eigen::Index k = k0;
  while (k < frf.lineCount() && frf.frequencyHz[k] <= band.bandHighHz) ++k;
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
  auto vp = ModalVarpro::create(frf, {LineSegment{k0, k - k0}}, nm, band.lowerResidual, band.upperResidual, false);
  if (!vp) return makeError(vp.error().code, vp.error().message, where + ", band");
  if (!vp->evaluate(theta, false)) {
    return makeError(ErrorCode::NumericalFailure, "basis is rank deficient: duplicate poles or too narrow a band",
                     where);
  }
  SelectionFit out;
  out.model = modalModelFromLinear(*vp, frf, poles);
  out.relativeError = std::sqrt(vp->explicitSsr() / vp->dataNorm2());
  out.synthesis.frequencyHz = frf.frequencyHz.segment(k0, k - k0);
  out.synthesis.responses = frf.responses;
  out.synthesis.references = frf.references;
  out.synthesis.type = frf.type;
  vp->modelValues(out.synthesis.h);
  return out;
}

}  // namespace mozzi::core::modal
