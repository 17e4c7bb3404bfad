// The kinematics & SPC page on the bundled demo (offscreen): the identified errors equal what
// `metrofit-cli kinematic identify` writes for the same file (within 1e-9) and the table shows
// them, as the ballbar table shows its "causes"; compensation brings the largest radial deviation below 2 um;
// both views show results; G-code and STEP-NC exports are written atomically and read back; a missing dataset
// is a message. Grabs of both views are saved into $METROFIT_TEST_OUT for a look.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <regex>
#include <sstream>

#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QScrollBar>
#include <QSpinBox>
#include <QStackedLayout>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QUndoStack>

#include <array>
#include <cstdlib>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/gui/kinematicspage.h"
#include "core/common/numformat.h"
#include "core/io/cmm_text_report.h"
#include "core/io/json_util.h"
#include "core/kinematics/part21.h"
#include "qtapp.h"
#include "testsupport.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"
#include "widgets/kinematics/ballbartext.h"
#include "widgets/kinematics/kinematicsviews.h"
#include "widgets/report/report.h"

#include <QProcess>
#include <fstream>

#include "core/project/project.h"
#include "core/sim/circular_sim.h"
#include "core/study/kinematic_study.h"
#include "core/study/study_settings.h"

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
  EXPECT_EQ(t->item(0, 1)->text(), QLocale().toString(r.errors.originMm.x() * 1000.0, 'f', 3));
  EXPECT_EQ(t->item(0, 2)->text(), QLocale().toString(r.standardErrors.originMm.x() * 1000.0, 'f', 3));
  EXPECT_EQ(t->item(2, 0)->text(), QStringLiteral("X axis angle a (deg)"));
  EXPECT_EQ(t->item(2, 1)->text(), QLocale().toString(r.errors.xAxisAngleDeg, 'f', 6));
  EXPECT_EQ(t->item(3, 1)->text(), QLocale().toString(r.errors.yAxisAngleDeg, 'f', 6));
  EXPECT_EQ(t->item(2, 3)->text(), QLocale().toString(0.01, 'f', 6));
  EXPECT_EQ(t->item(3, 3)->text(), QLocale().toString(-0.02, 'f', 6));
  // The ISO 230-4 results of the test equal the CLI's (identify's iso230_4) and the summary shows them in um.
  const Iso230Result& iso = page.study()->analysis.iso;
  ASSERT_EQ(iso.directions.size(), 2u);
  ASSERT_TRUE(iso.circularHysteresisMm);
  const nlohmann::json& ji = j["iso230_4"];
  EXPECT_NEAR(iso.directions[0].circularDeviationMm * 1000.0,
              ji["ccw"]["circular_deviation_g_um"].get<double>(), 1e-9);
  EXPECT_NEAR(iso.directions[1].circularDeviationMm * 1000.0,
              ji["cw"]["circular_deviation_g_um"].get<double>(), 1e-9);
  EXPECT_NEAR(iso.directions[1].radialDeviationMaxMm * 1000.0,
              ji["cw"]["radial_deviation_f_max_um"].get<double>(), 1e-9);
  EXPECT_NEAR(*iso.circularHysteresisMm * 1000.0, ji["circular_hysteresis_h_um"].get<double>(), 1e-9);
  const QString info = page.infoLabel()->text();
  EXPECT_TRUE(
      info.contains(QStringLiteral("ISO 230-4: CCW: G %1 µm, F %2 … %3 µm")
                        .arg(QLocale().toString(iso.directions[0].circularDeviationMm * 1000.0, 'f', 2))
                        .arg(QLocale().toString(iso.directions[0].radialDeviationMinMm * 1000.0, 'f', 2))
                        .arg(QLocale().toString(iso.directions[0].radialDeviationMaxMm * 1000.0, 'f', 2))))
      << info.toStdString();
  EXPECT_TRUE(info.contains(
      QStringLiteral("H %1 µm").arg(QLocale().toString(*iso.circularHysteresisMm * 1000.0, 'f', 2))))
      << info.toStdString();
  // The ballbar breakdown: the table shows the CLI's "causes" in its order (ranked by share), in um and %,
  // the squareness first on the demo (the circle's only error), equal to squareness_deg x R.
  const nlohmann::json& causes = j["causes"];
  QTableWidget* bt = page.ballbarTable();
  ASSERT_TRUE(causes.is_array());
  ASSERT_EQ(bt->rowCount(), static_cast<int>(causes.size()));
  for (int i = 0; i < bt->rowCount(); ++i) {
    const nlohmann::json& c = causes[static_cast<std::size_t>(i)];
    EXPECT_EQ(bt->item(i, 0)->text(), ballbarCauseName(c["name"].get<std::string>())) << i;
    EXPECT_EQ(bt->item(i, 1)->text(), QLocale().toString(c["value_um"].get<double>(), 'f', 3)) << i;
    EXPECT_EQ(bt->item(i, 3)->text(), QLocale().toString(c["share"].get<double>() * 100.0, 'f', 1)) << i;
  }
  EXPECT_EQ(bt->item(0, 0)->text(), QStringLiteral("Squareness"));
  EXPECT_EQ(bt->item(bt->rowCount() - 1, 0)->text(), QStringLiteral("Unexplained (RMS)"));
  EXPECT_NEAR(causes[0]["value_um"].get<double>(),
              r.errors.squarenessDeg() * M_PI / 180.0 * page.study()->analysis.radiusMm * 1000.0, 0.01);
  EXPECT_TRUE(page.ballbarLabel()->text().contains(QStringLiteral("Ballbar breakdown")));
  // A squareness error g = b - a turns the circle of radius R into an ellipse: r = R - g R sin(2 theta) / 2
  // to first order, so G = R |g|; the demo's noise (0.5 um per coordinate, 360 points per loop) widens
  // the range by up to about 3 sigma on each side.
  const double squarenessRad = std::abs(r.errors.squarenessDeg()) * M_PI / 180.0;
  for (const Iso230Direction& d : iso.directions) {
    EXPECT_NEAR(d.circularDeviationMm, page.study()->analysis.radiusMm * squarenessRad, 0.004);
  }

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
  EXPECT_EQ(t->item(0, 1)->text(), QLocale().toString(c->maxBeforeMm * 1000.0, 'f', 3));
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
  // Every G01 is "G01 X<number> Y<number>" with '.' decimals (ISO 6983 address words), whatever the
  // process locale (this test also runs under de_DE.UTF-8 and pl_PL.UTF-8), and gives the references.
  {
    std::istringstream in(g);
    std::size_t k = 0;
    const std::regex g01("^G01 X([+-]?[0-9]+\\.[0-9]{4}) Y([+-]?[0-9]+\\.[0-9]{4})( F[0-9]+)?$");
    for (std::string l; std::getline(in, l);) {
      if (l.rfind("G01", 0) != 0) continue;
      std::smatch m;
      ASSERT_TRUE(std::regex_match(l, m, g01)) << l;
      ASSERT_LT(k, page.compensation()->references.size());
      const Eigen::Vector2d& r = page.compensation()->references[k++];
      EXPECT_NEAR(test::cnumber(m[1].str()), r.x(), 0.5e-4 + 1e-9) << l;
      EXPECT_NEAR(test::cnumber(m[2].str()), r.y(), 0.5e-4 + 1e-9) << l;
    }
    EXPECT_EQ(k, page.compensation()->references.size());
  }
  const StepNcToolpath path = stepNcToolpath(readPart21(p21.toStdString()));
  ASSERT_EQ(path.points.size(), page.compensation()->references.size());
  EXPECT_DOUBLE_EQ(path.points[5].x(), page.compensation()->references[5].x());
  EXPECT_DOUBLE_EQ(path.points[5].y(), page.compensation()->references[5].y());
  // An unwritable target is an error message, not a crash, and leaves nothing.
  EXPECT_FALSE(page.exportGcode(QDir(dir_.path()).filePath(QStringLiteral("no/such/dir/c.nc")), &error));
  EXPECT_FALSE(error.isEmpty());
}

