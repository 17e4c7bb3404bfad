// ISO 230-4 results of circular tests (core/kinematics/iso230_4.h) against closed forms: an offset circle
// with a 3-lobe form error (G = 2A about the LSQ centre, F = +-e about the nominal centre), an ellipse
// (G = a - b), two loops a radial distance h apart (H = h); the LSQ circle against an independent Kasa fit
// solved here with Eigen's normal equations; the radial-only (ballbar) form written here from
// docs/file-formats.md#circular-test, with and without its nominal radius, and its errors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include <Eigen/Dense>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/kinematics/iso230_4.h"
#include "core/kinematics/measured_path.h"

namespace metrofit {
namespace {

constexpr double kPi = std::numbers::pi;

Eigen::Vector2d unit(double deg) {
  return {std::cos(deg * kPi / 180.0), std::sin(deg * kPi / 180.0)};
}

/// One loop CCW (0, 1, ..., 359 deg), then one CW (360 - k deg): commands on the nominal circle of radius R
/// about the origin; the measured point at command angle theta is measured(theta, ccw).
template <class F>
MeasuredPath twoLoops(double r, const F& measured, double cwOffsetDeg = 0.0) {
  MeasuredPath p;
  p.source = "loops.csv";
  for (int k = 0; k < 360; ++k) {
    p.command.push_back(r * unit(k));
    p.measured.push_back(measured(static_cast<double>(k), true));
  }
  for (int k = 0; k < 360; ++k) {
    const double th = 360.0 - k - cwOffsetDeg;
    p.command.push_back(r * unit(th));
    p.measured.push_back(measured(th, false));
  }
  return p;
}

TEST(Iso230_4, OffsetCircleWithLobesGivesGFromTheAnalyticRadiusRange) {
  // The measured path: radius R + A cos(3 theta) about c0. The LSQ centre and radius are c0 and R (the
  // residuals A cos 3 theta are orthogonal to 1, cos theta, sin theta over the full circle), so about the
  // LSQ centre the radius ranges from R - A (theta = 60) to R + A (theta = 0): G = 2A.
  const double r = 100.0, amp = 0.004;
  const Eigen::Vector2d c0(0.02, -0.015);
  const MeasuredPath path = twoLoops(r, [&](double th, bool) -> Eigen::Vector2d {
    return c0 + (r + amp * std::cos(3.0 * th * kPi / 180.0)) * unit(th);
  });
  const Iso230Result iso = evaluateIso230_4(circularTraceOf(path));
  ASSERT_EQ(iso.directions.size(), 2u);
  for (const Iso230Direction& d : iso.directions) {
    EXPECT_EQ(d.points, 360u);
    EXPECT_NEAR(d.circularDeviationMm, 2.0 * amp, 1e-9);
    EXPECT_NEAR(d.lsqCentreMm.x(), c0.x(), 1e-9);
    EXPECT_NEAR(d.lsqCentreMm.y(), c0.y(), 1e-9);
    ASSERT_TRUE(d.lsqRadiusMm);
    EXPECT_NEAR(*d.lsqRadiusMm, r, 1e-9);
  }
  EXPECT_TRUE(iso.directions[0].counterClockwise);
  EXPECT_FALSE(iso.directions[1].counterClockwise);
  ASSERT_TRUE(iso.circularHysteresisMm);
  EXPECT_NEAR(*iso.circularHysteresisMm, 0.0, 1e-9);
  EXPECT_NEAR(iso.nominalCentreMm.norm(), 0.0, 1e-12);
  ASSERT_TRUE(iso.nominalRadiusMm);
  EXPECT_NEAR(*iso.nominalRadiusMm, r, 1e-12);
}

TEST(Iso230_4, PureOffsetCircleHasNoCircularDeviationAndFOfTheOffset) {
  // A circle of the nominal radius about c0 = (e, 0): about the nominal centre its radius runs from R - e
  // (theta = 180) to R + e (theta = 0): F max = +e, F min = -e; about its own LSQ centre G = 0.
  const double r = 80.0, e = 0.025;
  const MeasuredPath path =
      twoLoops(r, [&](double th, bool) -> Eigen::Vector2d { return Eigen::Vector2d(e, 0.0) + r * unit(th); });
  const Iso230Result iso = evaluateIso230_4(circularTraceOf(path));
  ASSERT_EQ(iso.directions.size(), 2u);
  for (const Iso230Direction& d : iso.directions) {
    EXPECT_NEAR(d.radialDeviationMaxMm, e, 1e-12);
    EXPECT_NEAR(d.radialDeviationMinMm, -e, 1e-12);
    EXPECT_NEAR(d.circularDeviationMm, 0.0, 1e-9);
    EXPECT_NEAR(d.lsqCentreMm.x(), e, 1e-9);
    EXPECT_NEAR(d.lsqRadiusDeviationMm, 0.0, 1e-9);
  }
}

TEST(Iso230_4, EllipseGivesTheDifferenceOfItsSemiAxes) {
  // x = a cos t, y = b sin t: |p| runs from b (t = 90) to a (t = 0); the LSQ centre is the ellipse's centre
  // by symmetry, so G = a - b.
  const double a = 100.012, b = 99.995;
  const MeasuredPath path = twoLoops(100.0, [&](double th, bool) -> Eigen::Vector2d {
    return {a * std::cos(th * kPi / 180.0), b * std::sin(th * kPi / 180.0)};
  });
  const Iso230Result iso = evaluateIso230_4(circularTraceOf(path));
  ASSERT_EQ(iso.directions.size(), 2u);
  for (const Iso230Direction& d : iso.directions) {
    EXPECT_NEAR(d.circularDeviationMm, a - b, 1e-9);
    EXPECT_NEAR(d.lsqCentreMm.norm(), 0.0, 1e-9);
    EXPECT_NEAR(d.radialDeviationMaxMm, a - 100.0, 1e-9);
    EXPECT_NEAR(d.radialDeviationMinMm, b - 100.0, 1e-9);
  }
}

TEST(Iso230_4, LoopsRadiallyApartByHGiveHysteresisH) {
  const double r = 100.0, amp = 0.003, h = 0.0025;
  auto path = [&](double th, bool ccw) -> Eigen::Vector2d {
    return (r + amp * std::cos(3.0 * th * kPi / 180.0) + (ccw ? 0.0 : h)) * unit(th);
  };
  const Iso230Result same = evaluateIso230_4(circularTraceOf(twoLoops(r, path)));
  ASSERT_TRUE(same.circularHysteresisMm);
  EXPECT_NEAR(*same.circularHysteresisMm, h, 1e-9);
  EXPECT_NEAR(same.hysteresisCentreMm.norm(), 0.0, 1e-9);
  // Each loop alone keeps its form: G = 2A.
  for (const Iso230Direction& d : same.directions) EXPECT_NEAR(d.circularDeviationMm, 2.0 * amp, 1e-9);

  // The CW loop sampled half a degree off the CCW angles: the CCW radius is interpolated linearly, whose
  // error is at most A (3 dtheta)^2 / 8 for the 3-lobe form (dtheta = 1 deg in rad).
  const Iso230Result off = evaluateIso230_4(circularTraceOf(twoLoops(r, path, 0.5)));
  ASSERT_TRUE(off.circularHysteresisMm);
  const double bound = amp * std::pow(3.0 * kPi / 180.0, 2) / 8.0;
  EXPECT_NEAR(*off.circularHysteresisMm, h, bound);
  EXPECT_GT(bound, 1e-7);  // the bound is the interpolation's, not a tolerance for nothing
}

TEST(Iso230_4, HysteresisIsNotInterpolatedAcrossAPartialArcsGap) {
  // CCW: a full loop of radius R + A cos 3t; CW: only the half 180 -> 0 deg, h further out. Where both
  // exist the difference is h; interpolating the CW arc across its 180 deg gap would compare the CCW
  // radius at 240 deg (R + A) with the mean of the CW ends (R + h), a difference |A - h| = 2 um here.
  const double r = 100.0, amp = 0.003, h = 0.001;
  MeasuredPath p;
  p.source = "arc.csv";
  for (int k = 0; k < 360; ++k) {
    p.command.push_back(r * unit(k));
    p.measured.push_back((r + amp * std::cos(3.0 * k * kPi / 180.0)) * unit(k));
  }
  for (int k = 180; k >= 0; --k) {
    p.command.push_back(r * unit(k));
    p.measured.push_back((r + amp * std::cos(3.0 * k * kPi / 180.0) + h) * unit(k));
  }
  const Iso230Result iso = evaluateIso230_4(circularTraceOf(p));
  ASSERT_EQ(iso.directions.size(), 2u);
  ASSERT_TRUE(iso.circularHysteresisMm);
  // One LSQ centre of both: the half arc pulls it off the origin, but at the same angle both radii move
  // alike (to first order), so the difference stays h.
  EXPECT_NEAR(*iso.circularHysteresisMm, h, 1e-6);
}

TEST(Iso230_4, OneDirectionHasNoHysteresis) {
  MeasuredPath p;
  p.source = "ccw.csv";
  for (int k = 0; k < 90; ++k) {
    p.command.push_back(50.0 * unit(4.0 * k));
    p.measured.push_back((50.0 + 0.001 * std::sin(8.0 * k * kPi / 180.0)) * unit(4.0 * k));
  }
  const Iso230Result iso = evaluateIso230_4(circularTraceOf(p));
  ASSERT_EQ(iso.directions.size(), 1u);
  EXPECT_TRUE(iso.directions[0].counterClockwise);
  EXPECT_FALSE(iso.circularHysteresisMm);
  EXPECT_EQ(iso.direction(false), nullptr);
}

TEST(Iso230_4, LsqCircleAgreesWithAnIndependentKasaFit) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.002);
  std::uniform_real_distribution<double> angle(0.0, 360.0);
  const Eigen::Vector2d c0(3.0, -2.0);
  const double r0 = 50.0;
  std::vector<Eigen::Vector2d> pts;
  for (int k = 0; k < 400; ++k) pts.push_back(c0 + (r0 + noise(rng)) * unit(angle(rng)));

