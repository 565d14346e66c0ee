// Fuzz target: the files of the tyre and stability gap problems
// (mozzi-tire-gap/1 and mozzi-stability-gap/1 JSON, the relaxation-length and
// mode-frequency CSVs, docs/formats.md). Whatever is accepted must build a
// problem or give an error; nothing may crash.

#include <cstdint>
#include <string>

#include "core/gap/stability/stability_problem.h"
#include "core/gap/tire/tire_problem.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace mozzi::core::gap;
  const std::string text(reinterpret_cast<const char*>(data), size);
  auto tyre = parseTireGapModel(text, "fuzz.json");
  auto sigma = parseRelaxationCsv(text, "fuzz.csv");
  if (tyre) {
    // A parsed model with one plausible measurement, and with the fuzzed one.
    (void)TireGapProblem::create(*tyre, {{"", 2.0, 0.15, 0.01, 0}});
    if (sigma) (void)TireGapProblem::create(*tyre, *sigma);
  }
  // No parameter files are read from fuzz input: the bicycle uses its built-in data.
  auto stab = parseStabilityGapModel(text, "fuzz.json", "");
  auto modes = parseModeFrequencyCsv(text, "fuzz.csv");
  if (stab && stab->vehicle == StabilityVehicle::Bicycle && modes && modes->size() <= 8) {
    for (auto& m : *modes)
      if (m.speed > 60.0) m.speed = 60.0;  // keep the mode-tracking grid small
    (void)StabilityGapProblem::create(*stab, *modes);
  }
  return 0;
}
