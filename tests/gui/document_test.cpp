// ProjectDocument (undo/redo, merging, modified state, atomic save/load, file watching) and the
// bundled demo project.
#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <cstdio>

#include "core/common/error.h"
#include "core/matching/probe_points.h"
#include "core/project/project.h"
#include "core/thermal/thermal_log.h"
#include "qtapp.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"

namespace metrofit {
namespace {

void writeText(const QString& path, const QByteArray& text) {
  QFile f(path);
  ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate)) << path.toStdString();
  ASSERT_EQ(f.write(text), text.size());
}

class DocumentTest : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(dir_.isValid()); }
  QString path(const QString& name) const { return dir_.filePath(name); }

  QTemporaryDir dir_;
  ProjectDocument doc_;
};

TEST_F(DocumentTest, NewDocumentIsCleanAndUntitled) {
  EXPECT_FALSE(doc_.isModified());
  EXPECT_TRUE(doc_.fileName().isEmpty());
  EXPECT_EQ(doc_.project(), Project{});
  EXPECT_EQ(doc_.displayName(), QStringLiteral("Untitled"));
}

TEST_F(DocumentTest, NameEditIsUndoableAndRedoable) {
  doc_.setValue(ProjectField::name(), QStringLiteral("Cell 4"));
  EXPECT_EQ(doc_.project().name, "Cell 4");
  EXPECT_EQ(doc_.undoStack()->count(), 1);
  EXPECT_EQ(doc_.undoStack()->undoText(), QStringLiteral("Rename project"));
  doc_.undoStack()->undo();
  EXPECT_EQ(doc_.project().name, "Untitled");
  EXPECT_FALSE(doc_.isModified());
  doc_.undoStack()->redo();
  EXPECT_EQ(doc_.project().name, "Cell 4");
  EXPECT_TRUE(doc_.isModified());
}

TEST_F(DocumentTest, SettingTheSameValuePushesNothing) {
  doc_.setValue(ProjectField::name(), QStringLiteral("Untitled"));
  EXPECT_EQ(doc_.undoStack()->count(), 0);
  EXPECT_FALSE(doc_.isModified());
}

TEST_F(DocumentTest, DescriptionEditIsUndoable) {
  QSignalSpy fieldSpy(&doc_, &ProjectDocument::fieldChanged);
  doc_.setValue(ProjectField::description(), QStringLiteral("Spindle growth on the DMU 50"));
  EXPECT_EQ(doc_.project().description, "Spindle growth on the DMU 50");
  ASSERT_EQ(fieldSpy.count(), 1);
  EXPECT_EQ(fieldSpy.at(0).at(0).value<ProjectField>(), ProjectField::description());
  doc_.undoStack()->undo();
  EXPECT_EQ(doc_.project().description, "");
}

TEST_F(DocumentTest, ConsecutiveTypingMergesIntoOneUndoStep) {
  for (const char* text : {"D", "De", "Dem", "Demo"})
    doc_.setValue(ProjectField::name(), QString::fromLatin1(text));
  EXPECT_EQ(doc_.undoStack()->count(), 1);
  EXPECT_EQ(doc_.project().name, "Demo");
  // A different field does not merge.
  doc_.setValue(ProjectField::description(), QStringLiteral("x"));
  EXPECT_EQ(doc_.undoStack()->count(), 2);
  doc_.undoStack()->undo();
  doc_.undoStack()->undo();
  EXPECT_EQ(doc_.project().name, "Untitled");
  EXPECT_FALSE(doc_.isModified());
}

TEST_F(DocumentTest, EndingTheEditSequenceStopsMerging) {
  doc_.setValue(ProjectField::name(), QStringLiteral("A"));
  doc_.setValue(ProjectField::name(), QStringLiteral("AB"));
  doc_.endEditSequence();
  doc_.setValue(ProjectField::name(), QStringLiteral("ABC"));
  EXPECT_EQ(doc_.undoStack()->count(), 2);
  doc_.undoStack()->undo();
  EXPECT_EQ(doc_.project().name, "AB");
  doc_.undoStack()->undo();
  EXPECT_EQ(doc_.project().name, "Untitled");
}

