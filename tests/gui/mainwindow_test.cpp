// MainWindow under QT_QPA_PLATFORM=offscreen: the demo project, navigation, editing through the
// overview with undo, the 3D fallback, error and unsaved-changes handling, recent files.
#include <gtest/gtest.h>

#include <QAbstractItemModel>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QOpenGLWidget>
#include <QPlainTextEdit>
#include <QProcess>
#include <QPushButton>
#include <QScrollBar>
#include <QSignalSpy>
#include <QStackedWidget>
#include <QStyleOptionViewItem>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QTranslator>
#include <QUndoStack>
#include <functional>
#include <nlohmann/json.hpp>

#include "app/gui/datasettable.h"
#include "app/gui/diagnosispage.h"
#include "app/gui/filechangedbar.h"
#include "app/gui/kinematicspage.h"
#include "app/gui/mainwindow.h"
#include "app/gui/manual.h"
#include "app/gui/matchingpage.h"
#include "app/gui/overviewpage.h"
#include "app/gui/projectnavigator.h"
#include "app/gui/recentfiles.h"
#include "app/gui/reportexporter.h"
#include "app/gui/setuppage.h"
#include "app/gui/thermalpage.h"
#include "core/matching/probe_points.h"
#include "core/setup/model.h"
#include "core/study/setup_study.h"
#include "qtapp.h"
#include "ui_language.h"
#include "widgets/common/chartnavigation.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"
#include "widgets/matching/pointsetview.h"
#include "widgets/setup/setupmodeleditor.h"
#include "widgets/thermal/thermaltrendview.h"

namespace metrofit {
namespace {

// The report export runs metrofit-cli report as a child: seconds normally, minutes under
// AddressSanitizer (the CLI demo takes 433 s there), so the wait scales with the build.
#if defined(__SANITIZE_ADDRESS__)
constexpr int kReportWaitMs = 600000;
#else
constexpr int kReportWaitMs = 60000;
#endif

QAction* actionWithShortcut(QWidget& window, const QKeySequence& key) {
  for (QAction* action : window.findChildren<QAction*>()) {
    if (action->shortcuts().contains(key)) return action;
  }
  return nullptr;
}

/// Runs `handle` on the next modal dialog (message box) as soon as it is shown.
void onNextMessageBox(std::function<void(QMessageBox*)> handle) {
  auto* timer = new QTimer;
  timer->setInterval(20);
  QObject::connect(timer, &QTimer::timeout, [timer, handle] {
    if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
      timer->stop();
      timer->deleteLater();
      handle(box);
    }
  });
  timer->start();
}

class MainWindowTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    demo_ = extractDemoProject(dir_.filePath(QStringLiteral("demo")));
    ASSERT_TRUE(window_.openProject(demo_));
    window_.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window_));
  }
  void TearDown() override {
    // Closing must not ask anything in a test: leave the document clean.
    window_.document()->undoStack()->setClean();
  }

  QTemporaryDir dir_;
  QString demo_;
  MainWindow window_;
};

TEST_F(MainWindowTest, OpensTheDemoProject) {
  const ProjectDocument* doc = window_.document();
  EXPECT_EQ(doc->fileName(), QFileInfo(demo_).absoluteFilePath());
  EXPECT_FALSE(doc->project().datasets.empty());
  const QString name = QString::fromStdString(doc->project().name);
  EXPECT_EQ(window_.windowTitle(), name + QStringLiteral("[*] — Metrofit"));
  EXPECT_FALSE(window_.isWindowModified());
  EXPECT_EQ(window_.navigator()->topLevelItemCount(), 1);
  EXPECT_EQ(window_.navigator()->topLevelItem(0)->text(0), name);
  EXPECT_EQ(window_.overviewPage()->nameEdit()->text(), name);
  EXPECT_EQ(window_.overviewPage()->datasetTable()->rowCount(),
            static_cast<int>(doc->project().datasets.size()));
  EXPECT_TRUE(recentFiles().contains(doc->fileName()));
}

