// Posture matching against a CAD nominal (core/matching/cad_match.h). Analytic surfaces are written as
// STL by the test (../geometry/mesh_fixtures.h), points are sampled on the *analytic* surfaces, moved
// by a known posture and given seeded noise along the normal; the recovered posture must equal the
// known one within a bound computed here from the tessellation's chord error and the noise.
//
// The bound (first order): with J the Jacobian of the point-to-plane deviations at the true posture,
// rows -[(s_i x n_i)^T, n_i^T] over the free parameters (rotation about the CAD origin in rad,
// translation in mm), a deviation delta_i of point i from the mesh moves the least-squares posture by
// M delta, M = (J^T J)^-1 J^T. The vertices lie on the analytic surface, so a point of the convex
// surface lies outside its facet by 0 <= delta_i <= e_i (the chord error), i.e. delta_i = e_i/2 + eta_i
// with |eta_i| <= e_i/2, and |(M delta)_j| <= |sum_i M_ji e_i/2| + sum_i |M_ji| e_i/2; noise of sigma
// along the normal adds at most 5 sigma |M_j|_2 (5 standard deviations). The tests allow 1.2 times that
// (second-order terms: the facet normals' tilt, the small-angle map of the ZYX angles).
#include "core/matching/cad_match.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <nlohmann/json.hpp>

#include "../geometry/mesh_fixtures.h"
#include "core/common/error.h"
#include "core/common/rng.h"
#include "core/geometry/stl.h"
#include "core/io/csv.h"
#include "testsupport.h"

namespace metrofit::matching {
namespace {

using geometry::MeshSearch;

/// A point of an analytic surface with its outward normal and the chord error of its tessellation.
struct Sample {
  Eigen::Vector3d s, n;
  double e = 0.0;
};

void sphereSamples(std::vector<Sample>& out, const Eigen::Vector3d& c, double R, int n, double e) {
  const double golden = test::kMeshPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z);
    const Eigen::Vector3d d(r * std::cos(golden * i), r * std::sin(golden * i), z);
    out.push_back({c + R * d, d, e});
  }
}

/// Points of the lateral surface, heights in [h0, h1] along the axis.
void cylinderSamples(std::vector<Sample>& out, const Eigen::Vector3d& base, const Eigen::Vector3d& axis,
                     double R, double h0, double h1, int nAround, int nAlong, double e) {
  const Eigen::Vector3d u = axis.normalized();
  const Eigen::Vector3d t = std::abs(u.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = (t - t.dot(u) * u).normalized(), e2 = u.cross(e1);
  for (int i = 0; i < nAround; ++i) {
    for (int k = 0; k < nAlong; ++k) {
      const double ph = 2.0 * test::kMeshPi * (i + 0.37 * k) / nAround;
      const double h = h0 + (h1 - h0) * (k + 0.5) / nAlong;
      const Eigen::Vector3d d = std::cos(ph) * e1 + std::sin(ph) * e2;
      out.push_back({base + h * u + R * d, d, e});
    }
  }
}

/// Measured points: the posture applied to the samples moved by sigma * N(0, 1) along their normals.
ProbePointSet measure(const std::vector<Sample>& samples, const Pose& truth, double sigma, std::uint64_t seed,
                      std::vector<double>* noise = nullptr) {
  Rng rng(seed);
  ProbePointSet set;
  set.source = "points.csv";
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double z = sigma * rng.normal();
    if (noise) noise->push_back(z);
    ProbePoint p;
    p.id = "P" + std::to_string(i + 1);
    p.measured = truth.apply(samples[i].s + z * samples[i].n);
    set.points.push_back(p);
  }
  return set;
}

