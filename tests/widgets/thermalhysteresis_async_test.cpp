// ThermalHysteresisView::analyseLater (the thermal page's hysteresis off the GUI thread): the view says
// it is analysing, shows exactly what the synchronous setLog shows when the worker is done, drops a
// result a later request replaced, and finishAnalysis shows a pending result at once (the
// screenshot path). Offscreen.
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>
#include <QThreadPool>

#include "core/sim/thermal_sim.h"
#include "core/thermal/hysteresis.h"
#include "qtapp.h"
#include "widgets/thermal/thermalhysteresisview.h"

namespace metrofit {
namespace {

const std::vector<std::string> kInputs{"T1", "T2", "T3", "T4"};

void expectSameAnalysis(const thermal::HysteresisAnalysis& a, const thermal::HysteresisAnalysis& b) {
  EXPECT_EQ(a.target, b.target);
  EXPECT_EQ(a.heatingRows, b.heatingRows);
  EXPECT_EQ(a.coolingRows, b.coolingRows);
  ASSERT_EQ(a.sensors.size(), b.sensors.size());
  for (std::size_t i = 0; i < a.sensors.size(); ++i) {
    EXPECT_EQ(a.sensors[i].sensor, b.sensors[i].sensor);
    EXPECT_EQ(a.sensors[i].loopArea, b.sensors[i].loopArea);
    EXPECT_EQ(a.sensors[i].tauMin, b.sensors[i].tauMin);
  }
}

TEST(ThermalHysteresisAsync, WorkerShowsWhatTheSynchronousAnalysisShows) {
  const ThermalLog log = simulateThermalTest({});
  ThermalHysteresisView reference;
  ASSERT_TRUE(reference.setLog(log, "disp_z_um", kInputs));

  ThermalHysteresisView view;
  view.resize(1000, 700);
  QSignalSpy finished(&view, &ThermalHysteresisView::analysisFinished);
  view.analyseLater(log, "disp_z_um", kInputs);
  EXPECT_EQ(view.chartCount(), 0);  // nothing shown until the worker is done
  auto* table = view.findChild<QTableWidget*>(QStringLiteral("hysteresisTable"));
  ASSERT_NE(table, nullptr);
  EXPECT_EQ(table->rowCount(), 0);
  ASSERT_TRUE(finished.count() > 0 || finished.wait(20000));
  ASSERT_EQ(finished.count(), 1);
  EXPECT_TRUE(finished.at(0).at(0).toBool());
  EXPECT_FALSE(view.isAnalysing());
  EXPECT_EQ(view.chartCount(), 4);
  EXPECT_EQ(table->rowCount(), 4);
  expectSameAnalysis(view.analysis(), reference.analysis());
}

TEST(ThermalHysteresisAsync, ALaterRequestReplacesAPendingOne) {
  const ThermalLog log = simulateThermalTest({});
  ThermalHysteresisView view;
  QSignalSpy finished(&view, &ThermalHysteresisView::analysisFinished);
  view.analyseLater(log, "disp_z_um", kInputs);
  view.analyseLater(log, "disp_z_um", {"T2", "T3"});
  ASSERT_TRUE(finished.count() > 0 || finished.wait(20000));
  QThreadPool::globalInstance()->waitForDone();
  QCoreApplication::processEvents();
  EXPECT_EQ(finished.count(), 1);
  EXPECT_EQ(view.chartCount(), 2);
  ASSERT_EQ(view.analysis().sensors.size(), 2u);
  EXPECT_EQ(view.analysis().sensors[0].sensor, "T2");

  // A synchronous setLog replaces a pending analysis too: its result is never shown.
  view.analyseLater(log, "disp_z_um", kInputs);
  ASSERT_TRUE(view.setLog(log, "disp_z_um", {"T4"}));
  QThreadPool::globalInstance()->waitForDone();
  QCoreApplication::processEvents();
  EXPECT_EQ(finished.count(), 1);
  EXPECT_EQ(view.chartCount(), 1);
  ASSERT_EQ(view.analysis().sensors.size(), 1u);
  EXPECT_EQ(view.analysis().sensors[0].sensor, "T4");
}

TEST(ThermalHysteresisAsync, FinishAnalysisShowsThePendingResultNowAndErrorsToo) {
  const ThermalLog log = simulateThermalTest({});
  ThermalHysteresisView view;
  view.analyseLater(log, "disp_z_um", kInputs);
  EXPECT_TRUE(view.finishAnalysis());
  EXPECT_EQ(view.chartCount(), 4);
  EXPECT_TRUE(view.finishAnalysis());  // nothing pending: the result shown
  ThermalLog flat = log;
  for (double& v : flat.channels[static_cast<std::size_t>(flat.indexOf("T1"))].values) v = 20.0;
  view.analyseLater(flat, "disp_z_um", {"T1"});
  EXPECT_FALSE(view.finishAnalysis());
  EXPECT_FALSE(view.errorMessage().isEmpty());
  EXPECT_EQ(view.chartCount(), 0);
}

}  // namespace
}  // namespace metrofit
