// Three-axis actuator errors from circular tests in XY, YZ and ZX (core/kinematics/identification3.h,
// core/sim/circular_sim.h simulatePlaneCircularTest). References written here, not taken from the
// code under test:
//  * the ballbar closed form of a circular test on a machine with small squareness and origin
//    errors (first order in the errors): r(theta) - R = o_u cos(theta) + o_v sin(theta)
//    - (R S / 2) sin(2 theta), S = b - a the squareness in rad (an ellipse with its axes at
//    45 / 135 deg: a negative S stretches the 45 deg diagonal);
//  * test data made by the test's own forward model: directions built from three small rotations
//    about the machine axes (not the projection-angle formula of the code), projected to each plane.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/io/json_util.h"
#include "core/kinematics/identification3.h"
#include "core/sim/circular_sim.h"

namespace metrofit {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(Identification3, SimulatedPlaneTestsFollowTheBallbarClosedForm) {
  ActuatorErrors3 e;
  e.originMm = Eigen::Vector3d(0.003, -0.002, 0.004);
  e.uAngleDeg = {0.001, -0.0015, 0.0008};
  e.vAngleDeg = {-0.002, 0.0012, 0.0025};
  CircularSimOptions o;
  o.radiusMm = 150.0;
  o.noiseMm = 0.0;
  o.pointsPerLoop = 72;
  for (const TestPlane plane : kTestPlanes) {
    const MeasuredPath p = simulatePlaneCircularTest(e, plane, o);
    const auto ax = planeAxes(plane);
    const double S = e.squarenessDeg(plane) * kDeg;
    const double ou = e.originMm(ax[0]), ov = e.originMm(ax[1]);
    double worst = 0.0, amplitude = 0.0;
    for (std::size_t k = 0; k < p.size(); ++k) {
      const double th = std::atan2(p.command[k].y(), p.command[k].x());
      const double expected = ou * std::cos(th) + ov * std::sin(th) - 150.0 * S / 2.0 * std::sin(2.0 * th);
      const double dr = p.measured[k].norm() - 150.0;
      worst = std::max(worst, std::abs(dr - expected));
      amplitude = std::max(amplitude, std::abs(expected));
    }
    // Second order: R angle^2 + |o|^2 / R, below 1e-6 mm here; the signal is ~5 um.
    EXPECT_LT(worst, 1e-6) << planeName(plane);
    EXPECT_GT(amplitude, 0.002) << planeName(plane);
  }
}

/// The test's own machine: axis directions e_x, e_y, e_z turned by small rotations, then P = o +
/// D Pr. Returns the in-plane angles the code's convention gives for these directions (atan of the
/// projections), which the identification must find.
struct RotatedMachine {
  Eigen::Vector3d o;
  Eigen::Matrix3d D;
  std::array<double, 3> u{}, v{};  // a_p, b_p in deg, from D's projections
};

RotatedMachine rotatedMachine() {
  RotatedMachine m;
  m.o = Eigen::Vector3d(0.5, -0.3, 0.2);
  // X axis: yaw 2 deg about z, pitch -1.5 deg about y; Y axis: 3.5 deg about z, 1 deg about x;
  // Z axis: -2 deg about y, 0.5 deg about x.
  const auto R = [](double deg, const Eigen::Vector3d& axis) { return Eigen::AngleAxisd(deg * kDeg, axis); };
  m.D.col(0) =
      R(2.0, Eigen::Vector3d::UnitZ()) * (R(-1.5, Eigen::Vector3d::UnitY()) * Eigen::Vector3d::UnitX());
  m.D.col(1) =
      R(3.5, Eigen::Vector3d::UnitZ()) * (R(1.0, Eigen::Vector3d::UnitX()) * Eigen::Vector3d::UnitY());
  m.D.col(2) =
      R(-2.0, Eigen::Vector3d::UnitY()) * (R(0.5, Eigen::Vector3d::UnitX()) * Eigen::Vector3d::UnitZ());
  const Eigen::Matrix3d& D = m.D;
  // XY: X at atan2(i_y, i_x), Y at atan2(-j_x, j_y); YZ: Y at atan2(j_z, j_y), Z at atan2(-k_y, k_z);
  // ZX: Z at atan2(k_x, k_z), X at atan2(-i_z, i_x).
  m.u = {std::atan2(D(1, 0), D(0, 0)) / kDeg, std::atan2(D(2, 1), D(1, 1)) / kDeg,
         std::atan2(D(0, 2), D(2, 2)) / kDeg};
  m.v = {std::atan2(-D(0, 1), D(1, 1)) / kDeg, std::atan2(-D(1, 2), D(2, 2)) / kDeg,
         std::atan2(-D(2, 0), D(0, 0)) / kDeg};
  return m;
}

std::array<MeasuredPath, 3> testsOn(const RotatedMachine& m, double noise, unsigned seed) {
  std::mt19937_64 gen(seed);
  std::normal_distribution<double> nd(0.0, noise > 0.0 ? noise : 1.0);
  std::array<MeasuredPath, 3> tests;
  for (int p = 0; p < 3; ++p) {
    const int iu = p, iv = (p + 1) % 3;  // xy, yz, zx
    MeasuredPath& t = tests[static_cast<std::size_t>(p)];
    t.source = std::string("plane") + std::to_string(p) + ".csv";
    for (int k = 0; k < 360; ++k) {
      const double th = 2 * std::numbers::pi * k / 180.0 * (k < 180 ? 1 : -1);
      Eigen::Vector3d pr = Eigen::Vector3d::Zero();
      pr(iu) = 100.0 * std::cos(th);
      pr(iv) = 100.0 * std::sin(th);
      const Eigen::Vector3d pos = m.o + m.D * pr;
      t.command.emplace_back(pr(iu), pr(iv));
      Eigen::Vector2d meas(pos(iu), pos(iv));
      if (noise > 0.0) meas += Eigen::Vector2d(nd(gen), nd(gen));
      t.measured.push_back(meas);
    }
  }
  return tests;
}

TEST(Identification3, RecoversTheInjectedDegreeSizedErrorsExactly) {
  const RotatedMachine m = rotatedMachine();
  const Identify3Result r = identifyActuatorErrors3(testsOn(m, 0.0, 1));
  EXPECT_EQ(r.run.termination, Termination::Converged) << r.run.message;
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(r.errors.originMm(i), m.o(i), 1e-9) << i;
  for (std::size_t p = 0; p < 3; ++p) {
    EXPECT_NEAR(r.errors.uAngleDeg[p], m.u[p], 1e-9) << p;
    EXPECT_NEAR(r.errors.vAngleDeg[p], m.v[p], 1e-9) << p;
  }
  // The three-axis directions are the test's own rotated axes.
  EXPECT_LT((r.errors.directions() - m.D).cwiseAbs().maxCoeff(), 1e-12);
  // Squareness in the plane = b - a: to first order the angle between the axes minus 90 deg (the
  // out-of-plane tilts of 1-2 deg here differ from it by their products, 0.03 deg).
  const double angleXY = std::acos(m.D.col(0).dot(m.D.col(1))) / kDeg - 90.0;
  EXPECT_NEAR(r.errors.squarenessDeg(TestPlane::XY), angleXY, 0.05);  // second order: ~ tilt products
  EXPECT_LT(r.rmseMm, 1e-9);
}

TEST(Identification3, NoisyTestsRecoverTheErrorsWithinTheirStandardErrors) {
  RotatedMachine m = rotatedMachine();
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const Identify3Result r = identifyActuatorErrors3(testsOn(m, 0.0005, seed));
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(r.errors.originMm(i), m.o(i), 5 * r.standardErrors.originMm(i)) << i;
      EXPECT_LT(r.standardErrors.originMm(i), 5e-5);
    }
    for (std::size_t p = 0; p < 3; ++p) {
      EXPECT_NEAR(r.errors.uAngleDeg[p], m.u[p], 5 * r.standardErrors.uAngleDeg[p]) << p;
      EXPECT_NEAR(r.errors.vAngleDeg[p], m.v[p], 5 * r.standardErrors.vAngleDeg[p]) << p;
      EXPECT_NEAR(r.errors.squarenessDeg(static_cast<TestPlane>(p)), m.v[p] - m.u[p],
                  5 * r.squarenessStdErrDeg[p]);
      EXPECT_LT(r.squarenessStdErrDeg[p], 1e-4);
    }
    EXPECT_NEAR(r.sigmaMm, 0.0005, 0.00005);
  }
}

