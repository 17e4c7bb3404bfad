// The diagnosis page's settings and results in the project file (issue 27 items 3 and 4), offscreen:
//  * a run is stored under results.diagnosis.<dataset id> with the settings and the data's hash; after
//    Save As a fresh document shows the stored figures (equal to the computed ones) marked "From the saved
//    project (computed ...)", and as out of date once a setting changes;
//  * every control of the page set, saved, reopened: the values are back in the controls; the PDF report
//    of the saved project is exported (ReportExporter) and `metrofit-cli report` exits 0 on it.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>

#include "app/gui/diagnosispage.h"
#include "app/gui/reportexporter.h"
#include "core/project/project.h"
#include "core/study/diagnosis_study.h"
#include "qtapp.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"

namespace metrofit {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr int kReportWaitMs = 900000;
#else
constexpr int kReportWaitMs = 180000;
#endif

class DiagnosisRoundTripTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    demo_ = extractDemoProject(dir_.filePath(QStringLiteral("demo")));
    document_.load(demo_);
  }

  /// Selects the item whose data is `id` (the control writes the study).
  static void choose(QComboBox* combo, const QString& id) {
    const int i = combo->findData(id);
    ASSERT_GE(i, 0) << id.toStdString();
    combo->setCurrentIndex(i);
  }

  QTemporaryDir dir_;
  QString demo_;
  ProjectDocument document_;
};

TEST_F(DiagnosisRoundTripTest, ARunIsStoredAndShownAfterSaveAsAndReopen) {
  QString figures;
  diagnose::Diagnosis computed;
  const QString saved = dir_.filePath(QStringLiteral("elsewhere/saved.metrofit"));
  QDir().mkpath(QFileInfo(saved).absolutePath());
  {
    DiagnosisPage page(&document_);
    page.setDomain(DiagnosisDomain::Matching);
    ASSERT_TRUE(page.runNow()) << page.statusText().toStdString();
    computed = *page.result();
    const QString status = page.statusText();
    figures = status.left(status.indexOf(QStringLiteral(" Residual check:")));
    ASSERT_FALSE(figures.isEmpty());
    const nlohmann::json& stored = document_.project().results["diagnosis"]["diagnose_probe"];
    ASSERT_TRUE(stored.is_object());
    EXPECT_EQ(stored["settings"]["domain"], "matching");
    EXPECT_EQ(stored["settings"]["tolerance_mm"], 0.035);
    EXPECT_TRUE(stored["data_hash"].get<std::string>().starts_with("fnv1a64:"));
    // Save As keeps the result on the page (same project) and writes it into the file.
    document_.saveAs(saved);
    EXPECT_TRUE(page.result().has_value());
    EXPECT_EQ(page.statusText(), status);
  }
  const Project file = loadProject(saved.toStdString());
  const nlohmann::json& entry = file.results["diagnosis"]["diagnose_probe"];
  EXPECT_EQ(entry["baseline"]["rmse"].get<double>(), computed.baseline.rmse);
  EXPECT_EQ(entry["final"]["rmse"].get<double>(), computed.final.rmse);
  EXPECT_EQ(entry["effects"].size(), computed.effects.size());
  int accepted = 0;
  for (const auto& e : entry["effects"]) accepted += e["accepted"].get<bool>() ? 1 : 0;
  EXPECT_EQ(accepted, static_cast<int>(computed.accepted().size()));

  ProjectDocument reopened;
  reopened.load(saved);
  DiagnosisPage page(&reopened);
  page.setDomain(DiagnosisDomain::Matching);
  EXPECT_FALSE(page.result().has_value());
  const QString shown = page.statusText();
  EXPECT_TRUE(shown.startsWith(QStringLiteral("From the saved project (computed "))) << shown.toStdString();
  EXPECT_TRUE(shown.contains(figures)) << shown.toStdString() << "\n" << figures.toStdString();
  // Another domain has nothing stored.
  page.setDomain(DiagnosisDomain::Kinematic);
  EXPECT_TRUE(page.statusText().startsWith(QStringLiteral("Not run yet"))) << page.statusText().toStdString();
  // A changed setting: the stored result is out of date, not shown as current; undo makes it current again.
  page.setDomain(DiagnosisDomain::Matching);
  page.toleranceBox()->setValue(0.05);
  reopened.endEditSequence();
  EXPECT_TRUE(page.statusText().contains(QStringLiteral("out of date"))) << page.statusText().toStdString();
  EXPECT_FALSE(page.statusText().contains(figures));
  reopened.undoStack()->undo();
  EXPECT_TRUE(page.statusText().startsWith(QStringLiteral("From the saved project")))
      << page.statusText().toStdString();
  // Applying effects does not change what the loop computes: the result stays current.
  reopened.setStudyValue(QStringLiteral("diagnosis"), QStringLiteral("/matching/applied"),
                         nlohmann::json::array({{{"name", "scale"}, {"parameters", {{"ppm", 12.0}}}}}),
                         QStringLiteral("apply"));
  EXPECT_TRUE(page.statusText().startsWith(QStringLiteral("From the saved project")))
      << page.statusText().toStdString();
}

