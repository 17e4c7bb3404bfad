// Autosave and crash recovery (app/gui/autosave.h) without a main window: the side file is
// written after the interval with the document's content and without touching the undo stack, removed
// by a clean save, an undo back to the saved state and a discard; a newer side file is offered for
// recovery (the decision is injected) and the recovered project is modified, not saved; untitled
// projects; and a child process killed with SIGKILL while it edits and autosaves leaves an edit that
// the next start recovers.
#include <gtest/gtest.h>

#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QMessageBox>
#include <QProcess>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>
#include <functional>
#include <optional>
#include <vector>

#include "app/gui/autosave.h"
#include "core/common/error.h"
#include "core/common/rng.h"
#include "core/io/json_util.h"
#include "core/project/project.h"
#include "file_helpers.h"
#include "qtapp.h"
#include "testsupport.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"

namespace metrofit {
namespace {

using test::readAll;
using test::setModified;

class AutosaveTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    project_ = extractDemoProject(dir_.filePath(QStringLiteral("demo")));
    side_ = Autosave::autosaveFileFor(project_);
    untitled_ = dir_.filePath(QStringLiteral("untitled"));
  }
  /// An Autosave whose recovery decisions come from `choice` (and are recorded in offers_).
  std::unique_ptr<Autosave> makeAutosave(ProjectDocument& doc, RecoveryChoice choice) {
    auto a = std::make_unique<Autosave>(&doc);
    a->setIntervalMs(0);
    a->setUntitledFolder(untitled_);
    a->setDecider([this, choice](const RecoveryOffer& offer) {
      offers_.push_back(offer);
      return choice;
    });
    return a;
  }
  /// Writes a side file next to the project with the name changed, newer than the project.
  Project writeNewerSideFile(const std::string& name) {
    Project p = loadProject(project_.toStdString());
    p.name = name;
    p.studies["matching"]["tolerance_mm"] = 0.05;
    saveProject(p, side_.toStdString());
    const QDateTime now = QDateTime::currentDateTime();
    setModified(project_, now.addSecs(-60));
    setModified(side_, now);
    return p;
  }

  QTemporaryDir dir_;
  QString project_;
  QString side_;
  QString untitled_;
  std::vector<RecoveryOffer> offers_;
};

TEST_F(AutosaveTest, DefaultIntervalIsThreeMinutesFromTheSettings) {
  EXPECT_EQ(Autosave::intervalSetting(), 3);
  ProjectDocument doc;
  {
    Autosave a(&doc);
    EXPECT_EQ(a.intervalMs(), 3 * 60 * 1000);
  }
  Autosave::setIntervalSetting(7);
  EXPECT_EQ(Autosave::intervalSetting(), 7);
  {
    Autosave a(&doc);
    EXPECT_EQ(a.intervalMs(), 7 * 60 * 1000);
  }
  Autosave::setIntervalSetting(0);
  {
    Autosave a(&doc);
    EXPECT_EQ(a.intervalMs(), 0) << "0 turns autosave off";
  }
  Autosave::setIntervalSetting(Autosave::kDefaultIntervalMinutes);
  EXPECT_EQ(Autosave::autosaveFileFor(QStringLiteral("/w/cell.metrofit")),
            QStringLiteral("/w/cell.metrofit.autosave"));
}

