// The shared polish of the views: one palette (widgets/common/palette.h) used by the charts,
// chart export as PNG / SVG / clipboard image (widgets/common/chartexport.h) and tab-separated copying
// from tables with headers (widgets/common/tablecopy.h). Offscreen; images go to $METROFIT_TEST_OUT.
#include <gtest/gtest.h>

#include <QAbstractAxis>
#include <QAction>
#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QClipboard>
#include <QContextMenuEvent>
#include <QDir>
#include <QFile>
#include <QHeaderView>
#include <QImage>
#include <QLegend>
#include <QLineSeries>
#include <QLocale>
#include <QMenu>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QXmlStreamReader>
#include <cmath>
#include <memory>
#include <numbers>

#include "core/sim/thermal_sim.h"
#include "core/study/thermal_comparison.h"
#include "core/thermal/thermal_data.h"
#include "qtapp.h"
#include "testsupport.h"
#include "widgets/common/chartexport.h"
#include "widgets/common/palette.h"
#include "widgets/common/tablecopy.h"
#include "widgets/kinematics/kinematicplots.h"
#include "widgets/kinematics/kinematicsviews.h"
#include "widgets/thermal/thermalcharts.h"
#include "widgets/thermal/thermalmodelcharts.h"
#include "widgets/thermal/thermaltrendview.h"