TEST_F(DocumentTest, TypingBackToTheOriginalLeavesNothingToUndo) {
  doc_.setValue(ProjectField::name(), QStringLiteral("Untitled2"));
  EXPECT_TRUE(doc_.isModified());
  doc_.setValue(ProjectField::name(), QStringLiteral("Untitled"));
  EXPECT_EQ(doc_.undoStack()->count(), 0);
  EXPECT_FALSE(doc_.isModified());
}

TEST_F(DocumentTest, StudyNotesAreUndoneExactly) {
  const Project before = doc_.project();
  doc_.setValue(ProjectField::studyNotes(QStringLiteral("thermal")), QStringLiteral("Sensor T3 loose"));
  EXPECT_EQ(doc_.project().studies["thermal"]["notes"], "Sensor T3 loose");
  EXPECT_EQ(doc_.undoStack()->undoText(), QStringLiteral("Edit notes of Thermal"));
  doc_.undoStack()->undo();
  // The study object did not exist: undo removes it again, the project is exactly as before.
  EXPECT_EQ(doc_.project(), before);
  EXPECT_FALSE(doc_.project().studies.contains("thermal"));
}

TEST_F(DocumentTest, StudyNotesKeepTheStudySettings) {
  writeText(path(QStringLiteral("p.metrofit")),
            R"({"format": "metrofit-project", "version": 1, "name": "P",
                "studies": {"thermal": {"target": "disp_z_um"}}})");
  doc_.load(path(QStringLiteral("p.metrofit")));
  const Project before = doc_.project();
  doc_.setValue(ProjectField::studyNotes(QStringLiteral("thermal")), QStringLiteral("n"));
  EXPECT_EQ(doc_.project().studies["thermal"]["target"], "disp_z_um");
  doc_.undoStack()->undo();
  EXPECT_EQ(doc_.project(), before);
}

TEST_F(DocumentTest, StudyValueIsUndoableAndRedoable) {
  QSignalSpy changed(&doc_, &ProjectDocument::changed);
  QSignalSpy valueSpy(&doc_, &ProjectDocument::studyValueChanged);
  EXPECT_TRUE(doc_.studyValue(QStringLiteral("matching"), QStringLiteral("/tolerance_mm")).is_null());
  doc_.setStudyValue(QStringLiteral("matching"), QStringLiteral("/tolerance_mm"), 0.02,
                     QStringLiteral("Change tolerance"));
  EXPECT_EQ(doc_.project().studies, (nlohmann::json{{"matching", {{"tolerance_mm", 0.02}}}}));
  EXPECT_EQ(doc_.studyValue(QStringLiteral("matching"), QStringLiteral("/tolerance_mm")),
            nlohmann::json(0.02));
  EXPECT_EQ(doc_.undoStack()->count(), 1);
  EXPECT_EQ(doc_.undoStack()->undoText(), QStringLiteral("Change tolerance"));
  EXPECT_TRUE(doc_.isModified());
  EXPECT_EQ(changed.count(), 1);
  ASSERT_EQ(valueSpy.count(), 1);
  EXPECT_EQ(valueSpy.at(0).at(0).toString(), QStringLiteral("matching"));
  EXPECT_EQ(valueSpy.at(0).at(1).toString(), QStringLiteral("/tolerance_mm"));

  doc_.undoStack()->undo();
  EXPECT_EQ(doc_.project().studies, nlohmann::json::object()) << "the created study is removed again";
  EXPECT_FALSE(doc_.isModified());
  EXPECT_EQ(changed.count(), 2);
  doc_.undoStack()->redo();
  EXPECT_EQ(doc_.studyValue(QStringLiteral("matching"), QStringLiteral("/tolerance_mm")),
            nlohmann::json(0.02));
  EXPECT_TRUE(doc_.isModified());
  EXPECT_EQ(changed.count(), 3);
}

