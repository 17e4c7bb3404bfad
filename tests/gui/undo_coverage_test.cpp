// Undo / redo covers every edit of the project (docs/undo-coverage.md): each editor
// kind is driven like a user on its own, without a main window, on the bundled demo project, and the
// whole project JSON is compared after the edit, after undo (exactly the JSON before) and after redo
// (exactly the JSON after). Offscreen.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include "app/gui/matchingpage.h"
#include "app/gui/notesedit.h"
#include "app/gui/overviewpage.h"
#include "app/gui/setuppage.h"
#include "app/gui/thermalpage.h"
#include "core/project/project.h"
#include "qtapp.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"
#include "widgets/thermal/thermalmodelview.h"

namespace metrofit {
namespace {

class UndoCoverageTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    document_.load(extractDemoProject(dir_.path()));
    before_ = json();
  }
  nlohmann::json json() const { return document_.project().toJson(); }
  /// After the edits: the JSON differs from before as `expectChange` says; `steps` undo steps take it
  /// back exactly, as many redo steps forward exactly.
  void expectUndoRedo(int steps, const std::function<void(nlohmann::json&)>& expectChange) {
    nlohmann::json expected = before_;
    expectChange(expected);
    const nlohmann::json after = json();
    EXPECT_TRUE(after == expected) << "diff: " << nlohmann::json::diff(expected, after).dump();
    EXPECT_TRUE(document_.isModified());
    ASSERT_EQ(document_.undoStack()->count(), steps);
    for (int i = 0; i < steps; ++i) document_.undoStack()->undo();
    EXPECT_TRUE(json() == before_) << "diff: " << nlohmann::json::diff(before_, json()).dump();
    EXPECT_FALSE(document_.isModified());
    for (int i = 0; i < steps; ++i) document_.undoStack()->redo();
    EXPECT_TRUE(json() == after) << "diff: " << nlohmann::json::diff(after, json()).dump();
    EXPECT_TRUE(document_.isModified());
  }

  QTemporaryDir dir_;
  ProjectDocument document_;
  nlohmann::json before_;
};

TEST_F(UndoCoverageTest, OverviewNameAndDescription) {
  OverviewPage page(&document_);
  auto* name = page.findChild<QLineEdit*>(QStringLiteral("projectName"));
  auto* description = page.findChild<QPlainTextEdit*>(QStringLiteral("projectDescription"));
  ASSERT_TRUE(name && description);
  name->selectAll();
  QTest::keyClicks(name, QStringLiteral("Cell 7"));
  emit name->editingFinished();
  description->selectAll();
  QTest::keyClicks(description, QStringLiteral("Spindle 2"));
  expectUndoRedo(2, [](nlohmann::json& j) {
    j["name"] = "Cell 7";
    j["description"] = "Spindle 2";
  });
  document_.undoStack()->undo();
  document_.undoStack()->undo();
  EXPECT_EQ(name->text().toStdString(), before_["name"].get<std::string>()) << "the field follows undo";
}

TEST(OverviewName, AnUnnamedProjectShowsNoEnglishDefault) {
  // File › New: core names the project "Untitled"; the field is empty with the UI language's word
  // as its placeholder, and typing a name writes it.
  ProjectDocument document;
  OverviewPage page(&document);
  auto* name = page.findChild<QLineEdit*>(QStringLiteral("projectName"));
  ASSERT_TRUE(name);
  EXPECT_EQ(document.project().name, "Untitled");
  EXPECT_TRUE(name->text().isEmpty());
  EXPECT_EQ(name->placeholderText(), document.displayName());
  QTest::keyClicks(name, QStringLiteral("Zelle 3"));
  EXPECT_EQ(document.project().name, "Zelle 3");
  EXPECT_EQ(name->text(), QStringLiteral("Zelle 3"));
  EXPECT_EQ(name->placeholderText(), OverviewPage::tr("Project name"));
  document.undoStack()->undo();
  EXPECT_TRUE(name->text().isEmpty()) << "undo gives the unnamed project back";
}

