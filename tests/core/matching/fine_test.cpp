// Fine matching by SADE (Jiang et al. 2018, Section 2.3, Eq. 8-11) against the closed-form optimum.
#include "core/matching/fine.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/rng.h"
#include "core/matching/closed_form.h"
#include "core/matching/matching.h"
#include "core/optim/gasimplex.h"
#include "core/optim/sade.h"
#include "matching_fixtures.h"

namespace metrofit::matching {
namespace {

double rmse(const ProbePointSet& set, const Pose& p) {
  double s = 0.0;
  for (const auto& pt : set.points) s += (pt.measured - p.apply(pt.nominal)).squaredNorm();
  return std::sqrt(s / static_cast<double>(set.points.size()));
}

optim::Sade paperSade(std::uint64_t seed) {
  optim::Sade::Options o = paperSadeOptions();
  o.common.seed = seed;
  return optim::Sade(o);
}

TEST(Fine, ObjectiveIsEq8WithTheTranslationOfEq9) {
  // Evaluate Eq. (8)-(9) literally on the rough-matched points P' = A0 P + T0 and compare.
  const ProbePointSet set = test::simulatedBlock(0.4, -0.3, 0.8, {0.5, 0.2, -0.1}, 0.003, 5);
  const RoughResult rough = roughMatch(set);
  const FineMatchingProblem problem(set, rough, {}, false, 1.0);
  ASSERT_TRUE(problem.paperMode());
  std::vector<Eigen::Vector3d> Pp;
  Eigen::Vector3d meanQ = Eigen::Vector3d::Zero(), meanPp = Eigen::Vector3d::Zero();
  for (const auto& p : set.points) {
    Pp.push_back(rough.alignment * p.measured + rough.alignmentTranslation);  // Eq. (1)
    meanPp += Pp.back();
    meanQ += p.nominal;
  }
  meanQ /= static_cast<double>(Pp.size());
  meanPp /= static_cast<double>(Pp.size());
  Rng rng(1);
  for (int k = 0; k < 20; ++k) {
    const double x[3] = {rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)};
    const Eigen::Matrix3d A1 = rotationZyx(Eigen::Vector3d(x[0], x[1], x[2]) * kRadPerDeg);
    const Eigen::Vector3d T1 = meanQ - A1 * meanPp;  // Eq. (9)
    double f = 0.0;
    for (std::size_t i = 0; i < Pp.size(); ++i)
      f += (set.points[i].nominal - (A1 * Pp[i] + T1)).squaredNorm();
    f /= static_cast<double>(Pp.size());  // Eq. (8)
    EXPECT_NEAR(problem.evaluate(x, {}), std::sqrt(f), 1e-12);
    // The posture at x reproduces the same RMS in the match result's convention.
    EXPECT_NEAR(rmse(set, problem.poseAt(x)), std::sqrt(f), 1e-12);
  }
  // Bounds: [-|alpha0| - k, |alpha0| + k] etc.
  for (std::size_t j = 0; j < 3; ++j) {
    EXPECT_DOUBLE_EQ(problem.upper(j), std::abs(rough.pe0[j]) + 1.0);
    EXPECT_DOUBLE_EQ(problem.lower(j), -problem.upper(j));
  }
}

TEST(Fine, SadeReachesTheClosedFormOptimumOnNoisyData) {
  // Stated tolerance: rmse within 1e-9 mm of the least-squares optimum, angles within 1e-6 deg (25
  // seeds of this case measured: worst 9e-15 mm and 1.3e-9 deg; the target is 1e-6 mm).
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const ProbePointSet set = test::simulatedBlock(0.6, -0.4, 1.2, {1.5, -0.8, 0.4}, 0.002, seed);
    const ClosedFormResult cf = closedFormFit(set, {});
    const RoughResult rough = roughMatch(set);
    const FineResult fine = fineMatch(set, rough, paperSade(seed), {}, false, 1.0);
    const double best = rmse(set, cf.pose);
    EXPECT_LE(rmse(set, fine.pose) - best, 1e-9) << "seed " << seed;
    EXPECT_GE(rmse(set, fine.pose), best - 1e-12);
    EXPECT_LT((fine.pose.anglesDeg() - cf.pose.anglesDeg()).cwiseAbs().maxCoeff(), 1e-6) << "seed " << seed;
    EXPECT_NEAR(fine.objectiveMm, rmse(set, fine.pose), 1e-12);
    // The trace: generation 0 plus Gm = 200 generations, best never increasing.
    ASSERT_EQ(fine.optimisation.run.trace.size(), 201u);
    for (std::size_t g = 1; g < fine.optimisation.run.trace.size(); ++g)
      EXPECT_LE(fine.optimisation.run.trace[g].best, fine.optimisation.run.trace[g - 1].best);
    EXPECT_EQ(fine.optimisation.run.termination, Termination::MaxIterations);
    // Rough alone is worse than fine.
    EXPECT_GT(rmse(set, rough.posture), rmse(set, fine.pose));
  }
}

