#include "widgets/kinematics/kinematicsviews.h"
#include "widgets/common/chartexport.h"
#include "widgets/common/plotnavigation.h"
#include "widgets/common/tablecopy.h"
#include "widgets/diagnose/coretexts.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPainter>
#include <QStackedLayout>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace metrofit {
namespace {

void fillWhite(QPainter& p, const QWidget* w) {
  p.fillRect(w->rect(), Qt::white);
  p.setTransform(plotViewTransform(w));  // zoom and pan (plotnavigation.h)
}

/// How near (screen pixels) the cursor must be to a point for the read-out to name it.
constexpr double kReachPx = 12.0;

QString number(double v) {
  return QLocale().toString(v, 'g', 5);
}

double distance(const QPointF& a, const QPointF& b) {
  return std::hypot(a.x() - b.x(), a.y() - b.y());
}

}  // namespace

// ---- path ----------------------------------------------------------------------------------------

CircularPathView::CircularPathView(QWidget* parent) : QWidget(parent) {
  enableChartExport(this, QStringLiteral("kinematics-path"));
  // The read-out: the measured point nearest to the cursor, its position and radial deviation.
  enablePlotNavigation(this, [this](const QPointF& at, double scale) -> QString {
    if (data_.radiusMm <= 0.0 || data_.measured.size() != data_.nominal.size()) return {};
    const PathPlotLayout l = layout();
    double best = kReachPx / scale;
    std::size_t hit = data_.measured.size();
    for (std::size_t k = 0; k < data_.measured.size(); ++k) {
      const double d = distance(l.mapMagnified(data_.nominal[k], data_.measured[k]), at);
      if (d <= best) {
        best = d;
        hit = k;
      }
    }
    if (hit == data_.measured.size()) return {};
    const Eigen::Vector2d& p = data_.measured[hit];
    const bool ccw = data_.counterClockwise.empty() || data_.counterClockwise[hit];
    const double radialUm = ((p - data_.centreMm).norm() - data_.radiusMm) * 1000.0;
    return tr("point %1 (%2)\nx: %3 mm, y: %4 mm\nradial deviation: %5 \u00b5m")
        .arg(hit + 1)
        .arg(ccw ? tr("CCW") : tr("CW"))
        .arg(number(p.x()), number(p.y()), number(radialUm));
  });
  setMinimumSize(260, 260);
  setToolTip(
      tr("The XY path in mm: the nominal circle true to scale; the measured path, the compensated "
         "references and the expected result as deviations from the nominal point, magnified by the "
         "factor shown."));
}

void CircularPathView::setData(const PathPlotData& data) {
  data_ = data;
  update();
}

PathPlotLayout CircularPathView::layout() const {
  return PathPlotLayout(QRectF(rect()), data_);
}

void CircularPathView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  fillWhite(p, this);
  if (data_.radiusMm > 0.0) paintPathPlot(p, QRectF(rect()), data_, screenPlotStyle());
}

// ---- polar ----------------------------------------------------------------------------------------

PolarDeviationView::PolarDeviationView(QWidget* parent) : QWidget(parent) {
  enableChartExport(this, QStringLiteral("kinematics-polar"));
  // The read-out: the measured (or expected) point nearest to the cursor, its angle and deviation.
  enablePlotNavigation(this, [this](const QPointF& at, double scale) -> QString {
    if (data_.radiusMm <= 0.0) return {};
    const PolarPlotLayout l = layout();
    double best = kReachPx / scale;
    QString text;
    const auto consider = [&](const RadialPoint& r, const QString& what) {
      const double d = distance(l.map(r.angleDeg, r.deviationMm), at);
      if (d > best) return;
      best = d;
      text = tr("%1\nangle: %2\u00b0\ndeviation: %3 \u00b5m")
                 .arg(what, number(r.angleDeg), number(r.deviationMm * 1000.0));
    };
    for (const CircularLoop& loop : data_.loops)
      for (const RadialPoint& r : loop.points) consider(r, loop.counterClockwise ? tr("CCW") : tr("CW"));
    for (const RadialPoint& r : data_.compensated) consider(r, tr("expected after compensation"));
    return text;
  });
  setMinimumSize(260, 260);
  setToolTip(
      tr("Radial deviation of the measured path from the nominal circle, magnified (ballbar plot): "
         "plotted radius = R + k × deviation. Blue: CCW loop, orange: CW loop; the rings are labelled "
         "in µm."));
}

