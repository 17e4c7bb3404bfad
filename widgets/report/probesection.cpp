// Report section "Posture matching — probe points": per probe point set, the deviation statistics
// before matching (identity transform), XY and XZ projections of the measured points coloured by
// deviation with a colour bar in mm, and a table per surface.
//
// Deviation of point i (ProbePointSet::deviations): d_i = n_i . (p_i - q_i) when the file has
// normals (signed, positive out of the material), else |p_i - q_i| (>= 0). Statistics: mean |d|,
// RMS = sqrt(mean d^2), max |d|, and the count of |d| > the matching study's tolerance.
#include <QCoreApplication>
#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/common/axis_ticks.h"
#include "core/study/matching_study.h"
#include "widgets/report/reportpainter.h"
#include "widgets/report/sections.h"

namespace metrofit {
namespace {

struct ReportText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::Report)
};

constexpr double kFigureHeightMm = 78.0;
constexpr double kColourBarHeightMm = 18.0;

struct DeviationStats {
  std::size_t points = 0;
  double meanAbs = 0.0;
  double meanSigned = 0.0;
  double rms = 0.0;
  double maxAbs = 0.0;
  std::size_t maxIndex = 0;
  std::size_t outside = 0;
};

DeviationStats statsOf(const std::vector<double>& d, const std::vector<std::size_t>& rows,
                       double toleranceMm) {
  DeviationStats s;
  s.points = rows.size();
  if (rows.empty()) {
    return s;
  }
  double sumAbs = 0.0;
  double sum = 0.0;
  double sumSq = 0.0;
  for (std::size_t i : rows) {
    const double a = std::abs(d[i]);
    sumAbs += a;
    sum += d[i];
    sumSq += d[i] * d[i];
    if (a > s.maxAbs || i == rows.front()) {
      s.maxAbs = a;
      s.maxIndex = i;
    }
    if (a > toleranceMm) {
      ++s.outside;
    }
  }
  const auto n = static_cast<double>(rows.size());
  s.meanAbs = sumAbs / n;
  s.meanSigned = sum / n;
  s.rms = std::sqrt(sumSq / n);
  return s;
}

QString mmText(double v) {
  return ReportText::tr("%1 mm").arg(v, 0, 'f', 4);
}

int decimalsFor(double step) {
  return std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
}

QColor mix(const QColor& a, const QColor& b, double t) {
  return QColor::fromRgbF(static_cast<float>(a.redF() + (b.redF() - a.redF()) * t),
                          static_cast<float>(a.greenF() + (b.greenF() - a.greenF()) * t),
                          static_cast<float>(a.blueF() + (b.blueF() - a.blueF()) * t));
}

/// Piecewise-linear colour map through `stops` (equally spaced) at t in [0, 1].
template <std::size_t N>
QColor colourMap(const QRgb (&stops)[N], double t) {
  t = std::clamp(t, 0.0, 1.0) * static_cast<double>(N - 1);
  const auto i = std::min(static_cast<std::size_t>(t), N - 2);
  return mix(QColor(stops[i]), QColor(stops[i + 1]), t - static_cast<double>(i));
}

// ColorBrewer RdBu (diverging, signed deviations) and YlOrRd (sequential, distances).
constexpr QRgb kDiverging[] = {0x2166ac, 0x67a9cf, 0xf7f7f7, 0xef8a62, 0xb2182b};
constexpr QRgb kSequential[] = {0xffffcc, 0xfeb24c, 0xfc4e2a, 0xbd0026};

/// The colour scale of a probe set: [-limit, limit] for signed deviations, [0, limit] otherwise.
struct ColourScale {
  bool signedScale = true;
  double limit = kDefaultProbeToleranceMm;
  double step = 0.01;

  QColor colour(double d) const {
    return signedScale ? colourMap(kDiverging, 0.5 + 0.5 * d / limit) : colourMap(kSequential, d / limit);
  }
  double low() const { return signedScale ? -limit : 0.0; }
};

ColourScale scaleFor(const ProbePointSet& set, double maxAbs) {
  ColourScale s;
  s.signedScale = set.hasNormals;
  const double m = maxAbs > 0.0 ? maxAbs : kDefaultProbeToleranceMm;
  s.step = ticks::niceCeil(m / (s.signedScale ? 2.0 : 4.0));
  s.limit = std::ceil(m / s.step - 1e-9) * s.step;
  return s;
}

