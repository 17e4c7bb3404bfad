#pragma once
// Drawings of the closed loop's results, for the diagnosis page and the report:
//   * the residual of the declared model before and after an accepted effect against what explains
//     it (diagnose::ResidualPlot: time, path angle, part number, surface...): a Qt Charts scatter in
//     the GUI (ResidualPlotView), the same plot painted with QPainter for the PDF;
//   * the matching distortion's 2D vector field (ResidualPlot::vectors = x, y, dx, dy), painted with
//     QPainter, the arrows magnified by a round factor that is printed on the plot;
//   * before / after error bars (rmse, max |e|, held-out rmse) of a diagnosis (ErrorBarsView).
// Qt Charts stays inside the .cpp file.
#include <QLocale>
#include <QRectF>
#include <QString>
#include <QWidget>
#include <optional>

#include "core/diagnose/diagnosis.h"

class QPainter;
class QStackedWidget;

namespace metrofit {

/// True when the plot carries a 2D vector field (matching distortion).
bool hasVectorField(const diagnose::ResidualPlot& plot);
/// The arrow magnification of a vector field drawn in `rect`: the largest arrow is about 1/8 of the
/// plot's span, rounded down to 1, 2 or 5 x 10^n.
double vectorMagnification(const diagnose::ResidualPlot& plot, const QRectF& rect);

/// Residual before (grey) and after (blue) against plot.x, axes labelled with xLabel / yLabel, tick
/// numbers in `locale` (the report: C; the GUI's vector field: the user's).
void paintResidualScatter(QPainter& painter, const QRectF& rect, const diagnose::ResidualPlot& plot,
                          const QString& title, double fontPx = 10.0, const QLocale& locale = QLocale::c());
/// The vector field (arrows from (x, y) along (dx, dy) magnified); returns the magnification used.
double paintResidualVectors(QPainter& painter, const QRectF& rect, const diagnose::ResidualPlot& plot,
                            const QString& title, double fontPx = 10.0, const QLocale& locale = QLocale::c());

/// The residual plot of one effect: a Qt Charts scatter, or the vector field when the plot has one.
class ResidualPlotView : public QWidget {
  Q_OBJECT
 public:
  explicit ResidualPlotView(QWidget* parent = nullptr);
  ~ResidualPlotView() override;

  /// Shows `plot` with its axis titles translated (xLabelParts / yLabelParts, coretexts.h).
  void setPlot(const diagnose::ResidualPlot& plot, const QString& title);
  void clear();
  bool isEmpty() const { return !plot_.has_value(); }
  bool showsVectorField() const;
  /// The x axis title shown (translated, before units and category names are added); "" when empty.
  QString xAxisTitle() const { return plot_ ? QString::fromStdString(plot_->xLabel) : QString(); }
  /// Points in the scatter's "before" series (0 when empty or a vector field).
  int pointCount() const;

 private:
  class VectorWidget;
  class Charts;
  std::optional<diagnose::ResidualPlot> plot_;
  QStackedWidget* stack_;
  VectorWidget* vectors_;
  Charts* charts_;
};

/// Grouped bars: baseline vs final rmse, max |e| and (when known) held-out rmse, in the units.
class ErrorBarsView : public QWidget {
  Q_OBJECT
 public:
  explicit ErrorBarsView(QWidget* parent = nullptr);
  ~ErrorBarsView() override;
  void setDiagnosis(const diagnose::Diagnosis& diagnosis);
  void clear();
  /// Categories shown (rmse, max |e|[, held-out rmse]); 0 when empty.
  int categoryCount() const { return categories_; }

 private:
  class Charts;
  Charts* charts_;
  int categories_ = 0;
};

}  // namespace metrofit
