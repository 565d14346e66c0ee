// The CLI's contract as a user (or a script) sees it: exit codes and texts.
#include "app/cli/command.h"

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>

#include "cli_run.h"
#include "core/common/versions.h"

namespace mozzi::cli {
namespace {

TEST(Cli, VersionListsTheLinkedLibraries) {
  const CliRun r = run({"--version"});
  EXPECT_EQ(r.code, kExitOk);
  for (const auto& [name, version] : core::coreLibraryVersions()) {
    EXPECT_NE(r.out.find(name + " " + version), std::string::npos) << name;
  }
  EXPECT_NE(r.out.find(std::string("SQLite ") + sqlite3_libversion()), std::string::npos);
  for (const char* gui : {"Qt ", "Qwt ", "VTK ", "libusb "}) EXPECT_NE(r.out.find(gui), std::string::npos) << gui;
}

TEST(Cli, UnknownCommandExitsTwoWithUsage) {
  const CliRun r = run({"no-such-command"});
  EXPECT_EQ(r.code, kExitUsage);
  EXPECT_NE(r.err.find("unknown command 'no-such-command'"), std::string::npos);
  EXPECT_NE(r.err.find("Usage: mozzi-cli"), std::string::npos);
  EXPECT_EQ(run({}).code, kExitUsage);
}

TEST(Cli, HelpListsEveryRegisteredCommand) {
  const CliRun r = run({"--help"});
  EXPECT_EQ(r.code, kExitOk);
  ASSERT_FALSE(registeredCommands().empty());
  for (const auto& c : registeredCommands()) EXPECT_NE(r.out.find("mozzi-cli " + c.name), std::string::npos) << c.name;
}

// The real executable, as a shell would run it.
std::string readDoc(const std::string& relative) {
  std::ifstream in(std::string(MOZZI_SOURCE_DIR) + "/docs/" + relative, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The CLI reference against the program (issue 23): every command of --help
// has a row in docs/cli.md's command table linking to its page, and that page
// names every option the command's own table declares.
TEST(Cli, ReferenceDocumentsEveryCommandAndOption) {
  const std::string index = readDoc("cli.md");
  ASSERT_FALSE(index.empty());
  for (const auto& c : registeredCommands()) {
    // A table row whose first cell names the command ("| `twist`, `mozzi`, ..." or "| `project info`...").
    const std::regex row("\\n\\|[^|\\n]*`" + c.name + "[` ][^\\n]*?\\((cli/[a-z_-]+\\.md)\\)");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(index, m, row)) << "docs/cli.md has no row for '" << c.name << "'";
    const std::string page = readDoc(m[1].str());
    ASSERT_FALSE(page.empty()) << c.name << ": docs/" << m[1].str() << " is missing";
    if (!c.options) continue;
    std::vector<std::string> names(c.options->valued.begin(), c.options->valued.end());
    names.insert(names.end(), c.options->flags.begin(), c.options->flags.end());
    for (const auto& n : c.options->numbers) names.push_back(n.name);
    for (const auto& name : names) {
      EXPECT_NE(page.find(name), std::string::npos)
          << "docs/" << m[1].str() << " does not name " << c.name << " " << name;
    }
  }
}

TEST(Cli, ExecutableExitCodes) {
  const std::string cli = MOZZI_CLI_PATH;
  EXPECT_EQ(std::system((cli + " --version > /dev/null").c_str()), 0);
  const int status = std::system((cli + " bogus > /dev/null 2>&1").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
}

}  // namespace
}  // namespace mozzi::cli
