#pragma once
// Geometric element fitting (issue 30): plane, line, circle (in a 3D plane), sphere, cylinder, cone
// fitted to measured points, by least squares or minimum zone, free or of a fixed (calibrated) radius,
// optionally robust to stray points.
//
// Residuals (signed distances, mm, positive outside the material-free side named below):
//   plane     d = n . (p - c)                                 (positive along the normal n)
//   line      d = |(p - c) x u|                               (>= 0: distance from the line)
//   circle    d = rho - r, rho = |(p - c) - ((p - c).n) n|    (radial, in the circle's plane)
//   sphere    d = |p - c| - r
//   cylinder  d = |(p - c) x u| - r
//   cone      d = (rho - r - h tan a) cos a, h = (p - c).u, rho = |(p - c) - h u|   (orthogonal)
// where c is `centre`, n / u is `axis` (the cone's axis points towards the opening, a = half angle).
// The circle is the ISO 10360-6 / CMM form: its plane is the least-squares plane of the points and the
// residual is the radial one within it (as a CMM reports roundness); the other elements use the full
// orthogonal distance. form = max d - min d over the fitted points (the line: 2 max d, the diameter
// of the cylindrical straightness zone); rmse = sqrt(mean d^2) over the fitted points.
//
// Least squares (Gauss / orthogonal distance regression, A. B. Forbes, "Least-squares best-fit
// geometric elements", NPL report DITC 140/89, 1989; ISO 10360-6 Annex B): minimise sum d_i^2 with the
// shared Levenberg-Marquardt solver (core/optim/least_squares.h, forward-difference Jacobian), in a
// local frame (origin = centroid, z = the start axis) with the axis direction parametrised as
// (a, b, 1)/|(a, b, 1)|. Starts: the SVD plane / line of the centred points (these are already the
// exact orthogonal least-squares plane and line), the algebraic (Kasa) circle and sphere
// (linear least squares of |p|^2 = 2 c.p + k), and for the cylinder and the cone each of the three
// SVD axes with the algebraic circle of the projected points (the cone's radius and angle by a
// linear fit of rho against h); the lowest cost wins.
//
// Minimum zone (Chebyshev, the ISO 1101 default): minimise max |d_i| over the element's parameters
// (the radius or the plane offset free, so this is the narrowest zone max d - min d; with a fixed
// radius it is the smallest max |d - 0|). Sequential linear programming with a trust region
// (K. Madsen, IMA J. Appl. Math. 16, 1975), each LP
//   minimise t  subject to  -t <= d_i + g_i . dx <= t   (line: d_i + g_i . dx <= t),  |dx_j| <= Delta,
// solved by GLPK's simplex, g_i by central differences; started from the least-squares fit. The
// certificate (MinimaxCertificate) is the LP's own optimality proof at the final point, with the box
// widened so that it does not bind: GLPK's row duals lambda_i >= 0 (sum 1) on the contact points
// and sum lambda_i s_i g_i = 0 (s_i = +1 outer / -1 inner contact). That is the first-order
// (Kuhn-Tucker) condition of the minimax problem: no parameter change lowers the largest deviation to
// first order (a local minimum zone; for the linearised problem a global one, by LP duality).
//
// Fixed radius (sphere, circle, cylinder): r is not a parameter. Robust: first the least trimmed
// squares concentration of P. J. Rousseeuw and K. Van Driessen ("Computing LTS regression for large
// data sets", 2006): refit on the half of the points with the smallest |d| until that half stops
// changing; then, iterated until the set stops changing (at most robustMaxRounds), a point is
// excluded when |d_i - median| > k * 1.4826 * MAD (k = robustK, default 3.5, the modified z-score
// limit of Iglewicz and Hoaglin; MAD and median over the points kept in the previous round; nothing
// within robustFloorMm, 1 um, of the element is excluded). Excluded points still get a residual from
// the final element.
//
// Standard errors: Cov = s^2 (J^T J)^-1 at the least-squares solution, s^2 = sum d^2 / (m - k),
// propagated to the reported centre, axis, radius and half angle by differences (a circle's are those
// of its in-plane fit, given its plane). Condition: the noise
// amplification A = sqrt(m) / sigma_min(J_s), J_s the Jacobian with rotations scaled by the RMS
// radius of the points (so every parameter is in mm): a parameter combination moves A / sqrt(m) times
// the point noise. Measured on evenly spread sphere points (element_fit_test): a full sphere gives
// A = 2.0, a hemisphere 3.4, a 60 deg cap 7.5, a 30 deg cap 30, a 10 deg cap 270. A <=
// kWellConditionedAmplification (about a hemisphere or better) is "well conditioned", up to
// kBadConditionAmplification "weakly conditioned", above it "badly conditioned"; the text names the
// parameter that is worst determined (the smallest singular vector's largest component) and the angular
// coverage of the points (a sphere cap's half angle, the arc of a circle or cylinder).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/run.h"

