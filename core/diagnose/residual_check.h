#pragma once
// The open world of the closed loop (docs/file-formats.md#residual_check): is the final residual white,
// and if not, what does it still depend on? Shared by the four domains.
//
// Observations. A domain hands over its residual r (one value per observation, in the data's
// units), the columns of its fitted model at the solution (the declared model plus the accepted
// effects: the design matrix of a linear model, the Jacobian of a non-linear one; the intercept is
// always added here), the variables the data offer (one value per observation each) and, per
// observation, the unit it belongs to (a data row, a probed point: outliers are units).
//
// Tests (all p-values from Boost.Math distributions):
//   * Ljung-Box in every natural order (time, file row, path angle): the residual sorted by that
//     variable, Q = n (n + 2) sum_{k=1..h} rho_k^2 / (n - k), h = min(maxLag, n / 5), compared with
//     chi-square(h);
//   * against every variable, nested F tests of the model columns [1, J] against [1, J, G]:
//       F = ((SSE0 - SSE1) / q) / (SSE1 / (n - p - q)),  p = rank [1, J],  q = rank of G beyond it,
//     with G the basis of a form (generic_effect below): continuous variables `linear` (1 column),
//     `smooth` (natural cubic spline, knots at equally spaced quantiles, boundary knots at the extremes) and
//     `step` (one change point, the best of `stepPositions` candidate positions at quantiles; its p-value
//     Bonferroni-corrected for the search), a path angle `periodic` (harmonics 1..`harmonics`), a category
//     `level` (one constant per level), and with `periodSearch` an ordered continuous variable
//     (naturalOrder: time) `periodic` with an unknown period P (see below). Since r is orthogonal to [1, J],
//     SSE0 - SSE1 = r^T G (Gp^T Gp)^-1 G^T r with Gp = G - U U^T G (U an orthonormal basis of [1, J]): one
//     pass over the data per form.
//   * Family-wise level `level` (1 %) over all tests by Holm's step-down procedure. `white` is true
//     when no test is rejected. `structure` lists, per variable with a rejected test, its strongest
//     form (lowest p), strongest first by share = (SSE0 - SSE1) / SSE0.
// Period search (periodic in time): candidate periods P = span / c for c = 3, 3.25, ... cycles up to
// c_max = min(`periodMaxCycles`, span / (4 dt)) (dt the median spacing of the distinct values: 4
// samples a period at least), the pair sin(2 pi v / P), cos(2 pi v / P) tested at each; the best
// (largest SSE0 - SSE1) refined by a golden-section search within +-0.25 cycles. Its p-value is
// corrected for the search like the step's, by the false-alarm bound of the best period of a
// continuous search (Baluev 2008, uniform sampling): p (1 + W sqrt(pi z / 3)), z = -ln p, W = c_max - 3
// the band in cycles per span (periods one cycle per span apart are independent: a Bonferroni factor
// of W alone gave 2.5 % false alarms at the nominal 1 %). On white noise the corrected p is below 1 %
// in about 1 % of the data sets (periodic_time_test).
// Robustness: the tests use the residual winsorised at `winsorZ` robust standard deviations
// (1.4826 MAD) about its median, so that one large value of heavy-tailed noise cannot make a form
// of a small subset significant (measured: Laplace and Student-t5 clean setup reports were flagged
// in 8-11 % of 100 seeds without it).
// Blocks (test `block`, in every natural order, in the Holm family with the others): a block of
// consecutive observations far off the rest, e.g. ten points of a circular test read 24 sigma off
// over a damaged stretch of a scale. The single-point outlier rule lists none of them when they are
// more than `maxOutlierFraction` of the units, the winsorised F tests see them at 3 sigma, and a
// smooth or periodic form cannot follow a short block. The test: robust z_i = (r_i - median) /
// (1.4826 MAD) of the residual (not winsorised); in the variable's order, per coordinate of a vector
// residual and per sign, the observations with s z_i > `blockZ` (3) are the exceedances (m of the
// coordinate's N) and R is the longest run of consecutive exceedances. Under white noise (i.i.d.
// observations of any distribution: the bound is conditional on m, so heavy tails only raise m) every
// arrangement of the m exceedances is equally likely, and
//   P(a run of R or more | m) <= (N - R + 1) prod_{j=0..R-1} (m - j) / (N - j)
// (the union over the N - R + 1 windows of length R). The test's p is the smallest bound over the
// coordinates and both signs times their number 2 C (Bonferroni), runs of 1 excluded (a single point
// is the outlier rule's); on white noise p <= level in at most `level` of the data sets
// (residual_check_test measures it). When the test is rejected, every run whose corrected bound is at
// most level / (number of tests) is listed in ResidualCheck::blocks with its rows.
// Outliers: robust z = |r - median(r)| / (1.4826 MAD(r)) per observation; a unit is an outlier when
// any of its observations has z above
//   zThreshold = outlierFactor * Phi^-1(1 - 0.005 / n)      (2.5 x the Gaussian family-wise 1 %
//                                                            bound: 9.7 at n = 100, 12.2 at n = 10^4)
// so heavy-tailed clean noise is rarely flagged while a gross error is (factor 2 flagged 16 of 200
// Laplace sets of 100 points, 2.5 flags about 1 in 200; residual_check_test). When
// more than `maxOutlierFraction` of the units exceed it the data are heavy-tailed or structured, not
// spoiled by a few gross errors: none is listed. The domain refits without the outliers and checks
// the refitted residual.
//
// Generic effects (`unexplained:<against>`): the basis G of the strongest structure, fitted jointly
// with the model columns, is a candidate effect like a named one; GenericForm records the form and
// its fixed shape (knots, change point, harmonics, levels) so that the same basis can be evaluated
// on other rows (held-out rows, a re-read file).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "core/common/text.h"

