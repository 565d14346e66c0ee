// Issue 17: `mozzi-cli project new` and `project demo` killed (SIGKILL) 20
// times each at random moments leave no project or a whole one: never a
// partial demo with a few specimens, never a stub that blocks the next run.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <random>
#include <thread>

#include "core/io/project_store.h"
#include "devices/sim/virtual_specimens.h"

namespace mozzi::cli {
namespace {

namespace fs = std::filesystem;

pid_t spawn(const std::vector<std::string>& args) {
  const pid_t child = ::fork();
  if (child == 0) {
    const int devnull = ::open("/dev/null", O_WRONLY);
    ::dup2(devnull, 1);
    ::dup2(devnull, 2);
    std::vector<char*> argv{const_cast<char*>(MOZZI_CLI_PATH)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(MOZZI_CLI_PATH, argv.data());
    _exit(98);
  }
  return child;
}

// Runs to completion; returns the wall time in microseconds.
long timedRun(const std::vector<std::string>& args) {
  const auto start = std::chrono::steady_clock::now();
  const pid_t child = spawn(args);
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  return static_cast<long>(
      std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start).count());
}

void killTest(const std::string& sub, std::size_t specimens) {
  const fs::path dir = fs::temp_directory_path() / ("mozzi_kill_" + sub + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string target = (dir / "p.mozzi").string();
  // Kill moments spread over a whole run (measured here, on this machine).
  const long full = timedRun({"project", sub, target});
  fs::remove(target);
  std::mt19937 rng(1717);  // fixed seed: reproducible
  std::uniform_int_distribution<long> moment(0, full + full / 4);
  int whole = 0, none = 0;
  for (int round = 0; round < 20; ++round) {
    const pid_t child = spawn({"project", sub, target});
    std::this_thread::sleep_for(std::chrono::microseconds(moment(rng)));
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    if (!fs::exists(target)) {
      ++none;
    } else {
      // A project under the name is a whole one: it opens, every specimen is
      // there and every record passes its checksum.
      auto store = core::io::ProjectStore::open(target, core::io::ProjectStore::OpenMode::ReadOnly);
      ASSERT_TRUE(store.ok()) << "round " << round << ": " << store.error().describe();
      auto summary = store->summary();
      ASSERT_TRUE(summary.ok());
      EXPECT_EQ(summary->specimens.size(), specimens) << "round " << round << ": a partial project";
      auto report = store->checkIntegrity();
      ASSERT_TRUE(report.ok());
      EXPECT_TRUE(report->ok()) << "round " << round;
      ++whole;
      store = core::Error{};
      fs::remove(target);
    }
    // Whatever the kill left, the next run succeeds.
    ASSERT_FALSE(fs::exists(target));
  }
  std::printf("project %s killed 20 times (a full run takes %.1f ms): %d left no project, %d a whole one\n",
              sub.c_str(), full / 1000.0, none, whole);
  EXPECT_GT(none, 0) << "no kill landed before the end: the test does not test";
  // A re-run after all the kills works and clears the killed runs' leftovers.
  EXPECT_EQ(timedRun({"project", sub, target}) > 0, true);
  auto store = core::io::ProjectStore::open(target, core::io::ProjectStore::OpenMode::ReadOnly);
  ASSERT_TRUE(store.ok()) << store.error().describe();
  for (const auto& e : fs::directory_iterator(dir)) {
    EXPECT_EQ(e.path().filename(), "p.mozzi") << "left behind: " << e.path();
  }
  fs::remove_all(dir);
}

TEST(ProjectKill, NewKilledAtRandomMomentsLeavesNoPartialProject) {
  killTest("new", 0);
}

TEST(ProjectKill, DemoKilledAtRandomMomentsLeavesNoPartialProject) {
  killTest("demo", devices::sim::virtualSpecimens().size());
}

}  // namespace
}  // namespace mozzi::cli
