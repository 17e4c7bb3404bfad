// Report section "Thermal": per thermal log, a summary, the trend chart as vector graphics and a
// table of the channels with their ranges.
#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <map>

#include "widgets/charts/thermalcharts.h"
#include "widgets/charts/trendanalysis.h"
#include "widgets/report/reportpainter.h"
#include "widgets/report/sections.h"

namespace metrofit {
namespace {

struct ReportText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::Report)
};

constexpr double kChartHeightMm = 108.0;

/// "46.3 h" above 3 h, else "95 min".
QString formatDuration(double minutes) {
  return minutes > 180.0 ? ReportText::tr("%1 h").arg(minutes / 60.0, 0, 'f', 1)
                         : ReportText::tr("%1 min").arg(minutes, 0, 'f', minutes < 10.0 ? 1 : 0);
}

/// A value with as many decimals as the channel's range needs.
QString formatValue(double v, double range) {
  const int decimals = range >= 100.0 ? 1 : (range >= 1.0 ? 2 : 3);
  return QString::number(v, 'f', decimals);
}

double medianSpacingMin(const ThermalLog& log) {
  std::vector<double> dt;
  for (std::size_t i = 1; i < log.rows(); ++i) {
    dt.push_back(log.timeMin[i] - log.timeMin[i - 1]);
  }
  if (dt.empty()) {
    return 0.0;
  }
  std::nth_element(dt.begin(), dt.begin() + static_cast<std::ptrdiff_t>(dt.size() / 2), dt.end());
  return dt[dt.size() / 2];
}

QString formatSpacing(double minutes) {
  return minutes < 1.0 ? ReportText::tr("%1 s").arg(minutes * 60.0, 0, 'g', 3)
                       : ReportText::tr("%1 min").arg(minutes, 0, 'g', 3);
}

QString kindCounts(const ThermalLog& log) {
  std::map<ChannelKind, int> counts;
  for (const ThermalChannel& c : log.channels) {
    ++counts[channelKind(c)];
  }
  QStringList parts;
  const std::pair<ChannelKind, const char*> names[] = {
      {ChannelKind::Temperature, QT_TRANSLATE_NOOP("metrofit::Report", "%n temperature(s)")},
      {ChannelKind::Displacement, QT_TRANSLATE_NOOP("metrofit::Report", "%n displacement(s)")},
      {ChannelKind::Strain, QT_TRANSLATE_NOOP("metrofit::Report", "%n strain(s)")},
      {ChannelKind::Speed, QT_TRANSLATE_NOOP("metrofit::Report", "%n speed(s)")},
      {ChannelKind::Other, QT_TRANSLATE_NOOP("metrofit::Report", "%n other")}};
  for (const auto& [kind, text] : names) {
    if (counts[kind] > 0) {
      parts << ReportText::tr(text, nullptr, counts[kind]);
    }
  }
  return parts.join(QStringLiteral(", "));
}

QString phaseSummary(const PhaseDetection& detection) {
  const auto heating =
      std::count_if(detection.phases.begin(), detection.phases.end(),
                    [](const ThermalPhase& p) { return p.kind == ThermalPhaseKind::Heating; });
  const auto cooling = static_cast<qsizetype>(detection.phases.size()) - heating;
  switch (detection.source) {
    case PhaseSource::Speed:
      return ReportText::tr("%1 heating, %2 cooling, from the speed channel %3 (running = heating)")
          .arg(heating)
          .arg(cooling)
          .arg(QString::fromStdString(detection.channel));
    case PhaseSource::TemperatureSlope:
      if (detection.phases.empty()) {
        break;
      }
      return ReportText::tr("%1 heating, %2 cooling, from the slope of the mean temperature")
          .arg(heating)
          .arg(cooling);
    case PhaseSource::None:
      break;
  }
  return ReportText::tr("none detected");
}

void writeThermalLog(ReportPainter& out, const ReportDataset& dataset) {
  const ThermalLog& log = *dataset.thermal;
  out.subheading(ReportText::tr("Thermal log “%1”").arg(QString::fromStdString(dataset.ref.id)),
                 out.mm(40.0));
  if (!dataset.ref.description.empty()) {
    out.paragraph(QString::fromStdString(dataset.ref.description));
  }

  const QStringList shown = defaultThermalChannels(log);
  const PhaseDetection detection = detectThermalPhases(log);
  const double span = log.rows() > 1 ? log.timeMin.back() - log.timeMin.front() : 0.0;
  ReportTable facts;
  facts.widths = {1.0, 3.2};
  facts.widthFraction = 1.0;
  facts.rows = {
      {ReportText::tr("file"), QString::fromStdString(dataset.ref.path)},
      {ReportText::tr("rows"),
       ReportText::tr("%1, every %2 (median), time column %3")
           .arg(log.rows())
           .arg(formatSpacing(medianSpacingMin(log)), QString::fromStdString(log.timeColumn))},
      {ReportText::tr("duration"), formatDuration(span)},
      {ReportText::tr("channels"), kindCounts(log)},
      {ReportText::tr("phases"), phaseSummary(detection)},
      {ReportText::tr("chart"), ReportText::tr("%1 of %2 channels shown; the table lists all")
                                    .arg(shown.size())
                                    .arg(log.channels.size())},
  };
  out.table(facts);

  ThermalChartOptions chartOptions;
  chartOptions.channelLegend = true;
  out.chart(makeThermalTrendChart(log, shown, chartOptions), out.mm(kChartHeightMm));

  ReportTable channels;
  channels.header = {ReportText::tr("channel"), ReportText::tr("quantity"), ReportText::tr("min"),
                     ReportText::tr("max"), ReportText::tr("in chart")};
  channels.widths = {1.4, 1.8, 1.0, 1.0, 0.8};
  channels.alignment = {Qt::AlignLeft, Qt::AlignLeft, Qt::AlignRight, Qt::AlignRight, Qt::AlignHCenter};
  for (const ThermalChannel& c : log.channels) {
    if (c.values.empty()) {
      continue;
    }
    const auto [lo, hi] = std::minmax_element(c.values.begin(), c.values.end());
    const double range = std::max(std::abs(*lo), std::abs(*hi));
    const QString name = QString::fromStdString(c.name);
    channels.rows.push_back({name, channelAxisTitle(c), formatValue(*lo, range), formatValue(*hi, range),
                             shown.contains(name) ? ReportText::tr("yes") : QString()});
  }
  out.table(channels);
}

}  // namespace

QString thermalSectionTitle() {
  return ReportText::tr("Thermal");
}

void writeThermalSection(ReportPainter& out, const ReportContext& context) {
  bool first = true;
  for (const ReportDataset* dataset : context.ofKind(dataset_kind::kThermalLog)) {
    if (!first) {
      out.newPage();
    }
    first = false;
    writeThermalLog(out, *dataset);
  }
}

}  // namespace metrofit
