// Applied kinematic effects (core/diagnose/applied_kinematic.h): the effects the closed loop accepts,
// applied to the declared Cartesian model, make the identification's residual the diagnosis' own
// error after the effects, and the compensated references correct them: run through the true
// simulated machine (with its effect, noise free) the compensated path's error E1 is a fraction of
// the declared model's E0. On the demo's circular test (backlash 8 / 5 um) the expected error after
// compensation falls from the diagnosis' baseline to its 'after' figure. Bad entries name the field.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <random>
#include <string>

#include "core/common/error.h"
#include "core/diagnose/applied_entries.h"
#include "core/diagnose/applied_kinematic.h"
#include "core/diagnose/kinematic_diagnosis.h"
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
    nlohmann::json entry = {{"name", c->name}, {"parameters", params}};
    if (c->generic) entry["shape"] = diagnose::genericShapeJson(*c->generic);
    if (!c->genericCoefficients.empty()) entry["coefficients"] = c->genericCoefficients;
    out.push_back(std::move(entry));
  }
  return out;
}

double rmsDistance(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b) {
  double s = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) s += (a[k] - b[k]).squaredNorm();
  return std::sqrt(s / static_cast<double>(a.size()));
}

/// The expected path after compensation with the identified model (the measured residual stays):
/// rms distance from the nominal points (core/study/circular_analysis.h does the same).
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

/// A circular test written here from a closed form: radius 50 mm about (10, -5) mm, 720 points CCW then
/// 720 CW, on a machine with origin error (3, -2) um and axis angles 20 / -15 urad, plus a three-lobe
/// radial error 5 cos(3 theta) um that no catalogue effect models (a cyclic error follows one axis'
/// position, backlash the direction, scale the coordinate) and 0.3 um noise per coordinate.
MeasuredPath lobedPath(std::vector<Eigen::Vector2d>* lobes) {
  MeasuredPath p;
  p.source = "lobed.csv";
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.0003);
  const Eigen::Vector2d centre(10.0, -5.0), o(0.003, -0.002);
  const double a = 20e-6, b = -15e-6;
  const Eigen::Vector2d ir(std::cos(a), std::sin(a)), jr(-std::sin(b), std::cos(b));
  for (int loop = 0; loop < 2; ++loop) {
    for (int k = 0; k < 720; ++k) {
      const double t = (loop == 0 ? k : 720 - k) * 2.0 * std::numbers::pi / 720.0;
      const Eigen::Vector2d u(std::cos(t), std::sin(t));
      const Eigen::Vector2d c = centre + 50.0 * u;
      const Eigen::Vector2d lobe = 0.005 * std::cos(3.0 * t) * u;
      p.command.push_back(c);
      p.measured.push_back(o + ir * c.x() + jr * c.y() + lobe + Eigen::Vector2d(noise(rng), noise(rng)));
      if (lobes) lobes->push_back(lobe);
    }
  }
  return p;
}

TEST(KinematicAppliedGeneric, LobingAppliedAsAGenericEffectIsCompensated) {
  std::vector<Eigen::Vector2d> lobes;
  const MeasuredPath path = lobedPath(&lobes);
  const Diagnosis d = diagnose::diagnoseKinematic(path, {});
  const diagnose::Candidate* g = nullptr;
  for (const diagnose::Candidate* c : d.accepted())
    if (c->generic && c->generic->against == "angle") g = c;
  ASSERT_NE(g, nullptr) << diagnose::toJson(d).dump(1);
  EXPECT_EQ(g->generic->form, diagnose::DependenceForm::Periodic);
  ASSERT_FALSE(g->genericCoefficients.empty());

  const AxisEffects fx = axisEffectsFromApplied(appliedOf(d));
  ASSERT_EQ(fx.generic.size(), 1u);
  EXPECT_EQ(fx.text().rfind("unexplained:angle (periodic)", 0), 0u) << fx.text();
  // The displacement the applied effect gives on the path is the lobing of the closed form (the
  // basis' part in the declared model was absorbed by o, a, b; cos 3 theta has none).
  const std::vector<Eigen::Vector2d> shift = fx.displacement(path.command);
  const double lobeRms =
      rmsDistance(lobes, std::vector<Eigen::Vector2d>(lobes.size(), Eigen::Vector2d::Zero()));
  const double misfit = rmsDistance(shift, lobes);
  std::cout << "lobing rms " << lobeRms * 1e3 << " um, applied displacement minus lobing rms " << misfit * 1e3
            << " um\n";
  EXPECT_LT(misfit, 0.1 * lobeRms);

  // Compensation with the applied effect leaves the noise; without it the lobing stays.
  const double e0 = expectedRms(path, AxisEffects{});
  const double e1 = expectedRms(path, fx);
  std::cout << "expected after compensation: declared " << e0 * 1e3 << " um, with " << fx.text() << " "
            << e1 * 1e3 << " um; diagnosis " << d.baseline.rmse * 1e3 << " -> " << d.final.rmse * 1e3
            << " um\n";
  EXPECT_GT(e0, 0.8 * lobeRms);
  EXPECT_LT(e1, 0.6e-3);  // noise: 0.3 um per coordinate, 0.42 um as a distance
  EXPECT_NEAR(e1, d.final.rmse, 0.05 * d.final.rmse);
}

TEST(KinematicAppliedGeneric, BadGenericEntriesNameTheField) {
  using J = nlohmann::json;
  diagnose::GenericForm f;
  f.against = "angle";
  f.form = diagnose::DependenceForm::Periodic;
  f.harmonics = 2;
  f.components = 2;
  const J good = {{"name", "unexplained:angle"},
                  {"shape", diagnose::genericShapeJson(f)},
                  {"coefficients", {0.001, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0}}};
  EXPECT_EQ(axisEffectsFromApplied(J::array({good})).generic.size(), 1u);
  J few = good;
  few["coefficients"] = {0.001};
  EXPECT_EQ(fieldOf(J::array({few})), "studies.diagnosis.kinematic.applied[0].coefficients");
  J nan = good;
  nan["coefficients"][3] = "x";
  EXPECT_EQ(fieldOf(J::array({nan})), "studies.diagnosis.kinematic.applied[0].coefficients");
  J temp = good;
  temp["name"] = "unexplained:T1";
  temp["shape"]["against"] = "T1";
  EXPECT_EQ(fieldOf(J::array({temp})), "studies.diagnosis.kinematic.applied[0].name");
  J one = good;
  one["shape"]["components"] = 1;
  EXPECT_EQ(fieldOf(J::array({one})), "studies.diagnosis.kinematic.applied[0].shape.components");
  // cos(theta) of 1 um in x only: the displacement at angle 0 is (1, 0) um, at 90 deg zero.
  const std::vector<Eigen::Vector2d> cmd = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  const std::vector<Eigen::Vector2d> d = axisEffectsFromApplied(J::array({good})).displacement(cmd);
  EXPECT_NEAR(d[0].x(), 0.001, 1e-15);
  EXPECT_NEAR(d[0].y(), 0.0, 1e-15);
  EXPECT_NEAR(d[1].x(), 0.0, 1e-15);
  EXPECT_NEAR(d[2].x(), -0.001, 1e-15);
}

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
        "backlash, scale, cyclic, servo_lag, unexplained:<variable>)");
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
