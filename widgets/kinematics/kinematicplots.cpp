#include "widgets/kinematics/kinematicplots.h"
#include "widgets/common/palette.h"

#include <QCoreApplication>
#include <QFont>
#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>

#include <algorithm>
#include <cmath>
#include <numbers>
#include "core/common/axis_ticks.h"
#include "core/kinematics/iso230_4.h"
#include "core/kinematics/measured_path.h"
#include "core/spc/spc.h"

namespace metrofit {
namespace {

struct PlotText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::KinematicPlots)
};

constexpr double kDegToRad = std::numbers::pi / 180.0;

QFont plotFont(const PlotStyle& s, double factor = 1.0, bool bold = false) {
  QFont f;
  f.setPixelSize(std::max(1, static_cast<int>(std::lround(s.fontPx * factor))));
  f.setBold(bold);
  return f;
}

QPen pen(const QColor& c, double width, Qt::PenStyle style = Qt::SolidLine) {
  QPen p(c, width, style);
  p.setCapStyle(Qt::FlatCap);
  p.setJoinStyle(Qt::RoundJoin);
  return p;
}

int decimalsFor(double step) {
  if (!(step > 0.0) || !std::isfinite(step)) return 0;
  return std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 9);
}

/// Ticks j * step inside [lo, hi].
std::vector<double> ticks(double lo, double hi, double step) {
  std::vector<double> t;
  if (!(step > 0.0) || !(hi > lo)) return t;
  for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step) {
    t.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
    if (t.size() > 200) break;
  }
  return t;
}

void drawTitle(QPainter& p, const QRectF& r, const QString& text, const PlotStyle& s) {
  if (text.isEmpty()) return;
  p.setFont(plotFont(s, 1.1, true));
  p.setPen(Qt::black);
  p.drawText(r, Qt::AlignHCenter | Qt::AlignVCenter | Qt::TextSingleLine, text);
}

struct LegendItem {
  QColor colour;
  QString text;
  Qt::PenStyle style = Qt::SolidLine;
};

/// Legend entries in rows, left to right, wrapping at the area's width. Returns the height used.
double drawLegend(QPainter& p, const QRectF& area, const std::vector<LegendItem>& items, const PlotStyle& s,
                  bool background = false) {
  const QFont f = plotFont(s, 0.95);
  const QFontMetricsF fm(f);
  const double swatch = s.fontPx * 1.6, gap = s.fontPx * 0.5, line = fm.height() * 1.2;
  // Lay out first, to know the box.
  struct Placed {
    QPointF at;
    const LegendItem* item;
  };
  std::vector<Placed> placed;
  double x = area.left(), y = area.top(), widest = 0.0;
  for (const LegendItem& item : items) {
    const double w = swatch + gap * 0.6 + fm.horizontalAdvance(item.text);
    if (x > area.left() && x + w > area.right()) {
      x = area.left();
      y += line;
    }
    placed.push_back({QPointF(x, y), &item});
    x += w + gap * 2.0;
    widest = std::max(widest, x - area.left());
  }
  const double height = items.empty() ? 0.0 : y - area.top() + line;
  if (background && !items.empty()) {
    p.setPen(pen(QColor(190, 190, 190), 0.8));
    p.setBrush(QColor(255, 255, 255, 230));
    p.drawRect(QRectF(area.left() - gap, area.top() - gap * 0.5, widest + gap, height + gap));
    p.setBrush(Qt::NoBrush);
  }
  p.setFont(f);
  for (const Placed& pl : placed) {
    const double cy = pl.at.y() + line / 2.0;
    p.setPen(pen(pl.item->colour, s.lineWidth * 1.6, pl.item->style));
    p.drawLine(QPointF(pl.at.x(), cy), QPointF(pl.at.x() + swatch, cy));
    p.setPen(Qt::black);
    p.drawText(
        QRectF(pl.at.x() + swatch + gap * 0.6, pl.at.y(), fm.horizontalAdvance(pl.item->text) + 4.0, line),
        Qt::AlignLeft | Qt::AlignVCenter | Qt::TextSingleLine | Qt::TextDontClip, pl.item->text);
  }
  return height;
}

/// The height drawLegend() uses for `items` in an area `width` wide (same placement, no drawing).
double legendHeight(double width, const std::vector<LegendItem>& items, const PlotStyle& s) {
  if (items.empty()) return 0.0;
  const QFontMetricsF fm(plotFont(s, 0.95));
  const double swatch = s.fontPx * 1.6, gap = s.fontPx * 0.5, line = fm.height() * 1.2;
  double x = 0.0, y = 0.0;
  for (const LegendItem& item : items) {
    const double w = swatch + gap * 0.6 + fm.horizontalAdvance(item.text);
    if (x > 0.0 && x + w > width) {
      x = 0.0;
      y += line;
    }
    x += w + gap * 2.0;
  }
  return y + line;
}