void PolarDeviationView::setData(const PolarPlotData& data) {
  data_ = data;
  data_.autoScale();
  update();
}

PolarPlotLayout PolarDeviationView::layout() const {
  return PolarPlotLayout(QRectF(rect()), data_);
}

void PolarDeviationView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  fillWhite(p, this);
  if (data_.radiusMm > 0.0) paintPolarPlot(p, QRectF(rect()), data_, screenPlotStyle());
}

// ---- control chart ----------------------------------------------------------------------------------

ControlChartView::ControlChartView(ControlChartKind kind, QWidget* parent) : QWidget(parent), kind_(kind) {
  enableChartExport(
      this, kind == ControlChartKind::Mean ? QStringLiteral("xbar-chart") : QStringLiteral("r-chart"));
  // The read-out: the subgroup nearest to the cursor (by its point) and its value.
  enablePlotNavigation(this, [this](const QPointF& at, double scale) -> QString {
    if (!chart_) return {};
    const ControlChartLayout l = layout();
    const std::vector<double>& values = kind_ == ControlChartKind::Mean ? chart_->means : chart_->ranges;
    double best = kReachPx / scale;
    std::size_t hit = values.size();
    const bool mean = kind_ == ControlChartKind::Mean;
    const auto subgroupOf = [&](std::size_t k) { return mean ? k : chart_->rangeSubgroup(k); };
    for (std::size_t k = 0; k < values.size(); ++k) {
      const double d = distance(l.map(static_cast<double>(subgroupOf(k) + 1), values[k]), at);
      if (d <= best) {
        best = d;
        hit = k;
      }
    }
    if (hit == values.size()) return {};
    const QString unit = unit_.isEmpty() ? QString() : QLatin1Char(' ') + unit_;
    const std::size_t subgroup = subgroupOf(hit);
    QString text = (mean ? tr("subgroup %1\nmean: %2%3") : tr("subgroup %1\nrange: %2%3"))
                       .arg(subgroup + 1)
                       .arg(number(values[hit]), unit);
    for (const QString& rule : ruleBreaksAt(rules_, kind_, subgroup)) text += QLatin1Char('\n') + rule;
    return text;
  });
  setMinimumSize(300, 160);
  setToolTip(kind == ControlChartKind::Mean
                 ? tr("Subgroup means with the centre line and the control limits UCL/LCL = mean ± A2 · R̄ "
                      "(kinematic-compensation paper, Eq. 18–19); red points are out of control, ringed ones "
                      "break a Nelson rule (the read-out names it).")
                 : tr("Subgroup ranges with the centre line R̄ and the limits D4 · R̄ and D3 · R̄."));
}

void ControlChartView::setChart(const XbarRChart& chart, const QString& unit,
                                const std::vector<RuleBreak>& rules) {
  chart_ = chart;
  rules_ = rules;
  unit_ = unit;
  update();
}

void ControlChartView::clear() {
  chart_.reset();
  rules_.clear();
  update();
}

ControlChartLayout ControlChartView::layout() const {
  return ControlChartLayout(QRectF(rect()), chart_ ? *chart_ : XbarRChart{}, kind_);
}

void ControlChartView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  fillWhite(p, this);
  if (chart_) paintControlChart(p, QRectF(rect()), *chart_, kind_, unit_, screenPlotStyle(), rules_);
}

// ---- histogram -------------------------------------------------------------------------------------

