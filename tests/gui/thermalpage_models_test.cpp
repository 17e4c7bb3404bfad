// The thermal page's Hysteresis and Models tabs on generated data (offscreen): the GNNMCI metrics equal
// those of `metrofit-cli thermal fit` for the same seed, training in the worker reports live PSO
// progress, Cancel stops it, showView switches tabs with results on them. Grabs of the page go to
// $METROFIT_TEST_OUT/thermalpage for people to look at.
#include <gtest/gtest.h>

#include "core/thermal/model_verdict.h"

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>
#include <QUndoStack>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "app/gui/thermalpage.h"
#include "cli/cli_runner.h"
#include "core/io/file_io.h"
#include "core/project/project.h"
#include "core/sim/thermal_sim.h"
#include "core/study/thermal_comparison.h"
#include "qtapp.h"
#include "testsupport.h"
#include "widgets/document/projectdocument.h"
#include "widgets/thermal/thermalhysteresisview.h"
#include "widgets/thermal/thermalmodelview.h"

namespace metrofit {
namespace {

class ThermalPageModelsTest : public ::testing::Test {
 protected:
  /// A project with one generated log (thermal_sim.h, seed 3) of `minutes` minutes.
  void makeProject(double minutes) {
    ThermalSimOptions so;
    so.seed = 3;
    so.durationMin = minutes;
    test::writeText(tmp_.file("log.csv"), thermalLogToCsv(simulateThermalTest(so)));
    Project p;
    p.name = "generated";
    p.datasets.push_back({"gen", "thermal_log", "log.csv", "generated", "", {}});
    p.studies["thermal"] = {
        {"dataset", "gen"}, {"target", "disp_z_um"}, {"inputs", {"T1", "T2", "T3", "T4"}}};
    saveProject(p, tmp_.file("p.metrofit"));
    document_.load(QString::fromStdString(tmp_.file("p.metrofit")));
  }

  void grab(ThermalPage& page, const QString& name) {
    const QDir dir(QString::fromStdString((test::outDir() / "thermalpage").string()));
    QDir().mkpath(dir.path());
    page.resize(1180, 760);
    page.show();
    QTest::qWait(50);
    EXPECT_TRUE(page.grab().save(dir.filePath(name)));
  }

