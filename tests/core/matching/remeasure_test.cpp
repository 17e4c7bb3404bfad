// The remeasure loop of Step 7 with the simulator as machine and CMM.
#include "core/matching/remeasure.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include <nlohmann/json.hpp>

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

TEST(Remeasure, ToleranceBelowTheNoiseIsAFormError) {
  // A tolerance below the probing noise can never be met: the best fit itself leaves points out, so
  // the loop adjusts once, remeasures and stops instead of adjusting forever.
  RemeasureOptions o;
  o.match.method = MatchMethod::ClosedForm;
  o.match.toleranceMm = 0.0001;
  o.maxAdjustments = 4;
  const Pose truth = Pose::fromAnglesDeg({0.1, 0.0, 0.0}, {0.1, 0.0, 0.0});
  int seen = 0;
  FunctionObserver count([&](const IterationSummary&) {
    ++seen;
    return ObserverDecision::Continue;
  });
  const RemeasureResult r = remeasureLoop(simulatedCell(nominalBlock(), truth, 0.005, 1), o, &count);
  EXPECT_FALSE(r.inTolerance);
  EXPECT_EQ(r.outcome, RemeasureOutcome::FormError);
  EXPECT_EQ(r.run.termination, Termination::Failed);
  EXPECT_EQ(r.rounds.size(), 2u);
  EXPECT_EQ(seen, 2);
  EXPECT_FALSE(r.rounds.back().match.has_value());
  EXPECT_EQ(r.trueRemaining(), nullptr);  // a plain measure function knows no truth
}

TEST(Remeasure, GivesUpAfterMaxAdjustments) {
  // The control accepts 0.1 mm steps only: the 0.0234 mm left by rounding 0.1234 mm stays out of
  // +-0.01 mm in every round although the fit itself is perfect.
  RemeasureOptions o;
  o.match.method = MatchMethod::ClosedForm;
  o.match.toleranceMm = 0.01;
  o.maxAdjustments = 2;
  o.linearResolutionMm = 0.1;
  o.rotaryResolutionDeg = 0.0;
  const Pose truth = Pose::fromAnglesDeg({0.0, 0.0, 0.0}, {0.1234, 0.0, 0.0});
  const RemeasureResult r = remeasureLoop(simulatedCell(nominalBlock(), truth, 0.0, 1), o);
  EXPECT_FALSE(r.inTolerance);
  EXPECT_EQ(r.outcome, RemeasureOutcome::NotConverged);
  EXPECT_EQ(r.run.termination, Termination::MaxIterations);
  EXPECT_EQ(r.rounds.size(), 3u);
  EXPECT_NEAR(r.rounds.back().measured.overall.maxAbsMm, 0.0234, 1e-9);
  EXPECT_FALSE(r.rounds.back().match.has_value());
}

// ---- The loop can fail: an independent reference written here ----
// The true part: a_i = R* (q_i + f_i) + t* with R* = Rz Ry Rx built from Eigen::AngleAxis. The
// least-squares posture of a noise-free measurement is Eigen::umeyama on (q_i, W^-1 a_i); with axis
// resolution 0 the machine realises it exactly, so the WCS after one adjustment is W1 = W0 o U and the
// true remaining deviation of point i is n_i . (R_W1^T (a_i - t_W1) - q_i).

constexpr double kPi = 3.14159265358979323846;

