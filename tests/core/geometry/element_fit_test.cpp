// Element fitting (core/geometry/element_fit.h) against closed forms written here: points generated
// exactly on known elements in known poses (then with seeded noise), minimum zones checked by
// exhaustive search over candidate contact sets, and the certificate. No published circle / sphere
// test set with certified answers was used (none is known to us with certainty); the real-data checks
// are in real_element_test.cpp.
#include "core/geometry/element_fit.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/common/error.h"
#include "core/common/rng.h"

namespace metrofit::geometry {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Two unit vectors perpendicular to n and to each other.
void basis(const Eigen::Vector3d& n, Eigen::Vector3d& e1, Eigen::Vector3d& e2) {
  const Eigen::Vector3d t = std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  e1 = (t - t.dot(n) * n).normalized();
  e2 = n.cross(e1);
}

double lineDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& c, const Eigen::Vector3d& u) {
  const Eigen::Vector3d w = p - c;
  return (w - w.dot(u) * u).norm();
}

/// |a - b| up to sign (axes are unsigned).
double axisError(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::min((a - b).norm(), (a + b).norm());
}

PointSet pts(std::vector<Eigen::Vector3d> p) {
  return PointSet{"test", std::move(p)};
}

ElementFitResult fit(const PointSet& s, ElementKind k, FitCriterion c = FitCriterion::LeastSquares,
                     double R = 0.0, bool robust = false) {
  ElementFitOptions o;
  o.element = k;
  o.criterion = c;
  o.fixedRadiusMm = R;
  o.robust = robust;
  return fitElement(s, o);
}

const Eigen::Vector3d kAxis = Eigen::Vector3d(0.3, -0.4, 0.866).normalized();
const Eigen::Vector3d kCentre(12.0, -7.5, 30.25);

/// Points on a sphere, polar angle up to thetaMax from kAxis, with optional noise along the radius.
std::vector<Eigen::Vector3d> spherePoints(double R, double thetaMaxDeg, int rings, int perRing, double sigma,
                                          std::uint64_t seed) {
  Rng rng(seed);
  Eigen::Vector3d e1, e2;
  basis(kAxis, e1, e2);
  std::vector<Eigen::Vector3d> p;
  p.push_back(kCentre + (R + sigma * rng.normal()) * kAxis);
  for (int r = 1; r <= rings; ++r) {
    const double th = thetaMaxDeg * kPi / 180.0 * r / rings;
    for (int k = 0; k < perRing; ++k) {
      const double ph = 2.0 * kPi * (k + 0.37 * r) / perRing;
      const Eigen::Vector3d u = std::cos(th) * kAxis + std::sin(th) * (std::cos(ph) * e1 + std::sin(ph) * e2);
      p.push_back(kCentre + (R + sigma * rng.normal()) * u);
    }
  }
  return p;
}

TEST(ElementFit, PlaneClosedForm) {
  Eigen::Vector3d e1, e2;
  basis(kAxis, e1, e2);
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 4; ++j) p.push_back(kCentre + (i * 10.0 - 20.0) * e1 + (j * 7.0 - 10.0) * e2);
  const ElementFitResult r = fit(pts(p), ElementKind::Plane);
  EXPECT_LT(axisError(r.element.axis, kAxis), 1e-12);
  EXPECT_NEAR(r.element.axis.dot(r.element.centre - kCentre), 0.0, 1e-10);
  EXPECT_LT(r.formMm, 1e-10);
  EXPECT_TRUE(r.wellConditioned) << r.condition;
  EXPECT_NEAR(r.element.axis.cwiseAbs().maxCoeff(), r.element.axis.maxCoeff(), 0.0);  // largest component > 0
}

TEST(ElementFit, LineClosedFormWithNoise) {
  Rng rng(7);
  Eigen::Vector3d e1, e2;
  basis(kAxis, e1, e2);
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < 30; ++i)
    p.push_back(kCentre + (i * 3.0 - 40.0) * kAxis + 0.002 * rng.normal() * e1 + 0.002 * rng.normal() * e2);
  const ElementFitResult r = fit(pts(p), ElementKind::Line);
  EXPECT_LT(axisError(r.element.axis, kAxis), 1e-4);
  EXPECT_LT(lineDistance(r.element.centre, kCentre, kAxis), 2e-3);
  for (double d : r.residualsMm) EXPECT_GE(d, 0.0);
  EXPECT_NEAR(r.formMm, 2.0 * *std::max_element(r.residualsMm.begin(), r.residualsMm.end()), 1e-15);
}

