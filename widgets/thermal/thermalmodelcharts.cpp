// Hysteresis, model comparison, residual and training charts (see thermalmodelcharts.h).
#include "widgets/thermal/thermalmodelcharts.h"

#include <QAbstractAxis>
#include <QAreaSeries>
#include <QChart>
#include <QCoreApplication>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLocale>
#include <QLogValueAxis>
#include <QPen>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/axis_ticks.h"
#include "widgets/common/palette.h"
#include "widgets/thermal/thermalcharts.h"

namespace metrofit {
namespace {

struct ModelChartsText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::ThermalModelCharts)
};

using Range = ticks::Range;

QChart* newChart(const QString& title) {
  auto* chart = new QChart;
  chart->setAnimationOptions(QChart::NoAnimation);
  chart->setBackgroundRoundness(0);
  chart->setMargins(QMargins(4, 4, 4, 4));
  if (!title.isEmpty()) chart->setTitle(title);
  return chart;
}

/// Sets an axis to a padded range with round ticks.
void setRange(QValueAxis* axis, Range r) {
  if (!r.valid()) r = {0.0, 1.0};
  if (r.hi - r.lo <= 1e-12 * std::max(1.0, std::abs(r.hi))) {
    const double d = std::max(0.5, 0.05 * std::abs(r.hi));
    r = {r.lo - d, r.hi + d};
  }
  axis->setRange(r.lo, r.hi);
  axis->applyNiceNumbers();
}

QString unitSuffix(const ThermalLog& log, const std::string& column) {
  const int i = log.indexOf(column);
  if (i < 0) return {};
  const ThermalChannel& c = log.channels[static_cast<std::size_t>(i)];
  QString u = channelUnit(c);
  return u.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(u);
}

struct TimeAxis {
  QValueAxis* axis = nullptr;
  double scale = 1.0;  ///< minutes -> axis unit
};

TimeAxis addTimeAxis(QChart* chart, const std::vector<double>& timeMin, bool hours) {
  TimeAxis t;
  t.scale = hours ? 1.0 / 60.0 : 1.0;
  t.axis = new QValueAxis;
  t.axis->setTitleText(hours ? ModelChartsText::tr("time (h)") : ModelChartsText::tr("time (min)"));
  Range r;
  if (!timeMin.empty()) {
    r.add(timeMin.front() * t.scale);
    r.add(timeMin.back() * t.scale);
  }
  const double lo = r.valid() ? r.lo : 0.0, hi = r.valid() && r.hi > r.lo ? r.hi : lo + 1.0;
  t.axis->setRange(lo, hi);
  // Round ticks (1, 2 or 5 times a power of ten), anchored at 0, about 8 of them.
  const double raw = (hi - lo) / 8.0;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  const double step = raw <= p ? p : (raw <= 2 * p ? 2 * p : (raw <= 5 * p ? 5 * p : 10 * p));
  t.axis->setTickType(QValueAxis::TicksDynamic);
  t.axis->setTickAnchor(0.0);
  t.axis->setTickInterval(step);
  t.axis->setLabelFormat(step >= 1.0 ? QStringLiteral("%.0f") : QStringLiteral("%.1f"));
  chart->addAxis(t.axis, Qt::AlignBottom);
  return t;
}

/// A line of (time, value) decimated for display; non-finite values are left out.
QLineSeries* timeSeries(const std::vector<double>& timeMin, const std::vector<double>& values, double scale,
                        int maxPoints, Range* range) {
  std::vector<double> t, v;
  t.reserve(values.size());
  v.reserve(values.size());
  for (std::size_t k = 0; k < values.size() && k < timeMin.size(); ++k) {
    if (std::isfinite(values[k])) {
      t.push_back(timeMin[k]);
      v.push_back(values[k]);
    }
  }
  QList<QPointF> points;
  for (std::size_t row : decimateMinMax(t, v, static_cast<std::size_t>(std::max(4, maxPoints)))) {
    points << QPointF(t[row] * scale, v[row]);
    if (range) range->add(v[row]);
  }
  auto* series = new QLineSeries;
  series->replace(points);
  return series;
}

