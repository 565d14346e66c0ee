// Crash test of the project store (issue 4, "Reliability tests"): a child
// process commits hits in a loop and reports each id whose commitHit returned
// through a pipe; the parent kills it with SIGKILL at a random moment, then
// checks that the project opens, passes PRAGMA integrity_check and holds every
// reported hit with its exact samples. Repeated 60 times on the same file, so
// later rounds also exercise WAL recovery on top of earlier kills.

#include <gtest/gtest.h>
#include <signal.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <map>
#include <random>
#include <set>
#include <thread>
#include <vector>

#include "core/io/project_store.h"

namespace mozzi::core::io {
namespace {

namespace fs = std::filesystem;

constexpr int kRounds = 60;  // issue 4 asks for at least 50 kills
constexpr int kChannels = 4;
constexpr int kSamples = 2048;  // 32 KiB per hit: keeps 60 rounds within seconds

// Deterministic samples of hit `sequence`, so the parent can check every value.
Eigen::MatrixXf samplesFor(int sequence) {
  Eigen::MatrixXf s(kSamples, kChannels);
  std::uint32_t state = 2654435761u * static_cast<std::uint32_t>(sequence) + 12345u;
  for (Eigen::Index c = 0; c < s.cols(); ++c) {
    for (Eigen::Index r = 0; r < s.rows(); ++r) {
      state = state * 1664525u + 1013904223u;  // LCG, Numerical Recipes constants
      s(r, c) = static_cast<float>(static_cast<std::int32_t>(state >> 8) - (1 << 23)) / static_cast<float>(1 << 20);
    }
  }
  return s;
}

// Runs in the child: commit hits until killed. Never returns.
[[noreturn]] void writer(const std::string& path, std::int64_t campaignId, int firstSequence, int pipeFd,
                         SampleEncoding encoding) {
  auto store = ProjectStore::open(path);
  if (!store || store->isReadOnly()) _exit(3);
  store->setHitEncoding(encoding);
  const std::int64_t ready[2] = {0, 0};  // "opened, about to write"
  if (write(pipeFd, ready, sizeof ready) != static_cast<ssize_t>(sizeof ready)) _exit(5);
  for (int seq = firstSequence;; ++seq) {
    StoredHit hit;
    hit.campaignId = campaignId;
    hit.sequence = seq;
    hit.point = Dof{seq % 40 + 1, Direction::Z, false};
    hit.sampleRateHz = 51200.0;
    hit.samples = samplesFor(seq);
    hit.accepted = seq % 7 != 0;
    hit.qualityFlags = hit.accepted ? 0u : kHitDoubleHit;
    hit.qualityReasons = hit.accepted ? "" : "double hit";
    auto id = store->commitHit(hit);
    if (!id) _exit(4);
    const std::int64_t report[2] = {*id, seq};
    // The report goes out only after commitHit returned, i.e. after COMMIT.
    if (write(pipeFd, report, sizeof report) != static_cast<ssize_t>(sizeof report)) _exit(5);
  }
}

std::string integrityCheck(const std::string& path) {
  sqlite3* db = nullptr;
  std::string result = "cannot open";
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) == SQLITE_OK) {
    sqlite3_stmt* stmt = nullptr;
    if (sqlite3_prepare_v2(db, "PRAGMA integrity_check", -1, &stmt, nullptr) == SQLITE_OK) {
      result.clear();
      while (sqlite3_step(stmt) == SQLITE_ROW) result += reinterpret_cast<const char*>(sqlite3_column_text(stmt, 0));
    }
    sqlite3_finalize(stmt);
  }
  sqlite3_close_v2(db);
  return result;
}

