// Tests of the setup-correction page on the demo project (offscreen): it loads the study's model and
// report, the exact run fills the corrections table with the values of `metrofit-cli setup`, a
// metaheuristic run feeds the convergence chart from its worker thread and can be cancelled,
// showView("convergence") overlays exact, CRIPSO and PSO, and an edited model is saved atomically.
// The page is grabbed into $METROFIT_TEST_OUT (setuppage_*.png) for a look.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>
#include <iterator>
#include <map>

#include <QLocale>
#include <nlohmann/json.hpp>

#include "app/gui/setuppage.h"
#include "cli/cli_runner.h"
#include "core/project/project.h"
#include "core/setup/model.h"
#include "core/study/setup_validation.h"
#include "qtapp.h"
#include "testsupport.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"
#include "widgets/setup/setupconvergenceview.h"
#include "widgets/setup/setupmodeleditor.h"
#include "widgets/setup/setupresultsview.h"
#include "widgets/setup/setupvalidationview.h"

namespace metrofit {
namespace {

class SetupPageTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    project_ = extractDemoProject(dir_.path());
    document_.load(project_);
    page_ = std::make_unique<SetupPage>(&document_);
    page_->resize(1100, 760);
  }
  void grab(const char* name) {
    page_->show();
    QCoreApplication::processEvents();
    page_->grab().save(QString::fromStdString((test::outDir() / name).string()));
  }
  QString modelPath() const { return dir_.filePath(QStringLiteral("data/paper_example.json")); }

  QTemporaryDir dir_;
  QString project_;
  ProjectDocument document_;
  std::unique_ptr<SetupPage> page_;
};

TEST_F(SetupPageTest, LoadsTheDemoStudy) {
  EXPECT_TRUE(page_->errorMessage().isEmpty()) << page_->errorMessage().toStdString();
  EXPECT_EQ(page_->modelEditor()->model().setup.size(), 10u);
  EXPECT_EQ(page_->modelEditor()->model().dimensions.size(), 28u);
  EXPECT_EQ(page_->methodCombo()->currentData().toString(), QStringLiteral("exact"))
      << "studies.setup.method";
  EXPECT_EQ(page_->budgetSpin()->value(), 5000);
  EXPECT_TRUE(page_->runButton()->isEnabled());
  EXPECT_FALSE(page_->cancelButton()->isEnabled());
  EXPECT_EQ(page_->tabs()->count(), 4);
}

