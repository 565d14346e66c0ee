#pragma once
// A Diagnosis as JSON in the schema of issue 10 ("Command line"): gap_before,
// where, verdict, ranking[] (effect, location, parameters, std_errors,
// criterion, gap_after, shrink_pct) and best; documented in docs/gap.md.

#include <nlohmann/json.hpp>

#include "core/gap/diagnosis.h"

namespace mozzi::core::gap {

// Metrics as {"<residualName>": overall, "overall": overall, "<kind>s": [rows]}.
nlohmann::json metricsToJson(const GapMetrics& metrics);
nlohmann::json diagnosisToJson(const Diagnosis& diagnosis);

}  // namespace mozzi::core::gap
