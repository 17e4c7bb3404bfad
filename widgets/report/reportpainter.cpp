// Page and cursor helper of the PDF report (see reportpainter.h).
#include "widgets/report/reportpainter.h"

#include <QChart>
#include <QCoreApplication>
#include <QFontDatabase>
#include <QFontMetricsF>
#include <QGraphicsLayout>
#include <QGraphicsScene>
#include <QPainter>
#include <QPdfWriter>
#include <QRegularExpression>
#include <QTextOption>

#include <algorithm>
#include <numeric>
#include <utility>

#include "metrofit/version.h"

namespace metrofit {
namespace {

struct ReportText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::Report)
};

// Page geometry in mm (A4 portrait, 210 x 297).
constexpr double kMarginLeftMm = 18.0;
constexpr double kMarginRightMm = 18.0;
constexpr double kMarginTopMm = 12.0;
constexpr double kMarginBottomMm = 12.0;
constexpr double kHeaderMm = 11.0;  ///< header band below the top margin (pages after the first)
constexpr double kFooterMm = 9.0;   ///< footer band above the bottom margin

const QColor kRuleColor(0x90, 0x98, 0xa0);
const QColor kHeaderFill(0xe6, 0xeb, 0xf0);
const QColor kStripeFill(0xf6, 0xf7, 0xf9);
const QColor kMutedText(0x50, 0x58, 0x60);

}  // namespace

ReportPainter::ReportPainter(QPdfWriter& writer, QPainter& painter, QString runningTitle, int totalPages)
    : writer_(writer),
      painter_(painter),
      runningTitle_(std::move(runningTitle)),
      totalPages_(totalPages),
      dpi_(writer.resolution()) {
  const QString preferred = QStringLiteral("DejaVu Sans");
  fontFamily_ = QFontDatabase::hasFamily(preferred) ? preferred : QFont().family();
  painter_.setRenderHint(QPainter::Antialiasing);
  decoratePage();
}

QFont ReportPainter::font(Font role) const {
  QFont f(fontFamily_);
  // A (1/50 px) letter spacing makes Qt shape without ligatures, so "fi" stays two letters and the
  // PDF's text can be searched and extracted as written.
  f.setLetterSpacing(QFont::AbsoluteSpacing, 0.02);
  switch (role) {
    case Font::Body:
      f.setPointSizeF(9.5);
      break;
    case Font::Small:
      f.setPointSizeF(8.0);
      break;
    case Font::Bold:
      f.setPointSizeF(9.5);
      f.setBold(true);
      break;
    case Font::Subheading:
      f.setPointSizeF(11.5);
      f.setBold(true);
      break;
    case Font::Heading:
      f.setPointSizeF(16.0);
      f.setBold(true);
      break;
    case Font::Title:
      f.setPointSizeF(26.0);
      f.setBold(true);
      break;
  }
  return f;
}

double ReportPainter::lineHeight(Font role) const {
  return QFontMetricsF(font(role), &writer_).lineSpacing();
}

void ReportPainter::decoratePage() {
  const double pageW = writer_.width();
  const double pageH = writer_.height();
  const double left = mm(kMarginLeftMm);
  const double right = pageW - mm(kMarginRightMm);
  const double top = mm(kMarginTopMm);
  const double bottom = pageH - mm(kMarginBottomMm);
  const bool cover = page_ == 1;

  painter_.save();
  painter_.setPen(QPen(kRuleColor, mm(0.2)));
  if (!cover) {
    const QRectF band(left, top, right - left, mm(kHeaderMm - 3.0));
    painter_.drawLine(QPointF(left, band.bottom()), QPointF(right, band.bottom()));
    painter_.setFont(font(Font::Small));
    painter_.setPen(kMutedText);
    const QFontMetricsF fm(painter_.font(), &writer_);
    const QString version = ReportText::tr("Metrofit %1").arg(QString::fromUtf8(kVersion));
    const double versionWidth = fm.horizontalAdvance(version) + mm(4.0);
    // A long title is set smaller (down to 6 pt) and then wrapped: never elided.
    QFont titleFont = font(Font::Small);
    const double titleWidth = band.width() - versionWidth;
    while (titleFont.pointSizeF() > 6.0 &&
           QFontMetricsF(titleFont, &writer_).horizontalAdvance(runningTitle_) > titleWidth) {
      titleFont.setPointSizeF(titleFont.pointSizeF() - 0.5);
    }
    painter_.setFont(titleFont);
    QTextOption titleOption(Qt::AlignLeft | Qt::AlignBottom);
    titleOption.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    painter_.drawText(QRectF(band.left(), band.top() - mm(2.0), titleWidth, band.height() + mm(1.0)),
                      runningTitle_, titleOption);
    painter_.setFont(font(Font::Small));
    painter_.drawText(band.adjusted(0, 0, 0, -mm(1.0)), Qt::AlignRight | Qt::AlignBottom, version);
  }
  const QRectF footer(left, bottom - mm(kFooterMm - 3.0), right - left, mm(kFooterMm - 3.0));
  painter_.setPen(QPen(kRuleColor, mm(0.2)));
  painter_.drawLine(QPointF(left, footer.top()), QPointF(right, footer.top()));
  painter_.setFont(font(Font::Small));
  painter_.setPen(kMutedText);
  const QString number = totalPages_ > 0 ? ReportText::tr("page %1 of %2").arg(page_).arg(totalPages_)
                                         : ReportText::tr("page %1").arg(page_);
  painter_.drawText(footer, Qt::AlignRight | Qt::AlignBottom, number);
  painter_.restore();

  content_ = QRectF(QPointF(left, top + (cover ? mm(8.0) : mm(kHeaderMm + 3.0))),
                    QPointF(right, footer.top() - mm(4.0)));
  y_ = content_.top();
}

