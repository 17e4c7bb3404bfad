// Apply on the diagnosis page reaches the setup-correction and matching pages: on the demo
// project with the studies pointed at the data with one undeclared effect, the page's error without
// the applied effect (E0), with it after Apply (E1, near the diagnosis's "after" figure, the info
// line names the effect) and after Undo (E0 again, exactly); a bad entry shows the field. Offscreen.
#include <gtest/gtest.h>

#include <QDir>
#include <QPushButton>
#include <QTemporaryDir>
#include <QUndoStack>
#include <cmath>

#include "app/gui/diagnosispage.h"
#include "app/gui/matchingpage.h"
#include "app/gui/setuppage.h"
#include "core/project/project.h"
#include "core/setup/objective.h"
#include "core/study/diagnosis_study.h"
#include "demo_document_fixture.h"
#include "qtapp.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"

namespace metrofit {
namespace {

double normalRms(const matching::ToleranceEvaluation& e) {
  double ss = 0.0;
  for (double v : e.deviations) ss += v * v;
  return std::sqrt(ss / static_cast<double>(e.deviations.size()));
}

class AppliedEffectsTest : public test::DemoDocumentTest {
 protected:
  // The setup and matching studies on the diagnosis data (tool T23 wearing; the part probed warm).
  bool editDemo(Project& p) override {
    p.studies["setup"]["dataset"] = "diagnose_setup_report";
    p.studies["matching"]["dataset"] = "diagnose_probe";
    return true;
  }

