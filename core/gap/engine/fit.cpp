#include "core/gap/engine/fit.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "core/common/ceres_logging.h"
#include "core/common/text.h"

namespace mozzi::core::gap::engine {

Result<Scaled> scaleParameter(const Parameter& p, const std::string& where) {
  Scaled s;
  s.def = p;
  const std::string what = where + " parameter '" + p.name + "'";
  if (!std::isfinite(p.nominal)) return makeError(ErrorCode::InvalidArgument, "nominal value is not finite", what);
  if (std::isnan(p.lower) || std::isnan(p.upper) || p.lower > p.nominal || p.upper < p.nominal) {
    return makeError(ErrorCode::InvalidArgument,
                     "bounds [" + formatNumber(p.lower) + ", " + formatNumber(p.upper) + "] do not hold the nominal " +
                         formatNumber(p.nominal),
                     what);
  }
  if (p.priorSigma < 0.0 || std::isnan(p.priorSigma)) {
    return makeError(ErrorCode::InvalidArgument, "prior sigma is negative", what);
  }
  if (p.lower == p.upper) {
    s.fixed = true;
    return s;
  }
  // The span of the box when finite, else the prior's sigma, else the size of
  // the nominal: one unit of u is "the whole admissible range".
  if (std::isfinite(p.lower) && std::isfinite(p.upper)) {
    s.scale = p.upper - p.lower;
  } else if (p.priorSigma > 0.0) {
    s.scale = p.priorSigma;
  } else {
    s.scale = std::max(std::abs(p.nominal), 1.0);
  }
  s.uLower = std::isfinite(p.lower) ? (p.lower - p.nominal) / s.scale : -std::numeric_limits<double>::infinity();
  s.uUpper = std::isfinite(p.upper) ? (p.upper - p.nominal) / s.scale : std::numeric_limits<double>::infinity();
  return s;
}

Model::Model(const GapProblem& problem, std::vector<Scaled> theta, int candidate, std::vector<Scaled> phi,
             std::vector<int> rows)
    : problem_(problem),
      theta_(std::move(theta)),
      candidate_(candidate),
      phi_(std::move(phi)),
      rows_(std::move(rows)),
      theta_buf_(theta_.size()),
      phi_buf_(phi_.size()) {
  if (!rows_.empty()) full_buf_.resize(static_cast<std::size_t>(problem_.residualCount()));
}

bool Model::residuals(const double* u, double* r) const {
  for (std::size_t i = 0; i < theta_.size(); ++i) theta_buf_[i] = theta_[i].toX(u[i]);
  for (std::size_t i = 0; i < phi_.size(); ++i) phi_buf_[i] = phi_[i].toX(u[theta_.size() + i]);
  const double* phi = phi_.empty() ? nullptr : phi_buf_.data();
  const int candidate = phi_.empty() ? -1 : candidate_;
  bool ok;
  if (rows_.empty()) {
    ok = problem_.residuals({theta_buf_.data(), candidate, phi}, r);
    return ok && Eigen::Map<const Eigen::VectorXd>(r, problem_.residualCount()).allFinite();
  }
  ok = problem_.residuals({theta_buf_.data(), candidate, phi}, full_buf_.data());
  for (std::size_t j = 0; ok && j < rows_.size(); ++j) {
    r[j] = full_buf_[static_cast<std::size_t>(rows_[j])];
    ok = std::isfinite(r[j]);
  }
  return ok;
}

bool Model::jacobian(const Eigen::VectorXd& u, int first, int count, double h, Eigen::MatrixXd& jac,
                     const Eigen::VectorXd* r0) const {
  const int n = residualCount();
  jac.resize(n, count);
  Eigen::VectorXd up(u), plus(n), minus(n);
  for (int c = 0; c < count; ++c) {
    const int i = first + c;
    const Scaled& s = parameter(i);
    if (s.fixed) {
      jac.col(c).setZero();
      continue;
    }
    if (r0) {
      const double step = u[i] + h <= s.uUpper ? h : -h;
      up[i] = u[i] + step;
      const bool ok = residuals(up.data(), plus.data());
      up[i] = u[i];
      if (!ok) return false;
      jac.col(c) = (plus - *r0) / step;
      continue;
    }
    // Central where both sides are inside the box, else one-sided: the model
    // may be undefined outside its bounds (a negative mass).
    double hi = u[i] + h <= s.uUpper ? h : 0.0;
    double lo = u[i] - h >= s.uLower ? h : 0.0;
    if (hi == 0.0 && lo == 0.0) return false;
    up[i] = u[i] + hi;
    if (hi > 0.0) {
      if (!residuals(up.data(), plus.data())) return false;
    } else if (!residuals(u.data(), plus.data())) {
      return false;
    }
    up[i] = u[i] - lo;
    if (lo > 0.0) {
      if (!residuals(up.data(), minus.data())) return false;
    } else if (!residuals(u.data(), minus.data())) {
      return false;
    }
    up[i] = u[i];
    jac.col(c) = (plus - minus) / (hi + lo);
  }
  return true;
}

int Model::priorCount() const {
  int m = 0;
  for (int i = 0; i < parameterCount(); ++i) m += parameter(i).def.priorSigma > 0.0 && !parameter(i).fixed;
  return m;
}

void Model::priorResiduals(const double* u, double* r) const {
  int m = 0;
  for (int i = 0; i < parameterCount(); ++i) {
    const Scaled& s = parameter(i);
    if (s.def.priorSigma > 0.0 && !s.fixed) r[m++] = s.scale * u[i] / s.def.priorSigma;
  }
}

void Model::priorJacobian(Eigen::MatrixXd& jac) const {
  jac = Eigen::MatrixXd::Zero(priorCount(), parameterCount());
  int m = 0;
  for (int i = 0; i < parameterCount(); ++i) {
    const Scaled& s = parameter(i);
    if (s.def.priorSigma > 0.0 && !s.fixed) jac(m++, i) = s.scale / s.def.priorSigma;
  }
}

std::vector<double> Model::thetaX(const Eigen::VectorXd& u) const {
  std::vector<double> x(theta_.size());
  for (std::size_t i = 0; i < theta_.size(); ++i) x[i] = theta_[i].toX(u[static_cast<Eigen::Index>(i)]);
  return x;
}

std::vector<double> Model::phiX(const Eigen::VectorXd& u) const {
  std::vector<double> x(phi_.size());
  for (std::size_t i = 0; i < phi_.size(); ++i) x[i] = phi_[i].toX(u[static_cast<Eigen::Index>(theta_.size() + i)]);
  return x;
}

namespace {

// Step of the numerical Jacobian in u (a fraction of the bound span): small
// against the curvature of any physical effect over its range, large against
// the ~1e-12 rounding of an eigen-solution (error ~ 1e-12 / 1e-6).
constexpr double kJacobianStep = 1e-6;
// sigma_min / sigma_max of the whitened Jacobian below this is rank deficiency:
// a parameter combination moves the residuals by less than 1e-7 of the best
// determined one, beyond what a numerical Jacobian can resolve.
constexpr double kRankTolerance = 1e-7;

// Data residuals as one cost with one 1-vector block per parameter.
class DataCost : public ceres::CostFunction {
 public:
  explicit DataCost(const Model& model) : model_(model), u_(model.parameterCount()) {
    set_num_residuals(model.residualCount());
    for (int i = 0; i < model.parameterCount(); ++i) mutable_parameter_block_sizes()->push_back(1);
  }
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const int n = model_.residualCount(), p = model_.parameterCount();
    for (int i = 0; i < p; ++i) u_[i] = parameters[i][0];
    // Ceres' bounded Levenberg-Marquardt evaluates each trial point up to
    // three times: with the gradient (its projected line search), for the
    // cost, and once the step is accepted with the Jacobian again. The model
    // is deterministic: the last point's residuals and Jacobian serve again.
    if (!(lastValid_ && u_ == lastU_)) {
      lastValid_ = jacobianValid_ = false;
      if (!model_.residuals(u_.data(), residuals)) return false;
      lastU_ = u_;
      lastR_ = Eigen::Map<const Eigen::VectorXd>(residuals, n);
      lastValid_ = true;
    } else {
      std::copy(lastR_.data(), lastR_.data() + n, residuals);
    }
    if (!jacobians) return true;
    if (!jacobianValid_) {
      // Forward differences during the iterations (half the evaluations);
      // the covariance below uses central ones.
      lastJ_.resize(n, p);
      for (int i = 0; i < p; ++i) {
        if (!model_.jacobian(u_, i, 1, kJacobianStep, col_, &lastR_)) return false;
        lastJ_.col(i) = col_.col(0);
      }
      jacobianValid_ = true;
    }
    for (int i = 0; i < p; ++i)
      if (jacobians[i]) std::copy(lastJ_.col(i).data(), lastJ_.col(i).data() + n, jacobians[i]);
    return true;
  }

