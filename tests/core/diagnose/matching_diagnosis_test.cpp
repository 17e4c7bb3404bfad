// The matching closed loop (core/diagnose/matching_diagnosis.h) on point sets from
// core/sim/effects_matching.h.
#include "core/diagnose/matching_diagnosis.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/error.h"
#include "core/common/rng.h"
#include "core/sim/effects_matching.h"
#include "testsupport.h"

namespace metrofit::diagnose {
namespace {

constexpr double kPlateNoise = 0.006;  // per axis, like the SDSS plates
constexpr double kPlateRadius = 300.0;

HolePlateSimOptions plate(std::uint64_t seed) {
  HolePlateSimOptions o;
  o.holes = 400;
  o.radiusMm = kPlateRadius;
  o.noiseMm = kPlateNoise;
  o.seed = seed;
  return o;
}

/// ppm whose largest displacement on the plate is `ratio` noise sigmas.
double ppmAtRatio(double ratio) {
  return ratio * kPlateNoise / (kPlateRadius * 1e-6);
}

std::string describe(const Diagnosis& d) {
  std::string s;
  for (const Candidate& c : d.effects) s += c.name + (c.accepted ? " [accepted] " : " ") + c.evidence + "\n";
  return s;
}

double param(const Candidate& c, const std::string& name) {
  for (const Parameter& p : c.parameters)
    if (p.name == name) return std::get<double>(p.value);
  ADD_FAILURE() << "no parameter " << name;
  return 0.0;
}

const Candidate* find(const Diagnosis& d, const std::string& name) {
  for (const Candidate& c : d.effects)
    if (c.name == name) return &c;
  return nullptr;
}

TEST(MatchingDiagnosis, FindsScaleOnAPlanarHolePlate) {
  MatchingEffects e;
  e.scalePpm = ppmAtRatio(5.0);
  const Diagnosis d = diagnoseMatching(simulateHolePlate(plate(2), e));
  ASSERT_EQ(d.accepted().size(), 1u) << describe(d);
  const Candidate& c = *d.accepted().front();
  EXPECT_EQ(c.name, "scale");
  EXPECT_NEAR(param(c, "ppm"), e.scalePpm, 0.3 * e.scalePpm);
  EXPECT_NEAR(d.final.rmse, kPlateNoise * std::sqrt(2.0), 0.15 * kPlateNoise);
  EXPECT_EQ(d.domain, "matching");
  // Position-only data: no surface offsets, scale and distortion only.
  EXPECT_EQ(d.effects.size(), 2u);
  ASSERT_TRUE(c.plot);
  EXPECT_EQ(c.plot->x.size(), 400u);
}

TEST(MatchingDiagnosis, FindsTheFourLobedDistortion) {
  MatchingEffects e;
  e.distortionPpm = ppmAtRatio(5.0);
  e.distortionAngleDeg = 30.0;
  const Diagnosis d = diagnoseMatching(simulateHolePlate(plate(3), e));
  ASSERT_EQ(d.accepted().size(), 1u) << describe(d);
  const Candidate& c = *d.accepted().front();
  EXPECT_EQ(c.name, "distortion");
  EXPECT_NEAR(param(c, "ppm"), e.distortionPpm, 0.3 * e.distortionPpm);
  EXPECT_NEAR(param(c, "angle_deg"), 30.0, 5.0);
  ASSERT_TRUE(c.plot);
  EXPECT_EQ(c.plot->vectors.size(), 400u);
  EXPECT_EQ(c.plot->vectors.front().size(), 4u);
  // The angle is defined modulo 180 deg and reported in (-90, 90].
  e.distortionAngleDeg = 120.0;
  const Diagnosis d2 = diagnoseMatching(simulateHolePlate(plate(4), e));
  ASSERT_EQ(d2.accepted().size(), 1u) << describe(d2);
  EXPECT_NEAR(param(*d2.accepted().front(), "angle_deg"), -60.0, 5.0);
}

TEST(MatchingDiagnosis, FindsScaleAndDistortionBoth) {
  MatchingEffects e;
  e.scalePpm = ppmAtRatio(6.0);
  e.distortionPpm = ppmAtRatio(6.0);
  e.distortionAngleDeg = -20.0;
  HolePlateSimOptions o = plate(5);
  o.rotationDeg = 2.0;  // a large posture error does not matter
  const Diagnosis d = diagnoseMatching(simulateHolePlate(o, e));
  ASSERT_EQ(d.accepted().size(), 2u) << describe(d);
  const Candidate* s = find(d, "scale");
  const Candidate* t = find(d, "distortion");
  ASSERT_TRUE(s && t);
  EXPECT_TRUE(s->accepted && t->accepted);
  EXPECT_NEAR(param(*s, "ppm"), e.scalePpm, 0.3 * e.scalePpm);
  EXPECT_NEAR(param(*t, "ppm"), e.distortionPpm, 0.3 * e.distortionPpm);
  EXPECT_NEAR(param(*t, "angle_deg"), -20.0, 5.0);
}

TEST(MatchingDiagnosis, CleanPlatesAndPartsStayClean) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const Diagnosis d = diagnoseMatching(simulateHolePlate(plate(seed), {}));
    EXPECT_TRUE(d.accepted().empty()) << "plate seed " << seed << "\n" << describe(d);
    ProbeSimOptions s = ProbeSimOptions::sPieceDefaults();
    s.seed = seed;
    const Diagnosis ds = diagnoseMatching(simulateProbing(s));
    EXPECT_TRUE(ds.accepted().empty()) << "s-piece seed " << seed << "\n" << describe(ds);
    ProbeSimOptions b;
    b.seed = seed;
    const Diagnosis db = diagnoseMatching(simulateProbing(b));
    EXPECT_TRUE(db.accepted().empty()) << "block seed " << seed << "\n" << describe(db);
  }
}