TEST(ElementFit, CircleIn3dPlaneClosedForm) {
  Eigen::Vector3d e1, e2;
  basis(kAxis, e1, e2);
  std::vector<Eigen::Vector3d> p;
  for (int k = 0; k < 9; ++k) {
    const double ph = 2.0 * kPi * k / 9.0 + 0.1;
    p.push_back(kCentre + 25.0 * (std::cos(ph) * e1 + std::sin(ph) * e2));
  }
  const ElementFitResult r = fit(pts(p), ElementKind::Circle);
  EXPECT_LT((r.element.centre - kCentre).norm(), 1e-9);
  EXPECT_NEAR(r.element.radiusMm, 25.0, 1e-9);
  EXPECT_LT(axisError(r.element.axis, kAxis), 1e-12);
  EXPECT_NEAR(r.coverageDeg, 360.0 - 40.0, 1e-6);
  EXPECT_TRUE(r.wellConditioned) << r.condition;
  // Fixed radius: the same centre.
  const ElementFitResult f = fit(pts(p), ElementKind::Circle, FitCriterion::LeastSquares, 25.0);
  EXPECT_LT((f.element.centre - kCentre).norm(), 1e-9);
}

TEST(ElementFit, SphereClosedFormAndNoise) {
  const auto exact = spherePoints(12.5, 120.0, 4, 8, 0.0, 1);
  const ElementFitResult r = fit(pts(exact), ElementKind::Sphere);
  EXPECT_LT((r.element.centre - kCentre).norm(), 1e-9);
  EXPECT_NEAR(r.element.radiusMm, 12.5, 1e-9);
  EXPECT_LT(r.rmseMm, 1e-10);
  EXPECT_TRUE(r.wellConditioned) << r.condition;

  // Noise 1 um: the estimate is within 4 standard errors of the truth, the errors are of the expected size.
  const auto noisy = spherePoints(12.5, 120.0, 6, 12, 0.001, 2);
  const ElementFitResult n = fit(pts(noisy), ElementKind::Sphere);
  ASSERT_EQ(n.standardErrors.size(), 4u);
  EXPECT_EQ(n.standardErrors[3].name, "radius_mm");
  for (int i = 0; i < 3; ++i)
    EXPECT_LT(std::abs(n.element.centre(i) - kCentre(i)), 4.0 * n.standardErrors[i].value);
  EXPECT_LT(std::abs(n.element.radiusMm - 12.5), 4.0 * n.standardErrors[3].value);
  EXPECT_NEAR(n.rmseMm, 0.001, 0.0003);
  EXPECT_EQ(n.residualsMm.size(), noisy.size());
  for (std::size_t i = 0; i < noisy.size(); ++i)
    EXPECT_NEAR(n.residualsMm[i], (noisy[i] - n.element.centre).norm() - n.element.radiusMm, 1e-12);
}

TEST(ElementFit, CylinderClosedForm) {
  Eigen::Vector3d e1, e2;
  basis(kAxis, e1, e2);
  for (double length : {80.0, 6.0}) {  // long (axis = largest spread) and a short ring (axis = smallest)
    std::vector<Eigen::Vector3d> p;
    for (int ring = 0; ring < 3; ++ring)
      for (int k = 0; k < 8; ++k) {
        const double ph = 2.0 * kPi * k / 8.0 + 0.2 * ring;
        p.push_back(kCentre + (ring * length / 2.0 - length / 2.0) * kAxis +
                    20.0 * (std::cos(ph) * e1 + std::sin(ph) * e2));
      }
    const ElementFitResult r = fit(pts(p), ElementKind::Cylinder);
    EXPECT_LT(axisError(r.element.axis, kAxis), 1e-9) << length;
    EXPECT_LT(lineDistance(r.element.centre, kCentre, kAxis), 1e-8) << length;
    EXPECT_NEAR(r.element.radiusMm, 20.0, 1e-8) << length;
    const ElementFitResult f = fit(pts(p), ElementKind::Cylinder, FitCriterion::LeastSquares, 20.0);
    EXPECT_LT(axisError(f.element.axis, kAxis), 1e-9) << length;
    EXPECT_LT(f.rmseMm, 1e-9) << length;
  }
}

