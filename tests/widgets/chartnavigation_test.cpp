// Zoom, pan, reset and the cursor label of the pages' Qt Charts views (widgets/common/chartnavigation.h),
// driven by synthetic wheel, mouse and key events as a user makes them (offscreen).
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QDir>
#include <QKeyEvent>
#include <QLabel>
#include <QLineSeries>
#include <QLocale>
#include <QMouseEvent>
#include <QRubberBand>
#include <QScatterSeries>
#include <QTest>
#include <QValueAxis>
#include <QWheelEvent>
#include <memory>

#include "qtapp.h"
#include "testsupport.h"
#include "widgets/common/chartexport.h"
#include "widgets/common/chartnavigation.h"
#include "widgets/data/datasetview.h"
#include "widgets/thermal/thermaltrendview.h"

namespace metrofit {
namespace {

class ChartNavigationTest : public ::testing::Test {
 protected:
  void SetUp() override {
    chart_ = new QChart;
    series_ = new QLineSeries;
    series_->setName(QStringLiteral("spindle"));
    for (int i = 0; i <= 100; ++i) series_->append(i * 0.5, 10.0 + 0.1 * i);  // 0 .. 50 min, 10 .. 20 µm
    chart_->addSeries(series_);
    x_ = new QValueAxis;
    x_->setTitleText(QStringLiteral("time (min)"));
    x_->setRange(0.0, 50.0);
    y_ = new QValueAxis;
    y_->setTitleText(QStringLiteral("displacement (µm)"));
    y_->setRange(10.0, 20.0);
    chart_->addAxis(x_, Qt::AlignBottom);
    chart_->addAxis(y_, Qt::AlignLeft);
    series_->attachAxis(x_);
    series_->attachAxis(y_);
    view_ = std::make_unique<QChartView>(chart_);
    view_->resize(640, 420);
    enableChartExport(view_.get(), QStringLiteral("test"));
    enableChartNavigation(view_.get());
    enableChartNavigation(view_.get());  // twice changes nothing
    view_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(view_.get()));
    QApplication::processEvents();
  }

  QWidget* viewport() const { return view_->viewport(); }
  /// The viewport position of a value of the series.
  QPoint at(double x, double y) const {
    return view_->mapFromScene(chart_->mapToScene(chart_->mapToPosition(QPointF(x, y), series_)));
  }
  void wheel(const QPoint& pos, int delta, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    QWheelEvent e(QPointF(pos), QPointF(viewport()->mapToGlobal(pos)), QPoint(), QPoint(0, delta),
                  Qt::NoButton, modifiers, Qt::NoScrollPhase, false);
    QApplication::sendEvent(viewport(), &e);
  }
  void mouse(QEvent::Type type, const QPoint& pos, Qt::MouseButton button, Qt::MouseButtons buttons,
             Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    QMouseEvent e(type, QPointF(pos), QPointF(viewport()->mapToGlobal(pos)), button, buttons, modifiers);
    QApplication::sendEvent(viewport(), &e);
  }
  void drag(const QPoint& from, const QPoint& to, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    mouse(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton, modifiers);
    mouse(QEvent::MouseMove, (from + to) / 2, Qt::NoButton, Qt::LeftButton, modifiers);
    mouse(QEvent::MouseMove, to, Qt::NoButton, Qt::LeftButton, modifiers);
    mouse(QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton, modifiers);
  }