TEST(Identification3, SameDataSameResultAndTheObserverCanStop) {
  const auto tests = testsOn(rotatedMachine(), 0.0005, 9);
  const Identify3Result a = identifyActuatorErrors3(tests), b = identifyActuatorErrors3(tests);
  EXPECT_EQ(a.errors.originMm, b.errors.originMm);
  long seen = 0;
  FunctionObserver stop([&](const IterationSummary& s) {
    ++seen;
    EXPECT_EQ(s.bestX.size(), 9u);
    return ObserverDecision::Stop;
  });
  const Identify3Result c = identifyActuatorErrors3(tests, {}, &stop);
  EXPECT_EQ(seen, 1);
  EXPECT_EQ(c.run.termination, Termination::Cancelled);
}

TEST(Identification3, BadTestNamesThePlaneFileAndField) {
  auto tests = testsOn(rotatedMachine(), 0.0, 1);
  for (auto& p : tests[1].measured) p = Eigen::Vector2d(1.0, 2.0);  // YZ: all measured points equal
  try {
    identifyActuatorErrors3(tests);
    FAIL();
  } catch (const ValidationError& e) {
    const std::string w = e.what();
    EXPECT_NE(w.find("plane1.csv"), std::string::npos) << w;
    EXPECT_NE(w.find("y_meas_mm,z_meas_mm"), std::string::npos) << w;
    EXPECT_NE(w.find("(yz test)"), std::string::npos) << w;
  }
  // A ZX file with the XY columns: the reader names the missing ZX column.
  const CsvTable t = parseCsv("x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm\n1,2,3,4\n", "zx.csv");
  try {
    planePathFromCsv(t, TestPlane::ZX);
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("zx.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("z_cmd_mm"), std::string::npos) << e.what();
  }
}

TEST(Identification3, JsonRoundTrip) {
  const Identify3Result r = identifyActuatorErrors3(testsOn(rotatedMachine(), 0.0, 1));
  const ActuatorErrors3 e = actuatorErrors3FromJson(identify3ResultToJson(r), "e3.json");
  EXPECT_EQ(e.originMm, r.errors.originMm);
  EXPECT_EQ(e.uAngleDeg, r.errors.uAngleDeg);
  EXPECT_EQ(e.vAngleDeg, r.errors.vAngleDeg);
}

std::string errors3JsonError(const std::string& origin) {
  const std::string text = R"({"origin_mm": )" + origin +
                           R"(, "planes": {"xy": {"x_axis_angle_deg": 0, "y_axis_angle_deg": 0},
                               "yz": {"y_axis_angle_deg": 0, "z_axis_angle_deg": 0},
                               "zx": {"z_axis_angle_deg": 0, "x_axis_angle_deg": 0}}})";
  try {
    const ActuatorErrors3 e = actuatorErrors3FromJson(parseJson(text, "e3.json"), "e3.json");
    return "no error, origin z " + std::to_string(e.originMm.z());
  } catch (const InputError& e) {
    return e.what();
  }
}