  // Kasa: x^2 + y^2 + D x + E y + F = 0, normal equations solved with LDLT (uncentred data).
  Eigen::MatrixXd a(static_cast<Eigen::Index>(pts.size()), 3);
  Eigen::VectorXd b(static_cast<Eigen::Index>(pts.size()));
  for (Eigen::Index k = 0; k < a.rows(); ++k) {
    const Eigen::Vector2d& p = pts[static_cast<std::size_t>(k)];
    a.row(k) << p.x(), p.y(), 1.0;
    b(k) = -p.squaredNorm();
  }
  const Eigen::Vector3d x = (a.transpose() * a).ldlt().solve(a.transpose() * b);
  const Eigen::Vector2d kasaCentre(-x(0) / 2.0, -x(1) / 2.0);
  const double kasaRadius = std::sqrt(kasaCentre.squaredNorm() - x(2));

  const LsqCircle fit = fitLsqCircle(pts, "pts");
  // The geometric and the algebraic fit differ by O(noise^2 / R) = 1e-7 mm here.
  EXPECT_NEAR(fit.centreMm.x(), kasaCentre.x(), 1e-6);
  EXPECT_NEAR(fit.centreMm.y(), kasaCentre.y(), 1e-6);
  EXPECT_NEAR(fit.radiusMm, kasaRadius, 1e-6);
  EXPECT_NEAR(fit.rmsMm, 0.002, 0.0003);
  // Ours minimises the sum of squared radial residuals: no worse than Kasa's circle by that measure.
  double kasaSum = 0.0, ourSum = 0.0;
  for (const auto& p : pts) {
    kasaSum += std::pow((p - kasaCentre).norm() - kasaRadius, 2);
    ourSum += std::pow((p - fit.centreMm).norm() - fit.radiusMm, 2);
  }
  EXPECT_LE(ourSum, kasaSum * (1.0 + 1e-12));