HistogramView::HistogramView(QWidget* parent) : QWidget(parent) {
  enableChartExport(this, QStringLiteral("histogram"));
  // The read-out: the bin under the cursor, its bounds and count.
  enablePlotNavigation(this, [this](const QPointF& at, double) -> QString {
    if (data_.values.empty() || data_.bins.counts.empty()) return {};
    const HistogramLayout l = layout();
    if (!l.plotArea().contains(at)) return {};
    const double x0 = l.map(l.xMin(), 0).x(), x1 = l.map(l.xMax(), 0).x();
    if (x1 <= x0) return {};
    const double value = l.xMin() + (at.x() - x0) / (x1 - x0) * (l.xMax() - l.xMin());
    const double bin = std::floor((value - data_.bins.first) / data_.bins.width);
    if (bin < 0 || bin >= static_cast<double>(data_.bins.counts.size())) return {};
    const auto i = static_cast<std::size_t>(bin);
    const QString unit = data_.unit.isEmpty() ? QString() : QLatin1Char(' ') + data_.unit;
    return tr("%1 to %2%3\ncount: %4")
        .arg(number(data_.bins.edge(i)), number(data_.bins.edge(i + 1)), unit)
        .arg(data_.bins.counts[i]);
  });
  setMinimumSize(300, 160);
  setToolTip(
      tr("Distribution of the values with the specification limits LSL/USL, the nominal and the mean."));
}

void HistogramView::setData(const HistogramData& data) {
  data_ = data;
  update();
}

HistogramLayout HistogramView::layout() const {
  return HistogramLayout(QRectF(rect()), data_);
}

void HistogramView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  fillWhite(p, this);
  if (!data_.values.empty()) paintHistogram(p, QRectF(rect()), data_, screenPlotStyle());
}

// ---- SPC view ---------------------------------------------------------------------------------------

SpcView::SpcView(QWidget* parent)
    : QWidget(parent),
      mean_(new ControlChartView(ControlChartKind::Mean, this)),
      range_(new ControlChartView(ControlChartKind::Range, this)),
      histogram_(new HistogramView(this)),
      table_(new QTableWidget(this)),
      message_(new QLabel(this)) {
  table_->setObjectName(QStringLiteral("spcIndexTable"));
  enableTableCopy(table_);
  table_->setColumnCount(2);
  table_->setHorizontalHeaderLabels({tr("index"), tr("value")});
  table_->verticalHeader()->hide();
  table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setMaximumSectionSize(180);  // long names wrap, the values keep room
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setWordWrap(true);
  table_->setMinimumWidth(380);
  table_->setMaximumWidth(440);
  // Values wrap instead of scrolling sideways; rows follow the column widths the layout settles on.
  table_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  table_->setHorizontalScrollMode(QAbstractItemView::ScrollPerPixel);
  connect(table_->horizontalHeader(), &QHeaderView::sectionResized, table_,
          [this] { table_->resizeRowsToContents(); });
  message_->setObjectName(QStringLiteral("spcMessage"));
  message_->setWordWrap(true);
  message_->setAlignment(Qt::AlignCenter);

  auto* charts = new QVBoxLayout;
  charts->addWidget(mean_, 1);
  charts->addWidget(range_, 1);
  charts->addWidget(histogram_, 1);
  auto* content = new QWidget(this);
  auto* row = new QHBoxLayout(content);
  row->setContentsMargins(0, 0, 0, 0);
  row->addLayout(charts, 1);
  row->addWidget(table_);
  auto* stack = new QStackedLayout(this);
  stack->addWidget(content);
  stack->addWidget(message_);
  setMessage(tr("No SPC series yet."));
}

QString SpcView::compensationText(const SpcResult& r) {
  return coreText(r.decision.reasonParts, r.decision.reason);
}

void SpcView::setMessage(const QString& text) {
  message_->setText(text);
  static_cast<QStackedLayout*>(layout())->setCurrentWidget(message_);
  mean_->clear();
  range_->clear();
}