// Study settings are validated when the project is opened; a bad one is a marked message
// on the overview naming the study and the field (the demo has none).
TEST_F(MainWindowTest, BadStudySettingIsAMarkedMessageOnOpen) {
  EXPECT_TRUE(window_.overviewPage()->settingProblems()->isHidden());
  QFile file(demo_);
  ASSERT_TRUE(file.open(QIODevice::ReadOnly));
  nlohmann::json j = nlohmann::json::parse(file.readAll().toStdString());
  file.close();
  j["studies"]["thermal"]["targt"] = "disp_z_um";
  const QString bad = QFileInfo(demo_).dir().filePath(QStringLiteral("bad.metrofit"));
  QFile out(bad);
  ASSERT_TRUE(out.open(QIODevice::WriteOnly));
  out.write(QByteArray::fromStdString(j.dump()));
  out.close();
  ASSERT_TRUE(window_.openProject(bad));
  QLabel* problems = window_.overviewPage()->settingProblems();
  EXPECT_FALSE(problems->isHidden());
  EXPECT_TRUE(problems->text().contains(QStringLiteral("studies.thermal.targt")))
      << problems->text().toStdString();
  EXPECT_TRUE(problems->text().contains(QStringLiteral("is not a setting")))
      << problems->text().toStdString();
}

TEST_F(MainWindowTest, NavigatorShowsEveryPage) {
  ProjectNavigator* nav = window_.navigator();
  QTreeWidgetItem* root = nav->topLevelItem(0);
  ASSERT_EQ(root->childCount(), kPageCount - 1);
  const QStringList titles = {QStringLiteral("Setup correction"), QStringLiteral("Posture matching"),
                              QStringLiteral("Kinematics & SPC"), QStringLiteral("Thermal"),
                              QStringLiteral("Diagnosis")};
  for (int i = 0; i < root->childCount(); ++i) {
    EXPECT_EQ(root->child(i)->text(0), titles[i]);
    nav->setCurrentItem(root->child(i));
    const Page page = static_cast<Page>(i + 1);
    EXPECT_EQ(window_.currentPage(), page) << i;
    EXPECT_TRUE(window_.page(page)->isVisible()) << i;
  }
  nav->setCurrentItem(root);
  EXPECT_EQ(window_.currentPage(), Page::Overview);
  EXPECT_TRUE(window_.overviewPage()->isVisible());
}

// The navigator shows every title whole ("Demo cell: 5-axis machining ce..." was cut, then scrolled
// out of sight): a long project name wraps onto a second line within the dock, every item's text
// wrapped to its row fits the row's height, and at 1280 x 800 nothing needs a sideways scroll.
TEST_F(MainWindowTest, NavigatorTitlesAreWholeAndWrapInsteadOfScrolling) {
  window_.resize(1280, 800);
  QApplication::processEvents();
  ProjectNavigator* nav = window_.navigator();
  EXPECT_EQ(nav->textElideMode(), Qt::ElideNone);
  EXPECT_TRUE(nav->wordWrap());
  QAbstractItemModel* model = nav->model();
  QList<QModelIndex> pending{model->index(0, 0)};
  int checked = 0;
  while (!pending.isEmpty()) {
    const QModelIndex index = pending.takeFirst();
    for (int r = 0; r < model->rowCount(index); ++r) pending << model->index(r, 0, index);
    const QRect rect = nav->visualRect(index);
    const QFont font = qvariant_cast<QFont>(index.data(Qt::FontRole));
    const QFontMetrics fm(index.data(Qt::FontRole).isValid() ? font : nav->font());
    const QRect text =
        fm.boundingRect(QRect(0, 0, rect.width() - 6, 100000), Qt::TextWordWrap, index.data().toString());
    EXPECT_LE(text.height(), rect.height()) << index.data().toString().toStdString();
    EXPECT_LE(rect.right(), nav->viewport()->width()) << index.data().toString().toStdString();
    ++checked;
  }
  EXPECT_GT(checked, 20);
  EXPECT_FALSE(nav->horizontalScrollBar()->isVisible());
  // The demo's name is longer than the dock is wide: its row holds two lines.
  const QModelIndex root = model->index(0, 0);
  EXPECT_GE(nav->visualRect(root).height(), 2 * QFontMetrics(nav->font()).lineSpacing())
      << nav->visualRect(root).height();
}

