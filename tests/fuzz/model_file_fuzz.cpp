// Fuzz target: the mozzi-model/1 reader (core/gap/structural/model_file.h).
// Whatever it accepts must be writable and read back with the same DOFs and
// matrices; nothing may crash, whatever the JSON holds.

#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "core/gap/structural/model_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace mozzi::core::gap::structural;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto model = parseModelJson(text, "fuzz.json");
  if (!model) return 0;
  auto written = writeModelJson(*model);
  if (!written) std::abort();
  auto back = parseModelJson(*written, "again.json");
  if (!back || back->dofs != model->dofs || back->springs.size() != model->springs.size() ||
      back->parameters.size() != model->parameters.size())
    std::abort();
  return 0;
}