TEST(MatchingDiagnosis, FindsASurfaceOffsetAlongTheNormals) {
  ProbeSimOptions s = ProbeSimOptions::sPieceDefaults();
  s.seed = 7;
  MatchingEffects e;
  e.surfaceOffsetsMm = {{"ruled+", 5.0 * s.noiseMm}};
  const Diagnosis d = diagnoseMatching(simulateProbingWithEffects(s, e), {});
  ASSERT_EQ(d.accepted().size(), 1u) << describe(d);
  const Candidate& c = *d.accepted().front();
  EXPECT_EQ(c.name, "surface_offset:ruled+");
  EXPECT_NEAR(param(c, "mm"), 5.0 * s.noiseMm, 0.3 * 5.0 * s.noiseMm);
  ASSERT_TRUE(c.plot);
  EXPECT_EQ(c.plot->categories.size(), 5u);
  // Candidates: scale, one offset per surface (5), distortion.
  EXPECT_EQ(d.effects.size(), 7u);
}

TEST(MatchingDiagnosis, AnOffsetOfASinglePlaneIsNotIdentifiable) {
  // The block's top face is its only surface whose normal has a z component: its offset is a z
  // translation of the posture.
  MatchingEffects e;
  e.surfaceOffsetsMm = {{"top", 0.05}};
  const Diagnosis d = diagnoseMatching(simulateProbingWithEffects(ProbeSimOptions{}, e));
  EXPECT_TRUE(d.accepted().empty()) << describe(d);
  const Candidate* c = find(d, "surface_offset:top");
  ASSERT_TRUE(c);
  EXPECT_FALSE(c->accepted);
  EXPECT_NE(c->evidence.find("not identifiable"), std::string::npos) << c->evidence;
}