TEST_F(MainWindowTest, DatasetItemsSelectTheirData) {
  ProjectNavigator* nav = window_.navigator();
  QTreeWidgetItem* thermal = nav->itemForPage(Page::Thermal);
  ASSERT_GE(thermal->childCount(), 2) << "the demo has a simulated and a real thermal log";
  EXPECT_EQ(window_.thermalPage()->currentDataset(), thermal->child(0)->text(0));
  nav->setCurrentItem(thermal->child(1));
  EXPECT_EQ(window_.currentPage(), Page::Thermal);
  EXPECT_EQ(window_.thermalPage()->currentDataset(), thermal->child(1)->text(0));
  EXPECT_TRUE(window_.thermalPage()->errorMessage().isEmpty())
      << window_.thermalPage()->errorMessage().toStdString();
  EXPECT_FALSE(window_.thermalPage()->trendView()->visibleChannels().isEmpty());
}

TEST_F(MainWindowTest, CtrlDigitsSelectPages) {
  for (int i = 0; i < kPageCount; ++i) {
    QAction* action =
        actionWithShortcut(window_, QKeySequence(Qt::CTRL | static_cast<Qt::Key>(Qt::Key_1 + i)));
    ASSERT_NE(action, nullptr) << "Ctrl+" << i + 1;
    action->trigger();
    EXPECT_EQ(window_.currentPage(), static_cast<Page>(i));
    EXPECT_EQ(window_.navigator()->currentItem(), window_.navigator()->itemForPage(static_cast<Page>(i)));
  }
}

// F19: going back to a page whose navigator item is the parent of the highlighted one (Ctrl+1 after
// Ctrl+3: the overview is the root, the studies are its children) and File › New move the highlight.
TEST_F(MainWindowTest, NavigatorHighlightFollowsCtrlDigitsBackwardsAndFileNew) {
  ProjectNavigator* nav = window_.navigator();
  for (int i = kPageCount - 1; i >= 0; --i) {
    QAction* action =
        actionWithShortcut(window_, QKeySequence(Qt::CTRL | static_cast<Qt::Key>(Qt::Key_1 + i)));
    ASSERT_NE(action, nullptr);
    action->trigger();
    EXPECT_EQ(window_.currentPage(), static_cast<Page>(i));
    EXPECT_EQ(nav->currentItem(), nav->itemForPage(static_cast<Page>(i))) << "Ctrl+" << i + 1;
  }
  actionWithShortcut(window_, QKeySequence(Qt::CTRL | Qt::Key_3))->trigger();
  actionWithShortcut(window_, QKeySequence(Qt::CTRL | Qt::Key_1))->trigger();
  EXPECT_EQ(nav->currentItem(), nav->itemForPage(Page::Overview));

  // A dataset item stays highlighted while its own page is shown again.
  QTreeWidgetItem* thermal = nav->itemForPage(Page::Thermal);
  ASSERT_GT(thermal->childCount(), 0);
  nav->setCurrentItem(thermal->child(0));
  window_.showPage(Page::Thermal);
  EXPECT_EQ(nav->currentItem(), thermal->child(0));

  actionWithShortcut(window_, QKeySequence(Qt::CTRL | Qt::Key_6))->trigger();
  window_.setUnsavedChangesDecider([] { return MainWindow::UnsavedChoice::Discard; });
  QAction* fileNew = actionWithShortcut(window_, QKeySequence::New);
  ASSERT_NE(fileNew, nullptr);
  fileNew->trigger();
  EXPECT_EQ(window_.currentPage(), Page::Overview);
  EXPECT_EQ(nav->currentItem(), nav->itemForPage(Page::Overview));
}

// Every Qt Charts view of the pages zooms, pans and reads values (widgets/common/chartnavigation.h).
TEST_F(MainWindowTest, EveryChartOfThePagesZoomsAndShowsTheValueUnderTheCursor) {
  int charts = 0;
  for (int i = 0; i < kPageCount; ++i) window_.showPage(static_cast<Page>(i));
  for (QWidget* w : window_.findChildren<QWidget*>()) {
    if (!w->inherits("QChartView")) continue;
    ++charts;
    EXPECT_TRUE(hasChartNavigation(w)) << w->parentWidget()->metaObject()->className();
  }
  EXPECT_GE(charts, 8);
}