namespace metrofit::diagnose {

/// A variable the residual may depend on, one value per observation.
struct ResidualVariable {
  enum class Kind {
    Continuous,  ///< linear, smooth, step
    Angle,       ///< degrees; periodic
    Category     ///< values are level indices 0 .. levels.size() - 1; level
  };
  std::string name;  ///< "against" (docs/file-formats.md#residual_check): a column name, time, row, angle,
                     ///< direction, x, part, ...
  Kind kind = Kind::Continuous;
  std::vector<double> values;
  std::vector<std::string> levels;  ///< Category: the level names
  bool naturalOrder = false;        ///< Ljung-Box on the residual sorted by this variable
  Phrases label;                    ///< axis title for plots, e.g. "time (min)"
  /// Optional per-observation weights of the basis (variableBasis): a generic effect of this
  /// variable acts as weight * f(value), e.g. the gain of one setup datum on each dimension times a
  /// function of the part number (datum:<id>).
  std::vector<double> weights;
};

/// Forms of a dependence (docs/file-formats.md#residual_check).
enum class DependenceForm { Linear, Smooth, Step, Periodic, Level };
const char* formName(DependenceForm f);

/// The fixed shape of a generic effect of one variable: enough to evaluate its basis anywhere.
struct GenericForm {
  std::string against;  ///< the variable's name
  DependenceForm form = DependenceForm::Linear;
  std::vector<double> knots;  ///< Smooth: interior and boundary knots; Step: {change point}
  int harmonics = 0;          ///< Periodic
  /// Periodic: the period in the variable's unit (harmonics of sin / cos(2 pi k v / period)); 0: a
  /// path angle in degrees (period 360). Serialised as "period" only when not 0.
  double period = 0.0;
  int levels = 0;       ///< Level: number of levels (one column per level but the first)
  double centre = 0.0;  ///< Linear / Smooth: values are centred and scaled for conditioning
  double scale = 1.0;
  /// The variable applies to a subset of the observations only (NaN elsewhere, e.g. surface:<s>):
  /// linear, smooth and step forms then start with the subset's indicator column, so that the
  /// generic effect includes the subset's own constant (a bow of one surface with its offset).
  bool subset = false;
  /// Smooth: the linear column is left out (the model has the variable as a column already, so the
  /// generic effect is only its curvature; thermal, a declared input).
  bool withoutLinear = false;
  /// Vector observations (ResidualCheckInput::components): the basis is repeated per component
  /// (observation i is component i % components), q columns each, zero on the other components.
  int components = 1;
  /// Matching (core/diagnose/matching_diagnosis.h): the named effects the basis is projected off
  /// besides the posture (the catalogue's effects the loop could accept in its run); empty in the
  /// other domains. Serialised as "projected_off" only when not empty.
  std::vector<std::string> projectedOff;
};

/// The basis of `form` on `values` (one row per value; no intercept column).
Eigen::MatrixXd genericBasis(const GenericForm& form, const std::vector<double>& values);
/// genericBasis on the variable's values, rows multiplied by its weights when it has any.
Eigen::MatrixXd variableBasis(const GenericForm& form, const ResidualVariable& variable);

struct ResidualTest {
  std::string name;     ///< "ljung_box", "f_test" or "block"
  std::string against;  ///< ljung_box, block: the order; f_test: the variable
  std::string form;     ///< f_test: the form; empty for ljung_box
  double statistic = 0.0;
  double p = 1.0;  ///< as computed (Bonferroni-corrected for a step search)
  int dof = 0;     ///< Ljung-Box lags, the F test's numerator degrees of freedom, or a block's exceedances m
  bool rejected = false;  ///< by Holm at the family-wise level
};

struct StructureItem {
  std::string against;
  DependenceForm form = DependenceForm::Linear;
  double p = 1.0;
  double share = 0.0;  ///< part of the residual variance explained by the form
  GenericForm shape;   ///< the form's basis, for a generic effect
};

/// A block of consecutive observations off the rest (the `block` test, header comment).
struct ResidualBlock {
  std::string order;               ///< the natural order it was found in (e.g. "row", "time")
  int component = 0;               ///< vector residuals: the coordinate (0 = x, 1 = y, ...)
  std::vector<std::size_t> units;  ///< the units of its observations, in that order
  std::vector<long> rows;          ///< their 1-based data rows (unitRow, else unit + 1)
  double meanZ = 0.0;              ///< mean signed robust z of the block
  double p = 1.0;                  ///< the run's bound, corrected for coordinates and signs
};

struct Outlier {
  std::size_t unit = 0;     ///< the domain's unit index (0-based)
  std::optional<long> row;  ///< 1-based data row
  std::optional<std::string> part, dimension, id;
  double residual = 0.0;  ///< the observation with the largest robust z (data units)
  double robustZ = 0.0;
};

/// What the residual check needs besides the residual.
struct ResidualCheckInput {
  Eigen::VectorXd residual;      ///< n observations (outliers excluded already, or not)
  Eigen::MatrixXd modelColumns;  ///< n x p columns of the fitted model (may be 0 columns)
  std::vector<ResidualVariable> variables;
  std::vector<std::size_t> unitOf;  ///< per observation, its unit (empty: unit = observation)
  /// Vector residuals: observation i is coordinate i % components of its unit (x, y[, z]); the
  /// forms then have one set of columns per coordinate, and the intercept is one per coordinate.
  int components = 1;
  /// Per unit, what identifies it in the data (empty vectors when the file has no such field).
  std::vector<long> unitRow;
  std::vector<std::string> unitPart, unitDimension, unitId;
  /// Observations excluded as outliers (for the plot only): their residuals and, per variable (same
  /// order as `variables`), their values.
  std::vector<double> excludedResidual;
  std::vector<std::vector<double>> excludedValues;
};

struct ResidualCheckOptions {
  double level = 0.01;     ///< family-wise level of the tests
  int maxLag = 20;         ///< Ljung-Box lags (at most n / 5)
  int splineKnots = 5;     ///< smooth: knots (boundary included) at quantiles
  int harmonics = 4;       ///< periodic: harmonics 1 .. harmonics
  int stepPositions = 19;  ///< step: candidate change points at quantiles
  /// Periodic with an unknown period in the ordered continuous variables (naturalOrder) (see the
  /// header comment). Off by default: thermal turns it on (time); the other domains' ordered
  /// variables (file row, report time) have not been measured with it.
  bool periodSearch = false;
  int periodMaxCycles = 60;          ///< the shortest candidate period is span / periodMaxCycles (or 4 dt)
  double outlierFactor = 2.5;        ///< see the header comment
  double maxOutlierFraction = 0.02;  ///< more units beyond the threshold: none listed
  bool detectOutliers = true;
  double winsorZ = 3.0;  ///< 0: no winsorising
  /// Block test (header comment): robust z beyond which an observation counts as far off; 0: no
  /// block test.
  double blockZ = 3.0;

