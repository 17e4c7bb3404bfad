// "Show data" from the main window (app/gui/datasetactions.h): a double click on a dataset in the
// project navigator and in the overview's datasets table, and the context menu's first entry, open
// the dataset's table and plot (widgets/data/datasetview.h) in one non-modal window per dataset; the
// window follows the document (a removed dataset closes it) and a missing file is one line naming
// it. Files are written in the test: a thermal log with mapped columns and a PC-DMIS text report with
// one dimension out of tolerance. Offscreen; the screenshot goes to $METROFIT_TEST_OUT.
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QMenu>
#include <QSortFilterProxyModel>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidgetItemIterator>

#include "app/gui/datasetactions.h"
#include "app/gui/datasettable.h"
#include "app/gui/mainwindow.h"
#include "app/gui/projectnavigator.h"
#include "core/project/project.h"
#include "qtapp.h"
#include "testsupport.h"
#include "widgets/data/datasettablemodel.h"
#include "widgets/data/datasetview.h"
#include "widgets/document/projectdocument.h"

namespace metrofit {
namespace {

void writeFile(const QString& path, const QByteArray& text) {
  QFile f(path);
  ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate)) << path.toStdString();
  ASSERT_EQ(f.write(text), text.size());
}

/// The open data windows of `owner` (direct children shown as windows).
QList<QWidget*> dataWindows(QWidget* owner) {
  QList<QWidget*> out;
  for (QWidget* w :
       owner->findChildren<QWidget*>(QStringLiteral("datasetWindow"), Qt::FindDirectChildrenOnly))
    if (w->isVisible()) out << w;
  return out;
}

QTreeWidgetItem* navigatorItem(ProjectNavigator* navigator, const QString& id) {
  for (QTreeWidgetItemIterator it(navigator); *it; ++it)
    if ((*it)->data(0, ProjectNavigator::DatasetRole).toString() == id) return *it;
  return nullptr;
}

class DatasetDataTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    ASSERT_TRUE(QDir(dir_.path()).mkpath(QStringLiteral("data")));
    logPath_ = dir_.filePath(QStringLiteral("data/warmup.csv"));
    writeFile(logPath_,
              "Zeit [min],Temp Spindel [°C],Verlagerung Z [µm]\n"
              "0,20.5,0\n"
              "1,21.5,1.25\n"
              "2,22,2.5\n");
    reportPath_ = dir_.filePath(QStringLiteral("data/bracket.txt"));
    writeFile(reportPath_,
              "PART NAME  : BRACKET\n"
              "\n"
              "DIM LOC1= LOCATION OF CIRCLE CIR1  UNITS=MM ,$\n"
              "GRAPH=OFF  TEXT=OFF  MULT=10.00  OUTPUT=BOTH  HALF ANGLE=NO\n"
              "AX    NOMINAL       +TOL       -TOL       MEAS        DEV     OUTTOL\n"
              "X      25.000      0.050      0.050     25.012      0.012      0.000 ----#----\n"
              "Y      40.000      0.050      0.050     39.996     -0.004      0.000 ----#----\n"
              "END OF DIMENSION LOC1\n"
              "\n"
              "DIM LOC2= LOCATION OF PLANE PLN1  UNITS=MM ,$\n"
              "GRAPH=OFF  TEXT=OFF  MULT=10.00  OUTPUT=BOTH  HALF ANGLE=NO\n"
              "AX    NOMINAL       +TOL       -TOL       MEAS        DEV     OUTTOL\n"
              "Z      42.000      0.020      0.020     42.035      0.035      0.015 --------->\n"
              "END OF DIMENSION LOC2\n");
  }

  void addDatasets(ProjectDocument* doc) {
    doc->saveAs(dir_.filePath(QStringLiteral("shop.metrofit")));
    DatasetRef log;
    log.id = "warmup";
    log.kind = dataset_kind::kThermalLog;
    log.path = "data/warmup.csv";
    log.csv.columnMap = {{"time_min", "Zeit [min]"}, {"disp_z_um", "Verlagerung Z [µm]"}};
    doc->addDataset(log);
    DatasetRef report;
    report.id = "bracket";
    report.kind = dataset_kind::kCmmReport;
    report.path = "data/bracket.txt";
    doc->addDataset(report);
  }

  QTemporaryDir dir_;
  QString logPath_, reportPath_;
};

