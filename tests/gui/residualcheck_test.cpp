// The residual check of the closed loop (core/diagnose/residual_check.h) on the
// diagnosis page and in the report (offscreen):
//   * a hand-built diagnosis with a residual check: the verdict, the tests / structure / outlier
//     tables (values, p-value formatting, units, rejected flags), the chart's series (residual
//     points, generic fit line through the distinct x values, outliers) with their point counts,
//     the same in German numbers;
//   * generic effects in the candidate table (name, form) and Apply: the named effects are applied,
//     a generic one is not (the domains' applied-effects parsers cannot carry it yet), Apply is
//     disabled with a tooltip when only generic effects are accepted;
//   * the report: writeResidualCheck into a PDF, pdftotext finds the unexplained-structure sentence
//     in reader's words (no internal identifiers), the outlier and the generic term;
//   * the real loop on the demo data: every domain's residual check shown as core computed it, and
//     the demo report's diagnosis section says what is left unexplained.
#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QPainter>
#include <QPdfWriter>
#include <QProcess>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTranslator>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <set>

#include "app/gui/diagnosispage.h"
#include "core/diagnose/diagnosis.h"
#include "core/diagnose/kinematic_diagnosis.h"
#include "core/diagnose/matching_diagnosis.h"
#include "core/sim/circular_sim.h"
#include "core/sim/probe_sim.h"
#include "core/study/diagnosis_study.h"
#include "demo_document_fixture.h"
#include "qtapp.h"
#include "widgets/diagnose/coretexts.h"
#include "widgets/diagnose/residualchecktext.h"
#include "widgets/diagnose/residualcheckview.h"
#include "widgets/report/report.h"
#include "widgets/report/reportpainter.h"
#include "widgets/report/sections.h"

namespace metrofit {
namespace {

using diagnose::DependenceForm;
using A = PhraseArg;

/// Restores the default locale after a test.
class LocaleGuard {
 public:
  explicit LocaleGuard(const QLocale& locale) : saved_(QLocale()) { QLocale::setDefault(locale); }
  ~LocaleGuard() { QLocale::setDefault(saved_); }

