// startThreadOnAnotherCore: the body runs once, on a core other than the
// caller's when the caller may use another, and afterwards may run on every
// core the caller may (a placement at the start, not a pinning).
#include "core/common/thread_start.h"

#include <gtest/gtest.h>

#include <pthread.h>
#include <sched.h>

#include <atomic>

namespace mozzi::core {
namespace {

cpu_set_t allowedCores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  EXPECT_EQ(pthread_getaffinity_np(pthread_self(), sizeof set, &set), 0);
  return set;
}

// What the body saw: the core it started on and the cores it may use.
struct Started {
  int core = -1;
  cpu_set_t allowed{};
  int runs = 0;
};

Started startAndJoin() {
  Started seen;
  std::thread thread = startThreadOnAnotherCore([&seen] {
    seen.core = sched_getcpu();
    seen.allowed = allowedCores();
    ++seen.runs;
  });
  thread.join();
  return seen;
}

TEST(StartThreadOnAnotherCore, StartsOffTheCallersCoreAndMayThenUseAllOfItsCores) {
  const cpu_set_t callers = allowedCores();
  if (CPU_COUNT(&callers) < 2) GTEST_SKIP() << "one core allowed: there is no other core to start on";
  // The caller joins at once, so an unplaced thread would start on the
  // caller's core as soon as it sleeps. A placed one starts elsewhere; it
  // reads its core after widening its cores again, so a migration in between
  // could still put it back: 3 of 20 are allowed for that on a loaded machine.
  int elsewhere = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const int here = sched_getcpu();
    const Started seen = startAndJoin();
    ASSERT_EQ(seen.runs, 1);
    EXPECT_TRUE(CPU_EQUAL(&seen.allowed, &callers)) << "trial " << trial << ": the thread was left pinned";
    if (seen.core != here) ++elsewhere;
  }
  EXPECT_GE(elsewhere, 17) << "threads started off the caller's core, of 20";
}

TEST(StartThreadOnAnotherCore, RunsOnTheOnlyCoreACallerRestrictedToOneMayUse) {
  const cpu_set_t callers = allowedCores();
  const int only = sched_getcpu();
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(only, &one);
  ASSERT_EQ(pthread_setaffinity_np(pthread_self(), sizeof one, &one), 0);
  const Started seen = startAndJoin();
  ASSERT_EQ(pthread_setaffinity_np(pthread_self(), sizeof callers, &callers), 0);  // restore before asserting
  EXPECT_EQ(seen.runs, 1);
  EXPECT_EQ(seen.core, only);
  EXPECT_TRUE(CPU_EQUAL(&seen.allowed, &one));
}

}  // namespace
}  // namespace mozzi::core