namespace metrofit {
namespace {

/// A CCW loop on R = 50 mm with a smooth +-5 um two-lobe deviation.
PolarPlotData polarData() {
  PolarPlotData d;
  d.radiusMm = 50.0;
  CircularLoop loop;
  for (int a = 0; a < 360; ++a)
    loop.points.push_back({static_cast<double>(a), 0.005 * std::cos(2.0 * a * std::numbers::pi / 180.0)});
  d.loops.push_back(loop);
  d.magnification = 1000.0;
  d.ringStepMm = 0.005;
  return d;
}

/// Pixels within `tol` (per channel) of colour c in a window around p.
bool colourAround(const QImage& img, QPointF p, const QColor& c, int radius = 1, int tol = 40) {
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      const int x = static_cast<int>(std::lround(p.x())) + dx, y = static_cast<int>(std::lround(p.y())) + dy;
      if (!img.valid(x, y)) continue;
      const QColor q = img.pixelColor(x, y);
      if (std::abs(q.red() - c.red()) <= tol && std::abs(q.green() - c.green()) <= tol &&
          std::abs(q.blue() - c.blue()) <= tol)
        return true;
    }
  return false;
}

QString readAll(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

void saveImage(const QImage& img, const char* name) {
  img.save(QDir(QString::fromStdString(test::outDir().string())).filePath(QString::fromLatin1(name)));
}

// ---- palette ---------------------------------------------------------------------------------------

TEST(Palette, MeasuredIsTheSameColourInThePolarPlotAndInTheThermalModelChart) {
  // Chart 1 (QPainter): the measured CCW loop is drawn in the palette's measured colour.
  EXPECT_EQ(kinematic_colour::counterClockwise(), palette::measured());
  EXPECT_EQ(kinematic_colour::clockwise(), palette::measuredSecond());
  EXPECT_EQ(kinematic_colour::references(), palette::compensated());
  EXPECT_EQ(kinematic_colour::limit(), palette::controlLimit());
  EXPECT_EQ(kinematic_colour::specification(), palette::specLimit());
  PolarDeviationView polar;
  polar.resize(500, 500);
  polar.setData(polarData());
  const QImage img = polar.grab().toImage();
  saveImage(img, "polish-polar.png");
  int hits = 0;
  for (int a = 10; a < 360; a += 30)
    if (colourAround(img, polar.mapToWidget(a, 0.005 * std::cos(2.0 * a * std::numbers::pi / 180.0)),
                     palette::measured()))
      ++hits;
  EXPECT_GE(hits, 11) << "measured loop pixels in the palette colour at 12 angles";

  // Chart 2 (Qt Charts): the measured series of the thermal model comparison has the same colour,
  // the models theirs, the phase bands the palette's heating / cooling fills.
  ThermalSimOptions so;
  so.durationMin = 120.0;
  const ThermalLog log = simulateThermalTest(so);
  ThermalModelSettings settings;
  settings.target = "disp_z_um";
  settings.inputs = {"T1", "T2"};
  settings.trainFraction = 0.6;
  const ThermalComparison c = compareThermalModels(log, settings);
  ASSERT_FALSE(c.cancelled);
  std::unique_ptr<QChart> chart(makeModelComparisonChart(log, c));
  int measured = 0;
  for (QAbstractSeries* s : chart->series()) {
    auto* line = qobject_cast<QLineSeries*>(s);
    if (!line) continue;
    if (line->name() == QLatin1String("measured")) {
      ++measured;
      EXPECT_EQ(line->pen().color(), palette::measured());
    }
    if (line->name() == thermalModelName(thermal::ThermalModelKind::Gnnmci)) {
      EXPECT_EQ(line->pen().color(), palette::modelGnnmci());
    }
    if (line->name() == thermalModelName(thermal::ThermalModelKind::Gmc)) {
      EXPECT_EQ(line->pen().color(), palette::modelGmc());
    }
    if (line->name() == thermalModelName(thermal::ThermalModelKind::Mlp)) {
      EXPECT_EQ(line->pen().color(), palette::modelMlp());
    }
  }
  EXPECT_EQ(measured, 1);
  EXPECT_EQ(thermalPhaseColor(ThermalPhaseKind::Heating), palette::heatingFill());
  EXPECT_EQ(thermalPhaseColor(ThermalPhaseKind::Cooling), palette::coolingFill());
  EXPECT_EQ(thermalPhaseLineColor(ThermalPhaseKind::Heating), palette::heatingLine());
  EXPECT_EQ(thermalPhaseLineColor(ThermalPhaseKind::Cooling), palette::coolingLine());
}

TEST(Palette, SeriesColoursCycleThroughTenDistinctColours) {
  for (int i = 0; i < 10; ++i)
    for (int j = i + 1; j < 10; ++j) EXPECT_NE(palette::series(i), palette::series(j)) << i << " " << j;
  EXPECT_EQ(palette::series(10), palette::series(0));
  EXPECT_EQ(palette::series(-1), palette::series(9));
}

// ---- chart export ----------------------------------------------------------------------------------

QStringList actionNames(const QWidget* w) {
  QStringList names;
  for (const QAction* a : w->actions()) names << a->objectName();
  return names;
}

TEST(ChartExport, PainterChartToPngAndSvg) {
  PolarDeviationView polar;
  polar.resize(420, 380);
  polar.setData(polarData());
  polar.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&polar));
  ASSERT_TRUE(hasChartExport(&polar));
  EXPECT_EQ(polar.contextMenuPolicy(), Qt::ActionsContextMenu);
  // The export entries, then (plotnavigation.h) a separator and "Reset zoom".
  EXPECT_EQ(actionNames(&polar),
            (QStringList{QStringLiteral("chartExportPng"), QStringLiteral("chartExportSvg"),
                         QStringLiteral("chartCopyImage"), QString(), QStringLiteral("plotResetZoom")}));

  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  const QString png = dir.filePath(QStringLiteral("polar.png"));
  QString error;
  ASSERT_TRUE(exportChartPng(&polar, png, &error)) << error.toStdString();
  QImage image(png);
  ASSERT_FALSE(image.isNull());
  EXPECT_EQ(image.size(), QSize(420, 380) * polar.devicePixelRatio());
  int coloured = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (image.pixelColor(x, y) != QColor(Qt::white)) ++coloured;
  EXPECT_GT(coloured, 2000) << "the exported PNG shows the plot, not a blank widget";
  EXPECT_TRUE(colourAround(image,
                           polar.mapToWidget(100.0, 0.005 * std::cos(200.0 * std::numbers::pi / 180.0)),
                           palette::measured(), 2));

