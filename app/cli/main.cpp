// mozzi-cli: the batch face of Mozzi. Links core and devices only.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "app/cli/command.h"

int main(int argc, char** argv) {
#if defined(__GLIBC__)
  // A command is one short process that allocates the same large buffers
  // over and over (a hit's copy of the force, its spectrum: 0.5 MB each).
  // glibc serves blocks above its mmap threshold with mmap and trims the heap
  // above its trim threshold, so each of those allocations costs fresh
  // zero-filled pages: 40% of `frf`'s CPU time went to page faults (issue 19).
  // Keep freed memory in the heap for reuse; it goes back at exit.
  mallopt(M_MMAP_THRESHOLD, 256 << 20);
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
#endif
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
