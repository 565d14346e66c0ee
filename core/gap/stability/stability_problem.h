#pragma once
// The sim-to-real gap of stability-mode frequencies (weave, wobble, ...)
// against forward speed (issue 10; thesis §4.2 Figure 33 and §6.6: rigid
// against flexible fork).
//
// Model: the linear vehicle models of core/stability — Sharp's (1971)
// motorcycle (motorcycle.h) or the benchmark bicycle (benchmark_bicycle.h) —
// with rigid fork. At every measured speed the modes are tracked and named by
// core/stability/mode_tracking.h; the prediction is Im(lambda) / 2 pi of the
// named mode.
// Calibration theta: the trail scale (a measured geometric input that moves
// every steer mode; Gaussian prior of its relative uncertainty).
// Catalogue (phi at nominal = absent):
//   fork_bending     lateral bending compliance of the fork, compliance ratio
//                    phi = k_ref / k (0 = rigid); motorcycle: the lumped model 1
//                    of thesis §4.2 (Table 12); bicycle: the bending joint of
//                    appendix 3 (§6.5, h_W, k_beta). Damping ratio kept: c ~ sqrt(k).
//   fork_torsion     (bicycle) torsion joint of appendix 3 (§6.4), same form.
//   tyre_relaxation  (motorcycle) relaxation length scale of the side-force lag.
// Folds: speed ranges (equal-width bins of the measured speeds).

#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "core/common/result.h"
#include "core/gap/gap_problem.h"
#include "core/gap/tire/condition_series.h"
#include "core/stability/benchmark_bicycle.h"
#include "core/stability/compliant_fork_bicycle.h"
#include "core/stability/motorcycle.h"

namespace mozzi::core::gap {

enum class StabilityVehicle { Motorcycle, Bicycle };

struct StabilityGapModel {
  std::string label;
  StabilityVehicle vehicle = StabilityVehicle::Bicycle;
  stability::SharpParameters motorcycle;      // vehicle == Motorcycle
  stability::BenchmarkParameters bicycle;     // vehicle == Bicycle
  stability::LumpedForkModel motorcycleFork;  // reference fork bending (phi = 1), thesis model 1
  stability::ForkBending bicycleBending;      // reference bending joint (phi = 1)
  stability::ForkTorsion bicycleTorsion;      // reference torsion joint (phi = 1)
  double trailRelSigma = 0.05;                // prior on the trail scale
  int speedFolds = 3;                         // number of speed ranges for held-out checks
  double trackingStep = 1.0;  // [m/s] mode tracking grid between measured speeds (Sharp 1971: same names as 0.25)
};

// One measured frequency: mode name as core/stability names it ("weave",
// "wobble", "capsize", "castering", "fork bending", "fork torsion").
struct ModeFrequency {
  std::string mode;
  double speed = 0.0;        // [m/s]
  double frequencyHz = 0.0;  // Im(lambda) / 2 pi
  double sigmaHz = 0.0;
};

class StabilityGapProblem : public ConditionSeriesProblem {
 public:
  static Result<std::unique_ptr<StabilityGapProblem>> create(StabilityGapModel model,
                                                             std::vector<ModeFrequency> measured);

  std::string dataKind() const override { return "stability"; }
  std::vector<Parameter> calibrationParameters() const override;
  std::vector<Candidate> candidates() const override;
  std::vector<OverlayCurve> overlay(const ModelPoint& at) const override;
  // The condition rows, plus the downstream figures a user reads from the
  // model (GAP.md step 9): one "prediction" row per measured mode with the
  // first speed in [0.5 min, 1.5 max] of the measured speeds where its real part
  // crosses zero (value in m/s, detail "found" 0 when none; z = 0, not tested).
  GapMetrics metrics(const ModelPoint& at) const override;

  // Predicted frequency [Hz] of every measured (mode, speed); NaN where the
  // model cannot be built or the mode is not oscillating there.
  std::vector<double> predict(const ModelPoint& at) const override;
  const std::vector<ModeFrequency>& measured() const { return modes_; }

 protected:
  std::unique_ptr<GapProblem> withPoints(std::vector<ConditionPoint> points) const override;
  std::vector<std::vector<std::pair<std::string, double>>> details(const ModelPoint& at) const override;

 private:
  StabilityGapProblem(StabilityGapModel model, std::vector<ModeFrequency> modes);
  Result<stability::StabilitySystem> system(const ModelPoint& at) const;
  std::vector<std::string> effectNames() const;

  StabilityGapModel model_;
  std::vector<ModeFrequency> modes_;
  std::vector<double> speeds_;  // distinct measured speeds, increasing
};

struct StabilityLoadOptions {
  double minSpeed = 0.0;  // [m/s] rows outside are dropped
  double maxSpeed = 1e9;
};

// Model file: JSON, "schema": "mozzi-stability-gap/1" (docs/formats.md); a
// relative "parameters" path is taken from the model file's folder.
// Measured: CSV with columns speed_m_s, mode, frequency_hz, uncertainty_hz.
Result<StabilityGapModel> parseStabilityGapModel(const std::string& jsonText, const std::string& source,
                                                 const std::string& baseDir);
Result<std::vector<ModeFrequency>> parseModeFrequencyCsv(const std::string& csvText, const std::string& source);
Result<std::unique_ptr<GapProblem>> loadStabilityGapProblem(const std::string& modelPath,
                                                            const std::string& measuredPath,
                                                            const StabilityLoadOptions& options = {});

}  // namespace mozzi::core::gap
