// The ballbar breakdown (core/kinematics/ballbar.h). Every cause is checked on a circular test made here
// from that cause's physical definition alone, as an error of the axes applied to the commands of a CCW
// and a CW loop (not from the breakdown's signature columns): backlash moves an axis by -d b/2 with d the
// sign of its last move, a spike decays with the angle travelled since the axis' last reversal, scale
// errors scale the axis positions, squareness runs the commands through the actuator model of
// cartesian_model.h, and so on. The measured radius is exact (|p - c|), not linearised.
//
// Tolerances: without noise the breakdown is exact up to the first-order approximation dr = e . u (an
// error of |e|^2 / 2R, below 1e-3 um here), so the injected cause is recovered within 0.01 um and every
// other cause stays below 0.01 um. With noise sigma per coordinate: within 5 standard errors.
// Noise rule: on a clean circle with noise no cause is significant (|value| > 3 standard errors,
// BallbarOptions::significance) and the unexplained share is above 0.9.
#include <gtest/gtest.h>

#include <clocale>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/io/json_util.h"
#include "core/kinematics/ballbar.h"
#include "core/kinematics/cartesian_model.h"
#include "core/kinematics/identification.h"
#include "core/kinematics/measured_path.h"

namespace metrofit {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kR = 100.0;
const Eigen::Vector2d kCentre(250.0, -120.0);  // absolute machine position of the test's centre

/// What a cause sees of the machine at command k (all in mm / deg).
struct Motion {
  Eigen::Vector2d command = Eigen::Vector2d::Zero();  ///< absolute
  Eigen::Vector2d rel = Eigen::Vector2d::Zero();      ///< command - centre
  double thetaDeg = 0.0;                              ///< commanded angle
  bool ccw = true;                                    ///< direction of travel
  Eigen::Vector2d d =
      Eigen::Vector2d::Zero();  ///< sign of each axis' last move (the first point: its first move's)
  Eigen::Vector2d phiDeg =
      Eigen::Vector2d::Zero();  ///< angle travelled since each axis' last reversal (inf before the first)
};

/// One loop CCW (0, 1, ..., 359 deg), then one CW (0, -1, ..., -359 deg): the commands, and the axis
/// error `error(motion)` (mm) added to each; `ccwOnly` leaves the CW loop out.
MeasuredPath circularTest(const std::function<Eigen::Vector2d(const Motion&)>& error, bool ccwOnly = false) {
  std::vector<Motion> m;
  for (int loop = 0; loop < (ccwOnly ? 1 : 2); ++loop) {
    for (int k = 0; k < 360; ++k) {
      const double th = loop == 0 ? k : -k;
      Motion p;
      p.thetaDeg = th;
      p.ccw = loop == 0;
      p.rel = kR * Eigen::Vector2d(std::cos(th * kPi / 180.0), std::sin(th * kPi / 180.0));
      p.command = kCentre + p.rel;
      m.push_back(p);
    }
  }
  // Axis directions: the sign of the last move; reversal: where that sign changes (at the point before).
  const double inf = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 2; ++axis) {
    double first = m[1].command(axis) > m[0].command(axis) ? 1.0 : -1.0;
    double phi = inf;
    for (std::size_t k = 0; k < m.size(); ++k) {
      double dir = first;
      if (k > 0) {
        const double move = m[k].command(axis) - m[k - 1].command(axis);
        dir = move == 0.0 ? m[k - 1].d(axis) : (move > 0.0 ? 1.0 : -1.0);
        if (dir != m[k - 1].d(axis)) phi = 0.0;
        phi += 1.0;  // the commands are 1 deg apart
      }
      m[k].d(axis) = dir;
      m[k].phiDeg(axis) = phi;
    }
  }
  MeasuredPath path;
  path.source = "test.csv";
  for (const Motion& p : m) {
    path.command.push_back(p.command);
    path.measured.push_back(p.command + error(p));
  }
  return path;
}

