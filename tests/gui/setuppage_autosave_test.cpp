// The setup page's relation-graph edits and runs (offscreen):
//  * unsaved relation-graph edits are part of the autosave side file and come back on recovery as
//    unsaved edits (the project itself may be clean);
//  * the graph editor's Revert is one undo step: Ctrl+Z brings the edits back;
//  * the progress bar shows only while a run goes on (like the other pages).
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QHeaderView>
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
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"
#include "widgets/document/studyinfo.h"
#include "widgets/setup/setupgrapheditor.h"
#include "widgets/setup/setupgraphview.h"
#include "widgets/setup/setupmodeleditor.h"

namespace metrofit {
namespace {

using test::readAll;
using test::setModified;

class SetupGapsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    project_ = extractDemoProject(dir_.filePath(QStringLiteral("demo")));
    side_ = Autosave::autosaveFileFor(project_);
    model_ = dir_.filePath(QStringLiteral("demo/data/paper_example.json"));
    ASSERT_TRUE(QFileInfo::exists(model_));
  }
  std::unique_ptr<Autosave> makeAutosave(ProjectDocument& doc, RecoveryChoice choice) {
    auto a = std::make_unique<Autosave>(&doc);
    a->setIntervalMs(0);
    a->setUntitledFolder(dir_.filePath(QStringLiteral("untitled")));
    a->setDecider([this, choice](const RecoveryOffer& offer) {
      offers_.push_back(offer);
      return choice;
    });
    return a;
  }
  static nlohmann::json modelJson(const SetupPage& page) {
    return setup::modelToJson(page.modelEditor()->model());
  }
  static QPushButton* button(const QWidget& page, const QString& text) {
    for (QPushButton* b : page.findChildren<QPushButton*>())
      if (b->text() == text) return b;
    return nullptr;
  }

  QTemporaryDir dir_;
  QString project_, side_, model_;
  std::vector<RecoveryOffer> offers_;
};

TEST_F(SetupGapsTest, GraphEditsAreAutosavedAlsoWhenTheProjectIsClean) {
  ProjectDocument doc;
  doc.load(project_);
  SetupPage page(&doc);
  auto a = makeAutosave(doc, RecoveryChoice::Recover);
  EXPECT_FALSE(a->tick()) << "nothing unsaved";

  SetupModelEditor* editor = page.modelEditor();
  ASSERT_TRUE(editor->setTolerance(0, 12.0, -0.09, 0.1));
  ASSERT_FALSE(doc.isModified());
  ASSERT_TRUE(a->tick()) << "the graph edit is unsaved work";
  a->waitForWrite();
  ASSERT_EQ(a->writtenFile(), side_);
  const nlohmann::json side = parseJson(readAll(side_), side_.toStdString());
  EXPECT_EQ(loadProject(side_.toStdString()), doc.project()) << "still a project file";
  ASSERT_TRUE(side.contains("unsaved")) << side.dump();
  const nlohmann::json& unsaved = side["unsaved"]["setup_model"];
  EXPECT_EQ(unsaved["dataset"], "setup_model");
  EXPECT_EQ(unsaved["model"], modelJson(page));
  EXPECT_DOUBLE_EQ(unsaved["model"]["dimensions"][0]["lower"].get<double>(), -0.09);
  EXPECT_TRUE(editor->isModified()) << "autosaving only reads";
  EXPECT_EQ(editor->undoStack()->count(), 1);

  // A new edit is written on the next tick; nothing new, nothing written.
  EXPECT_FALSE(a->tick());
  ASSERT_TRUE(editor->addArc(QStringLiteral("W1"), QStringLiteral("nowhere"), 1));  // invalid for now
  ASSERT_TRUE(a->tick());
  a->waitForWrite();
  EXPECT_EQ(parseJson(readAll(side_), "side")["unsaved"]["setup_model"]["model"], modelJson(page));

  // Undone back to the file: the side file goes.
  editor->undoStack()->undo();
  editor->undoStack()->undo();
  EXPECT_FALSE(editor->isModified());
  EXPECT_FALSE(QFileInfo::exists(side_));
  EXPECT_TRUE(a->writtenFile().isEmpty());

  // Saving the model also removes it; a document edit next to it keeps the project's part.
  ASSERT_TRUE(editor->setTolerance(0, 12.0, -0.08, 0.1));
  doc.setValue(ProjectField::name(), QStringLiteral("edited cell"));
  ASSERT_TRUE(a->tick());
  a->waitForWrite();
  EXPECT_EQ(loadProject(side_.toStdString()).name, "edited cell");
  QString error;
  ASSERT_TRUE(page.saveModel(&error)) << error.toStdString();
  EXPECT_FALSE(QFileInfo::exists(side_)) << "saved: the side file never holds what is older than the files";
  ASSERT_TRUE(a->tick()) << "the document is still unsaved";
  a->waitForWrite();
  const nlohmann::json again = parseJson(readAll(side_), "side");
  EXPECT_FALSE(again.contains("unsaved")) << again.dump();
  EXPECT_EQ(loadProject(side_.toStdString()).name, "edited cell");
}