TEST_F(AutosaveTest, WritesAfterTheIntervalWithTheDocumentContent) {
  ProjectDocument doc;
  doc.load(project_);
  auto a = makeAutosave(doc, RecoveryChoice::Recover);
  QSignalSpy written(a.get(), &Autosave::written);
  a->setIntervalMs(50);
  QTest::qWait(200);
  EXPECT_EQ(written.count(), 0) << "a clean document is not autosaved";
  EXPECT_FALSE(QFileInfo::exists(side_));

  doc.setValue(ProjectField::name(), QStringLiteral("edited cell"));
  doc.setStudyValue(QStringLiteral("matching"), QStringLiteral("/tolerance_mm"), 0.02, QStringLiteral("tol"));
  const int count = doc.undoStack()->count();
  const int index = doc.undoStack()->index();
  ASSERT_TRUE(written.wait(5000));
  EXPECT_EQ(written.first().first().toString(), side_);
  EXPECT_EQ(a->writtenFile(), side_);
  EXPECT_EQ(readAll(side_), dumpJson(doc.project().toJson())) << "the side file is the in-memory document";
  EXPECT_EQ(loadProject(side_.toStdString()), doc.project());
  EXPECT_NE(loadProject(project_.toStdString()).name, "edited cell") << "the project file is untouched";
  // Autosaving only reads: the undo stack and the modified flag are as they were.
  EXPECT_TRUE(doc.isModified());
  EXPECT_EQ(doc.undoStack()->count(), count);
  EXPECT_EQ(doc.undoStack()->index(), index);
  EXPECT_EQ(doc.undoStack()->undoText(), QStringLiteral("tol"));

  // Nothing new: the timer does not write again; a new edit is written on the next tick.
  a->setIntervalMs(0);
  EXPECT_FALSE(a->tick());
  doc.setValue(ProjectField::description(), QStringLiteral("second edit"));
  EXPECT_TRUE(a->tick());
  a->waitForWrite();
  EXPECT_EQ(loadProject(side_.toStdString()).description, "second edit");
  EXPECT_EQ(written.count(), 2);
  // No temporary files of the atomic writes stay behind.
  for (const QString& f : QDir(QFileInfo(project_).path()).entryList(QDir::Files))
    EXPECT_FALSE(f.contains(QLatin1String(".tmp-"))) << f.toStdString();
}

TEST_F(AutosaveTest, TickTakesLittleTimeOnTheGuiThread) {
  ProjectDocument doc;
  doc.load(project_);
  auto a = makeAutosave(doc, RecoveryChoice::Recover);
  doc.setValue(ProjectField::name(), QStringLiteral("timed"));
  QElapsedTimer timer;
  timer.start();
  ASSERT_TRUE(a->tick());
  const qint64 tickNs = timer.nsecsElapsed();
  a->waitForWrite();
  const qint64 totalNs = timer.nsecsElapsed();
  std::printf("autosave of the demo project (%zu bytes): tick() %.3f ms on the GUI thread, write %.3f ms\n",
              readAll(side_).size(), tickNs / 1e6, totalNs / 1e6);
  EXPECT_LT(tickNs, 100'000'000) << "serialising the project took more than 100 ms";
}

TEST_F(AutosaveTest, CleanSaveUndoToSavedAndDiscardRemoveTheSideFile) {
  ProjectDocument doc;
  doc.load(project_);
  auto a = makeAutosave(doc, RecoveryChoice::Recover);

  doc.setValue(ProjectField::name(), QStringLiteral("to be saved"));
  ASSERT_TRUE(a->tick());
  a->waitForWrite();
  ASSERT_TRUE(QFileInfo::exists(side_));
  doc.save();
  EXPECT_FALSE(QFileInfo::exists(side_)) << "a clean save removes the side file";
  EXPECT_TRUE(a->writtenFile().isEmpty());

  doc.setValue(ProjectField::name(), QStringLiteral("undone"));
  ASSERT_TRUE(a->tick());
  a->waitForWrite();
  ASSERT_TRUE(QFileInfo::exists(side_));
  doc.undoStack()->undo();
  EXPECT_FALSE(QFileInfo::exists(side_)) << "back at the saved state: nothing to recover";

  doc.setValue(ProjectField::name(), QStringLiteral("discarded"));
  ASSERT_TRUE(a->tick());
  a->waitForWrite();
  ASSERT_TRUE(QFileInfo::exists(side_));
  a->removeWritten();  // the main window's Discard and clean close
  EXPECT_FALSE(QFileInfo::exists(side_));

  // A save while the worker writes: the copy it finishes is removed too.
  doc.setValue(ProjectField::name(), QStringLiteral("saved while writing"));
  ASSERT_TRUE(a->tick());
  doc.save();
  a->waitForWrite();
  EXPECT_FALSE(QFileInfo::exists(side_));
}

TEST_F(AutosaveTest, UntitledProjectsGoToTheAutosaveFolderAndSaveAsRemovesIt) {
  ProjectDocument doc;
  auto a = makeAutosave(doc, RecoveryChoice::Recover);
  doc.setValue(ProjectField::name(), QStringLiteral("never saved"));
  ASSERT_TRUE(a->tick());
  a->waitForWrite();
  const QString expected = QDir(untitled_).filePath(
      QStringLiteral("untitled-%1.metrofit.autosave").arg(QCoreApplication::applicationPid()));
  EXPECT_EQ(a->writtenFile(), expected);
  EXPECT_EQ(loadProject(expected.toStdString()).name, "never saved");
  EXPECT_TRUE(a->orphanedUntitledFile().isEmpty()) << "this process's own file is not an orphan";

  doc.saveAs(dir_.filePath(QStringLiteral("named.metrofit")));
  EXPECT_FALSE(QFileInfo::exists(expected));
  EXPECT_FALSE(QFileInfo::exists(Autosave::autosaveFileFor(dir_.filePath(QStringLiteral("named.metrofit")))));
}