TEST(MatchingDiagnosis, PositionOnly3dPointsUseTheWholeResidual) {
  // The block's points without normals, with isotropic noise: three observations per point.
  ProbeSimOptions b;
  b.noiseMm = 0.0;
  MatchingEffects e;
  e.scalePpm = 50.0;
  for (const bool withEffect : {false, true}) {
    ProbePointSet set = simulateProbingWithEffects(b, withEffect ? e : MatchingEffects{});
    set.hasNormals = false;
    Rng rng(3);
    for (ProbePoint& p : set.points) {
      p.normal = Eigen::Vector3d::Zero();
      for (int k = 0; k < 3; ++k) p.measured(k) += rng.normal(0.0, 0.001);
    }
    const Diagnosis d = diagnoseMatching(set);
    EXPECT_EQ(d.effects.size(), 2u);  // scale, distortion
    if (!withEffect) {
      EXPECT_TRUE(d.accepted().empty()) << describe(d);
      EXPECT_NEAR(d.baseline.rmse, 0.001 * std::sqrt(3.0), 0.0005);
    } else {
      ASSERT_EQ(d.accepted().size(), 1u) << describe(d);
      EXPECT_EQ(d.accepted().front()->name, "scale");
      EXPECT_NEAR(param(*d.accepted().front(), "ppm"), 50.0, 15.0);
    }
  }
}

TEST(MatchingDiagnosis, BadInputs) {
  ProbePointSet two = simulateHolePlate(plate(1), {});
  two.points.resize(1);
  EXPECT_THROW(diagnoseMatching(two), ValidationError);
  MatchingDiagnosisOptions bad;
  bad.toleranceMm = 0.0;
  EXPECT_THROW(diagnoseMatching(simulateHolePlate(plate(1), {}), bad), OptionsError);
  MatchingEffects e;
  e.surfaceOffsetsMm = {{"nowhere", 0.01}};
  EXPECT_THROW(simulateProbingWithEffects(ProbeSimOptions{}, e), OptionsError);
  EXPECT_THROW(simulateHolePlate(plate(1), e), OptionsError);  // no normals
  HolePlateSimOptions p = plate(1);
  p.holes = 2;
  EXPECT_THROW(simulateHolePlate(p, {}), OptionsError);
}

TEST(MatchingDiagnosis, JsonAndDeterminism) {
  MatchingEffects e;
  e.distortionPpm = 80.0;
  e.distortionAngleDeg = 10.0;
  const ProbePointSet a = simulateHolePlate(plate(8), e), b = simulateHolePlate(plate(8), e);
  ASSERT_EQ(a.points.size(), b.points.size());
  EXPECT_EQ(a.points[17].measured, b.points[17].measured);
  const nlohmann::json j = toJson(diagnoseMatching(a));
  EXPECT_EQ(j["domain"], "matching");
  EXPECT_EQ(j["effects"][0]["name"], "distortion");
  EXPECT_TRUE(j["effects"][0]["parameters"].contains("ppm"));
  EXPECT_TRUE(j["effects"][0]["parameters"].contains("angle_deg"));
  EXPECT_TRUE(j["effects"][0]["uncertainty"].contains("angle_deg"));
}

/// The demo's probe data with one undeclared effect (resources/demo/README.md): the S-piece with the
/// paper-like posture error (ProbeSimOptions::sPieceDefaults, noise 0.006 mm), probed 4 K warm:
/// aluminium, 23.1 ppm/K, scale 92.4 ppm; seed 7. METROFIT_WRITE_DEMO=1 rewrites the file.
TEST(MatchingDiagnosis, DemoProbeDataIsTheDocumentedSimulationOfAWarmPart) {
  ProbeSimOptions s = ProbeSimOptions::sPieceDefaults();
  s.seed = 7;
  MatchingEffects e;
  e.scalePpm = 4.0 * 23.1;
  ProbePointSet set = simulateProbingWithEffects(s, e);
  const std::string text = probePointsToCsv(set);
  const std::string path = (test::sourceDir() / "resources/demo/data/diagnose_probe.csv").string();
  if (test::env("METROFIT_WRITE_DEMO") == "1") test::writeText(path, text);
  EXPECT_EQ(test::readText(path), text);
  const Diagnosis d = diagnoseMatching(readProbePoints(path), {});
  ASSERT_EQ(d.accepted().size(), 1u) << describe(d);
  EXPECT_EQ(d.accepted().front()->name, "scale");
  EXPECT_NEAR(param(*d.accepted().front(), "ppm"), 92.4, 0.3 * 92.4);
}

}  // namespace
}  // namespace metrofit::diagnose
