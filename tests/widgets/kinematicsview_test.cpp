// Tests of the kinematics & SPC views (widgets/kinematics): the polar plot's geometry (a point with
// +10 um radial deviation at 90 deg lands at R + k d on the screen, in the loop's colour), the
// automatic magnification, the path view's magnified mapping, the control limits drawn at the
// values core/spc computes, the histogram bins and the specification limits. Rendered offscreen;
// grabbed images are saved into $METROFIT_TEST_OUT for a look.
#include <gtest/gtest.h>

#include <QColor>
#include <QDir>
#include <QImage>
#include <QPainter>
#include <QTableWidget>
#include <QTest>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/kinematics/iso230_4.h"
#include "core/kinematics/measured_path.h"
#include "core/spc/control_chart.h"
#include "core/spc/spc.h"
#include "core/study/circular_analysis.h"
#include "qtapp.h"
#include "testsupport.h"
#include "widgets/common/plotnavigation.h"
#include "widgets/kinematics/kinematicplots.h"
#include "widgets/kinematics/kinematicsviews.h"

namespace metrofit {
namespace {

/// True when pixel `a` is colour `b` drawn over white with at least 45 % coverage (antialiased
/// lines blend with the white background): a = white - alpha (white - b), alpha >= 0.45.
bool close(const QColor& a, const QColor& b) {
  const double pa[3] = {255.0 - a.red(), 255.0 - a.green(), 255.0 - a.blue()};
  const double pb[3] = {255.0 - b.red(), 255.0 - b.green(), 255.0 - b.blue()};
  double ab = 0.0, bb = 0.0;
  for (int i = 0; i < 3; ++i) {
    ab += pa[i] * pb[i];
    bb += pb[i] * pb[i];
  }
  const double alpha = bb > 0.0 ? ab / bb : 0.0;
  double residual = 0.0;
  for (int i = 0; i < 3; ++i) residual += std::abs(pa[i] - alpha * pb[i]);
  return alpha >= 0.45 && residual <= 30.0 * std::max(alpha, 0.5);
}

/// True when a pixel within `radius` of p has colour c.
bool colourNear(const QImage& img, QPointF p, const QColor& c, int radius = 1) {
  const int x0 = static_cast<int>(std::lround(p.x())), y0 = static_cast<int>(std::lround(p.y()));
  for (int y = y0 - radius; y <= y0 + radius; ++y) {
    for (int x = x0 - radius; x <= x0 + radius; ++x) {
      if (img.valid(x, y) && close(img.pixelColor(x, y), c)) return true;
    }
  }
  return false;
}

/// Fraction of the pixels of row y between x0 and x1 that have colour c (also y +- 1).
double rowFraction(const QImage& img, double y, double x0, double x1, const QColor& c) {
  int hits = 0, total = 0;
  for (int x = static_cast<int>(x0); x <= static_cast<int>(x1); ++x) {
    ++total;
    bool hit = false;
    for (int dy = -1; dy <= 1; ++dy)
      hit = hit || close(img.pixelColor(x, static_cast<int>(std::lround(y)) + dy), c);
    if (hit) ++hits;
  }
  return total ? static_cast<double>(hits) / total : 0.0;
}

/// Fraction of the pixels of column x between y0 and y1 that have colour c (also x +- 1).
double columnFraction(const QImage& img, double x, double y0, double y1, const QColor& c) {
  int hits = 0, total = 0;
  for (int y = static_cast<int>(y0); y <= static_cast<int>(y1); ++y) {
    ++total;
    bool hit = false;
    for (int dx = -1; dx <= 1; ++dx)
      hit = hit || close(img.pixelColor(static_cast<int>(std::lround(x)) + dx, y), c);
    if (hit) ++hits;
  }
  return total ? static_cast<double>(hits) / total : 0.0;
}

/// Pixels of colour c within `half` of p.
int pixelsNear(const QImage& img, QPointF p, const QColor& c, int half) {
  int n = 0;
  for (int y = static_cast<int>(p.y()) - half; y <= static_cast<int>(p.y()) + half; ++y)
    for (int x = static_cast<int>(p.x()) - half; x <= static_cast<int>(p.x()) + half; ++x)
      n += img.valid(x, y) && close(img.pixelColor(x, y), c);
  return n;
}

void save(const QImage& img, const char* name) {
  img.save(QDir(QString::fromStdString(test::outDir().string())).filePath(QString::fromLatin1(name)));
}

/// A CCW loop on R = 50 with zero deviation except +10 um at 90 deg.
PolarPlotData bumpAt90() {
  PolarPlotData d;
  d.radiusMm = 50.0;
  CircularLoop loop;
  for (int a = 0; a < 360; ++a) loop.points.push_back({static_cast<double>(a), a == 90 ? 0.010 : 0.0});
  d.loops.push_back(loop);
  return d;
}

TEST(PolarPlot, AutoScaleChoosesRingStepAndMagnification) {
  PolarPlotData d = bumpAt90();
  d.autoScale();
  // Largest deviation 10 um: ring step niceStep(10 um, 2) = 5 um, two rings outside, k the largest
  // 1/2/5 value with k * 10 um <= 0.4 R = 20 mm: 2000.
  EXPECT_DOUBLE_EQ(d.ringStepMm, 0.005);
  EXPECT_DOUBLE_EQ(d.magnification, 2000.0);
}

TEST(PolarPlot, PlusTenMicrometresAt90DegLandsAtRPlusKd) {
  PolarDeviationView view;
  view.resize(520, 600);
  PolarPlotData d = bumpAt90();
  d.magnification = 1000.0;
  d.ringStepMm = 0.005;
  view.setData(d);
  const PolarPlotLayout L = view.layout();
  EXPECT_DOUBLE_EQ(L.magnification(), 1000.0);
  EXPECT_EQ(L.outerRing(), 2);
  EXPECT_EQ(L.innerRing(), -1);

  // The centre and the pixel scale from the nominal circle at 0 and 180 deg.
  const QPointF p0 = view.mapToWidget(0.0, 0.0), p180 = view.mapToWidget(180.0, 0.0);
  const QPointF centre = (p0 + p180) / 2.0;
  const double s = (p0.x() - p180.x()) / (2.0 * 50.0);
  EXPECT_NEAR(centre.x(), L.centre().x(), 1e-9);
  EXPECT_NEAR(centre.y(), L.centre().y(), 1e-9);
  EXPECT_NEAR(p0.y(), centre.y(), 1e-9);
  // The outer ring (50 + 1000 * 2 * 5 um = 60 mm) fills the plot's circle area.
  EXPECT_GT(s * 60.0, 0.3 * 520);
  EXPECT_LE(s * 60.0, 0.5 * 520);
  // +10 um at 90 deg: straight above the centre, at (R + k d) = 60 plot mm.
  const QPointF p = view.mapToWidget(90.0, 0.010);
  EXPECT_NEAR(p.x(), centre.x(), 1e-9);
  EXPECT_NEAR(centre.y() - p.y(), s * (50.0 + 1000.0 * 0.010), 1e-9);
  // 0 deviation at 90 deg sits on the nominal circle, 10 mm of plot (10 * s px) lower.
  EXPECT_NEAR(view.mapToWidget(90.0, 0.0).y() - p.y(), s * 10.0, 1e-9);
  // Angles run counter-clockwise on screen: 45 deg is up and right.
  const QPointF p45 = view.mapToWidget(45.0, 0.0);
  EXPECT_NEAR(p45.x() - centre.x(), s * 50.0 * std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(centre.y() - p45.y(), s * 50.0 * std::sqrt(0.5), 1e-9);

  // In the pixels: the CCW colour at the bump's tip and on the loop at 0 deg; at twice the
  // magnification the tip moves out by another 10 plot-mm.
  const QImage img = view.grab().toImage();
  save(img, "kinematics-polar-bump.png");
  EXPECT_TRUE(colourNear(img, p, kinematic_colour::counterClockwise()));
  EXPECT_TRUE(colourNear(img, view.mapToWidget(200.0, 0.0), kinematic_colour::counterClockwise()));
  EXPECT_FALSE(colourNear(img, centre, kinematic_colour::counterClockwise(), 3));
}

TEST(PolarPlot, CcwAndCwLoopsHaveTheirColours) {
  PolarDeviationView view;
  view.resize(500, 560);
  PolarPlotData d;
  d.radiusMm = 100.0;
  CircularLoop ccw, cw;
  cw.counterClockwise = false;
  for (int a = 0; a < 360; ++a) {
    const double t = a * std::numbers::pi / 180.0;
    ccw.points.push_back({static_cast<double>(a), 0.004 * std::cos(2 * t)});
    cw.points.push_back({static_cast<double>(a), -0.004 * std::cos(2 * t)});
  }
  d.loops = {ccw, cw};
  view.setData(d);
  const QImage img = view.grab().toImage();
  save(img, "kinematics-polar-loops.png");
  EXPECT_TRUE(colourNear(img, view.mapToWidget(0.0, 0.004), kinematic_colour::counterClockwise()));
  EXPECT_TRUE(colourNear(img, view.mapToWidget(0.0, -0.004), kinematic_colour::clockwise()));
  EXPECT_TRUE(colourNear(img, view.mapToWidget(90.0, 0.004), kinematic_colour::clockwise()));
}

TEST(PathPlot, DeviationsAreMagnifiedAboutTheNominalPoint) {
  CircularPathView view;
  view.resize(500, 500);
  PathPlotData d;
  d.radiusMm = 50.0;
  d.magnification = 100.0;
  for (int a = 0; a < 360; a += 10) {
    const double t = a * std::numbers::pi / 180.0;
    const Eigen::Vector2d n(50.0 * std::cos(t), 50.0 * std::sin(t));
    d.nominal.push_back(n);
    d.measured.push_back(n + Eigen::Vector2d(0.01, 0.0));  // shifted 10 um in x
  }
  view.setData(d);
  const PathPlotLayout L = view.layout();
  // Equal scales in x and y.
  const QPointF o = L.map({0.0, 0.0}), ex = L.map({10.0, 0.0}), ey = L.map({0.0, 10.0});
  EXPECT_NEAR(ex.x() - o.x(), o.y() - ey.y(), 1e-9);
  // The measured point is drawn k * 10 um = 1 mm right of its nominal point.
  const QPointF m = L.mapMagnified(d.nominal[0], d.measured[0]);
  EXPECT_NEAR(m.x() - L.map(d.nominal[0]).x(), (ex.x() - o.x()) / 10.0, 1e-9);
  const QImage img = view.grab().toImage();
  save(img, "kinematics-path.png");
  EXPECT_TRUE(
      colourNear(img, L.mapMagnified(d.nominal[9], d.measured[9]), kinematic_colour::counterClockwise()));
}

std::vector<double> series() {
  // 8 subgroups of 5 with a known spread.
  std::vector<double> v;
  const double pattern[5] = {0.0, 0.004, -0.003, 0.002, -0.001};
  for (int g = 0; g < 8; ++g)
    for (int i = 0; i < 5; ++i)
      v.push_back(100.0 + 0.001 * (g % 3) + (1.0 + 0.25 * (g % 4)) * pattern[(i + g) % 5]);
  return v;
}

TEST(ControlChart, LimitsAreDrawnAtTheCoresValues) {
  const XbarRChart chart = xbarRChart(series(), 5);
  const ControlChartConstants& k = controlChartConstants(5);
  ASSERT_NEAR(chart.xbarUcl, chart.grandMean + k.A2 * chart.meanRange, 1e-12);

  for (const ControlChartKind kind : {ControlChartKind::Mean, ControlChartKind::Range}) {
    ControlChartView view(kind);
    view.resize(640, 280);
    view.setChart(chart, QStringLiteral("mm"));
    const ControlChartLayout L = view.layout();
    const QImage img = view.grab().toImage();
    save(img, kind == ControlChartKind::Mean ? "kinematics-xbar.png" : "kinematics-r.png");
    const double ucl = kind == ControlChartKind::Mean ? chart.xbarUcl : chart.rUcl;
    const double cl = kind == ControlChartKind::Mean ? chart.grandMean : chart.meanRange;
    const double lcl = kind == ControlChartKind::Mean ? chart.xbarLcl : chart.rLcl;
    // The limits lie inside the plot, in order.
    EXPECT_LT(L.yOf(ucl), L.yOf(cl));
    EXPECT_GE(L.yOf(ucl), L.plotArea().top());
    EXPECT_LE(L.yOf(lcl), L.plotArea().bottom() + 1e-9);
    // Dashed red lines at UCL and LCL, a solid green line at CL, over the plot's width (the labels
    // cover the right end).
    const double x0 = L.plotArea().left() + 2, x1 = L.plotArea().left() + 0.6 * L.plotArea().width();
    EXPECT_GT(rowFraction(img, L.yOf(ucl), x0, x1, kinematic_colour::limit()), 0.35)
        << static_cast<int>(kind);
    EXPECT_GT(rowFraction(img, L.yOf(cl), x0, x1, kinematic_colour::centreLine()), 0.6)
        << static_cast<int>(kind);
    if (lcl > L.yMin()) {
      EXPECT_GT(rowFraction(img, L.yOf(lcl), x0, x1, kinematic_colour::limit()), 0.35)
          << static_cast<int>(kind);
    }
    // Halfway between the lines there is no line.
    EXPECT_LT(rowFraction(img, (L.yOf(ucl) + L.yOf(cl)) / 2 + 0.5, x0, x1, kinematic_colour::limit()), 0.1);
  }
  // R chart with n = 5: D3 = 0, so the LCL is 0 on the axis.
  EXPECT_DOUBLE_EQ(chart.rLcl, 0.0);
}

// Phase I / phase II and the Nelson rules on the chart (the series of tests/core/spc/spc_test.cpp):
// six subgroups of 4, limits from the first four, subgroup 6 shifted beyond the UCL (Nelson 1).
TEST(ControlChart, NelsonRulesAndThePhaseBoundaryAreMarked) {
  QLocale::setDefault(QLocale::c());
  const std::vector<double> phases = {10.0, 10.2, 9.9,  10.1, 10.1, 9.9,  10.0, 10.2, 9.8,  10.0, 10.1, 9.9,
                                      10.0, 9.8,  10.2, 9.9,  10.1, 10.0, 9.9,  10.0, 10.4, 10.3, 10.5, 10.4};
  SpcOptions o;
  o.subgroupSize = 4;
  o.baseSubgroups = 4;
  const SpcResult r = analyseSpc(phases, o);
  ASSERT_EQ(r.rules.size(), 1u);
  ControlChartView plain(ControlChartKind::Mean), marked(ControlChartKind::Mean);
  for (ControlChartView* v : {&plain, &marked}) v->resize(640, 280);
  plain.setChart(r.chart, QStringLiteral("mm"));
  marked.setChart(r.chart, QStringLiteral("mm"), r.rules);
  const ControlChartLayout L = marked.layout();
  const QImage img = marked.grab().toImage();
  save(img, "kinematics-xbar-phase2.png");
  // The read-out of subgroup 6 names the rule; subgroup 5 breaks none.
  EXPECT_EQ(plotReadoutAt(&marked, L.map(6.0, r.chart.means[5])),
            QStringLiteral("subgroup 6\nmean: 10.4 mm\nNelson 1: one point beyond the control limits"));
  EXPECT_EQ(plotReadoutAt(&marked, L.map(5.0, r.chart.means[4])), QStringLiteral("subgroup 5\nmean: 10 mm"));
  // A dashed line between subgroups 4 and 5 over the plot's height, none between 3 and 4.
  const double top = L.plotArea().top() + 20, bottom = L.plotArea().bottom() - 2;
  EXPECT_GT(columnFraction(img, L.map(4.5, 0).x(), top, bottom, phaseBoundaryColour()), 0.3);
  EXPECT_LT(columnFraction(img, L.map(3.5, 0).x(), top, bottom, phaseBoundaryColour()), 0.05);
  // The rule's point is ringed in red: more red around it than without the rules.
  const QPointF six = L.map(6.0, r.chart.means[5]);
  const QImage without = plain.grab().toImage();
  EXPECT_GT(pixelsNear(img, six, kinematic_colour::limit(), 12),
            pixelsNear(without, six, kinematic_colour::limit(), 12) + 8);
  EXPECT_EQ(nelsonRulesSummary(r), QStringLiteral("X-bar 1 at 6 (limits from subgroups 1–4)"));
  EXPECT_EQ(ruleBreaksAt(r.rules, ControlChartKind::Range, 5), QStringList());
}

// Individuals: the moving-range chart starts at subgroup 2 and names its rules there.
TEST(ControlChart, MovingRangesAreDrawnAtTheirLaterSubgroup) {
  QLocale::setDefault(QLocale::c());
  SpcOptions o;
  o.subgroupSize = 1;
  o.baseSubgroups = 8;
  const SpcResult r = analyseSpc({10.0, 10.2, 10.1, 10.4, 10.2, 10.3, 10.1, 10.2, 11.0, 10.2}, o);
  ControlChartView range(ControlChartKind::Range);
  range.resize(640, 280);
  range.setChart(r.chart, QStringLiteral("mm"), r.rules);
  const ControlChartLayout L = range.layout();
  save(range.grab().toImage(), "kinematics-mr.png");
  EXPECT_TRUE(
      plotReadoutAt(&range, L.map(2.0, r.chart.ranges[0])).startsWith(QStringLiteral("subgroup 2\nrange: ")));
  EXPECT_EQ(plotReadoutAt(&range, L.map(10.0, r.chart.ranges[8])),
            QStringLiteral("subgroup 10\nrange: 0.8 mm\nNelson 1: one point beyond the control limits\n"
                           "Nelson 5: two of three beyond 2 σ on the same side"));
  EXPECT_EQ(nelsonRulesSummary(r),
            QStringLiteral("X 1 at 9; MR 1 at 9, 10; MR 5 at 10 (limits from subgroups 1–8)"));
  // Three subgroups of 5 with no rule broken (tests/core/spc/spc_test.cpp, kData).
  SpcOptions five;
  five.subgroupSize = 5;
  EXPECT_EQ(nelsonRulesSummary(analyseSpc(
                {10.0, 10.2, 9.9, 10.1, 9.8, 10.1, 10.3, 10.0, 10.2, 9.9, 9.9, 10.1, 9.8, 10.0, 9.7}, five)),
            QStringLiteral("none broken"));
}

TEST(Histogram, BinsCoverMinToMaxWithEqualWidths) {
  const std::vector<double> v{1, 2, 2, 3, 3, 3, 4, 4, 4, 4};
  const HistogramBins h = histogramBins(v, 4);
  EXPECT_DOUBLE_EQ(h.first, 1.0);
  EXPECT_DOUBLE_EQ(h.width, 0.75);
  EXPECT_EQ(h.counts, (std::vector<int>{1, 2, 3, 4}));
  EXPECT_DOUBLE_EQ(h.edge(4), 4.0);
  // Automatic count: ceil(sqrt(N)) clamped to [5, 20].
  EXPECT_EQ(histogramBins(v).counts.size(), 5u);
  EXPECT_EQ(histogramBins(std::vector<double>(1000, 0.0)).counts.size(), 20u);
  std::vector<double> many;
  for (int i = 0; i < 100; ++i) many.push_back(i * 0.1);
  const HistogramBins m = histogramBins(many);
  ASSERT_EQ(m.counts.size(), 10u);
  for (int c : m.counts) EXPECT_EQ(c, 10);
  // All values equal: every value in a bin.
  const HistogramBins flat = histogramBins(std::vector<double>(7, 5.0));
  int total = 0;
  for (int c : flat.counts) total += c;
  EXPECT_EQ(total, 7);
  EXPECT_TRUE(histogramBins({}).counts.size() == 5u);
}

TEST(Histogram, SpecificationLimitsAreDrawnAtTheirValues) {
  HistogramView view;
  view.resize(600, 280);
  HistogramData d;
  d.values = series();
  d.bins = histogramBins(d.values);
  d.lsl = 99.99;
  d.usl = 100.01;
  view.setData(d);
  const HistogramLayout L = view.layout();
  EXPECT_LE(L.xMin(), 99.99);
  EXPECT_GE(L.xMax(), 100.01);
  const QImage img = view.grab().toImage();
  save(img, "kinematics-histogram.png");
  for (const double limit : {99.99, 100.01}) {
    const QPointF top = L.map(limit, 0);
    int hits = 0;
    for (int y = static_cast<int>(L.plotArea().top()) + 20; y < static_cast<int>(L.plotArea().bottom()) - 2;
         ++y) {
      if (colourNear(img, QPointF(top.x(), y), kinematic_colour::specification(), 1)) ++hits;
    }
    EXPECT_GT(hits, static_cast<int>(0.8 * (L.plotArea().height() - 22))) << limit;
  }
  // A bar's top at its count.
  const std::size_t tallest = static_cast<std::size_t>(
      std::max_element(d.bins.counts.begin(), d.bins.counts.end()) - d.bins.counts.begin());
  const QPointF mid = L.map(d.bins.edge(tallest) + d.bins.width / 2, d.bins.counts[tallest] / 2.0);
  EXPECT_TRUE(colourNear(img, mid, kinematic_colour::bars(), 0));
}

TEST(SpcView, TableShowsTheIndicesOfTheAnalysis) {
  SpcOptions o;
  o.subgroupSize = 5;
  o.lsl = 99.99;
  o.usl = 100.01;
  o.nominal = 100.0;
  const std::vector<double> v = series();
  const SpcResult r = analyseSpc(v, o);
  SpcView view;
  view.resize(900, 700);
  view.setResult(r, v, QStringLiteral("diameter_mm"), QStringLiteral("mm"));
  EXPECT_TRUE(view.meanChart()->hasChart());
  QStringList keys;
  QTableWidget* t = view.indexTable();
  for (int i = 0; i < t->rowCount(); ++i) keys << t->item(i, 0)->text();
  const int cp = static_cast<int>(keys.indexOf(QStringLiteral("Cp (Eq. 16)")));
  ASSERT_GE(cp, 0);
  EXPECT_EQ(t->item(cp, 1)->text(), QString::number(*r.capability.cp, 'f', 2));
  const int cpk = static_cast<int>(keys.indexOf(QStringLiteral("Cpk")));
  ASSERT_GE(cpk, 0);
  EXPECT_EQ(t->item(cpk, 1)->text(), QString::number(*r.capability.cpk, 'f', 2));
  EXPECT_GE(keys.indexOf(QStringLiteral("natural tolerance (Eq. 17)")), 0);
  EXPECT_GE(keys.indexOf(QStringLiteral("systematic error (Eq. 20)")), 0);
  EXPECT_GE(keys.indexOf(QStringLiteral("regression offset angle")), 0);
  save(view.grab().toImage(), "kinematics-spcview.png");
  view.setMessage(QStringLiteral("nothing"));
  EXPECT_FALSE(view.meanChart()->hasChart());
}

// The plot data the kinematics page and the report both draw (one builder each, widgets/kinematics/
// kinematicplots.h): loop directions per point, the preview's radial deviations |e - c| - R at
// atan2 angles written out here, the histogram of only the values the chart used, and a radial-only
// test without a radius drawn around 100 mm and marked so.
TEST(PlotData, CircularTestBuildersCarryTheStudyAsTheFormulasSay) {
  MeasuredPath m;
  for (int i = 0; i < 6; ++i) {
    const double t = i * 60.0 * std::numbers::pi / 180.0;
    m.command.emplace_back(50.0 * std::cos(t), 50.0 * std::sin(t));
    m.measured.emplace_back(50.01 * std::cos(t), 50.01 * std::sin(t));
  }
  CircularAnalysis a;
  a.centreMm = Eigen::Vector2d(0.002, -0.001);
  a.radiusMm = 50.0;
  a.loops.resize(2);
  a.loops[0].counterClockwise = true;
  a.loops[0].first = 0;
  a.loops[0].points.resize(2);
  a.loops[1].counterClockwise = false;
  a.loops[1].first = 2;
  a.loops[1].points.resize(4);
  const PathPlotData path = circularPathData(m, a, QStringLiteral("t"));
  ASSERT_EQ(path.counterClockwise.size(), 6u);
  EXPECT_EQ(path.counterClockwise, (std::vector<bool>{true, true, false, false, false, false}));
  EXPECT_EQ(path.nominal, m.command);
  EXPECT_EQ(path.measured, m.measured);
  EXPECT_DOUBLE_EQ(path.radiusMm, 50.0);
  EXPECT_EQ(path.title, QStringLiteral("t"));

  PathPlotData p2 = path;
  PolarPlotData polar = circularPolarData(a, QStringLiteral("p"));
  EXPECT_EQ(polar.loops.size(), 2u);
  CompensationPreview c;
  c.references = {Eigen::Vector2d(1, 2)};
  c.expected = {Eigen::Vector2d(0.002, 50.006), Eigen::Vector2d(-49.990, -0.001)};
  addCompensationPreview(p2, polar, c, a);
  EXPECT_EQ(p2.references, c.references);
  EXPECT_EQ(p2.expected, c.expected);
  ASSERT_EQ(polar.compensated.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const Eigen::Vector2d d = c.expected[i] - a.centreMm;
    double angle = std::atan2(d.y(), d.x()) * 180.0 / std::numbers::pi;
    if (angle < 0.0) angle += 360.0;
    EXPECT_NEAR(polar.compensated[i].deviationMm, d.norm() - 50.0, 1e-12) << i;
    EXPECT_NEAR(polar.compensated[i].angleDeg, angle, 1e-9) << i;
  }
  EXPECT_NEAR(polar.compensated[0].deviationMm, 0.007, 1e-12);
  EXPECT_GT(polar.magnification, 0.0);  // chosen again for the preview
  EXPECT_GT(polar.ringStepMm, 0.0);

  CircularTrace trace;
  trace.radialOnly = true;
  const PolarPlotData noRadius = radialTestPolarData(trace, a, QStringLiteral("r"));
  EXPECT_DOUBLE_EQ(noRadius.radiusMm, 100.0);
  EXPECT_FALSE(noRadius.radiusKnown);
  trace.nominalRadiusMm = 75.0;
  const PolarPlotData withRadius = radialTestPolarData(trace, a, QStringLiteral("r"));
  EXPECT_DOUBLE_EQ(withRadius.radiusMm, 75.0);
  EXPECT_TRUE(withRadius.radiusKnown);

  SpcResult r;
  r.valuesUsed = 10;  // two subgroups of five; the eleventh value is the incomplete subgroup
  r.options.lsl = 9.9;
  r.options.usl = 10.1;
  r.options.nominal = 10.0;
  r.chart.grandMean = 10.02;
  std::vector<double> values;
  for (int i = 0; i < 11; ++i) values.push_back(10.0 + 0.01 * i);
  const HistogramData h = spcHistogramData(r, values, QStringLiteral("mm"), QStringLiteral("h"));
  ASSERT_EQ(h.values.size(), 10u);
  EXPECT_DOUBLE_EQ(h.values.back(), 10.09);
  EXPECT_EQ(*h.lsl, 9.9);
  EXPECT_EQ(*h.usl, 10.1);
  EXPECT_EQ(*h.nominal, 10.0);
  EXPECT_EQ(*h.mean, 10.02);
  int counted = 0;
  for (int n : h.bins.counts) counted += n;
  EXPECT_EQ(counted, 10);
}

// Zoom, pan and the cursor read-out of the QPainter plots (widgets/common/plotnavigation.h, issue 28
// item 5): the wheel magnifies around the cursor (the point under it stays), the pixels follow, the
// read-out names the point under the cursor with its values, a double click shows the whole plot.
TEST(PlotNavigation, PolarPlotZoomsAroundTheCursorAndReadsThePointUnderIt) {
  QLocale::setDefault(QLocale::c());
  PolarDeviationView view;
  view.resize(520, 600);
  PolarPlotData d = bumpAt90();
  d.magnification = 1000.0;
  d.ringStepMm = 0.005;
  view.setData(d);
  ASSERT_TRUE(hasPlotNavigation(&view));
  const QPointF tip = view.mapToWidget(90.0, 0.010);
  // Unzoomed: at the bump's tip the read-out names its angle and deviation.
  QString text = plotReadoutAt(&view, tip);
  EXPECT_TRUE(text.contains(QStringLiteral("angle: 90")) && text.contains(QStringLiteral("deviation: 10 ")))
      << text.toStdString();
  EXPECT_TRUE(plotReadoutAt(&view, QPointF(3, 3)).isEmpty()) << "no point near the corner";

  // Four wheel notches at the tip: magnified by 1.25^4, the tip stays under the cursor.
  QWheelEvent wheel(tip, view.mapToGlobal(tip), QPoint(), QPoint(0, 4 * 120), Qt::NoButton, Qt::NoModifier,
                    Qt::NoScrollPhase, false);
  QCoreApplication::sendEvent(&view, &wheel);
  ASSERT_TRUE(isPlotZoomed(&view));
  const QTransform t = plotViewTransform(&view);
  EXPECT_NEAR(t.m11(), std::pow(1.25, 4), 1e-12);
  EXPECT_NEAR(t.map(tip).x(), tip.x(), 1e-9);
  EXPECT_NEAR(t.map(tip).y(), tip.y(), 1e-9);
  const QImage zoomed = view.grab().toImage();
  save(zoomed, "kinematics-polar-zoomed.png");
  EXPECT_TRUE(colourNear(zoomed, tip, kinematic_colour::counterClockwise()));
  // The loop at 0 deg, 20 px right of the centre line at unzoomed scale, is drawn where the
  // transform puts it (checked in the pixels).
  const QPointF at0 = t.map(view.mapToWidget(45.0, 0.0));
  if (QRectF(view.rect()).contains(at0))
    EXPECT_TRUE(colourNear(zoomed, at0, kinematic_colour::counterClockwise(), 2));
  // Still the same point under the cursor after the zoom.
  EXPECT_EQ(plotReadoutAt(&view, tip), text);
  // A drag pans: the plot moves with the mouse.
  QTest::mousePress(&view, Qt::LeftButton, Qt::NoModifier, QPoint(200, 200));
  QTest::mouseMove(&view, QPoint(230, 210));
  QTest::mouseRelease(&view, Qt::LeftButton, Qt::NoModifier, QPoint(230, 210));
  const QTransform panned = plotViewTransform(&view);
  EXPECT_NEAR(panned.dx() - t.dx(), 30.0, 1e-9);
  EXPECT_NEAR(panned.dy() - t.dy(), 10.0, 1e-9);
  // A double click shows the whole plot again.
  QTest::mouseDClick(&view, Qt::LeftButton, Qt::NoModifier, QPoint(100, 100));
  EXPECT_FALSE(isPlotZoomed(&view));
  EXPECT_TRUE(plotViewTransform(&view).isIdentity());
  EXPECT_FALSE(resetPlotZoom(&view)) << "nothing to reset";
}

TEST(PlotNavigation, ControlChartAndHistogramReadTheirValues) {
  QLocale::setDefault(QLocale::c());
  const XbarRChart chart = xbarRChart(series(), 5);
  ControlChartView mean(ControlChartKind::Mean);
  mean.resize(640, 280);
  mean.setChart(chart, QStringLiteral("mm"));
  const QPointF third = mean.layout().map(3.0, chart.means[2]);
  EXPECT_EQ(plotReadoutAt(&mean, third),
            QStringLiteral("subgroup 3\nmean: %1 mm").arg(QLocale::c().toString(chart.means[2], 'g', 5)));
  ControlChartView range(ControlChartKind::Range);
  range.resize(640, 280);
  range.setChart(chart, QStringLiteral("mm"));
  EXPECT_TRUE(plotReadoutAt(&range, range.layout().map(5.0, chart.ranges[4]))
                  .startsWith(QStringLiteral("subgroup 5\nrange: ")));
  // Zoomed 3 x around the third point, the read-out there is the same.
  zoomPlot(&mean, third, 3.0);
  EXPECT_TRUE(plotReadoutAt(&mean, third).startsWith(QStringLiteral("subgroup 3\n")));

  HistogramView histogram;
  histogram.resize(640, 280);
  HistogramData h;
  h.values = {1.0, 1.05, 1.5, 1.7, 2.0};
  h.bins = histogramBins(h.values, 5);  // width 0.2 from 1.0: counts 2, 0, 1, 1, 1
  h.unit = QStringLiteral("mm");
  histogram.setData(h);
  const HistogramLayout L = histogram.layout();
  const double y = L.plotArea().center().y();
  EXPECT_EQ(plotReadoutAt(&histogram, QPointF(L.map(1.1, 0).x(), y)),
            QStringLiteral("1 to 1.2 mm\ncount: 2"));
  EXPECT_EQ(plotReadoutAt(&histogram, QPointF(L.map(1.7, 0).x(), y)),
            QStringLiteral("1.6 to 1.8 mm\ncount: 1"));
  EXPECT_TRUE(plotReadoutAt(&histogram, QPointF(2, 2)).isEmpty());
}

}  // namespace
}  // namespace metrofit