const std::vector<std::string> kReversalCauses = {"backlash_x",       "backlash_y",     "reversal_spike_x",
                                                  "reversal_spike_y", "lateral_play_x", "lateral_play_y",
                                                  "servo_mismatch"};
const std::vector<std::string> kGeometricCauses = {"scale_mismatch", "squareness", "straightness_x",
                                                   "straightness_y"};

/// The injected cause comes first with its value within `tol` um; every other cause below `others` um.
void expectOnly(const BallbarBreakdown& b, const std::string& name, double valueUm, double tol = 0.01,
                double others = 0.01) {
  ASSERT_FALSE(b.causes.empty());
  EXPECT_EQ(b.causes.front().name, name);
  const BallbarCause* c = b.cause(name);
  ASSERT_NE(c, nullptr) << name;
  EXPECT_NEAR(c->valueUm, valueUm, tol) << name;
  EXPECT_GT(c->share, 0.99) << name;
  for (const BallbarCause& o : b.causes) {
    if (o.name != name) {
      EXPECT_LT(std::abs(o.valueUm), others) << o.name << " in the test of " << name;
    }
  }
  double sum = b.unexplainedShare;
  for (const BallbarCause& o : b.causes) sum += o.share;
  EXPECT_NEAR(sum, 1.0, 1e-12);
}

TEST(Ballbar, BacklashXIsAStepOfTheXAxisAtItsReversals) {
  const double b = 0.006;  // lost motion 6 um: X lags by b/2 behind its direction of motion
  const auto path = circularTest(
      [&](const Motion& m) -> Eigen::Vector2d { return Eigen::Vector2d(-m.d.x() * b / 2.0, 0.0); });
  expectOnly(ballbarBreakdown(path), "backlash_x", 6.0);
}

TEST(Ballbar, BacklashYIsAStepOfTheYAxisAtItsReversals) {
  const double b = 0.004;
  const auto path = circularTest(
      [&](const Motion& m) -> Eigen::Vector2d { return Eigen::Vector2d(0.0, -m.d.y() * b / 2.0); });
  expectOnly(ballbarBreakdown(path), "backlash_y", 4.0);
}

TEST(Ballbar, ReversalSpikeIsADecayingLagAfterEachReversal) {
  // X sticks for a moment after each reversal: it lags h exp(-phi / w) behind its new direction.
  const double h = 0.008, w = BallbarOptions{}.spikeWidthDeg;
  const auto path = circularTest([&](const Motion& m) -> Eigen::Vector2d {
    return Eigen::Vector2d(-m.d.x() * h * std::exp(-m.phiDeg.x() / w), 0.0);
  });
  expectOnly(ballbarBreakdown(path), "reversal_spike_x", 8.0);
  const auto pathY = circularTest([&](const Motion& m) -> Eigen::Vector2d {
    return Eigen::Vector2d(0.0, -m.d.y() * 0.005 * std::exp(-m.phiDeg.y() / w));
  });
  expectOnly(ballbarBreakdown(pathY), "reversal_spike_y", 5.0);
}

TEST(Ballbar, LateralPlayIsAStepOfThePerpendicularAxisAtAReversal) {
  // The X carriage shifts in Y by p when X reverses (towards -Y while X moves in +X).
  const double p = 0.005;
  const auto path = circularTest(
      [&](const Motion& m) -> Eigen::Vector2d { return Eigen::Vector2d(0.0, -m.d.x() * p / 2.0); });
  expectOnly(ballbarBreakdown(path), "lateral_play_x", 5.0);
  const auto pathY = circularTest(
      [&](const Motion& m) -> Eigen::Vector2d { return Eigen::Vector2d(-m.d.y() * 0.003 / 2.0, 0.0); });
  expectOnly(ballbarBreakdown(pathY), "lateral_play_y", 3.0);
}

