// Round trips of every control of the Setup, Thermal and Matching pages (issue 27 item 3, "A test
// sets every control of every page, saves, reopens, exports the PDF and runs `metrofit-cli report` on
// the saved project, for each page"), and the setup page's stored result (item 4). Offscreen.
//
// Each page test sets every control that writes a study value to a value other than the demo's, saves
// the project with Save As to another folder, opens the saved file in a fresh document and page (the
// controls show the values, the study's settings are valid), exports the PDF report of it as the GUI
// does (ReportExporter, which runs metrofit-cli) and runs `metrofit-cli report` on the saved file
// (exit 0). The demo project is cut down to the page's own study and datasets so that the reports
// stay quick.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QListWidget>
#include <QLocale>
#include <QProcess>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QUndoStack>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "app/gui/matchingpage.h"
#include "app/gui/reportexporter.h"
#include "app/gui/setuppage.h"
#include "app/gui/thermalpage.h"
#include "core/project/project.h"
#include "core/study/study_check.h"
#include "qtapp.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"
#include "widgets/setup/setupresultsview.h"
#include "widgets/thermal/thermalmodelview.h"

namespace metrofit {
namespace {

#ifdef NDEBUG
constexpr int kReportWaitMs = 300000;
#else
constexpr int kReportWaitMs = 900000;
#endif

class SettingsRoundTripTest : public ::testing::Test {
 protected:
  /// The demo project with only `study` and `datasets` (the report of the page's study alone).
  void openDemo(const char* study, const std::set<std::string>& datasets) {
    ASSERT_TRUE(dir_.isValid());
    const QString demo = extractDemoProject(dir_.filePath(QStringLiteral("demo")));
    Project p = loadProject(demo.toStdString());
    Project only = p;
    only.datasets.clear();
    for (const DatasetRef& d : p.datasets)
      if (datasets.count(d.id)) only.datasets.push_back(d);
    only.studies = nlohmann::json::object();
    only.studies[study] = p.studies[study];
    only.results = nlohmann::json::object();
    path_ = dir_.filePath(QStringLiteral("demo/only.metrofit"));
    saveProject(only, path_.toStdString());
    document_.load(path_);
  }

  /// Save As into another folder (the dataset paths are rewritten to still name the demo's files).
  QString saveAsElsewhere() {
    const QString saved = dir_.filePath(QStringLiteral("elsewhere/saved.metrofit"));
    QDir().mkpath(QFileInfo(saved).absolutePath());
    document_.saveAs(saved);
    EXPECT_FALSE(document_.isModified());
    return saved;
  }

  /// The saved study is valid for the validator the report uses.
  static void expectValidStudies(const QString& path) {
    const std::vector<StudyIssue> issues = checkStudies(loadProject(path.toStdString()));
    EXPECT_TRUE(issues.empty()) << issues.front().field << ": " << issues.front().message;
  }

  /// The PDF report of `document` as File › Export report writes it (metrofit-cli behind it).
  void exportReport(const ProjectDocument& document, QWidget* parent) {
    ReportExporter exporter(parent);
    exporter.setCliPath(QStringLiteral(METROFIT_CLI_EXECUTABLE));
    QSignalSpy finished(&exporter, &ReportExporter::finished);
    const QString pdf = dir_.filePath(QStringLiteral("gui-report.pdf"));
    ASSERT_TRUE(exporter.start(document, pdf));
    ASSERT_TRUE(finished.wait(kReportWaitMs));
    ASSERT_EQ(finished.at(0).at(0).value<ReportExporter::Outcome>(), ReportExporter::Outcome::Written)
        << finished.at(0).at(1).toString().toStdString();
    EXPECT_GT(QFileInfo(pdf).size(), 1000);
  }