  static void grab(QWidget& page, const QString& name) {
    DemoDocumentTest::grab(page, QStringLiteral("appliedeffects"), name, QSize(1200, 760));
  }
};

TEST_F(AppliedEffectsTest, SetupPageUsesTheAppliedToolWearAndUndoRestoresTheDeclaredModel) {
  SetupPage setup(&document_);
  ASSERT_TRUE(setup.errorMessage().isEmpty()) << setup.errorMessage().toStdString();
  ASSERT_TRUE(setup.prediction().has_value());
  const double e0 = setup.prediction()->rmseMm;
  EXPECT_NEAR(e0, 0.00829, 0.0002);
  EXPECT_TRUE(setup.appliedEffects().empty());
  EXPECT_FALSE(setup.infoText().contains(QStringLiteral("Includes applied effects")));
  ASSERT_NE(setup.instance(), nullptr);
  const std::vector<double> before = [&] {
    std::vector<double> v;
    for (std::size_t q = 0; q < setup.instance()->dimensions(); ++q)
      v.push_back(setup.instance()->deviation(q));
    return v;
  }();
  ASSERT_TRUE(setup.runSynchronously(QStringLiteral("exact"), 0, 0));

  DiagnosisPage diagnosis(&document_);
  diagnosis.setDomain(DiagnosisDomain::Setup);
  ASSERT_TRUE(diagnosis.runNow()) << diagnosis.statusText().toStdString();
  const double after = diagnosis.result()->final.rmse;
  ASSERT_TRUE(diagnosis.applyAccepted());

  // The setup page follows: the deviations are those predicted for part 13.
  ASSERT_EQ(setup.appliedEffects().size(), 1u);
  EXPECT_EQ(setup.appliedEffects()[0].name, "tool_wear:T23");
  EXPECT_TRUE(
      setup.infoText().contains(QStringLiteral("Includes applied effects: tool_wear:T23 (0.002098 mm/part)")))
      << setup.infoText().toStdString();
  EXPECT_TRUE(setup.infoText().contains(QStringLiteral("predicted for part 13")))
      << setup.infoText().toStdString();
  const double e1 = setup.prediction()->rmseMm;
  EXPECT_NEAR(e1, 0.00559, 0.0002);
  EXPECT_LT(e1, 0.75 * e0);
  EXPECT_NEAR(e1, after, 0.0005);
  ASSERT_NE(setup.instance(), nullptr);
  double changed = 0.0;
  for (std::size_t q = 0; q < before.size(); ++q)
    changed = std::max(changed, std::abs(setup.instance()->deviation(q) - before[q]));
  EXPECT_NEAR(changed, 2 * 0.002098 * 6.5, 0.0005);  // dimensions with gain 2 on T23
  EXPECT_TRUE(setup.runButton()->isEnabled());
  ASSERT_TRUE(setup.runSynchronously(QStringLiteral("exact"), 0, 0));
  grab(setup, QStringLiteral("setup-applied"));

  // The study on another report: the effects were estimated on diagnose_setup_report, so this one
  // keeps the declared model (E0 of its own rows) and the info line says where they belong.
  document_.setStudyValue(QStringLiteral("setup"), QStringLiteral("/dataset"), "setup_report",
                          QStringLiteral("other report"));
  EXPECT_TRUE(setup.errorMessage().isEmpty()) << setup.errorMessage().toStdString();
  EXPECT_TRUE(setup.appliedEffects().empty());
  EXPECT_FALSE(setup.infoText().contains(QStringLiteral("Includes applied effects")));
  EXPECT_TRUE(setup.infoText().contains(
      QStringLiteral("Effects applied on the Diagnosis page belong to the report diagnose_setup_report")))
      << setup.infoText().toStdString();
  ASSERT_TRUE(setup.prediction() && setup.declaredPrediction());
  EXPECT_DOUBLE_EQ(setup.prediction()->rmseMm, setup.declaredPrediction()->rmseMm);
  grab(setup, QStringLiteral("setup-other-report"));
  document_.undoStack()->undo();  // back to the diagnosed report: the effects again
  ASSERT_EQ(setup.appliedEffects().size(), 1u);
  EXPECT_DOUBLE_EQ(setup.prediction()->rmseMm, e1);
  EXPECT_FALSE(setup.infoText().contains(QStringLiteral("belong to the report")));

  // Undo: the declared model again, the same figures as before Apply.
  document_.undoStack()->undo();
  EXPECT_TRUE(setup.appliedEffects().empty());
  EXPECT_FALSE(setup.infoText().contains(QStringLiteral("Includes applied effects")));
  EXPECT_DOUBLE_EQ(setup.prediction()->rmseMm, e0);
  for (std::size_t q = 0; q < before.size(); ++q) EXPECT_DOUBLE_EQ(setup.instance()->deviation(q), before[q]);

  // A bad entry: the page names the field and does not run.
  document_.setStudyValue(
      QStringLiteral("diagnosis"), QStringLiteral("/setup/applied"),
      nlohmann::json::array({{{"name", "tool_wear:T99"}, {"parameters", {{"mm_per_part", 0.002}}}}}),
      QStringLiteral("bad"));
  EXPECT_TRUE(setup.errorMessage().contains(QStringLiteral("studies.diagnosis.setup.applied[0].name")))
      << setup.errorMessage().toStdString();
  EXPECT_FALSE(setup.runButton()->isEnabled());
  EXPECT_EQ(setup.instance(), nullptr);
  document_.undoStack()->undo();
  EXPECT_TRUE(setup.errorMessage().isEmpty()) << setup.errorMessage().toStdString();
  EXPECT_DOUBLE_EQ(setup.prediction()->rmseMm, e0);
}

TEST_F(AppliedEffectsTest, MatchingPageUsesTheAppliedScaleAndUndoRestoresTheDeclaredModel) {
  MatchingPage matching(&document_);
  EXPECT_EQ(matching.currentDataset(), QStringLiteral("diagnose_probe"));
  ASSERT_TRUE(matching.runNow()) << matching.errorMessage().toStdString();
  const double e0 = normalRms(matching.result()->primaryRun().after);
  EXPECT_NEAR(e0, 0.00731, 0.0003);
  EXPECT_TRUE(matching.appliedText().isEmpty());
  // The other part's points, before Apply: their declared result.
  matching.selectDataset(QStringLiteral("probe_s_piece"));
  ASSERT_EQ(matching.currentDataset(), QStringLiteral("probe_s_piece"));
  ASSERT_TRUE(matching.runNow()) << matching.errorMessage().toStdString();
  const double other0 = normalRms(matching.result()->primaryRun().after);
  matching.selectDataset(QStringLiteral("diagnose_probe"));

  DiagnosisPage diagnosis(&document_);
  diagnosis.setDomain(DiagnosisDomain::Matching);
  ASSERT_TRUE(diagnosis.runNow()) << diagnosis.statusText().toStdString();
  const double after = diagnosis.result()->final.rmse;
  ASSERT_TRUE(diagnosis.applyAccepted());

  EXPECT_FALSE(matching.result().has_value());  // the model changed: the old result is gone
  EXPECT_TRUE(
      matching.appliedText().startsWith(QStringLiteral("Includes applied effects: scale (+93.99 ppm)")))
      << matching.appliedText().toStdString();
  EXPECT_TRUE(matching.infoText().contains(matching.appliedText()));
  ASSERT_TRUE(matching.runNow()) << matching.errorMessage().toStdString();
  const double e1 = normalRms(matching.result()->primaryRun().after);
  EXPECT_NEAR(e1, 0.00533, 0.0003);
  EXPECT_LT(e1, 0.8 * e0);
  EXPECT_NEAR(e1, after, 0.0005);
  EXPECT_LT(matching.result()->primaryRun().after.overall.rmseMm, 0.006);
  grab(matching, QStringLiteral("matching-applied"));

  // The other part's points: the scale was estimated on diagnose_probe, so they keep the declared
  // rigid model (the same result as before Apply) and the info line says where it belongs.
  matching.selectDataset(QStringLiteral("probe_s_piece"));
  EXPECT_TRUE(matching.appliedText().isEmpty());
  EXPECT_TRUE(matching.infoText().contains(
      QStringLiteral("Effects applied on the Diagnosis page belong to the probe points diagnose_probe")))
      << matching.infoText().toStdString();
  ASSERT_TRUE(matching.runNow()) << matching.errorMessage().toStdString();
  EXPECT_DOUBLE_EQ(normalRms(matching.result()->primaryRun().after), other0);
  grab(matching, QStringLiteral("matching-other-points"));
  matching.selectDataset(QStringLiteral("diagnose_probe"));
  EXPECT_TRUE(matching.appliedText().startsWith(QStringLiteral("Includes applied effects: scale")));
  EXPECT_FALSE(matching.infoText().contains(QStringLiteral("belong to the probe points")));

  document_.undoStack()->undo();
  EXPECT_TRUE(matching.appliedText().isEmpty());
  ASSERT_TRUE(matching.runNow()) << matching.errorMessage().toStdString();
  EXPECT_NEAR(normalRms(matching.result()->primaryRun().after), e0, 1e-9);

  // A bad entry: the page names the field and does not run.
  document_.setStudyValue(QStringLiteral("diagnosis"), QStringLiteral("/matching/applied"),
                          nlohmann::json::array({{{"name", "scale"}, {"parameters", {{"ppm", "warm"}}}}}),
                          QStringLiteral("bad"));
  EXPECT_TRUE(matching.errorMessage().contains(
      QStringLiteral("studies.diagnosis.matching.applied[0].parameters.ppm")))
      << matching.errorMessage().toStdString();
  EXPECT_FALSE(matching.runNow());
}

}  // namespace
}  // namespace metrofit
