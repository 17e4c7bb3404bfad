// The matching page (app/gui/matchingpage.h) under xvfb-run (QT_QPA_PLATFORM=xcb, the 3D views render):
// the S-piece project, Run in the worker with progress and Cancel, the results tables against
// core/matching, method / tolerance / lock controls, showView, the before / after views (pixels, linked
// camera) and bad data. Grabs go to $METROFIT_TEST_OUT/matchingpage for people to look at.
#include <gtest/gtest.h>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QLocale>
#include <QProcess>
#include <QPushButton>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>
#include <cmath>
#include <fstream>
#include <memory>

#include <nlohmann/json.hpp>

#define METROFIT_TEST_QT_XVFB
#include "app/gui/machinedialog.h"
#include "app/gui/matchingpage.h"
#include "core/common/numformat.h"
#include "core/machine/controller_frame.h"
#include "core/project/project.h"
#include "core/sim/probe_sim.h"
#include "core/study/study_settings.h"
#include "qtapp.h"
#include "samples/box_stl.h"
#include "testsupport.h"
#include "widgets/document/projectdocument.h"
#include "widgets/matching/matchingcurveview.h"
#include "widgets/matching/pointsetview.h"

namespace metrofit {
namespace {

/// A table cell's number as the page formats it (locale); a cell that is not a number fails the test
/// instead of reading as 0.
double cellNumber(const QTableWidgetItem* item) {
  if (item == nullptr) {
    ADD_FAILURE() << "no such cell";
    return std::nan("");
  }
  bool ok = false;
  const double v = QLocale().toDouble(item->text(), &ok);
  if (!ok) ADD_FAILURE() << "not a number: '" << item->text().toStdString() << "'";
  return ok ? v : std::nan("");
}

int countWhere(const QImage& image, const std::function<bool(QColor)>& f) {
  int n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) n += f(QColor(image.pixel(x, y))) ? 1 : 0;
  return n;
}
bool reddish(QColor c) {
  return c.red() > 150 && c.green() < 110 && c.blue() < 110;
}
bool bluish(QColor c) {
  return c.blue() > 150 && c.red() < 120 && c.green() < 150;
}
bool greenish(QColor c) {
  return c.green() > 120 && c.red() < 100 && c.blue() < 100;
}

class MatchingPageTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(PointSetView::canRender3D()) << "run under xvfb-run with QT_QPA_PLATFORM=xcb";
    ASSERT_TRUE(dir_.isValid());
    ProbeSimOptions o = ProbeSimOptions::sPieceDefaults();
    o.seed = 7;
    set_ = simulateProbing(o);
    test::writeText(dir_.filePath(QStringLiteral("s.csv")).toStdString(), probePointsToCsv(set_));
    test::writeText(dir_.filePath(QStringLiteral("bad.csv")).toStdString(),
                    "id,qx,qy,px,py\nA,0,0,0,0\nA,1,0,1,0\n");
    Project p;
    p.name = "matching page test";
    p.datasets.push_back({"s_piece", dataset_kind::kProbePoints, "s.csv", "S-piece", "", {}});
    p.datasets.push_back({"bad", dataset_kind::kProbePoints, "bad.csv", "duplicate ids", "", {}});
    p.studies["matching"] = {
        {"dataset", "s_piece"}, {"tolerance_mm", 0.035}, {"machine", {{"topology", "ac"}}}};
    const QString path = dir_.filePath(QStringLiteral("p.metrofit"));
    saveProject(p, path.toStdString());
    document_.load(path);
    page_ = std::make_unique<MatchingPage>(&document_);
    page_->resize(1400, 900);
    page_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(page_.get()));
  }

  void save(const QImage& image, const QString& name) {
    const QDir out(QString::fromStdString((test::outDir() / "matchingpage").string()));
    QDir().mkpath(out.path());
    EXPECT_TRUE(image.save(out.filePath(name)));
  }

  QTemporaryDir dir_;
  ProbePointSet set_;
  ProjectDocument document_;
  std::unique_ptr<MatchingPage> page_;
};