TEST_F(KinematicsPageTest, RadialOnlyTestSaysWhyItCannotBeIdentifiedAndShowsItsIsoResults) {
  // A ballbar export (docs/file-formats.md#circular-test): 360 points CCW, 360 CW (directions from the
  // angles), an offset of 5 um with a 3-lobe form of 2 um, the CW run 1.5 um out: G = 4 um, H = 1.5 um.
  std::string text = "angle_deg,deviation_um\n";
  for (int loop = 0; loop < 2; ++loop) {
    for (int k = 0; k < 360; ++k) {
      const int deg = loop == 0 ? k : 360 - k;
      const double th = deg * M_PI / 180.0;
      // num::toString: '.' decimals whatever the test process's locale (the test data, not the subject).
      text += std::to_string(deg) + "," +
              num::toString(5.0 * std::cos(th) + 2.0 * std::cos(3.0 * th) + (loop == 1 ? 1.5 : 0.0)) + "\n";
    }
  }
  std::ofstream(QDir(dir_.path()).filePath(QStringLiteral("ballbar.csv")).toStdString()) << text;
  DatasetRef ref;
  ref.id = "ballbar";
  ref.kind = dataset_kind::kCircularTest;
  ref.path = QDir(dir_.path()).filePath(QStringLiteral("ballbar.csv")).toStdString();
  doc_.addDataset(ref);
  KinematicsPage page(&doc_);
  page.selectDataset(QStringLiteral("ballbar"));
  EXPECT_EQ(page.study(), nullptr);
  EXPECT_TRUE(page.errorMessage().contains(QStringLiteral("ballbar.csv: is a radial-only circular test")))
      << page.errorMessage().toStdString();
  const QString message = page.messageLabel()->text();
  // Numbers in the UI's locale (this test also runs with LC_ALL=de_DE.UTF-8 and pl_PL.UTF-8).
  const QString four = QLocale().toString(4.0, 'f', 2), oneAndAHalf = QLocale().toString(1.5, 'f', 2);
  EXPECT_TRUE(message.contains(QStringLiteral("ISO 230-4: CCW: G %1 µm").arg(four))) << message.toStdString();
  EXPECT_TRUE(message.contains(QStringLiteral("CW: G %1 µm").arg(four))) << message.toStdString();
  EXPECT_TRUE(message.contains(QStringLiteral("H %1 µm").arg(oneAndAHalf))) << message.toStdString();
  // Instead of the tabs: the message and the polar plot of both runs (drawn on 100 mm: no radius_mm).
  ASSERT_NE(page.radialPolarView(), nullptr);
  EXPECT_EQ(page.currentView(), page.radialPolarView()->parentWidget());
  const PolarPlotData& polar = page.radialPolarView()->data();
  ASSERT_EQ(polar.loops.size(), 2u);
  EXPECT_TRUE(polar.loops[0].counterClockwise);
  EXPECT_FALSE(polar.loops[1].counterClockwise);
  EXPECT_EQ(polar.loops[1].points.size(), 360u);
  EXPECT_EQ(polar.radiusMm, 100.0);
  EXPECT_FALSE(polar.radiusKnown);  // the legend says the radius is only the drawing's
  page.resize(900, 600);
  save(page, "kinematics_radial_only.png");
  EXPECT_FALSE(page.compensateButton()->isEnabled());

  // As the kinematics study's test, the report shows its ISO 230-4 results and says why there is no
  // identification (the report of an x/y test would fail on it).
  doc_.setStudyValue(QStringLiteral("kinematics"), QStringLiteral("/dataset"), "ballbar",
                     QStringLiteral("x"));
  doc_.save();
  const QString pdf = QDir(dir_.path()).filePath(QStringLiteral("r.pdf"));
  ReportOptions o;
  o.projectPath = projectPath_;
  o.resolutionDpi = 100;
  writeReport(loadProject(projectPath_.toStdString()), pdf, o);
  QProcess p;
  p.start(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")});
  ASSERT_TRUE(p.waitForFinished(60000));
  const QString report = QString::fromUtf8(p.readAllStandardOutput()).simplified();
  EXPECT_TRUE(report.contains(QStringLiteral("720 points of a radial-only circular test")))
      << report.toStdString();
  EXPECT_TRUE(report.contains(QStringLiteral("ISO 230-4 results")));
  EXPECT_TRUE(report.contains(QStringLiteral("largest circular deviation G 4.0 µm"))) << report.toStdString();
  EXPECT_TRUE(report.contains(QStringLiteral("Circular hysteresis H 1.5 µm")));
}

// Found in the de_DE walk (2026-11-30): the SPC tab of a project made in the GUI said to set "spc" in the
// project file. The series, its characteristic, the subgroup and the limits are chosen on the tab, each an
// undoable edit; a limit alone is not written (the study would refuse it), both are; the chart shows the
// values of the file, read here by the test.
TEST_F(KinematicsPageTest, SpcSeriesAndLimitsAreChosenOnTheTabWithoutTheProjectFile) {
  // The number entry is checked in C and German below, whatever the locale the test runs under.
  const QLocale outer;
  QLocale::setDefault(QLocale::c());
  Project p = doc_.project();
  p.studies["kinematics"].erase("spc");
  saveProject(p, projectPath_.toStdString());
  doc_.load(projectPath_);
  KinematicsPage page(&doc_);
  ASSERT_NE(page.study(), nullptr) << page.errorMessage().toStdString();
  EXPECT_FALSE(page.study()->spc.has_value());
  EXPECT_TRUE(page.spcView()->messageLabel()->text().contains(QStringLiteral("choose the measured series")))
      << page.spcView()->messageLabel()->text().toStdString();
  EXPECT_FALSE(page.spcLslEdit()->isEnabled());
  const auto spc = [&] { return doc_.studyValue(QStringLiteral("kinematics"), QStringLiteral("/spc")); };

  const int before = doc_.undoStack()->index();
  QComboBox* series = page.spcSeriesCombo();
  ASSERT_GE(series->findData(QStringLiteral("bores_demo")), 0);
  series->setCurrentIndex(series->findData(QStringLiteral("bores_demo")));
  EXPECT_EQ(doc_.undoStack()->index(), before + 1);
  // The part counter is not the characteristic: the diameter is.
  EXPECT_EQ(spc()["dataset"], "bores_demo");
  EXPECT_EQ(spc()["column"], "diameter_mm");
  // The subgroup box shows what the study uses (the default 5 here; the screenshot showed 2 once).
  EXPECT_EQ(page.spcSubgroupBox()->value(), KinematicsSettings::Spc{}.subgroup);
  ASSERT_NE(page.study(), nullptr);
  ASSERT_TRUE(page.study()->spc.has_value()) << page.study()->spcError;
  // The file's diameters, read by the test.
  std::vector<double> diameters;
  {
    std::ifstream in(
        QDir(QFileInfo(projectPath_).path()).filePath(QStringLiteral("data/bores_demo.csv")).toStdString());
    std::string line;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#' || line.rfind("part,", 0) == 0) continue;
      const std::size_t a = line.find(',');
      // QByteArray::toDouble: the C format whatever the process locale (std::stod follows LC_NUMERIC).
      bool ok = false;
      diameters.push_back(
          QByteArray::fromStdString(line.substr(a + 1, line.find(',', a + 1) - a - 1)).toDouble(&ok));
      EXPECT_TRUE(ok) << line;
    }
  }
  ASSERT_EQ(diameters.size(), 25u);
  ASSERT_EQ(page.study()->spc->values.size(), diameters.size());
  for (std::size_t i = 0; i < diameters.size(); ++i)
    EXPECT_NEAR(page.study()->spc->values[i], diameters[i], 1e-9) << i;
  // The characteristic list holds the numeric columns.
  EXPECT_GE(page.spcColumnCombo()->findData(QStringLiteral("centre_x_mm")), 0);

  // A limit alone: not written, the hint says why; with both: one step, the study's Cp follows.
  page.spcLslEdit()->setText(QStringLiteral("99.98"));
  emit page.spcLslEdit()->editingFinished();
  EXPECT_FALSE(spc().contains("lsl"));
  EXPECT_TRUE(page.spcLimitsHint().contains(QStringLiteral("both"))) << page.spcLimitsHint().toStdString();
  page.spcUslEdit()->setText(QStringLiteral("100.02"));
  emit page.spcUslEdit()->editingFinished();
  EXPECT_EQ(spc()["lsl"], 99.98);
  EXPECT_EQ(spc()["usl"], 100.02);
  EXPECT_TRUE(page.spcLimitsHint().isEmpty());
  ASSERT_TRUE(page.study()->spc->result.capability.cp.has_value());
  EXPECT_GT(*page.study()->spc->result.capability.cp, 0.0);
  // In a German UI the decimal comma is read ("100,0" is 100, not 1000), and the point as well.
  QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
  page.spcNominalEdit()->setText(QStringLiteral("100,0"));
  emit page.spcNominalEdit()->editingFinished();
  EXPECT_EQ(spc()["nominal"], 100.0);
  page.spcNominalEdit()->setText(QStringLiteral("100.001"));
  emit page.spcNominalEdit()->editingFinished();
  EXPECT_EQ(spc()["nominal"], 100.001);
  QLocale::setDefault(QLocale::c());
  // The limits were shown in the German form meanwhile ("99,98"); the UI language does not change in a
  // session, so the test puts the C form back.
  page.spcLslEdit()->setText(QStringLiteral("99.98"));
  page.spcUslEdit()->setText(QStringLiteral("100.02"));
  // Under C a comma is no decimal mark: refused with the text named, nothing written.
  page.spcNominalEdit()->setText(QStringLiteral("100,0"));
  emit page.spcNominalEdit()->editingFinished();
  EXPECT_EQ(spc()["nominal"], 100.001);
  EXPECT_TRUE(page.spcLimitsHint().contains(QStringLiteral("100,0"))) << page.spcLimitsHint().toStdString();
  page.spcNominalEdit()->setText(QStringLiteral("100"));
  emit page.spcNominalEdit()->editingFinished();
  EXPECT_EQ(spc()["nominal"], 100.0);
  page.spcSubgroupBox()->setValue(4);
  doc_.endEditSequence();
  EXPECT_EQ(spc()["subgroup"], 4);
  EXPECT_EQ(page.study()->settings.spc->options.subgroupSize, 4);

  // Undo back to the start removes the block; the tab says to choose a series again.
  doc_.undoStack()->setIndex(before);
  EXPECT_TRUE(spc().is_null()) << spc();
  EXPECT_FALSE(page.study()->spc.has_value());
  EXPECT_EQ(page.spcSeriesCombo()->currentData().toString(), QString());
  QLocale::setDefault(outer);
}

