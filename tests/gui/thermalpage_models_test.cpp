// The thermal page's Hysteresis and Models tabs on generated data (offscreen): the GNNMCI metrics equal
// those of `metrofit-cli thermal fit` for the same seed, training in the worker reports live PSO
// progress, Cancel stops it, showView switches tabs with results on them. Grabs of the page go to
// $METROFIT_TEST_OUT/thermalpage for people to look at.
#include <gtest/gtest.h>
#include <cmath>

#include "core/thermal/model_verdict.h"

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QInputDialog>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStackedWidget>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>

#include "app/gui/thermalpage.h"
#include "cli/cli_runner.h"
#include "core/io/file_io.h"
#include "core/project/project.h"
#include "core/sim/thermal_sim.h"
#include "core/study/thermal_comparison.h"
#include "core/thermal/control_export.h"
#include "core/thermal/thermal_model.h"
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

// Issue 27 item 3: a bad study setting is refused on the page as in the report, the field named in a
// message on the page, never replaced by a default (the page used to fit with the default fraction).
TEST_F(ThermalPageModelsTest, BadStudySettingIsRefusedNamingTheField) {
  makeProject(240.0);
  ThermalPage page(&document_);
  auto* tabs = page.findChild<QTabWidget*>(QStringLiteral("thermalTabs"));
  auto* message = page.findChild<QLabel*>(QStringLiteral("thermalMessage"));
  ASSERT_TRUE(tabs && message);
  auto* stack = qobject_cast<QStackedWidget*>(tabs->parentWidget());
  ASSERT_NE(stack, nullptr);
  EXPECT_EQ(stack->currentWidget(), tabs);
  document_.setStudyValue(QStringLiteral("thermal"), QStringLiteral("/train_fraction"), 1.5,
                          QStringLiteral("break"));
  EXPECT_EQ(stack->currentWidget(), message);
  EXPECT_TRUE(message->text().contains(QStringLiteral("studies.thermal.train_fraction")))
      << message->text().toStdString();
  document_.undoStack()->undo();
  EXPECT_EQ(stack->currentWidget(), tabs) << message->text().toStdString();
  EXPECT_DOUBLE_EQ(page.modelView()->settings().trainFraction, 0.5);

  // A target the log lacks: refused by name, not swapped for the first displacement channel.
  document_.setStudyValue(QStringLiteral("thermal"), QStringLiteral("/target"), "disp_x_um",
                          QStringLiteral("break"));
  EXPECT_EQ(stack->currentWidget(), message);
  EXPECT_TRUE(message->text().contains(QStringLiteral("studies.thermal.target")))
      << message->text().toStdString();
  document_.save();
  ProjectDocument reopened;
  reopened.load(document_.fileName());
  ThermalPage other(&reopened);
  auto* otherMessage = other.findChild<QLabel*>(QStringLiteral("thermalMessage"));
  ASSERT_NE(otherMessage, nullptr);
  EXPECT_TRUE(otherMessage->text().contains(QStringLiteral("disp_x_um")))
      << otherMessage->text().toStdString();
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
  // A pooled model whose prediction runs away (RMSE above 100 x the error, the verdict's divergence
  // rule) reads "diverges" in every figure, never a number like 2e+305; every other row has figures.
  for (std::size_t i = 0; i < kThermalModelOrder.size(); ++i) {
    const thermal::ModularEvaluation& ev = m.models[i];
    const int row = static_cast<int>(i);
    if (!m.fitted(i)) continue;
    const bool runaway = !std::isfinite(ev.test.rmse) || ev.test.rmse > 100.0 * ev.errorPeak;
    for (int c = 1; c <= 5; ++c) {
      const QString text = table->item(row, c)->text();
      EXPECT_EQ(text == QStringLiteral("diverges"), runaway) << i << " " << c << " " << text.toStdString();
      EXPECT_FALSE(text.contains(QStringLiteral("e+"))) << text.toStdString();
    }
  }
  if (auto* tabs = view->findChild<QTabWidget*>(QStringLiteral("thermalModelResultTabs")))
    tabs->setCurrentIndex(1);
  grab(page, QStringLiteral("modular-modules.png"));
}

