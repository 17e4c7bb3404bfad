#pragma once
// Charts of the thermal models without a widget, shared by the thermal page and the PDF report (like
// thermalcharts.h for the trend chart). Qt Charts stays out of this header.
//
//  * Hysteresis chart (Abdulshahed 2016, grey neural network thermal model, Fig. 9): the target
//  (displacement) against one sensor, one line per
//    heating or cooling run of the hysteresis analysis (core/thermal/hysteresis.h), heating and
//    cooling in the hues of the trend chart's phase bands (thermalPhaseColor), saturated so that a
//    line is visible: thermalPhaseLineColor. A run of rows [first, last] is drawn through the first
//    row of the next run, so the loop is closed where the phase changes.
//  * Model comparison (Fig. 10-14): measured and the three models' outputs against time, the
//    boundary between the fitted and the held-out rows as a vertical line, the held-out part shaded.
//  * Residuals: measured - model for each model against time, same boundary.
//  * Training: the best fitness of Eq. 2.9 against the PSO iteration (log scale).
#include <QColor>
#include <QString>
#include <cstddef>
#include <vector>

#include "core/study/thermal_comparison.h"
#include "core/study/trend_analysis.h"

QT_BEGIN_NAMESPACE
class QChart;
QT_END_NAMESPACE

namespace metrofit {

/// Line colour of a phase: the hue of thermalPhaseColor(kind), saturation 210, value 210.
QColor thermalPhaseLineColor(ThermalPhaseKind kind);
/// Colour of a model's line (palette::modelGnnmci/modelGmc/modelMlp; measured: palette::measured()).
QColor thermalModelColor(thermal::ThermalModelKind kind);
/// "GNNMCI(1,N)", "GMC(1,N)", "MLP".
QString thermalModelName(thermal::ThermalModelKind kind);

/// Rows of one drawn run: first..last plus the first row of the next run (when there is one),
/// thinned to every `stride`-th row with the run's ends kept.
std::vector<std::size_t> hysteresisRunRows(const PhaseRun& run, std::size_t rows, std::size_t stride = 1);

struct HysteresisChartOptions {
  int maxPoints = 2000;  ///< rows are thinned to about this many points per chart
  bool legend = true;
  bool compactTitle = false;  ///< sensor name and lag only (small multiples)
};

/// Target against input `input` of `series` (an index into series.inputs), coloured by the phases of
/// `analysis`. Axis titles carry the units of `log`'s channels. Caller owns the chart.
QChart* makeHysteresisChart(const ThermalLog& log, const thermal::ThermalSeries& series,
                            const thermal::HysteresisAnalysis& analysis, int input,
                            const HysteresisChartOptions& options = {});

struct ModelChartOptions {
  QString title;
  int maxPointsPerSeries = 2000;
  bool legend = true;
};

/// Measured and predicted target against time (see above); models that were not fitted (a cancelled
/// comparison) are left out. Time in h above 3 h, else min.
QChart* makeModelComparisonChart(const ThermalLog& log, const ThermalComparison& comparison,
                                 const ModelChartOptions& options = {});
/// Residuals (measured - model) against time.
QChart* makeResidualChart(const ThermalLog& log, const ThermalComparison& comparison,
                          const ModelChartOptions& options = {});
/// The combined modular test: measured and the three models' predictions against time.
QChart* makeModularChart(const ThermalLog& testLog, const ModularComparison& modular,
                         const ModelChartOptions& options = {});
/// Best fitness (Eq. 2.9, target units^2) against PSO iteration, log y axis.
QChart* makeTrainingChart(const std::vector<double>& bestPerIteration, const QString& yTitle);

}  // namespace metrofit
