#pragma once
// Runs the mozzi-cli dispatcher in-process, capturing exit code and both streams:
// the one helper every CLI test uses.

#include <sstream>
#include <string>
#include <vector>

#include "app/cli/command.h"

namespace mozzi::cli {

struct CliRun {
  int code;
  std::string out;
  std::string err;
};

inline CliRun run(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int code = runCli(args, out, err);
  return {code, out.str(), err.str()};
}

}  // namespace mozzi::cli