TEST_F(SetupPageTest, ExactRunShowsTheCliCorrections) {
  test::TempDir tmp;
  const test::CliRun cli = test::cli(
      "setup --model '" + modelPath().toStdString() + "' --data '" +
          dir_.filePath(QStringLiteral("data/paper_example_report.csv")).toStdString() + "' --method exact",
      tmp);
  ASSERT_EQ(cli.code, 0) << cli.err;
  const auto j = nlohmann::json::parse(cli.out);

  page_->methodCombo()->setCurrentIndex(page_->methodCombo()->findData(QStringLiteral("exact")));
  ASSERT_TRUE(page_->startRun());
  page_->waitForRun();
  SetupResultsView* results = page_->resultsView();
  ASSERT_TRUE(results->hasResult());
  QTableWidget* table = results->correctionsTable();
  ASSERT_EQ(table->rowCount(), 10);
  std::map<std::string, double> shown;
  for (int row = 0; row < table->rowCount(); ++row) {
    const std::string id = table->item(row, 0)->text().toStdString();
    const QString text = table->item(row, 3)->text();
    EXPECT_EQ(text.count(QLatin1Char('.')) + text.count(QLatin1Char(',')), 1) << text.toStdString();
    EXPECT_EQ(text.size() - std::max(text.indexOf(QLatin1Char('.')), text.indexOf(QLatin1Char(','))) - 1, 3)
        << "3 decimals: " << text.toStdString();
    shown[id] = table->item(row, 3)->data(Qt::UserRole).toDouble();
  }
  ASSERT_EQ(j["corrections_mm"].size(), shown.size());
  for (const auto& [id, value] : j["corrections_mm"].items()) {
    ASSERT_TRUE(shown.count(id)) << id;
    EXPECT_NEAR(shown[id], value.get<double>(), 1e-9) << id;
  }
  EXPECT_TRUE(results->summaryText().contains(QStringLiteral("f1 proven optimal")))
      << results->summaryText().toStdString();
  EXPECT_TRUE(results->summaryText().contains(QLocale().toString(j["f1_mm"].get<double>(), 'f', 4)))
      << results->summaryText().toStdString();
  EXPECT_TRUE(results->partsText().contains(QStringLiteral("of 3"))) << results->partsText().toStdString();
  EXPECT_EQ(page_->convergenceView()->hasExact(), true);

  // Export of the shown corrections in every format: exactly what the CLI writes (the CLI runs in the
  // C locale; this test also runs under de_DE.UTF-8 and pl_PL.UTF-8, where printf writes "0,013").
  QString error;
  for (const auto format : {setup::ControllerFormat::Fanuc, setup::ControllerFormat::Heidenhain,
                            setup::ControllerFormat::Siemens, setup::ControllerFormat::Csv}) {
    const std::string name = setup::toString(format);
    const QString nc = QString::fromStdString(tmp.file("offsets." + name));
    ASSERT_TRUE(results->exportTo(format, nc, &error)) << error.toStdString();
    const test::CliRun cliExport =
        test::cli("setup --model '" + modelPath().toStdString() + "' --data '" +
                      dir_.filePath(QStringLiteral("data/paper_example_report.csv")).toStdString() +
                      "' --method exact --export " + name + " --export-out cli." + name + " --out r.json",
                  tmp);
    ASSERT_EQ(cliExport.code, 0) << cliExport.err;
    const std::string gui = test::readText(nc.toStdString());
    EXPECT_EQ(gui, test::readText(tmp.file("cli." + name))) << name;
  }
  EXPECT_FALSE(
      results->exportTo(setup::ControllerFormat::Csv, QStringLiteral("/nonexistent-folder/c.csv"), &error));
  EXPECT_TRUE(error.contains(QStringLiteral("/nonexistent-folder/c.csv"))) << error.toStdString();
  page_->tabs()->setCurrentIndex(2);
  grab("setuppage_results.png");
}

TEST_F(SetupPageTest, MetaheuristicRunFeedsTheChartAndCanBeCancelled) {
  page_->methodCombo()->setCurrentIndex(page_->methodCombo()->findData(QStringLiteral("cripso")));
  page_->budgetSpin()->setValue(50'000'000);
  ASSERT_TRUE(page_->startRun());
  EXPECT_TRUE(page_->isRunning());
  EXPECT_TRUE(page_->cancelButton()->isEnabled());
  EXPECT_FALSE(page_->runButton()->isEnabled());
  EXPECT_FALSE(page_->startRun()) << "one run at a time";
  // Live points arrive while it runs.
  QElapsedTimer timer;
  timer.start();
  while (page_->convergenceView()->runs().empty() || page_->convergenceView()->runs()[0].trace.size() < 3) {
    ASSERT_LT(timer.elapsed(), 20000) << "no live trace";
    QTest::qWait(50);
  }
  EXPECT_TRUE(page_->isRunning());
  page_->cancelButton()->click();
  page_->waitForRun();
  EXPECT_LT(timer.elapsed(), 30000);
  EXPECT_FALSE(page_->isRunning());
  ASSERT_TRUE(page_->resultsView()->hasResult());
  const SetupRunOutcome& o = *page_->resultsView()->result();
  EXPECT_EQ(o.termination, Termination::Cancelled);
  EXPECT_LT(o.evaluations, 50'000'000);
  EXPECT_GT(o.evaluations, 0);
  EXPECT_TRUE(page_->resultsView()->summaryText().contains(QStringLiteral("cancelled")));
  EXPECT_TRUE(page_->runButton()->isEnabled());
  EXPECT_FALSE(page_->cancelButton()->isEnabled());

  // A full run afterwards overlays a second curve.
  page_->budgetSpin()->setValue(5000);
  page_->seedSpin()->setValue(3);
  ASSERT_TRUE(page_->startRun());
  page_->waitForRun();
  ASSERT_EQ(page_->convergenceView()->runs().size(), 2u);
  const auto& trace = page_->convergenceView()->runs()[1].trace;
  ASSERT_FALSE(trace.empty());
  EXPECT_EQ(trace.back().evaluations, 5000);
  EXPECT_EQ(page_->progressBar()->value(), page_->progressBar()->maximum());
}

