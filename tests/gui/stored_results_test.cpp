// Results that stay (issue 27 item 4), offscreen:
//  * a page's result survives Save As to another folder, is stored in the project (results.<study>) with
//    the settings and the data's hash, and a fresh document shows it marked "From the saved project";
//    changed settings or a changed data file mark it out of date instead;
//  * File › New (and Open) leave no page with the last project's results, charts or texts;
//  * the report chooses the Thermal page's model with the page's held-out figure on a log long enough
//    that the report used to fit every k-th row (F8), and says so;
//  * the report has the matching section after the page ran with its defaults only (F7).
#include <gtest/gtest.h>

#include <QAction>
#include <QChart>
#include <QChartView>
#include <QDir>
#include <QFile>
#include <QLocale>
#include <QProcess>
#include <QRegularExpression>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "app/gui/diagnosispage.h"
#include "app/gui/kinematicspage.h"
#include "app/gui/mainwindow.h"
#include "app/gui/matchingpage.h"
#include "app/gui/setuppage.h"
#include "app/gui/thermalpage.h"
#include "core/io/file_io.h"
#include "core/project/project.h"
#include "core/sim/thermal_sim.h"
#include "core/study/diagnosis_study.h"
#include "core/study/thermal_comparison.h"
#include "core/study/thermal_result.h"
#include "core/thermal/model_verdict.h"
#include "core/thermal/thermal_model.h"
#include "demo_document_fixture.h"
#include "qtapp.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"
#include "widgets/report/report.h"
#include "widgets/setup/setupvalidationview.h"
#include "widgets/thermal/thermalmodelview.h"

namespace metrofit {
namespace {

void writeText(const QString& path, const std::string& text) {
  QDir().mkpath(QFileInfo(path).absolutePath());
  std::ofstream(path.toStdString(), std::ios::binary) << text;
}

/// 36 probe points on three faces of a block, measured p = q + d n (as report_test's).
std::string probeCsv() {
  std::ostringstream s;
  s << "id,surface,qx,qy,qz,nx,ny,nz,px,py,pz\n";
  int id = 0;
  const auto point = [&](const char* surface, double qx, double qy, double qz, double nx, double ny,
                         double nz) {
    const double d = -0.03 + 0.0009 * qx + 0.01 * std::sin(id * 1.7);
    s << "P" << ++id << ',' << surface << ',' << qx << ',' << qy << ',' << qz << ',' << nx << ',' << ny << ','
      << nz << ',' << qx + d * nx << ',' << qy + d * ny << ',' << qz + d * nz << '\n';
  };
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 3; ++j) {
      point("top", 10 + 33.0 * i, 10 + 30.0 * j, 50, 0, 0, 1);
      point("front", 10 + 33.0 * i, 0, 10 + 15.0 * j, 0, -1, 0);
      point("right", 120, 10 + 20.0 * i, 10 + 15.0 * j, 1, 0, 0);
    }
  }
  return s.str();
}