  /// `metrofit-cli report` on the saved project: exit 0.
  void cliReport(const QString& project) {
    QProcess cli;
    const QString pdf = dir_.filePath(QStringLiteral("cli-report.pdf"));
    cli.start(QStringLiteral(METROFIT_CLI_EXECUTABLE),
              {QStringLiteral("report"), QStringLiteral("--project"), project, QStringLiteral("--out"), pdf});
    ASSERT_TRUE(cli.waitForFinished(kReportWaitMs));
    EXPECT_EQ(cli.exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();
    EXPECT_GT(QFileInfo(pdf).size(), 1000);
  }

  QTemporaryDir dir_;
  QString path_;
  ProjectDocument document_;
};

// ---- Setup ---------------------------------------------------------------------------------------

TEST_F(SettingsRoundTripTest, SetupPage) {
  openDemo("setup", {"setup_model", "setup_report"});
  {
    SetupPage page(&document_);
    ASSERT_TRUE(page.settingsError().isEmpty()) << page.settingsError().toStdString();
    page.methodCombo()->setCurrentIndex(page.methodCombo()->findData(QStringLiteral("cripso")));
    page.budgetSpin()->setValue(7000);
    document_.endEditSequence();
    page.seedSpin()->setValue(42);
    document_.endEditSequence();
    EXPECT_EQ(document_.undoStack()->count(), 3) << "one undo step per edit";
  }
  const QString saved = saveAsElsewhere();
  expectValidStudies(saved);
  const nlohmann::json study = loadProject(saved.toStdString()).studies["setup"];
  EXPECT_EQ(study.value("method", std::string()), "cripso");
  EXPECT_EQ(study.value("budget", 0L), 7000);
  EXPECT_EQ(study.value("seed", 0ULL), 42u);

  ProjectDocument reopened;
  reopened.load(saved);
  SetupPage page(&reopened);
  EXPECT_TRUE(page.settingsError().isEmpty()) << page.settingsError().toStdString();
  EXPECT_EQ(page.methodCombo()->currentData().toString(), QStringLiteral("cripso"));
  EXPECT_EQ(page.budgetSpin()->value(), 7000);
  EXPECT_EQ(page.seedSpin()->value(), 42);
  EXPECT_TRUE(page.runButton()->isEnabled());
  EXPECT_FALSE(reopened.isModified()) << "showing the values is no edit";
  exportReport(reopened, &page);
  cliReport(saved);
}

// The setup run's figures are stored with the project (results.setup.<report>) and shown when the
// saved project is opened again, marked as stored; other settings or another report mark them out of
// date.
TEST_F(SettingsRoundTripTest, SetupStoredResult) {
  openDemo("setup", {"setup_model", "setup_report"});
  QString shownSummary;
  {
    SetupPage page(&document_);
    page.methodCombo()->setCurrentIndex(page.methodCombo()->findData(QStringLiteral("cripso")));
    page.budgetSpin()->setValue(2000);
    document_.endEditSequence();
    page.seedSpin()->setValue(3);
    document_.endEditSequence();
    ASSERT_TRUE(page.startRun());
    page.waitForRun();
    QCoreApplication::processEvents();  // the finished run is shown
    for (int i = 0; i < 100 && !page.resultsView()->hasResult(); ++i) QCoreApplication::processEvents();
    ASSERT_TRUE(page.resultsView()->hasResult());
    EXPECT_TRUE(document_.hasUnsavedResults());
    shownSummary = page.resultsView()->summaryText();
  }
  const nlohmann::json stored = document_.project().results["setup"]["setup_report"];
  ASSERT_TRUE(stored.is_object()) << document_.project().results.dump();
  EXPECT_EQ(stored["method"], "cripso");
  EXPECT_EQ(stored["budget"], 2000);
  EXPECT_EQ(stored["seed"], 3);
  EXPECT_EQ(stored["settings"]["study"]["method"], "cripso");
  for (const char* key : {"f1_before", "f1", "f2", "f"}) EXPECT_TRUE(stored[key].is_number()) << key;
  ASSERT_TRUE(stored["corrections"].is_array());
  EXPECT_EQ(stored["corrections"].size(), 10u) << "one per setup datum";
  EXPECT_TRUE(stored["exact"]["f1"].is_number());
  EXPECT_TRUE(stored["parts"]["parts"].is_number_integer());

  const QString saved = saveAsElsewhere();
  expectValidStudies(saved);
  EXPECT_FALSE(document_.hasUnsavedResults());
  ProjectDocument reopened;
  reopened.load(saved);
  SetupPage page(&reopened);
  const QString text = page.resultsView()->summaryText();
  EXPECT_TRUE(text.startsWith(QStringLiteral("From the saved project (computed"))) << text.toStdString();
  EXPECT_EQ(text, page.storedResultText());
  // The figures are those the run showed (f1 after, 4 decimals as on the Results tab).
  const QString f1 = QLocale().toString(stored["f1"].get<double>(), 'f', 4);
  EXPECT_TRUE(text.contains(f1)) << text.toStdString();
  EXPECT_TRUE(shownSummary.contains(f1)) << shownSummary.toStdString();
  EXPECT_FALSE(reopened.hasUnsavedResults());

  // Another seed: out of date; undo: current again.
  page.seedSpin()->setValue(4);
  reopened.endEditSequence();
  EXPECT_TRUE(page.resultsView()->summaryText().contains(QStringLiteral("out of date")))
      << page.resultsView()->summaryText().toStdString();
  reopened.undoStack()->undo();
  EXPECT_TRUE(page.resultsView()->summaryText().startsWith(QStringLiteral("From the saved project")))
      << page.resultsView()->summaryText().toStdString();

  // The report file changed since: out of date.
  const QString report = reopened.datasetPath(*reopened.project().dataset("setup_report"));
  {
    std::ofstream out(report.toStdString(), std::ios::app);
    out << "\n";
  }
  ProjectDocument changed;
  changed.load(saved);
  SetupPage other(&changed);
  EXPECT_TRUE(other.resultsView()->summaryText().contains(QStringLiteral("the CMM report changed")))
      << other.resultsView()->summaryText().toStdString();
}

// ---- Thermal -------------------------------------------------------------------------------------

TEST_F(SettingsRoundTripTest, ThermalPage) {
  openDemo("thermal", {"thermal_sim"});
  QString target;
  std::vector<std::string> inputs;
  {
    ThermalPage page(&document_);
    ASSERT_TRUE(page.errorMessage().isEmpty()) << page.errorMessage().toStdString();
    ThermalModelView* view = page.modelView();
    auto* targetCombo = view->findChild<QComboBox*>(QStringLiteral("thermalModelTarget"));
    auto* inputList = view->findChild<QListWidget*>(QStringLiteral("thermalModelInputs"));
    auto* fraction = view->findChild<QDoubleSpinBox*>(QStringLiteral("thermalModelTrainFraction"));
    auto* seed = view->findChild<QSpinBox*>(QStringLiteral("thermalModelSeed"));
    ASSERT_TRUE(targetCombo && inputList && fraction && seed);
    // Inputs: one checked sensor less (the first checked one is unchecked).
    for (int i = 0; i < inputList->count(); ++i) {
      QListWidgetItem* item = inputList->item(i);
      if (!item->isHidden() && item->checkState() == Qt::Checked) {
        item->setCheckState(Qt::Unchecked);
        break;
      }
    }
    document_.endEditSequence();
    fraction->setValue(0.55);
    document_.endEditSequence();
    seed->setValue(17);
    document_.endEditSequence();
    target = targetCombo->currentData().toString();
    inputs = view->settings().inputs;
    ASSERT_FALSE(inputs.empty());
  }
  const QString saved = saveAsElsewhere();
  expectValidStudies(saved);
  const nlohmann::json study = loadProject(saved.toStdString()).studies["thermal"];
  EXPECT_DOUBLE_EQ(study.value("train_fraction", 0.0), 0.55);
  EXPECT_EQ(study.value("seed", 0ULL), 17u);
  EXPECT_EQ(study["inputs"].get<std::vector<std::string>>(), inputs);

  ProjectDocument reopened;
  reopened.load(saved);
  ThermalPage page(&reopened);
  ASSERT_TRUE(page.errorMessage().isEmpty()) << page.errorMessage().toStdString();
  const ThermalModelSettings shown = page.modelView()->settings();
  EXPECT_EQ(QString::fromStdString(shown.target), target);
  EXPECT_EQ(shown.inputs, inputs);
  EXPECT_DOUBLE_EQ(shown.trainFraction, 0.55);
  EXPECT_EQ(shown.seed, 17u);
  EXPECT_EQ(page.modelView()->findChild<QSpinBox*>(QStringLiteral("thermalModelSeed"))->value(), 17);
  EXPECT_FALSE(reopened.isModified());
  exportReport(reopened, &page);
  cliReport(saved);
}

// A train fraction the study accepts but the page's control would round or clamp is refused with the
// field named (the page used to fit with the clamped value while the report used the study's); a
// fraction the control can show is used as it is.
TEST_F(SettingsRoundTripTest, ThermalValueThePageCannotShowIsRefused) {
  openDemo("thermal", {"thermal_sim"});
  document_.setStudyValue(QStringLiteral("thermal"), QStringLiteral("/train_fraction"), 0.995,
                          QStringLiteral("edit"));
  ThermalPage page(&document_);
  EXPECT_TRUE(page.errorMessage().contains(QStringLiteral("studies.thermal.train_fraction")))
      << page.errorMessage().toStdString();
  document_.endEditSequence();
  document_.setStudyValue(QStringLiteral("thermal"), QStringLiteral("/train_fraction"), 0.95,
                          QStringLiteral("edit"));
  EXPECT_TRUE(page.errorMessage().isEmpty()) << page.errorMessage().toStdString();
  EXPECT_DOUBLE_EQ(page.modelView()->settings().trainFraction, 0.95);
  document_.undoStack()->undo();
  EXPECT_TRUE(page.errorMessage().contains(QStringLiteral("studies.thermal.train_fraction")))
      << page.errorMessage().toStdString();
}

// ---- Matching ------------------------------------------------------------------------------------

TEST_F(SettingsRoundTripTest, MatchingPage) {
  openDemo("matching", {"probe_s_piece"});
  {
    MatchingPage page(&document_);
    ASSERT_TRUE(page.errorMessage().isEmpty()) << page.errorMessage().toStdString();
    auto* method = page.findChild<QComboBox*>(QStringLiteral("matchingMethod"));
    auto* tolerance = page.findChild<QDoubleSpinBox*>(QStringLiteral("matchingTolerance"));
    ASSERT_TRUE(method && tolerance);
    method->setCurrentIndex(method->findData(static_cast<int>(matching::MatchMethod::ClosedForm)));
    tolerance->setValue(0.05);
    document_.endEditSequence();
    for (QCheckBox* box : page.findChildren<QCheckBox*>()) {
      const QString text = box->text().remove(QLatin1Char('&'));
      if (text == QStringLiteral("Allow scale") || text == QStringLiteral("rz") ||
          text == QStringLiteral("z"))
        box->setChecked(true);
    }
    page.setFrameFormat(machine::FrameFormat::Siemens);
    page.frameDecimalsSpin()->setValue(5);
    document_.endEditSequence();
  }
  const QString saved = saveAsElsewhere();
  expectValidStudies(saved);
  const nlohmann::json study = loadProject(saved.toStdString()).studies["matching"];
  EXPECT_EQ(study.value("method", std::string()), "closed-form");
  EXPECT_DOUBLE_EQ(study.value("tolerance_mm", 0.0), 0.05);
  EXPECT_EQ(study.value("allow_scale", false), true);
  EXPECT_EQ(study.value("locks", std::string()), "rz,z");
  EXPECT_EQ(study.value("frame_decimals", 0), 5);

  ProjectDocument reopened;
  reopened.load(saved);
  MatchingPage page(&reopened);
  EXPECT_FALSE(page.statusText().contains(QStringLiteral("invalid"))) << page.statusText().toStdString();
  auto* method = page.findChild<QComboBox*>(QStringLiteral("matchingMethod"));
  auto* tolerance = page.findChild<QDoubleSpinBox*>(QStringLiteral("matchingTolerance"));
  ASSERT_TRUE(method && tolerance);
  EXPECT_EQ(method->currentData().toInt(), static_cast<int>(matching::MatchMethod::ClosedForm));
  EXPECT_DOUBLE_EQ(tolerance->value(), 0.05);
  std::set<QString> checked;
  for (QCheckBox* box : page.findChildren<QCheckBox*>())
    if (box->isChecked()) checked.insert(box->text().remove(QLatin1Char('&')));
  EXPECT_EQ(checked,
            (std::set<QString>{QStringLiteral("Allow scale"), QStringLiteral("rz"), QStringLiteral("z")}));
  EXPECT_EQ(page.frameFormat(), machine::FrameFormat::Siemens);
  EXPECT_EQ(page.frameDecimalsSpin()->value(), 5);
  EXPECT_FALSE(reopened.isModified());
  exportReport(reopened, &page);
  cliReport(saved);
}

}  // namespace
}  // namespace metrofit

namespace metrofit {
namespace {

// A tolerance the study accepts but the page's spin box would clamp or round (0, 20 mm, 0.0355 mm) is
// refused with the field named and nothing is matched (the page used to match with the clamped value
// while the report used the study's); a value the control shows is used as it is.
TEST_F(SettingsRoundTripTest, MatchingToleranceThePageCannotShowIsRefused) {
  openDemo("matching", {"probe_s_piece"});
  for (const double bad : {0.0, 20.0, 0.0355}) {
    document_.endEditSequence();
    document_.setStudyValue(QStringLiteral("matching"), QStringLiteral("/tolerance_mm"), bad,
                            QStringLiteral("edit"));
    MatchingPage page(&document_);
    EXPECT_TRUE(page.statusText().contains(QStringLiteral("studies.matching.tolerance_mm")))
        << bad << ": " << page.statusText().toStdString();
    EXPECT_FALSE(page.runNow()) << bad;
  }
  MatchingPage page(&document_);
  document_.endEditSequence();
  document_.setStudyValue(QStringLiteral("matching"), QStringLiteral("/tolerance_mm"), 0.04,
                          QStringLiteral("edit"));
  EXPECT_FALSE(page.statusText().contains(QStringLiteral("studies.matching")))
      << page.statusText().toStdString();
  EXPECT_DOUBLE_EQ(page.findChild<QDoubleSpinBox*>(QStringLiteral("matchingTolerance"))->value(), 0.04);
  EXPECT_TRUE(page.runNow()) << page.errorMessage().toStdString();
  document_.undoStack()->undo();  // back to 0.0355
  EXPECT_TRUE(page.statusText().contains(QStringLiteral("studies.matching.tolerance_mm")))
      << page.statusText().toStdString();
}

}  // namespace
}  // namespace metrofit
