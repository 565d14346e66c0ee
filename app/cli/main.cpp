// mozzi-cli: the batch face of Mozzi. Links core and devices only.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "app/cli/command.h"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  const int code = mozzi::cli::runCli(args, std::cout, std::cerr);
  // Standard output is an output too: a report that could not be written
  // (a full disk behind a redirection, /dev/full, a closed pipe) fails the run.
  std::cout.flush();
  if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout)) {
    std::cerr << "mozzi-cli: cannot write the standard output" << (errno ? ": " : "")
              << (errno ? std::strerror(errno) : "") << "\n";
    return code == 0 ? 1 : code;
  }
  return code;
}
