// Training the thermal models with applied effects (each model fitted with and without them, the two
// fits at once: core/diagnose/thermal_applied.h fitDeclaredAndWithEffects) in the model view's
// worker gives the synchronous training's results bit for bit, and Cancel stops it. Offscreen.
#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/study/thermal_comparison.h"
#include "core/thermal/thermal_data.h"
#include "qtapp.h"
#include "testsupport.h"
#include "widgets/thermal/thermalmodelview.h"

namespace metrofit {
namespace {

ThermalLog demoLog() {
  return readThermalLog((test::sourceDir() / "resources/demo/data/diagnose_thermal.csv").string());
}

ThermalModelSettings appliedSettings() {
  ThermalModelSettings s;
  s.target = "disp_z_um";
  s.inputs = {"T2", "T4", "T_amb"};
  s.trainFraction = 0.5;
  s.seed = 1;
  s.applied =
      nlohmann::json::parse(R"([{"name": "lag:T2", "parameters": {"tau_min": 15.0}}, {"name": "drift"}])");
  return s;
}

TEST(ThermalAppliedTraining, WorkerGivesTheSynchronousResultsBitForBit) {
  const ThermalLog log = demoLog();
  ThermalModelView worker;
  worker.setLog(log, appliedSettings());
  QSignalSpy finished(&worker, &ThermalModelView::trainingFinished);
  worker.train();
  ASSERT_TRUE(worker.isRunning());
  ASSERT_TRUE(finished.wait(120000));
  ASSERT_TRUE(finished.at(0).at(0).toBool());
  ASSERT_NE(worker.comparison(), nullptr);

  ThermalModelView now;
  now.setLog(log, appliedSettings());
  ASSERT_TRUE(now.trainNow());
  const ThermalComparison& a = *worker.comparison();
  const ThermalComparison& b = *now.comparison();
  EXPECT_EQ(a.appliedText, "lag:T2 (15 min), drift");
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(a.models[i].predicted, b.models[i].predicted) << i;
    EXPECT_EQ(a.usesApplied[i], b.usesApplied[i]) << i;
    EXPECT_EQ(a.declaredHeldoutRmse[i], b.declaredHeldoutRmse[i]) << i;
    EXPECT_EQ(a.appliedHeldoutRmse[i], b.appliedHeldoutRmse[i]) << i;
  }
  // Both variants of every model were fitted.
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_TRUE(std::isfinite(a.declaredHeldoutRmse[i])) << i;
    EXPECT_TRUE(std::isfinite(a.appliedHeldoutRmse[i])) << i;
  }
}

TEST(ThermalAppliedTraining, CancelStopsTheTraining) {
  ThermalModelView view;
  view.setLog(demoLog(), appliedSettings());
  QSignalSpy finished(&view, &ThermalModelView::trainingFinished);
  view.train();
  view.cancel();
  ASSERT_TRUE(finished.count() > 0 || finished.wait(120000));
  EXPECT_FALSE(finished.at(0).at(0).toBool());
  EXPECT_FALSE(view.isRunning());
  EXPECT_EQ(view.comparison(), nullptr);  // nothing trained before: no results shown
}

}  // namespace
}  // namespace metrofit
