// Thermal trend chart construction (see thermalcharts.h).
#include "widgets/thermal/thermalcharts.h"

#include <QAreaSeries>
#include <QChart>
#include <QCoreApplication>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QPen>
#include <QValueAxis>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "core/common/axis_ticks.h"
#include "core/thermal/thermal_log.h"
#include "widgets/common/palette.h"

namespace metrofit {
namespace {

struct ThermalChartsText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::ThermalCharts)
};

constexpr double kHoursThresholdMin = 180.0;
constexpr int kMaxDefaultTemperatures = 8;
constexpr int kTargetTicks = 6;
constexpr int kMaxLegendRow = 8;  ///< legend entries that still fit in one row below the plot

/// Sort rank of an axis group: temperatures first (left), speed last (outermost on the right).
int kindRank(ChannelKind kind) {
  switch (kind) {
    case ChannelKind::Temperature:
      return 0;
    case ChannelKind::Displacement:
      return 1;
    case ChannelKind::Strain:
      return 2;
    case ChannelKind::Other:
      return 3;
    case ChannelKind::Speed:
      return 4;
  }
  return 3;
}

QString kindWord(ChannelKind kind) {
  switch (kind) {
    case ChannelKind::Temperature:
      return ThermalChartsText::tr("temperature");
    case ChannelKind::Displacement:
      return ThermalChartsText::tr("displacement");
    case ChannelKind::Strain:
      return ThermalChartsText::tr("strain");
    case ChannelKind::Speed:
      return ThermalChartsText::tr("speed");
    case ChannelKind::Other:
      break;
  }
  return ThermalChartsText::tr("value");
}

/// Group title word: what the channels of a group are ("temperatures", "displacements", ...).
QString groupWord(ChannelKind kind) {
  switch (kind) {
    case ChannelKind::Temperature:
      return ThermalChartsText::tr("temperatures");
    case ChannelKind::Displacement:
      return ThermalChartsText::tr("displacements");
    case ChannelKind::Strain:
      return ThermalChartsText::tr("strains");
    case ChannelKind::Speed:
      return ThermalChartsText::tr("speed");
    case ChannelKind::Other:
      break;
  }
  return ThermalChartsText::tr("other channels");
}

/// printf format with as many decimals as a tick step needs.
QString labelFormat(double step) {
  const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
  return QStringLiteral("%.%1f").arg(decimals);
}

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool valid() const { return lo <= hi; }
};

/// Pads a data range so it is never empty.
Range padded(Range r) {
  if (!r.valid()) {
    return {0.0, 1.0};
  }
  if (r.hi - r.lo <= 1e-12 * std::max(1.0, std::abs(r.hi))) {
    const double d = std::max(0.5, 0.05 * std::abs(r.hi));
    return {r.lo - d, r.hi + d};
  }
  return r;
}

/// Sets an axis to cover r with `ticks` fixed ticks on round values; ticks <= 0 picks the count.
/// Returns the tick count used, so further axes can share the grid lines.
int setNiceRange(QValueAxis* axis, Range r, int ticks) {
  r = padded(r);
  double step = 0.0;
  double lo = 0.0;
  if (ticks <= 0) {
    step = ticks::niceCeil((r.hi - r.lo) / kTargetTicks);
    lo = std::floor(r.lo / step) * step;
    const double hi = std::ceil(r.hi / step - 1e-9) * step;
    ticks = static_cast<int>(std::lround((hi - lo) / step)) + 1;
  } else {
    step = ticks::niceCeil((r.hi - r.lo) / (ticks - 1));
    lo = std::floor(r.lo / step) * step;
    while (lo + step * (ticks - 1) < r.hi - 1e-12 * std::abs(r.hi)) {
      step = ticks::niceCeil(step * 1.0001);
      lo = std::floor(r.lo / step) * step;
    }
  }
  axis->setRange(lo, lo + step * (ticks - 1));
  axis->setTickType(QValueAxis::TicksFixed);
  axis->setTickCount(ticks);
  axis->setLabelFormat(labelFormat(step));
  return ticks;
}

