// The objectives of the setup correction (core/setup/objective.h, paper Eq. 6-10) on hand-computed
// cases of the small model: D1 = W1 + T5 within [-0.02, 0.02], D2 = 2 W1 + T5 within [-0.05, 0.03].
#include <gtest/gtest.h>

#include <cmath>

#include "core/common/error.h"
#include "core/setup/objective.h"
#include "setup_fixtures.h"

namespace metrofit::setup {
namespace {

using metrofit::test::near;

SetupInstance smallInstance() {
  return SetupInstance(test::smallModel(), {0.010, -0.005});
}

TEST(SetupObjective, BeforeCorrection) {
  const SetupInstance inst = smallInstance();
  const std::vector<double> zero{0.0, 0.0};
  // delta_1 = min(0.02 - 0.01, 0.01 + 0.02) = 0.01; delta_2 = min(0.03 + 0.005, -0.005 + 0.05) = 0.035
  const auto b = inst.budgets(zero);
  EXPECT_TRUE(near(b[0], 0.010, 1e-15));
  EXPECT_TRUE(near(b[1], 0.035, 1e-15));
  const SetupScore s = inst.score(zero);
  EXPECT_TRUE(near(s.f1, 0.010, 1e-15));
  EXPECT_EQ(s.f2, 0.0);
  EXPECT_TRUE(near(s.f, 0.1, 1e-15));
  EXPECT_TRUE(near(inst.f1Before(), 0.010, 1e-15));
}

TEST(SetupObjective, AfterACorrection) {
  const SetupInstance inst = smallInstance();
  const std::vector<double> x{0.002, -0.006};
  // e'_1 = 0.01 + 0.002 - 0.006 = 0.006 -> delta_1 = min(0.014, 0.026) = 0.014
  // e'_2 = -0.005 + 0.004 - 0.006 = -0.007 -> delta_2 = min(0.037, 0.043) = 0.037
  const auto e = inst.deviationsAfter(x);
  EXPECT_TRUE(near(e[0], 0.006, 1e-15));
  EXPECT_TRUE(near(e[1], -0.007, 1e-15));
  const SetupScore s = inst.score(x);
  EXPECT_TRUE(near(s.f1, 0.014, 1e-15));
  EXPECT_TRUE(near(s.f2, std::sqrt(40e-6), 1e-15));
  EXPECT_TRUE(near(s.f, 0.14 - std::sqrt(40e-6), 1e-15));
  EXPECT_TRUE(near(inst.bonus(x), 0.004, 1e-15));
}

TEST(SetupObjective, OutOfToleranceGivesNegativeBudget) {
  const SetupInstance inst = smallInstance();
  const std::vector<double> x{0.02, 0.0};
  // e'_1 = 0.03 > 0.02: delta_1 = -0.01; e'_2 = 0.035 > 0.03: delta_2 = -0.005
  const auto b = inst.budgets(x);
  EXPECT_TRUE(near(b[0], -0.010, 1e-15));
  EXPECT_TRUE(near(b[1], -0.005, 1e-15));
  EXPECT_TRUE(near(inst.f1(x), -0.010, 1e-15));
  EXPECT_TRUE(near(inst.bonus(x), -0.020, 1e-15));
}

TEST(SetupObjective, SetupProblemForTheMetaheuristics) {
  const SetupProblem p(smallInstance());
  EXPECT_EQ(p.name(), "setup");
  EXPECT_EQ(p.dimension(), 2u);
  EXPECT_EQ(p.gridStep(), 0.001);
  EXPECT_EQ(p.lower(0), -0.1);
  EXPECT_EQ(p.upper(1), 0.1);
  EXPECT_EQ(p.componentNames(), (std::vector<std::string>{"f1", "f2", "f"}));
  const std::vector<double> x{0.002, -0.006};
  std::vector<double> c(3);
  const double obj = p.evaluate(x, c);
  EXPECT_TRUE(near(c[0], 0.014, 1e-15));
  EXPECT_TRUE(near(c[1], std::sqrt(40e-6), 1e-15));
  EXPECT_TRUE(near(c[2], 0.14 - std::sqrt(40e-6), 1e-15));
  EXPECT_EQ(obj, -c[2]);  // minimisation of -f
  std::vector<double> off{0.0024, 0.5};
  p.snap(off);
  EXPECT_TRUE(near(off[0], 0.002, 1e-12));
  EXPECT_TRUE(near(off[1], 0.1, 1e-12));
  EXPECT_TRUE(p.isFeasible(off));
}

TEST(SetupObjective, PerDatumBoundsAndGrid) {
  Model m = test::smallModel();
  m.setup[0].boundsMm = std::make_pair(-0.0105, 0.01);
  const SetupInstance inst(m, {0.0, 0.0});
  EXPECT_EQ(inst.xLower(0), -0.0105);
  EXPECT_EQ(inst.gridPoints(0), 20);  // -0.0105 + 20 * 0.001 = 0.0095 <= 0.01
  EXPECT_EQ(inst.gridPoints(1), 200);
  const std::vector<long> k{3, 100};
  const auto x = inst.fromGrid(k);
  EXPECT_TRUE(near(x[0], -0.0075, 1e-15));
  EXPECT_TRUE(near(x[1], 0.0, 1e-15));
}

TEST(SetupObjective, DeviationCountMustMatch) {
  EXPECT_THROW(SetupInstance(test::smallModel(), {0.0}), ValidationError);
  EXPECT_THROW(SetupInstance(test::smallModel(), {0.0, std::nan("")}), ValidationError);
}

}  // namespace
}  // namespace metrofit::setup
