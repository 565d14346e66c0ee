// Fuzz target: the campaign definition reader (devices/campaign/
// campaign_definition.h), i.e. campaign.settings_json of a project, which a
// hostile or damaged file may hold. Whatever it accepts must validate, be
// written and read back to the same JSON; nothing may crash.

#include <cstdint>
#include <cstdlib>
#include <string>

#include "devices/campaign/campaign_definition.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace mozzi::devices::campaign;
  const std::string text(reinterpret_cast<const char*>(data), size);
  auto d = parseDefinition(text);
  if (!d) return 0;
  if (!d->validate()) std::abort();
  const std::string once = definitionToJson(*d).dump();
  auto back = parseDefinition(once);
  if (!back || definitionToJson(*back).dump() != once) std::abort();
  (void)d->recordScans();
  (void)d->frfOptions();
  (void)acquisitionConfigFor(*d, d->points.front());
  return 0;
}