  bool isValid(std::string* why) const;
};

struct ResidualCheck {
  bool white = true;
  double level = 0.01;
  std::vector<ResidualTest> tests;
  std::vector<StructureItem> structure;  ///< strongest first
  std::vector<Outlier> outliers;
  /// Blocks of consecutive observations off the rest (the `block` test rejected), largest first.
  std::vector<ResidualBlock> blocks;
  double outlierThreshold = 0.0;  ///< the robust z threshold used
  std::size_t observations = 0;
  /// One line a person can read: "white: no test finds structure at the 1 % family-wise level" or
  /// "still depends on T1 (smooth, 62 % of the variance), ...".
  std::string summary;
  Phrases summaryParts;  ///< summary == english(summaryParts)
  /// The residual against the variable of the strongest structure with the generic fit (for the
  /// GUI and the report); x, before = residual, after = residual minus the generic fit.
  struct Plot {
    std::string against;
    Phrases xLabel;
    std::vector<double> x, residual, fit;
    std::vector<std::string> categories;
    std::vector<double> outlierX, outlierResidual;  ///< the excluded outliers, at their x
    /// Vector residuals (ResidualCheckInput::components): observation i is coordinate i % components,
    /// and the fit is one curve per coordinate.
    int components = 1;
  };
  std::optional<Plot> plot;
};

/// Robust outliers of `residual` by unit (see the header comment). Returns the unit indices.
std::vector<Outlier> findOutliers(const ResidualCheckInput& in, const ResidualCheckOptions& options,
                                  double* threshold = nullptr);

/// The block test of the header comment on one order (`order`: one value per observation) of a
/// residual with `components` coordinates: the test (p corrected, statistic = the longest run) and
/// every run whose corrected bound is at most `listBelow`. Exposed for its tests.
ResidualTest blockTest(const ResidualCheckInput& in, const std::vector<double>& order,
                       const std::string& name, double blockZ, double listBelow,
                       std::vector<ResidualBlock>* blocks);

/// The tests and the structure list of the residual (outliers are not searched here: pass the
/// residual without them, and set `outliers` of the result from findOutliers).
ResidualCheck checkResidual(const ResidualCheckInput& in, const ResidualCheckOptions& options = {});

/// Candidate shapes of a variable (the forms its kind allows), fixed on `values`.
std::vector<GenericForm> candidateForms(const ResidualVariable& v, const ResidualCheckOptions& options);

/// Parameters of a fitted generic effect for the JSON and the evidence: the form, the rms and the
/// range (max - min) of the fitted contribution over `values`, and for a step its position and size,
/// for periodic the amplitude and harmonic of the largest harmonic. `unit` e.g. "mm", "um".
struct GenericSummary {
  std::vector<std::pair<std::string, double>> numbers;  ///< name -> value
  Phrases text;                                         ///< e.g. "smooth in T1, rms 2.1 um"
};
GenericSummary summariseGeneric(const GenericForm& form, const Eigen::VectorXd& coefficients,
                                const std::vector<double>& values, const std::string& unit);
/// The rms and range part of summariseGeneric from the fitted contribution itself (one value per
/// observation), for a domain that fits a transformed basis.
GenericSummary summariseContribution(const GenericForm& form, Eigen::VectorXd contribution,
                                     const std::string& unit);

/// The period search of the header comment on one variable: the best period of a sin / cos pair for
/// the residual `r` (orthogonal to [1, modelColumns] already) beyond the model columns, its F test's p
/// value corrected for the search (`searched`: the band W in cycles per span, rounded up). nullopt when the
/// variable is too short or has too few distinct values for periods of 3 to 4 cycles or more.
struct PeriodSearch {
  double period = 0.0;
  double F = 0.0, p = 1.0;  ///< p corrected
  int searched = 0;         ///< M
  double ssr = 0.0;         ///< SSE0 - SSE1
};
std::optional<PeriodSearch> searchPeriod(const Eigen::VectorXd& residual, const Eigen::MatrixXd& modelColumns,
                                         const std::vector<double>& values,
                                         const ResidualCheckOptions& options);

/// The generic candidates of a loop round: the shapes of the strongest structures of `check`, at
/// most `count`, skipping the variables named in `taken` (they have a generic effect already).
std::vector<GenericForm> genericCandidates(const ResidualCheck& check, const std::vector<std::string>& taken,
                                           std::size_t count = 3);

/// The evidence penalty of a generic candidate for having been chosen by a search over the
/// variables and forms of the check: 2 ln(number of tests) (the cyclic search of the kinematic
/// loop is penalised the same way). The `block` tests are not counted: they offer no generic shape.
double genericSearchPenalty(const ResidualCheck& check);

/// The variable named `name` in `variables` (nullptr when absent).
const ResidualVariable* findVariable(const std::vector<ResidualVariable>& variables, const std::string& name);

/// The JSON of a check (docs/file-formats.md#residual_check): {"white", "tests", "structure", "outliers"} (+
/// "level", "outlier_threshold", "summary", "blocks").
nlohmann::json toJson(const ResidualCheck& c);

}  // namespace metrofit::diagnose