TEST_F(DocumentTest, NestedStudyValueIsUndoneExactly) {
  const nlohmann::json before = {{"notes", "n"}, {"thermal", "not an object"}, {"setup", {{"applied", 1}}}};
  doc_.setValue(ProjectField::studyNotes(QStringLiteral("diagnosis")), QStringLiteral("n"));
  doc_.endEditSequence();
  doc_.setStudyValue(QStringLiteral("diagnosis"), QStringLiteral("/thermal"), "not an object",
                     QStringLiteral("a"));
  doc_.setStudyValue(QStringLiteral("diagnosis"), QStringLiteral("/setup/applied"), 1, QStringLiteral("b"));
  doc_.endEditSequence();
  ASSERT_EQ(doc_.project().studies["diagnosis"], before);
  const nlohmann::json applied = nlohmann::json::array({{{"name", "drift"}, {"per_min", 0.1}}});
  doc_.setStudyValue(QStringLiteral("diagnosis"), QStringLiteral("/thermal/applied"), applied,
                     QStringLiteral("Apply"));
  EXPECT_EQ(doc_.studyValue(QStringLiteral("diagnosis"), QStringLiteral("/thermal/applied")), applied);
  EXPECT_EQ(doc_.studyValue(QStringLiteral("diagnosis"), QStringLiteral("/setup")),
            nlohmann::json({{"applied", 1}}));
  EXPECT_TRUE(doc_.studyValue(QStringLiteral("diagnosis"), QStringLiteral("/kinematic/applied")).is_null());
  EXPECT_TRUE(doc_.studyValue(QStringLiteral("nosuch"), QStringLiteral("")).is_null());
  doc_.undoStack()->undo();
  EXPECT_EQ(doc_.project().studies["diagnosis"], before);
  // A null value removes the member.
  doc_.setStudyValue(QStringLiteral("diagnosis"), QStringLiteral("/setup"), nullptr,
                     QStringLiteral("Remove"));
  EXPECT_FALSE(doc_.project().studies["diagnosis"].contains("setup"));
  doc_.undoStack()->undo();
  EXPECT_EQ(doc_.project().studies["diagnosis"], before);
}

TEST_F(DocumentTest, SettingTheSameStudyValuePushesNothing) {
  doc_.setStudyValue(QStringLiteral("thermal"), QStringLiteral("/seed"), 7, QStringLiteral("Seed"));
  doc_.endEditSequence();
  QSignalSpy changed(&doc_, &ProjectDocument::changed);
  doc_.setStudyValue(QStringLiteral("thermal"), QStringLiteral("/seed"), 7, QStringLiteral("Seed"));
  doc_.setStudyValue(QStringLiteral("thermal"), QStringLiteral("/absent"), nullptr, QStringLiteral("Remove"));
  EXPECT_EQ(doc_.undoStack()->count(), 1);
  EXPECT_EQ(changed.count(), 0);
}

TEST_F(DocumentTest, StudyValueTypingMergesAndEndingTheSequenceStops) {
  const QString study = QStringLiteral("thermal");
  const QString key = QStringLiteral("/train_fraction");
  doc_.setStudyValue(study, QStringLiteral("/dataset"), "log", QStringLiteral("Dataset"));
  doc_.endEditSequence();
  doc_.setStudyValue(study, key, 0.6, QStringLiteral("Fraction"));
  doc_.setStudyValue(study, key, 0.65, QStringLiteral("Fraction"));
  doc_.setStudyValue(study, key, 0.7, QStringLiteral("Fraction"));
  EXPECT_EQ(doc_.undoStack()->count(), 2) << "typing in one field is one undo step";
  doc_.setStudyValue(study, QStringLiteral("/seed"), 3, QStringLiteral("Seed"));
  EXPECT_EQ(doc_.undoStack()->count(), 3) << "another key does not merge";
  doc_.undoStack()->undo();
  doc_.undoStack()->undo();
  EXPECT_EQ(doc_.project().studies[study.toStdString()], nlohmann::json({{"dataset", "log"}}));
  doc_.undoStack()->redo();
  doc_.endEditSequence();
  doc_.setStudyValue(study, key, 0.8, QStringLiteral("Fraction"));
  EXPECT_EQ(doc_.undoStack()->count(), 3) << "after endEditSequence a new step starts";
  // Typing back to the original value leaves nothing to undo.
  doc_.endEditSequence();
  doc_.setStudyValue(study, key, 0.75, QStringLiteral("Fraction"));
  doc_.setStudyValue(study, key, 0.8, QStringLiteral("Fraction"));
  EXPECT_EQ(doc_.undoStack()->count(), 3);
  EXPECT_EQ(doc_.studyValue(study, key), nlohmann::json(0.8));
}