/// Frame, grid, tick labels and axis titles of a Cartesian plot. mapX / mapY give pixels.
template <class MapX, class MapY>
void drawAxes(QPainter& p, const QRectF& plot, double x0, double x1, double xStep, double y0, double y1,
              double yStep, const QString& xTitle, const QString& yTitle, const PlotStyle& s, MapX mapX,
              MapY mapY, bool integerX = false) {
  const QFont f = plotFont(s, 0.9);
  const QFontMetricsF fm(f);
  p.setFont(f);
  const QPen grid = pen(palette::grid(), 0.8);
  const int xd = integerX ? 0 : decimalsFor(xStep), yd = decimalsFor(yStep);
  for (double v : ticks(y0, y1, yStep)) {
    const double y = mapY(v);
    p.setPen(grid);
    p.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
    p.setPen(Qt::black);
    p.drawText(QRectF(plot.left() - s.fontPx * 8.0, y - fm.height() / 2, s.fontPx * 7.5, fm.height()),
               Qt::AlignRight | Qt::AlignVCenter, s.locale.toString(v, 'f', yd));
  }
  for (double v : ticks(x0, x1, xStep)) {
    const double x = mapX(v);
    p.setPen(grid);
    p.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
    p.setPen(Qt::black);
    p.drawText(QRectF(x - s.fontPx * 5.0, plot.bottom() + s.fontPx * 0.3, s.fontPx * 10.0, fm.height()),
               Qt::AlignHCenter | Qt::AlignTop, s.locale.toString(v, 'f', xd));
  }
  p.setPen(pen(QColor(90, 90, 90), 1.0));
  p.setBrush(Qt::NoBrush);
  p.drawRect(plot);
  p.setPen(Qt::black);
  if (!xTitle.isEmpty()) {
    p.drawText(QRectF(plot.left(), plot.bottom() + fm.height() * 1.25, plot.width(), fm.height() * 1.2),
               Qt::AlignHCenter | Qt::AlignTop, xTitle);
  }
  if (!yTitle.isEmpty()) {
    p.save();
    p.translate(plot.left() - s.fontPx * 7.0, plot.center().y());
    p.rotate(-90.0);
    p.drawText(QRectF(-plot.height() / 2, -fm.height(), plot.height(), fm.height() * 1.1),
               Qt::AlignHCenter | Qt::AlignBottom, yTitle);
    p.restore();
  }
}

/// Sum of |angle steps| of a loop (deg): a full loop is about 360.
double angularSpan(const std::vector<RadialPoint>& pts) {
  double span = 0.0;
  for (std::size_t i = 1; i < pts.size(); ++i) {
    double d = std::abs(pts[i].angleDeg - pts[i - 1].angleDeg);
    if (d > 180.0) d = 360.0 - d;
    span += d;
  }
  return span;
}

void deviationRange(const PolarPlotData& d, double* lo, double* hi) {
  *lo = 0.0;
  *hi = 0.0;
  for (const CircularLoop& l : d.loops) {
    for (const RadialPoint& r : l.points) {
      *lo = std::min(*lo, r.deviationMm);
      *hi = std::max(*hi, r.deviationMm);
    }
  }
  for (const RadialPoint& r : d.compensated) {
    *lo = std::min(*lo, r.deviationMm);
    *hi = std::max(*hi, r.deviationMm);
  }
}

}  // namespace

namespace kinematic_colour {
QColor nominal() {
  return palette::nominal();
}
QColor counterClockwise() {
  return palette::measured();
}
QColor clockwise() {
  return palette::measuredSecond();
}
QColor references() {
  return palette::compensated();
}
QColor expected() {
  return palette::predicted();
}
QColor limit() {
  return palette::controlLimit();
}
QColor centreLine() {
  return palette::centreLine();
}
QColor specification() {
  return palette::specLimit();
}
QColor bars() {
  return palette::histogramBars();
}
}  // namespace kinematic_colour

PlotStyle screenPlotStyle() {
  PlotStyle s;
  s.locale = QLocale();
  s.locale.setNumberOptions(s.locale.numberOptions() | QLocale::OmitGroupSeparator);
  return s;
}

// ---- polar -------------------------------------------------------------------------------------

void PolarPlotData::autoScale() {
  double lo = 0.0, hi = 0.0;
  deviationRange(*this, &lo, &hi);
  const double largest = std::max({std::abs(lo), std::abs(hi), 1e-5});
  if (!(ringStepMm > 0.0)) ringStepMm = ticks::niceStep(largest, 2);
  if (!(magnification > 0.0)) {
    const int jMax = std::max(1, static_cast<int>(std::ceil(hi / ringStepMm - 1e-9)));
    const int jMin = std::min(-1, static_cast<int>(std::floor(lo / ringStepMm + 1e-9)));
    const double extent = std::max(jMax, -jMin) * ringStepMm;
    magnification = ticks::niceFloor(0.4 * radiusMm / extent);
  }
}

namespace {

/// The polar plot's legend entries (loops present, expected result, nominal circle).
std::vector<LegendItem> polarLegendItems(const PolarPlotData& d, const QLocale& locale) {
  std::vector<LegendItem> items;
  bool ccw = false, cw = false;
  for (const CircularLoop& l : d.loops) (l.counterClockwise ? ccw : cw) = true;
  if (ccw) items.push_back({kinematic_colour::counterClockwise(), PlotText::tr("measured, CCW loop")});
  if (cw) items.push_back({kinematic_colour::clockwise(), PlotText::tr("measured, CW loop")});
  if (!d.compensated.empty())
    items.push_back({kinematic_colour::expected(), PlotText::tr("expected after compensation")});
  items.push_back({kinematic_colour::nominal(),
                   d.radiusKnown ? PlotText::tr("nominal R %1 mm").arg(locale.toString(d.radiusMm, 'g', 6))
                                 : PlotText::tr("nominal circle (radius not in the file, drawn as %1 mm)")
                                       .arg(locale.toString(d.radiusMm, 'g', 6)),
                   Qt::DashLine});
  return items;
}

/// The note under the legend (d after autoScale()).
QString polarNote(const PolarPlotData& d, const PlotStyle& s) {
  return PlotText::tr("plotted radius = R + k × radial deviation, k = %1; rings every %2 µm")
      .arg(s.locale.toString(d.magnification, 'g', 6))
      .arg(s.locale.toString(d.ringStepMm * 1000.0, 'g', 4));
}

}  // namespace