 private:
  const Model& model_;
  mutable Eigen::VectorXd u_;
  mutable Eigen::MatrixXd col_;
  // The last point evaluated, its residuals and (when asked for) Jacobian;
  // one Ceres solve evaluates from one thread (Solver::Options::num_threads = 1).
  mutable Eigen::VectorXd lastU_, lastR_;
  mutable Eigen::MatrixXd lastJ_;
  mutable bool lastValid_ = false, jacobianValid_ = false;
};

// Gaussian prior N(nominal, sigma) on one parameter: r = scale u / sigma.
class PriorCost : public ceres::SizedCostFunction<1, 1> {
 public:
  explicit PriorCost(double gain) : gain_(gain) {}
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    residuals[0] = gain_ * parameters[0][0];
    if (jacobians && jacobians[0]) jacobians[0][0] = gain_;
    return true;
  }

 private:
  double gain_;
};

struct Built {
  ceres::Problem problem;
  std::vector<double> u;
  Built() : problem(options()) {}
  static ceres::Problem::Options options() {
    ceres::Problem::Options o;
    o.cost_function_ownership = ceres::TAKE_OWNERSHIP;
    return o;
  }
};

void build(const Model& model, const Eigen::VectorXd& start, Built& b) {
  const int p = model.parameterCount();
  b.u.assign(start.data(), start.data() + p);
  std::vector<double*> blocks;
  for (int i = 0; i < p; ++i) blocks.push_back(&b.u[static_cast<std::size_t>(i)]);
  b.problem.AddResidualBlock(new DataCost(model), nullptr, blocks);
  for (int i = 0; i < p; ++i) {
    const Scaled& s = model.parameter(i);
    if (s.fixed) {
      b.problem.SetParameterBlockConstant(blocks[i]);
      continue;
    }
    if (s.def.priorSigma > 0.0)
      b.problem.AddResidualBlock(new PriorCost(s.scale / s.def.priorSigma), nullptr, blocks[i]);
    if (std::isfinite(s.uLower)) b.problem.SetParameterLowerBound(blocks[i], 0, s.uLower);
    if (std::isfinite(s.uUpper)) b.problem.SetParameterUpperBound(blocks[i], 0, s.uUpper);
  }
}