TEST_F(AutosaveTest, NewerSideFileIsOfferedAndRecoveredAsAModifiedDocument) {
  const Project original = loadProject(project_.toStdString());
  const Project autosaved = writeNewerSideFile("recovered cell");
  ProjectDocument doc;
  auto a = makeAutosave(doc, RecoveryChoice::Recover);
  EXPECT_EQ(a->open(project_), RecoveryChoice::Recover);
  ASSERT_EQ(offers_.size(), 1u);
  EXPECT_EQ(offers_[0].projectFile, QFileInfo(project_).absoluteFilePath());
  EXPECT_EQ(offers_[0].autosaveFile, side_);
  EXPECT_EQ(offers_[0].projectName, QStringLiteral("recovered cell"));
  EXPECT_GT(offers_[0].autosaved, offers_[0].saved);

  EXPECT_EQ(doc.project(), autosaved);
  EXPECT_EQ(doc.fileName(), QFileInfo(project_).absoluteFilePath());
  EXPECT_TRUE(doc.isModified());
  EXPECT_EQ(loadProject(project_.toStdString()), original) << "nothing is written over the original";
  // The recovery is one undo step back to the project as saved.
  EXPECT_EQ(doc.undoStack()->undoText(), QStringLiteral("Recover autosaved changes"));
  doc.undoStack()->undo();
  EXPECT_EQ(doc.project(), original);
  EXPECT_FALSE(doc.isModified());
  doc.undoStack()->redo();
  EXPECT_EQ(doc.project(), autosaved);
  // Saving makes it the project and removes the side file.
  doc.save();
  EXPECT_EQ(loadProject(project_.toStdString()), autosaved);
  EXPECT_FALSE(QFileInfo::exists(side_));
}

TEST_F(AutosaveTest, DiscardDeletesTheSideFileOpenOriginalKeepsIt) {
  const Project original = loadProject(project_.toStdString());
  writeNewerSideFile("kept");
  {
    ProjectDocument doc;
    auto a = makeAutosave(doc, RecoveryChoice::OpenOriginal);
    EXPECT_EQ(a->open(project_), RecoveryChoice::OpenOriginal);
    EXPECT_EQ(doc.project(), original);
    EXPECT_FALSE(doc.isModified());
    EXPECT_TRUE(QFileInfo::exists(side_)) << "kept for later";
  }
  ProjectDocument doc;
  auto a = makeAutosave(doc, RecoveryChoice::Discard);
  EXPECT_EQ(a->open(project_), RecoveryChoice::Discard);
  EXPECT_EQ(offers_.size(), 2u) << "offered again the second time";
  EXPECT_EQ(doc.project(), original);
  EXPECT_FALSE(doc.isModified());
  EXPECT_FALSE(QFileInfo::exists(side_));
  EXPECT_EQ(a->open(project_), std::nullopt) << "nothing left to offer";
}

TEST_F(AutosaveTest, OlderOrBrokenSideFilesAreNotOffered) {
  writeNewerSideFile("older");
  const QDateTime now = QDateTime::currentDateTime();
  setModified(project_, now);
  setModified(side_, now.addSecs(-60));
  ProjectDocument doc;
  auto a = makeAutosave(doc, RecoveryChoice::Recover);
  EXPECT_EQ(a->open(project_), std::nullopt);
  EXPECT_TRUE(offers_.empty());
  EXPECT_FALSE(doc.isModified());

  QFile broken(side_);
  ASSERT_TRUE(broken.open(QIODevice::WriteOnly | QIODevice::Truncate));
  broken.write("{\"format\": \"metrofit-project\", trunc");
  broken.close();
  setModified(side_, now.addSecs(60));
  QSignalSpy failed(a.get(), &Autosave::failed);
  EXPECT_EQ(a->open(project_), std::nullopt);
  EXPECT_TRUE(offers_.empty());
  ASSERT_EQ(failed.count(), 1);
  EXPECT_TRUE(
      failed.first().first().toString().startsWith(QStringLiteral("The autosaved copy cannot be read: ")))
      << failed.first().first().toString().toStdString();
  EXPECT_EQ(doc.fileName(), QFileInfo(project_).absoluteFilePath());
}

