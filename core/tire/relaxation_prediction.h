#pragma once
// First-order prediction of the relaxation length from the ring modal model,
// the cornering stiffness and the contact patch (thesis §5.4, eq. 48 to 50,
// Fig. 43):
//   sigma = a m + C_bFalpha (1/C_y + r^2/C_xx + 1/C_res)          eq. 48
//   m = 1 - C_bFalpha tan(alpha) / (3 lambda F_z)                  eq. 49
//   1/C_res = 1/C_C + 1/C_S (+ further ring modes k >= 4)          eq. 50
// With the modal stiffnesses referred to the lowest point, 1/C_y = 1/C_0 and
// r^2/C_xx = 1/C_1 (ring_model.h).

#include <string>
#include <vector>

#include "core/common/result.h"
#include "core/tire/ring_model.h"

namespace mozzi::core::tire {

struct ContactPatchInputs {
  double halfLength = 0.0;                                  // a [m] (Table 17)
  double corneringStiffness = 0.0;                          // C_bFalpha [N/rad]
  double verticalLoad = 0.0;                                // F_z [N]
  double friction = 1.0;                                    // lambda
  double slipAngle = 1.5 * 3.14159265358979323846 / 180.0;  // alpha [rad], §5.4: 1.5 deg
};

// m of eq. 49. Error when m <= 0 (the whole patch slides at this alpha) or an
// input is out of range.
Result<double> adhesionFraction(const ContactPatchInputs& in);

// Per-term contributions of Fig. 43, all [m].
struct RelaxationPrediction {
  double adhesionFraction = 0.0;                                       // m
  double contactPatch = 0.0;                                           // sigma_c = a m
  double camber = 0.0;                                                 // C/C_1 = C r^2/C_xx
  double lateral = 0.0;                                                // C/C_0
  double cShaped = 0.0;                                                // C/C_2
  double sShaped = 0.0;                                                // C/C_3
  double higherModes = 0.0;                                            // C sum_{k>=4} 1/C_k
  double residual() const { return cShaped + sShaped + higherModes; }  // C/C_res
  double carcass() const { return camber + lateral + residual(); }
  double total() const { return contactPatch + carcass(); }  // eq. 48
};

// Needs modes k = 0 and k = 1 (eq. 48 has no meaning without them); k = 2, 3
// and higher enter the residual when present.
Result<RelaxationPrediction> predictRelaxationLength(const RingModel& ring, const ContactPatchInputs& in);

// One inflation pressure: its contact patch, cornering stiffness and ring model.
struct PressureCase {
  double pressure = 0.0;  // [Pa]
  ContactPatchInputs contact;
  RingModel ring;
};
struct PressurePrediction {
  double pressure = 0.0;
  RelaxationPrediction prediction;
};
// Every pressure in order; the first failing case gives the error (with its pressure).
Result<std::vector<PressurePrediction>> predictOverPressures(const std::vector<PressureCase>& cases);

}  // namespace mozzi::core::tire
