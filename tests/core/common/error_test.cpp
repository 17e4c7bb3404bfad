#include "core/common/error.h"

#include <gtest/gtest.h>

#include "core/common/run.h"

namespace metrofit {
namespace {

TEST(Error, MessageNamesFileLineColumnAndField) {
  const ParseError e(ErrorContext{"log.csv", 12, 3, "T1"}, "'abc' is not a number");
  EXPECT_STREQ(e.what(), "log.csv:12:3: field 'T1': 'abc' is not a number");
  EXPECT_EQ(e.detail(), "'abc' is not a number");
  EXPECT_EQ(e.context().line, 12);
}

TEST(Error, OmitsUnknownParts) {
  EXPECT_STREQ(ValidationError(ErrorContext{"m.json", 0, 0, "bounds_mm"}, "reversed").what(),
               "m.json: field 'bounds_mm': reversed");
  EXPECT_STREQ(InputError(ErrorContext{}, "plain").what(), "plain");
  EXPECT_STREQ(InputError(ErrorContext{{}, 4, 2, {}}, "x").what(), "line 4, column 2: x");
}

TEST(Error, HierarchyMapsToExitCodes) {
  // Everything a user can cause is an InputError (CLI exit code 2).
  EXPECT_NO_THROW(
      (void)dynamic_cast<const InputError&>(static_cast<const Error&>(ParseError(ErrorContext{}, "a"))));
  EXPECT_NO_THROW(
      (void)dynamic_cast<const InputError&>(static_cast<const Error&>(FileError(ErrorContext{}, "a"))));
  EXPECT_NO_THROW(
      (void)dynamic_cast<const InputError&>(static_cast<const Error&>(OptionsError(ErrorContext{}, "a"))));
}

struct DemoOptions {
  int population = 10;
  bool isValid(std::string* why) const {
    if (population < 2) {
      if (why) *why = "population must be at least 2";
      return false;
    }
    return true;
  }
};

TEST(Run, RequireValidThrowsOptionsErrorWithReason) {
  DemoOptions o;
  EXPECT_NO_THROW(requireValid(o, "demo options"));
  o.population = 1;
  try {
    requireValid(o, "demo options");
    FAIL() << "expected OptionsError";
  } catch (const OptionsError& e) {
    EXPECT_STREQ(e.what(), "field 'demo options': population must be at least 2");
  }
}

TEST(Run, NotifyRecordsTraceAndObserverCanStop) {
  RunInfo run;
  int calls = 0;
  FunctionObserver obs([&](const IterationSummary& s) {
    ++calls;
    return s.iteration >= 2 ? ObserverDecision::Stop : ObserverDecision::Continue;
  });
  bool stopped = false;
  long it = 0;
  for (; it < 10 && !stopped; ++it) {
    IterationSummary s;
    s.iteration = it;
    s.evaluations = 10 * (it + 1);
    stopped = notify(&obs, run, s, true);
  }
  EXPECT_EQ(calls, 3);
  EXPECT_EQ(run.trace.size(), 3u);
  EXPECT_EQ(run.termination, Termination::Cancelled);
  EXPECT_EQ(run.evaluations, 30);
  EXPECT_EQ(run.iterations, 3);
}

TEST(Run, CancelTokenStopsFromAnotherThread) {
  CancelToken token;
  IterationSummary s;
  EXPECT_EQ(token.onIteration(s), ObserverDecision::Continue);
  token.cancel();
  EXPECT_EQ(token.onIteration(s), ObserverDecision::Stop);
  EXPECT_STREQ(toString(Termination::BudgetExhausted), "budget exhausted");
}

}  // namespace
}  // namespace metrofit
