// The remeasure loop of Step 7 with the simulator as machine and CMM.
#include "core/matching/remeasure.h"

#include <gtest/gtest.h>

#include "matching_fixtures.h"

namespace metrofit::matching {
namespace {

ProbePointSet nominalBlock() {
  return test::simulatedBlock(0.0, 0.0, 0.0, {0, 0, 0}, 0.0);
}

TEST(Remeasure, SimulatedCellMeasuresInTheCurrentWcs) {
  const Pose truth = Pose::fromAnglesDeg({0.5, -0.4, 0.9}, {1.2, -0.7, 0.4});
  const MeasureFunction cell = simulatedCell(nominalBlock(), truth, 0.0, 1);
  // In the original WCS the posture is the true one; in the true WCS the part is exactly nominal.
  const ProbePointSet first = cell(Pose{}, 0);
  for (const auto& p : first.points) EXPECT_LT((p.measured - truth.apply(p.nominal)).norm(), 1e-12);
  const ProbePointSet aligned = cell(truth, 1);
  for (const auto& p : aligned.points) EXPECT_LT((p.measured - p.nominal).norm(), 1e-12);
}

TEST(Remeasure, PaperLikePostureErrorEndsInTolerance) {
  // A posture error of the size of the paper's example (every point out of +-0.035 mm by ~1-2 mm).
  const Pose truth = Pose::fromAnglesDeg({0.4, -0.6, 0.8}, {1.1, -0.9, 0.6});
  for (machine::Topology topo : {machine::Topology::Xfyzba, machine::Topology::AcTable}) {
    RemeasureOptions o;
    o.match.method = MatchMethod::Sade;
    o.match.toleranceMm = 0.035;
    o.machine = machine::MachineDefinition::preset(topo);
    const RemeasureResult r = remeasureLoop(simulatedCell(nominalBlock(), truth, 0.002, 3), o);
    ASSERT_GE(r.rounds.size(), 2u);
    EXPECT_TRUE(r.inTolerance) << r.run.message;
    EXPECT_EQ(r.run.termination, Termination::Converged);
    EXPECT_GE(r.rounds.front().measured.overall.outOfTolerance, 30u);  // of 35
    EXPECT_GT(r.rounds.front().measured.overall.meanOverToleranceMm, 0.5);
    EXPECT_EQ(r.rounds.back().measured.overall.outOfTolerance, 0u);
    EXPECT_FALSE(r.rounds.back().match.has_value());
    EXPECT_TRUE(r.rounds.front().adjustment.has_value());
    EXPECT_EQ(r.run.trace.size(), r.rounds.size());
    // The realised WCS sits on the true posture within the resolution and the noise.
    const Pose last = r.rounds.back().wcs;
    EXPECT_LT((last.anglesDeg() - truth.anglesDeg()).cwiseAbs().maxCoeff(), 0.005);
    EXPECT_LT((last.translation - truth.translation).cwiseAbs().maxCoeff(), 0.01);
  }
}

TEST(Remeasure, GivesUpAfterMaxAdjustments) {
  // A tolerance below the probing noise can never be met.
  RemeasureOptions o;
  o.match.method = MatchMethod::ClosedForm;
  o.match.toleranceMm = 0.0001;
  o.maxAdjustments = 2;
  const Pose truth = Pose::fromAnglesDeg({0.1, 0.0, 0.0}, {0.1, 0.0, 0.0});
  int seen = 0;
  FunctionObserver count([&](const IterationSummary&) {
    ++seen;
    return ObserverDecision::Continue;
  });
  const RemeasureResult r = remeasureLoop(simulatedCell(nominalBlock(), truth, 0.005, 1), o, &count);
  EXPECT_FALSE(r.inTolerance);
  EXPECT_EQ(r.run.termination, Termination::MaxIterations);
  EXPECT_EQ(r.rounds.size(), 3u);
  EXPECT_EQ(seen, 3);
  EXPECT_FALSE(r.rounds.back().match.has_value());
}

TEST(Remeasure, InvalidOptions) {
  RemeasureOptions o;
  o.maxAdjustments = 0;
  EXPECT_THROW(remeasureLoop(simulatedCell(nominalBlock(), Pose{}, 0.0, 1), o), OptionsError);
  EXPECT_THROW(simulatedCell(nominalBlock(), Pose{}, -1.0, 1), OptionsError);
}

}  // namespace
}  // namespace metrofit::matching