TEST_F(SetupPageTest, ConvergenceViewOverlaysExactCripsoAndPso) {
  page_->showView(QStringLiteral("convergence"));
  EXPECT_EQ(page_->tabs()->currentIndex(), 1);
  SetupConvergenceView* view = page_->convergenceView();
  EXPECT_TRUE(view->hasExact());
  ASSERT_EQ(view->runs().size(), 2u);
  EXPECT_EQ(view->runs()[0].method, QStringLiteral("cripso"));
  EXPECT_EQ(view->runs()[1].method, QStringLiteral("pso"));
  const QStringList legend = view->legendLabels();
  EXPECT_TRUE(legend.contains(QStringLiteral("CRIPSO, seed 1"))) << legend.join(',').toStdString();
  EXPECT_TRUE(legend.contains(QStringLiteral("PSO, seed 1")));
  EXPECT_TRUE(legend.filter(QStringLiteral("exact optimum f1")).size() == 1);
  grab("setuppage_convergence.png");
  page_->showView(QStringLiteral("convergence"));
  EXPECT_EQ(view->runs().size(), 2u) << "runs only once";
  page_->showView(QStringLiteral("graph"));
  EXPECT_EQ(page_->tabs()->currentIndex(), 0);
  grab("setuppage_graph.png");
}

TEST_F(SetupPageTest, ValidationRunsAndCancels) {
  SetupValidationView* v = page_->validationView();
  EXPECT_EQ(v->sets(), 100);  // the paper's 100 sets x 10 trials by default
  EXPECT_EQ(v->trials(), 10);
  v->setSets(6);
  v->setTrials(2);
  v->setBudget(2000);
  ASSERT_TRUE(v->start());
  v->waitForFinished();
  ASSERT_NE(v->result(), nullptr);
  EXPECT_EQ(v->result()->sets.size(), 6u);
  EXPECT_EQ(v->result()->sets[0].trials.size(), 2u);
  EXPECT_TRUE(v->summaryText().contains(QStringLiteral("CRIPSO: mean gap")))
      << v->summaryText().toStdString();
  EXPECT_EQ(v->progressBar()->value(), 6);
  // The paper's range is checked (w1 = 0.03, w2 = 0.02 by default) and the setup share estimated.
  EXPECT_TRUE(v->summaryText().contains(QStringLiteral("is consistent with the simulator")))
      << v->summaryText().toStdString();
  EXPECT_TRUE(v->summaryText().contains(QStringLiteral("Share of the setup data")))
      << v->summaryText().toStdString();
  // The share in the demo report's three parts is the CLI's (setup validate --data).
  {
    test::TempDir tmp;
    const test::CliRun cli =
        test::cli("setup validate --sets 1 --trials 0 --model '" + modelPath().toStdString() + "' --data '" +
                      dir_.filePath(QStringLiteral("data/paper_example_report.csv")).toStdString() + "'",
                  tmp);
    ASSERT_EQ(cli.code, 0) << cli.err;
    const double share = nlohmann::json::parse(cli.out)["data_share"]["weight_share"].get<double>();
    const QString expected = QStringLiteral("In the project's measurements (3 part(s)): %1 % of the weights")
                                 .arg(QLocale().toString(100.0 * share, 'f', 0));
    EXPECT_TRUE(v->summaryText().contains(expected)) << v->summaryText().toStdString() << " / " << share;
  }
  page_->tabs()->setCurrentIndex(3);
  grab("setuppage_validation.png");
  v->setSets(5000);
  ASSERT_TRUE(v->start());
  v->cancel();
  v->waitForFinished();
  EXPECT_TRUE(v->result()->cancelled);
  EXPECT_LT(v->result()->sets.size(), 5000u);
}