namespace metrofit::geometry {

enum class ElementKind { Plane, Line, Circle, Sphere, Cylinder, Cone };
enum class FitCriterion { LeastSquares, Minimax };

/// "plane", "line", "circle", "sphere", "cylinder", "cone".
const char* toString(ElementKind kind);
/// "ls", "minimax".
const char* toString(FitCriterion criterion);
/// The names above; false for anything else.
bool parseElementKind(std::string_view text, ElementKind* kind);
bool parseFitCriterion(std::string_view text, FitCriterion* criterion);
/// True for the elements that take a fixed radius (sphere, circle, cylinder).
bool takesFixedRadius(ElementKind kind);
/// Fewest points that determine the element (with a fixed radius one fewer).
std::size_t minimumPoints(ElementKind kind, bool fixedRadius);

/// Noise amplification up to which a fit is well conditioned, and above which it is badly
/// conditioned (see the header); in between it is weakly conditioned.
inline constexpr double kWellConditionedAmplification = 4.0;
inline constexpr double kBadConditionAmplification = 10.0;

struct ElementFitOptions {
  ElementKind element = ElementKind::Sphere;
  FitCriterion criterion = FitCriterion::LeastSquares;
  double fixedRadiusMm = 0.0;  ///< > 0: the radius is fixed (sphere, circle, cylinder only)
  bool robust = false;
  double robustK = 3.5;  ///< > 0
  /// The exclusion threshold is never below this (mm): a point within 1 µm of the element (a CMM's
  /// print resolution) is not a stray, however small the MAD of nearly exact data is.
  double robustFloorMm = 0.001;
  int robustMaxRounds = 20;        ///< >= 1
  long maxIterations = 200;        ///< Levenberg-Marquardt iterations per fit, >= 1
  int minimaxMaxIterations = 200;  ///< LP iterations, >= 1
  bool keepTrace = false;

