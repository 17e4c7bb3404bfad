#pragma once
// QPainter renderings of the kinematics & SPC views, shared by the widgets (kinematicsviews.h) and
// the PDF report (one drawing code, so the report shows what the screen shows). Every plot draws
// into a rectangle in the painter's current coordinates; lengths of text and lines come from
// PlotStyle (pixels of that coordinate system). Each plot has a Layout class that maps data to
// those coordinates, so tests and tooltips can ask where something lands.
//
// Polar plot (ballbar style): a point at angle t with radial deviation d is drawn at plot radius
//   rho = R + k d   (mm of the plot, R the nominal radius, k the magnification shown in the legend)
// and at pixel  centre + s rho (cos t, -sin t), s pixels per mm of the plot. Scale rings are drawn at
// d = j * ringStep (labelled in um), the ring d = 0 is the nominal circle.
//
// Path plot: the XY plane in mm, equal scales; the nominal circle true to scale and every other
// path as deviations from its nominal point magnified by k: c_k + k (p_k - c_k).
//
// Control charts: subgroup number 1..k against the subgroup mean (X-bar) or range (R), centre line
// and control limits of core/spc (xbarRChart) drawn as horizontal lines and labelled with values.
// Histogram: equal-width bins over [min, max] of the values, specification limits and the nominal
// drawn as vertical lines.
#include <QColor>
#include <QLocale>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/spc/control_chart.h"
#include "core/spc/nelson.h"
#include "core/study/circular_analysis.h"

namespace metrofit {
struct MeasuredPath;
struct CircularTrace;
struct SpcResult;
}  // namespace metrofit

class QPainter;

namespace metrofit {

struct PlotStyle {
  double fontPx = 11.0;
  double lineWidth = 1.4;
  double pointRadius = 2.6;
  /// Numbers on the plot: '.' decimals (C) in the report; the views use the user's locale
  /// (screenPlotStyle()).
  QLocale locale = QLocale::c();
};

/// The style of the on-screen views: the default sizes with the user's locale (no group separators).
PlotStyle screenPlotStyle();

/// The colours of the kinematics plots (views, legend and report agree).
namespace kinematic_colour {
QColor nominal();
QColor counterClockwise();
QColor clockwise();
QColor references();
QColor expected();
QColor limit();
QColor centreLine();
QColor specification();
QColor bars();
}  // namespace kinematic_colour

// ---- polar plot ------------------------------------------------------------------------------

struct PolarPlotData {
  double radiusMm = 0.0;
  /// False when the test gives no nominal radius (a radial-only test without radius_mm): radiusMm is then
  /// only the circle the deviations are drawn around, and the legend says so.
  bool radiusKnown = true;
  std::vector<CircularLoop> loops;       ///< measured, CCW / CW
  std::vector<RadialPoint> compensated;  ///< expected after compensation (may be empty)
  /// Magnification k and ring step (mm); 0 chooses them from the data (see autoScale()).
  double magnification = 0.0;
  double ringStepMm = 0.0;
  QString title;

  /// Fills magnification and ringStepMm when 0: the ring step is a 1/2/5 step with about two rings
  /// on the larger side of the deviations, k the largest 1/2/5 value with k * (outer ring) <= 0.4 R.
  void autoScale();
};

/// The radial deviations of a circular test's loops about its nominal circle (page and report).
PolarPlotData circularPolarData(const CircularAnalysis& analysis, const QString& title);

/// The same for a radial-only test (a ballbar export): the deviations are drawn around its nominal
/// radius, or around 100 mm, marked as not the test's radius, when the file gives none.
PolarPlotData radialTestPolarData(const CircularTrace& trace, const CircularAnalysis& analysis,
                                  const QString& title);

class PolarPlotLayout {
 public:
  PolarPlotLayout(const QRectF& area, const PolarPlotData& data, const PlotStyle& style = {});
  /// Where a point at `angleDeg` with radial deviation `deviationMm` is drawn.
  QPointF map(double angleDeg, double deviationMm) const;
  QPointF centre() const { return centre_; }
  double pixelsPerMm() const { return scale_; }
  double magnification() const { return k_; }
  double ringStepMm() const { return step_; }
  int innerRing() const { return jMin_; }  ///< rings j = innerRing..outerRing (deviation j * step)
  int outerRing() const { return jMax_; }
  QRectF legendArea() const { return legend_; }
  QRectF titleArea() const { return title_; }

