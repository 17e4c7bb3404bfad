#include "widgets/setup/setupmargins.h"
#include "widgets/common/chartexport.h"
#include "widgets/common/palette.h"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QLocale>
#include <QPainter>
#include <algorithm>
#include <cmath>
#include "core/common/axis_ticks.h"

namespace metrofit {

namespace {
struct MarginsText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::SetupMargins)
};

constexpr double kLegendRows = 1.6;  ///< legend height in row heights
constexpr double kAxisRows = 1.6;    ///< axis height in row heights
const QColor kZone = palette::toleranceZone();
const QColor kBefore = palette::before();
const QColor kAfter = palette::after();
const QColor kOut = palette::outOfTolerance();

}  // namespace

double setupMarginsHeight(std::size_t rows, double rowHeight) {
  return (static_cast<double>(rows) + kLegendRows + kAxisRows) * rowHeight;
}

void paintSetupMargins(QPainter& painter, const QRectF& rect, const std::vector<SetupMarginRow>& rows,
                       const QFont& font, double rowHeight, const QLocale& locale) {
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing);
  painter.setFont(font);
  const QFontMetricsF fm(font, painter.device());
  const double u = rowHeight / 20.0;  // one screen pixel at the on-screen row height
  double lo = 0.0, hi = 0.0;
  double labelWidth = fm.horizontalAdvance(QStringLiteral("dimension"));
  for (const auto& r : rows) {
    for (double v : {r.lower, r.upper, r.before, r.after}) {
      if (!std::isfinite(v)) continue;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    labelWidth = std::max(labelWidth, fm.horizontalAdvance(r.id));
  }
  if (hi - lo < 1e-6) {
    lo -= 0.1;
    hi += 0.1;
  }
  const double step = ticks::niceStep(hi - lo, 6);
  lo = std::floor(lo / step + 1e-9) * step;
  hi = std::ceil(hi / step - 1e-9) * step;
  const QString valueSample = QStringLiteral("−0.000 → −0.000");
  const double valueWidth = fm.horizontalAdvance(valueSample) + 8.0 * u;
  const double plotLeft = rect.left() + labelWidth + 10.0 * u;
  const double plotRight = rect.right() - valueWidth - 6.0 * u;
  const double top = rect.top() + kLegendRows * rowHeight;
  const double bottom = top + static_cast<double>(rows.size()) * rowHeight;
  auto xOf = [&](double v) { return plotLeft + (v - lo) / (hi - lo) * (plotRight - plotLeft); };

  // Legend.
  {
    double x = rect.left();
    const double y = rect.top() + 0.2 * rowHeight;
    auto item = [&](const QColor& c, const QString& text, bool band) {
      const QRectF swatch(x, y + 0.25 * rowHeight, 18.0 * u, 0.45 * rowHeight);
      if (band) {
        painter.fillRect(swatch, kZone);
      } else {
        painter.fillRect(swatch, c);
      }
      x += 22.0 * u;
      painter.setPen(QColor(0x30, 0x30, 0x30));
      painter.drawText(QRectF(x, y, fm.horizontalAdvance(text) + 4 * u, rowHeight), Qt::AlignVCenter, text);
      x += fm.horizontalAdvance(text) + 16.0 * u;
    };
    item(kZone, MarginsText::tr("tolerance zone"), true);
    item(kBefore, MarginsText::tr("before: deviation and margin to the nearer limit"), false);
    item(kAfter, MarginsText::tr("after correction"), false);
    item(kOut, MarginsText::tr("out of tolerance"), false);
  }

  // Grid and axis.
  painter.setPen(QPen(QColor(0xd0, 0xd0, 0xd0), 0.8 * u));
  for (double v = lo; v <= hi + step * 1e-6; v += step)
    painter.drawLine(QPointF(xOf(v), top), QPointF(xOf(v), bottom));
  painter.setPen(QPen(QColor(0x60, 0x60, 0x60), 1.0 * u, Qt::DashLine));
  painter.drawLine(QPointF(xOf(0.0), top - 2 * u), QPointF(xOf(0.0), bottom + 2 * u));
  painter.setPen(QColor(0x30, 0x30, 0x30));
  for (double v = lo; v <= hi + step * 1e-6; v += step) {
    const QString t = locale.toString(std::abs(v) < step * 1e-6 ? 0.0 : v, 'f', step < 0.01 ? 3 : 2);
    const double w = fm.horizontalAdvance(t);
    painter.drawText(QRectF(xOf(v) - w / 2 - 2 * u, bottom + 2 * u, w + 4 * u, rowHeight * 0.8),
                     Qt::AlignCenter, t);
  }
  const QString axisTitle = MarginsText::tr("deviation from nominal (mm)");
  painter.drawText(QRectF(plotLeft, bottom + 0.8 * rowHeight, plotRight - plotLeft, rowHeight * 0.8),
                   Qt::AlignCenter, axisTitle);
  painter.drawText(QRectF(plotRight + 6.0 * u, bottom + 0.8 * rowHeight, valueWidth, rowHeight * 0.8),
                   Qt::AlignLeft | Qt::AlignVCenter, MarginsText::tr("margin (mm)"));

  // Rows.
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const SetupMarginRow& r = rows[i];
    const double y = top + static_cast<double>(i) * rowHeight;
    painter.setPen(QColor(0x20, 0x20, 0x20));
    painter.drawText(QRectF(rect.left(), y, labelWidth + 4, rowHeight), Qt::AlignVCenter | Qt::AlignLeft,
                     r.id);
    painter.fillRect(QRectF(xOf(r.lower), y + 0.1 * rowHeight, xOf(r.upper) - xOf(r.lower), 0.8 * rowHeight),
                     kZone);
    auto bar = [&](double dev, const QColor& color, double yc) {
      const double toLower = dev - r.lower, toUpper = r.upper - dev;
      const double margin = std::min(toLower, toUpper);
      const double limit = toLower < toUpper ? r.lower : r.upper;
      const QColor c = margin < 0.0 ? kOut : color;
      const double x0 = xOf(std::min(dev, limit)), x1 = xOf(std::max(dev, limit));
      painter.fillRect(QRectF(x0, yc - 0.12 * rowHeight, std::max(u, x1 - x0), 0.24 * rowHeight), c);
      painter.setPen(QPen(c.darker(130), 2.0 * u));
      painter.drawLine(QPointF(xOf(dev), yc - 0.2 * rowHeight), QPointF(xOf(dev), yc + 0.2 * rowHeight));
      return margin;
    };
    const double mb = bar(r.before, kBefore, y + 0.32 * rowHeight);
    const double ma = bar(r.after, kAfter, y + 0.68 * rowHeight);
    painter.setPen(ma < 0.0 ? kOut : QColor(0x20, 0x20, 0x20));
    const QString values = QStringLiteral("%1 → %2")
                               .arg(locale.toString(mb, 'f', 3), locale.toString(ma, 'f', 3))
                               .replace('-', QChar(0x2212));
    painter.drawText(QRectF(plotRight + 6.0 * u, y, valueWidth, rowHeight), Qt::AlignVCenter | Qt::AlignLeft,
                     values);
  }
  painter.restore();
}

SetupMarginsWidget::SetupMarginsWidget(QWidget* parent) : QWidget(parent) {
  enableChartExport(this, QStringLiteral("setup-margins"));
  setObjectName(QStringLiteral("setupMargins"));
  setMinimumWidth(420);
}

void SetupMarginsWidget::setRows(std::vector<SetupMarginRow> rows) {
  rows_ = std::move(rows);
  const double rowHeight = fontMetrics().height() + 6.0;
  setMinimumHeight(
      static_cast<int>(std::ceil(setupMarginsHeight(std::max<std::size_t>(rows_.size(), 1), rowHeight))) + 8);
  update();
}

void SetupMarginsWidget::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), palette().base());
  if (rows_.empty()) {
    painter.setPen(palette().color(QPalette::PlaceholderText));
    painter.drawText(rect(), Qt::AlignCenter,
                     tr("Run a method to see the margins before and after correction."));
    return;
  }
  const double rowHeight = fontMetrics().height() + 6.0;
  paintSetupMargins(painter, QRectF(rect()).adjusted(6, 4, -6, -4), rows_, font(), rowHeight);
}

}  // namespace metrofit