/// The held-out part as a light band and the boundary as a dashed line, on a hidden 0..1 axis.
void addHeldOutBand(QChart* chart, const TimeAxis& time, double boundaryMin, double endMin) {
  auto* bandAxis = new QValueAxis;
  bandAxis->setRange(0.0, 1.0);
  bandAxis->setVisible(false);
  chart->addAxis(bandAxis, Qt::AlignRight);
  const double a = boundaryMin * time.scale, b = endMin * time.scale;
  auto* upper = new QLineSeries;
  upper->replace(QList<QPointF>{QPointF(a, 1.0), QPointF(b, 1.0)});
  auto* lower = new QLineSeries;
  lower->replace(QList<QPointF>{QPointF(a, 0.0), QPointF(b, 0.0)});
  auto* band = new QAreaSeries(upper, lower);
  upper->setParent(band);
  lower->setParent(band);
  band->setName(ModelChartsText::tr("held out"));
  band->setPen(QPen(Qt::NoPen));
  band->setBrush(QColor(0xee, 0xee, 0xee));
  chart->addSeries(band);
  band->attachAxis(time.axis);
  band->attachAxis(bandAxis);
  auto* line = new QLineSeries;
  line->setName(ModelChartsText::tr("fit | held-out boundary"));
  line->replace(QList<QPointF>{QPointF(a, 0.0), QPointF(a, 1.0)});
  QPen pen(QColor(0x60, 0x60, 0x60), 1.2, Qt::DashLine);
  line->setPen(pen);
  chart->addSeries(line);
  line->attachAxis(time.axis);
  line->attachAxis(bandAxis);
  // The dashed line is the band's edge: the band's "held out" entry explains both, and one entry
  // fewer keeps the legend row short enough not to be elided.
  for (QLegendMarker* marker : chart->legend()->markers(line)) marker->setVisible(false);
}

void finishLegend(QChart* chart, bool legend) {
  chart->legend()->setVisible(legend);
  chart->legend()->setAlignment(Qt::AlignBottom);
}

bool fitted(const ThermalComparison& c, std::size_t i) {
  return c.fitted(i) && c.models[i].training.run.termination != Termination::Cancelled;
}

/// A legend entry without a curve for a model that could not be fitted ("GMC(1,N): not fitted"); the
/// reason is in the tables next to the chart.
void addNotFittedEntry(QChart* chart, std::size_t i, QAbstractAxis* x, QAbstractAxis* y) {
  auto* entry = new QLineSeries;
  entry->setName(ModelChartsText::tr("%1: not fitted").arg(thermalModelName(kThermalModelOrder[i])));
  entry->setPen(QPen(thermalModelColor(kThermalModelOrder[i]), 1.5, Qt::DotLine));
  chart->addSeries(entry);
  entry->attachAxis(x);
  entry->attachAxis(y);
}

}  // namespace

QColor thermalPhaseLineColor(ThermalPhaseKind kind) {
  return kind == ThermalPhaseKind::Heating ? palette::heatingLine() : palette::coolingLine();
}

QColor thermalModelColor(thermal::ThermalModelKind kind) {
  switch (kind) {
    case thermal::ThermalModelKind::Gnnmci:
      return palette::modelGnnmci();
    case thermal::ThermalModelKind::Gmc:
      return palette::modelGmc();
    case thermal::ThermalModelKind::Mlp:
      return palette::modelMlp();
    case thermal::ThermalModelKind::Linear:
      return QColor(0x55, 0x55, 0x55);
    case thermal::ThermalModelKind::Lag:
      return QColor(0x1b, 0x9e, 0x77);
    case thermal::ThermalModelKind::DistributedLag:
      return QColor(0x75, 0x70, 0xb3);
  }
  return QColor(Qt::black);
}

