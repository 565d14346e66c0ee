#pragma once
// The gap diagnosis in a report (issue 23): the one place that says which
// effect a diagnosis puts forward ("best effect") and the one builder of its
// report section, used by the Model vs Test page, `mozzi-cli gap` and the
// project report.

#include <string>

#include "core/gap/diagnosis.h"
#include "core/io/project_records.h"
#include "core/report/report.h"
#include "core/report/report_text.h"

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
// "residual_mode at 1+Y": the effect and its location (parts joined by ", "),
// as the overlay's legend names it; the effect alone when it is global. Two
// residual modes read "model + residual_mode + residual_mode" without it.
std::string effectAtLocation(const gap::Candidate& candidate);

// Section "gap" for a diagnosis of `model` against `test` (file names or
// record names): verdict and explanation, gap before and where, the ranked
// effects (size ± standard error, likelihood ratio, threshold, held-out gain,
// shrink) and a "gap-overlay" figure placeholder.
Section gapDiagnosisSection(const gap::Diagnosis& diagnosis, const std::string& model, const std::string& test,
                            const Texts& texts = Texts());

// The blocks of a gap diagnosis stored in the project (findings table, the
// verdict when its result JSON holds one, and a "gap-overlay" figure of the
// analysis when it holds overlay curves, storedOverlayJson below).
std::vector<Block> storedAnalysisBlocks(const io::StoredAnalysis& analysis, const Texts& texts = Texts());

// The analysis record of a diagnosis of `problem` (its findings: the verdict's
// effect, or each flagged band when no effect explains the gap; resultJson:
// diagnosisToJson plus "overlay", the measured and model curves before and
// after the best effect with at most `maxPoints` points each, so a report can
// draw them without the model and test files). specimenId and the record
// links are the caller's.
io::StoredAnalysis analysisFromDiagnosis(const gap::GapProblem& problem, const gap::Diagnosis& diagnosis,
                                         const std::string& name, int maxCurves = 4, int maxPoints = 400);

}  // namespace mozzi::core::report
