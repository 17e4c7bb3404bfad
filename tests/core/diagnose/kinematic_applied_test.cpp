// Applied kinematic effects (core/kinematics/axis_effects.h): the effects the closed loop accepts,
// applied to the declared Cartesian model, make the identification's residual the diagnosis' own
// error after the effects, and the compensated references correct them: run through the true
// simulated machine (with its effect, noise free) the compensated path's error E1 is a fraction of
// the declared model's E0. On the demo's circular test (backlash 8 / 5 um) the expected error after
// compensation falls from the diagnosis' baseline to its 'after' figure. Bad entries name the field.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "core/common/error.h"
#include "core/diagnose/kinematic_diagnosis.h"
#include "core/kinematics/axis_effects.h"
#include "core/kinematics/identification.h"
#include "core/sim/effects_kinematic.h"
#include "testsupport.h"

namespace metrofit {
namespace {

using diagnose::Diagnosis;

/// The applied list as the diagnosis page's Apply stores it (widgets/diagnose appliedEffects).
nlohmann::json appliedOf(const Diagnosis& d) {
  nlohmann::json out = nlohmann::json::array();
  for (const diagnose::Candidate* c : d.accepted()) {
    nlohmann::json params = nlohmann::json::object();
    for (const diagnose::Parameter& p : c->parameters) {
      if (const double* v = std::get_if<double>(&p.value))
        params[p.name] = *v;
      else
        params[p.name] = std::get<std::string>(p.value);
    }
    out.push_back({{"name", c->name}, {"parameters", params}});
  }
  return out;
}

double rmsDistance(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b) {
  double s = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) s += (a[k] - b[k]).squaredNorm();
  return std::sqrt(s / static_cast<double>(a.size()));
}

/// The expected path after compensation with the identified model (the measured residual stays):
/// rms distance from the nominal points (widgets/kinematics/circularanalysis.h does the same).
double expectedRms(const MeasuredPath& path, const AxisEffects& fx) {
  const IdentifyResult id = identifyActuatorErrors(withEffectiveJoints(path, fx));
  const CartesianMachine2 m = CartesianMachine2::fromErrors(id.errors);
  const std::vector<Eigen::Vector2d> refs = compensatePathWithEffects(m, fx, path.command);
  const std::vector<Eigen::Vector2d> atRefs = runPathWithEffects(m, fx, refs, path.command);
  EXPECT_LT(rmsDistance(atRefs, path.command), 1e-9);  // the model lands on the nominal points
  const std::vector<Eigen::Vector2d> atNominal = runPathWithEffects(m, fx, path.command, path.command);
  std::vector<Eigen::Vector2d> expected;
  for (std::size_t k = 0; k < path.size(); ++k)
    expected.push_back(path.measured[k] + atRefs[k] - atNominal[k]);
  return rmsDistance(expected, path.command);
}

std::string fieldOf(const nlohmann::json& applied) {
  try {
    (void)axisEffectsFromApplied(applied, 1000.0);
  } catch (const ValidationError& e) {
    return e.context().field;
  }
  return "(no error)";
}

struct Case {
  const char* name;
};
class KinematicApplied : public ::testing::TestWithParam<Case> {};

TEST_P(KinematicApplied, CompensationWithTheAppliedEffectRemovesIt) {
  const std::string name = GetParam().name;
  KinematicEffectsOptions o;
  o.circle.seed = 41;
  KinematicEffects& e = o.effects;
  if (name == "backlash") {
    e.backlashXMm = 0.008;
    e.backlashYMm = 0.005;
  } else if (name == "scale") {
    e.scaleXPpm = 60.0;
    e.scaleYPpm = -40.0;
  } else if (name == "cyclic") {
    e.cyclicAxis = 'y';
    e.cyclicPeriodMm = 16.0;
    e.cyclicAmplitudeMm = 0.004;
    e.cyclicPhaseDeg = -40.0;
  } else {
    e.servoLagS = 0.004;
    e.feedMmPerMin = 2000.0;
  }
  const MeasuredPath path = simulateCircularTestWithEffects(o);
  diagnose::KinematicDiagnosisOptions dopt;
  dopt.feedMmPerMin = e.feedMmPerMin;
  const Diagnosis d = diagnose::diagnoseKinematic(path, dopt);
  ASSERT_EQ(d.accepted().size(), 1u) << diagnose::toJson(d).dump(1);
  ASSERT_EQ(d.accepted()[0]->name, name);
  const AxisEffects fx = axisEffectsFromApplied(appliedOf(d), e.feedMmPerMin);
  ASSERT_EQ(fx.labels.size(), 1u);
  EXPECT_TRUE(fx.labels[0].starts_with(name)) << fx.labels[0];

  // The identification with the applied effect has the diagnosis' residual after the effect.
  const IdentifyResult declared = identifyActuatorErrors(path);
  const IdentifyResult with = identifyActuatorErrors(withEffectiveJoints(path, fx));
  EXPECT_NEAR(declared.rmseMm, d.baseline.rmse, 1e-4 * d.baseline.rmse);
  EXPECT_NEAR(with.rmseMm, d.final.rmse, 0.01 * d.final.rmse);
  EXPECT_NEAR(expectedRms(path, fx), d.final.rmse, 0.01 * d.final.rmse);
  EXPECT_NEAR(expectedRms(path, AxisEffects{}), d.baseline.rmse, 1e-4 * d.baseline.rmse);

  // The true machine (its errors and effect, noise free) run with the compensated references.
  const std::vector<Eigen::Vector2d> refs0 =
      compensatePath(CartesianMachine2::fromErrors(declared.errors), path.command);
  const std::vector<Eigen::Vector2d> refs1 =
      compensatePathWithEffects(CartesianMachine2::fromErrors(with.errors), fx, path.command);
  const double e0 = rmsDistance(simulateMachineWithEffects(o.circle.errors, e, refs0, 0.0, 0), path.command);
  const double e1 = rmsDistance(simulateMachineWithEffects(o.circle.errors, e, refs1, 0.0, 0), path.command);
  std::cout << name << ": diagnosis rmse " << d.baseline.rmse * 1e3 << " -> " << d.final.rmse * 1e3
            << " um; true machine after compensation: declared " << e0 * 1e3
            << " um, with the applied effect " << e1 * 1e3 << " um\n";
  EXPECT_LT(e1, 0.3 * e0);
  EXPECT_LT(e1, 0.6e-3);  // below the 0.5 um noise level the effect was estimated from, plus margin
}

INSTANTIATE_TEST_SUITE_P(Effects, KinematicApplied,
                         ::testing::Values(Case{"backlash"}, Case{"scale"}, Case{"cyclic"},
                                           Case{"servo_lag"}),
                         [](const auto& info) {
                           return std::string(info.param.name) == "servo_lag" ? "servo" : info.param.name;
                         });

TEST(KinematicAppliedDemo, BacklashAppliedLowersTheCompensatedErrorToTheDiagnosisAfterFigure) {
  const MeasuredPath path =
      readMeasuredPath((test::sourceDir() / "resources/demo/data/diagnose_circular.csv").string());
  const Diagnosis d = diagnose::diagnoseKinematic(path, {});
  ASSERT_EQ(d.accepted().size(), 1u);
  ASSERT_EQ(d.accepted()[0]->name, "backlash");
  const AxisEffects fx = axisEffectsFromApplied(appliedOf(d));
  const double e0 = expectedRms(path, AxisEffects{});
  const double e1 = expectedRms(path, fx);
  std::cout << "demo: diagnosis rmse " << d.baseline.rmse * 1e3 << " -> " << d.final.rmse * 1e3
            << " um; expected after compensation: declared " << e0 * 1e3 << " um, with backlash " << e1 * 1e3
            << " um (" << fx.text() << ")\n";
  EXPECT_NEAR(e0, d.baseline.rmse, 1e-4 * d.baseline.rmse);
  EXPECT_NEAR(e1, d.final.rmse, 0.01 * d.final.rmse);
  EXPECT_LT(e1, 0.5 * e0);
}

TEST(KinematicAppliedErrors, BadEntriesNameTheField) {
  using J = nlohmann::json;
  EXPECT_EQ(fieldOf(J::parse(R"([{"name": "wobble", "parameters": {}}])")),
            "studies.diagnosis.kinematic.applied[0].name");
  EXPECT_EQ(fieldOf(J::parse(R"([{"name": "scale", "parameters": {"x_ppm": 1, "y_ppm": 2}},
                                  {"name": "backlash", "parameters": {"x_mm": 0.001}}])")),
            "studies.diagnosis.kinematic.applied[1].parameters.y_mm");
  EXPECT_EQ(fieldOf(J::parse(R"([{"name": "cyclic", "parameters": {"axis": "z", "period_mm": 5,
                                  "amplitude_mm": 0.001}}])")),
            "studies.diagnosis.kinematic.applied[0].parameters.axis");
  EXPECT_EQ(fieldOf(J::parse(R"([{"name": "cyclic", "parameters": {"axis": "x", "period_mm": 0,
                                  "amplitude_mm": 0.001}}])")),
            "studies.diagnosis.kinematic.applied[0].parameters.period_mm");
  EXPECT_EQ(fieldOf(J::parse(R"([{"name": "servo_lag", "parameters": {"tau_s": "slow"}}])")),
            "studies.diagnosis.kinematic.applied[0].parameters.tau_s");
  EXPECT_EQ(fieldOf(J::parse(R"([{"name": "servo_lag", "parameters": {"tau_s": 0.001}},
                                  {"name": "servo_lag", "parameters": {"tau_s": 0.002}}])")),
            "studies.diagnosis.kinematic.applied[1].name");
  EXPECT_EQ(fieldOf(J::parse(R"(["backlash"])")), "studies.diagnosis.kinematic.applied[0]");
  EXPECT_EQ(fieldOf(J::parse(R"({"name": "scale"})")), "studies.diagnosis.kinematic.applied");
  try {
    (void)axisEffectsFromApplied(J::parse(R"([{"name": "wobble"}])"));
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_EQ(
        std::string(e.what()),
        "field 'studies.diagnosis.kinematic.applied[0].name': unknown kinematic effect 'wobble' (known: "
        "backlash, scale, cyclic, servo_lag)");
  }
  // Cyclic on both axes is two effects; nothing applied is no effect.
  const AxisEffects two = axisEffectsFromApplied(J::parse(
      R"([{"name": "cyclic", "parameters": {"axis": "x", "period_mm": 5, "amplitude_mm": 0.001}},
          {"name": "cyclic", "parameters": {"axis": "y", "period_mm": 7, "amplitude_mm": 0.002}}])"));
  EXPECT_EQ(two.cyclic.size(), 2u);
  EXPECT_TRUE(axisEffectsFromApplied(J::array()).empty());
  EXPECT_TRUE(axisEffectsFromApplied(J()).empty());
}

}  // namespace
}  // namespace metrofit
