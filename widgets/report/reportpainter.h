#pragma once
// ReportPainter: the page and cursor helper every report section writes through.
//
// It owns nothing but the layout state: an A4 page with fixed margins, a running header (report
// title left, "Metrofit <version>" right) on every page but the cover, a footer "page n of N", and
// a vertical cursor that the building blocks below advance. A block that does not fit on the
// rest of the page starts a new one; tables break between rows and repeat their header.
// All lengths are in device units of the QPdfWriter (resolution dpi); mm() converts.
#include <QFont>
#include <QList>
#include <QRectF>
#include <QString>
#include <QStringList>
#include <functional>

QT_BEGIN_NAMESPACE
class QPainter;
class QPdfWriter;
class QChart;
QT_END_NAMESPACE

namespace metrofit {

/// A simple table: header (may be empty), rows of cells, relative column widths, alignments.
struct ReportTable {
  QStringList header;
  QList<QStringList> rows;
  QList<double> widths;            ///< relative widths, one per column (equal when empty)
  QList<Qt::Alignment> alignment;  ///< per column (left when missing)
  double widthFraction = 1.0;      ///< of the content width
};

class ReportPainter {
 public:
  enum class Font { Body, Small, Bold, Heading, Subheading, Title };

  /// Starts on the writer's first page. `runningTitle` heads every page after the first;
  /// `totalPages` completes the footer ("page n of N"), 0 when not known yet.
  ReportPainter(QPdfWriter& writer, QPainter& painter, QString runningTitle, int totalPages);

  QPainter& painter() { return painter_; }
  /// Millimetres to device units.
  double mm(double millimetres) const { return millimetres * dpi_ / 25.4; }
  /// The writable area of the page (between header and footer).
  QRectF content() const { return content_; }
  double y() const { return y_; }
  double remaining() const { return content_.bottom() - y_; }
  /// 1-based number of the current page.
  int page() const { return page_; }
  QFont font(Font role) const;

  /// Starts a new page (header, footer, cursor at the top).
  void newPage();
  /// Starts a new page unless `height` still fits below the cursor.
  void ensureSpace(double height);
  /// Moves the cursor down (at most to the bottom of the page).
  void skip(double height);
  /// A full-width rectangle of `height` at the cursor (on a new page if needed); advances past it.
  QRectF reserve(double height);

  /// The cover title (large).
  void title(const QString& text);
  /// A section heading; starts a new page unless the cursor is at the top of one.
  void heading(const QString& text);
  /// A heading inside a section; kept together with at least `keepWithNext` of what follows.
  void subheading(const QString& text, double keepWithNext = 0.0);
  /// Word-wrapped text in the given font.
  void paragraph(const QString& text, Font role = Font::Body);
  /// A table; breaks between rows, repeating the header on the next page.
  void table(const ReportTable& table);
  /// Renders a chart as vector graphics into a full-width box of `height`; takes ownership.
  /// The chart is laid out at `designWidthPx` scene pixels wide, which sets its text size
  /// relative to the page.
  void chart(QChart* chart, double height, double designWidthPx = 760.0);
  /// Calls `paint` to draw into `rect` laid out at `designWidth` logical pixels wide (which sets the
  /// text size relative to the page), as the on-screen views draw the same plot.
  void drawScaled(const QRectF& rect, double designWidth,
                  const std::function<void(QPainter&, const QRectF&)>& paint);

 private:
  void decoratePage();
  double lineHeight(Font role) const;

  QPdfWriter& writer_;
  QPainter& painter_;
  QString runningTitle_;
  int totalPages_ = 0;
  int page_ = 1;
  double dpi_ = 300.0;
  QRectF content_;
  double y_ = 0.0;
  QString fontFamily_;
};

}  // namespace metrofit
