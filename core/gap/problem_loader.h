#pragma once
// Chooses and builds the gap problem from the files a user names
// (`mozzi-cli gap --model MODEL --measured TEST`, the "Model vs test" view):
//  - model "mozzi-model/1" JSON or a UFF 55 modal model -> structural problem,
//    with UFF 58 FRFs (any FRF type) or UFF 55 identified modes as the test;
//  - "mozzi-tire-gap/1" and "mozzi-stability-gap/1" -> the tyre and stability
//    problems (core/gap/tire, core/gap/stability).

#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/common/result.h"
#include "core/gap/gap_problem.h"

namespace mozzi::core::gap {

struct LoadOptions {
  double bandLowHz = 0.0;  // fitted band (structural data)
  double bandHighHz = std::numeric_limits<double>::infinity();
  std::vector<std::pair<double, double>> reportBands;  // "where" bands; empty = octaves
  // FRF noise model (structural::StructuralOptions::NoiseSource): "auto"
  // (coherence when the file has it, else estimated from the data),
  // "estimated", "coherence" or "stated" (relativeFloor and additiveFloor).
  std::string noise = "auto";
  double relativeFloor = 0.01;  // stated relative sigma per component
  double additiveFloor = 0.0;   // stated additive sigma per component, in the FRF's unit
  int averages = 10;            // averages behind the coherence (noise from coherence)
};

// The schema of a JSON model file ("mozzi-model/1", ...), or "uff" for a
// Universal File; an error when the file is neither.
Result<std::string> modelFileKind(const std::string& modelPath);

Result<std::unique_ptr<GapProblem>> loadGapProblem(const std::string& modelPath, const std::string& measuredPath,
                                                   const LoadOptions& options);

}  // namespace mozzi::core::gap
