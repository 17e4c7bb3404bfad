// Hysteresis and model-comparison charts (widgets/thermal/thermalmodelcharts.h), the hysteresis view and
// the Qt-free helpers behind them (thermal_comparison.h).
#include <QAreaSeries>
#include <QChart>
#include <QChartView>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QTableWidget>
#include <QTest>
#include <QValueAxis>

#include <cmath>
#include <memory>

#include "core/common/error.h"
#include "core/sim/thermal_sim.h"
#include "core/study/thermal_comparison.h"
#include "core/thermal/hysteresis.h"
#include "core/thermal/thermal_data.h"
#include "qtapp.h"
#include "testsupport.h"
#include "widgets/thermal/thermalcharts.h"
#include "widgets/thermal/thermalhysteresisview.h"
#include "widgets/thermal/thermalmodelcharts.h"

namespace metrofit {
namespace {

/// A log that heats for 60 min and cools for 60 min: sensor S follows the heat source quickly, the
/// displacement lags it (first-order, 8 min), so the loop opens.
ThermalLog loopLog() {
  ThermalLog log;
  log.source = "loop.csv";
  log.timeColumn = "time_min";
  ThermalChannel s{"T1", "degC", {}}, y{"disp_z_um", "um", {}};
  double lag = 0.0;
  for (int k = 0; k <= 120; ++k) {
    const double t = k;
    const double source = k <= 60 ? 10.0 * (1.0 - std::exp(-t / 15.0))
                                  : 10.0 * (1.0 - std::exp(-60.0 / 15.0)) * std::exp(-(t - 60.0) / 15.0);
    lag += (1.0 - std::exp(-1.0 / 8.0)) * (source - lag);
    log.timeMin.push_back(t);
    s.values.push_back(20.0 + source);
    y.values.push_back(-3.0 * lag);
  }
  log.channels = {s, y};
  return log;
}

/// Line series named `name` (or "<name> (off scale)", as an unstable grey model is named).
std::vector<QLineSeries*> lines(QChart* chart, const QString& name) {
  std::vector<QLineSeries*> out;
  for (QAbstractSeries* s : chart->series()) {
    auto* l = qobject_cast<QLineSeries*>(s);
    if (l && (l->name() == name || l->name() == name + QStringLiteral(" (off scale)"))) out.push_back(l);
  }
  return out;
}

TEST(ThermalModelCharts, PhaseRunsAndRowsOfEachRun) {
  const std::vector<PhaseRun> runs = phaseRuns({1, 1, 1, -1, -1, 1});
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_EQ(runs[0].phase, 1);
  EXPECT_EQ(runs[0].first, 0u);
  EXPECT_EQ(runs[0].last, 2u);
  EXPECT_EQ(runs[1].phase, -1);
  EXPECT_EQ(runs[1].first, 3u);
  EXPECT_EQ(runs[1].last, 4u);
  EXPECT_EQ(runs[2].first, 5u);
  // Each run is drawn through the first row of the next one, so the loop has no gap.
  EXPECT_EQ(hysteresisRunRows(runs[0], 6), (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_EQ(hysteresisRunRows(runs[1], 6), (std::vector<std::size_t>{3, 4, 5}));
  EXPECT_EQ(hysteresisRunRows(runs[2], 6), (std::vector<std::size_t>{5}));
  // Thinned: every 2nd row, the ends kept.
  EXPECT_EQ(hysteresisRunRows({1, 0, 6}, 10, 2), (std::vector<std::size_t>{0, 2, 4, 6, 7}));
  EXPECT_TRUE(phaseRuns({}).empty());
}

TEST(ThermalModelCharts, HysteresisSeriesSplitAtThePhaseChangeInTheTrendColours) {
  const ThermalLog log = loopLog();
  const thermal::ThermalSeries s = thermal::selectThermalSeries(log, "disp_z_um", {"T1"});
  const thermal::HysteresisAnalysis a = thermal::analyseHysteresis(s);
  // The displacement's change grows while heating, shrinks while cooling: one run each.
  const std::vector<PhaseRun> runs = phaseRuns(a.phase);
  ASSERT_EQ(runs.size(), 2u);
  ASSERT_EQ(runs[0].phase, 1);
  const std::size_t split = runs[1].first;
  // The phases come from the displacement smoothed over 10 min (hysteresis.h): the change starts
  // shrinking near the end of heating (t = 60 min).
  EXPECT_GT(split, 50u);
  EXPECT_LT(split, 85u);

  std::unique_ptr<QChart> chart(makeHysteresisChart(log, s, a, 0));
  const auto heating = lines(chart.get(), QStringLiteral("heating"));
  const auto cooling = lines(chart.get(), QStringLiteral("cooling"));
  ASSERT_EQ(heating.size(), 1u);
  ASSERT_EQ(cooling.size(), 1u);
  // Heating: rows 0..split (through the first cooling row); cooling: rows split..120.
  ASSERT_EQ(heating[0]->count(), static_cast<int>(split) + 1);
  ASSERT_EQ(cooling[0]->count(), static_cast<int>(121 - split));
  EXPECT_EQ(heating[0]->at(0), QPointF(log.channels[0].values[0], log.channels[1].values[0]));
  EXPECT_EQ(heating[0]->points().back(),
            QPointF(log.channels[0].values[split], log.channels[1].values[split]));
  EXPECT_EQ(cooling[0]->at(0), heating[0]->points().back());
  EXPECT_EQ(cooling[0]->points().back(), QPointF(log.channels[0].values[120], log.channels[1].values[120]));
  // Colours: the hues of the trend chart's phase bands.
  EXPECT_EQ(heating[0]->pen().color(), thermalPhaseLineColor(ThermalPhaseKind::Heating));
  EXPECT_EQ(cooling[0]->pen().color(), thermalPhaseLineColor(ThermalPhaseKind::Cooling));
  EXPECT_EQ(heating[0]->pen().color().hsvHue(), thermalPhaseColor(ThermalPhaseKind::Heating).hsvHue());
  EXPECT_EQ(cooling[0]->pen().color().hsvHue(), thermalPhaseColor(ThermalPhaseKind::Cooling).hsvHue());
  EXPECT_NE(heating[0]->pen().color(), cooling[0]->pen().color());
  // Axes carry the units.
  const auto x = chart->axes(Qt::Horizontal);
  const auto y = chart->axes(Qt::Vertical);
  ASSERT_EQ(x.size(), 1);
  ASSERT_EQ(y.size(), 1);
  EXPECT_EQ(qobject_cast<QValueAxis*>(x[0])->titleText(), QStringLiteral("T1 (°C)"));
  EXPECT_EQ(qobject_cast<QValueAxis*>(y[0])->titleText(), QStringLiteral("disp_z_um (µm)"));
  EXPECT_TRUE(chart->title().contains(QStringLiteral("lag"))) << chart->title().toStdString();
}

TEST(ThermalModelCharts, ManyRunsHaveOneLegendEntryPerPhase) {
  thermal::ThermalSeries s;
  s.targetName = "y";
  s.inputNames = {"x"};
  s.inputs = {{}};
  thermal::HysteresisAnalysis a;
  a.target = "y";
  for (int k = 0; k < 40; ++k) {
    s.timeMin.push_back(k);
    s.target.push_back(std::sin(k * 0.3));
    s.inputs[0].push_back(std::cos(k * 0.3));
    a.phase.push_back((k / 5) % 2 == 0 ? 1 : -1);
  }
  a.sensors.push_back({});
  a.sensors[0].sensor = "x";
  ThermalLog log;
  QChartView view(makeHysteresisChart(log, s, a, 0));
  view.resize(500, 400);
  view.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
  QChart* chart = view.chart();
  EXPECT_EQ(lines(chart, QStringLiteral("heating")).size(), 4u);
  EXPECT_EQ(lines(chart, QStringLiteral("cooling")).size(), 4u);
  QStringList visible;
  for (QLegendMarker* m : chart->legend()->markers()) {
    if (m->isVisible()) visible << m->label();
  }
  EXPECT_EQ(visible, (QStringList{QStringLiteral("heating"), QStringLiteral("cooling")}));
}

TEST(ThermalModelCharts, ComparisonChartMarksTheFitBoundary) {
  ThermalSimOptions so;
  so.durationMin = 240.0;
  const ThermalLog log = simulateThermalTest(so);
  ThermalModelSettings settings;
  settings.target = "disp_z_um";
  settings.inputs = {"T1", "T2"};
  settings.trainFraction = 0.6;
  const ThermalComparison c = compareThermalModels(log, settings);
  ASSERT_FALSE(c.cancelled);
  EXPECT_EQ(c.models[0].fitRows, 145u);  // round(0.6 * 241)
  std::unique_ptr<QChart> chart(makeModelComparisonChart(log, c));
  const auto boundary = lines(chart.get(), QStringLiteral("fit | held-out boundary"));
  ASSERT_EQ(boundary.size(), 1u);
  // The band's "held out" entry explains the line: no legend entry of its own (one entry fewer, so
  // the legend row is not elided).
  for (QLegendMarker* marker : chart->legend()->markers(boundary[0])) EXPECT_FALSE(marker->isVisible());
  // 4 h: the time axis is in hours.
  EXPECT_DOUBLE_EQ(boundary[0]->at(0).x(), 0.5 * (log.timeMin[144] + log.timeMin[145]) / 60.0);
  EXPECT_EQ(lines(chart.get(), QStringLiteral("measured")).size(), 1u);
  for (auto kind : kThermalModelOrder) {
    const auto l = lines(chart.get(), thermalModelName(kind));
    ASSERT_EQ(l.size(), 1u) << thermalModelName(kind).toStdString();
    EXPECT_EQ(l[0]->pen().color(), thermalModelColor(kind));
  }
  std::unique_ptr<QChart> residuals(makeResidualChart(log, c));
  const auto g = lines(residuals.get(), QStringLiteral("GNNMCI(1,N)"));
  ASSERT_EQ(g.size(), 1u);
  // Residual = measured - predicted at the first row: 0 for a grey model (it starts from y(1)).
  EXPECT_DOUBLE_EQ(g[0]->at(0).y(), 0.0);
}

TEST(ThermalComparisonHelpers, DefaultSettingsAndDecimation) {
  const ThermalLog log = simulateThermalTest({});
  // The project's study for its dataset; otherwise the largest displacement and the temperatures.
  const nlohmann::json study = {
      {"dataset", "sim"}, {"target", "disp_z_um"}, {"inputs", {"T1", "T3"}}, {"train_fraction", 0.6}};
  ThermalModelSettings s = defaultThermalModelSettings(log, study, "sim");
  EXPECT_EQ(s.target, "disp_z_um");
  EXPECT_EQ(s.inputs, (std::vector<std::string>{"T1", "T3"}));
  EXPECT_EQ(s.trainFraction, 0.6);
  s = defaultThermalModelSettings(log, study, "other");
  EXPECT_EQ(s.target, "disp_z_um");
  EXPECT_EQ(s.inputs, (std::vector<std::string>{"T1", "T2", "T3", "T4"}));  // T_amb left out
  EXPECT_EQ(s.trainFraction, 0.5);
  // The study's own log: a bad value is refused naming the field, not replaced by a default.
  for (const auto& [key, value] : std::vector<std::pair<std::string, nlohmann::json>>{
           {"train_fraction", 1.5}, {"target", "disp_x_um"}, {"inputs", {"T1", "T9"}}, {"seed", -1}}) {
    nlohmann::json bad = study;
    bad[key] = value;
    try {
      (void)defaultThermalModelSettings(log, bad, "sim");
      ADD_FAILURE() << key << " was not refused";
    } catch (const ValidationError& e) {
      EXPECT_EQ(e.context().field, "studies.thermal." + key) << e.what();
    }
  }

  const ThermalLog d = decimateThermalLog(log, 4);
  ASSERT_EQ(d.rows(), 121u);  // rows 0, 4, ..., 480
  EXPECT_EQ(d.timeMin[1], log.timeMin[4]);
  EXPECT_EQ(d.channels[2].values[120], log.channels[2].values[480]);
  EXPECT_EQ(decimateThermalLog(log, 1).rows(), log.rows());
  const ThermalLog odd = decimateThermalLog(log, 7);  // the last row is always kept
  EXPECT_EQ(odd.timeMin.back(), log.timeMin.back());
}

TEST(ThermalHysteresisView, AllSensorsOrOneAndTheTable) {
  const ThermalLog log = simulateThermalTest({});
  ThermalHysteresisView view;
  view.resize(1000, 700);
  ASSERT_TRUE(view.setLog(log, "disp_z_um", {"T1", "T2", "T3", "T4"}));
  EXPECT_EQ(view.chartCount(), 4);
  EXPECT_TRUE(view.sensor().isEmpty());
  auto* table = view.findChild<QTableWidget*>(QStringLiteral("hysteresisTable"));
  ASSERT_NE(table, nullptr);
  ASSERT_EQ(table->rowCount(), 4);
  EXPECT_EQ(table->item(1, 0)->text(), QStringLiteral("T2"));
  const thermal::SensorHysteresis& t2 = view.analysis().sensors[1];
  EXPECT_EQ(table->item(1, 3)->text(), QString::number(t2.tauMin, 'f', 1));
  EXPECT_EQ(table->item(1, 2)->text(), QString::number(t2.normalisedLoopArea, 'f', 3));
  view.setSensor(QStringLiteral("T2"));
  EXPECT_EQ(view.chartCount(), 1);
  EXPECT_EQ(view.sensor(), QStringLiteral("T2"));
  view.setSensor(QString());
  EXPECT_EQ(view.chartCount(), 4);
  // A constant column is an error shown in the view, not a crash.
  ThermalLog flat = log;
  for (double& v : flat.channels[static_cast<std::size_t>(flat.indexOf("T1"))].values) v = 20.0;
  EXPECT_FALSE(view.setLog(flat, "disp_z_um", {"T1"}));
  EXPECT_FALSE(view.errorMessage().isEmpty());
  EXPECT_EQ(view.chartCount(), 0);
}

}  // namespace
}  // namespace metrofit