// Help › Manual (F1) hands the documentation's first page to the opener (a window by default; here
// the test records it): from the build folder, the source tree's docs/README.md.
TEST_F(MainWindowTest, HelpManualIsF1AndOpensTheDocumentation) {
  QAction* manual = actionWithShortcut(window_, QKeySequence(Qt::Key_F1));
  ASSERT_NE(manual, nullptr);
  EXPECT_EQ(manual->objectName(), QStringLiteral("helpManual"));
  const QList<QAction*> menus = window_.menuBar()->actions();
  ASSERT_FALSE(menus.isEmpty());
  EXPECT_EQ(menus.last()->text(), QStringLiteral("&Help"));
  EXPECT_TRUE(menus.last()->menu()->actions().contains(manual));
  QString opened;
  window_.setManualOpener([&opened](const QString& path) {
    opened = path;
    return true;
  });
  manual->trigger();
  ASSERT_FALSE(opened.isEmpty());
  EXPECT_TRUE(QFileInfo(opened).isFile()) << opened.toStdString();
  EXPECT_EQ(opened, findManual(QCoreApplication::applicationDirPath()));
  QFile page(opened);
  ASSERT_TRUE(page.open(QIODevice::ReadOnly));
  EXPECT_TRUE(page.readLine().startsWith("# Metrofit documentation"));
}

TEST_F(MainWindowTest, EditingTheNameIsUndoable) {
  QLineEdit* name = window_.overviewPage()->nameEdit();
  const QString original = name->text();
  name->setFocus();
  name->end(false);
  QTest::keyClicks(name, QStringLiteral(" v2"));
  const QString edited = original + QStringLiteral(" v2");
  EXPECT_EQ(QString::fromStdString(window_.document()->project().name), edited);
  EXPECT_TRUE(window_.isWindowModified());
  EXPECT_EQ(window_.windowTitle(), edited + QStringLiteral("[*] — Metrofit"));
  EXPECT_EQ(window_.navigator()->topLevelItem(0)->text(0), edited);
  EXPECT_EQ(window_.document()->undoStack()->count(), 1) << "typing is one undo step";

  QAction* undo = actionWithShortcut(window_, QKeySequence(QKeySequence::Undo));
  ASSERT_NE(undo, nullptr);
  EXPECT_TRUE(undo->isEnabled());
  undo->trigger();
  EXPECT_EQ(name->text(), original);
  EXPECT_EQ(QString::fromStdString(window_.document()->project().name), original);
  EXPECT_FALSE(window_.isWindowModified());
  EXPECT_EQ(window_.windowTitle(), original + QStringLiteral("[*] — Metrofit"));

  QAction* redo = actionWithShortcut(window_, QKeySequence(QKeySequence::Redo));
  ASSERT_NE(redo, nullptr);
  redo->trigger();
  EXPECT_EQ(name->text(), edited);
  EXPECT_TRUE(window_.isWindowModified());
}

TEST_F(MainWindowTest, EditingTheDescriptionIsUndoable) {
  QPlainTextEdit* description = window_.overviewPage()->descriptionEdit();
  const QString original = description->toPlainText();
  description->setFocus();
  description->moveCursor(QTextCursor::End);
  QTest::keyClicks(description, QStringLiteral(" More."));
  EXPECT_EQ(QString::fromStdString(window_.document()->project().description),
            original + QStringLiteral(" More."));
  EXPECT_EQ(window_.document()->undoStack()->count(), 1);
  window_.document()->undoStack()->undo();
  EXPECT_EQ(description->toPlainText(), original);
  EXPECT_FALSE(window_.isWindowModified());
}

TEST_F(MainWindowTest, PagesShowTheDemoData) {
  window_.showPage(Page::Thermal);
  EXPECT_TRUE(window_.thermalPage()->errorMessage().isEmpty())
      << window_.thermalPage()->errorMessage().toStdString();
  EXPECT_GE(window_.thermalPage()->datasetCombo()->count(), 2);

  window_.showPage(Page::Matching);
  MatchingPage* matching = window_.matchingPage();
  EXPECT_TRUE(matching->errorMessage().isEmpty()) << matching->errorMessage().toStdString();
  const DatasetRef* points = window_.document()->project().firstOfKind(dataset_kind::kProbePoints);
  ASSERT_NE(points, nullptr);
  EXPECT_EQ(matching->currentDataset(), QString::fromStdString(points->id));
  const ProbePointSet set = readProbePoints(window_.document()->datasetPath(*points).toStdString());
  EXPECT_EQ(matching->pointTable()->rowCount(), static_cast<int>(set.points.size()));

  // Every study has its own page on the demo, and none reports a problem with the demo data.
  window_.showPage(Page::Setup);
  auto* setup = qobject_cast<SetupPage*>(window_.page(Page::Setup));
  ASSERT_NE(setup, nullptr);
  EXPECT_TRUE(setup->errorMessage().isEmpty()) << setup->errorMessage().toStdString();
  EXPECT_EQ(setup->modelEditor()->model().dimensions.size(), 28u) << "the paper example's 28 dimensions";

  window_.showPage(Page::Kinematics);
  auto* kinematics = qobject_cast<KinematicsPage*>(window_.page(Page::Kinematics));
  ASSERT_NE(kinematics, nullptr);
  EXPECT_TRUE(kinematics->errorMessage().isEmpty()) << kinematics->errorMessage().toStdString();

  window_.showPage(Page::Diagnosis);
  auto* diagnosis = qobject_cast<DiagnosisPage*>(window_.page(Page::Diagnosis));
  ASSERT_NE(diagnosis, nullptr);
  EXPECT_TRUE(diagnosis->message().isEmpty()) << diagnosis->message().toStdString();
}

