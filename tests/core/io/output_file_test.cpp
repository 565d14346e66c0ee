// The output helper (core/io/output_file.h): the target is the old file or the
// whole new one, never the input, and a failed write is an error naming it.

#include "core/io/output_file.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace mozzi::core::io {
namespace {

namespace fs = std::filesystem;

class OutputFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mozzi_output_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add);
    fs::remove_all(dir_);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  static std::string slurp(const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  static void spit(const std::string& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }
  // Entries of the folder other than the named ones: temporary files left behind.
  std::size_t strayFiles(std::initializer_list<std::string> known) const {
    std::size_t n = 0;
    for (const auto& e : fs::directory_iterator(dir_)) {
      bool isKnown = false;
      for (const auto& k : known) isKnown = isKnown || e.path().filename() == k;
      n += isKnown ? 0 : 1;
    }
    return n;
  }
  fs::path dir_;
};

TEST_F(OutputFileTest, WritesANewFileAndReplacesAnOldOne) {
  const std::string out = path("out.txt");
  ASSERT_TRUE(writeOutputFile(out, std::string_view("first\n")).ok());
  EXPECT_EQ(slurp(out), "first\n");
  ASSERT_TRUE(writeOutputFile(out, std::string_view("second\n")).ok());
  EXPECT_EQ(slurp(out), "second\n");
  EXPECT_EQ(strayFiles({"out.txt"}), 0u);
}

TEST_F(OutputFileTest, RefusesTheInputByPathSymlinkAndHardLink) {
  const std::string in = path("in.uff");
  spit(in, "precious data\n");
  fs::create_symlink(in, path("link.uff"));
  fs::create_hard_link(in, path("hard.uff"));
  for (const std::string& target : {in, path("./in.uff"), path("link.uff"), path("hard.uff")}) {
    auto r = writeOutputFile(target, std::string_view("clobber"), {in});
    ASSERT_FALSE(r.ok()) << target;
    EXPECT_EQ(r.error().where, target);
    EXPECT_NE(r.error().message.find("refusing to write the output onto the input"), std::string::npos);
  }
  // The input is checked through links too: input named by its symlink.
  auto viaLink = writeOutputFile(in, std::string_view("clobber"), {path("link.uff")});
  EXPECT_FALSE(viaLink.ok());
  EXPECT_EQ(slurp(in), "precious data\n");
}

TEST_F(OutputFileTest, ASymlinkTargetKeepsTheLinkAndReplacesTheFile) {
  const std::string real = path("real.csv");
  spit(real, "old");
  fs::create_symlink(real, path("alias.csv"));
  ASSERT_TRUE(writeOutputFile(path("alias.csv"), std::string_view("new")).ok());
  EXPECT_TRUE(fs::is_symlink(path("alias.csv")));
  EXPECT_EQ(slurp(real), "new");
}

TEST_F(OutputFileTest, KeepsTheReplacedFilesPermissions) {
  const std::string out = path("script.csv");
  spit(out, "old");
  fs::permissions(out, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  ASSERT_TRUE(writeOutputFile(out, std::string_view("new")).ok());
  EXPECT_EQ(fs::status(out).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

// /dev/full: every write fails with ENOSPC. A special file is written
// directly, so the error must come from the checked write, naming the file.
TEST_F(OutputFileTest, DevFullFailsNamingTheFile) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  auto r = writeOutputFile("/dev/full", std::string_view("x"));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().where, "/dev/full");
  EXPECT_NE(r.error().message.find("No space left on device"), std::string::npos) << r.error().message;
  // A large write too (beyond the stream buffer).
  auto big = writeOutputFile("/dev/full", std::string(1 << 20, 'x'));
  EXPECT_FALSE(big.ok());
}

TEST_F(OutputFileTest, DevNullIsWrittenDirectly) {
  auto file = OutputFile::open("/dev/null");
  ASSERT_TRUE(file.ok()) << file.error().describe();
  EXPECT_TRUE(file->writesDirectly());
  file->stream() << "discarded";
  EXPECT_TRUE(file->commit().ok());
}

// A write that fails half-way (here: the file-size limit, EFBIG, as a full
// disk gives ENOSPC) leaves the earlier file as it was and no temporary file.
TEST_F(OutputFileTest, AFailedWriteLeavesTheEarlierFileUntouched) {
  const std::string out = path("history.csv");
  spit(out, "earlier result\n");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    struct rlimit limit {
      4096, 4096
    };
    ::setrlimit(RLIMIT_FSIZE, &limit);
    auto r = writeOutputFile(out, std::string(1 << 20, 'y'));
    const bool namesFile = !r.ok() && r.error().where == out &&
                           r.error().message.find("write failed") != std::string::npos &&
                           r.error().message.find("untouched") != std::string::npos;
    _exit(namesFile ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "the failed write was not reported naming the file";
  EXPECT_EQ(slurp(out), "earlier result\n");
  EXPECT_EQ(strayFiles({"history.csv"}), 0u);
}

TEST_F(OutputFileTest, AnAbandonedOutputLeavesNothing) {
  const std::string out = path("never.uff");
  {
    auto file = OutputFile::open(out);
    ASSERT_TRUE(file.ok());
    file->stream() << "half";
  }  // no commit: e.g. the computation failed after opening
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(strayFiles({}), 0u);
}

TEST_F(OutputFileTest, RefusesAFolderAMissingFolderAndAnEmptyName) {
  EXPECT_FALSE(writeOutputFile(dir_.string(), std::string_view("x")).ok());
  auto missing = writeOutputFile(path("no/such/folder/out.csv"), std::string_view("x"));
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("folder"), std::string::npos);
  EXPECT_FALSE(writeOutputFile("", std::string_view("x")).ok());
}

// A read-only folder: the temporary file cannot be created, the command fails
// naming the file, and the earlier file stays. Root ignores permissions, so
// the check runs in a child that drops to 'nobody' when the test runs as root.
TEST_F(OutputFileTest, AReadOnlyFolderFailsAndKeepsTheEarlierFile) {
  const std::string out = path("result.csv");
  spit(out, "earlier\n");
  ::chmod(out.c_str(), 0666);
  ::chmod(dir_.c_str(), 0555);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) _exit(2);
    auto r = writeOutputFile(out, std::string_view("new\n"));
    _exit(!r.ok() && r.error().where == out && r.error().message.find("temporary file") != std::string::npos ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(slurp(out), "earlier\n");
}

}  // namespace
}  // namespace mozzi::core::io