TEST_F(SetupPageTest, EditedModelIsSavedAtomically) {
  SetupModelEditor* editor = page_->modelEditor();
  ASSERT_TRUE(editor->setTolerance(0, 12.0, -0.09, 0.1));
  EXPECT_TRUE(editor->isModified());
  // Runs use the edited tolerance before it is saved.
  ASSERT_TRUE(page_->errorMessage().isEmpty()) << page_->errorMessage().toStdString();
  QString error;
  ASSERT_TRUE(page_->saveModel(&error)) << error.toStdString();
  EXPECT_FALSE(editor->isModified());
  const setup::Model saved = setup::readModel(modelPath().toStdString());
  EXPECT_DOUBLE_EQ(saved.dimensions[0].lower, -0.09);
  EXPECT_EQ(QDir(dir_.filePath(QStringLiteral("data")))
                .entryList(QStringList{QStringLiteral("*.tmp*")}, QDir::Files)
                .size(),
            0);

  // An invalid model is not saved.
  ASSERT_TRUE(editor->addArc(QStringLiteral("W1"), QStringLiteral("nowhere"), 1));
  EXPECT_FALSE(page_->saveModel(&error));
  EXPECT_TRUE(error.contains(QStringLiteral("unknown node 'nowhere'"))) << error.toStdString();
  EXPECT_FALSE(page_->runButton()->isEnabled());
  EXPECT_TRUE(page_->errorMessage().contains(QStringLiteral("problem")))
      << page_->errorMessage().toStdString();
  editor->undoStack()->undo();
  EXPECT_TRUE(page_->runButton()->isEnabled());

  // A file that cannot be written: a readable error naming it.
  ASSERT_TRUE(editor->setTolerance(0, 12.0, -0.1, 0.1));
  QFile::remove(modelPath());
  ASSERT_TRUE(QDir().mkpath(modelPath() + QStringLiteral("/blocked")));  // a folder where the file was
  EXPECT_FALSE(page_->saveModel(&error));
  EXPECT_TRUE(error.contains(QStringLiteral("paper_example.json"))) << error.toStdString();
  EXPECT_FALSE(error.contains(QLatin1Char('\n'))) << error.toStdString();
}

}  // namespace
}  // namespace metrofit

