// Real data (issue 16): the ModeLAB free-free beam's nine measured
// accelerances (shared/data/modelab-beam) against an Euler-Bernoulli model
// built from the beam's geometry (tests/validation/gap/modelab_beam_model.h).
// The worked example of docs/gap.md: the noise model is estimated from the
// data (the export has no coherence), the calibration takes EI, rho A and the
// damping level, and the verdict is pinned here.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "core/gap/diagnosis.h"
#include "core/gap/diagnosis_json.h"
#include "core/gap/structural/structural_problem.h"
#include "core/io/uff/uff.h"
#include "validation/gap/modelab_beam_model.h"

namespace mozzi::gap_bench {
namespace {

TEST(GapModelabBeam, WorkedExample) {
  const auto model = modelabBeamModel();
  // 65 Hz (setup.csv fMin) to 1000 Hz, every 32nd line (0.625 Hz): 1,497 lines.
  auto frf = modelabBeamFrfs(32, 65.0, 1000.0);
  ASSERT_TRUE(frf.ok()) << frf.error().describe();
  // The files a user hands to `mozzi-cli gap` (docs/gap.md).
  {
    auto text = core::gap::structural::writeModelJson(model);
    ASSERT_TRUE(text.ok());
    std::ofstream(std::string(MOZZI_BINARY_DIR) + "/gap_modelab_beam.json") << *text;
    auto records = core::io::uff::fromFrfMatrix(*frf);
    ASSERT_TRUE(records.ok());
    core::io::uff::UffFile file;
    for (auto& r : *records) file.datasets.push_back(core::io::uff::makeDataset(std::move(r)));
    ASSERT_TRUE(core::io::uff::writeFile(std::string(MOZZI_BINARY_DIR) + "/gap_modelab_beam.uff", file).ok());
  }
  auto problem = core::gap::structural::makeFrfProblem(model, *frf);
  ASSERT_TRUE(problem.ok()) << problem.error().describe();
  core::gap::DiagnosisOptions opt;
  opt.bootstrapSamples = 40;
  opt.multistarts = 4;
  auto d = core::gap::diagnose(**problem, opt);
  ASSERT_TRUE(d.ok()) << d.error().describe();
  std::printf("%s\n", core::gap::diagnosisToJson(*d).dump(1).substr(0, 20000).c_str());
  std::printf("verdict %s\n%s\n", core::gap::verdictName(d->verdict), d->explanation.c_str());
  // Pinned (25 Nov 2026): the export has no coherence, so the noise model is
  // estimated from the data; the calibrated geometry model stays far from the
  // measurement (chi-square 5.07e6 on 26,943 degrees of freedom) and the best
  // candidate (a 0.145 kg mass at hammer point 8) makes the held-out bands
  // worse, so nothing is attributed: `unexplained`, no effect named.
  EXPECT_EQ(d->noise.source, "estimated");
  EXPECT_EQ(d->verdict, core::gap::Verdict::Unexplained) << d->explanation;
  EXPECT_TRUE(d->verdictSet.empty());
  ASSERT_FALSE(d->ranking.empty());
  EXPECT_LT(d->ranking[0].heldOutImprovement, 0.0);
}

}  // namespace
}  // namespace mozzi::gap_bench