/// An axis group: the channels sharing one y axis (same kind and unit).
struct AxisGroup {
  ChannelKind kind = ChannelKind::Other;
  QString unit;
  std::vector<int> channels;  ///< indices into log.channels
  Range range;
};

}  // namespace

QStringList defaultThermalChannels(const ThermalLog& log) {
  QStringList names;
  int temperatures = 0;
  for (const ThermalChannel& c : log.channels) {
    if (channelKind(c) == ChannelKind::Temperature && ++temperatures > kMaxDefaultTemperatures) {
      continue;
    }
    names << QString::fromStdString(c.name);
  }
  return names;
}

std::vector<ThermalChannelGroup> thermalChannelGroups(const ThermalLog& log) {
  std::vector<ThermalChannelGroup> groups;
  for (int i = 0; i < static_cast<int>(log.channels.size()); ++i) {
    const ThermalChannel& c = log.channels[i];
    const ChannelKind kind = channelKind(c);
    const QString unit = channelUnit(c);
    auto it = std::find_if(groups.begin(), groups.end(),
                           [&](const ThermalChannelGroup& g) { return g.kind == kind && g.unit == unit; });
    if (it == groups.end()) {
      ThermalChannelGroup g;
      g.kind = kind;
      g.unit = unit;
      QString word = groupWord(kind);
      if (unit.endsWith(QLatin1String("/min"))) word = ThermalChartsText::tr("feed speed");
      g.title = unit.isEmpty() ? word : ThermalChartsText::tr("%1 (%2)").arg(word, unit);
      groups.push_back(g);
      it = groups.end() - 1;
    }
    it->channels.push_back(i);
  }
  std::stable_sort(groups.begin(), groups.end(),
                   [](const ThermalChannelGroup& a, const ThermalChannelGroup& b) {
                     return kindRank(a.kind) < kindRank(b.kind);
                   });
  return groups;
}

QColor thermalChannelColor(const ThermalLog& log, int channelIndex) {
  if (channelIndex < 0 || channelIndex >= static_cast<int>(log.channels.size())) {
    return QColor(Qt::black);
  }
  // Rank among the channels of the same palette family: temperatures; displacements, strains and
  // other channels; speeds.
  const auto family = [](ChannelKind k) {
    return k == ChannelKind::Temperature || k == ChannelKind::Speed ? k : ChannelKind::Displacement;
  };
  const ChannelKind kind = channelKind(log.channels[channelIndex]);
  int rank = 0;
  for (int i = 0; i < channelIndex; ++i) {
    rank += family(channelKind(log.channels[i])) == family(kind) ? 1 : 0;
  }
  switch (kind) {
    case ChannelKind::Temperature:
      return palette::temperatureSeries(rank);
    case ChannelKind::Speed:
      return palette::speedSeries(rank);
    case ChannelKind::Displacement:
    case ChannelKind::Strain:
    case ChannelKind::Other:
      break;
  }
  return palette::displacementSeries(rank);
}

Qt::PenStyle thermalChannelPenStyle(const ThermalLog& log, int channelIndex) {
  if (channelIndex < 0 || channelIndex >= static_cast<int>(log.channels.size())) {
    return Qt::SolidLine;
  }
  switch (channelKind(log.channels[channelIndex])) {
    case ChannelKind::Temperature:
      return Qt::SolidLine;
    case ChannelKind::Displacement:
    case ChannelKind::Strain:
      return Qt::DashLine;
    case ChannelKind::Speed:
      return Qt::DashDotLine;
    case ChannelKind::Other:
      break;
  }
  return Qt::DotLine;
}

QString channelLegendName(const ThermalChannel& channel) {
  QString name = QString::fromStdString(channel.name);
  const QString unit = channelUnit(channel);
  if (unit.isEmpty()) {
    return name;
  }
  if (!channel.unit.empty()) {
    const QString suffix = QLatin1Char('_') + QString::fromStdString(channel.unit);
    if (name.endsWith(suffix, Qt::CaseInsensitive) && name.size() > suffix.size()) {
      name.chop(suffix.size());
    }
  }
  return ThermalChartsText::tr("%1 (%2)").arg(name, unit);
}

QColor thermalPhaseColor(ThermalPhaseKind kind) {
  return kind == ThermalPhaseKind::Heating ? palette::heatingFill() : palette::coolingFill();
}