double dataChiSquare(const Model& model, const Eigen::VectorXd& u) {
  Eigen::VectorXd r(model.residualCount());
  if (!model.residuals(u.data(), r.data())) return std::numeric_limits<double>::infinity();
  return r.squaredNorm();
}

void covarianceAt(const Model& model, FitResult& fit) {
  const int p = model.parameterCount();
  // The whitened Jacobian with the prior rows, for the report either way.
  Eigen::MatrixXd jd, jp;
  if (!model.jacobian(fit.u, 0, p, kJacobianStep, jd)) {
    fit.rankDeficient = true;
    return;
  }
  model.priorJacobian(jp);
  Eigen::MatrixXd jac(jd.rows() + jp.rows(), p);
  jac << jd, jp;
  std::vector<int> free;
  for (int i = 0; i < p; ++i) {
    if (!model.parameter(i).fixed) free.push_back(i);
  }
  Eigen::MatrixXd jf(jac.rows(), static_cast<Eigen::Index>(free.size()));
  for (std::size_t c = 0; c < free.size(); ++c) jf.col(static_cast<Eigen::Index>(c)) = jac.col(free[c]);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(jf, Eigen::ComputeThinV);
  fit.singularValues = svd.singularValues();
  fit.nullDirection = Eigen::VectorXd::Zero(p);
  if (!free.empty()) {
    const Eigen::VectorXd v = svd.matrixV().col(static_cast<Eigen::Index>(free.size()) - 1);
    for (std::size_t c = 0; c < free.size(); ++c) fit.nullDirection[free[c]] = v[static_cast<Eigen::Index>(c)];
  }

  // Ceres' dense-SVD covariance refuses the same matrices (sigma_min / sigma_max
  // below sqrt(min_reciprocal_condition_number)); deciding here first keeps its
  // log line out of reports.
  if (free.empty() || !(fit.singularValues[fit.singularValues.size() - 1] > kRankTolerance * fit.singularValues[0])) {
    fit.rankDeficient = true;
    return;
  }
  Built b;
  build(model, fit.u, b);
  ceres::Covariance::Options co;
  // Dense SVD refuses (Compute returns false) when sigma_min / sigma_max of the
  // Jacobian is below sqrt(min_reciprocal_condition_number) = 1e-7: we report
  // that as "not identifiable" instead of pseudo-inverting (GAP.md principles).
  co.algorithm_type = ceres::DENSE_SVD;
  co.min_reciprocal_condition_number = kRankTolerance * kRankTolerance;
  co.null_space_rank = 0;
  co.num_threads = 1;
  quietCeresLogging();  // a singular covariance is reported below, not by glog
  ceres::Covariance covariance(co);
  std::vector<std::pair<const double*, const double*>> pairs;
  for (int i : free) pairs.emplace_back(&b.u[static_cast<std::size_t>(i)], &b.u[static_cast<std::size_t>(i)]);
  if (!covariance.Compute(pairs, &b.problem)) {
    fit.rankDeficient = true;
    return;
  }
  fit.stdErrors.assign(static_cast<std::size_t>(p), 0.0);
  for (int i : free) {
    double var = 0.0;
    covariance.GetCovarianceBlock(&b.u[static_cast<std::size_t>(i)], &b.u[static_cast<std::size_t>(i)], &var);
    fit.stdErrors[static_cast<std::size_t>(i)] = model.parameter(i).scale * std::sqrt(std::max(var, 0.0));
  }
}

}  // namespace

