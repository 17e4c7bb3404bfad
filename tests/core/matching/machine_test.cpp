// Machine adjustment values (Jiang et al. 2018, Section 3, Eq. 12-13) against the forward chains.
// (core/machine has no test folder of its own yet; its tests live with the matching tests.)
#include "core/machine/machine.h"

#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/common/rng.h"
#include "core/matching/pose.h"

namespace metrofit::machine {
namespace {

using matching::Pose;

std::vector<Pose> postures() {
  Rng rng(17);
  std::vector<Pose> out = {Pose{}, Pose::fromAnglesDeg({0.02, -0.015, 0.05}, {0.12, -0.08, 0.05}),
                           Pose::fromAnglesDeg({0.0, 10.0, 0.0}, {0, 0, 0}),
                           Pose::fromAnglesDeg({25.0, -30.0, 170.0}, {-40.0, 12.0, 3.0})};
  for (int k = 0; k < 20; ++k) {
    out.push_back(Pose::fromAnglesDeg({rng.uniform(-20, 20), rng.uniform(-20, 20), rng.uniform(-180, 180)},
                                      {rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)}));
  }
  return out;
}

TEST(Machine, HeadHeadRoundTripThroughEq12And13) {
  MachineDefinition m = MachineDefinition::preset(Topology::Xfyzba);
  m.lx = 3.0;
  m.ly = -2.0;
  m.lz = -180.0;
  m.lab = -120.0;
  for (const Pose& p : postures()) {
    const Adjustment a = adjustmentFor(m, p.rotation, p.translation);
    // The 4x4 chain of Eq. (13) puts the cutter location point on the new WCS origin and Eq. (12)
    // the tool along the new WCS z axis.
    Eigen::Vector3d cl, axis;
    headHeadForward(m, a.linearMm, a.rotaryDeg[0], a.rotaryDeg[1], &cl, &axis);
    EXPECT_LT((cl - p.translation).norm(), 1e-10);
    EXPECT_LT((axis - p.rotation.col(2)).norm(), 1e-12);
    const Frame f = realisedFrame(m, a);
    EXPECT_LT((f.rotation - p.rotation).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((f.origin - p.translation).norm(), 1e-10);
  }
}

TEST(Machine, HeadHeadHandCases) {
  const MachineDefinition m = MachineDefinition::preset(Topology::Xfyzba);
  // Identity posture: nothing moves.
  const Adjustment zero = adjustmentFor(m, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
  EXPECT_LT(zero.linearMm.norm(), 1e-12);
  EXPECT_EQ(zero.rotaryDeg[0], 0.0);
  EXPECT_EQ(zero.rotaryDeg[1], 0.0);
  // Vertical head: axis values are the cutter location point (the offsets of Eq. 13 cancel).
  Eigen::Vector3d cl;
  headHeadForward(m, {10.0, 20.0, 30.0}, 0.0, 0.0, &cl, nullptr);
  EXPECT_LT((cl - Eigen::Vector3d(10, 20, 30)).norm(), 1e-12);
  // A pure tilt about y is SB; the pivot compensation moves X and Z: with LX = LY = 0 the tool tip
  // swings on a radius |LZ + LAB| about the B pivot, so SX = -(LZ + LAB) sin SB etc.
  const Pose tiltB = Pose::fromAnglesDeg({0.0, 10.0, 0.0}, {0, 0, 0});
  const Adjustment b = adjustmentFor(m, tiltB.rotation, tiltB.translation);
  EXPECT_NEAR(b.rotaryDeg[1], 10.0, 1e-12);
  EXPECT_NEAR(b.rotaryDeg[0], 0.0, 1e-12);
  EXPECT_NEAR(b.frameRotationDeg, 0.0, 1e-12);
  const double L = m.lz + m.lab, s = std::sin(10.0 * matching::kRadPerDeg),
               c = std::cos(10.0 * matching::kRadPerDeg);
  EXPECT_NEAR(b.linearMm.x(), -L * s, 1e-10);
  EXPECT_NEAR(b.linearMm.z(), L - L * c, 1e-10);
  // A rotation about z alone cannot be made by A and B: it is the frame rotation.
  const Pose rz = Pose::fromAnglesDeg({0.0, 0.0, 3.0}, {0, 0, 0});
  const Adjustment z = adjustmentFor(m, rz.rotation, rz.translation);
  EXPECT_NEAR(z.frameRotationDeg, 3.0, 1e-12);
  EXPECT_NEAR(z.rotaryDeg[0], 0.0, 1e-12);
}

TEST(Machine, TableTableForwardCheckForEveryPoint) {
  for (Topology t : {Topology::AcTable, Topology::BcTable}) {
    MachineDefinition m = MachineDefinition::preset(t);
    m.tiltAxisPoint = {5.0, 30.0, -120.0};
    m.rotaryAxisPoint = {40.0, -25.0, 7.0};
    for (const Pose& p : postures()) {
      const Adjustment a = adjustmentFor(m, p.rotation, p.translation);
      EXPECT_LE(std::abs(a.rotaryDeg[1]), 90.0 + 1e-9);
      // Every nominal point q, placed on the workpiece at R q + t, is carried by the table to
      // S + Rz(phi) q: the nominal program runs unchanged in the adjusted WCS.
      const Eigen::Matrix3d phi = matching::rotationZyx({0, 0, a.frameRotationDeg * matching::kRadPerDeg});
      for (const Eigen::Vector3d& q : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(100, 0, 0),
                                       Eigen::Vector3d(0, 80, 20), Eigen::Vector3d(-30, 45, -60)}) {
        const Eigen::Vector3d onTable = p.rotation * q + p.translation;
        const Eigen::Vector3d machine = tableToMachine(m, a.rotaryDeg[0], a.rotaryDeg[1], onTable);
        EXPECT_LT((machine - (a.linearMm + phi * q)).norm(), 1e-9) << topologyName(t);
      }
      const Frame f = realisedFrame(m, a);
      EXPECT_LT((f.rotation - p.rotation).cwiseAbs().maxCoeff(), 1e-12);
      EXPECT_LT((f.origin - p.translation).norm(), 1e-9);
      EXPECT_LT((f.toolAxis - p.rotation.col(2)).norm(), 1e-12);
    }
  }
}

TEST(Machine, TrunnionHandCase) {
  // AC table, workpiece tilted by +2 deg about x: the WCS z axis is (0, -sin 2, cos 2), so the
  // table tilts A = -2 deg (C = 0) to bring it back under the spindle.
  const MachineDefinition m = MachineDefinition::preset(Topology::AcTable);
  const Pose p = Pose::fromAnglesDeg({2.0, 0.0, 0.0}, {0, 0, 0});
  const Adjustment a = adjustmentFor(m, p.rotation, p.translation);
  EXPECT_NEAR(a.rotaryDeg[0], -2.0, 1e-12);
  EXPECT_NEAR(a.rotaryDeg[1], 0.0, 1e-12);
  EXPECT_NEAR(a.frameRotationDeg, 0.0, 1e-12);
}

TEST(Machine, TravelLimitsAreReported) {
  MachineDefinition m = MachineDefinition::preset(Topology::AcTable);
  m.rotaryMinDeg[0] = -30.0;
  m.rotaryMaxDeg[0] = 30.0;
  const Pose p = Pose::fromAnglesDeg({40.0, 0.0, 0.0}, {0, 0, 0});
  const Adjustment a = adjustmentFor(m, p.rotation, p.translation);
  EXPECT_FALSE(a.withinTravel);
  EXPECT_NE(a.travelMessage.find("A = -40"), std::string::npos) << a.travelMessage;
  const nlohmann::json j = adjustmentToJson(a);
  EXPECT_EQ(j.at("within_travel"), false);
  EXPECT_TRUE(j.contains("SA_deg"));
  EXPECT_TRUE(j.contains("SC_deg"));
}

TEST(Machine, DefinitionJsonRoundTripAndErrors) {
  MachineDefinition m = MachineDefinition::preset(Topology::BcTable);
  m.tiltAxisPoint = {1, 2, 3};
  m.lab = -7.5;
  const MachineDefinition back = MachineDefinition::fromJson(m.toJson(), "p.metrofit");
  EXPECT_EQ(back.topology, Topology::BcTable);
  EXPECT_EQ(back.tiltAxisPoint, m.tiltAxisPoint);
  EXPECT_EQ(back.lab, -7.5);
  EXPECT_EQ(back.rotaryMaxDeg, m.rotaryMaxDeg);
  try {
    MachineDefinition::fromJson(nlohmann::json{{"topology", "xfyzba"}, {"LZ_mm", "long"}}, "p.metrofit");
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("p.metrofit: field 'LZ_mm'"), std::string::npos) << e.what();
  }
  try {
    MachineDefinition::fromJson(nlohmann::json{{"topology", "hexapod"}}, "p.metrofit");
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown machine topology 'hexapod'"), std::string::npos);
  }
  EXPECT_THROW(MachineDefinition::fromJson(nlohmann::json{{"rotary_travel_deg", {{10, -10}, {0, 1}}}}, "p"),
               ValidationError);
  EXPECT_THROW(parseTopology("abc", "--machine"), OptionsError);
  EXPECT_EQ(parseTopology("ac-table", "--machine"), Topology::AcTable);
}

/// The head-table chain written out here as 4x4 homogeneous transforms, independently of machine.cpp:
/// a table point x lies at Tr(c0) Rz(C) Tr(-c0) x; the tool of a B head with pivot length L at axis
/// values S has its cutter location point at Tr(S + (0,0,L)) Ry(B) Tr(0,0,-L) [0 0 0 1]^T and its axis
/// Ry(B) [0 0 1 0]^T.
struct HeadTableChain {
  Eigen::Vector3d c0;
  double pivot;
  static Eigen::Matrix4d rot(const Eigen::Vector3d& axis, double deg) {
    Eigen::Matrix4d H = Eigen::Matrix4d::Identity();
    H.topLeftCorner<3, 3>() = Eigen::AngleAxisd(deg * M_PI / 180.0, axis).toRotationMatrix();
    return H;
  }
  static Eigen::Matrix4d tr(const Eigen::Vector3d& v) {
    Eigen::Matrix4d H = Eigen::Matrix4d::Identity();
    H.topRightCorner<3, 1>() = v;
    return H;
  }
  Eigen::Vector3d table(double cDeg, const Eigen::Vector3d& x) const {
    return (tr(c0) * rot(Eigen::Vector3d::UnitZ(), cDeg) * tr(-c0) * x.homogeneous()).head<3>();
  }
  Eigen::Matrix4d head(const Eigen::Vector3d& S, double bDeg) const {
    return tr(S + Eigen::Vector3d(0, 0, pivot)) * rot(Eigen::Vector3d::UnitY(), bDeg) *
           tr(Eigen::Vector3d(0, 0, -pivot));
  }
};

TEST(Machine, HeadTableForwardCheckForEveryPoint) {
  MachineDefinition m = MachineDefinition::preset(Topology::HeadTable);
  m.rotaryAxisPoint = {40.0, -25.0, 7.0};
  m.pivot = 212.5;
  const HeadTableChain chain{m.rotaryAxisPoint, m.pivot};
  for (const Pose& p : postures()) {
    const Adjustment a = adjustmentFor(m, p.rotation, p.translation);
    EXPECT_EQ(a.topology, Topology::HeadTable);
    EXPECT_LE(std::abs(a.rotaryDeg[1]), 90.0 + 1e-9);
    const Eigen::Matrix4d head = chain.head(a.linearMm, a.rotaryDeg[0]);
    // The tool lies along the workpiece's z axis as the table has turned it.
    const Eigen::Vector3d axis = (head * Eigen::Vector4d(0, 0, 1, 0)).head<3>();
    const Eigen::Vector3d wz = chain.table(a.rotaryDeg[1], p.translation + p.rotation.col(2)) -
                               chain.table(a.rotaryDeg[1], p.translation);
    EXPECT_LT((axis - wz).norm(), 1e-9);
    // Every nominal point q, on the workpiece at R q + t, is where the tool goes for q programmed in
    // the tilted working plane rotated by phi about the tool: CL(q) = head * (Rz(phi) q).
    const Eigen::Matrix3d phi = matching::rotationZyx({0, 0, a.frameRotationDeg * matching::kRadPerDeg});
    for (const Eigen::Vector3d& q : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(100, 0, 0),
                                     Eigen::Vector3d(0, 80, 20), Eigen::Vector3d(-30, 45, -60)}) {
      const Eigen::Vector3d onMachine = chain.table(a.rotaryDeg[1], p.rotation * q + p.translation);
      const Eigen::Vector3d tool = (head * (phi * q).homogeneous()).head<3>();
      EXPECT_LT((onMachine - tool).norm(), 1e-9);
    }
    const Frame f = realisedFrame(m, a);
    EXPECT_LT((f.rotation - p.rotation).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((f.origin - p.translation).norm(), 1e-9);
    EXPECT_LT((f.toolAxis - p.rotation.col(2)).norm(), 1e-12);
  }
}

TEST(Machine, HeadTableHandCases) {
  // Workpiece tilted +10 deg about y at the table centre: the head swivels B = +10 deg, the table
  // stays (C = 0), and the linear axes take the pivot's swing: SX = L sin 10, SZ = L cos 10 - L.
  MachineDefinition m = MachineDefinition::preset(Topology::HeadTable);
  m.pivot = 200.0;
  const double s10 = std::sin(10.0 * M_PI / 180.0), c10 = std::cos(10.0 * M_PI / 180.0);
  Adjustment a =
      adjustmentFor(m, Pose::fromAnglesDeg({0.0, 10.0, 0.0}, {0, 0, 0}).rotation, Eigen::Vector3d::Zero());
  EXPECT_NEAR(a.rotaryDeg[0], 10.0, 1e-12);
  EXPECT_NEAR(a.rotaryDeg[1], 0.0, 1e-12);
  EXPECT_NEAR(a.frameRotationDeg, 0.0, 1e-12);
  EXPECT_NEAR(a.linearMm.x(), 200.0 * s10, 1e-9);
  EXPECT_NEAR(a.linearMm.y(), 0.0, 1e-9);
  EXPECT_NEAR(a.linearMm.z(), 200.0 * c10 - 200.0, 1e-9);
  // The same tilt turned 30 deg about z (R = Rz(30) Ry(10)): the table turns it back, C = -30 deg.
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(30.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
      Eigen::AngleAxisd(10.0 * M_PI / 180.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
  a = adjustmentFor(m, R, Eigen::Vector3d::Zero());
  EXPECT_NEAR(a.rotaryDeg[0], 10.0, 1e-12);
  EXPECT_NEAR(a.rotaryDeg[1], -30.0, 1e-12);
  EXPECT_NEAR(a.frameRotationDeg, 0.0, 1e-12);
  const nlohmann::json j = adjustmentToJson(a);
  EXPECT_TRUE(j.contains("SB_deg"));
  EXPECT_TRUE(j.contains("SC_deg"));
  EXPECT_EQ(j.at("topology"), "head-table");
}

TEST(Machine, LinearTravelLimitsAreReportedAndRoundTrip) {
  MachineDefinition m = MachineDefinition::preset(Topology::Xfyzba);
  EXPECT_FALSE(m.toJson().contains("linear_travel_mm"));  // unlimited by default
  const Pose p = Pose::fromAnglesDeg({0.0, 0.0, 0.0}, {0.5, -2.0, 0.1});
  EXPECT_TRUE(adjustmentFor(m, p.rotation, p.translation).withinTravel);
  m.linearMinMm[1] = -1.0;  // SY = -2 mm is below it
  const Adjustment a = adjustmentFor(m, p.rotation, p.translation);
  EXPECT_FALSE(a.withinTravel);
  EXPECT_NE(a.travelMessage.find("SY = -2"), std::string::npos) << a.travelMessage;
  EXPECT_EQ(a.travelMessage.find("SX"), std::string::npos) << a.travelMessage;
  const nlohmann::json j = m.toJson();
  ASSERT_TRUE(j.contains("linear_travel_mm"));
  EXPECT_TRUE(j["linear_travel_mm"][0][0].is_null());
  EXPECT_EQ(j["linear_travel_mm"][1][0], -1.0);
  const MachineDefinition back = MachineDefinition::fromJson(j, "m.json");
  EXPECT_EQ(back.linearMinMm, m.linearMinMm);
  EXPECT_EQ(back.linearMaxMm, m.linearMaxMm);
  try {
    MachineDefinition::fromJson(
        nlohmann::json::parse(R"({"linear_travel_mm": [[0, 1], [5, -5], [null, null]]})"), "m.json");
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("linear_travel_mm[1]"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("travel of linear axis Y"), std::string::npos) << e.what();
  }
  EXPECT_THROW(MachineDefinition::fromJson(nlohmann::json::parse(R"({"linear_travel_mm": [[0, 1]]})"), "m"),
               ValidationError);
  const MachineDefinition ht =
      MachineDefinition::fromJson(nlohmann::json{{"topology", "head-table"}, {"pivot_mm", 90.5}}, "m");
  EXPECT_EQ(ht.topology, Topology::HeadTable);
  EXPECT_EQ(ht.pivot, 90.5);
  EXPECT_EQ(ht.rotaryMaxDeg[0], 110.0);
}

}  // namespace
}  // namespace metrofit::machine
