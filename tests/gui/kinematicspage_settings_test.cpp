// The kinematics page and its study's settings (issue 27: one owner per study's settings, results that
// stay): a bad value in the project file is refused on the page with the field named and nothing runs;
// the compensated result is stored in the project and shown after Save As and reopen in a fresh document
// ("From the saved project", the figures the page computed), out of date after a settings change; every
// control of the page survives save and reopen, and the saved project exports its PDF report (GUI and
// `metrofit-cli report`).
#include <gtest/gtest.h>

#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QProcess>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QUndoStack>

#include <array>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/gui/kinematicspage.h"
#include "app/gui/reportexporter.h"
#include "core/io/json_util.h"
#include "core/kinematics/identification3.h"
#include "core/project/project.h"
#include "core/sim/circular_sim.h"
#include "core/study/kinematic_study.h"
#include "qtapp.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"

namespace metrofit {
namespace {

const QString kKin = QStringLiteral("kinematics");

class KinematicsSettingsPageTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    projectPath_ = extractDemoProject(dir_.path());
  }

  /// Writes `value` at `pointer` of the demo's kinematics study in the project file.
  void writeStudyValue(const std::string& pointer, const nlohmann::json& value) {
    nlohmann::json j = readJsonFile(projectPath_.toStdString());
    j["studies"]["kinematics"][nlohmann::json::json_pointer(pointer)] = value;
    std::ofstream(projectPath_.toStdString()) << dumpJson(j);
  }

  QTemporaryDir dir_;
  QString projectPath_;
};

QString cell(const QTableWidget* t, int row, int column) {
  const QTableWidgetItem* item = t->item(row, column);
  return item ? item->text() : QString();
}

TEST_F(KinematicsSettingsPageTest, ABadStudyValueIsRefusedNamingTheFieldAndNothingRuns) {
  for (const nlohmann::json& bad : {nlohmann::json(0), nlohmann::json("abc"), nlohmann::json(26)}) {
    SCOPED_TRACE(bad.dump());
    writeStudyValue("/spc/subgroup", bad);
    ProjectDocument doc;
    doc.load(projectPath_);
    KinematicsPage page(&doc);
    const QString message = page.messageLabel()->text();
    EXPECT_TRUE(message.contains(QStringLiteral("studies.kinematics.spc.subgroup"))) << message.toStdString();
    EXPECT_TRUE(page.settingsError().contains(QStringLiteral("studies.kinematics.spc.subgroup")));
    EXPECT_EQ(page.currentView(), page.messageLabel());
    EXPECT_EQ(page.study(), nullptr) << "never identified with a default in place of the bad value";
    EXPECT_FALSE(page.compensateButton()->isEnabled());
    EXPECT_FALSE(page.identify());
    EXPECT_FALSE(page.compensate());
    QString error;
    EXPECT_FALSE(page.exportGcode(dir_.filePath(QStringLiteral("c.nc")), &error));
    EXPECT_FALSE(QFileInfo::exists(dir_.filePath(QStringLiteral("c.nc"))));
    page.showView(QStringLiteral("path"));
    EXPECT_EQ(page.study(), nullptr);
    EXPECT_TRUE(page.storedLabel()->isHidden());
  }
}

TEST_F(KinematicsSettingsPageTest, ABadValueSetWhileOpenIsRefusedAndUndoRunsAgain) {
  ProjectDocument doc;
  doc.load(projectPath_);
  KinematicsPage page(&doc);
  ASSERT_NE(page.study(), nullptr) << page.errorMessage().toStdString();
  doc.setStudyValue(kKin, QStringLiteral("/from_spc/coverage"), -1, QStringLiteral("break"));
  EXPECT_EQ(page.study(), nullptr);
  EXPECT_TRUE(page.messageLabel()->text().contains(QStringLiteral("studies.kinematics.from_spc.coverage")))
      << page.messageLabel()->text().toStdString();
  EXPECT_FALSE(page.compensateButton()->isEnabled());
  doc.undoStack()->undo();
  EXPECT_NE(page.study(), nullptr) << page.errorMessage().toStdString();
  EXPECT_TRUE(page.settingsError().isEmpty());
  EXPECT_TRUE(page.compensateButton()->isEnabled());
}

