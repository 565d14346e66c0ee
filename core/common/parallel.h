#pragma once
// Independent tasks spread over the machine's cores. The tasks must not share
// mutable state; each writes its own slot of a result vector, so the results
// do not depend on the number of threads or on the order the tasks run in.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "core/common/thread_start.h"

namespace mozzi::core {

// Runs body(i) for i in [0, n) on up to `threads` threads (0: one per
// hardware thread), the calling thread among them. The first exception a
// task throws is rethrown here once every thread has stopped.
template <typename Body>
void parallelFor(std::size_t n, Body&& body, unsigned threads = 0) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, n));
  if (threads <= 1) {
    for (std::size_t i = 0; i < n; ++i) body(i);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto worker = [&] {
    for (std::size_t i = next++; i < n; i = next++) {
      try {
        body(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failureMutex);
        if (!failure) failure = std::current_exception();
        next = n;
      }
    }
  };
  std::vector<std::thread> pool;
  // Placed off the calling thread's core, which is busy with worker() below.
  for (unsigned t = 1; t < threads; ++t) pool.push_back(startThreadOnAnotherCore(worker));
  worker();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace mozzi::core
