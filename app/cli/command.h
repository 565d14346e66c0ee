#pragma once
// mozzi-cli subcommands. Each subcommand lives in app/cli/commands/<name>.cpp and
// registers itself with a static CommandRegistrar, so adding a command touches
// no shared file. Exit codes (docs/cli.md): 0 success; 1 the input could not be
// processed (a file, or an option's value outside its stated range, a failed
// write, a failed identification), the message naming the file or option;
// 2 usage error (unknown command or option, a missing argument).

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "app/cli/args.h"

namespace mozzi::cli {

enum ExitCode : int { kExitOk = 0, kExitFailure = 1, kExitUsage = 2 };

struct Command {
  std::string name;      // first word after mozzi-cli, e.g. "frf" or "uff"
  std::string synopsis;  // argument summary shown by --help, e.g. "HITS.uff --estimator H1|H2|Hv [--json]"
  std::string summary;   // one line saying what it does
  std::function<int(const std::vector<std::string>& args, std::ostream& out, std::ostream& err)> run;
  // The command's option table (numeric ranges, output files), shown by
  // 'mozzi-cli COMMAND --help'; the same object the command parses with.
  const OptionSpec* options = nullptr;
};

// All registered commands, sorted by name.
std::vector<Command> registeredCommands();

struct CommandRegistrar {
  explicit CommandRegistrar(Command command);
};

// The whole CLI: argv without the program name. Handles --help, --version,
// dispatch, and usage errors (exit 2).
int runCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

// The text of --help.
std::string usageText();

}  // namespace mozzi::cli
