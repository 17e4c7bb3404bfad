#pragma once
// Exports of a compensated path (the references Pr of Eq. 15 of the kinematic-compensation paper,
// IEEE Access, kinematic compensation algorithm) for the machine controller: ISO 6983 G-code and a STEP-NC
// Part 21 file.
//
// G-code: a '%' tape frame, a comment header that states the machine model, the errors the path
// compensates and the sign convention, then G21 G90 G17 and one G01 block per point (absolute mm,
// the feed on the first block), M30. Comments use parentheses, so the header text never contains
// any (brackets instead). Coordinates are fixed-point with `decimals` digits; -0 is written as 0.
//
// STEP-NC: an ISO 10303-21 file whose entities follow the ISO 14649-10/-11 information model that
// STEP-NC AP238 adopts (its ARM), as far as a toolpath needs them:
//   PROJECT(its_id, main_workplan, its_workpieces, its_owner, its_release, its_status)
//   WORKPLAN(its_id, its_elements, its_channel, its_setup, its_effect)
//   WORKPIECE(its_id, its_material, global_tolerance, its_rawpiece, its_geometry,
//             its_bounding_geometry, clamping_positions)
//   MACHINING_WORKINGSTEP(its_id, its_secplane, its_feature, its_operation, its_effect)
//   PLANE(name, position), AXIS2_PLACEMENT_3D(name, location, axis, ref_direction), DIRECTION
//   TOOLPATH_FEATURE(its_id, its_workpiece, its_operations, feature_placement)
//   FREEFORM_OPERATION(its_toolpath, its_tool_direction, its_id, retract_plane, start_point,
//                      its_tool, its_technology, its_machine_functions, overcut_length, approach,
//                      retract, its_machining_strategy)
//   TOOLPATH_LIST(its_list)
//   CUTTER_LOCATION_TRAJECTORY(its_priority, its_type, its_speed, its_technology,
//                              its_machine_functions, its_direction, basiccurve, its_toolaxis,
//                              surface_normal, its_contact_type)
//   POLYLINE(name, points), CARTESIAN_POINT(name, coordinates)
// Tool, technology and machine functions are not known here and are unset ($): the file carries
// the geometry of the compensated path; the CAM job supplies the process data. FILE_SCHEMA names
// the ISO 14649 ARM schema, MACHINING_SCHEMA. Reals are written in their shortest round-trip form
// (Part 21 syntax: a '.' always, 'E' for the exponent), so a reader gets the doubles back exactly.
// part21.h reads these files.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/kinematics/cartesian_model.h"
#include "core/kinematics/effects.h"

namespace metrofit {

struct GcodeOptions {
  std::string programName = "compensated path";  ///< parentheses and line breaks are replaced
  double feedMmPerMin = kDefaultFeedMmPerMin;
  int decimals = 4;  ///< 0.1 um

  bool isValid(std::string* why) const;
};

/// G-code for `commands` (the compensated references), stating `errors` in the header.
std::string compensatedPathToGcode(const std::vector<Eigen::Vector2d>& commands,
                                   const ActuatorErrors2& errors, const GcodeOptions& options = {});

struct StepNcOptions {
  std::string fileName = "compensated.p21";       ///< FILE_NAME name
  std::string timestamp = "2000-01-01T00:00:00";  ///< FILE_NAME time_stamp (ISO 8601)
  std::string projectName = "Metrofit compensated path";
  double zMm = 0.0;               ///< z of every path point
  double securityPlaneMm = 50.0;  ///< z of the security plane

  bool isValid(std::string* why) const;
};

/// The STEP-NC Part 21 text (see the header comment).
std::string compensatedPathToStepNc(const std::vector<Eigen::Vector2d>& commands,
                                    const ActuatorErrors2& errors, const StepNcOptions& options = {});

/// A Part 21 REAL in its shortest round-trip form: "1.", "-0.25", "1.5E-07".
std::string part21Real(double value);
/// A Part 21 string literal: quotes doubled, backslashes doubled, characters outside printable
/// ASCII replaced by '?'.
std::string part21String(const std::string& text);

}  // namespace metrofit