// A shop's part series without any circular test (the walk's SPC journey): the page shows the SPC tab alone,
// the other tabs disabled and the reason above them, and charts the series chosen there.
TEST_F(KinematicsPageTest, SpcWithoutACircularTestShowsTheSpcTabAlone) {
  Project p = doc_.project();
  std::erase_if(p.datasets, [](const DatasetRef& d) { return d.kind == "circular_test"; });
  p.studies["kinematics"].erase("dataset");
  p.studies["kinematics"].erase("simulated_machine");
  p.studies["kinematics"].erase("spc");
  p.studies["diagnosis"].erase("kinematic");
  saveProject(p, projectPath_.toStdString());
  doc_.load(projectPath_);
  KinematicsPage page(&doc_);
  EXPECT_EQ(page.study(), nullptr);
  EXPECT_TRUE(page.errorMessage().contains(QStringLiteral("circular_test")));
  ASSERT_EQ(page.currentView(), page.tabs());
  QWidget* spcTab = page.tabs()->currentWidget();
  ASSERT_EQ(page.tabs()->tabText(page.tabs()->currentIndex()), QStringLiteral("S&PC"));
  for (int i = 0; i < page.tabs()->count(); ++i)
    EXPECT_EQ(page.tabs()->isTabEnabled(i), page.tabs()->widget(i) == spcTab) << i;
  EXPECT_TRUE(page.infoLabel()->text().contains(QStringLiteral("only the SPC tab")))
      << page.infoLabel()->text().toStdString();
  auto* stack = static_cast<QStackedLayout*>(page.spcView()->layout());
  EXPECT_EQ(stack->currentWidget(), page.spcView()->messageLabel());

  QComboBox* series = page.spcSeriesCombo();
  series->setCurrentIndex(series->findData(QStringLiteral("bores_demo")));
  EXPECT_NE(stack->currentWidget(), page.spcView()->messageLabel())
      << page.spcView()->messageLabel()->text().toStdString();
  EXPECT_GT(page.spcView()->indexTable()->rowCount(), 0);
  EXPECT_FALSE(page.compensateButton()->isEnabled());
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

/// The demo extended by the kinematic-compensation paper's chain: edges along X and Y machined on the demo's
/// simulated machine (origin (4, -3) um, a = 0.01 deg, b = -0.02 deg; 0.5 um noise) and circular tests in XY,
/// YZ and ZX of a three-axis machine with known squareness.
class KinematicsActuatorsTest : public ::testing::Test {
 protected:
  static ActuatorErrors3 machine3() {
    ActuatorErrors3 e;
    e.originMm = Eigen::Vector3d(0.006, -0.004, 0.003);
    e.uAngleDeg = {0.002, -0.001, 0.0015};
    e.vAngleDeg = {-0.003, 0.002, -0.0025};
    return e;
  }

  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    projectPath_ = extractDemoProject(dir_.path());
    const QDir d(dir_.path());
    ActuatorErrors2 demo;
    demo.originMm = Eigen::Vector2d(0.004, -0.003);
    demo.xAxisAngleDeg = 0.01;
    demo.yAxisAngleDeg = -0.02;
    for (const char axis : {'x', 'y'}) {
      EdgeSimOptions o;
      o.axis = axis;
      o.errors = demo;
      o.seed = axis == 'x' ? 13 : 14;  // (seed 12's Y edge raises a 3-sigma false alarm, ~1 in 10)
      std::ofstream(d.filePath(QStringLiteral("edge_%1.csv").arg(QLatin1Char(axis))).toStdString())
          << axisFeatureToCsv(simulateAxisFeature(o));
    }
    for (const TestPlane p : kTestPlanes) {
      CircularSimOptions o;
      o.seed = 20 + static_cast<int>(p);
      std::ofstream(d.filePath(QStringLiteral("plane_%1.csv").arg(QLatin1String(planeName(p)))).toStdString())
          << planePathToCsv(simulatePlaneCircularTest(machine3(), p, o), p);
    }
    Project project = loadProject(projectPath_.toStdString());
    project.datasets.push_back(
        {"edge_x", dataset_kind::kFeatureSeries, "edge_x.csv", "Edge along X", "", {}});
    project.datasets.push_back(
        {"edge_y", dataset_kind::kFeatureSeries, "edge_y.csv", "Edge along Y", "", {}});
    for (const TestPlane p : kTestPlanes) {
      const std::string n = planeName(p);
      project.datasets.push_back(
          {"plane_" + n, dataset_kind::kFeatureSeries, "plane_" + n + ".csv", "", "", {}});
    }
    project.studies["kinematics"]["from_spc"] = {{"x_dataset", "edge_x"}, {"y_dataset", "edge_y"}};
    project.studies["kinematics"]["planes"] = {{"xy", "plane_xy"}, {"yz", "plane_yz"}, {"zx", "plane_zx"}};
    saveProject(project, projectPath_.toStdString());
    doc_.load(projectPath_);
  }

  QTemporaryDir dir_;
  QString projectPath_;
  ProjectDocument doc_;
};

