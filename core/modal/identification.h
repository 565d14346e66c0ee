#pragma once
// The identification pipeline as one call, the code `mozzi-cli identify` runs
// and the workbench's identification page calls (issue 19):
//   band, method, orders -> stabilization diagram (pLSCF or LSCE) ->
//   automatic pole selection -> LSFD -> refinement (variable projection,
//   standard errors), with progress and cancel.
// After a click in the stabilization diagram, without re-running the diagram:
// fitSelectedPoles (LSFD residues and the synthesised FRFs for a pole set,
// the preview: 34 ms on the ModeLAB beam; SelectionFitter, the same fit for
// repeated clicks on one band, synthesising only the FRFs shown) and reselectModes (the same result
// as identifyModes for a selection of diagram poles, refinement and standard
// errors included). Figures: docs/performance/commands.md.

#include <functional>
#include <optional>
#include <vector>

#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/modal/lsce.h"
#include "core/modal/lsfd.h"
#include "core/modal/modal_model.h"
#include "core/modal/plscf.h"
#include "core/modal/refine.h"
#include "core/modal/varpro.h"

namespace mozzi::core::modal {

enum class IdentificationMethod { Plscf, Lsce };

enum class IdentificationStage { Diagram, Selection, Lsfd, Refinement };
const char* identificationStageName(IdentificationStage stage);  // "stabilization diagram", ...

struct IdentificationProgress {
  IdentificationStage stage = IdentificationStage::Diagram;
  double fraction = 0.0;  // of the stage, 0..1 (diagram: orders done; refinement: iterations of the maximum)
};
// Returning false cancels: identifyModes returns ErrorCode::Cancelled.
using IdentificationCallback = std::function<bool(const IdentificationProgress&)>;

// Bands of more lines than this are refined on the lines carrying the modes
// (refine.h); the measurements behind the figure: identification.cpp.
extern const Eigen::Index kRefineLinesCarryingModes;

struct IdentificationOptions {
  IdentificationMethod method = IdentificationMethod::Plscf;
  // Band, orders, stability criteria, automatic selection; the LSCE window
  // (pLSCF ignores it). Its orderProgress is replaced by the callback's.
  LsceOptions estimator;
  bool refine = true;
  int maxRefineIterations = 50;
  // Refinement on the lines carrying the modes when the band holds more
  // (RefineOptions::maxLines); 0 = every line. The default is the one of
  // `mozzi-cli identify` and the workbench (identification.cpp says why).
  Eigen::Index refineMaxLines = kRefineLinesCarryingModes;
};

struct IdentificationResult {
  StabilizationDiagram diagram;
  std::vector<SelectedPole> selected;
  // LSFD for the selected poles, lower and upper residuals: over the band's
  // lines, or over the refinement's fitted lines when it was thinned (the
  // refined model is then the one used: no LSFD over the band for it).
  ModalModel lsfdModel;
  std::optional<RefineResult> refined;  // when options.refine
  // The final model: refined when refinement ran, else the LSFD one.
  const ModalModel& model() const { return refined ? refined->model : lsfdModel; }
};

// Errors: those of the estimator (band, orders, singular equations), no
// stable mode in band (NotFound), LSFD and refinement failures, Cancelled.
Result<IdentificationResult> identifyModes(const FrfMatrix& frf, const IdentificationOptions& options,
                                           const IdentificationCallback& progress = {});

// The refinement as identifyModes runs it, from a model of the band (only
// its poles and participation factors are used): band, iterations and the
// lines it fits (options.refineMaxLines: on the lines carrying the modes when
// the band holds more; the model and the standard errors still describe
// every line of the band, refine.h) from `options`; progress: Refinement
// stage. The workbench's "refine the selection" runs this too.
// Errors: refineModalModel's.
Result<RefineResult> refineSelection(const FrfMatrix& frf, const ModalModel& start,
                                     const IdentificationOptions& options, const IdentificationCallback& progress = {});

// --- Re-selection -------------------------------------------------------------

// The user changed the selection in the diagram of a previous identifyModes:
// `diagramPoles` are indices into diagram.poles (a click picks the pole
// nearest the cursor; clusterSize 1, no spreads). The diagram is kept (pass
// the previous result's, moved); LSFD and, when options.refine, the
// refinement with its standard errors run for the new selection, in
// frequency order: the cost of an LSFD plus a refinement, not of the diagram
// (docs/performance/commands.md). options.estimator gives the band.
// Errors: no pole, an index outside the diagram or given twice
// (InvalidArgument), then as identifyModes after the selection.
Result<IdentificationResult> reselectModes(const FrfMatrix& frf, StabilizationDiagram diagram,
                                           const std::vector<std::size_t>& diagramPoles,
                                           const IdentificationOptions& options,
                                           const IdentificationCallback& progress = {});

struct SelectionFit {
  ModalModel model;            // LSFD residues and residual terms for the chosen poles
  FrfMatrix synthesis;         // the model's FRFs on the band's lines (responses, references, type of the data)
  double relativeError = 0.0;  // sqrt(sum |H - H_model|^2 / sum |H|^2) over the band
};

// LSFD and synthesis for a pole set the user chose (a pole clicked in the
// stabilization diagram added or removed): one QR of the basis and three
// products over the band's data (Q^T Y, the residual, the synthesis of every
// FRF). Errors: as lsfd(). A page that plots one FRF uses SelectionFitter.
Result<SelectionFit> fitSelectedPoles(const FrfMatrix& frf, const std::vector<Complex>& poles, const LsfdOptions& band);

// What a pole click needs (the identification page), without the synthesis
// of every FRF.
struct PoleSetFit {
  ModalModel model;  // LSFD residues and residual terms for the chosen poles, in the order given
  // Relative residual per FRF (no x ni): sqrt(sum |H - H_model|^2 / sum |H|^2)
  // over the band's lines; 0 for an FRF that is zero there.
  Matrix residual;
  double relativeError = 0.0;  // the same over every FRF (fitSelectedPoles' relativeError)
};

// The fit behind pole clicks on one band of one FRF set: fitSelectedPoles'
// numbers, with what does not depend on the poles done once (the band's
// lines, sum |H|^2 per FRF) and the workspaces of the last few mode counts
// kept, so that a click allocates nothing of the data's size. A fit is one
// QR of the basis and two products over the band's data (Q^T Y; the residual
// R = Y - Q Z per block of lines); the model's FRFs are computed only for the
// FRFs asked for afterwards. On 100 FRFs x 18,000 lines that is about half
// of fitSelectedPoles' work (docs/performance/workbench-plots.md).
class SelectionFitter {
 public:
  // `frf` must outlive the fitter (nothing is copied). Errors: frf.validate()'s.
  static Result<SelectionFitter> create(const FrfMatrix& frf, const LsfdOptions& band);