TEST_F(AutosaveTest, OpeningAMissingProjectThrowsAndKeepsTheDocument) {
  ProjectDocument doc;
  doc.load(project_);
  auto a = makeAutosave(doc, RecoveryChoice::Recover);
  EXPECT_THROW(a->open(dir_.filePath(QStringLiteral("missing.metrofit"))), InputError);
  EXPECT_EQ(doc.fileName(), QFileInfo(project_).absoluteFilePath());
}

TEST_F(AutosaveTest, UntitledSideFileOfAFinishedProcessIsRecovered) {
  ASSERT_TRUE(QDir().mkpath(untitled_));
  Project p;
  p.name = "orphan";
  p.description = "typed before the crash";
  // 2^31 - 2: larger than any pid Linux hands out (pid_max is at most 2^22), so no process runs with it.
  const QString orphan = QDir(untitled_).filePath(QStringLiteral("untitled-2147483646.metrofit.autosave"));
  saveProject(p, orphan.toStdString());
  // One of a running process (ours) is never offered.
  const QString running = QDir(untitled_).filePath(
      QStringLiteral("untitled-%1.metrofit.autosave").arg(QCoreApplication::applicationPid()));
  Project mine;
  mine.name = "mine";
  saveProject(mine, running.toStdString());
  setModified(running, QDateTime::currentDateTime().addSecs(60));

  ProjectDocument doc;
  auto a = makeAutosave(doc, RecoveryChoice::Recover);
  EXPECT_EQ(a->orphanedUntitledFile(), orphan);
  EXPECT_EQ(a->recoverUntitled(), RecoveryChoice::Recover);
  ASSERT_EQ(offers_.size(), 1u);
  EXPECT_TRUE(offers_[0].projectFile.isEmpty());
  EXPECT_EQ(offers_[0].projectName, QStringLiteral("orphan"));
  EXPECT_EQ(doc.project(), p);
  EXPECT_TRUE(doc.fileName().isEmpty());
  EXPECT_TRUE(doc.isModified());

  // The next autosave goes to this process's file and the recovered orphan is gone.
  doc.setValue(ProjectField::name(), QStringLiteral("orphan, continued"));
  ASSERT_TRUE(a->tick());
  a->waitForWrite();
  EXPECT_FALSE(QFileInfo::exists(orphan));
  EXPECT_EQ(loadProject(running.toStdString()).name, "orphan, continued");
  EXPECT_TRUE(a->orphanedUntitledFile().isEmpty());
}

TEST_F(AutosaveTest, UntitledDiscardDeletesTheOrphan) {
  ASSERT_TRUE(QDir().mkpath(untitled_));
  const QString orphan = QDir(untitled_).filePath(QStringLiteral("untitled-2147483646.metrofit.autosave"));
  saveProject(Project{}, orphan.toStdString());
  ProjectDocument doc;
  auto a = makeAutosave(doc, RecoveryChoice::Discard);
  EXPECT_EQ(a->recoverUntitled(), RecoveryChoice::Discard);
  EXPECT_FALSE(QFileInfo::exists(orphan));
  EXPECT_FALSE(doc.isModified());
  EXPECT_EQ(a->recoverUntitled(), std::nullopt);
}

/// Clicks the button with this text on the next modal message box, after saving a grab of it to
/// $METROFIT_TEST_OUT/autosave/<grab>.png for people to look at.
void clickOnNextMessageBox(const QString& buttonText, const QString& grab, QString* text) {
  auto* timer = new QTimer;
  timer->setInterval(20);
  QObject::connect(timer, &QTimer::timeout, [timer, buttonText, grab, text] {
    auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
    if (box == nullptr) return;
    timer->stop();
    timer->deleteLater();
    *text = box->text();
    const QString dir = QString::fromStdString((test::outDir() / "autosave").string());
    QDir().mkpath(dir);
    box->grab().save(dir + QLatin1Char('/') + grab + QStringLiteral(".png"));
    for (QAbstractButton* b : box->buttons())
      if (b->text() == buttonText) b->click();
  });
  timer->start();
}

