// The kinematics & SPC page on the bundled demo (offscreen): the identified errors equal what
// `metrofit-cli kinematic identify` writes for the same file (within 1e-9) and the table shows
// them; compensation brings the largest radial deviation below 2 um; both views show results;
// G-code and STEP-NC exports are written atomically and read back; a missing dataset is a message.
// Grabs of both views are saved into $METROFIT_TEST_OUT for a look.
#include <gtest/gtest.h>

#include <QDir>
#include <QImage>
#include <QLabel>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>

#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

#include "app/gui/kinematicspage.h"
#include "core/io/json_util.h"
#include "core/kinematics/part21.h"
#include "qtapp.h"
#include "testsupport.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"
#include "widgets/kinematics/kinematicsviews.h"

namespace metrofit {
namespace {

class KinematicsPageTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    projectPath_ = extractDemoProject(dir_.path());
    doc_.load(projectPath_);
  }

  QTemporaryDir dir_;
  QString projectPath_;
  ProjectDocument doc_;
};

void save(QWidget& w, const char* name) {
  w.grab().toImage().save(
      QDir(QString::fromStdString(test::outDir().string())).filePath(QString::fromLatin1(name)));
}

TEST_F(KinematicsPageTest, IdentifiedErrorsEqualTheClis) {
  KinematicsPage page(&doc_);
  ASSERT_TRUE(page.errorMessage().isEmpty()) << page.errorMessage().toStdString();
  ASSERT_NE(page.study(), nullptr);
  EXPECT_EQ(page.currentDataset(), QStringLiteral("circular_demo"));
  const std::string data = page.study()->path;
  const std::string out = QDir(dir_.path()).filePath(QStringLiteral("e.json")).toStdString();
  const std::string cmd = std::string("'") + METROFIT_CLI_EXECUTABLE + "' kinematic identify --data '" +
                          data + "' --out '" + out + "' 2>/dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const nlohmann::json j = readJsonFile(out);
  const IdentifyResult& r = page.study()->identification;
  EXPECT_NEAR(r.errors.originMm.x(), j["origin_mm"][0].get<double>(), 1e-9);
  EXPECT_NEAR(r.errors.originMm.y(), j["origin_mm"][1].get<double>(), 1e-9);
  EXPECT_NEAR(r.errors.xAxisAngleDeg, j["x_axis_angle_deg"].get<double>(), 1e-9);
  EXPECT_NEAR(r.errors.yAxisAngleDeg, j["y_axis_angle_deg"].get<double>(), 1e-9);
  EXPECT_NEAR(r.rmseMm, j["rmse_mm"].get<double>(), 1e-9);
  EXPECT_NEAR(r.standardErrors.xAxisAngleDeg, j["standard_errors"]["x_axis_angle_deg"].get<double>(), 1e-9);

  // The table shows them in um and deg with the standard errors, next to the simulated truth.
  QTableWidget* t = page.errorTable();
  ASSERT_GE(t->rowCount(), 5);
  EXPECT_EQ(t->item(0, 0)->text(), QStringLiteral("origin x (µm)"));
  EXPECT_EQ(t->item(0, 1)->text(), QString::number(r.errors.originMm.x() * 1000.0, 'f', 3));
  EXPECT_EQ(t->item(0, 2)->text(), QString::number(r.standardErrors.originMm.x() * 1000.0, 'f', 3));
  EXPECT_EQ(t->item(2, 0)->text(), QStringLiteral("X axis angle a (deg)"));
  EXPECT_EQ(t->item(2, 1)->text(), QString::number(r.errors.xAxisAngleDeg, 'f', 6));
  EXPECT_EQ(t->item(3, 1)->text(), QString::number(r.errors.yAxisAngleDeg, 'f', 6));
  EXPECT_EQ(t->item(2, 3)->text(), QStringLiteral("0.010000"));
  EXPECT_EQ(t->item(3, 3)->text(), QStringLiteral("-0.020000"));
  // The targets on the demo (0.5 um noise).
  EXPECT_NEAR(r.errors.xAxisAngleDeg, 0.01, 1e-3);
  EXPECT_NEAR(r.errors.yAxisAngleDeg, -0.02, 1e-3);
  EXPECT_NEAR(r.errors.originMm.x(), 0.004, 1e-3);
  EXPECT_NEAR(r.errors.originMm.y(), -0.003, 1e-3);
}