TEST_F(KinematicsSettingsPageTest, ABadDatasetChoiceIsShownAndTheChooserReplacesIt) {
  writeStudyValue("/planes/yz", 5);
  ProjectDocument doc;
  doc.load(projectPath_);
  KinematicsPage page(&doc);
  EXPECT_EQ(page.study(), nullptr);
  EXPECT_TRUE(page.messageLabel()->text().contains(QStringLiteral("studies.kinematics.planes.yz")))
      << page.messageLabel()->text().toStdString();
  QComboBox* yz = page.planeCombo(TestPlane::YZ);
  EXPECT_TRUE(yz->currentText().contains(QStringLiteral("not a dataset id")))
      << yz->currentText().toStdString();
  yz->setCurrentIndex(0);  // (none): the key goes, the study runs
  EXPECT_EQ(doc.studyValue(kKin, QStringLiteral("/planes/yz")), nlohmann::json());
  EXPECT_NE(page.study(), nullptr) << page.errorMessage().toStdString();
  EXPECT_TRUE(page.settingsError().isEmpty());
  doc.undoStack()->undo();
  EXPECT_EQ(page.study(), nullptr);
  EXPECT_TRUE(yz->currentText().contains(QStringLiteral("not a dataset id")));
}

TEST_F(KinematicsSettingsPageTest, TheCompensatedResultIsStoredAndShownAfterSaveAsAndReopen) {
  ProjectDocument doc;
  doc.load(projectPath_);
  KinematicsPage page(&doc);
  EXPECT_TRUE(page.storedLabel()->isHidden()) << "nothing stored in the demo";
  ASSERT_TRUE(page.compensate()) << page.errorMessage().toStdString();
  const KinematicStudyData study = *page.study();
  const CompensationPreview compensation = *page.compensation();
  // What the page shows as its result: the identified errors and the compensation's figures.
  QStringList shown;
  for (int row = 0; row < 6; ++row) shown << cell(page.errorTable(), row, 1);
  const QTableWidget* comp = page.compensationTable();
  shown << cell(comp, 0, 1) << cell(comp, 2, 1) << cell(comp, 3, 1) << cell(comp, comp->rowCount() - 1, 1);
  for (const QString& s : shown) ASSERT_FALSE(s.isEmpty());
  EXPECT_TRUE(page.storedLabel()->isHidden()) << "the page shows the result it computed";

  QTemporaryDir other;
  ASSERT_TRUE(other.isValid());
  const QString saved = QDir(other.path()).filePath(QStringLiteral("copy.metrofit"));
  doc.saveAs(saved);

  // The file holds the figures computed, with the settings they came from.
  const Project p = loadProject(saved.toStdString());
  const nlohmann::json entry = p.results.at("kinematics").at("circular_demo");
  EXPECT_DOUBLE_EQ(entry.at("identified").at("origin_x_mm").get<double>(),
                   study.identification.errors.originMm.x());
  EXPECT_DOUBLE_EQ(entry.at("identified").at("y_axis_angle_deg").get<double>(),
                   study.identification.errors.yAxisAngleDeg);
  EXPECT_DOUBLE_EQ(entry.at("compensation").at("max_expected_mm").get<double>(), compensation.maxExpectedMm);
  EXPECT_DOUBLE_EQ(entry.at("compensation").at("max_before_mm").get<double>(), compensation.maxBeforeMm);
  EXPECT_EQ(entry.at("settings"), kinematicStoredSettings(p, "circular_demo"));
  EXPECT_FALSE(entry.at("settings").at("study").at("spc").contains("subgroup"))
      << "the default is not written";

  // Reopened in a fresh document: the stored figures, marked as the saved project's, equal the computed.
  ProjectDocument reopened;
  reopened.load(saved);
  KinematicsPage again(&reopened);
  ASSERT_NE(again.study(), nullptr) << again.errorMessage().toStdString();
  ASSERT_FALSE(again.storedLabel()->isHidden());
  const QString text = again.storedLabel()->text();
  EXPECT_TRUE(text.startsWith(QStringLiteral("From the saved project, computed "))) << text.toStdString();
  for (const QString& s : shown)
    EXPECT_TRUE(text.contains(s)) << s.toStdString() << " in " << text.toStdString();

  // A settings change: the stored result is out of date (and says so); undo: current again.
  const int edge = again.edgeCombo(0)->findData(QStringLiteral("bores_demo"));
  ASSERT_GE(edge, 1);
  again.edgeCombo(0)->setCurrentIndex(edge);
  EXPECT_EQ(reopened.studyValue(kKin, QStringLiteral("/from_spc/x_dataset")), nlohmann::json("bores_demo"));
  EXPECT_FALSE(again.storedLabel()->isHidden());
  EXPECT_TRUE(again.storedLabel()->text().contains(QStringLiteral("out of date")))
      << again.storedLabel()->text().toStdString();
  reopened.undoStack()->undo();
  EXPECT_TRUE(again.storedLabel()->text().startsWith(QStringLiteral("From the saved project")))
      << again.storedLabel()->text().toStdString();
  // Compensating again: the page's own result, the label hidden.
  ASSERT_TRUE(again.compensate());
  EXPECT_TRUE(again.storedLabel()->isHidden());
}