TEST_F(MainWindowTest, EditUndoAndRedoActOnTheGraphEditsOnTheSetupGraphTab) {
  window_.showPage(Page::Setup);
  auto* setup = qobject_cast<SetupPage*>(window_.page(Page::Setup));
  ASSERT_NE(setup, nullptr);
  setup->tabs()->setCurrentIndex(0);  // Graph
  SetupModelEditor* editor = setup->modelEditor();
  ASSERT_FALSE(editor->model().arcs.empty());
  const nlohmann::json before = setup::modelToJson(editor->model());
  QAction* undo = window_.findChild<QAction*>(QStringLiteral("editUndo"));
  QAction* redo = window_.findChild<QAction*>(QStringLiteral("editRedo"));
  ASSERT_NE(undo, nullptr);
  ASSERT_NE(redo, nullptr);
  EXPECT_EQ(undo, actionWithShortcut(window_, QKeySequence(QKeySequence::Undo)));
  ASSERT_FALSE(window_.isWindowModified());
  EXPECT_FALSE(undo->isEnabled());

  ASSERT_TRUE(editor->setArcWeight(0, -editor->model().arcs[0].weight));
  const nlohmann::json edited = setup::modelToJson(editor->model());
  ASSERT_NE(edited, before);
  EXPECT_TRUE(window_.isWindowModified()) << "the title shows the unsaved graph edit";
  EXPECT_FALSE(window_.document()->isModified()) << "the project file itself is unchanged";
  ASSERT_TRUE(undo->isEnabled());
  EXPECT_TRUE(undo->text().contains(editor->undoStack()->undoText())) << undo->text().toStdString();

  undo->trigger();
  EXPECT_EQ(setup::modelToJson(editor->model()), before);
  EXPECT_FALSE(window_.isWindowModified()) << "back at the saved model";
  ASSERT_TRUE(redo->isEnabled());
  redo->trigger();
  EXPECT_EQ(setup::modelToJson(editor->model()), edited);
  EXPECT_TRUE(window_.isWindowModified());

  // Elsewhere Edit › Undo is the project's again (nothing to undo there), and back on the graph the
  // model's.
  window_.showPage(Page::Overview);
  EXPECT_FALSE(undo->isEnabled());
  window_.showPage(Page::Setup);
  EXPECT_TRUE(undo->isEnabled());
  setup->tabs()->setCurrentIndex(1);  // Run: its settings are the project's
  EXPECT_FALSE(undo->isEnabled());
  setup->tabs()->setCurrentIndex(0);

  // Save writes the model file too: clean title, and the file has the edit.
  QAction* save = actionWithShortcut(window_, QKeySequence(QKeySequence::Save));
  ASSERT_NE(save, nullptr);
  save->trigger();
  EXPECT_FALSE(window_.isWindowModified());
  EXPECT_FALSE(editor->isModified());
  const SetupStudyFiles files =
      setupStudyFiles(window_.document()->project(), window_.document()->fileName().toStdString());
  EXPECT_EQ(setup::modelToJson(setup::readModel(files.modelPath)), edited);
}

TEST_F(MainWindowTest, The3DViewShowsItsFallbackOffscreen) {
  ASSERT_FALSE(PointSetView::canRender3D()) << "this test runs with QT_QPA_PLATFORM=offscreen";
  window_.showPage(Page::Matching);
  QApplication::processEvents();
  PointSetView* view = window_.matchingPage()->pointView();
  ASSERT_TRUE(view->isVisible());
  bool message = false;
  for (const QLabel* label : view->findChildren<QLabel*>()) {
    if (label->isVisible() && !label->text().isEmpty()) message = true;
  }
  EXPECT_TRUE(message) << "the point view explains why there is no 3D scene";
  EXPECT_TRUE(window_.findChildren<QOpenGLWidget*>().isEmpty()) << "no OpenGL without X";
  const QImage image = window_.grab().toImage();
  EXPECT_FALSE(image.isNull());
}