 private:
  QPointF centre_;
  double scale_ = 1.0, radius_ = 0.0, k_ = 1.0, step_ = 0.001;
  int jMin_ = -1, jMax_ = 1;
  QRectF legend_, title_;
};

void paintPolarPlot(QPainter& painter, const QRectF& area, const PolarPlotData& data,
                    const PlotStyle& style = {});

// ---- path plot -------------------------------------------------------------------------------

struct PathPlotData {
  Eigen::Vector2d centreMm = Eigen::Vector2d::Zero();
  double radiusMm = 0.0;
  std::vector<Eigen::Vector2d> nominal;   ///< c_k
  std::vector<Eigen::Vector2d> measured;  ///< p_k (same length as nominal)
  std::vector<bool> counterClockwise;     ///< per point (empty: all CCW)
  std::vector<Eigen::Vector2d> references;
  std::vector<Eigen::Vector2d> expected;
  double magnification = 0.0;  ///< 0: niceFloor(0.3 R / largest deviation)
  QString title;
};

/// The measured path of a circular test as the kinematics page and the report draw it: the nominal
/// circle of the analysis, commanded and measured points, each point's loop direction.
PathPlotData circularPathData(const MeasuredPath& measured, const CircularAnalysis& analysis,
                              const QString& title);

/// Adds a compensation preview to both plots: the compensated references and the expected path, and
/// the expected path's radial deviations (the polar scale is chosen again for them).
void addCompensationPreview(PathPlotData& path, PolarPlotData& polar, const CompensationPreview& preview,
                            const CircularAnalysis& analysis);

class PathPlotLayout {
 public:
  PathPlotLayout(const QRectF& area, const PathPlotData& data, const PlotStyle& style = {});
  /// Pixel of an XY position (mm).
  QPointF map(const Eigen::Vector2d& mm) const;
  /// Pixel of the k-th point of a path drawn magnified about nominal[k].
  QPointF mapMagnified(const Eigen::Vector2d& nominal, const Eigen::Vector2d& point) const;
  QRectF plotArea() const { return plot_; }
  double magnification() const { return k_; }
  double xMin() const { return x0_; }
  double xMax() const { return x1_; }
  double yMin() const { return y0_; }
  double yMax() const { return y1_; }

 private:
  QRectF plot_;
  double x0_ = -1, x1_ = 1, y0_ = -1, y1_ = 1, k_ = 1.0;
};

void paintPathPlot(QPainter& painter, const QRectF& area, const PathPlotData& data,
                   const PlotStyle& style = {});

// ---- control charts and histogram ----------------------------------------------------------

enum class ControlChartKind { Mean, Range };

class ControlChartLayout {
 public:
  ControlChartLayout(const QRectF& area, const XbarRChart& chart, ControlChartKind kind,
                     const PlotStyle& style = {});
  QPointF map(double subgroup, double value) const;  ///< subgroup 1-based
  double yOf(double value) const { return map(1.0, value).y(); }
  QRectF plotArea() const { return plot_; }
  double yMin() const { return y0_; }
  double yMax() const { return y1_; }

 private:
  QRectF plot_;
  double x0_ = 0.5, x1_ = 1.5, y0_ = 0, y1_ = 1;
};

/// `unit` is appended to the axis title ("diameter_mm" -> "mean (mm)"). Points beyond the limits or
/// breaking one of `rules` (core/spc/nelson.h) are red, those breaking a rule also ringed; with a phase
/// I base shorter than the series (XbarRChart::baseSubgroups) a dashed line after subgroup K marks
/// where phase II begins. Moving ranges are drawn at their later subgroup (from 2).
void paintControlChart(QPainter& painter, const QRectF& area, const XbarRChart& chart, ControlChartKind kind,
                       const QString& unit, const PlotStyle& style = {},
                       const std::vector<RuleBreak>& rules = {});

/// What Nelson rule `rule` (1..8) looks for, in the user's language ("nine in a row on one side of the
/// centre line").
QString nelsonRuleText(int rule);
/// One line per rule broken at the 0-based `subgroup` on the chart of `kind`: "Nelson 2: nine in a row
/// on one side of the centre line". Empty when none is.
QStringList ruleBreaksAt(const std::vector<RuleBreak>& rules, ControlChartKind kind, std::size_t subgroup);
/// The Nelson rules broken in `result`, "X-bar 2 at 9, 10; R 1 at 4" (subgroups 1-based; X and MR for
/// individuals), or "none broken"; with the phase I base when it is shorter than the series.
QString nelsonRulesSummary(const SpcResult& result);
/// The colour of the phase I / phase II boundary.
QColor phaseBoundaryColour();

struct HistogramBins {
  double first = 0.0;  ///< left edge of the first bin
  double width = 1.0;
  std::vector<int> counts;
  double edge(std::size_t i) const { return first + width * static_cast<double>(i); }
};

/// Equal-width bins from min to max of the values (the maximum falls into the last bin). bins <= 0:
/// ceil(sqrt(N)) clamped to [5, 20]. All values equal: one value-centred bin of width 1e-9 * max(1, |v|)
/// repeated `bins` times around it.
HistogramBins histogramBins(const std::vector<double>& values, int bins = 0);

struct HistogramData {
  std::vector<double> values;
  HistogramBins bins;
  std::optional<double> lsl, usl, nominal, mean;
  QString unit;
  QString title;
};

/// The histogram of an SPC series as the SPC view and the report draw it: the values the chart used,
/// their bins, the specification limits, the nominal and the grand mean.
HistogramData spcHistogramData(const SpcResult& result, const std::vector<double>& values,
                               const QString& unit, const QString& title);

class HistogramLayout {
 public:
  HistogramLayout(const QRectF& area, const HistogramData& data, const PlotStyle& style = {});
  QPointF map(double value, double count) const;
  QRectF plotArea() const { return plot_; }
  double xMin() const { return x0_; }
  double xMax() const { return x1_; }

 private:
  QRectF plot_;
  double x0_ = 0, x1_ = 1, y1_ = 1;
};

void paintHistogram(QPainter& painter, const QRectF& area, const HistogramData& data,
                    const PlotStyle& style = {});

}  // namespace metrofit
