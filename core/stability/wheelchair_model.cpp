#include "core/stability/wheelchair_model.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>

namespace mozzi::core::stability {
namespace {

constexpr double kPi = 3.14159265358979323846;
const char* kWhere = "wheelchair model (thesis §7.2)";

// State vector: x, y, psi, u, v, r, deltaR, deltaL.
using State = std::array<double, 8>;

struct Forces {
  double slipR, slipL, fyR, fyL, mzR, mzL;
};

// Rear wheels: y_R = -w, y_L = +w; alpha_i = (v - b r)/(u - r y_i) (small angles).
Forces rearForces(const WheelchairParameters& p, double u, double v, double r) {
  const double w = p.rearHalfTrack, b = p.rearAxleBehindCoM;
  Forces f;
  f.slipR = (v - b * r) / (u + r * w);
  f.slipL = (v - b * r) / (u - r * w);
  f.fyR = -p.rearCorneringStiffness * f.slipR;
  f.fyL = -p.rearCorneringStiffness * f.slipL;
  f.mzR = p.rearAligningStiffness * f.slipR;
  f.mzL = p.rearAligningStiffness * f.slipL;
  return f;
}

// Caster follows with zero slip: d delta/dt, caster at y_c = -+w_f.
double casterRate(const WheelchairParameters& p, double delta, double yc, double u, double v, double r) {
  return (-std::sin(delta) * (u - r * yc) + std::cos(delta) * (v + r * p.casterAheadOfCoM)) / p.casterTrail - r;
}

State derivative(const WheelchairParameters& p, const Manoeuvre& m, double t, const State& s) {
  const double u = s[3], v = s[4], r = s[5];
  const Forces f = rearForces(p, u, v, r);
  const double Rw = p.rearWheelRadius, Js = p.rearWheelSpinInertia, w = p.rearHalfTrack;
  const double dT = m.differentialTorque ? m.differentialTorque(t) : 0.0;
  State d{};
  d[0] = u * std::cos(s[2]) - v * std::sin(s[2]);
  d[1] = u * std::sin(s[2]) + v * std::cos(s[2]);
  d[2] = r;
  if (m.speedHold) {
    d[3] = 0.0;  // T_R + T_L = -m v r R_w
  } else {
    const double sumT = m.commonTorque ? m.commonTorque(t) : 0.0;
    d[3] = (p.mass * v * r + sumT / Rw) / (p.mass + 2.0 * Js / (Rw * Rw));
  }
  d[4] = (f.fyR + f.fyL) / p.mass - u * r;
  d[5] = (w * dT / Rw - p.rearAxleBehindCoM * (f.fyR + f.fyL) + f.mzR + f.mzL) /
         (p.yawInertia + 2.0 * Js * w * w / (Rw * Rw));
  d[6] = casterRate(p, s[6], -p.casterHalfTrack, u, v, r);
  d[7] = casterRate(p, s[7], p.casterHalfTrack, u, v, r);
  return d;
}

WheelchairState toOutput(const WheelchairParameters& p, const Manoeuvre& m, double t, const State& s) {
  WheelchairState o;
  o.t = t;
  o.x = s[0], o.y = s[1], o.psi = s[2], o.u = s[3], o.v = s[4], o.r = s[5];
  o.deltaRight = s[6], o.deltaLeft = s[7];
  const Forces f = rearForces(p, s[3], s[4], s[5]);
  o.slipRight = f.slipR, o.slipLeft = f.slipL;
  const double dT = m.differentialTorque ? m.differentialTorque(t) : 0.0;
  const double sumT =
      m.speedHold ? -p.mass * s[4] * s[5] * p.rearWheelRadius : (m.commonTorque ? m.commonTorque(t) : 0.0);
  o.torqueRight = 0.5 * (sumT + dT);
  o.torqueLeft = 0.5 * (sumT - dT);
  return o;
}

// Steady caster angle: -sin(d) B + cos(d) A = e r, A = v + r a_f, B = u - r y_c,
// the trailing root near atan2(A, B).
double steadyCaster(const WheelchairParameters& p, double yc, double u, double v, double r) {
  const double A = v + r * p.casterAheadOfCoM, B = u - r * yc;
  double d = std::atan2(A, B);
  for (int i = 0; i < 50; ++i) {
    const double g = -std::sin(d) * B + std::cos(d) * A - p.casterTrail * r;
    const double dg = -std::cos(d) * B - std::sin(d) * A;
    const double step = g / dg;
    d -= step;
    if (std::abs(step) < 1e-15) break;
  }
  return d;
}

// A slalom frequency f [Hz] the simulation's output sampling can follow.
Result<void> checkSlalomFrequency(double f) {
  if (!std::isfinite(f) || f <= 0.0)
    return makeError(ErrorCode::InvalidArgument, "slalom frequency must be positive", kWhere);
  if (f > kMaxSlalomFrequencyHz) {
    return makeError(ErrorCode::InvalidArgument,
                     "slalom frequency " + std::to_string(f) + " Hz is above " + std::to_string(kMaxSlalomFrequencyHz) +
                         " Hz: the 10 ms output sampling would alias the torque input",
                     kWhere);
  }
  return {};
}

}  // namespace

Result<void> validate(const WheelchairParameters& p) {
  const std::pair<const char*, double> positive[] = {{"mass", p.mass},
                                                     {"yaw inertia", p.yawInertia},
                                                     {"rear half-track", p.rearHalfTrack},
                                                     {"caster half-track", p.casterHalfTrack},
                                                     {"caster trail", p.casterTrail},
                                                     {"rear wheel radius", p.rearWheelRadius},
                                                     {"rear cornering stiffness", p.rearCorneringStiffness},
                                                     {"caster cornering stiffness", p.casterCorneringStiffness}};
  for (const auto& [name, value] : positive)
    if (!std::isfinite(value) || value <= 0.0)
      return makeError(ErrorCode::InvalidArgument, std::string(name) + " must be positive", kWhere);
  const std::pair<const char*, double> finite[] = {{"rear axle position b", p.rearAxleBehindCoM},
                                                   {"caster position a_f", p.casterAheadOfCoM},
                                                   {"rear wheel spin inertia", p.rearWheelSpinInertia},
                                                   {"rear aligning stiffness", p.rearAligningStiffness},
                                                   {"caster aligning stiffness", p.casterAligningStiffness}};
  for (const auto& [name, value] : finite)
    if (!std::isfinite(value) || value < 0.0)
      return makeError(ErrorCode::InvalidArgument, std::string(name) + " must be finite and not negative", kWhere);
  if (std::abs(p.casterAligningStiffness - p.casterTrail * p.casterCorneringStiffness) <
      1e-9 * p.casterTrail * p.casterCorneringStiffness)
    return makeError(ErrorCode::InvalidArgument,
                     "caster equilibrium is degenerate: C_Mc = e C_c leaves the caster slip angle undetermined",
                     kWhere);
  return {};
}

namespace {

Result<void> checkSpeed(double u) {
  if (!std::isfinite(u) || u <= 0.0)
    return makeError(ErrorCode::InvalidArgument, "forward speed must be positive (a chair at rest has no slip angle)",
                     std::string(kWhere) + ", steady turning");
  return {};
}

Error innerWheelStopped() {
  return makeError(ErrorCode::NumericalFailure, "the inner rear wheel would roll backwards: turn too tight", kWhere);
}

// Checks and derived quantities shared by both steady-turn definitions.
Result<SteadyTurn> finishSteadyTurn(const WheelchairParameters& p, double u, double v, double r, double dT) {
  if (std::abs(r) * p.rearHalfTrack >= u) return innerWheelStopped();
  SteadyTurn s;
  s.u = u, s.v = v, s.r = r;
  s.differentialTorque = dT;
  const Forces f = rearForces(p, u, v, r);
  s.slipRight = f.slipR, s.slipLeft = f.slipL;
  if (std::max(std::abs(f.slipR), std::abs(f.slipL)) > 10.0 * kPi / 180.0) {
    std::ostringstream msg;
    msg << "rear slip angle " << std::max(std::abs(f.slipR), std::abs(f.slipL)) * 180 / kPi
        << " deg is outside the small-angle linear tyre of §7.2";
    return makeError(ErrorCode::NumericalFailure, msg.str(), kWhere);
  }
  s.radius = r != 0.0 ? std::hypot(u, v) / std::abs(r) : HUGE_VAL;
  s.deltaRight = steadyCaster(p, -p.casterHalfTrack, u, v, r);
  s.deltaLeft = steadyCaster(p, p.casterHalfTrack, u, v, r);
  s.commonTorque = -p.mass * v * r * p.rearWheelRadius;
  return s;
}

}  // namespace

Result<SteadyTurn> steadyTurn(const WheelchairParameters& p, double u, double dT) {
  MOZZI_TRY(validate(p));
  MOZZI_TRY(checkSpeed(u));
  if (!std::isfinite(dT)) return makeError(ErrorCode::InvalidArgument, "differential torque must be finite", kWhere);
  const double m = p.mass, b = p.rearAxleBehindCoM, w = p.rearHalfTrack, Rw = p.rearWheelRadius;
  const double Ca = p.rearCorneringStiffness, Cm = p.rearAligningStiffness;
  // Linear start (both wheels alpha = (v - b r)/u):
  // r = w dT/R_w / (m u (b + C_M/C_alpha)), v - b r = -m u^2 r/(2 C_alpha).
  double r = w * dT / Rw / (m * u * (b + Cm / Ca));
  double v = b * r - m * u * u * r / (2.0 * Ca);
  for (int it = 0; it < 100; ++it) {
    auto res = [&](double vv, double rr) {
      const Forces f = rearForces(p, u, vv, rr);
      return std::array<double, 2>{f.fyR + f.fyL - m * u * rr, w * dT / Rw - b * (f.fyR + f.fyL) + f.mzR + f.mzL};
    };
    const auto f0 = res(v, r);
    const double hv = 1e-7 * (std::abs(v) + 1e-3), hr = 1e-7 * (std::abs(r) + 1e-3);
    const auto fv = res(v + hv, r), fr = res(v, r + hr);
    const double a11 = (fv[0] - f0[0]) / hv, a21 = (fv[1] - f0[1]) / hv;
    const double a12 = (fr[0] - f0[0]) / hr, a22 = (fr[1] - f0[1]) / hr;
    const double det = a11 * a22 - a12 * a21;
    if (!std::isfinite(det) || det == 0.0)
      return makeError(ErrorCode::NumericalFailure, "steady-turning Jacobian is singular", kWhere);
    const double dv = (a22 * f0[0] - a12 * f0[1]) / det, dr = (-a21 * f0[0] + a11 * f0[1]) / det;
    v -= dv;
    r -= dr;
    if (std::abs(dv) < 1e-14 && std::abs(dr) < 1e-14) break;
    if (it == 99) return makeError(ErrorCode::NumericalFailure, "steady-turning solution did not converge", kWhere);
  }
  return finishSteadyTurn(p, u, v, r, dT);
}

Result<SteadyTurn> steadyTurnAtYawRate(const WheelchairParameters& p, double u, double r) {
  MOZZI_TRY(validate(p));
  MOZZI_TRY(checkSpeed(u));
  if (!std::isfinite(r)) return makeError(ErrorCode::InvalidArgument, "yaw rate must be finite", kWhere);
  const double w = p.rearHalfTrack, Ca = p.rearCorneringStiffness;
  if (std::abs(r) * w >= u) return innerWheelStopped();
  // Lateral balance -C_alpha (v - b r) (1/(u + r w) + 1/(u - r w)) = m u r.
  const double v = p.rearAxleBehindCoM * r - p.mass * r * (u * u - r * r * w * w) / (2.0 * Ca);
  const double dT = p.rearWheelRadius * p.mass * u * r * (p.rearAxleBehindCoM + p.rearAligningStiffness / Ca) / w;
  return finishSteadyTurn(p, u, v, r, dT);
}

Result<std::vector<WheelchairState>> simulate(const WheelchairParameters& p, const Manoeuvre& m) {
  MOZZI_TRY(validate(p));
  const std::string where = std::string(kWhere) + ", manoeuvre";
  if (!std::isfinite(m.speed) || m.speed <= 0.0)
    return makeError(ErrorCode::InvalidArgument, "initial forward speed must be positive", where);
  if (!(m.duration > 0.0) || !(m.timeStep > 0.0) || !(m.outputInterval > 0.0) || !std::isfinite(m.duration))
    return makeError(ErrorCode::InvalidArgument, "duration, time step and output interval must be positive", where);
  if (m.duration / std::min(m.timeStep, m.outputInterval) > 5e7)
    return makeError(ErrorCode::InvalidArgument, "too many steps: shorten the manoeuvre or enlarge the step", where);
  // Fastest tyre time constants: lateral m u/(2 C_alpha (1 + ...)), caster e/u.
  const double tauLat = p.mass * m.speed / (2.0 * p.rearCorneringStiffness);
  const double tauYaw = p.yawInertia * m.speed /
                        (2.0 * p.rearCorneringStiffness * (p.rearAxleBehindCoM * p.rearAxleBehindCoM + 1e-4) +
                         2.0 * p.rearAligningStiffness * p.rearAxleBehindCoM + 1e-12);
  const double tauCaster = p.casterTrail / m.speed;
  const double h0 = std::min({m.timeStep, 0.2 * tauLat, 0.2 * tauYaw, 0.2 * tauCaster});
  const int perOutput = std::max(1, static_cast<int>(std::ceil(m.outputInterval / h0)));
  const double h = m.outputInterval / perOutput;
  const long outputs = static_cast<long>(std::floor(m.duration / m.outputInterval + 1e-9));
  State s{};
  s[3] = m.speed;
  std::vector<WheelchairState> out;
  out.reserve(static_cast<std::size_t>(outputs) + 1);
  out.push_back(toOutput(p, m, 0.0, s));
  double t = 0.0;
  for (long k = 0; k < outputs; ++k) {
    for (int j = 0; j < perOutput; ++j) {  // classical RK4
      const State k1 = derivative(p, m, t, s);
      State y;
      for (int i = 0; i < 8; ++i) y[i] = s[i] + 0.5 * h * k1[i];
      const State k2 = derivative(p, m, t + 0.5 * h, y);
      for (int i = 0; i < 8; ++i) y[i] = s[i] + 0.5 * h * k2[i];
      const State k3 = derivative(p, m, t + 0.5 * h, y);
      for (int i = 0; i < 8; ++i) y[i] = s[i] + h * k3[i];
      const State k4 = derivative(p, m, t + h, y);
      for (int i = 0; i < 8; ++i) s[i] += h / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
      t += h;
    }
    for (double x : s)
      if (!std::isfinite(x))
        return makeError(ErrorCode::NumericalFailure, "state became non-finite",
                         where + " at t = " + std::to_string(t));
    if (s[3] <= 0.0 || std::abs(s[5]) * p.rearHalfTrack >= s[3])
      return makeError(ErrorCode::NumericalFailure, "forward speed of a rear wheel reached zero: slip angle undefined",
                       where + " at t = " + std::to_string(t));
    out.push_back(toOutput(p, m, t, s));
  }
  return out;
}

Manoeuvre slalomManoeuvre(double speed, double amplitude, double f, double duration) {
  Manoeuvre m;
  m.speed = speed;
  m.duration = duration;
  m.differentialTorque = [amplitude, f](double t) { return amplitude * std::cos(2.0 * kPi * f * t); };
  return m;
}

Manoeuvre steadyTurningManoeuvre(double speed, double torque, double rampTime, double duration) {
  Manoeuvre m;
  m.speed = speed;
  m.duration = duration;
  m.differentialTorque = [torque, rampTime](double t) {
    return rampTime > 0.0 && t < rampTime ? torque * t / rampTime : torque;
  };
  return m;
}

Result<SlalomSummary> summariseSlalom(const std::vector<WheelchairState>& h, double from, double f) {
  MOZZI_TRY(checkSlalomFrequency(f));
  SlalomSummary s;
  // The drift of y (a heading offset left by the start transient) is removed
  // as c0 + c1 t fitted together with the slalom's fundamental
  // a cos(wt) + b sin(wt): a straight line alone over a whole number of
  // cycles correlates with the sine and takes a share of it.
  // Whole cycles only, so that the slip means are not biased by a part cycle.
  const double cycles = h.empty() ? 0.0 : std::floor((h.back().t - from) * f + 1e-9);
  if (cycles < 1.0)
    return makeError(ErrorCode::InvalidArgument, "less than one slalom cycle after the start time", kWhere);
  const double to = from + cycles / f;
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < h.size(); ++i)
    if (h[i].t >= from && h[i].t < to - 1e-9) idx.push_back(i);
  if (idx.size() < 5) return makeError(ErrorCode::InvalidArgument, "fewer than 5 samples after the start time", kWhere);
  const double w = 2.0 * kPi * f;
  Eigen::MatrixXd X(static_cast<Eigen::Index>(idx.size()), 4);
  Eigen::VectorXd Y(X.rows());
  for (Eigen::Index k = 0; k < X.rows(); ++k) {
    const auto& x = h[idx[static_cast<std::size_t>(k)]];
    X.row(k) << 1.0, x.t, std::cos(w * x.t), std::sin(w * x.t);
    Y[k] = x.y;
  }
  const Eigen::Vector4d c = X.colPivHouseholderQr().solve(Y);
  const double c0 = c[0], c1 = c[1];
  double ymin = HUGE_VAL, ymax = -HUGE_VAL, rmin = HUGE_VAL, rmax = -HUGE_VAL, lmin = HUGE_VAL, lmax = -HUGE_VAL;
  double sr = 0, sl = 0;
  int n = 0;
  for (const std::size_t i : idx) {
    const auto& x = h[i];
    const double y = x.y - c0 - c1 * x.t;
    ymin = std::min(ymin, y), ymax = std::max(ymax, y);
    rmin = std::min(rmin, x.slipRight), rmax = std::max(rmax, x.slipRight);
    lmin = std::min(lmin, x.slipLeft), lmax = std::max(lmax, x.slipLeft);
    sr += x.slipRight, sl += x.slipLeft, ++n;
  }
  s.lateralAmplitude = 0.5 * (ymax - ymin);
  s.slipAmplitudeRight = 0.5 * (rmax - rmin);
  s.slipAmplitudeLeft = 0.5 * (lmax - lmin);
  s.slipMeanRight = sr / n;
  s.slipMeanLeft = sl / n;
  return s;
}