TEST_F(DocumentTest, StudyValueSurvivesSaveAndReload) {
  doc_.setValue(ProjectField::studyNotes(QStringLiteral("matching")), QStringLiteral("fixture B"));
  doc_.setStudyValue(QStringLiteral("matching"), QStringLiteral("/tolerance_mm"), 0.025,
                     QStringLiteral("Tol"));
  doc_.setStudyValue(QStringLiteral("matching"), QStringLiteral("/locks"), "z,rz", QStringLiteral("Locks"));
  const QString file = path(QStringLiteral("study.metrofit"));
  doc_.saveAs(file);
  EXPECT_FALSE(doc_.isModified());
  ProjectDocument other;
  other.load(file);
  EXPECT_EQ(other.project().studies, doc_.project().studies);
  EXPECT_EQ(other.studyValue(QStringLiteral("matching"), QStringLiteral("/tolerance_mm")),
            nlohmann::json(0.025));
  EXPECT_EQ(other.studyValue(QStringLiteral("matching"), QStringLiteral("/locks")), nlohmann::json("z,rz"));
  EXPECT_EQ(other.value(ProjectField::studyNotes(QStringLiteral("matching"))), QStringLiteral("fixture B"));
}

TEST_F(DocumentTest, ModifiedFollowsTheCleanState) {
  QSignalSpy spy(&doc_, &ProjectDocument::modifiedChanged);
  doc_.setValue(ProjectField::name(), QStringLiteral("A"));
  ASSERT_EQ(spy.count(), 1);
  EXPECT_TRUE(spy.takeFirst().at(0).toBool());
  doc_.saveAs(path(QStringLiteral("a.metrofit")));
  EXPECT_FALSE(doc_.isModified());
  ASSERT_EQ(spy.count(), 1);
  EXPECT_FALSE(spy.takeFirst().at(0).toBool());
  // After a save, a new edit does not merge into the saved one: undo returns to the saved state.
  doc_.setValue(ProjectField::name(), QStringLiteral("AB"));
  EXPECT_TRUE(doc_.isModified());
  doc_.undoStack()->undo();
  EXPECT_FALSE(doc_.isModified());
  EXPECT_EQ(doc_.project().name, "A");
  doc_.undoStack()->undo();  // before the save: modified again
  EXPECT_TRUE(doc_.isModified());
  EXPECT_EQ(doc_.project().name, "Untitled");
}

TEST_F(DocumentTest, SaveAndLoadRoundTrip) {
  doc_.setValue(ProjectField::name(), QStringLiteral("Zelle 3 — Łódź"));
  doc_.setValue(ProjectField::description(), QStringLiteral("line one\nline two"));
  doc_.setValue(ProjectField::studyNotes(QStringLiteral("matching")), QStringLiteral("fixture B"));
  QSignalSpy nameSpy(&doc_, &ProjectDocument::fileNameChanged);
  const QString file = path(QStringLiteral("round.metrofit"));
  doc_.saveAs(file);
  EXPECT_EQ(doc_.fileName(), QFileInfo(file).absoluteFilePath());
  EXPECT_EQ(nameSpy.count(), 1);
  EXPECT_FALSE(doc_.isModified());
  // No temporary file is left next to the project.
  EXPECT_EQ(QDir(dir_.path()).entryList(QDir::Files), QStringList{QStringLiteral("round.metrofit")});

  ProjectDocument other;
  other.load(file);
  EXPECT_EQ(other.project(), doc_.project());
  EXPECT_EQ(other.project().name, "Zelle 3 — Łódź");
  EXPECT_EQ(other.fileName(), doc_.fileName());
  EXPECT_FALSE(other.isModified());
  EXPECT_EQ(other.undoStack()->count(), 0);

  // save() writes to the same file again.
  other.setValue(ProjectField::name(), QStringLiteral("renamed"));
  other.save();
  EXPECT_EQ(loadProject(file.toStdString()).name, "renamed");
}

TEST_F(DocumentTest, SaveWithoutAFileNameThrows) {
  doc_.setValue(ProjectField::name(), QStringLiteral("A"));
  EXPECT_THROW(doc_.save(), FileError);
  EXPECT_TRUE(doc_.isModified());
}

