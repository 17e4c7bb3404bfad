#include "core/common/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace metrofit {
namespace {

TEST(Rng, SameSeedSameSequenceBitForBit) {
  Rng a(42), b(42), c(43);
  bool differs = false;
  for (int i = 0; i < 1000; ++i) {
    const double x = a.normal(), y = b.normal(), z = c.normal();
    ASSERT_EQ(x, y);
    differs |= (x != z);
  }
  EXPECT_TRUE(differs);
}

TEST(Rng, KnownFirstValuesPinTheAlgorithm) {
  // xoshiro256** seeded by splitmix64(0): guards against an accidental change of the generator,
  // which would silently change every seeded result in the project.
  Rng r(0);
  const std::uint64_t first = r.next();
  Rng r2(0);
  EXPECT_EQ(first, r2.next());
  EXPECT_EQ(first, 0x99EC5F36CB75F2B4ULL);
}

TEST(Rng, UniformAndNormalMoments) {
  Rng r(7);
  const int n = 200000;
  double su = 0, sn = 0, sn2 = 0, lo = 1, hi = 0;
  for (int i = 0; i < n; ++i) {
    const double u = r.uniform();
    lo = std::min(lo, u);
    hi = std::max(hi, u);
    su += u;
    const double g = r.normal();
    sn += g;
    sn2 += g * g;
  }
  EXPECT_GE(lo, 0.0);
  EXPECT_LT(hi, 1.0);
  EXPECT_NEAR(su / n, 0.5, 0.005);
  EXPECT_NEAR(sn / n, 0.0, 0.01);
  EXPECT_NEAR(sn2 / n, 1.0, 0.015);
}

TEST(Rng, BelowStaysInRange) {
  Rng r(3);
  std::vector<int> hits(7, 0);
  for (int i = 0; i < 7000; ++i) ++hits[r.below(7)];
  for (int h : hits) EXPECT_GT(h, 800);
  EXPECT_EQ(r.below(0), 0u);
}

}  // namespace
}  // namespace metrofit
