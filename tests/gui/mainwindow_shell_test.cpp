// The first-run hint on the overview ("New here? Open the demo project…"), the main window's keyboard
// shortcuts (shown in the menus), the copy action of the dataset table, and the main window fitting a
// 1280 x 800 screen in German and Polish with the demo project open (offscreen).
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QDir>
#include <QFile>
#include <QFrame>
#include <QLayout>
#include <QLocale>
#include <QMenuBar>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QTranslator>

#include "app/gui/datasettable.h"
#include "app/gui/mainwindow.h"
#include "app/gui/overviewpage.h"
#include "app/gui/pageid.h"
#include "app/gui/projectnavigator.h"
#include "qtapp.h"
#include "testsupport.h"
#include "ui_language.h"
#include "widgets/common/tablecopy.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"

namespace metrofit {
namespace {

const QString kKey = QString::fromLatin1(OverviewPage::kFirstRunHintKey);

TEST(FirstRunHint, ShownOnFirstStartAndDismissedForGood) {
  QSettings().remove(kKey);
  {
    MainWindow window;
    QFrame* hint = window.overviewPage()->firstRunHint();
    ASSERT_NE(hint, nullptr);
    EXPECT_TRUE(hint->isVisibleTo(window.overviewPage()));
    window.resize(1280, 800);
    window.grab().save(
        QDir(QString::fromStdString(test::outDir().string())).filePath(QStringLiteral("first-run-hint.png")));
    auto* dismiss = hint->findChild<QToolButton*>(QStringLiteral("firstRunDismiss"));
    ASSERT_NE(dismiss, nullptr);
    QSignalSpy demo(window.overviewPage(), &OverviewPage::openDemoRequested);
    dismiss->click();
    EXPECT_FALSE(hint->isVisibleTo(window.overviewPage()));
    EXPECT_EQ(demo.count(), 0);
    EXPECT_TRUE(QSettings().value(kKey).toBool());
  }
  MainWindow again;  // remembered: the next start shows no hint
  EXPECT_FALSE(again.overviewPage()->firstRunHint()->isVisibleTo(again.overviewPage()));
}

TEST(FirstRunHint, ButtonOpensTheBundledDemo) {
  QTemporaryDir data;  // the demo is copied below XDG_DATA_HOME
  ASSERT_TRUE(data.isValid());
  const QByteArray oldData = qgetenv("XDG_DATA_HOME");
  qputenv("XDG_DATA_HOME", QFile::encodeName(data.path()));
  QSettings().remove(kKey);
  {
    MainWindow window;
    EXPECT_TRUE(window.document()->fileName().isEmpty());
    QFrame* hint = window.overviewPage()->firstRunHint();
    auto* open = hint->findChild<QPushButton*>(QStringLiteral("firstRunOpenDemo"));
    ASSERT_NE(open, nullptr);
    open->click();
    EXPECT_TRUE(window.document()->fileName().startsWith(data.path()))
        << window.document()->fileName().toStdString();
    EXPECT_TRUE(window.document()->fileName().endsWith(QLatin1String(".metrofit")));
    EXPECT_FALSE(hint->isVisibleTo(window.overviewPage()));
    EXPECT_TRUE(QSettings().value(kKey).toBool());
    EXPECT_TRUE(window.statusBar()->currentMessage().contains(QDir::toNativeSeparators(data.path())))
        << window.statusBar()->currentMessage().toStdString();
  }
  if (oldData.isEmpty())
    qunsetenv("XDG_DATA_HOME");
  else
    qputenv("XDG_DATA_HOME", oldData);
}

QAction* menuAction(QMainWindow& window, const QKeySequence& key) {
  for (QAction* menu : window.menuBar()->actions())
    for (QAction* a : menu->menu()->actions())
      if (a->shortcuts().contains(key)) return a;
  return nullptr;
}

TEST(Shortcuts, CommonActionsAreInTheMenusWithTheirKeys) {
  MainWindow window;
  const QList<QKeySequence> keys = {QKeySequence(QKeySequence::Open),
                                    QKeySequence(QKeySequence::Save),
                                    QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S),
                                    QKeySequence(QKeySequence::Undo),
                                    QKeySequence(QKeySequence::Redo).isEmpty()
                                        ? QKeySequence(Qt::CTRL | Qt::Key_Y)
                                        : QKeySequence(QKeySequence::Redo),
                                    QKeySequence(Qt::CTRL | Qt::Key_E),
                                    QKeySequence(Qt::CTRL | Qt::Key_1),
                                    QKeySequence(Qt::CTRL | Qt::Key_6)};
  for (const QKeySequence& key : keys)
    EXPECT_NE(menuAction(window, key), nullptr) << key.toString().toStdString();
  EXPECT_TRUE(
      menuAction(window, QKeySequence(Qt::CTRL | Qt::Key_E))->text().contains(QLatin1String("report")));
}

TEST(Shortcuts, RunAndCancelTakeF5AndEscWhereThePageHasNoOwn) {
  MainWindow window;
  auto* run = window.findChild<QAction*>(QStringLiteral("runStudy"));
  auto* cancel = window.findChild<QAction*>(QStringLiteral("cancelRun"));
  ASSERT_NE(run, nullptr);
  ASSERT_NE(cancel, nullptr);
  // In the View menu, after the page actions.
  QAction* viewMenu = nullptr;
  for (QAction* top : window.menuBar()->actions())
    if (top->menu() && top->menu()->actions().contains(run)) viewMenu = top;
  ASSERT_NE(viewMenu, nullptr);
  EXPECT_TRUE(viewMenu->menu()->actions().contains(cancel));
  window.showPage(Page::Overview);
  EXPECT_EQ(run->shortcut(), QKeySequence(Qt::Key_F5));
  EXPECT_EQ(cancel->shortcut(), QKeySequence(Qt::Key_Escape));
  // Nothing to run on the overview: the status bar says so.
  run->trigger();
  EXPECT_EQ(window.statusBar()->currentMessage(), QStringLiteral("Nothing to run on this page"));
  cancel->trigger();
  EXPECT_EQ(window.statusBar()->currentMessage(), QStringLiteral("Nothing is running"));
  // The kinematics page runs with its own F5 (Identify): the menu action leaves the key to it.
  window.showPage(Page::Kinematics);
  EXPECT_TRUE(run->shortcut().isEmpty());
  // The diagnosis page has its own Esc (Cancel) but no F5.
  window.showPage(Page::Diagnosis);
  EXPECT_EQ(run->shortcut(), QKeySequence(Qt::Key_F5));
  EXPECT_TRUE(cancel->shortcut().isEmpty());
}

TEST(DatasetTableCopy, CopiesTheRowsWithHeaders) {
  MainWindow window;
  DatasetTable* table = window.overviewPage()->datasetTable();
  ASSERT_NE(table, nullptr);
  table->setRowCount(1);
  table->setItem(0, 0, new QTableWidgetItem(QStringLiteral("probe")));
  table->setItem(0, 1, new QTableWidgetItem(QStringLiteral("probe points")));
  table->setItem(0, 2, new QTableWidgetItem(QStringLiteral("data/probe.csv")));
  table->setItem(0, 3, new QTableWidgetItem(QStringLiteral("CC0")));
  table->selectRow(0);
  bool found = false;
  for (QAction* a : table->actions())
    if (a->objectName() == QLatin1String("tableCopy")) {
      a->trigger();
      found = true;
    }
  ASSERT_TRUE(found);
  EXPECT_EQ(
      QApplication::clipboard()->text().toStdString(),
      (table->horizontalHeaderItem(0)->text() + QLatin1Char('\t') + table->horizontalHeaderItem(1)->text() +
       QLatin1Char('\t') + table->horizontalHeaderItem(2)->text() + QLatin1Char('\t') +
       table->horizontalHeaderItem(3)->text() +
       QStringLiteral("\nprobe\tprobe points\tdata/probe.csv\tCC0\n"))
          .toStdString());
}

TEST(Layout, EveryPageFitsA1280x800ScreenInGermanAndPolish) {
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  const QString project = extractDemoProject(dir.path());
  for (const QString& language : {QStringLiteral("de"), QStringLiteral("pl")}) {
    SCOPED_TRACE(language.toStdString());
    const test::ScopedUiLanguage ui(language);
    ASSERT_TRUE(ui.ok()) << ui.why();
    {
      MainWindow window;
      QString error;
      ASSERT_TRUE(window.openProject(project, &error)) << error.toStdString();
      window.resize(1280, 800);
      window.show();
      ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
      for (int i = 0; i < kPageCount; ++i) {
        window.showPage(static_cast<Page>(i));
        QApplication::processEvents();
        const QSize page = window.page(static_cast<Page>(i))->minimumSizeHint();
        EXPECT_LE(page.width() + window.navigator()->parentWidget()->minimumSizeHint().width(), 1280 - 8)
            << "page " << i << " needs " << page.width() << " px";
        EXPECT_LE(page.height(), 800 - 80) << "page " << i << " needs " << page.height() << " px";
      }
      const QSize minimum = window.minimumSizeHint().expandedTo(window.minimumSize());
      EXPECT_LE(minimum.width(), 1280);
      EXPECT_LE(minimum.height(), 800);
      EXPECT_EQ(window.width(), 1280);
    }
  }
}

}  // namespace
}  // namespace metrofit
