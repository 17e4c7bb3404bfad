// The thermal page's hysteresis runs on a worker (offscreen, the demo project): a click on the tab
// returns at once with nothing shown yet, the result appears when the worker is done and is the
// synchronous analysis exactly; back on the tab nothing is recomputed; showView("hysteresis") (the
// screenshot path) shows the finished charts at once.
#include <gtest/gtest.h>

#include <QSignalSpy>
#include <QTabWidget>
#include <QTest>

#include "app/gui/thermalpage.h"
#include "core/thermal/hysteresis.h"
#include "demo_document_fixture.h"
#include "qtapp.h"
#include "widgets/thermal/thermalhysteresisview.h"

namespace metrofit {
namespace {

const std::vector<std::string> kInputs{"T1", "T2", "T3", "T4"};  // the demo's thermal study

class ThermalPageHysteresisTest : public test::DemoDocumentTest {
 protected:
  ThermalLog demoLog() {
    const DatasetRef* d = document_.project().dataset("thermal_sim");
    return readThermalLog(document_.datasetPath(*d).toStdString());
  }
};

TEST_F(ThermalPageHysteresisTest, TabShowsTheWorkersResultWhenReady) {
  ThermalPage page(&document_);
  ThermalHysteresisView* view = page.hysteresisView();
  QSignalSpy finished(view, &ThermalHysteresisView::analysisFinished);
  page.tabs()->setCurrentIndex(1);
  EXPECT_EQ(view->chartCount(), 0);  // not analysed on the GUI thread
  ASSERT_TRUE(finished.wait(30000));
  ASSERT_EQ(finished.count(), 1);
  EXPECT_TRUE(finished.at(0).at(0).toBool());
  EXPECT_EQ(view->chartCount(), 4);

  ThermalHysteresisView reference;
  ASSERT_TRUE(reference.setLog(demoLog(), "disp_z_um", kInputs));
  ASSERT_EQ(view->analysis().sensors.size(), reference.analysis().sensors.size());
  for (std::size_t i = 0; i < reference.analysis().sensors.size(); ++i) {
    EXPECT_EQ(view->analysis().sensors[i].sensor, reference.analysis().sensors[i].sensor);
    EXPECT_EQ(view->analysis().sensors[i].loopArea, reference.analysis().sensors[i].loopArea);
    EXPECT_EQ(view->analysis().sensors[i].tauMin, reference.analysis().sensors[i].tauMin);
  }

  page.tabs()->setCurrentIndex(0);
  page.tabs()->setCurrentIndex(1);  // same log and settings: shown as it is
  QTest::qWait(100);
  EXPECT_EQ(finished.count(), 1);
  EXPECT_EQ(view->chartCount(), 4);
}

TEST_F(ThermalPageHysteresisTest, ShowViewShowsTheFinishedChartsAtOnce) {
  ThermalPage page(&document_);
  page.showView(QStringLiteral("hysteresis"));
  EXPECT_EQ(page.tabs()->currentIndex(), 1);
  EXPECT_FALSE(page.hysteresisView()->isAnalysing());
  EXPECT_EQ(page.hysteresisView()->chartCount(), 4);
  EXPECT_EQ(page.hysteresisView()->analysis().sensors.size(), 4u);
  EXPECT_TRUE(page.hysteresisView()->errorMessage().isEmpty());
}

}  // namespace
}  // namespace metrofit