// One model's failure marks that model only: a noise-free log whose target is exactly linear in its
// one input (3.25 um/K, written with every decimal) makes GMC(1,N)'s least squares rank deficient. The
// Models tab shows GMC(1,N)'s row as "not fitted: <reason>", the linear model's rows with a held-out
// RMSE of 0 (the closed form: an exact fit), and never names GMC(1,N) the best model.
TEST_F(ThermalPageModelsTest, AModelThatCannotBeFittedIsMarkedAndTheOthersAreShown) {
  std::string csv = "time_s,T1,disp_z_um\n";
  for (int r = 0; r < 120; ++r) {
    const double t = 30.0 * r;
    const double temperature = std::round((21.0 + 9.0 * (1.0 - std::exp(-t / 1500.0))) * 1e4) / 1e4;
    char line[96];
    std::snprintf(line, sizeof line, "%d,%.4f,%.6f\n", static_cast<int>(t), temperature,
                  3.25 * (temperature - 21.0) - 0.8);
    csv += line;
  }
  test::writeText(tmp_.file("linear.csv"), csv);
  Project p;
  p.name = "linear";
  p.datasets.push_back({"spindel", "thermal_log", "linear.csv", "", "", {}});
  p.studies["thermal"] = {{"dataset", "spindel"}, {"target", "disp_z_um"}, {"inputs", {"T1"}}};
  saveProject(p, tmp_.file("p.metrofit"));
  document_.load(QString::fromStdString(tmp_.file("p.metrofit")));
  ThermalPage page(&document_);
  page.showView(QStringLiteral("models"));
  const ThermalComparison* c = page.modelView()->comparison();
  ASSERT_NE(c, nullptr) << page.modelView()->statusText().toStdString();
  ASSERT_FALSE(c->failed[1].empty());  // GMC(1,N)
  ASSERT_TRUE(c->fitted(3));           // linear
  EXPECT_LT(c->models[3].heldout.rmse, 1e-9);

  const QTableWidget* table = page.modelView()->metricsTable();
  // GNNMCI two rows, GMC one, then MLP, linear, lag, dlag two each.
  ASSERT_EQ(table->rowCount(), 11) << page.modelView()->statusText().toStdString();
  EXPECT_EQ(table->item(2, 0)->text(), QStringLiteral("GMC(1,N)"));
  const QString gmcRow = table->item(2, 1)->text();
  EXPECT_TRUE(gmcRow.startsWith(QStringLiteral("not fitted: ")) &&
              gmcRow.contains(QStringLiteral("rank deficient")))
      << gmcRow.toStdString();
  EXPECT_EQ(table->columnSpan(2, 1), table->columnCount() - 1);
  EXPECT_EQ(table->item(5, 0)->text(), QStringLiteral("linear"));
  EXPECT_TRUE(table->item(6, 1)->text().startsWith(QStringLiteral("held out")));
  EXPECT_EQ(table->item(6, 3)->text(), QLocale().toString(0.0, 'f', 2));  // RMSE 0.00 µm
  // No NaN anywhere in the table.
  for (int r = 0; r < table->rowCount(); ++r) {
    for (int col = 0; col < table->columnCount(); ++col) {
      if (const QTableWidgetItem* item = table->item(r, col)) {
        EXPECT_FALSE(item->text().contains(QStringLiteral("nan"), Qt::CaseInsensitive)) << r << "," << col;
      }
    }
  }
  const QString status = page.modelView()->statusText();
  EXPECT_TRUE(status.contains(QStringLiteral("GMC(1,N) not fitted: "))) << status.toStdString();
  EXPECT_FALSE(status.contains(QStringLiteral("Best usable model: GMC(1,N)"))) << status.toStdString();
  grab(page, QStringLiteral("models-one-not-fitted.png"));
}

// The Modular tab identifies one module again. A two-drive plant written out here (independent of the
// simulator, as in the core's module test): the Z and C drive nodes are first-order lags of their drives
// (tau 20 and 15 min), the ram grows -5 um/K dTz + kc dTc plus 0.1 um noise. The Z and C tests were
// recorded with kc = -3; then the C drive changed (kc = -4): the combined test and a new C test are of
// the changed machine. The modules identified on the old tests predict the combined test poorly;
// "Identify again" of C on the new C test re-fits C alone: Z's model stays bit for bit, the combined
// RMSE falls below 0.15 um (the noise and the estimation error, the core test's bound). The choice is
// the project setting studies.thermal.modules.thermal_modular_c.dataset, undone in one step. "Save
// module models" writes the files `thermal modular --save-modules` writes for the same modules.
namespace plant {

/// time_min,Tz,Tc,disp_z_um with drives z, c in [0, 1] for the first 120 of 240 min.
std::string test(double z, double c, double kc, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.1);
  std::string csv = "time_min,Tz,Tc,disp_z_um\n";
  double tz = 20.0, tc = 20.0;
  for (int k = 0; k <= 240; ++k) {
    char line[128];
    std::snprintf(line, sizeof line, "%d,%.6f,%.6f,%.6f\n", k, tz, tc,
                  -5.0 * (tz - 20.0) + kc * (tc - 20.0) + noise(rng));
    csv += line;
    const double uz = k < 120 ? 8.0 * z : 0.0, uc = k < 120 ? 6.0 * c : 0.0;
    tz = 20.0 + uz + (tz - 20.0 - uz) * std::exp(-1.0 / 20.0);
    tc = 20.0 + uc + (tc - 20.0 - uc) * std::exp(-1.0 / 15.0);
  }
  return csv;
}

}  // namespace plant