TEST(ProjectCrashTest, EveryCommittedHitSurvivesSigkill) {
  const fs::path dir = fs::temp_directory_path() / ("mozzi_crash_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string path = (dir / "crash.mozzi").string();
  std::int64_t campaignId = 0;
  {
    auto store = ProjectStore::create(path, "test");
    ASSERT_TRUE(store.ok()) << store.error().describe();
    auto specimen = store->addSpecimen("Frame A", "frame", "crash test");
    ASSERT_TRUE(specimen.ok());
    StoredCampaign campaign;
    campaign.specimenId = *specimen;
    campaign.name = "roving hammer";
    auto c = store->addCampaign(campaign);
    ASSERT_TRUE(c.ok()) << c.error().describe();
    campaignId = *c;
  }

  std::mt19937 rng(20261121);  // fixed seed: a failure is reproducible
  // Kill moments: in one round of six right after fork (the kill lands while
  // the child opens the project); otherwise after the child has reported
  // 0..3 commits, plus 0..15 ms, i.e. anywhere in the hit loop: inside
  // encode, INSERT, COMMIT (the WAL fsync) or the report. Counting reports
  // rather than only sleeping keeps the kills mid-stream on a loaded machine,
  // where one fsync can take tens of milliseconds.
  std::uniform_int_distribution<int> killAfterUs(0, 15000);
  std::uniform_int_distribution<int> killAfterCommits(0, 3);
  std::map<std::int64_t, int> committed;  // hit id -> sequence, over all rounds
  int nextSequence = 1;
  int killsMidStream = 0;
  const auto start = std::chrono::steady_clock::now();

  for (int round = 0; round < kRounds; ++round) {
    int fds[2];
    ASSERT_EQ(pipe(fds), 0);
    // Alternate the blob encodings so both survive a kill.
    const SampleEncoding encoding = round % 2 == 0 ? SampleEncoding::Raw : SampleEncoding::ShuffledZlib;
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      close(fds[0]);
      writer(path, campaignId, nextSequence, fds[1], encoding);
    }
    close(fds[1]);
    const int delayUs = killAfterUs(rng);
    const int waitCommits = killAfterCommits(rng);
    int reportedThisRound = 0;
    if (round % 6 != 5) {
      // Wait for "ready" and then for `waitCommits` reported commits.
      bool ready = false;
      while (!ready || reportedThisRound < waitCommits) {
        std::int64_t report[2];
        const ssize_t n = read(fds[0], report, sizeof report);
        if (n < 0 && errno == EINTR) continue;
        ASSERT_EQ(n, static_cast<ssize_t>(sizeof report)) << "round " << round << ": writer died early";
        if (report[0] == 0) {
          ready = true;
          continue;
        }
        committed[report[0]] = static_cast<int>(report[1]);
        nextSequence = std::max(nextSequence, static_cast<int>(report[1]) + 1);
        ++reportedThisRound;
      }
    }
    std::this_thread::sleep_for(std::chrono::microseconds(delayUs));
    ASSERT_EQ(kill(child, SIGKILL), 0);
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    // A child that exited by itself (status 3..5) failed to write: report it.
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
        << "round " << round << ": writer exited with status " << (WIFEXITED(status) ? WEXITSTATUS(status) : -1);

    // Drain the reports the child managed to send before it died.
    for (;;) {
      std::int64_t report[2];
      const ssize_t n = read(fds[0], report, sizeof report);
      if (n == 0) break;
      if (n < 0 && errno == EINTR) continue;
      ASSERT_EQ(n, static_cast<ssize_t>(sizeof report)) << "torn report in round " << round;
      if (report[0] == 0) continue;  // the ready marker
      committed[report[0]] = static_cast<int>(report[1]);
      nextSequence = std::max(nextSequence, static_cast<int>(report[1]) + 1);
      ++reportedThisRound;
    }
    close(fds[0]);
    if (reportedThisRound > 0) ++killsMidStream;

    // The kill may have hit a commit in flight: that hit may or may not be
    // there, but nothing reported may be missing. Sequences of unreported
    // hits can exist, so the next child starts past them.
    ASSERT_EQ(integrityCheck(path), "ok") << "round " << round;
    auto store = ProjectStore::open(path);
    ASSERT_TRUE(store.ok()) << "round " << round << ": " << store.error().describe();
    ASSERT_FALSE(store->isReadOnly()) << "the killed writer's lock must be gone: " << store->readOnlyReason();
    auto list = store->hits(campaignId);
    ASSERT_TRUE(list.ok()) << list.error().describe();
    std::set<std::int64_t> present;
    for (const auto& h : *list) {
      present.insert(h.id);
      nextSequence = std::max(nextSequence, h.sequence + 1);
    }
    for (const auto& [id, seq] : committed) {
      ASSERT_TRUE(present.count(id)) << "round " << round << ": committed hit " << id << " (sequence " << seq
                                     << ") is missing";
    }
    // Full content check of this round's newest committed hit and a sample of
    // older ones: exact float equality (lossless storage, both encodings).
    int checked = 0;
    for (auto it = committed.rbegin(); it != committed.rend() && checked < 3; ++it, ++checked) {
      auto hit = store->hit(it->first);
      ASSERT_TRUE(hit.ok()) << hit.error().describe();
      EXPECT_EQ(hit->sequence, it->second);
      ASSERT_EQ(hit->samples.rows(), kSamples);
      ASSERT_EQ(hit->samples.cols(), kChannels);
      EXPECT_TRUE(hit->samples == samplesFor(it->second)) << "hit " << it->first << " samples differ";
      EXPECT_EQ(hit->accepted, it->second % 7 != 0);
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("crash test: %d kills, %zu committed hits verified, %d kills after at least one commit, %.1f s\n",
              kRounds, committed.size(), killsMidStream, seconds);
  // The kills must land during writing, not only before the first commit:
  // three quarters of the waiting rounds wait for at least one commit by
  // construction, so at least half of all rounds kill mid-stream.
  EXPECT_GE(killsMidStream, kRounds / 2);

  // Final full check: every committed hit, every sample.
  auto store = ProjectStore::open(path);
  ASSERT_TRUE(store.ok());
  for (const auto& [id, seq] : committed) {
    auto hit = store->hit(id);
    ASSERT_TRUE(hit.ok()) << hit.error().describe();
    ASSERT_TRUE(hit->samples == samplesFor(seq)) << "hit " << id;
  }
  fs::remove_all(dir);
}

// Issue 17: the same kill test for the other record kinds, each with its
// checksum. A child adds, in turn, an FRF set, a modal result and a rig test
// with one time record, reporting (kind, id, k) after each call returned; the
// parent kills it at random moments (20 rounds), then requires a clean
// checkIntegrity (every checksum verified) and every reported record back
// with exactly its content.
enum RecordKind : std::int64_t { kFrfSet = 1, kModal = 2, kRigTest = 3 };

FrfMatrix frfFor(int k) {
  FrfMatrix f;
  f.type = FrfType::Accelerance;
  f.frequencyHz = Vector::LinSpaced(129, 0.0, 512.0);
  f.responses = {Dof{k % 50 + 1, Direction::Z, false}, Dof{k % 50 + 2, Direction::Y, true}};
  f.references = {Dof{1, Direction::Z, false}};
  ComplexMatrix h(129, 2);
  Matrix c(129, 2);
  for (int l = 0; l < 129; ++l) {
    for (int o = 0; o < 2; ++o) {
      h(l, o) = Complex(std::cos(0.01 * l * (o + 1) + k), std::sin(0.003 * l * k) / (1.0 + o));
      c(l, o) = 0.5 + 0.4 * std::cos(0.03 * l + o + k);
    }
  }
  f.h = {h};
  f.coherence = {c};
  return f;
}

ModalTable modesFor(int k) {
  ModalTable t;
  t.dofs = {Dof{1, Direction::X, false}, Dof{2, Direction::Z, true}, Dof{3, Direction::Y, false}};
  for (int m = 0; m < 3; ++m) {
    StoredMode mode{10.0 * (m + 1) + 0.001 * k, 0.01 + 0.0001 * k, ComplexVector(3)};
    for (int d = 0; d < 3; ++d) mode.shape[d] = Complex(std::cos(k + m + d), std::sin(k * m - d));
    t.modes.push_back(mode);
  }
  return t;
}

Eigen::MatrixXf recordFor(int k) {
  Eigen::MatrixXf r(512, 3);
  for (Eigen::Index c = 0; c < 3; ++c)
    for (Eigen::Index i = 0; i < 512; ++i) r(i, c) = static_cast<float>(std::sin(0.01 * i * (c + 1) + k));
  return r;
}

[[noreturn]] void recordWriter(const std::string& path, std::int64_t specimen, int first, int pipeFd) {
  auto store = ProjectStore::open(path);
  if (!store || store->isReadOnly()) _exit(3);
  const std::int64_t ready[3] = {0, 0, 0};
  if (write(pipeFd, ready, sizeof ready) != static_cast<ssize_t>(sizeof ready)) _exit(5);
  for (int k = first;; ++k) {
    const auto kind = static_cast<RecordKind>(k % 3 + 1);
    Result<std::int64_t> id = std::int64_t{0};
    if (kind == kFrfSet) {
      FrfSetInfo info;
      info.specimenId = specimen;
      info.name = "set " + std::to_string(k);
      id = store->addFrfSet(info, frfFor(k));
    } else if (kind == kModal) {
      ModalResultInfo info;
      info.specimenId = specimen;
      info.name = "modes " + std::to_string(k);
      info.bandHighHz = 100.0 + k;
      id = store->addModalResult(info, modesFor(k));
    } else {
      StoredRigTest t;
      t.specimenId = specimen;
      t.name = "test " + std::to_string(k);
      t.parametersJson = "{\"k\": " + std::to_string(k) + "}";
      t.results = {{"stiffness", 1000.0 * k, "N/m", 1.0}};
      id = store->addRigTest(t);
      if (id && !store->addRigTestRecord(*id, 0, 2048.0, recordFor(k))) _exit(4);
    }
    if (!id) _exit(4);
    const std::int64_t report[3] = {kind, *id, k};
    if (write(pipeFd, report, sizeof report) != static_cast<ssize_t>(sizeof report)) _exit(5);
  }
}

TEST(ProjectCrashTest, FrfSetsModalResultsAndRigTestsSurviveSigkillWithChecksums) {
  const fs::path dir = fs::temp_directory_path() / ("mozzi_crash_records_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string path = (dir / "records.mozzi").string();
  std::int64_t specimen = 0;
  {
    auto store = ProjectStore::create(path, "test");
    ASSERT_TRUE(store.ok()) << store.error().describe();
    specimen = *store->addSpecimen("Fork A", "fork", "crash test");
  }
  std::mt19937 rng(20261125);  // fixed seed: a failure is reproducible
  std::uniform_int_distribution<int> killAfterUs(0, 20000);
  std::uniform_int_distribution<int> killAfterRecords(0, 4);
  std::map<std::pair<std::int64_t, std::int64_t>, int> reported;  // (kind, id) -> k
  int next = 0;
  constexpr int kRecordRounds = 20;
  for (int round = 0; round < kRecordRounds; ++round) {
    int fds[2];
    ASSERT_EQ(pipe(fds), 0);
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      close(fds[0]);
      recordWriter(path, specimen, next, fds[1]);
    }
    close(fds[1]);
    const int waitRecords = killAfterRecords(rng);
    auto take = [&](const std::int64_t(&r)[3]) {
      if (r[0] == 0) return;
      reported[{r[0], r[1]}] = static_cast<int>(r[2]);
      next = std::max(next, static_cast<int>(r[2]) + 1);
    };
    int seen = 0;
    bool ready = false;
    while (!ready || seen < waitRecords) {
      std::int64_t r[3];
      const ssize_t n = read(fds[0], r, sizeof r);
      if (n < 0 && errno == EINTR) continue;
      ASSERT_EQ(n, static_cast<ssize_t>(sizeof r)) << "round " << round << ": writer died early";
      if (r[0] == 0) {
        ready = true;
      } else {
        take(r);
        ++seen;
      }
    }
    std::this_thread::sleep_for(std::chrono::microseconds(killAfterUs(rng)));
    ASSERT_EQ(kill(child, SIGKILL), 0);
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status)) << "round " << round << ": writer exited by itself";
    for (;;) {
      std::int64_t r[3];
      const ssize_t n = read(fds[0], r, sizeof r);
      if (n == 0) break;
      if (n < 0 && errno == EINTR) continue;
      ASSERT_EQ(n, static_cast<ssize_t>(sizeof r));
      take(r);
    }
    close(fds[0]);
    // Names of unreported records may exist (a commit in flight): skip past them.
    next += 3;

    auto store = ProjectStore::open(path, ProjectStore::OpenMode::ReadOnly);
    ASSERT_TRUE(store.ok()) << "round " << round << ": " << store.error().describe();
    auto report = store->checkIntegrity();
    ASSERT_TRUE(report.ok()) << report.error().describe();
    ASSERT_TRUE(report->ok()) << "round " << round << ": " << report->problems.front().record << ": "
                              << report->problems.front().message;
    EXPECT_EQ(report->recordsWithoutChecksum, 0);
  }
  // Every reported record, exactly.
  auto store = ProjectStore::open(path, ProjectStore::OpenMode::ReadOnly);
  ASSERT_TRUE(store.ok());
  int frfSets = 0, modal = 0, rigTests = 0;
  for (const auto& [key, k] : reported) {
    const auto [kind, id] = key;
    if (kind == kFrfSet) {
      auto f = store->frfSet(id);
      ASSERT_TRUE(f.ok()) << f.error().describe();
      const FrfMatrix want = frfFor(k);
      EXPECT_TRUE(f->h[0] == want.h[0] && f->coherence[0] == want.coherence[0] && f->responses == want.responses)
          << "FRF set " << id;
      ++frfSets;
    } else if (kind == kModal) {
      auto m = store->modalResult(id);
      ASSERT_TRUE(m.ok()) << m.error().describe();
      const ModalTable want = modesFor(k);
      ASSERT_EQ(m->modes.size(), want.modes.size());
      for (std::size_t r = 0; r < want.modes.size(); ++r) {
        EXPECT_EQ(m->modes[r].frequencyHz, want.modes[r].frequencyHz);
        EXPECT_TRUE(m->modes[r].shape == want.modes[r].shape);
      }
      ++modal;
    } else {
      auto t = store->rigTest(id);
      ASSERT_TRUE(t.ok()) << t.error().describe();
      ASSERT_EQ(t->results.size(), 1u);
      EXPECT_EQ(t->results[0].value, 1000.0 * k);
      // The record is committed after the test in its own transaction: it
      // may be missing only for the last test of a round.
      auto rec = store->rigTestRecord(id, 0);
      if (rec) {
        EXPECT_TRUE(*rec == recordFor(k)) << "rig test " << id;
      }
      ++rigTests;
    }
  }
  std::printf("record crash test: %d kills, %d FRF sets, %d modal results, %d rig tests verified\n", kRecordRounds,
              frfSets, modal, rigTests);
  EXPECT_GT(frfSets, 0);
  EXPECT_GT(modal, 0);
  EXPECT_GT(rigTests, 0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mozzi::core::io
