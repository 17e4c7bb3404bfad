// Periodic in time with an unknown period (core/diagnose/residual_check.h, the period search; the
// thermal loop's generic `unexplained:time` periodic; its shape applied to the thermal models),
// against references the project did not make: the basis against values computed by hand, the
// search's corrected p-value against its nominal level on white noise, and thermal logs written here
// from a closed form (2 um/K of T1 plus a 3 um cycle of 47 min plus 0.3 um of noise), with the same
// log without the cycle as the control.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include <Eigen/Dense>

#include "core/common/error.h"
#include "core/diagnose/applied_entries.h"
#include "core/diagnose/residual_check.h"
#include "core/diagnose/thermal_applied.h"
#include "core/diagnose/thermal_diagnosis.h"
#include "core/thermal/lag_regression.h"
#include "core/thermal/thermal_data.h"
#include "core/thermal/thermal_model.h"

namespace metrofit::diagnose {
namespace {

const double kPi = std::acos(-1.0);

TEST(PeriodicInTime, BasisIsSineAndCosineOfTheVariableOverThePeriod) {
  GenericForm f;
  f.against = "time";
  f.form = DependenceForm::Periodic;
  f.harmonics = 2;
  f.period = 47.0;
  // v = P/4, P/2, P/8: angles pi/2, pi, pi/4 (and twice that for the second harmonic).
  const Eigen::MatrixXd G = genericBasis(f, {11.75, 23.5, 5.875});
  ASSERT_EQ(G.rows(), 3);
  ASSERT_EQ(G.cols(), 4);  // cos 1, sin 1, cos 2, sin 2
  const double h = std::sqrt(0.5);
  const double expected[3][4] = {{0.0, 1.0, -1.0, 0.0}, {-1.0, 0.0, 1.0, 0.0}, {h, h, 0.0, 1.0}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(G(i, j), expected[i][j], 1e-12) << i << "," << j;
  // Without a period the values are a path angle in degrees, as before.
  f.period = 0.0;
  const Eigen::MatrixXd A = genericBasis(f, {90.0});
  EXPECT_NEAR(A(0, 0), 0.0, 1e-12);
  EXPECT_NEAR(A(0, 1), 1.0, 1e-12);
  EXPECT_NEAR(A(0, 2), -1.0, 1e-12);
}

TEST(PeriodicInTime, SearchFindsThePeriodAndItsCorrectedPIsCalibratedOnWhiteNoise) {
  const int n = 240;
  std::vector<double> t(n);
  for (int k = 0; k < n; ++k) t[static_cast<std::size_t>(k)] = k;
  const Eigen::MatrixXd none(n, 0);
  std::mt19937 rng(5);
  std::normal_distribution<double> z(0.0, 1.0);
  // White noise: the search's corrected p below 1 % in about 1 % of the sets (at most 2 %: room for
  // the binomial spread of 600 sets, sd 0.4 %; a Bonferroni factor of the independent periods alone
  // gave 15 of 600).
  int below = 0, sets = 600;
  for (int s = 0; s < sets; ++s) {
    Eigen::VectorXd r(n);
    for (int k = 0; k < n; ++k) r(k) = z(rng);
    const auto found = searchPeriod(r, none, t, {});
    ASSERT_TRUE(found.has_value());
    EXPECT_EQ(found->searched, 57);  // ceil(59.75 - 3): span 239 over 4 samples is 59.75 cycles
    below += found->p < 0.01;
  }
  std::cout << "white noise: corrected p < 1 % in " << below << " of " << sets << " sets\n";
  EXPECT_LE(below, sets / 50);
  // A cycle of 47 samples at 1.5 noise sd: found within 1 % of its period.
  Eigen::VectorXd r(n);
  for (int k = 0; k < n; ++k) r(k) = 1.5 * std::sin(2.0 * kPi * k / 47.0 + 0.4) + z(rng);
  const auto found = searchPeriod(r, none, t, {});
  ASSERT_TRUE(found.has_value());
  EXPECT_NEAR(found->period, 47.0, 0.47);
  EXPECT_LT(found->p, 1e-10);
}

// A long series (100 000 samples, a week of 1 Hz data is 604 800) is searched on 20 000 evenly strided
// samples and tested on all of them: the period of a weak cycle (0.1 noise sd, far below what 20 000
// samples alone would show at this p) is found within 0.5 %, its p is that of the full test, and a
// linear model column is still taken off first (a ramp in the residual is not a cycle).
TEST(PeriodicInTime, ALongSeriesIsSearchedOnAStridedSampleAndTestedOnAll) {
  const int n = 100000;
  std::vector<double> t(n);
  for (int k = 0; k < n; ++k) t[static_cast<std::size_t>(k)] = k;
  Eigen::MatrixXd ramp(n, 1);
  std::mt19937 rng(9);
  std::normal_distribution<double> z(0.0, 1.0);
  Eigen::VectorXd r(n);
  const double period = 4321.0;
  for (int k = 0; k < n; ++k) {
    ramp(k, 0) = k / 1000.0;
    r(k) = 0.05 * ramp(k, 0) + 0.1 * std::sin(2.0 * kPi * k / period + 1.1) + z(rng);
  }
  const auto found = searchPeriod(r, ramp, t, {});
  ASSERT_TRUE(found.has_value());
  EXPECT_NEAR(found->period, period, 0.005 * period);
  EXPECT_LT(found->p, 1e-20);
  // White noise of the same length: no cycle.
  Eigen::VectorXd w(n);
  for (int k = 0; k < n; ++k) w(k) = z(rng);
  const auto none = searchPeriod(w, ramp, t, {});
  ASSERT_TRUE(none.has_value());
  EXPECT_GT(none->p, 0.01);
}

/// A log written from the closed form of the header: T1 slowly warming and cooling, the target
/// 2 um/K of T1, with `cycle` a 3 um sine of 47 min (phase 0.4) that no column sees, and 0.3 um noise.
ThermalLog cycleLog(bool cycle, unsigned seed = 3) {
  ThermalLog log;
  log.source = "cycle.csv";
  log.timeColumn = "time_min";
  ThermalChannel t1{"T1", "degC", {}}, y{"disp_z_um", "um", {}};
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.3);
  for (int k = 0; k < 600; ++k) {
    const double t = k;
    const double a = 20.0 + 3.0 * std::sin(2.0 * kPi * t / 250.0);
    log.timeMin.push_back(t);
    t1.values.push_back(a);
    y.values.push_back(2.0 * (a - 20.0) + (cycle ? 3.0 * std::sin(2.0 * kPi * t / 47.0 + 0.4) : 0.0) +
                       noise(rng));
  }
  log.channels = {t1, y};
  return log;
}

ThermalDiagnosisOptions cycleOptions() {
  ThermalDiagnosisOptions o;
  o.target = "disp_z_um";
  o.inputs = {"T1"};
  return o;
}

const Candidate* acceptedPeriodic(const Diagnosis& d) {
  for (const Candidate* c : d.accepted())
    if (c->generic && c->generic->form == DependenceForm::Periodic) return c;
  return nullptr;
}

TEST(PeriodicInTime, ThermalLoopExplainsACycleNoColumnSees) {
  const ThermalLog log = cycleLog(true);
  const Diagnosis d = diagnoseThermal(log, cycleOptions());
  const Candidate* c = acceptedPeriodic(d);
  ASSERT_NE(c, nullptr) << toJson(d).dump(1);
  EXPECT_EQ(c->name, "unexplained:time");
  EXPECT_NEAR(c->generic->period, 47.0, 0.03 * 47.0);
  // Nothing else: the cycle is not a catalogue effect.
  EXPECT_EQ(d.accepted().size(), 1u) << toJson(d).dump(1);
  // After it, the fit's error is the noise (0.3 um) and the residual is white.
  EXPECT_LT(d.final.rmse, 0.36);
  EXPECT_GT(d.final.rmse, 0.24);
  ASSERT_TRUE(d.final.heldoutRmse.has_value());
  EXPECT_LT(*d.final.heldoutRmse, 0.45);  // the cycle carries over to the rows the fit did not see
  ASSERT_TRUE(d.residualCheck.has_value());
  EXPECT_TRUE(d.residualCheck->white) << d.residualCheck->summary;
  // The JSON names the form; the structure's period is written where it is one.
  const nlohmann::json j = toJson(d);
  bool listed = false;
  for (const auto& e : j["effects"])
    if (e["name"] == "unexplained:time" && e["accepted"] == true) listed = e["form"] == "periodic";
  EXPECT_TRUE(listed);
}

TEST(PeriodicInTime, WithoutTheCycleNothingPeriodicIsAccepted) {
  for (unsigned seed : {3u, 4u, 5u}) {
    const Diagnosis d = diagnoseThermal(cycleLog(false, seed), cycleOptions());
    EXPECT_EQ(acceptedPeriodic(d), nullptr) << seed << toJson(d).dump(1);
    EXPECT_TRUE(d.accepted().empty()) << seed << toJson(d).dump(1);
    ASSERT_TRUE(d.residualCheck.has_value());
    EXPECT_TRUE(d.residualCheck->white) << seed << d.residualCheck->summary;
  }
}

TEST(PeriodicInTime, ShapeWithThePeriodRoundTripsThroughApply) {
  const ThermalLog log = cycleLog(true);
  const ThermalDiagnosisOptions o = cycleOptions();
  const Diagnosis d = diagnoseThermal(log, o);
  const Candidate* c = acceptedPeriodic(d);
  ASSERT_NE(c, nullptr);
  const nlohmann::json shape = genericShapeJson(*c->generic);
  ASSERT_TRUE(shape.contains("period"));
  EXPECT_DOUBLE_EQ(shape["period"].get<double>(), c->generic->period);
  // The JSON as a project file stores it (text), read back.
  const nlohmann::json entry = nlohmann::json::parse(
      nlohmann::json{{"name", c->name}, {"parameters", nlohmann::json::object()}, {"shape", shape}}.dump());
  const GenericForm back = genericShapeOf(AppliedEntry{0, entry, c->name, "applied[0]"});
  EXPECT_EQ(back.form, DependenceForm::Periodic);
  EXPECT_EQ(back.period, c->generic->period);
  EXPECT_EQ(back.harmonics, c->generic->harmonics);

  const AppliedThermalEffects a =
      appliedThermalEffects(nlohmann::json::array({entry}), log, o.target, o.inputs);
  EXPECT_EQ(a.text(), "unexplained:time (periodic)");
  const ThermalLogWithEffects with = withThermalEffects(log, o.inputs, a.effects);
  ASSERT_EQ(with.inputs.size(), 1u + 2u);  // T1, then cos and sin of the cycle
  // The static regression with the effect's columns: the held-out error falls from the cycle's
  // (3 um / sqrt 2 = 2.1 um) to the noise (0.3 um).
  thermal::ThermalFitOptions fo;
  fo.model = thermal::ThermalModelKind::Linear;
  const auto e0 = thermal::fitAndEvaluate(thermal::selectThermalSeries(log, o.target, o.inputs), 0.5, fo);
  const auto e1 =
      thermal::fitAndEvaluate(thermal::selectThermalSeries(with.log, o.target, with.inputs), 0.5, fo);
  std::cout << "linear model held-out rmse (um): declared " << e0.heldout.rmse << ", with unexplained:time "
            << e1.heldout.rmse << "\n";
  EXPECT_GT(e0.heldout.rmse, 1.8);
  EXPECT_LT(e1.heldout.rmse, 0.4);
  EXPECT_GT(e1.heldout.rmse, 0.2);

  // A period on a form that is not periodic, or not positive, names the field.
  const auto message = [&](const nlohmann::json& s) -> std::string {
    nlohmann::json x = entry;
    x["shape"] = s;
    try {
      (void)appliedThermalEffects(nlohmann::json::array({x}), log, o.target, o.inputs);
    } catch (const ValidationError& err) {
      return err.what();
    }
    return "(no error)";
  };
  nlohmann::json negative = shape;
  negative["period"] = -47.0;
  EXPECT_EQ(
      message(negative),
      "field 'studies.diagnosis.thermal.applied[0].shape.period': must be a positive number (the period "
      "of a periodic form)");
  nlohmann::json step = shape;
  step["form"] = "step";
  step["knots"] = {100.0};
  EXPECT_EQ(
      message(step),
      "field 'studies.diagnosis.thermal.applied[0].shape.period': must be a positive number (the period "
      "of a periodic form)");
}

}  // namespace
}  // namespace metrofit::diagnose