/// One projection panel: measured points on axes (a, b) (0 = X, 1 = Y, 2 = Z), equal scale,
/// ticks in mm, largest deviations drawn last (on top).
void drawProjection(ReportPainter& out, const QRectF& panel, const ProbePointSet& set,
                    const std::vector<double>& d, const ColourScale& scale, int a, int b,
                    const QString& title) {
  QPainter& p = out.painter();
  const char* axisNames[] = {"X", "Y", "Z"};
  const QFont small = out.font(ReportPainter::Font::Small);
  const QFontMetricsF fm(small, p.device());

  const QRectF plot = panel.adjusted(out.mm(13.0), out.mm(6.0), -out.mm(2.0), -out.mm(10.0));
  p.setFont(out.font(ReportPainter::Font::Bold));
  p.setPen(Qt::black);
  p.drawText(QRectF(plot.left(), panel.top(), plot.width(), out.mm(5.0)), Qt::AlignLeft | Qt::AlignVCenter,
             title);

  // Data bounds of nominal and measured points, padded, stretched to the plot's aspect ratio.
  double lo[2] = {INFINITY, INFINITY};
  double hi[2] = {-INFINITY, -INFINITY};
  for (const ProbePoint& pt : set.points) {
    for (const Eigen::Vector3d* v : {&pt.nominal, &pt.measured}) {
      lo[0] = std::min(lo[0], (*v)[a]);
      hi[0] = std::max(hi[0], (*v)[a]);
      lo[1] = std::min(lo[1], (*v)[b]);
      hi[1] = std::max(hi[1], (*v)[b]);
    }
  }
  double range[2];
  double centre[2];
  for (int k = 0; k < 2; ++k) {
    range[k] = std::max((hi[k] - lo[k]) * 1.1, 1.0);
    centre[k] = 0.5 * (hi[k] + lo[k]);
  }
  const double aspect = plot.width() / plot.height();
  if (range[0] / range[1] < aspect) {
    range[0] = range[1] * aspect;
  } else {
    range[1] = range[0] / aspect;
  }
  const double x0 = centre[0] - range[0] / 2;
  const double y0 = centre[1] - range[1] / 2;
  const auto map = [&](double u, double v) {
    return QPointF(plot.left() + (u - x0) / range[0] * plot.width(),
                   plot.bottom() - (v - y0) / range[1] * plot.height());
  };

  // Frame, grid and ticks.
  p.setPen(QPen(QColor(0xdd, 0xdd, 0xdd), out.mm(0.1)));
  p.setFont(small);
  const double tickLength = out.mm(1.0);
  for (int k = 0; k < 2; ++k) {
    const double step = ticks::niceStep(range[k], 8);
    const double origin = k == 0 ? x0 : y0;
    for (double t = std::ceil(origin / step) * step; t <= origin + range[k] + 1e-9 * step; t += step) {
      const QPointF at = k == 0 ? map(t, y0) : map(x0, t);
      const QString label = QString::number(std::abs(t) < 1e-9 * step ? 0.0 : t, 'f', decimalsFor(step));
      p.setPen(QPen(QColor(0xdd, 0xdd, 0xdd), out.mm(0.1)));
      if (k == 0) {
        p.drawLine(QPointF(at.x(), plot.top()), QPointF(at.x(), plot.bottom()));
        p.setPen(Qt::black);
        p.drawLine(at, at + QPointF(0, tickLength));
        p.drawText(QRectF(at.x() - out.mm(10), plot.bottom() + tickLength, out.mm(20), fm.height()),
                   Qt::AlignHCenter | Qt::AlignTop, label);
      } else {
        p.drawLine(QPointF(plot.left(), at.y()), QPointF(plot.right(), at.y()));
        p.setPen(Qt::black);
        p.drawLine(at, at - QPointF(tickLength, 0));
        p.drawText(QRectF(panel.left(), at.y() - fm.height() / 2,
                          plot.left() - panel.left() - tickLength * 1.5, fm.height()),
                   Qt::AlignRight | Qt::AlignVCenter, label);
      }
    }
  }
  p.setPen(QPen(Qt::black, out.mm(0.2)));
  p.setBrush(Qt::NoBrush);
  p.drawRect(plot);
  p.drawText(QRectF(plot.left(), plot.bottom() + tickLength + fm.height(), plot.width(), fm.height() * 1.2),
             Qt::AlignHCenter | Qt::AlignVCenter, ReportText::tr("%1 (mm)").arg(QLatin1String(axisNames[a])));
  p.save();
  p.translate(panel.left() + fm.height() * 0.2, plot.center().y());
  p.rotate(-90);
  p.drawText(QRectF(-plot.height() / 2, 0, plot.height(), fm.height()), Qt::AlignHCenter | Qt::AlignTop,
             ReportText::tr("%1 (mm)").arg(QLatin1String(axisNames[b])));
  p.restore();

  // Points, smallest |deviation| first.
  std::vector<std::size_t> order(set.points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return std::abs(d[i]) < std::abs(d[j]); });
  const double r = out.mm(1.1);
  p.save();
  p.setClipRect(plot);
  p.setPen(QPen(QColor(0x40, 0x40, 0x40), out.mm(0.12)));
  for (std::size_t i : order) {
    const Eigen::Vector3d& m = set.points[i].measured;
    p.setBrush(scale.colour(d[i]));
    p.drawEllipse(map(m[a], m[b]), r, r);
  }
  p.restore();
}