QString thermalModelName(thermal::ThermalModelKind kind) {
  switch (kind) {
    case thermal::ThermalModelKind::Gnnmci:
      return QStringLiteral("GNNMCI(1,N)");
    case thermal::ThermalModelKind::Gmc:
      return QStringLiteral("GMC(1,N)");
    case thermal::ThermalModelKind::Mlp:
      return QStringLiteral("MLP");
    case thermal::ThermalModelKind::Linear:
      return QStringLiteral("linear");
    case thermal::ThermalModelKind::Lag:
      return QStringLiteral("lag");
    case thermal::ThermalModelKind::DistributedLag:
      return QStringLiteral("dlag");
  }
  return {};
}

std::vector<std::size_t> hysteresisRunRows(const PhaseRun& run, std::size_t rows, std::size_t stride) {
  std::vector<std::size_t> out;
  if (rows == 0 || run.first >= rows) return out;
  const std::size_t end = std::min(run.last + 1, rows - 1);  // through the next run's first row
  stride = std::max<std::size_t>(stride, 1);
  for (std::size_t k = run.first; k <= end; k += stride) out.push_back(k);
  if (out.back() != end) out.push_back(end);
  return out;
}

QChart* makeHysteresisChart(const ThermalLog& log, const thermal::ThermalSeries& series,
                            const thermal::HysteresisAnalysis& analysis, int input,
                            const HysteresisChartOptions& options) {
  const std::size_t n = series.rows();
  const bool ok = input >= 0 && static_cast<std::size_t>(input) < series.inputs.size() &&
                  series.hasTarget() && analysis.phase.size() == n;
  const QString sensor =
      ok ? QString::fromStdString(series.inputNames[static_cast<std::size_t>(input)]) : QString();
  QString title;
  if (ok && static_cast<std::size_t>(input) < analysis.sensors.size()) {
    const thermal::SensorHysteresis& h = analysis.sensors[static_cast<std::size_t>(input)];
    const QLocale locale;
    title = options.compactTitle
                ? ModelChartsText::tr("%1: lag %2 min").arg(sensor, locale.toString(h.tauMin, 'f', 1))
                : ModelChartsText::tr("%1 against %2: lag %3 min, loop %4")
                      .arg(QString::fromStdString(series.targetName), sensor,
                           locale.toString(h.tauMin, 'f', 1), locale.toString(h.normalisedLoopArea, 'f', 3));
  }
  QChart* chart = newChart(title);
  auto* x = new QValueAxis;
  auto* y = new QValueAxis;
  x->setTitleText(sensor + unitSuffix(log, sensor.toStdString()));
  y->setTitleText(QString::fromStdString(series.targetName) + unitSuffix(log, series.targetName));
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);
  Range rx, ry;
  if (ok) {
    const auto& s = series.inputs[static_cast<std::size_t>(input)];
    const std::size_t stride =
        std::max<std::size_t>(1, n / static_cast<std::size_t>(std::max(10, options.maxPoints)) + 1);
    bool named[2] = {false, false};
    for (const PhaseRun& run : phaseRuns(analysis.phase)) {
      const ThermalPhaseKind kind = run.phase > 0 ? ThermalPhaseKind::Heating : ThermalPhaseKind::Cooling;
      QList<QPointF> points;
      for (std::size_t k : hysteresisRunRows(run, n, stride)) {
        points << QPointF(s[k], series.target[k]);
        rx.add(s[k]);
        ry.add(series.target[k]);
      }
      auto* line = new QLineSeries;
      line->setName(kind == ThermalPhaseKind::Heating ? ModelChartsText::tr("heating")
                                                      : ModelChartsText::tr("cooling"));
      line->setPen(QPen(thermalPhaseLineColor(kind), 1.8));
      line->replace(points);
      chart->addSeries(line);
      line->attachAxis(x);
      line->attachAxis(y);
      // One legend entry per phase kind.
      bool& seen = named[kind == ThermalPhaseKind::Heating ? 0 : 1];
      const auto markers = chart->legend()->markers(line);
      for (QLegendMarker* m : markers) m->setVisible(!seen);
      seen = true;
    }
  }
  setRange(x, rx);
  setRange(y, ry);
  finishLegend(chart, options.legend);
  return chart;
}

