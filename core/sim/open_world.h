#pragma once
// The open world of the closed loop (docs/file-formats.md#residual_check): simulated data
// sets with effects that NO catalogue entry of `diagnose` models, gross errors, and clean data with
// non-Gaussian noise. They are made from the existing simulators' clean, noiseless data (the
// declared model exact), plus one effect, plus noise:
//   data = clean(seed) + amplitude * shape(case, seed) + noise(kind, sigma, seed)
// with three independent random streams derived from the seed (base data, effect parameters,
// noise), so that a case and the clean data of the same seed and noise kind differ by the effect
// alone. Every case keeps its truth (OpenWorldTruth): the form and the variables the structure
// depends on, in the `against` vocabulary of docs/file-formats.md#residual_check, and for gross errors the
// unit hit.
//
// Effect-to-noise ratio r. The part of an effect the declared model cannot absorb is what a
// diagnosis can see: the effect projected off the columns of the declared model, linearised at the
// clean data (least squares, rank-deficient columns allowed):
//   thermal    [1, declared inputs] over all rows (as bench_diagnose.cpp);
//   kinematic  per point two observations (x, y); the Cartesian machine's origin (1, 0), (0, 1) and
//              orientation errors a: (0, x_cmd), b: (-y_cmd, 0);
//   setup      per report row one observation; the gain matrix row G[q][.] of its dimension;
//   matching   per point one observation along the nominal normal; the rigid posture
//              [n, q x n] (translation and small rotation, in the part frame).
// The amplitude makes rms(visible part) = r * sigma ("visibleRms"); "effectRms" is the rms of the
// whole contribution (data - clean data) over all observations. Gross-error cases instead have a
// gross error of size outlierSigmasPerRatio * r * sigma (default 6 r: 30 sigma at r = 5), random
// sign (and direction), in one unit.
//
// Noise (NoiseKind), standard deviation sigma, independent per observation:
//   Gaussian   N(0, sigma^2) (metrofit::Rng::normal);
//   Laplace    b = sigma / sqrt 2, x = -b sgn(u) ln(1 - 2 |u|), u uniform in (-1/2, 1/2); kurtosis 6;
//   StudentT5  sqrt(3/5) sigma Z / sqrt(V / 5), Z ~ N(0, 1), V ~ chi^2(5) (sum of 5 squared
//              normals); variance sigma^2, kurtosis 9, tails ~ |x|^-6.
//
// Domains, clean data and effects (lengths: thermal um, others mm; angles deg):
//
// THERMAL: the spindle test of thermal_sim.h (480 min at 1 min, sensor seed = seed, its sensor
// noise kept), target disp_z_um = -3 (T2 - T2_0) - 1.5 (T4 - T4_0) + (T_amb - T_amb_0) as
// effects_thermal.h without effects; declared inputs T2, T4, T_amb; sigma 0.25 um.
//   sensor_rezero   the displacement sensor is bumped / re-zeroed at t*: + A for t >= t*, t* uniform
//                   in [0.25, 0.75] of the duration (form step; against time, row);
//   coolant_cycle   the spindle chiller cycles on / off: + A sin(2 pi t / P + phi), P uniform in
//                   [30, 60] min, phi uniform; no logged column sees it (form periodic; time, row);
//   quadratic_T2    a non-linear thermal expansion (a gap closing as the housing warms):
//                   + A ((T2 - T2_0) / max |T2 - T2_0|)^2 (form smooth; against T2);
//   centrifugal_rpm the spindle nose grows with the centrifugal force: + A (rpm / rpm_max)^2, on a
//                   stepped speed programme (0, 1500 .. 9000 rpm, each speed in both halves of the
//                   log); the nearest catalogue name is input:spindle_rpm, linear (form smooth;
//                   against spindle_rpm);
//   outlier_spike   one row (uniform in the rows) + or - the gross error (a spike of the gauge);
// KINEMATIC: the circular test of circular_sim.h (R 100 mm, 360 points per loop, CCW then CW,
// default actuator errors), per coordinate noise; sigma 0.5 um. Rows k = 0..n-1 are in time order
// at constant feed (time is proportional to the row).
//   thermal_drift   the machine warms during the test: the tool-to-table offset grows as
//                   A (1 - exp(-k / (0.5 n))) along a direction theta uniform (smooth; time, row);
//   reversal_spike  a quadrant glitch: after axis i reverses (its direction of motion, pathMotion
//                   of effects_kinematic.h, changes sign), it lags by friction with a spike
//                   -A d_new exp(-m / L) along that axis, m samples since the reversal, L uniform
//                   in [2, 5] samples; no spike before an axis' first reversal (catalogue backlash
//                   is a constant lost motion over the whole half-loop, not a decaying spike)
//                   (smooth; against reversal, and angle: the axes reverse at fixed path angles,
//                   0, 90, 180, 270 deg, with the same sign in both loops);
//   straightness_bow the X guideway is bowed: y += A ((x_cmd - c_x) / R)^2, sign random; the
//                   linear part is squareness (declared) (smooth; against x, and y and angle: on a
//                   circle (x / R)^2 = 1 - (y / R)^2, a second harmonic of the path angle);
//   scale_damage    a damaged stretch of the X scale: the X reading is off by A (sign random) over
//                   the x range of ten consecutive points of the first loop's upper half (start
//                   uniform in 20 .. 150 deg), so every pass over it (both halves of both loops: 4 x
//                   10 points) is a block of ten consecutive points; A = 4.8 r sigma (24 sigma at
//                   r = 5), not sized by its visible rms (form block; against x, angle, row; the
//                   points hit in OpenWorldTruth::blockUnits / blockRows);
//   local_bump      a worn spot of the X ball screw: the X error + A exp(-((x_cmd - x0) / w)^2 / 2),
//                   w = 0.08 R, x0 uniform within +-0.6 R of the centre (smooth; against x, angle);
//   outlier_point   one point (uniform) displaced by the gross error in a uniform direction;
// SETUP: the CMM report series of effects_setup.h on the given model without effects, rounding or
// noise (w1 = 0.03 mm setup errors drawn from the seed, parts 1..P (default 20), 12 min per part with
// time jitter 0.5), then per row effect + noise; sigma 0.005 mm. Report rows are part-major.
//   reclamp_step    the part is re-clamped (or a tool replaced) from part p*, uniform in
//                   [P/4, 3P/4]: a setup datum i (uniform among those that reach a dimension)
//                   steps by A: + G[q][i] A for p >= p* (form step; part, time, row and every
//                   dimension:<d> it reaches);
//   fixture_alternation  the parts alternate between two fixtures; fixture B's locator sits A off
//                   on a work-offset datum (uniform among the wks data that reach a dimension,
//                   else any): + G[q][i] A for even parts (form level; part, row and every
//                   dimension:<d>);
//   dimension_wear  one dimension q* (uniform) wears non-linearly (a form tool that wears faster as
//                   it dulls): + A ((p - 1) / (P - 1))^2 on q* only (smooth; dimension:<q*>, part,
//                   time, row);
//   tool_runin      a new tool runs in: its datum (uniform among the tool data that reach a
//                   dimension) changes as A (1 - exp(-(p - 1) / p0)), p0 uniform in [1.5, 3] parts,
//                   + G[q][i] times that; the nearest catalogue name is tool_wear:<tool>, a constant
//                   rate (smooth; against datum:<tool>, part, time, row and every dimension:<d>);
//   outlier_row     one report row (uniform) off by the gross error (a CMM probing a chip);
// MATCHING: the S-piece of probe_sim.h (sPieceDefaults posture, 40 points with normals), deviations
// along the (rotated) nominal normal; sigma 0.006 mm.
//   surface_bow     a form error of one surface (uniform among ruled+, ruled-, plane): a bow
//                   A (u^2 - mean u^2) along its longest extent u in [-1, 1] (zero mean on the
//                   surface, so it is no surface offset) (smooth; against surface:<s>);
//   plate_bending   the thin base plate bends: displacement (0, 0, A ((x - 160) / 160)^2) seen along
//                   the normal, n_z A ((x - 160) / 160)^2 (smooth; against x, and surface:plane:
//                   the plane's 8 points, n_z = 1, carry most of it and its longest extent is x);
//   probe_lobing    a three-lobed touch-trigger probe: the pre-travel depends on the probing
//                   direction, deviation -A sqrt(n_x^2 + n_y^2) cos(3 (phi_n - phi0)), phi_n the
//                   azimuth of the nominal normal, phi0 uniform (periodic; against normal,
//                   direction, and the normal's components nx, ny);
//   surface_tilt    one surface (uniform among ruled+, ruled-, plane) is tilted: A (u - mean u)
//                   along its longest extent u in [-1, 1] (zero mean: no surface offset) (smooth;
//                   against surface:<s>);
//   outlier_point   one point (uniform) off along its normal by the gross error;
// CLEAN (every domain): clean_gauss, clean_laplace, clean_t5: the clean data with that noise.
//
// Deterministic by seed; no I/O.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/common/rng.h"
#include "core/kinematics/effects.h"
#include "core/kinematics/measured_path.h"
#include "core/matching/probe_points.h"
#include "core/setup/model.h"
#include "core/setup/report.h"
#include "core/thermal/thermal_log.h"