/// Horizontal colour bar centred in `box`: the title above, ticks and labels below.
void drawColourBar(ReportPainter& out, const QRectF& box, const ColourScale& scale, const QString& title) {
  QPainter& p = out.painter();
  const QFont small = out.font(ReportPainter::Font::Small);
  const QFontMetricsF fm(small, p.device());
  const double barWidth = std::min(out.mm(110.0), box.width());
  const QRectF titleBox(box.center().x() - barWidth / 2, box.top(), barWidth, fm.height() * 1.2);
  const QRectF bar(titleBox.left(), titleBox.bottom(), barWidth, out.mm(4.0));
  constexpr int kSlices = 120;
  const double span = scale.limit - scale.low();
  for (int i = 0; i < kSlices; ++i) {
    const double v = scale.low() + span * (i + 0.5) / kSlices;
    // Slightly overlapping slices, so no hairline gaps show in viewers.
    p.fillRect(QRectF(bar.left() + bar.width() * i / kSlices, bar.top(), bar.width() / kSlices + out.mm(0.05),
                      bar.height()),
               scale.colour(v));
  }
  p.setPen(QPen(Qt::black, out.mm(0.15)));
  p.setBrush(Qt::NoBrush);
  p.drawRect(bar);
  p.setFont(small);
  p.drawText(titleBox, Qt::AlignHCenter | Qt::AlignTop, title);
  const int decimals = decimalsFor(scale.step);
  for (double t = scale.low(); t <= scale.limit + 1e-9 * scale.step; t += scale.step) {
    const double x = bar.left() + (t - scale.low()) / span * bar.width();
    p.drawLine(QPointF(x, bar.bottom()), QPointF(x, bar.bottom() + out.mm(1.0)));
    const double shown = std::abs(t) < 1e-9 * scale.step ? 0.0 : t;
    p.drawText(QRectF(x - out.mm(8), bar.bottom() + out.mm(1.6), out.mm(16), fm.height()),
               Qt::AlignHCenter | Qt::AlignTop, QString::number(shown, 'f', decimals));
  }
}