PolarPlotLayout::PolarPlotLayout(const QRectF& area, const PolarPlotData& data, const PlotStyle& s) {
  PolarPlotData d = data;
  if (!(d.radiusMm > 0.0)) d.radiusMm = 1.0;
  d.autoScale();
  radius_ = d.radiusMm;
  k_ = d.magnification;
  step_ = d.ringStepMm;
  double lo = 0.0, hi = 0.0;
  deviationRange(d, &lo, &hi);
  jMax_ = std::max(1, static_cast<int>(std::ceil(hi / step_ - 1e-9)));
  jMin_ = std::min(-1, static_cast<int>(std::floor(lo / step_ + 1e-9)));
  // Keep the innermost ring outside the centre.
  while (jMin_ < -1 && radius_ + k_ * jMin_ * step_ <= 0.1 * radius_) ++jMin_;

  const double titleH = d.title.isEmpty() ? 0.0 : s.fontPx * 1.9;
  // Room for the legend and the note below it (more when a translation wraps them to more lines).
  const double legendWidth = area.width() - 2 * s.fontPx;
  const double noteH = QFontMetricsF(plotFont(s, 0.95))
                           .boundingRect(QRectF(0, 0, std::max(1.0, legendWidth), 1e6),
                                         Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, polarNote(d, s))
                           .height();
  const double legendH =
      std::max(s.fontPx * 1.25 * 4.3,
               legendHeight(legendWidth, polarLegendItems(d, s.locale), s) + noteH + s.fontPx * 0.3);
  title_ = QRectF(area.left(), area.top(), area.width(), titleH);
  legend_ = QRectF(area.left() + s.fontPx, area.bottom() - legendH, area.width() - 2 * s.fontPx, legendH);
  const double pad = s.fontPx * 2.4;
  const QRectF circle(area.left() + pad, area.top() + titleH + pad * 0.6, area.width() - 2 * pad,
                      area.height() - titleH - legendH - pad * 1.4);
  centre_ = circle.center();
  const double outer = radius_ + k_ * jMax_ * step_;
  scale_ = std::max(1e-9, std::min(circle.width(), circle.height()) / 2.0 / outer);
}

QPointF PolarPlotLayout::map(double angleDeg, double deviationMm) const {
  const double rho = (radius_ + k_ * deviationMm) * scale_;
  const double t = angleDeg * kDegToRad;
  return centre_ + QPointF(rho * std::cos(t), -rho * std::sin(t));
}

void paintPolarPlot(QPainter& p, const QRectF& area, const PolarPlotData& data, const PlotStyle& s) {
  PolarPlotData d = data;
  if (!(d.radiusMm > 0.0)) d.radiusMm = 1.0;
  d.autoScale();
  const PolarPlotLayout L(area, d, s);
  p.save();
  p.setRenderHint(QPainter::Antialiasing, true);
  drawTitle(p, L.titleArea(), d.title, s);

  const QPointF c = L.centre();
  const QFont small = plotFont(s, 0.85);
  const QFontMetricsF fm(small);
  // Spokes every 30 deg and their labels.
  p.setFont(small);
  const double inner = (d.radiusMm + L.magnification() * L.innerRing() * L.ringStepMm()) * L.pixelsPerMm();
  const double outer = (d.radiusMm + L.magnification() * L.outerRing() * L.ringStepMm()) * L.pixelsPerMm();
  for (int a = 0; a < 360; a += 30) {
    const double t = a * kDegToRad;
    const QPointF u(std::cos(t), -std::sin(t));
    p.setPen(pen(QColor(225, 225, 225), 0.8));
    p.drawLine(c + u * inner, c + u * outer);
    if (a % 90 == 0) {
      p.setPen(Qt::black);
      const QPointF at = c + u * (outer + s.fontPx * 1.1);
      p.drawText(QRectF(at.x() - s.fontPx * 2, at.y() - fm.height() / 2, s.fontPx * 4, fm.height()),
                 Qt::AlignCenter, QStringLiteral("%1°").arg(a));
    }
  }
  // Scale rings: deviation j * step; the ring 0 is the nominal circle. Their labels are drawn after
  // the loops, on a white box, so a curve passing the label's place never hides it.
  std::vector<std::pair<QRectF, QString>> ringLabels;
  for (int j = L.innerRing(); j <= L.outerRing(); ++j) {
    const double rho = (d.radiusMm + L.magnification() * j * L.ringStepMm()) * L.pixelsPerMm();
    p.setPen(j == 0 ? pen(kinematic_colour::nominal(), s.lineWidth, Qt::DashLine)
                    : pen(QColor(200, 200, 200), 0.9, Qt::DotLine));
    p.drawEllipse(c, rho, rho);
    const double um = j * L.ringStepMm() * 1000.0;
    const QString label = j == 0 ? PlotText::tr("0 µm")
                                 : QStringLiteral("%1%2 µm")
                                       .arg(j > 0 ? QStringLiteral("+") : QString())
                                       .arg(s.locale.toString(um, 'g', 4));
    const double t = 62.0 * kDegToRad;
    const QPointF at = c + QPointF(rho * std::cos(t), -rho * std::sin(t));
    ringLabels.push_back(
        {QRectF(at.x() + 2, at.y() - fm.height(), fm.horizontalAdvance(label) + 2, fm.height()), label});
  }
  // The loops.
  auto drawRadial = [&](const std::vector<RadialPoint>& pts, const QColor& colour, double width) {
    if (pts.empty()) return;
    QPolygonF poly;
    poly.reserve(static_cast<qsizetype>(pts.size()) + 1);
    for (const RadialPoint& r : pts) poly << L.map(r.angleDeg, r.deviationMm);
    if (pts.size() >= 3 && angularSpan(pts) > 350.0) poly << poly.front();
    p.setPen(pen(colour, width));
    p.drawPolyline(poly);
  };
  drawRadial(d.compensated, kinematic_colour::expected(), s.lineWidth);
  for (const CircularLoop& l : d.loops) {
    drawRadial(l.points,
               l.counterClockwise ? kinematic_colour::counterClockwise() : kinematic_colour::clockwise(),
               s.lineWidth);
  }
  p.setFont(small);
  for (const auto& [box, label] : ringLabels) {
    p.fillRect(box.adjusted(-1, 0, 1, 0), QColor(255, 255, 255, 215));
    p.setPen(QColor(80, 80, 80));
    p.drawText(box, Qt::AlignLeft | Qt::AlignBottom, label);
  }
  // Legend.
  const double used = drawLegend(p, L.legendArea(), polarLegendItems(d, s.locale), s);
  p.setFont(plotFont(s, 0.95));
  p.setPen(Qt::black);
  p.drawText(QRectF(L.legendArea().left(), L.legendArea().top() + used, L.legendArea().width(),
                    std::max(0.0, L.legendArea().height() - used)),
             Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, polarNote(d, s));
  p.restore();
}

