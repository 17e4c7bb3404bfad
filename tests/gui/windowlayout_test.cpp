// The main window's layout across a restart (issue 28, F12): geometry, the navigator dock's width,
// every named splitter and the last page are kept in the settings by a close and given back by
// restoreLayout() of the next window (offscreen; the settings live in the test's temporary folder).
#include <gtest/gtest.h>

#include <QDockWidget>
#include <QMouseEvent>
#include <QSettings>
#include <QSplitter>
#include <QSplitterHandle>
#include <QTemporaryDir>
#include <QTest>
#include <memory>

#include "app/gui/mainwindow.h"
#include "app/gui/projectnavigator.h"
#include "app/gui/windowlayout.h"
#include "qtapp.h"
#include "widgets/document/demoproject.h"

namespace metrofit {
namespace {

/// Drags the first handle of `splitter` by `dx` pixels with the left button, as a user does.
void dragHandle(QSplitter* splitter, int dx) {
  QSplitterHandle* handle = splitter->handle(1);
  ASSERT_NE(handle, nullptr);
  const QPointF start = QPointF(handle->rect().center());
  const QPointF end = start + QPointF(dx, 0);
  QMouseEvent press(QEvent::MouseButtonPress, start, handle->mapToGlobal(start), Qt::LeftButton,
                    Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(handle, &press);
  QMouseEvent move(QEvent::MouseMove, end, handle->mapToGlobal(end), Qt::NoButton, Qt::LeftButton,
                   Qt::NoModifier);
  QApplication::sendEvent(handle, &move);
  QMouseEvent release(QEvent::MouseButtonRelease, end, handle->mapToGlobal(end), Qt::LeftButton, Qt::NoButton,
                      Qt::NoModifier);
  QApplication::sendEvent(handle, &release);
}

class WindowLayoutTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    demo_ = extractDemoProject(dir_.filePath(QStringLiteral("demo")));
    QSettings().remove(QStringLiteral("window"));
  }
  void TearDown() override { QSettings().remove(QStringLiteral("window")); }

  std::unique_ptr<MainWindow> newWindow(bool restore) {
    auto window = std::make_unique<MainWindow>();
    window->setUnsavedChangesDecider([] { return MainWindow::UnsavedChoice::Discard; });
    if (restore) window->restoreLayout();
    EXPECT_TRUE(window->openProject(demo_));
    window->show();
    EXPECT_TRUE(QTest::qWaitForWindowExposed(window.get()));
    return window;
  }

  QTemporaryDir dir_;
  QString demo_;
};

TEST_F(WindowLayoutTest, EveryPageSplitterHasAUniqueKey) {
  auto window = newWindow(false);
  QWidget* pages = window->page(Page::Overview)->parentWidget();
  const QList<QSplitter*> all = pages->findChildren<QSplitter*>();
  const QHash<QString, QSplitter*> named = namedSplitters(pages);
  // Every splitter of a page is named (else its sizes are forgotten), and no two share a key.
  for (QSplitter* s : all)
    EXPECT_FALSE(splitterKey(pages, s).isEmpty()) << s->parent()->metaObject()->className();
  EXPECT_EQ(named.size(), all.size());
  EXPECT_GE(named.size(), 8);
  EXPECT_TRUE(named.contains(QStringLiteral("kinematicsPage/kinematicsPathSplitter")))
      << QStringList(named.keys()).join(QLatin1Char(' ')).toStdString();
}

TEST_F(WindowLayoutTest, ALayoutSurvivesARestart) {
  QRect geometry;
  int dockWidth = 0;
  QList<int> pathSizes;
  QList<int> resultsSizes;
  {
    auto window = newWindow(false);
    window->resize(1500, 930);  // the size of the run in F12
    window->move(41, 50);
    auto* dock = window->findChild<QDockWidget*>(QStringLiteral("navigatorDock"));
    ASSERT_NE(dock, nullptr);
    window->resizeDocks({dock}, {330}, Qt::Horizontal);
    window->showPage(Page::Kinematics);
    QApplication::processEvents();
    auto* path = window->findChild<QSplitter*>(QStringLiteral("kinematicsPathSplitter"));
    ASSERT_NE(path, nullptr);
    const QList<int> before = path->sizes();
    dragHandle(path, 80);
    ASSERT_NE(path->sizes(), before) << "the drag did not move the splitter";
    // A splitter of a page that is not shown keeps its sizes too.
    auto* results = window->findChild<QSplitter*>(QStringLiteral("setupResultsSplitter"));
    ASSERT_NE(results, nullptr);
    results->setSizes({250, 700});
    QApplication::processEvents();
    geometry = window->geometry();
    dockWidth = dock->width();
    pathSizes = path->sizes();
    resultsSizes = results->sizes();
    ASSERT_TRUE(window->close());
  }
  {
    const WindowLayout stored = [] {
      QSettings settings;
      return WindowLayout::read(settings);
    }();
    EXPECT_EQ(stored.page, static_cast<int>(Page::Kinematics));
    EXPECT_FALSE(stored.geometry.isEmpty());
    EXPECT_FALSE(stored.state.isEmpty());
    EXPECT_TRUE(stored.splitters.contains(QStringLiteral("kinematicsPage/kinematicsPathSplitter")));
  }
  auto window = newWindow(true);
  QApplication::processEvents();
  EXPECT_EQ(window->currentPage(), Page::Kinematics);
  EXPECT_EQ(window->navigator()->currentItem(), window->navigator()->itemForPage(Page::Kinematics));
  EXPECT_EQ(window->geometry().size(), geometry.size());
  EXPECT_EQ(window->geometry().topLeft(), geometry.topLeft());
  EXPECT_EQ(window->findChild<QDockWidget*>(QStringLiteral("navigatorDock"))->width(), dockWidth);
  EXPECT_EQ(window->findChild<QSplitter*>(QStringLiteral("kinematicsPathSplitter"))->sizes(), pathSizes);
  window->showPage(Page::Setup);
  QApplication::processEvents();
  EXPECT_EQ(window->findChild<QSplitter*>(QStringLiteral("setupResultsSplitter"))->sizes(), resultsSizes);
  window->close();
}

TEST_F(WindowLayoutTest, AWindowWithoutStoredLayoutStartsWithTheDefaults) {
  auto window = newWindow(true);
  EXPECT_EQ(window->currentPage(), Page::Overview);
  EXPECT_EQ(window->size(), QSize(1280, 800));
}

TEST_F(WindowLayoutTest, AStoredPageOutOfRangeIsIgnored) {
  {
    QSettings settings;
    WindowLayout layout;
    layout.page = 99;
    layout.geometry = QByteArray("not a geometry");
    layout.write(settings);
  }
  auto window = newWindow(true);
  EXPECT_EQ(window->currentPage(), Page::Overview);
  EXPECT_EQ(window->size(), QSize(1280, 800));
}

}  // namespace
}  // namespace metrofit
