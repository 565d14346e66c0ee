#pragma once
// Wheelchair on a horizontal road (thesis §7.2-§7.4): five rigid bodies (the
// chair with its user, two rear wheels, two castering front wheels), five
// degrees of freedom (longitudinal and lateral motion of the chair's centre of
// mass, its yaw psi, the caster angles delta_fr and delta_fl), with the
// assumptions listed in §7.2:
// - the user is rigid with the chair and applies a propulsive torque to each
//   rear wheel;
// - wheels roll without longitudinal slip and slip laterally; slip angles are
//   small: alpha = v_lateral / v_longitudinal (wheel axes), F_y = -C_alpha alpha,
//   M_z = C_M alpha (aligning: turns the wheel toward its velocity);
// - no longitudinal or lateral load transfer;
// - caster wheels massless and without inertia: their yaw equilibrium about
//   the caster pivot (C_Mc - e C_c) alpha_c = 0 gives alpha_c = 0, so the
//   casters follow (a first-order equation for delta) and carry no side force;
// - no tyre transients (relaxation length) at wheelchair speeds.
// Equations in the chair axes x_m (forward), y_m (left), velocity (u, v) of
// the centre of mass G, yaw rate r; rear wheels at (-b, -+w) (right, left),
// caster pivots at (a_f, -+w_f), caster trail e, wheel radius R_w, spin
// inertia J_s per rear wheel, F_x,i = (T_i - J_s d(omega_i)/dt)/R_w with
// omega_i = (u - r y_i)/R_w:
//   (m + 2 J_s/R_w^2) du/dt = m v r + (T_R + T_L)/R_w
//   m (dv/dt + u r)          = sum F_y,i
//   (I_z + 2 J_s w^2/R_w^2) dr/dt = w (T_R - T_L)/R_w - b sum F_y,i + sum M_z,i
//   d delta_i/dt = [-sin delta_i (u - r y_c) + cos delta_i (v + r a_f)]/e - r
// "The forward speed u is constant" (§7.3): with speedHold the common torque
// T_R + T_L = -m v r R_w keeps du/dt = 0 and only the differential torque is given.

#include <functional>
#include <vector>

#include "core/common/result.h"