TEST_F(KinematicsActuatorsTest, PageShowsTheErrorsDerivedFromSpcAndTheThreeAxes) {
  KinematicsPage page(&doc_);
  page.resize(1150, 720);
  page.showView(QStringLiteral("actuators"));
  EXPECT_EQ(page.tabs()->currentIndex(), 2);
  const KinematicStudyData* s = page.study();
  ASSERT_NE(s, nullptr);
  ASSERT_TRUE(s->fromSpc.has_value()) << s->fromSpcError;
  ASSERT_TRUE(s->threeAxis.has_value()) << s->threeAxisError;
  const SpcActuatorResult& r = *s->fromSpc;
  // The injected errors; the offset angles' se is ~7e-5 deg (0.5 um over 200 mm), the origin's ~0.1 um.
  EXPECT_NEAR(r.errors.xAxisAngleDeg, 0.01, 5e-4);
  EXPECT_NEAR(r.errors.yAxisAngleDeg, -0.02, 5e-4);
  EXPECT_NEAR(r.errors.originMm.x(), 0.004, 5e-4);
  EXPECT_NEAR(r.errors.originMm.y(), -0.003, 5e-4);
  // ... and the circular test, an independent estimate of the same machine, agrees.
  EXPECT_NEAR(r.errors.squarenessDeg(), s->identification.errors.squarenessDeg(), 1e-3);
  // The references derived from SPC, run through the circular test's model, nearly reach the circle.
  EXPECT_GT(s->fromSpcModelBeforeMm, 0.02);
  EXPECT_LT(s->fromSpcModelAfterMm, 0.003);

  QTableWidget* t = page.fromSpcTable();
  EXPECT_FALSE(t->isHidden());
  ASSERT_EQ(t->rowCount(), 9);
  EXPECT_EQ(t->item(0, 1)->text(), QLocale().toString(r.x.line.angleDeg, 'f', 6));
  EXPECT_EQ(t->item(4, 0)->text(), QStringLiteral("X axis angle a (deg)"));
  EXPECT_EQ(t->item(4, 1)->text(), QLocale().toString(r.errors.xAxisAngleDeg, 'f', 6));
  EXPECT_EQ(t->item(4, 2)->text(), QLocale().toString(s->identification.errors.xAxisAngleDeg, 'f', 6));
  EXPECT_TRUE(page.fromSpcLabel()->text().contains(QStringLiteral("compensation applied")))
      << page.fromSpcLabel()->text().toStdString();

  QTableWidget* t3 = page.threeAxisTable();
  EXPECT_FALSE(t3->isHidden());
  ASSERT_EQ(t3->rowCount(), 3);
  const ActuatorErrors3 truth = machine3();
  for (const TestPlane p : kTestPlanes) {
    const int row = static_cast<int>(p);
    EXPECT_EQ(t3->item(row, 0)->text(), QString::fromLatin1(planeName(p)).toUpper());
    // The table shows the joint identification of the three simulated tests (0.5 um noise); its
    // squareness is within a few of the fit's own standard errors of the machine's true value, and
    // 1.5e-4 deg (0.5 um over 200 mm) bounds that from the noise alone.
    EXPECT_NEAR(QLocale().toDouble(t3->item(row, 3)->text()), truth.squarenessDeg(p), 1.5e-4) << planeName(p);
    const double se = s->threeAxis->squarenessStdErrDeg[static_cast<std::size_t>(row)];
    EXPECT_GT(se, 0.0) << planeName(p);
    EXPECT_LE(std::abs(QLocale().toDouble(t3->item(row, 3)->text()) - truth.squarenessDeg(p)),
              5.0 * se + 5e-7)
        << planeName(p) << " se " << se;  // + half a unit of the table's last digit
  }
  save(page, "kinematics_actuators.png");
}

