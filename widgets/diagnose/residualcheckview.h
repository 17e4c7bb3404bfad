#pragma once
// The residual check of a diagnosis (core/diagnose/residual_check.h) on the
// diagnosis page: what the final residual (after every accepted effect, outliers excluded) still
// depends on.
//   * the verdict (white / still depends on ...), core's summary translated;
//   * the structure list: variable, form, share of the residual variance in %, p;
//   * the outliers the fit excluded: row / part / dimension / id, residual with its unit, robust z;
//   * every test: name (Ljung-Box, F test), order or variable, form, statistic, degrees of
//     freedom, p-value, rejected by Holm at the family-wise level;
//   * a chart of the residual against the variable of the strongest structure (ResidualCheck::Plot):
//     the residual as points, the generic fit as a line through the distinct x values in order
//     (one line per coordinate of a vector residual: kinematic x / y, matching x / y / z), the
//     excluded outliers as red triangles. Without a plot (a white residual) the chart is hidden. Categories
//     (parts, surfaces) are labelled on the x axis.
// Numbers in the user's locale; "um" shown as "µm". Qt Charts stays inside the .cpp file.
//
// paintResidualCheck draws the same chart with QPainter for the report.
#include <QLocale>
#include <QRectF>
#include <QString>
#include <QWidget>

#include "core/diagnose/diagnosis.h"

class QLabel;
class QPainter;
class QTableWidget;

namespace metrofit {

/// At most this many points per chart series: longer series are thinned to every k-th point (the
/// tables and the verdict always use every observation).
inline constexpr int kMaxResidualCheckChartPoints = 20000;

/// The residual (points), the generic fit (line) and the outliers (crosses) of `plot` against its x,
/// axis titles translated, tick numbers in `locale` (the report: C).
void paintResidualCheck(QPainter& painter, const QRectF& rect, const diagnose::ResidualCheck::Plot& plot,
                        const QString& units, const QString& title, double fontPx = 10.0,
                        const QLocale& locale = QLocale::c());

class ResidualCheckView : public QWidget {
  Q_OBJECT
 public:
  explicit ResidualCheckView(QWidget* parent = nullptr);
  ~ResidualCheckView() override;

  /// Shows the diagnosis' residual check (or says that it has none).
  void setDiagnosis(const diagnose::Diagnosis& diagnosis);
  void clear();
  bool hasCheck() const { return hasCheck_; }
  /// False when the check has no plot (white, or no single variable): the tables take the width.
  bool chartShown() const;

  QString verdictText() const;
  QTableWidget* testTable() const { return tests_; }
  QTableWidget* structureTable() const { return structure_; }
  QTableWidget* outlierTable() const { return outliers_; }

  /// Points of the chart's series: residual, generic fit line(s), outliers (0 when absent).
  int residualPointCount() const;
  int fitPointCount() const;  ///< over every fit line
  /// Fit lines: one, or one per coordinate of a vector residual (ResidualCheck::Plot::components).
  int fitLineCount() const;
  int outlierPointCount() const;
  /// The chart's title as shown (also when there is no plot: why), and its x axis title ("" then).
  QString chartTitle() const;
  QString xAxisTitle() const;

 private:
  class Charts;
  void showChart(const diagnose::ResidualCheck& check, const QString& units);

  QLabel* verdict_;
  QLabel* structureLabel_;
  QLabel* outlierLabel_;
  QLabel* testLabel_;
  QTableWidget* structure_;
  QTableWidget* outliers_;
  QTableWidget* tests_;
  Charts* charts_;
  bool hasCheck_ = false;
};

}  // namespace metrofit