  test::TempDir tmp_;
  ProjectDocument document_;
};

TEST_F(ThermalPageModelsTest, GnnmciMetricsEqualTheCliForTheSameSeed) {
  makeProject(480.0);
  ThermalPage page(&document_);
  page.showView(QStringLiteral("models"));
  EXPECT_EQ(page.tabs()->currentIndex(), 2);
  const ThermalComparison* c = page.modelView()->comparison();
  ASSERT_NE(c, nullptr) << page.modelView()->statusText().toStdString();
  EXPECT_EQ(c->settings.inputs, (std::vector<std::string>{"T1", "T2", "T3", "T4"}));
  EXPECT_EQ(c->settings.trainFraction, 0.5);
  EXPECT_EQ(c->settings.seed, 1u);

  const test::CliRun r = test::cli(
      "thermal fit --data log.csv --target disp_z_um --inputs T1,T2,T3,T4 --model gnnmci --train-fraction "
      "0.5 "
      "--seed 1 --out fit.json",
      tmp_);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(test::readText(tmp_.file("fit.json")));
  const thermal::ThermalEvaluation& g = c->models[0];
  EXPECT_EQ(j["train_rows"].get<std::size_t>(), g.fitRows);
  EXPECT_NEAR(j["fit_rmse"].get<double>(), g.fit.rmse, 1e-9);
  EXPECT_NEAR(j["heldout_rmse"].get<double>(), g.heldout.rmse, 1e-9);
  EXPECT_NEAR(j["R"].get<double>(), g.heldout.r, 1e-9);
  EXPECT_NEAR(j["E"].get<double>(), g.heldout.e, 1e-9);
  EXPECT_NEAR(j["residual_band"].get<double>(), g.heldout.residualBand, 1e-9);
  EXPECT_NEAR(j["fit"]["E"].get<double>(), g.fit.e, 1e-9);

  // Table 4 on screen: two rows (fit, held out) per model, the held-out RMSE as computed.
  const QTableWidget* table = page.modelView()->metricsTable();
  ASSERT_EQ(table->rowCount(), 12);  // the paper's three, then linear, lag, dlag
  EXPECT_EQ(table->item(0, 0)->text(), QStringLiteral("GNNMCI(1,N)"));
  EXPECT_EQ(table->item(1, 3)->text(), QString::number(g.heldout.rmse, 'f', 2));
  EXPECT_EQ(table->item(2, 0)->text(), QStringLiteral("GMC(1,N)"));
  EXPECT_EQ(table->item(4, 0)->text(), QStringLiteral("MLP"));
  EXPECT_EQ(table->item(6, 0)->text(), QStringLiteral("linear"));
  EXPECT_EQ(table->item(8, 0)->text(), QStringLiteral("lag"));
  EXPECT_EQ(table->item(10, 0)->text(), QStringLiteral("dlag"));
  // Each held-out row carries the verdict; the status names the best usable model.
  for (int row : {1, 3, 5}) {
    ASSERT_NE(table->item(row, 6), nullptr) << row;
    EXPECT_TRUE(table->item(row, 6)->text().startsWith(QStringLiteral("usable")) ||
                table->item(row, 6)->text() == QStringLiteral("not usable"))
        << table->item(row, 6)->text().toStdString();
  }
  EXPECT_EQ(table->item(1, 6)->text().startsWith(QStringLiteral("usable")),
            thermal::judgeThermalModel(g.heldout, thermal::targetScale(c->series.target)) ==
                thermal::ModelVerdict::Usable);
  EXPECT_TRUE(page.modelView()->statusText().contains(QStringLiteral("Best usable model: ")) ||
              page.modelView()->statusText().contains(QStringLiteral("No model is usable")))
      << page.modelView()->statusText().toStdString();
  grab(page, QStringLiteral("models.png"));

  page.showView(QStringLiteral("hysteresis"));
  EXPECT_EQ(page.tabs()->currentIndex(), 1);
  EXPECT_EQ(page.hysteresisView()->chartCount(), 4);
  EXPECT_EQ(page.hysteresisView()->analysis().sensors.size(), 4u);
  grab(page, QStringLiteral("hysteresis.png"));
  page.showView(QStringLiteral("trend"));
  EXPECT_EQ(page.tabs()->currentIndex(), 0);
}

TEST_F(ThermalPageModelsTest, WorkerReportsLiveProgressAndFinishes) {
  makeProject(240.0);
  ThermalPage page(&document_);
  ThermalModelView* view = page.modelView();
  QSignalSpy finished(view, &ThermalModelView::trainingFinished);
  view->trainButton()->click();
  EXPECT_TRUE(view->isRunning());
  EXPECT_FALSE(view->trainButton()->isEnabled());
  EXPECT_TRUE(view->cancelButton()->isEnabled());
  ASSERT_TRUE(finished.wait(60000));
  EXPECT_TRUE(finished.takeFirst().at(0).toBool());
  const ThermalComparison* c = view->comparison();
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(view->liveIterations(), c->models[0].training.run.iterations);
  EXPECT_EQ(view->progressBar()->value(), view->progressBar()->maximum());
  EXPECT_TRUE(view->trainButton()->isEnabled());
  EXPECT_FALSE(view->cancelButton()->isEnabled());
}

TEST_F(ThermalPageModelsTest, CancelStopsTraining) {
  makeProject(6000.0);  // 6001 rows: long enough to cancel in the middle of the swarm
  ThermalPage page(&document_);
  ThermalModelView* view = page.modelView();
  QSignalSpy finished(view, &ThermalModelView::trainingFinished);
  view->train();
  ASSERT_TRUE(QTest::qWaitFor([&] { return view->liveIterations() >= 1; }, 60000));
  view->cancelButton()->click();
  ASSERT_TRUE(finished.wait(60000));
  EXPECT_FALSE(finished.takeFirst().at(0).toBool());
  EXPECT_LT(view->liveIterations(), 100);
  EXPECT_EQ(view->comparison(), nullptr);  // nothing was trained before
  EXPECT_TRUE(view->statusText().contains(QStringLiteral("cancelled"))) << view->statusText().toStdString();
  EXPECT_FALSE(view->isRunning());
  EXPECT_TRUE(view->trainButton()->isEnabled());
}

TEST_F(ThermalPageModelsTest, BadSettingsGiveAMessage) {
  makeProject(240.0);
  ThermalPage page(&document_);
  ThermalModelView* view = page.modelView();
  ThermalModelSettings s = view->settings();
  s.inputs.clear();
  view->setSettings(s);
  EXPECT_FALSE(view->trainNow());
  EXPECT_EQ(view->statusText(), QStringLiteral("Choose at least one input."));
  s.inputs = {"spindle_rpm", "T1"};
  s.trainFraction = 0.9;
  view->setSettings(s);
  // The speed is 0 for the first 10 min only, so it is not constant; training works.
  EXPECT_TRUE(view->trainNow()) << view->statusText().toStdString();
}

TEST_F(ThermalPageModelsTest, SettingsEditsAreWrittenToTheStudyAndUndone) {
  makeProject(240.0);
  ThermalPage page(&document_);
  ThermalModelView* view = page.modelView();
  auto* seed = view->findChild<QSpinBox*>(QStringLiteral("thermalModelSeed"));
  auto* fraction = view->findChild<QDoubleSpinBox*>(QStringLiteral("thermalModelTrainFraction"));
  auto* target = view->findChild<QComboBox*>(QStringLiteral("thermalModelTarget"));
  ASSERT_TRUE(seed && fraction && target);
  const nlohmann::json before = document_.project().studies["thermal"];
  EXPECT_FALSE(document_.isModified());
  EXPECT_EQ(document_.undoStack()->count(), 0) << "showing the settings is no edit";

  // The first edit writes the settings the study did not have yet (one undo step).
  seed->setValue(7);
  nlohmann::json expected = before;
  expected["train_fraction"] = 0.5;
  expected["seed"] = 7;
  EXPECT_EQ(document_.project().studies["thermal"], expected);
  EXPECT_TRUE(document_.isModified());
  EXPECT_EQ(document_.undoStack()->count(), 1);
  // Typing in the fraction box is one more step.
  fraction->setValue(0.6);
  fraction->setValue(0.7);
  expected["train_fraction"] = 0.7;
  EXPECT_EQ(document_.project().studies["thermal"], expected);
  EXPECT_EQ(document_.undoStack()->count(), 2);
  // A new target hides it from the inputs: target and inputs change in one step.
  target->setCurrentIndex(target->findData(QStringLiteral("T1")));
  expected["target"] = "T1";
  expected["inputs"] = {"T2", "T3", "T4"};
  EXPECT_EQ(document_.project().studies["thermal"], expected);
  EXPECT_EQ(document_.undoStack()->count(), 3);

  document_.undoStack()->undo();
  EXPECT_EQ(view->settings().target, "disp_z_um");
  EXPECT_EQ(view->settings().inputs, (std::vector<std::string>{"T1", "T2", "T3", "T4"}));
  document_.undoStack()->undo();
  EXPECT_DOUBLE_EQ(fraction->value(), 0.5);
  EXPECT_EQ(seed->value(), 7);
  document_.undoStack()->undo();
  EXPECT_EQ(document_.project().studies["thermal"], before);
  EXPECT_EQ(seed->value(), 1);
  EXPECT_FALSE(document_.isModified());
  EXPECT_EQ(document_.undoStack()->count(), 3) << "restoring the controls pushes nothing";
  document_.undoStack()->redo();
  EXPECT_EQ(seed->value(), 7);
  EXPECT_EQ(document_.project().studies["thermal"]["seed"], 7);
}

// The demo's modular case on the Models tab: besides the pooled models, the same case module by module
// (each module identified on its own test with the channels its own heating moves, the helical test
// predicted as their sum): a last table row and a line naming each module's inputs and contribution,
// the figures those of the study code (core/study/thermal_comparison.h) for the same logs.
TEST_F(ThermalPageModelsTest, ModularCaseShowsEachModulesContribution) {
  std::filesystem::copy(test::sourceDir() / "resources/demo", tmp_.file("demo"),
                        std::filesystem::copy_options::recursive);
  document_.load(QString::fromStdString(tmp_.file("demo/demo.metrofit")));
  ThermalPage page(&document_);
  page.selectDataset(QString::fromLatin1(kModularCombinedId));
  page.showView(QStringLiteral("models"));
  ThermalModelView* view = page.modelView();
  const QTableWidget* table = view->modularTable();
  const int last = static_cast<int>(kThermalModelOrder.size());  // after the pooled models
  // The modular run is a background run.
  ASSERT_TRUE(QTest::qWaitFor([&] { return table->rowCount() == last + 1; }, 120000))
      << view->statusText().toStdString();
  ASSERT_EQ(table->rowCount(), last + 1) << view->statusText().toStdString();
  EXPECT_EQ(table->item(last, 0)->text(), QStringLiteral("modules, summed (distributed lag)"));
  const QString line = view->modularModulesLabel()->text();
  EXPECT_TRUE(
      line.contains(QStringLiteral("thermal_modular_z (inputs T5, T6, FBG1_ue, FBG4_ue) contributes up to")))
      << line.toStdString();
  EXPECT_TRUE(line.contains(QStringLiteral("thermal_modular_c (inputs T1, T3) contributes up to")))
      << line.toStdString();
  // The table's reduction is the study code's for the same three logs.
  const auto log = [&](const char* id) {
    return readThermalLog(document_.datasetPath(*document_.project().dataset(id)).toStdString());
  };
  const ThermalLog z = log(kModularZId), c = log(kModularCId), h = log(kModularCombinedId);
  const ModularComparison m =
      compareModularModels({&z, &c}, h, "disp_z_um", modularInputs(h), 1, {}, {kModularZId, kModularCId});
  ASSERT_TRUE(m.modules.evaluation.has_value());
  EXPECT_EQ(table->item(last, 2)->text(),
            QLocale().toString(100.0 * m.modules.evaluation->reductionPeak, 'f', 1));
  if (auto* tabs = view->findChild<QTabWidget*>(QStringLiteral("thermalModelResultTabs")))
    tabs->setCurrentIndex(1);
  grab(page, QStringLiteral("modular-modules.png"));
}

}  // namespace
}  // namespace metrofit
