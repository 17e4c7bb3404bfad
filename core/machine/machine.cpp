#include "core/machine/machine.h"
#include "core/common/numformat.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/common/run.h"
#include "core/io/json_util.h"

namespace metrofit::machine {
namespace {

constexpr double kDeg = 0.017453292519943295769236907684886;

Eigen::Matrix3d rotX(double rad) {
  return Eigen::AngleAxisd(rad, Eigen::Vector3d::UnitX()).toRotationMatrix();
}
Eigen::Matrix3d rotY(double rad) {
  return Eigen::AngleAxisd(rad, Eigen::Vector3d::UnitY()).toRotationMatrix();
}
Eigen::Matrix3d rotZ(double rad) {
  return Eigen::AngleAxisd(rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

Eigen::Matrix4d homRot(const Eigen::Matrix3d& R) {
  Eigen::Matrix4d H = Eigen::Matrix4d::Identity();
  H.topLeftCorner<3, 3>() = R;
  return H;
}
Eigen::Matrix4d homTr(const Eigen::Vector3d& v) {
  Eigen::Matrix4d H = Eigen::Matrix4d::Identity();
  H.topRightCorner<3, 1>() = v;
  return H;
}

/// Rotation of the tilt axis: about x for A, about y for B.
Eigen::Matrix3d tiltRotation(Topology t, double rad) {
  return t == Topology::BcTable ? rotY(rad) : rotX(rad);
}

/// Wraps an angle in degrees to (-180, 180].
double wrap180(double deg) {
  double w = std::remainder(deg, 360.0);
  if (w <= -180.0) w += 360.0;
  return w;
}

Eigen::Vector3d vec3(const JsonReader& parent, const std::string& key, const Eigen::Vector3d& fallback) {
  if (!parent.has(key)) return fallback;
  const JsonReader a = parent.array(key);
  if (a.size() != 3) parent.fail("expected an array of 3 numbers", key);
  Eigen::Vector3d v;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& e = a.at(i).json();
    if (!e.is_number() || !std::isfinite(e.get<double>()))
      parent.fail("expected an array of 3 finite numbers", key);
    v(static_cast<Eigen::Index>(i)) = e.get<double>();
  }
  return v;
}

constexpr Topology kTopologies[] = {Topology::Xfyzba, Topology::AcTable, Topology::BcTable,
                                    Topology::HeadTable};

std::string topologyList() {
  std::string s;
  for (Topology t : kTopologies) s += std::string(s.empty() ? "" : ", ") + topologyName(t);
  return s;
}

void checkTravel(const MachineDefinition& m, Adjustment& a) {
  const auto names = rotaryAxisNames(m.topology);
  static constexpr const char* kLinear[3] = {"X", "Y", "Z"};
  for (Eigen::Index i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (a.linearMm(i) < m.linearMinMm[k] - 1e-9 || a.linearMm(i) > m.linearMaxMm[k] + 1e-9) {
      a.withinTravel = false;
      if (!a.travelMessage.empty()) a.travelMessage += "; ";
      a.travelMessage += std::string("S") + kLinear[k] + " = " + num::toString(a.linearMm(i)) +
                         " mm is outside its travel [" + num::toString(m.linearMinMm[k]) + ", " +
                         num::toString(m.linearMaxMm[k]) + "]";
    }
  }
  for (std::size_t i = 0; i < 2; ++i) {
    if (a.rotaryDeg[i] < m.rotaryMinDeg[i] - 1e-9 || a.rotaryDeg[i] > m.rotaryMaxDeg[i] + 1e-9) {
      a.withinTravel = false;
      if (!a.travelMessage.empty()) a.travelMessage += "; ";
      a.travelMessage += std::string(names[i]) + " = " + num::toString(a.rotaryDeg[i]) +
                         " deg is outside its travel [" + num::toString(m.rotaryMinDeg[i]) + ", " +
                         num::toString(m.rotaryMaxDeg[i]) + "]";
    }
  }
}

}  // namespace

const char* topologyName(Topology t) {
  switch (t) {
    case Topology::Xfyzba:
      return "xfyzba";
    case Topology::AcTable:
      return "ac-table";
    case Topology::BcTable:
      return "bc-table";
    case Topology::HeadTable:
      return "head-table";
  }
  return "?";
}

std::vector<std::string> topologyNames() {
  return {"xfyzba", "ac-table", "bc-table", "head-table"};
}

Topology parseTopology(const std::string& name, const std::string& field) {
  for (Topology t : kTopologies) {
    if (name == topologyName(t)) return t;
  }
  throw OptionsError(ErrorContext{{}, 0, 0, field},
                     "unknown machine topology '" + name + "' (one of " + topologyList() + ")");
}

std::array<const char*, 2> rotaryAxisNames(Topology t) {
  switch (t) {
    case Topology::Xfyzba:
      return {"A", "B"};
    case Topology::AcTable:
      return {"A", "C"};
    case Topology::BcTable:
    case Topology::HeadTable:
      return {"B", "C"};
  }
  return {"?", "?"};
}

bool MachineDefinition::isValid(std::string* why) const {
  auto no = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  for (double v : {lx, ly, lz, lab, pivot}) {
    if (!std::isfinite(v)) return no("pivot lengths LX, LY, LZ, LAB and pivot_mm must be finite");
  }
  for (std::size_t i = 0; i < 3; ++i) {
    if (std::isnan(linearMinMm[i]) || std::isnan(linearMaxMm[i]) || linearMinMm[i] == kUnlimited ||
        linearMaxMm[i] == -kUnlimited || linearMinMm[i] > linearMaxMm[i])
      return no(std::string("travel of linear axis ") + "XYZ"[i] + " must have min <= max");
  }
  if (!tiltAxisPoint.allFinite() || !rotaryAxisPoint.allFinite()) return no("axis points must be finite");
  for (std::size_t i = 0; i < 2; ++i) {
    if (!std::isfinite(rotaryMinDeg[i]) || !std::isfinite(rotaryMaxDeg[i]) ||
        rotaryMinDeg[i] > rotaryMaxDeg[i])
      return no(std::string("travel of rotary axis ") + rotaryAxisNames(topology)[i] +
                " must be finite with min <= max");
  }
  return true;
}

nlohmann::json MachineDefinition::toJson() const {
  nlohmann::json j;
  j["topology"] = topologyName(topology);
  j["LX_mm"] = lx;
  j["LY_mm"] = ly;
  j["LZ_mm"] = lz;
  j["LAB_mm"] = lab;
  j["tilt_axis_point_mm"] = {tiltAxisPoint.x(), tiltAxisPoint.y(), tiltAxisPoint.z()};
  j["rotary_axis_point_mm"] = {rotaryAxisPoint.x(), rotaryAxisPoint.y(), rotaryAxisPoint.z()};
  j["pivot_mm"] = pivot;
  j["rotary_travel_deg"] = {{rotaryMinDeg[0], rotaryMaxDeg[0]}, {rotaryMinDeg[1], rotaryMaxDeg[1]}};
  bool limited = false;
  nlohmann::json linear = nlohmann::json::array();
  for (std::size_t i = 0; i < 3; ++i) {
    auto bound = [&](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
    limited = limited || std::isfinite(linearMinMm[i]) || std::isfinite(linearMaxMm[i]);
    linear.push_back({bound(linearMinMm[i]), bound(linearMaxMm[i])});
  }
  if (limited) j["linear_travel_mm"] = std::move(linear);
  return j;
}

MachineDefinition MachineDefinition::fromJson(const nlohmann::json& j, const std::string& source) {
  const JsonReader r(j, source);
  r.requireObject();
  MachineDefinition m;
  if (r.has("topology")) {
    const std::string name = r.string("topology");
    bool known = false;
    for (Topology t : kTopologies) {
      if (name == topologyName(t)) {
        m = preset(t);
        known = true;
      }
    }
    if (!known) r.fail("unknown machine topology '" + name + "' (one of " + topologyList() + ")", "topology");
  }
  m.lx = r.number("LX_mm", m.lx);
  m.ly = r.number("LY_mm", m.ly);
  m.lz = r.number("LZ_mm", m.lz);
  m.lab = r.number("LAB_mm", m.lab);
  m.tiltAxisPoint = vec3(r, "tilt_axis_point_mm", m.tiltAxisPoint);
  m.rotaryAxisPoint = vec3(r, "rotary_axis_point_mm", m.rotaryAxisPoint);
  m.pivot = r.number("pivot_mm", m.pivot);
  if (r.has("linear_travel_mm")) {
    const JsonReader a = r.array("linear_travel_mm");
    const char* shape = "expected [[min, max], [min, max], [min, max]] for X, Y, Z (null: no limit)";
    if (a.size() != 3) r.fail(shape, "linear_travel_mm");
    for (std::size_t i = 0; i < 3; ++i) {
      const auto& e = a.at(i).json();
      if (!e.is_array() || e.size() != 2) r.fail(shape, "linear_travel_mm");
      for (std::size_t k = 0; k < 2; ++k) {
        if (e[k].is_null()) continue;
        if (!e[k].is_number() || !std::isfinite(e[k].get<double>())) r.fail(shape, "linear_travel_mm");
        (k == 0 ? m.linearMinMm : m.linearMaxMm)[i] = e[k].get<double>();
      }
      if (!(m.linearMinMm[i] <= m.linearMaxMm[i]))
        a.at(i).fail(std::string("travel of linear axis ") + "XYZ"[i] + " must have min <= max");
    }
  }
  if (r.has("rotary_travel_deg")) {
    const JsonReader a = r.array("rotary_travel_deg");
    if (a.size() != 2) r.fail("expected [[min, max], [min, max]]", "rotary_travel_deg");
    for (std::size_t i = 0; i < 2; ++i) {
      const auto& e = a.at(i).json();
      if (!e.is_array() || e.size() != 2 || !e[0].is_number() || !e[1].is_number())
        r.fail("expected [[min, max], [min, max]]", "rotary_travel_deg");
      m.rotaryMinDeg[i] = e[0].get<double>();
      m.rotaryMaxDeg[i] = e[1].get<double>();
      if (!(m.rotaryMinDeg[i] <= m.rotaryMaxDeg[i]))
        a.at(i).fail(std::string("travel of rotary axis ") + rotaryAxisNames(m.topology)[i] +
                     " must be finite with min <= max");
    }
  }
  std::string why;
  if (!m.isValid(&why)) r.fail(why);
  return m;
}

MachineDefinition MachineDefinition::preset(Topology t) {
  MachineDefinition m;
  m.topology = t;
  if (t == Topology::Xfyzba) {
    m.rotaryMinDeg = {-95.0, -180.0};  // A tilts the spindle, B swivels it
    m.rotaryMaxDeg = {95.0, 180.0};
  } else if (t == Topology::HeadTable) {
    m.rotaryMinDeg = {-110.0, -360.0};  // B swivel head, endless C table within one turn each way
    m.rotaryMaxDeg = {110.0, 360.0};
  } else {
    m.rotaryMinDeg = {-120.0, -360.0};  // trunnion tilt, endless C within one turn each way
    m.rotaryMaxDeg = {120.0, 360.0};
  }
  return m;
}

void headHeadForward(const MachineDefinition& m, const Eigen::Vector3d& S, double saDeg, double sbDeg,
                     Eigen::Vector3d* cutterLocation, Eigen::Vector3d* toolAxis) {
  const Eigen::Matrix4d chain = homTr({S.x() - m.lx, S.y() - m.ly, S.z() - m.lz - m.lab}) *
                                homRot(rotY(sbDeg * kDeg)) * homTr({0.0, 0.0, m.lab}) *
                                homRot(rotX(saDeg * kDeg)) * homTr({m.lx, m.ly, m.lz});
  if (cutterLocation) *cutterLocation = (chain * Eigen::Vector4d(0, 0, 0, 1)).head<3>();
  if (toolAxis) *toolAxis = (chain * Eigen::Vector4d(0, 0, 1, 0)).head<3>();
}

Eigen::Vector3d tableToMachine(const MachineDefinition& m, double tiltDeg, double cDeg,
                               const Eigen::Vector3d& x) {
  const Eigen::Vector3d& a0 = m.tiltAxisPoint;
  const Eigen::Vector3d& c0 = m.rotaryAxisPoint;
  return a0 + tiltRotation(m.topology, tiltDeg * kDeg) * (c0 - a0 + rotZ(cDeg * kDeg) * (x - c0));
}

void headTableForward(const MachineDefinition& m, const Eigen::Vector3d& S, double bDeg,
                      Eigen::Vector3d* cutterLocation, Eigen::Vector3d* toolAxis) {
  const Eigen::Matrix3d head = rotY(bDeg * kDeg);
  const Eigen::Vector3d pivot(0.0, 0.0, m.pivot);
  if (cutterLocation) *cutterLocation = S + pivot - head * pivot;
  if (toolAxis) *toolAxis = head * Eigen::Vector3d::UnitZ();
}

Adjustment adjustmentFor(const MachineDefinition& m, const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  requireValid(m, "machine definition");
  if (!R.allFinite() || !t.allFinite() || std::abs(R.determinant() - 1.0) > 1e-6 ||
      !(R.transpose() * R).isApprox(Eigen::Matrix3d::Identity(), 1e-6)) {
    throw std::invalid_argument("machine adjustment: the posture rotation is not a proper rotation");
  }
  Adjustment a;
  a.topology = m.topology;
  const Eigen::Vector3d c = R.col(2);
  if (m.topology == Topology::Xfyzba) {
    // Eq. (12): c = (sin SB cos SA, -sin SA, cos SB cos SA).
    const double sa = std::asin(std::clamp(-c.y(), -1.0, 1.0));
    const double sb = std::atan2(c.x(), c.z());
    const Eigen::Matrix3d head = rotY(sb) * rotX(sa);
    const Eigen::Matrix3d rest = head.transpose() * R;
    a.rotaryDeg = {sa / kDeg, sb / kDeg};
    a.frameRotationDeg = std::atan2(rest(1, 0), rest(0, 0)) / kDeg;
    // Eq. (13) solved for the linear axes.
    a.linearMm = t + Eigen::Vector3d(m.lx, m.ly, m.lz + m.lab) -
                 rotY(sb) * (Eigen::Vector3d(0.0, 0.0, m.lab) + rotX(sa) * Eigen::Vector3d(m.lx, m.ly, m.lz));
  } else if (m.topology == Topology::HeadTable) {
    // c = (cos C sin B, -sin C sin B, cos B).
    const double sB = std::hypot(c.x(), c.y());
    double b = std::atan2(sB, c.z());  // in [0, pi]
    double rot = 0.0;
    if (sB > 1e-15) {
      rot = std::atan2(-c.y(), c.x());
      if (std::abs(rot) > std::numbers::pi / 2.0) {  // (-B, C + 180 deg) keeps |C| <= 90 deg
        b = -b;
        rot = rot > 0.0 ? rot - std::numbers::pi : rot + std::numbers::pi;
      }
    }
    const Eigen::Matrix3d head = rotY(b);
    const Eigen::Matrix3d rest = head.transpose() * rotZ(rot) * R;
    a.rotaryDeg = {b / kDeg, rot / kDeg};
    a.frameRotationDeg = std::atan2(rest(1, 0), rest(0, 0)) / kDeg;
    const Eigen::Vector3d& c0 = m.rotaryAxisPoint;
    const Eigen::Vector3d pivot(0.0, 0.0, m.pivot);
    a.linearMm = c0 + rotZ(rot) * (t - c0) - pivot + head * pivot;
  } else {
    const double sT = std::hypot(c.x(), c.y());
    double tilt = std::atan2(sT, c.z());  // in [0, pi]
    double rot = 0.0;
    if (sT > 1e-15) {
      rot = m.topology == Topology::AcTable ? std::atan2(c.x(), c.y()) : std::atan2(c.y(), -c.x());
      // The other solution (-T, C + 180 deg) when it keeps |C| <= 90 deg.
      if (std::abs(rot) > std::numbers::pi / 2.0) {
        tilt = -tilt;
        rot = rot > 0.0 ? rot - std::numbers::pi : rot + std::numbers::pi;
      }
    }
    const Eigen::Matrix3d Q = tiltRotation(m.topology, tilt) * rotZ(rot);
    const Eigen::Matrix3d rest = Q * R;
    a.rotaryDeg = {tilt / kDeg, rot / kDeg};
    a.frameRotationDeg = std::atan2(rest(1, 0), rest(0, 0)) / kDeg;
    a.linearMm = tableToMachine(m, a.rotaryDeg[0], a.rotaryDeg[1], t);
  }
  a.frameRotationDeg = wrap180(a.frameRotationDeg);
  checkTravel(m, a);
  return a;
}

Frame realisedFrame(const MachineDefinition& m, const Adjustment& v) {
  requireValid(m, "machine definition");
  Frame f;
  const Eigen::Matrix3d phi = rotZ(v.frameRotationDeg * kDeg);
  if (m.topology == Topology::Xfyzba) {
    headHeadForward(m, v.linearMm, v.rotaryDeg[0], v.rotaryDeg[1], &f.origin, &f.toolAxis);
    f.rotation = rotY(v.rotaryDeg[1] * kDeg) * rotX(v.rotaryDeg[0] * kDeg) * phi;
  } else if (m.topology == Topology::HeadTable) {
    // Machine -> table coordinates: x = c0 + Rz(C)^T (M - c0).
    const Eigen::Matrix3d Rz = rotZ(v.rotaryDeg[1] * kDeg);
    const Eigen::Matrix3d head = rotY(v.rotaryDeg[0] * kDeg);
    const Eigen::Vector3d& c0 = m.rotaryAxisPoint;
    Eigen::Vector3d cl, axis;
    headTableForward(m, v.linearMm, v.rotaryDeg[0], &cl, &axis);
    f.origin = c0 + Rz.transpose() * (cl - c0);
    f.rotation = Rz.transpose() * head * phi;
    f.toolAxis = Rz.transpose() * axis;
  } else {
    const Eigen::Matrix3d Q = tiltRotation(m.topology, v.rotaryDeg[0] * kDeg) * rotZ(v.rotaryDeg[1] * kDeg);
    // Invert M(x) = a0 + Q' (c0 - a0 + Rz (x - c0)) for the machine point S.
    const Eigen::Vector3d& a0 = m.tiltAxisPoint;
    const Eigen::Vector3d& c0 = m.rotaryAxisPoint;
    const Eigen::Matrix3d T = tiltRotation(m.topology, v.rotaryDeg[0] * kDeg);
    const Eigen::Matrix3d Rz = rotZ(v.rotaryDeg[1] * kDeg);
    f.origin = c0 + Rz.transpose() * (T.transpose() * (v.linearMm - a0) + a0 - c0);
    f.rotation = Q.transpose() * phi;
    f.toolAxis = Q.transpose() * Eigen::Vector3d::UnitZ();
  }
  return f;
}

nlohmann::json adjustmentToJson(const Adjustment& a) {
  nlohmann::json j;
  const auto names = rotaryAxisNames(a.topology);
  j["topology"] = topologyName(a.topology);
  j["SX_mm"] = a.linearMm.x();
  j["SY_mm"] = a.linearMm.y();
  j["SZ_mm"] = a.linearMm.z();
  j[std::string("S") + names[0] + "_deg"] = a.rotaryDeg[0];
  j[std::string("S") + names[1] + "_deg"] = a.rotaryDeg[1];
  j["frame_rotation_deg"] = a.frameRotationDeg;
  j["within_travel"] = a.withinTravel;
  if (!a.withinTravel) j["travel_message"] = a.travelMessage;
  return j;
}

}  // namespace metrofit::machine