TEST_F(MatchingPageTest, RunFillsEveryTableWithTheCoreResults) {
  EXPECT_EQ(page_->currentDataset(), QStringLiteral("s_piece"));  // the study's dataset
  EXPECT_TRUE(page_->errorMessage().isEmpty()) << page_->errorMessage().toStdString();
  ASSERT_TRUE(page_->runNow()) << page_->errorMessage().toStdString();
  const auto& res = page_->result();
  ASSERT_TRUE(res.has_value());
  EXPECT_EQ(res->runs.size(), 4u);
  EXPECT_EQ(res->machine.topology, machine::Topology::AcTable);

  // Methods: rough + four methods; the SADE row's numbers are the core result's.
  QTableWidget* methods = page_->methodsTable();
  ASSERT_EQ(methods->rowCount(), 5);
  const matching::MatchResult& sade = *res->of(matching::MatchMethod::Sade);
  EXPECT_EQ(methods->item(1, 11)->text(), QStringLiteral("0 / 40"));
  EXPECT_EQ(methods->item(1, 10)->text(), QStringLiteral("40 / 40"));
  EXPECT_NEAR(cellNumber(methods->item(1, 8)), sade.after.overall.rmseMm, 1e-5);
  EXPECT_NEAR(cellNumber(methods->item(1, 3)), sade.pose.anglesDeg().z(), 1e-4);

  // Machine: AC trunnion, SA / SC.
  QTableWidget* machine = page_->machineTable();
  ASSERT_EQ(machine->rowCount(), 6);
  EXPECT_EQ(machine->item(3, 0)->text(), QStringLiteral("SA"));
  EXPECT_EQ(machine->item(4, 0)->text(), QStringLiteral("SC"));
  EXPECT_NEAR(cellNumber(machine->item(0, 1)), res->adjustment.linearMm.x(), 1e-4);

  // Remeasure loop: first round all out, last none.
  QTableWidget* loop = page_->remeasureTable();
  ASSERT_GE(loop->rowCount(), 2);
  EXPECT_EQ(loop->item(0, 2)->text(), QStringLiteral("40 / 40"));
  EXPECT_EQ(loop->item(loop->rowCount() - 1, 2)->text(), QStringLiteral("0 / 40"));

  // Curve: SADE and GA-simplex; points: before and after deviations.
  EXPECT_EQ(page_->curveView()->curveNames(),
            (QStringList{QStringLiteral("GA-simplex"), QStringLiteral("SADE")}));
  ASSERT_EQ(page_->pointTable()->rowCount(), 40);
  EXPECT_NEAR(cellNumber(page_->pointTable()->item(0, 3)), sade.after.deviations[0], 1e-4);

  // The method selector switches the posture shown and adjusted, without running again.
  page_->setMethod(matching::MatchMethod::Minimax);
  EXPECT_EQ(page_->result()->primary, matching::MatchMethod::Minimax);
  const matching::MatchResult& mm = *res->of(matching::MatchMethod::Minimax);
  const machine::Adjustment a = machine::adjustmentFor(res->machine, mm.pose.rotation, mm.pose.translation);
  EXPECT_NEAR(cellNumber(machine->item(3, 1)), a.rotaryDeg[0], 1e-5);

  // A tighter tolerance re-evaluates the counts.
  page_->setTolerance(0.001);
  EXPECT_NE(methods->item(1, 11)->text(), QStringLiteral("0 / 40"));
}

TEST_F(MatchingPageTest, RoughRowMarksTheLockedParametersItCannotHold) {
  // rx locked: the rough three-point frames still give an rx (a whole rigid frame), the SADE row holds
  // rx at 0. The rough row's rx cell is greyed and says why; its free cells are not.
  page_->setLocked(0, true);
  ASSERT_TRUE(page_->runNow()) << page_->errorMessage().toStdString();
  const matching::MatchResult& sade = *page_->result()->of(matching::MatchMethod::Sade);
  ASSERT_TRUE(sade.rough.has_value());
  QTableWidget* methods = page_->methodsTable();
  ASSERT_EQ(methods->item(0, 0)->text(), MatchingPage::tr("Rough"));
  EXPECT_NEAR(cellNumber(methods->item(0, 1)), sade.rough->posture.anglesDeg().x(), 1e-4);
  EXPECT_NEAR(cellNumber(methods->item(1, 1)), 0.0, 1e-9) << "SADE holds the lock";
  EXPECT_TRUE(methods->item(0, 1)->toolTip().contains(QStringLiteral("rx"))) << "names the lock";
  EXPECT_EQ(methods->item(0, 1)->foreground().color(),
            page_->palette().color(QPalette::Disabled, QPalette::Text));
  EXPECT_TRUE(methods->item(0, 2)->toolTip().isEmpty()) << "ry is free";
}