// ---- path --------------------------------------------------------------------------------------

namespace {

double pathMagnification(const PathPlotData& d) {
  if (d.magnification > 0.0) return d.magnification;
  double largest = 0.0;
  auto scan = [&](const std::vector<Eigen::Vector2d>& v) {
    for (std::size_t i = 0; i < v.size() && i < d.nominal.size(); ++i)
      largest = std::max(largest, (v[i] - d.nominal[i]).norm());
  };
  scan(d.measured);
  scan(d.references);
  scan(d.expected);
  if (!(largest > 0.0)) return 1.0;
  return ticks::niceFloor(0.3 * std::max(d.radiusMm, 1e-9) / largest);
}

}  // namespace

PathPlotLayout::PathPlotLayout(const QRectF& area, const PathPlotData& d, const PlotStyle& s) {
  k_ = pathMagnification(d);
  const double r = std::max(d.radiusMm, 1e-9);
  double x0 = d.centreMm.x() - r, x1 = d.centreMm.x() + r, y0 = d.centreMm.y() - r, y1 = d.centreMm.y() + r;
  auto grow = [&](const std::vector<Eigen::Vector2d>& v) {
    for (std::size_t i = 0; i < v.size() && i < d.nominal.size(); ++i) {
      const Eigen::Vector2d q = d.nominal[i] + k_ * (v[i] - d.nominal[i]);
      x0 = std::min(x0, q.x());
      x1 = std::max(x1, q.x());
      y0 = std::min(y0, q.y());
      y1 = std::max(y1, q.y());
    }
  };
  grow(d.measured);
  grow(d.references);
  grow(d.expected);
  const double pad = 0.06 * std::max(x1 - x0, y1 - y0);
  x0 -= pad;
  x1 += pad;
  y0 -= pad;
  y1 += pad;
  const double titleH = d.title.isEmpty() ? s.fontPx * 0.6 : s.fontPx * 1.9;
  const QRectF avail(area.left() + s.fontPx * 8.5, area.top() + titleH, area.width() - s.fontPx * 9.5,
                     area.height() - titleH - s.fontPx * 3.4);
  // Equal scales: widen the range of the roomier direction.
  const double scale = std::min(avail.width() / (x1 - x0), avail.height() / (y1 - y0));
  const double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  const double hw = avail.width() / scale / 2, hh = avail.height() / scale / 2;
  x0_ = cx - hw;
  x1_ = cx + hw;
  y0_ = cy - hh;
  y1_ = cy + hh;
  plot_ = avail;
}

QPointF PathPlotLayout::map(const Eigen::Vector2d& mm) const {
  return {plot_.left() + (mm.x() - x0_) / (x1_ - x0_) * plot_.width(),
          plot_.bottom() - (mm.y() - y0_) / (y1_ - y0_) * plot_.height()};
}

QPointF PathPlotLayout::mapMagnified(const Eigen::Vector2d& nominal, const Eigen::Vector2d& point) const {
  return map(nominal + k_ * (point - nominal));
}

