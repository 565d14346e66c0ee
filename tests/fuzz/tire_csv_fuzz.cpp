// Fuzz target: the tyre test file readers (core/tire/tire_csv.h) and what the
// CLI feeds their output to: harmonic yaw records into the relaxation-length
// fit (§1.9), steady-state sweeps into the slope regression (appendix 2), and
// the "a:b:c,..." option lists. Bad input must give an error, never a crash.

#include <cstdint>
#include <string>
#include <string_view>

#include "core/tire/tire_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace mozzi::core::tire;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (auto t = parseNumericTable(text, "fuzz.csv", harmonicYawColumns())) {
    // Bounded so one input stays cheap (sine fits are linear in the samples).
    if (auto recs = harmonicYawRecords(*t, "fuzz.csv"); recs && t->rows.size() <= 20000) {
      HarmonicYawSettings s;
      s.halfLength = 0.05;
      (void)relaxationFromHarmonicYaw(*recs, s);
    }
  }
  if (auto t = parseNumericTable(text, "fuzz.csv", steadyStateColumns())) {
    if (auto sweeps = steadyStateSweeps(*t, "fuzz.csv"))
      for (const auto& s : *sweeps) (void)characteriseSweep(s.sweep);
    (void)steadyStatePoints(*t);
  }
  (void)parseNumericTable(text, "fuzz.csv", {});
  for (std::size_t width = 1; width <= 3; ++width) (void)parseNumberTuples(text, width, "--fuzz");
  return 0;
}