TEST_F(MatchingPageTest, ASphereIsRefusedWithAButtonThatLocksTheRotations) {
  // Points probed on a ball, shifted by (0.02, -0.01, 0.03) mm: no rotation is determined. The page says
  // why and offers "Lock rx, ry, rz and run": one undo step, then the run succeeds with the shift found.
  std::string csv = "id,qx,qy,qz,nx,ny,nz,px,py,pz\n";
  const Eigen::Vector3d shift(0.02, -0.01, 0.03);
  int id = 0;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 6; ++j) {
      const double polar = 0.3 + 0.3 * i, azimuth = 1.05 * j + 0.4 * i;
      const Eigen::Vector3d n(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                              std::cos(polar));
      const Eigen::Vector3d q = 12.5 * n, p = q + shift;
      csv += "S" + std::to_string(++id) + "," + num::shortest(q.x()) + "," + num::shortest(q.y()) + "," +
             num::shortest(q.z()) + "," + num::shortest(n.x()) + "," + num::shortest(n.y()) + "," +
             num::shortest(n.z()) + "," + num::shortest(p.x()) + "," + num::shortest(p.y()) + "," +
             num::shortest(p.z()) + "\n";
    }
  }
  test::writeText(dir_.filePath(QStringLiteral("ball.csv")).toStdString(), csv);
  Project p;
  p.name = "ball";
  p.datasets.push_back({"ball", dataset_kind::kProbePoints, "ball.csv", "", "", {}});
  p.studies["matching"] = {{"dataset", "ball"}, {"tolerance_mm", 0.035}};
  const QString path = dir_.filePath(QStringLiteral("ball.metrofit"));
  saveProject(p, path.toStdString());
  ProjectDocument document;
  document.load(path);
  MatchingPage page(&document);
  EXPECT_FALSE(page.runNow());
  EXPECT_NE(page.errorMessage().indexOf(QStringLiteral("undetermined")), -1)
      << page.errorMessage().toStdString();
  QPushButton* lock = page.lockMissingButton();
  ASSERT_TRUE(lock);
  EXPECT_FALSE(lock->isHidden());
  EXPECT_EQ(lock->text(), MatchingPage::tr("Lock %1 and run").arg(QStringLiteral("rx, ry, rz")));
  QSignalSpy finished(&page, &MatchingPage::finished);
  lock->click();
  EXPECT_EQ(document.project().studies["matching"]["locks"], "rx,ry,rz");
  EXPECT_EQ(document.undoStack()->count(), 1) << "one undo step for the three locks";
  ASSERT_TRUE(finished.wait(60000));
  ASSERT_TRUE(page.result().has_value()) << page.errorMessage().toStdString();
  EXPECT_TRUE(lock->isHidden());
  const matching::MatchResult& r = page.result()->primaryRun();
  // The pose maps the nominal points onto the measured ones: its translation is the shift.
  EXPECT_NEAR(r.pose.translation.x(), shift.x(), 1e-6);
  EXPECT_NEAR(r.pose.translation.y(), shift.y(), 1e-6);
  EXPECT_NEAR(r.pose.translation.z(), shift.z(), 1e-6);
  document.undoStack()->undo();
  EXPECT_TRUE(document.project().studies["matching"].value("locks", nlohmann::json()).is_null());
}

TEST_F(MatchingPageTest, SettingsEditsAreWrittenToTheStudyAndUndone) {
  auto* tolerance = page_->findChild<QDoubleSpinBox*>(QStringLiteral("matchingTolerance"));
  auto* method = page_->findChild<QComboBox*>(QStringLiteral("matchingMethod"));
  QCheckBox* lockZ = nullptr;
  for (QCheckBox* box : page_->findChildren<QCheckBox*>())
    if (box->text() == QLatin1String("z")) lockZ = box;
  ASSERT_TRUE(tolerance && method && lockZ);
  const nlohmann::json before = document_.project().studies["matching"];
  EXPECT_DOUBLE_EQ(tolerance->value(), 0.035);
  EXPECT_FALSE(document_.isModified());
  EXPECT_EQ(document_.undoStack()->count(), 0) << "showing the settings is no edit";

  page_->setTolerance(0.02);
  page_->setTolerance(0.025);  // typing: one undo step
  emit tolerance->editingFinished();
  page_->setMethod(matching::MatchMethod::Minimax);
  page_->setLocked(2, true);
  page_->setLocked(5, true);
  nlohmann::json expected = before;
  expected["tolerance_mm"] = 0.025;
  expected["method"] = "minimax";
  expected["locks"] = "rz,z";
  EXPECT_EQ(document_.project().studies["matching"], expected);
  EXPECT_TRUE(document_.isModified());
  EXPECT_EQ(document_.undoStack()->count(), 4);

  document_.undoStack()->undo();
  EXPECT_FALSE(lockZ->isChecked());
  EXPECT_EQ(document_.project().studies["matching"]["locks"], "rz");
  document_.undoStack()->undo();
  document_.undoStack()->undo();
  EXPECT_EQ(method->currentData().toInt(), static_cast<int>(matching::MatchMethod::Sade));
  EXPECT_DOUBLE_EQ(tolerance->value(), 0.025);
  document_.undoStack()->undo();
  EXPECT_EQ(document_.project().studies["matching"], before);
  EXPECT_DOUBLE_EQ(tolerance->value(), 0.035);
  EXPECT_FALSE(document_.isModified());
  EXPECT_EQ(document_.undoStack()->count(), 4) << "restoring the controls pushes nothing";
  document_.undoStack()->redo();
  EXPECT_DOUBLE_EQ(tolerance->value(), 0.025);
}