TEST(Ballbar, ServoMismatchIsTheDifferenceOfTheAxesFollowingErrors) {
  // First-order servo lags: each axis trails its command by tau v along the path tangent. Feed 1000
  // mm/min, tau_x = 2 ms, tau_y = 1.4 ms: m = v (tau_x - tau_y) = 16.67 mm/s * 0.6 ms = 10 um.
  const double v = 1000.0 / 60.0, tauX = 0.002, tauY = 0.0014;
  const auto path = circularTest([&](const Motion& m) -> Eigen::Vector2d {
    const double th = m.thetaDeg * kPi / 180.0, s = m.ccw ? 1.0 : -1.0;
    const Eigen::Vector2d t = s * Eigen::Vector2d(-std::sin(th), std::cos(th));
    return Eigen::Vector2d(-tauX * v * t.x(), -tauY * v * t.y());
  });
  // The turn between the loops: the breakdown takes the tangent of the incoming move there (effects.h),
  // this definition the outgoing one; one point of 720, hence the wider tolerance.
  expectOnly(ballbarBreakdown(path), "servo_mismatch", v * (tauX - tauY) * 1000.0, 0.05, 0.05);
}

TEST(Ballbar, ScaleMismatchIsTheDifferenceOfTheAxesScaleTimesTheRadius) {
  // Scale errors of the axes' measuring systems act on the absolute positions: X +30 ppm, Y -20 ppm.
  const double sx = 30e-6, sy = -20e-6;
  const auto path = circularTest([&](const Motion& m) -> Eigen::Vector2d {
    return Eigen::Vector2d(sx * m.command.x(), sy * m.command.y());
  });
  expectOnly(ballbarBreakdown(path), "scale_mismatch", (sx - sy) * kR * 1000.0);
}

TEST(Ballbar, SquarenessIsTheShearOfTheActuatorModelOverTheRadius) {
  // The machine of cartesian_model.h with the Y axis turned by b = 0.004 deg (squareness b - a):
  // the value is S R with S in rad; identify's squareness_deg gives the same.
  ActuatorErrors2 e;
  e.yAxisAngleDeg = 0.004;
  const CartesianMachine2 machine = CartesianMachine2::fromErrors(e);
  const auto path = circularTest([&](const Motion& m) -> Eigen::Vector2d {
    return Eigen::Vector2d(machine.forward(m.command) - m.command);
  });
  const double expected = 0.004 * kPi / 180.0 * kR * 1000.0;  // 6.98 um
  const BallbarBreakdown b = ballbarBreakdown(path);
  expectOnly(b, "squareness", expected);
  const IdentifyResult id = identifyActuatorErrors(path);
  EXPECT_NEAR(b.cause("squareness")->valueUm, id.errors.squarenessDeg() * kPi / 180.0 * kR * 1000.0, 0.01);
}

TEST(Ballbar, StraightnessIsABowOfAnAxisAcrossItsTravel) {
  // The X axis' travel over [-R, R] about the centre bows towards +Y by d in the middle.
  const double d = 0.003;
  const auto path = circularTest([&](const Motion& m) -> Eigen::Vector2d {
    const double x = m.rel.x() / kR;
    return Eigen::Vector2d(0.0, d * (1.0 - x * x));
  });
  expectOnly(ballbarBreakdown(path), "straightness_x", 3.0);
  const auto pathY = circularTest([&](const Motion& m) -> Eigen::Vector2d {
    const double y = m.rel.y() / kR;
    return Eigen::Vector2d(-0.002 * (1.0 - y * y), 0.0);
  });
  expectOnly(ballbarBreakdown(pathY), "straightness_y", -2.0);
}

TEST(Ballbar, CyclicErrorHasThePeriodOfTheScrewPitch) {
  // X's ball screw of lead 10 mm: e_x = A sin(2 pi x / 10 + 40 deg), A = 2 um, x the absolute position.
  BallbarOptions o;
  o.screwPitchMm = 10.0;
  const auto path = circularTest([&](const Motion& m) -> Eigen::Vector2d {
    return Eigen::Vector2d(0.002 * std::sin(2.0 * kPi * m.command.x() / 10.0 + 40.0 * kPi / 180.0), 0.0);
  });
  expectOnly(ballbarBreakdown(path, o), "cyclic_error_x", 2.0);
  const auto pathY = circularTest([&](const Motion& m) -> Eigen::Vector2d {
    return Eigen::Vector2d(0.0, 0.0015 * std::cos(2.0 * kPi * m.command.y() / 10.0));
  });
  expectOnly(ballbarBreakdown(pathY, o), "cyclic_error_y", 1.5);
  // Without a pitch the cyclic error is not fitted.
  EXPECT_EQ(ballbarBreakdown(path).cause("cyclic_error_x"), nullptr);
}