  bool isValid(std::string* why) const;
};

/// A fitted element in the input coordinates (mm). See the header for each kind's meaning.
struct FittedElement {
  ElementKind kind = ElementKind::Sphere;
  /// plane, line, cylinder: the foot of the points' centroid on the element (axis); circle, sphere:
  /// the centre; cone: the point of the axis at the height of the centroid.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  /// Unit normal (plane, circle) or axis direction (line, cylinder; cone towards the opening); its
  /// largest component is positive except for the cone. Zero for a sphere.
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();
  double radiusMm = 0.0;      ///< circle, sphere, cylinder; cone: at `centre`; 0 for plane and line
  double halfAngleRad = 0.0;  ///< cone only
  Eigen::Vector3d apex = Eigen::Vector3d::Zero();  ///< cone only
};

/// The signed residual of p for the element (the header's formulas).
double elementResidual(const FittedElement& element, const Eigen::Vector3d& p);

struct ContactPoint {
  std::size_t index = 0;    ///< 0-based input index
  int side = 0;             ///< +1: on the outer (upper) zone boundary, -1: on the inner (lower) one
  double multiplier = 0.0;  ///< LP dual lambda_i >= 0
};

/// The minimum-zone certificate (see the header).
struct MinimaxCertificate {
  bool holds = false;
  std::vector<ContactPoint> contacts;
  double maxAbsMm = 0.0;             ///< max |d| at the final element (exact, not from the LP)
  double lpOptimumMm = 0.0;          ///< the LP's optimum t* at the final linearisation (box not binding)
  double predictedDecreaseMm = 0.0;  ///< maxAbs - t*: 0 (to rounding) when no direction improves
  double multiplierSum = 0.0;        ///< sum of lambda (1 when the duals are consistent)
  double stationarity = 0.0;         ///< |sum lambda_i s_i g_i|_inf (mm per mm of parameter change)
  double minMultiplier = 0.0;        ///< smallest lambda over the contact rows
  std::string meaning;               ///< what was checked, in words
};

struct NamedStandardError {
  std::string name;  ///< "centre_x_mm", ..., "axis_x", ..., "radius_mm", "half_angle_deg"
  double value = 0.0;
};

struct ElementFitResult {
  FittedElement element;
  FitCriterion criterion = FitCriterion::LeastSquares;
  bool fixedRadius = false;
  double formMm = 0.0;  ///< max d - min d over the fitted points (line: 2 max d)
  double rmseMm = 0.0;  ///< over the fitted points
  double maxAbsMm = 0.0;
  std::vector<double> residualsMm;    ///< every input point, input order (excluded ones too)
  std::vector<std::size_t> excluded;  ///< 0-based input indices left out by the robust rule
  double robustThresholdMm = 0.0;     ///< k * 1.4826 * MAD of the last robust round (0 if not robust)
  /// Standard errors of the least-squares fit on the fitted points (also given for minimax, as the
  /// least-squares fit's); empty when there are no degrees of freedom.
  std::vector<NamedStandardError> standardErrors;
  double noiseAmplification = 0.0;
  double coverageDeg = 0.0;  ///< sphere: cap half angle; circle, cylinder, cone: arc covered around the axis
  bool wellConditioned = true;  ///< noiseAmplification <= kWellConditionedAmplification
  /// One line: "well conditioned: ...", "weakly conditioned: ..." or "badly conditioned: ...".
  std::string condition;
  std::optional<MinimaxCertificate> certificate;  ///< minimax only
  int lpSolves = 0;
  RunInfo run;
};

/// The foot of a point on an element and the element's unit normal there: p = point + d * normal with
/// d = elementResidual(element, p). The normal points the way the residual grows: along a plane's axis,
/// away from a sphere's centre, radially away from a cylinder's or cone's axis (a cone's normal is
/// orthogonal to its surface line), radially in a circle's plane (its foot keeps p's height above that
/// plane: it lies on the cylinder through the circle). A line has no normal (hasNormal false; the foot
/// is on the axis and d = |p - point|). Where the direction is undefined (p at a sphere's centre or on
/// an axis) the normal is a fixed unit vector perpendicular to the axis (a sphere: +x).
struct ElementFoot {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  bool hasNormal = true;
};
ElementFoot footOnElement(const FittedElement& element, const Eigen::Vector3d& p);

/// Points to fit; `source` names the file in error messages.
struct PointSet {
  std::string source;
  std::vector<Eigen::Vector3d> points;
  /// The points' ids (the file's `id` column), empty when it has none.
  std::vector<std::string> ids = {};
  /// The physical line of the file each point comes from (0 when unknown), for error messages.
  std::vector<long> lines = {};
};

/// Fits the element. ValidationError (naming set.source) for too few, non-finite or degenerate points,
/// OptionsError for invalid options. The observer sees every Levenberg-Marquardt iteration and every
/// LP iteration; when it stops the run the result is the last finite element (run.termination
/// Cancelled).
ElementFitResult fitElement(const PointSet& set, const ElementFitOptions& options,
                            Observer* observer = nullptr);

}  // namespace metrofit::geometry
