#pragma once
// The one place the workbench calls core/modal's identification (issue 18):
// the run behind the identification page (diagram, automatic selection, LSFD,
// refinement with standard errors - the calls `mozzi-cli identify` makes, so
// the numbers are the CLI's), the cheap re-fit behind a pole click
// (SelectionFitter), and the refinement of a hand-made selection. When core/modal exposes one pipeline
// function (issue 19: identifyModes, fitSelectedPoles), only this file changes.
// No widget here; the functions run on a worker (identify, refine) or the GUI
// thread (SelectionFitter: milliseconds).

#include <memory>
#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/modal/identification.h"
#include "core/modal/modal_model.h"
#include "core/modal/plscf.h"
#include "core/modal/refine.h"

namespace mozzi {
namespace views {

class JobProgress;

namespace identification {

enum class Method { Plscf = 0, Lsce, Peak, CircleFit };
const char* methodKey(Method method);         // "plscf", "lsce", "peak", "circle" (the CLI's --method)
std::string storedMethodName(Method method);  // "PolyMAX", ... as the CLI stores it (core::modal::storedMethodName)
enum class Backdrop { Sum = 0, Cmif };

struct Options {
  Method method = Method::Plscf;
  double bandLowHz = 0.0, bandHighHz = 0.0;
  int maxOrder = 60;  // the CLI's default
  Backdrop backdrop = Backdrop::Sum;
  // Refine the automatic selection (the CLI always does: its numbers need it).
  // Off, the run ends with the LSFD fit and no standard errors; a save refines.
  bool refine = true;
};

// Estimator options as the CLI builds them (pLSCF options plus the LSCE window).
core::modal::PlscfOptions estimatorOptions(const Options& options);

struct Outcome {
  Options options;
  // Stabilization diagram (pLSCF, LSCE); null for the single-mode methods.
  std::shared_ptr<const core::modal::StabilizationDiagram> diagram;
  std::vector<core::modal::SelectedPole> automatic;  // the automatic selection (a start)
  core::modal::ModalModel model;                     // model of the automatic selection
  bool refined = false;                              // model refined (the CLI's numbers)
  std::vector<double> frequencyStdHz, zetaStd;       // its standard errors (when refined)
  Eigen::Index refinedLines = 0, bandLines = 0;      // lines the refinement fitted, of the band's (when refined)
  std::shared_ptr<const core::Vector> backdropDb;    // 20 log10 |sum| or of the first CMIF value, every line
};

// The diagram's backdrop of `frf` on every line [dB]: 20 log10 |sum of the
// FRFs| or of the first CMIF value; null when it cannot be formed.
std::shared_ptr<const core::Vector> backdropDb(const core::FrfMatrix& frf, Backdrop kind);

// Worker thread. Errors: those of core (band, orders, no stable mode, ...), Cancelled.
core::Result<Outcome> identify(const core::FrfMatrix& frf, const Options& options, JobProgress& progress);

struct Fit {
  core::modal::ModalModel model;  // LSFD residues and residual terms for the poles
  core::Matrix residual;          // relative residual per FRF (no x ni); empty: no fit over the data
  double relativeError = 0.0;     // over all FRFs
};

// The fit behind pole clicks over a run's band (GUI thread: about 20 ms on
// 100 FRFs x 18,000 lines, docs/performance/workbench-plots.md): LSFD for the
// chosen poles and the residual of every FRF; the synthesis only of the FRF
// shown. What does not depend on the poles is done once per band.
class SelectionFitter {
 public:
  // Keeps `frf` (shared). Errors: an FRF set core refuses.
  static core::Result<SelectionFitter> create(std::shared_ptr<const core::FrfMatrix> frf, double bandLowHz,
                                              double bandHighHz);
  core::Result<Fit> fit(const std::vector<core::Complex>& poles);
  // The band's lines [Hz] (one vector for every fit: the plots share it).
  const std::shared_ptr<const core::Vector>& frequencyHz() const { return lines_; }
  // FRF (response, reference) measured on the band's lines (a view into the set).
  core::ComplexVectorRef measured(Eigen::Index response, Eigen::Index reference) const;
  // The last successful fit's model of FRF (response, reference) on the band's lines; false: no fit.
  bool synthesis(Eigen::Index response, Eigen::Index reference, core::ComplexVector& out) const;
  // Each FRF's level on the band: the RMS of its lines against the strongest
  // FRF's [dB] (-inf for a zero FRF), responses x references. Computed once per
  // band, not per fit.
  const core::Matrix& levelsDb() const { return levelsDb_; }

 private:
  SelectionFitter(std::shared_ptr<const core::FrfMatrix> frf, core::modal::SelectionFitter fitter);
  std::shared_ptr<const core::FrfMatrix> frf_;
  core::modal::SelectionFitter fitter_;
  std::shared_ptr<const core::Vector> lines_;
  core::Matrix levelsDb_;
};

// The residual of every FRF of a fit with the FRF's level
// (SelectionFitter::levelsDb) and the misfit's level, level + 20 log10
// residual: the RMS of H - synthesis over the band against the strongest
// FRF's. Worst first by the misfit: a residual near 100 % on an FRF 60 dB
// down is that FRF's noise (a DOF the modes barely move, by a constraint), not
// a mode the fit missed, and comes after a 20 % residual on a strong FRF.
struct FrfResidual {
  Eigen::Index response = 0, reference = 0;
  double residual = 0.0;  // relative, as Fit::residual
  double levelDb = 0.0;
  double misfitDb = 0.0;  // -inf for a perfect fit or an FRF without level
};
std::vector<FrfResidual> residualsWorstFirst(const SelectionFitter& fitter, const core::Matrix& residual);

// Refinement of a model (worker thread), as the CLI refines the automatic selection.
core::Result<core::modal::RefineResult> refine(const core::FrfMatrix& frf, const core::modal::ModalModel& model,
                                               double bandLowHz, double bandHighHz, JobProgress& progress);

}  // namespace identification
}  // namespace views
}  // namespace mozzi