Eigen::Matrix3d rotationXyzDeg(double rx, double ry, double rz) {
  const double d = kPi / 180.0;
  return (Eigen::AngleAxisd(rz * d, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(ry * d, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rx * d, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

struct Reference {
  std::vector<Eigen::Vector3d> actual;  // a_i
  Eigen::Matrix3d fitR;                 // umeyama posture of a_i on q_i
  Eigen::Vector3d fitT;
  std::vector<double> before, after;  // n_i . (a_i - q_i), n_i . (W1^-1 a_i - q_i)
};

Reference reference(const ProbePointSet& nominal, const Eigen::Matrix3d& R, const Eigen::Vector3d& t,
                    const std::vector<Eigen::Vector3d>& form) {
  Reference ref;
  const std::size_t n = nominal.points.size();
  Eigen::Matrix3Xd q(3, n), a(3, n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = nominal.points[i];
    ref.actual.push_back(R * (p.nominal + form[i]) + t);
    q.col(i) = p.nominal;
    a.col(i) = ref.actual.back();
  }
  const Eigen::Matrix4d T = Eigen::umeyama(q, a, false);
  ref.fitR = T.topLeftCorner<3, 3>();
  ref.fitT = T.topRightCorner<3, 1>();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = nominal.points[i];
    ref.before.push_back(p.normal.dot(ref.actual[i] - p.nominal));
    ref.after.push_back(p.normal.dot(ref.fitR.transpose() * (ref.actual[i] - ref.fitT) - p.nominal));
  }
  return ref;
}

double maxAbs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

std::size_t countOut(const std::vector<double>& v, double tol) {
  std::size_t k = 0;
  for (double x : v) k += std::abs(x) > tol ? 1 : 0;
  return k;
}

RemeasureOptions exactLoopOptions(double tol) {
  RemeasureOptions o;
  o.match.method = MatchMethod::ClosedForm;
  o.match.toleranceMm = tol;
  o.linearResolutionMm = 0.0;
  o.rotaryResolutionDeg = 0.0;
  o.machine = machine::MachineDefinition::preset(machine::Topology::Xfyzba);
  return o;
}

SimulatedPart part(const ProbePointSet& nominal, const Eigen::Matrix3d& R, const Eigen::Vector3d& t,
                   const std::vector<Eigen::Vector3d>& form) {
  SimulatedPart p;
  p.nominal = nominal;
  p.truePosture.rotation = R;
  p.truePosture.translation = t;
  p.formErrorMm = form;
  return p;
}

TEST(Remeasure, SmallFormErrorSucceedsWithTheTrueRemainingError) {
  const ProbePointSet nominal = nominalBlock();
  const Eigen::Matrix3d R = rotationXyzDeg(0.3, -0.5, 0.7);
  const Eigen::Vector3d t(0.8, -1.2, 0.5);
  std::vector<Eigen::Vector3d> form(nominal.points.size(), Eigen::Vector3d::Zero());
  for (std::size_t i = 0; i < form.size(); i += 4) form[i] = 0.012 * nominal.points[i].normal;  // bumps
  const Reference ref = reference(nominal, R, t, form);
  const double tol = 0.035;
  ASSERT_GT(countOut(ref.before, tol), 30u);  // the part starts far out
  ASSERT_EQ(countOut(ref.after, tol), 0u);    // and the fit brings every point in

  const RemeasureResult r =
      remeasureLoop(simulateCell(part(nominal, R, t, form), 0.0, 5), exactLoopOptions(tol));
  EXPECT_EQ(r.outcome, RemeasureOutcome::InTolerance) << r.run.message;
  EXPECT_TRUE(r.inTolerance);
  ASSERT_EQ(r.rounds.size(), 2u);
  ASSERT_TRUE(r.rounds[0].truth.has_value());
  EXPECT_NEAR(r.rounds[0].truth->overall.maxAbsMm, maxAbs(ref.before), 1e-9);
  EXPECT_EQ(r.rounds[0].truth->overall.outOfTolerance, countOut(ref.before, tol));
  // The WCS after one adjustment is the least-squares posture of the true part, not the true posture.
  const Pose w1 = r.rounds[1].wcs;
  EXPECT_LT((w1.rotation - ref.fitR).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((w1.translation - ref.fitT).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_GT((w1.translation - t).norm(), 1e-4);  // the form error moved the fit off the true posture
  const ToleranceEvaluation* remaining = r.trueRemaining();
  ASSERT_NE(remaining, nullptr);
  ASSERT_EQ(remaining->deviations.size(), ref.after.size());
  for (std::size_t i = 0; i < ref.after.size(); ++i)
    EXPECT_NEAR(remaining->deviations[i], ref.after[i], 1e-9);
  EXPECT_NEAR(remaining->overall.maxAbsMm, maxAbs(ref.after), 1e-9);
  EXPECT_GT(remaining->overall.maxAbsMm, 0.005);  // the form error remains, visibly
}

TEST(Remeasure, FormErrorBeyondToleranceFailsVisibly) {
  const ProbePointSet nominal = nominalBlock();
  const Eigen::Matrix3d R = rotationXyzDeg(-0.4, 0.2, 0.6);
  const Eigen::Vector3d t(-0.7, 0.9, 0.3);
  std::vector<Eigen::Vector3d> form(nominal.points.size(), Eigen::Vector3d::Zero());
  for (std::size_t i : {3u, 17u, 29u}) form[i] = 0.12 * nominal.points[i].normal;  // a 0.12 mm dent each
  const Reference ref = reference(nominal, R, t, form);
  const double tol = 0.035;
  const std::size_t outAfter = countOut(ref.after, tol);
  ASSERT_GE(outAfter, 3u);

  RemeasureOptions o = exactLoopOptions(tol);
  const RemeasureResult r = remeasureLoop(simulateCell(part(nominal, R, t, form), 0.0, 5), o);
  EXPECT_FALSE(r.inTolerance);
  EXPECT_EQ(r.outcome, RemeasureOutcome::FormError);
  EXPECT_EQ(r.run.termination, Termination::Failed);
  EXPECT_NE(r.run.message.find("FAILED"), std::string::npos) << r.run.message;
  ASSERT_EQ(r.rounds.size(), 2u);  // adjusted once, remeasured, stopped: no WCS can help
  ASSERT_TRUE(r.rounds[0].match.has_value());
  EXPECT_EQ(r.rounds[0].match->after.overall.outOfTolerance, outAfter);
  const ToleranceEvaluation* remaining = r.trueRemaining();
  ASSERT_NE(remaining, nullptr);
  EXPECT_EQ(remaining->overall.outOfTolerance, outAfter);
  EXPECT_NEAR(remaining->overall.maxAbsMm, maxAbs(ref.after), 1e-9);
  for (std::size_t i = 0; i < ref.after.size(); ++i)
    EXPECT_NEAR(remaining->deviations[i], ref.after[i], 1e-9);
  const nlohmann::json j = toJson(r);
  EXPECT_EQ(j["outcome"], "form_error");
  EXPECT_EQ(j["true_remaining"]["out_of_tolerance"], outAfter);
}

TEST(Remeasure, AdjustmentBeyondTravelFailsAndLeavesTheWcs) {
  const ProbePointSet nominal = nominalBlock();
  const Eigen::Matrix3d R = rotationXyzDeg(0.5, -0.3, 0.4);
  const Eigen::Vector3d t(0.6, 0.4, -0.2);
  const std::vector<Eigen::Vector3d> form(nominal.points.size(), Eigen::Vector3d::Zero());
  const Reference ref = reference(nominal, R, t, form);
  RemeasureOptions o = exactLoopOptions(0.035);
  o.machine.rotaryMinDeg = {-0.1, -360.0};  // A travels only +-0.1 deg
  o.machine.rotaryMaxDeg = {0.1, 360.0};
  // Eq. (12) by hand: the tool along R e_z needs SA = asin(-c_y), here about 0.5 deg.
  const double sa = std::asin(-(R * Eigen::Vector3d::UnitZ()).y()) * 180.0 / kPi;
  ASSERT_GT(std::abs(sa), 0.1);
  const RemeasureResult r = remeasureLoop(simulateCell(part(nominal, R, t, form), 0.0, 5), o);
  EXPECT_FALSE(r.inTolerance);
  EXPECT_EQ(r.outcome, RemeasureOutcome::BeyondTravel);
  EXPECT_EQ(r.run.termination, Termination::Failed);
  EXPECT_NE(r.run.message.find("travel"), std::string::npos) << r.run.message;
  ASSERT_EQ(r.rounds.size(), 1u);
  ASSERT_TRUE(r.rounds[0].adjustment.has_value());
  EXPECT_FALSE(r.rounds[0].adjustment->withinTravel);
  EXPECT_NEAR(r.rounds[0].adjustment->rotaryDeg[0], sa, 1e-9);
  EXPECT_LT((r.rounds[0].nextWcs.translation).norm(), 1e-15);  // not moved
  ASSERT_NE(r.trueRemaining(), nullptr);
  EXPECT_NEAR(r.trueRemaining()->overall.maxAbsMm, maxAbs(ref.before), 1e-9);
  EXPECT_EQ(r.trueRemaining()->overall.outOfTolerance, countOut(ref.before, 0.035));
}

TEST(Remeasure, PartAsMeasuredIsWhereTheProbeFoundIt) {
  const ProbePointSet measured = test::simulatedBlock(0.4, -0.2, 0.3, {0.5, 0.1, -0.3}, 0.01, 9);
  const SimulatedPart p = partAsMeasured(measured);
  const auto a = p.actualPoints();
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_LT((a[i] - measured.points[i].measured).norm(), 1e-9);
  const SimulatedCell cell = simulateCell(p, 0.0, 1);
  const ProbePointSet again = cell.truth(Pose{});
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_LT((again.points[i].measured - measured.points[i].measured).norm(), 1e-9);
}

TEST(Remeasure, InvalidOptions) {
  RemeasureOptions o;
  o.maxAdjustments = 0;
  EXPECT_THROW(remeasureLoop(simulatedCell(nominalBlock(), Pose{}, 0.0, 1), o), OptionsError);
  EXPECT_THROW(simulatedCell(nominalBlock(), Pose{}, -1.0, 1), OptionsError);
  SimulatedPart wrong;
  wrong.nominal = nominalBlock();
  wrong.formErrorMm.resize(3);
  EXPECT_THROW(simulateCell(wrong, 0.0, 1), OptionsError);
}

}  // namespace
}  // namespace metrofit::matching
