// The unsaved-changes question of the main window (close, New) with an injected answer (Save /
// Discard / Cancel), unsaved edits of the setup model (its own undo stack) in the same question, the
// main window's autosave wiring (side file removed by Discard and a clean close, recovery offered when
// a project is opened) and the autosave interval in the Preferences dialog. Offscreen.
#include <gtest/gtest.h>

#include <QAction>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include "app/gui/autosave.h"
#include "app/gui/mainwindow.h"
#include "app/gui/preferencesdialog.h"
#include "app/gui/setuppage.h"
#include "core/project/project.h"
#include "core/setup/model.h"
#include "qtapp.h"
#include "testsupport.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"
#include "widgets/setup/setupmodeleditor.h"

namespace metrofit {
namespace {

using Choice = MainWindow::UnsavedChoice;

QAction* actionWithShortcut(QWidget& window, const QKeySequence& key) {
  for (QAction* action : window.findChildren<QAction*>())
    if (action->shortcuts().contains(key)) return action;
  return nullptr;
}

class UnsavedChangesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    demo_ = extractDemoProject(dir_.filePath(QStringLiteral("demo")));
    side_ = Autosave::autosaveFileFor(demo_);
    window_.autosave()->setIntervalMs(0);
    window_.autosave()->setUntitledFolder(dir_.filePath(QStringLiteral("untitled")));
    window_.setUnsavedChangesDecider([this] {
      ++asked_;
      return answer_;
    });
    ASSERT_TRUE(window_.openProject(demo_));
    window_.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window_));
  }
  void TearDown() override {
    answer_ = Choice::Discard;  // closing at the end asks nothing that blocks
  }
  void edit(const QString& name) {
    window_.document()->setValue(ProjectField::name(), name);
    ASSERT_TRUE(window_.autosave()->tick());
    window_.autosave()->waitForWrite();
    ASSERT_TRUE(QFileInfo::exists(side_));
  }

  QTemporaryDir dir_;
  QString demo_;
  QString side_;
  MainWindow window_;
  Choice answer_ = Choice::Cancel;
  int asked_ = 0;
};

TEST_F(UnsavedChangesTest, NothingIsAskedWhenNothingChanged) {
  EXPECT_TRUE(window_.close());
  EXPECT_EQ(asked_, 0);
}

TEST_F(UnsavedChangesTest, CloseCancelKeepsEverything) {
  edit(QStringLiteral("changed"));
  answer_ = Choice::Cancel;
  EXPECT_FALSE(window_.close());
  EXPECT_EQ(asked_, 1);
  EXPECT_TRUE(window_.isVisible());
  EXPECT_TRUE(window_.document()->isModified());
  EXPECT_EQ(window_.document()->project().name, "changed");
  EXPECT_TRUE(QFileInfo::exists(side_)) << "the autosaved copy stays while the changes are open";
}

TEST_F(UnsavedChangesTest, CloseDiscardClosesAndRemovesTheAutosave) {
  const Project before = loadProject(demo_.toStdString());
  edit(QStringLiteral("changed"));
  answer_ = Choice::Discard;
  EXPECT_TRUE(window_.close());
  EXPECT_EQ(asked_, 1);
  EXPECT_EQ(loadProject(demo_.toStdString()), before);
  EXPECT_FALSE(QFileInfo::exists(side_));
}

TEST_F(UnsavedChangesTest, CloseSaveSavesAndRemovesTheAutosave) {
  edit(QStringLiteral("saved on close"));
  answer_ = Choice::Save;
  EXPECT_TRUE(window_.close());
  EXPECT_EQ(loadProject(demo_.toStdString()).name, "saved on close");
  EXPECT_FALSE(window_.document()->isModified());
  EXPECT_FALSE(QFileInfo::exists(side_));
}

TEST_F(UnsavedChangesTest, NewAsksFirst) {
  QAction* newAction = actionWithShortcut(window_, QKeySequence::New);
  ASSERT_NE(newAction, nullptr);
  edit(QStringLiteral("changed"));
  answer_ = Choice::Cancel;
  newAction->trigger();
  EXPECT_EQ(asked_, 1);
  EXPECT_EQ(window_.document()->fileName(), QFileInfo(demo_).absoluteFilePath());
  EXPECT_EQ(window_.document()->project().name, "changed");

  answer_ = Choice::Discard;
  newAction->trigger();
  EXPECT_EQ(asked_, 2);
  EXPECT_TRUE(window_.document()->fileName().isEmpty());
  EXPECT_FALSE(window_.document()->isModified());
  EXPECT_EQ(window_.document()->project(), Project{});
  EXPECT_FALSE(QFileInfo::exists(side_));

  newAction->trigger();  // clean: nothing to ask
  EXPECT_EQ(asked_, 2);
}