/// Per parameter (rx, ry, rz in rad; x, y, z in mm) the bound of the header; locked ones 0.
std::array<double, 6> poseBounds(const std::vector<Sample>& samples, const DofLocks& locks, double sigma) {
  std::vector<int> free;
  for (int j = 0; j < 6; ++j)
    if (!locks.locked[j]) free.push_back(j);
  Eigen::MatrixXd J(static_cast<Eigen::Index>(samples.size()), static_cast<Eigen::Index>(free.size()));
  for (std::size_t i = 0; i < samples.size(); ++i) {
    Eigen::Matrix<double, 6, 1> row;
    row << samples[i].s.cross(samples[i].n), samples[i].n;
    for (std::size_t c = 0; c < free.size(); ++c)
      J(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(c)) = -row(free[c]);
  }
  const Eigen::MatrixXd M = (J.transpose() * J).ldlt().solve(J.transpose());
  std::array<double, 6> b{};
  for (std::size_t c = 0; c < free.size(); ++c) {
    double sum = 0.0, abs = 0.0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const double m = M(static_cast<Eigen::Index>(c), static_cast<Eigen::Index>(i));
      sum += m * samples[i].e / 2.0;
      abs += std::abs(m) * samples[i].e / 2.0;
    }
    b[static_cast<std::size_t>(free[c])] =
        1.2 * (std::abs(sum) + abs + 5.0 * sigma * M.row(static_cast<Eigen::Index>(c)).norm());
  }
  return b;
}

/// Recovered vs true posture within the bounds; locked parameters exactly at 0.
void expectPose(const Pose& got, const Pose& truth, const std::array<double, 6>& bound,
                const DofLocks& locks) {
  const Eigen::Vector3d ga = got.anglesDeg() * kRadPerDeg, ta = truth.anglesDeg() * kRadPerDeg;
  for (int j = 0; j < 6; ++j) {
    const double g = j < 3 ? ga(j) : got.translation(j - 3), t = j < 3 ? ta(j) : truth.translation(j - 3);
    if (locks.locked[j]) {
      EXPECT_EQ(g, 0.0) << dofName(j) << " is locked";
    } else {
      EXPECT_LE(std::abs(g - t), bound[static_cast<std::size_t>(j)])
          << dofName(j) << ": recovered " << g << ", true " << t << (j < 3 ? " rad" : " mm");
    }
  }
}

const Pose kTruth = Pose::fromAnglesDeg({0.4, -0.3, 0.6}, {0.3, -0.2, 0.15});
constexpr double kSigma = 0.001;

/// A part with a sphere, a cylinder (axis y) and a plane: together they fix all six parameters.
struct Part {
  std::vector<test::Facet> facets;
  std::vector<Sample> samples;
};

Part compositePart(double floatError) {
  Part p;
  const Eigen::Vector3d sc(30, 0, 20), cb(-30, -20, 20);
  const auto sphere = test::sphereFacets(sc, 10.0, 144, 72);
  const double es = test::sphereChordError(sphere, 10.0) + floatError;
  const double ec = test::cylinderChordError(10.0, 256) + floatError;
  p.facets = sphere;
  for (const auto& f : test::cylinderFacets(cb, {0, 1, 0}, 10.0, 40.0, 256, 2)) p.facets.push_back(f);
  for (const auto& f : test::planeFacets(-60, 60, -60, 60, 0.0, 1, 1)) p.facets.push_back(f);
  sphereSamples(p.samples, sc, 10.0, 200, es);
  cylinderSamples(p.samples, cb, {0, 1, 0}, 10.0, 8.0, 32.0, 25, 6, ec);
  for (int i = 0; i < 11; ++i) {
    for (int k = 0; k < 11; ++k) {
      const double x = -55.0 + 11.0 * i, y = -55.0 + 11.0 * k;
      if (std::abs(x - 30) < 15 && std::abs(y) < 15) continue;  // under the sphere
      if (std::abs(x + 30) < 15 && std::abs(y) < 25) continue;  // under the cylinder
      p.samples.push_back({{x, y, 0.0}, Eigen::Vector3d::UnitZ(), floatError});
    }
  }
  return p;
}

