// Fuzz target: the plate CSV reader of `mozzi-cli twist`/`mozzi` and the Twist
// Axes page (core/stiffness/plate_csv.h) and what both feed its output to:
// the kind guess, the static, dynamic and modal interpretations, the twist
// axes they give and the imported-test view the page draws. Bad input must
// give an error, never a crash.

#include <cstdint>
#include <string>

#include "core/stiffness/dynamic_twist.h"
#include "core/stiffness/plate_csv.h"
#include "devices/rigtests/imported_twist.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace st = mozzi::core::stiffness;
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (bool needSensors : {true, false}) {
    auto csv = st::parsePlateCsv(text, "fuzz.csv", needSensors, false);
    if (!csv || csv->rows.size() > 2000 || csv->sensors.size() > 64) continue;  // bounded work per input
    (void)st::guessPlateCsvKind(*csv);
    (void)mozzi::devices::rigtests::staticViewFromCsv(*csv, "fuzz");
    (void)mozzi::devices::rigtests::dynamicViewFromCsv(*csv, "fuzz");
    if (auto frf = st::modalFrfFromCsv(*csv, mozzi::core::FrfType::Accelerance)) {
      const auto peaks = st::frfPeakFrequencies(*frf, 2);
      std::vector<int> cols;
      for (std::size_t i = 0; i < csv->sensors.size(); ++i) cols.push_back(static_cast<int>(i));
      for (double f : peaks) (void)st::modalTwistAxis(*frf, cols, 0, f, csv->sensors, csv->load);
    }
  }
  return 0;
}
