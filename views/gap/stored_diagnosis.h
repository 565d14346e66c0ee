#pragma once
// A gap diagnosis kept in the project (an analysis of kind "gap-diagnosis",
// core/report/gap_report.h analysisFromDiagnosis) read back for the Model vs
// Test page: what the page shows of a diagnosis (verdict, explanation, the gap
// before by kind, the ranked effects, the overlay curves before and after the
// best effect) without the model and test files it was run on.

#include <limits>
#include <string>
#include <vector>

#include "core/common/result.h"
#include "core/gap/gap_problem.h"

namespace mozzi::views {

struct StoredDiagnosis {
  struct Parameter {
    std::string name, unit;
    double value = 0.0;
    double stdError = -1.0;  // < 0: not stored
  };
  struct RankedEffect {
    std::string effect;
    std::vector<std::string> location;
    // The other locations of a family that changes the data alike
    // (diagnosis JSON "equivalent_locations"); empty when alone.
    std::vector<std::vector<std::string>> equivalent;
    std::vector<Parameter> parameters;
    bool identifiable = true;
    bool inVerdict = false;
    double likelihoodRatio = 0.0;
    double heldOutImprovement = 0.0;  // fraction by which the held-out residual is lower
    double shrinkPct = 0.0;
    double gapAfter = 0.0;  // in-sample gap with the effect (gap_after.overall)
  };
  std::string name;     // the analysis's name (set by the page that reads it)
  std::string verdict;  // "effect", "none", "ambiguous", "partial", "unexplained", "not_identifiable"
  std::string explanation;
  double threshold = 0.0;
  core::gap::GapMetrics gapBefore;
  std::vector<RankedEffect> ranking;
  int best = -1;      // the ranking row the verdict puts forward (-1: none)
  bool pair = false;  // the verdict names two effects fitted together
  double pairHeldOutImprovement = std::numeric_limits<double>::quiet_NaN();  // the pair's, when pair
  std::vector<core::gap::OverlayCurve> before, after;
  std::string afterLabel;
};

// Parses an analysis's result JSON; an error names what is missing.
core::Result<StoredDiagnosis> parseStoredDiagnosis(const std::string& resultJson);

}  // namespace mozzi::views