TEST(CadMatch, CompositePartRecoversTheKnownPosture) {
  test::TempDir tmp;
  // Binary STL (float32: |coordinates| <= 60 mm move by < 4e-6 mm) read from a file.
  const Part part = compositePart(4e-6);
  test::writeText(tmp.file("part.stl"), test::binaryStl(part.facets));
  const MeshSearch cad(geometry::readStl(tmp.file("part.stl")));
  std::vector<double> noise;
  const ProbePointSet points = measure(part.samples, kTruth, kSigma, 42, &noise);
  CadMatchOptions o;
  const CadMatchResult r = matchToCad(points, cad, o);
  EXPECT_EQ(r.match.run.termination, Termination::Converged) << r.match.run.message;
  EXPECT_LT(r.match.run.iterations, 20);
  const auto bound = poseBounds(part.samples, DofLocks{}, kSigma);
  for (double b : bound) EXPECT_LT(b, 0.01);  // the bound is tight enough to mean something
  expectPose(r.match.pose, kTruth, bound, DofLocks{});
  // Before: the posture error itself (about 0.6 mm at 60 mm); after: noise plus chord error.
  EXPECT_GT(r.match.before.overall.maxAbsMm, 0.3);
  EXPECT_LT(r.match.after.overall.maxAbsMm, 5 * kSigma + 2 * test::sphereChordError(part.facets, 10.0));
  // Per point: the signed deviation is the noise plus the point's chord deviation (0..e), up to the
  // small posture error.
  for (std::size_t i = 0; i < part.samples.size(); ++i) {
    const double d = r.match.after.deviations[i];
    EXPECT_GE(d - noise[i], -2e-3) << i;
    EXPECT_LE(d - noise[i], part.samples[i].e + 2e-3) << i;
  }
  EXPECT_EQ(r.triangles, part.facets.size());
  EXPECT_NEAR(r.maxDistanceMm, r.match.after.overall.maxAbsMm, 1e-12);
}

TEST(CadMatch, AsciiAndBinaryAgree) {
  const Part part = compositePart(0.0);
  const ProbePointSet points = measure(part.samples, kTruth, kSigma, 1);
  const MeshSearch ascii(geometry::parseStl(test::asciiStl(part.facets), "a.stl"));
  const MeshSearch binary(geometry::parseStl(test::binaryStl(part.facets), "b.stl"));
  const CadMatchResult a = matchToCad(points, ascii, {}), b = matchToCad(points, binary, {});
  expectPose(a.match.pose, kTruth, poseBounds(part.samples, DofLocks{}, kSigma), DofLocks{});
  EXPECT_LE((a.match.pose.translation - b.match.pose.translation).norm(), 2e-5);
  EXPECT_LE((a.match.pose.anglesDeg() - b.match.pose.anglesDeg()).norm(), 1e-5);
}

TEST(CadMatch, SphereWithRotationsLocked) {
  const Eigen::Vector3d c(5, -3, 8);
  const auto facets = test::sphereFacets(c, 10.0, 144, 72);
  std::vector<Sample> samples;
  sphereSamples(samples, c, 10.0, 300, test::sphereChordError(facets, 10.0));
  const Pose truth = Pose::fromAnglesDeg({0, 0, 0}, {0.2, -0.1, 0.3});
  const ProbePointSet points = measure(samples, truth, kSigma, 7);
  CadMatchOptions o;
  o.locks = DofLocks::parse("rx,ry,rz", "--lock");
  const CadMatchResult r =
      matchToCad(points, MeshSearch(geometry::parseStl(test::asciiStl(facets), "s.stl")), o);
  EXPECT_EQ(r.match.run.termination, Termination::Converged) << r.match.run.message;
  const auto bound = poseBounds(samples, o.locks, kSigma);
  expectPose(r.match.pose, truth, bound, o.locks);
  EXPECT_EQ(r.match.pose.rotation, Eigen::Matrix3d::Identity());
}

TEST(CadMatch, CylinderWithAxialFreedomsLocked) {
  // A cylinder along z cannot fix rz (about its axis) or z (along it): both locked.
  const auto facets = test::cylinderFacets({0, 0, -20}, {0, 0, 1}, 12.0, 40.0, 256, 4);
  std::vector<Sample> samples;
  cylinderSamples(samples, {0, 0, -20}, {0, 0, 1}, 12.0, 5.0, 35.0, 30, 8,
                  test::cylinderChordError(12.0, 256));
  const Pose truth = Pose::fromAnglesDeg({0.3, -0.2, 0.0}, {0.1, -0.25, 0.0});
  const ProbePointSet points = measure(samples, truth, kSigma, 8);
  CadMatchOptions o;
  o.locks = DofLocks::parse("rz,z", "--lock");
  const CadMatchResult r =
      matchToCad(points, MeshSearch(geometry::parseStl(test::asciiStl(facets), "c.stl")), o);
  EXPECT_EQ(r.match.run.termination, Termination::Converged) << r.match.run.message;
  expectPose(r.match.pose, truth, poseBounds(samples, o.locks, kSigma), o.locks);
  EXPECT_EQ(r.match.pose.translation.z(), 0.0);
}