TEST_F(DiagnosisRoundTripTest, EveryControlSavedReopenedAndReported) {
  {
    DiagnosisPage page(&document_);
    page.setDomain(DiagnosisDomain::Thermal);
    page.trainFractionBox()->setValue(0.6);
    document_.endEditSequence();
    page.setDomain(DiagnosisDomain::Kinematic);
    choose(page.datasetCombo(DiagnosisDomain::Kinematic), QStringLiteral("circular_demo"));
    page.feedBox()->setValue(2000.0);
    document_.endEditSequence();
    page.setDomain(DiagnosisDomain::Setup);
    choose(page.datasetCombo(DiagnosisDomain::Setup), QStringLiteral("setup_report"));
    choose(page.setupModelCombo(), QStringLiteral("setup_model"));
    page.setDomain(DiagnosisDomain::Matching);
    choose(page.datasetCombo(DiagnosisDomain::Matching), QStringLiteral("probe_block"));
    page.toleranceBox()->setValue(0.04);
    document_.endEditSequence();
    choose(page.datasetCombo(DiagnosisDomain::Thermal), QStringLiteral("diagnose_thermal"));
    for (DiagnosisDomain d : kDiagnosisDomains) {
      page.setDomain(d);
      EXPECT_TRUE(page.settingsError().isEmpty()) << page.settingsError().toStdString();
    }
  }
  const QString saved = dir_.filePath(QStringLiteral("set/every.metrofit"));
  QDir().mkpath(QFileInfo(saved).absolutePath());
  document_.saveAs(saved);

  ProjectDocument reopened;
  reopened.load(saved);
  {
    DiagnosisPage page(&reopened);
    EXPECT_DOUBLE_EQ(page.trainFractionBox()->value(), 0.6);
    EXPECT_DOUBLE_EQ(page.feedBox()->value(), 2000.0);
    EXPECT_DOUBLE_EQ(page.toleranceBox()->value(), 0.04);
    EXPECT_EQ(page.datasetCombo(DiagnosisDomain::Thermal)->currentData().toString(),
              QStringLiteral("diagnose_thermal"));
    EXPECT_EQ(page.datasetCombo(DiagnosisDomain::Kinematic)->currentData().toString(),
              QStringLiteral("circular_demo"));
    EXPECT_EQ(page.datasetCombo(DiagnosisDomain::Setup)->currentData().toString(),
              QStringLiteral("setup_report"));
    EXPECT_EQ(page.setupModelCombo()->currentData().toString(), QStringLiteral("setup_model"));
    EXPECT_EQ(page.datasetCombo(DiagnosisDomain::Matching)->currentData().toString(),
              QStringLiteral("probe_block"));
    for (DiagnosisDomain d : kDiagnosisDomains) {
      page.setDomain(d);
      EXPECT_TRUE(page.message().isEmpty()) << page.message().toStdString();
    }
    EXPECT_FALSE(reopened.isModified());
  }
  // The values as the study holds them (and the core reader takes them).
  EXPECT_DOUBLE_EQ(
      diagnosisSettings(reopened.project(), saved.toStdString(), DiagnosisDomain::Thermal).trainFraction,
      0.6);
  EXPECT_DOUBLE_EQ(
      diagnosisSettings(reopened.project(), saved.toStdString(), DiagnosisDomain::Kinematic).feedMmPerMin,
      2000.0);
  EXPECT_DOUBLE_EQ(
      diagnosisSettings(reopened.project(), saved.toStdString(), DiagnosisDomain::Matching).toleranceMm,
      0.04);

  // The PDF report of what the user sees (the GUI's export) and the CLI's report of the saved file.
  ReportExporter exporter(nullptr);
  exporter.setCliPath(QStringLiteral(METROFIT_CLI_EXECUTABLE));
  QSignalSpy finished(&exporter, &ReportExporter::finished);
  const QString pdf = dir_.filePath(QStringLiteral("set/report.pdf"));
  ASSERT_TRUE(exporter.start(reopened, pdf));
  ASSERT_TRUE(finished.wait(kReportWaitMs));
  ASSERT_EQ(finished.at(0).at(0).value<ReportExporter::Outcome>(), ReportExporter::Outcome::Written)
      << finished.at(0).at(1).toString().toStdString();
  EXPECT_GT(QFileInfo(pdf).size(), 1000);

  QProcess cli;
  cli.start(QStringLiteral(METROFIT_CLI_EXECUTABLE),
            {QStringLiteral("report"), QStringLiteral("--project"), saved, QStringLiteral("--out"),
             dir_.filePath(QStringLiteral("set/cli.pdf"))});
  ASSERT_TRUE(cli.waitForFinished(kReportWaitMs));
  EXPECT_EQ(cli.exitStatus(), QProcess::NormalExit);
  EXPECT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();
  EXPECT_GT(QFileInfo(dir_.filePath(QStringLiteral("set/cli.pdf"))).size(), 1000);
}

}  // namespace
}  // namespace metrofit
