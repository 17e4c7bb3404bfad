// The diagnosis page (app/gui/diagnosispage.h) on the bundled demo (offscreen): the candidate table
// lists exactly the effects and accepted flags of the core loop (core/study/diagnosis_study.h
// runDiagnosis on the same settings), the worker gives the same result as the synchronous run,
// Apply writes studies.diagnosis.<domain>.applied and Undo restores the study JSON exactly, and
// missing or invalid settings show a message naming the field instead of crashing.
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QImage>
#include <QMenu>
#include <QPainter>
#include <QPushButton>
#include <QSignalSpy>
#include <QStyle>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QUndoStack>
#include <algorithm>
#include <cmath>
#include <set>

#include "app/gui/diagnosispage.h"
#include "core/project/project.h"
#include "core/study/diagnosis_study.h"
#include "core/study/study_settings.h"
#include "demo_document_fixture.h"
#include "qtapp.h"
#include "widgets/diagnose/residualplot.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"

namespace metrofit {
namespace {

constexpr int kEffectColumn = 1;
constexpr int kAcceptedColumn = 6;

class DiagnosisPageTest : public test::DemoDocumentTest {
 protected:
  /// The page's table against the core loop on the same settings.
  void expectTableMatchesCore(DiagnosisPage& page, DiagnosisDomain domain) {
    const diagnose::Diagnosis core =
        runDiagnosis(diagnosisSettings(document_.project(), project_.toStdString(), domain));
    ASSERT_TRUE(page.result().has_value());
    const QTableWidget* t = page.candidateTable();
    ASSERT_EQ(t->rowCount(), static_cast<int>(core.effects.size()));
    for (int r = 0; r < t->rowCount(); ++r) {
      const diagnose::Candidate& c = core.effects[static_cast<std::size_t>(r)];
      EXPECT_EQ(t->item(r, kEffectColumn)->text().toStdString(), c.name) << "row " << r;
      EXPECT_EQ(t->item(r, kAcceptedColumn)->data(Qt::UserRole).toBool(), c.accepted) << c.name;
      EXPECT_EQ(t->item(r, kAcceptedColumn)->text(), c.accepted ? QStringLiteral("✓") : QStringLiteral("✗"));
    }
    EXPECT_DOUBLE_EQ(page.result()->baseline.rmse, core.baseline.rmse);
    EXPECT_DOUBLE_EQ(page.result()->final.rmse, core.final.rmse);
  }