TEST_F(MainWindowTest, StudyNotesGoThroughTheUndoStack) {
  window_.showPage(Page::Thermal);
  auto* notes = window_.thermalPage()->findChild<QPlainTextEdit*>();
  ASSERT_NE(notes, nullptr);
  notes->setFocus();
  QTest::keyClicks(notes, QStringLiteral("T3 loose"));
  EXPECT_EQ(window_.document()->value(ProjectField::studyNotes(QStringLiteral("thermal"))),
            QStringLiteral("T3 loose"));
  EXPECT_TRUE(window_.isWindowModified());
  window_.document()->undoStack()->undo();
  EXPECT_TRUE(notes->toPlainText().isEmpty());
  EXPECT_FALSE(window_.isWindowModified());
}

TEST_F(MainWindowTest, OpeningABrokenFileKeepsTheProject) {
  const Project before = window_.document()->project();
  const QString broken = dir_.filePath(QStringLiteral("broken.metrofit"));
  QFile f(broken);
  ASSERT_TRUE(f.open(QIODevice::WriteOnly));
  f.write(R"({"format": "something-else", "version": 1})");
  f.close();

  QString error;
  EXPECT_FALSE(window_.openProject(broken, &error));
  EXPECT_TRUE(error.contains(QStringLiteral("broken.metrofit"))) << error.toStdString();
  EXPECT_FALSE(error.contains(QLatin1Char('\n'))) << error.toStdString();

  // Without an error pointer the message goes to a message box.
  QString shown;
  onNextMessageBox([&shown](QMessageBox* box) {
    shown = box->text();
    box->accept();
  });
  EXPECT_FALSE(window_.openProject(broken));
  EXPECT_EQ(shown, error);
  EXPECT_EQ(window_.document()->project(), before);
  EXPECT_EQ(window_.document()->fileName(), QFileInfo(demo_).absoluteFilePath());
}

TEST_F(MainWindowTest, CloseAsksAboutUnsavedChanges) {
  window_.document()->setValue(ProjectField::name(), QStringLiteral("changed"));
  onNextMessageBox([](QMessageBox* box) { box->button(QMessageBox::Cancel)->click(); });
  EXPECT_FALSE(window_.close());
  EXPECT_TRUE(window_.isVisible());
  EXPECT_TRUE(window_.document()->isModified());

  onNextMessageBox([](QMessageBox* box) { box->button(QMessageBox::Save)->click(); });
  EXPECT_TRUE(window_.close());
  EXPECT_FALSE(window_.document()->isModified());
  EXPECT_EQ(loadProject(demo_.toStdString()).name, "changed");
}

TEST_F(MainWindowTest, CloseCanDiscardChanges) {
  window_.document()->setValue(ProjectField::name(), QStringLiteral("changed"));
  onNextMessageBox([](QMessageBox* box) { box->button(QMessageBox::Discard)->click(); });
  EXPECT_TRUE(window_.close());
  EXPECT_NE(loadProject(demo_.toStdString()).name, "changed");
}

TEST_F(MainWindowTest, ChangesOnDiskShowTheReloadBar) {
  FileChangedBar* bar = window_.fileChangedBar();
  EXPECT_FALSE(bar->isVisible());
  Project changed = window_.document()->project();
  changed.name = "edited in another program";
  saveProject(changed, demo_.toStdString());
  ASSERT_TRUE(QTest::qWaitFor([bar] { return bar->isVisible(); }, 5000));
  EXPECT_TRUE(bar->message().contains(QStringLiteral("changed by another program")));
  auto* reload = bar->findChild<QPushButton*>();
  ASSERT_NE(reload, nullptr);
  reload->click();
  EXPECT_FALSE(bar->isVisible());
  EXPECT_EQ(window_.document()->project().name, "edited in another program");
}