TEST(ElementFit, ConeClosedForm) {
  Eigen::Vector3d e1, e2;
  basis(kAxis, e1, e2);
  const double alpha = 20.0 * kPi / 180.0;
  const Eigen::Vector3d apex = kCentre - 50.0 * kAxis;  // opening along +kAxis
  std::vector<Eigen::Vector3d> p;
  for (int ring = 0; ring < 4; ++ring) {
    const double h = 30.0 + 10.0 * ring;
    for (int k = 0; k < 7; ++k) {
      const double ph = 2.0 * kPi * k / 7.0 + 0.3 * ring;
      p.push_back(apex + h * kAxis + h * std::tan(alpha) * (std::cos(ph) * e1 + std::sin(ph) * e2));
    }
  }
  const ElementFitResult r = fit(pts(p), ElementKind::Cone);
  EXPECT_LT((r.element.axis - kAxis).norm(), 1e-8);  // towards the opening
  EXPECT_NEAR(r.element.halfAngleRad, alpha, 1e-9);
  EXPECT_LT((r.element.apex - apex).norm(), 1e-7);
  EXPECT_LT(lineDistance(r.element.centre, apex, kAxis), 1e-8);
  EXPECT_NEAR(r.element.radiusMm, (r.element.centre - apex).dot(kAxis) * std::tan(alpha), 1e-8);
  EXPECT_LT(r.rmseMm, 1e-9);
}

TEST(ElementFit, FixedRadiusSphereCap) {
  // A 30 deg cap with 5 um noise: the fixed radius gives the centre the free fit cannot.
  const auto cap = spherePoints(50.0, 30.0, 5, 10, 0.005, 3);
  const ElementFitResult fixed = fit(pts(cap), ElementKind::Sphere, FitCriterion::LeastSquares, 50.0);
  const ElementFitResult free = fit(pts(cap), ElementKind::Sphere);
  EXPECT_EQ(fixed.element.radiusMm, 50.0);
  EXPECT_LT((fixed.element.centre - kCentre).norm(), 0.01);
  std::printf("[ measured ] 30 deg cap, fixed radius: %s\n[ measured ] 30 deg cap, free radius: %s\n",
              fixed.condition.c_str(), free.condition.c_str());
  EXPECT_LT(fixed.noiseAmplification, kBadConditionAmplification) << fixed.condition;
  EXPECT_FALSE(free.wellConditioned) << free.condition;
  EXPECT_EQ(free.condition.rfind("badly conditioned", 0), 0u) << free.condition;
  EXPECT_NEAR(free.coverageDeg, 30.0, 0.5);
  EXPECT_GT(free.noiseAmplification, kBadConditionAmplification);
  EXPECT_EQ(fixed.standardErrors.size(), 3u);  // centre only
}

TEST(ElementFit, ConditionGrowsAsTheCapShrinks) {
  double previous = 0.0;
  for (double cap : {180.0, 120.0, 90.0, 60.0, 30.0, 10.0}) {
    const ElementFitResult r = fit(pts(spherePoints(25.0, cap, 6, 12, 0.001, 11)), ElementKind::Sphere);
    std::printf("[ measured ] sphere cap half angle %.0f deg: noise amplification %.3g, %s\n", cap,
                r.noiseAmplification, r.condition.c_str());
    EXPECT_GT(r.noiseAmplification, previous);
    EXPECT_EQ(r.wellConditioned, cap >= 90.0) << r.condition;
    EXPECT_EQ(r.condition.rfind("badly conditioned", 0) == 0, cap <= 30.0) << r.condition;
    EXPECT_NEAR(r.coverageDeg, cap, 1.0);
    previous = r.noiseAmplification;
  }
}