TEST_F(KinematicsActuatorsTest, UnconfiguredStudySaysHowToConfigureIt) {
  Project project = loadProject(projectPath_.toStdString());
  project.studies["kinematics"].erase("from_spc");
  project.studies["kinematics"]["planes"]["yz"] = "plane_xy";  // XY columns where YZ ones belong
  saveProject(project, projectPath_.toStdString());
  ProjectDocument doc;
  doc.load(projectPath_);
  KinematicsPage page(&doc);
  ASSERT_NE(page.study(), nullptr);
  EXPECT_TRUE(page.fromSpcTable()->isHidden());
  EXPECT_TRUE(page.fromSpcLabel()->text().contains(QStringLiteral("choose the edges")));
  EXPECT_TRUE(page.threeAxisTable()->isHidden());
  EXPECT_TRUE(page.threeAxisLabel()->text().contains(QStringLiteral("y_cmd_mm")))
      << page.threeAxisLabel()->text().toStdString();
}

/// The least-squares line d = c + s u through a CSV's position_mm / deviation_mm columns, written here
/// from the textbook formula (s = Sud / Suu) with its own reader: the paper's regression line (Fig. 10).
double leastSquaresSlope(const std::string& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "position_mm,deviation_mm") << file;
  std::vector<double> u, d;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto comma = line.find(',');
    u.push_back(test::cnumber(line.substr(0, comma)));
    d.push_back(test::cnumber(line.substr(comma + 1)));
  }
  double mu = 0.0, md = 0.0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    mu += u[i];
    md += d[i];
  }
  mu /= static_cast<double>(u.size());
  md /= static_cast<double>(u.size());
  double suu = 0.0, sud = 0.0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    suu += (u[i] - mu) * (u[i] - mu);
    sud += (u[i] - mu) * (d[i] - md);
  }
  return sud / suu;
}

QStringList columnTexts(const QTableWidget* t, int column) {
  QStringList out;
  for (int r = 0; r < t->rowCount(); ++r)
    out << (t->item(r, column) ? t->item(r, column)->text() : QString());
  return out;
}

