// The "Show data" view (widgets/data/datasetview.h) and the content it reads
// (core/project/dataset_content.h): a PC-DMIS text report written here from the format's help (the
// example of tests/core/setup/cmm_text_report_test.cpp, one dimension out of tolerance), a CSV CMM
// report series, a German thermal log (';', decimal commas, a title line, mapped columns), the DMIS
// output of the fuzz corpus, a missing file, and the REAL OGP step report
// ../shared/data/real/cmm-ogp-hps-svt/survey_data/meas1/L0_axial_top_module1_1.txt (GPL-3.0, read in
// place as tests/gui/import_dialog_test.cpp does; skipped when it is not there). Offscreen; the
// screenshots go to $METROFIT_TEST_OUT.
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QChartView>
#include <QClipboard>
#include <QComboBox>
#include <QDir>
#include <QElapsedTimer>
#include <QHeaderView>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QSignalSpy>
#include <QSortFilterProxyModel>
#include <QSplitter>
#include <QTableView>
#include <QTest>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

#include "core/project/dataset_content.h"
#include "core/project/project.h"
#include "qtapp.h"
#include "samples/pcdmis_reports.h"
#include "testsupport.h"
#include "widgets/data/datasettablemodel.h"
#include "widgets/data/datasetview.h"

namespace metrofit {
namespace {

const char* const kPcDmis = ::metrofit::test::kPcDmisBracketReport;

QString cell(const DatasetView& view, int row, int column) {
  return view.proxy()->index(row, column).data().toString();
}

QString header(const DatasetView& view, int column) {
  return view.model()->headerData(column, Qt::Horizontal).toString();
}

int columnOf(const DatasetView& view, const QString& name) {
  for (int c = 0; c < view.model()->columnCount(); ++c)
    if (header(view, c) == name) return c;
  return -1;
}

void saveShot(QWidget& w, const char* name) {
  w.resize(1000, 640);
  w.show();
  QApplication::processEvents();
  const QImage img = w.grab().toImage();
  ASSERT_FALSE(img.isNull());
  img.save(QDir(QString::fromStdString(test::outDir().string())).filePath(QString::fromLatin1(name)));
}

DatasetRef datasetOf(const char* kind, const std::string& path) {
  DatasetRef d;
  d.id = "d";
  d.kind = kind;
  d.path = path;
  return d;
}

/// Ctrl+C on the table (the action enableTableCopy adds), then the clipboard's text.
QString copied(const DatasetView& view) {
  QApplication::clipboard()->clear();
  QAction* copy = view.table()->findChild<QAction*>(QStringLiteral("tableCopy"));
  EXPECT_NE(copy, nullptr);
  if (copy) copy->trigger();
  return QApplication::clipboard()->text();
}

class DatasetViewTest : public ::testing::Test {
 protected:
  void SetUp() override { QLocale::setDefault(QLocale::c()); }
  void TearDown() override { QLocale::setDefault(QLocale::c()); }
  test::TempDir dir_;
};

TEST_F(DatasetViewTest, PcDmisReportIsAFeatureTableWithTheOutOfToleranceRowMarked) {
  const std::string file = dir_.file("bracket.txt");
  test::writeText(file, kPcDmis);
  DatasetView view;
  ASSERT_TRUE(view.showDataset(QString::fromStdString(file), datasetOf(dataset_kind::kCmmReport, file)))
      << view.errorText().toStdString();
  EXPECT_TRUE(view.errorText().isEmpty());
  ASSERT_TRUE(view.model()->isFeatureTable());
  ASSERT_EQ(view.model()->rowCount(), 4);
  // One unit for every row: in the headers, no Unit column; no Part column for a single part.
  const QStringList expected{QStringLiteral("Feature"),         QStringLiteral("Characteristic"),
                             QStringLiteral("Nominal [mm]"),    QStringLiteral("Actual [mm]"),
                             QStringLiteral("Deviation [mm]"),  QStringLiteral("Lower tol. [mm]"),
                             QStringLiteral("Upper tol. [mm]"), QStringLiteral("Status")};
  ASSERT_EQ(view.model()->columnCount(), expected.size());
  for (int c = 0; c < expected.size(); ++c) EXPECT_EQ(header(view, c), expected[c]);
  // Row 3 (file order): LOC1 D 18.5 -0.05/+0.03, actual 18.52, in tolerance.
  EXPECT_EQ(cell(view, 2, 0), QStringLiteral("LOC1"));
  EXPECT_EQ(cell(view, 2, 1), QStringLiteral("D"));
  EXPECT_EQ(cell(view, 2, 2), QStringLiteral("18.5"));
  EXPECT_EQ(cell(view, 2, 3), QStringLiteral("18.52"));
  EXPECT_NEAR(view.proxy()->index(2, 4).data(DatasetTableModel::SortRole).toDouble(), 0.02, 1e-12);
  EXPECT_EQ(cell(view, 2, 5), QStringLiteral("-0.05"));
  EXPECT_EQ(cell(view, 2, 6), QStringLiteral("0.03"));
  EXPECT_EQ(cell(view, 2, 7), QStringLiteral("in tolerance"));
  EXPECT_FALSE(view.proxy()->index(2, 7).data(DatasetTableModel::OutOfToleranceRole).toBool());
  // LOC2 Z: 42.035 against 42 +0.02: out of tolerance, in text, icon and colour.
  const QModelIndex oot = view.proxy()->index(3, 7);
  EXPECT_EQ(cell(view, 3, 0), QStringLiteral("LOC2"));
  EXPECT_EQ(oot.data().toString(), QStringLiteral("out of tolerance"));
  EXPECT_TRUE(oot.data(DatasetTableModel::OutOfToleranceRole).toBool());
  EXPECT_FALSE(oot.data(Qt::DecorationRole).isNull());
  EXPECT_TRUE(view.proxy()->index(3, 0).data(Qt::BackgroundRole).value<QColor>().isValid());
  EXPECT_FALSE(view.proxy()->index(0, 0).data(Qt::BackgroundRole).value<QColor>().isValid());
  EXPECT_NE(view.summaryText().indexOf(QStringLiteral("1 out of tolerance")), -1)
      << view.summaryText().toStdString();

  // Sorting by deviation (a header click): -0.004, 0.012, 0.02, 0.035, numerically.
  view.table()->horizontalHeader()->setSortIndicator(4, Qt::AscendingOrder);
  ASSERT_TRUE(view.table()->isSortingEnabled());
  EXPECT_EQ(cell(view, 0, 4), QStringLiteral("-0.004"));
  EXPECT_EQ(cell(view, 1, 4), QStringLiteral("0.012"));
  EXPECT_EQ(cell(view, 2, 4), QStringLiteral("0.02"));
  EXPECT_EQ(cell(view, 3, 4), QStringLiteral("0.035"));
  view.table()->horizontalHeader()->setSortIndicator(4, Qt::DescendingOrder);
  EXPECT_EQ(cell(view, 0, 1), QStringLiteral("Z"));

  // The filter keeps the rows with the text in any cell.
  view.filterEdit()->setText(QStringLiteral("loc1"));
  EXPECT_EQ(view.proxy()->rowCount(), 3);
  view.filterEdit()->setText(QStringLiteral("out of"));
  EXPECT_EQ(view.proxy()->rowCount(), 1);
  EXPECT_NE(view.summaryText().indexOf(QStringLiteral("1 shown")), -1);

  // Ctrl+C with nothing selected: the shown rows with the header, tab-separated.
  EXPECT_EQ(copied(view),
            QStringLiteral("Feature\tCharacteristic\tNominal [mm]\tActual [mm]\tDeviation [mm]\tLower tol. "
                           "[mm]\tUpper tol. [mm]\tStatus\n"
                           "LOC2\tZ\t42\t42.035\t0.035\t-0.02\t0.02\tout of tolerance\n"));
  view.filterEdit()->clear();
  EXPECT_EQ(view.proxy()->rowCount(), 4);
  // A selection: the selected cells' rows and columns only.
  view.table()->horizontalHeader()->setSortIndicator(-1, Qt::AscendingOrder);
  view.proxy()->sort(-1);
  view.table()->selectionModel()->select(view.proxy()->index(0, 0), QItemSelectionModel::Select);
  view.table()->selectionModel()->select(view.proxy()->index(0, 3), QItemSelectionModel::Select);
  EXPECT_EQ(copied(view), QStringLiteral("Feature\tActual [mm]\nLOC1\t25.012\n"));

  // The plot: the deviations against the row number, all rows in file order.
  EXPECT_EQ(view.plotColumnBox()->currentText(), QStringLiteral("Deviation [mm]"));
  const std::vector<QPointF> points = view.plottedPoints();
  ASSERT_EQ(points.size(), 4u);
  const double dev[] = {0.012, -0.004, 0.02, 0.035};
  for (int i = 0; i < 4; ++i) {
    EXPECT_DOUBLE_EQ(points[static_cast<std::size_t>(i)].x(), i + 1.0);
    EXPECT_NEAR(points[static_cast<std::size_t>(i)].y(), dev[i], 1e-12);
  }
  view.setPlot(3);  // Actual
  ASSERT_EQ(view.plottedPoints().size(), 4u);
  EXPECT_DOUBLE_EQ(view.plottedPoints()[3].y(), 42.035);
  saveShot(view, "datasetview-pcdmis.png");
}

TEST_F(DatasetViewTest, CsvCmmReportSeriesMarksTheRowOutsideItsLimits) {
  const std::string file = dir_.file("series.csv");
  test::writeText(file,
                  "part,time_min,dimension,nominal_mm,measured_mm,lower_tol_mm,upper_tol_mm\n"
                  "P1,0,D1,18.5,18.51,-0.02,0.02\n"
                  "P1,0,D2,42,41.97,-0.02,0.02\n"
                  "P2,30,D1,18.5,18.49,-0.02,0.02\n"
                  "P2,30,D2,42,42.001,-0.02,0.02\n");
  DatasetView view;
  ASSERT_TRUE(view.showDataset(QString::fromStdString(file), datasetOf(dataset_kind::kCmmReport, file)));
  ASSERT_EQ(view.model()->rowCount(), 4);
  EXPECT_EQ(header(view, 0), QStringLiteral("Part"));
  EXPECT_EQ(cell(view, 1, 0), QStringLiteral("P1"));
  EXPECT_EQ(cell(view, 1, 1), QStringLiteral("D2"));
  const int status = columnOf(view, QStringLiteral("Status"));
  ASSERT_GE(status, 0);
  for (int r = 0; r < 4; ++r)
    EXPECT_EQ(view.model()->outOfTolerance(r), r == 1) << "row " << r;  // -0.03 < -0.02
  EXPECT_EQ(cell(view, 1, status), QStringLiteral("out of tolerance"));
  EXPECT_EQ(cell(view, 3, status), QStringLiteral("in tolerance"));
  EXPECT_NEAR(view.model()->number(1, columnOf(view, QStringLiteral("Deviation [mm]"))), -0.03, 1e-12);
}

TEST_F(DatasetViewTest, GermanThermalLogShowsItsColumnsWithUnitsAndPlotsAgainstTime) {
  // As a German spreadsheet writes it: a title line, ';', decimal commas, units in brackets; the
  // dataset maps Zeit to time_min and Drehzahl to spindle_rpm.
  const std::string file = dir_.file("waermegang.csv");
  test::writeText(file,
                  "Spindel Wärmegang 2026-11-28\n"
                  "Zeit [min];Temperatur T1 [°C];Verlagerung K3 [µm];Drehzahl [1/min]\n"
                  "0;20,5;0,0;0\n"
                  "0,25;20,75;1,5;5000\n"
                  "0,5;21,25;-2,25;5000\n"
                  "0,75;21,5;3;2500\n");
  DatasetRef d = datasetOf(dataset_kind::kThermalLog, file);
  d.csv.columnMap = {{"time_min", "Zeit [min]"}, {"spindle_rpm", "Drehzahl [1/min]"}};
  QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
  DatasetView view;
  ASSERT_TRUE(view.showDataset(QString::fromStdString(file), d)) << view.errorText().toStdString();
  ASSERT_FALSE(view.model()->isFeatureTable());
  ASSERT_EQ(view.model()->rowCount(), 4);
  ASSERT_EQ(view.model()->columnCount(), 4);
  // Mapped columns by their role with the unit; the file's own names state theirs already.
  EXPECT_EQ(header(view, 0), QStringLiteral("time_min [min]"));
  EXPECT_EQ(header(view, 1), QStringLiteral("Temperatur T1 [°C]"));
  EXPECT_EQ(header(view, 2), QStringLiteral("Verlagerung K3 [µm]"));
  EXPECT_EQ(header(view, 3), QStringLiteral("spindle_rpm [1/min]"));
  EXPECT_EQ(view.model()->columnUnit(1), QStringLiteral("°C"));
  EXPECT_EQ(view.model()->columnUnit(2), QStringLiteral("µm"));
  EXPECT_EQ(view.model()->columnUnit(3), QStringLiteral("1/min"));
  EXPECT_NE(view.model()
                ->headerData(0, Qt::Horizontal, Qt::ToolTipRole)
                .toString()
                .indexOf(QStringLiteral("Zeit [min]")),
            -1);
  // Numbers in the UI language: decimal commas, no group separator.
  EXPECT_EQ(cell(view, 1, 1), QStringLiteral("20,75"));
  EXPECT_EQ(cell(view, 2, 2), QStringLiteral("-2,25"));
  EXPECT_EQ(cell(view, 1, 3), QStringLiteral("5000"));
  EXPECT_DOUBLE_EQ(view.model()->number(1, 1), 20.75);

  // Sorting a numeric column numerically (not as text).
  view.table()->horizontalHeader()->setSortIndicator(2, Qt::AscendingOrder);
  EXPECT_EQ(cell(view, 0, 2), QStringLiteral("-2,25"));
  EXPECT_EQ(cell(view, 3, 2), QStringLiteral("3"));
  view.table()->horizontalHeader()->setSortIndicator(2, Qt::DescendingOrder);
  EXPECT_EQ(cell(view, 0, 2), QStringLiteral("3"));
  // The filter on the text shown.
  view.filterEdit()->setText(QStringLiteral("5000"));
  EXPECT_EQ(view.proxy()->rowCount(), 2);
  view.filterEdit()->clear();

  // The plot: the first column after the time, against the time.
  EXPECT_EQ(view.plotAxisBox()->currentData().toInt(), 0);
  EXPECT_EQ(view.plotColumnBox()->currentData().toInt(), 1);
  std::vector<QPointF> points = view.plottedPoints();
  ASSERT_EQ(points.size(), 4u);
  EXPECT_DOUBLE_EQ(points[2].x(), 0.5);
  EXPECT_DOUBLE_EQ(points[2].y(), 21.25);
  view.setPlot(2, 0);
  points = view.plottedPoints();
  ASSERT_EQ(points.size(), 4u);
  EXPECT_DOUBLE_EQ(points[3].x(), 0.75);
  EXPECT_DOUBLE_EQ(points[2].y(), -2.25);
  view.setPlot(3);  // against the row number
  points = view.plottedPoints();
  ASSERT_EQ(points.size(), 4u);
  EXPECT_DOUBLE_EQ(points[0].x(), 1.0);
  EXPECT_DOUBLE_EQ(points[1].y(), 5000.0);

  // Copy: the header with units, numbers as shown.
  view.table()->selectionModel()->select(view.proxy()->index(1, 0), QItemSelectionModel::Select);
  view.table()->selectionModel()->select(view.proxy()->index(1, 2), QItemSelectionModel::Select);
  EXPECT_EQ(copied(view), QStringLiteral("time_min [min]\tVerlagerung K3 [µm]\n0,25\t1,5\n"));
  saveShot(view, "datasetview-thermal-de.png");
}

TEST_F(DatasetViewTest, DmisOutputIsAFeatureTable) {
  const std::string file = (test::sourceDir() / "fuzz/corpus/dmis/part_17.dmo").string();
  DatasetView view;
  ASSERT_TRUE(view.showDataset(QString::fromStdString(file), datasetOf(dataset_kind::kDmis, file)))
      << view.errorText().toStdString();
  ASSERT_TRUE(view.model()->isFeatureTable());
  // DATUM_A X/Y/Z, POS_D1 X/Y/Z (F and FA), D2 (T and TA).
  ASSERT_EQ(view.model()->rowCount(), 7);
  EXPECT_EQ(cell(view, 5, 0), QStringLiteral("POS_D1"));
  EXPECT_EQ(cell(view, 5, 1), QStringLiteral("Z"));
  EXPECT_EQ(cell(view, 5, 2), QStringLiteral("42"));
  EXPECT_EQ(cell(view, 5, 3), QStringLiteral("42.013"));
  EXPECT_EQ(cell(view, 6, 0), QStringLiteral("D2"));
  EXPECT_EQ(cell(view, 6, 1), QStringLiteral("DISTB"));
  EXPECT_EQ(cell(view, 6, 2), QStringLiteral("18.5"));
  EXPECT_EQ(cell(view, 6, 4), QStringLiteral("-0.021"));
  EXPECT_EQ(cell(view, 6, 5), QStringLiteral("-0.05"));
  EXPECT_EQ(cell(view, 6, 6), QStringLiteral("0.03"));
  EXPECT_EQ(cell(view, 6, 7), QStringLiteral("in tolerance"));
}

TEST_F(DatasetViewTest, MissingFileIsOneLineNamingIt) {
  const std::string file = dir_.file("gone.csv");
  DatasetView view;
  view.resize(800, 500);
  view.show();
  EXPECT_FALSE(view.showDataset(QString::fromStdString(file), datasetOf(dataset_kind::kThermalLog, file)));
  const QString error = view.errorText();
  EXPECT_TRUE(error.startsWith(QStringLiteral("Cannot show gone.csv: "))) << error.toStdString();
  EXPECT_FALSE(error.contains(QLatin1Char('\n')));
  EXPECT_FALSE(view.table()->isVisible());
  EXPECT_EQ(view.model()->rowCount(), 0);
  // A file that is there again is shown again.
  test::writeText(file, "time_min,T1_degC,disp_z_um\n0,20,0\n1,21,2\n");
  ASSERT_TRUE(view.showDataset(QString::fromStdString(file), datasetOf(dataset_kind::kThermalLog, file)));
  EXPECT_TRUE(view.errorText().isEmpty());
  EXPECT_TRUE(view.table()->isVisible());
  EXPECT_EQ(header(view, 2), QStringLiteral("disp_z_um [µm]"));
}

TEST_F(DatasetViewTest, RealOgpStepReportIsAFeatureTable) {
  const std::filesystem::path real =
      test::realData("cmm-ogp-hps-svt/survey_data/meas1/L0_axial_top_module1_1.txt");
  METROFIT_REQUIRE_PATH(real);
  DatasetView view;
  ASSERT_TRUE(view.showDataset(QString::fromStdString(real.string()),
                               datasetOf(dataset_kind::kCmmReport, real.string())))
      << view.errorText().toStdString();
  ASSERT_TRUE(view.model()->isFeatureTable());
  EXPECT_GE(view.model()->rowCount(), 160);
  // Step 1 "diagball", as printed: Diameter +006.35549 against +006.35896, limits 0 / 0 (none).
  EXPECT_EQ(cell(view, 0, 0), QStringLiteral("diagball"));
  EXPECT_EQ(cell(view, 0, 1), QStringLiteral("Diameter"));
  const int nominal = columnOf(view, QStringLiteral("Nominal [mm]"));
  const int actual = columnOf(view, QStringLiteral("Actual [mm]"));
  const int deviation = columnOf(view, QStringLiteral("Deviation [mm]"));
  const int status = columnOf(view, QStringLiteral("Status"));
  if (nominal < 0) {  // a report with angles has a Unit column and no unit in the headers
    ASSERT_GE(columnOf(view, QStringLiteral("Unit")), 0);
  }
  const int n = nominal >= 0 ? nominal : columnOf(view, QStringLiteral("Nominal"));
  const int a = actual >= 0 ? actual : columnOf(view, QStringLiteral("Actual"));
  const int dv = deviation >= 0 ? deviation : columnOf(view, QStringLiteral("Deviation"));
  ASSERT_GE(n, 0);
  EXPECT_EQ(cell(view, 0, n), QStringLiteral("6.35896"));
  EXPECT_EQ(cell(view, 0, a), QStringLiteral("6.35549"));
  EXPECT_NEAR(view.model()->number(0, dv), 6.35549 - 6.35896, 1e-12);
  EXPECT_EQ(cell(view, 0, status), QStringLiteral("no tolerance"));
  // Sphericity +000.00000 with Tolerance +00.00000: no nominal, no deviation, no tolerance.
  EXPECT_EQ(cell(view, 4, 1), QStringLiteral("Sphericity"));
  EXPECT_EQ(cell(view, 4, a), QStringLiteral("0"));
  EXPECT_TRUE(cell(view, 4, n).isEmpty());
  EXPECT_TRUE(cell(view, 4, dv).isEmpty());
  EXPECT_EQ(cell(view, 4, status), QStringLiteral("no tolerance"));
  // Y Location -031.03925 against -031.02581: plain sign actual - nominal.
  EXPECT_EQ(cell(view, 2, 1), QStringLiteral("Y Location"));
  EXPECT_NEAR(view.model()->number(2, dv), -31.03925 + 31.02581, 1e-12);
  view.filterEdit()->setText(QStringLiteral("oriball"));
  EXPECT_EQ(view.proxy()->rowCount(), 6);  // Diameter, X/Y/Z Location, Sphericity, True Position
  view.filterEdit()->clear();
  saveShot(view, "datasetview-ogp-real.png");
}

// A log of 100 000 rows (a thermal log at 1 s for 28 h): the model reads the core table, nothing is
// copied into items; sorting, filtering and the plot stay usable. Times are printed, not asserted
// (two shared cores); the values are.
TEST_F(DatasetViewTest, HundredThousandRowLogIsShownSortedFilteredAndPlotted) {
  const std::string file = dir_.file("long.csv");
  std::string text = "time_s,T1_degC,disp_z_um\n";
  constexpr int kRows = 100000;
  for (int r = 0; r < kRows; ++r)
    text += std::to_string(r) + "," + std::to_string(20 + (r % 1000)) + ".5," +
            std::to_string((r * 7919) % 100003) + "\n";
  test::writeText(file, text);
  QElapsedTimer clock;
  clock.start();
  DatasetView view;
  view.resize(1000, 640);
  view.show();
  ASSERT_TRUE(view.showDataset(QString::fromStdString(file), datasetOf(dataset_kind::kThermalLog, file)));
  QApplication::processEvents();
  const qint64 shown = clock.restart();
  ASSERT_EQ(view.model()->rowCount(), kRows);
  EXPECT_EQ(header(view, 0), QStringLiteral("time_s [s]"));
  EXPECT_EQ(view.plottedPoints().size(), static_cast<std::size_t>(kRows));
  view.table()->horizontalHeader()->setSortIndicator(2, Qt::DescendingOrder);
  QApplication::processEvents();
  const qint64 sorted = clock.restart();
  double largest = 0;
  for (int r = 0; r < kRows; ++r) largest = std::max(largest, view.model()->number(r, 2));
  EXPECT_DOUBLE_EQ(view.proxy()->index(0, 2).data(DatasetTableModel::SortRole).toDouble(), largest);
  view.filterEdit()->setText(QStringLiteral("99999"));
  QApplication::processEvents();
  const qint64 filtered = clock.restart();
  EXPECT_GE(view.proxy()->rowCount(), 1);
  const QImage img = view.grab().toImage();
  const qint64 drawn = clock.restart();
  EXPECT_FALSE(img.isNull());
  std::cout << "100k rows: shown " << shown << " ms, sorted " << sorted << " ms, filtered " << filtered
            << " ms, drawn " << drawn << " ms\n";
}

// The real CAIVIAC spindle log (../shared/data/real/thermal-spindle-caiviac, MIT, read in place):
// 23 columns with their units from the role suffixes, plotted against time.
TEST_F(DatasetViewTest, RealCaiviacLogHasItsUnitsAndIsPlottedAgainstTime) {
  const std::filesystem::path real = test::realData("thermal-spindle-caiviac/thermal_caiviac.csv");
  METROFIT_REQUIRE_PATH(real);
  DatasetView view;
  ASSERT_TRUE(view.showDataset(QString::fromStdString(real.string()),
                               datasetOf(dataset_kind::kThermalLog, real.string())))
      << view.errorText().toStdString();
  ASSERT_EQ(view.model()->columnCount(), 23);
  EXPECT_EQ(header(view, 0), QStringLiteral("time_s [s]"));
  EXPECT_EQ(header(view, 1), QStringLiteral("spindle_rpm [1/min]"));
  EXPECT_EQ(header(view, 2), QStringLiteral("ch1_um [µm]"));
  EXPECT_EQ(header(view, 7), QStringLiteral("t1_degC [°C]"));
  EXPECT_GT(view.model()->rowCount(), 10000);
  // First row as the file has it: 0,0,0.377453,...,26.190862
  EXPECT_EQ(cell(view, 0, 2), QStringLiteral("0.377453"));
  EXPECT_EQ(cell(view, 0, 7), QStringLiteral("26.190862"));
  EXPECT_EQ(cell(view, 1, 0), QStringLiteral("15"));
  EXPECT_EQ(view.plotAxisBox()->currentData().toInt(), 0);
  view.setPlot(7, 0);
  const std::vector<QPointF> points = view.plottedPoints();
  ASSERT_EQ(points.size(), static_cast<std::size_t>(view.model()->rowCount()));
  EXPECT_DOUBLE_EQ(points[1].x(), 15.0);
  EXPECT_DOUBLE_EQ(points[0].y(), 26.190862);
  // The filter finds a number typed with the other decimal mark (a German UI, a '.' file).
  view.filterEdit()->setText(QStringLiteral("26,190862"));
  ASSERT_GE(view.proxy()->rowCount(), 1);
  EXPECT_EQ(cell(view, 0, 7), QStringLiteral("26.190862"));
  view.filterEdit()->clear();
  saveShot(view, "datasetview-caiviac-real.png");
}

// The real OGP summary of 13 runs (GPL-3.0, read in place): a Part column, numbers in Polish.
TEST_F(DatasetViewTest, RealOgpSummaryHasAPartColumnAndLocaleNumbers) {
  const std::filesystem::path real = test::realData("cmm-ogp-hps-svt/survey_data/L123_fixture_sho.txt");
  METROFIT_REQUIRE_PATH(real);
  QLocale::setDefault(QLocale(QLocale::Polish, QLocale::Poland));
  DatasetView view;
  ASSERT_TRUE(view.showDataset(QString::fromStdString(real.string()),
                               datasetOf(dataset_kind::kCmmReport, real.string())))
      << view.errorText().toStdString();
  EXPECT_EQ(header(view, 0), QStringLiteral("Part"));
  EXPECT_EQ(cell(view, 0, 0), QStringLiteral("run 1 (#4, Wed Oct 01 17:29:15 2014)"));
  const int actual = columnOf(view, QStringLiteral("Actual"));
  ASSERT_GE(actual, 0);
  EXPECT_EQ(cell(view, 0, actual), QStringLiteral("23,608"));
  view.filterEdit()->setText(QStringLiteral("run 13 "));
  EXPECT_GT(view.proxy()->rowCount(), 0);
  for (int r = 0; r < view.proxy()->rowCount(); ++r)
    EXPECT_TRUE(cell(view, r, 0).startsWith(QStringLiteral("run 13 ")));
  view.filterEdit()->clear();
  saveShot(view, "datasetview-ogp-summary-pl.png");
}

// Off the GUI thread: "Reading …" until the content is there; the last of two quick requests
// wins; an unreadable file ends in the error line. datasetShown() tells each end.
TEST_F(DatasetViewTest, BackgroundReadShowsTheLastRequestAndErrors) {
  const std::string a = dir_.file("a.csv"), b = dir_.file("b.csv");
  test::writeText(a, "time_min,T1_degC\n0,20\n");
  test::writeText(b, "time_min,T1_degC\n0,20\n1,21\n2,22\n");
  DatasetView view;
  QSignalSpy shown(&view, &DatasetView::datasetShown);
  view.showDatasetInBackground(QString::fromStdString(a), datasetOf(dataset_kind::kThermalLog, a));
  EXPECT_TRUE(view.isReading());
  EXPECT_TRUE(view.summaryText().startsWith(QStringLiteral("Reading a.csv")))
      << view.summaryText().toStdString();
  view.showDatasetInBackground(QString::fromStdString(b), datasetOf(dataset_kind::kThermalLog, b));
  QTRY_VERIFY(!view.isReading());
  ASSERT_EQ(shown.count(), 1);
  EXPECT_TRUE(shown.front().front().toBool());
  EXPECT_EQ(view.model()->rowCount(), 3);
  EXPECT_EQ(view.plottedPoints().size(), 3u);

  const std::string bad = dir_.file("bad.csv");
  test::writeText(bad, "time_min,T1_degC\n0,20\n1\n");
  view.showDatasetInBackground(QString::fromStdString(bad), datasetOf(dataset_kind::kThermalLog, bad));
  QTRY_VERIFY(!view.isReading());
  ASSERT_EQ(shown.count(), 2);
  EXPECT_FALSE(shown.back().front().toBool());
  EXPECT_TRUE(view.errorText().startsWith(QStringLiteral("Cannot show bad.csv: ")))
      << view.errorText().toStdString();
  EXPECT_EQ(view.model()->rowCount(), 0);
}

// The demo's point set, circular test and SPC feature series (resources/demo/data): their columns
// with the units of their role names, and a plot of a chosen column.
TEST_F(DatasetViewTest, DemoPointSetCircularTestAndFeatureSeriesShowTheirColumnsWithUnits) {
  const auto demo = [](const char* name) {
    return (test::sourceDir() / "resources/demo/data" / name).string();
  };
  DatasetView view;
  const std::string points = demo("probe_points_demo.csv");
  ASSERT_TRUE(view.showDataset(QString::fromStdString(points), datasetOf(dataset_kind::kProbePoints, points)))
      << view.errorText().toStdString();
  ASSERT_EQ(view.model()->rowCount(), 35);
  EXPECT_EQ(header(view, 0), QStringLiteral("id"));
  EXPECT_EQ(header(view, 2), QStringLiteral("qx [mm]"));
  EXPECT_EQ(header(view, 5), QStringLiteral("nx"));
  EXPECT_EQ(header(view, 8), QStringLiteral("px [mm]"));
  EXPECT_EQ(cell(view, 0, 0), QStringLiteral("P001"));
  EXPECT_EQ(cell(view, 0, 8), QStringLiteral("20.083356"));
  view.filterEdit()->setText(QStringLiteral("P00"));
  EXPECT_EQ(view.proxy()->rowCount(), 9);  // P001 .. P009
  view.filterEdit()->clear();

  const std::string circle = demo("circular_demo.csv");
  ASSERT_TRUE(
      view.showDataset(QString::fromStdString(circle), datasetOf(dataset_kind::kCircularTest, circle)));
  ASSERT_EQ(view.model()->rowCount(), 720);
  EXPECT_EQ(header(view, 2), QStringLiteral("x_meas_mm [mm]"));
  view.setPlot(3, 2);  // y_meas against x_meas: the measured circle
  const std::vector<QPointF> xy = view.plottedPoints();
  ASSERT_EQ(xy.size(), 720u);
  EXPECT_DOUBLE_EQ(xy[0].x(), 50.00448141938281);
  EXPECT_DOUBLE_EQ(xy[0].y(), 0.005194769616926916);
  saveShot(view, "datasetview-circular-demo.png");

  const std::string bores = demo("bores_demo.csv");
  ASSERT_TRUE(
      view.showDataset(QString::fromStdString(bores), datasetOf(dataset_kind::kFeatureSeries, bores)));
  ASSERT_EQ(view.model()->rowCount(), 25);
  EXPECT_EQ(header(view, 1), QStringLiteral("diameter_mm [mm]"));
  EXPECT_EQ(view.plotColumnBox()->currentData().toInt(), 0);  // part: the first numeric column
  view.setPlot(1);
  ASSERT_EQ(view.plottedPoints().size(), 25u);
  EXPECT_DOUBLE_EQ(view.plottedPoints()[0].y(), 99.998061388);
  view.table()->horizontalHeader()->setSortIndicator(1, Qt::AscendingOrder);
  EXPECT_LE(view.proxy()->index(0, 1).data(DatasetTableModel::SortRole).toDouble(),
            view.proxy()->index(1, 1).data(DatasetTableModel::SortRole).toDouble());
}

}  // namespace
}  // namespace metrofit