TEST(ElementFit, RobustExcludesStrayPointsByTheMadRule) {
  auto p = spherePoints(20.0, 150.0, 5, 12, 0.002, 4);
  std::vector<std::size_t> stray = {3, 17, 30, 44};
  for (std::size_t i : stray) p[i] += 0.5 * (p[i] - kCentre).normalized();
  p[50] += -0.3 * (p[50] - kCentre).normalized();
  stray.push_back(50);
  const ElementFitResult r = fit(pts(p), ElementKind::Sphere, FitCriterion::LeastSquares, 0.0, true);
  // Every stray point is excluded, and the rule as stated holds for every point: excluded exactly when
  // |d - median| > k 1.4826 MAD (median and MAD of the kept points; a good point in the noise's tail
  // may be excluded too: at k = 3.5 about 1 in 2000 Gaussian points).
  for (std::size_t i : stray) EXPECT_TRUE(std::binary_search(r.excluded.begin(), r.excluded.end(), i)) << i;
  EXPECT_LE(r.excluded.size(), stray.size() + 1);
  std::vector<double> kept;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!std::binary_search(r.excluded.begin(), r.excluded.end(), i)) kept.push_back(r.residualsMm[i]);
  auto med = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
  };
  const double m = med(kept);
  std::vector<double> dev;
  for (double v : kept) dev.push_back(std::abs(v - m));
  const double limit = 3.5 * 1.4826 * med(dev);
  EXPECT_NEAR(r.robustThresholdMm, limit, 1e-6);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool out = std::binary_search(r.excluded.begin(), r.excluded.end(), i);
    if (std::abs(std::abs(r.residualsMm[i] - m) - limit) > 1e-6)
      EXPECT_EQ(out, std::abs(r.residualsMm[i] - m) > limit)
          << "point " << i << " residual " << r.residualsMm[i];
  }
  EXPECT_LT((r.element.centre - kCentre).norm(), 0.003);
  EXPECT_NEAR(r.element.radiusMm, 20.0, 0.003);
  EXPECT_GT(r.robustThresholdMm, 0.0);
  EXPECT_LT(r.robustThresholdMm, 0.02);
  EXPECT_NEAR(r.residualsMm[3], 0.5, 0.01);  // excluded points keep a residual
  // Exact data: nothing below 1 nm is excluded.
  const ElementFitResult e = fit(pts(spherePoints(20.0, 150.0, 3, 8, 0.0, 5)), ElementKind::Sphere,
                                 FitCriterion::LeastSquares, 0.0, true);
  EXPECT_TRUE(e.excluded.empty());
}

TEST(ElementFit, RobustCircleTakesItsPlaneFromTheKeptPoints) {
  Eigen::Vector3d e1, e2;
  basis(kAxis, e1, e2);
  Rng rng(12);
  std::vector<Eigen::Vector3d> p;
  for (int k = 0; k < 24; ++k) {
    const double ph = 2.0 * kPi * k / 24.0;
    p.push_back(kCentre + (25.0 + 0.001 * rng.normal()) * (std::cos(ph) * e1 + std::sin(ph) * e2) +
                0.001 * rng.normal() * kAxis);
  }
  p[5] += 3.0 * kAxis;  // a stray point well off the circle's plane and radius
  p[5] += 1.0 * (p[5] - kCentre).normalized();
  const ElementFitResult r = fit(pts(p), ElementKind::Circle, FitCriterion::LeastSquares, 0.0, true);
  EXPECT_EQ(r.excluded, std::vector<std::size_t>{5});
  EXPECT_LT(axisError(r.element.axis, kAxis), 2e-4);
  EXPECT_LT((r.element.centre - kCentre).norm(), 0.002);
}

// ---- minimum zone ----------------------------------------------------------------------------

/// Minimum width of a slab holding the points: the optimum is a facet-vertex or an edge-edge contact
/// (of the convex hull), so the smallest width over every triple's normal and every pair of pairs'
/// cross product is the exact minimum zone (flatness).
double bruteFlatness(const std::vector<Eigen::Vector3d>& p) {
  const std::size_t n = p.size();
  double best = std::numeric_limits<double>::infinity();
  auto width = [&](Eigen::Vector3d nrm) {
    if (nrm.norm() < 1e-12) return;
    nrm.normalize();
    double lo = 1e300, hi = -1e300;
    for (const auto& q : p) {
      lo = std::min(lo, nrm.dot(q));
      hi = std::max(hi, nrm.dot(q));
    }
    best = std::min(best, hi - lo);
  };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) width((p[j] - p[i]).cross(p[k] - p[i]));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = 0; k < n; ++k)
        for (std::size_t l = k + 1; l < n; ++l) width((p[j] - p[i]).cross(p[l] - p[k]));
  return best;
}

