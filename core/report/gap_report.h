#pragma once
// The gap diagnosis in a report (issue 23): the one place that says which
// effect a diagnosis puts forward ("best effect") and the one builder of its
// report section, used by the Model vs Test page, `mozzi-cli gap` and the
// project report.

#include <string>

#include "core/gap/diagnosis.h"
#include "core/io/project_records.h"
#include "core/report/report.h"

namespace mozzi::core::report {

// The effect(s) a diagnosis puts forward.
struct BestEffect {
  // Two effects at once (issue 16): the verdict names both members of the pair.
  const gap::EffectPair* pair = nullptr;
  // The first effect of the verdict set; when the verdict set is empty, the
  // top-ranked effect (inVerdict false), which the overlay still draws.
  const gap::RankedEffect* single = nullptr;
  bool inVerdict = false;
};
BestEffect bestEffect(const gap::Diagnosis& diagnosis);

// "(global)" or the location parts joined by " - ".
std::string locationText(const gap::Candidate& candidate);

// Section "gap" for a diagnosis of `model` against `test` (file names or
// record names): verdict and explanation, gap before and where, the ranked
// effects (size ± standard error, likelihood ratio, threshold, held-out gain,
// shrink) and a "gap-overlay" figure placeholder.
Section gapDiagnosisSection(const gap::Diagnosis& diagnosis, const std::string& model, const std::string& test);

// The blocks of a gap diagnosis stored in the project (findings table, and
// the verdict when its result JSON holds one).
std::vector<Block> storedAnalysisBlocks(const io::StoredAnalysis& analysis);

}  // namespace mozzi::core::report
