// mozzi-cli: the batch face of Mozzi. Links core and devices only.
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

#include "app/cli/command.h"

#if defined(__GLIBC__)
namespace {
// The heap grown once by 64 MB of address space (M_TOP_PAD: nothing is
// touched, so nothing is resident) and that range marked for transparent
// huge pages. A command's large buffers (`frf`: two hits' samples, spectra,
// accumulators, the FRF: 13 MB) then fault in 2 MB at a time instead of
// 4 kB: `frf` took 4,240 page faults and 14 ms of system time, 1,000 and 7 ms
// with this (issue 19). Where the kernel has no huge page free it falls back
// to small pages; where THP is off ("never") the advice does nothing.
void heapOnHugePages() {
  constexpr std::size_t kPad = std::size_t{64} << 20;
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  mallopt(M_TOP_PAD, static_cast<int>(kPad));
  void* volatile grow = std::malloc(std::size_t{1} << 20);  // volatile: the pair is not elided
  std::free(grow);
  const auto top = reinterpret_cast<std::uintptr_t>(sbrk(0));
  const std::size_t arena = mallinfo2().arena;  // the main heap, from its start to top
  if (arena < kPad || top < arena) return;      // not grown in place (sbrk failed, malloc used mmap)
  const std::uintptr_t from = (top - arena + kHuge - 1) / kHuge * kHuge, to = top / kHuge * kHuge;
  if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_HUGEPAGE);  // advice only: failure is harmless
}
}  // namespace
#endif

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
  // One arena for every thread: `frf` averages on a second thread, whose
  // buffers would otherwise come from a per-thread arena of fresh 4 kB pages
  // outside the huge-page heap below.
  mallopt(M_ARENA_MAX, 1);
  heapOnHugePages();
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