/// Minimum-zone circle of planar points (z = 0): the optimal centre is equidistant from two outer and
/// two inner contacts, or the circumcentre of three; the smallest zone over every such candidate centre.
double bruteRoundness(const std::vector<Eigen::Vector3d>& p) {
  const std::size_t n = p.size();
  double best = std::numeric_limits<double>::infinity();
  auto zone = [&](const Eigen::Vector2d& c) {
    if (!c.allFinite()) return;
    double lo = 1e300, hi = -1e300;
    for (const auto& q : p) {
      const double d = (q.head<2>() - c).norm();
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
    best = std::min(best, hi - lo);
  };
  // Points equidistant from a and b: (b - a).c = (|b|^2 - |a|^2) / 2.
  auto bisector = [&](std::size_t a, std::size_t b, Eigen::Vector2d& row, double& rhs) {
    const Eigen::Vector2d A = p[a].head<2>(), B = p[b].head<2>();
    row = B - A;
    rhs = 0.5 * (B.squaredNorm() - A.squaredNorm());
  };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = 0; k < n; ++k)
        for (std::size_t l = k + 1; l < n; ++l) {
          if (i == k && j == l) continue;
          Eigen::Matrix2d M;
          Eigen::Vector2d r1, r2, rhs;
          bisector(i, j, r1, rhs(0));
          bisector(k, l, r2, rhs(1));
          M.row(0) = r1;
          M.row(1) = r2;
          if (std::abs(M.determinant()) < 1e-12) continue;
          zone(M.partialPivLu().solve(rhs));  // covers the 3-point circumcentres too (shared point)
        }
  return best;
}

TEST(MinimumZone, PlaneAgreesWithExhaustiveSearchAndIsCertified) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    Rng rng(seed);
    Eigen::Vector3d e1, e2;
    basis(kAxis, e1, e2);
    std::vector<Eigen::Vector3d> p;
    const int n = 5 + static_cast<int>(seed % 4);  // 5..8 points
    for (int i = 0; i < n; ++i)
      p.push_back(kCentre + rng.uniform(-30, 30) * e1 + rng.uniform(-30, 30) * e2 +
                  rng.uniform(-0.01, 0.01) * kAxis);
    const ElementFitResult ls = fit(pts(p), ElementKind::Plane);
    const ElementFitResult mz = fit(pts(p), ElementKind::Plane, FitCriterion::Minimax);
    const double brute = bruteFlatness(p);
    EXPECT_NEAR(mz.formMm, brute, 1e-9) << "seed " << seed;
    EXPECT_LE(mz.formMm, ls.formMm + 1e-12) << "seed " << seed;
    ASSERT_TRUE(mz.certificate.has_value());
    EXPECT_TRUE(mz.certificate->holds) << mz.certificate->meaning << " stat " << mz.certificate->stationarity
                                       << " pred " << mz.certificate->predictedDecreaseMm;
    EXPECT_GE(mz.certificate->contacts.size(), 4u);  // 3 parameters: at least 4 contacts
    EXPECT_NEAR(mz.certificate->multiplierSum, 1.0, 1e-9);
    for (const auto& c : mz.certificate->contacts)
      EXPECT_NEAR(std::abs(mz.residualsMm[c.index]), mz.formMm / 2.0, 1e-9) << "contact on the zone boundary";
  }
}

TEST(MinimumZone, CircleAgreesWithExhaustiveSearchAndIsCertified) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    Rng rng(seed + 10);
    std::vector<Eigen::Vector3d> p;
    const int n = 5 + static_cast<int>(seed % 4);
    for (int i = 0; i < n; ++i) {
      const double ph = 2.0 * kPi * (i + rng.uniform(-0.3, 0.3)) / n;
      const double r = 30.0 + rng.uniform(-0.02, 0.02);
      p.emplace_back(4.0 + r * std::cos(ph), -3.0 + r * std::sin(ph), 0.0);
    }
    const ElementFitResult ls = fit(pts(p), ElementKind::Circle);
    const ElementFitResult mz = fit(pts(p), ElementKind::Circle, FitCriterion::Minimax);
    const double brute = bruteRoundness(p);
    EXPECT_NEAR(mz.formMm, brute, 1e-9) << "seed " << seed;
    EXPECT_LE(mz.formMm, ls.formMm + 1e-12);
    ASSERT_TRUE(mz.certificate.has_value());
    EXPECT_TRUE(mz.certificate->holds) << mz.certificate->meaning;
    EXPECT_GE(mz.certificate->contacts.size(), 4u);
  }
}