QString pdfText(const QString& pdf) {
  QProcess p;
  p.start(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")});
  EXPECT_TRUE(p.waitForFinished(60000));
  // One line per paragraph line: joined with spaces so that wrapped sentences can be searched.
  QString text = QString::fromUtf8(p.readAllStandardOutput()).simplified();
  // The report's font sets "fi" and "ff" as ligatures.
  text.replace(QChar(0xFB01), QStringLiteral("fi")).replace(QChar(0xFB00), QStringLiteral("ff"));
  return text;
}

/// A number as the report prints figures (metric(): C locale, fixed decimals).
QString reportFigure(double v, int decimals) {
  return QString::number(v, 'f', decimals);
}

class StoredResultsTest : public ::testing::Test {
 protected:
  /// data/log.csv: a generated log of `minutes` one-minute rows; data/points.csv: probe points.
  /// The project (in `folder`) has a thermal study on the log and no matching study.
  QString makeProject(const QString& folder, double minutes) {
    ThermalSimOptions so;
    so.seed = 3;
    so.durationMin = minutes;
    writeText(QDir(folder).filePath(QStringLiteral("data/log.csv")),
              thermalLogToCsv(simulateThermalTest(so)));
    writeText(QDir(folder).filePath(QStringLiteral("data/points.csv")), probeCsv());
    Project p;
    p.name = "stored";
    p.datasets.push_back({"gen", "thermal_log", "data/log.csv", "generated", "", {}});
    p.datasets.push_back({"points", "probe_points", "data/points.csv", "block", "", {}});
    p.studies["thermal"] = {
        {"dataset", "gen"}, {"target", "disp_z_um"}, {"inputs", {"T1", "T2", "T3", "T4"}}};
    const QString path = QDir(folder).filePath(QStringLiteral("p.metrofit"));
    saveProject(p, path.toStdString());
    return path;
  }

  QTemporaryDir dir_;
};

TEST_F(StoredResultsTest, ThermalResultSurvivesSaveAsAndReopensMarkedAsStored) {
  ASSERT_TRUE(dir_.isValid());
  const QString original = makeProject(dir_.filePath(QStringLiteral("a")), 360.0);
  ProjectDocument document;
  document.load(original);
  ThermalPage page(&document);
  page.tabs()->setCurrentIndex(2);
  ASSERT_TRUE(page.modelView()->trainNow());
  const ThermalComparison* trained = page.modelView()->comparison();
  ASSERT_NE(trained, nullptr);
  const int best = bestUsableThermalModel(*trained);
  ASSERT_GE(best, 0);
  const std::string bestName = thermal::toString(kThermalModelOrder[static_cast<std::size_t>(best)]);
  const double heldout = trained->models[static_cast<std::size_t>(best)].heldout.rmse;

  // Save As into another folder (relative dataset paths are rewritten): the trained models stay.
  const QString copy = dir_.filePath(QStringLiteral("b/deeper/copy.metrofit"));
  QDir().mkpath(QFileInfo(copy).absolutePath());
  document.saveAs(copy);
  ASSERT_NE(page.modelView()->comparison(), nullptr) << "Save As dropped the trained models";
  EXPECT_EQ(page.modelView()->comparison(), trained);

  // The file holds the result with its settings and the data's hash.
  const nlohmann::json saved = nlohmann::json::parse(readFile(copy.toStdString()));
  const nlohmann::json entry =
      saved.value(nlohmann::json::json_pointer("/results/thermal/gen"), nlohmann::json());
  ASSERT_TRUE(entry.is_object()) << saved.dump();
  EXPECT_EQ(entry["best_model"], bestName);
  EXPECT_EQ(entry["settings"]["target"], "disp_z_um");
  EXPECT_EQ(entry["data_hash"].get<std::string>().rfind("fnv1a64:", 0), 0u);
  bool found = false;
  for (const nlohmann::json& m : entry["models"]) {
    if (m["model"] != bestName) continue;
    found = true;
    EXPECT_NEAR(m["heldout_rmse"].get<double>(), heldout, 1e-12);
  }
  EXPECT_TRUE(found);

  // A fresh document and page: the stored figures, marked as stored.
  {
    ProjectDocument reopened;
    reopened.load(copy);
    ThermalPage again(&reopened);
    EXPECT_EQ(again.modelView()->comparison(), nullptr);
    const QString text = again.storedResultText();
    EXPECT_TRUE(text.startsWith(QStringLiteral("From the saved project, computed "))) << text.toStdString();
    EXPECT_TRUE(
        text.contains(QStringLiteral("best usable model %1 (held-out RMSE %2")
                          .arg(QString::fromStdString(bestName), QLocale().toString(heldout, 'f', 2))))
        << text.toStdString();
    EXPECT_EQ(again.modelView()->statusText(), text);

    // Other settings: out of date, not shown as current.
    reopened.setStudyValue(QStringLiteral("thermal"), QStringLiteral("/train_fraction"), 0.6,
                           QStringLiteral("fraction"));
    const QString changed = again.storedResultText();
    EXPECT_TRUE(changed.contains(QStringLiteral("out of date: the model settings changed")))
        << changed.toStdString();
    EXPECT_FALSE(changed.contains(QStringLiteral("From the saved project")));
  }

  // The data file changed since: out of date.
  {
    const QString log = dir_.filePath(QStringLiteral("a/data/log.csv"));
    std::string csv = readFile(log.toStdString());
    csv.insert(0, "# edited after the run\n");
    writeText(log, csv);
    ProjectDocument reopened;
    reopened.load(copy);
    ThermalPage again(&reopened);
    const QString text = again.storedResultText();
    EXPECT_TRUE(text.contains(QStringLiteral("out of date: the data file changed"))) << text.toStdString();
    EXPECT_EQ(again.modelView()->statusText(), text);
  }
}

TEST_F(StoredResultsTest, MatchingResultSurvivesSaveAsAndReopensMarkedAsStored) {
  ASSERT_TRUE(dir_.isValid());
  const QString original = makeProject(dir_.filePath(QStringLiteral("a")), 120.0);
  ProjectDocument document;
  document.load(original);
  MatchingPage page(&document);
  ASSERT_TRUE(page.runNow());
  ASSERT_TRUE(page.result().has_value());
  const matching::MatchResult primary = page.result()->primaryRun();
  const QString copy = dir_.filePath(QStringLiteral("c/copy.metrofit"));
  QDir().mkpath(QFileInfo(copy).absolutePath());
  document.saveAs(copy);
  ASSERT_TRUE(page.result().has_value()) << "Save As dropped the matching result";

  const nlohmann::json saved = nlohmann::json::parse(readFile(copy.toStdString()));
  const nlohmann::json entry =
      saved.value(nlohmann::json::json_pointer("/results/matching/points"), nlohmann::json());
  ASSERT_TRUE(entry.is_object()) << saved.dump();
  EXPECT_NEAR(entry["rmse_mm"].get<double>(), primary.after.overall.rmseMm, 1e-12);
  EXPECT_EQ(entry["out_of_tolerance"]["after"].get<long long>(),
            static_cast<long long>(primary.after.overall.outOfTolerance));

  ProjectDocument reopened;
  reopened.load(copy);
  MatchingPage again(&reopened);
  EXPECT_FALSE(again.result().has_value());
  const QString text = again.storedResultText();
  EXPECT_TRUE(text.startsWith(QStringLiteral("From the saved project, computed "))) << text.toStdString();
  EXPECT_TRUE(text.contains(
      QStringLiteral("RMSE %1 mm").arg(QLocale().toString(primary.after.overall.rmseMm, 'f', 4))))
      << text.toStdString();
  EXPECT_EQ(again.statusText(), text);

  reopened.setStudyValue(QStringLiteral("matching"), QStringLiteral("/tolerance_mm"), 0.02,
                         QStringLiteral("tolerance"));
  EXPECT_TRUE(again.storedResultText().contains(QStringLiteral("out of date: the matching settings changed")))
      << again.storedResultText().toStdString();
}

TEST_F(StoredResultsTest, ReportHasTheMatchingTheDefaultRunShowed) {
  ASSERT_TRUE(dir_.isValid());
  const QString path = makeProject(dir_.filePath(QStringLiteral("a")), 120.0);
  ProjectDocument document;
  document.load(path);
  MatchingPage page(&document);
  ASSERT_TRUE(page.runNow());  // the defaults: no setting touched
  EXPECT_EQ(document.studyValue(QStringLiteral("matching"), QStringLiteral("/dataset")), "points");
  document.save();
  const QString pdf = dir_.filePath(QStringLiteral("matching.pdf"));
  ReportOptions o;
  o.projectPath = path;
  o.resolutionDpi = 72;
  const ReportSummary summary = writeReport(loadProject(path.toStdString()), pdf, o);
  const QString text = pdfText(pdf);
  EXPECT_FALSE(text.contains(QStringLiteral("used by no study"))) << text.toStdString();
  bool matchingSection = false;
  for (const QString& s : summary.sections)
    matchingSection |= s.contains(QStringLiteral("matching"), Qt::CaseInsensitive);
  EXPECT_TRUE(matchingSection) << summary.sections.join(QStringLiteral(" | ")).toStdString();
}

TEST_F(StoredResultsTest, ReportChoosesTheThermalPagesModelOnALongLog) {
  ASSERT_TRUE(dir_.isValid());
  // 1 800 one-minute rows: more than the report's 1 500, so it used to fit every 2nd row.
  const QString path = makeProject(dir_.filePath(QStringLiteral("a")), 1800.0);
  ProjectDocument document;
  document.load(path);
  ThermalPage page(&document);
  ASSERT_TRUE(page.modelView()->trainNow());
  const ThermalComparison* c = page.modelView()->comparison();
  ASSERT_NE(c, nullptr);
  ASSERT_GT(c->series.rows(), 1500u);
  const int best = bestUsableThermalModel(*c);
  ASSERT_GE(best, 0);
  const thermal::ThermalEvaluation& ev = c->models[static_cast<std::size_t>(best)];
  const double scale = thermal::targetScale(c->series.target);
  const int dec = scale >= 100.0 ? 1 : (scale >= 1.0 ? 2 : 3);
  const QString bestLabel = page.modelView()
                                ->statusText()
                                .section(QStringLiteral("Best usable model: "), 1)
                                .section(QLatin1Char('.'), 0, 0);
  ASSERT_FALSE(bestLabel.isEmpty()) << page.modelView()->statusText().toStdString();
  document.save();

  const QString pdf = dir_.filePath(QStringLiteral("thermal.pdf"));
  ReportOptions o;
  o.projectPath = path;
  o.resolutionDpi = 72;
  writeReport(loadProject(path.toStdString()), pdf, o);
  const QString text = pdfText(pdf);
  const QString expected = QStringLiteral("Best usable model of disp_z_um: %1, held-out RMSE %2")
                               .arg(bestLabel, reportFigure(ev.heldout.rmse, dec));
  EXPECT_TRUE(text.contains(expected)) << expected.toStdString() << "\n" << text.toStdString();
  EXPECT_TRUE(text.contains(QStringLiteral("Every row of the log is fitted, as on the Thermal page")));
  EXPECT_FALSE(text.contains(QStringLiteral("is fitted on every 2th row")));

  // Without the page's result the report fits every 2nd row and says so.
  Project other = loadProject(path.toStdString());
  other.results = nlohmann::json::object();
  const QString otherPath = dir_.filePath(QStringLiteral("a/other.metrofit"));
  saveProject(other, otherPath.toStdString());
  o.projectPath = otherPath;
  writeReport(other, pdf, o);
  const QString sub = pdfText(pdf);
  EXPECT_TRUE(sub.contains(QStringLiteral("is fitted on every 2th row"))) << sub.toStdString();
  EXPECT_TRUE(sub.contains(QStringLiteral("may choose another model")));
}

TEST(FileNewTest, LeavesEveryPageEmpty) {
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  MainWindow window;
  window.setUnsavedChangesDecider([] { return MainWindow::UnsavedChoice::Discard; });
  ASSERT_TRUE(window.openProject(extractDemoProject(dir.path())));
  auto* setup = qobject_cast<SetupPage*>(window.page(Page::Setup));
  auto* diagnosis = qobject_cast<DiagnosisPage*>(window.page(Page::Diagnosis));
  ASSERT_NE(setup, nullptr);
  ASSERT_NE(diagnosis, nullptr);
  SetupValidationView* validation = setup->validationView();
  const QString intro = validation->summaryText();
  validation->setSets(3);
  validation->setTrials(1);
  ASSERT_TRUE(validation->start());
  validation->waitForFinished();
  ASSERT_NE(validation->result(), nullptr);
  auto* chartView = validation->findChild<QChartView*>(QStringLiteral("setupValidationChart"));
  ASSERT_NE(chartView, nullptr);
  ASSERT_FALSE(chartView->chart()->series().isEmpty());
  ASSERT_TRUE(window.matchingPage()->runNow());
  ASSERT_TRUE(window.matchingPage()->result().has_value());
  ASSERT_TRUE(diagnosis->runNow());
  ASSERT_TRUE(diagnosis->result().has_value());

  // A Save As keeps them (F9) ...
  QDir().mkpath(dir.filePath(QStringLiteral("elsewhere")));
  window.document()->saveAs(dir.filePath(QStringLiteral("elsewhere/demo-copy.metrofit")));
  EXPECT_NE(validation->result(), nullptr);
  EXPECT_TRUE(window.matchingPage()->result().has_value());
  EXPECT_TRUE(diagnosis->result().has_value());

  // ... File › New drops every one of them (F4).
  QAction* newAction = nullptr;
  for (QAction* a : window.findChildren<QAction*>())
    if (a->text() == QStringLiteral("&New")) newAction = a;
  ASSERT_NE(newAction, nullptr);
  newAction->trigger();
  EXPECT_TRUE(window.document()->fileName().isEmpty());
  EXPECT_EQ(validation->result(), nullptr);
  EXPECT_EQ(validation->summaryText(), intro);
  EXPECT_TRUE(chartView->chart()->series().isEmpty());
  EXPECT_FALSE(window.matchingPage()->result().has_value());
  EXPECT_TRUE(window.matchingPage()->storedResultText().isEmpty());
  EXPECT_FALSE(diagnosis->result().has_value());
  EXPECT_EQ(window.thermalPage()->modelView()->comparison(), nullptr);
  EXPECT_TRUE(window.thermalPage()->currentDataset().isEmpty());
}

/// The report (72 dpi) of `project` written to `pdf`: its text with -layout (a table row stays on one
/// line).
QString demoReportLayoutText(const QString& project, const QString& pdf) {
  ReportOptions o;
  o.projectPath = project;
  o.resolutionDpi = 72;
  writeReport(loadProject(project.toStdString()), pdf, o);
  QProcess p;
  p.start(QStringLiteral("pdftotext"), {QStringLiteral("-layout"), pdf, QStringLiteral("-")});
  EXPECT_TRUE(p.waitForFinished(60000));
  return QString::fromUtf8(p.readAllStandardOutput());
}

/// The demo project extracted to a temporary folder and loaded (dir_, project_, document_).
using ReportAndPagesTest = test::DemoDocumentTest;

// The kinematics page and the report show the same identified errors for the demo project: every row of
// the page's table (origin, axis angles, squareness, RMS residual) is found in the report's table with
// the same value, to the digits either shows (both run core/study/kinematic_study.h on the same test).
TEST_F(ReportAndPagesTest, KinematicsIdentifiedFiguresAreThePages) {
  KinematicsPage page(&document_);
  ASSERT_TRUE(page.errorMessage().isEmpty()) << page.errorMessage().toStdString();
  ASSERT_NE(page.study(), nullptr);
  const QTableWidget* table = page.errorTable();
  ASSERT_GE(table->rowCount(), 6);
  const QString text = demoReportLayoutText(project_, dir_.filePath(QStringLiteral("k.pdf")));
  ASSERT_FALSE(text.isEmpty());
  for (int row = 0; row < 6; ++row) {
    const QString name = table->item(row, 0)->text();
    const QString cell = table->item(row, 1)->text();
    bool ok = false;
    const double shown = QLocale().toDouble(cell, &ok);
    ASSERT_TRUE(ok) << cell.toStdString();
    // The report's row: the name, then the identified value (C locale).
    const QRegularExpression re(QRegularExpression::escape(name) + QStringLiteral("\\s+(-?[0-9.]+)"));
    const QRegularExpressionMatch m = re.match(text);
    ASSERT_TRUE(m.hasMatch()) << "no row '" << name.toStdString() << "' in the report";
    const double reported = m.captured(1).toDouble(&ok);
    ASSERT_TRUE(ok) << m.captured(1).toStdString();
    const int decimals = static_cast<int>(cell.size() - cell.lastIndexOf(QLocale().decimalPoint()) - 1);
    EXPECT_NEAR(reported, shown, 0.51 * std::pow(10.0, -decimals) + 1e-12) << name.toStdString();
  }
}

// The diagnosis page and the report accept the same effects for every domain the demo configures, and
// reach the same final error (the report: "Accepted: <names>. Final model: rmse <v> <unit>").
TEST_F(ReportAndPagesTest, DiagnosisAcceptedEffectsAreThePages) {
  DiagnosisPage page(&document_);
  QStringList pageAccepted;
  std::vector<double> pageFinal;
  for (DiagnosisDomain d : kDiagnosisDomains) {
    if (!hasDiagnosisSettings(document_.project(), d)) continue;
    page.setDomain(d);
    ASSERT_TRUE(page.runNow()) << page.statusText().toStdString();
    QStringList names;
    for (const auto* c : page.result()->accepted()) names << QString::fromStdString(c->name);
    pageAccepted << (names.isEmpty() ? QStringLiteral("-") : names.join(QStringLiteral(", ")));
    pageFinal.push_back(page.result()->final.rmse);
  }
  ASSERT_EQ(pageAccepted.size(), 4);

  QString text = demoReportLayoutText(project_, dir_.filePath(QStringLiteral("d.pdf")));
  text.replace(QRegularExpression(QStringLiteral("\\s+")), QStringLiteral(" "));
  // One sentence per domain, in the order of the pages' domains.
  const QRegularExpression re(QStringLiteral(
      "(?:Accepted: (.+?)\\. Final model: rmse (-?[0-9.e+-]+)|No candidate passed the evidence test: the "
      "declared model is kept\\. rmse (-?[0-9.e+-]+))"));
  QStringList reportAccepted;
  std::vector<double> reportFinal;
  for (auto it = re.globalMatch(text); it.hasNext();) {
    const QRegularExpressionMatch m = it.next();
    const bool none = m.captured(1).isEmpty();
    reportAccepted << (none ? QStringLiteral("-") : m.captured(1));
    bool ok = false;
    const QString figure = none ? m.captured(3) : m.captured(2);
    reportFinal.push_back(figure.toDouble(&ok));
    EXPECT_TRUE(ok) << "report figure '" << figure.toStdString() << "' is not a number";
  }
  EXPECT_EQ(reportAccepted, pageAccepted) << text.toStdString();
  ASSERT_EQ(reportFinal.size(), pageFinal.size());
  for (std::size_t k = 0; k < pageFinal.size(); ++k)  // the report: four significant digits
    EXPECT_NEAR(reportFinal[k], pageFinal[k], 6e-4 * std::abs(pageFinal[k]) + 1e-12) << k;
}

}  // namespace
}  // namespace metrofit