  // Errors: as fitSelectedPoles (no pole, a pole not admissible, too few
  // lines in the band, rank-deficient basis).
  Result<PoleSetFit> fit(const std::vector<Complex>& poles);

  // The last successful fit's model on the band's lines (Phi X = Q Z, as
  // fitSelectedPoles' synthesis): one FRF, or every FRF (one nf x no matrix
  // per reference). False (and `out` untouched) when there is no such fit.
  bool synthesis(Eigen::Index response, Eigen::Index reference, ComplexVector& out) const;
  bool synthesis(std::vector<ComplexMatrix>& out) const;

  // The band's lines: frf.frequencyHz[firstLine() .. firstLine() + lineCount()).
  Eigen::Index firstLine() const { return first_; }
  Eigen::Index lineCount() const { return count_; }

 private:
  SelectionFitter() = default;
  const FrfMatrix* frf_ = nullptr;
  LsfdOptions band_;
  Eigen::Index first_ = 0, count_ = 0;
  Matrix norm2_;  // sum |H|^2 over the band's lines, per FRF (no x ni)
  // Evaluators by mode count, the last used (the last fit's when
  // lastValid_) at the back; at most kKeptWorkspaces.
  std::vector<ModalVarpro> workspaces_;
  bool lastValid_ = false;
};

}  // namespace mozzi::core::modal