TEST(MinimumZone, NeverWiderThanLeastSquaresAndCertifiedForEveryElement) {
  Rng rng(99);
  Eigen::Vector3d e1, e2;
  basis(kAxis, e1, e2);
  std::vector<Eigen::Vector3d> sphere = spherePoints(15.0, 140.0, 4, 9, 0.003, 6), cyl, cone, line;
  for (int i = 0; i < 40; ++i) {
    const double ph = 2.0 * kPi * i / 13.0, h = -30.0 + 1.5 * i;
    cyl.push_back(kCentre + h * kAxis +
                  (10.0 + rng.uniform(-0.005, 0.005)) * (std::cos(ph) * e1 + std::sin(ph) * e2));
    const double hc = 20.0 + i;
    cone.push_back(kCentre + hc * kAxis +
                   (hc * 0.3 + rng.uniform(-0.005, 0.005)) * (std::cos(ph) * e1 + std::sin(ph) * e2));
    line.push_back(kCentre + h * kAxis + rng.uniform(-0.01, 0.01) * e1 + rng.uniform(-0.01, 0.01) * e2);
  }
  const std::vector<std::pair<ElementKind, std::vector<Eigen::Vector3d>>> cases = {
      {ElementKind::Sphere, sphere},
      {ElementKind::Cylinder, cyl},
      {ElementKind::Cone, cone},
      {ElementKind::Line, line}};
  for (const auto& [kind, p] : cases) {
    const ElementFitResult ls = fit(pts(p), kind);
    const ElementFitResult mz = fit(pts(p), kind, FitCriterion::Minimax);
    EXPECT_LE(mz.formMm, ls.formMm + 1e-12) << toString(kind);
    EXPECT_LT(mz.formMm, ls.formMm) << toString(kind);
    ASSERT_TRUE(mz.certificate.has_value());
    EXPECT_TRUE(mz.certificate->holds)
        << toString(kind) << ": " << mz.certificate->meaning << " stat " << mz.certificate->stationarity
        << " pred " << mz.certificate->predictedDecreaseMm;
  }
  // Fixed radius: the largest |deviation| (what is minimised) is never above the least-squares one.
  const ElementFitResult ls = fit(pts(sphere), ElementKind::Sphere, FitCriterion::LeastSquares, 15.0);
  const ElementFitResult mz = fit(pts(sphere), ElementKind::Sphere, FitCriterion::Minimax, 15.0);
  EXPECT_LE(mz.maxAbsMm, ls.maxAbsMm + 1e-12);
  EXPECT_TRUE(mz.certificate->holds);
}

TEST(ElementFit, BadInputIsNamed) {
  const auto p = spherePoints(10.0, 90.0, 1, 2, 0.0, 1);  // 3 points
  try {
    fit(pts(p), ElementKind::Sphere);
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("test"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("at least 4 points, got 3"), std::string::npos) << e.what();
  }
  EXPECT_THROW(fit(pts(p), ElementKind::Plane, FitCriterion::LeastSquares, 5.0), OptionsError);
  // Collinear points determine no circle.
  std::vector<Eigen::Vector3d> col;
  for (int i = 0; i < 6; ++i) col.emplace_back(i, 2.0 * i, 0.0);
  EXPECT_THROW(fit(pts(col), ElementKind::Circle), ValidationError);
  auto bad = spherePoints(10.0, 90.0, 2, 4, 0.0, 1);
  bad[2].x() = std::nan("");
  EXPECT_THROW(fit(pts(bad), ElementKind::Sphere), ValidationError);
}

TEST(ElementFit, ObserverSeesIterationsAndCanStop) {
  const auto p = spherePoints(12.0, 100.0, 4, 8, 0.01, 8);
  long seen = 0;
  FunctionObserver count([&](const IterationSummary&) {
    ++seen;
    return ObserverDecision::Continue;
  });
  ElementFitOptions o;
  o.criterion = FitCriterion::Minimax;
  const ElementFitResult r = fitElement(pts(p), o, &count);
  EXPECT_GT(seen, 2);
  EXPECT_EQ(r.run.iterations, seen);
  FunctionObserver stop([](const IterationSummary&) { return ObserverDecision::Stop; });
  const ElementFitResult s = fitElement(pts(p), o, &stop);
  EXPECT_EQ(s.run.termination, Termination::Cancelled);
  EXPECT_TRUE(s.element.centre.allFinite());
  for (double d : s.residualsMm) EXPECT_TRUE(std::isfinite(d));
}

}  // namespace
}  // namespace metrofit::geometry