// The controller frame's control is bound like every other control (app/gui/studysettingbinding.h): a
// choice writes studies.matching.frame (the name the study reads), undo puts the combo back, and choosing
// the default again keeps the key (the study says which control it is for).
TEST_F(MatchingPageTest, FrameControlIsWrittenToTheStudyAndUndone) {
  auto* frame = page_->findChild<QComboBox*>(QStringLiteral("frameControl"));
  ASSERT_TRUE(frame);
  const nlohmann::json before = document_.project().studies["matching"];
  const QString shown = frame->currentText();
  int other = -1;
  for (int i = 0; i < frame->count() && other < 0; ++i)
    if (frame->itemText(i).contains(QLatin1String("Fanuc"), Qt::CaseInsensitive)) other = i;
  ASSERT_GE(other, 0);
  ASSERT_NE(other, frame->currentIndex());
  frame->setCurrentIndex(other);
  const auto format = static_cast<machine::FrameFormat>(frame->currentData().toInt());
  EXPECT_EQ(document_.project().studies["matching"]["frame"], machine::toString(format));
  EXPECT_EQ(document_.undoStack()->count(), 1);
  const MatchingSettings read = MatchingSettings::fromJson(document_.project().studies["matching"]);
  EXPECT_EQ(read.frame, format);

  document_.undoStack()->undo();
  EXPECT_EQ(document_.project().studies["matching"], before);
  EXPECT_EQ(frame->currentText(), shown);
  EXPECT_EQ(document_.undoStack()->count(), 1) << "restoring the control pushes nothing";
  document_.undoStack()->redo();
  EXPECT_EQ(frame->currentIndex(), other);
  EXPECT_EQ(document_.project().studies["matching"]["frame"], machine::toString(format));
}

TEST_F(MatchingPageTest, WorkerRunReportsFinishesAndCanBeCancelled) {
  QSignalSpy finished(page_.get(), &MatchingPage::finished);
  page_->startRun();
  EXPECT_TRUE(page_->isRunning());  // until finished() is delivered
  EXPECT_FALSE(page_->runNow()) << "no second run while the worker runs";
  ASSERT_TRUE(finished.count() == 1 || finished.wait(30000));
  EXPECT_FALSE(page_->isRunning());
  ASSERT_TRUE(page_->result().has_value());
  EXPECT_EQ(page_->result()->runs.size(), 4u);

  // Locks: rz and z held at 0 give a constrained optimum with exactly those values.
  page_->setLocked(2, true);
  page_->setLocked(5, true);
  ASSERT_TRUE(page_->runNow());
  for (const matching::MatchResult& r : page_->result()->runs) {
    EXPECT_NEAR(r.pose.anglesDeg().z(), 0.0, 1e-9) << matching::toString(r.method);
    EXPECT_NEAR(r.pose.translation.z(), 0.0, 1e-12) << matching::toString(r.method);
  }

  // Cancel right after the start: the run ends early (SADE stops, the study stops after it). A
  // large set (20000 points: a full SADE run takes far longer than the cancel) keeps this
  // deterministic on a loaded machine.
  page_->setLocked(2, false);
  page_->setLocked(5, false);
  ProbeSimOptions big = ProbeSimOptions::sPieceDefaults();
  ProbePointSet large;
  large.hasNormals = true;
  for (int copy = 0; copy < 500; ++copy) {
    big.seed = static_cast<std::uint64_t>(copy + 1);
    for (ProbePoint p : simulateProbing(big).points) {
      p.id = "C" + std::to_string(copy) + "_" + p.id;
      large.points.push_back(std::move(p));
    }
  }
  test::writeText(dir_.filePath(QStringLiteral("large.csv")).toStdString(), probePointsToCsv(large));
  Project p = document_.project();
  p.datasets.push_back({"large", dataset_kind::kProbePoints, "large.csv", "20000 points", "", {}});
  saveProject(p, document_.fileName().toStdString());
  document_.load(document_.fileName());
  page_->selectDataset(QStringLiteral("large"));
  ASSERT_EQ(page_->currentDataset(), QStringLiteral("large"));
  ASSERT_TRUE(page_->errorMessage().isEmpty()) << page_->errorMessage().toStdString();
  finished.clear();
  page_->startRun();
  page_->cancelRun();
  ASSERT_TRUE(finished.count() == 1 || finished.wait(30000));
  ASSERT_TRUE(page_->result().has_value());
  EXPECT_EQ(page_->result()->runs.size(), 1u);
  EXPECT_EQ(page_->result()->runs[0].run.termination, Termination::Cancelled);
}

