#include "widgets/diagnose/residualplot.h"
#include "widgets/common/chartexport.h"
#include "widgets/common/chartnavigation.h"
#include "widgets/common/palette.h"
#include "widgets/diagnose/coretexts.h"

#include <QBarCategoryAxis>
#include <QBarSeries>
#include <QBarSet>
#include <QChart>
#include <QChartView>
#include <QCoreApplication>
#include <QFontInfo>
#include <QHorizontalBarSeries>
#include <QLegend>
#include <QLocale>
#include <QPaintEvent>
#include <QPainter>
#include <QPainterPath>
#include <QRegularExpression>
#include <QScatterSeries>
#include <QStackedWidget>
#include <QVBoxLayout>
#include <QValueAxis>
#include <algorithm>
#include <cmath>
#include <limits>
#include "core/common/axis_ticks.h"

namespace metrofit {
namespace {

const QColor kBefore = palette::before();
const QColor kAfter = palette::after();

using Range = ticks::Range;

/// Tick values of a nice step covering r (about `count` ticks).
std::vector<double> ticks(const Range& r, int count) {
  const double step = ticks::niceFloor(std::max(1e-12, (r.hi - r.lo) / count));
  std::vector<double> out;
  for (double v = std::ceil(r.lo / step) * step; v <= r.hi + 1e-9 * step; v += step) out.push_back(v);
  return out;
}

QString tickText(double v, const QLocale& locale) {
  if (std::abs(v) < 1e-12) v = 0.0;
  return locale.toString(v, 'g', 5);
}

/// Frame, title, axis labels and ticks; returns the plot area and sets the value -> pixel maps.
struct Axes {
  QRectF area;
  Range xr, yr;
  QPointF map(double x, double y) const {
    return {area.left() + (x - xr.lo) / (xr.hi - xr.lo) * area.width(),
            area.bottom() - (y - yr.lo) / (yr.hi - yr.lo) * area.height()};
  }
};

Axes drawAxes(QPainter& p, const QRectF& rect, const Range& xr, const Range& yr, const QString& title,
              const QString& xLabel, const QString& yLabel, double fontPx, const QLocale& locale,
              const QStringList& categories = {}) {
  QFont f = p.font();
  f.setPixelSize(std::max(1, static_cast<int>(std::lround(fontPx))));
  p.setFont(f);
  const QFontMetricsF fm(f);
  const double line = fm.height();
  Axes a;
  a.xr = xr;
  a.yr = yr;
  const auto yt = ticks(yr, 5);
  double tickWidth = 0.0;
  for (double v : yt) tickWidth = std::max(tickWidth, fm.horizontalAdvance(tickText(v, locale)));
  a.area = QRectF(rect.left() + line * 1.4 + tickWidth + 6.0, rect.top() + line * 1.6, 0.0, 0.0);
  a.area.setRight(rect.right() - fm.horizontalAdvance(QStringLiteral("0000")) / 2.0);
  a.area.setBottom(rect.bottom() - line * 2.6);
  p.setPen(QPen(Qt::black, 0));
  QFont bold = f;
  bold.setBold(true);
  p.setFont(bold);
  p.drawText(QRectF(rect.left(), rect.top(), rect.width(), line * 1.4), Qt::AlignCenter, title);
  p.setFont(f);
  p.setPen(QPen(palette::grid(), 0));
  for (double v : yt) {
    const double y = a.map(xr.lo, v).y();
    p.drawLine(QPointF(a.area.left(), y), QPointF(a.area.right(), y));
  }
  p.setPen(QPen(Qt::black, 0));
  p.drawRect(a.area);
  for (double v : yt) {
    const double y = a.map(xr.lo, v).y();
    p.drawText(QRectF(a.area.left() - tickWidth - 6.0, y - line / 2, tickWidth + 3.0, line),
               Qt::AlignRight | Qt::AlignVCenter, tickText(v, locale));
  }
  if (!categories.isEmpty()) {
    for (int i = 0; i < categories.size(); ++i) {
      const double x = a.map(i, yr.lo).x();
      p.drawText(QRectF(x - 60.0, a.area.bottom() + 2.0, 120.0, line), Qt::AlignHCenter | Qt::AlignTop,
                 fm.elidedText(categories[i], Qt::ElideRight,
                               std::max(20.0, a.area.width() / std::max<qsizetype>(1, categories.size()))));
    }
  } else {
    for (double v : ticks(xr, 6)) {
      const double x = a.map(v, yr.lo).x();
      p.drawLine(QPointF(x, a.area.bottom()), QPointF(x, a.area.bottom() + 3.0));
      p.drawText(QRectF(x - 40.0, a.area.bottom() + 2.0, 80.0, line), Qt::AlignHCenter | Qt::AlignTop,
                 tickText(v, locale));
    }
  }
  p.drawText(QRectF(a.area.left(), a.area.bottom() + line * 1.2, a.area.width(), line * 1.3), Qt::AlignCenter,
             xLabel);
  p.save();
  p.translate(rect.left() + line * 0.7, a.area.center().y());
  p.rotate(-90.0);
  p.drawText(QRectF(-a.area.height() / 2, -line * 0.7, a.area.height(), line * 1.4), Qt::AlignCenter, yLabel);
  p.restore();
  return a;
}

void drawLegend(QPainter& p, const QRectF& area, const QList<QPair<QColor, QString>>& entries) {
  const QFontMetricsF fm(p.font());
  double w = 0.0;
  for (const auto& e : entries) w = std::max(w, fm.horizontalAdvance(e.second));
  const double line = fm.height();
  QRectF box(area.right() - w - line * 1.6 - 4.0, area.top() + 4.0, w + line * 1.6,
             line * static_cast<double>(entries.size()) + 4.0);
  p.fillRect(box, QColor(255, 255, 255, 220));
  for (int i = 0; i < entries.size(); ++i) {
    const double y = box.top() + 2.0 + line * i;
    p.setPen(Qt::NoPen);
    p.setBrush(entries[i].first);
    p.drawEllipse(QPointF(box.left() + line * 0.6, y + line / 2), line * 0.25, line * 0.25);
    p.setPen(Qt::black);
    p.drawText(QRectF(box.left() + line * 1.2, y, w + 4.0, line), Qt::AlignLeft | Qt::AlignVCenter,
               entries[i].second);
  }
  p.setBrush(Qt::NoBrush);
}

/// "um" -> "µm" for display (core writes the ASCII unit names of docs/file-formats.md).
QString displayUnits(const std::string& text) {
  QString s = QString::fromStdString(text);
  s.replace(QRegularExpression(QStringLiteral("\\bum\\b")), QStringLiteral("µm"));
  return s;
}

QStringList toStringList(const std::vector<std::string>& v) {
  QStringList out;
  for (const auto& s : v) out << QString::fromStdString(s);
  return out;
}

}  // namespace

bool hasVectorField(const diagnose::ResidualPlot& plot) {
  return !plot.vectors.empty();
}

double vectorMagnification(const diagnose::ResidualPlot& plot, const QRectF& rect) {
  Range xr, yr;
  double longest = 0.0;
  for (const auto& v : plot.vectors) {
    if (v.size() < 4) continue;
    xr.add(v[0]);
    yr.add(v[1]);
    longest = std::max(longest, std::hypot(v[2], v[3]));
  }
  if (!xr.valid() || longest <= 0.0) return 1.0;
  const double span = std::max({xr.hi - xr.lo, yr.hi - yr.lo, 1e-9});
  (void)rect;
  return ticks::niceFloor(span / 8.0 / longest);
}

void paintResidualScatter(QPainter& p, const QRectF& rect, const diagnose::ResidualPlot& plot,
                          const QString& title, double fontPx, const QLocale& locale) {
  p.save();
  p.setRenderHint(QPainter::Antialiasing, true);
  Range xr, yr;
  const std::size_t n = plot.x.size();
  for (std::size_t i = 0; i < n; ++i) {
    xr.add(plot.x[i]);
    if (i < plot.before.size()) yr.add(plot.before[i]);
    if (i < plot.after.size()) yr.add(plot.after[i]);
  }
  yr.add(0.0);
  Range xp = xr.padded();
  if (!plot.categories.empty()) xp = {-0.5, static_cast<double>(plot.categories.size()) - 0.5};
  const Axes a = drawAxes(p, rect, xp, yr.padded(), title, displayUnits(plot.xLabel),
                          displayUnits(plot.yLabel), fontPx, locale, toStringList(plot.categories));
  p.setClipRect(a.area);
  p.setPen(QPen(Qt::black, 0, Qt::DashLine));
  p.drawLine(a.map(xp.lo, 0.0), a.map(xp.hi, 0.0));
  const double r = std::max(1.0, std::min(3.0, a.area.width() / std::max<double>(1.0, std::sqrt(n) * 12.0)));
  p.setPen(Qt::NoPen);
  for (int pass = 0; pass < 2; ++pass) {
    const auto& ys = pass == 0 ? plot.before : plot.after;
    p.setBrush(pass == 0 ? kBefore : kAfter);
    for (std::size_t i = 0; i < n && i < ys.size(); ++i) {
      if (std::isfinite(plot.x[i]) && std::isfinite(ys[i])) p.drawEllipse(a.map(plot.x[i], ys[i]), r, r);
    }
  }
  p.setClipping(false);
  drawLegend(p, a.area,
             {{kBefore, QCoreApplication::translate("metrofit::ResidualPlot", "before the effect")},
              {kAfter, QCoreApplication::translate("metrofit::ResidualPlot", "after")}});
  p.restore();
}

double paintResidualVectors(QPainter& p, const QRectF& rect, const diagnose::ResidualPlot& plot,
                            const QString& title, double fontPx, const QLocale& locale) {
  p.save();
  p.setRenderHint(QPainter::Antialiasing, true);
  Range xr, yr;
  for (const auto& v : plot.vectors) {
    if (v.size() < 4) continue;
    xr.add(v[0]);
    yr.add(v[1]);
  }
  const double mag = vectorMagnification(plot, rect);
  for (const auto& v : plot.vectors) {  // the arrow tips stay inside the plot
    if (v.size() < 4) continue;
    xr.add(v[0] + mag * v[2]);
    yr.add(v[1] + mag * v[3]);
  }
  // Equal scales on x and y: widen the shorter range to the area's aspect ratio after the axes.
  Range xp = xr.padded(), yp = yr.padded();
  const QString titleText = title + QCoreApplication::translate("metrofit::ResidualPlot", " (arrows × %1)")
                                        .arg(locale.toString(mag, 'g', 6));
  QFont f = p.font();
  f.setPixelSize(std::max(1, static_cast<int>(std::lround(fontPx))));
  const QFontMetricsF fm(f);
  const double line = fm.height();
  const double w = rect.width() - line * 4.0, h = rect.height() - line * 4.2;
  if (w > 0 && h > 0) {
    const double sx = (xp.hi - xp.lo) / w, sy = (yp.hi - yp.lo) / h;
    if (sx > sy) {
      const double c = 0.5 * (yp.lo + yp.hi), half = 0.5 * sx * h;
      yp = {c - half, c + half};
    } else {
      const double c = 0.5 * (xp.lo + xp.hi), half = 0.5 * sy * w;
      xp = {c - half, c + half};
    }
  }
  p.fillRect(rect, Qt::white);
  const Axes a =
      drawAxes(p, rect, xp, yp, titleText, QCoreApplication::translate("metrofit::ResidualPlot", "x (mm)"),
               QCoreApplication::translate("metrofit::ResidualPlot", "y (mm)"), fontPx, locale);
  p.setClipRect(a.area);
  const double head = std::max(2.0, fontPx * 0.45);
  for (const auto& v : plot.vectors) {
    if (v.size() < 4) continue;
    const QPointF from = a.map(v[0], v[1]);
    const QPointF to = a.map(v[0] + mag * v[2], v[1] + mag * v[3]);
    p.setPen(QPen(kAfter, std::max(1.0, fontPx / 8.0)));
    p.drawLine(from, to);
    const QPointF d = to - from;
    const double len = std::hypot(d.x(), d.y());
    if (len > head) {
      const QPointF u = d / len, nrm(-u.y(), u.x());
      QPainterPath arrow;
      arrow.moveTo(to);
      arrow.lineTo(to - u * head + nrm * head * 0.45);
      arrow.lineTo(to - u * head - nrm * head * 0.45);
      arrow.closeSubpath();
      p.fillPath(arrow, kAfter);
    }
    p.setPen(Qt::NoPen);
    p.setBrush(Qt::black);
    p.drawEllipse(from, 1.5, 1.5);
  }
  p.restore();
  return mag;
}

// ---------------------------------------------------------------------------------------------
class ResidualPlotView::VectorWidget : public QWidget {
 public:
  explicit VectorWidget(QWidget* parent) : QWidget(parent) {
    setMinimumSize(240, 200);
    setAutoFillBackground(true);
    QPalette pal = palette();
    pal.setColor(QPalette::Window, Qt::white);
    setPalette(pal);
  }
  diagnose::ResidualPlot plot;
  QString title;
  double magnification = 1.0;