TEST(Ballbar, ThreeCausesTogetherAreEachRecovered) {
  // Backlash X 4 um, squareness 6 um (S R), servo mismatch 3 um, and noise 0.2 um per coordinate.
  const double b = 0.004, s = 0.006 / kR, m = 0.003, noise = 0.0002;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> gauss(0.0, noise);
  ActuatorErrors2 e;
  e.xAxisAngleDeg = -s / 2.0 * 180.0 / kPi;
  e.yAxisAngleDeg = s / 2.0 * 180.0 / kPi;
  const CartesianMachine2 machine = CartesianMachine2::fromErrors(e);
  const auto path = circularTest([&](const Motion& p) -> Eigen::Vector2d {
    const double th = p.thetaDeg * kPi / 180.0, dir = p.ccw ? 1.0 : -1.0;
    const Eigen::Vector2d t = dir * Eigen::Vector2d(-std::sin(th), std::cos(th));
    Eigen::Vector2d err = machine.forward(p.command) - p.command;  // squareness
    err.x() += -p.d.x() * b / 2.0 - m * t.x();                     // backlash X, X lags m more than Y
    err += Eigen::Vector2d(gauss(rng), gauss(rng));
    return err;
  });
  const BallbarBreakdown r = ballbarBreakdown(path);
  const std::vector<std::string> top = {r.causes[0].name, r.causes[1].name, r.causes[2].name};
  EXPECT_EQ(top, (std::vector<std::string>{"squareness", "backlash_x", "servo_mismatch"}));
  for (const auto& [name, value] : std::vector<std::pair<std::string, double>>{
           {"backlash_x", 4.0}, {"squareness", 6.0}, {"servo_mismatch", 3.0}}) {
    const BallbarCause* c = r.cause(name);
    ASSERT_NE(c, nullptr);
    EXPECT_NEAR(c->valueUm, value, 5.0 * c->stdErrorUm) << name;
    EXPECT_TRUE(c->significant) << name;
  }
  for (const BallbarCause& c : r.causes) {
    if (c.name != "backlash_x" && c.name != "squareness" && c.name != "servo_mismatch") {
      EXPECT_LT(std::abs(c.valueUm), 5.0 * c.stdErrorUm) << c.name;
    }
  }
}

TEST(Ballbar, CleanCircleWithNoiseHasNoCauseAboveTheNoise) {
  // Only a centre offset, a radius offset and noise 0.5 um per coordinate: nothing to find.
  BallbarOptions o;
  o.screwPitchMm = 5.0;
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> gauss(0.0, 0.0005);
    const auto path = circularTest([&](const Motion& m) -> Eigen::Vector2d {
      return Eigen::Vector2d(0.004, -0.003) + 0.002 * m.rel / kR + Eigen::Vector2d(gauss(rng), gauss(rng));
    });
    const BallbarBreakdown b = ballbarBreakdown(path, o);
    EXPECT_EQ(b.causes.size(), 13u);
    for (const BallbarCause& c : b.causes) {
      EXPECT_FALSE(c.significant) << c.name << " " << c.valueUm << " +- " << c.stdErrorUm << " (seed " << seed
                                  << ")";
      EXPECT_LT(std::abs(c.valueUm), 3.0 * c.stdErrorUm) << c.name;
    }
    EXPECT_GT(b.unexplainedShare, 0.9);
    EXPECT_NEAR(b.residualRmsUm, 0.5, 0.05);  // the radial part of the noise
  }
}