namespace mozzi::core::stability {

struct WheelchairParameters {
  // Assumed (the thesis prints no chair data): 110 kg with 71% on the rear
  // axle gives 384 N per rear wheel, the 400 N reference load of §7.1.
  double mass = 110.0;                       // chair + user + rear wheels [kg]
  double yawInertia = 7.0;                   // about G, vertical [kg m^2]
  double rearAxleBehindCoM = 0.13;           // b [m]
  double casterAheadOfCoM = 0.32;            // a_f [m] (wheelbase 0.45 m)
  double rearHalfTrack = 0.28;               // w [m]
  double casterHalfTrack = 0.20;             // w_f [m]
  double casterTrail = 0.05;                 // e [m]
  double rearWheelRadius = 0.305;            // R_w [m], 24 inch
  double rearWheelSpinInertia = 0.10;        // J_s per wheel [kg m^2]
  double rearCorneringStiffness = 4000.0;    // C_alpha per rear tyre [N/rad] (10 F_z/rad at 400 N)
  double rearAligningStiffness = 30.0;       // C_M per rear tyre [N m/rad] (7.5 mm pneumatic trail)
  double casterCorneringStiffness = 1500.0;  // C_c [N/rad], only for the caster equilibrium check
  double casterAligningStiffness = 5.0;      // C_Mc [N m/rad]
};

struct WheelchairState {
  double t = 0.0;
  double x = 0.0, y = 0.0, psi = 0.0;          // G in the road frame [m], yaw [rad]
  double u = 0.0, v = 0.0, r = 0.0;            // chair-axis velocity of G [m/s], yaw rate [rad/s]
  double deltaRight = 0.0, deltaLeft = 0.0;    // caster angles [rad], positive to the left
  double slipRight = 0.0, slipLeft = 0.0;      // rear-wheel slip angles alpha_i [rad]
  double torqueRight = 0.0, torqueLeft = 0.0;  // propulsive torques [N m]
};

struct SteadyTurn {
  double u = 0.0, v = 0.0, r = 0.0;  // [m/s], [rad/s]
  double radius = 0.0;               // of G's path: sqrt(u^2 + v^2)/|r| [m]
  double slipRight = 0.0, slipLeft = 0.0;
  double deltaRight = 0.0, deltaLeft = 0.0;
  double commonTorque = 0.0;        // T_R + T_L needed to hold u [N m]
  double differentialTorque = 0.0;  // T_R - T_L: the input, or what a prescribed path needs [N m]
};

// Errors for every parameter out of range (mass, inertias, lengths, stiffness
// not positive; a degenerate caster with C_Mc = e C_c).
Result<void> validate(const WheelchairParameters& p);

// Steady turn at forward speed u [m/s] with differential torque
// T_R - T_L [N m] (positive turns left). Newton on the force and moment
// balance for (v, r), then the caster angles. Both wheels share v - b r, so
// the balance has the closed form r = w dT/R_w / (m u (b + C_M/C_alpha))
// (exact in this model, used as the start and checked by the tests).
// Errors: u <= 0 (a wheelchair at rest has no slip angle), no convergence,
// a slip angle above 10 deg (outside the linear tyre assumption).
Result<SteadyTurn> steadyTurn(const WheelchairParameters& p, double speed, double differentialTorque);

// Steady turn on a prescribed path: forward speed u and yaw rate r given, the
// lateral velocity v and the differential torque that hold it returned. With
// (u, r) fixed the lateral force sum F_y = m u r is fixed, both rear wheels
// share v - b r, and the slip angles are exactly F_y/C_alpha-proportional:
//   v - b r = -m r (u^2 - r^2 w^2)/(2 C_alpha),   alpha_R,L = (v - b r)/(u +- r w),
//   T_R - T_L = R_w m u r (b + C_M/C_alpha)/w.
// Errors as steadyTurn, and r w >= u (inner wheel stopped).
Result<SteadyTurn> steadyTurnAtYawRate(const WheelchairParameters& p, double speed, double yawRate);

struct Manoeuvre {
  double speed = 1.11;                               // u at t = 0 [m/s] (4 km/h, §7.1 disc speed)
  std::function<double(double)> differentialTorque;  // T_R - T_L [N m] against t [s]
  std::function<double(double)> commonTorque;        // T_R + T_L, used only without speedHold
  bool speedHold = true;
  double duration = 10.0;        // [s]
  double timeStep = 1e-3;        // RK4 step upper bound [s] (reduced to a fifth of the fastest tyre time constant)
  double outputInterval = 0.01;  // [s]
};

// Time history from straight running (v = r = delta = 0). Errors: bad
// parameters, speed not positive or dropping to zero, a non-finite state.
Result<std::vector<WheelchairState>> simulate(const WheelchairParameters& p, const Manoeuvre& m);

// Slalom: dT(t) = amplitude cos(2 pi f t): yaw rate ~ cos, heading ~ sin with
// zero mean, so the path weaves about the initial direction.
Manoeuvre slalomManoeuvre(double speed, double torqueAmplitude, double frequencyHz, double duration);
// Steady turning manoeuvre: dT ramps to `torque` over `rampTime` then holds.
Manoeuvre steadyTurningManoeuvre(double speed, double torque, double rampTime, double duration);

struct SlalomSummary {
  double lateralAmplitude = 0.0;                             // half peak-to-peak of y, linear drift removed [m]
  double slipAmplitudeRight = 0.0, slipAmplitudeLeft = 0.0;  // half peak-to-peak [rad]
  double slipMeanRight = 0.0, slipMeanLeft = 0.0;            // [rad]
};
// Over the whole cycles from fromTime on; frequencyHz is the slalom's (the lateral
// drift is fitted together with its fundamental). Errors: frequency not
// positive, less than one cycle or fewer than 5 samples.
Result<SlalomSummary> summariseSlalom(const std::vector<WheelchairState>& history, double fromTime, double frequencyHz);

// The slalom manoeuvre simulated and summarised after two cycles of start
// transient. Errors: frequency not positive or fewer than 3 cycles in the
// duration (2 to settle, 1 to measure), and those of simulate.
// Highest slalom frequency: the history is sampled every 10 ms
// (Manoeuvre::outputInterval) and the summary fits the input's fundamental, so
// a cycle needs at least 20 samples; above that the torque input is aliased
// by the sampling (and, above 50 Hz, by the 1 ms integration step) and the
// amplitudes are meaningless. A manual slalom is below 1 Hz.
inline constexpr double kMaxSlalomFrequencyHz = 5.0;

struct SlalomRun {
  std::vector<WheelchairState> history;
  SlalomSummary summary;
};
Result<SlalomRun> runSlalom(const WheelchairParameters& p, double speed, double torqueAmplitude, double frequencyHz,
                            double duration);

// §7.3/§7.4: the rear cornering or aligning stiffness scaled by each factor
// (thesis: 0.5, 1, 2), the other one held, at the same speed and torque input
// (the thesis's study). `Tyre` scales both together (pneumatic trail
// C_M/C_alpha held): not a thesis study, the reference case in which slip
// angles scale exactly as 1/C_alpha (docs/validation/tire.md).
struct SensitivityCase {
  double factor = 1.0;
  SteadyTurn steady;
  SlalomSummary slalom;
};
enum class WheelchairStiffness { Cornering, Aligning, Tyre };
Result<std::vector<SensitivityCase>> stiffnessSensitivity(const WheelchairParameters& p, WheelchairStiffness which,
                                                          const std::vector<double>& factors, double speed,
                                                          double turnTorque, double slalomTorque,
                                                          double slalomFrequencyHz, double slalomDuration);

}  // namespace mozzi::core::stability
