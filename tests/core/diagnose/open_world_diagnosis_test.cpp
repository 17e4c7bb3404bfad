// The open world of the closed loop (docs/file-formats.md#residual_check) in the setup, matching and
// kinematic domains (and thermal: a curvature, a re-zeroed sensor and a gross error after the fit
// rows): effects that no catalogue entry models are added here, in the test, to clean
// simulated data (not by the project's effect simulators), and the loop must not name a catalogue
// effect for them; it must flag or explain the structure. Gross errors are listed as outliers with
// their row; clean data stay white with nothing accepted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "core/common/rng.h"
#include "core/diagnose/kinematic_diagnosis.h"
#include "core/diagnose/matching_diagnosis.h"
#include "core/diagnose/setup_diagnosis.h"
#include "core/diagnose/thermal_diagnosis.h"
#include "core/io/csv.h"
#include "core/setup/report.h"
#include "core/sim/circular_sim.h"
#include "core/sim/effects_setup.h"
#include "core/sim/effects_thermal.h"
#include "core/sim/open_world.h"
#include "core/sim/probe_sim.h"
#include "core/thermal/thermal_log.h"
#include "testsupport.h"

namespace metrofit::diagnose {
namespace {

std::string describe(const Diagnosis& d) {
  return toJson(d).dump(1).substr(0, 6000);
}

/// A catalogue (named) effect was accepted.
bool catalogueAccepted(const Diagnosis& d) {
  for (const Candidate* c : d.accepted())
    if (!c->generic) return true;
  return false;
}

/// Structure flagged (residual not white) or explained by a generic effect.
bool flaggedOrExplained(const Diagnosis& d) {
  for (const Candidate* c : d.accepted())
    if (c->generic) return true;
  return d.residualCheck && !d.residualCheck->white;
}

// ---- setup --------------------------------------------------------------------------------------

setup::Model paperModel() {
  return setup::readModel((test::sourceDir() / "resources/demo/setup/paper_example.json").string());
}

constexpr double kW2 = 0.01;  // uniform noise +-w2
const double kSigma = kW2 / std::sqrt(3.0);

setup::Measurements cleanSetup(const setup::Model& model, std::uint64_t seed, int parts = 12) {
  SetupEffectsSimOptions o;
  o.base.w1 = 0.03;
  o.base.w2 = kW2;
  o.base.parts = parts;
  o.base.minutesPerPart = 12.0;
  o.base.resolutionMm = 0.0001;
  o.base.seed = seed;
  return setup::cmmReportFromCsv(parseCsv(simulateSetupEffectsReport(model, o), "sim.csv"), model);
}

TEST(OpenWorldSetup, CleanReportsAreWhiteWithNothingAccepted) {
  const setup::Model model = paperModel();
  int flagged = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Diagnosis d = diagnoseSetup(model, cleanSetup(model, seed));
    ASSERT_TRUE(d.residualCheck.has_value());
    EXPECT_TRUE(d.accepted().empty()) << "seed " << seed << "\n" << describe(d);
    EXPECT_TRUE(d.residualCheck->outliers.empty()) << "seed " << seed;
    if (!d.residualCheck->white) ++flagged;
  }
  EXPECT_LE(flagged, 1);
}

TEST(OpenWorldSetup, AStepOfOneDimensionAfterARefixtureIsNotCalledWearOrDrift) {
  // From part 7 on, one dimension sits 6 sigma higher (the part was re-clamped against a chip): a
  // step in the part number of that dimension, which neither tool wear nor drift (linear) models.
  const setup::Model model = paperModel();
  int ok = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    setup::Measurements m = cleanSetup(model, seed);
    const std::size_t dim = m.rows.front().dimension;
    for (auto& r : m.rows)
      if (r.dimension == dim && std::stoi(r.part) >= 7) r.deviationMm += 6.0 * kSigma;
    const Diagnosis d = diagnoseSetup(model, m);
    EXPECT_FALSE(catalogueAccepted(d)) << "seed " << seed << "\n" << describe(d);
    if (flaggedOrExplained(d)) ++ok;
  }
  EXPECT_GE(ok, 4);
}

