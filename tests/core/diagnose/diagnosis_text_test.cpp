// The texts of the closed loop in two forms (core/common/text.h, core/diagnose/diagnosis.h): the
// English strings of docs/file-formats.md stay exactly as they were, and each equals the English form of the
// phrases recorded next to it (evidence, notes, residual-plot axis titles, acceptance reasons), which
// is what the GUI translates. Also the phrase formatting itself and the shared progress / cancel
// helper (LoopProgress) of the four loops.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/common/text.h"
#include "core/diagnose/kinematic_diagnosis.h"
#include "core/diagnose/linear_evidence.h"
#include "core/diagnose/matching_diagnosis.h"
#include "core/diagnose/setup_diagnosis.h"
#include "core/diagnose/thermal_diagnosis.h"
#include "core/kinematics/measured_path.h"
#include "core/matching/hole_table.h"
#include "core/setup/model.h"
#include "core/setup/report.h"
#include "core/thermal/thermal_log.h"
#include "testsupport.h"

namespace metrofit::diagnose {
namespace {

using A = PhraseArg;

std::string demo(const std::string& name) {
  return (test::sourceDir() / "resources/demo" / name).string();
}

Diagnosis thermalDemo(Observer* observer = nullptr) {
  ThermalDiagnosisOptions o;
  o.target = "disp_z_um";
  o.inputs = {"T2", "T4", "T_amb"};
  return diagnoseThermal(readThermalLog(demo("data/diagnose_thermal.csv")), o, observer);
}

Diagnosis kinematicDemo(Observer* observer = nullptr) {
  return diagnoseKinematic(readMeasuredPath(demo("data/diagnose_circular.csv")), {}, observer);
}

Diagnosis setupDemo(Observer* observer = nullptr) {
  const setup::Model model = setup::readModel(demo("setup/paper_example.json"));
  return diagnoseSetup(model, setup::readMeasurements({demo("data/diagnose_setup_report.csv")}, model), {},
                       observer);
}

Diagnosis matchingDemo(Observer* observer = nullptr) {
  MatchingDiagnosisOptions o;
  o.toleranceMm = 0.035;
  return diagnoseMatching(readProbePointsAnyFormat(demo("data/diagnose_probe.csv")), o, observer);
}

/// Every text of `d` equals the English form of its phrases; every candidate has phrases.
void expectPhrasesMatchStrings(const Diagnosis& d) {
  ASSERT_EQ(d.notes.size(), d.notesParts.size()) << d.domain;
  for (std::size_t i = 0; i < d.notes.size(); ++i) {
    EXPECT_FALSE(d.notesParts[i].empty()) << d.domain;
    EXPECT_EQ(d.notes[i], english(d.notesParts[i])) << d.domain;
  }
  for (const Candidate& c : d.effects) {
    EXPECT_FALSE(c.evidenceParts.empty()) << d.domain << " " << c.name;
    EXPECT_EQ(c.evidence, english(c.evidenceParts)) << d.domain << " " << c.name;
    if (c.plot) {
      EXPECT_FALSE(c.plot->xLabelParts.empty()) << c.name;
      EXPECT_EQ(c.plot->xLabel, english(c.plot->xLabelParts)) << c.name;
      EXPECT_EQ(c.plot->yLabel, english(c.plot->yLabelParts)) << c.name;
    }
  }
}

const Candidate* find(const Diagnosis& d, const std::string& name) {
  for (const Candidate& c : d.effects)
    if (c.name == name) return &c;
  return nullptr;
}

TEST(PhraseTest, FormatsNumbersLikePrintfInTheCLocale) {
  EXPECT_EQ(A::number(0.0123456, 3).english(), "0.0123");
  EXPECT_EQ(A::number(1000.0, 3).english(), "1e+03");
  EXPECT_EQ(A::number(2.5).english(), "2.5");
  EXPECT_EQ(A::fixed(-2.04, 1).english(), "-2.0");
  EXPECT_EQ(A::fixed(0.123456, 5).english(), "0.12346");
  EXPECT_EQ(A::integer(42).english(), "42");
  EXPECT_EQ(A::signedNumber(5.234, 2).english(), "+5.2");
  EXPECT_EQ(A::signedNumber(-90.2, 2).english(), "-90");
  EXPECT_EQ(A::numberOrNa(std::numeric_limits<double>::quiet_NaN()).english(), "n/a");
  EXPECT_EQ(A::numberOrNa(std::numeric_limits<double>::infinity()).english(), "n/a");
  EXPECT_EQ(A::number(std::numeric_limits<double>::infinity()).english(), "inf");
  EXPECT_EQ(A::name("lag:T2").english(), "lag:T2");
  EXPECT_EQ(A::unit(" um").english(), " um");
  EXPECT_EQ(A::text({Phrase("a %1", {A::integer(1)}), Phrase(", b")}).english(), "a 1, b");
}

TEST(PhraseTest, SubstitutesPlaceholdersInOnePass) {
  EXPECT_EQ(substitutePlaceholders("%1 %", {"5"}), "5 %");
  EXPECT_EQ(substitutePlaceholders("(-%1 %, below %2 %)", {"3.0", "2.0"}), "(-3.0 %, below 2.0 %)");
  EXPECT_EQ(substitutePlaceholders("%2%1", {"a", "b"}), "ba");
  EXPECT_EQ(substitutePlaceholders("%1 and %3", {"a", "b"}), "a and %3");  // beyond the arguments
  EXPECT_EQ(substitutePlaceholders("%1 %2", {"%2", "x"}), "%2 x");         // never scanned again
  EXPECT_EQ(substitutePlaceholders("%10|%1", {"1", "2", "3", "4", "5", "6", "7", "8", "9", "ten"}), "ten|1");
  EXPECT_EQ(substitutePlaceholders("100%", {}), "100%");
  const Phrase p("held-out rmse %1 -> %2%3 (%4)", {A::number(2.94, 3), A::number(0.291, 3), A::unit(" um"),
                                                   A::text({Phrase("%1 %", {A::signedNumber(-90.1, 2)})})});
  EXPECT_EQ(p.english(), "held-out rmse 2.94 -> 0.291 um (-90 %)");
  std::vector<std::string> formats;
  collectFormats({p}, formats);
  EXPECT_EQ(formats, (std::vector<std::string>{"held-out rmse %1 -> %2%3 (%4)", "%1 %"}));
}

// The English evidence of the demo data, exactly as the CLI wrote it before the texts had phrases.
TEST(DiagnosisTextTest, ThermalEnglishUnchangedAndEqualToItsPhrases) {
  const Diagnosis d = thermalDemo();
  expectPhrasesMatchStrings(d);
  const Candidate* c = find(d, "lag:T2");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(
      c->evidence,
      "accepted: validation rmse 4.08 -> 0.262 um (-94 %), fit rmse 1.64 -> 0.262 um, held-out rmse 2.94 -> "
      "0.291 um, tau 15.5 +- 0.2 min");
  EXPECT_EQ(c->evidenceParts.front().format, "accepted: ");
  EXPECT_EQ(c->plot->xLabel, "time (min)");
  EXPECT_EQ(c->plot->yLabel, "residual (um)");
  ASSERT_EQ(d.notes.size(), 3u);
  EXPECT_EQ(d.notesParts[0].front().format, "declared model (static, fitted on the first %1 of %2 rows): %3");
}

TEST(DiagnosisTextTest, KinematicEnglishUnchangedAndEqualToItsPhrases) {
  const Diagnosis d = kinematicDemo();
  expectPhrasesMatchStrings(d);
  const Candidate* c = find(d, "backlash");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(
      c->evidence,
      "accepted: rmse 4.79 -> 0.707 um (-85 %), dBIC -5498, backlash x 8.03 +- 0.037 um, y 5.04 +- 0.037 um");
  EXPECT_EQ(c->plot->xLabel, "path angle (deg)");
}

TEST(DiagnosisTextTest, SetupEnglishUnchangedAndEqualToItsPhrases) {
  const Diagnosis d = setupDemo();
  expectPhrasesMatchStrings(d);
  const Candidate* c = find(d, "tool_wear:T23");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(
      c->evidence,
      "0.0021 +- 0.00011 mm/part (t = 19.4); dBIC = -245.4 < -10, rmse 0.00836 -> 0.005694 mm (-31.9 %)");
  EXPECT_EQ(c->plot->yLabel, "apparent error of T23 (mm)");
}

TEST(DiagnosisTextTest, MatchingEnglishUnchangedAndEqualToItsPhrases) {
  const Diagnosis d = matchingDemo();
  expectPhrasesMatchStrings(d);
  const Candidate* c = find(d, "distortion");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(
      c->evidence,
      "ppm = 19.57 +- 27, angle_deg = 89.54 +- 58; dBIC = 6.8 not below -10, rmse 0.005221 -> 0.005176 mm "
      "(-0.9 %)");
}

TEST(DiagnosisTextTest, AcceptanceReasonEqualsItsPhraseInEveryCase) {
  AcceptanceOptions o;
  o.minRelativeReduction = 0.5;
  // strong but not relevant (relative), strong and relevant, weak.
  for (const auto& [before, after] : {std::pair{1.0, 0.6}, std::pair{1.0, 0.01}, std::pair{1.0, 0.999}}) {
    const AcceptanceDecision dec = decideAcceptance(o, before, after, 400, 394, 1, "mm");
    ASSERT_EQ(dec.reasonParts.size(), 1u);
    EXPECT_EQ(dec.reason, english(dec.reasonParts));
  }
  EXPECT_EQ(decideAcceptance(o, 1.0, 0.6, 400, 394, 1, "mm").reason,
            "dBIC = -195.3 < -10, rmse 0.05 -> 0.03873 mm (-22.5 %, below the relevant 50.0 %)");
  AcceptanceOptions absolute;
  absolute.minAbsoluteReduction = 1.0;
  EXPECT_EQ(decideAcceptance(absolute, 1.0, 0.6, 400, 394, 1, "mm").reason,
            "dBIC = -195.3 < -10, rmse 0.05 -> 0.03873 mm (-22.5 %, below the relevant 1 mm)");
}

TEST(DiagnosisTextTest, StopNotesComeFromTheSharedProgressHelper) {
  CancelToken cancel;
  cancel.cancel();
  const Diagnosis t = thermalDemo(&cancel);
  ASSERT_FALSE(t.notes.empty());
  EXPECT_EQ(t.notes.back(), "cancelled");
  expectPhrasesMatchStrings(t);
  const Diagnosis k = kinematicDemo(&cancel);
  EXPECT_EQ(k.notes.back(), "cancelled");
  // Setup and matching report per round; the demo accepts an effect in round 0, so a stop there
  // ends the loop with the note naming the round.
  const Diagnosis s = setupDemo(&cancel);
  EXPECT_EQ(s.notes.back(), "stopped by the observer after round 0");
  EXPECT_EQ(s.notesParts.back().front().format, "stopped by the observer after round %1");
  const Diagnosis m = matchingDemo(&cancel);
  EXPECT_EQ(m.notes.back(), "stopped by the observer after round 0");
  // The observer sees the same summaries as before: per candidate with progress (thermal), per
  // round without (setup).
  std::vector<IterationSummary> seen;
  FunctionObserver record([&](const IterationSummary& s) {
    seen.push_back(s);
    return ObserverDecision::Continue;
  });
  (void)kinematicDemo(&record);
  ASSERT_GE(seen.size(), 4u);
  EXPECT_EQ(seen[0].iteration, 0);
  EXPECT_EQ(seen[0].evaluations, 1);
  // The last candidate of round 0 (four named ones and the generic effects of the residual's
  // structures) completes the round.
  std::size_t lastOfRound0 = 0;
  for (std::size_t i = 0; i < seen.size(); ++i)
    if (seen[i].components.at(0).value == 0.0) lastOfRound0 = i;
  EXPECT_GE(lastOfRound0, 3u);
  EXPECT_DOUBLE_EQ(seen[lastOfRound0].progress, 1.0);
  EXPECT_EQ(seen[0].components.at(1).name, "rmse_mm");
  seen.clear();
  (void)setupDemo(&record);
  ASSERT_EQ(seen.size(), 2u);  // round 0 accepts T23, round 1 nothing
  EXPECT_EQ(seen[1].iteration, 1);
  EXPECT_DOUBLE_EQ(seen[1].progress, -1.0);
  EXPECT_EQ(seen[1].components.at(1).name, "accepted");
  EXPECT_DOUBLE_EQ(seen[1].components.at(1).value, 1.0);
}

}  // namespace
}  // namespace metrofit::diagnose
