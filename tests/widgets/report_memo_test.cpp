// ReportMemo (widgets/report/sections.h), the results a report's sections keep between the two
// layout passes: made once per key and type, kept by the context of one report only, nothing kept
// when making fails.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "widgets/report/sections.h"

namespace metrofit {
namespace {

TEST(ReportMemo, MakesEachValueOncePerKeyAndType) {
  ReportContext context;
  int made = 0;
  auto make = [&made] { return std::make_shared<const int>(++made); };
  const std::shared_ptr<const int> a = context.memo.get<int>("a", make);
  const std::shared_ptr<const int> again = context.memo.get<int>("a", make);
  EXPECT_EQ(a, again);  // the same object, not made twice
  EXPECT_EQ(*again, 1);
  EXPECT_EQ(*context.memo.get<int>("b", make), 2);
  // Another type under the same key is another value.
  const auto text =
      context.memo.get<std::string>("a", [] { return std::make_shared<const std::string>("x"); });
  EXPECT_EQ(*text, "x");
  EXPECT_EQ(made, 2);
  EXPECT_EQ(context.memo.size(), 3u);
}

TEST(ReportMemo, NothingIsKeptWhenMakingFails) {
  ReportContext context;
  EXPECT_THROW(
      context.memo.get<int>("k", []() -> std::shared_ptr<const int> { throw std::runtime_error("no"); }),
      std::runtime_error);
  EXPECT_EQ(context.memo.size(), 0u);
  EXPECT_EQ(*context.memo.get<int>("k", [] { return std::make_shared<const int>(7); }), 7);
}

TEST(ReportMemo, EveryReportContextHasItsOwn) {
  ReportContext first, second;
  (void)first.memo.get<int>("k", [] { return std::make_shared<const int>(1); });
  EXPECT_EQ(*second.memo.get<int>("k", [] { return std::make_shared<const int>(2); }), 2);
  EXPECT_EQ(*first.memo.get<int>("k", [] { return std::make_shared<const int>(3); }), 1);
}

}  // namespace
}  // namespace metrofit