void ReportPainter::newPage() {
  writer_.newPage();
  ++page_;
  decoratePage();
}

void ReportPainter::ensureSpace(double height) {
  if (height > remaining() && y_ > content_.top()) {
    newPage();
  }
}

void ReportPainter::skip(double height) {
  y_ = std::min(y_ + height, content_.bottom());
}

QRectF ReportPainter::reserve(double height) {
  ensureSpace(height);
  height = std::min(height, remaining());
  const QRectF r(content_.left(), y_, content_.width(), height);
  y_ += height;
  return r;
}

void ReportPainter::title(const QString& text) {
  const QRectF r = reserve(lineHeight(Font::Title) * 1.3);
  painter_.setFont(font(Font::Title));
  painter_.setPen(Qt::black);
  painter_.drawText(r, Qt::AlignLeft | Qt::AlignVCenter, text);
}

void ReportPainter::heading(const QString& text) {
  if (y_ > content_.top() + mm(1.0)) {
    newPage();
  }
  const QRectF r = reserve(lineHeight(Font::Heading) * 1.25);
  painter_.setFont(font(Font::Heading));
  painter_.setPen(Qt::black);
  painter_.drawText(r, Qt::AlignLeft | Qt::AlignTop, text);
  painter_.setPen(QPen(kRuleColor, mm(0.3)));
  painter_.drawLine(QPointF(r.left(), r.bottom()), QPointF(r.right(), r.bottom()));
  skip(mm(4.0));
}

void ReportPainter::subheading(const QString& text, double keepWithNext) {
  const double h = lineHeight(Font::Subheading) * 1.3;
  ensureSpace(h + keepWithNext);
  const QRectF r = reserve(h);
  painter_.setFont(font(Font::Subheading));
  painter_.setPen(Qt::black);
  painter_.drawText(r, Qt::AlignLeft | Qt::AlignVCenter, text);
  skip(mm(1.0));
}

void ReportPainter::paragraph(const QString& text, Font role) {
  painter_.setFont(font(role));
  QTextOption option(Qt::AlignLeft);
  option.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);  // a long file name breaks, not overflows
  const QRectF bounds =
      painter_.boundingRect(QRectF(content_.left(), 0, content_.width(), 1e7), text, option);
  const QRectF r = reserve(bounds.height());
  painter_.setPen(Qt::black);
  painter_.drawText(QRectF(r.left(), r.top(), r.width(), bounds.height()), text, option);
  skip(mm(2.0));
}