Eigen::VectorXd clipToBox(const Model& model, Eigen::VectorXd u) {
  for (int i = 0; i < model.parameterCount(); ++i) {
    const Scaled& s = model.parameter(i);
    u[i] = s.fixed ? 0.0 : std::clamp(u[i], s.uLower, s.uUpper);
  }
  return u;
}

double dataCost(const Model& model, const Eigen::VectorXd& u, Eigen::VectorXd& r) {
  r.resize(model.residualCount());
  if (!model.residuals(u.data(), r.data())) return std::numeric_limits<double>::infinity();
  return r.squaredNorm();
}

std::vector<Eigen::VectorXd> gridStarts(const Model& model, Eigen::Index first, Eigen::Index count,
                                        const Eigen::VectorXd& u, int maxStarts, double below) {
  Eigen::VectorXd r;
  std::vector<std::pair<double, Eigen::VectorXd>> minima;
  for (Eigen::Index j = first; j < first + count; ++j) {
    const Scaled& s = model.parameter(static_cast<int>(j));
    if (s.fixed) continue;
    // The line from the lower bound through u to the upper bound, in order.
    std::vector<double> values;
    for (double t = 1.0; t >= 1.0 / 64.0; t /= 2.0)
      if (std::isfinite(s.uLower) && s.uLower < u[j]) values.push_back(u[j] + t * (s.uLower - u[j]));
    values.push_back(u[j]);
    for (double t = 1.0 / 64.0; t <= 1.0; t *= 2.0)
      if (std::isfinite(s.uUpper) && s.uUpper > u[j]) values.push_back(u[j] + t * (s.uUpper - u[j]));
    std::vector<double> cost(values.size());
    for (std::size_t k = 0; k < values.size(); ++k) {
      Eigen::VectorXd trial = u;
      trial[j] = values[k];
      cost[k] = dataCost(model, trial, r);
    }
    for (std::size_t k = 0; k < values.size(); ++k) {
      if (values[k] == u[j] || !std::isfinite(cost[k]) || !(cost[k] < below)) continue;
      const bool belowLeft = k == 0 || cost[k] < cost[k - 1];
      const bool belowRight = k + 1 == values.size() || cost[k] < cost[k + 1];
      if (!belowLeft || !belowRight) continue;
      Eigen::VectorXd start = u;
      start[j] = values[k];
      minima.emplace_back(cost[k], std::move(start));
    }
  }
  std::sort(minima.begin(), minima.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Eigen::VectorXd> out;
  for (std::size_t k = 0; k < minima.size() && static_cast<int>(k) < maxStarts; ++k) out.push_back(minima[k].second);
  return out;
}

Eigen::VectorXd randomStart(const Model& model, std::mt19937_64& rng) {
  Eigen::VectorXd u(model.parameterCount());
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int i = 0; i < model.parameterCount(); ++i) {
    const Scaled& s = model.parameter(i);
    if (s.fixed) {
      u[i] = 0.0;
    } else if (std::isfinite(s.uLower) && std::isfinite(s.uUpper)) {
      u[i] = s.uLower + uniform(rng) * (s.uUpper - s.uLower);
    } else {
      u[i] = std::clamp(normal(rng), s.uLower, s.uUpper);
    }
  }
  return u;
}