/// The demo with two machined edges and circular tests in three planes: every choice the page offers.
class KinematicsRoundTripTest : public KinematicsSettingsPageTest {
 protected:
  void SetUp() override {
    KinematicsSettingsPageTest::SetUp();
    const QDir d(dir_.path());
    for (const char axis : {'x', 'y'}) {
      EdgeSimOptions o;
      o.axis = axis;
      o.errors.originMm = Eigen::Vector2d(0.004, -0.003);
      o.errors.xAxisAngleDeg = 0.01;
      o.errors.yAxisAngleDeg = -0.02;
      o.seed = axis == 'x' ? 13 : 14;
      std::ofstream(d.filePath(QStringLiteral("edge_%1.csv").arg(QLatin1Char(axis))).toStdString())
          << axisFeatureToCsv(simulateAxisFeature(o));
    }
    ActuatorErrors3 e;
    e.originMm = Eigen::Vector3d(0.006, -0.004, 0.003);
    e.uAngleDeg = {0.002, -0.001, 0.0015};
    e.vAngleDeg = {-0.003, 0.002, -0.0025};
    Project project = loadProject(projectPath_.toStdString());
    for (const TestPlane p : kTestPlanes) {
      CircularSimOptions o;
      o.seed = 20 + static_cast<int>(p);
      const std::string n = planeName(p);
      std::ofstream(d.filePath(QString::fromStdString("plane_" + n + ".csv")).toStdString())
          << planePathToCsv(simulatePlaneCircularTest(e, p, o), p);
      project.datasets.push_back(
          {"plane_" + n, dataset_kind::kFeatureSeries, "plane_" + n + ".csv", "", "", {}});
    }
    project.datasets.push_back(
        {"edge_x", dataset_kind::kFeatureSeries, "edge_x.csv", "Edge along X", "", {}});
    project.datasets.push_back(
        {"edge_y", dataset_kind::kFeatureSeries, "edge_y.csv", "Edge along Y", "", {}});
    saveProject(project, projectPath_.toStdString());
  }
};

