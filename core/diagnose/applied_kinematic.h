#pragma once
// Effects of the axes added to the declared Cartesian model ("Apply adds the accepted effect
// to the study's model so later runs and compensations include it").
//
// The closed loop (core/diagnose/kinematic_diagnosis.h) finds effects that act on the joint
// coordinates before the machine's geometry, exactly as the simulator's (core/sim/effects_kinematic.h):
//   je = effective joints(c) = c (1 + s 1e-6) - d b / 2 - tau v t + [cyclic] A sin(2 pi c_a / p + phi)
//   P  = o + ir(a) je_x + jr(b) je_y
// The diagnosis page's Apply stores them (studies.diagnosis.kinematic.applied, names of
// docs/file-formats.md#effect-catalogue):
//   [{"name": "backlash", "parameters": {"x_mm": 0.008, "y_mm": 0.005}},
//    {"name": "scale", "parameters": {"x_ppm": 20, "y_ppm": -10}},
//    {"name": "cyclic", "parameters": {"axis": "x", "period_mm": 5, "amplitude_mm": 0.002,
//                                      "phase_deg": 30}},
//    {"name": "servo_lag", "parameters": {"tau_s": 0.002}},    (lag at the test's feed)
//    {"name": "unexplained:angle", "parameters": {...}, "shape": {...}, "coefficients": [...]}]
// A generic effect (docs/file-formats.md#generic-effects) is a displacement D_k of every point, the basis of
// its shape (applied_entries.h genericShapeJson) on the path variable it names (path_variables.h)
// times its coefficients: P = o + ir je_x + jr je_y + D_k. Identification then fits the measured
// points minus D_k, and compensation aims at N_k - D_k.
// With the effects fixed at these values the model is the declared one in the effective joints, so
//  * identification: the declared o, a, b are identified (identification.h, unchanged) from the path
//    whose commands are replaced by their effective joints (withEffectiveJoints); the residual is
//    (and the measured points moved by -D_k); the residual is then the one the diagnosis reports
//    after adding the effects;
//  * compensation: the references r_k must satisfy o + [ir jr] je(r_k) + D_k = N_k, i.e.
//    je(r_k) = [ir jr]^-1 (N_k - D_k - o) (Eq. 15); r_k is found by the fixed-point iteration
//    r <- r + (q - je(r)) (je is the identity plus terms of size 1e-3 and slopes far below 1), with
//    the direction and tangent of every point from the nominal path (pathMotion).
// Errors (ValidationError, field "<field>[i].name" or "<field>[i].parameters.<key>"): an entry that
// is not an object, a missing or unknown name, an effect given twice (cyclic: twice on one axis), a
// missing or non-finite parameter, a cyclic axis other than "x" / "y", a period not above 0; a generic
// effect of another variable than row, angle, direction, reversal, x, y, a bad shape (field
// "<field>[i].shape.<key>") or coefficients that are not one finite number per basis column.
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "core/diagnose/residual_check.h"
#include "core/kinematics/cartesian_model.h"
#include "core/kinematics/effects.h"
#include "core/kinematics/measured_path.h"

namespace metrofit {

/// Where the diagnosis page stores the applied kinematic effects (the field errors name).
inline constexpr const char* kKinematicAppliedField = "studies.diagnosis.kinematic.applied";

/// One cyclic error term A sin(2 pi c_axis / period + phase) on an axis.
struct CyclicTerm {
  int axis = 0;  ///< 0: x, 1: y
  double periodMm = 1.0;
  double amplitudeMm = 0.0;
  double phaseDeg = 0.0;
};

/// An applied generic effect `unexplained:<against>` (docs/file-formats.md#generic-effects): a displacement
/// of every point, genericBasis(shape) w on the path variable `against` (path_variables.h; x and y as two
/// components), with w as the diagnosis estimated it.
struct GenericDisplacement {
  diagnose::GenericForm shape;
  std::vector<double> coefficients;  ///< w, one per basis column (mm)
};

/// The applied effects (see the header comment).
struct AxisEffects {
  KinematicEffects base;           ///< backlash, scale, servo lag, feed; its own cyclic amplitude stays 0
  std::vector<CyclicTerm> cyclic;  ///< at most one per axis
  std::vector<GenericDisplacement> generic;  ///< at most one per variable
  std::vector<std::string> labels;           ///< per applied entry, e.g. "backlash (x 8 um, y 5 um)"

  bool empty() const { return labels.empty(); }
  /// The labels joined with ", ".
  std::string text() const;
  /// The joint coordinates the axes reach for command `c` (direction d, unit tangent t of the motion).
  Eigen::Vector2d effectiveJoints(const Eigen::Vector2d& c, const Eigen::Vector2d& d,
                                  const Eigen::Vector2d& t) const;
  /// The generic effects' displacement of every point of the path `commands` (zero without any).
  std::vector<Eigen::Vector2d> displacement(const std::vector<Eigen::Vector2d>& commands) const;
};

/// Reads an applied list (see the header comment); `feedMmPerMin` is the feed of the test the
/// servo lag was found on. An empty or null list gives no effects.
AxisEffects axisEffectsFromApplied(const nlohmann::json& applied, double feedMmPerMin = kDefaultFeedMmPerMin,
                                   const std::string& field = kKinematicAppliedField);

/// The path with every command replaced by its effective joints (motion from the commands).
MeasuredPath withEffectiveJoints(const MeasuredPath& path, const AxisEffects& effects);

/// The modelled machine with the effects run with `commands`; the motion of every point from `motionOf`
/// (the nominal path; empty: the commands themselves).
std::vector<Eigen::Vector2d> runPathWithEffects(const CartesianMachine2& machine, const AxisEffects& effects,
                                                const std::vector<Eigen::Vector2d>& commands,
                                                const std::vector<Eigen::Vector2d>& motionOf = {});

/// Compensated references: forward(je(r_k)) = N_k for every nominal point (see the header comment).
std::vector<Eigen::Vector2d> compensatePathWithEffects(const CartesianMachine2& machine,
                                                       const AxisEffects& effects,
                                                       const std::vector<Eigen::Vector2d>& nominal);

// The effects a project applies to a circular test (studies.diagnosis.kinematic: applied, dataset,
// feed_mm_per_min) are read in core/study (kinematic_study.h projectAxisEffects) through the settings'
// one owner, DiagnosisDomainSettings; this module only reads the list it is given.

}  // namespace metrofit
