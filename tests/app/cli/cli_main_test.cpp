// The CLI's contract as a user (or a script) sees it: exit codes and texts.
#include "app/cli/command.h"

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cstdio>
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
TEST(Cli, ExecutableExitCodes) {
  const std::string cli = MOZZI_CLI_PATH;
  EXPECT_EQ(std::system((cli + " --version > /dev/null").c_str()), 0);
  const int status = std::system((cli + " bogus > /dev/null 2>&1").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
}

}  // namespace
}  // namespace mozzi::cli