FitResult fitModel(const Model& model, const std::vector<Eigen::VectorXd>& starts, const FitOptions& options) {
  FitResult best;
  best.nll = std::numeric_limits<double>::infinity();
  if (model.parameterCount() == 0) {
    // Nothing to fit (a model without calibration parameters): evaluate.
    best.starts = best.feasibleStarts = 1;
    best.u = Eigen::VectorXd(0);
    best.chiSquare = dataChiSquare(model, best.u);
    best.ok = std::isfinite(best.chiSquare);
    best.nll = 0.5 * best.chiSquare;
    return best;
  }
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = options.maxIterations;
  so.function_tolerance = options.functionTolerance;
  so.gradient_tolerance = 1e-12;
  so.parameter_tolerance = 1e-10;
  so.logging_type = ceres::SILENT;
  so.minimizer_progress_to_stdout = false;
  so.num_threads = 1;
  const bool staged =
      starts.size() > 1 && options.startIterations > 0 && options.startIterations < options.maxIterations;
  if (staged) so.max_num_iterations = options.startIterations;
  auto run = [&](const Eigen::VectorXd& start) {
    Built b;
    build(model, clipToBox(model, start), b);
    double cost0 = 0.0;
    if (!b.problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost0, nullptr, nullptr, nullptr)) return;
    ceres::Solver::Summary summary;
    ceres::Solve(so, &b.problem, &summary);
    if (!std::isfinite(summary.final_cost)) return;
    ++best.feasibleStarts;
    if (summary.final_cost < best.nll) {
      best.ok = true;
      best.nll = summary.final_cost;
      best.u = Eigen::Map<const Eigen::VectorXd>(b.u.data(), static_cast<Eigen::Index>(b.u.size()));
    }
  };
  for (const auto& start : starts) {
    ++best.starts;
    run(start);
  }
  if (!best.ok) return best;
  if (staged) {
    so.max_num_iterations = options.maxIterations;
    --best.feasibleStarts;  // the polish continues a start already counted
    run(Eigen::VectorXd(best.u));
  }
  best.chiSquare = dataChiSquare(model, best.u);
  if (options.covariance) covarianceAt(model, best);
  return best;
}

}  // namespace mozzi::core::gap::engine