TEST_F(DatasetDataTest, NavigatorDoubleClickOpensOneWindowPerDataset) {
  MainWindow window;
  addDatasets(window.document());
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  auto* navigator = window.findChild<ProjectNavigator*>();
  ASSERT_NE(navigator, nullptr);
  QTreeWidgetItem* item = navigatorItem(navigator, QStringLiteral("warmup"));
  ASSERT_NE(item, nullptr);
  emit navigator->itemDoubleClicked(item, 0);
  QList<QWidget*> windows = dataWindows(&window);
  ASSERT_EQ(windows.size(), 1);
  EXPECT_TRUE(windows[0]->isWindow());
  EXPECT_FALSE(windows[0]->isModal());
  EXPECT_TRUE(windows[0]->windowTitle().startsWith(QStringLiteral("warmup")));
  auto* view = windows[0]->findChild<DatasetView*>();
  ASSERT_NE(view, nullptr);
  QTRY_VERIFY(!view->isReading());  // read off the GUI thread
  EXPECT_TRUE(view->errorText().isEmpty()) << view->errorText().toStdString();
  ASSERT_EQ(view->model()->rowCount(), 3);
  EXPECT_EQ(view->model()->headerData(0, Qt::Horizontal).toString(), QStringLiteral("time_min [min]"));
  EXPECT_EQ(view->model()->headerData(1, Qt::Horizontal).toString(), QStringLiteral("Temp Spindel [°C]"));
  EXPECT_EQ(view->model()->headerData(2, Qt::Horizontal).toString(), QStringLiteral("disp_z_um [µm]"));
  EXPECT_EQ(view->proxy()->index(1, 2).data().toString(), QStringLiteral("1.25"));
  EXPECT_EQ(view->plottedPoints().size(), 3u);

  // Asked again: the same window; another dataset: a second one.
  emit navigator->itemDoubleClicked(item, 0);
  EXPECT_EQ(dataWindows(&window).size(), 1);
  emit navigator->itemDoubleClicked(navigatorItem(navigator, QStringLiteral("bracket")), 0);
  windows = dataWindows(&window);
  ASSERT_EQ(windows.size(), 2);
  DatasetView* report = nullptr;
  for (QWidget* w : windows)
    if (w->windowTitle().startsWith(QStringLiteral("bracket"))) report = w->findChild<DatasetView*>();
  ASSERT_NE(report, nullptr);
  QTRY_VERIFY(!report->isReading());
  ASSERT_TRUE(report->model()->isFeatureTable());
  ASSERT_EQ(report->model()->rowCount(), 3);
  EXPECT_TRUE(report->model()->outOfTolerance(2));
  EXPECT_FALSE(report->model()->outOfTolerance(0));
  const QImage shot = report->window()->grab().toImage();
  shot.save(QDir(QString::fromStdString(test::outDir().string()))
                .filePath(QStringLiteral("dataset-data-window.png")));

  // Removing the dataset closes its window (undo brings the dataset, not the window, back).
  window.document()->removeDataset(QStringLiteral("warmup"));
  QApplication::processEvents();
  EXPECT_EQ(dataWindows(&window).size(), 1);
}

TEST_F(DatasetDataTest, OverviewTableDoubleClickAndContextMenuShowData) {
  ProjectDocument doc;
  addDatasets(&doc);
  DatasetTable table;
  table.setDatasets(doc, doc.project().datasets);
  table.enableEditing(&doc);
  table.show();
  ASSERT_EQ(table.datasetId(1), QStringLiteral("bracket"));
  emit table.cellDoubleClicked(1, 2);
  QList<QWidget*> windows = dataWindows(&table);
  ASSERT_EQ(windows.size(), 1);
  auto* view = windows[0]->findChild<DatasetView*>();
  ASSERT_NE(view, nullptr);
  QTRY_VERIFY(!view->isReading());
  EXPECT_TRUE(view->model()->isFeatureTable());
  windows[0]->close();
  QApplication::processEvents();

  // The context menu's first entry is "Show data" (before rename, re-link, remove).
  QMenu menu;
  addDatasetActions(&menu, &doc, QStringLiteral("warmup"), &table);
  QStringList names;
  for (QAction* a : menu.actions())
    if (!a->isSeparator()) names << a->objectName();
  EXPECT_EQ(names, (QStringList{QStringLiteral("showDatasetData"), QStringLiteral("renameDataset"),
                                QStringLiteral("relinkDataset"), QStringLiteral("removeDataset")}));
  menu.actions().front()->trigger();
  windows = dataWindows(&table);
  ASSERT_EQ(windows.size(), 1);
  view = windows[0]->findChild<DatasetView*>();
  ASSERT_NE(view, nullptr);
  QTRY_VERIFY(!view->isReading());
  EXPECT_EQ(view->model()->rowCount(), 3);

  // A file that has gone: one line naming it instead of the table.
  ASSERT_TRUE(QFile::remove(logPath_));
  QWidget* again = showDatasetData(&doc, QStringLiteral("warmup"), &table);
  ASSERT_EQ(again, windows[0]);
  QTRY_VERIFY(!view->isReading());
  EXPECT_TRUE(view->errorText().startsWith(QStringLiteral("Cannot show warmup.csv: ")))
      << view->errorText().toStdString();
  EXPECT_FALSE(view->table()->isVisible());
}

}  // namespace
}  // namespace metrofit
