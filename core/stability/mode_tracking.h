#pragma once
// Eigenvalues against speed with modes tracked by eigenvector continuity, named
// (capsize, weave, wobble, castering, fork bending, fork torsion) and their
// critical speeds (real part crossing zero) refined by Brent's method.
// Thesis §4.2 (Figure 33), §6.6 (Figures 51, 52); Meijaard et al. (2007) §6.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/common/eigen_types.h"
#include "core/common/result.h"
#include "core/stability/bicycle_model.h"

namespace mozzi::core::stability {

enum class VehicleKind { Bicycle, Motorcycle };

// What a sweep needs from a model: its state matrix at speed v and which state
// rows describe the motion, for the eigenvector comparison and the naming.
struct StabilitySystem {
  std::function<Result<Matrix>(double v)> stateMatrix;
  std::vector<std::string> shapeNames;  // "roll", "steer", "bend", "torsion", "yaw", "lateral"
  std::vector<int> shapeRows;           // state row of each shape entry
  std::vector<bool> shapeIsRate;        // the row holds a rate: amplitude = row / lambda
  VehicleKind kind = VehicleKind::Bicycle;
};

struct Root {
  Complex lambda;       // eigenvalue [1/s]; one per conjugate pair (Im >= 0)
  ComplexVector shape;  // amplitudes over shapeNames, unit norm
  std::string name;     // mode name after tracking
  int track = -1;       // index of the mode track
};

struct SpeedPoint {
  double v = 0.0;  // [m/s]
  std::vector<Root> roots;
};

struct ModeEvent {
  std::string mode;
  double v = 0.0;          // [m/s]
  std::string kind;        // "stabilises" or "destabilises" (real part crosses zero), "pair born", "pair splits"
  double lambda = 0.0;     // eigenvalue at the event (0 for a crossing; the double real root for births/splits)
  double frequency = 0.0;  // imaginary part at a crossing [rad/s]
};

struct StabilitySweep {
  std::vector<SpeedPoint> points;
  std::vector<ModeEvent> events;  // sorted by speed
  // First speed where the named mode's real part crosses zero, if any.
  std::optional<double> criticalSpeed(const std::string& mode) const;
  // First event of a kind for a mode, if any.
  std::optional<ModeEvent> firstEvent(const std::string& mode, const std::string& kind) const;
};

// The bicycle model of eq. 65 as a system: shape = [phi, delta(, beta|gamma)].
StabilitySystem bicycleSystem(const BicycleModel& model);

// speeds must be strictly increasing and finite. Modes are tracked on a grid
// that adds speeds between the requested ones so no step exceeds
// maxTrackingStep [m/s]; points holds the requested speeds only.
Result<StabilitySweep> sweepSpeeds(const StabilitySystem& system, const std::vector<double>& speeds,
                                   double maxTrackingStep = 0.25);

// A:B:STEP grid (inclusive of B within STEP/1e6); errors name the part.
Result<std::vector<double>> speedGrid(double from, double to, double step);

// Eigenvalues, eigenvectors, roots with Im >= 0 and their shapes at one speed.
Result<SpeedPoint> solveAtSpeed(const StabilitySystem& system, double v);

}  // namespace mozzi::core::stability