void ReportPainter::table(const ReportTable& table) {
  const int columns = static_cast<int>(
      std::max<qsizetype>(table.header.size(), table.rows.isEmpty() ? 0 : table.rows.front().size()));
  if (columns == 0) {
    return;
  }
  QList<double> widths = table.widths;
  widths.resize(columns, 1.0);
  const double totalWeight = std::accumulate(widths.begin(), widths.end(), 0.0);
  const double tableWidth = content_.width() * std::clamp(table.widthFraction, 0.1, 1.0);
  const double pad = mm(1.5);
  const QFont body = font(Font::Small);
  QFont bold = body;
  bold.setBold(true);
  const double lineH = QFontMetricsF(body, &writer_).lineSpacing();
  QList<double> columnWidths;
  for (int c = 0; c < columns; ++c)
    columnWidths << tableWidth * widths[c] / (totalWeight > 0 ? totalWeight : 1.0);
  // A column narrower than its longest word ("Lageausrichtung", "Einrichtdatenkorrektur" in German)
  // takes the room from columns that have more than their own longest word needs, so words break
  // inside only when the table cannot hold them at all.
  {
    static const QRegularExpression kSpace(QStringLiteral("\\s+"));
    const QFontMetricsF bodyMetrics(body, &writer_), boldMetrics(bold, &writer_);
    QList<double> need(columns, 0.0);
    const auto measure = [&](const QStringList& cells, const QFontMetricsF& metrics) {
      for (int c = 0; c < columns && c < cells.size(); ++c)
        for (const QString& word : cells[c].split(kSpace, Qt::SkipEmptyParts))
          need[c] = std::max(need[c], metrics.horizontalAdvance(word) + 2 * pad + mm(0.5));
    };
    measure(table.header, boldMetrics);
    for (const QStringList& row : table.rows) measure(row, bodyMetrics);
    double deficit = 0.0, slack = 0.0;
    for (int c = 0; c < columns; ++c) {
      deficit += std::max(0.0, need[c] - columnWidths[c]);
      slack += std::max(0.0, columnWidths[c] - need[c]);
    }
    if (deficit > 0.0 && slack >= deficit) {
      const double share = deficit / slack;
      for (int c = 0; c < columns; ++c)
        columnWidths[c] =
            columnWidths[c] < need[c] ? need[c] : columnWidths[c] - (columnWidths[c] - need[c]) * share;
    }
  }
  // Cells wrap (at word boundaries, inside a word only when it is wider than its column): a table
  // never elides or clips what it says.
  QTextOption wrap;
  wrap.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
  const auto cellText = [](const QStringList& cells, int c) {
    return c < cells.size() ? cells[c] : QString();
  };
  const auto rowHeight = [&](const QStringList& cells, bool header) {
    painter_.setFont(header ? bold : body);
    double h = lineH;
    for (int c = 0; c < columns; ++c) {
      const QString text = cellText(cells, c);
      if (text.isEmpty()) continue;
      const QRectF box(0, 0, std::max(columnWidths[c] - 2 * pad, 1.0), 1e7);
      h = std::max(h, painter_.boundingRect(box, text, wrap).height());
    }
    return h + mm(1.6);
  };

  const auto drawRow = [&](const QStringList& cells, bool header, bool stripe) {
    const double rowH = rowHeight(cells, header);
    const QRectF row(content_.left(), y_, tableWidth, rowH);
    if (header) {
      painter_.fillRect(row, kHeaderFill);
    } else if (stripe) {
      painter_.fillRect(row, kStripeFill);
    }
    painter_.setFont(header ? bold : body);
    painter_.setPen(Qt::black);
    double x = row.left();
    for (int c = 0; c < columns; ++c) {
      const double w = columnWidths[c];
      const QRectF cell(x + pad, row.top() + mm(0.8), w - 2 * pad, row.height() - mm(1.6));
      const Qt::Alignment align = c < table.alignment.size() ? table.alignment[c] : Qt::AlignLeft;
      QTextOption option = wrap;
      option.setAlignment(align | Qt::AlignVCenter);
      painter_.drawText(cell, cellText(cells, c), option);
      x += w;
    }
    painter_.setPen(QPen(kRuleColor, mm(header ? 0.25 : 0.1)));
    painter_.drawLine(row.bottomLeft(), row.bottomRight());
    y_ += rowH;
  };

  const bool hasHeader = !table.header.isEmpty();
  const double headerH = hasHeader ? rowHeight(table.header, true) : 0.0;
  // Keep the header with at least two rows.
  double firstRows = 0.0;
  for (int r = 0; r < std::min<qsizetype>(2, table.rows.size()); ++r)
    firstRows += rowHeight(table.rows[r], false);
  ensureSpace(headerH + firstRows);
  if (hasHeader) {
    drawRow(table.header, true, false);
  }
  for (int r = 0; r < table.rows.size(); ++r) {
    if (rowHeight(table.rows[r], false) > remaining() && y_ > content_.top() + headerH + mm(0.5)) {
      newPage();
      if (hasHeader) {
        drawRow(table.header, true, false);
      }
    }
    drawRow(table.rows[r], false, r % 2 == 1);
  }
  skip(mm(3.0));
}

void ReportPainter::drawScaled(const QRectF& rect, double designWidth,
                               const std::function<void(QPainter&, const QRectF&)>& paint) {
  painter_.save();
  painter_.translate(rect.topLeft());
  const double s = rect.width() / designWidth;
  painter_.scale(s, s);
  paint(painter_, QRectF(0.0, 0.0, designWidth, rect.height() / s));
  painter_.restore();
}

void ReportPainter::chart(QChart* chart, double height, double designWidthPx) {
  QGraphicsScene scene;  // owns the chart from here on
  scene.addItem(chart);
  const QRectF target = reserve(height);
  chart->resize(designWidthPx, designWidthPx * target.height() / target.width());
  if (chart->layout() != nullptr) {
    chart->layout()->activate();
  }
  const QRectF source = chart->sceneBoundingRect();
  scene.setSceneRect(source);
  scene.render(&painter_, target, source, Qt::KeepAspectRatio);
  skip(mm(2.0));
}

}  // namespace metrofit
