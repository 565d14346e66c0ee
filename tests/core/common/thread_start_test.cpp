// startThreadOnAnotherCore: the body runs once, on a core other than the
// caller's when the caller may use another, and afterwards may run on every
// core the caller may (a placement at the start, not a pinning).
// PairedThread: while the helper runs, it and its creator are held on two
// different cores; join() gives the creator back its cores.
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

cpu_set_t onlyCore(int core) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(core, &set);
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
  const cpu_set_t one = onlyCore(only);
  ASSERT_EQ(pthread_setaffinity_np(pthread_self(), sizeof one, &one), 0);
  const Started seen = startAndJoin();
  ASSERT_EQ(pthread_setaffinity_np(pthread_self(), sizeof callers, &callers), 0);  // restore before asserting
  EXPECT_EQ(seen.runs, 1);
  EXPECT_EQ(seen.core, only);
  EXPECT_TRUE(CPU_EQUAL(&seen.allowed, &one));
}

TEST(PairedThread, HoldsTheHelperAndItsCreatorOnTwoCoresUntilJoined) {
  const cpu_set_t callers = allowedCores();
  if (CPU_COUNT(&callers) < 2) GTEST_SKIP() << "one core allowed: there is no other core to hold the helper on";
  std::atomic<bool> creatorLooked{false};
  cpu_set_t creatorWhileRunning{};
  int creatorCore = -1;
  Started helper;
  PairedThread paired([&] {
    helper.core = sched_getcpu();
    helper.allowed = allowedCores();
    ++helper.runs;
    while (!creatorLooked.load()) std::this_thread::yield();  // the creator looks while the helper lives
  });
  creatorCore = sched_getcpu();
  creatorWhileRunning = allowedCores();
  creatorLooked.store(true);
  ASSERT_TRUE(paired.joinable());
  paired.join();
  EXPECT_FALSE(paired.joinable());
  EXPECT_EQ(helper.runs, 1);
  // The creator is held on one core, the helper on the creator's others.
  EXPECT_EQ(CPU_COUNT(&creatorWhileRunning), 1);
  EXPECT_TRUE(CPU_ISSET(creatorCore, &creatorWhileRunning));
  EXPECT_FALSE(CPU_ISSET(creatorCore, &helper.allowed));
  EXPECT_EQ(CPU_COUNT(&helper.allowed), CPU_COUNT(&callers) - 1);
  EXPECT_NE(helper.core, creatorCore);
  const cpu_set_t after = allowedCores();
  EXPECT_TRUE(CPU_EQUAL(&after, &callers)) << "join() did not give the creator back its cores";
}

TEST(PairedThread, IsAPlainThreadForACreatorRestrictedToOneCore) {
  const cpu_set_t callers = allowedCores();
  const int only = sched_getcpu();
  const cpu_set_t one = onlyCore(only);
  ASSERT_EQ(pthread_setaffinity_np(pthread_self(), sizeof one, &one), 0);
  Started helper;
  {
    PairedThread paired([&] {
      helper.core = sched_getcpu();
      ++helper.runs;
    });
  }  // the destructor joins
  const cpu_set_t after = allowedCores();
  ASSERT_EQ(pthread_setaffinity_np(pthread_self(), sizeof callers, &callers), 0);  // restore before asserting
  EXPECT_EQ(helper.runs, 1);
  EXPECT_EQ(helper.core, only);
  EXPECT_TRUE(CPU_EQUAL(&after, &one)) << "a creator with one core keeps exactly that core";
}

}  // namespace
}  // namespace mozzi::core
