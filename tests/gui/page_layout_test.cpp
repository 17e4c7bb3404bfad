// What the pages show fits and reads (offscreen; loads the built .qm files):
//  * every dataset kind of the project format has a readable title on the project overview;
//  * the matching page's tables fit the default window (1280 x 800) in German and Polish, and the
//    kinematics page's long labels wrap instead of being cut short.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollBar>
#include <QSet>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>
#include <QUndoStack>
#include <fstream>
#include <memory>
#include <regex>
#include <sstream>

#include "app/gui/autosave.h"
#include "app/gui/mainwindow.h"
#include "app/gui/matchingpage.h"
#include "app/gui/setuppage.h"
#include "core/io/json_util.h"
#include "core/project/project.h"
#include "core/setup/model.h"
#include "file_helpers.h"
#include "qtapp.h"
#include "testsupport.h"
#include "ui_language.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"
#include "widgets/document/studyinfo.h"
#include "widgets/setup/setupgrapheditor.h"
#include "widgets/setup/setupgraphview.h"
#include "widgets/setup/setupmodeleditor.h"

namespace metrofit {
namespace {
/// The dataset kinds declared in core/project/project.h (namespace dataset_kind), read from the
/// source so that a kind added there without a title fails this test.
std::vector<std::string> declaredDatasetKinds() {
  std::ifstream in(test::sourceDir() / "core/project/project.h");
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const std::size_t begin = s.find("namespace dataset_kind {");
  const std::size_t end = s.find("}  // namespace dataset_kind");
  if (begin == std::string::npos || end == std::string::npos) return {};
  const std::string block = s.substr(begin, end - begin);
  static const std::regex kind(R"re(inline constexpr const char\* k\w+ = "([a-z_]+)";)re");
  std::vector<std::string> kinds;
  for (auto it = std::sregex_iterator(block.begin(), block.end(), kind); it != std::sregex_iterator(); ++it)
    kinds.push_back((*it)[1]);
  return kinds;
}

TEST(DatasetKindTitle, EveryKindOfTheProjectFormatHasItsOwnTitle) {
  const std::vector<std::string> kinds = declaredDatasetKinds();
  ASSERT_GE(kinds.size(), 6u) << "core/project/project.h dataset_kind was not found";
  QSet<QString> titles;
  for (const std::string& k : kinds) {
    const QString kind = QString::fromStdString(k);
    const QString title = datasetKindTitle(kind);
    EXPECT_FALSE(title.isEmpty()) << k;
    EXPECT_NE(title, kind) << k << " has no human title";
    EXPECT_FALSE(title.contains(QLatin1Char('_'))) << k << ": " << title.toStdString();
    titles.insert(title);
  }
  EXPECT_EQ(titles.size(), static_cast<qsizetype>(kinds.size())) << "two kinds share a title";
  EXPECT_EQ(datasetKindTitle(QString::fromLatin1(dataset_kind::kFeatureSeries)),
            QStringLiteral("SPC feature series"));
  // Every kind the demo project uses is one of them.
  QTemporaryDir dir;
  const Project demo = loadProject(extractDemoProject(dir.filePath(QStringLiteral("demo"))).toStdString());
  for (const DatasetRef& d : demo.datasets)
    EXPECT_NE(std::find(kinds.begin(), kinds.end(), d.kind), kinds.end()) << d.id << " " << d.kind;
}

using test::readAll;
using test::setModified;

/// Widths of the visible columns of a table (for the failure message).
std::string columnWidths(const QTableWidget* t) {
  std::string s;
  for (int c = 0; c < t->columnCount(); ++c) {
    if (t->isColumnHidden(c)) continue;
    const QTableWidgetItem* h = t->horizontalHeaderItem(c);
    s += (h ? h->text().replace(QLatin1Char('\n'), QLatin1Char(' ')).toStdString() : std::string("?")) + "=" +
         std::to_string(t->columnWidth(c)) + " ";
  }
  return s + "| viewport " + std::to_string(t->viewport()->width());
}

/// No horizontal scrolling, and no cell or header text wider than its column (nothing clipped).
void expectFits(QTableWidget* t, const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_TRUE(t->isVisible());
  EXPECT_FALSE(t->horizontalScrollBar()->isVisible()) << columnWidths(t);
  EXPECT_LE(t->horizontalHeader()->length(), t->viewport()->width()) << columnWidths(t);
  const QFontMetrics fm(t->font());
  for (int c = 0; c < t->columnCount(); ++c) {
    if (t->isColumnHidden(c)) continue;
    const QTableWidgetItem* h = t->horizontalHeaderItem(c);
    ASSERT_NE(h, nullptr);
    for (const QString& line : h->text().split(QLatin1Char('\n')))
      EXPECT_LE(fm.horizontalAdvance(line), t->columnWidth(c)) << "header " << line.toStdString();
    for (int r = 0; r < t->rowCount(); ++r) {
      const QTableWidgetItem* item = t->item(r, c);
      if (item == nullptr || t->columnSpan(r, c) > 1) continue;
      // Text may wrap at spaces (onto a higher row), no word may be cut.
      const QFontMetrics fm(item->font());
      for (const QString& word : item->text().split(QLatin1Char(' '), Qt::SkipEmptyParts))
        EXPECT_LE(fm.horizontalAdvance(word), t->columnWidth(c))
            << "row " << r << ": " << item->text().toStdString();
      const QRect box =
          fm.boundingRect(QRect(0, 0, t->columnWidth(c) - 6, 10000), Qt::TextWordWrap, item->text());
      EXPECT_LE(box.height(), t->rowHeight(r)) << "row " << r << ": " << item->text().toStdString();
    }
  }
}

class MatchingTablesTest : public ::testing::TestWithParam<const char*> {};

TEST_P(MatchingTablesTest, FitTheDefaultWindowWithoutScrollingSideways) {
  const QString language = QString::fromLatin1(GetParam());
  const test::ScopedUiLanguage ui(language);
  ASSERT_TRUE(ui.ok()) << ui.why();
  {
    QTemporaryDir dir;
    const QString demo = extractDemoProject(dir.filePath(QStringLiteral("demo")));
    MainWindow window;
    QString error;
    ASSERT_TRUE(window.openProject(demo, &error)) << error.toStdString();
    window.resize(1280, 800);  // the default size, as in the screenshots
    window.show();
    window.showPage(Page::Matching);
    MatchingPage* page = window.matchingPage();
    page->showView(QStringLiteral("results"));
    ASSERT_TRUE(page->result().has_value());
    QTest::qWait(50);
    expectFits(page->methodsTable(), "methods");
    expectFits(page->machineTable(), "machine");
    page->showView(QStringLiteral("remeasure"));
    QTest::qWait(50);
    expectFits(page->remeasureTable(), "remeasure");
    page->showView(QStringLiteral("points"));
    QTest::qWait(50);
    expectFits(page->pointTable(), "points");
    window.document()->undoStack()->setClean();
  }
}

/// The kinematics page's tables: the label column takes what the numbers leave; a long (translated)
/// label wraps onto a higher row instead of being cut short ("Winkel der X-…").
TEST_P(MatchingTablesTest, KinematicsLabelsWrapInsteadOfBeingCut) {
  const QString language = QString::fromLatin1(GetParam());
  const test::ScopedUiLanguage ui(language, test::ScopedUiLanguage::Locale::Keep);
  ASSERT_TRUE(ui.ok()) << ui.why();
  {
    QTemporaryDir dir;
    MainWindow window;
    QString error;
    ASSERT_TRUE(window.openProject(extractDemoProject(dir.filePath(QStringLiteral("demo"))), &error))
        << error.toStdString();
    window.resize(1280, 800);
    window.show();
    window.showPage(Page::Kinematics);
    QWidget* page = window.page(Page::Kinematics);
    QMetaObject::invokeMethod(page, "showView", Q_ARG(QString, QStringLiteral("path")));
    QTest::qWait(50);
    for (const char* name : {"identifiedErrorTable", "compensationTable"}) {
      SCOPED_TRACE(name);
      auto* t = page->findChild<QTableWidget*>(QString::fromLatin1(name));
      ASSERT_NE(t, nullptr);
      ASSERT_GE(t->rowCount(), 6);
      EXPECT_EQ(t->textElideMode(), Qt::ElideNone);
      for (int r = 0; r < t->rowCount(); ++r) {
        const QTableWidgetItem* item = t->item(r, 0);
        ASSERT_NE(item, nullptr);
        const QFontMetrics fm(item->font());
        for (const QString& word : item->text().split(QLatin1Char(' '), Qt::SkipEmptyParts))
          EXPECT_LE(fm.horizontalAdvance(word), t->columnWidth(0)) << item->text().toStdString();
        const QRect box =
            fm.boundingRect(QRect(0, 0, t->columnWidth(0) - 8, 10000), Qt::TextWordWrap, item->text());
        EXPECT_LE(box.height(), t->rowHeight(r))
            << "row " << r << " cut short: " << item->text().toStdString();
      }
    }
    // The actuators view's dataset choosers: each label shown in full next to its combo box.
    QMetaObject::invokeMethod(page, "showView", Q_ARG(QString, QStringLiteral("actuators")));
    QTest::qWait(50);
    for (const char* name : {"edgeXCombo", "edgeYCombo", "planeXyCombo", "planeYzCombo", "planeZxCombo"}) {
      SCOPED_TRACE(name);
      auto* combo = page->findChild<QComboBox*>(QString::fromLatin1(name));
      ASSERT_NE(combo, nullptr);
      EXPECT_TRUE(combo->isVisible());
      const QLabel* label = nullptr;
      for (const QLabel* l : page->findChildren<QLabel*>())
        if (l->buddy() == combo) label = l;
      ASSERT_NE(label, nullptr);
      EXPECT_GE(label->width(), label->sizeHint().width()) << label->text().toStdString();
      EXPECT_GE(combo->width(), combo->minimumSizeHint().width());
    }
    window.grab().save(QString::fromStdString(
        (test::outDir() / ("kinematics-actuators-" + language.toStdString() + ".png")).string()));
  }
}

INSTANTIATE_TEST_SUITE_P(Languages, MatchingTablesTest, ::testing::Values("de", "pl", "en"));

// The dataset chooser of the matching, thermal and kinematics pages (fillDatasetCombo): what was
// there goes, each dataset is one item with its id as text and data and its description as tooltip.
TEST(DatasetCombo, ItemsAreTheIdsWithTheirDescriptionsAsTooltips) {
  QComboBox combo;
  combo.addItem(QStringLiteral("stale"));
  std::vector<DatasetRef> sets(2);
  sets[0].id = "thermal_caiviac";
  sets[0].description = "CAIVIAC spindle, 46 h";
  sets[1].id = "thermal_sim";
  int emitted = 0;
  QObject::connect(&combo, &QComboBox::currentIndexChanged, [&] { ++emitted; });
  // The dataset asked for is chosen, without a signal (the page shows it itself).
  EXPECT_EQ(fillDatasetCombo(&combo, sets, QStringLiteral("thermal_sim")), 1);
  EXPECT_EQ(combo.currentIndex(), 1);
  EXPECT_EQ(emitted, 0);
  // A dataset the project no longer has: the first.
  EXPECT_EQ(fillDatasetCombo(&combo, sets, QStringLiteral("gone")), 0);
  ASSERT_EQ(combo.count(), 2);
  EXPECT_EQ(combo.itemText(0), QStringLiteral("thermal_caiviac"));
  EXPECT_EQ(combo.itemData(0).toString(), QStringLiteral("thermal_caiviac"));
  EXPECT_EQ(combo.itemData(0, Qt::ToolTipRole).toString(), QStringLiteral("CAIVIAC spindle, 46 h"));
  EXPECT_EQ(combo.findData(QStringLiteral("thermal_sim")), 1);
  EXPECT_EQ(fillDatasetCombo(&combo, {}, QStringLiteral("thermal_sim")), -1);
  EXPECT_EQ(combo.count(), 0);
  EXPECT_EQ(emitted, 0);
}

}  // namespace
}  // namespace metrofit
