#pragma once
// Polyreference least-squares complex frequency-domain estimator (pLSCF,
// "PolyMAX"; Peeters, Van der Auweraer, Guillaume, Leuridan, Shock and
// Vibration 11, 2004) with a stabilization diagram and automatic pole
// selection. Replaces the commercial curve fitter of thesis §1.6 ("FRFs have
// been analyzed with the ICATS software").
//
// Right matrix-fraction model per output o in z = exp(i omega dt):
//   H_o(omega) = B_o(z) A(z)^-1,  A(z) = sum_{j=0}^{n} z^j alpha_j (ni x ni),
//   B_o(z) = sum_j z^j beta_oj (1 x ni), real coefficients, alpha_n = I.
// Reduced normal equations: with R = Re(X^H X), S_o = Re(X^H Y_o),
// T_o = Re(Y_o^H Y_o) (all block Toeplitz in the lag l - j),
//   M_n = sum_o (T_o - S_o^T R^-1 S_o),   [M_n]_{0..n-1} alpha_{0..n-1} = -[M_n]_{., n}.
// The lags are sums over lines of z^d times data, evaluated for all d at once
// by one FFT per series on an even grid. M for every order m <= n comes from one
// Cholesky factor R = L L^T: with W_o = L^-1 S_o (nested), the order-m matrix
// is T_m - sum_{j <= m} sum_o w_oj^T w_oj (leading block), a running sum.

#include <functional>
#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/modal/modal_model.h"

namespace mozzi::core::modal {

enum class StabilityVector {
  ShapeMac,       // MAC of the pole's mode shape B_o(z_r) l_r between orders
  Participation,  // MAC of the participation vector l_r (meaningful for ni > 1)
};

struct StabilityCriteria {
  double frequencyTolerance = 0.01;  // |f_m - f_{m-1}| / f_{m-1}
  double dampingTolerance = 0.05;    // |zeta_m - zeta_{m-1}| / zeta_{m-1}
  double macThreshold = 0.98;        // vector consistency between orders
  StabilityVector vector = StabilityVector::ShapeMac;
  double maxZeta = 0.25;  // poles more damped than this are not physical candidates
};

struct PlscfOptions {
  double bandLowHz = 0.0;
  double bandHighHz = 0.0;  // lines with bandLowHz <= f <= bandHighHz are fitted
  int minOrder = 2;
  int maxOrder = 40;  // polynomial degree n; n ni poles
  int orderStep = 1;
  StabilityCriteria criteria;
  // Automatic selection: a cluster of stable poles is a physical mode when it
  // holds poles from at least this fraction of the evaluated orders ...
  double minClusterFraction = 0.3;
  // ... and at least this many poles.
  int minClusterSize = 5;
  // Poles join a cluster within this relative frequency distance of its median.
  double clusterFrequencyTolerance = 0.005;
  // Called before each order of the diagram is solved (pLSCF and LSCE);
  // returning false stops with ErrorCode::Cancelled. Empty: not called.
  std::function<bool(int order)> orderProgress;
};

enum class PoleStatus {
  New = 0,               // 'o' no matching pole at the previous order
  Frequency = 1,         // 'f' frequency stable
  FrequencyDamping = 2,  // 'd' frequency and damping stable
  FrequencyVector = 3,   // 'v' frequency and vector stable
  Stable = 4,            // 's' all three
};

char poleStatusSymbol(PoleStatus status);

struct StabilizationPole {
  int order = 0;
  Complex pole;  // lambda [rad/s]
  double frequencyHz = 0.0;
  double zeta = 0.0;
  PoleStatus status = PoleStatus::New;
  ComplexVector participation;  // l_r (ni)
  ComplexVector shape;          // B_o(z_r) l_r over outputs (no), unnormalised
};

struct StabilizationDiagram {
  std::vector<int> orders;               // evaluated orders
  std::vector<StabilizationPole> poles;  // physical candidates of every order (band, 0 < zeta <= maxZeta)
  double bandLowHz = 0.0, bandHighHz = 0.0;
  double samplingTime = 0.0;  // dt of the z-domain model [s]
  double resolutionHz = 0.0;  // line spacing of the fitted FRFs in the band (mode_merging.h)
};

struct SelectedPole {
  Complex pole;
  ComplexVector participation;
  int clusterSize = 0;           // stable poles in the cluster
  double frequencySpreadHz = 0;  // standard deviation of the cluster's frequencies
  double zetaSpread = 0;         // standard deviation of the cluster's damping ratios
  ComplexVector shape;           // shape of the cluster's highest-order pole (same-mode check)
};

// The highest order the band's lines support (a fit of order n needs
// 2 (n + 1) lines, bandLowHz <= f <= bandHighHz): what a default order is
// capped at, so a narrow band of a short record still gets a diagram.
int plscfOrderLimit(const FrfMatrix& frf, double bandLowHz, double bandHighHz);

// Stabilization diagram of the FRFs in the band. Errors: fewer lines than the
// highest order needs, an order range too small to judge stability (fewer
// orders than minClusterSize), invalid FRFs, singular normal equations.
// With more references than responses it fits the transposed FRFs
// (stabilizationOnFewerReferences in stabilization.h); participation and shape
// still refer to this FRF's references and responses.
Result<StabilizationDiagram> plscfStabilization(const FrfMatrix& frf, const PlscfOptions& options);

// Clusters the stable ('s') poles, keeps one pole per physical mode
// (mode_merging.h: closer than the resolution or the same shape); NotFound when no cluster qualifies
// ("no stable mode in band"), never an invented mode.
Result<std::vector<SelectedPole>> selectPoles(const StabilizationDiagram& diagram, const PlscfOptions& options);

struct PlscfResult {
  StabilizationDiagram diagram;
  std::vector<SelectedPole> selected;
  ModalModel model;  // LSFD residues for the selected poles, lower and upper residuals
};

// Automatic selection on a diagram (of pLSCF or LSCE) and LSFD over the band
// with lower and upper residuals.
Result<PlscfResult> modalModelFromDiagram(const FrfMatrix& frf, StabilizationDiagram diagram,
                                          const PlscfOptions& options);

// Whole chain: stabilization diagram, automatic selection, LSFD over the band
// with lower and upper residuals.
Result<PlscfResult> identifyPlscf(const FrfMatrix& frf, const PlscfOptions& options);

// Writes the diagram as CSV: order,frequency_hz,zeta,status.
Result<void> writeStabilizationCsv(const StabilizationDiagram& diagram, const std::string& path);

}  // namespace mozzi::core::modal