TEST_F(ThermalPageModelsTest, IdentifyOneModuleAgainKeepsTheOtherAndIsUndoable) {
  test::writeText(tmp_.file("z.csv"), plant::test(1, 0, -3.0, 1));
  test::writeText(tmp_.file("c.csv"), plant::test(0, 1, -3.0, 2));
  test::writeText(tmp_.file("combined.csv"), plant::test(0.5, 0.5, -4.0, 5));
  test::writeText(tmp_.file("c_new.csv"), plant::test(0, 1, -4.0, 4));
  Project p;
  p.name = "two drives";
  p.datasets.push_back({kModularZId, "thermal_log", "z.csv", "", "", {}});
  p.datasets.push_back({kModularCId, "thermal_log", "c.csv", "", "", {}});
  p.datasets.push_back({kModularCombinedId, "thermal_log", "combined.csv", "", "", {}});
  p.datasets.push_back({"c_after_bearings", "thermal_log", "c_new.csv", "", "", {}});
  saveProject(p, tmp_.file("p.metrofit"));
  document_.load(QString::fromStdString(tmp_.file("p.metrofit")));
  ThermalPage page(&document_);
  page.selectDataset(QString::fromLatin1(kModularCombinedId));
  page.showView(QStringLiteral("models"));
  ThermalModelView* view = page.modelView();
  ASSERT_TRUE(QTest::qWaitFor([&] { return page.modularComparison() != nullptr; }, 120000));
  const ModularComparison before = *page.modularComparison();
  ASSERT_TRUE(before.modules.evaluation.has_value()) << before.modules.why;
  ASSERT_EQ(before.modules.inputs, (std::vector<std::vector<std::string>>{{"Tz"}, {"Tc"}}));
  EXPECT_GT(before.modules.evaluation->test.rmse, 1.0);  // the C module of the old machine
  const QTableWidget* modules = view->modulesTable();
  ASSERT_EQ(modules->rowCount(), 2);
  EXPECT_EQ(modules->item(1, 1)->text(), QString::fromLatin1(kModularCId));
  EXPECT_EQ(modules->item(1, 2)->text(), QStringLiteral("Tc"));
  auto* again = modules->cellWidget(1, 4);
  ASSERT_NE(again, nullptr);
  EXPECT_TRUE(again->isEnabled());
  const int undoCount = document_.undoStack()->count();

  // Identify C again on the new C test: the row's "Identify again…" asks for the test (the project's
  // thermal logs but the combined test), then runs on the page's background run.
  QStringList offered;
  const auto chooseNewCTest = [&offered] {
    QTimer::singleShot(0, [&offered] {
      for (QWidget* w : QApplication::topLevelWidgets()) {
        if (auto* dialog = qobject_cast<QInputDialog*>(w); dialog && dialog->isVisible()) {
          offered = dialog->comboBoxItems();
          dialog->setTextValue(QStringLiteral("c_after_bearings"));
          dialog->accept();
        }
      }
    });
  };
  // First cancelled: while it runs, Cancel and the progress bar are there and the actions are not;
  // after Cancel the modules shown and the project are unchanged.
  chooseNewCTest();
  qobject_cast<QPushButton*>(again)->click();
  ASSERT_TRUE(page.modularRun()->isRunning());
  EXPECT_TRUE(view->modulesCancelButton()->isEnabled());
  EXPECT_FALSE(view->modulesProgressBar()->isHidden());
  EXPECT_FALSE(view->saveModulesButton()->isEnabled());
  EXPECT_FALSE(again->isEnabled());
  view->modulesCancelButton()->click();
  ASSERT_TRUE(QTest::qWaitFor([&] { return !page.modularRun()->isRunning(); }, 60000));
  EXPECT_EQ(page.modularComparison()->modules.tests, before.modules.tests);
  EXPECT_EQ(document_.undoStack()->count(), undoCount);
  EXPECT_TRUE(view->modulesMessage().startsWith(QStringLiteral("Cancelled")))
      << view->modulesMessage().toStdString();
  EXPECT_TRUE(again->isEnabled());
  EXPECT_TRUE(view->modulesProgressBar()->isHidden());
  // Then to the end.
  chooseNewCTest();
  qobject_cast<QPushButton*>(again)->click();
  EXPECT_EQ(offered, (QStringList{QString::fromLatin1(kModularZId), QString::fromLatin1(kModularCId),
                                  QStringLiteral("c_after_bearings")}));
  ASSERT_TRUE(QTest::qWaitFor(
      [&] {
        return !page.modularRun()->isRunning() &&
               page.modularComparison()->modules.tests.back() != kModularCId;
      },
      60000))
      << view->modulesMessage().toStdString();
  const ModularComparison* after = page.modularComparison();
  ASSERT_NE(after, nullptr);
  ASSERT_TRUE(after->modules.evaluation.has_value()) << view->modulesMessage().toStdString();
  EXPECT_EQ(after->modules.tests, (std::vector<std::string>{kModularZId, "c_after_bearings"}));
  // Z's model bit for bit (the same JSON: every coefficient the same double), C's a new one.
  EXPECT_EQ(thermal::thermalModelToJson(after->modules.fitted[0].training.model),
            thermal::thermalModelToJson(before.modules.fitted[0].training.model));
  EXPECT_EQ(after->modules.evaluation->contributions[0], before.modules.evaluation->contributions[0]);
  EXPECT_NE(thermal::thermalModelToJson(after->modules.fitted[1].training.model),
            thermal::thermalModelToJson(before.modules.fitted[1].training.model));
  EXPECT_LT(after->modules.evaluation->test.rmse, 0.15);
  // The pooled models are not fitted again.
  for (std::size_t i = 0; i < kThermalModelCount; ++i)
    EXPECT_EQ(thermal::thermalModelToJson(after->models[i].training.model),
              thermal::thermalModelToJson(before.models[i].training.model))
        << i;
  EXPECT_EQ(modules->item(1, 1)->text(), QStringLiteral("c_after_bearings"));
  // One undoable project setting.
  EXPECT_EQ(document_.project().studies["thermal"]["modules"],
            (nlohmann::json{{kModularCId, {{"dataset", "c_after_bearings"}}}}));
  EXPECT_EQ(document_.undoStack()->count(), undoCount + 1);
  EXPECT_EQ(document_.undoStack()->undoText(),
            QStringLiteral("Identify module thermal_modular_c again on c_after_bearings"));

  // Save module models: the files `metrofit-cli thermal modular --save-modules` writes for the same
  // modules (the core's function on the same data, and the CLI itself).
  const std::filesystem::path guiDir = tmp_.path() / "gui-modules";
  std::filesystem::create_directories(guiDir);
  ASSERT_TRUE(page.saveModuleModels(QString::fromStdString(guiDir.string())))
      << view->modulesMessage().toStdString();
  thermal::ThermalFitOptions o;
  o.model = thermal::ThermalModelKind::DistributedLag;
  o.setSeed(1);
  const ThermalLog zLog = readThermalLog(tmp_.file("z.csv")), cLog = readThermalLog(tmp_.file("c_new.csv"));
  const std::filesystem::path coreDir = tmp_.path() / "core-modules";
  std::filesystem::create_directories(coreDir);
  thermal::saveThermalModules(
      {thermal::fitThermalModule(kModularZId, thermal::selectThermalSeries(zLog, "disp_z_um", {"Tz"}), o),
       thermal::fitThermalModule(kModularCId, thermal::selectThermalSeries(cLog, "disp_z_um", {"Tc"}), o)},
      coreDir.string());
  std::filesystem::create_directories(tmp_.path() / "cli-modules");
  const test::CliRun r =
      test::cli(std::string("thermal modular --module ") + kModularZId + ":z.csv:Tz --module " + kModularCId +
                    ":c_new.csv:Tc --test combined.csv --target disp_z_um --model dlag "
                    "--seed 1 --save-modules cli-modules --out modular.json",
                tmp_);
  for (const char* name : {kModularZId, kModularCId}) {
    const std::string file = std::string(name) + ".json";
    const std::string gui = test::readText((guiDir / file).string());
    ASSERT_FALSE(gui.empty()) << file;
    EXPECT_EQ(gui, test::readText((coreDir / file).string())) << file;
    if (r.code == 0) {
      EXPECT_EQ(gui, test::readText((tmp_.path() / "cli-modules" / file).string())) << file;
    }
  }
  EXPECT_EQ(r.code, 0) << r.err;
  if (r.code == 0) {
    const nlohmann::json j = nlohmann::json::parse(test::readText(tmp_.file("modular.json")));
    EXPECT_NEAR(j["RMSE"].get<double>(), after->modules.evaluation->test.rmse, 1e-12);
  }
  if (auto* tabs = view->findChild<QTabWidget*>(QStringLiteral("thermalModelResultTabs")))
    tabs->setCurrentIndex(1);
  grab(page, QStringLiteral("modular-identify-again.png"));

  // Undo: C is identified on its first test again (the same model as before), Z untouched.
  document_.undoStack()->undo();
  ASSERT_TRUE(QTest::qWaitFor([&] { return !page.modularRun()->isRunning(); }, 60000));
  const ModularComparison* undone = page.modularComparison();
  ASSERT_NE(undone, nullptr);
  EXPECT_FALSE(document_.project().studies.contains("thermal") &&
               document_.project().studies["thermal"].contains("modules"));
  EXPECT_EQ(undone->modules.tests, (std::vector<std::string>{kModularZId, kModularCId}));
  EXPECT_EQ(thermal::thermalModelToJson(undone->modules.fitted[0].training.model),
            thermal::thermalModelToJson(before.modules.fitted[0].training.model));
  EXPECT_EQ(thermal::thermalModelToJson(undone->modules.fitted[1].training.model),
            thermal::thermalModelToJson(before.modules.fitted[1].training.model));
  EXPECT_EQ(undone->modules.evaluation->test.rmse, before.modules.evaluation->test.rmse);
  // Redo brings the new C test back.
  document_.undoStack()->redo();
  ASSERT_TRUE(QTest::qWaitFor([&] { return !page.modularRun()->isRunning(); }, 60000));
  EXPECT_EQ(page.modularComparison()->modules.tests,
            (std::vector<std::string>{kModularZId, "c_after_bearings"}));
  EXPECT_LT(page.modularComparison()->modules.evaluation->test.rmse, 0.15);
}