namespace metrofit {

enum class NoiseKind { Gaussian, Laplace, StudentT5 };
/// "gauss", "laplace", "t5".
const char* toString(NoiseKind kind);
/// One draw with mean 0 and standard deviation sigma (see the header comment).
double drawNoise(Rng& rng, NoiseKind kind, double sigma);

enum class OpenWorldDomain { Thermal, Kinematic, Setup, Matching };
/// "thermal", "kinematic", "setup", "matching".
const char* toString(OpenWorldDomain domain);

enum class OpenCaseKind { Effect, Outlier, Clean };

struct OpenWorldCaseInfo {
  std::string name;
  OpenCaseKind kind = OpenCaseKind::Effect;
  std::string form;  ///< form of the structure (docs/file-formats.md#residual_check), "spike" for a gross
                     ///< error, "block" for a block of points off the rest, "" clean
};

/// The cases of a domain, effects first, then the gross error, then the clean data.
std::vector<OpenWorldCaseInfo> openWorldCases(OpenWorldDomain domain);

struct OpenWorldOptions {
  NoiseKind noise = NoiseKind::Gaussian;  ///< noise of effect and outlier cases (clean cases: their own)
  double noiseSigma = 0.0;                ///< 0: the domain's default (header comment)
  double outlierSigmasPerRatio = 6.0;     ///< gross error = this * ratio * sigma
  int setupParts = 20;                    ///< parts of a setup report series
};

/// What was simulated: what a diagnosis should find.
struct OpenWorldTruth {
  std::string caseName;
  OpenCaseKind kind = OpenCaseKind::Clean;
  std::string form;
  /// The variables the structure depends on (docs/file-formats.md#residual_check), the primary one first.
  std::vector<std::string> against;
  NoiseKind noise = NoiseKind::Gaussian;
  double noiseSigma = 0.0;
  double ratio = 0.0;       ///< requested effect-to-noise ratio (0 for clean data)
  double amplitude = 0.0;   ///< A of the header comment (data units)
  double effectRms = 0.0;   ///< rms of (data - clean data) over all observations
  double visibleRms = 0.0;  ///< rms of its part the declared model cannot absorb
  /// Gross error: the unit hit (0-based: thermal row, path point, report row, probe point), its
  /// 1-based data row, and the part / dimension (setup) or id (matching) when the data have them.
  std::optional<std::size_t> outlierUnit;
  std::optional<long> outlierRow;
  std::string outlierPart, outlierDimension, outlierId;
  /// Steps and gross errors: where in the data order they sit, 0 (first row / part) to 1 (last);
  /// e.g. a thermal step at 0.6 lies in the held-out rows of a fit on the first half.
  std::optional<double> position;
  /// A block of points off the rest (kinematic scale_damage): the units hit (0-based) and their
  /// 1-based data rows.
  std::vector<std::size_t> blockUnits;
  std::vector<long> blockRows;
  std::string description;  ///< the drawn parameters in words
};

struct OpenThermalCase {
  ThermalLog log;
  std::string target;               ///< "disp_z_um"
  std::vector<std::string> inputs;  ///< the declared inputs
  OpenWorldTruth truth;
};

struct OpenKinematicCase {
  MeasuredPath path;
  double feedMmPerMin = kDefaultFeedMmPerMin;
  OpenWorldTruth truth;
};

struct OpenSetupCase {
  setup::Measurements measurements;
  OpenWorldTruth truth;
};

struct OpenMatchingCase {
  ProbePointSet points;
  OpenWorldTruth truth;
};

/// The data of case `name` of the domain (OptionsError for an unknown case, a ratio <= 0 for a
/// non-clean case, or invalid options). `ratio` is ignored for clean cases.
OpenThermalCase openWorldThermal(const std::string& name, double ratio, std::uint64_t seed,
                                 const OpenWorldOptions& options = {});
OpenKinematicCase openWorldKinematic(const std::string& name, double ratio, std::uint64_t seed,
                                     const OpenWorldOptions& options = {});
OpenSetupCase openWorldSetup(const setup::Model& model, const std::string& name, double ratio,
                             std::uint64_t seed, const OpenWorldOptions& options = {});
OpenMatchingCase openWorldMatching(const std::string& name, double ratio, std::uint64_t seed,
                                   const OpenWorldOptions& options = {});

}  // namespace metrofit
