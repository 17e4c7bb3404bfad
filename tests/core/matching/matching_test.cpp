// matchPosture end to end: the four methods agree where they should, JSON carries the keys of
// docs/file-formats.md#match-result.
#include "core/matching/matching.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "matching_fixtures.h"

namespace metrofit::matching {
namespace {

MatchOptions options(MatchMethod m, double tol = 0.035) {
  MatchOptions o;
  o.method = m;
  o.toleranceMm = tol;
  return o;
}

TEST(Match, AllMethodsOnThePaperLikeCase) {
  const ProbePointSet set = test::simulatedBlock(0.4, -0.6, 0.8, {1.1, -0.9, 0.6}, 0.002, 1);
  const MatchResult cf = matchPosture(set, options(MatchMethod::ClosedForm));
  const MatchResult sade = matchPosture(set, options(MatchMethod::Sade));
  const MatchResult mm = matchPosture(set, options(MatchMethod::Minimax));
  const MatchResult ga = matchPosture(set, options(MatchMethod::GaSimplex));
  for (const MatchResult* r : {&cf, &sade, &mm, &ga}) {
    EXPECT_GE(r->before.overall.outOfTolerance, 30u) << toString(r->method);  // of 35
    EXPECT_EQ(r->after.overall.outOfTolerance, 0u) << toString(r->method);
    EXPECT_LT((r->pose.anglesDeg() - Eigen::Vector3d(0.4, -0.6, 0.8)).cwiseAbs().maxCoeff(), 0.002);
  }
  EXPECT_LE(sade.after.overall.rmseMm - cf.after.overall.rmseMm, 1e-9);
  EXPECT_LE(ga.after.overall.rmseMm - cf.after.overall.rmseMm, 1e-6);
  EXPECT_LE(mm.after.overall.maxAbsMm, cf.after.overall.maxAbsMm);
  EXPECT_TRUE(sade.rough.has_value());
  EXPECT_TRUE(sade.fine.has_value());
  EXPECT_EQ(sade.run.trace.size(), 201u);
  EXPECT_TRUE(mm.minimax.has_value());
  EXPECT_FALSE(cf.rough.has_value());
}

TEST(Match, JsonHasTheContractKeys) {
  const ProbePointSet set = test::simulatedBlock(0.02, -0.015, 0.05, {0.12, -0.08, 0.05}, 0.002, 1);
  MatchOptions o = options(MatchMethod::Sade, 0.005);
  const MatchResult r = matchPosture(set, o);
  const nlohmann::json j = toJson(r, set);
  EXPECT_EQ(j.at("method"), "sade");
  ASSERT_EQ(j.at("rotation_deg").size(), 3u);
  ASSERT_EQ(j.at("translation_mm").size(), 3u);
  EXPECT_FALSE(j.contains("scale"));
  EXPECT_DOUBLE_EQ(j.at("rmse_mm").get<double>(), r.after.overall.rmseMm);
  EXPECT_DOUBLE_EQ(j.at("max_abs_mm").get<double>(), r.after.overall.maxAbsMm);
  EXPECT_EQ(j.at("out_of_tolerance").at("before").get<std::size_t>(), r.before.overall.outOfTolerance);
  EXPECT_EQ(j.at("out_of_tolerance").at("after").get<std::size_t>(), r.after.overall.outOfTolerance);
  EXPECT_EQ(j.at("rotation_deg")[2].get<double>(), r.pose.anglesDeg().z());
  EXPECT_EQ(j.at("after").at("surfaces").size(), 4u);
  EXPECT_EQ(j.at("trace").size(), 201u);
  EXPECT_EQ(j.at("rough").at("reference_ids").size(), 3u);
  EXPECT_TRUE(j.at("rough").at("pe0").contains("gamma0_deg"));
  EXPECT_EQ(j.at("fine").at("variables").size(), 3u);
  EXPECT_EQ(j.at("seed"), 1);
  o.allowScale = true;
  o.method = MatchMethod::ClosedForm;
  const nlohmann::json js = toJson(matchPosture(set, o), set);
  EXPECT_TRUE(js.contains("scale"));
}

TEST(Match, RmseAndMaxFollowTheContractForEveryMethod) {
  // Independent recomputation: rmse over whole distances, max over normal deviations.
  const ProbePointSet set = test::simulatedBlock(0.1, 0.2, 0.3, {0.1, 0.2, 0.3}, 0.01, 2);
  for (MatchMethod m : {MatchMethod::Sade, MatchMethod::ClosedForm, MatchMethod::Minimax}) {
    const MatchResult r = matchPosture(set, options(m, 0.01));
    double ss = 0.0, mx = 0.0;
    std::size_t out = 0;
    for (const auto& p : set.points) {
      const Eigen::Vector3d res = p.measured - r.pose.apply(p.nominal);
      ss += res.squaredNorm();
      const double d = std::abs(res.dot(r.pose.rotation * p.normal));
      mx = std::max(mx, d);
      out += d > 0.01 ? 1 : 0;
    }
    EXPECT_NEAR(r.after.overall.rmseMm, std::sqrt(ss / static_cast<double>(set.points.size())), 1e-15)
        << toString(m);
    EXPECT_NEAR(r.after.overall.maxAbsMm, mx, 1e-15) << toString(m);
    EXPECT_EQ(r.after.overall.outOfTolerance, out) << toString(m);
  }
}

TEST(Match, PlanarDataFitOnlyInPlane) {
  ProbePointSet set;
  set.source = "plate.csv";
  set.planar = true;
  const Pose truth = Pose::fromAnglesDeg({0, 0, 0.3}, {0.2, -0.1, 0});
  for (int i = 0; i < 6; ++i) {
    ProbePoint p;
    p.id = "H" + std::to_string(i);
    p.nominal = {30.0 * i, 17.0 * (i % 3), 0.0};
    p.measured = truth.apply(p.nominal);
    set.points.push_back(p);
  }
  for (MatchMethod m : {MatchMethod::Sade, MatchMethod::ClosedForm, MatchMethod::Minimax}) {
    const MatchResult r = matchPosture(set, options(m, 0.01));
    EXPECT_EQ(r.locks.toString(), "rx,ry,z");
    EXPECT_EQ(r.pose.anglesDeg().x(), 0.0) << toString(m);
    EXPECT_EQ(r.pose.anglesDeg().y(), 0.0) << toString(m);
    EXPECT_EQ(r.pose.translation.z(), 0.0) << toString(m);
    EXPECT_LT(test::poseDistance(r.pose, truth), 1e-5) << toString(m);
  }
}

TEST(Match, OptionsAndMethodsAreValidated) {
  const ProbePointSet set = test::simulatedBlock(0.1, 0.2, 0.3, {0.1, 0.2, 0.3}, 0.01, 2);
  MatchOptions o;
  o.toleranceMm = -1.0;
  EXPECT_THROW(matchPosture(set, o), OptionsError);
  o = MatchOptions{};
  o.boundMarginDeg = 0.0;
  EXPECT_THROW(matchPosture(set, o), OptionsError);
  o = MatchOptions{};
  o.referenceIds = {"P001"};
  EXPECT_THROW(matchPosture(set, o), OptionsError);
  EXPECT_EQ(parseMatchMethod("minimax", "--method"), MatchMethod::Minimax);
  EXPECT_THROW(parseMatchMethod("icp", "--method"), OptionsError);
  // Degenerate input is named before any method runs.
  ProbePointSet few = set;
  few.points.resize(2);
  try {
    matchPosture(few, MatchOptions{});
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_EQ(std::string(e.what()),
              "simulated probing: has 2 points, the SADE fine matching needs at least 3 (three non-collinear "
              "points fix a rotation)");
  }
}

TEST(Match, ReferenceIdsAreUsed) {
  const ProbePointSet set = test::simulatedBlock(0.1, 0.2, 0.3, {0.1, 0.2, 0.3}, 0.002, 2);
  MatchOptions o;
  o.referenceIds = {"P001", "P015", "P030"};
  const MatchResult r = matchPosture(set, o);
  const nlohmann::json j = toJson(r, set);
  EXPECT_EQ(j.at("rough").at("reference_ids"), nlohmann::json({"P001", "P015", "P030"}));
}

}  // namespace
}  // namespace metrofit::matching