TEST_F(UnsavedChangesTest, UnsavedSetupModelEditsAreAskedAboutAndSaved) {
  auto* setup = qobject_cast<SetupPage*>(window_.page(Page::Setup));
  ASSERT_NE(setup, nullptr);
  SetupModelEditor* editor = setup->modelEditor();
  ASSERT_FALSE(editor->model().dimensions.empty());
  const setup::Dimension d = editor->model().dimensions.front();
  const double lower = d.lower - 0.001;
  ASSERT_TRUE(editor->setTolerance(0, d.nominal, lower, d.upper));
  ASSERT_TRUE(editor->isModified());
  ASSERT_FALSE(window_.document()->isModified()) << "the model is its own file";

  answer_ = Choice::Cancel;
  EXPECT_FALSE(window_.close());
  EXPECT_EQ(asked_, 1);
  EXPECT_TRUE(editor->isModified());

  answer_ = Choice::Save;
  EXPECT_TRUE(window_.close());
  EXPECT_EQ(asked_, 2);
  EXPECT_FALSE(editor->isModified());
  const Project project = loadProject(demo_.toStdString());
  const setup::Model saved =
      setup::readModel(resolveDatasetPath(demo_.toStdString(), *project.dataset("setup_model")));
  EXPECT_DOUBLE_EQ(saved.dimensions.front().lower, lower);
}

// Issue 27 item 4: a run keeps its result in the project (results.<study>) without an edit, so
// quitting or File › New after a run used to lose it without a question. The document tracks results
// that are not saved (cleared by a save, a load and New); the question says so and Save keeps them.
TEST_F(UnsavedChangesTest, UnsavedResultsOfARunAreAskedAboutAndSaved) {
  auto* setup = qobject_cast<SetupPage*>(window_.page(Page::Setup));
  ASSERT_NE(setup, nullptr);
  ProjectDocument* document = window_.document();
  ASSERT_FALSE(document->hasUnsavedResults());
  EXPECT_FALSE(window_.isWindowModified());
  ASSERT_TRUE(setup->startRun()) << setup->errorMessage().toStdString();  // the study's method: exact
  ASSERT_TRUE(document->project().results.contains("setup"));
  EXPECT_FALSE(document->isModified()) << "a result is not an edit (no undo step)";
  EXPECT_TRUE(document->hasUnsavedResults());
  EXPECT_TRUE(window_.isWindowModified()) << "the title says something is not saved";
  const QString text = window_.unsavedChangesText();
  EXPECT_TRUE(text.contains(QStringLiteral("results of the last run are not saved"))) << text.toStdString();

  answer_ = Choice::Cancel;
  EXPECT_FALSE(window_.close());
  EXPECT_EQ(asked_, 1);
  QAction* newAction = actionWithShortcut(window_, QKeySequence::New);
  ASSERT_NE(newAction, nullptr);
  newAction->trigger();
  EXPECT_EQ(asked_, 2) << "File › New asks too";
  EXPECT_EQ(document->fileName(), QFileInfo(demo_).absoluteFilePath());
  EXPECT_TRUE(document->hasUnsavedResults());

  // With an edit as well, one question names both.
  document->setValue(ProjectField::name(), QStringLiteral("edited and run"));
  EXPECT_TRUE(window_.unsavedChangesText().contains(QStringLiteral("unsaved changes")));
  EXPECT_TRUE(window_.unsavedChangesText().contains(QStringLiteral("results of the last run")));

  answer_ = Choice::Save;
  EXPECT_TRUE(window_.close());
  EXPECT_EQ(asked_, 3);
  EXPECT_FALSE(document->hasUnsavedResults());
  const Project saved = loadProject(demo_.toStdString());
  EXPECT_EQ(saved.name, "edited and run");
  ASSERT_TRUE(saved.results.contains("setup"));
  EXPECT_TRUE(saved.results["setup"].contains("setup_report")) << saved.results.dump();
}

