#pragma once
// The batch file of `mozzi-cli run` (format "mozzi-batch/1", docs/cli/run.md):
// a list of projects and a chain of steps, each step one mozzi-cli command line
// with {variables} filled in per project. Parsed and expanded here, without
// running anything, so every error in the file is found before the first step
// runs and names its place in the file (steps[2].run[3]).

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "core/common/result.h"

namespace mozzi::cli {

inline constexpr const char* kBatchFormat = "mozzi-batch/1";
inline constexpr std::size_t kMaxBatchProjects = 10000;
inline constexpr std::size_t kMaxBatchSteps = 1000;

struct BatchProject {
  std::string file;                         // as written in the script
  std::map<std::string, std::string> vars;  // its own variables (over the script's)
};

struct BatchStep {
  std::string name;               // "identify" unless the script names it
  std::vector<std::string> argv;  // the command line with {variables} unexpanded; argv[0] is the command
};

struct BatchScript {
  std::vector<BatchProject> projects;
  std::map<std::string, std::string> vars;  // script-wide variables
  std::vector<BatchStep> steps;
};

// Parses the text of a batch file; `where` names it in errors. Checks the
// structure only (known keys, types, sizes); commands are checked by the
// caller, which knows them.
core::Result<BatchScript> parseBatchScript(const std::string& text, const std::string& where);

// The built-in variables of a project (project, name, stem, dir), then the
// script's, then the project's own: later ones win.
std::map<std::string, std::string> batchVariables(const BatchScript& script, const BatchProject& project);

// Step `index` of the script for one project: every "{name}" replaced by its
// value, "{{" and "}}" by single braces. An unknown or unterminated variable
// is an error naming steps[index].run[k] and the project.
core::Result<std::vector<std::string>> expandBatchStep(const BatchScript& script, std::size_t index,
                                                       const BatchProject& project);

}  // namespace mozzi::cli