TEST(Fine, GaSimplexComparisonGetsCloseAtTheSameBudget) {
  // The paper's comparison method (Section 4.2). Stated tolerance: rmse within 1e-6 mm of the
  // least-squares optimum at SADE's evaluation budget (25 seeds measured: worst 1.6e-13 mm).
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const ProbePointSet set = test::simulatedBlock(0.6, -0.4, 1.2, {1.5, -0.8, 0.4}, 0.002, seed);
    const ClosedFormResult cf = closedFormFit(set, {});
    optim::GaSimplex::Options go = comparisonGaSimplexOptions();
    go.common.seed = seed;
    const FineResult fine = fineMatch(set, roughMatch(set), optim::GaSimplex(go), {}, false, 1.0);
    EXPECT_LE(rmse(set, fine.pose) - rmse(set, cf.pose), 1e-6) << "seed " << seed;
    EXPECT_LE(fine.optimisation.run.evaluations, paperSadeOptions().common.maxEvaluations);
    EXPECT_FALSE(fine.optimisation.run.trace.empty());
  }
}

TEST(Fine, SameSeedSameTraceBitForBit) {
  const ProbePointSet set = test::simulatedBlock(0.2, 0.1, -0.3, {0.1, 0.2, 0.3}, 0.002, 8);
  const RoughResult rough = roughMatch(set);
  const FineResult a = fineMatch(set, rough, paperSade(42), {}, false, 1.0);
  const FineResult b = fineMatch(set, rough, paperSade(42), {}, false, 1.0);
  const FineResult c = fineMatch(set, rough, paperSade(43), {}, false, 1.0);
  ASSERT_EQ(a.optimisation.run.trace.size(), b.optimisation.run.trace.size());
  for (std::size_t g = 0; g < a.optimisation.run.trace.size(); ++g)
    EXPECT_EQ(a.optimisation.run.trace[g].best, b.optimisation.run.trace[g].best);
  EXPECT_EQ(a.bestDeg, b.bestDeg);
  EXPECT_NE(a.optimisation.run.trace[5].best, c.optimisation.run.trace[5].best);
}

TEST(Fine, RotationLocksSwitchToPostureAnglesAndKeepLocksExact) {
  const ProbePointSet set = test::simulatedBlock(0.3, -0.2, 0.5, {0.2, 0.1, -0.3}, 0.002, 3);
  DofLocks locks;
  locks.lock(Dof::Rx);
  locks.lock(Dof::Y, 0.05);
  const RoughResult rough = roughMatch(set);
  const FineResult fine = fineMatch(set, rough, paperSade(1), locks, false, 1.0);
  EXPECT_FALSE(fine.paperMode);
  EXPECT_EQ(fine.variables, (std::vector<std::string>{"ry", "rz"}));
  EXPECT_EQ(fine.pose.anglesDeg().x(), 0.0);
  EXPECT_EQ(fine.pose.translation.y(), 0.05);
  ClosedFormOptions co;
  co.locks = locks;
  const ClosedFormResult cf = closedFormFit(set, co);
  EXPECT_LE(rmse(set, fine.pose) - rmse(set, cf.pose), 1e-9);
  EXPECT_LT((fine.pose.anglesDeg() - cf.pose.anglesDeg()).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(Fine, AllAnglesLockedNeedsNoSearch) {
  const ProbePointSet set = test::simulatedBlock(0.0, 0.0, 0.0, {0.2, 0.1, -0.3}, 0.002, 3);
  DofLocks locks;
  locks.lock(Dof::Rx);
  locks.lock(Dof::Ry);
  locks.lock(Dof::Rz);
  const FineResult fine = fineMatch(set, roughMatch(set), paperSade(1), locks, false, 1.0);
  EXPECT_TRUE(fine.optimisation.run.trace.empty());
  EXPECT_LT((fine.pose.translation - Eigen::Vector3d(0.2, 0.1, -0.3)).norm(), 0.002);
}

TEST(Fine, ObserverCanStopTheRun) {
  const ProbePointSet set = test::simulatedBlock(0.2, 0.1, -0.3, {0.1, 0.2, 0.3}, 0.002, 8);
  int calls = 0;
  FunctionObserver stopAtTen([&](const IterationSummary& s) {
    ++calls;
    return s.iteration >= 10 ? ObserverDecision::Stop : ObserverDecision::Continue;
  });
  const FineResult r = fineMatch(set, roughMatch(set), paperSade(1), {}, false, 1.0, &stopAtTen);
  EXPECT_EQ(calls, 11);
  EXPECT_EQ(r.optimisation.run.termination, Termination::Cancelled);
}

}  // namespace
}  // namespace metrofit::matching
