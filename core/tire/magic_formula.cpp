#include "core/tire/magic_formula.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>

#include "core/common/ceres_logging.h"

namespace mozzi::core::tire {
namespace {

constexpr double kPi = 3.14159265358979323846;

enum L {
  pCy1,
  pDy1,
  pDy2,
  pDy3,
  pEy1,
  pEy2,
  pEy3,
  pEy4,
  pKy1,
  pKy2,
  pKy3,
  pHy1,
  pHy2,
  pHy3,
  pVy1,
  pVy2,
  pVy3,
  pVy4,
  ppy1,
  ppy2,
  ppy3,
  ppy4
};
enum A {
  qBz1,
  qBz2,
  qBz3,
  qBz4,
  qBz5,
  qBz9,
  qBz10,
  qCz1,
  qDz1,
  qDz2,
  qDz3,
  qDz4,
  qDz6,
  qDz7,
  qDz8,
  qDz9,
  qEz1,
  qEz2,
  qEz3,
  qEz4,
  qEz5,
  qHz1,
  qHz2,
  qHz3,
  qHz4,
  ppz1,
  ppz2
};

struct Condition {
  double alpha, gamma, load, pressure;
};

// Intermediate lateral quantities, needed by M_z as well.
template <class T>
struct LateralParts {
  T fy, svy, shy, kya, by, cy;
};

template <class T>
LateralParts<T> lateral(const T* p, const MfConstants& c, const Condition& x) {
  using std::atan;
  using std::sin;
  const double dfz = (x.load - c.nominalLoad) / c.nominalLoad;
  const double dpi = (x.pressure - c.nominalPressure) / c.nominalPressure;
  const double g = x.gamma;
  LateralParts<T> o;
  o.shy = p[pHy1] + p[pHy2] * dfz + p[pHy3] * g;
  o.svy = x.load * (p[pVy1] + p[pVy2] * dfz + (p[pVy3] + p[pVy4] * dfz) * g);
  const T ay = T(x.alpha) + o.shy;
  o.cy = p[pCy1];
  const T mu = (p[pDy1] + p[pDy2] * dfz) * (1.0 + p[ppy3] * dpi + p[ppy4] * dpi * dpi) * (1.0 - p[pDy3] * g * g);
  const T dy = mu * x.load;
  const double sgn = ay < T(0.0) ? -1.0 : 1.0;
  const T ey = (p[pEy1] + p[pEy2] * dfz) * (1.0 - (p[pEy3] + p[pEy4] * g) * sgn);
  o.kya = p[pKy1] * c.nominalLoad * (1.0 + p[ppy1] * dpi) *
          sin(2.0 * atan(x.load / (p[pKy2] * c.nominalLoad * (1.0 + p[ppy2] * dpi)))) * (1.0 - p[pKy3] * std::abs(g));
  o.by = o.kya / (o.cy * dy);
  const T bx = o.by * ay;
  o.fy = dy * sin(o.cy * atan(bx - ey * (bx - atan(bx)))) + o.svy;
  return o;
}

template <class T>
T aligning(const T* q, const LateralParts<double>& lat, const MfConstants& c, const Condition& x) {
  using std::atan;
  using std::cos;
  const double dfz = (x.load - c.nominalLoad) / c.nominalLoad;
  const double dpi = (x.pressure - c.nominalPressure) / c.nominalPressure;
  const double g = x.gamma, ag = std::abs(g);
  const T sht = q[qHz1] + q[qHz2] * dfz + (q[qHz3] + q[qHz4] * dfz) * g;
  const T at = T(x.alpha) + sht;
  const T bt = (q[qBz1] + q[qBz2] * dfz + q[qBz3] * dfz * dfz) * (1.0 + q[qBz4] * g + q[qBz5] * ag);
  const T ct = q[qCz1];
  const T dt = x.load * (c.unloadedRadius / c.nominalLoad) * (q[qDz1] + q[qDz2] * dfz) * (1.0 + q[ppz1] * dpi) *
               (1.0 + q[qDz3] * g + q[qDz4] * g * g);
  const T et = (q[qEz1] + q[qEz2] * dfz + q[qEz3] * dfz * dfz) *
               (1.0 + (q[qEz4] + q[qEz5] * g) * (2.0 / kPi) * atan(bt * ct * at));
  const T btat = bt * at;
  const T t = dt * cos(ct * atan(btat - et * (btat - atan(btat)))) * std::cos(x.alpha);
  const double ar = x.alpha + lat.shy + lat.svy / lat.kya;
  const T br = q[qBz9] + q[qBz10] * lat.by * lat.cy;
  const T dr =
      x.load * c.unloadedRadius * (q[qDz6] + q[qDz7] * dfz + (q[qDz8] + q[qDz9] * dfz) * (1.0 + q[ppz2] * dpi) * g);
  const T mzr = dr * cos(atan(br * ar)) * std::cos(x.alpha);
  return -t * (lat.fy - lat.svy) + mzr;
}

struct LateralResidual {
  MfConstants c;
  Condition x;
  double measured;
  template <class T>
  bool operator()(const T* p, T* r) const {
    r[0] = lateral<T>(p, c, x).fy - measured;
    return true;
  }
};

struct AligningResidual {
  MfConstants c;
  Condition x;
  LateralParts<double> lat;
  double measured;
  template <class T>
  bool operator()(const T* q, T* r) const {
    r[0] = aligning<T>(q, lat, c, x) - measured;
    return true;
  }
};

struct DataSpread {
  int pressures = 0, loads = 0, cambers = 0;
  bool slipTwoSided = false, camberTwoSided = false;
};

int distinct(std::vector<double> v, double tol) {
  std::sort(v.begin(), v.end());
  int n = 0;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (i == 0 || v[i] - v[i - 1] > tol) ++n;
  return n;
}

DataSpread spread(const std::vector<SteadyStatePoint>& d) {
  std::vector<double> p, l, g;
  DataSpread s;
  bool slipNeg = false, slipPos = false, gNeg = false, gPos = false;
  for (const auto& x : d) {
    p.push_back(x.pressure);
    l.push_back(x.load);
    g.push_back(x.camber);
    slipNeg |= x.slip < -1e-6;
    slipPos |= x.slip > 1e-6;
    gNeg |= x.camber < -1e-6;
    gPos |= x.camber > 1e-6;
  }
  s.pressures = distinct(p, 1.0);  // 1 Pa
  s.loads = distinct(l, 1e-3);     // 1 mN
  s.cambers = distinct(g, 1e-6);   // 1 urad
  s.slipTwoSided = slipNeg && slipPos;
  s.camberTwoSided = gNeg && gPos;
  return s;
}

// The spread of a fit's data, once the constants are positive and every point
// is finite with positive load and pressure.
Result<DataSpread> checkedSpread(const std::vector<SteadyStatePoint>& d, const MfConstants& c, const char* where) {
  if (c.nominalLoad <= 0 || c.nominalPressure <= 0 || c.unloadedRadius <= 0)
    return makeError(ErrorCode::InvalidArgument, "nominal load, pressure and radius must be positive", where);
  for (std::size_t i = 0; i < d.size(); ++i) {
    const auto& x = d[i];
    const std::string at = std::string(where) + ", point " + std::to_string(i + 1);
    if (!std::isfinite(x.slip) || !std::isfinite(x.camber) || !std::isfinite(x.force) || !std::isfinite(x.torque))
      return makeError(ErrorCode::InvalidArgument, "angle, force or torque is NaN or infinite", at);
    if (!std::isfinite(x.load) || x.load <= 0.0)
      return makeError(ErrorCode::InvalidArgument, "vertical load must be positive", at);
    if (!std::isfinite(x.pressure) || x.pressure <= 0.0)
      return makeError(ErrorCode::InvalidArgument, "inflation pressure must be positive", at);
  }
  return spread(d);
}

template <std::size_t N>
Result<std::array<bool, N>> freeMask(const std::array<std::string, N>& names, const std::set<std::string>& fixed,
                                     const std::set<std::string>& autoHeld, std::vector<std::string>& held,
                                     const char* where) {
  std::array<bool, N> mask{};
  for (const auto& f : fixed)
    if (std::find(names.begin(), names.end(), f) == names.end())
      return makeError(ErrorCode::InvalidArgument, "unknown Magic Formula parameter '" + f + "'", where);
  for (std::size_t i = 0; i < N; ++i) {
    mask[i] = !fixed.count(names[i]) && !autoHeld.count(names[i]);
    if (!fixed.count(names[i]) && autoHeld.count(names[i])) held.push_back(names[i]);
  }
  return mask;
}

// Runs LM on `problem` over the block `x` with the mask, fills value/stdError.
template <std::size_t N>
Result<MfFit<N>> solve(ceres::Problem& problem, std::array<double, N>& x, const std::array<bool, N>& mask, int n,
                       int maxIterations, const char* where) {
  MfFit<N> fit;
  fit.free = mask;
  std::vector<int> constant;
  for (std::size_t i = 0; i < N; ++i)
    if (!mask[i]) constant.push_back(static_cast<int>(i));
  const int nFree = static_cast<int>(N) - static_cast<int>(constant.size());
  if (nFree == 0) return makeError(ErrorCode::InvalidArgument, "every parameter is held: nothing to fit", where);
  if (n <= nFree) {
    std::ostringstream m;
    m << n << " points for " << nFree << " free parameters: more points (or held parameters) needed";
    return makeError(ErrorCode::InvalidArgument, m.str(), where);
  }
  if (!constant.empty()) problem.SetManifold(x.data(), new ceres::SubsetManifold(static_cast<int>(N), constant));
  ceres::Solver::Options opt;
  opt.linear_solver_type = ceres::DENSE_QR;
  opt.max_num_iterations = maxIterations;
  opt.function_tolerance = 1e-12;
  opt.parameter_tolerance = 1e-12;
  opt.gradient_tolerance = 1e-14;
  ceres::Solver::Summary summary;
  ceres::Solve(opt, &problem, &summary);
  if (!summary.IsSolutionUsable() || summary.termination_type == ceres::NO_CONVERGENCE)
    return makeError(ErrorCode::NumericalFailure, "Magic Formula fit did not converge: " + summary.message, where);
  for (double v : x)
    if (!std::isfinite(v))
      return makeError(ErrorCode::NumericalFailure, "fit produced a non-finite coefficient", where);
  const double rss = 2.0 * summary.final_cost;
  const double s2 = rss / (n - nFree);
  ceres::Covariance::Options copt;
  copt.algorithm_type = ceres::DENSE_SVD;
  quietCeresLogging();  // a singular covariance is reported below, not by glog
  ceres::Covariance cov(copt);
  std::vector<std::pair<const double*, const double*>> blocks = {{x.data(), x.data()}};
  if (!cov.Compute(blocks, &problem))
    return makeError(ErrorCode::NumericalFailure,
                     "covariance is singular: the data cannot separate the free parameters (hold some)", where);
  std::vector<double> c(N * N);
  cov.GetCovarianceBlock(x.data(), x.data(), c.data());
  for (std::size_t i = 0; i < N; ++i) fit.stdError[i] = mask[i] ? std::sqrt(std::max(0.0, s2 * c[i * N + i])) : 0.0;
  fit.value = x;
  fit.rmsResidual = std::sqrt(rss / n);
  fit.observations = n;
  fit.freeParameters = nFree;
  fit.iterations = static_cast<int>(summary.iterations.size());
  return fit;
}

// Slope of y over slip near alpha = 0 from points with |alpha| <= 2 deg and
// the smallest |camber|: a start value, not a result.
double roughSlope(const std::vector<SteadyStatePoint>& d, bool torque) {
  double gmin = HUGE_VAL;
  for (const auto& x : d) gmin = std::min(gmin, std::abs(x.camber));
  double sxx = 0, sxy = 0, sx = 0, sy = 0;
  int n = 0;
  for (const auto& x : d)
    if (std::abs(x.slip) <= 2.0 * kPi / 180 && std::abs(std::abs(x.camber) - gmin) < 1e-6) {
      const double y = torque ? x.torque : x.force;
      sxx += x.slip * x.slip, sxy += x.slip * y, sx += x.slip, sy += y, ++n;
    }
  const double den = n * sxx - sx * sx;
  return n >= 2 && den > 0 ? (n * sxy - sx * sy) / den : 0.0;
}

}  // namespace

const std::array<std::string, kMfLateralCount>& mfLateralNames() {
  static const std::array<std::string, kMfLateralCount> n = {
      "pCy1", "pDy1", "pDy2", "pDy3", "pEy1", "pEy2", "pEy3", "pEy4", "pKy1", "pKy2", "pKy3",
      "pHy1", "pHy2", "pHy3", "pVy1", "pVy2", "pVy3", "pVy4", "ppy1", "ppy2", "ppy3", "ppy4"};
  return n;
}

const std::array<std::string, kMfAligningCount>& mfAligningNames() {
  static const std::array<std::string, kMfAligningCount> n = {
      "qBz1", "qBz2", "qBz3", "qBz4", "qBz5", "qBz9", "qBz10", "qCz1", "qDz1", "qDz2", "qDz3", "qDz4", "qDz6", "qDz7",
      "qDz8", "qDz9", "qEz1", "qEz2", "qEz3", "qEz4", "qEz5",  "qHz1", "qHz2", "qHz3", "qHz4", "ppz1", "ppz2"};
  return n;
}

MfLateralCoefficients mfLateralDefaults() {
  MfLateralCoefficients p{};
  p[pCy1] = 1.3;
  p[pDy1] = 1.0;
  p[pEy1] = -0.5;
  p[pKy1] = 15.0;
  p[pKy2] = 2.0;
  return p;
}

MfAligningCoefficients mfAligningDefaults() {
  MfAligningCoefficients q{};
  q[qBz1] = 10.0;
  q[qCz1] = 1.2;
  q[qDz1] = 0.1;
  q[qEz1] = -1.0;
  q[qBz9] = 10.0;
  return q;
}

double mfLateralForce(const MfLateralCoefficients& p, const MfConstants& c, double alpha, double gamma, double load,
                      double pressure) {
  return lateral<double>(p.data(), c, {alpha, gamma, load, pressure}).fy;
}

double mfAligningTorque(const MfAligningCoefficients& q, const MfLateralCoefficients& p, const MfConstants& c,
                        double alpha, double gamma, double load, double pressure) {
  const Condition x{alpha, gamma, load, pressure};
  return aligning<double>(q.data(), lateral<double>(p.data(), c, x), c, x);
}

Result<MfLateralFit> fitMfLateral(const std::vector<SteadyStatePoint>& data, const MfConstants& c,
                                  const MfFitOptions& options, std::optional<MfLateralCoefficients> start) {
  const char* where = "Magic Formula lateral force fit";
  MOZZI_TRY_ASSIGN(const DataSpread s, checkedSpread(data, c, where));
  std::set<std::string> held;
  if (options.autoFix) {
    if (s.pressures < 2) held.insert({"ppy1", "ppy2", "ppy3", "ppy4"});
    if (s.pressures < 3) held.insert("ppy4");
    if (s.loads < 2) held.insert({"pDy2", "pEy2", "pHy2", "pVy2", "pVy4", "pKy2", "ppy2"});
    if (s.cambers < 2) held.insert({"pDy3", "pEy4", "pKy3", "pHy3", "pVy3", "pVy4"});
    if (s.cambers < 3) held.insert("pDy3");
    if (!s.camberTwoSided) held.insert("pKy3");          // |gamma| and gamma alias on one side
    if (!s.slipTwoSided) held.insert({"pEy3", "pEy4"});  // sgn(alpha) constant
  }
  std::vector<std::string> heldNames;
  MOZZI_TRY_ASSIGN(const auto mask, freeMask(mfLateralNames(), options.fixed, held, heldNames, where));
  MfLateralCoefficients x = start.value_or(mfLateralDefaults());
  if (!start) {  // data-driven start: peak and slope
    double peak = 0, meanLoad = 0;
    for (const auto& d : data) peak = std::max(peak, std::abs(d.force) / d.load), meanLoad += d.load / data.size();
    const double k = roughSlope(data, false);
    x[pDy1] = std::max(0.05, 1.05 * peak);
    if (k != 0.0) x[pKy1] = k / (c.nominalLoad * std::sin(2 * std::atan(meanLoad / (x[pKy2] * c.nominalLoad))));
  }
  ceres::Problem problem;
  for (const auto& d : data)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<LateralResidual, 1, kMfLateralCount>(
                                 new LateralResidual{c, {d.slip, d.camber, d.load, d.pressure}, d.force}),
                             nullptr, x.data());
  auto fit = solve(problem, x, mask, static_cast<int>(data.size()), options.maxIterations, where);
  if (fit) fit->heldByData = heldNames;
  return fit;
}