  EXPECT_THROW(fitLsqCircle({{0, 0}, {1, 1}, {2, 2}, {3, 3}}, "line"), ValidationError);
  EXPECT_THROW(fitLsqCircle({{0, 0}, {1, 1}}, "two"), ValidationError);
}

/// A ballbar export as docs/file-formats.md#circular-test describes it: one CCW then one CW run of 360
/// points, deviation in micrometres, of a machine whose path is an offset circle with a 3-lobe form.
std::string ballbarCsv(bool withRadius, bool withDirection, const std::string& unitColumn = "deviation_um") {
  const double r = 100.0, amp = 0.002, h = 0.0015;
  const Eigen::Vector2d c0(0.005, -0.003);
  std::string text = "angle_deg," + unitColumn + (withDirection ? ",direction,run" : "") +
                     (withRadius ? ",radius_mm" : "") + "\n";
  const double scale = unitColumn == "deviation_um" ? 1000.0 : 1.0;
  for (int loop = 0; loop < 2; ++loop) {
    for (int k = 0; k < 360; ++k) {
      const double th = loop == 0 ? k : 360.0 - k;
      // The point at angle th about the pivot has radius R + d; for the small offset and form the radial
      // deviation about the pivot is to first order c0 . u + A cos 3th (+ h on the CW run), written exactly:
      const Eigen::Vector2d p =
          c0 + (r + amp * std::cos(3.0 * th * kPi / 180.0) + (loop ? h : 0.0)) * unit(th);
      const double angleAbout = std::atan2(p.y(), p.x()) * 180.0 / kPi;
      text += CsvWriter::formatNumber(angleAbout) + "," + CsvWriter::formatNumber((p.norm() - r) * scale);
      if (withDirection) text += loop == 0 ? ",CCW,1" : ",CW,2";
      if (withRadius) text += ",100";
      text += "\n";
    }
  }
  return text;
}

