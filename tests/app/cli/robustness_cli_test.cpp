// Issue 17: the table-driven robustness test over every command and option.
// Bad values (missing, empty, NaN, Inf, 1e308, negative, too long...) of every
// numeric option a command declares, bad files (missing, empty, a folder, an
// endless device), outputs onto their own input (by path, symlink, hard link),
// /dev/full and a read-only folder: each must give exit code 1 and a message
// naming the option or the file, never a crash, a hang or exit 0. The option
// tables come from the registry, so a new command or option is covered as
// soon as it is declared.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "app/cli/args.h"
#include "app/cli/command.h"
#include "cli_run.h"
#include "core/io/project_store.h"
#include "core/io/uff/uff.h"
#include "core/signal/hit_synthesis.h"

namespace mozzi::cli {
namespace {

namespace fs = std::filesystem;
namespace uff = core::io::uff;
namespace sg = core::signal;

// --- fixtures -------------------------------------------------------------------

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// One folder of inputs shared by the tests: a hammer-hit UFF, the FRF UFF the
// CLI makes from it, a project holding that FRF set, a plate CSV, a tyre CSV.
class Inputs {
 public:
  static Inputs& get() {
    static Inputs inputs;
    return inputs;
  }
  fs::path dir;
  std::string hits, frf, project, plate, tyre, params;

