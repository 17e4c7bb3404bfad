#pragma once
// What the kinematics views and the report show of a circular test (IEEE Access, kinematic compensation
// algorithm; docs/file-formats.md#circular-test): the nominal circle, the radial deviations of the measured
// path per loop (CCW / CW), the compensated references for the nominal circle and what they are expected to
// give. Plain C++ on top of core/kinematics; no Qt, so the page, the report and the tests share it.
//
// Nominal circle: centre = mean of the commanded points, radius = mean distance of the commanded
// points from it (the commands of a circular test lie on the circle). A radial-only test (the ballbar
// form, docs/file-formats.md#circular-test) is already about its nominal circle: centre (0, 0), radius
// its radius_mm column (0 when it has none; the radial deviations do not need it).
// ISO 230-4 results (G, H, F per direction): core/kinematics/iso230_4.h, on every test.
// Ballbar breakdown into named causes (core/kinematics/ballbar.h, default options as `metrofit-cli
// kinematic identify` without --screw-pitch): x/y tests whose commands are one full circle.
// Radial deviation of a point p: |p - centre| - radius (mm), at the angle of p about the centre.
// Loops: a point belongs to a CCW loop when the command turns counter-clockwise about the centre
// from it to the next point (the last point takes its predecessor's direction); consecutive points
// of one direction form a loop.
//
// Compensation preview (the nominal circle = the commanded points of the test):
//   references   r_k = compensatePath(identified machine, c_k)        (Eq. 15)
//   model        runPath(identified machine, r_k)                     (= c_k up to rounding)
//   expected     p_k + [ir jr] (r_k - c_k): the measured path moved by what the new references change
//                through the identified axes, so the residual the model does not explain (noise,
//                unmodelled effects) stays in (a prediction of the next circular test)
//   simulated    when the machine is known (a simulated test): the references run through the true
//                machine, noise free
// Each with its largest |radial deviation|.
//
// With applied effects (core/diagnose/applied_kinematic.h: backlash, scale, cyclic, servo lag added
// with Apply on the diagnosis page) the model is P = o + [ir jr] je(c): the references solve
// model(r_k) = c_k (compensatePathWithEffects), and the expected path is p_k + model(r_k) - model(c_k)
// (the same as above for the declared model, which is linear in c), so the residual the model with
// the effects does not explain stays. The motion of every point (backlash direction, servo-lag
// tangent) is the nominal path's.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/diagnose/applied_kinematic.h"
#include "core/kinematics/ballbar.h"
#include "core/kinematics/cartesian_model.h"
#include "core/kinematics/identification.h"
#include "core/kinematics/iso230_4.h"
#include "core/kinematics/measured_path.h"

namespace metrofit {

struct RadialPoint {
  double angleDeg = 0.0;     ///< angle of the point about the centre, [0, 360)
  double deviationMm = 0.0;  ///< |p - centre| - radius
};

struct CircularLoop {
  bool counterClockwise = true;
  std::size_t first = 0;  ///< index of the loop's first point in the path
  std::vector<RadialPoint> points;
};

struct CircularAnalysis {
  Eigen::Vector2d centreMm = Eigen::Vector2d::Zero();
  double radiusMm = 0.0;
  std::vector<CircularLoop> loops;  ///< of the measured path
  double maxAbsDeviationMm = 0.0;   ///< over all measured points
  double minDeviationMm = 0.0, maxDeviationMm = 0.0;
  bool radialOnly = false;  ///< a radial-only test: no x/y, no identification
  Iso230Result iso;         ///< ISO 230-4 results
  /// The ballbar breakdown (analyseCircularTest only); absent with the reason in ballbarUnavailable.
  std::optional<BallbarBreakdown> ballbar;
  std::string ballbarUnavailable;
};

/// The InputError of checkIdentifiable (core/kinematics/identification.h: the checks of `metrofit-cli
/// kinematic identify`) when the path cannot be identified; ValidationError (field x_cmd_mm) when the
/// commanded points have no radius.
CircularAnalysis analyseCircularTest(const MeasuredPath& path);
/// Any circular test (the x/y form through circularTraceOf, or a radial-only one): the loops, the radial
/// deviations and the ISO 230-4 results. ValidationError for fewer than 3 points.
CircularAnalysis analyseCircularTrace(const CircularTrace& trace);

/// Radial deviations of points about a circle.
std::vector<RadialPoint> radialDeviations(const std::vector<Eigen::Vector2d>& points,
                                          const Eigen::Vector2d& centreMm, double radiusMm);
/// Largest |radial deviation| of points about a circle (0 for no points).
double maxAbsRadialDeviation(const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& centreMm,
                             double radiusMm);

struct CompensationPreview {
  std::vector<Eigen::Vector2d> nominal;     ///< c_k
  std::vector<Eigen::Vector2d> references;  ///< r_k
  std::vector<Eigen::Vector2d> model;       ///< identified machine run with r_k
  std::vector<Eigen::Vector2d> expected;    ///< measured path moved by the correction
  std::vector<Eigen::Vector2d> simulated;   ///< true machine run with r_k (empty when unknown)
  double maxBeforeMm = 0.0;                 ///< measured path
  double maxModelMm = 0.0;
  double maxExpectedMm = 0.0;
  double rmsBeforeMm = 0.0;    ///< RMS of |p_k - c_k| (measured path against the nominal points)
  double rmsExpectedMm = 0.0;  ///< RMS of |expected_k - c_k|: the identification's residual rmse
  std::optional<double> maxSimulatedMm;
  double largestCorrectionMm = 0.0;  ///< max |r_k - c_k|
};

/// `effects`: applied effects the model includes (nullptr or empty: the declared model).
CompensationPreview previewCompensation(const MeasuredPath& path, const CircularAnalysis& analysis,
                                        const ActuatorErrors2& identified,
                                        const std::optional<ActuatorErrors2>& trueMachine = std::nullopt,
                                        const AxisEffects* effects = nullptr);

}  // namespace metrofit