QString displayUnit(const std::string& unit) {
  QString u = QString::fromStdString(unit);
  const QString key = u.toLower();
  if (key == QLatin1String("um")) {
    return QStringLiteral("µm");
  }
  if (key == QLatin1String("degc") || key == QLatin1String("c")) {
    return QStringLiteral("°C");
  }
  if (key == QLatin1String("ue") || key == QLatin1String("microstrain")) {
    return QStringLiteral("µε");
  }
  return u;
}

QString channelUnit(const ThermalChannel& channel) {
  QString unit = displayUnit(channel.unit);
  if (unit.isEmpty()) {
    // Suffixes core does not know as units: "_mpm" is a feed speed in m/min (e.g. z_speed_mpm).
    const QString name = QString::fromStdString(channel.name).toLower();
    if (name.endsWith(QLatin1String("_mpm")) || name.endsWith(QLatin1String("_m_per_min"))) {
      unit = QStringLiteral("m/min");
    } else if (name.endsWith(QLatin1String("_mmpm")) || name.endsWith(QLatin1String("_mm_per_min"))) {
      unit = QStringLiteral("mm/min");
    } else if (channelKind(channel) == ChannelKind::Temperature) {
      unit = QStringLiteral("°C");
    }
  }
  return unit;
}

QString channelAxisTitle(const ThermalChannel& channel) {
  const ChannelKind kind = channelKind(channel);
  const QString unit = channelUnit(channel);
  QString word = kindWord(kind);
  if (unit.endsWith(QLatin1String("/min"))) word = ThermalChartsText::tr("feed speed");
  return unit.isEmpty() ? word : ThermalChartsText::tr("%1 (%2)").arg(word, unit);
}

bool thermalTimeAxisInHours(const ThermalLog& log) {
  return log.rows() >= 2 && log.timeMin.back() - log.timeMin.front() > kHoursThresholdMin;
}