 private:
  Inputs() {
    dir = fs::temp_directory_path() / ("mozzi_robust_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::permissions(dir, fs::perms::all, fs::perm_options::replace);  // 0777: the 'nobody' runs write here too
    hits = (dir / "hits.uff").string();
    sg::LinearMdof s;
    s.mass = Eigen::Vector2d(1.0, 0.5).asDiagonal();
    s.stiffness.resize(2, 2);
    s.stiffness << 1.5e5, -5e4, -5e4, 5e4;
    s.damping = 2e-4 * s.stiffness;
    uff::UffFile file;
    for (int h = 1; h <= 2; ++h) {
      sg::HammerHitSpec spec;
      spec.sampleCount = 4096;
      spec.pulseWidthS = 4e-3;
      spec.peakForceN = 90.0;
      spec.seed = static_cast<std::uint64_t>(h);
      auto rec = sg::synthesizeHammerHit(s, spec);
      if (!rec) throw std::runtime_error(rec.error().describe());
      for (Eigen::Index c = 0; c < rec->channelCount(); ++c) {
        uff::Function58 f;
        f.functionType = uff::FunctionType::TimeResponse;
        f.loadCase = h;
        f.response = uff::Channel58::fromDof(rec->channels[static_cast<std::size_t>(c)].dof);
        f.ordinateType = uff::OrdinateType::RealDouble;
        f.abscissaMin = -static_cast<double>(rec->preTriggerSamples) / rec->sampleRateHz;
        f.abscissaIncrement = 1.0 / rec->sampleRateHz;
        const bool force = rec->channels[static_cast<std::size_t>(c)].transducer.kind == sg::TransducerKind::Force;
        f.ordinateNumerator.specificDataType = force ? 13 : 12;
        f.ordinateNumerator.unitsLabel = force ? "N" : "m/s^2";
        f.real = rec->samples.col(c);
        file.datasets.push_back(uff::makeDataset(f));
      }
    }
    if (!uff::writeFile(hits, file)) throw std::runtime_error("cannot write hits");
    frf = (dir / "frf.uff").string();
    const CliRun r = run({"frf", hits, "--estimator", "H1", "--out", frf});
    if (r.code != kExitOk) throw std::runtime_error("frf: " + r.err);
    project = (dir / "p.mozzi").string();
    {
      auto store = core::io::ProjectStore::create(project, "test");
      auto sp = store->addSpecimen("Frame A", "frame", "robustness");
      auto read = uff::readFile(frf);
      auto m = uff::toFrfMatrix(*read);
      core::io::FrfSetInfo info;
      info.specimenId = *sp;
      info.name = "H1";
      if (!m || !store->addFrfSet(info, *m)) throw std::runtime_error("cannot fill the project");
    }
    plate = (dir / "plate.csv").string();
    std::ofstream(plate) << "sensor,0,0\nsensor,0.1,0\nsensor,0,0.1\nload,0.05,0.05\nforce,w1,w2,w3\n"
                            "100,1e-5,2e-5,1.5e-5\n200,2e-5,4e-5,3e-5\n";
    tyre = (dir / "yaw.csv").string();
    std::ofstream(tyre) << "frequency_hz,time_s,yaw_rate_rad_s,lateral_force_n\n1,0,0.1,10\n1,0.01,0.09,12\n";
    params = (dir / "bicycle.csv").string();
    std::ofstream(params) << "name,value\nw,1.02\n";
    for (const auto& e : fs::directory_iterator(dir)) ::chmod(e.path().c_str(), 0644);
  }
};

// Runs the real executable (as 'nobody' when asked and running as root:
// root ignores permissions, the read-only cases need a user who does not).
CliRun runExe(const std::vector<std::string>& args, bool asNobody = false, const std::string& stdoutPath = {}) {
  int errPipe[2], outPipe[2];
  if (::pipe(errPipe) != 0 || ::pipe(outPipe) != 0) return {-1, "", "pipe failed"};
  const pid_t child = ::fork();
  if (child == 0) {
    if (asNobody && ::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) _exit(99);
    ::dup2(errPipe[1], 2);
    if (stdoutPath.empty()) {
      ::dup2(outPipe[1], 1);
    } else {
      const int fd = ::open(stdoutPath.c_str(), O_WRONLY);
      ::dup2(fd, 1);
    }
    ::close(errPipe[0]);
    ::close(outPipe[0]);
    std::vector<char*> argv{const_cast<char*>(MOZZI_CLI_PATH)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(MOZZI_CLI_PATH, argv.data());
    _exit(98);
  }
  ::close(errPipe[1]);
  ::close(outPipe[1]);
  auto drain = [](int fd) {
    std::string s;
    char buf[4096];
    ssize_t n;
    while ((n = ::read(fd, buf, sizeof buf)) > 0) s.append(buf, static_cast<std::size_t>(n));
    ::close(fd);
    return s;
  };
  // stderr is small; read stdout first (it may be large) then stderr.
  std::string out = drain(outPipe[0]);
  std::string err = drain(errPipe[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), out, err};
}

std::string describe(const std::vector<std::string>& args) {
  std::string s = "mozzi-cli";
  for (const auto& a : args) s += " " + (a.size() > 60 ? a.substr(0, 60) + "...(" + std::to_string(a.size()) + ")" : a);
  return s;
}

// --- every numeric option ------------------------------------------------------------

// Where each command parses its options: the words before the options. The
// range check runs in ParsedArgs::parse, before any file is read.
std::vector<std::string> baseArgs(const std::string& command) {
  if (command == "fork") return {"fork", "bicycle"};
  if (command == "stiffness") return {"stiffness", "decompose"};
  if (command == "twist") return {"twist", "modal", Inputs::get().plate};
  if (command == "wheelchair") return {"wheelchair", "slalom"};
  if (command == "tire") return {"tire", "ring"};
  if (command == "stability") return {"stability", "bicycle"};
  if (command == "project") return {"project", "export", Inputs::get().project};
  if (command == "identify" || command == "frf") return {command, Inputs::get().hits};
  if (command == "mozzi") return {"mozzi", Inputs::get().plate};
  return {command};
}

// A value inside the range, as text.
std::string inside(const NumberRange& r) {
  double v = r.max > 1.0 && r.min < 1.0 ? 1.0 : 0.5 * (r.min + r.max);
  if (r.integer) v = std::ceil(r.min + (r.minOpen ? 1 : 0));
  if (!r.contains(v)) v = r.max;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

const std::vector<std::string>& badNumbers() {
  static const std::vector<std::string> values = {"",
                                                  " ",
                                                  "abc",
                                                  "nan",
                                                  "NaN",
                                                  "inf",
                                                  "-inf",
                                                  "1e308",
                                                  "-1e308",
                                                  "1e400",
                                                  "-1",
                                                  "1e-320",
                                                  "0x1p-1070",
                                                  "1.5.2",
                                                  "12abc",
                                                  "-0",
                                                  std::string(100000, '9')};
  return values;
}

TEST(Robustness, EveryCommandDeclaresItsOptionTable) {
  for (const auto& c : registeredCommands()) {
    EXPECT_NE(c.options, nullptr) << c.name << " registers no option table (numeric ranges, outputs)";
    if (!c.options) continue;
    // Every numeric option shows its range in --help.
    const CliRun help = run({c.name, "--help"});
    EXPECT_EQ(help.code, kExitOk);
    for (const auto& n : c.options->numbers) {
      EXPECT_NE(help.out.find(n.name), std::string::npos) << c.name << " --help omits " << n.name;
      EXPECT_NE(help.out.find(n.rangeText()), std::string::npos) << c.name << " --help omits the range of " << n.name;
    }
  }
}

TEST(Robustness, EveryNumericOptionRejectsBadValuesNamingTheOption) {
  int cases = 0;
  for (const auto& c : registeredCommands()) {
    if (!c.options) continue;
    for (const auto& option : c.options->numbers) {
      // The option's value as a list of field texts (one field for a scalar).
      std::vector<std::string> valid;
      std::vector<NumberRange> ranges;
      if (option.fields.empty()) {
        valid.push_back(inside(option.range));
        ranges.push_back(option.range);
      } else {
        for (const auto& f : option.fields) {
          valid.push_back(inside(f.range));
          ranges.push_back(f.range);
        }
        // LO:HI style options need LO < HI: the first field smaller.
        if (valid.size() >= 2 && option.separator == ':' && ranges[0].contains(0.0)) valid[0] = "0";
      }
      auto join = [&](const std::vector<std::string>& fields) {
        std::string s;
        for (std::size_t k = 0; k < fields.size(); ++k) s += (k ? std::string(1, option.separator) : "") + fields[k];
        return s;
      };
      for (std::size_t field = 0; field < valid.size(); ++field) {
        for (const auto& bad : badNumbers()) {
          if (parseInRange(bad, ranges[field], "x").ok()) continue;  // e.g. -1 for a signed torque
          std::vector<std::string> fields = valid;
          fields[field] = bad;
          std::vector<std::string> args = baseArgs(c.name);
          args.push_back(option.name);
          args.push_back(join(fields));
          const CliRun r = run(args);
          ++cases;
          EXPECT_EQ(r.code, kExitFailure) << describe(args) << "\n" << r.err;
          EXPECT_NE(r.err.find(option.name), std::string::npos) << describe(args) << ": " << r.err;
          EXPECT_LT(r.err.size(), 2000u) << "the message must not carry the whole value";
        }
      }
      // Missing value at the end of the line: a usage error naming the option.
      std::vector<std::string> args = baseArgs(c.name);
      args.push_back(option.name);
      const CliRun missing = run(args);
      EXPECT_EQ(missing.code, kExitUsage) << describe(args);
      EXPECT_NE(missing.err.find(option.name), std::string::npos) << describe(args) << ": " << missing.err;
    }
  }
  std::printf("robustness: %d bad option values, each exit 1 naming the option\n", cases);
  EXPECT_GT(cases, 500);
}

// The named cases, each at its root.
TEST(Robustness, TheNamedNumericEdgeCases) {
  struct Case {
    std::vector<std::string> args;
    std::string mustName;
  };
  const auto& in = Inputs::get();
  const std::vector<Case> cases = {
      {{"fork",
        "bicycle",
        "--fork-mass",
        "1e308",
        "--wheel-mass",
        "2",
        "--wheel-radius",
        "0.3",
        "--hub-mass",
        "0.3",
        "--hub-radius",
        "0.03",
        "--hub-length",
        "0.1",
        "--tip-distance",
        "0.35",
        "--f-tors-wheel",
        "10",
        "--eta-tors-wheel",
        "0.05",
        "--f-tors-alone",
        "60",
        "--f-bend-wheel",
        "20",
        "--eta-bend-wheel",
        "0.05",
        "--f-bend-alone",
        "80"},
       "--fork-mass"},
      {{"stability", "bicycle", "--fork-bending", "1e308,0.8,0.21", "--speeds", "0:10:1"}, "--fork-bending"},
      {{"wheelchair", "slalom", "--frequency", "1000"}, "--frequency"},
      {{"frf", in.hits, "--estimator", "H1", "--force-window", "1e-6"}, "--force-window"},
      {{"wheelchair", "steady", "--speed", "1e-320"}, "--speed"},
      {{"identify", in.frf, "--band", "300:200"}, "--band"},
      {{"stability", "bicycle", "--speeds", "0:1e3:1e-9"}, "--speeds"},
  };
  for (const auto& c : cases) {
    const auto start = std::chrono::steady_clock::now();
    const CliRun r = run(c.args);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.code, kExitFailure) << describe(c.args) << "\n" << r.err << r.out;
    EXPECT_NE(r.err.find(c.mustName), std::string::npos) << describe(c.args) << ": " << r.err;
    EXPECT_LT(s, 10.0) << describe(c.args) << " took " << s << " s";
  }
  // In range but at the edges of what the maths can hold: an answer or an
  // error, never a hang, a crash or a non-finite number printed.
  const std::vector<std::vector<std::string>> edges = {
      {"stability", "bicycle", "--fork-bending", "1e12,1e6,5", "--speeds", "0:10:1", "--json"},
      {"stability", "bicycle", "--fork-torsion", "1e-300,0", "--speeds", "0:10:1"},
      {"fork", "lumped", "--k", "1e9", "--l1", "10", "--l2", "-10", "--wheel-centre", "10", "--mass", "1e-300",
       "--wheel-inertia", "0", "--freq", "1e4", "--zeta", "1"},
      {"wheelchair", "slalom", "--frequency", "5", "--duration", "3600", "--speed", "10"},
  };
  for (const auto& args : edges) {
    const auto start = std::chrono::steady_clock::now();
    const CliRun r = run(args);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_TRUE(r.code == kExitOk || r.code == kExitFailure) << describe(args) << ": " << r.code;
    if (r.code == kExitOk) {
      for (const char* bad : {"nan", "inf", "NaN", "Inf"})
        EXPECT_EQ(r.out.find(bad), std::string::npos) << describe(args) << " printed " << bad << ":\n" << r.out;
    } else {
      EXPECT_FALSE(r.err.empty());
    }
    EXPECT_LT(s, 60.0) << describe(args) << " took " << s << " s";
  }
}

// --- files ----------------------------------------------------------------------------

TEST(Robustness, BadInputFilesFailNamingTheFile) {
  const auto& in = Inputs::get();
  const std::string empty = (in.dir / "empty.txt").string();
  std::ofstream{empty};
  const std::string nanRow = (in.dir / "nan.csv").string();
  std::ofstream(nanRow) << "1,2,3,0.1,0.2,0.3\nnan,2,3,0.1,0.2,0.3\n4,5,6,0.1,0.2,0.3\n";
  // FILE stands for the bad file.
  const std::vector<std::vector<std::string>> commands = {
      {"frf", "FILE", "--estimator", "H1"},
      {"identify", "FILE", "--band", "20:380"},
      {"uff", "info", "FILE"},
      {"uff", "convert", "FILE", (in.dir / "converted.uff").string()},
      {"twist", "static", "FILE"},
      {"twist", "dynamic", "FILE"},
      {"twist", "modal", "FILE", "--freq", "10"},
      {"mozzi", "FILE"},
      {"tire", "relaxation", "FILE", "--half-length", "0.05"},
      {"tire", "steady", "FILE"},
      {"stability", "bicycle", "--params", "FILE", "--speeds", "0:10:1"},
      {"stability", "motorcycle", "--params", "FILE", "--speeds", "1:10:1"},
      {"gap", "--model", "FILE", "--measured", in.frf},
      {"project", "info", "FILE"},
      {"project", "check", "FILE"},
      {"project", "export", "FILE", "--csv", (in.dir / "x.csv").string()},
      {"rig", "caps", "sim-replay", "--file", "FILE"},
  };
  // /dev/zero: an endless file; every reader must stop at its size cap.
  const std::vector<std::string> bad = {"/nonexistent/dir/file", empty, in.dir.string(), "/dev/zero", nanRow};
  for (const auto& command : commands) {
    for (const auto& file : bad) {
      if (file == nanRow && command[0] != "mozzi") continue;
      std::vector<std::string> args = command;
      for (auto& a : args)
        if (a == "FILE") a = file;
      const auto start = std::chrono::steady_clock::now();
      const CliRun r = run(args);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      // An empty UFF is a valid file with no datasets: 'uff info' lists none.
      if (file == empty && command[0] == "uff" && command[1] == "info") {
        EXPECT_EQ(r.code, kExitOk);
        continue;
      }
      EXPECT_EQ(r.code, kExitFailure) << describe(args) << "\n" << r.err << r.out;
      EXPECT_NE(r.err.find(file), std::string::npos) << describe(args) << ": " << r.err;
      EXPECT_LT(r.err.size(), 4000u) << describe(args);
      EXPECT_LT(s, 30.0) << describe(args) << " took " << s << " s";
    }
  }
}

// --- outputs ----------------------------------------------------------------------------

TEST(Robustness, AnOutputOntoItsInputIsRefusedAndTheInputKept) {
  const auto& in = Inputs::get();
  // A copy of each input per case, with a symlink and a hard link to it.
  struct Case {
    std::vector<std::string> args;  // IN = the input, OUT = the output
    std::string input;
  };
  const std::vector<Case> cases = {
      {{"uff", "convert", "IN", "OUT"}, in.frf},
      {{"frf", "IN", "--estimator", "H1", "--out", "OUT"}, in.hits},
      {{"identify", "IN", "--band", "20:380", "--modes", "OUT"}, in.frf},
      {{"identify", "IN", "--band", "20:380", "--stabilization", "OUT"}, in.frf},
      {{"project", "export", "IN", "--uff", "OUT"}, in.project},
      {{"project", "export", "IN", "--csv", "OUT"}, in.project},
  };
  int n = 0;
  for (const auto& c : cases) {
    const fs::path copy = in.dir / ("victim" + std::to_string(n) + fs::path(c.input).extension().string());
    fs::copy_file(c.input, copy, fs::copy_options::overwrite_existing);
    const std::string before = slurp(copy.string());
    const fs::path sym = in.dir / ("sym" + std::to_string(n));
    const fs::path hard = in.dir / ("hard" + std::to_string(n));
    fs::remove(sym);
    fs::remove(hard);
    fs::create_symlink(copy, sym);
    fs::create_hard_link(copy, hard);
    const std::string dotted = (in.dir / "." / copy.filename()).string();
    for (const std::string& out : {copy.string(), dotted, sym.string(), hard.string()}) {
      std::vector<std::string> args = c.args;
      for (auto& a : args) {
        if (a == "IN") a = copy.string();
        if (a == "OUT") a = out;
      }
      const CliRun r = run(args);
      EXPECT_EQ(r.code, kExitFailure) << describe(args) << "\n" << r.err;
      EXPECT_NE(r.err.find("refusing to write the output onto the input"), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(out), std::string::npos) << r.err;
      EXPECT_EQ(slurp(copy.string()), before) << describe(args) << " changed its input";
    }
    ++n;
  }
}

TEST(Robustness, DevFullFailsEveryWriterNamingIt) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const auto& in = Inputs::get();
  const std::vector<std::vector<std::string>> cases = {
      {"uff", "convert", in.frf, "/dev/full"},
      {"frf", in.hits, "--estimator", "H1", "--out", "/dev/full"},
      {"identify", in.frf, "--band", "20:380", "--modes", "/dev/full"},
      {"identify", in.frf, "--band", "20:380", "--stabilization", "/dev/full"},
      {"project", "export", in.project, "--uff", "/dev/full"},
      {"project", "export", in.project, "--csv", "/dev/full"},
      {"wheelchair", "slalom", "--out", "/dev/full"},
  };
  for (const auto& args : cases) {
    const CliRun r = run(args);
    EXPECT_EQ(r.code, kExitFailure) << describe(args) << "\n" << r.err;
    EXPECT_NE(r.err.find("/dev/full"), std::string::npos) << describe(args) << ": " << r.err;
    EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  }
  // The standard output is an output too.
  const CliRun list = runExe({"rig", "list", "--json"}, false, "/dev/full");
  EXPECT_EQ(list.code, kExitFailure) << list.err;
  EXPECT_NE(list.err.find("standard output"), std::string::npos) << list.err;
}

TEST(Robustness, AReadOnlyFolderFailsTheWriteAndKeepsTheEarlierFile) {
  const auto& in = Inputs::get();
  const fs::path ro = in.dir / "readonly";
  fs::create_directories(ro);
  const std::string earlier = (ro / "slalom.csv").string();
  std::ofstream(earlier) << "earlier result\n";
  ::chmod(earlier.c_str(), 0666);
  ::chmod(ro.c_str(), 0555);
  const CliRun r = runExe({"wheelchair", "slalom", "--out", earlier}, true);
  EXPECT_EQ(r.code, kExitFailure) << r.err;
  EXPECT_NE(r.err.find(earlier), std::string::npos) << r.err;
  EXPECT_EQ(slurp(earlier), "earlier result\n");
  const CliRun convert = runExe({"uff", "convert", in.frf, (ro / "new.uff").string()}, true);
  EXPECT_EQ(convert.code, kExitFailure) << convert.err;
  EXPECT_NE(convert.err.find((ro / "new.uff").string()), std::string::npos) << convert.err;
  EXPECT_FALSE(fs::exists(ro / "new.uff"));
  ::chmod(ro.c_str(), 0755);
}

// A colleague's share: the project in a folder the user cannot write. Reading
// commands work and leave no -wal or -shm behind.
TEST(Robustness, ReadOnlyCommandsWorkOnAProjectInAReadOnlyFolder) {
  const auto& in = Inputs::get();
  const fs::path share = in.dir / "share";
  fs::create_directories(share);
  const std::string project = (share / "p.mozzi").string();
  fs::copy_file(in.project, project, fs::copy_options::overwrite_existing);
  ::chmod(project.c_str(), 0644);
  ::chmod(share.c_str(), 0555);
  const std::string out = (in.dir / "from_share.csv").string();
  for (const auto& args : std::vector<std::vector<std::string>>{{"project", "info", project},
                                                                {"project", "info", project, "--json"},
                                                                {"project", "check", project},
                                                                {"project", "export", project, "--csv", out}}) {
    const CliRun r = runExe(args, true);
    EXPECT_EQ(r.code, kExitOk) << describe(args) << "\n" << r.err;
    EXPECT_FALSE(fs::exists(project + "-wal")) << describe(args);
    EXPECT_FALSE(fs::exists(project + "-shm")) << describe(args);
  }
  // And in a writable folder as well.
  for (const auto& args :
       std::vector<std::vector<std::string>>{{"project", "info", in.project}, {"project", "check", in.project}}) {
    const CliRun r = runExe(args);
    EXPECT_EQ(r.code, kExitOk) << r.err;
    EXPECT_FALSE(fs::exists(in.project + "-wal"));
    EXPECT_FALSE(fs::exists(in.project + "-shm"));
  }
  ::chmod(share.c_str(), 0755);
}

TEST(Robustness, ProjectCheckNamesEveryDamagedRecord) {
  const auto& in = Inputs::get();
  const std::string damaged = (in.dir / "damaged.mozzi").string();
  fs::copy_file(in.project, damaged, fs::copy_options::overwrite_existing);
  const CliRun clean = run({"project", "check", damaged});
  EXPECT_EQ(clean.code, kExitOk) << clean.err;
  EXPECT_NE(clean.out.find("no damaged record"), std::string::npos) << clean.out;
  {
    auto store = core::io::ProjectStore::open(damaged);
    ASSERT_TRUE(store.ok());
    ASSERT_EQ(sqlite3_exec(store->connection(), "UPDATE frf SET h = zeroblob(length(h))", nullptr, nullptr, nullptr),
              SQLITE_OK);
  }
  const CliRun r = run({"project", "check", damaged, "--json"});
  EXPECT_EQ(r.code, kExitFailure);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["ok"].get<bool>());
  ASSERT_GE(j["problems"].size(), 1u);
  EXPECT_NE(j["problems"][0]["record"].get<std::string>().find("FRF set 1"), std::string::npos);
  EXPECT_NE(r.err.find("damaged"), std::string::npos);
  // Export refuses the damaged set instead of writing wrong FRFs.
  const CliRun ex = run({"project", "export", damaged, "--csv", (in.dir / "damaged.csv").string()});
  EXPECT_EQ(ex.code, kExitFailure);
  EXPECT_NE(ex.err.find("checksum mismatch"), std::string::npos) << ex.err;
  EXPECT_FALSE(fs::exists(in.dir / "damaged.csv"));
}

// The ranges live in one place (each command's OptionSpec); docs/cli.md must
// state each of them as the code does (regenerate the table with
// scripts/cli-ranges-table.sh after changing a range).
TEST(Robustness, DocsStateEveryRange) {
  const std::string docs = slurp(std::string(MOZZI_SOURCE_DIR) + "/docs/cli.md");
  ASSERT_FALSE(docs.empty());
  for (const auto& c : registeredCommands()) {
    if (!c.options) continue;
    for (const auto& n : c.options->numbers) {
      const std::string row = "| `" + c.name + "` | `" + n.name + "` | " + n.help + " | " + n.rangeText() + " |";
      EXPECT_NE(docs.find(row), std::string::npos) << "docs/cli.md lacks the row\n" << row;
    }
  }
}

}  // namespace
}  // namespace mozzi::cli