Result<MfAligningFit> fitMfAligning(const std::vector<SteadyStatePoint>& data, const MfConstants& c,
                                    const MfLateralCoefficients& lat, const MfFitOptions& options,
                                    std::optional<MfAligningCoefficients> start) {
  const char* where = "Magic Formula aligning torque fit";
  MOZZI_TRY_ASSIGN(const DataSpread s, checkedSpread(data, c, where));
  std::set<std::string> held;
  if (options.autoFix) {
    if (s.pressures < 2) held.insert({"ppz1", "ppz2"});
    if (s.loads < 2) held.insert({"qBz2", "qBz3", "qDz2", "qDz7", "qDz9", "qEz2", "qEz3", "qHz2", "qHz4"});
    if (s.loads < 3) held.insert({"qBz3", "qEz3"});
    if (s.cambers < 2) held.insert({"qBz4", "qBz5", "qDz3", "qDz4", "qDz8", "qDz9", "qEz5", "qHz3", "qHz4", "ppz2"});
    if (s.cambers < 3) held.insert("qDz4");
    if (!s.camberTwoSided) held.insert("qBz5");
    // B_r = qBz9 + qBz10 B_y C_y: B_y C_y = K_ya/D_y is one number at one condition.
    if (s.loads < 2 && s.pressures < 2 && s.cambers < 2) held.insert("qBz10");
  }
  std::vector<std::string> heldNames;
  MOZZI_TRY_ASSIGN(const auto mask, freeMask(mfAligningNames(), options.fixed, held, heldNames, where));
  MfAligningCoefficients x = start.value_or(mfAligningDefaults());
  if (!start) {  // trail at the origin from the slopes: dM_z/dalpha ~ -t0 K_ya
    const double kf = roughSlope(data, false), km = roughSlope(data, true);
    double meanLoad = 0;
    for (const auto& d : data) meanLoad += d.load / data.size();
    if (kf != 0.0 && km != 0.0) x[qDz1] = -km / kf * c.nominalLoad / (meanLoad * c.unloadedRadius);
  }
  ceres::Problem problem;
  for (const auto& d : data) {
    const Condition cond{d.slip, d.camber, d.load, d.pressure};
    const LateralParts<double> lp = lateral<double>(lat.data(), c, cond);
    if (!std::isfinite(lp.fy) || lp.kya == 0.0)
      return makeError(ErrorCode::InvalidArgument, "the lateral coefficients give no finite F_y or zero K_ya here",
                       std::string(where) + ", point " + std::to_string(&d - data.data() + 1));
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<AligningResidual, 1, kMfAligningCount>(
                                 new AligningResidual{c, cond, lp, d.torque}),
                             nullptr, x.data());
  }
  auto fit = solve(problem, x, mask, static_cast<int>(data.size()), options.maxIterations, where);
  if (fit) fit->heldByData = heldNames;
  return fit;
}

}  // namespace mozzi::core::tire