TEST_F(UndoCoverageTest, StudyNotes) {
  NotesEdit notes(&document_, QStringLiteral("kinematics"));
  QTest::keyClicks(&notes, QStringLiteral("ballbar on Monday"));
  expectUndoRedo(1, [](nlohmann::json& j) { j["studies"]["kinematics"]["notes"] = "ballbar on Monday"; });
}

TEST_F(UndoCoverageTest, SetupRunSettings) {
  SetupPage page(&document_);
  EXPECT_EQ(document_.undoStack()->count(), 0) << "showing the settings is no edit";
  QComboBox* method = page.methodCombo();
  method->setCurrentIndex(method->findData(QStringLiteral("cripso")));
  page.budgetSpin()->setValue(6000);
  page.budgetSpin()->setValue(7000);  // typing: one step
  emit page.budgetSpin()->editingFinished();
  page.seedSpin()->setValue(42);
  emit page.seedSpin()->editingFinished();
  expectUndoRedo(3, [](nlohmann::json& j) {
    j["studies"]["setup"]["method"] = "cripso";
    j["studies"]["setup"]["budget"] = 7000;
    j["studies"]["setup"]["seed"] = 42;
  });
  EXPECT_TRUE(document_.project().studies["setup"]["seed"].is_number_unsigned()) << "read back as a seed";
  // Undo moves the controls back.
  document_.undoStack()->undo();
  EXPECT_EQ(page.seedSpin()->value(), 1);
  document_.undoStack()->undo();
  EXPECT_EQ(page.budgetSpin()->value(), 5000);
  document_.undoStack()->undo();
  EXPECT_EQ(method->currentData().toString(), QStringLiteral("exact"));
  EXPECT_EQ(document_.undoStack()->count(), 3) << "restoring the controls pushes nothing";
}

TEST_F(UndoCoverageTest, MatchingSettings) {
  MatchingPage page(&document_);
  EXPECT_EQ(document_.undoStack()->count(), 0);
  page.setTolerance(0.02);
  page.setMethod(matching::MatchMethod::Minimax);
  page.setLocked(5, true);  // z (the DOF order is rx, ry, rz, x, y, z)
  auto* tolerance = page.findChild<QDoubleSpinBox*>(QStringLiteral("matchingTolerance"));
  ASSERT_NE(tolerance, nullptr);
  expectUndoRedo(3, [](nlohmann::json& j) {
    j["studies"]["matching"]["tolerance_mm"] = 0.02;
    j["studies"]["matching"]["method"] = "minimax";
    j["studies"]["matching"]["locks"] = "z";
  });
}

TEST_F(UndoCoverageTest, ThermalModelSettings) {
  ThermalPage page(&document_);
  ThermalModelView* view = page.modelView();
  auto* seed = view->findChild<QSpinBox*>(QStringLiteral("thermalModelSeed"));
  auto* fraction = view->findChild<QDoubleSpinBox*>(QStringLiteral("thermalModelTrainFraction"));
  ASSERT_TRUE(seed && fraction);
  EXPECT_EQ(document_.undoStack()->count(), 0);
  seed->setValue(9);
  emit seed->editingFinished();
  fraction->setValue(0.6);
  emit fraction->editingFinished();
  expectUndoRedo(2, [](nlohmann::json& j) {
    j["studies"]["thermal"]["seed"] = 9;
    j["studies"]["thermal"]["train_fraction"] = 0.6;
  });
}

TEST_F(UndoCoverageTest, RecoveringAnAutosaveIsOneStep) {
  Project recovered = document_.project();
  recovered.name = "recovered";
  recovered.studies["matching"]["tolerance_mm"] = 0.04;
  recovered.datasets.pop_back();
  recovered.results["setup"] = {{"f1", 0.1}};
  document_.replaceProject(recovered, QStringLiteral("Recover autosaved changes"));
  expectUndoRedo(1, [&](nlohmann::json& j) { j = recovered.toJson(); });
}

}  // namespace
}  // namespace metrofit