/// Chooses the dataset `id` in a combo as a user does (the change signal is not blocked).
void choose(QComboBox* combo, const QString& id) {
  const int index = combo->findData(id);
  ASSERT_GE(index, 0) << id.toStdString();
  combo->setCurrentIndex(index);
}

TEST_F(KinematicsActuatorsTest, PickersChooseTheDatasetsUndoablyAndTheTablesShowWhatCoreGives) {
  // The study without the chain's settings, and an edge file without the deviation column.
  const QDir d(dir_.path());
  std::ofstream(d.filePath(QStringLiteral("bad_edge.csv")).toStdString())
      << "position_mm,dev_um\n-100,1\n0,2\n100,3\n";
  Project project = loadProject(projectPath_.toStdString());
  project.studies["kinematics"].erase("from_spc");
  project.studies["kinematics"].erase("planes");
  project.datasets.push_back({"bad_edge", dataset_kind::kFeatureSeries, "bad_edge.csv", "", "", {}});
  saveProject(project, projectPath_.toStdString());
  doc_.load(projectPath_);
  const QString kin = QStringLiteral("kinematics");

  KinematicsPage page(&doc_);
  page.resize(1150, 760);
  page.showView(QStringLiteral("actuators"));
  ASSERT_NE(page.study(), nullptr) << page.errorMessage().toStdString();
  QComboBox* x = page.edgeCombo(0);
  QComboBox* y = page.edgeCombo(1);
  // Keyboard: every chooser has a label whose buddy it is (Alt + the label's letter).
  for (QComboBox* c : {x, y, page.planeCombo(TestPlane::XY), page.planeCombo(TestPlane::YZ),
                       page.planeCombo(TestPlane::ZX)}) {
    bool buddy = false;
    for (const QLabel* l : page.findChildren<QLabel*>()) buddy = buddy || l->buddy() == c;
    EXPECT_TRUE(buddy) << c->objectName().toStdString();
    EXPECT_NE(c->focusPolicy() & Qt::TabFocus, 0) << c->objectName().toStdString();
  }
  // Items: none, then the feature series (edges) or the circular tests and feature series (planes).
  EXPECT_EQ(x->itemData(0).toString(), QString());
  EXPECT_EQ(x->currentIndex(), 0);
  EXPECT_GE(x->findData(QStringLiteral("edge_x")), 1);
  EXPECT_GE(x->findData(QStringLiteral("bad_edge")), 1);
  EXPECT_LT(x->findData(QStringLiteral("circular_demo")), 0);
  EXPECT_GE(page.planeCombo(TestPlane::XY)->findData(QStringLiteral("circular_demo")), 1);
  EXPECT_GE(page.planeCombo(TestPlane::YZ)->findData(QStringLiteral("plane_yz")), 1);
  EXPECT_TRUE(page.fromSpcTable()->isHidden());
  EXPECT_TRUE(page.fromSpcLabel()->text().contains(QStringLiteral("choose the edges")))
      << page.fromSpcLabel()->text().toStdString();
  EXPECT_FALSE(page.edgesDfqButton()->isEnabled());

  // One edge: the setting is written, and the study says which edge is missing.
  choose(x, QStringLiteral("edge_x"));
  EXPECT_EQ(doc_.studyValue(kin, QStringLiteral("/from_spc/x_dataset")), "edge_x");
  EXPECT_TRUE(page.fromSpcTable()->isHidden());
  EXPECT_TRUE(page.fromSpcLabel()->text().contains(QStringLiteral(
      "field 'studies.kinematics.from_spc.y_dataset': missing: choose the edge machined along Y")))
      << page.fromSpcLabel()->text().toStdString();
  choose(y, QStringLiteral("edge_y"));
  EXPECT_EQ(doc_.studyValue(kin, QStringLiteral("/from_spc/y_dataset")), "edge_y");
  EXPECT_EQ(page.tabs()->currentIndex(), 2);  // the view stays on the actuators

  // The table equals core called directly on the same files ...
  const std::string fx = d.filePath(QStringLiteral("edge_x.csv")).toStdString();
  const std::string fy = d.filePath(QStringLiteral("edge_y.csv")).toStdString();
  const AxisFeatureSeries sx = axisFeatureFromCsv(readFeatureTable(fx), "position_mm", "deviation_mm");
  const AxisFeatureSeries sy = axisFeatureFromCsv(readFeatureTable(fy), "position_mm", "deviation_mm");
  const SpcActuatorResult r = actuatorErrorsFromSpc(sx, sy);
  QTableWidget* t = page.fromSpcTable();
  ASSERT_FALSE(t->isHidden()) << page.fromSpcLabel()->text().toStdString();
  ASSERT_EQ(t->rowCount(), 9);
  EXPECT_EQ(t->item(0, 1)->text(), QLocale().toString(r.x.line.angleDeg, 'f', 6));
  EXPECT_EQ(t->item(1, 1)->text(), QLocale().toString(r.y.line.angleDeg, 'f', 6));
  EXPECT_EQ(t->item(2, 1)->text(), QLocale().toString(r.errors.originMm.x() * 1000.0, 'f', 3));
  EXPECT_EQ(t->item(3, 1)->text(), QLocale().toString(r.errors.originMm.y() * 1000.0, 'f', 3));
  EXPECT_EQ(t->item(4, 1)->text(), QLocale().toString(r.errors.xAxisAngleDeg, 'f', 6));
  EXPECT_EQ(t->item(5, 1)->text(), QLocale().toString(r.errors.yAxisAngleDeg, 'f', 6));
  EXPECT_EQ(t->item(6, 1)->text(), QLocale().toString(r.errors.squarenessDeg(), 'f', 6));
  // ... and the paper: the regression line's offset angle is atan(slope) (Fig. 10), the X actuator's
  // angle a = atan(s_X), b = -atan(s_Y) (Eq. 9); slopes from the least-squares formula here.
  const double slopeX = leastSquaresSlope(fx), slopeY = leastSquaresSlope(fy);
  const double toDeg = 180.0 / M_PI;
  // A cell's number; a cell that is not a number fails here instead of reading as 0.
  const auto cellValue = [&](int row) {
    bool ok = false;
    const double v = QLocale().toDouble(t->item(row, 1)->text(), &ok);
    EXPECT_TRUE(ok) << "row " << row << ": '" << t->item(row, 1)->text().toStdString() << "'";
    return ok ? v : std::numeric_limits<double>::quiet_NaN();
  };
  EXPECT_NEAR(cellValue(0), std::atan(slopeX) * toDeg, 5.1e-7);
  EXPECT_NEAR(cellValue(4), std::atan(slopeX) * toDeg, 5.1e-7);
  EXPECT_NEAR(cellValue(5), -std::atan(slopeY) * toDeg, 5.1e-7);
  // The simulated machine's a = 0.01 deg, b = -0.02 deg: se of the angle ~7e-5 deg (0.5 um over 200 mm).
  EXPECT_NEAR(cellValue(4), 0.01, 4e-4);
  EXPECT_NEAR(cellValue(5), -0.02, 4e-4);

  // Save DFQ writes what `metrofit-cli kinematic from-spc --dfq` writes for the same files.
  ASSERT_TRUE(page.edgesDfqButton()->isEnabled());
  const QString guiDfq = d.filePath(QStringLiteral("gui.dfq"));
  QString error;
  ASSERT_TRUE(page.exportEdgesDfq(guiDfq, &error)) << error.toStdString();
  const std::string cliDfq = d.filePath(QStringLiteral("cli.dfq")).toStdString();
  const std::string cmd = std::string("'") + METROFIT_CLI_EXECUTABLE + "' kinematic from-spc --x-data '" +
                          fx + "' --y-data '" + fy + "' --dfq '" + cliDfq + "' --out /dev/null 2>/dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  EXPECT_EQ(test::readText(guiDfq.toStdString()), test::readText(cliDfq));
  EXPECT_NE(test::readText(cliDfq).find("K2001/1 X edge deviation_mm"), std::string::npos);

  // The three planes, one choice at a time.
  EXPECT_TRUE(page.threeAxisTable()->isHidden());
  choose(page.planeCombo(TestPlane::XY), QStringLiteral("plane_xy"));
  choose(page.planeCombo(TestPlane::YZ), QStringLiteral("plane_yz"));
  EXPECT_TRUE(page.threeAxisLabel()->text().contains(QStringLiteral(
      "field 'studies.kinematics.planes.zx': missing: choose the circular test in the ZX plane")))
      << page.threeAxisLabel()->text().toStdString();
  choose(page.planeCombo(TestPlane::ZX), QStringLiteral("plane_zx"));
  EXPECT_EQ(doc_.studyValue(kin, QStringLiteral("/planes")),
            nlohmann::json({{"xy", "plane_xy"}, {"yz", "plane_yz"}, {"zx", "plane_zx"}}));
  std::array<MeasuredPath, 3> tests;
  for (const TestPlane p : kTestPlanes) {
    tests[static_cast<std::size_t>(p)] = readPlanePath(
        d.filePath(QStringLiteral("plane_%1.csv").arg(QLatin1String(planeName(p)))).toStdString(), p);
  }
  const Identify3Result r3 = identifyActuatorErrors3(tests);
  QTableWidget* t3 = page.threeAxisTable();
  ASSERT_FALSE(t3->isHidden()) << page.threeAxisLabel()->text().toStdString();
  ASSERT_EQ(t3->rowCount(), 3);
  const ActuatorErrors3 truth = machine3();
  for (const TestPlane p : kTestPlanes) {
    const int row = static_cast<int>(p);
    const auto i = static_cast<std::size_t>(p);
    EXPECT_EQ(t3->item(row, 1)->text(), QLocale().toString(r3.errors.uAngleDeg[i], 'f', 6));
    EXPECT_EQ(t3->item(row, 2)->text(), QLocale().toString(r3.errors.vAngleDeg[i], 'f', 6));
    EXPECT_EQ(t3->item(row, 3)->text(), QLocale().toString(r3.errors.squarenessDeg(p), 'f', 6));
    // The simulated machine's squareness (0.5 um noise on 720 points of R 100 mm: se ~ 3e-5 deg).
    EXPECT_NEAR(QLocale().toDouble(t3->item(row, 3)->text()), truth.squarenessDeg(p), 1.5e-4) << planeName(p);
  }
  const QStringList threeAxisTexts = columnTexts(t3, 3);
  page.show();  // the rows fit their labels once the tables have their widths (queued)
  QCoreApplication::processEvents();
  QCoreApplication::processEvents();
  save(page, "kinematics_actuator_pickers.png");
  // The three-axis table shows its three rows without scrolling.
  EXPECT_FALSE(t3->verticalScrollBar()->isVisible());

  // Undo takes the choices back one at a time, the combos and the tables with them; redo again.
  QUndoStack* stack = doc_.undoStack();
  stack->undo();
  EXPECT_EQ(page.planeCombo(TestPlane::ZX)->currentData().toString(), QString());
  EXPECT_EQ(page.planeCombo(TestPlane::ZX)->currentText(), QStringLiteral("(none)"));
  EXPECT_TRUE(doc_.studyValue(kin, QStringLiteral("/planes/zx")).is_null());
  EXPECT_TRUE(page.threeAxisTable()->isHidden());
  stack->undo();
  stack->undo();
  EXPECT_EQ(page.planeCombo(TestPlane::XY)->currentData().toString(), QString());
  EXPECT_TRUE(page.threeAxisLabel()->text().contains(QStringLiteral("choose the circular tests")))
      << page.threeAxisLabel()->text().toStdString();
  stack->undo();  // the Y edge
  EXPECT_EQ(y->currentData().toString(), QString());
  EXPECT_TRUE(page.fromSpcTable()->isHidden());
  for (int k = 0; k < 4; ++k) stack->redo();
  EXPECT_EQ(y->currentData().toString(), QStringLiteral("edge_y"));
  EXPECT_EQ(page.planeCombo(TestPlane::ZX)->currentData().toString(), QStringLiteral("plane_zx"));
  EXPECT_FALSE(page.fromSpcTable()->isHidden());
  EXPECT_EQ(page.fromSpcTable()->item(4, 1)->text(), QLocale().toString(r.errors.xAxisAngleDeg, 'f', 6));
  EXPECT_FALSE(page.threeAxisTable()->isHidden());
  EXPECT_EQ(columnTexts(page.threeAxisTable(), 3), threeAxisTexts);

  // A file without the deviation column: core's one-line message in the label, the table hidden.
  std::string expected;
  try {
    axisFeatureFromCsv(readFeatureTable(d.filePath(QStringLiteral("bad_edge.csv")).toStdString()),
                       "position_mm", "deviation_mm");
  } catch (const std::exception& e) {
    expected = e.what();
  }
  ASSERT_FALSE(expected.empty());
  ASSERT_EQ(expected.find('\n'), std::string::npos) << expected;
  choose(x, QStringLiteral("bad_edge"));
  EXPECT_TRUE(page.fromSpcTable()->isHidden());
  EXPECT_TRUE(page.fromSpcLabel()->text().contains(QString::fromStdString(expected).toHtmlEscaped()))
      << page.fromSpcLabel()->text().toStdString() << "\nexpected: " << expected;
  EXPECT_FALSE(page.edgesDfqButton()->isEnabled());
  EXPECT_FALSE(page.threeAxisTable()->isHidden());  // the other study part is unaffected
  QCoreApplication::processEvents();
  save(page, "kinematics_actuator_pickers_bad_edge.png");
  stack->undo();
  EXPECT_EQ(x->currentData().toString(), QStringLiteral("edge_x"));
  EXPECT_FALSE(page.fromSpcTable()->isHidden());

  // Renaming a chosen dataset renames the setting; removing one removes it (the chooser goes back to
  // none and the study says what is missing); undo brings both back.
  EXPECT_EQ(doc_.datasetReferences(QStringLiteral("edge_y")),
            QStringList{QStringLiteral("studies.kinematics.from_spc.y_dataset")});
  EXPECT_EQ(doc_.datasetReferences(QStringLiteral("plane_yz")),
            QStringList{QStringLiteral("studies.kinematics.planes.yz")});
  doc_.renameDataset(QStringLiteral("edge_y"), QStringLiteral("kante_y"));
  EXPECT_EQ(doc_.studyValue(kin, QStringLiteral("/from_spc/y_dataset")), "kante_y");
  EXPECT_EQ(y->currentData().toString(), QStringLiteral("kante_y"));
  EXPECT_FALSE(page.fromSpcTable()->isHidden());
  doc_.removeDataset(QStringLiteral("plane_yz"));
  EXPECT_TRUE(doc_.studyValue(kin, QStringLiteral("/planes/yz")).is_null());
  EXPECT_EQ(page.planeCombo(TestPlane::YZ)->currentData().toString(), QString());
  EXPECT_TRUE(
      page.threeAxisLabel()->text().contains(QStringLiteral("choose the circular test in the YZ plane")))
      << page.threeAxisLabel()->text().toStdString();
  stack->undo();
  stack->undo();
  EXPECT_EQ(y->currentData().toString(), QStringLiteral("edge_y"));
  EXPECT_EQ(page.planeCombo(TestPlane::YZ)->currentData().toString(), QStringLiteral("plane_yz"));
  EXPECT_EQ(columnTexts(page.threeAxisTable(), 3), threeAxisTexts);
}

