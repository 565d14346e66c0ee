#pragma once
// Small self-contained GapProblems for the engine tests, where the theory is
// exact: whitened residuals r = (A theta + S_k phi_k - y) / sigma with Gaussian
// noise, so likelihood ratios follow chi-square laws (Wilks 1938) and least
// squares estimates are unbiased with covariance (X'X)^-1.

#include <Eigen/Dense>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "core/gap/gap_problem.h"

namespace mozzi::core::gap::testing {

struct LinearCandidate {
  std::string effect;
  Eigen::MatrixXd signature;  // n x q: d prediction / d phi
  double lower = -5.0, upper = 5.0;
};

class LinearGapProblem : public GapProblem {
 public:
  LinearGapProblem(Eigen::MatrixXd a, std::vector<LinearCandidate> cands, Eigen::VectorXd measured, double sigma,
                   int foldCount = 4)
      : a_(std::move(a)), cands_(std::move(cands)), y_(std::move(measured)), sigma_(sigma), folds_(foldCount) {}

  // Measured = prediction(theta, k, phi) + N(0, sigma^2) noise.
  static std::unique_ptr<LinearGapProblem> generate(const Eigen::MatrixXd& a, std::vector<LinearCandidate> cands,
                                                    const Eigen::VectorXd& theta, int k, const Eigen::VectorXd& phi,
                                                    const Eigen::VectorXd& extra, double sigma, std::mt19937_64& rng,
                                                    int foldCount = 4) {
    auto p = std::make_unique<LinearGapProblem>(a, std::move(cands), Eigen::VectorXd::Zero(a.rows()), sigma, foldCount);
    Eigen::VectorXd y = p->prediction(theta.data(), k, phi.data()) + extra;
    std::normal_distribution<double> noise(0.0, sigma);
    for (Eigen::Index i = 0; i < y.size(); ++i) y[i] += noise(rng);
    p->y_ = y;
    return p;
  }

  // Gaussian prior N(0, sigma^2) on every calibration parameter (0: none).
  void setPrior(double sigma) { priorSigma_ = sigma; }
  const Eigen::VectorXd& measured() const { return y_; }

  Eigen::VectorXd prediction(const double* theta, int k, const double* phi) const {
    Eigen::VectorXd pred = a_ * Eigen::Map<const Eigen::VectorXd>(theta, a_.cols());
    if (k >= 0) {
      const auto& s = cands_[static_cast<std::size_t>(k)].signature;
      pred += s * Eigen::Map<const Eigen::VectorXd>(phi, s.cols());
    }
    return pred;
  }

  std::string dataKind() const override { return "linear"; }
  std::vector<Parameter> calibrationParameters() const override {
    std::vector<Parameter> out;
    for (Eigen::Index j = 0; j < a_.cols(); ++j)
      out.push_back({"theta" + std::to_string(j), "", 0.0, -100.0, 100.0, priorSigma_});
    return out;
  }
  std::vector<Candidate> candidates() const override {
    std::vector<Candidate> out;
    for (std::size_t k = 0; k < cands_.size(); ++k) {
      Candidate c{cands_[k].effect, {std::to_string(k + 1) + "+Z"}, {}};
      for (Eigen::Index j = 0; j < cands_[k].signature.cols(); ++j) {
        c.parameters.push_back({"size" + std::to_string(j), "kg", 0.0, cands_[k].lower, cands_[k].upper, 0.0});
      }
      out.push_back(c);
    }
    return out;
  }
  int residualCount() const override { return static_cast<int>(y_.size()); }
  bool residuals(const ModelPoint& at, double* r) const override {
    Eigen::Map<Eigen::VectorXd>(r, y_.size()) = (prediction(at.theta, at.candidate, at.phi) - y_) / sigma_;
    return true;
  }
  std::vector<int> folds() const override {
    std::vector<int> f(static_cast<std::size_t>(y_.size()));
    for (std::size_t i = 0; i < f.size(); ++i) f[i] = static_cast<int>(i % static_cast<std::size_t>(folds_));
    return f;
  }
  std::unique_ptr<GapProblem> simulated(const ModelPoint& at, std::mt19937_64& rng) const override {
    auto p = std::make_unique<LinearGapProblem>(*this);
    p->y_ = prediction(at.theta, at.candidate, at.phi);
    std::normal_distribution<double> noise(0.0, sigma_);
    for (Eigen::Index i = 0; i < p->y_.size(); ++i) p->y_[i] += noise(rng);
    return p;
  }
  // overall: relative residual |pred - y| / |y|; one "band" row per block of
  // eight residuals with z = (sum r^2 - m) / sqrt(2 m) (standardised chi-square).
  GapMetrics metrics(const ModelPoint& at) const override {
    GapMetrics m;
    m.residualName = "residual";
    const Eigen::VectorXd d = prediction(at.theta, at.candidate, at.phi) - y_;
    m.overall = d.norm() / y_.norm();
    for (Eigen::Index b = 0; b * 8 < d.size(); ++b) {
      const Eigen::Index len = std::min<Eigen::Index>(8, d.size() - b * 8);
      const double ss = (d.segment(b * 8, len) / sigma_).squaredNorm();
      GapEntry e;
      e.kind = "band";
      e.label = "block " + std::to_string(b);
      e.value = std::sqrt(ss / len);
      e.z = (ss - len) / std::sqrt(2.0 * len);
      m.entries.push_back(e);
    }
    return m;
  }