TEST_F(KinematicsPageTest, CompensationBringsTheRadialDeviationBelow2um) {
  KinematicsPage page(&doc_);
  page.resize(1150, 720);
  EXPECT_EQ(page.compensation(), nullptr);
  ASSERT_TRUE(page.compensate()) << page.errorMessage().toStdString();
  const CompensationPreview* c = page.compensation();
  ASSERT_NE(c, nullptr);
  // Squareness -0.03 deg on R 50 mm: about 13 um before.
  EXPECT_GT(c->maxBeforeMm, 0.010);
  ASSERT_TRUE(c->maxSimulatedMm.has_value());
  EXPECT_LT(*c->maxSimulatedMm, 0.002);
  EXPECT_LT(c->maxExpectedMm, 0.002);
  EXPECT_LT(c->maxModelMm, 1e-9);
  EXPECT_EQ(c->references.size(), page.study()->measured.size());
  // The tables and the views show them.
  QTableWidget* t = page.compensationTable();
  ASSERT_GE(t->rowCount(), 4);
  EXPECT_EQ(t->item(0, 1)->text(), QString::number(c->maxBeforeMm * 1000.0, 'f', 3));
  EXPECT_EQ(page.pathView()->data().references.size(), c->references.size());
  EXPECT_FALSE(page.polarView()->data().compensated.empty());
}

TEST_F(KinematicsPageTest, ShowViewShowsResultsOnBothViews) {
  KinematicsPage page(&doc_);
  page.resize(1150, 720);
  page.show();
  page.showView(QStringLiteral("path"));
  EXPECT_EQ(page.tabs()->currentIndex(), 0);
  ASSERT_NE(page.compensation(), nullptr);
  EXPECT_EQ(page.polarView()->data().loops.size(), 2u);
  EXPECT_TRUE(page.polarView()->data().loops[0].counterClockwise);
  EXPECT_FALSE(page.polarView()->data().loops[1].counterClockwise);
  save(page, "kinematicspage-path.png");

  page.showView(QStringLiteral("spc"));
  EXPECT_EQ(page.tabs()->currentIndex(), 1);
  ASSERT_TRUE(page.study()->spc.has_value()) << page.study()->spcError;
  EXPECT_TRUE(page.spcView()->meanChart()->hasChart());
  EXPECT_TRUE(page.spcView()->rangeChart()->hasChart());
  EXPECT_GT(page.spcView()->indexTable()->rowCount(), 8);
  EXPECT_EQ(page.study()->spc->result.chart.subgroups(), 5u);
  save(page, "kinematicspage-spc.png");
}

TEST_F(KinematicsPageTest, ExportsGcodeAndStepNc) {
  KinematicsPage page(&doc_);
  const QString gcode = QDir(dir_.path()).filePath(QStringLiteral("c.nc"));
  const QString p21 = QDir(dir_.path()).filePath(QStringLiteral("c.p21"));
  QString error;
  ASSERT_TRUE(page.exportGcode(gcode, &error)) << error.toStdString();
  ASSERT_TRUE(page.exportStepNc(p21, &error)) << error.toStdString();
  const std::string g = test::readText(gcode.toStdString());
  EXPECT_EQ(g.rfind("%\n", 0), 0u) << g.substr(0, 80);
  EXPECT_NE(g.find("G01"), std::string::npos);
  const StepNcToolpath path = stepNcToolpath(readPart21(p21.toStdString()));
  ASSERT_EQ(path.points.size(), page.compensation()->references.size());
  EXPECT_DOUBLE_EQ(path.points[5].x(), page.compensation()->references[5].x());
  EXPECT_DOUBLE_EQ(path.points[5].y(), page.compensation()->references[5].y());
  // An unwritable target is an error message, not a crash, and leaves nothing.
  EXPECT_FALSE(page.exportGcode(QDir(dir_.path()).filePath(QStringLiteral("no/such/dir/c.nc")), &error));
  EXPECT_FALSE(error.isEmpty());
}

TEST(KinematicsPageEmpty, ProjectWithoutCircularTestShowsAMessage) {
  ProjectDocument doc;
  KinematicsPage page(&doc);
  EXPECT_EQ(page.study(), nullptr);
  EXPECT_TRUE(page.errorMessage().contains(QStringLiteral("circular_test")));
  EXPECT_FALSE(page.compensateButton()->isEnabled());
  EXPECT_FALSE(page.compensate());
  page.showView(QStringLiteral("path"));  // no crash
}

}  // namespace
}  // namespace metrofit
