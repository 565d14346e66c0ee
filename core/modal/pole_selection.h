#pragma once
// What the identification page shows and does with a pole selection, without
// a widget: which diagram pole stands for a selected mode, the modal table
// (frequency, zeta, eta, their standard errors, MPC, MPD, complexity), the
// residual of the synthesis per FRF, and the same-mode warnings for a
// selection made by hand (mode_merging.h). `mozzi-cli identify --store` and
// the page save the same ModalTable (modalTableOf).

#include <optional>
#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/io/project_records.h"
#include "core/io/project_store.h"
#include "core/modal/modal_model.h"
#include "core/modal/mode_merging.h"
#include "core/modal/plscf.h"

namespace mozzi::core::modal {

// The diagram pole drawn as a selected mode: among the stable poles within the
// clustering tolerance of the mode's frequency, the one of the highest order
// (nearest in frequency at that order); if none is stable, any status. -1 when
// the diagram holds no pole that near.
int representativePole(const StabilizationDiagram& diagram, Complex pole, double relativeTolerance);

// Index of the diagram pole nearest to a point of the diagram's plane
// (frequency [Hz], order), distances measured in units of hzScale and
// orderScale (the size of a pixel, so "nearest on screen"); -1 when none is
// within maxDistance such units.
int nearestDiagramPole(const StabilizationDiagram& diagram, double frequencyHz, double order, double hzScale,
                       double orderScale, double maxDistance);

struct ModalTableRow {
  double frequencyHz = 0.0;
  double zeta = 0.0;
  double eta = 0.0;                                       // loss factor 2 zeta
  std::optional<double> frequencyStdHz, zetaStd, etaStd;  // standard errors (after refinement)
  double mpc = 0.0;                                       // modal phase collinearity [0, 1]
  double mpdDegrees = 0.0;                                // mean phase deviation [deg]
  double complexity = 0.0;                                // 1 - MPC: 0 for a real (normal) mode
};

// Rows of the modal table: shapes from the residues of reference 0 (as the
// CLI). Standard errors when given (one per mode), else empty.
Result<std::vector<ModalTableRow>> modalTableRows(const ModalModel& model,
                                                  const std::vector<double>& frequencyStdHz = {},
                                                  const std::vector<double>& zetaStd = {});

// Relative residual per FRF over the band: sqrt(sum |H - H_model|^2 / sum |H|^2)
// for every (response, reference), as a no x ni matrix. `synthesis` on the
// same lines as `measured`. Errors: shapes differ, no line in the band.
Result<Matrix> residualPerFrf(const FrfMatrix& measured, const FrfMatrix& synthesis, double bandLowHz,
                              double bandHighHz);

// Same-mode warnings for a hand-made selection: every pair of chosen poles
// that are one mode, described in words (describeSameMode).
struct SelectionWarning {
  std::size_t first = 0, second = 0;
  SameModePair pair;
  std::string text;
};
std::vector<SelectionWarning> selectionWarnings(const std::vector<ModeCandidate>& chosen,
                                                const SameModeCriteria& criteria);

// Method name stored with a modal result for the CLI's --method key
// ("plscf" -> "PolyMAX", "lsce" -> "LSCE", "peak" -> "peak picking",
// "circle" -> "circle fit"); the key itself when unknown.
std::string storedMethodName(const std::string& methodKey);
// "PolyMAX 65 .. 1000 Hz": the name of a stored result when none is given.
std::string defaultModalResultName(const std::string& methodKey, double bandLowHz, double bandHighHz);
// `name` if no result of the specimen has it, else "name (2)", "name (3)", ...:
// a project holds one modal result of a name per specimen, and identifying the
// same band twice with the default name must not fail.
std::string uniqueModalResultName(const std::vector<io::ModalResultInfo>& existing, std::int64_t specimenId,
                                  const std::string& name);

// The modal result stored in a project: DOFs = the model's responses, one
// StoredMode per mode with f, zeta and the shape of reference 0 (unit modal
// mass at a driving point, else max component: modeShapes), and the standard
// errors of f and zeta when given (one per mode, the refinement's).
Result<io::ModalTable> modalTableOf(const ModalModel& model, const std::vector<double>& frequencyStdHz = {},
                                    const std::vector<double>& zetaStd = {});

// Removes the decay an exponential window of time constant tauS [s] added to
// every mode (core::signal::correctExponentialWindowDamping): natural
// frequency and zeta (and eta) of each row / stored mode. Standard errors are
// kept (the correction shifts the decay rate by the constant 1/tau). tauS <= 0
// changes nothing. Errors: those of the correction, naming the mode.
Result<void> removeExponentialWindow(std::vector<ModalTableRow>& rows, double tauS);
Result<void> removeExponentialWindow(io::ModalTable& table, double tauS);

// Keeps `model` as a modal result of the project, as `mozzi-cli identify
// --store` and the demo project do: modalTableOf (with the standard errors
// when given), the exponential window's
// decay removed (tauS), the method's stored name, and the default name of
// method and band made unique for the specimen. `info` gives the specimen, the
// FRF set and the band. Returns the new result's id.
Result<std::int64_t> storeModalResult(io::ProjectStore& store, const ModalModel& model, io::ModalResultInfo info,
                                      const std::string& methodKey, double tauS,
                                      const std::vector<double>& frequencyStdHz = {},
                                      const std::vector<double>& zetaStd = {});

}  // namespace mozzi::core::modal