 private:
  QLocale saved_;
};

constexpr int kPlotPoints = 60;     // observations in the plot
constexpr int kDistinctX = 30;      // every x value twice
constexpr double kOutlierX = 10.5;  // where the outlier sits

/// A thermal diagnosis: `lag:T2` and the generic `unexplained:T1` accepted (unless `genericOnly`:
/// then only the generic one), a residual check that still finds a smooth dependence on T1 and a
/// step in time, one outlier.
diagnose::Diagnosis fixture(bool genericOnly = false) {
  diagnose::Diagnosis d;
  d.domain = "thermal";
  d.units = "um";
  d.baseline = {8.9, 21.0, 9.4};
  d.final = {0.41, 1.3, 0.45};
  diagnose::Candidate lag;
  lag.name = "lag:T2";
  lag.accepted = !genericOnly;
  lag.parameters = {{"tau_min", 15.5, 0.2}};
  lag.rmseBefore = 8.9;
  lag.rmseAfter = 2.0;
  lag.setEvidence({Phrase("tau %1 min", {A::number(15.5, 3)})});
  d.effects.push_back(lag);
  diagnose::Candidate generic;
  generic.name = "unexplained:T1";
  generic.accepted = true;
  generic.round = 1;
  generic.parameters = {{"form", std::string("smooth"), std::nullopt},  // as the loops write it
                        {"rms", 2.1, std::nullopt},
                        {"range", 6.3, std::nullopt}};
  generic.rmseBefore = 2.0;
  generic.rmseAfter = 0.41;
  diagnose::GenericForm shape;
  shape.against = "T1";
  shape.form = DependenceForm::Smooth;
  shape.knots = {20.0, 22.0, 24.0, 26.0, 28.0};
  generic.generic = shape;
  generic.setEvidence(
      {Phrase("%1 in %2, rms %3%4, range %5%4", {A::text({Phrase("smooth")}), A::name("T1"),
                                                 A::number(2.1, 3), A::unit(" um"), A::number(6.3, 3)})});
  d.effects.push_back(generic);

  diagnose::ResidualCheck c;
  c.white = false;
  c.level = 0.01;
  c.observations = 500;
  c.outlierThreshold = 9.61;
  c.tests = {{"ljung_box", "time", "", 81.2, 3e-12, 20, true},
             {"f_test", "T1", "linear", 12.5, 0.0004, 1, true},
             {"f_test", "T1", "smooth", 40.1, 1.2e-9, 4, true},
             {"f_test", "T3", "linear", 0.8, 0.37, 1, false},
             {"f_test", "time", "step", 9.7, 0.0002, 1, true}};
  diagnose::StructureItem s1;
  s1.against = "T1";
  s1.form = DependenceForm::Smooth;
  s1.p = 1.2e-9;
  s1.share = 0.62;
  s1.shape = shape;
  diagnose::StructureItem s2;
  s2.against = "time";
  s2.form = DependenceForm::Step;
  s2.p = 0.0002;
  s2.share = 0.081;
  s2.shape.against = "time";
  s2.shape.form = DependenceForm::Step;
  s2.shape.knots = {125.0};
  c.structure = {s1, s2};
  diagnose::Outlier o;
  o.unit = 411;
  o.row = 412;
  o.residual = 8.1;
  o.robustZ = 21.3;
  c.outliers = {o};
  c.summaryParts = {Phrase("not white: still depends on "),
                    Phrase("%1 (%2, %3 % of the residual variance)",
                           {A::name("T1"), A::text({Phrase("smooth")}), A::number(62.0, 2)}),
                    Phrase(", "),
                    Phrase("%1 (%2, %3 % of the residual variance)",
                           {A::name("time"), A::text({Phrase("step")}), A::number(8.1, 2)})};
  c.summary = english(c.summaryParts);
  diagnose::ResidualCheck::Plot plot;
  plot.against = "T1";
  plot.xLabel = {Phrase("%1", {A::name("T1")})};
  for (int i = 0; i < kPlotPoints; ++i) {
    const double x = 20.0 + 0.25 * (i % kDistinctX);
    plot.x.push_back(x);
    plot.fit.push_back(0.5 * std::sin(x));
    plot.residual.push_back(0.5 * std::sin(x) + ((i * 37) % 11 - 5) * 0.02);
  }
  plot.residual[7] = std::nan("");  // a missing value is not drawn
  plot.outlierX = {kOutlierX + 10.0};
  plot.outlierResidual = {8.1};
  c.plot = plot;
  d.residualCheck = c;
  return d;
}

QString cell(const QTableWidget* t, int row, int col) {
  const QTableWidgetItem* item = t->item(row, col);
  return item ? item->text() : QStringLiteral("<none>");
}

class ResidualCheckPageTest : public test::DemoDocumentTest {
 protected:
  static void grab(QWidget& page, const QString& name) {
    QCoreApplication::processEvents();  // the chart lays out its title and series in the event loop
    DemoDocumentTest::grab(page, QStringLiteral("residualcheck"), name, QSize(1280, 760));
  }
};

TEST_F(ResidualCheckPageTest, HandBuiltCheckFillsVerdictTablesAndChart) {
  const LocaleGuard locale(QLocale::c());
  DiagnosisPage page(&document_);
  page.setDomain(DiagnosisDomain::Thermal);
  page.setResult(fixture());
  const ResidualCheckView* v = page.residualCheckView();
  ASSERT_TRUE(v->hasCheck());
  EXPECT_EQ(
      v->verdictText().toStdString(),
      "not white: still depends on T1 (smooth, 62 % of the residual variance), time (step, 8.1 % of the "
      "residual variance)");
  EXPECT_TRUE(page.statusText().contains(QStringLiteral("Residual check: not white: still depends on T1")))
      << page.statusText().toStdString();
  EXPECT_TRUE(page.resultTabs()->tabText(1).contains(QStringLiteral("structure left")));

  const QTableWidget* s = v->structureTable();
  ASSERT_EQ(s->rowCount(), 2);
  EXPECT_EQ(cell(s, 0, 0), QStringLiteral("T1"));
  EXPECT_EQ(cell(s, 0, 1), QStringLiteral("smooth"));
  EXPECT_EQ(cell(s, 0, 2), QStringLiteral("62.0"));
  EXPECT_EQ(cell(s, 0, 3), QStringLiteral("1.2e-09"));
  EXPECT_EQ(cell(s, 1, 0), QStringLiteral("time"));
  EXPECT_EQ(cell(s, 1, 1), QStringLiteral("step"));
  EXPECT_EQ(cell(s, 1, 2), QStringLiteral("8.1"));
  EXPECT_EQ(cell(s, 1, 3), QStringLiteral("2.0e-04"));

  const QTableWidget* t = v->testTable();
  ASSERT_EQ(t->rowCount(), 5);
  EXPECT_EQ(cell(t, 0, 0), QStringLiteral("Ljung-Box"));
  EXPECT_EQ(cell(t, 0, 1), QStringLiteral("time"));
  EXPECT_EQ(cell(t, 0, 2), QStringLiteral("–"));
  EXPECT_EQ(cell(t, 0, 3), QStringLiteral("81.2"));
  EXPECT_EQ(cell(t, 0, 4), QStringLiteral("20"));
  EXPECT_EQ(cell(t, 0, 5), QStringLiteral("3.0e-12"));
  EXPECT_EQ(cell(t, 0, 6), QStringLiteral("✓"));
  EXPECT_EQ(cell(t, 2, 0), QStringLiteral("F test"));
  EXPECT_EQ(cell(t, 2, 1), QStringLiteral("T1"));
  EXPECT_EQ(cell(t, 2, 2), QStringLiteral("smooth"));
  EXPECT_EQ(cell(t, 2, 5), QStringLiteral("1.2e-09"));
  EXPECT_EQ(cell(t, 3, 5), QStringLiteral("0.37"));  // >= 0.001: three significant digits
  EXPECT_EQ(cell(t, 3, 6), QStringLiteral("–"));
  EXPECT_FALSE(t->item(3, 6)->data(Qt::UserRole).toBool());
  EXPECT_EQ(t->horizontalHeaderItem(6)->text(), QStringLiteral("Rejected at 1 %"));

  const QTableWidget* o = v->outlierTable();
  ASSERT_EQ(o->rowCount(), 1);
  EXPECT_EQ(cell(o, 0, 0), QStringLiteral("412"));
  EXPECT_EQ(cell(o, 0, 1), QStringLiteral("–"));
  EXPECT_EQ(cell(o, 0, 4), QStringLiteral("8.1 µm"));
  EXPECT_EQ(cell(o, 0, 5), QStringLiteral("21.3"));
  EXPECT_EQ(o->horizontalHeaderItem(4)->text(), QStringLiteral("Residual (µm)"));

  // Chart: the residual's finite points, the fit through the distinct x values, the outlier.
  EXPECT_EQ(v->residualPointCount(), kPlotPoints - 1);
  EXPECT_EQ(v->fitPointCount(), kDistinctX);
  EXPECT_EQ(v->fitLineCount(), 1);
  EXPECT_TRUE(v->chartShown());
  EXPECT_EQ(v->outlierPointCount(), 1);
  EXPECT_EQ(v->xAxisTitle(), QStringLiteral("T1"));
  EXPECT_EQ(v->chartTitle(), QStringLiteral("Final residual against T1 with the generic fit (smooth)"));

  page.resultTabs()->setCurrentIndex(1);
  grab(page, QStringLiteral("fixture-en"));
}

TEST_F(ResidualCheckPageTest, GermanNumbersInTheCheck) {
  const LocaleGuard locale(QLocale(QLocale::German, QLocale::Germany));
  DiagnosisPage page(&document_);
  page.setDomain(DiagnosisDomain::Thermal);
  page.setResult(fixture());
  const ResidualCheckView* v = page.residualCheckView();
  EXPECT_TRUE(v->verdictText().contains(QStringLiteral("8,1 %"))) << v->verdictText().toStdString();
  EXPECT_EQ(cell(v->structureTable(), 0, 2), QStringLiteral("62,0"));
  EXPECT_EQ(cell(v->structureTable(), 0, 3), QStringLiteral("1,2E-09"));  // the German locale's exponent
  EXPECT_EQ(cell(v->testTable(), 3, 5), QStringLiteral("0,37"));
  EXPECT_EQ(cell(v->outlierTable(), 0, 4), QStringLiteral("8,1 µm"));
  EXPECT_EQ(formatPValue(0.0, QLocale(QLocale::German)), QStringLiteral("< 1E-300"));
  EXPECT_EQ(formatPValue(0.0, QLocale::c()), QStringLiteral("< 1e-300"));
}

/// Installs the built translation of `language` (metrofit_<language>.qm) while it lives.
class TranslationGuard {
 public:
  explicit TranslationGuard(const QString& language) {
    const QString qmDir = qEnvironmentVariable("METROFIT_TEST_QM_DIR", QStringLiteral(METROFIT_QM_DIR));
    loaded_ = translator_.load(QDir(qmDir).filePath(QStringLiteral("metrofit_") + language));
    if (loaded_) QCoreApplication::installTranslator(&translator_);
  }
  ~TranslationGuard() {
    if (loaded_) QCoreApplication::removeTranslator(&translator_);
  }
  bool loaded() const { return loaded_; }

