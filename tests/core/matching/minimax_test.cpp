// Minimax fit by sequential LPs (GLPK): optimality against hand-derived and independent solutions.
#include "core/matching/minimax.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/rng.h"
#include "core/matching/closed_form.h"
#include "core/matching/evaluation.h"
#include "matching_fixtures.h"

namespace metrofit::matching {
namespace {

/// Brute-force local search around a posture: random and coordinate perturbations of the free
/// parameters at step sizes from 1e-2 to 1e-7 (mm; rad x 100 mm). Returns the best max |d| found.
double localSearch(const ProbePointSet& set, const Pose& start, const DofLocks& locks, std::uint64_t seed) {
  Rng rng(seed);
  Eigen::Vector3d a = eulerZyx(start.rotation);
  Eigen::Vector3d t = start.translation;
  auto F = [&](const Eigen::Vector3d& ang, const Eigen::Vector3d& tr) {
    Pose p;
    p.rotation = rotationZyx(ang);
    p.translation = tr;
    return maxAbsDeviation(set, p);
  };
  double best = F(a, t);
  for (double step = 1e-2; step >= 1e-7; step /= 3.0) {
    for (int k = 0; k < 400; ++k) {
      Eigen::Vector3d da = Eigen::Vector3d::Zero(), dt = Eigen::Vector3d::Zero();
      for (int j = 0; j < 6; ++j) {
        if (locks.locked[j]) continue;
        const double v = (k < 12 ? (j == k / 2 ? (k % 2 ? -1.0 : 1.0) : 0.0) : rng.uniform(-1.0, 1.0)) * step;
        if (j < 3)
          da(j) = v / 100.0;
        else
          dt(j - 3) = v;
      }
      const double f = F(a + da, t + dt);
      if (f < best) {
        best = f;
        a += da;
        t += dt;
      }
    }
  }
  return best;
}

TEST(Minimax, OneDimensionalCaseIsTheMidrange) {
  // Normals along +x, only x free: d_i = (p_i - q_i).x - t_x; minimax t_x = (max + min) / 2.
  Rng rng(2);
  std::vector<Eigen::Vector3d> q, off;
  double lo = 1e9, hi = -1e9;
  for (int i = 0; i < 9; ++i) {
    q.emplace_back(rng.uniform(0, 100), rng.uniform(0, 100), rng.uniform(0, 100));
    off.emplace_back(rng.normal(0, 0.05), rng.normal(0, 0.05), 0.0);
    lo = std::min(lo, off.back().x());
    hi = std::max(hi, off.back().x());
  }
  const ProbePointSet set =
      test::setFrom(q, Pose{}, std::vector<Eigen::Vector3d>(q.size(), Eigen::Vector3d::UnitX()), off);
  MinimaxOptions o;
  for (Dof d : {Dof::Rx, Dof::Ry, Dof::Rz, Dof::Y, Dof::Z}) o.locks.lock(d);
  const MinimaxResult r = minimaxFit(set, Pose{}, o);
  EXPECT_EQ(r.run.termination, Termination::Converged) << r.run.message;
  EXPECT_NEAR(r.pose.translation.x(), (hi + lo) / 2.0, 1e-12);
  EXPECT_NEAR(r.maxAbsMm, (hi - lo) / 2.0, 1e-12);
  EXPECT_EQ(r.pose.translation.y(), 0.0);
  EXPECT_TRUE(r.pose.rotation.isIdentity(0.0));
  EXPECT_GE(r.active.size(), 2u);
}

TEST(Minimax, TranslationOnlyPositionFitIsTheSmallestEnclosingCircle) {
  // Planar, position-only, only x and y free: the optimum is the centre of the smallest circle
  // enclosing the offsets p_i - q_i; computed independently over all pairs and triples.
  Rng rng(6);
  std::vector<Eigen::Vector3d> q, off;
  for (int i = 0; i < 10; ++i) {
    q.emplace_back(rng.uniform(-50, 50), rng.uniform(-50, 50), 0.0);
    off.emplace_back(rng.normal(0, 0.03), rng.normal(0, 0.03), 0.0);
  }
  ProbePointSet set = test::setFrom(q, Pose{}, {}, off);
  set.planar = true;
  double radius = 1e9;
  auto encloses = [&](const Eigen::Vector2d& c, double r) {
    for (const auto& o : off)
      if ((o.head<2>() - c).norm() > r + 1e-13) return false;
    return true;
  };
  const std::size_t n = off.size();
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      const Eigen::Vector2d A = off[a].head<2>(), B = off[b].head<2>();
      const Eigen::Vector2d c = (A + B) / 2.0;
      if (encloses(c, (A - c).norm())) radius = std::min(radius, (A - c).norm());
      for (std::size_t k = b + 1; k < n; ++k) {
        const Eigen::Vector2d C = off[k].head<2>();
        const double d = 2.0 * (A.x() * (B.y() - C.y()) + B.x() * (C.y() - A.y()) + C.x() * (A.y() - B.y()));
        if (std::abs(d) < 1e-300) continue;
        const Eigen::Vector2d cc((A.squaredNorm() * (B.y() - C.y()) + B.squaredNorm() * (C.y() - A.y()) +
                                  C.squaredNorm() * (A.y() - B.y())) /
                                     d,
                                 (A.squaredNorm() * (C.x() - B.x()) + B.squaredNorm() * (A.x() - C.x()) +
                                  C.squaredNorm() * (B.x() - A.x())) /
                                     d);
        if (encloses(cc, (A - cc).norm())) radius = std::min(radius, (A - cc).norm());
      }
    }
  }
  MinimaxOptions o;
  for (Dof d : {Dof::Rx, Dof::Ry, Dof::Rz, Dof::Z}) o.locks.lock(d);
  const MinimaxResult r = minimaxFit(set, Pose{}, o);
  EXPECT_NEAR(r.maxAbsMm, radius, 1e-7) << r.run.message;
  EXPECT_GE(r.maxAbsMm, radius - 1e-12);
}

