// The kill test of issue 15: `mozzi-cli campaign run` (the real executable,
// a child process) is SIGKILLed 20 times at random moments and run again
// each time, which resumes the campaign; then it runs to the end. Every hit
// the killed runs committed must still be there, bit for bit, and the whole
// campaign (hits, flags, FRF set) must equal an uninterrupted run with the
// same seed. Kill moments: 0.3 s plus a uniform share of up to 5% of an
// uninterrupted run's wall time after the start (fixed generator seed), so
// that kills land in start-up, in acquisition, in commits and, for the last
// runs, in the final FRF computation, and 20 kills fit in one campaign.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <random>
#include <thread>

#include "core/io/project_store.h"
#include "devices/campaign/campaign_store.h"

namespace mozzi::cli {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

const char* const kSpecimen = "frame-a-front-constrained";

pid_t spawnCampaign(const std::string& project) {
  const pid_t pid = fork();
  if (pid == 0) {
    const int devnull = ::open("/dev/null", O_WRONLY);
    ::dup2(devnull, STDOUT_FILENO);
    ::dup2(devnull, STDERR_FILENO);
    execl(MOZZI_CLI_PATH, MOZZI_CLI_PATH, "campaign", "run", project.c_str(), "--specimen", kSpecimen, "--rig",
          "sim-hammer", "--hits", "5", "--seed", "2024", static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

// Exit status of a child run to its end.
int runToEnd(const std::string& project) {
  const pid_t pid = spawnCampaign(project);
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

struct Snapshot {
  std::vector<core::io::HitInfo> hits;
  std::vector<Eigen::MatrixXf> samples;
};

Snapshot snapshot(const std::string& project) {
  Snapshot s;
  auto store = core::io::ProjectStore::open(project, core::io::ProjectStore::OpenMode::ReadOnly);
  if (!store) return s;
  auto h = store->hits(1);
  if (!h) return s;
  s.hits = *h;
  for (const auto& info : s.hits) s.samples.push_back(store->hit(info.id)->samples);
  return s;
}

bool sameBits(const Eigen::MatrixXf& a, const Eigen::MatrixXf& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(float) * static_cast<std::size_t>(a.size())) == 0;
}

TEST(CampaignKill, TwentyKillsAndResumesGiveTheUninterruptedCampaign) {
  const fs::path dir = fs::path(MOZZI_BINARY_DIR) / ("campaign_kill_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string straight = (dir / "straight.mozzi").string(), killed = (dir / "killed.mozzi").string();
  for (const auto& p : {straight, killed}) ASSERT_TRUE(core::io::ProjectStore::create(p, "kill test").ok());

  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_EQ(runToEnd(straight), 0);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("uninterrupted run: %.2f s\n", wall);

  std::mt19937 rng(20261125);
  std::uniform_real_distribution<double> share(0.0, 0.05 * wall);
  auto moment = [&](std::mt19937& g) { return 0.3 + share(g); };
  int kills = 0, attempts = 0;
  Snapshot before;
  while (kills < 20) {
    ASSERT_LT(++attempts, 200) << "the campaign finished before 20 kills";
    const pid_t pid = spawnCampaign(killed);
    std::this_thread::sleep_for(std::chrono::duration<double>(moment(rng)));
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) {
      // It finished before the kill: the campaign is done; start over on a
      // fresh copy is not needed, the kills so far are the test.
      ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
      break;
    }
    ASSERT_EQ(kill(pid, SIGKILL), 0);
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status));
    ++kills;
    // Every hit committed before this kill is still there, bit for bit.
    const Snapshot after = snapshot(killed);
    ASSERT_GE(after.hits.size(), before.hits.size());
    for (std::size_t k = 0; k < before.hits.size(); ++k) {
      ASSERT_EQ(after.hits[k].id, before.hits[k].id);
      ASSERT_EQ(after.hits[k].accepted, before.hits[k].accepted);
      ASSERT_TRUE(sameBits(after.samples[k], before.samples[k])) << "hit " << k + 1 << " changed";
    }
    before = after;
  }
  std::printf("%d kills; %zu hits committed by the killed runs\n", kills, before.hits.size());
  EXPECT_GE(kills, 20);
  ASSERT_EQ(runToEnd(killed), 0);

  const Snapshot a = snapshot(straight), b = snapshot(killed);
  ASSERT_EQ(a.hits.size(), b.hits.size());
  for (std::size_t k = 0; k < a.hits.size(); ++k) {
    EXPECT_EQ(a.hits[k].sequence, b.hits[k].sequence);
    EXPECT_EQ(a.hits[k].point, b.hits[k].point);
    EXPECT_EQ(a.hits[k].accepted, b.hits[k].accepted);
    EXPECT_EQ(a.hits[k].qualityFlags, b.hits[k].qualityFlags);
    EXPECT_TRUE(sameBits(a.samples[k], b.samples[k])) << "hit " << k + 1;
  }
  auto sa = core::io::ProjectStore::open(straight, core::io::ProjectStore::OpenMode::ReadOnly).value();
  auto sb = core::io::ProjectStore::open(killed, core::io::ProjectStore::OpenMode::ReadOnly).value();
  auto la = devices::campaign::loadCampaign(sa, 1).value();
  auto lb = devices::campaign::loadCampaign(sb, 1).value();
  ASSERT_TRUE(la.finished() && lb.finished());
  const auto fa = sa.frfSet(*la.frfSetId).value(), fb = sb.frfSet(*lb.frfSetId).value();
  ASSERT_EQ(fa.h.size(), fb.h.size());
  for (std::size_t i = 0; i < fa.h.size(); ++i) {
    EXPECT_TRUE((fa.h[i].array() == fb.h[i].array()).all()) << "FRFs of reference " << i << " differ";
    EXPECT_TRUE((fa.coherence[i].array() == fb.coherence[i].array()).all());
  }
  EXPECT_EQ(sa.frfSetHits(*la.frfSetId)->size(), sb.frfSetHits(*lb.frfSetId)->size());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mozzi::cli
