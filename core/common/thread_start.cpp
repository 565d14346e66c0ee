#include "core/common/thread_start.h"

#include <atomic>
#include <memory>
#include <optional>
#include <utility>

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#endif

namespace mozzi::core {

#if defined(__linux__)
namespace {
// The calling thread's core, the cores it may use, and those but its own.
struct CallerCores {
  int here = -1;
  cpu_set_t allowed{};
  cpu_set_t elsewhere{};
};
// Empty where the core or the cores cannot be read, or no other core is allowed.
std::optional<CallerCores> callerCores() {
  CallerCores c;
  c.here = sched_getcpu();
  if (c.here < 0 || c.here >= CPU_SETSIZE || pthread_getaffinity_np(pthread_self(), sizeof c.allowed, &c.allowed) != 0)
    return std::nullopt;
  c.elsewhere = c.allowed;
  CPU_CLR(c.here, &c.elsewhere);
  if (CPU_COUNT(&c.elsewhere) == 0) return std::nullopt;
  return c;
}
}  // namespace
#endif

std::thread startThreadOnAnotherCore(std::function<void()> body) {
#if defined(__linux__)
  if (const auto cores = callerCores()) {
    const cpu_set_t allowed = cores->allowed, elsewhere = cores->elsewhere;
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
#endif
  return std::thread(std::move(body));
}

#if defined(__linux__)
struct PairedThread::CreatorCores {
  pthread_t thread;
  cpu_set_t cores;
};
#else
struct PairedThread::CreatorCores {};
#endif

PairedThread::PairedThread(std::function<void()> body) {
#if defined(__linux__)
  if (const auto cores = callerCores()) {
    const cpu_set_t elsewhere = cores->elsewhere;
    cpu_set_t mine;
    CPU_ZERO(&mine);
    CPU_SET(cores->here, &mine);
    if (pthread_setaffinity_np(pthread_self(), sizeof mine, &mine) == 0) {
      creator_ = std::make_unique<CreatorCores>(CreatorCores{pthread_self(), cores->allowed});
      // The helper waits until it is held elsewhere, so that it never starts
      // on the creator's core.
      auto held = std::make_shared<std::atomic<bool>>(false);
      thread_ = std::thread([held, body = std::move(body)]() mutable {
        while (!held->load(std::memory_order_acquire)) std::this_thread::yield();
        body();
      });
      (void)pthread_setaffinity_np(thread_.native_handle(), sizeof elsewhere, &elsewhere);  // a hint: may fail
      held->store(true, std::memory_order_release);
      return;
    }
  }
#endif
  thread_ = std::thread(std::move(body));
}

PairedThread::PairedThread() = default;
PairedThread::PairedThread(PairedThread&&) noexcept = default;

PairedThread& PairedThread::operator=(PairedThread&& other) noexcept {
  if (this != &other) {
    if (joinable()) join();
    thread_ = std::move(other.thread_);
    creator_ = std::move(other.creator_);
  }
  return *this;
}

PairedThread::~PairedThread() {
  if (joinable()) join();
}

void PairedThread::join() {
  thread_.join();
#if defined(__linux__)
  if (creator_) (void)pthread_setaffinity_np(creator_->thread, sizeof creator_->cores, &creator_->cores);
#endif
  creator_.reset();
}

}  // namespace mozzi::core