void writeProbeSet(ReportPainter& out, const ReportDataset& dataset, double toleranceMm) {
  const ProbePointSet& set = *dataset.probes;
  out.subheading(ReportText::tr("Probe points “%1”").arg(QString::fromStdString(dataset.ref.id)),
                 out.mm(40.0));
  if (!dataset.ref.description.empty()) {
    out.paragraph(QString::fromStdString(dataset.ref.description));
  }

  const std::vector<double> d = set.deviations();
  std::vector<std::size_t> all(set.points.size());
  std::iota(all.begin(), all.end(), std::size_t{0});
  const DeviationStats stats = statsOf(d, all, toleranceMm);
  std::vector<std::string> surfaces;
  for (const ProbePoint& pt : set.points) {
    if (std::find(surfaces.begin(), surfaces.end(), pt.surface) == surfaces.end()) {
      surfaces.push_back(pt.surface);
    }
  }

  const QString tolerance = QString::number(toleranceMm, 'f', 3);
  ReportTable facts;
  facts.widths = {1.3, 3.0};
  facts.rows = {
      {ReportText::tr("file"), QString::fromStdString(dataset.ref.path)},
      {ReportText::tr("points"), QString::number(stats.points)},
      {ReportText::tr("surfaces"), QString::number(surfaces.size())},
      {ReportText::tr("deviation"), set.hasNormals
                                        ? ReportText::tr("along the nominal normal, before matching")
                                        : ReportText::tr("distance |p − q| (no normals), before matching")},
      {ReportText::tr("mean |deviation|"), mmText(stats.meanAbs)},
      {ReportText::tr("RMS deviation"), mmText(stats.rms)},
      {ReportText::tr("max |deviation|"),
       stats.points > 0
           ? ReportText::tr("%1 (point %2)")
                 .arg(mmText(stats.maxAbs), QString::fromStdString(set.points[stats.maxIndex].id))
           : QString()},
      {ReportText::tr("outside ±%1 mm").arg(tolerance),
       ReportText::tr("%1 of %2").arg(stats.outside).arg(stats.points)},
  };
  if (set.hasNormals) {
    facts.rows.insert(5, {ReportText::tr("mean deviation"), mmText(stats.meanSigned)});
  }
  out.table(facts);

  // The projections: XY (top) and, unless the set is planar, XZ (front), then the colour bar.
  const ColourScale scale = scaleFor(set, stats.maxAbs);
  const QRectF figure = out.reserve(out.mm(kFigureHeightMm));
  if (set.planar) {
    drawProjection(out, figure, set, d, scale, 0, 1, ReportText::tr("Top view (XY)"));
  } else {
    const double gap = out.mm(4.0);
    const double w = (figure.width() - gap) / 2;
    drawProjection(out, QRectF(figure.left(), figure.top(), w, figure.height()), set, d, scale, 0, 1,
                   ReportText::tr("Top view (XY)"));
    drawProjection(out, QRectF(figure.left() + w + gap, figure.top(), w, figure.height()), set, d, scale, 0,
                   2, ReportText::tr("Front view (XZ)"));
  }
  drawColourBar(out, out.reserve(out.mm(kColourBarHeightMm)), scale,
                set.hasNormals ? ReportText::tr("deviation along the normal (mm)")
                               : ReportText::tr("distance |p − q| (mm)"));

  ReportTable bySurface;
  bySurface.header = {
      ReportText::tr("surface"), ReportText::tr("points"),
      set.hasNormals ? ReportText::tr("mean deviation (mm)") : ReportText::tr("mean distance (mm)"),
      ReportText::tr("max |deviation| (mm)"), ReportText::tr("outside ±%1 mm").arg(tolerance)};
  bySurface.widths = {1.4, 0.6, 1.3, 1.3, 1.3};
  bySurface.alignment = {Qt::AlignLeft, Qt::AlignRight, Qt::AlignRight, Qt::AlignRight, Qt::AlignRight};
  for (const std::string& surface : surfaces) {
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < set.points.size(); ++i) {
      if (set.points[i].surface == surface) {
        rows.push_back(i);
      }
    }
    const DeviationStats s = statsOf(d, rows, toleranceMm);
    bySurface.rows.push_back({surface.empty() ? ReportText::tr("(none)") : QString::fromStdString(surface),
                              QString::number(s.points), QString::number(s.meanSigned, 'f', 4),
                              QString::number(s.maxAbs, 'f', 4), QString::number(s.outside)});
  }
  out.table(bySurface);
}

}  // namespace

QString probePointsSectionTitle() {
  return ReportText::tr("Posture matching — probe points");
}

void writeProbePointsSection(ReportPainter& out, const ReportContext& context) {
  // Only the matching study's probe points: the report shows the studies the project declares.
  const std::string id = matching::matchingStudySettings(*context.project).datasetId;
  for (const ReportDataset* dataset : context.ofKind(dataset_kind::kProbePoints)) {
    if (dataset->ref.id == id) writeProbeSet(out, *dataset, context.probeToleranceMm);
  }
}

}  // namespace metrofit