TEST(OpenWorldSetup, AGrossCmmErrorIsListedWithItsRowAndExcluded) {
  const setup::Model model = paperModel();
  setup::Measurements m = cleanSetup(model, 4);
  m.rows[37].deviationMm += 40.0 * kSigma;
  const Diagnosis d = diagnoseSetup(model, m);
  ASSERT_TRUE(d.residualCheck.has_value());
  ASSERT_EQ(d.residualCheck->outliers.size(), 1u) << describe(d);
  const Outlier& o = d.residualCheck->outliers.front();
  ASSERT_TRUE(o.row.has_value());
  EXPECT_EQ(*o.row, 38);
  EXPECT_EQ(o.part.value_or(""), m.rows[37].part);
  EXPECT_EQ(o.dimension.value_or(""), model.dimensions[m.rows[37].dimension].id);
  EXPECT_NEAR(o.residual, 40.0 * kSigma, 8.0 * kSigma);
  EXPECT_TRUE(d.accepted().empty()) << describe(d);
  EXPECT_TRUE(d.residualCheck->white) << describe(d);
  const nlohmann::json j = toJson(d);
  ASSERT_TRUE(j.contains("residual_check"));
  EXPECT_EQ(j["residual_check"]["outliers"][0]["row"], 38);
}

// ---- kinematic ----------------------------------------------------------------------------------

MeasuredPath cleanCircle(std::uint64_t seed) {
  CircularSimOptions o;
  o.seed = seed;
  return simulateCircularTest(o);
}

TEST(OpenWorldKinematic, CleanCircularTestsAreWhite) {
  int flagged = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const Diagnosis d = diagnoseKinematic(cleanCircle(seed), {});
    ASSERT_TRUE(d.residualCheck.has_value());
    EXPECT_TRUE(d.accepted().empty()) << "seed " << seed << "\n" << describe(d);
    if (!d.residualCheck->white) ++flagged;
  }
  EXPECT_LE(flagged, 1);
}

TEST(OpenWorldKinematic, ThermalDriftDuringTheTestIsNotBacklash) {
  // The machine warms up during the test: the x position drifts linearly with time (row), by 8
  // noise sigmas over the two loops, and y by half of that.
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    MeasuredPath p = cleanCircle(seed);
    const double sigma = CircularSimOptions{}.noiseMm;
    const double n = static_cast<double>(p.size());
    for (std::size_t k = 0; k < p.size(); ++k) {
      p.measured[k].x() += 8.0 * sigma * k / n;
      p.measured[k].y() += 4.0 * sigma * k / n;
    }
    const Diagnosis d = diagnoseKinematic(p, {});
    EXPECT_FALSE(catalogueAccepted(d)) << "seed " << seed << "\n" << describe(d);
    EXPECT_TRUE(flaggedOrExplained(d)) << "seed " << seed << "\n" << describe(d);
  }
}

TEST(OpenWorldKinematic, AGrossPointIsAnOutlier) {
  MeasuredPath p = cleanCircle(2);
  p.measured[100].x() += 0.02;  // 40 sigma
  const Diagnosis d = diagnoseKinematic(p, {});
  ASSERT_TRUE(d.residualCheck.has_value());
  ASSERT_EQ(d.residualCheck->outliers.size(), 1u) << describe(d);
  EXPECT_EQ(d.residualCheck->outliers.front().row.value_or(0), 101);
  EXPECT_TRUE(d.accepted().empty()) << describe(d);
}

// ---- matching -----------------------------------------------------------------------------------

TEST(OpenWorldMatching, CleanBlocksAreWhite) {
  int flagged = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    ProbeSimOptions o;
    o.seed = seed;
    const Diagnosis d = diagnoseMatching(simulateProbing(o));
    ASSERT_TRUE(d.residualCheck.has_value());
    EXPECT_TRUE(d.accepted().empty()) << "seed " << seed << "\n" << describe(d);
    if (!d.residualCheck->white) ++flagged;
  }
  EXPECT_LE(flagged, 1);
}