Result<SlalomRun> runSlalom(const WheelchairParameters& p, double speed, double torque, double f, double duration) {
  MOZZI_TRY(checkSlalomFrequency(f));
  if (!std::isfinite(duration) || duration > 3600.0)
    return makeError(ErrorCode::InvalidArgument, "slalom duration must be at most 3600 s", kWhere);
  if (!std::isfinite(duration) || f * duration < 3.0)
    return makeError(ErrorCode::InvalidArgument,
                     "the slalom needs at least 3 cycles (2 to settle, 1 to measure): raise the duration or frequency",
                     kWhere);
  SlalomRun run;
  MOZZI_TRY_ASSIGN(run.history, simulate(p, slalomManoeuvre(speed, torque, f, duration)));
  // after two cycles of start transient
  MOZZI_TRY_ASSIGN(run.summary, summariseSlalom(run.history, 2.0 / f, f));
  return run;
}

Result<std::vector<SensitivityCase>> stiffnessSensitivity(const WheelchairParameters& p, WheelchairStiffness which,
                                                          const std::vector<double>& factors, double speed,
                                                          double turnTorque, double slalomTorque, double f,
                                                          double duration) {
  std::vector<SensitivityCase> out;
  for (double k : factors) {
    if (!std::isfinite(k) || k <= 0.0)
      return makeError(ErrorCode::InvalidArgument, "stiffness factor must be positive", kWhere);
    WheelchairParameters q = p;
    if (which != WheelchairStiffness::Aligning) q.rearCorneringStiffness *= k;
    if (which != WheelchairStiffness::Cornering) q.rearAligningStiffness *= k;
    SensitivityCase c;
    c.factor = k;
    MOZZI_TRY_ASSIGN(c.steady, steadyTurn(q, speed, turnTorque));
    MOZZI_TRY_ASSIGN(const SlalomRun slalom, runSlalom(q, speed, slalomTorque, f, duration));
    c.slalom = slalom.summary;
    out.push_back(c);
  }
  return out;
}

}  // namespace mozzi::core::stability