QChart* makeThermalTrendChart(const ThermalLog& log, const QStringList& channels,
                              const ThermalChartOptions& options) {
  auto* chart = new QChart;
  chart->setAnimationOptions(QChart::NoAnimation);
  chart->setBackgroundRoundness(0);
  chart->setMargins(QMargins(4, 4, 4, 4));
  if (!options.title.isEmpty()) {
    chart->setTitle(options.title);
  }

  const bool hours = thermalTimeAxisInHours(log);
  const double timeScale = hours ? 1.0 / 60.0 : 1.0;
  auto* timeAxis = new QValueAxis;
  timeAxis->setTitleText(hours ? ThermalChartsText::tr("time (h)") : ThermalChartsText::tr("time (min)"));
  Range timeRange;
  if (log.rows() > 0) {
    timeRange = {log.timeMin.front() * timeScale, log.timeMin.back() * timeScale};
  }
  {
    const Range r = padded(timeRange);
    const double step = ticks::niceCeil((r.hi - r.lo) / 8.0);
    timeAxis->setRange(r.lo, r.hi);
    timeAxis->setTickType(QValueAxis::TicksDynamic);
    timeAxis->setTickAnchor(0.0);
    timeAxis->setTickInterval(step);
    timeAxis->setLabelFormat(labelFormat(step));
  }
  chart->addAxis(timeAxis, Qt::AlignBottom);

  // The groups of the requested channels (kind and unit), temperatures first.
  std::vector<AxisGroup> groups;
  for (const ThermalChannelGroup& g : thermalChannelGroups(log)) {
    AxisGroup axisGroup{g.kind, g.unit, {}, {}};
    for (int i : g.channels) {
      const ThermalChannel& c = log.channels[i];
      if (channels.contains(QString::fromStdString(c.name)) && c.values.size() == log.rows()) {
        axisGroup.channels.push_back(i);
      }
    }
    if (!axisGroup.channels.empty()) groups.push_back(axisGroup);
  }

  // Phase bands first, so the lines are drawn over them; on a hidden 0..1 axis spanning the plot.
  if (options.shadePhases && log.rows() >= 3) {
    const PhaseDetection detection = detectThermalPhases(log);
    auto* bandAxis = new QValueAxis;
    bandAxis->setRange(0.0, 1.0);
    bandAxis->setVisible(false);
    bool bandAxisUsed = false;
    for (ThermalPhaseKind kind : {ThermalPhaseKind::Heating, ThermalPhaseKind::Cooling}) {
      QList<QPointF> upperPoints;
      for (const ThermalPhase& p : detection.phases) {
        if (p.kind == kind) {
          const double a = p.startMin * timeScale;
          const double b = p.endMin * timeScale;
          upperPoints << QPointF(a, 0.0) << QPointF(a, 1.0) << QPointF(b, 1.0) << QPointF(b, 0.0);
        }
      }
      if (upperPoints.isEmpty()) {
        continue;
      }
      auto* upper = new QLineSeries;
      upper->replace(upperPoints);
      auto* lower = new QLineSeries;
      lower->replace(QList<QPointF>{QPointF(timeRange.lo, 0.0), QPointF(timeRange.hi, 0.0)});
      auto* band = new QAreaSeries(upper, lower);
      upper->setParent(band);
      lower->setParent(band);
      band->setName(kind == ThermalPhaseKind::Heating ? ThermalChartsText::tr("heating")
                                                      : ThermalChartsText::tr("cooling"));
      band->setPen(QPen(Qt::NoPen));
      band->setBrush(thermalPhaseColor(kind));
      chart->addSeries(band);
      if (!bandAxisUsed) {
        chart->addAxis(bandAxis, Qt::AlignLeft);
        bandAxisUsed = true;
      }
      band->attachAxis(timeAxis);
      band->attachAxis(bandAxis);
    }
    if (!bandAxisUsed) {
      delete bandAxis;
    }
  }

  // One line series per channel, decimated; one y axis per group.
  int ticks = 0;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    AxisGroup& group = groups[g];
    auto* axis = new QValueAxis;
    axis->setTitleText(channelAxisTitle(log.channels[group.channels.front()]));
    chart->addAxis(axis, g == 0 ? Qt::AlignLeft : Qt::AlignRight);
    if (g > 0) {
      axis->setGridLineVisible(false);
    }
    for (int index : group.channels) {
      const ThermalChannel& c = log.channels[index];
      const std::vector<std::size_t> rows = decimateMinMax(
          log.timeMin, c.values, static_cast<std::size_t>(std::max(4, options.maxPointsPerSeries)));
      QList<QPointF> points;
      points.reserve(static_cast<qsizetype>(rows.size()));
      for (std::size_t row : rows) {
        points << QPointF(log.timeMin[row] * timeScale, c.values[row]);
        group.range.add(c.values[row]);
      }
      auto* series = new QLineSeries;
      series->setName(channelLegendName(c));
      series->setObjectName(QString::fromStdString(c.name));
      QPen pen(thermalChannelColor(log, index), group.kind == ChannelKind::Temperature ? 1.6 : 2.0);
      pen.setStyle(thermalChannelPenStyle(log, index));
      series->setPen(pen);
      series->replace(points);
      chart->addSeries(series);
      series->attachAxis(timeAxis);
      series->attachAxis(axis);
    }
    ticks = setNiceRange(axis, group.range, g == 0 ? 0 : ticks);
  }

  // Legend: channel entries only when asked for; hidden when there is nothing to explain.
  // Many entries do not fit in one row below the plot (Qt Charts elides them): list them on the right.
  int markers = 0;
  for (QLegendMarker* marker : chart->legend()->markers()) {
    const bool visible = marker->type() == QLegendMarker::LegendMarkerTypeArea || options.channelLegend;
    marker->setVisible(visible);
    markers += visible ? 1 : 0;
    // Channels show their line (solid, dashed, dash-dotted), the phase bands a filled square.
    marker->setShape(marker->type() == QLegendMarker::LegendMarkerTypeArea ? QLegend::MarkerShapeRectangle
                                                                           : QLegend::MarkerShapeFromSeries);
  }
  chart->legend()->setVisible(markers > 0);
  chart->legend()->setAlignment(markers > kMaxLegendRow ? Qt::AlignRight : Qt::AlignBottom);
  return chart;
}

}  // namespace metrofit