TEST_F(AutosaveTest, TheRecoveryDialogOffersThreeChoices) {
  const QDateTime now = QDateTime::currentDateTime();
  const RecoveryOffer offer{QStringLiteral("/work/cell 4.metrofit"),
                            QStringLiteral("/work/cell 4.metrofit.autosave"),
                            now,
                            now.addSecs(-600),
                            QStringLiteral("Cell 4"),
                            {}};
  QString text;
  clickOnNextMessageBox(QStringLiteral("&Recover"), QStringLiteral("recover-project"), &text);
  EXPECT_EQ(Autosave::askUser(nullptr, offer), RecoveryChoice::Recover);
  EXPECT_TRUE(text.contains(QStringLiteral("/work/cell 4.metrofit"))) << text.toStdString();
  clickOnNextMessageBox(QStringLiteral("&Discard"), QStringLiteral("discard"), &text);
  EXPECT_EQ(Autosave::askUser(nullptr, offer), RecoveryChoice::Discard);
  clickOnNextMessageBox(QStringLiteral("&Open original"), QStringLiteral("original"), &text);
  EXPECT_EQ(Autosave::askUser(nullptr, offer), RecoveryChoice::OpenOriginal);
  const RecoveryOffer untitled{QString(),
                               QStringLiteral("/tmp/untitled-7.metrofit.autosave"),
                               now,
                               QDateTime(),
                               QStringLiteral("Cell 5"),
                               {}};
  clickOnNextMessageBox(QStringLiteral("&Keep for later"), QStringLiteral("recover-untitled"), &text);
  EXPECT_EQ(Autosave::askUser(nullptr, untitled), RecoveryChoice::OpenOriginal);
  EXPECT_TRUE(text.contains(QStringLiteral("“Cell 5”"))) << text.toStdString();
}

// A child process (autosave_child) opens the project, edits the name ("edit <n>") and autosaves
// over and over; it is killed with SIGKILL at a random moment. The next start recovers the last edit
// it autosaved (or the one it was writing), and the side file is always a complete project.
TEST_F(AutosaveTest, KilledWhileEditingTheNextStartRecoversTheEdit) {
  const Project original = loadProject(project_.toStdString());
  Rng rng(20261121);
  constexpr int kKills = 6;
  for (int k = 0; k < kKills; ++k) {
    QFile::remove(side_);
    QProcess child;
    child.setProgram(QStringLiteral(METROFIT_AUTOSAVE_CHILD));
    child.setArguments({project_});
    child.start();
    ASSERT_TRUE(child.waitForStarted(10000));
    // Wait until it reports a first autosave, then kill it a random 0-30 ms later.
    QByteArray out;
    while (!out.contains("autosaved ") && child.state() == QProcess::Running) {
      child.waitForReadyRead(10000);
      out += child.readAllStandardOutput();
    }
    ASSERT_TRUE(out.contains("autosaved ")) << child.readAllStandardError().toStdString();
    QTest::qWait(static_cast<int>(rng.uniform() * 30));
    child.kill();  // SIGKILL
    ASSERT_TRUE(child.waitForFinished(10000));
    EXPECT_EQ(child.exitStatus(), QProcess::CrashExit);
    out += child.readAllStandardOutput();
    // The last edit the child reported as autosaved.
    const QList<QByteArray> lines = out.split('\n');
    int lastReported = -1;
    for (const QByteArray& line : lines)
      if (line.startsWith("autosaved ")) lastReported = line.mid(10).toInt();
    ASSERT_GE(lastReported, 0);

    ProjectDocument doc;
    auto a = makeAutosave(doc, RecoveryChoice::Recover);
    ASSERT_EQ(a->open(project_), RecoveryChoice::Recover) << "kill " << k;
    const std::string name = doc.project().name;
    ASSERT_EQ(name.rfind("edit ", 0), 0u) << name;
    const int recovered = std::stoi(name.substr(5));
    // The side file holds the last reported edit, or the next one when the kill came after its
    // rename but before the report.
    EXPECT_TRUE(recovered == lastReported || recovered == lastReported + 1)
        << "recovered " << recovered << ", last reported " << lastReported;
    EXPECT_TRUE(doc.isModified());
    Project expected = original;
    expected.name = name;
    expected.description = "autosave child";
    EXPECT_EQ(doc.project(), expected);
    EXPECT_EQ(loadProject(project_.toStdString()), original) << "the project file is never written";
    offers_.clear();
    doc.undoStack()->setClean();  // leaves the side file for the next round to replace
  }
}

}  // namespace
}  // namespace metrofit
