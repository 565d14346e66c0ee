#pragma once
// Null calibration of the attribution threshold by parametric bootstrap (GAP.md
// step 5): simulate data from the calibrated baseline (no effect), refit the
// baseline and every identifiable candidate, and take the (1 - alpha) quantile
// of the largest likelihood ratio. Cached in memory per problem layout,
// candidate set and options.

#include <Eigen/Dense>
#include <functional>
#include <random>
#include <vector>

#include "core/common/result.h"
#include "core/gap/engine/fit.h"
#include "core/gap/engine/screen.h"

namespace mozzi::core::gap::engine {

enum class NullMode { FullRefit, Linearised };

struct NullOptions {
  int samples = 200;
  double alpha = 0.05;
  unsigned long long seed = 1;
  NullMode mode = NullMode::FullRefit;
  int maxIterations = 30;  // per bootstrap refit: warm starts from the truth converge in a few
  bool useCache = true;
  std::function<bool(double)> progress;  // fraction done; false cancels
};

struct NullCalibration {
  double threshold = 0.0;
  std::vector<double> maxRatios;  // max_k LR_k per bootstrap sample
  // Baseline chi-square |r|^2 after the (linearised or full) refit per sample:
  // the goodness-of-fit null when the noise model is estimated from the data.
  std::vector<double> baselineChiSquares;
  NullMode mode = NullMode::FullRefit;
  bool fromCache = false;
};

// An independent, reproducible generator for (seed, stream, index).
std::mt19937_64 seededRng(unsigned long long seed, unsigned long long stream, unsigned long long index);

// `candidates`: indices into screen.candidates of the identifiable ones.
Result<NullCalibration> calibrateNull(const Model& baseline, const Eigen::VectorXd& u0, const Screen& screen,
                                      const std::vector<int>& candidates, const NullOptions& options);

// Forget every cached threshold (tests, or when memory matters).
void clearNullCache();

}  // namespace mozzi::core::gap::engine
