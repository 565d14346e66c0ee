// Stability gap problem on published data (docs/gap.md "Stability"): the
// weave and wobble frequencies Sharp (1971) published for his own model
// (shared/data/motorcycle/README.md) against core/stability's model built from
// the third-party transcription of his parameters. The thesis's §4.2 multibody
// motorcycle is not available, so this is the reference for the rigid-fork
// model the §4.2/§6.6 fork effects are added to.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/gap/diagnosis.h"
#include "core/gap/stability/stability_problem.h"

namespace mozzi::core::gap {
namespace {

constexpr double kTwoPi = 6.28318530717958647692;

TEST(GapThesisStability, SharpPublishedFrequenciesAgainstTheTranscription) {
  const std::string json = R"({"schema": "mozzi-stability-gap/1", "vehicle": "motorcycle", "parameters": ")" +
                           std::string(MOZZI_SHARED_DATA_DIR) + "/motorcycle/sharp1971-parameters.csv\"}";
  auto model = parseStabilityGapModel(json, "sharp", "");
  ASSERT_TRUE(model) << model.error().describe();
  // Published Im(lambda) / 2 pi at 30-160 ft/s, 0.05 rad/s uncertainty (half a
  // unit of the printed last digit): docs/gap/sharp1971-published-modes.csv,
  // checked here against the README's table.
  auto text = readTextFile(std::string(MOZZI_SOURCE_DIR) + "/docs/gap/sharp1971-published-modes.csv");
  ASSERT_TRUE(text);
  auto published = parseModeFrequencyCsv(*text, "sharp1971-published-modes.csv");
  ASSERT_TRUE(published) << published.error().describe();
  const double weave[] = {4.56, 11.4, 16.8, 19.2, 20.4, 21.2};
  const double wobble[] = {55.5, 54.6, 54.0, 54.3, 55.6, 57.5};
  ASSERT_EQ(published->size(), 12u);
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_NEAR((*published)[2 * i].frequencyHz * kTwoPi, weave[i], 1e-4);  // 5 decimals in the file
    EXPECT_NEAR((*published)[2 * i + 1].frequencyHz * kTwoPi, wobble[i], 1e-4);
  }
  auto p = StabilityGapProblem::create(*model, *published);
  ASSERT_TRUE(p) << p.error().describe();
  DiagnosisOptions o;
  o.bootstrapSamples = 50;  // kept small: every refit sweeps the modes (about 1 ms per evaluation)
  o.multistarts = 3;
  o.nullMethod = NullMethod::Linearised;
  const auto d = diagnose(**p, o);
  ASSERT_TRUE(d) << d.error().describe();
  std::printf("Sharp 1971 published vs transcription: verdict %s\n  %s\n", verdictName(d->verdict),
              d->explanation.c_str());
  for (const auto& e : d->gapBefore.entries)
    std::printf(e.kind == "condition" ? "  %-28s %+6.2f%%  z %+7.1f\n" : "  %-28s %6.2f m/s\n", e.label.c_str(),
                e.value, e.z);
  // The transcription reproduces the frequencies to a few per cent
  // (stability_motorcycle_test: weave within 5%, wobble 2%), far beyond the
  // 3-figure rounding: the gap is real. Neither a compliant fork nor another
  // relaxation length accounts for it (the README names the cause: the front
  // frame's mass centre is not tabulated), so the verdict must not name one.
  EXPECT_LT(d->fitPValue, 1e-6);
  EXPECT_TRUE(d->verdict == Verdict::Unexplained || d->verdict == Verdict::Partial) << verdictName(d->verdict);
  for (const auto& e : d->gapBefore.entries) {
    if (e.kind != "condition") continue;  // the critical-speed rows are predictions, not data
    EXPECT_LT(std::abs(e.value), 5.0) << e.label;
  }
}

}  // namespace
}  // namespace mozzi::core::gap