void paintPathPlot(QPainter& p, const QRectF& area, const PathPlotData& d, const PlotStyle& s) {
  const PathPlotLayout L(area, d, s);
  p.save();
  p.setRenderHint(QPainter::Antialiasing, true);
  drawTitle(p, QRectF(area.left(), area.top(), area.width(), s.fontPx * 1.9), d.title, s);
  const double xStep = ticks::niceStep(L.xMax() - L.xMin(), 6),
               yStep = ticks::niceStep(L.yMax() - L.yMin(), 6);
  drawAxes(
      p, L.plotArea(), L.xMin(), L.xMax(), xStep, L.yMin(), L.yMax(), yStep, PlotText::tr("X (mm)"),
      PlotText::tr("Y (mm)"), s, [&](double x) { return L.map(Eigen::Vector2d(x, L.yMin())).x(); },
      [&](double y) { return L.map(Eigen::Vector2d(L.xMin(), y)).y(); });
  p.setClipRect(L.plotArea());

  // Nominal circle, true to scale.
  QPolygonF circle;
  for (int i = 0; i <= 360; ++i) {
    const double t = i * kDegToRad;
    circle << L.map(d.centreMm + d.radiusMm * Eigen::Vector2d(std::cos(t), std::sin(t)));
  }
  p.setPen(pen(kinematic_colour::nominal(), s.lineWidth, Qt::DashLine));
  p.drawPolyline(circle);

  auto drawPath = [&](const std::vector<Eigen::Vector2d>& v, const QColor& colour,
                      const std::vector<bool>* dirs, bool wantCcw) {
    QPolygonF poly;
    auto flush = [&] {
      if (poly.size() > 1) {
        p.setPen(pen(colour, s.lineWidth));
        p.drawPolyline(poly);
      }
      poly.clear();
    };
    for (std::size_t i = 0; i < v.size() && i < d.nominal.size(); ++i) {
      const bool ccw = dirs == nullptr || dirs->empty() || (*dirs)[i];
      if (dirs != nullptr && ccw != wantCcw) {
        flush();
        continue;
      }
      poly << L.mapMagnified(d.nominal[i], v[i]);
    }
    flush();
  };
  drawPath(d.references, kinematic_colour::references(), nullptr, true);
  drawPath(d.expected, kinematic_colour::expected(), nullptr, true);
  drawPath(d.measured, kinematic_colour::counterClockwise(), &d.counterClockwise, true);
  drawPath(d.measured, kinematic_colour::clockwise(), &d.counterClockwise, false);
  p.setClipping(false);

  std::vector<LegendItem> items{{kinematic_colour::nominal(), PlotText::tr("nominal circle"), Qt::DashLine}};
  if (!d.measured.empty()) {
    items.push_back({kinematic_colour::counterClockwise(), PlotText::tr("measured CCW")});
    if (std::find(d.counterClockwise.begin(), d.counterClockwise.end(), false) != d.counterClockwise.end())
      items.push_back({kinematic_colour::clockwise(), PlotText::tr("measured CW")});
  }
  if (!d.references.empty())
    items.push_back({kinematic_colour::references(), PlotText::tr("compensated references")});
  if (!d.expected.empty()) items.push_back({kinematic_colour::expected(), PlotText::tr("expected after")});
  const QRectF legend(L.plotArea().left() + s.fontPx * 0.8, L.plotArea().top() + s.fontPx * 0.6,
                      L.plotArea().width() * 0.6, L.plotArea().height());
  drawLegend(p, legend, items, s, true);
  p.setFont(plotFont(s, 0.9));
  p.setPen(Qt::black);
  p.drawText(L.plotArea().adjusted(s.fontPx * 0.5, 0, -s.fontPx * 0.5, -s.fontPx * 0.4),
             Qt::AlignRight | Qt::AlignBottom | Qt::TextWordWrap,  // a narrow plot wraps it, never cuts it
             PlotText::tr("deviations from the nominal point × %1")
                 .arg(s.locale.toString(L.magnification(), 'g', 6)));
  p.restore();
}

// ---- control charts ------------------------------------------------------------------------------

namespace {

const std::vector<double>& chartValues(const XbarRChart& c, ControlChartKind kind) {
  return kind == ControlChartKind::Mean ? c.means : c.ranges;
}

void chartLines(const XbarRChart& c, ControlChartKind kind, double* cl, double* ucl, double* lcl) {
  if (kind == ControlChartKind::Mean) {
    *cl = c.grandMean;
    *ucl = c.xbarUcl;
    *lcl = c.xbarLcl;
  } else {
    *cl = c.meanRange;
    *ucl = c.rUcl;
    *lcl = c.rLcl;
  }
}

}  // namespace

/// The 1-based subgroup (the x of the chart) of point i of the chart of `kind`.
static double subgroupOf(const XbarRChart& c, ControlChartKind kind, std::size_t i) {
  return static_cast<double>((kind == ControlChartKind::Mean ? i : c.rangeSubgroup(i)) + 1);
}

QString nelsonRuleText(int rule) {
  switch (rule) {
    case 1:
      return PlotText::tr("one point beyond the control limits");
    case 2:
      return PlotText::tr("nine in a row on one side of the centre line");
    case 3:
      return PlotText::tr("six in a row steadily increasing or decreasing");
    case 4:
      return PlotText::tr("fourteen in a row alternating up and down");
    case 5:
      return PlotText::tr("two of three beyond 2 σ on the same side");
    case 6:
      return PlotText::tr("four of five beyond 1 σ on the same side");
    case 7:
      return PlotText::tr("fifteen in a row within 1 σ");
    case 8:
      return PlotText::tr("eight in a row beyond 1 σ on either side");
    default:
      return {};
  }
}

QStringList ruleBreaksAt(const std::vector<RuleBreak>& rules, ControlChartKind kind, std::size_t subgroup) {
  const RuleChart chart = kind == ControlChartKind::Mean ? RuleChart::Mean : RuleChart::Range;
  QStringList out;
  for (const RuleBreak& b : rules) {
    if (b.chart != chart) continue;
    if (std::find(b.subgroups.begin(), b.subgroups.end(), subgroup) == b.subgroups.end()) continue;
    out << PlotText::tr("Nelson %1: %2").arg(b.rule).arg(nelsonRuleText(b.rule));
  }
  return out;
}