  /// Saves a grab of the page to $METROFIT_TEST_OUT/diagnosispage/<name>.png for people to look at.
  static void grab(DiagnosisPage& page, const QString& name) {
    DemoDocumentTest::grab(page, QStringLiteral("diagnosispage"), name, QSize(1100, 720));
  }
};

TEST_F(DiagnosisPageTest, SetupTableListsTheCoreLoopsEffectsAndFindsTheToolWear) {
  DiagnosisPage page(&document_);
  page.setDomain(DiagnosisDomain::Setup);
  EXPECT_TRUE(page.message().isEmpty()) << page.message().toStdString();
  ASSERT_TRUE(page.runNow()) << page.statusText().toStdString();
  expectTableMatchesCore(page, DiagnosisDomain::Setup);
  // The demo report carries one undeclared effect: tool T23 wears 0.002 mm per part.
  const auto accepted = page.result()->accepted();
  ASSERT_EQ(accepted.size(), 1u);
  EXPECT_EQ(accepted[0]->name, "tool_wear:T23");
  EXPECT_LT(page.result()->final.rmse, page.result()->baseline.rmse);
  EXPECT_TRUE(page.applyButton()->isEnabled());
  EXPECT_FALSE(page.residualPlot()->isEmpty());
  EXPECT_GT(page.residualPlot()->pointCount(), 0);
  EXPECT_EQ(page.errorBars()->categoryCount(), 2);  // rmse, max |e| (no held-out rows in setup)
  grab(page, QStringLiteral("setup"));
}

TEST_F(DiagnosisPageTest, MatchingTableListsTheCoreLoopsEffectsAndFindsTheScale) {
  DiagnosisPage page(&document_);
  page.setDomain(DiagnosisDomain::Matching);
  ASSERT_TRUE(page.runNow()) << page.statusText().toStdString();
  expectTableMatchesCore(page, DiagnosisDomain::Matching);
  const auto accepted = page.result()->accepted();
  ASSERT_EQ(accepted.size(), 1u);
  EXPECT_EQ(accepted[0]->name, "scale");  // the demo part was probed 4 K warm: +92.4 ppm
  grab(page, QStringLiteral("matching"));
}

TEST_F(DiagnosisPageTest, KinematicAndThermalTablesListTheCoreLoopsEffects) {
  DiagnosisPage page(&document_);
  page.setDomain(DiagnosisDomain::Kinematic);
  ASSERT_TRUE(page.runNow()) << page.statusText().toStdString();
  expectTableMatchesCore(page, DiagnosisDomain::Kinematic);
  EXPECT_FALSE(page.result()->accepted().empty());
  grab(page, QStringLiteral("kinematic"));
  page.setDomain(DiagnosisDomain::Thermal);
  EXPECT_FALSE(page.result().has_value());  // a new domain clears the result
  ASSERT_TRUE(page.runNow()) << page.statusText().toStdString();
  expectTableMatchesCore(page, DiagnosisDomain::Thermal);
  EXPECT_FALSE(page.result()->accepted().empty());
  EXPECT_EQ(page.errorBars()->categoryCount(), 3);  // rmse, max |e|, held-out rmse
  grab(page, QStringLiteral("thermal"));
}

// The evidence ("validation rmse 4.08 → 0.9...": cut short at 1280 x 800) wraps onto higher rows:
// every word fits its column and every row is as high as its wrapped text.
TEST_F(DiagnosisPageTest, EvidenceWrapsInsteadOfBeingCutShort) {
  DiagnosisPage page(&document_);
  page.resize(1000, 700);
  page.show();
  page.setDomain(DiagnosisDomain::Thermal);
  ASSERT_TRUE(page.runNow()) << page.statusText().toStdString();
  QTest::qWait(50);
  const QTableWidget* t = page.candidateTable();
  constexpr int kEvidence = 5;
  EXPECT_EQ(t->textElideMode(), Qt::ElideNone);
  EXPECT_TRUE(t->wordWrap());
  ASSERT_GT(t->rowCount(), 3);
  int wrapped = 0;
  for (int r = 0; r < t->rowCount(); ++r) {
    const QTableWidgetItem* item = t->item(r, kEvidence);
    ASSERT_NE(item, nullptr);
    const QFontMetrics fm(item->data(Qt::FontRole).isValid() ? item->font() : t->font());  // bold: accepted
    // The delegate's text rect: the cell less the focus-frame margin + 1 on each side.
    const int margin = 2 * (t->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, t) + 1);
    const int width = t->columnWidth(kEvidence) - margin;
    const QRect box = fm.boundingRect(QRect(0, 0, width, 10000), Qt::TextWordWrap, item->text());
    EXPECT_LE(box.height(), t->rowHeight(r)) << "row " << r << " cut short: " << item->text().toStdString();
    if (box.height() > fm.height()) ++wrapped;
  }
  EXPECT_GT(wrapped, 0);  // the thermal evidence is longer than the column: the test sees wrapping
  grab(page, QStringLiteral("thermal-evidence"));
}

TEST_F(DiagnosisPageTest, WorkerGivesTheSynchronousResult) {
  DiagnosisPage page(&document_);
  page.setDomain(DiagnosisDomain::Setup);
  QSignalSpy finished(&page, &DiagnosisPage::finished);
  page.startRun();
  ASSERT_TRUE(page.isRunning()) << page.message().toStdString();
  ASSERT_TRUE(finished.wait(120000));
  EXPECT_FALSE(page.isRunning());
  expectTableMatchesCore(page, DiagnosisDomain::Setup);
}

TEST_F(DiagnosisPageTest, CancelStopsTheWorkerAndSaysSo) {
  DiagnosisPage page(&document_);
  page.setDomain(DiagnosisDomain::Thermal);
  QSignalSpy finished(&page, &DiagnosisPage::finished);
  page.startRun();
  ASSERT_TRUE(page.isRunning()) << page.message().toStdString();
  page.cancelRun();  // the loop tries 15 candidates with a lag search each: it is still in the first
  ASSERT_TRUE(finished.wait(120000));
  EXPECT_FALSE(page.isRunning());
  ASSERT_TRUE(page.result().has_value());
  const auto& notes = page.result()->notes;
  EXPECT_NE(std::find(notes.begin(), notes.end(), "cancelled"), notes.end());
  EXPECT_TRUE(page.statusText().contains(QStringLiteral("Cancelled"))) << page.statusText().toStdString();
}

TEST_F(DiagnosisPageTest, ApplyThenUndoRestoresTheStudyJsonExactly) {
  DiagnosisPage page(&document_);
  page.setDomain(DiagnosisDomain::Setup);
  ASSERT_TRUE(page.runNow());
  const nlohmann::json before = document_.project().studies;
  const int undoCount = document_.undoStack()->count();
  ASSERT_FALSE(document_.isModified());

  ASSERT_TRUE(page.applyAccepted());
  EXPECT_TRUE(document_.isModified());
  EXPECT_EQ(document_.undoStack()->count(), undoCount + 1);
  const nlohmann::json applied = document_.project().studies["diagnosis"]["setup"]["applied"];
  ASSERT_TRUE(applied.is_array());
  ASSERT_EQ(applied.size(), 1u);
  EXPECT_EQ(applied[0]["name"], "tool_wear:T23");
  ASSERT_TRUE(applied[0]["parameters"].contains("mm_per_part"));
  EXPECT_NEAR(applied[0]["parameters"]["mm_per_part"].get<double>(), 0.002, 0.0006);
  // The other keys of the study are untouched, and the result stays on the page.
  EXPECT_EQ(document_.project().studies["diagnosis"]["setup"]["dataset"], "diagnose_setup_report");
  EXPECT_TRUE(page.result().has_value());
  EXPECT_FALSE(page.applyAccepted());  // already applied: no second edit
  EXPECT_EQ(document_.undoStack()->count(), undoCount + 1);

  document_.undoStack()->undo();
  EXPECT_EQ(document_.project().studies, before);
  EXPECT_FALSE(document_.isModified());
  document_.undoStack()->redo();
  EXPECT_EQ(document_.project().studies["diagnosis"]["setup"]["applied"], applied);

  // Saved with the project.
  const QString saved = dir_.filePath(QStringLiteral("saved.metrofit"));
  document_.saveAs(saved);
  const Project reloaded = loadProject(saved.toStdString());
  EXPECT_EQ(reloaded.studies["diagnosis"]["setup"]["applied"][0]["name"], "tool_wear:T23");
}

TEST_F(DiagnosisPageTest, MissingDatasetShowsAMessageNamingTheField) {
  Project p = document_.project();
  p.studies["diagnosis"]["thermal"]["dataset"] = "no_such_log";
  const QString path = dir_.filePath(QStringLiteral("missing.metrofit"));
  saveProject(p, path.toStdString());
  document_.load(path);
  DiagnosisPage page(&document_);
  page.setDomain(DiagnosisDomain::Thermal);
  EXPECT_TRUE(page.message().contains(QStringLiteral("no_such_log"))) << page.message().toStdString();
  EXPECT_TRUE(page.message().contains(QStringLiteral("studies.diagnosis.thermal.dataset")))
      << page.message().toStdString();
  EXPECT_FALSE(page.runNow());
  EXPECT_FALSE(page.result().has_value());
  page.showView(QStringLiteral("thermal"));  // no crash, still the message
  EXPECT_FALSE(page.message().isEmpty());
}

TEST_F(DiagnosisPageTest, NoDiagnosisStudyAndBadKeysShowMessages) {
  Project p = document_.project();
  p.studies.erase("diagnosis");
  const QString path = dir_.filePath(QStringLiteral("none.metrofit"));
  saveProject(p, path.toStdString());
  document_.load(path);
  DiagnosisPage page(&document_);
  for (DiagnosisDomain d : kDiagnosisDomains) {
    page.setDomain(d);
    // The way on, on the page: choose the data (the demo has data of every domain), no project file.
    EXPECT_TRUE(page.message().contains(QStringLiteral("choose the data to diagnose above")))
        << page.message().toStdString();
    EXPECT_FALSE(page.message().contains(QStringLiteral("project file"))) << page.message().toStdString();
  }
  page.showView(QStringLiteral("diagnosis"));
  EXPECT_FALSE(page.result().has_value());

  p.studies["diagnosis"] = {
      {"thermal", {{"dataset", "thermal_sim"}, {"target", "disp_z_um"}, {"inputs", "T1"}}}};
  saveProject(p, path.toStdString());
  document_.load(path);
  page.setDomain(DiagnosisDomain::Matching);
  page.setDomain(DiagnosisDomain::Thermal);
  EXPECT_TRUE(page.message().contains(QStringLiteral("studies.diagnosis.thermal.inputs")))
      << page.message().toStdString();
}

// One policy for a bad value (issue 27): a study value the project file holds out of range is refused on the
// page, the field named in the visible message, nothing runs; the control shows the nearest value it can
// hold but nothing is written until the user edits it, and an edit on the page corrects it.
TEST_F(DiagnosisPageTest, ABadStudyValueIsRefusedNamingTheFieldAndNothingRuns) {
  Project p = document_.project();
  p.studies["diagnosis"]["thermal"]["train_fraction"] = 2;
  p.studies["diagnosis"]["matching"]["tolerance_mm"] = -0.01;
  const QString path = dir_.filePath(QStringLiteral("bad.metrofit"));
  saveProject(p, path.toStdString());
  document_.load(path);
  DiagnosisPage page(&document_);
  page.setDomain(DiagnosisDomain::Thermal);
  EXPECT_TRUE(page.message().contains(QStringLiteral("studies.diagnosis.thermal.train_fraction")))
      << page.message().toStdString();
  EXPECT_TRUE(page.message().contains(QStringLiteral("between 0.05 and 0.95")))
      << page.message().toStdString();
  EXPECT_TRUE(page.settingsError().contains(QStringLiteral("studies.diagnosis.thermal.train_fraction")));
  EXPECT_FALSE(page.runButton()->isEnabled());
  EXPECT_FALSE(page.runNow());
  page.startRun();
  EXPECT_FALSE(page.isRunning());
  EXPECT_FALSE(page.result().has_value());
  // Nothing was substituted: the project still holds the bad value (no edit by showing it).
  EXPECT_EQ(document_.project().studies["diagnosis"]["thermal"]["train_fraction"], 2);
  EXPECT_FALSE(document_.isModified());
  page.setDomain(DiagnosisDomain::Matching);
  EXPECT_TRUE(page.message().contains(QStringLiteral("studies.diagnosis.matching.tolerance_mm")))
      << page.message().toStdString();
  EXPECT_FALSE(page.runButton()->isEnabled());
  // The other domains still run.
  page.setDomain(DiagnosisDomain::Setup);
  EXPECT_TRUE(page.message().isEmpty()) << page.message().toStdString();
  EXPECT_TRUE(page.runButton()->isEnabled());
  // Corrected on the page (one undoable edit): accepted, Run enabled; Undo brings the refusal back.
  page.setDomain(DiagnosisDomain::Thermal);
  page.trainFractionBox()->setValue(0.6);
  EXPECT_EQ(document_.project().studies["diagnosis"]["thermal"]["train_fraction"], 0.6);
  EXPECT_TRUE(page.message().isEmpty()) << page.message().toStdString();
  EXPECT_TRUE(page.settingsError().isEmpty());
  EXPECT_TRUE(page.runButton()->isEnabled());
  document_.undoStack()->undo();
  EXPECT_EQ(document_.project().studies["diagnosis"]["thermal"]["train_fraction"], 2);
  EXPECT_TRUE(page.message().contains(QStringLiteral("studies.diagnosis.thermal.train_fraction")));
  EXPECT_FALSE(page.runButton()->isEnabled());
}

// The controls edit studies.diagnosis.<domain> through the undo stack and follow undo / redo.
TEST_F(DiagnosisPageTest, ControlsWriteTheStudyAndFollowUndo) {
  DiagnosisPage page(&document_);
  const auto value = [&](const char* domain, const char* key) {
    return document_.project().studies["diagnosis"][domain].value(key, nlohmann::json());
  };
  EXPECT_EQ(page.datasetCombo(DiagnosisDomain::Thermal)->currentData().toString(),
            QStringLiteral("diagnose_thermal"));
  EXPECT_DOUBLE_EQ(page.trainFractionBox()->value(), 0.5);
  EXPECT_DOUBLE_EQ(page.toleranceBox()->value(), 0.035);
  EXPECT_DOUBLE_EQ(page.feedBox()->value(), DiagnosisDomainSettings{}.feedMmPerMin);
  EXPECT_EQ(page.setupModelCombo()->currentData().toString(), QStringLiteral("setup_model"));
  EXPECT_FALSE(document_.isModified());  // showing is not an edit
  page.setDomain(DiagnosisDomain::Kinematic);
  page.feedBox()->setValue(2500.0);
  EXPECT_EQ(value("kinematic", "feed_mm_per_min"), 2500.0);
  const int circular =
      page.datasetCombo(DiagnosisDomain::Kinematic)->findData(QStringLiteral("circular_demo"));
  ASSERT_GE(circular, 0);
  page.datasetCombo(DiagnosisDomain::Kinematic)->setCurrentIndex(circular);
  EXPECT_EQ(value("kinematic", "dataset"), "circular_demo");
  EXPECT_TRUE(page.message().isEmpty()) << page.message().toStdString();
  document_.undoStack()->undo();
  EXPECT_EQ(value("kinematic", "dataset"), "diagnose_circular");
  EXPECT_EQ(page.datasetCombo(DiagnosisDomain::Kinematic)->currentData().toString(),
            QStringLiteral("diagnose_circular"));
  document_.undoStack()->undo();
  EXPECT_TRUE(value("kinematic", "feed_mm_per_min").is_null());
  EXPECT_DOUBLE_EQ(page.feedBox()->value(), DiagnosisDomainSettings{}.feedMmPerMin);
  // Only the datasets of the domain's kind are offered.
  for (int i = 0; i < page.datasetCombo(DiagnosisDomain::Matching)->count(); ++i) {
    const DatasetRef* d = document_.project().dataset(
        page.datasetCombo(DiagnosisDomain::Matching)->itemData(i).toString().toStdString());
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->kind, "probe_points");
  }
}