TEST(OpenWorldMatching, AThinPartBendingUnderTheClampIsNotScaleOrOffset) {
  // The block sags between its clamps: a deviation along the normal that is quadratic in x
  // (largest in the middle), 10 noise sigmas at the middle.
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    ProbeSimOptions o;
    o.seed = seed;
    ProbePointSet s = simulateProbing(o);
    const double half = o.length / 2.0;
    for (ProbePoint& p : s.points) {
      const double u = (p.nominal.x() - half) / half;  // -1 .. 1 along the block
      p.measured += 10.0 * o.noiseMm * (1.0 - u * u) * p.normal;
    }
    const Diagnosis d = diagnoseMatching(s);
    EXPECT_FALSE(catalogueAccepted(d)) << "seed " << seed << "\n" << describe(d);
    EXPECT_TRUE(flaggedOrExplained(d)) << "seed " << seed << "\n" << describe(d);
  }
}

TEST(OpenWorldMatching, AGrossProbingErrorIsListedWithItsId) {
  ProbeSimOptions o;
  o.seed = 3;
  ProbePointSet s = simulateProbing(o);
  s.points[5].measured += 40.0 * o.noiseMm * s.points[5].normal;
  const Diagnosis d = diagnoseMatching(s);
  ASSERT_TRUE(d.residualCheck.has_value());
  ASSERT_EQ(d.residualCheck->outliers.size(), 1u) << describe(d);
  EXPECT_EQ(d.residualCheck->outliers.front().id.value_or(""), s.points[5].id);
  EXPECT_EQ(d.residualCheck->outliers.front().row.value_or(0), 6);
  EXPECT_TRUE(d.accepted().empty()) << describe(d);
}

// ---- thermal ------------------------------------------------------------------------------------

/// A clean simulated log (the declared static model T2, T4, T_amb is exact up to the noise).
ThermalLog cleanThermal(std::uint64_t seed) {
  ThermalEffectsOptions o;
  o.seed = seed;
  o.noiseUm = 0.25;
  return simulateThermalEffects(o);
}

ThermalDiagnosisOptions thermalOptions() {
  ThermalDiagnosisOptions o;
  o.target = "disp_z_um";
  o.inputs = {"T2", "T4", "T_amb"};
  return o;
}

std::vector<double>& target(ThermalLog& log) {
  for (auto& c : log.channels)
    if (c.name == "disp_z_um") return c.values;
  throw std::runtime_error("no target");
}

TEST(OpenWorldThermal, ACurvatureInADeclaredSensorIsNotALag) {
  // A quadratic dependence on the declared sensor T2 (a nonlinear expansion: no lag, no other input):
  // 15 um over the log's T2 range
  // (about the bench's quadratic_T2 at effect-to-noise 5; at 4 um a linear term of T3, which follows
  // T2 with a curvature, explains it as well as anything, and input:T3 is then a fair reading). The loop must
  // not call it lag, lag:T2 or input:<c>; it explains it as a function of a temperature (T2, or T1 that
  // follows T2) or flags it.
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    ThermalLog log = cleanThermal(seed);
    const std::vector<double>& t2 = log.channel("T2").values;
    double range = 0.0;
    for (double v : t2) range = std::max(range, std::abs(v - t2.front()));
    std::vector<double>& y = target(log);
    for (std::size_t k = 0; k < y.size(); ++k) y[k] += 15.0 * std::pow((t2[k] - t2.front()) / range, 2);
    const Diagnosis d = diagnoseThermal(log, thermalOptions());
    EXPECT_FALSE(catalogueAccepted(d)) << "seed " << seed << "\n" << describe(d);
    EXPECT_TRUE(flaggedOrExplained(d)) << "seed " << seed << "\n" << describe(d);
  }
}

