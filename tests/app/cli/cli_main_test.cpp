// The CLI's contract as a user (or a script) sees it: exit codes and texts.
#include "app/cli/command.h"

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cstdio>
#include <fstream>
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
    // A table row whose first cell names the command ("| `twist`, `mozzi`, ..." or "| `project info`..."),
    // and the first page it links (no <regex>: gcc 12 warns inside it under the sanitizers).
    std::string pagePath;
    std::istringstream lines(index);
    for (std::string line; pagePath.empty() && std::getline(lines, line);) {
      if (line.rfind("| `", 0) != 0) continue;
      const std::string firstCell = line.substr(0, line.find('|', 1));
      const auto at = firstCell.find("`" + c.name);
      const char after = at == std::string::npos ? '\0' : firstCell[at + 1 + c.name.size()];
      if (after != '`' && after != ' ') continue;
      const auto link = line.find("(cli/");
      const auto end = line.find(".md)", link);
      if (link != std::string::npos && end != std::string::npos) pagePath = line.substr(link + 1, end + 3 - link - 1);
    }
    ASSERT_FALSE(pagePath.empty()) << "docs/cli.md has no row for '" << c.name << "'";
    const std::string page = readDoc(pagePath);
    ASSERT_FALSE(page.empty()) << c.name << ": docs/" << pagePath << " is missing";
    if (!c.options) continue;
    std::vector<std::string> names(c.options->valued.begin(), c.options->valued.end());
    names.insert(names.end(), c.options->flags.begin(), c.options->flags.end());
    for (const auto& n : c.options->numbers) names.push_back(n.name);
    for (const auto& name : names) {
      EXPECT_NE(page.find(name), std::string::npos)
          << "docs/" << pagePath << " does not name " << c.name << " " << name;
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