 private:
  QTranslator translator_;
  bool loaded_ = false;
};

TEST_F(ResidualCheckPageTest, GermanAndPolishTranslations) {
  {
    const LocaleGuard locale(QLocale(QLocale::German, QLocale::Germany));
    const TranslationGuard german(QStringLiteral("de"));
    ASSERT_TRUE(german.loaded());
    DiagnosisPage page(&document_);
    page.setDomain(DiagnosisDomain::Thermal);
    page.setResult(fixture());
    const ResidualCheckView* v = page.residualCheckView();
    // Core's summary phrases and the form names translated, numbers German.
    EXPECT_EQ(v->verdictText().toStdString(),
              "nicht weiß: hängt noch ab von T1 (glatt, 62 % der Residuenvarianz), Zeit (Sprung, 8,1 % der "
              "Residuenvarianz)");
    EXPECT_EQ(cell(v->structureTable(), 1, 0), QStringLiteral("Zeit"));
    EXPECT_EQ(cell(v->testTable(), 2, 0), QStringLiteral("F-Test"));
    EXPECT_EQ(v->testTable()->horizontalHeaderItem(6)->text(), QStringLiteral("Abgelehnt bei 1 %"));
    EXPECT_TRUE(page.resultTabs()->tabText(1).startsWith(QStringLiteral("Residuen&prüfung")));
    page.resultTabs()->setCurrentIndex(1);
    grab(page, QStringLiteral("fixture-de"));
  }
  {
    const TranslationGuard polish(QStringLiteral("pl"));
    ASSERT_TRUE(polish.loaded());
    const QLocale pl(QLocale::Polish, QLocale::Poland);
    const QStringList s = residualCheckSentences(fixture(), pl);
    ASSERT_EQ(s.size(), 3);
    EXPECT_TRUE(
        s[0].startsWith(QStringLiteral("Co pozostaje niewyjaśnione: końcowe residuum wciąż zależy od kolumny "
                                       "T1 (gładka krzywa, 62,0 % wariancji residuum")))
        << s[0].toStdString();
    EXPECT_EQ(
        s[2].toStdString(),
        "1 pomiar wykluczony z dopasowania jako błąd gruby (odporne z powyżej 9,61): wiersz 412 (residuum "
        "8,1 µm, odporne z 21,3).");
  }
}

TEST_F(ResidualCheckPageTest, GenericEffectIsListedWithItsFormAndAppliedInThermal) {
  const LocaleGuard locale(QLocale::c());
  DiagnosisPage page(&document_);
  page.setDomain(DiagnosisDomain::Thermal);
  page.setResult(fixture());
  const QTableWidget* t = page.candidateTable();
  ASSERT_EQ(t->rowCount(), 2);
  EXPECT_EQ(cell(t, 1, 1), QStringLiteral("unexplained:T1"));
  EXPECT_TRUE(cell(t, 1, 2).startsWith(QStringLiteral("form: smooth; rms = 2.1 µm; range = 6.3 µm")))
      << cell(t, 1, 2).toStdString();
  EXPECT_TRUE(t->item(1, 6)->data(Qt::UserRole).toBool());

  // Thermal: Apply takes the named and the generic effect, the generic one with its shape (the
  // thermal study refits its basis columns).
  ASSERT_TRUE(page.applyButton()->isEnabled());
  EXPECT_FALSE(page.applyButton()->toolTip().contains(QStringLiteral("only")))
      << page.applyButton()->toolTip().toStdString();
  ASSERT_TRUE(page.applyAccepted());
  const nlohmann::json applied = document_.project().studies.at("diagnosis").at("thermal").at("applied");
  ASSERT_EQ(applied.size(), 2u) << applied.dump();
  EXPECT_EQ(applied[0].at("name"), "lag:T2");
  EXPECT_EQ(applied[1].at("name"), "unexplained:T1");
  EXPECT_EQ(applied[1].at("shape").at("form"), "smooth");
  EXPECT_EQ(applied[1].at("shape").at("knots"), nlohmann::json::parse("[20.0, 22.0, 24.0, 26.0, 28.0]"));
  EXPECT_EQ(applied[1].at("parameters").at("rms"), 2.1);

  // Setup applies a generic effect only with its coefficients and only of a variable that predicts the
  // next part (time, datum:<id>, dimension:<id>); the fixture's (against T1, no coefficients) is left
  // out, the tooltip says why, and with only a generic effect accepted nothing can be applied.
  diagnose::Diagnosis kinematic = fixture();
  kinematic.domain = "setup";
  DiagnosisPage kin(&document_);
  kin.setDomain(DiagnosisDomain::Setup);
  kin.setResult(kinematic);
  ASSERT_TRUE(kin.applyButton()->isEnabled());
  EXPECT_TRUE(kin.applyButton()->toolTip().contains(QStringLiteral("Applies lag:T2 only")))
      << kin.applyButton()->toolTip().toStdString();
  EXPECT_TRUE(kin.applyButton()->toolTip().contains(QStringLiteral("unexplained:T1")));
  diagnose::Diagnosis only = fixture(true);
  only.domain = "setup";
  DiagnosisPage other(&document_);
  other.setDomain(DiagnosisDomain::Setup);
  other.setResult(only);
  EXPECT_FALSE(other.applyButton()->isEnabled());
  EXPECT_TRUE(other.applyButton()->toolTip().startsWith(QStringLiteral("Nothing to apply.")))
      << other.applyButton()->toolTip().toStdString();
  EXPECT_FALSE(other.applyAccepted());
  EXPECT_TRUE(appliedEffects(only).empty());
  EXPECT_EQ(appliedEffects(fixture(true)).size(), 1u);
  EXPECT_TRUE(other.applyButton()->toolTip().contains(QStringLiteral("says nothing about the next part")))
      << other.applyButton()->toolTip().toStdString();
  diagnose::Diagnosis timed = fixture(true);
  timed.domain = "setup";
  for (diagnose::Candidate& c : timed.effects)
    if (c.generic) {
      c.name = "unexplained:time";
      c.generic->against = "time";
      c.genericCoefficients = {0.001, 0.002};
    }
  DiagnosisPage third(&document_);
  third.setDomain(DiagnosisDomain::Setup);
  third.setResult(timed);
  EXPECT_TRUE(third.applyButton()->isEnabled()) << third.applyButton()->toolTip().toStdString();
  ASSERT_EQ(appliedEffects(timed).size(), 1u);
  EXPECT_EQ(appliedEffects(timed)[0].at("coefficients"), nlohmann::json::parse("[0.001, 0.002]"));
}

TEST(ResidualCheckTextTest, SentencesInReadersWords) {
  const QStringList s = residualCheckSentences(fixture(), QLocale::c());
  ASSERT_EQ(s.size(), 3);
  EXPECT_EQ(
      s[0].toStdString(),
      "What is left unexplained: the final residual still depends on column T1 (a smooth curve, 62.0 % of "
      "the residual variance, p = 1.2e-09) and time (a step at 125, 8.1 % of the residual variance, p = "
      "2.0e-04). No effect of the catalogue explains this (tests at the 1 % family-wise level).");
  EXPECT_TRUE(s[1].contains(QStringLiteral("a smooth curve in column T1"))) << s[1].toStdString();
  EXPECT_EQ(s[2].toStdString(),
            "1 measurement(s) excluded from the fit as gross errors (robust z above 9.61): row 412 (residual "
            "8.1 µm, robust z 21.3).");
  // White: says so.
  diagnose::Diagnosis white = fixture();
  white.residualCheck->white = true;
  white.residualCheck->structure.clear();
  white.residualCheck->outliers.clear();
  const QStringList w = residualCheckSentences(white, QLocale::c());
  ASSERT_GE(w.size(), 1);
  EXPECT_TRUE(w[0].contains(QStringLiteral("None of the 5 test(s)"))) << w[0].toStdString();
  EXPECT_TRUE(w.back().startsWith(QStringLiteral("No measurement was excluded"))) << w.back().toStdString();
}

TEST(ResidualCheckTextTest, ACycleInTimeReadsWithItsPeriodInMinutes) {
  // Thermal: a cycle of 47 min in time, left in the residual and accepted as a generic effect.
  diagnose::Diagnosis d = fixture();
  diagnose::GenericForm cycle;
  cycle.against = "time";
  cycle.form = DependenceForm::Periodic;
  cycle.harmonics = 1;
  cycle.period = 47.0;
  d.residualCheck->structure[1].form = DependenceForm::Periodic;
  d.residualCheck->structure[1].shape = cycle;
  d.effects[1].name = "unexplained:time";
  d.effects[1].generic = cycle;
  const QStringList s = residualCheckSentences(d, QLocale::c());
  ASSERT_GE(s.size(), 2);
  EXPECT_TRUE(s[0].contains(
      QStringLiteral("time (a cycle with a period of 47.0 min, 8.1 % of the residual variance")))
      << s[0].toStdString();
  EXPECT_TRUE(s[1].contains(QStringLiteral("a cycle with a period of 47.0 min in time")))
      << s[1].toStdString();
  EXPECT_EQ(dependenceFormLabel(cycle, QLocale::c()).toStdString(), "periodic, period 47.0 min");
  EXPECT_EQ(dependenceFormLabel(d.residualCheck->structure[1], QLocale(QLocale::German)).toStdString(),
            "periodic, period 47,0 min");  // untranslated here: the German number only
  // A path angle's harmonics keep their plain name (period 360 degrees implied).
  diagnose::GenericForm angle = cycle;
  angle.against = "angle";
  angle.period = 0.0;
  EXPECT_EQ(dependenceFormLabel(angle, QLocale::c()).toStdString(), "periodic");
  EXPECT_EQ(dependenceFormWords(angle, QLocale::c()).toStdString(), "a periodic pattern");
  // Another ordered variable: the number alone (its unit is not known).
  diagnose::GenericForm rows = cycle;
  rows.against = "row";
  EXPECT_EQ(dependenceFormLabel(rows, QLocale::c()).toStdString(), "periodic, period 47.0");
}

TEST(ResidualCheckTextTest, HeldOutRowsGetTheirOwnSentences) {
  // Thermal: the held-out rows' check (a step after the fit rows, one gross error) is said apart.
  diagnose::Diagnosis d = fixture();
  diagnose::ResidualCheck h = *d.residualCheck;
  h.structure.resize(1);
  h.structure[0].against = "time";
  h.structure[0].form = diagnose::DependenceForm::Step;
  h.structure[0].shape.form = diagnose::DependenceForm::Step;
  h.structure[0].shape.knots = {384.0};
  h.structure[0].share = 0.4;
  h.structure[0].p = 1e-12;
  h.outliers.resize(1);
  h.outliers[0].row = 950;
  d.heldoutCheck = h;
  const QStringList s = residualCheckSentences(d, QLocale::c());
  ASSERT_EQ(s.size(), 5);
  EXPECT_EQ(
      s[3].toStdString(),
      "On the held-out rows, which only report the error, the residual still depends on time (a step at "
      "384, 40.0 % of the residual variance, p = 1.0e-12): the model misses something there that the "
      "fit rows did not show.");
  EXPECT_EQ(s[4].toStdString(),
            "1 held-out measurement(s) left out of the held-out error as gross errors: row 950.");
  d.heldoutCheck->white = true;
  d.heldoutCheck->structure.clear();
  d.heldoutCheck->outliers.clear();
  const QStringList w = residualCheckSentences(d, QLocale::c());
  ASSERT_EQ(w.size(), 4);
  EXPECT_TRUE(w[3].contains(QStringLiteral("looks like noise as well"))) << w[3].toStdString();
  // Accepted effects that made the held-out error worse (CAIVIAC ch5: 7.27 -> 12.3 um) are a warning.
  ASSERT_FALSE(d.accepted().empty());
  d.baseline.heldoutRmse = 7.27;
  d.final.heldoutRmse = 12.3;
  const QStringList v = residualCheckSentences(d, QLocale::c());
  ASSERT_EQ(v.size(), 5);
  EXPECT_TRUE(v[3].startsWith(QStringLiteral("Warning: the held-out error rose from 7.27 to 12.3 µm")))
      << v[3].toStdString();
}

/// Runs a program; its standard output ("" when it cannot run).
QString run(const QString& program, const QStringList& args) {
  QProcess p;
  p.start(program, args);
  if (!p.waitForFinished(120000) || p.exitCode() != 0) return {};
  return QString::fromUtf8(p.readAllStandardOutput());
}

/// pdftotext's text with line breaks and runs of spaces made single spaces.
QString pdfText(const QString& pdf) {
  return run(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")}).simplified();
}

TEST(ResidualCheckReportTest, PdfSaysWhatIsLeftUnexplainedInReadersWords) {
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  const QString pdf = dir.filePath(QStringLiteral("residual.pdf"));
  {
    QPdfWriter writer(pdf);
    writer.setResolution(300);
    writer.setPageSize(QPageSize(QPageSize::A4));
    QPainter painter(&writer);
    ReportPainter out(writer, painter, QStringLiteral("Residual check"), 1);
    writeResidualCheck(out, fixture());
  }
  if (const QString out = qEnvironmentVariable("METROFIT_TEST_OUT"); !out.isEmpty()) {  // for a look
    QDir().mkpath(QDir(out).filePath(QStringLiteral("residualcheck")));
    const QString copy = QDir(out).filePath(QStringLiteral("residualcheck/fixture-report.pdf"));
    QFile::remove(copy);
    QFile::copy(pdf, copy);
  }
  const QString text = pdfText(pdf);
  ASSERT_FALSE(text.isEmpty()) << "pdftotext gave nothing";
  EXPECT_TRUE(
      text.contains(QStringLiteral("the final residual still depends on column T1 (a smooth curve, 62.0 % "
                                   "of the residual variance")))
      << text.toStdString();
  EXPECT_TRUE(text.contains(QStringLiteral("row 412 (residual 8.1 µm, robust z 21.3)")))
      << text.toStdString();
  EXPECT_TRUE(text.contains(QStringLiteral("a generic term"))) << text.toStdString();
  // The plot's title and legend are text in the PDF.
  EXPECT_TRUE(text.contains(QStringLiteral("Final residual against T1 with the generic fit (smooth)")))
      << text.toStdString();
  EXPECT_TRUE(text.contains(QStringLiteral("excluded outliers")));
  for (const char* identifier : {"unexplained:T1", "ljung_box", "f_test", "robust_z"})
    EXPECT_FALSE(text.contains(QLatin1String(identifier))) << identifier << " in " << text.toStdString();
}

/// The chart's expected point counts for a plot (the rule of residualcheckview.h: finite points,
/// the fit through the distinct x values, at most kMaxResidualCheckChartPoints each).
struct ExpectedCounts {
  int residual = 0, fit = 0, outliers = 0;
};
ExpectedCounts expectedCounts(const diagnose::ResidualCheck::Plot& p) {
  auto capped = [](std::size_t n) {
    const std::size_t max = kMaxResidualCheckChartPoints;
    return static_cast<int>(n <= max ? n : (n + ((n + max - 1) / max) - 1) / ((n + max - 1) / max));
  };
  std::size_t residual = 0, outliers = 0;
  const std::size_t components = static_cast<std::size_t>(std::max(1, p.components));
  std::vector<std::set<double>> xs(components);  // per coordinate
  for (std::size_t i = 0; i < p.x.size(); ++i) {
    if (!std::isfinite(p.x[i])) continue;
    if (i < p.residual.size() && std::isfinite(p.residual[i])) ++residual;
    if (i < p.fit.size() && std::isfinite(p.fit[i])) xs[i % components].insert(p.x[i]);
  }
  for (std::size_t i = 0; i < p.outlierX.size() && i < p.outlierResidual.size(); ++i)
    if (std::isfinite(p.outlierX[i]) && std::isfinite(p.outlierResidual[i])) ++outliers;
  int fit = 0;
  for (const auto& x : xs) fit += capped(x.size());
  return {capped(residual), fit, capped(outliers)};
}

/// The page shows the residual check of its result as core computed it: verdict, every test, the
/// structure, the outliers, the chart's series and counts, the generic effects in the candidates.
void expectShowsCheck(const DiagnosisPage& page) {
  ASSERT_TRUE(page.result().has_value());
  ASSERT_TRUE(page.result()->residualCheck.has_value()) << "core gave no residual check";
  const diagnose::ResidualCheck& c = *page.result()->residualCheck;
  const ResidualCheckView* v = page.residualCheckView();
  ASSERT_TRUE(v->hasCheck());
  EXPECT_EQ(v->verdictText(), residualCheckVerdict(c));
  if (c.structure.empty()) {
    EXPECT_EQ(v->verdictText(), coreText(c.summaryParts, c.summary));
  }
  EXPECT_FALSE(v->verdictText().isEmpty());
  EXPECT_TRUE(page.statusText().contains(v->verdictText())) << page.statusText().toStdString();
  EXPECT_GT(c.tests.size(), 0u);
  ASSERT_EQ(v->testTable()->rowCount(), static_cast<int>(c.tests.size()));
  for (int r = 0; r < v->testTable()->rowCount(); ++r) {
    const diagnose::ResidualTest& t = c.tests[static_cast<std::size_t>(r)];
    EXPECT_EQ(cell(v->testTable(), r, 0), residualTestName(t.name));
    EXPECT_EQ(cell(v->testTable(), r, 1), residualVariableName(t.against));
    EXPECT_EQ(cell(v->testTable(), r, 5), formatPValue(t.p, QLocale::c()));
    EXPECT_EQ(v->testTable()->item(r, 6)->data(Qt::UserRole).toBool(), t.rejected);
  }
  // White exactly when no test is rejected (docs/file-formats.md#residual_check), and the structure listed as
  // core has it.
  EXPECT_EQ(c.white, std::none_of(c.tests.begin(), c.tests.end(), [](const auto& t) { return t.rejected; }));
  ASSERT_EQ(v->structureTable()->rowCount(), static_cast<int>(c.structure.size()));
  for (int r = 0; r < v->structureTable()->rowCount(); ++r) {
    const diagnose::StructureItem& s = c.structure[static_cast<std::size_t>(r)];
    EXPECT_EQ(cell(v->structureTable(), r, 0), residualVariableName(s.against));
    EXPECT_EQ(cell(v->structureTable(), r, 2), QLocale::c().toString(100.0 * s.share, 'f', 1));
  }
  EXPECT_EQ(v->outlierTable()->rowCount(), static_cast<int>(c.outliers.size()));
  if (c.plot) {
    const ExpectedCounts e = expectedCounts(*c.plot);
    EXPECT_GT(e.residual, 0);
    EXPECT_TRUE(v->chartShown());
    EXPECT_EQ(v->residualPointCount(), e.residual);
    EXPECT_EQ(v->fitPointCount(), e.fit);
    EXPECT_EQ(v->fitLineCount(), std::max(1, c.plot->components));
    EXPECT_EQ(v->outlierPointCount(), e.outliers);
  } else {
    EXPECT_EQ(v->residualPointCount(), 0);
    EXPECT_TRUE(c.structure.empty());
    // The chart is hidden; its title says why (for an export).
    EXPECT_FALSE(v->chartShown());
    EXPECT_EQ(v->chartTitle(), c.white ? QStringLiteral("The final residual is white: nothing left to plot")
                                       : QStringLiteral("No single variable explains the structure left"));
  }
  // Every generic effect is in the candidate table under its name, with its form.
  for (std::size_t i = 0; i < page.result()->effects.size(); ++i) {
    const diagnose::Candidate& e = page.result()->effects[i];
    if (!e.generic) continue;
    EXPECT_EQ(cell(page.candidateTable(), static_cast<int>(i), 1).toStdString(), e.name);
    EXPECT_TRUE(cell(page.candidateTable(), static_cast<int>(i), 2)
                    .startsWith(QStringLiteral("form: ") + dependenceFormName(e.generic->form)));
  }
}

/// The thermal loop gets its residual check in the lead's branch wt-thermal (commit 3453f47: "Work in
/// progress: thermal"); until then a thermal diagnosis without one is let through (and said so).
/// Every other domain must have it.
bool checkPending(const diagnose::Diagnosis& d) {
  if (d.residualCheck || d.domain != "thermal") return false;
  std::cout << "note: the thermal diagnosis has no residual check yet (wt-thermal not merged)\n";
  return true;
}

// The real loops on the demo data: what the page shows is the check core computed.
TEST_F(ResidualCheckPageTest, DemoLoopsShowTheirResidualCheck) {
  const LocaleGuard locale(QLocale::c());
  DiagnosisPage page(&document_);
  for (DiagnosisDomain domain : kDiagnosisDomains) {
    SCOPED_TRACE(diagnosisDomainKey(domain));
    page.setDomain(domain);
    ASSERT_TRUE(page.runNow()) << page.statusText().toStdString();
    if (checkPending(*page.result())) continue;
    expectShowsCheck(page);
    page.resultTabs()->setCurrentIndex(1);
    grab(page, QStringLiteral("demo-") + QString::fromLatin1(diagnosisDomainKey(domain)));
  }
}

// The demo project's other files through the loops (the variations diagnosis_locale_test runs):
// whatever each check finds, the page shows it; some leave structure (a plot, vector residuals).
TEST_F(ResidualCheckPageTest, OtherDemoFilesShowTheirResidualCheck) {
  const LocaleGuard locale(QLocale::c());
  auto settings = [&](DiagnosisDomain domain, const char* file) {
    DiagnosisSettings s = diagnosisSettings(document_.project(), project_.toStdString(), domain);
    s.datasetPath = QDir(dir_.path()).filePath(QStringLiteral("data/") + QLatin1String(file)).toStdString();
    return s;
  };
  std::vector<std::pair<std::string, DiagnosisSettings>> runs = {
      {"kinematic circular_demo", settings(DiagnosisDomain::Kinematic, "circular_demo.csv")},
      {"setup paper_example_report", settings(DiagnosisDomain::Setup, "paper_example_report.csv")},
  };
  for (const auto& [file, tolerance] :
       {std::pair{"probe_points_demo.csv", 0.05}, std::pair{"probe_s_piece.csv", 0.01}}) {
    DiagnosisSettings s = settings(DiagnosisDomain::Matching, file);
    s.toleranceMm = tolerance;
    runs.push_back({std::string("matching ") + file, s});
  }
  DiagnosisPage page(&document_);
  int withPlot = 0;
  for (const auto& [name, s] : runs) {
    SCOPED_TRACE(name);
    page.setDomain(s.domain);
    page.setResult(runDiagnosis(s));
    expectShowsCheck(page);
    const auto& c = page.result()->residualCheck;
    if (c && c->plot) ++withPlot;
    std::cout << name << ": " << (c ? c->summary : std::string("no check")) << " (plot components "
              << (c && c->plot ? c->plot->components : 0) << ", outliers " << (c ? c->outliers.size() : 0u)
              << ")\n";
    page.resultTabs()->setCurrentIndex(1);
    QString shot = QString::fromStdString(name);
    shot.replace(QLatin1Char(' '), QLatin1Char('-'));
    grab(page, QStringLiteral("other-") + shot);
  }
  std::cout << withPlot << " of " << runs.size() << " with a plot\n";
}

// Effects in no catalogue, added here to clean simulated data as in open_world_diagnosis_test: the
// real loops flag or explain them, and the page shows the structure (with the vector residual's
// fit lines), the generic effects and the gross error.
TEST_F(ResidualCheckPageTest, OpenWorldCasesShowTheirStructureAndOutlier) {
  const LocaleGuard locale(QLocale::c());
  DiagnosisPage page(&document_);
  auto expectFlaggedOrExplained = [&](const diagnose::Diagnosis& d) {
    const bool generic = std::any_of(d.effects.begin(), d.effects.end(),
                                     [](const diagnose::Candidate& c) { return c.accepted && c.generic; });
    EXPECT_TRUE(generic || !d.residualCheck->white) << toJson(d).dump(1);
    if (!d.residualCheck->white) {
      EXPECT_GT(page.residualCheckView()->structureTable()->rowCount(), 0);
      EXPECT_TRUE(page.resultTabs()->tabText(1).contains(QStringLiteral("structure left")));
    }
  };
  {
    SCOPED_TRACE("kinematic: thermal drift during the test, one gross point");
    CircularSimOptions o;
    o.seed = 1;
    MeasuredPath p = simulateCircularTest(o);
    const double n = static_cast<double>(p.size());
    for (std::size_t k = 0; k < p.size(); ++k) {
      p.measured[k].x() += 8.0 * o.noiseMm * k / n;
      p.measured[k].y() += 4.0 * o.noiseMm * k / n;
    }
    p.measured[100].x() += 40.0 * o.noiseMm;
    page.setDomain(DiagnosisDomain::Kinematic);
    page.setResult(diagnose::diagnoseKinematic(p, {}));
    expectShowsCheck(page);
    const diagnose::Diagnosis& d = *page.result();
    expectFlaggedOrExplained(d);
    ASSERT_EQ(d.residualCheck->outliers.size(), 1u) << toJson(d).dump(1);
    EXPECT_EQ(cell(page.residualCheckView()->outlierTable(), 0, 0), QStringLiteral("101"));
    EXPECT_TRUE(cell(page.residualCheckView()->outlierTable(), 0, 4).endsWith(QStringLiteral(" mm")));
    if (d.residualCheck->plot) {
      EXPECT_EQ(page.residualCheckView()->fitLineCount(), 2);  // x and y
    }
    page.resultTabs()->setCurrentIndex(1);
    grab(page, QStringLiteral("open-kinematic-drift"));
    page.resultTabs()->setCurrentIndex(0);
    grab(page, QStringLiteral("open-kinematic-drift-effects"));
  }
  {
    SCOPED_TRACE("matching: a thin part bending under the clamp");
    ProbeSimOptions o;
    o.seed = 1;
    ProbePointSet s = simulateProbing(o);
    const double half = o.length / 2.0;
    for (ProbePoint& pt : s.points) {
      const double u = (pt.nominal.x() - half) / half;
      pt.measured += 10.0 * o.noiseMm * (1.0 - u * u) * pt.normal;
    }
    page.setDomain(DiagnosisDomain::Matching);
    page.setResult(diagnose::diagnoseMatching(s));
    expectShowsCheck(page);
    expectFlaggedOrExplained(*page.result());
    page.resultTabs()->setCurrentIndex(1);
    grab(page, QStringLiteral("open-matching-bending"));
  }
}

// The demo report: per configured domain, the diagnosis section says what is left unexplained.
TEST_F(ResidualCheckPageTest, DemoReportSaysWhatIsLeftUnexplained) {
  const QString pdf = dir_.filePath(QStringLiteral("demo.pdf"));
  ReportOptions options;
  options.projectPath = project_;
  options.resolutionDpi = 150;
  writeReport(document_.project(), pdf, options);
  if (const QString out = qEnvironmentVariable("METROFIT_TEST_OUT"); !out.isEmpty()) {  // for a look
    QDir().mkpath(QDir(out).filePath(QStringLiteral("residualcheck")));
    const QString copy = QDir(out).filePath(QStringLiteral("residualcheck/demo-report.pdf"));
    QFile::remove(copy);
    QFile::copy(pdf, copy);
  }
  const QString text = pdfText(pdf);
  ASSERT_FALSE(text.isEmpty());
  int expected = 0;
  for (DiagnosisDomain domain : kDiagnosisDomains) {
    if (!hasDiagnosisSettings(document_.project(), domain)) continue;
    const diagnose::Diagnosis d =
        runDiagnosis(diagnosisSettings(document_.project(), project_.toStdString(), domain));
    if (checkPending(d)) continue;
    ASSERT_TRUE(d.residualCheck.has_value()) << diagnosisDomainKey(domain);
    ++expected;
    // The verdict's sentence as the report words it (its start: the rest may wrap around a page break).
    const QString first = residualCheckSentences(d, QLocale::c()).front().simplified();
    EXPECT_TRUE(text.contains(first.left(60))) << diagnosisDomainKey(domain) << ": " << first.toStdString();
  }
  EXPECT_EQ(static_cast<int>(text.count(QStringLiteral("What is left unexplained:"))), expected);
}

}  // namespace
}  // namespace metrofit