TEST(OpenWorldThermal, ASensorReZeroedAfterTheFitRowsShowsInTheHeldOutCheckOnly) {
  // The target steps by 3 um at 80 % of the log (a probe re-zeroed): the fit rows (first half) cannot
  // see it and choose nothing for it; the held-out check finds a step in time there, and the choice
  // and the fit-row check are those of the log without the step.
  ThermalLog log = cleanThermal(4);
  const Diagnosis clean = diagnoseThermal(log, thermalOptions());
  std::vector<double>& y = target(log);
  const std::size_t at = y.size() * 8 / 10;
  for (std::size_t k = at; k < y.size(); ++k) y[k] += 3.0;
  const Diagnosis d = diagnoseThermal(log, thermalOptions());
  EXPECT_TRUE(d.accepted().empty()) << describe(d);
  ASSERT_TRUE(d.residualCheck && d.heldoutCheck);
  EXPECT_TRUE(d.residualCheck->white) << describe(d);
  EXPECT_EQ(d.residualCheck->summary, clean.residualCheck->summary);
  EXPECT_TRUE(clean.heldoutCheck->white) << describe(clean);
  EXPECT_FALSE(d.heldoutCheck->white) << describe(d);
  // A step in time (or row) among what the held-out residual depends on (a sensor that rises
  // steadily there, e.g. T3, shows the same step), at its place within 2 % of the log.
  const auto& st = d.heldoutCheck->structure;
  const auto s = std::find_if(st.begin(), st.end(), [](const StructureItem& x) {
    return (x.against == "time" || x.against == "row") && x.form == DependenceForm::Step;
  });
  ASSERT_NE(s, st.end()) << describe(d);
  ASSERT_FALSE(s->shape.knots.empty());
  const double pos = s->against == "time" ? s->shape.knots.front()
                                          : log.timeMin[static_cast<std::size_t>(s->shape.knots.front()) - 1];
  EXPECT_NEAR(pos, log.timeMin[at], 0.02 * (log.timeMin.back() - log.timeMin.front()));
  EXPECT_GT(*d.final.heldoutRmse, *clean.final.heldoutRmse + 1.0);
}

TEST(OpenWorldThermal, AGrossErrorInTheHeldOutRowsIsListedAndLeftOutOfTheHeldOutError) {
  ThermalLog log = cleanThermal(5);
  const Diagnosis clean = diagnoseThermal(log, thermalOptions());
  std::vector<double>& y = target(log);
  const std::size_t row = y.size() * 9 / 10;
  y[row] += 40.0 * 0.25;
  const Diagnosis d = diagnoseThermal(log, thermalOptions());
  ASSERT_TRUE(d.heldoutCheck.has_value());
  ASSERT_EQ(d.heldoutCheck->outliers.size(), 1u) << describe(d);
  EXPECT_EQ(d.heldoutCheck->outliers.front().row.value_or(0), static_cast<long>(row + 1));
  EXPECT_TRUE(d.residualCheck->outliers.empty());
  EXPECT_TRUE(d.accepted().empty()) << describe(d);
  // Without the row, the held-out rms of the same residual: the clean log's one less that row's part.
  // Computed here from the clean result: n * clean^2 = (n - 1) * without^2 + r_row^2, so the held-out
  // error with the gross error left out stays within 5 % of the clean log's.
  EXPECT_NEAR(*d.final.heldoutRmse, *clean.final.heldoutRmse, 0.05 * *clean.final.heldoutRmse);
  EXPECT_TRUE(d.heldoutCheck->white) << describe(d);
}

// ---- issue 32 item 5: the loop's two misses ------------------------------------------------------