 protected:
  void paintEvent(QPaintEvent*) override {
    QPainter p(this);
    if (plot.vectors.empty()) return;
    const double px = QFontInfo(font()).pixelSize();
    magnification =
        paintResidualVectors(p, QRectF(rect()).adjusted(4, 4, -4, -4), plot, title, px, QLocale());
  }
};

class ResidualPlotView::Charts {
 public:
  QChartView* view = nullptr;
  QScatterSeries* before = nullptr;
  QScatterSeries* after = nullptr;
};

ResidualPlotView::ResidualPlotView(QWidget* parent)
    : QWidget(parent),
      stack_(new QStackedWidget(this)),
      vectors_(new VectorWidget(this)),
      charts_(new Charts) {
  charts_->view = new QChartView(this);
  charts_->view->setRenderHint(QPainter::Antialiasing);
  // High enough for the residual axis title at 1280 x 800 (Qt Charts cuts it otherwise: clipping_test).
  charts_->view->setMinimumSize(280, 240);
  stack_->addWidget(charts_->view);
  stack_->addWidget(vectors_);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(stack_);
  enableChartExport(this, QStringLiteral("diagnosis-residual"));
  enableChartNavigation(charts_->view);  // after the export: "Reset zoom" joins its menu
  clear();
}

ResidualPlotView::~ResidualPlotView() {
  delete charts_;
}

bool ResidualPlotView::showsVectorField() const {
  return plot_ && hasVectorField(*plot_);
}

int ResidualPlotView::pointCount() const {
  return charts_->before ? static_cast<int>(charts_->before->count()) : 0;
}

void ResidualPlotView::clear() {
  plot_.reset();
  auto* chart = new QChart;
  chart->setTitle(tr("Residual plot: run the diagnosis (Ctrl+R)"));
  chart->legend()->hide();
  QChart* old = charts_->view->chart();
  charts_->view->setChart(chart);
  delete old;
  charts_->before = charts_->after = nullptr;
  vectors_->plot = {};
  stack_->setCurrentWidget(charts_->view);
}

void ResidualPlotView::setPlot(const diagnose::ResidualPlot& source, const QString& title) {
  clear();
  // The axis titles translated (core's phrases, widgets/diagnose/coretexts.h); the report keeps English.
  diagnose::ResidualPlot plot = source;
  plot.xLabel = coreText(source.xLabelParts, source.xLabel).toStdString();
  plot.yLabel = coreText(source.yLabelParts, source.yLabel).toStdString();
  plot_ = plot;
  if (hasVectorField(plot)) {
    vectors_->plot = plot;
    vectors_->title = title;
    stack_->setCurrentWidget(vectors_);
    vectors_->update();
    return;
  }
  auto* chart = charts_->view->chart();
  chart->setLocale(QLocale());  // axis numbers with the user's decimal separator
  chart->setLocalizeNumbers(true);
  chart->setTitle(title);
  chart->legend()->show();
  chart->legend()->setAlignment(Qt::AlignBottom);
  charts_->before = new QScatterSeries;
  charts_->before->setName(tr("residual before the effect"));
  charts_->before->setColor(kBefore);
  charts_->before->setBorderColor(kBefore);
  charts_->before->setMarkerSize(6.0);
  charts_->after = new QScatterSeries;
  charts_->after->setName(tr("after"));
  charts_->after->setColor(kAfter);
  charts_->after->setBorderColor(kAfter);
  charts_->after->setMarkerSize(6.0);
  Range xr, yr;
  for (std::size_t i = 0; i < plot.x.size(); ++i) {
    if (!std::isfinite(plot.x[i])) continue;
    xr.add(plot.x[i]);
    if (i < plot.before.size() && std::isfinite(plot.before[i])) {
      charts_->before->append(plot.x[i], plot.before[i]);
      yr.add(plot.before[i]);
    }
    if (i < plot.after.size() && std::isfinite(plot.after[i])) {
      charts_->after->append(plot.x[i], plot.after[i]);
      yr.add(plot.after[i]);
    }
  }
  yr.add(0.0);
  chart->addSeries(charts_->before);
  chart->addSeries(charts_->after);
  auto* ax = new QValueAxis;
  auto* ay = new QValueAxis;
  QString xLabel = displayUnits(plot.xLabel);
  if (!plot.categories.empty()) {
    QStringList names = toStringList(plot.categories);
    QStringList shown;
    for (int i = 0; i < names.size(); ++i) shown << QStringLiteral("%1 = %2").arg(i).arg(names[i]);
    xLabel += QStringLiteral(" (") + shown.join(QStringLiteral(", ")) + QStringLiteral(")");
    ax->setTickType(QValueAxis::TicksDynamic);
    ax->setTickAnchor(0.0);
    ax->setTickInterval(1.0);
    ax->setLabelFormat(QStringLiteral("%d"));
    ax->setRange(-0.5, static_cast<double>(names.size()) - 0.5);
  } else {
    const Range xp = xr.valid() && xr.hi > xr.lo ? xr : xr.padded();
    ax->setRange(xp.lo, xp.hi);
    ax->applyNiceNumbers();
  }
  const Range yp = yr.padded();
  ay->setRange(yp.lo, yp.hi);
  ay->applyNiceNumbers();
  ax->setTitleText(xLabel);
  ay->setTitleText(displayUnits(plot.yLabel));
  // The plot is low at 1280 x 800: a bold title of more than a word ("Residuum (µm)") is cut by Qt
  // Charts; long labels ("apparent error of T23 (mm)") get a smaller font still (clipping_test).
  if (plot.yLabel.size() > 8) {
    QFont f = ay->titleFont();
    f.setPointSizeF(f.pointSizeF() * (plot.yLabel.size() > 22 ? 0.8 : 0.9));
    f.setBold(false);
    ay->setTitleFont(f);
  }
  chart->addAxis(ax, Qt::AlignBottom);
  chart->addAxis(ay, Qt::AlignLeft);
  for (auto* s : {charts_->before, charts_->after}) {
    s->attachAxis(ax);
    s->attachAxis(ay);
  }
  stack_->setCurrentWidget(charts_->view);
}

// ---------------------------------------------------------------------------------------------
class ErrorBarsView::Charts {
 public:
  QChartView* view = nullptr;
};

ErrorBarsView::ErrorBarsView(QWidget* parent) : QWidget(parent), charts_(new Charts) {
  enableChartExport(this, QStringLiteral("diagnosis-before-after"));
  charts_->view = new QChartView(this);
  charts_->view->setRenderHint(QPainter::Antialiasing);
  charts_->view->setMinimumSize(300, 200);
  enableChartNavigation(charts_->view);
  charts_->view->setToolTip(tr(
      "rmse and largest |error| of the fitted data, rmse of the held-out rows (thermal): the declared model "
      "(grey) and the model with the accepted effects (blue)"));
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(charts_->view);
  clear();
}

ErrorBarsView::~ErrorBarsView() {
  delete charts_;
}

void ErrorBarsView::clear() {
  auto* chart = new QChart;
  chart->setTitle(tr("Error before / after"));
  chart->legend()->hide();
  QChart* old = charts_->view->chart();
  charts_->view->setChart(chart);
  delete old;
  categories_ = 0;
}

void ErrorBarsView::setDiagnosis(const diagnose::Diagnosis& d) {
  clear();
  auto* chart = charts_->view->chart();
  chart->setLocale(QLocale());
  chart->setLocalizeNumbers(true);
  const QString unit = displayUnits(d.units);
  chart->setTitle(tr("Error before / after (%1)").arg(unit));
  auto* before = new QBarSet(tr("declared"));
  auto* after = new QBarSet(tr("+ effects"));
  before->setColor(kBefore);
  after->setColor(kAfter);
  QStringList categories{tr("rmse"), tr("max |e|")};
  *before << d.baseline.rmse << d.baseline.maxAbs;
  *after << d.final.rmse << d.final.maxAbs;
  double top = std::max({d.baseline.rmse, d.baseline.maxAbs, d.final.rmse, d.final.maxAbs});
  if (d.baseline.heldoutRmse && d.final.heldoutRmse) {
    categories << tr("held-out");
    *before << *d.baseline.heldoutRmse;
    *after << *d.final.heldoutRmse;
    top = std::max({top, *d.baseline.heldoutRmse, *d.final.heldoutRmse});
  }
  // Horizontal bars: the category names get the room on the left, the values run along the bottom.
  auto* series = new QHorizontalBarSeries;
  series->append(before);
  series->append(after);
  chart->addSeries(series);
  auto* ax = new QBarCategoryAxis;
  ax->append(categories);
  auto* ay = new QValueAxis;
  ay->setRange(0.0, top > 0.0 ? top * 1.2 : 1.0);
  ay->applyNiceNumbers();
  ay->setTitleText(unit);
  chart->addAxis(ax, Qt::AlignLeft);
  chart->addAxis(ay, Qt::AlignBottom);
  series->attachAxis(ax);
  series->attachAxis(ay);
  chart->legend()->show();
  chart->legend()->setAlignment(Qt::AlignBottom);
  categories_ = static_cast<int>(categories.size());
}

}  // namespace metrofit