TEST_F(SetupGapsTest, AfterACrashTheGraphEditsAreRecoveredAsUnsavedEdits) {
  const std::string onDisk = readAll(model_);
  nlohmann::json edited;
  {
    ProjectDocument doc;
    doc.load(project_);
    SetupPage page(&doc);
    auto a = makeAutosave(doc, RecoveryChoice::Recover);
    SetupModelEditor* editor = page.modelEditor();
    ASSERT_TRUE(editor->setTolerance(1, std::nullopt, -0.07, 0.11));
    ASSERT_TRUE(editor->addNode(SetupLevel::Tool, QStringLiteral("T99")));
    ASSERT_TRUE(editor->addArc(QStringLiteral("T99"), QStringLiteral("nowhere"), -1));  // a model in progress
    ASSERT_FALSE(editor->isValid());
    edited = modelJson(page);
    ASSERT_TRUE(a->tick());
    a->waitForWrite();
    // The process dies here: nothing is saved, nothing removes the side file.
  }
  ASSERT_TRUE(QFileInfo::exists(side_));
  const QDateTime now = QDateTime::currentDateTime();
  setModified(project_, now.addSecs(-60));
  setModified(side_, now);

  ProjectDocument doc;
  SetupPage page(&doc);
  auto a = makeAutosave(doc, RecoveryChoice::Recover);
  EXPECT_EQ(a->open(project_), RecoveryChoice::Recover);
  ASSERT_EQ(offers_.size(), 1u);
  EXPECT_EQ(offers_[0].unsaved, QStringList{QStringLiteral("setup_model")});
  EXPECT_EQ(modelJson(page), edited) << "the edits are back, invalid model included";
  SetupModelEditor* editor = page.modelEditor();
  EXPECT_TRUE(editor->isModified());
  EXPECT_FALSE(editor->isValid());
  EXPECT_FALSE(doc.isModified()) << "the project itself had no unsaved change";
  EXPECT_EQ(readAll(model_), onDisk) << "nothing is written over the model file";
  EXPECT_TRUE(page.infoText().contains(QStringLiteral("Edited, not saved"))) << page.infoText().toStdString();
  // One undo step back to the model file.
  EXPECT_EQ(editor->undoStack()->undoText(), QStringLiteral("Recover autosaved model edits"));
  editor->undoStack()->undo();
  EXPECT_EQ(modelJson(page), setup::modelToJson(setup::readModel(model_.toStdString())));
  EXPECT_FALSE(editor->isModified());
  EXPECT_FALSE(QFileInfo::exists(side_)) << "back to the saved state: the side file goes";
  editor->undoStack()->redo();
  EXPECT_EQ(modelJson(page), edited);
}

TEST_F(SetupGapsTest, RecoveredEditsOfAnotherModelAreReportedNotApplied) {
  ProjectDocument doc;
  doc.load(project_);
  const Project project = doc.project();
  nlohmann::json side = project.toJson();
  side["unsaved"]["setup_model"] = {{"dataset", "other_model"}, {"model", nlohmann::json::object()}};
  {
    std::ofstream out(side_.toStdString());
    out << side.dump(2);
  }
  const QDateTime now = QDateTime::currentDateTime();
  setModified(project_, now.addSecs(-60));
  setModified(side_, now);
  ProjectDocument doc2;
  SetupPage page(&doc2);
  auto a = makeAutosave(doc2, RecoveryChoice::Recover);
  QStringList failures;
  QObject::connect(a.get(), &Autosave::failed, [&](const QString& m) { failures << m; });
  EXPECT_EQ(a->open(project_), RecoveryChoice::Recover);
  ASSERT_EQ(failures.size(), 1);
  EXPECT_TRUE(failures[0].contains(QStringLiteral("other_model"))) << failures[0].toStdString();
  EXPECT_FALSE(page.modelEditor()->isModified());
}