// (b) A circular test whose X reading is 24 sigma off over ten consecutive points (a damaged stretch
// of the scale): more than 2 % of the 360 points, so the single-point outlier rule lists none of
// them; the block test must report them (not white, their rows listed).
TEST(OpenWorldDiagnosis, KinematicBlockOfTenPointsIsNotWhiteAndItsRowsAreReported) {
  CircularSimOptions c;
  c.pointsPerLoop = 180;
  c.seed = 3;
  MeasuredPath path = simulateCircularTest(c);
  const double sigma = c.noiseMm;
  for (std::size_t k = 40; k < 50; ++k) path.measured[k].x() += 24.0 * sigma;
  const Diagnosis d = diagnoseKinematic(path, KinematicDiagnosisOptions{});
  ASSERT_TRUE(d.residualCheck);
  const ResidualCheck& rc = *d.residualCheck;
  EXPECT_FALSE(rc.white) << describe(d);
  std::set<long> reported;
  for (const Outlier& o : rc.outliers) reported.insert(o.row.value_or(0));
  for (const ResidualBlock& b : rc.blocks) reported.insert(b.rows.begin(), b.rows.end());
  for (long row = 41; row <= 50; ++row)
    EXPECT_TRUE(reported.count(row)) << "row " << row << "\n" << describe(d);
  ASSERT_FALSE(rc.blocks.empty()) << describe(d);
  EXPECT_EQ(rc.blocks.front().rows.front(), 41);
  EXPECT_EQ(rc.blocks.front().rows.back(), 50);
  EXPECT_NE(rc.summary.find("10 consecutive observations in row order off the rest (rows 41 to 50"),
            std::string::npos)
      << rc.summary;
}

// (a) A worn spot of the X ball screw (a bump of the X error in x, open_world.h local_bump): the
// catalogue's nearest name, cyclic on x, passes in the first round, but the generic effect of x
// explains clearly more (dBIC -736 against -219, margin 10): the generic one is accepted there.
TEST(OpenWorldDiagnosis, KinematicNameIsNotTakenWhereAGenericOfItsVariableExplainsClearlyMore) {
  const OpenKinematicCase c = openWorldKinematic("local_bump", 5.0, 1);
  const Diagnosis d = diagnoseKinematic(c.path, KinematicDiagnosisOptions{});
  const Candidate* cyclic0 = nullptr;
  const Candidate* generic0 = nullptr;
  for (const Candidate& e : d.effects) {
    if (e.round != 0) continue;
    if (e.name == "cyclic") cyclic0 = &e;
    if (e.name == "unexplained:x") generic0 = &e;
  }
  ASSERT_TRUE(cyclic0 && generic0) << describe(d);
  EXPECT_FALSE(cyclic0->accepted) << describe(d);
  EXPECT_NE(cyclic0->evidence.find("not taken: the generic unexplained:x"), std::string::npos)
      << cyclic0->evidence;
  EXPECT_TRUE(generic0->accepted) << describe(d);
  EXPECT_LT(generic0->score, cyclic0->score - KinematicDiagnosisOptions{}.bicMargin);
}

// (a) Setup: a tool that runs in (1 - exp(-(p - 1) / p0)), open_world.h tool_runin: tool_wear and
// drift of that tool are linear in the part number / time and pass, but the generic effect of
// datum:<tool> explains clearly more, so it is accepted first and no name of that datum is. (Seed 1
// is left out: there names of other data, drift:W5 .. drift:W1, pass one per round on a sliver of the
// run-in before the generic effect; the rule is about names of the same variable.)
TEST(OpenWorldDiagnosis, SetupToolRunInIsTheGenericEffectNotToolWear) {
  const setup::Model model = paperModel();
  for (std::uint64_t seed = 2; seed <= 5; ++seed) {
    const OpenSetupCase c = openWorldSetup(model, "tool_runin", 5.0, seed);
    const Diagnosis d = diagnoseSetup(model, c.measurements);
    const std::string datum = c.truth.against.front().substr(6);  // datum:<tool>
    const std::vector<const Candidate*> acc = d.accepted();
    ASSERT_FALSE(acc.empty()) << describe(d);
    EXPECT_EQ(acc.front()->name, "unexplained:datum:" + datum) << describe(d);
    for (const Candidate* a : acc)
      EXPECT_TRUE(a->name != "tool_wear:" + datum && a->name != "drift:" + datum) << describe(d);
  }
}

}  // namespace
}  // namespace metrofit::diagnose
