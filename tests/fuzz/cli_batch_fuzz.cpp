// Fuzz target: the batch file of `mozzi-cli run` (app/cli/batch_script.h).
// Whatever parses must expand for every project without crashing; an error
// names its place and carries at most a bounded excerpt of the input.

#include <cstdint>
#include <cstdlib>
#include <string>

#include "app/cli/batch_script.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace mozzi::cli;
  const std::string text(reinterpret_cast<const char*>(data), size);
  auto script = parseBatchScript(text, "fuzz.json");
  if (!script) {
    if (script.error().where.rfind("fuzz.json", 0) != 0) std::abort();  // the place is always named
    if (script.error().message.size() > 4096) std::abort();             // the whole input in a message
    return 0;
  }
  if (script->projects.empty() || script->steps.empty()) std::abort();  // a runnable file has both
  for (const auto& project : script->projects) {
    for (std::size_t s = 0; s < script->steps.size(); ++s) {
      auto argv = expandBatchStep(*script, s, project);
      if (!argv) {
        if (argv.error().message.size() > 4096) std::abort();
        continue;
      }
      if (argv->size() != script->steps[s].argv.size()) std::abort();  // one argument per argument
    }
  }
  return 0;
}