// The origin of the three-axis JSON is read as the 2D one is (one shared reader): the same checks
// and messages with three coordinates.
TEST(Identification3, MalformedOriginInJsonNamesTheField) {
  EXPECT_EQ(errors3JsonError("[1, 2, 3.5]"), "no error, origin z 3.500000");
  EXPECT_EQ(errors3JsonError("[1, 2]"),
            "e3.json: field 'origin_mm': expected 3 numbers [x, y, z], found 2 elements");
  EXPECT_EQ(errors3JsonError("[1]"),
            "e3.json: field 'origin_mm': expected 3 numbers [x, y, z], found 1 element");
  EXPECT_EQ(errors3JsonError(R"([1, 2, "3"])"),
            "e3.json: field 'origin_mm[2]': expected a number, found string");
  EXPECT_EQ(errors3JsonError("7"), "e3.json: field 'origin_mm': expected an array, found number");
}

TEST(Identification3, CompensatedReferencesPutTheTestsOwnMachineOnTheNominalPath) {
  const RotatedMachine m = rotatedMachine();
  const Identify3Result r = identifyActuatorErrors3(testsOn(m, 0.0, 1));
  std::vector<Eigen::Vector3d> nominal;
  for (int k = 0; k < 24; ++k) {
    const double t = 2 * std::numbers::pi * k / 24;
    nominal.emplace_back(80.0 * std::cos(t), 60.0 * std::sin(t), 10.0 + 5.0 * k);  // a helix
  }
  const auto refs = compensatePath3(r.errors, nominal);
  double before = 0.0, after = 0.0;
  for (std::size_t k = 0; k < nominal.size(); ++k) {
    before = std::max(before, (m.o + m.D * nominal[k] - nominal[k]).norm());
    after = std::max(after, (m.o + m.D * refs[k] - nominal[k]).norm());
  }
  EXPECT_GT(before, 1.0);  // degree-sized errors: millimetres
  EXPECT_LT(after, 1e-8);
}

}  // namespace
}  // namespace metrofit