TEST_F(DocumentTest, SaveToAnUnwritablePathThrowsAndKeepsTheDocument) {
  const QString good = path(QStringLiteral("good.metrofit"));
  doc_.saveAs(good);
  doc_.setValue(ProjectField::name(), QStringLiteral("edited"));
  const Project before = doc_.project();
  // A path below a regular file cannot be written, not even by root.
  writeText(path(QStringLiteral("blocker")), "x");
  const QString bad = path(QStringLiteral("blocker/p.metrofit"));
  QSignalSpy nameSpy(&doc_, &ProjectDocument::fileNameChanged);
  try {
    doc_.saveAs(bad);
    FAIL() << "saveAs to " << bad.toStdString() << " did not throw";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("blocker/p.metrofit"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line: " << e.what();
  }
  EXPECT_TRUE(doc_.isModified());
  EXPECT_EQ(doc_.project(), before);
  EXPECT_EQ(doc_.fileName(), QFileInfo(good).absoluteFilePath());
  EXPECT_EQ(nameSpy.count(), 0);
  EXPECT_EQ(doc_.undoStack()->count(), 1);
  EXPECT_EQ(loadProject(good.toStdString()).name, "Untitled");  // the saved file is untouched
}

TEST_F(DocumentTest, FailedLoadKeepsTheDocument) {
  doc_.setValue(ProjectField::name(), QStringLiteral("work in progress"));
  const Project before = doc_.project();
  const QString broken = path(QStringLiteral("broken.metrofit"));
  writeText(broken, R"({"format": "metrofit-project", "version": 1, "name": )");
  EXPECT_THROW(doc_.load(broken), InputError);
  EXPECT_THROW(doc_.load(path(QStringLiteral("missing.metrofit"))), FileError);
  EXPECT_EQ(doc_.project(), before);
  EXPECT_TRUE(doc_.fileName().isEmpty());
  EXPECT_TRUE(doc_.isModified());
  EXPECT_EQ(doc_.undoStack()->count(), 1);
}

TEST_F(DocumentTest, NewProjectClearsEverything) {
  doc_.setValue(ProjectField::name(), QStringLiteral("A"));
  doc_.saveAs(path(QStringLiteral("a.metrofit")));
  doc_.setValue(ProjectField::name(), QStringLiteral("B"));
  doc_.newProject();
  EXPECT_EQ(doc_.project(), Project{});
  EXPECT_TRUE(doc_.fileName().isEmpty());
  EXPECT_FALSE(doc_.isModified());
  EXPECT_EQ(doc_.undoStack()->count(), 0);
}

TEST_F(DocumentTest, OwnSavesAreNotReportedAsChangesOnDisk) {
  const QString file = path(QStringLiteral("watched.metrofit"));
  doc_.saveAs(file);
  QSignalSpy spy(&doc_, &ProjectDocument::fileChangedOnDisk);
  for (const char* name : {"one", "two", "three"}) {
    doc_.setValue(ProjectField::name(), QString::fromLatin1(name));
    doc_.save();
  }
  EXPECT_FALSE(spy.wait(800));
  EXPECT_EQ(spy.count(), 0);
}

TEST_F(DocumentTest, ChangesByAnotherProgramAreReported) {
  const QString file = path(QStringLiteral("watched.metrofit"));
  doc_.saveAs(file);
  QSignalSpy spy(&doc_, &ProjectDocument::fileChangedOnDisk);
  // An editor that writes in place.
  writeText(file, R"({"format": "metrofit-project", "version": 1, "name": "changed elsewhere"})");
  ASSERT_TRUE(spy.wait(5000));
  EXPECT_EQ(spy.takeFirst().at(0).toString(), doc_.fileName());
  EXPECT_FALSE(spy.wait(500)) << "one change is reported once";
  // A program that saves atomically (write a new file, rename it over the old one): the watcher
  // must follow the new file.
  const QString temporary = path(QStringLiteral("watched.metrofit.new"));
  writeText(temporary, R"({"format": "metrofit-project", "version": 1, "name": "replaced elsewhere!"})");
  ASSERT_EQ(::rename(QFile::encodeName(temporary).constData(), QFile::encodeName(file).constData()), 0);
  ASSERT_TRUE(spy.wait(5000));
  spy.clear();
  writeText(file, R"({"format": "metrofit-project", "version": 1, "name": "and again, in place"})");
  EXPECT_TRUE(spy.wait(5000));
}

TEST_F(DocumentTest, SaveAsElsewhereKeepsDatasetsPointingAtTheSameFiles) {
  const QString original = extractDemoProject(path(QStringLiteral("demo")));
  doc_.load(original);
  QStringList before;
  for (const DatasetRef& d : doc_.project().datasets) before << doc_.datasetPath(d);
  ASSERT_TRUE(QDir(dir_.path()).mkpath(QStringLiteral("elsewhere")));
  doc_.saveAs(path(QStringLiteral("elsewhere/copy.metrofit")));
  for (const DatasetRef& d : doc_.project().datasets) {
    EXPECT_TRUE(QString::fromStdString(d.path).startsWith(QStringLiteral("../demo/data/"))) << d.path;
  }
  QStringList after;
  for (const DatasetRef& d : doc_.project().datasets) {
    after << doc_.datasetPath(d);
    EXPECT_TRUE(QFileInfo::exists(doc_.datasetPath(d))) << d.path;
  }
  EXPECT_EQ(after, before);
  ProjectDocument reloaded;
  reloaded.load(doc_.fileName());
  for (const DatasetRef& d : reloaded.project().datasets) {
    EXPECT_TRUE(QFileInfo::exists(reloaded.datasetPath(d))) << d.path;
  }
}

TEST(DemoProjectTest, ExtractsTheProjectAndItsData) {
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  const QString target = dir.filePath(QStringLiteral("new/folder"));
  const QString project = extractDemoProject(target);
  EXPECT_TRUE(QFileInfo(project).isFile());
  EXPECT_TRUE(QFileInfo(project).isAbsolute());
  EXPECT_TRUE(QFileInfo(project).isWritable());
  const QStringList bundled = QDir(QStringLiteral(":/demo/data")).entryList(QDir::Files);
  ASSERT_FALSE(bundled.isEmpty());
  for (const QString& name : bundled) {
    QFile resource(QStringLiteral(":/demo/data/") + name);
    ASSERT_TRUE(resource.open(QIODevice::ReadOnly));
    QFile copy(target + QStringLiteral("/data/") + name);
    ASSERT_TRUE(copy.open(QIODevice::ReadOnly)) << name.toStdString();
    EXPECT_EQ(copy.readAll(), resource.readAll()) << name.toStdString();
  }

  ProjectDocument doc;
  doc.load(project);
  ASSERT_FALSE(doc.project().datasets.empty());
  int thermalLogs = 0;
  int probeSets = 0;
  for (const DatasetRef& d : doc.project().datasets) {
    const std::string file = doc.datasetPath(d).toStdString();
    if (d.kind == dataset_kind::kThermalLog) {
      EXPECT_GT(readThermalLog(file).rows(), 10u) << file;
      ++thermalLogs;
    } else if (d.kind == dataset_kind::kProbePoints) {
      EXPECT_GE(readProbePoints(file).points.size(), 3u) << file;
      ++probeSets;
    }
  }
  EXPECT_GE(thermalLogs, 1);
  EXPECT_GE(probeSets, 1);

  // Extracting again over an existing copy replaces it.
  EXPECT_EQ(extractDemoProject(target), project);
}

// Help › Open demo project keeps a demo the user saved with edits (gui-run F15): a fresh or unchanged
// copy is reused, an edited one gets a sibling folder.
TEST(DemoProjectTest, AnEditedDemoIsNotOverwritten) {
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  const QString base = dir.filePath(QStringLiteral("demo"));
  EXPECT_EQ(demoFolderFor(base), base);  // nothing there yet
  const QString project = extractDemoProject(base);
  EXPECT_EQ(demoFolderFor(base), base);  // the bundled demo, unchanged: reused
  QFile file(project);
  ASSERT_TRUE(file.open(QIODevice::ReadOnly));
  QByteArray edited = file.readAll();
  file.close();
  edited.replace("Demo cell", "My cell");
  writeText(project, edited);
  EXPECT_EQ(demoFolderFor(base), base + QStringLiteral("-2"));
  extractDemoProject(base + QStringLiteral("-2"));
  EXPECT_EQ(demoFolderFor(base), base + QStringLiteral("-2"));  // the unchanged second copy
  // The edited demo is still there.
  ASSERT_TRUE(file.open(QIODevice::ReadOnly));
  EXPECT_TRUE(file.readAll().contains("My cell"));
}

TEST(DemoProjectTest, UnwritableFolderThrowsFileError) {
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  writeText(dir.filePath(QStringLiteral("file")), "x");
  EXPECT_THROW(extractDemoProject(dir.filePath(QStringLiteral("file/demo"))), FileError);
}

}  // namespace
}  // namespace metrofit
