#pragma once
// Qt-free helpers behind the thermal trend chart: heating / cooling phase detection and min/max
// decimation of long series for display. Pure functions of plain vectors, so tests call them
// directly and the chart, the report and the GUI agree on the phases they show.
//
// Phases (times in minutes, as in ThermalLog::timeMin):
//  * From a speed channel (spindle_rpm, ...), when the log has one and the machine ran at all:
//    a row is "running" when |speed| > speedOnFraction * max|speed|. Running intervals are heating
//    phases, stopped intervals that follow a running one are cooling phases; an idle start is
//    neither.
//  * Otherwise from the mean temperature T(t) of the machine's temperature channels (ambient
//    sensors left out, see meanTemperature): the local slope s_i is the least-squares slope of T
//    over the rows with |t - t_i| <= w/2 (a moving linear fit, which smooths and differentiates in
//    one step), with w = max(smoothingFraction * span, 4 * median row spacing). With S = the 95th
//    percentile of |s|, a row is heating when s_i > slopeDeadBand * S, cooling when
//    s_i < -slopeDeadBand * S, and neither otherwise. A slope phase whose integrated change
//    sum(s_i * dt_i) is smaller than minPhaseChange (degC) is noise and counts as neither.
// In both cases a run of equally labelled rows shorter than minPhaseFraction * span is absorbed
// into its longer neighbour (noise flicker, a short tool change), shortest first; an idle run at
// either end of the log is kept, and with a speed channel every end run is kept (a short final
// stop is a real cooling start). Boundaries lie halfway between the rows where the label changes.
#include <cstddef>
#include <string>
#include <vector>

namespace metrofit {
struct ThermalLog;

enum class ThermalPhaseKind { Heating, Cooling };

/// One heating or cooling interval of a log, [startMin, endMin] in minutes.
struct ThermalPhase {
  ThermalPhaseKind kind = ThermalPhaseKind::Heating;
  double startMin = 0.0;
  double endMin = 0.0;
};

/// Where the phases came from.
enum class PhaseSource { None, Speed, TemperatureSlope };

struct PhaseOptions {
  double smoothingFraction = 0.03;  ///< slope window as a fraction of the log's time span
  double slopeDeadBand = 0.01;      ///< |slope| below this fraction of its 95th percentile is neither
  double speedOnFraction = 0.02;    ///< |speed| above this fraction of max|speed| counts as running
  double minPhaseFraction = 0.01;   ///< runs shorter than this fraction of the span are absorbed
  double minPhaseChange = 0.1;      ///< slope phases must change the signal by this much (degC)

  /// All fractions must lie in [0, 1) (smoothingFraction in (0, 1)), minPhaseChange >= 0.
  bool isValid(std::string* why) const;
};

struct PhaseDetection {
  PhaseSource source = PhaseSource::None;
  std::string channel;  ///< the speed channel used, or empty
  std::vector<ThermalPhase> phases;
};

/// Least-squares slope of `value` against `timeMin` in a moving window of width `windowMin`
/// centred on every row (units of value per minute). Both vectors must have the same size.
std::vector<double> localSlope(const std::vector<double>& timeMin, const std::vector<double>& value,
                               double windowMin);

/// Phases from the slope of one temperature-like signal (see the header comment).
std::vector<ThermalPhase> phasesFromSlope(const std::vector<double>& timeMin,
                                          const std::vector<double>& value, const PhaseOptions& options = {});

/// Phases from a speed signal (see the header comment). Empty when the speed is zero throughout.
std::vector<ThermalPhase> phasesFromSpeed(const std::vector<double>& timeMin,
                                          const std::vector<double>& speed, const PhaseOptions& options = {});

/// Mean of the log's machine temperature channels per row: ambient channels (name containing
/// "amb", e.g. T_amb) are left out unless there are no others. Empty when the log has none.
std::vector<double> meanTemperature(const ThermalLog& log);

/// Phases of a log: from its first speed channel when the machine ran, else from the slope of the
/// mean temperature; PhaseSource::None when neither is possible. Throws OptionsError on bad options.
PhaseDetection detectThermalPhases(const ThermalLog& log, const PhaseOptions& options = {});

/// Row indices to draw for a series of n = timeMin.size() rows with at most maxPoints points:
/// all rows when n <= maxPoints, otherwise the first and last row plus, for each of
/// (maxPoints - 2) / 2 equal time buckets, the rows of the bucket's minimum and maximum value, in
/// increasing order (so peaks and dips survive decimation). maxPoints must be >= 4.
std::vector<std::size_t> decimateMinMax(const std::vector<double>& timeMin, const std::vector<double>& value,
                                        std::size_t maxPoints);

}  // namespace metrofit
