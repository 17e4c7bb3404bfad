#pragma once
// The widgets of the kinematics & SPC page: the path view, the ballbar-style polar plot of the
// radial deviations, the X-bar / R control charts, the histogram and the SPC view that combines
// them with a side table of the indices. They draw with kinematicplots.h (QPainter), so the PDF
// report shows the same pictures; each exposes its layout mapping for tests and tooltips.
#include <QWidget>

#include <optional>
#include <vector>

#include "core/spc/spc.h"
#include "widgets/kinematics/kinematicplots.h"

class QTableWidget;
class QLabel;

namespace metrofit {

/// Nominal circle, measured path (CCW / CW), compensated references and the expected result.
class CircularPathView : public QWidget {
  Q_OBJECT
 public:
  explicit CircularPathView(QWidget* parent = nullptr);
  void setData(const PathPlotData& data);
  const PathPlotData& data() const { return data_; }
  PathPlotLayout layout() const;
  QSize sizeHint() const override { return {420, 420}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  PathPlotData data_;
};

/// Magnified radial deviation (ballbar polar plot).
class PolarDeviationView : public QWidget {
  Q_OBJECT
 public:
  explicit PolarDeviationView(QWidget* parent = nullptr);
  /// Magnification and ring step 0 are chosen from the data (PolarPlotData::autoScale).
  void setData(const PolarPlotData& data);
  const PolarPlotData& data() const { return data_; }
  PolarPlotLayout layout() const;
  /// Widget coordinates of a point at `angleDeg` with radial deviation `deviationMm`.
  QPointF mapToWidget(double angleDeg, double deviationMm) const {
    return layout().map(angleDeg, deviationMm);
  }
  QSize sizeHint() const override { return {420, 420}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  PolarPlotData data_;
};

/// X-bar or R chart of an XbarRChart (X or MR for individuals), with the Nelson rules broken marked
/// and named in the read-out.
class ControlChartView : public QWidget {
  Q_OBJECT
 public:
  ControlChartView(ControlChartKind kind, QWidget* parent = nullptr);
  void setChart(const XbarRChart& chart, const QString& unit, const std::vector<RuleBreak>& rules = {});
  void clear();
  bool hasChart() const { return chart_.has_value(); }
  ControlChartLayout layout() const;
  ControlChartKind kind() const { return kind_; }
  QSize sizeHint() const override { return {520, 220}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  ControlChartKind kind_;
  std::optional<XbarRChart> chart_;
  std::vector<RuleBreak> rules_;
  QString unit_;
};

class HistogramView : public QWidget {
  Q_OBJECT
 public:
  explicit HistogramView(QWidget* parent = nullptr);
  void setData(const HistogramData& data);
  const HistogramData& data() const { return data_; }
  HistogramLayout layout() const;
  QSize sizeHint() const override { return {520, 220}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  HistogramData data_;
};

/// X-bar chart, R chart and histogram on the left, the indices on the right.
class SpcView : public QWidget {
  Q_OBJECT
 public:
  explicit SpcView(QWidget* parent = nullptr);
  /// Shows an analysis of `values` (the series in sample order) in `unit` of feature `name`.
  void setResult(const SpcResult& result, const std::vector<double>& values, const QString& name,
                 const QString& unit);
  /// Shows a message instead of charts (no series, or an error).
  void setMessage(const QString& text);

  ControlChartView* meanChart() const { return mean_; }
  ControlChartView* rangeChart() const { return range_; }
  HistogramView* histogram() const { return histogram_; }
  QTableWidget* indexTable() const { return table_; }
  QLabel* messageLabel() const { return message_; }
  /// The compensation decision of `r` in the user's language with the locale's numbers: core's
  /// decision phrases (core/spc gateCompensation) translated; `decision.reason` stays the English
  /// text of the JSON / CLI.
  static QString compensationText(const SpcResult& r);

 private:
  ControlChartView* mean_;
  ControlChartView* range_;
  HistogramView* histogram_;
  QTableWidget* table_;
  QLabel* message_;
};

}  // namespace metrofit
