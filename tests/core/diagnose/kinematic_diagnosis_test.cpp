// The kinematic closed loop (core/diagnose/kinematic_diagnosis.h) and its simulator
// (core/sim/effects_kinematic.h): backlash, scale, cyclic and servo lag found in circular tests at
// an effect-to-noise ratio of 5 with parameters within 30 %, clean tests clean, two effects found
// both, the JSON of docs/file-formats.md#diagnose-result, bad inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/common/error.h"
#include "core/diagnose/kinematic_diagnosis.h"
#include "core/sim/effects_kinematic.h"

namespace metrofit::diagnose {
namespace {

/// Noise for an effect-to-noise ratio: rms per coordinate of the effect's displacement / ratio.
double noiseFor(const KinematicEffectsOptions& o, double ratio) {
  const auto cmd = circularTestCommands(o.circle);
  const auto with = simulateMachineWithEffects(o.circle.errors, o.effects, cmd, 0.0, 1);
  const auto without = simulateMachine(o.circle.errors, cmd, 0.0, 1);
  double ss = 0.0;
  for (std::size_t k = 0; k < cmd.size(); ++k) ss += (with[k] - without[k]).squaredNorm();
  return std::sqrt(ss / (2.0 * static_cast<double>(cmd.size()))) / ratio;
}

Diagnosis run(const KinematicEffectsOptions& o) {
  KinematicDiagnosisOptions d;
  d.feedMmPerMin = o.effects.feedMmPerMin;
  return diagnoseKinematic(simulateCircularTestWithEffects(o), d);
}

const Candidate* acceptedNamed(const Diagnosis& d, const std::string& name) {
  for (const Candidate* c : d.accepted())
    if (c->name == name) return c;
  return nullptr;
}

double param(const Candidate& c, const std::string& name) {
  for (const auto& p : c.parameters)
    if (p.name == name && std::holds_alternative<double>(p.value)) return std::get<double>(p.value);
  ADD_FAILURE() << "no parameter " << name;
  return 0.0;
}

std::string textParam(const Candidate& c, const std::string& name) {
  for (const auto& p : c.parameters)
    if (p.name == name && std::holds_alternative<std::string>(p.value)) return std::get<std::string>(p.value);
  return {};
}

TEST(KinematicEffectsSim, PathMotionDirectionsAndTangents) {
  const std::vector<Eigen::Vector2d> c{{0, 0}, {1, 0}, {2, 1}, {1, 1}, {1, 1}};
  const PathMotion m = pathMotion(c);
  ASSERT_EQ(m.direction.size(), 5u);
  EXPECT_EQ(m.direction[0], Eigen::Vector2d(1, 1));   // first moves: +x, +y
  EXPECT_EQ(m.direction[3], Eigen::Vector2d(-1, 1));  // x reversed, y last moved up
  EXPECT_EQ(m.direction[4], Eigen::Vector2d(-1, 1));  // no move: keeps the last direction
  EXPECT_NEAR(m.tangent[0].x(), 1.0, 1e-15);
  EXPECT_NEAR(m.tangent[1].norm(), 1.0, 1e-15);
  // At the reversal (2,1): the incoming move.
  EXPECT_NEAR(m.tangent[2].x(), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(m.tangent[2].y(), std::sqrt(0.5), 1e-15);
}

TEST(KinematicEffectsSim, NoEffectsIsTheDeclaredMachineAndBacklashIsLostMotion) {
  KinematicEffectsOptions o;
  o.circle.seed = 4;
  const MeasuredPath a = simulateCircularTestWithEffects(o);
  const MeasuredPath b = simulateCircularTest(o.circle);
  ASSERT_EQ(a.measured.size(), 720u);
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_EQ(a.measured[k], b.measured[k]);
  // Backlash: a point reached moving +x lags by bx / 2, one reached moving -x leads by bx / 2.
  o.circle.noiseMm = 0.0;
  o.circle.errors = ActuatorErrors2{};
  o.effects.backlashXMm = 0.01;
  const MeasuredPath p = simulateCircularTestWithEffects(o);
  // Point 90 (t = 90 deg, CCW) is reached moving -x; point 270 (t = 270 deg) moving +x.
  EXPECT_NEAR(p.measured[90].x() - p.command[90].x(), 0.005, 1e-12);
  EXPECT_NEAR(p.measured[270].x() - p.command[270].x(), -0.005, 1e-12);
  o.effects.cyclicAxis = 'z';
  EXPECT_THROW(simulateCircularTestWithEffects(o), OptionsError);
}

struct KinCase {
  const char* name;
};

void PrintTo(const KinCase& c, std::ostream* os) {
  *os << c.name;
}

class KinematicEffectFound : public ::testing::TestWithParam<KinCase> {};

TEST_P(KinematicEffectFound, AtRatioFiveWithin30Percent) {
  const std::string name = GetParam().name;
  for (std::uint64_t seed : {31u, 32u}) {
    KinematicEffectsOptions o;
    o.circle.seed = seed;
    KinematicEffects& e = o.effects;
    if (name == "backlash") {
      e.backlashXMm = 0.006;
      e.backlashYMm = 0.004;
    } else if (name == "scale") {
      e.scaleXPpm = 20.0;
      e.scaleYPpm = -10.0;
    } else if (name == "cyclic") {
      e.cyclicAxis = 'y';
      e.cyclicPeriodMm = 16.0;
      e.cyclicAmplitudeMm = 0.003;
      e.cyclicPhaseDeg = -40.0;
    } else {
      e.servoLagS = 0.004;
      e.feedMmPerMin = 2000.0;
    }
    o.circle.noiseMm = noiseFor(o, 5.0);
    const Diagnosis d = run(o);
    const Candidate* c = acceptedNamed(d, name);
    ASSERT_NE(c, nullptr) << name << " seed " << seed << ": " << toJson(d).dump(1);
    EXPECT_EQ(d.accepted().size(), 1u) << toJson(d).dump(1);
    if (name == "backlash") {
      EXPECT_NEAR(param(*c, "x_mm"), 0.006, 0.3 * 0.006);
      EXPECT_NEAR(param(*c, "y_mm"), 0.004, 0.3 * 0.004);
    } else if (name == "scale") {
      EXPECT_NEAR(param(*c, "x_ppm"), 20.0, 6.0);
      EXPECT_NEAR(param(*c, "y_ppm"), -10.0, 3.0);
    } else if (name == "cyclic") {
      EXPECT_EQ(textParam(*c, "axis"), "y");
      EXPECT_NEAR(param(*c, "period_mm"), 16.0, 0.3 * 16.0);
      EXPECT_NEAR(param(*c, "amplitude_mm"), 0.003, 0.3 * 0.003);
    } else {
      EXPECT_NEAR(param(*c, "tau_s"), 0.004, 0.3 * 0.004);
    }
    EXPECT_LT(c->score, -10.0);
    EXPECT_LE(c->rmseAfter, 0.95 * c->rmseBefore);
    EXPECT_LT(d.final.rmse, d.baseline.rmse);
    ASSERT_TRUE(c->plot.has_value());
    EXPECT_EQ(c->plot->xLabel, "path angle (deg)");
    EXPECT_EQ(c->plot->x.size(), 720u);
    EXPECT_NE(c->evidence.find("dBIC"), std::string::npos);
  }
}

INSTANTIATE_TEST_SUITE_P(Effects, KinematicEffectFound,
                         ::testing::Values(KinCase{"backlash"}, KinCase{"scale"}, KinCase{"cyclic"},
                                           KinCase{"servo_lag"}),
                         [](const auto& info) {
                           return std::string(info.param.name) == "servo_lag" ? "servo" : info.param.name;
                         });

TEST(KinematicDiagnosis, CleanDataComesOutClean) {
  for (std::uint64_t seed = 200; seed < 208; ++seed) {
    KinematicEffectsOptions o;
    o.circle.seed = seed;
    const Diagnosis d = run(o);
    EXPECT_TRUE(d.accepted().empty()) << "seed " << seed << ": " << toJson(d).dump(1);
    EXPECT_EQ(d.effects.size(), 4u);
    EXPECT_NEAR(d.final.rmse, d.baseline.rmse, 1e-9);
  }
}

TEST(KinematicDiagnosis, TwoEffectsAreBothFound) {
  KinematicEffectsOptions o;
  o.circle.seed = 41;
  o.effects.backlashXMm = 0.008;
  o.effects.backlashYMm = 0.005;
  o.effects.cyclicAxis = 'x';
  o.effects.cyclicPeriodMm = 10.0;
  o.effects.cyclicAmplitudeMm = 0.002;
  const Diagnosis d = run(o);
  const Candidate* b = acceptedNamed(d, "backlash");
  const Candidate* c = acceptedNamed(d, "cyclic");
  ASSERT_NE(b, nullptr) << toJson(d).dump(1);
  ASSERT_NE(c, nullptr) << toJson(d).dump(1);
  EXPECT_EQ(d.accepted().size(), 2u);
  EXPECT_NEAR(param(*b, "x_mm"), 0.008, 0.0005);
  EXPECT_NEAR(param(*c, "period_mm"), 10.0, 0.1);
  EXPECT_NEAR(param(*c, "amplitude_mm"), 0.002, 0.0003);
  EXPECT_NEAR(d.final.rmse, std::sqrt(2.0) * 0.0005, 0.0001);  // down to the noise
}

TEST(KinematicDiagnosis, ContractJson) {
  KinematicEffectsOptions o;
  o.effects.backlashXMm = 0.008;
  const nlohmann::json j = toJson(run(o));
  EXPECT_EQ(j.at("domain"), "kinematic");
  for (const char* k : {"rmse", "max_abs"}) EXPECT_TRUE(j.at("baseline").at(k).is_number());
  EXPECT_FALSE(j.at("baseline").contains("heldout_rmse"));
  for (const auto& e : j.at("effects")) {
    for (const char* k : {"name", "accepted", "parameters", "rmse_before", "rmse_after", "evidence"})
      EXPECT_TRUE(e.contains(k)) << k;
    const auto& p = e.at("parameters");
    if (e.at("name") == "backlash") {
      EXPECT_TRUE(p.at("x_mm").is_number() && p.at("y_mm").is_number());
    }
    if (e.at("name") == "scale") {
      EXPECT_TRUE(p.at("x_ppm").is_number() && p.at("y_ppm").is_number());
    }
    if (e.at("name") == "cyclic") {
      EXPECT_TRUE(p.at("axis").is_string() && p.at("period_mm").is_number() &&
                  p.at("amplitude_mm").is_number());
    }
    if (e.at("name") == "servo_lag") {
      EXPECT_TRUE(p.at("tau_s").is_number());
    }
  }
  EXPECT_EQ(j.at("effects").at(0).at("name"), "backlash");
  EXPECT_EQ(j.at("effects").at(0).at("accepted"), true);
}

TEST(KinematicDiagnosis, BadInputs) {
  MeasuredPath p;
  p.source = "few.csv";
  p.command = {{0, 0}, {1, 0}};
  p.measured = p.command;
  EXPECT_THROW(diagnoseKinematic(p, {}), InputError);
  KinematicDiagnosisOptions o;
  o.feedMmPerMin = 0.0;
  EXPECT_THROW(diagnoseKinematic(simulateCircularTestWithEffects({}), o), OptionsError);
}

}  // namespace
}  // namespace metrofit::diagnose