TEST_F(UnsavedChangesTest, UnsavedResultsAreDiscardedOnNewAndClearedBySaveAndOpen) {
  auto* setup = qobject_cast<SetupPage*>(window_.page(Page::Setup));
  ASSERT_NE(setup, nullptr);
  ProjectDocument* document = window_.document();
  ASSERT_TRUE(setup->startRun());
  ASSERT_TRUE(document->hasUnsavedResults());
  document->save();  // a save clears it: nothing more to ask
  EXPECT_FALSE(document->hasUnsavedResults());
  EXPECT_FALSE(window_.isWindowModified());
  EXPECT_TRUE(loadProject(demo_.toStdString()).results.contains("setup"));

  ASSERT_TRUE(setup->startRun());
  ASSERT_TRUE(document->hasUnsavedResults());
  ASSERT_TRUE(window_.openProject(demo_));  // reopened (no question: openProject is the caller's choice)
  EXPECT_FALSE(document->hasUnsavedResults());

  ASSERT_TRUE(setup->startRun());
  answer_ = Choice::Discard;
  QAction* newAction = actionWithShortcut(window_, QKeySequence::New);
  ASSERT_NE(newAction, nullptr);
  newAction->trigger();
  EXPECT_EQ(asked_, 1);
  EXPECT_TRUE(document->fileName().isEmpty());
  EXPECT_FALSE(document->hasUnsavedResults());
  EXPECT_FALSE(window_.isWindowModified());
}

TEST_F(UnsavedChangesTest, OpeningAProjectWithANewerAutosaveOffersRecovery) {
  Project autosaved = loadProject(demo_.toStdString());
  autosaved.name = "from the autosave";
  saveProject(autosaved, side_.toStdString());
  const QDateTime now = QDateTime::currentDateTime();
  {
    QFile project(demo_), side(side_);
    ASSERT_TRUE(project.open(QIODevice::ReadWrite) && side.open(QIODevice::ReadWrite));
    ASSERT_TRUE(project.setFileTime(now.addSecs(-120), QFileDevice::FileModificationTime));
    ASSERT_TRUE(side.setFileTime(now, QFileDevice::FileModificationTime));
  }
  int offered = 0;
  window_.autosave()->setDecider([&offered](const RecoveryOffer&) {
    ++offered;
    return RecoveryChoice::Recover;
  });
  ASSERT_TRUE(window_.openProject(demo_));
  EXPECT_EQ(offered, 1);
  EXPECT_EQ(window_.document()->project(), autosaved);
  EXPECT_TRUE(window_.document()->isModified());
  EXPECT_TRUE(window_.isWindowModified());
  EXPECT_NE(loadProject(demo_.toStdString()).name, "from the autosave");
  // Closing with Discard drops the recovered changes and their side file.
  answer_ = Choice::Discard;
  EXPECT_TRUE(window_.close());
  EXPECT_FALSE(QFileInfo::exists(side_));
}

TEST(PreferencesAutosaveTest, IntervalIsStoredInTheSettings) {
  Autosave::setIntervalSetting(Autosave::kDefaultIntervalMinutes);
  PreferencesDialog dialog;
  QSpinBox* spin = dialog.autosaveSpin();
  ASSERT_NE(spin, nullptr);
  EXPECT_EQ(spin->value(), 3);
  EXPECT_EQ(spin->minimum(), 0);
  EXPECT_EQ(spin->specialValueText(), QStringLiteral("Off"));
  // A grab for people to look at: $METROFIT_TEST_OUT/unsaved_changes/preferences.png.
  dialog.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&dialog));
  const QString out = QString::fromStdString((test::outDir() / "unsaved_changes").string());
  QDir().mkpath(out);
  EXPECT_TRUE(dialog.grab().save(out + QStringLiteral("/preferences.png")));
  spin->setValue(10);
  EXPECT_FALSE(dialog.apply()) << "the language did not change";
  EXPECT_EQ(Autosave::intervalSetting(), 10);
  spin->setValue(0);
  dialog.apply();
  EXPECT_EQ(Autosave::intervalSetting(), 0);
  Autosave::setIntervalSetting(Autosave::kDefaultIntervalMinutes);
}

}  // namespace
}  // namespace metrofit
