// mozzi-cli project: create, inspect and demo projects.
#include <ostream>

#include "app/build_info.h"
#include "app/cli/args.h"
#include "app/cli/command.h"
#include "core/io/project_store.h"
#include "devices/sim/virtual_specimens.h"

namespace mozzi::cli {
namespace {

int projectCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const auto parsed = ParsedArgs::parse(args, OptionSpec{{}, {"--json"}});
  if (!parsed || parsed->positional().size() != 2) {
    err << "mozzi-cli project: " << (parsed ? "expected a subcommand and a file" : parsed.error().describe())
        << "\nUsage: mozzi-cli project info|new|demo FILE.mozzi\n";
    return kExitUsage;
  }
  const std::string& sub = parsed->positional()[0];
  const std::string& file = parsed->positional()[1];
  if (sub == "new") {
    auto store = core::io::ProjectStore::create(file, buildinfo::kMozziVersion);
    if (!store) {
      err << "mozzi-cli project new: " << store.error().describe() << "\n";
      return kExitFailure;
    }
    out << "created " << file << " (schema " << store->schemaVersion() << ")\n";
    return kExitOk;
  }
  if (sub == "demo") {
    if (auto r = devices::sim::createDemoProject(file, buildinfo::kMozziVersion); !r) {
      err << "mozzi-cli project demo: " << r.error().describe() << "\n";
      return kExitFailure;
    }
    out << "created demo project " << file << " with " << devices::sim::virtualSpecimens().size()
        << " virtual specimens\n";
    return kExitOk;
  }
  if (sub == "info") {
    auto store = core::io::ProjectStore::open(file, core::io::ProjectStore::OpenMode::ReadOnly);
    if (!store) {
      err << "mozzi-cli project info: " << store.error().describe() << "\n";
      return kExitFailure;
    }
    auto summary = store->summary();
    if (!summary) {
      err << "mozzi-cli project info: " << summary.error().describe() << "\n";
      return kExitFailure;
    }
    out << "project " << file << "\n  schema " << summary->schemaVersion << ", created " << summary->createdUtc
        << " by Mozzi " << summary->mozziVersion << "\n  specimens: " << summary->specimens.size() << "\n";
    for (const auto& sp : summary->specimens) out << "    " << sp.name << " [" << sp.kind << "]\n";
    for (const auto& c : summary->counts) out << "  " << c.table << ": " << c.rows << " rows\n";
    return kExitOk;
  }
  err << "mozzi-cli project: unknown subcommand '" << sub << "'\nUsage: mozzi-cli project info|new|demo FILE.mozzi\n";
  return kExitUsage;
}

const CommandRegistrar kRegistrar({"project", "info|new|demo FILE.mozzi",
                                   "Create a project (empty or the demo) or summarise one", projectCommand});

}  // namespace
}  // namespace mozzi::cli
