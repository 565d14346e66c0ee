// mozzi-cli run: a batch file of mozzi-cli steps over several projects (issue
// 23, docs/cli/run.md). Every step is a command of this program run in this
// process with its own option table, so a batch does exactly what the same
// commands typed one by one would do. The whole file is checked before the
// first step runs; a failed step stops its project (later steps need its
// results), the other projects go on, and the run exits 1 naming each failed
// step and file. Many projects on many machines: one `mozzi-cli run --project`
// per project under any scheduler.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>

#include "app/cli/args.h"
#include "app/cli/batch_script.h"
#include "app/cli/command.h"
#include "core/io/text_file.h"

namespace mozzi::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kSynopsis = "SCRIPT.json [--project FILE] [--check] [--quiet | --json]";

const OptionSpec kSpec{{"--project"}, {"--check", "--quiet", "--json"}};

int usage(std::ostream& err, const std::string& why) {
  err << "mozzi-cli run: " << why << "\nUsage: mozzi-cli run " << kSynopsis << "\n";
  return kExitUsage;
}

// The first line of a step's error output, bounded: what the summary quotes.
std::string firstLine(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  constexpr std::size_t kShown = 300;
  if (line.size() > kShown) line = line.substr(0, kShown) + "...";
  return line;
}

std::string commandLine(const std::vector<std::string>& argv) {
  std::string text = "mozzi-cli";
  for (const auto& a : argv) text += " " + (a.find(' ') == std::string::npos && !a.empty() ? a : "'" + a + "'");
  return text;
}

// Runs in the script's folder (relative paths in a batch file are relative to
// it, wherever the run is started) and returns to where it was.
class FolderScope {
 public:
  explicit FolderScope(const fs::path& folder) : previous_(fs::current_path(ec_)) {
    if (!ec_ && !folder.empty()) fs::current_path(folder, ec_);
  }
  ~FolderScope() {
    std::error_code ignored;
    if (!previous_.empty()) fs::current_path(previous_, ignored);
  }
  FolderScope(const FolderScope&) = delete;
  FolderScope& operator=(const FolderScope&) = delete;
  const std::error_code& error() const { return ec_; }

 private:
  std::error_code ec_;
  fs::path previous_;
};

// The progress line on a terminal (redrawn in place), else one line per step.
class Progress {
 public:
  Progress(std::ostream& err, std::size_t total, bool enabled)
      : err_(err), total_(total), enabled_(enabled), terminal_(enabled && &err == &std::cerr && ::isatty(2) == 1) {}

  void start(std::size_t done, const std::string& project, const std::string& step) {
    if (!enabled_) return;
    if (terminal_) {
      constexpr std::size_t kWidth = 24;
      const std::size_t filled = total_ ? done * kWidth / total_ : kWidth;
      err_ << "\r\033[K[" << std::string(filled, '#') << std::string(kWidth - filled, '.') << "] " << done << "/"
           << total_ << " " << project << ": " << step << std::flush;
    }
  }
  void finish(std::size_t done, const std::string& project, const std::string& step, bool ok, double seconds) {
    if (!enabled_) return;
    clear();
    if (!terminal_) {
      char time[32];
      std::snprintf(time, sizeof time, "%.1f s", seconds);
      err_ << "mozzi-cli run: [" << done << "/" << total_ << "] " << project << ": " << step << " "
           << (ok ? "done" : "FAILED") << " (" << time << ")\n";
    }
  }
  // Before anything else is written to the terminal.
  void clear() {
    if (terminal_) err_ << "\r\033[K" << std::flush;
  }

 private:
  std::ostream& err_;
  std::size_t total_;
  bool enabled_;
  bool terminal_;
};

struct StepOutcome {
  std::string name;
  std::vector<std::string> argv;
  int exitCode = 0;
  double seconds = 0.0;
  std::string error;  // first line of its error output when it failed
};

struct ProjectOutcome {
  std::string file;
  std::vector<StepOutcome> steps;  // the steps that ran, in order
  bool failed = false;
};

int runCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const auto parsed = ParsedArgs::parse(args, kSpec);
  if (!parsed) {
    err << "mozzi-cli run: " << parsed.error().describe() << "\nUsage: mozzi-cli run " << kSynopsis << "\n";
    return exitCodeFor(parsed.error());
  }
  if (parsed->positional().size() != 1) return usage(err, "expected one batch file");
  if (parsed->flag("--quiet") && parsed->flag("--json")) return usage(err, "--quiet and --json exclude each other");
  const std::string scriptPath = parsed->positional()[0];
  const bool json = parsed->flag("--json");

  // 1. The file: read (1 MiB cap), parsed, every step expanded for every
  // project and its options parsed by its command's table — nothing runs
  // until the whole file is known to be runnable.
  auto text = core::io::readTextFile(scriptPath, "batch file", core::io::kMaxParameterFileBytes);
  if (!text) {
    err << "mozzi-cli run: " << text.error().describe() << "\n";
    return kExitFailure;
  }
  auto script = parseBatchScript(*text, scriptPath);
  if (!script) {
    err << "mozzi-cli run: " << script.error().describe() << "\n";
    return kExitFailure;
  }
  std::vector<const BatchProject*> projects;
  const auto only = parsed->value("--project");
  for (const auto& p : script->projects) {
    if (!only || p.file == *only) projects.push_back(&p);
  }
  if (projects.empty()) {
    err << "mozzi-cli run: " << scriptPath << " lists no project " << quotedArg(*only) << "\n";
    return kExitFailure;
  }
  std::map<std::string, Command> commands;
  for (auto& c : registeredCommands()) commands.emplace(c.name, c);
  std::vector<std::vector<std::vector<std::string>>> lines(projects.size());
  for (std::size_t p = 0; p < projects.size(); ++p) {
    for (std::size_t s = 0; s < script->steps.size(); ++s) {
      auto argv = expandBatchStep(*script, s, *projects[p]);
      if (!argv) {
        err << "mozzi-cli run: " << scriptPath << ": " << argv.error().describe() << "\n";
        return kExitFailure;
      }
      const std::string place =
          scriptPath + ": steps[" + std::to_string(s) + "] for project " + quotedArg(projects[p]->file) + ": ";
      const auto it = commands.find(argv->front());
      if (it == commands.end()) {
        err << "mozzi-cli run: " << place << "unknown command " << quotedArg(argv->front())
            << " (see 'mozzi-cli --help')\n";
        return kExitFailure;
      }
      if (it->first == "run") {
        err << "mozzi-cli run: " << place << "a batch step cannot be another batch run\n";
        return kExitFailure;
      }
      if (it->second.options) {
        const std::vector<std::string> rest(argv->begin() + 1, argv->end());
        if (auto check = ParsedArgs::parse(rest, *it->second.options); !check) {
          err << "mozzi-cli run: " << place << argv->front() << ": " << check.error().describe() << "\n";
          return kExitFailure;
        }
      }
      lines[p].push_back(std::move(*argv));
    }
  }
  if (parsed->flag("--check")) {
    if (!json) {
      out << scriptPath << ": " << projects.size() << " project" << (projects.size() == 1 ? "" : "s") << " x "
          << script->steps.size() << " step" << (script->steps.size() == 1 ? "" : "s") << ", every step checked\n";
      for (std::size_t p = 0; p < projects.size(); ++p) {
        for (const auto& argv : lines[p]) out << "  " << commandLine(argv) << "\n";
      }
    } else {
      nlohmann::json j{{"script", scriptPath}, {"checked", true}, {"projects", nlohmann::json::array()}};
      for (std::size_t p = 0; p < projects.size(); ++p) {
        nlohmann::json steps = nlohmann::json::array();
        for (const auto& argv : lines[p]) steps.push_back(argv);
        j["projects"].push_back({{"file", projects[p]->file}, {"steps", steps}});
      }
      out << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    }
    return kExitOk;
  }

  // 2. The run, in the script's folder.
  FolderScope folder(fs::path(scriptPath).parent_path());
  if (folder.error()) {
    err << "mozzi-cli run: cannot enter the folder of " << scriptPath << ": " << folder.error().message() << "\n";
    return kExitFailure;
  }
  const bool quiet = parsed->flag("--quiet");
  Progress progress(err, projects.size() * script->steps.size(), !quiet);
  std::vector<ProjectOutcome> outcomes;
  std::size_t done = 0;
  for (std::size_t p = 0; p < projects.size(); ++p) {
    ProjectOutcome outcome{projects[p]->file, {}, false};
    for (std::size_t s = 0; s < lines[p].size(); ++s) {
      const std::string& name = script->steps[s].name;
      progress.start(done, outcome.file, name);
      std::ostringstream stepOut, stepErr;
      const auto t0 = std::chrono::steady_clock::now();
      const int code = runCli(lines[p][s], stepOut, stepErr);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      ++done;
      progress.finish(done, outcome.file, name, code == kExitOk, seconds);
      if (!json && !quiet) out << "== " << outcome.file << ": " << name << " ==\n" << stepOut.str() << std::flush;
      err << stepErr.str();
      StepOutcome step{name, lines[p][s], code, seconds, code == kExitOk ? "" : firstLine(stepErr.str())};
      outcome.steps.push_back(step);
      if (code != kExitOk) {
        outcome.failed = true;
        done += lines[p].size() - s - 1;  // the project's later steps are not run
        break;
      }
    }
    outcomes.push_back(std::move(outcome));
  }
  progress.clear();

  // 3. What failed, named; the JSON summary.
  std::size_t failed = 0;
  for (const auto& o : outcomes) {
    if (!o.failed) continue;
    ++failed;
    const StepOutcome& s = o.steps.back();
    const std::size_t index = o.steps.size() - 1;
    err << "mozzi-cli run: project " << o.file << ": step " << index + 1 << " '" << s.name << "' ("
        << commandLine(s.argv) << ") failed with exit " << s.exitCode << (s.error.empty() ? "" : ": " + s.error) << "; "
        << script->steps.size() - index - 1 << " later step" << (script->steps.size() - index - 1 == 1 ? "" : "s")
        << " not run\n";
  }
  if (json) {
    nlohmann::json j{{"script", scriptPath}, {"failed_projects", failed}, {"projects", nlohmann::json::array()}};
    for (const auto& o : outcomes) {
      nlohmann::json steps = nlohmann::json::array();
      for (const auto& s : o.steps) {
        steps.push_back(
            {{"name", s.name}, {"command", s.argv}, {"exit", s.exitCode}, {"seconds", s.seconds}, {"error", s.error}});
      }
      j["projects"].push_back({{"file", o.file},
                               {"status", o.failed ? "failed" : "done"},
                               {"steps_run", o.steps.size()},
                               {"steps", steps}});
    }
    out << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  } else if (!quiet) {
    out << "mozzi-cli run: " << outcomes.size() - failed << " of " << outcomes.size() << " project"
        << (outcomes.size() == 1 ? "" : "s") << " done\n";
  }
  return failed == 0 ? kExitOk : kExitFailure;
}

const CommandRegistrar kRegistrar({"run", kSynopsis,
                                   "Run a batch file: a chain of mozzi-cli steps (import, campaign, frf, identify, "
                                   "stiffness, stability, gap, report...) over several projects",
                                   runCommand, &kSpec});

}  // namespace
}  // namespace mozzi::cli
