#pragma once
// Construction of the thermal trend chart without a widget, shared by ThermalTrendView (on screen)
// and the PDF report (rendered as vector graphics through a QGraphicsScene).
//
// Layout of the chart:
//  * x: time in hours when the log spans more than 3 h, else in minutes ("time (h)" / "time (min)");
//  * left y: temperatures, "temperature (°C)";
//  * right y: one axis per other kind of channel and unit, e.g. "displacement (µm)", "speed (rpm)";
//    when no temperature is shown, the first of those goes on the left;
//  * background bands: heating and cooling phases (trend_analysis.h), one legend entry each;
//  * every series decimated to at most ThermalChartOptions::maxPointsPerSeries points (min/max per
//    time bucket), no animations.
// Qt Charts stays out of this header: QChart is only forward-declared.
#include <QColor>
#include <QString>
#include <QStringList>

#include <string>
#include <vector>

#include "core/study/trend_analysis.h"
#include "core/thermal/thermal_log.h"

QT_BEGIN_NAMESPACE
class QChart;
QT_END_NAMESPACE

namespace metrofit {

struct ThermalChartOptions {
  int maxPointsPerSeries = 2000;  ///< decimation limit per series (>= 4)
  bool shadePhases = true;        ///< draw heating / cooling bands
  bool channelLegend = true;      ///< legend entries for the channels (the bands always have one)
  QString title;                  ///< chart title, none when empty
};

/// Channels shown by default: every channel, but at most the first 8 temperatures.
QStringList defaultThermalChannels(const ThermalLog& log);

/// The channels of one kind and unit: one y axis of the chart, one group of its legend and of the
/// view's channel list ("temperatures (°C)", "displacements (µm)", "speed (rpm)").
struct ThermalChannelGroup {
  ChannelKind kind = ChannelKind::Other;
  QString unit;               ///< as printed: "°C", "µm", "rpm", ... or empty
  QString title;              ///< "temperatures (°C)", "displacements (µm)", "speed (rpm)", ...
  std::vector<int> channels;  ///< indices into log.channels, in the log's order
};

/// Every channel of the log in its group; temperatures first, then displacements, strains, other
/// channels, speeds last (the order of the axes, the legend and the channel list).
std::vector<ThermalChannelGroup> thermalChannelGroups(const ThermalLog& log);

/// Colour of the log's channel number `channelIndex`: the palette of its group (palette.h:
/// temperatureSeries, displacementSeries, speedSeries) at its rank in its group, so no two channels
/// of a group share a colour and a colour does not depend on what else is shown.
QColor thermalChannelColor(const ThermalLog& log, int channelIndex);

/// Line style of a channel: temperatures solid, displacements and strains dashed, speeds
/// dash-dotted, other channels dotted.
Qt::PenStyle thermalChannelPenStyle(const ThermalLog& log, int channelIndex);

/// Legend name of a channel: its column name without a unit suffix, with the unit:
/// "t1_degC" -> "t1 (°C)", "disp_z_um" -> "disp_z (µm)", "T1" -> "T1 (°C)", "spindle_rpm" ->
/// "spindle (rpm)"; the bare name when the channel has no unit.
QString channelLegendName(const ThermalChannel& channel);

/// Fill colour of the background band of a phase (opaque, light).
QColor thermalPhaseColor(ThermalPhaseKind kind);

/// Unit of a channel as printed: "um" -> "µm", "degC" -> "°C", "ue" -> "µε", others as they are.
QString displayUnit(const std::string& unit);

/// Unit of a channel as printed: displayUnit(channel.unit), else from a name suffix core does not
/// treat as a unit ("z_speed_mpm" -> "m/min"), "°C" for a temperature without one, else empty.
QString channelUnit(const ThermalChannel& channel);

/// Axis title of a channel: "temperature (°C)", "displacement (µm)", "speed (rpm)",
/// "feed speed (m/min)", ...
QString channelAxisTitle(const ThermalChannel& channel);

/// True when the time axis is in hours (the log spans more than 180 min).
bool thermalTimeAxisInHours(const ThermalLog& log);

/// A new chart (owned by the caller) of the named channels of `log`, in the log's channel order;
/// unknown names are ignored. Without a QApplication this must not be called.
QChart* makeThermalTrendChart(const ThermalLog& log, const QStringList& channels,
                              const ThermalChartOptions& options = {});

}  // namespace metrofit