QChart* makeModelComparisonChart(const ThermalLog& log, const ThermalComparison& c,
                                 const ModelChartOptions& options) {
  QChart* chart = newChart(options.title);
  const thermal::ThermalSeries& s = c.series;
  const TimeAxis time = addTimeAxis(chart, s.timeMin, thermalTimeAxisInHours(log));
  auto* y = new QValueAxis;
  y->setTitleText(QString::fromStdString(s.targetName) + unitSuffix(log, s.targetName));
  chart->addAxis(y, Qt::AlignLeft);
  const std::size_t fitRows = c.fitRows;
  if (s.rows() >= 2 && fitRows > 0 && fitRows < s.rows()) {
    addHeldOutBand(chart, time, 0.5 * (s.timeMin[fitRows - 1] + s.timeMin[fitRows]), s.timeMin.back());
  }
  Range measured;
  QLineSeries* m = timeSeries(s.timeMin, s.target, time.scale, options.maxPointsPerSeries, &measured);
  m->setName(ModelChartsText::tr("measured"));
  m->setPen(QPen(palette::measured(), 2.0));
  chart->addSeries(m);
  m->attachAxis(time.axis);
  m->attachAxis(y);
  for (std::size_t i = 0; i < kThermalModelOrder.size(); ++i) {
    if (!c.failed[i].empty()) addNotFittedEntry(chart, i, time.axis, y);
    if (!fitted(c, i)) continue;
    Range pr;
    QLineSeries* p =
        timeSeries(s.timeMin, c.models[i].predicted, time.scale, options.maxPointsPerSeries, &pr);
    const double span = measured.valid() ? std::max(measured.hi - measured.lo, 1e-9) : 1.0;
    const bool offScale =
        measured.valid() && (!pr.valid() || pr.hi > measured.hi + span || pr.lo < measured.lo - span);
    p->setName(offScale ? ModelChartsText::tr("%1 (off scale)").arg(thermalModelName(kThermalModelOrder[i]))
                        : thermalModelName(kThermalModelOrder[i]));
    p->setPen(QPen(thermalModelColor(kThermalModelOrder[i]), 1.5, i == 0 ? Qt::SolidLine : Qt::DashLine));
    chart->addSeries(p);
    p->attachAxis(time.axis);
    p->attachAxis(y);
  }
  // The measured range with a margin: an unstable grey model (b1 <= 0) runs off the chart.
  if (measured.valid()) {
    const double pad = 0.15 * std::max(measured.hi - measured.lo, 1e-9);
    setRange(y, {measured.lo - pad, measured.hi + pad});
  } else {
    setRange(y, measured);
  }
  finishLegend(chart, options.legend);
  return chart;
}

