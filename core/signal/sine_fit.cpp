#include "core/signal/sine_fit.h"

#include <ceres/ceres.h>

#include <Eigen/QR>
#include <cmath>
#include <string>

#include "core/signal/fft.h"

namespace mozzi::core::signal {

namespace {
constexpr double kPi = 3.14159265358979323846;

Result<void> checkInput(const VectorRef& y, double fs, const char* where) {
  if (!std::isfinite(fs) || fs <= 0.0) {
    return makeError(ErrorCode::InvalidArgument, "sample rate must be finite and positive", where);
  }
  if (y.size() < 5) {
    return makeError(ErrorCode::InvalidArgument,
                     "need at least 5 samples to fit a sine with uncertainties, got " + std::to_string(y.size()),
                     where);
  }
  for (Eigen::Index i = 0; i < y.size(); ++i) {
    if (!std::isfinite(y[i])) {
      return makeError(ErrorCode::InvalidArgument, "sample is NaN or infinite",
                       std::string(where) + ", sample " + std::to_string(i));
    }
  }
  return {};
}

// Fills A, phi and their standard errors from (a, b) and their 2x2 covariance.
void polarFromCartesian(double a, double b, const Eigen::Matrix2d& cov, SineFit& fit) {
  const double amp = std::hypot(a, b);
  fit.amplitude = amp;
  fit.phaseRad = wrapPhase(std::atan2(-b, a));  // A cos(wt + phi) = A cos(phi) cos(wt) - A sin(phi) sin(wt)
  if (amp > 0.0) {
    // dA/d(a,b) = (a, b)/A;  dphi/d(a,b) = (b, -a)/A^2
    const Eigen::Vector2d gA(a / amp, b / amp);
    const Eigen::Vector2d gP(b / (amp * amp), -a / (amp * amp));
    fit.amplitudeStdError = std::sqrt(std::max(0.0, gA.dot(cov * gA)));
    fit.phaseStdError = std::sqrt(std::max(0.0, gP.dot(cov * gP)));
  }
}

// Residual of one sample for Ceres: r = y - (c + a cos(w t) + b sin(w t)),
// parameters p = (a, b, c, w), analytic Jacobian.
class SineResidual final : public ceres::SizedCostFunction<1, 4> {
 public:
  SineResidual(double t, double y) : t_(t), y_(y) {}
  bool Evaluate(double const* const* p, double* r, double** jac) const override {
    const double a = p[0][0], b = p[0][1], c = p[0][2], w = p[0][3];
    const double cs = std::cos(w * t_), sn = std::sin(w * t_);
    r[0] = y_ - (c + a * cs + b * sn);
    if (jac != nullptr && jac[0] != nullptr) {
      jac[0][0] = -cs;
      jac[0][1] = -sn;
      jac[0][2] = -1.0;
      jac[0][3] = -(-a * t_ * sn + b * t_ * cs);
    }
    return true;
  }

