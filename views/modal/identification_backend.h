#pragma once
// The one place the workbench calls core/modal's identification (issue 18):
// the run behind the identification page (diagram, automatic selection, LSFD,
// refinement with standard errors - the calls `mozzi-cli identify` makes, so
// the numbers are the CLI's), the cheap re-fit behind a pole click, and the
// refinement of a hand-made selection. When core/modal exposes one pipeline
// function (issue 19: identifyModes, fitSelectedPoles), only this file changes.
// No widget here; the functions run on a worker (identify, refine) or the GUI
// thread (fitSelection: milliseconds).

#include <memory>
#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/frf_matrix.h"
#include "core/common/result.h"
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
  std::shared_ptr<const core::Vector> backdropDb;    // 20 log10 |sum| or of the first CMIF value, every line
};

// Worker thread. Errors: those of core (band, orders, no stable mode, ...), Cancelled.
core::Result<Outcome> identify(const core::FrfMatrix& frf, const Options& options, JobProgress& progress);

struct Fit {
  core::modal::ModalModel model;  // LSFD residues and residual terms for the poles
  core::FrfMatrix measured;       // the FRFs on the band's lines
  core::FrfMatrix synthesis;      // the model on the same lines
  core::Matrix residual;          // relative residual per FRF (no x ni)
  double relativeError = 0.0;     // over all FRFs
};

// LSFD and synthesis for a chosen pole set, over the band (GUI thread).
core::Result<Fit> fitSelection(const core::FrfMatrix& frf, const std::vector<core::Complex>& poles, double bandLowHz,
                               double bandHighHz);

// Refinement of a model (worker thread), as the CLI refines the automatic selection.
core::Result<core::modal::RefineResult> refine(const core::FrfMatrix& frf, const core::modal::ModalModel& model,
                                               double bandLowHz, double bandHighHz, JobProgress& progress);

}  // namespace identification
}  // namespace views
}  // namespace mozzi