QChart* makeResidualChart(const ThermalLog& log, const ThermalComparison& c,
                          const ModelChartOptions& options) {
  QChart* chart = newChart(options.title);
  const thermal::ThermalSeries& s = c.series;
  const TimeAxis time = addTimeAxis(chart, s.timeMin, thermalTimeAxisInHours(log));
  auto* y = new QValueAxis;
  y->setTitleText(ModelChartsText::tr("residual") + unitSuffix(log, s.targetName));
  chart->addAxis(y, Qt::AlignLeft);
  const std::size_t fitRows = c.fitRows;
  if (s.rows() >= 2 && fitRows > 0 && fitRows < s.rows()) {
    addHeldOutBand(chart, time, 0.5 * (s.timeMin[fitRows - 1] + s.timeMin[fitRows]), s.timeMin.back());
  }
  Range target;
  for (double v : s.target) target.add(v);
  const double scale = target.valid() ? std::max(target.hi - target.lo, 1e-9) : 1.0;
  // The axis covers the residuals of the models that stay within the target's range; a model that
  // runs away (an unstable grey model) is drawn off scale and named so.
  double extent = 0.0;
  for (std::size_t i = 0; i < kThermalModelOrder.size(); ++i) {
    if (!c.failed[i].empty()) addNotFittedEntry(chart, i, time.axis, y);
    if (!fitted(c, i)) continue;
    std::vector<double> r(s.rows());
    for (std::size_t k = 0; k < s.rows(); ++k) r[k] = s.target[k] - c.models[i].predicted[k];
    Range rr;
    QLineSeries* line = timeSeries(s.timeMin, r, time.scale, options.maxPointsPerSeries, &rr);
    const double ext = rr.valid() ? std::max(std::abs(rr.lo), std::abs(rr.hi)) : 0.0;
    const bool offScale = !rr.valid() || ext > scale;
    if (!offScale) extent = std::max(extent, ext);
    line->setName(offScale
                      ? ModelChartsText::tr("%1 (off scale)").arg(thermalModelName(kThermalModelOrder[i]))
                      : thermalModelName(kThermalModelOrder[i]));
    line->setPen(QPen(thermalModelColor(kThermalModelOrder[i]), 1.4, i == 0 ? Qt::SolidLine : Qt::DashLine));
    chart->addSeries(line);
    line->attachAxis(time.axis);
    line->attachAxis(y);
  }
  if (!(extent > 0.0)) extent = scale;
  setRange(y, {-1.1 * extent, 1.1 * extent});
  finishLegend(chart, options.legend);
  return chart;
}

QChart* makeModularChart(const ThermalLog& testLog, const ModularComparison& modular,
                         const ModelChartOptions& options) {
  QChart* chart = newChart(options.title);
  const thermal::ThermalSeries& s = modular.test;
  const TimeAxis time = addTimeAxis(chart, s.timeMin, thermalTimeAxisInHours(testLog));
  auto* y = new QValueAxis;
  y->setTitleText(QString::fromStdString(s.targetName) + unitSuffix(testLog, s.targetName));
  chart->addAxis(y, Qt::AlignLeft);
  Range measured;
  QLineSeries* m = timeSeries(s.timeMin, s.target, time.scale, options.maxPointsPerSeries, &measured);
  m->setName(ModelChartsText::tr("measured (combined test)"));
  m->setPen(QPen(palette::measured(), 2.0));
  chart->addSeries(m);
  m->attachAxis(time.axis);
  m->attachAxis(y);
  for (std::size_t i = 0; i < kThermalModelOrder.size(); ++i) {
    const auto& ev = modular.models[i];
    if (!modular.failed[i].empty()) addNotFittedEntry(chart, i, time.axis, y);
    if (!modular.fitted(i)) continue;
    QLineSeries* p = timeSeries(s.timeMin, ev.predicted, time.scale, options.maxPointsPerSeries, nullptr);
    p->setName(thermalModelName(kThermalModelOrder[i]));
    p->setPen(QPen(thermalModelColor(kThermalModelOrder[i]), 1.5, i == 0 ? Qt::SolidLine : Qt::DashLine));
    chart->addSeries(p);
    p->attachAxis(time.axis);
    p->attachAxis(y);
  }
  // Module by module: each module's contribution (drawn from the test's first value) and their sum.
  if (const auto& ev = modular.modules.evaluation; ev && ev->predicted.size() == s.rows()) {
    const QColor colours[] = {QColor(0x00, 0x80, 0x80), QColor(0x80, 0x00, 0x80), QColor(0x80, 0x60, 0x00)};
    // Legend names without the modules' common prefix up to an underscore ("thermal_modular_z" -> "z").
    std::vector<std::string> names = modular.modules.names;
    std::size_t common = 0;
    if (names.size() > 1) {
      std::size_t n = 0;
      while (std::all_of(names.begin(), names.end(),
                         [&](const std::string& s) { return n < s.size() && s[n] == names.front()[n]; }))
        ++n;
      const std::size_t cut = names.front().rfind('_', n == 0 ? 0 : n - 1);
      if (cut != std::string::npos && cut + 1 <= n) common = cut + 1;
    }
    for (std::string& n : names)
      if (common < n.size()) n = n.substr(common);
    for (std::size_t i = 0; i < ev->contributions.size() && i < names.size(); ++i) {
      std::vector<double> v = ev->contributions[i];
      for (double& x : v) x += s.target.front();
      QLineSeries* c = timeSeries(s.timeMin, v, time.scale, options.maxPointsPerSeries, nullptr);
      c->setName(ModelChartsText::tr("module %1").arg(QString::fromStdString(names[i])));
      c->setPen(QPen(colours[i % 3], 1.2, Qt::DotLine));
      chart->addSeries(c);
      c->attachAxis(time.axis);
      c->attachAxis(y);
    }
    QLineSeries* sum = timeSeries(s.timeMin, ev->predicted, time.scale, options.maxPointsPerSeries, nullptr);
    sum->setName(ModelChartsText::tr("modules, summed"));
    sum->setPen(QPen(Qt::black, 1.5, Qt::DashDotLine));
    chart->addSeries(sum);
    sum->attachAxis(time.axis);
    sum->attachAxis(y);
    measured.add(ev->predicted.front());
    for (const auto& c : ev->contributions)
      for (double x : c) measured.add(s.target.front() + x);
  }
  if (measured.valid()) {
    const double pad = 0.15 * std::max(measured.hi - measured.lo, 1e-9);
    setRange(y, {measured.lo - pad, measured.hi + pad});
  }
  finishLegend(chart, options.legend);
  return chart;
}