TEST(Minimax, NeverWorseThanLeastSquaresAndLocallyOptimal) {
  for (bool normals : {true, false}) {
    for (std::uint64_t seed : {1, 2, 3}) {
      ProbePointSet set = test::simulatedBlock(0.3, -0.2, 0.4, {0.2, -0.1, 0.3}, 0.01, seed);
      if (!normals) set = test::withoutNormals(set);
      const ClosedFormResult ls = closedFormFit(set, {});
      const double lsMax = maxAbsDeviation(set, ls.pose);
      const MinimaxResult mm = minimaxFit(set, ls.pose, {});
      EXPECT_LE(mm.maxAbsMm, lsMax + 1e-15);
      EXPECT_LT(mm.maxAbsMm, lsMax * 0.95) << "normals " << normals << " seed " << seed;
      EXPECT_EQ(mm.maxAbsMm, maxAbsDeviation(set, mm.pose));  // certified by exact re-evaluation
      EXPECT_NEAR(mm.startMaxAbsMm, lsMax, 1e-12);
      const double searched = localSearch(set, mm.pose, {}, seed);
      EXPECT_GE(searched, mm.maxAbsMm - 1e-9)
          << "normals " << normals << " seed " << seed << ": " << mm.run.message;
      // A Chebyshev optimum of k free parameters has at least k + 1 active points in general position
      // (normals); with distances at least 2.
      EXPECT_GE(mm.active.size(), normals ? 7u : 2u) << "normals " << normals << " seed " << seed;
    }
  }
}

TEST(Minimax, LocksAreHeldExactlyAndStillOptimal) {
  const ProbePointSet set = test::simulatedBlock(0.3, -0.2, 0.4, {0.2, -0.1, 0.3}, 0.01, 4);
  DofLocks locks;
  locks.lock(Dof::Rz);
  locks.lock(Dof::X, 0.15);
  ClosedFormOptions co;
  co.locks = locks;
  const ClosedFormResult ls = closedFormFit(set, co);
  MinimaxOptions o;
  o.locks = locks;
  const MinimaxResult mm = minimaxFit(set, ls.pose, o);
  EXPECT_EQ(mm.pose.anglesDeg().z(), 0.0);
  EXPECT_EQ(mm.pose.translation.x(), 0.15);
  EXPECT_LE(mm.maxAbsMm, maxAbsDeviation(set, ls.pose));
  EXPECT_GE(localSearch(set, mm.pose, locks, 9), mm.maxAbsMm - 1e-9);
  // Freeing the parameters can only help.
  const MinimaxResult free = minimaxFit(set, closedFormFit(set, {}).pose, {});
  EXPECT_LE(free.maxAbsMm, mm.maxAbsMm + 1e-12);
}

TEST(Minimax, ScaleIsFittedWhenAllowed) {
  ProbePointSet set = test::simulatedBlock(0.1, 0.1, 0.1, {0.1, 0.1, 0.1}, 0.002, 5);
  for (auto& p : set.points) p.measured *= 1.0003;
  MinimaxOptions o;
  const MinimaxResult rigid = minimaxFit(set, closedFormFit(set, {}).pose, o);
  o.allowScale = true;
  ClosedFormOptions co;
  co.allowScale = true;
  const MinimaxResult scaled = minimaxFit(set, closedFormFit(set, co).pose, o);
  EXPECT_LT(scaled.maxAbsMm, rigid.maxAbsMm);
  EXPECT_NEAR(scaled.pose.scale, 1.0003, 5e-5);
}

TEST(Minimax, TraceAndObserver) {
  const ProbePointSet set = test::simulatedBlock(0.3, -0.2, 0.4, {0.2, -0.1, 0.3}, 0.01, 1);
  int calls = 0;
  FunctionObserver stop([&](const IterationSummary&) {
    ++calls;
    return calls >= 2 ? ObserverDecision::Stop : ObserverDecision::Continue;
  });
  const MinimaxResult r = minimaxFit(set, closedFormFit(set, {}).pose, {}, &stop);
  EXPECT_EQ(r.run.termination, Termination::Cancelled);
  EXPECT_EQ(r.run.trace.size(), 2u);
  const MinimaxResult full = minimaxFit(set, closedFormFit(set, {}).pose, {});
  for (std::size_t i = 1; i < full.run.trace.size(); ++i)
    EXPECT_LE(full.run.trace[i].best, full.run.trace[i - 1].best);
}

}  // namespace
}  // namespace metrofit::matching