TEST_F(KinematicsActuatorsTest, ReportStatesTheChainAndTheThreeAxes) {
  const QString pdf = QDir(dir_.path()).filePath(QStringLiteral("r.pdf"));
  ReportOptions o;
  o.projectPath = projectPath_;
  o.resolutionDpi = 100;
  writeReport(loadProject(projectPath_.toStdString()), pdf, o);
  QProcess p;
  p.start(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")});
  ASSERT_TRUE(p.waitForFinished(60000));
  const QString text = QString::fromUtf8(p.readAllStandardOutput()).simplified();
  EXPECT_TRUE(text.contains(QStringLiteral("From the SPC offset angle to actuator errors")))
      << text.toStdString();
  EXPECT_TRUE(text.contains(QStringLiteral("Compensation applied (Eq. 15)")));
  EXPECT_TRUE(text.contains(QStringLiteral("Three axes: circular tests in XY, YZ and ZX")));
  EXPECT_TRUE(text.contains(QStringLiteral("From the SPC offset angles: origin")));
  // The ISO 230-4 results of the circular test, H with the value the study computes.
  EXPECT_TRUE(text.contains(QStringLiteral("ISO 230-4 results"))) << text.toStdString();
  const KinematicStudyData s =
      loadKinematicStudy(loadProject(projectPath_.toStdString()), [this](const DatasetRef& d) {
        return QDir(QFileInfo(projectPath_).path()).filePath(QString::fromStdString(d.path)).toStdString();
      });
  ASSERT_TRUE(s.analysis.iso.circularHysteresisMm);
  EXPECT_TRUE(text.contains(QStringLiteral("Circular hysteresis H"))) << text.toStdString();
  EXPECT_TRUE(text.contains(
      QStringLiteral("): %1 µm.").arg(*s.analysis.iso.circularHysteresisMm * 1000.0, 0, 'f', 2)))
      << text.toStdString();
  // The ballbar breakdown, its first cause with its value.
  ASSERT_TRUE(s.analysis.ballbar) << s.analysis.ballbarUnavailable;
  EXPECT_TRUE(text.contains(QStringLiteral("Ballbar breakdown"))) << text.toStdString();
  const BallbarCause& first = s.analysis.ballbar->causes.front();
  EXPECT_TRUE(text.contains(ballbarCauseName(first.name) + QStringLiteral(" ") +
                            QString::number(first.valueUm, 'f', 3)))
      << text.toStdString();
}

}  // namespace
}  // namespace metrofit