TEST(CadMatch, PlaneNeedsItsInPlaneFreedomsLocked) {
  const auto facets = test::planeFacets(-50, 50, -50, 50, 0.0, 4, 4);
  std::vector<Sample> samples;
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 8; ++k)
      samples.push_back({{-40.0 + 11.0 * i, -38.0 + 10.5 * k, 0.0}, {0, 0, 1}, 0.0});
  const Pose truth = Pose::fromAnglesDeg({0.2, 0.1, 0.0}, {0.0, 0.0, 0.05});
  const ProbePointSet points = measure(samples, truth, kSigma, 9);
  const MeshSearch cad(geometry::parseStl(test::asciiStl(facets), "plane.stl"));
  // Unlocked: x, y, rz are not determined by one plane, and the error says so, naming the data file.
  try {
    matchToCad(points, cad, {});
    ADD_FAILURE() << "no ValidationError";
  } catch (const ValidationError& e) {
    EXPECT_EQ(e.context().file, "points.csv");
    EXPECT_NE(std::string(e.what()).find("least-squares fit to the CAD surface"), std::string::npos)
        << e.what();
  }
  CadMatchOptions o;
  o.locks = DofLocks::parse("rz,x,y", "--lock");
  const CadMatchResult r = matchToCad(points, cad, o);
  EXPECT_EQ(r.match.run.termination, Termination::Converged) << r.match.run.message;
  // The plane is exact (no chord error): noise only.
  expectPose(r.match.pose, truth, poseBounds(samples, o.locks, kSigma), o.locks);
}

TEST(CadMatch, MinimaxLowersTheLargestDeviation) {
  const Part part = compositePart(0.0);
  const ProbePointSet points = measure(part.samples, kTruth, kSigma, 3);
  const MeshSearch cad(geometry::parseStl(test::binaryStl(part.facets), "b.stl"));
  CadMatchOptions o;
  const CadMatchResult ls = matchToCad(points, cad, o);
  o.method = MatchMethod::Minimax;
  const CadMatchResult mm = matchToCad(points, cad, o);
  EXPECT_NE(mm.match.run.termination, Termination::Failed) << mm.match.run.message;
  EXPECT_LE(mm.match.after.overall.maxAbsMm, ls.match.after.overall.maxAbsMm + 1e-9);
  ASSERT_TRUE(mm.match.minimax.has_value());
  // Still the true posture within the same kind of bound (a minimax fit moves by at most the zone).
  expectPose(mm.match.pose, kTruth, poseBounds(part.samples, DofLocks{}, 5 * kSigma), DofLocks{});
}

TEST(CadMatch, DeterministicTraceAndCancellation) {
  const Part part = compositePart(0.0);
  const ProbePointSet points = measure(part.samples, kTruth, kSigma, 4);
  const MeshSearch cad(geometry::parseStl(test::binaryStl(part.facets), "b.stl"));
  const CadMatchResult a = matchToCad(points, cad, {}), b = matchToCad(points, cad, {});
  ASSERT_EQ(a.match.run.trace.size(), b.match.run.trace.size());
  ASSERT_GE(a.match.run.trace.size(), 2u);
  for (std::size_t i = 0; i < a.match.run.trace.size(); ++i) {
    EXPECT_EQ(a.match.run.trace[i].best, b.match.run.trace[i].best);
    EXPECT_EQ(a.match.run.trace[i].bestX, b.match.run.trace[i].bestX);
  }
  // The trace decreases to the end (the loop converges).
  EXPECT_LT(a.match.run.trace.back().best, a.match.run.trace.front().best);
  // An observer stops after the second iteration: Cancelled, two iterations, the posture of then.
  int calls = 0;
  FunctionObserver stop([&](const IterationSummary& s) {
    ++calls;
    return s.iteration == 1 ? ObserverDecision::Stop : ObserverDecision::Continue;
  });
  const CadMatchResult c = matchToCad(points, cad, {}, &stop);
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(c.match.run.termination, Termination::Cancelled);
  EXPECT_EQ(c.match.run.iterations, 2);
  EXPECT_EQ(c.match.run.trace[1].bestX, a.match.run.trace[1].bestX);
}