 private:
  Eigen::MatrixXd a_;
  std::vector<LinearCandidate> cands_;
  Eigen::VectorXd y_;
  double sigma_;
  int folds_;
  double priorSigma_ = 0.0;
};

// Smooth, mutually non-orthogonal columns on t in [0, 1] (a polynomial
// calibration basis) and localised bumps for candidates: the kind of shapes a
// structural residual has.
inline Eigen::MatrixXd polynomialBasis(int n, int p) {
  Eigen::MatrixXd a(n, p);
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) / n;
    for (int j = 0; j < p; ++j) a(i, j) = std::pow(t, j);
  }
  return a;
}

inline Eigen::VectorXd bump(int n, double centre, double width) {
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) / n;
    v[i] = std::exp(-0.5 * std::pow((t - centre) / width, 2));
  }
  return v;
}

}  // namespace mozzi::core::gap::testing

namespace mozzi::core::gap::testing {

// A mildly nonlinear problem: prediction = theta0 exp(-theta1 t) + theta0
// (exp(phi b_k(t)) - 1), with b_k a bump at centre_k. The effect interacts
// with the calibration (its signature scales with theta0) and is nonlinear in
// phi, so the linearised bootstrap is an approximation here.
class NonlinearGapProblem : public GapProblem {
 public:
  NonlinearGapProblem(int n, std::vector<double> centres, double sigma)
      : n_(n), centres_(std::move(centres)), sigma_(sigma), y_(Eigen::VectorXd::Zero(n)) {}

  Eigen::VectorXd prediction(const double* theta, int k, const double* phi) const {
    Eigen::VectorXd pred(n_);
    for (int i = 0; i < n_; ++i) {
      const double t = (i + 0.5) / n_;
      pred[i] = theta[0] * std::exp(-theta[1] * t);
    }
    if (k >= 0) {
      const Eigen::VectorXd b = bump(n_, centres_[static_cast<std::size_t>(k)], 0.06);
      pred += theta[0] * ((phi[0] * b).array().exp() - 1.0).matrix();
    }
    return pred;
  }
  void setMeasured(Eigen::VectorXd y) { y_ = std::move(y); }

  std::string dataKind() const override { return "nonlinear"; }
  std::vector<Parameter> calibrationParameters() const override {
    return {{"amplitude", "", 1.0, 0.1, 10.0, 0.0}, {"decay", "1/s", 1.0, 0.0, 5.0, 0.5}};
  }
  std::vector<Candidate> candidates() const override {
    std::vector<Candidate> out;
    for (std::size_t k = 0; k < centres_.size(); ++k) {
      out.push_back({"element_stiffness", {std::to_string(k + 1) + "+X"}, {{"log_factor", "", 0.0, -1.0, 1.0, 0.0}}});
    }
    return out;
  }
  int residualCount() const override { return n_; }
  bool residuals(const ModelPoint& at, double* r) const override {
    Eigen::Map<Eigen::VectorXd>(r, n_) = (prediction(at.theta, at.candidate, at.phi) - y_) / sigma_;
    return true;
  }
  std::unique_ptr<GapProblem> simulated(const ModelPoint& at, std::mt19937_64& rng) const override {
    auto p = std::make_unique<NonlinearGapProblem>(*this);
    p->y_ = prediction(at.theta, at.candidate, at.phi);
    std::normal_distribution<double> noise(0.0, sigma_);
    for (int i = 0; i < n_; ++i) p->y_[i] += noise(rng);
    return p;
  }
  GapMetrics metrics(const ModelPoint& at) const override {
    GapMetrics m;
    m.overall = (prediction(at.theta, at.candidate, at.phi) - y_).norm() / y_.norm();
    return m;
  }

 private:
  int n_;
  std::vector<double> centres_;
  double sigma_;
  Eigen::VectorXd y_;
};

}  // namespace mozzi::core::gap::testing
