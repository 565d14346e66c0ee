#pragma once
// Gap problems of the thesis's fork worked examples (issue 10, shared/GAP.md
// "Worked cases"), on the lumped models of core/stiffness/fork_models.h.
//
// ForkLumpedGapProblem (thesis §4.2, Tables 10 to 12): fork A's 1-DOF bending
// model 1 — static stiffness k_1 at the static twist axis L_1, wheel and
// unsprung mass M at the wheel centre — predicts 18.4 Hz against 22.3 Hz
// measured. Data: that frequency and, optionally, the static lateral stiffness
// at the contact point (Table 10: 56.1 kN/m), predicted as the bending spring
// and the decomposition's torsion part in series,
//   K_lat = 1 / (L_1^2 / k_1 + c_t),   c_t = L_t^2 / k_t  (Table 10: 0.066 m, 3 kNm/rad).
// Calibration theta: the unsprung mass (part of M, estimated rather than
// weighed: §4.2 "3 kg"), with a Gaussian prior. Catalogue, one parameter each:
//   stiffness_location   (model 2) the spring sits at the dynamic twist axis
//                        L_2 (0.846 m) with stiffness s k_1; inertia about L_2.
//   bending_stiffness    the spring stays at L_1 with stiffness s k_1.
//   inertia              (model 3) a pure moment dJ added to the vibrating inertia.
//   residual_compliance  a share rho of the static bending compliance belongs to
//                        a part the bending mode does not deform (fixture, play):
//                        the mode sees k_1 / (1 - rho), the static test all of it.
// Folds: none (a frequency and a static stiffness cannot predict each other).
//
// StiffnessEstimatesGapProblem (thesis §6.4): several estimates of one
// stiffness from different test configurations (the carbon fork's torsion:
// 1208 Nm/rad with the wheel, 1253 Nm/rad alone). Model: one stiffness k
// (theta = k / first estimate). Catalogue: inertia_error at one configuration
// (k_hat = k / s there: the configuration's inertia is s times the assumed),
// boundary_stiffness (a clamp compliance in series, the same in every
// configuration: k_hat = k / (1 + rho); not separable from k by construction).

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "core/common/result.h"
#include "core/gap/gap_problem.h"
#include "core/gap/tire/condition_series.h"
#include "core/stiffness/fork_models.h"

namespace mozzi::core::gap {

struct ForkLumpedGapInput {
  stiffness::ForkLumpedInput fork;      // k_1, L_1, L_2, wheel centre, M, J_wheel, measured f, zeta
  double frequencySigmaHz = 0.0;        // standard uncertainty of the measured frequency
  bool withStatic = false;              // add the static lateral stiffness as a datum
  double staticLateralStiffness = 0.0;  // measured [N/m]
  double staticSigma = 0.0;             // [N/m]
  double torsionCompliance = 0.0;       // c_t [m/N], the torsion part of the static test
  double unsprungMass = 3.0;            // [kg], included in fork.vibratingMass (§4.2: 8 kg wheel + 3 kg)
  double unsprungMassSigma = 0.5;       // [kg] prior standard uncertainty
};

class ForkLumpedGapProblem : public ConditionSeriesProblem {
 public:
  static Result<std::unique_ptr<ForkLumpedGapProblem>> create(const ForkLumpedGapInput& in);

  std::string dataKind() const override { return "modes"; }
  std::vector<Parameter> calibrationParameters() const override;
  std::vector<Candidate> candidates() const override;
  GapMetrics metrics(const ModelPoint& at) const override;

  // [frequency Hz, (static lateral stiffness N/m)] for the given effect;
  // at.theta = nullptr means the nominal unsprung mass.
  std::vector<double> predict(const ModelPoint& at) const override;

 protected:
  std::unique_ptr<GapProblem> withPoints(std::vector<ConditionPoint> points) const override;

 private:
  ForkLumpedGapProblem(ForkLumpedGapInput in, std::vector<ConditionPoint> points)
      : ConditionSeriesProblem(std::move(points), "relative_residual"), in_(std::move(in)) {}
  ForkLumpedGapInput in_;
};

struct StiffnessEstimate {
  std::string configuration;  // "with wheel", "fork alone"
  double value = 0.0;         // [N m/rad] or [N/m]
  double sigma = 0.0;         // standard uncertainty, same unit
};

class StiffnessEstimatesGapProblem : public ConditionSeriesProblem {
 public:
  static Result<std::unique_ptr<StiffnessEstimatesGapProblem>> create(std::vector<StiffnessEstimate> estimates,
                                                                      std::string unit);

  std::string dataKind() const override { return "stiffness"; }
  std::vector<Parameter> calibrationParameters() const override;
  std::vector<Candidate> candidates() const override;

  std::vector<double> predict(const ModelPoint& at) const override;
  double reference() const { return reference_; }

 protected:
  std::unique_ptr<GapProblem> withPoints(std::vector<ConditionPoint> points) const override;

 private:
  StiffnessEstimatesGapProblem(std::vector<ConditionPoint> points, std::string unit, double reference)
      : ConditionSeriesProblem(std::move(points), "relative_residual"), unit_(std::move(unit)), reference_(reference) {}
  std::string unit_;
  double reference_ = 1.0;  // theta = 1 is this stiffness (the first estimate)
};

}  // namespace mozzi::core::gap