// Found in the de_DE walk (2026-11-30): a project made in the GUI from an imported log had no way to its
// thermal diagnosis but the project file (target and inputs had no control). Choosing the data on the
// page declares the dataset, a target and inputs the log has (one undo step); the target and each input
// are changed on the page; the loop then runs.
TEST_F(DiagnosisPageTest, ThermalDiagnosisIsReachedFromThePageWithoutTheProjectFile) {
  Project p = document_.project();
  p.studies.erase("diagnosis");
  p.studies.erase("thermal");
  const QString path = dir_.filePath(QStringLiteral("imported.metrofit"));
  saveProject(p, path.toStdString());
  document_.load(path);
  DiagnosisPage page(&document_);
  page.setDomain(DiagnosisDomain::Thermal);
  EXPECT_TRUE(page.message().contains(QStringLiteral("choose the data"))) << page.message().toStdString();
  EXPECT_FALSE(page.thermalTargetCombo()->isEnabled());
  const auto block = [&] {
    return document_.studyValue(QStringLiteral("diagnosis"), QStringLiteral("/thermal"));
  };

  QComboBox* data = page.datasetCombo(DiagnosisDomain::Thermal);
  const int undoBefore = document_.undoStack()->index();
  data->setCurrentIndex(data->findData(QStringLiteral("diagnose_thermal")));
  EXPECT_EQ(document_.undoStack()->index(), undoBefore + 1);  // one step
  EXPECT_EQ(block()["dataset"], "diagnose_thermal");
  // The log's one displacement column (read by the test from the file's header: disp_z_um) is the target;
  // the inputs are columns of the log, not the target.
  EXPECT_EQ(block()["target"], "disp_z_um");
  ASSERT_TRUE(block()["inputs"].is_array());
  ASSERT_FALSE(block()["inputs"].empty());
  const std::set<std::string> header = {"spindle_rpm", "T1", "T2", "T3", "T4", "T_amb", "disp_z_um"};
  for (const auto& in : nlohmann::json(block()["inputs"])) {
    EXPECT_TRUE(header.count(in.get<std::string>())) << in;
    EXPECT_NE(in, "disp_z_um");
  }
  EXPECT_TRUE(page.message().isEmpty()) << page.message().toStdString();
  EXPECT_EQ(page.thermalTargetCombo()->currentData().toString(), QStringLiteral("disp_z_um"));
  EXPECT_EQ(page.thermalTargetCombo()->count(), 7);

  // The inputs menu: one checkable action per column, the study's inputs checked; a click is one step.
  QMenu* menu = page.thermalInputsButton()->menu();
  ASSERT_NE(menu, nullptr);
  ASSERT_EQ(menu->actions().size(), 7);
  QAction* ambient = nullptr;
  for (QAction* a : menu->actions())
    if (a->data().toString() == QLatin1String("T_amb")) ambient = a;
  ASSERT_NE(ambient, nullptr);
  const bool wasChecked = ambient->isChecked();
  ambient->trigger();  // toggles, then triggered()
  bool inInputs = false;
  for (const auto& in : nlohmann::json(block()["inputs"])) inInputs = inInputs || in == "T_amb";
  EXPECT_EQ(inInputs, !wasChecked);
  document_.undoStack()->undo();
  inInputs = false;
  for (const auto& in : nlohmann::json(block()["inputs"])) inInputs = inInputs || in == "T_amb";
  EXPECT_EQ(inInputs, wasChecked);

  ASSERT_TRUE(page.runNow()) << page.statusText().toStdString() << page.message().toStdString();
  ASSERT_TRUE(page.result().has_value());
  EXPECT_GT(page.candidateTable()->rowCount(), 0);

  // Undo of the choice removes dataset, target and inputs together.
  document_.undoStack()->setIndex(undoBefore);
  EXPECT_TRUE(block().is_null() || !block().contains("dataset")) << block();
  EXPECT_FALSE(block().is_object() && block().contains("target")) << block();
}