  const QString svg = dir.filePath(QStringLiteral("polar.svg"));
  ASSERT_TRUE(exportChartSvg(&polar, svg, &error)) << error.toStdString();
  const QString text = readAll(svg);
  EXPECT_TRUE(text.contains(QLatin1String("<svg"))) << text.left(200).toStdString();
  EXPECT_TRUE(text.contains(QLatin1String("<path")) || text.contains(QLatin1String("<polyline")));
  EXPECT_TRUE(text.contains(QLatin1String("viewBox=\"0 0 420 380\"")));
  QXmlStreamReader xml(text);
  while (!xml.atEnd()) xml.readNext();
  EXPECT_FALSE(xml.hasError()) << xml.errorString().toStdString();

  // "Copy image" puts the same picture on the clipboard.
  QApplication::clipboard()->clear();
  for (QAction* a : polar.actions())
    if (a->objectName() == QLatin1String("chartCopyImage")) a->trigger();
  EXPECT_EQ(QApplication::clipboard()->image().size(), image.size());
}

TEST(ChartExport, QtChartsViewToPngAndSvg) {
  auto* chart = new QChart;
  auto* series = new QLineSeries;
  series->setName(QStringLiteral("measured"));
  for (int i = 0; i < 50; ++i) series->append(i, std::sin(i / 5.0));
  series->setPen(QPen(palette::measured(), 2.0));
  chart->addSeries(series);
  chart->createDefaultAxes();
  QChartView view(chart);
  view.resize(500, 320);
  enableChartExport(&view, QStringLiteral("sine"));
  enableChartExport(&view, QStringLiteral("again"));  // twice changes nothing
  EXPECT_EQ(view.actions().size(), 3);
  view.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
  QTemporaryDir dir;
  const QString png = dir.filePath(QStringLiteral("sine.png")),
                svg = dir.filePath(QStringLiteral("sine.svg"));
  // A right click on the plot opens the menu with the three entries.
  QStringList shown;
  QTimer::singleShot(100, [&shown] {
    if (auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget())) {
      for (const QAction* a : menu->actions()) shown << a->objectName();
      menu->close();
    }
  });
  const QPoint inside = view.viewport()->rect().center();
  QContextMenuEvent event(QContextMenuEvent::Mouse, inside, view.viewport()->mapToGlobal(inside));
  QApplication::sendEvent(view.viewport(), &event);
  EXPECT_EQ(shown, (QStringList{QStringLiteral("chartExportPng"), QStringLiteral("chartExportSvg"),
                                QStringLiteral("chartCopyImage")}));

  // Shown in a view, the chart's numbers follow the user's locale; shortened legend labels get tooltips.
  EXPECT_TRUE(QTest::qWaitFor([chart] { return chart->localizeNumbers(); }, 2000));
  EXPECT_TRUE(chart->legend()->showToolTips());
  ASSERT_TRUE(exportChartPng(&view, png));
  const QImage image(png);
  EXPECT_EQ(image.size(), QSize(500, 320) * view.devicePixelRatio());
  saveImage(image, "polish-chartview.png");
  int blue = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (colourAround(image, QPointF(x, y), palette::measured(), 0, 30)) ++blue;
  EXPECT_GT(blue, 100) << "the measured series is in the exported PNG";
  ASSERT_TRUE(exportChartSvg(&view, svg));
  const QString text = readAll(svg);
  EXPECT_TRUE(text.contains(QLatin1String("<svg")));
  EXPECT_TRUE(text.contains(QLatin1String("<path")) || text.contains(QLatin1String("<polyline")));
  EXPECT_TRUE(text.contains(palette::measured().name(), Qt::CaseInsensitive)) << "the series stays a vector";

  // The tooltip names the point under the mouse with the units of the axis titles.
  chart->axes(Qt::Horizontal).first()->setTitleText(QStringLiteral("time (min)"));
  chart->axes(Qt::Vertical).first()->setTitleText(QStringLiteral("displacement (µm)"));
  QApplication::processEvents();
  const QPointF point(10.0, std::sin(2.0));
  const QPoint pos = view.mapFromScene(chart->mapToScene(chart->mapToPosition(point, series)));
  EXPECT_EQ(chartPointTooltip(&view, pos + QPoint(2, 1)).toStdString(),
            (QStringLiteral("measured\ntime: 10 min\ndisplacement: ") +
             QLocale().toString(std::sin(2.0), 'g', 5) + QStringLiteral(" µm"))
                .toStdString());
  EXPECT_TRUE(chartPointTooltip(&view, QPoint(3, 3)).isEmpty()) << "outside the plot area";
}