/// The text of a PDF (pdftotext from poppler-utils).
QString pdfText(const QString& pdf) {
  QProcess p;
  p.start(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")});
  if (!p.waitForFinished(30000)) return {};
  return QString::fromUtf8(p.readAllStandardOutput());
}

TEST_F(MainWindowTest, ReportExportRunsInTheBackgroundAndShowsUnsavedEdits) {
  ReportExporter exporter(&window_);
  exporter.setCliPath(QStringLiteral(METROFIT_CLI_EXECUTABLE));
  QSignalSpy finished(&exporter, &ReportExporter::finished);
  // An unsaved edit is part of the report: the exporter reports what the user sees.
  window_.document()->setValue(ProjectField::name(), QStringLiteral("Cell 7 before the rebuild"));
  const QString pdf = dir_.filePath(QStringLiteral("report.pdf"));
  ASSERT_TRUE(exporter.start(*window_.document(), pdf));
  EXPECT_TRUE(exporter.isRunning());
  EXPECT_FALSE(exporter.start(*window_.document(), pdf)) << "one export at a time";
  ASSERT_TRUE(finished.wait(kReportWaitMs));
  EXPECT_FALSE(exporter.isRunning());
  ASSERT_EQ(finished.at(0).at(0).value<ReportExporter::Outcome>(), ReportExporter::Outcome::Written)
      << finished.at(0).at(1).toString().toStdString();
  EXPECT_TRUE(finished.at(0).at(1).toString().contains(QStringLiteral("report.pdf")));
  const QString text = pdfText(pdf);
  EXPECT_TRUE(text.contains(QStringLiteral("Cell 7 before the rebuild"))) << text.left(400).toStdString();
  // The saved file was not touched by the export.
  EXPECT_NE(loadProject(demo_.toStdString()).name, "Cell 7 before the rebuild");
  EXPECT_TRUE(window_.document()->isModified());
}

TEST_F(MainWindowTest, ReportExportErrorsAreOneLine) {
  ReportExporter exporter(&window_);
  exporter.setCliPath(QStringLiteral(METROFIT_CLI_EXECUTABLE));
  QSignalSpy finished(&exporter, &ReportExporter::finished);
  QFile blocker(dir_.filePath(QStringLiteral("blocker")));
  ASSERT_TRUE(blocker.open(QIODevice::WriteOnly));
  blocker.close();
  ASSERT_TRUE(exporter.start(*window_.document(), dir_.filePath(QStringLiteral("blocker/inside.pdf"))));
  ASSERT_TRUE(finished.wait(kReportWaitMs));
  EXPECT_EQ(finished.at(0).at(0).value<ReportExporter::Outcome>(), ReportExporter::Outcome::Failed);
  const QString message = finished.at(0).at(1).toString();
  EXPECT_TRUE(message.contains(QStringLiteral("inside.pdf"))) << message.toStdString();
  EXPECT_FALSE(message.contains(QLatin1Char('\n'))) << message.toStdString();

  exporter.setCliPath(dir_.filePath(QStringLiteral("no-such-metrofit-cli")));
  ASSERT_TRUE(exporter.start(*window_.document(), dir_.filePath(QStringLiteral("r.pdf"))));
  ASSERT_TRUE(finished.wait(10000));
  EXPECT_EQ(finished.at(1).at(0).value<ReportExporter::Outcome>(), ReportExporter::Outcome::Failed);
  EXPECT_TRUE(finished.at(1).at(1).toString().contains(QStringLiteral("no-such-metrofit-cli")));
  EXPECT_FALSE(exporter.isRunning());
}

// F2 of the GUI run: the error dialog said "metrofit-cli: metrofit-xPqdqI/demo.metrofit: ..." (the
// helper program and the temporary snapshot of the unsaved project). It names the user's file instead.
TEST_F(MainWindowTest, ReportExportErrorNamesTheUsersFile) {
  ReportExporter exporter(&window_);
  exporter.setCliPath(QStringLiteral(METROFIT_CLI_EXECUTABLE));
  QSignalSpy finished(&exporter, &ReportExporter::finished);
  window_.document()->setStudyValue(QStringLiteral("matching"), QStringLiteral("/frame_decimals"), 13,
                                    QStringLiteral("bad decimals"));
  ASSERT_TRUE(exporter.start(*window_.document(), dir_.filePath(QStringLiteral("bad.pdf"))));
  ASSERT_TRUE(finished.wait(kReportWaitMs));
  EXPECT_EQ(finished.at(0).at(0).value<ReportExporter::Outcome>(), ReportExporter::Outcome::Failed);
  const QString message = finished.at(0).at(1).toString();
  EXPECT_TRUE(message.startsWith(QFileInfo(demo_).fileName() + QStringLiteral(": ")))
      << message.toStdString();
  EXPECT_TRUE(message.contains(QStringLiteral("studies.matching.frame_decimals"))) << message.toStdString();
  EXPECT_FALSE(message.contains(QStringLiteral("metrofit-cli"))) << message.toStdString();
  EXPECT_FALSE(message.contains(QLatin1Char('/'))) << message.toStdString();
}

TEST_F(MainWindowTest, ReportExportCanBeCancelled) {
  ReportExporter exporter(&window_);
  exporter.setCliPath(QStringLiteral(METROFIT_CLI_EXECUTABLE));
  QSignalSpy finished(&exporter, &ReportExporter::finished);
  ASSERT_TRUE(exporter.start(*window_.document(), dir_.filePath(QStringLiteral("cancelled.pdf"))));
  exporter.cancel();
  ASSERT_TRUE(finished.wait(10000));
  EXPECT_EQ(finished.at(0).at(0).value<ReportExporter::Outcome>(), ReportExporter::Outcome::Cancelled);
  EXPECT_FALSE(exporter.isRunning());
}

TEST(RecentFilesTest, KeepsEightExistingFilesMostRecentFirst) {
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  clearRecentFiles();
  QStringList files;
  for (int i = 0; i < 10; ++i) {
    files << dir.filePath(QStringLiteral("p%1.metrofit").arg(i));
    QFile f(files.last());
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    addRecentFile(files.last());
  }
  QStringList recent = recentFiles();
  ASSERT_EQ(recent.size(), kMaxRecentFiles);
  EXPECT_EQ(recent.first(), files[9]);
  EXPECT_EQ(recent.last(), files[2]);
  addRecentFile(files[5]);  // re-opening moves it to the top without duplicates
  recent = recentFiles();
  EXPECT_EQ(recent.first(), files[5]);
  EXPECT_EQ(recent.count(files[5]), 1);
  ASSERT_TRUE(QFile::remove(files[9]));
  recent = recentFiles();
  EXPECT_FALSE(recent.contains(files[9]));
  EXPECT_EQ(recent.size(), kMaxRecentFiles - 1);
  clearRecentFiles();
  EXPECT_TRUE(recentFiles().isEmpty());
}

}  // namespace
}  // namespace metrofit