TEST_F(MatchingPageTest, BeforeAndAfterViewsAreReadableAndShareTheCamera) {
  page_->showView(QStringLiteral("3d"));
  ASSERT_TRUE(page_->result().has_value());
  QTest::qWait(100);
  const QImage before = page_->beforeView()->renderImage();
  const QImage after = page_->afterView()->renderImage();
  ASSERT_FALSE(before.isNull());
  ASSERT_FALSE(after.isNull());
  save(before, QStringLiteral("before.png"));
  save(after, QStringLiteral("after.png"));
  save(page_->grab().toImage(), QStringLiteral("page_3d.png"));
  // Scene only (left of the scalar bar strip, above the axes marker row).
  const QRect scene(0, 0, static_cast<int>(0.82 * before.width()), static_cast<int>(0.78 * before.height()));
  const int redBefore = countWhere(before.copy(scene), reddish),
            blueBefore = countWhere(before.copy(scene), bluish);
  const int greenAfter = countWhere(after.copy(scene), greenish),
            redAfter = countWhere(after.copy(scene), reddish);
  EXPECT_GT(redBefore + blueBefore, 400) << "before: the out-of-tolerance points are red / blue";
  EXPECT_GT(greenAfter, 200) << "after: the points are green (inside the tolerance)";
  EXPECT_LT(redAfter, 50);
  EXPECT_LT(countWhere(before.copy(scene), greenish), greenAfter / 4);
  // The scalar bar has its own strip: its colours are right of the scene.
  const QRect strip(static_cast<int>(0.86 * before.width()), 0,
                    before.width() - static_cast<int>(0.86 * before.width()), before.height());
  EXPECT_GT(countWhere(before.copy(strip), greenish), 20);
  EXPECT_GT(countWhere(before.copy(strip), reddish), 20);
  // One camera for both views.
  EXPECT_EQ(page_->beforeView()->cameraPosition(), page_->afterView()->cameraPosition());
  EXPECT_EQ(page_->beforeView()->exaggeration(), page_->afterView()->exaggeration());

  page_->showView(QStringLiteral("convergence"));
  QTest::qWait(50);
  save(page_->grab().toImage(), QStringLiteral("page_convergence.png"));
  page_->showView(QStringLiteral("remeasure"));
  QTest::qWait(50);
  save(page_->grab().toImage(), QStringLiteral("page_remeasure.png"));
}

TEST_F(MatchingPageTest, BadDataShowAReadableMessage) {
  page_->selectDataset(QStringLiteral("bad"));
  EXPECT_EQ(page_->currentDataset(), QStringLiteral("bad"));
  EXPECT_TRUE(page_->errorMessage().contains(QStringLiteral("duplicate point id 'A'")))
      << page_->errorMessage().toStdString();
  EXPECT_FALSE(page_->runNow());
  EXPECT_FALSE(page_->result().has_value());
  page_->selectDataset(QStringLiteral("s_piece"));
  EXPECT_TRUE(page_->errorMessage().isEmpty());
  EXPECT_TRUE(page_->runNow());
}

