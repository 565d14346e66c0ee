#include "devices/campaign/frf_set_window.h"

#include <string>

#include "devices/campaign/campaign_definition.h"

namespace mozzi::devices::campaign {

core::Result<double> frfSetExponentialTauS(const core::io::ProjectStore& store, std::int64_t frfSetId) {
  auto sets = store.frfSets();
  if (!sets) return sets.error();
  for (const auto& s : *sets) {
    if (s.id != frfSetId) continue;
    if (!s.campaignId) return 0.0;
    auto c = store.campaign(*s.campaignId);
    if (!c) return c.error();
    if (c->settingsJson.empty() || c->settingsJson == "{}") return 0.0;
    auto def = parseDefinition(c->settingsJson);
    if (!def) return def.error();
    return def->windows.exponentialTauS;
  }
  return core::makeError(
      core::ErrorCode::NotFound,
      "the project has no FRF set " + std::to_string(frfSetId) + " (mozzi-cli project info lists them)", "FRF set");
}

}  // namespace mozzi::devices::campaign