void SpcView::setResult(const SpcResult& r, const std::vector<double>& values, const QString& name,
                        const QString& unit) {
  mean_->setChart(r.chart, unit, r.rules);
  range_->setChart(r.chart, unit, r.rules);
  HistogramData h = spcHistogramData(r, values, unit, QString());
  h.title = tr("Histogram of %1 (%2 values)").arg(name).arg(h.values.size());
  histogram_->setData(h);

  const QString u = unit.isEmpty() ? QString() : QLatin1Char(' ') + unit;
  const QLocale locale;
  auto num = [&locale](double v, int sig = 6) { return locale.toString(v, 'g', sig); };
  QList<QPair<QString, QString>> rows;
  rows.append({tr("feature"), name});
  rows.append({tr("subgroups × size"),
               tr("%1 × %2").arg(r.chart.subgroups()).arg(r.chart.subgroupSize) +
                   (r.valuesIgnored ? tr(" (%1 left out)").arg(r.valuesIgnored) : QString())});
  rows.append({tr("in control"), r.chart.inControl() ? tr("yes")
                                                     : tr("no: %1 X-bar, %2 R points beyond limits")
                                                           .arg(r.chart.xbarOutOfControl.size())
                                                           .arg(r.chart.rOutOfControl.size())});
  rows.append({tr("Nelson rules"), nelsonRulesSummary(r)});
  rows.append(
      {tr("A2 / D3 / D4"), QStringLiteral("%1 / %2 / %3")
                               .arg(num(r.constants.A2, 4), num(r.constants.D3, 4), num(r.constants.D4, 4))});
  rows.append({tr("X-bar CL / UCL / LCL"),
               QStringLiteral("%1 / %2 / %3")
                       .arg(num(r.chart.grandMean, 8), num(r.chart.xbarUcl, 8), num(r.chart.xbarLcl, 8)) +
                   u});
  rows.append({tr("R CL / UCL / LCL"),
               QStringLiteral("%1 / %2 / %3")
                       .arg(num(r.chart.meanRange, 4), num(r.chart.rUcl, 4), num(r.chart.rLcl, 4)) +
                   u});
  rows.append({tr("σ within (R̄/d2)"), num(r.capability.sigmaWithin, 4) + u});
  if (r.options.lsl && r.options.usl) {
    rows.append(
        {tr("LSL / USL"), QStringLiteral("%1 / %2").arg(num(*r.options.lsl, 8), num(*r.options.usl, 8)) + u});
  }
  rows.append(
      {tr("Cp (Eq. 16)"), r.capability.cp ? locale.toString(*r.capability.cp, 'f', 2) : tr("— (no limits)")});
  rows.append(
      {tr("Cpk"), r.capability.cpk ? locale.toString(*r.capability.cpk, 'f', 2) : tr("— (no limits)")});
  rows.append({tr("natural tolerance (Eq. 17)"), num(r.capability.naturalTolerance, 4) + u});
  if (r.systematic) {
    const SystematicError& s = *r.systematic;
    rows.append({tr("systematic error (Eq. 20)"),
                 tr("%1%2 ± %3 (%4)")
                     .arg(num(s.error, 4), u, num(s.halfWidth, 2))
                     .arg(s.significant ? tr("significant") : tr("not significant"))});
  } else {
    rows.append({tr("systematic error (Eq. 20)"), tr("— (no nominal)")});
  }
  rows.append({tr("regression offset angle"),
               tr("%1° (slope %2%3 per sample, r² %4)")
                   .arg(locale.toString(r.trend.angleDeg, 'g', 3), num(r.trend.slope, 3), u,
                        locale.toString(r.trend.r2, 'f', 2))});
  rows.append({tr("compensation"), compensationText(r)});
  table_->setRowCount(static_cast<int>(rows.size()));
  for (int i = 0; i < rows.size(); ++i) {
    table_->setItem(i, 0, new QTableWidgetItem(rows[i].first));
    auto* item = new QTableWidgetItem(rows[i].second);
    item->setToolTip(rows[i].second);
    table_->setItem(i, 1, item);
  }
  table_->resizeRowsToContents();
  static_cast<QStackedLayout*>(layout())->setCurrentIndex(0);
}

}  // namespace metrofit