TEST(Ballbar, OneDirectionFitsTheGeometricCausesOnly) {
  ActuatorErrors2 e;
  e.yAxisAngleDeg = 0.004;
  const CartesianMachine2 machine = CartesianMachine2::fromErrors(e);
  const auto path = circularTest(
      [&](const Motion& m) -> Eigen::Vector2d {
        return Eigen::Vector2d(machine.forward(m.command) - m.command);
      },
      true);
  const BallbarBreakdown b = ballbarBreakdown(path);
  EXPECT_FALSE(b.bothDirections);
  for (const std::string& name : kReversalCauses) EXPECT_EQ(b.cause(name), nullptr) << name;
  for (const std::string& name : kGeometricCauses) EXPECT_NE(b.cause(name), nullptr) << name;
  expectOnly(b, "squareness", 0.004 * kPi / 180.0 * kR * 1000.0);
}

TEST(Ballbar, RefusesPathsThatAreNoCircularTest) {
  MeasuredPath line;
  line.source = "line.csv";
  for (int k = 0; k < 100; ++k) {
    line.command.emplace_back(k, 0.0);
    line.measured.emplace_back(k, 0.0);
  }
  std::string why;
  EXPECT_FALSE(isCircularTest(line, &why));
  EXPECT_FALSE(why.empty());
  EXPECT_THROW(ballbarBreakdown(line), ValidationError);
  // A square path is not a circle either.
  MeasuredPath square = line;
  square.command = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {5, 0}, {10, 5}, {5, 10}, {0, 5}};
  square.measured = square.command;
  EXPECT_FALSE(isCircularTest(square, &why));
  EXPECT_NE(why.find("not on one circle"), std::string::npos) << why;
  // Half a circle leaves a gap.
  MeasuredPath half = circularTest([](const Motion&) -> Eigen::Vector2d { return Eigen::Vector2d::Zero(); });
  half.command.resize(180);
  half.measured.resize(180);
  try {
    ballbarBreakdown(half);
    ADD_FAILURE() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "test.csv: field 'x_cmd_mm': no ballbar breakdown: the CCW run leaves a gap"),
              std::string::npos)
        << e.what();
  }
  BallbarOptions bad;
  bad.spikeWidthDeg = 0.0;
  EXPECT_THROW(ballbarBreakdown(half, bad), OptionsError);
}

TEST(Ballbar, JsonIsTheSameUnderEveryLocale) {
  const auto path = circularTest([](const Motion& m) -> Eigen::Vector2d {
    return Eigen::Vector2d(-m.d.x() * 0.003 + 1.234567e-5 * m.rel.x() / kR, 0.0021 * m.rel.y() / kR);
  });
  const BallbarBreakdown b = ballbarBreakdown(path);
  std::vector<std::string> out;
  for (const char* locale : {"C.UTF-8", "de_DE.UTF-8", "pl_PL.UTF-8"}) {
    if (std::setlocale(LC_ALL, locale) == nullptr) {
      ADD_FAILURE() << "locale " << locale << " is not installed (packaging/install-deps.sh generates it)";
    }
    out.push_back(dumpJson(ballbarCausesToJson(ballbarBreakdown(path))));
    std::setlocale(LC_ALL, "C");
  }
  EXPECT_EQ(out[1], out[0]);
  EXPECT_EQ(out[2], out[0]);
  EXPECT_EQ(out[0], dumpJson(ballbarCausesToJson(b)));
  const nlohmann::json j = nlohmann::json::parse(out[0]);
  ASSERT_TRUE(j.is_array());
  EXPECT_EQ(j.front().at("name"), "backlash_x");
  EXPECT_NEAR(j.front().at("value_um").get<double>(), 6.0, 0.01);
  EXPECT_EQ(j.back().at("name"), "unexplained");
  double sum = 0.0;
  for (const auto& c : j) {
    EXPECT_EQ(c.size(), 3u);
    sum += c.at("share").get<double>();
  }
  EXPECT_NEAR(sum, 1.0, 1e-12);
}

}  // namespace
}  // namespace metrofit