QChart* makeTrainingChart(const std::vector<double>& best, const QString& yTitle) {
  QChart* chart = newChart(QString());
  auto* x = new QValueAxis;
  x->setTitleText(ModelChartsText::tr("PSO iteration"));
  x->setLabelFormat(QStringLiteral("%.0f"));
  Range r;
  for (double b : best) {
    if (b > 0.0) r.add(b);
  }
  // Log scale when the fitness falls by more than a factor of 20, else linear (readable ticks).
  const bool logScale = r.valid() && r.hi > 20.0 * r.lo;
  QAbstractAxis* y = nullptr;
  if (logScale) {
    auto* a = new QLogValueAxis;
    a->setLabelFormat(QStringLiteral("%.3g"));
    a->setRange(r.lo / 1.5, r.hi * 1.5);
    y = a;
  } else {
    auto* a = new QValueAxis;
    setRange(a, r.valid() ? Range{0.0, r.hi} : Range{0.0, 1.0});
    a->setLabelFormat(QStringLiteral("%.3g"));
    y = a;
  }
  y->setTitleText(yTitle);
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);
  auto* line = new QLineSeries;
  line->setName(ModelChartsText::tr("best fitness"));
  line->setPen(QPen(thermalModelColor(thermal::ThermalModelKind::Gnnmci), 1.6));
  QList<QPointF> points;
  for (std::size_t i = 0; i < best.size(); ++i) {
    if (best[i] > 0.0 && std::isfinite(best[i])) points << QPointF(static_cast<double>(i), best[i]);
  }
  line->replace(points);
  chart->addSeries(line);
  line->attachAxis(x);
  line->attachAxis(y);
  x->setRange(0.0, std::max(1.0, static_cast<double>(best.size()) - 1.0));
  chart->legend()->setVisible(false);
  return chart;
}

}  // namespace metrofit
