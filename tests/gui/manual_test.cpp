// Help › Manual (app/gui/manual.h): where the manual is looked for (the install layout next to the
// program first, the source tree's docs for a build folder) and the window that renders the Markdown
// documents and follows the links between them (offscreen).
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QUrl>

#include "app/gui/manual.h"
#include "qtapp.h"
#include "testsupport.h"

namespace metrofit {
namespace {

TEST(Manual, AnInstalledManualNextToTheProgramComesFirst) {
  QTemporaryDir prefix;
  ASSERT_TRUE(prefix.isValid());
  ASSERT_TRUE(QDir(prefix.path()).mkpath(QStringLiteral("bin")));
  ASSERT_TRUE(QDir(prefix.path()).mkpath(QStringLiteral("share/doc/metrofit")));
  const QString page = prefix.filePath(QStringLiteral("share/doc/metrofit/README.md"));
  QFile file(page);
  ASSERT_TRUE(file.open(QIODevice::WriteOnly));
  file.write("# Installed\n");
  file.close();
  const QString bin = prefix.filePath(QStringLiteral("bin"));
  EXPECT_EQ(manualCandidates(bin).constFirst(), page);
  EXPECT_EQ(findManual(bin), page);
}

TEST(Manual, ABuildFolderShowsTheSourceDocuments) {
  // The test runs from the build folder: nothing is installed next to it.
  const QString path = findManual(QCoreApplication::applicationDirPath());
  ASSERT_FALSE(path.isEmpty())
      << manualCandidates(QCoreApplication::applicationDirPath()).join(QLatin1Char(' ')).toStdString();
  EXPECT_TRUE(QFileInfo(path).isFile());
  const QString source = QString::fromStdString((test::sourceDir() / "docs" / "README.md").string());
  EXPECT_EQ(QFileInfo(path).canonicalFilePath(), QFileInfo(source).canonicalFilePath());
}

TEST(Manual, TheWindowRendersTheMarkdownAndFollowsItsLinks) {
  const QString path = findManual(QCoreApplication::applicationDirPath());
  ASSERT_FALSE(path.isEmpty());
  ManualWindow window;
  ASSERT_TRUE(window.openPage(path));
  QTextBrowser* browser = window.browser();
  const QString text = browser->toPlainText();
  EXPECT_TRUE(text.startsWith(QLatin1String("Metrofit documentation"))) << "the heading, not '# ...'";
  EXPECT_FALSE(text.contains(QLatin1String("| ---"))) << "the table is rendered";
  EXPECT_TRUE(text.contains(QLatin1String("file-formats.md")));
  // A picture to look at: the index as a reader sees it.
  window.resize(900, 600);
  window.show();
  window.grab().save(
      QDir(QString::fromStdString(test::outDir().string())).filePath(QStringLiteral("manual-window.png")));
  EXPECT_FALSE(window.openPage(QStringLiteral("/nonexistent/README.md")));

  // A link to another document opens it in the window; Back returns.
  emit browser->anchorClicked(QUrl(QStringLiteral("file-formats.md")));
  EXPECT_EQ(browser->source().fileName(), QStringLiteral("file-formats.md"));
  EXPECT_FALSE(browser->toPlainText().isEmpty());
  EXPECT_TRUE(browser->isBackwardAvailable());
  browser->backward();
  EXPECT_EQ(browser->source().fileName(), QStringLiteral("README.md"));
}

}  // namespace
}  // namespace metrofit