TEST(CadMatch, JsonHasTheMatchKeysPerPointAndCad) {
  const Part part = compositePart(0.0);
  const ProbePointSet points = measure(part.samples, kTruth, kSigma, 5);
  const MeshSearch cad(geometry::parseStl(test::binaryStl(part.facets), "part.stl"));
  const CadMatchResult r = matchToCad(points, cad, {});
  const nlohmann::json j = toJson(r);
  for (const char* key : {"method", "rotation_deg", "translation_mm", "rmse_mm", "max_abs_mm",
                          "out_of_tolerance", "per_point", "cad", "trace", "termination"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["method"], "closed-form");
  EXPECT_EQ(j["cad"]["file"], "part.stl");
  EXPECT_EQ(j["cad"]["triangles"], part.facets.size());
  EXPECT_EQ(j["cad"]["max_distance_mm"].get<double>(), r.maxDistanceMm);
  EXPECT_EQ(j["cad"]["winding_disagreements"], 0);
  ASSERT_EQ(j["per_point"].size(), points.points.size());
  const auto& p0 = j["per_point"][0];
  EXPECT_EQ(p0["id"], "P1");
  for (const char* key : {"d_mm", "dx_mm", "dy_mm", "dz_mm"}) EXPECT_TRUE(p0.contains(key)) << key;
  // d is the signed distance: |d| = |(dx, dy, dz)| (the residual lies along the surface normal).
  for (const auto& p : j["per_point"]) {
    const Eigen::Vector3d dv(p["dx_mm"].get<double>(), p["dy_mm"].get<double>(), p["dz_mm"].get<double>());
    EXPECT_NEAR(std::abs(p["d_mm"].get<double>()), dv.norm(), 1e-12);
  }
  EXPECT_NEAR(j["rotation_deg"][2].get<double>(), 0.6, 0.01);
}

TEST(CadMatch, RefusesPointPairMethodsAndBadOptions) {
  const MeshSearch cad(geometry::parseStl(test::asciiStl(test::planeFacets(0, 1, 0, 1, 0, 1, 1)), "p.stl"));
  ProbePointSet points;
  points.source = "p.csv";
  points.points.resize(3);
  CadMatchOptions o;
  o.method = MatchMethod::Sade;
  EXPECT_THROW(matchToCad(points, cad, o), OptionsError);
  o.method = MatchMethod::ClosedForm;
  o.convergenceMm = 0.0;
  EXPECT_THROW(matchToCad(points, cad, o), OptionsError);
}

TEST(CadMatch, MeasuredPointsCsv) {
  const ProbePointSet a = measuredPointsFromCsv(parseCsv("id,px,py,pz\nA,1,2,3\nB,4,5,6\n", "a.csv"));
  ASSERT_EQ(a.points.size(), 2u);
  EXPECT_EQ(a.points[1].id, "B");
  EXPECT_EQ(a.points[1].measured, Eigen::Vector3d(4, 5, 6));
  const ProbePointSet b = measuredPointsFromCsv(parseCsv("x_mm,y_mm,z_mm\n1,2,3\n", "b.csv"));
  EXPECT_EQ(b.points[0].id, "1");
  try {
    measuredPointsFromCsv(parseCsv("id,a,b,c\n1,2,3,4\n", "c.csv"));
    ADD_FAILURE() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_EQ(std::string(e.what()),
              "c.csv:1: measured points need the columns px,py,pz, x_mm,y_mm,z_mm or x,y,z");
  }
  EXPECT_THROW(measuredPointsFromCsv(parseCsv("id,px,py,pz\nA,1,2,3\nA,4,5,6\n", "d.csv")), InputError);
  EXPECT_THROW(measuredPointsFromCsv(parseCsv("id,px,py,pz\nA,1,x,3\n", "e.csv")), InputError);
  EXPECT_THROW(measuredPointsFromCsv(parseCsv("id,px,py\nA,1,2\n", "f.csv")), InputError);
}

}  // namespace
}  // namespace metrofit::matching