TEST(Iso230_4, RadialFormWithItsRadiusGivesTheClosedForms) {
  const CircularTrace t = circularTraceFromCsv(parseCsv(ballbarCsv(true, true), "ballbar.csv"));
  EXPECT_TRUE(t.radialOnly);
  ASSERT_EQ(t.size(), 720u);
  ASSERT_TRUE(t.nominalRadiusMm);
  EXPECT_EQ(*t.nominalRadiusMm, 100.0);
  EXPECT_EQ(t.run.front(), 1);
  EXPECT_EQ(t.run.back(), 2);
  const Iso230Result iso = evaluateIso230_4(t);
  ASSERT_EQ(iso.directions.size(), 2u);
  EXPECT_FALSE(iso.linearised);
  for (const Iso230Direction& d : iso.directions) {
    EXPECT_NEAR(d.circularDeviationMm, 0.004, 1e-9);  // G = 2A; both runs keep the 3-lobe form
    EXPECT_NEAR(d.lsqCentreMm.x(), 0.005, 1e-9);
    EXPECT_NEAR(d.lsqCentreMm.y(), -0.003, 1e-9);
  }
  EXPECT_NEAR(iso.direction(false)->lsqRadiusDeviationMm, 0.0015, 1e-9);
  ASSERT_TRUE(iso.circularHysteresisMm);
  EXPECT_NEAR(*iso.circularHysteresisMm, 0.0015, 1e-9);  // H = h
}

TEST(Iso230_4, RadialFormWithoutRadiusUsesTheLinearisedCircle) {
  // Without a nominal radius the LSQ circle is the limacon fit, exact to O(e^2 / R) ~ 1e-7 mm here; the
  // directions come from the angles (no direction column).
  const CircularTrace t = circularTraceFromCsv(parseCsv(ballbarCsv(false, false, "deviation_mm"), "b.csv"));
  EXPECT_FALSE(t.nominalRadiusMm);
  EXPECT_TRUE(t.counterClockwise.front());
  EXPECT_FALSE(t.counterClockwise.back());
  EXPECT_EQ(std::count(t.counterClockwise.begin(), t.counterClockwise.end(), true), 360);
  const Iso230Result iso = evaluateIso230_4(t);
  EXPECT_TRUE(iso.linearised);
  ASSERT_EQ(iso.directions.size(), 2u);
  for (const Iso230Direction& d : iso.directions) {
    EXPECT_NEAR(d.circularDeviationMm, 0.004, 1e-6);
    EXPECT_NEAR(d.lsqCentreMm.x(), 0.005, 1e-6);
    EXPECT_NEAR(d.lsqCentreMm.y(), -0.003, 1e-6);
    EXPECT_FALSE(d.lsqRadiusMm);
  }
  ASSERT_TRUE(iso.circularHysteresisMm);
  EXPECT_NEAR(*iso.circularHysteresisMm, 0.0015, 1e-6);
  // F is the range of the file's own deviations (about the pivot): the offset e = |c0| adds to the form,
  // so F spans at least G and at most A + e either side.
  const double e = std::hypot(0.005, 0.003);
  for (const Iso230Direction& d : iso.directions) {
    EXPECT_LE(d.radialDeviationMaxMm, 0.002 + e + (d.counterClockwise ? 0.0 : 0.0015) + 1e-9);
    EXPECT_GE(d.radialDeviationMinMm, -(0.002 + e) - 1e-9);
    EXPECT_GE(d.radialDeviationMaxMm - d.radialDeviationMinMm, d.circularDeviationMm - 1e-9);
  }
}

std::string messageOf(const std::string& csv, const std::string& name) {
  try {
    (void)circularTraceFromCsv(parseCsv(csv, name));
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Iso230_4, RadialFormErrorsNameFileLineAndField) {
  EXPECT_EQ(messageOf("angle_deg,deviation_um,direction\n0,1,ccw\n1,2,sideways\n2,3,cw\n", "r.csv"),
            "r.csv:3:3: field 'direction': 'sideways' is not a direction (ccw or cw)");
  EXPECT_NE(messageOf("angle_deg,deviation_um\n0,1\n1,x\n2,3\n", "r.csv").find("r.csv:3:2"),
            std::string::npos);
  EXPECT_NE(messageOf("angle_deg,deviation_um\n0,1\n", "r.csv").find("r.csv"), std::string::npos);
  EXPECT_NE(messageOf("angle_deg,deviation_um,radius_mm\n0,1,100\n1,2,100\n2,3,150\n", "r.csv")
                .find("r.csv:4:3: field 'radius_mm'"),
            std::string::npos);
  EXPECT_NE(messageOf("angle_deg,deviation_um,deviation_mm\n0,1,1\n1,2,1\n2,3,1\n", "r.csv").find("not both"),
            std::string::npos);
}

TEST(Iso230_4, RadialFormIsRefusedForTheIdentificationWithTheFileNamed) {
  try {
    (void)measuredPathFromCsv(parseCsv(ballbarCsv(false, true), "ballbar.csv"));
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("ballbar.csv: is a radial-only circular test", 0), 0u) << m;
    EXPECT_NE(m.find("x_cmd_mm"), std::string::npos);
    EXPECT_EQ(m.find('\n'), std::string::npos);
  }
}

}  // namespace
}  // namespace metrofit