// The machine of the project (issue 27 item 5): the dialog's definition goes into the study as one
// undo step, the adjustment values follow it without a new run, and the exported JSON is what
// `metrofit-cli match --machine-def` reads: the CLI gives the page's values for the same posture.
TEST_F(MatchingPageTest, MachineDialogDefinesTheMachineUndoablyAndTheCliReadsTheSameJson) {
  page_->setMethod(matching::MatchMethod::ClosedForm);  // deterministic: the CLI finds the same posture
  ASSERT_TRUE(page_->runNow()) << page_->errorMessage().toStdString();
  QTableWidget* table = page_->machineTable();
  ASSERT_EQ(table->rowCount(), 6);
  EXPECT_EQ(table->item(3, 0)->text(), QStringLiteral("SA"));
  EXPECT_TRUE(page_->machineLabel()->text().contains(QStringLiteral("project's machine ac-table")))
      << page_->machineLabel()->text().toStdString();
  const double acX = cellNumber(table->item(0, 1));

  // The dialog: head-table with a pivot, a C axis off the origin, SY limited so that the values leave it.
  MachineDialog dialog(page_->result()->machine, machine::FrameFormat::Heidenhain);
  QComboBox* topology = dialog.topologyCombo();
  topology->setCurrentIndex(topology->findData(static_cast<int>(machine::Topology::HeadTable)));
  dialog.findChild<QDoubleSpinBox*>(QStringLiteral("machinePivot"))->setValue(212.5);
  dialog.findChild<QDoubleSpinBox*>(QStringLiteral("machineRotaryPointx"))->setValue(40.0);
  dialog.findChild<QDoubleSpinBox*>(QStringLiteral("machineRotaryPointy"))->setValue(-25.0);
  dialog.findChild<QCheckBox*>(QStringLiteral("machineLinearLimitedY"))->setChecked(true);
  dialog.findChild<QDoubleSpinBox*>(QStringLiteral("machineLinearMinY"))->setValue(0.5);
  dialog.findChild<QDoubleSpinBox*>(QStringLiteral("machineLinearMaxY"))->setValue(0.6);
  ASSERT_TRUE(dialog.isDefinitionValid()) << dialog.problem().toStdString();
  dialog.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&dialog));
  save(dialog.grab().toImage(), QStringLiteral("machine-dialog.png"));
  dialog.hide();
  const machine::MachineDefinition def = dialog.definition();
  EXPECT_EQ(def.topology, machine::Topology::HeadTable);
  EXPECT_EQ(def.pivot, 212.5);
  EXPECT_EQ(def.linearMinMm[1], 0.5);
  EXPECT_TRUE(std::isinf(def.linearMinMm[0]));

  const int undoBefore = document_.undoStack()->count();
  page_->setMachine(def, dialog.controller());
  EXPECT_EQ(document_.undoStack()->count(), undoBefore + 1) << "one undo step";
  EXPECT_EQ(document_.project().studies["matching"]["machine"], def.toJson());
  EXPECT_FALSE(document_.project().studies["matching"].contains("frame")) << "the control did not change";
  // The values follow the machine without a new run: B and C rows, values of the head-table chain.
  ASSERT_EQ(table->rowCount(), 6);
  EXPECT_EQ(table->item(3, 0)->text(), QStringLiteral("SB"));
  EXPECT_EQ(table->item(4, 0)->text(), QStringLiteral("SC"));
  const matching::MatchResult& cf = *page_->result()->of(matching::MatchMethod::ClosedForm);
  const machine::Adjustment a = machine::adjustmentFor(def, cf.pose.rotation, cf.pose.translation);
  EXPECT_NEAR(cellNumber(table->item(0, 1)), a.linearMm.x(), 1e-4);
  EXPECT_NEAR(cellNumber(table->item(3, 1)), a.rotaryDeg[0], 1e-5);
  EXPECT_GT(std::abs(cellNumber(table->item(0, 1)) - acX), 1e-3) << "another machine, other values";
  EXPECT_FALSE(a.withinTravel);
  EXPECT_TRUE(page_->machineLabel()->text().contains(QStringLiteral("OUTSIDE TRAVEL: SY")))
      << page_->machineLabel()->text().toStdString();

  // Export: the CLI reads the same JSON and writes the page's values.
  const QString machineFile = dir_.filePath(QStringLiteral("machine.json"));
  ASSERT_TRUE(dialog.exportFile(machineFile)) << dialog.problem().toStdString();
  QProcess cli;
  const QString out = dir_.filePath(QStringLiteral("match.json"));
  cli.start(QStringLiteral(METROFIT_CLI_EXECUTABLE),
            {QStringLiteral("match"), QStringLiteral("--data"), dir_.filePath(QStringLiteral("s.csv")),
             QStringLiteral("--method"), QStringLiteral("closed-form"), QStringLiteral("--machine-def"),
             machineFile, QStringLiteral("--out"), out});
  ASSERT_TRUE(cli.waitForFinished(60000));
  ASSERT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();
  std::ifstream in(out.toStdString());
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["machine"]["topology"], "head-table");
  EXPECT_NEAR(j["machine"]["SX_mm"].get<double>(), cellNumber(table->item(0, 1)), 1e-4);
  EXPECT_NEAR(j["machine"]["SY_mm"].get<double>(), cellNumber(table->item(1, 1)), 1e-4);
  EXPECT_NEAR(j["machine"]["SZ_mm"].get<double>(), cellNumber(table->item(2, 1)), 1e-4);
  EXPECT_NEAR(j["machine"]["SB_deg"].get<double>(), cellNumber(table->item(3, 1)), 1e-5);
  EXPECT_NEAR(j["machine"]["SC_deg"].get<double>(), cellNumber(table->item(4, 1)), 1e-5);
  EXPECT_EQ(j["machine"]["within_travel"], false);

  // Undo: the project's AC machine and its values are back.
  document_.undoStack()->undo();
  EXPECT_EQ(document_.project().studies["matching"]["machine"], nlohmann::json({{"topology", "ac"}}));
  EXPECT_EQ(table->item(3, 0)->text(), QStringLiteral("SA"));
  EXPECT_NEAR(cellNumber(table->item(0, 1)), acX, 1e-9);

  // No machine in the project: the label says the values are the default machine's.
  document_.setStudyValue(QStringLiteral("matching"), QStringLiteral("/machine"), nlohmann::json(),
                          QStringLiteral("remove"));
  EXPECT_TRUE(page_->machineLabel()->text().contains(QStringLiteral("no machine is defined")))
      << page_->machineLabel()->text().toStdString();
  EXPECT_EQ(table->item(3, 0)->text(), QStringLiteral("SA"));
  EXPECT_EQ(table->item(4, 0)->text(), QStringLiteral("SB"));
}

