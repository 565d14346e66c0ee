#pragma once
// Single-mode methods for one selected band (Ewins, "Modal testing", ch. 4):
// peak picking with half-power damping and the Kennedy-Pancu circle fit.

#include "core/common/eigen_types.h"
#include "core/common/frf_matrix.h"
#include "core/common/result.h"
#include "core/modal/modal_model.h"

namespace mozzi::core::modal {

struct SdofEstimate {
  double frequencyHz = 0.0;
  double zeta = 0.0;
  ComplexVector residue;  // per response of the chosen reference: receptance residue R (modal_model.h)
};

// Peak picking: the natural frequency is the peak of sum_o |H_o|^2 in the band
// (parabolic interpolation over three lines); zeta = (f2^2 - f1^2) / (4 fr^2)
// from the half-power points f1, f2 (|H| = |H|max / sqrt 2, linear
// interpolation) of the strongest response. Residues: R = A / (2 i omega_d) with
// the modal constant A = i 2 zeta omega_r^2 H_rec(omega_r). Errors: band with
// fewer than 5 lines, peak on the band edge, half-power point outside the band.
Result<SdofEstimate> peakPicking(const FrfMatrix& frf, Eigen::Index reference, double bandLowHz, double bandHighHz);

// Circle fit (Kennedy-Pancu): the mobility of a viscous mode traces a circle in
// the Nyquist plane. Per response: least-squares circle (Kasa) through the
// band's points; the natural frequency is where the angle sweeps fastest per
// omega^2; zeta from point pairs either side, zeta = (wa^2 - wb^2) /
// (2 wr (wa tan(ta/2) + wb tan(tb/2))) averaged; modal constant from the
// diameter D = |A| / (2 zeta wr) and the circle's orientation. Frequency and
// damping are the averages over responses weighted by diameter.
Result<SdofEstimate> circleFit(const FrfMatrix& frf, Eigen::Index reference, double bandLowHz, double bandHighHz);

}  // namespace mozzi::core::modal