 private:
  double t_, y_;
};
// The residual statistics of a least-squares fit of `parameters` values to
// n samples with residual sum of squares rss: RMS, sigma = sqrt(rss / (n - p))
// and the 97.5% Student-t quantile for n - p degrees of freedom.
SineFit residualStatistics(double frequencyHz, double offset, Eigen::Index n, int parameters, double rss) {
  SineFit fit;
  fit.frequencyHz = frequencyHz;
  fit.offset = offset;
  fit.sampleCount = n;
  fit.degreesOfFreedom = static_cast<int>(n - parameters);
  fit.residualRms = std::sqrt(rss / static_cast<double>(n));
  fit.sigma = std::sqrt(rss / static_cast<double>(n - parameters));
  fit.tQuantile95 = studentT975(fit.degreesOfFreedom);
  return fit;
}

}  // namespace

double wrapPhase(double phi) {
  double w = std::remainder(phi, 2.0 * kPi);  // in [-pi, pi]
  if (w <= -kPi) w += 2.0 * kPi;
  return w;
}

double studentT975(int dof) {
  if (dof < 1) return 0.0;
  const double z = 1.959963984540054;
  const double v = static_cast<double>(dof);
  const double z3 = z * z * z, z5 = z3 * z * z, z7 = z5 * z * z, z9 = z7 * z * z;
  return z + (z3 + z) / (4 * v) + (5 * z5 + 16 * z3 + 3 * z) / (96 * v * v) +
         (3 * z7 + 19 * z5 + 17 * z3 - 15 * z) / (384 * v * v * v) +
         (79 * z9 + 776 * z7 + 1482 * z5 - 1920 * z3 - 945 * z) / (92160 * v * v * v * v);
}

Result<SineFit> fitSineKnownFrequency(const VectorRef& y, double fs, double frequencyHz, double t0) {
  const char* where = "sine fit (known frequency)";
  MOZZI_TRY(checkInput(y, fs, where));
  if (!std::isfinite(frequencyHz) || frequencyHz <= 0.0 || frequencyHz >= 0.5 * fs) {
    return makeError(
        ErrorCode::InvalidArgument,
        "frequency " + std::to_string(frequencyHz) + " Hz must lie in (0, fs/2 = " + std::to_string(0.5 * fs) + ") Hz",
        where);
  }
  const Eigen::Index n = y.size();
  const double w = 2.0 * kPi * frequencyHz;
  Matrix x(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double t = t0 + static_cast<double>(i) / fs;
    x(i, 0) = std::cos(w * t);
    x(i, 1) = std::sin(w * t);
    x(i, 2) = 1.0;
  }
  Eigen::ColPivHouseholderQR<Matrix> qr(x);
  qr.setThreshold(1e-10);
  if (qr.rank() < 3) {
    return makeError(ErrorCode::NumericalFailure,
                     "cos, sin and offset columns are not independent at this frequency and record length", where);
  }
  const Eigen::Vector3d beta = qr.solve(y);
  const Vector res = y - x * beta;
  SineFit fit = residualStatistics(frequencyHz, beta[2], n, 3, res.squaredNorm());
  // Cov(beta) = s^2 (X'X)^-1
  const Eigen::Matrix3d cov = fit.sigma * fit.sigma * (x.transpose() * x).inverse();
  fit.offsetStdError = std::sqrt(cov(2, 2));
  polarFromCartesian(beta[0], beta[1], cov.topLeftCorner<2, 2>(), fit);
  return fit;
}

Result<SineFit> fitSine(const VectorRef& y, double fs, std::optional<double> guessHz, double t0) {
  const char* where = "sine fit (unknown frequency)";
  MOZZI_TRY(checkInput(y, fs, where));
  const Eigen::Index n = y.size();
  double f0 = 0.0;
  if (guessHz) {
    f0 = *guessHz;
  } else {
    // FFT peak of the mean-removed record zero-padded 4x, parabolic interpolation
    // of the magnitude over the three lines around the peak.
    const Eigen::Index np = 4 * n;
    Vector padded = Vector::Zero(np);
    padded.head(n) = y.array() - y.mean();
    MOZZI_TRY_ASSIGN(auto fft, RealFft::forLength(np));
    MOZZI_TRY_ASSIGN(auto spec, fft->transform(padded));
    const Vector mag = spec.cwiseAbs();
    Eigen::Index k = 1;
    for (Eigen::Index j = 1; j < mag.size() - 1; ++j) {
      if (mag[j] > mag[k]) k = j;
    }
    double delta = 0.0;
    if (k > 0 && k + 1 < mag.size()) {
      const double a = mag[k - 1], b = mag[k], c = mag[k + 1];
      const double den = a - 2 * b + c;
      if (den != 0.0) delta = 0.5 * (a - c) / den;
    }
    f0 = (static_cast<double>(k) + delta) * fs / static_cast<double>(np);
  }
  if (!std::isfinite(f0) || f0 <= 0.0 || f0 >= 0.5 * fs) {
    return makeError(ErrorCode::InvalidArgument, "starting frequency must lie in (0, fs/2)", where);
  }
  // linear start at f0, then all four parameters together
  MOZZI_TRY_ASSIGN(auto start, fitSineKnownFrequency(y, fs, f0, t0));
  double p[4];
  {
    const double A = start.amplitude, ph = start.phaseRad;
    p[0] = A * std::cos(ph);
    p[1] = -A * std::sin(ph);
    p[2] = start.offset;
    p[3] = 2.0 * kPi * f0;
  }
  ceres::Problem problem;
  for (Eigen::Index i = 0; i < n; ++i) {
    problem.AddResidualBlock(new SineResidual(t0 + static_cast<double>(i) / fs, y[i]), nullptr, p);
  }
  ceres::Solver::Options opts;
  opts.linear_solver_type = ceres::DENSE_QR;
  opts.max_num_iterations = 200;
  opts.function_tolerance = 1e-16;
  opts.gradient_tolerance = 1e-16;
  opts.parameter_tolerance = 1e-15;
  opts.logging_type = ceres::SILENT;
  opts.minimizer_progress_to_stdout = false;
  ceres::Solver::Summary summary;
  ceres::Solve(opts, &problem, &summary);
  if (!summary.IsSolutionUsable() || !std::isfinite(p[3])) {
    return makeError(ErrorCode::NumericalFailure, "sine fit did not converge: " + summary.message, where);
  }
  const double w = std::abs(p[3]);
  if (p[3] < 0.0) p[1] = -p[1];  // cos is even, sin odd: (a, b, -w) == (a, -b, w)
  if (w <= 0.0 || w >= kPi * fs) {
    return makeError(ErrorCode::NumericalFailure, "fitted frequency left (0, fs/2)", where);
  }
  Matrix j(n, 4);
  Vector res(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double t = t0 + static_cast<double>(i) / fs;
    const double cs = std::cos(w * t), sn = std::sin(w * t);
    j(i, 0) = cs;
    j(i, 1) = sn;
    j(i, 2) = 1.0;
    j(i, 3) = -p[0] * t * sn + p[1] * t * cs;
    res[i] = y[i] - (p[2] + p[0] * cs + p[1] * sn);
  }
  const Eigen::Matrix4d jtj = j.transpose() * j;
  Eigen::FullPivLU<Eigen::Matrix4d> lu(jtj);
  if (!lu.isInvertible()) {
    return makeError(ErrorCode::NumericalFailure, "fit is singular (no sine in the record?)", where);
  }
  SineFit fit = residualStatistics(w / (2.0 * kPi), p[2], n, 4, res.squaredNorm());
  const Eigen::Matrix4d cov = fit.sigma * fit.sigma * lu.inverse();
  fit.offsetStdError = std::sqrt(std::max(0.0, cov(2, 2)));
  fit.frequencyStdError = std::sqrt(std::max(0.0, cov(3, 3))) / (2.0 * kPi);
  polarFromCartesian(p[0], p[1], cov.topLeftCorner<2, 2>(), fit);
  return fit;
}

PhaseDifference phaseDifference(const SineFit& a, const SineFit& b) {
  return PhaseDifference{wrapPhase(a.phaseRad - b.phaseRad), std::hypot(a.phaseStdError, b.phaseStdError)};
}

double displacementPhaseFromVelocity(double velocityPhaseRad) {
  return wrapPhase(velocityPhaseRad - 0.5 * kPi);
}

}  // namespace mozzi::core::signal
