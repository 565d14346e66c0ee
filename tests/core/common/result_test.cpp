#include "core/common/result.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace mozzi::core {
namespace {

// Counts how often the tried expression is evaluated: each macro must
// evaluate it exactly once, on success and on failure.
struct Calls {
  int count = 0;
  Result<int> number(bool ok, int value) {
    ++count;
    if (!ok) return makeError(ErrorCode::ParseError, "bad number", "line " + std::to_string(value));
    return value;
  }
  Result<void> check(bool ok) {
    ++count;
    if (!ok) return makeError(ErrorCode::NotFound, "missing", "check");
    return {};
  }
};

Result<void> tryVoid(Calls& calls, bool ok, bool* reachedEnd) {
  MOZZI_TRY(calls.check(ok));
  *reachedEnd = true;
  return {};
}

// MOZZI_TRY in a function of another result type: the Error converts.
Result<std::string> tryInString(Calls& calls, bool ok) {
  MOZZI_TRY(calls.check(ok));
  return std::string("done");
}

Result<int> sumOfTwo(Calls& calls, bool firstOk, bool secondOk) {
  MOZZI_TRY_ASSIGN(const int a, calls.number(firstOk, 20));
  MOZZI_TRY_ASSIGN(int b, calls.number(secondOk, 22));
  b += a;
  return b;
}

Result<std::unique_ptr<int>> makeOwned(bool ok) {
  if (!ok) return makeError(ErrorCode::InvalidArgument, "no value");
  return std::make_unique<int>(7);
}

// A move-only value is moved out of the Result, not copied.
Result<int> readOwned(bool ok) {
  MOZZI_TRY_ASSIGN(std::unique_ptr<int> owned, makeOwned(ok));
  return *owned * 6;
}

// Assigning to an existing variable (no declaration) also works.
Result<int> assignExisting(Calls& calls, bool ok) {
  int value = -1;
  MOZZI_TRY_ASSIGN(value, calls.number(ok, 5));
  return value + 1;
}

TEST(MozziTry, SuccessContinuesAndEvaluatesOnce) {
  Calls calls;
  bool reached = false;
  EXPECT_TRUE(tryVoid(calls, true, &reached).ok());
  EXPECT_TRUE(reached);
  EXPECT_EQ(calls.count, 1);
  auto s = tryInString(calls, true);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(*s, "done");
  EXPECT_EQ(calls.count, 2);
}

TEST(MozziTry, ErrorReturnsEarlyWithTheSameError) {
  Calls calls;
  bool reached = false;
  auto r = tryVoid(calls, false, &reached);
  ASSERT_FALSE(r.ok());
  EXPECT_FALSE(reached);
  EXPECT_EQ(calls.count, 1);
  EXPECT_EQ(r.error().code, ErrorCode::NotFound);
  EXPECT_EQ(r.error().message, "missing");
  EXPECT_EQ(r.error().where, "check");
  auto s = tryInString(calls, false);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().describe(), "not found: missing (check)");
}

TEST(MozziTryAssign, BindsValuesAndStopsAtTheFirstError) {
  Calls calls;
  auto sum = sumOfTwo(calls, true, true);
  ASSERT_TRUE(sum.ok());
  EXPECT_EQ(*sum, 42);
  EXPECT_EQ(calls.count, 2);

  calls.count = 0;
  auto first = sumOfTwo(calls, false, true);
  ASSERT_FALSE(first.ok());
  EXPECT_EQ(first.error().where, "line 20");
  EXPECT_EQ(calls.count, 1);  // the second call never ran

  calls.count = 0;
  auto second = sumOfTwo(calls, true, false);
  ASSERT_FALSE(second.ok());
  EXPECT_EQ(second.error().code, ErrorCode::ParseError);
  EXPECT_EQ(second.error().where, "line 22");
  EXPECT_EQ(calls.count, 2);
}

TEST(MozziTryAssign, MovesMoveOnlyValuesAndAssignsExistingVariables) {
  auto owned = readOwned(true);
  ASSERT_TRUE(owned.ok());
  EXPECT_EQ(*owned, 42);
  auto missing = readOwned(false);
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().message, "no value");

  Calls calls;
  auto assigned = assignExisting(calls, true);
  ASSERT_TRUE(assigned.ok());
  EXPECT_EQ(*assigned, 6);
  EXPECT_FALSE(assignExisting(calls, false).ok());
}

}  // namespace
}  // namespace mozzi::core
