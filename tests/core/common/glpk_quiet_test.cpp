// core/common/glpk_quiet.h: GLPK's terminal output is off while a guard lives and the previous setting
// comes back after it; the two GLPK users (the exact setup optimum and the minimax posture fit) print
// nothing even when the calling thread has GLPK's output on, and leave that setting as it was.
#include "core/common/glpk_quiet.h"

#include <gtest/gtest.h>

#include <glpk.h>

#include <string>
#include <vector>

#include "../matching/matching_fixtures.h"
#include "../setup/setup_fixtures.h"
#include "core/matching/minimax.h"
#include "core/setup/exact.h"

namespace metrofit {
namespace {

/// GLPK's terminal output setting of this thread (read without changing it).
int termOut() {
  const int now = glp_term_out(GLP_ON);
  glp_term_out(now);
  return now;
}

TEST(GlpkQuiet, OffInsideOnAgainAfterNested) {
  glp_term_out(GLP_ON);
  {
    const GlpkQuiet outer;
    EXPECT_EQ(termOut(), GLP_OFF);
    {
      const GlpkQuiet inner;
      EXPECT_EQ(termOut(), GLP_OFF);
    }
    EXPECT_EQ(termOut(), GLP_OFF);  // the inner guard restores the outer one's setting
  }
  EXPECT_EQ(termOut(), GLP_ON);
  glp_term_out(GLP_OFF);
  { const GlpkQuiet quiet; }
  EXPECT_EQ(termOut(), GLP_OFF);  // off stays off
}

TEST(GlpkQuiet, ExactOptimumPrintsNothingAndKeepsTheCallersSetting) {
  const setup::SetupInstance inst(setup::test::smallModel(), {0.010, -0.005});
  glp_term_out(GLP_ON);
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  const setup::ExactResult r = setup::solveExact(inst);
  const std::string out = ::testing::internal::GetCapturedStdout();
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(termOut(), GLP_ON);
  glp_term_out(GLP_OFF);
  EXPECT_EQ(out, "");
  EXPECT_EQ(err, "");
  EXPECT_TRUE(r.certificate.f1Optimal);
}

TEST(GlpkQuiet, MinimaxFitPrintsNothingAndKeepsTheCallersSetting) {
  std::vector<Eigen::Vector3d> q, off;
  for (int i = 0; i < 8; ++i) {
    q.emplace_back(10.0 * i, 5.0 * (i % 3), 2.0 * (i % 2));
    off.emplace_back(0.01 * ((i * 7) % 5) - 0.02, 0.0, 0.0);
  }
  const ProbePointSet set = test::setFrom(
      q, matching::Pose{}, std::vector<Eigen::Vector3d>(q.size(), Eigen::Vector3d::UnitX()), off);
  matching::MinimaxOptions o;
  for (matching::Dof d :
       {matching::Dof::Rx, matching::Dof::Ry, matching::Dof::Rz, matching::Dof::Y, matching::Dof::Z})
    o.locks.lock(d);
  glp_term_out(GLP_ON);
  ::testing::internal::CaptureStdout();
  const matching::MinimaxResult r = matching::minimaxFit(set, matching::Pose{}, o);
  const std::string out = ::testing::internal::GetCapturedStdout();
  EXPECT_EQ(termOut(), GLP_ON);
  glp_term_out(GLP_OFF);
  EXPECT_EQ(out, "");
  EXPECT_EQ(r.run.termination, Termination::Converged) << r.run.message;
  EXPECT_NEAR(r.maxAbsMm, 0.02, 1e-12);  // offsets -0.02 .. 0.02: the midrange leaves 0.02
}

}  // namespace
}  // namespace metrofit