TEST_F(SetupGapsTest, RevertIsOneUndoStepThatUndoBringsTheEditsBack) {
  ProjectDocument doc;
  doc.load(project_);
  SetupPage page(&doc);
  page.show();
  SetupModelEditor* editor = page.modelEditor();
  const nlohmann::json saved = modelJson(page);
  ASSERT_TRUE(editor->setTolerance(0, 12.0, -0.09, 0.1));
  ASSERT_TRUE(editor->renameNode(QStringLiteral("W1"), QStringLiteral("W11")));
  const nlohmann::json edits = modelJson(page);
  QPushButton* revert = button(page, QStringLiteral("Re&vert"));
  ASSERT_NE(revert, nullptr);
  EXPECT_TRUE(revert->isEnabled());

  revert->click();
  EXPECT_EQ(modelJson(page), saved);
  EXPECT_FALSE(editor->isModified());
  EXPECT_FALSE(revert->isEnabled());
  EXPECT_EQ(editor->undoStack()->count(), 3) << "the edits stay on the stack";
  EXPECT_EQ(editor->undoStack()->undoText(), QStringLiteral("Revert the setup model"));
  EXPECT_TRUE(page.errorMessage().isEmpty()) << page.errorMessage().toStdString();

  // Ctrl+Z in the graph editor brings the edits back.
  QTest::keyClick(page.graphEditor()->view(), Qt::Key_Z, Qt::ControlModifier);
  EXPECT_EQ(modelJson(page), edits);
  EXPECT_TRUE(editor->isModified());
  EXPECT_TRUE(revert->isEnabled());
  editor->undoStack()->redo();
  EXPECT_EQ(modelJson(page), saved);
  EXPECT_FALSE(editor->isModified());

  // A model file that cannot be read: Revert fails with its message and the edits stay.
  editor->undoStack()->undo();
  QFile::rename(model_, model_ + QStringLiteral(".away"));
  QString error;
  EXPECT_FALSE(page.revertModel(&error));
  EXPECT_TRUE(error.contains(QStringLiteral("paper_example.json"))) << error.toStdString();
  EXPECT_EQ(modelJson(page), edits);
  EXPECT_TRUE(editor->isModified());
  QFile::rename(model_ + QStringLiteral(".away"), model_);
  // Reverting an unedited model changes nothing and pushes nothing.
  ASSERT_TRUE(page.revertModel(&error)) << error.toStdString();
  const int count = editor->undoStack()->count();
  ASSERT_TRUE(page.revertModel(&error)) << error.toStdString();
  EXPECT_EQ(editor->undoStack()->count(), count);
}

TEST_F(SetupGapsTest, ProgressBarShowsOnlyWhileARunGoesOn) {
  ProjectDocument doc;
  doc.load(project_);
  SetupPage page(&doc);
  page.resize(1100, 760);
  page.show();
  page.tabs()->setCurrentIndex(1);
  QProgressBar* bar = page.progressBar();
  EXPECT_FALSE(bar->isVisibleTo(&page)) << "no run yet";

  page.methodCombo()->setCurrentIndex(page.methodCombo()->findData(QStringLiteral("cripso")));
  page.budgetSpin()->setValue(50'000'000);
  ASSERT_TRUE(page.startRun());
  EXPECT_TRUE(bar->isVisibleTo(&page));
  QTest::qWait(200);
  page.cancelRun();
  page.waitForRun();
  EXPECT_FALSE(bar->isVisibleTo(&page)) << "hidden after Cancel";

  page.budgetSpin()->setValue(5000);
  ASSERT_TRUE(page.startRun());
  EXPECT_TRUE(bar->isVisibleTo(&page));
  page.waitForRun();
  EXPECT_FALSE(bar->isVisibleTo(&page)) << "hidden after the run, the status line has the result";
  page.methodCombo()->setCurrentIndex(page.methodCombo()->findData(QStringLiteral("exact")));
  ASSERT_TRUE(page.startRun());
  EXPECT_FALSE(bar->isVisibleTo(&page)) << "the exact optimum is shown at once";
}

}  // namespace
}  // namespace metrofit