TEST(ChartExport, ViewsOfThePagesOfferIt) {
  ThermalTrendView trend;
  const auto views = trend.findChildren<QChartView*>();
  ASSERT_FALSE(views.isEmpty());
  EXPECT_TRUE(hasChartExport(views.first()));
  SpcView spc;
  EXPECT_TRUE(hasChartExport(spc.findChild<HistogramView*>()));
  EXPECT_EQ(spc.findChildren<ControlChartView*>().size(), 2);
  for (const ControlChartView* v : spc.findChildren<ControlChartView*>()) EXPECT_TRUE(hasChartExport(v));
  // The SPC index table copies.
  auto* table = spc.findChild<QTableWidget*>(QStringLiteral("spcIndexTable"));
  ASSERT_NE(table, nullptr);
  EXPECT_TRUE(actionNames(table).contains(QStringLiteral("tableCopy")));
}

// ---- table copy ------------------------------------------------------------------------------------

class TableCopyTest : public ::testing::Test {
 protected:
  void SetUp() override {
    table_.setColumnCount(3);
    table_.setRowCount(3);
    table_.setHorizontalHeaderLabels(
        {QStringLiteral("Id"), QStringLiteral("Value (mm)"), QStringLiteral("Note")});
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        table_.setItem(r, c, new QTableWidgetItem(QStringLiteral("r%1c%2").arg(r).arg(c)));
    table_.item(2, 2)->setText(QStringLiteral("two\tparts\nline"));
    enableTableCopy(&table_);
  }
  QTableWidget table_;
};

TEST_F(TableCopyTest, CtrlCCopiesTheSelectionWithHeaders) {
  table_.show();
  QApplication::setActiveWindow(&table_);
  ASSERT_TRUE(QTest::qWaitForWindowActive(&table_));
  table_.setFocus();
  table_.clearSelection();
  table_.selectionModel()->select(table_.model()->index(0, 0), QItemSelectionModel::Select);
  table_.selectionModel()->select(table_.model()->index(1, 2), QItemSelectionModel::Select);
  QApplication::clipboard()->setText(QStringLiteral("old"));
  QTest::keyClick(&table_, Qt::Key_C, Qt::ControlModifier);
  EXPECT_EQ(QApplication::clipboard()->text().toStdString(), "Id\tNote\nr0c0\t\n\tr1c2\n");
}

TEST_F(TableCopyTest, ContextMenuCopyWithoutSelectionCopiesAllButHiddenColumns) {
  EXPECT_EQ(table_.contextMenuPolicy(), Qt::ActionsContextMenu);
  ASSERT_EQ(table_.actions().size(), 2);
  EXPECT_EQ(table_.actions().first()->shortcut(), QKeySequence(QKeySequence::Copy));
  table_.setColumnHidden(1, true);
  table_.clearSelection();
  table_.actions().first()->trigger();
  EXPECT_EQ(QApplication::clipboard()->text().toStdString(),
            "Id\tNote\nr0c0\tr0c2\nr1c0\tr1c2\nr2c0\ttwo parts line\n");
}

TEST_F(TableCopyTest, WholeRowsInTheOrderShown) {
  table_.setSelectionBehavior(QAbstractItemView::SelectRows);
  table_.horizontalHeader()->moveSection(2, 0);  // Note shown first
  table_.selectRow(1);
  EXPECT_EQ(tableSelectionText(&table_).toStdString(), "Note\tId\tValue (mm)\nr1c2\tr1c0\tr1c1\n");
}

}  // namespace
}  // namespace metrofit
