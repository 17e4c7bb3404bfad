#pragma once
// The per-dimension margins before and after a correction, drawn inside the tolerance zones (one
// row per dimension, a common mm axis): the zone [lower, upper] as a light band, the deviation
// before (grey) and after (blue) as markers, and a bar from each to the nearer tolerance limit:
// the unilateral error budget delta_q of objective.h (red when the dimension is out of
// tolerance). Drawn with QPainter, so the results view and the PDF report share it.
#include <QFont>
#include <QLocale>
#include <QRectF>
#include <QString>
#include <QWidget>
#include <vector>

class QPainter;

namespace metrofit {

struct SetupMarginRow {
  QString id;
  double lower = 0.0, upper = 0.0;   ///< tolerance limits relative to the nominal, mm
  double before = 0.0, after = 0.0;  ///< deviation before / after the correction, mm
};

/// Height of the drawing for `rows` rows at `rowHeight` (plus legend and axis).
double setupMarginsHeight(std::size_t rows, double rowHeight);
/// Draws the rows into `rect` (see above). `font` sets the text size.
/// Numbers in `locale`: the page's UI language by default; the report (in English) passes QLocale::c().
void paintSetupMargins(QPainter& painter, const QRectF& rect, const std::vector<SetupMarginRow>& rows,
                       const QFont& font, double rowHeight, const QLocale& locale = QLocale());

/// A widget showing paintSetupMargins (its minimum height grows with the rows; put it in a scroll area).
class SetupMarginsWidget : public QWidget {
  Q_OBJECT
 public:
  explicit SetupMarginsWidget(QWidget* parent = nullptr);
  void setRows(std::vector<SetupMarginRow> rows);
  const std::vector<SetupMarginRow>& rows() const { return rows_; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  std::vector<SetupMarginRow> rows_;
};

}  // namespace metrofit
