#include "core/common/thread_start.h"

#include <atomic>
#include <memory>
#include <utility>

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#endif

namespace mozzi::core {

std::thread startThreadOnAnotherCore(std::function<void()> body) {
#if defined(__linux__)
  cpu_set_t allowed;
  const int here = sched_getcpu();
  if (here >= 0 && here < CPU_SETSIZE && pthread_getaffinity_np(pthread_self(), sizeof allowed, &allowed) == 0) {
    cpu_set_t elsewhere = allowed;
    CPU_CLR(here, &elsewhere);
    if (CPU_COUNT(&elsewhere) > 0) {
      // The thread restores the caller's set only after the caller has placed
      // it, so that the placement cannot outlast the start.
      auto placed = std::make_shared<std::atomic<bool>>(false);
      std::thread thread([placed, allowed, body = std::move(body)]() mutable {
        while (!placed->load(std::memory_order_acquire)) std::this_thread::yield();
        // On failure it stays off the caller's core: it still runs, on fewer cores.
        (void)pthread_setaffinity_np(pthread_self(), sizeof allowed, &allowed);
        body();
      });
      (void)pthread_setaffinity_np(thread.native_handle(), sizeof elsewhere, &elsewhere);  // a hint: may fail
      placed->store(true, std::memory_order_release);
      return thread;
    }
  }
#endif
  return std::thread(std::move(body));
}

}  // namespace mozzi::core