TEST_F(KinematicsRoundTripTest, EveryControlSurvivesSaveAndReopenAndTheReportBuilds) {
  const std::array<QString, 5> chosen = {QStringLiteral("edge_x"), QStringLiteral("edge_y"),
                                         QStringLiteral("plane_xy"), QStringLiteral("plane_yz"),
                                         QStringLiteral("plane_zx")};
  const std::array<QString, 5> keys = {QStringLiteral("/from_spc/x_dataset"),
                                       QStringLiteral("/from_spc/y_dataset"), QStringLiteral("/planes/xy"),
                                       QStringLiteral("/planes/yz"), QStringLiteral("/planes/zx")};
  const auto combos = [](const KinematicsPage& page) {
    return std::array<QComboBox*, 5>{page.edgeCombo(0), page.edgeCombo(1), page.planeCombo(TestPlane::XY),
                                     page.planeCombo(TestPlane::YZ), page.planeCombo(TestPlane::ZX)};
  };
  QString saved;
  {
    ProjectDocument doc;
    doc.load(projectPath_);
    KinematicsPage page(&doc);
    ASSERT_NE(page.study(), nullptr) << page.errorMessage().toStdString();
    const auto c = combos(page);
    for (std::size_t i = 0; i < c.size(); ++i) {
      const int index = c[i]->findData(chosen[i]);
      ASSERT_GE(index, 1) << chosen[i].toStdString();
      c[i]->setCurrentIndex(index);
      EXPECT_EQ(doc.studyValue(kKin, keys[i]), nlohmann::json(chosen[i].toStdString()));
    }
    EXPECT_EQ(doc.undoStack()->count(), 5) << "one undo step per choice";
    ASSERT_NE(page.study(), nullptr) << page.errorMessage().toStdString();
    EXPECT_TRUE(page.study()->fromSpc.has_value()) << page.study()->fromSpcError;
    EXPECT_TRUE(page.study()->threeAxis.has_value()) << page.study()->threeAxisError;
    ASSERT_TRUE(page.compensate());
    saved = QDir(dir_.path()).filePath(QStringLiteral("every_control.metrofit"));
    doc.saveAs(saved);
  }
  // Reopened: every control shows its value again, the stored result is current.
  ProjectDocument doc;
  doc.load(saved);
  KinematicsPage page(&doc);
  const auto c = combos(page);
  for (std::size_t i = 0; i < c.size(); ++i)
    EXPECT_EQ(c[i]->currentData().toString(), chosen[i]) << keys[i].toStdString();
  ASSERT_NE(page.study(), nullptr) << page.errorMessage().toStdString();
  EXPECT_TRUE(page.study()->fromSpc.has_value());
  EXPECT_TRUE(page.study()->threeAxis.has_value());
  EXPECT_TRUE(page.storedLabel()->text().startsWith(QStringLiteral("From the saved project")))
      << page.storedLabel()->text().toStdString();
  EXPECT_FALSE(doc.isModified()) << "showing a project is not an edit";

  // The PDF report of the reopened project, from the GUI ...
  ReportExporter exporter(&page);
  exporter.setCliPath(QStringLiteral(METROFIT_CLI_EXECUTABLE));
  QSignalSpy finished(&exporter, &ReportExporter::finished);
  const QString pdf = QDir(dir_.path()).filePath(QStringLiteral("gui.pdf"));
  ASSERT_TRUE(exporter.start(doc, pdf));
  ASSERT_TRUE(finished.wait(600000));
  ASSERT_EQ(finished.at(0).at(0).value<ReportExporter::Outcome>(), ReportExporter::Outcome::Written)
      << finished.at(0).at(1).toString().toStdString();
  EXPECT_GT(QFileInfo(pdf).size(), 1000);
  // ... and from the command line on the saved file.
  QProcess cli;
  const QString cliPdf = QDir(dir_.path()).filePath(QStringLiteral("cli.pdf"));
  cli.start(QStringLiteral(METROFIT_CLI_EXECUTABLE),
            {QStringLiteral("report"), QStringLiteral("--project"), saved, QStringLiteral("--out"), cliPdf});
  ASSERT_TRUE(cli.waitForFinished(600000));
  EXPECT_EQ(cli.exitStatus(), QProcess::NormalExit);
  EXPECT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();
  EXPECT_GT(QFileInfo(cliPdf).size(), 1000);
}

}  // namespace
}  // namespace metrofit
