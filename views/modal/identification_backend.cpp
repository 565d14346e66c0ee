#include "views/modal/identification_backend.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/frf_display.h"
#include "core/modal/identification.h"
#include "core/modal/lsce.h"
#include "core/modal/lsfd.h"
#include "core/modal/pole_selection.h"
#include "core/modal/sdof.h"
#include "core/modal/shape_tools.h"
#include "views/common/job_runner.h"

namespace mozzi {
namespace views {
namespace identification {

namespace md = core::modal;

const char* methodKey(Method m) {
  switch (m) {
    case Method::Plscf: return "plscf";
    case Method::Lsce: return "lsce";
    case Method::Peak: return "peak";
    case Method::CircleFit: return "circle";
  }
  return "plscf";
}

std::string storedMethodName(Method m) {
  return md::storedMethodName(methodKey(m));
}

md::PlscfOptions estimatorOptions(const Options& o) {
  md::LsceOptions opt;
  opt.bandLowHz = o.bandLowHz;
  opt.bandHighHz = o.bandHighHz;
  opt.maxOrder = o.maxOrder;
  return opt;
}

namespace {

core::Result<void> cancelledIf(JobProgress& p) {
  if (p.cancelled()) return core::makeError(core::ErrorCode::Cancelled, "cancelled by the user", "identification");
  return {};
}

}  // namespace

std::shared_ptr<const core::Vector> backdropDb(const core::FrfMatrix& frf, Backdrop kind) {
  core::Vector mag;
  if (kind == Backdrop::Cmif) {
    auto sv = md::cmif(frf);
    if (sv) mag = sv->col(0);
  }
  if (mag.size() == 0) {
    auto sum = core::frfMagnitudeSum(frf, core::pickFrfs(frf, {}));
    if (!sum) return nullptr;
    mag = std::move(*sum);
  }
  core::Vector db(mag.size());
  for (Eigen::Index k = 0; k < mag.size(); ++k) db[k] = 20.0 * std::log10(std::max(mag[k], 1e-300));
  return std::make_shared<const core::Vector>(std::move(db));
}

core::Result<Outcome> identify(const core::FrfMatrix& frf, const Options& options, JobProgress& progress) {
  Outcome out;
  out.options = options;
  out.backdropDb = backdropDb(frf, options.backdrop);
  if (options.method == Method::Peak || options.method == Method::CircleFit) {
    progress.report(0.2, "single-mode fit");
    auto est = options.method == Method::Peak ? md::peakPicking(frf, 0, options.bandLowHz, options.bandHighHz)
                                              : md::circleFit(frf, 0, options.bandLowHz, options.bandHighHz);
    if (!est) return est.error();
    // As the CLI: one mode, residues of reference 0.
    out.model.responses = frf.responses;
    out.model.references = {frf.references[0]};
    md::Mode mode;
    mode.pole = md::poleFromFrequencyDamping(est->frequencyHz, est->zeta);
    mode.residue = est->residue;
    out.model.modes.push_back(mode);
    md::SelectedPole s;
    s.pole = mode.pole;
    out.automatic.push_back(s);
    out.refined = true;  // nothing to refine: the CLI's numbers as they are
    return out;
  }
  // The CLI's calls (app/cli/commands/identify.cpp): estimator with its
  // defaults, automatic selection, LSFD, refinement over the band.
  md::LsceOptions opt;
  static_cast<md::PlscfOptions&>(opt) = estimatorOptions(options);
  progress.report(0.05, "stabilization diagram");
  if (auto c = cancelledIf(progress); !c) return c.error();
  const bool lsce = options.method == Method::Lsce;
  auto diagram = lsce ? md::lsceStabilization(frf, opt) : md::plscfStabilization(frf, opt);
  if (!diagram) return diagram.error();
  if (auto c = cancelledIf(progress); !c) return c.error();
  progress.report(0.5, "automatic selection and LSFD");
  auto res = md::modalModelFromDiagram(frf, *diagram, opt);
  out.diagram = std::make_shared<const md::StabilizationDiagram>(std::move(diagram).value());
  if (!res) return res.error();
  out.automatic = res->selected;
  if (auto c = cancelledIf(progress); !c) return c.error();
  if (!options.refine) {
    out.model = res->model;
    progress.report(1.0, "done");
    return out;
  }
  progress.report(0.6, "refinement");
  auto refined = refine(frf, res->model, options.bandLowHz, options.bandHighHz, progress);
  if (!refined) return refined.error();
  out.model = refined->model;
  out.refined = true;
  out.frequencyStdHz = refined->frequencyStdHz;
  out.zetaStd = refined->zetaStd;
  out.refinedLines = refined->fittedLines;
  out.bandLines = refined->bandLines;
  progress.report(1.0, "done");
  return out;
}

SelectionFitter::SelectionFitter(std::shared_ptr<const core::FrfMatrix> frf, md::SelectionFitter fitter)
    : frf_(std::move(frf)), fitter_(std::move(fitter)) {
  lines_ = std::make_shared<const core::Vector>(frf_->frequencyHz.segment(fitter_.firstLine(), fitter_.lineCount()));
  const auto no = static_cast<Eigen::Index>(frf_->responseCount());
  const auto ni = static_cast<Eigen::Index>(frf_->referenceCount());
  core::Matrix rms(no, ni);
  for (Eigen::Index i = 0; i < ni; ++i) {
    for (Eigen::Index o = 0; o < no; ++o) {
      const core::ComplexVectorRef h = measured(o, i);
      rms(o, i) = h.size() ? h.norm() / std::sqrt(static_cast<double>(h.size())) : 0.0;
    }
  }
  const double strongest = rms.size() ? rms.maxCoeff() : 0.0;
  levelsDb_ = rms.unaryExpr([strongest](double r) {
    return r > 0.0 && strongest > 0.0 ? 20.0 * std::log10(r / strongest) : -std::numeric_limits<double>::infinity();
  });
}

core::Result<SelectionFitter> SelectionFitter::create(std::shared_ptr<const core::FrfMatrix> frf, double lo,
                                                      double hi) {
  if (!frf) return core::makeError(core::ErrorCode::InvalidArgument, "no FRF set", "pole selection fit");
  md::LsfdOptions band;
  band.bandLowHz = lo;
  band.bandHighHz = hi;
  auto fitter = md::SelectionFitter::create(*frf, band);  // *frf stays where it is: the pointer moves
  if (!fitter) return fitter.error();
  return SelectionFitter(std::move(frf), std::move(fitter).value());
}

core::Result<Fit> SelectionFitter::fit(const std::vector<core::Complex>& poles) {
  // core's one-QR fit (identification.h): LSFD and the residual per FRF in
  // two products over the band's data; no synthesis of the FRFs not shown.
  auto selection = fitter_.fit(poles);
  if (!selection) return selection.error();
  Fit fit;
  fit.model = std::move(selection->model);
  fit.residual = std::move(selection->residual);
  fit.relativeError = selection->relativeError;
  return fit;
}

core::ComplexVectorRef SelectionFitter::measured(Eigen::Index response, Eigen::Index reference) const {
  return frf_->h[static_cast<std::size_t>(reference)].col(response).segment(fitter_.firstLine(), fitter_.lineCount());
}

bool SelectionFitter::synthesis(Eigen::Index response, Eigen::Index reference, core::ComplexVector& out) const {
  return fitter_.synthesis(response, reference, out);
}

std::vector<FrfResidual> residualsWorstFirst(const SelectionFitter& fitter, const core::Matrix& residual) {
  std::vector<FrfResidual> rows;
  rows.reserve(static_cast<std::size_t>(residual.size()));
  for (Eigen::Index i = 0; i < residual.cols(); ++i) {
    for (Eigen::Index o = 0; o < residual.rows(); ++o) {
      const double r = residual(o, i), level = fitter.levelsDb()(o, i);
      const double misfit = r > 0.0 ? level + 20.0 * std::log10(r) : -std::numeric_limits<double>::infinity();
      rows.push_back({o, i, r, level, std::isnan(misfit) ? -std::numeric_limits<double>::infinity() : misfit});
    }
  }
  std::stable_sort(rows.begin(), rows.end(), [](const FrfResidual& a, const FrfResidual& b) {
    return a.misfitDb > b.misfitDb || (a.misfitDb == b.misfitDb && a.residual > b.residual);
  });
  return rows;
}

core::Result<md::RefineResult> refine(const core::FrfMatrix& frf, const md::ModalModel& model, double lo, double hi,
                                      JobProgress& progress) {
  if (auto c = cancelledIf(progress); !c) return c.error();
  md::IdentificationOptions opt;  // the CLI's refinement: the lines it fits are the core's default
  opt.estimator.bandLowHz = lo;
  opt.estimator.bandHighHz = hi;
  return md::refineSelection(frf, model, opt);
}

}  // namespace identification
}  // namespace views
}  // namespace mozzi