QColor phaseBoundaryColour() {
  return {90, 90, 160};
}

QString nelsonRulesSummary(const SpcResult& r) {
  QStringList parts;
  const bool individuals = r.chart.type == ChartType::IndividualsMR;
  for (const RuleBreak& b : r.rules) {
    QStringList at;
    for (const std::size_t g : b.subgroups) at << QString::number(g + 1);
    const QString chart = b.chart == RuleChart::Mean
                              ? (individuals ? PlotText::tr("X") : PlotText::tr("X-bar"))
                              : (individuals ? PlotText::tr("MR") : PlotText::tr("R"));
    parts << PlotText::tr("%1 %2 at %3").arg(chart).arg(b.rule).arg(at.join(QStringLiteral(", ")));
  }
  QString text = parts.isEmpty() ? PlotText::tr("none broken") : parts.join(QStringLiteral("; "));
  if (r.chart.baseSubgroups < r.chart.subgroups())
    text += PlotText::tr(" (limits from subgroups 1–%1)").arg(r.chart.baseSubgroups);
  return text;
}

ControlChartLayout::ControlChartLayout(const QRectF& area, const XbarRChart& chart, ControlChartKind kind,
                                       const PlotStyle& s) {
  const auto& v = chartValues(chart, kind);
  double cl = 0, ucl = 0, lcl = 0;
  chartLines(chart, kind, &cl, &ucl, &lcl);
  double lo = std::min(lcl, cl), hi = std::max(ucl, cl);
  for (double x : v) {
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  if (!(hi > lo)) {
    hi = lo + 1.0;
  }
  const double pad = 0.1 * (hi - lo);
  y0_ = kind == ControlChartKind::Range ? std::max(0.0, lo - pad) : lo - pad;
  if (kind == ControlChartKind::Range && lo - pad < 0.0) y0_ = 0.0;
  y1_ = hi + pad;
  x0_ = 0.5;
  x1_ = static_cast<double>(std::max<std::size_t>(1, chart.subgroups())) + 0.5;  // moving ranges: from 2
  const double titleH = s.fontPx * 1.9;  // the right margin holds the labels of CL and the limits
  plot_ = QRectF(area.left() + s.fontPx * 8.5, area.top() + titleH, area.width() - s.fontPx * 16.0,
                 area.height() - titleH - s.fontPx * 3.4);
}

QPointF ControlChartLayout::map(double subgroup, double value) const {
  return {plot_.left() + (subgroup - x0_) / (x1_ - x0_) * plot_.width(),
          plot_.bottom() - (value - y0_) / (y1_ - y0_) * plot_.height()};
}

void paintControlChart(QPainter& p, const QRectF& area, const XbarRChart& chart, ControlChartKind kind,
                       const QString& unit, const PlotStyle& s, const std::vector<RuleBreak>& rules) {
  const ControlChartLayout L(area, chart, kind, s);
  const auto& v = chartValues(chart, kind);
  double cl = 0, ucl = 0, lcl = 0;
  chartLines(chart, kind, &cl, &ucl, &lcl);
  p.save();
  p.setRenderHint(QPainter::Antialiasing, true);
  const bool mean = kind == ControlChartKind::Mean;
  const bool individuals = chart.type == ChartType::IndividualsMR;
  const double count = static_cast<double>(chart.subgroups());
  QString title = individuals ? (mean ? PlotText::tr("X chart (individual values)")
                                      : PlotText::tr("MR chart (moving range of 2)"))
                              : (mean ? PlotText::tr("X-bar chart (subgroups of %1)").arg(chart.subgroupSize)
                                      : PlotText::tr("R chart (subgroups of %1)").arg(chart.subgroupSize));
  if (chart.baseSubgroups < chart.subgroups())
    title += PlotText::tr(", limits from subgroups 1–%1").arg(chart.baseSubgroups);
  drawTitle(p, QRectF(area.left(), area.top(), area.width(), s.fontPx * 1.9), title, s);
  const double yStep = ticks::niceStep(L.yMax() - L.yMin(), 5);
  const double xStep = std::max(1.0, ticks::niceStep(count, 8));
  const QString u = unit.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(unit);
  const QString yTitle = individuals
                             ? (mean ? PlotText::tr("value") : PlotText::tr("moving range"))
                             : (mean ? PlotText::tr("subgroup mean") : PlotText::tr("subgroup range"));
  drawAxes(
      p, L.plotArea(), 1.0, count, xStep, L.yMin(), L.yMax(), yStep, PlotText::tr("subgroup"), yTitle + u, s,
      [&](double x) { return L.map(x, 0).x(); }, [&](double y) { return L.yOf(y); }, true);

  // Centre line and limits, labelled with their values.
  const int decimals = decimalsFor(yStep) + 1;
  const QFont small = plotFont(s, 0.85);
  const QFontMetricsF fm(small);
  p.setFont(small);
  struct Line {
    double value;
    QColor colour;
    Qt::PenStyle style;
    QString name;
  };
  const Line lines[] = {
      {ucl, kinematic_colour::limit(), Qt::DashLine, PlotText::tr("UCL", "upper control limit")},
      {cl, kinematic_colour::centreLine(), Qt::SolidLine, PlotText::tr("CL", "centre line")},
      {lcl, kinematic_colour::limit(), Qt::DashLine, PlotText::tr("LCL", "lower control limit")}};
  for (const Line& line : lines) {
    const double y = L.yOf(line.value);
    p.setPen(pen(line.colour, s.lineWidth, line.style));
    p.drawLine(QPointF(L.plotArea().left(), y), QPointF(L.plotArea().right(), y));
    p.setPen(line.colour.darker(130));
    p.drawText(
        QRectF(L.plotArea().right() + s.fontPx * 0.4, y - fm.height() / 2, s.fontPx * 7.4, fm.height()),
        Qt::AlignLeft | Qt::AlignVCenter,
        QStringLiteral("%1 %2").arg(line.name, s.locale.toString(line.value, 'f', decimals)));
  }
  // Phase I / phase II: a dashed line between subgroup K and K + 1, labelled on both sides.
  if (chart.baseSubgroups < chart.subgroups()) {
    const double x = L.map(static_cast<double>(chart.baseSubgroups) + 0.5, 0.0).x();
    p.setPen(pen(phaseBoundaryColour(), s.lineWidth, Qt::DashLine));
    p.drawLine(QPointF(x, L.plotArea().top()), QPointF(x, L.plotArea().bottom()));
    p.setPen(phaseBoundaryColour());
    const double w = s.fontPx * 6.0;
    p.drawText(QRectF(x - w - s.fontPx * 0.3, L.plotArea().top(), w, fm.height()),
               Qt::AlignRight | Qt::AlignTop, PlotText::tr("phase I"));
    p.drawText(QRectF(x + s.fontPx * 0.3, L.plotArea().top(), w, fm.height()), Qt::AlignLeft | Qt::AlignTop,
               PlotText::tr("phase II"));
  }
  // The points, out-of-control ones (beyond the limits or breaking a Nelson rule) in red; those
  // breaking a rule also ringed.
  const auto& out = mean ? chart.xbarOutOfControl : chart.rOutOfControl;
  QPolygonF poly;
  for (std::size_t i = 0; i < v.size(); ++i) poly << L.map(subgroupOf(chart, kind, i), v[i]);
  p.setPen(pen(QColor(60, 60, 60), s.lineWidth * 0.8));
  p.drawPolyline(poly);
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::size_t subgroup = mean ? i : chart.rangeSubgroup(i);
    const bool beyond = std::find(out.begin(), out.end(), subgroup) != out.end();
    const bool rule = !ruleBreaksAt(rules, kind, subgroup).isEmpty();
    p.setPen(Qt::NoPen);
    p.setBrush(beyond || rule ? kinematic_colour::limit() : kinematic_colour::counterClockwise());
    p.drawEllipse(poly[static_cast<qsizetype>(i)], s.pointRadius, s.pointRadius);
    if (rule) {
      p.setPen(pen(kinematic_colour::limit(), s.lineWidth));
      p.setBrush(Qt::NoBrush);
      p.drawEllipse(poly[static_cast<qsizetype>(i)], s.pointRadius * 2.2, s.pointRadius * 2.2);
    }
  }
  p.restore();
}