  QChart* chart_ = nullptr;
  QLineSeries* series_ = nullptr;
  QValueAxis* x_ = nullptr;
  QValueAxis* y_ = nullptr;
  std::unique_ptr<QChartView> view_;
};

TEST_F(ChartNavigationTest, WheelZoomsAroundTheCursorAndResetRestores) {
  EXPECT_TRUE(hasChartNavigation(view_.get()));
  EXPECT_FALSE(isChartZoomed(view_.get()));
  const QPoint cursor = at(20.0, 14.0);
  wheel(cursor, 120);  // one notch in
  EXPECT_TRUE(isChartZoomed(view_.get()));
  EXPECT_NEAR(x_->max() - x_->min(), 50.0 / 1.25, 0.5);
  EXPECT_NEAR(y_->max() - y_->min(), 10.0 / 1.25, 0.1);
  // The value under the cursor stays where it was.
  EXPECT_LT(x_->min(), 20.0);
  EXPECT_GT(x_->max(), 20.0);
  EXPECT_NEAR(x_->min(), 20.0 - 20.0 / 1.25, 0.5);
  EXPECT_NEAR(y_->min(), 14.0 - 4.0 / 1.25, 0.1);

  wheel(cursor, -240);  // two notches out: wider than at the start
  EXPECT_GT(x_->max() - x_->min(), 50.0);

  // Shift + wheel zooms the time axis only.
  ASSERT_TRUE(resetChartZoom(view_.get()));
  wheel(cursor, 120, Qt::ShiftModifier);
  EXPECT_NEAR(x_->max() - x_->min(), 40.0, 0.5);
  EXPECT_DOUBLE_EQ(y_->min(), 10.0);
  EXPECT_DOUBLE_EQ(y_->max(), 20.0);

  // A double click shows the whole chart again.
  mouse(QEvent::MouseButtonDblClick, cursor, Qt::LeftButton, Qt::LeftButton);
  EXPECT_DOUBLE_EQ(x_->min(), 0.0);
  EXPECT_DOUBLE_EQ(x_->max(), 50.0);
  EXPECT_DOUBLE_EQ(y_->min(), 10.0);
  EXPECT_DOUBLE_EQ(y_->max(), 20.0);
  EXPECT_FALSE(isChartZoomed(view_.get()));

  // So does the Home key, and the context menu's entry.
  wheel(cursor, 120);
  QKeyEvent home(QEvent::KeyPress, Qt::Key_Home, Qt::NoModifier);
  QApplication::sendEvent(view_.get(), &home);
  EXPECT_DOUBLE_EQ(x_->max(), 50.0);
  wheel(cursor, 120);
  QAction* reset = nullptr;
  for (QAction* a : view_->actions())
    if (a->objectName() == QLatin1String("chartResetZoom")) reset = a;
  ASSERT_NE(reset, nullptr);
  reset->trigger();
  EXPECT_DOUBLE_EQ(x_->min(), 0.0);
  EXPECT_DOUBLE_EQ(y_->max(), 20.0);
}

TEST_F(ChartNavigationTest, LeftDragPansAndShiftDragZoomsIntoTheRectangle) {
  // Dragging the plot to the right shows earlier times; up shows larger values.
  const QPoint from = at(25.0, 15.0);
  const QPoint to = at(20.0, 14.0);  // 5 min to the left, 1 µm down
  drag(to, from);
  EXPECT_NEAR(x_->min(), -5.0, 0.2);
  EXPECT_NEAR(x_->max(), 45.0, 0.2);
  EXPECT_NEAR(y_->min(), 9.0, 0.05);
  EXPECT_NEAR(y_->max(), 19.0, 0.05);
  EXPECT_DOUBLE_EQ(x_->max() - x_->min(), 50.0);
  ASSERT_TRUE(resetChartZoom(view_.get()));
  EXPECT_DOUBLE_EQ(x_->min(), 0.0);

  // Shift + drag: the rubber band's rectangle fills the plot.
  drag(at(10.0, 18.0), at(30.0, 12.0), Qt::ShiftModifier);
  EXPECT_NEAR(x_->min(), 10.0, 0.3);
  EXPECT_NEAR(x_->max(), 30.0, 0.3);
  EXPECT_NEAR(y_->min(), 12.0, 0.1);
  EXPECT_NEAR(y_->max(), 18.0, 0.1);
  for (const QRubberBand* band : viewport()->findChildren<QRubberBand*>()) EXPECT_TRUE(band->isHidden());
}

TEST_F(ChartNavigationTest, TheCursorLabelShowsTheNearestPointInTheUiLanguage) {
  const QLocale previous;
  QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
  // Next to the point (12.5 min, 12.5 µm; the next ones are 5 px away): the label names it with a
  // decimal comma and the units.
  mouse(QEvent::MouseMove, at(12.5, 12.5) + QPoint(1, -1), Qt::NoButton, Qt::NoButton);
  auto* label = viewport()->findChild<QLabel*>(QStringLiteral("chartCursorLabel"));
  ASSERT_NE(label, nullptr);
  EXPECT_TRUE(label->isVisible());
  EXPECT_EQ(chartCursorText(view_.get()).toStdString(), "spindle\ntime: 12,5 min\ndisplacement: 12,5 µm");
  EXPECT_TRUE(viewport()->rect().contains(label->geometry()));
  // A picture to look at: the label beside the cursor, the ring on the point.
  view_->grab().save(QDir(QString::fromStdString(test::outDir().string()))
                         .filePath(QStringLiteral("chartnavigation-cursor-label.png")));
  // After a zoom, the point nearest to the cursor is still found in the zoomed range.
  wheel(at(40.0, 18.0), 360);
  mouse(QEvent::MouseMove, at(40.0, 18.0), Qt::NoButton, Qt::NoButton);
  EXPECT_EQ(chartCursorText(view_.get()).toStdString(), "spindle\ntime: 40 min\ndisplacement: 18 µm");
  // Outside the plot area, and after leaving the view, there is no label.
  mouse(QEvent::MouseMove, QPoint(2, 2), Qt::NoButton, Qt::NoButton);
  EXPECT_TRUE(chartCursorText(view_.get()).isEmpty());
  mouse(QEvent::MouseMove, at(40.0, 18.0), Qt::NoButton, Qt::NoButton);
  QEvent leave(QEvent::Leave);
  QApplication::sendEvent(viewport(), &leave);
  EXPECT_TRUE(chartCursorText(view_.get()).isEmpty());
  QLocale::setDefault(previous);
}

TEST_F(ChartNavigationTest, ARangeSetForNewDataIsTheNewWholeChart) {
  wheel(at(25.0, 15.0), 120);
  ASSERT_TRUE(isChartZoomed(view_.get()));
  // The page shows new data: its range replaces the one from before the zoom.
  x_->setRange(0.0, 100.0);
  EXPECT_FALSE(isChartZoomed(view_.get()));
  EXPECT_FALSE(resetChartZoom(view_.get()));
  EXPECT_DOUBLE_EQ(x_->max(), 100.0);
  // A new chart in the view: navigation acts on it.
  auto* chart = new QChart;
  auto* points = new QScatterSeries;
  points->append(1.0, 2.0);
  points->append(3.0, 4.0);
  chart->addSeries(points);
  chart->createDefaultAxes();
  QChart* old = view_->chart();
  view_->setChart(chart);
  delete old;
  chart_ = nullptr;
  QApplication::processEvents();
  const auto* x = qobject_cast<QValueAxis*>(chart->axes(Qt::Horizontal).first());
  const double width = x->max() - x->min();
  const QPoint centre = view_->mapFromScene(chart->mapToScene(chart->plotArea().center()));
  wheel(centre, 120);
  EXPECT_NEAR(x->max() - x->min(), width / 1.25, 1e-6 * width);
  EXPECT_TRUE(resetChartZoom(view_.get()));
  EXPECT_NEAR(x->max() - x->min(), width, 1e-9);
}

TEST(ChartNavigation, TheThermalTrendChartHasIt) {
  ThermalTrendView trend;
  const auto views = trend.findChildren<QChartView*>();
  ASSERT_FALSE(views.isEmpty());
  for (QChartView* v : views) EXPECT_TRUE(hasChartNavigation(v));
}

TEST(ChartNavigation, TheDatasetPlotHasIt) {
  DatasetView view;
  const auto views = view.findChildren<QChartView*>();
  ASSERT_FALSE(views.isEmpty());
  for (QChartView* v : views) EXPECT_TRUE(hasChartNavigation(v));
}

}  // namespace
}  // namespace metrofit
