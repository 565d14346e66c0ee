// Fuzz target: the CLI's option parser with every command's range table
// (app/cli/args.h). Input: arguments separated by newlines. Whatever is
// accepted must lie inside its declared range; nothing may crash, and no
// error message may carry more than a bounded excerpt of its input.

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/cli/args.h"
#include "app/cli/command.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace mozzi::cli;
  std::vector<std::string> args(1);
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == '\n') {
      args.emplace_back();
    } else {
      args.back() += static_cast<char>(data[i]);
    }
  }
  for (const auto& command : registeredCommands()) {
    if (!command.options) continue;
    auto parsed = ParsedArgs::parse(args, *command.options);
    if (!parsed) {
      if (parsed.error().message.size() > 4096) std::abort();  // the whole input in a message
      continue;
    }
    for (const auto& option : command.options->numbers) {
      if (!parsed->value(option.name)) continue;
      const auto values = parsed->numbers(option.name);
      for (std::size_t k = 0; k < values.size(); ++k) {
        const NumberRange& range = option.fields.empty() ? option.range : option.fields[k % option.fields.size()].range;
        if (!range.contains(values[k])) std::abort();  // accepted outside its range
      }
    }
  }
  for (const auto& a : args) (void)parseInRange(a, closed(-1, 1), "fuzz");
  return 0;
}