// ---- histogram -------------------------------------------------------------------------------------

HistogramBins histogramBins(const std::vector<double>& values, int bins) {
  HistogramBins h;
  const int n = static_cast<int>(values.size());
  if (bins <= 0) bins = std::clamp(static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n)))), 5, 20);
  h.counts.assign(static_cast<std::size_t>(bins), 0);
  if (values.empty()) return h;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  double first = *lo, width = (*hi - *lo) / bins;
  if (!(width > 0.0)) {
    width = 1e-9 * std::max(1.0, std::abs(*lo));
    first = *lo - width * bins / 2.0;
  }
  h.first = first;
  h.width = width;
  for (double v : values) {
    auto i = static_cast<long>(std::floor((v - first) / width));
    i = std::clamp(i, 0L, static_cast<long>(bins) - 1);
    ++h.counts[static_cast<std::size_t>(i)];
  }
  return h;
}

HistogramLayout::HistogramLayout(const QRectF& area, const HistogramData& d, const PlotStyle& s) {
  double lo = d.bins.first, hi = d.bins.edge(d.bins.counts.size());
  for (const auto& limit : {d.lsl, d.usl, d.nominal}) {
    if (limit) {
      lo = std::min(lo, *limit);
      hi = std::max(hi, *limit);
    }
  }
  if (!(hi > lo)) hi = lo + 1.0;
  const double pad = 0.06 * (hi - lo);
  x0_ = lo - pad;
  x1_ = hi + pad;
  int most = 1;
  for (int c : d.bins.counts) most = std::max(most, c);
  y1_ = most * 1.18;
  const double titleH = s.fontPx * 1.9;
  plot_ = QRectF(area.left() + s.fontPx * 8.5, area.top() + titleH, area.width() - s.fontPx * 9.5,
                 area.height() - titleH - s.fontPx * 3.4);
}

QPointF HistogramLayout::map(double value, double count) const {
  return {plot_.left() + (value - x0_) / (x1_ - x0_) * plot_.width(),
          plot_.bottom() - count / y1_ * plot_.height()};
}