TEST_F(MatchingPageTest, MachineDialogRefusesInconsistentTravelAndNamesBadImports) {
  MachineDialog dialog(machine::MachineDefinition::preset(machine::Topology::BcTable),
                       machine::FrameFormat::Fanuc);
  EXPECT_EQ(dialog.controller(), machine::FrameFormat::Fanuc);
  EXPECT_TRUE(dialog.isDefinitionValid());
  auto* ok = dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
  dialog.findChild<QDoubleSpinBox*>(QStringLiteral("machineRotaryMin0"))->setValue(50.0);
  dialog.findChild<QDoubleSpinBox*>(QStringLiteral("machineRotaryMax0"))->setValue(40.0);
  EXPECT_FALSE(dialog.isDefinitionValid());
  EXPECT_FALSE(ok->isEnabled());
  EXPECT_TRUE(dialog.problem().contains(QStringLiteral("SB"))) << dialog.problem().toStdString();
  dialog.findChild<QDoubleSpinBox*>(QStringLiteral("machineRotaryMax0"))->setValue(60.0);
  EXPECT_TRUE(dialog.isDefinitionValid());
  EXPECT_TRUE(ok->isEnabled());

  // A machine file with a bad value: the reason names the file and the field; the fields stay.
  const QString bad = dir_.filePath(QStringLiteral("bad-machine.json"));
  test::writeText(bad.toStdString(), R"({"topology": "head-table", "pivot_mm": "long"})");
  EXPECT_FALSE(dialog.importFile(bad));
  EXPECT_TRUE(dialog.problem().contains(QStringLiteral("bad-machine.json")))
      << dialog.problem().toStdString();
  EXPECT_TRUE(dialog.problem().contains(QStringLiteral("pivot_mm"))) << dialog.problem().toStdString();
  EXPECT_EQ(dialog.definition().topology, machine::Topology::BcTable);
  // A project file: its matching study's machine.
  EXPECT_TRUE(dialog.importFile(dir_.filePath(QStringLiteral("p.metrofit"))))
      << dialog.problem().toStdString();
  EXPECT_EQ(dialog.definition().topology, machine::Topology::AcTable);
}