// Export compensation…: the trained models a control can run are offered (the best first), then the forms
// the chosen one can take; the file written is thermal::exportControl's text of that model.
TEST_F(ThermalPageModelsTest, ExportCompensationWritesTheChosenModelInTheChosenForm) {
  makeProject(480.0);
  ThermalPage page(&document_);
  page.showView(QStringLiteral("models"));
  const ThermalComparison* c = page.modelView()->comparison();
  ASSERT_NE(c, nullptr) << page.modelView()->statusText().toStdString();
  auto* button = page.findChild<QPushButton*>(QStringLiteral("thermalExportCompensation"));
  ASSERT_NE(button, nullptr);
  const QString path = QString::fromStdString(tmp_.file("lag.st"));
  QStringList models, forms;
  int step = 0;
  QTimer driver;
  driver.setInterval(10);
  QObject::connect(&driver, &QTimer::timeout, [&] {
    QWidget* w = QApplication::activeModalWidget();
    if (auto* d = qobject_cast<QInputDialog*>(w); d && d->isVisible()) {
      if (step == 0) {
        models = d->comboBoxItems();
        for (const QString& m : models)
          if (m.startsWith(QStringLiteral("lag "))) d->setTextValue(m);
      } else {
        forms = d->comboBoxItems();
        d->setTextValue(QStringLiteral("st"));
      }
      ++step;
      d->accept();
    } else if (auto* f = qobject_cast<QFileDialog*>(w); f && f->isVisible()) {
      f->selectFile(path);
      static_cast<QDialog*>(f)->accept();  // QFileDialog::accept is protected; the dialog checks the name
      ++step;
    }
  });
  driver.start();
  button->click();
  driver.stop();
  EXPECT_EQ(step, 3);
  EXPECT_EQ(models.size(), 6) << models.join(QStringLiteral(", ")).toStdString();  // every model fitted
  EXPECT_EQ(forms, (QStringList{"st", "siemens", "heidenhain", "isg", "csv"}));
  thermal::ControlExportOptions o;
  o.source = "gen";
  const thermal::ThermalModel& lag = c->models[4].training.model;
  ASSERT_EQ(lag.kind, thermal::ThermalModelKind::Lag);
  EXPECT_EQ(test::readText(path.toStdString()), thermal::exportControl(lag, thermal::ControlFormat::St, o));
}

}  // namespace
}  // namespace metrofit