namespace metrofit {
namespace {

// Issue 27 item 3: a bad run setting written in the project file (studies.setup.method, budget,
// seed) is refused with the field named on the page and Run is disabled; the control is never set
// to a default in its place, and choosing a value in the control corrects the study (undoable).
struct BadSetupSetting {
  const char* key;
  nlohmann::json value;
  const char* field;
};

class SetupSettingsRefusalTest : public ::testing::TestWithParam<int> {};

const BadSetupSetting kBadSettings[] = {
    {"method", "simplex", "studies.setup.method"},
    {"method", 3, "studies.setup.method"},
    {"budget", -5, "studies.setup.budget"},
    {"budget", "lots", "studies.setup.budget"},
    {"budget", 2500.5, "studies.setup.budget"},
    {"budget", 1e10, "studies.setup.budget"},  // valid for the study, more than the page can run
    {"seed", -1, "studies.setup.seed"},
    {"seed", "one", "studies.setup.seed"},
};

TEST_P(SetupSettingsRefusalTest, IsNamedAndNothingRuns) {
  const BadSetupSetting& bad = kBadSettings[GetParam()];
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  const QString path = extractDemoProject(dir.path());
  Project p = loadProject(path.toStdString());
  p.studies["setup"]["method"] = "pso";  // a good value beside the bad one stays shown
  p.studies["setup"][bad.key] = bad.value;
  saveProject(p, path.toStdString());
  ProjectDocument document;
  document.load(path);
  SetupPage page(&document);
  const QString field = QString::fromLatin1(bad.field);
  EXPECT_TRUE(page.settingsError().contains(field)) << page.settingsError().toStdString();
  EXPECT_TRUE(page.infoText().contains(field)) << page.infoText().toStdString();
  EXPECT_FALSE(page.runButton()->isEnabled()) << "refused, not replaced by a default";
  EXPECT_FALSE(page.startRun());
  EXPECT_FALSE(page.resultsView()->hasResult());
  EXPECT_FALSE(document.isModified()) << "showing a bad project is no edit";
  EXPECT_EQ(document.project().studies["setup"][bad.key], bad.value) << "the bad value is not rewritten";
  if (std::string(bad.key) != "method") {
    EXPECT_EQ(page.methodCombo()->currentData().toString(), QStringLiteral("pso"));
  }

  // Choosing a value in the control corrects the study in one undo step; undo brings the refusal back.
  if (std::string(bad.key) == "method") {
    page.methodCombo()->setCurrentIndex(page.methodCombo()->findData(QStringLiteral("cripso")));
    EXPECT_EQ(document.project().studies["setup"]["method"], "cripso");
  } else if (std::string(bad.key) == "budget") {
    page.budgetSpin()->setValue(page.budgetSpin()->value() == 3000 ? 3001 : 3000);
    EXPECT_TRUE(document.project().studies["setup"]["budget"].is_number_integer());
  } else {
    page.seedSpin()->setValue(page.seedSpin()->value() == 7 ? 8 : 7);
    EXPECT_TRUE(document.project().studies["setup"]["seed"].is_number_unsigned());
  }
  EXPECT_TRUE(page.settingsError().isEmpty()) << page.settingsError().toStdString();
  EXPECT_TRUE(page.runButton()->isEnabled());
  EXPECT_FALSE(page.infoText().contains(field)) << page.infoText().toStdString();
  document.undoStack()->undo();
  EXPECT_EQ(document.project().studies["setup"][bad.key], bad.value);
  EXPECT_TRUE(page.settingsError().contains(field)) << page.settingsError().toStdString();
  EXPECT_FALSE(page.runButton()->isEnabled());
}

INSTANTIATE_TEST_SUITE_P(BadValues, SetupSettingsRefusalTest,
                         ::testing::Range(0, static_cast<int>(std::size(kBadSettings))));

// A setting broken by an edit (another page, an import) is refused the same way.
TEST(SetupSettingsRefusal, AnEditThatBreaksASettingDisablesRun) {
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  ProjectDocument document;
  document.load(extractDemoProject(dir.path()));
  SetupPage page(&document);
  ASSERT_TRUE(page.runButton()->isEnabled());
  const int budget = page.budgetSpin()->value();
  document.setStudyValue(QStringLiteral("setup"), QStringLiteral("/budget"), 0, QStringLiteral("break"));
  EXPECT_TRUE(page.settingsError().contains(QStringLiteral("studies.setup.budget")));
  EXPECT_FALSE(page.runButton()->isEnabled());
  EXPECT_EQ(page.budgetSpin()->value(), budget) << "the control is not moved to a substitute";
  document.undoStack()->undo();
  EXPECT_TRUE(page.settingsError().isEmpty());
  EXPECT_TRUE(page.runButton()->isEnabled());
}

}  // namespace
}  // namespace metrofit
