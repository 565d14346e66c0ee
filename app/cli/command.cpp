#include "app/cli/command.h"

#include <algorithm>
#include <map>
#include <ostream>
#include <sstream>

#include "app/build_info.h"
#include "core/common/versions.h"
#include "devices/common/versions.h"

namespace mozzi::cli {
namespace {

std::map<std::string, Command>& registry() {
  static std::map<std::string, Command> commands;
  return commands;
}

}  // namespace

CommandRegistrar::CommandRegistrar(Command command) {
  const std::string name = command.name;
  registry().emplace(name, std::move(command));
}

std::vector<Command> registeredCommands() {
  std::vector<Command> out;
  for (const auto& [name, command] : registry()) out.push_back(command);
  return out;
}

std::string usageText() {
  std::ostringstream text;
  text << "Usage: mozzi-cli [--help | --version]\n"
          "       mozzi-cli COMMAND [ARGS...]\n\n"
          "Batch computations of the Mozzi workbench on the same files the GUI uses.\n\n"
          "Commands:\n";
  std::size_t width = 0;
  for (const auto& c : registeredCommands()) width = std::max(width, c.name.size());
  for (const auto& c : registeredCommands()) {
    text << "  " << c.name << std::string(width - c.name.size() + 2, ' ') << c.summary << "\n"
         << "  " << std::string(width + 2, ' ') << "mozzi-cli " << c.name << " " << c.synopsis << "\n";
  }
  text << "\n'mozzi-cli COMMAND --help' describes one command with its options' valid ranges.\n"
          "Exit status: 0 done; 1 the input could not be processed (a file, or a value outside\n"
          "its range; the message names it); 2 usage error.\n";
  return text.str();
}

std::string versionText() {
  std::ostringstream text;
  text << "mozzi-cli " << buildinfo::kMozziVersion << "\n";
  for (const auto& [name, version] : core::coreLibraryVersions()) text << name << " " << version << "\n";
  for (const auto& [name, version] : devices::deviceLibraryVersions()) text << name << " " << version << "\n";
  // The CLI does not link the GUI libraries; these are the versions the GUI of
  // this build was compiled against (the GUI's About box reads them at run time).
  text << "Qt " << buildinfo::kQtVersion << " (GUI build)\n"
       << "Qwt " << buildinfo::kQwtVersion << " (GUI build)\n"
       << "VTK " << buildinfo::kVtkVersion << " (GUI build)\n";
  return text.str();
}

int runCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (args.empty()) {
    err << usageText();
    return kExitUsage;
  }
  const std::string& first = args.front();
  if (first == "--help" || first == "-h" || first == "help") {
    out << usageText();
    return kExitOk;
  }
  if (first == "--version" || first == "-V") {
    out << versionText();
    return kExitOk;
  }
  const auto& commands = registry();
  const auto it = commands.find(first);
  if (it == commands.end()) {
    err << "mozzi-cli: unknown command '" << first << "'\n\n" << usageText();
    return kExitUsage;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (!rest.empty() && (rest.front() == "--help" || rest.front() == "-h")) {
    out << "Usage: mozzi-cli " << it->second.name << " " << it->second.synopsis << "\n" << it->second.summary << "\n";
    if (it->second.options) out << it->second.options->helpText();
    return kExitOk;
  }
  return it->second.run(rest, out, err);
}

}  // namespace mozzi::cli