TEST_F(DiagnosisPageTest, ShowViewRunsAConfiguredDomain) {
  DiagnosisPage page(&document_);
  page.showView(QStringLiteral("diagnosis"));
  ASSERT_TRUE(page.result().has_value()) << page.statusText().toStdString();
  EXPECT_GT(page.candidateTable()->rowCount(), 0);
  EXPECT_FALSE(page.result()->accepted().empty());
}

TEST(ResidualPlotTest, VectorFieldIsDrawnWithARoundMagnification) {
  // A 2D distortion field: 0.01 mm at most over a 200 x 100 mm part.
  diagnose::ResidualPlot plot;
  for (int i = 0; i <= 10; ++i) {
    for (int j = 0; j <= 5; ++j) {
      const double x = -100.0 + 20.0 * i, y = -50.0 + 20.0 * j;
      plot.vectors.push_back({x, y, 1e-4 * x, -1e-4 * y});
    }
  }
  double longest = 0.0;
  for (const auto& v : plot.vectors) longest = std::max(longest, std::hypot(v[2], v[3]));
  const QRectF rect(0, 0, 480, 360);
  const double mag = vectorMagnification(plot, rect);
  // 1, 2 or 5 x 10^n, the largest arrow about 1/8 of the 200 mm span (at most, at least 2/5 of it).
  const double mantissa = mag / std::pow(10.0, std::floor(std::log10(mag) + 1e-9));
  EXPECT_TRUE(std::abs(mantissa - 1.0) < 1e-9 || std::abs(mantissa - 2.0) < 1e-9 ||
              std::abs(mantissa - 5.0) < 1e-9)
      << mag;
  EXPECT_LE(mag * longest, 200.0 / 8.0 + 1e-9);
  EXPECT_GT(mag * longest, 200.0 / 8.0 * 0.4);

  QImage image(480, 360, QImage::Format_RGB32);
  image.fill(Qt::white);
  {
    QPainter p(&image);
    EXPECT_DOUBLE_EQ(paintResidualVectors(p, rect, plot, QStringLiteral("distortion"), 11.0), mag);
  }
  int blue = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const QColor c = image.pixelColor(x, y);
      if (c.blue() > 150 && c.red() < 90) ++blue;
    }
  }
  EXPECT_GT(blue, 300);  // the arrows
  if (const QString out = qEnvironmentVariable("METROFIT_TEST_OUT"); !out.isEmpty()) {
    QDir().mkpath(out);
    image.save(QDir(out).filePath(QStringLiteral("diagnosis-vectors.png")));
  }

  ResidualPlotView view;
  view.setPlot(plot, QStringLiteral("distortion"));
  EXPECT_TRUE(view.showsVectorField());
  EXPECT_EQ(view.pointCount(), 0);
}

}  // namespace
}  // namespace metrofit