namespace metrofit {
namespace {

/// The menu titles of a window, in order.
QStringList menuTitles(const QMainWindow& window) {
  QStringList titles;
  for (const QAction* action : window.menuBar()->actions()) titles << action->text();
  return titles;
}

/// The .ts contexts must match the runtime class names (metrofit::MainWindow, ...): load the
/// translations the build made and check that the window really speaks German and Polish.
TEST(TranslationTest, WindowIsTranslated) {
  const QStringList english = menuTitles(MainWindow());
  EXPECT_EQ(english, (QStringList{QStringLiteral("&File"), QStringLiteral("&Edit"), QStringLiteral("&View"),
                                  QStringLiteral("&Help")}));
  const QList<std::pair<QString, QStringList>> languages = {
      {QStringLiteral("de"),
       {QStringLiteral("&Datei"), QStringLiteral("&Bearbeiten"), QStringLiteral("&Ansicht"),
        QStringLiteral("&Hilfe")}},
      {QStringLiteral("pl"),
       {QStringLiteral("&Plik"), QStringLiteral("&Edycja"), QStringLiteral("&Widok"),
        QStringLiteral("Pomo&c")}},
  };
  for (const auto& [language, menus] : languages) {
    SCOPED_TRACE(language.toStdString());
    const test::ScopedUiLanguage ui(language, test::ScopedUiLanguage::Locale::Keep);
    ASSERT_TRUE(ui.ok()) << ui.why();
    {
      MainWindow window;
      EXPECT_EQ(menuTitles(window), menus);
      window.document()->setValue(ProjectField::name(), QStringLiteral("x"));
      // Strings of the document layer (undo command texts) and of the study list are translated too.
      EXPECT_NE(window.document()->undoStack()->undoText(), QStringLiteral("Rename project"));
      EXPECT_NE(window.navigator()->itemForPage(Page::Setup)->text(0), QStringLiteral("Setup correction"));
      window.document()->undoStack()->setClean();
    }
  }
}

}  // namespace
}  // namespace metrofit