void paintHistogram(QPainter& p, const QRectF& area, const HistogramData& d, const PlotStyle& s) {
  const HistogramLayout L(area, d, s);
  p.save();
  p.setRenderHint(QPainter::Antialiasing, true);
  drawTitle(p, QRectF(area.left(), area.top(), area.width(), s.fontPx * 1.9),
            d.title.isEmpty() ? PlotText::tr("Histogram") : d.title, s);
  int most = 1;
  for (int c : d.bins.counts) most = std::max(most, c);
  const double xStep = ticks::niceStep(L.xMax() - L.xMin(), 5);
  const double yStep = std::max(1.0, ticks::niceStep(most * 1.18, 5));
  const QString u = d.unit.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(d.unit);
  drawAxes(
      p, L.plotArea(), L.xMin(), L.xMax(), xStep, 0.0, most * 1.18, yStep, PlotText::tr("value") + u,
      PlotText::tr("count"), s, [&](double x) { return L.map(x, 0).x(); },
      [&](double y) { return L.map(0, y).y(); });
  p.setPen(pen(QColor(50, 100, 150), 0.8));
  p.setBrush(kinematic_colour::bars());
  for (std::size_t i = 0; i < d.bins.counts.size(); ++i) {
    if (d.bins.counts[i] == 0) continue;
    p.drawRect(QRectF(L.map(d.bins.edge(i), d.bins.counts[i]), L.map(d.bins.edge(i + 1), 0)));
  }
  p.setBrush(Qt::NoBrush);
  const QFont small = plotFont(s, 0.85);
  const QFontMetricsF fm(small);
  p.setFont(small);
  struct Mark {
    std::optional<double> value;
    QString name;
    QColor colour;
    Qt::PenStyle style;
  };
  const Mark marks[] = {{d.lsl, PlotText::tr("LSL", "lower specification limit"),
                         kinematic_colour::specification(), Qt::SolidLine},
                        {d.usl, PlotText::tr("USL", "upper specification limit"),
                         kinematic_colour::specification(), Qt::SolidLine},
                        {d.nominal, PlotText::tr("nominal"), kinematic_colour::nominal(), Qt::DashLine},
                        {d.mean, PlotText::tr("mean"), kinematic_colour::centreLine(), Qt::DashDotLine}};
  // Each label goes on the first text row (from the top) where it overlaps no label placed before,
  // so labels of close lines (nominal and mean) are staggered vertically and never overlap.
  std::vector<QRectF> placed;
  for (const Mark& m : marks) {
    if (!m.value) continue;
    const double x = L.map(*m.value, 0).x();
    p.setPen(pen(m.colour, s.lineWidth * 1.2, m.style));
    p.drawLine(QPointF(x, L.plotArea().top()), QPointF(x, L.plotArea().bottom()));
    p.setPen(m.colour.darker(120));
    const bool right = x < L.plotArea().center().x();
    const double w = fm.horizontalAdvance(m.name) + 4;
    QRectF box(right ? x + 3 : x - w - 3, L.plotArea().top() + 2, w, fm.height());
    while (std::any_of(placed.begin(), placed.end(),
                       [&box](const QRectF& q) { return q.adjusted(-2, 0, 2, 0).intersects(box); }))
      box.translate(0, fm.height());
    placed.push_back(box);
    p.drawText(box, Qt::AlignVCenter | (right ? Qt::AlignLeft : Qt::AlignRight), m.name);
  }
  p.restore();
}

// ---- plot data shared by the views and the report ---------------------------------------------

PathPlotData circularPathData(const MeasuredPath& measured, const CircularAnalysis& analysis,
                              const QString& title) {
  PathPlotData pd;
  pd.centreMm = analysis.centreMm;
  pd.radiusMm = analysis.radiusMm;
  pd.nominal = measured.command;
  pd.measured = measured.measured;
  pd.counterClockwise.assign(measured.size(), true);
  for (const CircularLoop& l : analysis.loops) {
    for (std::size_t i = 0; i < l.points.size() && l.first + i < pd.counterClockwise.size(); ++i)
      pd.counterClockwise[l.first + i] = l.counterClockwise;
  }
  pd.title = title;
  return pd;
}

PolarPlotData circularPolarData(const CircularAnalysis& analysis, const QString& title) {
  PolarPlotData polar;
  polar.radiusMm = analysis.radiusMm;
  polar.loops = analysis.loops;
  polar.title = title;
  return polar;
}

PolarPlotData radialTestPolarData(const CircularTrace& trace, const CircularAnalysis& analysis,
                                  const QString& title) {
  PolarPlotData polar = circularPolarData(analysis, title);
  // The plot needs a radius to draw the deviations around; a file without radius_mm is drawn on 100 mm.
  polar.radiusMm = trace.nominalRadiusMm.value_or(100.0);
  polar.radiusKnown = trace.nominalRadiusMm.has_value();
  return polar;
}

void addCompensationPreview(PathPlotData& path, PolarPlotData& polar, const CompensationPreview& preview,
                            const CircularAnalysis& analysis) {
  path.references = preview.references;
  path.expected = preview.expected;
  polar.compensated = radialDeviations(preview.expected, analysis.centreMm, analysis.radiusMm);
  polar.magnification = 0.0;
  polar.ringStepMm = 0.0;
  polar.autoScale();
}

HistogramData spcHistogramData(const SpcResult& result, const std::vector<double>& values,
                               const QString& unit, const QString& title) {
  HistogramData h;
  const std::size_t used = std::min(result.valuesUsed, values.size());
  h.values.assign(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(used));
  h.bins = histogramBins(h.values);
  h.lsl = result.options.lsl;
  h.usl = result.options.usl;
  h.nominal = result.options.nominal;
  h.mean = result.chart.grandMean;
  h.unit = unit;
  h.title = title;
  return h;
}

}  // namespace metrofit