// Nominals from a CAD part (issue 28 item 4 / issue 30): a box written as STL, measured points on its
// faces moved by a known posture with the top face 30 um high; the page runs closed form on the points
// re-projected onto the part, draws the part in both views coloured by the deviation probed on it, and
// refuses a method that needs fixed point pairs with the setting named.
TEST(MatchingPageCad, TheBoxIsMatchedAndDrawnColouredByDeviation) {
  ASSERT_TRUE(PointSetView::canRender3D()) << "run under xvfb-run with QT_QPA_PLATFORM=xcb";
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  test::writeText(dir.filePath(QStringLiteral("box.stl")).toStdString(), test::boxStl(100, 60, 40));
  const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(0.003, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(0.002, Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  const Eigen::Vector3d shift(0.12, -0.05, 0.04);
  std::string csv = "id,x,y,z\n";
  int k = 0;
  for (double x : {15.0, 50.0, 85.0})
    for (double y : {10.0, 30.0, 50.0}) {
      for (double z : {0.0, 40.0}) {
        const Eigen::Vector3d p = rotation * Eigen::Vector3d(x, y, z + (z > 0 ? 0.030 : 0.0)) + shift;
        csv += "P" + std::to_string(++k) + "," + num::general(p.x(), 17) + "," + num::general(p.y(), 17) +
               "," + num::general(p.z(), 17) + "\n";
      }
    }
  for (const Eigen::Vector3d& q :
       {Eigen::Vector3d(20, 0, 10), Eigen::Vector3d(80, 0, 30), Eigen::Vector3d(50, 60, 20),
        Eigen::Vector3d(100, 20, 15), Eigen::Vector3d(100, 45, 30), Eigen::Vector3d(0, 30, 20),
        Eigen::Vector3d(0, 50, 10), Eigen::Vector3d(70, 60, 30)}) {
    const Eigen::Vector3d p = rotation * q + shift;
    csv += "P" + std::to_string(++k) + "," + num::general(p.x(), 17) + "," + num::general(p.y(), 17) + "," +
           num::general(p.z(), 17) + "\n";
  }
  test::writeText(dir.filePath(QStringLiteral("points.csv")).toStdString(), csv);
  Project p;
  p.name = "CAD nominal";
  p.datasets.push_back({"box", dataset_kind::kCadModel, "box.stl", "", "", {}});
  DatasetRef points{"points", dataset_kind::kProbePoints, "points.csv", "", "", {}};
  points.nominals.from = "cad";
  points.nominals.cad = "box";
  p.datasets.push_back(points);
  p.studies["matching"] = {{"dataset", "points"}, {"tolerance_mm", 0.02}, {"method", "sade"}};
  const QString path = dir.filePath(QStringLiteral("p.metrofit"));
  saveProject(p, path.toStdString());
  ProjectDocument document;
  document.load(path);
  MatchingPage page(&document);
  page.resize(1400, 900);
  page.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&page));
  ASSERT_TRUE(page.errorMessage().isEmpty()) << page.errorMessage().toStdString();
  EXPECT_EQ(page.beforeView()->surfaceTriangles(), 12u);
  // The study's method is sade: refused, naming the setting.
  EXPECT_FALSE(page.runNow());
  EXPECT_TRUE(page.statusText().contains(QStringLiteral("closed-form (least squares) or minimax")))
      << page.statusText().toStdString();
  page.setMethod(matching::MatchMethod::ClosedForm);
  ASSERT_TRUE(page.runNow()) << page.statusText().toStdString();
  const matching::MatchResult& r = page.result()->primaryRun();
  // The top face's 30 um form error biases the z shift (least squares over 9 of 26 points), nothing
  // else: x, y, the rotation about z come back to a few um / urad.
  EXPECT_NEAR(r.pose.translation.x(), shift.x(), 0.005);
  EXPECT_NEAR(r.pose.translation.y(), shift.y(), 0.005);
  EXPECT_NEAR(r.pose.anglesDeg().z(), 0.003 * 180.0 / 3.14159265358979, 0.002);
  EXPECT_EQ(page.afterView()->surfaceTriangles(), 12u);
  ASSERT_EQ(page.result()->cadAfter.size(), page.result()->runs.size());
  QTest::qWait(300);
  const QImage before = page.beforeView()->renderImage();
  const QImage after = page.afterView()->renderImage();
  ASSERT_FALSE(after.isNull());
  const QDir out(QString::fromStdString((test::outDir() / "matchingpage").string()));
  QDir().mkpath(out.path());
  EXPECT_TRUE(before.save(out.filePath(QStringLiteral("cad_box_before.png"))));
  EXPECT_TRUE(after.save(out.filePath(QStringLiteral("cad_box_after.png"))));
  EXPECT_TRUE(page.grab().save(out.filePath(QStringLiteral("cad_box_page.png"))));
  // The part is drawn, its faces in the tolerance green after matching: far more green pixels than the
  // 26 point markers alone make (about 2000 at this size), in the scene left of the colour bar.
  int green = 0;
  for (int y = 0; y < after.height(); ++y)
    for (int x = 0; x < after.width() * 3 / 4; ++x) {
      const QColor c = after.pixelColor(x, y);
      if (c.green() > c.red() + 40 && c.green() > c.blue() + 40) ++green;
    }
  EXPECT_GT(green, 15000) << "the part's faces are not drawn";
}

}  // namespace
}  // namespace metrofit
