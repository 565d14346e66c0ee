#pragma once
// The inputs of the lumped fork models (thesis §4.2, Table 12) and of the
// bicycle-fork stiffness and damping (§6.4, §6.5) as parameter specs, so the
// Lumped Fork page builds its forms from them (views/panels/parameter_form)
// with the ranges `mozzi-cli fork` accepts; the conversions to
// core/stiffness/fork_models.h's inputs; the models' JSON (the keys of
// `mozzi-cli fork lumped --json`), which the page stores as a project model
// of kind "lumped".
//
// Defaults are the thesis's: Table 12's inputs for the enduro fork (k from
// Table 10, mode from Table 11), Table 21 and the carbon fork's modes of
// Tables 19 and 20 for the bicycle fork, with the blade-tip distance d =
// 0.060 m that docs/validation/stiffness.md assumes (not printed).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/stiffness/fork_models.h"
#include "devices/common/parameters.h"

namespace mozzi::devices::rigtests {

std::vector<ParameterSpec> lumpedForkParameterSpecs();
core::stiffness::ForkLumpedInput lumpedForkInput(const ParameterMap& values);
// The same inputs as `mozzi-cli fork lumped` options ("--k", "28000", ...),
// numbers with 17 significant digits.
std::vector<std::string> lumpedForkCliArguments(const core::stiffness::ForkLumpedInput& in);

struct BicycleForkInput {
  core::stiffness::BicycleForkParameters parameters;
  double torsionWithWheelHz = 0.0, torsionWithWheelEta = 0.0;  // eta: hysteretic, as Tables 19, 20 print
  double torsionAloneHz = 0.0, torsionAlone2Hz = 0.0;          // second: 0 when one mode
  double bendingWithWheelHz = 0.0, bendingWithWheelEta = 0.0;
  double bendingAloneHz = 0.0;
};
std::vector<ParameterSpec> bicycleForkParameterSpecs();
BicycleForkInput bicycleForkInput(const ParameterMap& values);
std::vector<std::string> bicycleForkCliArguments(const BicycleForkInput& in);

// {"model1": {...}, "model2": ..., "model3": ...} with the keys of
// `mozzi-cli fork lumped --json` (stiffness_Nm_per_rad, arm_m, ...).
nlohmann::json lumpedModelsJson(const core::stiffness::ForkLumpedModels& models);
nlohmann::json lumpedInputJson(const core::stiffness::ForkLumpedInput& in);

}  // namespace mozzi::devices::rigtests
