// Core's texts on the diagnosis page, translated and with the user's number format
// (widgets/diagnose/coretexts.h, core/common/text.h):
//  * coverage: the four loops run on the demo data and on variations (other inputs, other files,
//    cancelled runs) and every phrase template they produce must be in the GUI's QT_TRANSLATE_NOOP
//    list (coreTextSources), every parameter key must have a display name: a new core sentence
//    cannot silently stay untranslated;
//  * German: evidence, notes, parameters and axis titles with ',' decimals on the page, and a
//    translated template (a stub translator in the context "metrofit::core") with its arguments in
//    the German locale;
//  * the built metrofit_de.qm / metrofit_pl.qm: once core's texts are in them, all of them are.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QDir>
#include <QLabel>
#include <QLocale>
#include <QRegularExpression>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTranslator>
#include <iostream>
#include <set>
#include <string>

#include "app/gui/diagnosispage.h"
#include "core/common/text.h"
#include "core/study/diagnosis_study.h"
#include "qtapp.h"
#include "widgets/diagnose/coretexts.h"
#include "widgets/diagnose/residualcheckview.h"
#include "widgets/diagnose/residualplot.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"

namespace metrofit {
namespace {

constexpr int kEffectColumn = 1;
constexpr int kParameterColumn = 2;
constexpr int kEvidenceColumn = 5;

/// Restores the default locale (C-like English in the test environment) after a test.
class LocaleGuard {
 public:
  explicit LocaleGuard(const QLocale& locale) : saved_(QLocale()) { QLocale::setDefault(locale); }
  ~LocaleGuard() { QLocale::setDefault(saved_); }

 private:
  QLocale saved_;
};

/// A translator that knows a few of core's templates in German (the mechanism, independent of what
/// the .ts files hold at the moment).
class StubGermanTranslator : public QTranslator {
 public:
  bool isEmpty() const override { return false; }
  QString translate(const char* context, const char* source, const char* = nullptr, int = -1) const override {
    if (QLatin1String(context) != QLatin1String(kCoreTextContext)) return {};
    const QString s = QString::fromUtf8(source);
    if (s == QLatin1String("accepted: ")) return QStringLiteral("angenommen: ");
    if (s ==
        QLatin1String("validation rmse %1 -> %2%3 (%4), fit rmse %5 -> %6%3, held-out rmse %7 -> %8%3, %9"))
      return QStringLiteral(
          "RMSE Validierung %1 → %2%3 (%4), RMSE Anpassung %5 → %6%3, RMSE zurückgehalten %7 → %8%3, %9");
    if (s == QLatin1String("tau %1 +- %2 min")) return QStringLiteral("τ %1 ± %2 min");
    if (s == QLatin1String("time (min)")) return QStringLiteral("Zeit (min)");
    return {};
  }
};

class DiagnosisLocaleTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    project_ = extractDemoProject(dir_.path());
    document_.load(project_);
  }

  DiagnosisSettings demoSettings(DiagnosisDomain domain) const {
    return diagnosisSettings(document_.project(), project_.toStdString(), domain);
  }

  std::string data(const char* name) const {
    return QDir(dir_.path()).filePath(QStringLiteral("data/") + name).toStdString();
  }

  QTemporaryDir dir_;
  QString project_;
  ProjectDocument document_;
};

void collect(const diagnose::Diagnosis& d, std::set<std::string>& formats, std::set<std::string>& keys) {
  std::vector<std::string> out;
  for (const Phrases& note : d.notesParts) collectFormats(note, out);
  for (const diagnose::Candidate& c : d.effects) {
    collectFormats(c.evidenceParts, out);
    if (c.plot) {
      collectFormats(c.plot->xLabelParts, out);
      collectFormats(c.plot->yLabelParts, out);
    }
    for (const diagnose::Parameter& p : c.parameters) keys.insert(p.name);
  }
  if (d.residualCheck) {  // the residual check's verdict and its plot's axis title
    collectFormats(d.residualCheck->summaryParts, out);
    if (d.residualCheck->plot) collectFormats(d.residualCheck->plot->xLabel, out);
  }
  formats.insert(out.begin(), out.end());
}

TEST_F(DiagnosisLocaleTest, EveryTemplateTheLoopsProduceIsInTheTranslationList) {
  std::vector<DiagnosisSettings> runs;
  for (DiagnosisDomain d : kDiagnosisDomains) runs.push_back(demoSettings(d));
  auto thermal = [&](const char* file, const std::string& target, std::vector<std::string> inputs,
                     double fraction = 0.5) {
    DiagnosisSettings s = demoSettings(DiagnosisDomain::Thermal);
    s.datasetPath = data(file);
    s.target = target;
    s.inputs = std::move(inputs);
    s.trainFraction = fraction;
    runs.push_back(s);
  };
  thermal("diagnose_thermal.csv", "disp_z_um", {"T2"});
  thermal("diagnose_thermal.csv", "disp_z_um", {"T1", "T3"}, 0.4);
  thermal("thermal_demo.csv", "disp_z_um", {"T1", "T2", "T3", "T4", "T_amb"});
  thermal("thermal_modular_combined.csv", "disp_z_um", {"T1", "T_amb", "FBG1_ue"});
  {
    DiagnosisSettings s = demoSettings(DiagnosisDomain::Kinematic);
    s.datasetPath = data("circular_demo.csv");
    runs.push_back(s);
  }
  {
    DiagnosisSettings s = demoSettings(DiagnosisDomain::Setup);
    s.datasetPath = data("paper_example_report.csv");
    runs.push_back(s);
  }
  for (const auto& [file, tolerance] :
       {std::pair{"probe_points_demo.csv", 0.05}, std::pair{"diagnose_probe.csv", 0.5},
        std::pair{"probe_s_piece.csv", 0.01}}) {
    DiagnosisSettings s = demoSettings(DiagnosisDomain::Matching);
    s.datasetPath = data(file);
    s.toleranceMm = tolerance;
    runs.push_back(s);
  }
  std::set<std::string> formats, keys;
  for (const DiagnosisSettings& s : runs) collect(runDiagnosis(s), formats, keys);
  for (DiagnosisDomain d : kDiagnosisDomains) {  // stopped at once: "cancelled" / "stopped by ..."
    CancelToken cancel;
    cancel.cancel();
    collect(runDiagnosis(demoSettings(d), &cancel), formats, keys);
  }
  EXPECT_GE(formats.size(), 45u);  // the runs above reach most of core's sentences
  EXPECT_GE(keys.size(), 15u);
  std::cout << formats.size() << " templates and " << keys.size() << " parameter keys produced, "
            << coreTextSources().size() << " templates listed\n";
  for (const std::string& f : formats)
    EXPECT_TRUE(isCoreTextSource(f)) << "core produces the template \"" << f
                                     << "\", which is not in widgets/diagnose/coretexts.cpp (kCoreTexts)";
  for (const std::string& k : keys)
    EXPECT_TRUE(hasParameterDisplayName(k)) << "no display name for the parameter key " << k;
  // The termination reasons of core/common/run.cpp too.
  for (Termination t : {Termination::Converged, Termination::BudgetExhausted, Termination::MaxIterations,
                        Termination::Cancelled, Termination::Failed})
    EXPECT_TRUE(isCoreTextSource(toString(t))) << toString(t);
}

TEST_F(DiagnosisLocaleTest, GermanPageShowsCommaDecimalsInEvidenceNotesParametersAndPlot) {
  const LocaleGuard locale(QLocale(QLocale::German, QLocale::Germany));
  StubGermanTranslator translator;
  QCoreApplication::installTranslator(&translator);
  DiagnosisPage page(&document_);
  page.setDomain(DiagnosisDomain::Thermal);
  const bool ran = page.runNow();
  QCoreApplication::removeTranslator(&translator);
  ASSERT_TRUE(ran) << page.statusText().toStdString();
  const QTableWidget* t = page.candidateTable();
  int accepted = -1;
  for (int r = 0; r < t->rowCount(); ++r)
    if (t->item(r, kEffectColumn)->text() == QLatin1String("lag:T2")) accepted = r;
  ASSERT_GE(accepted, 0);
  // Core wrote "accepted: validation rmse 4.08 -> 0.262 um (-94 %), fit rmse 1.64 -> 0.262 um, held-out
  // rmse 2.94 -> 0.291 um, tau 15.5 +- 0.2 min".
  EXPECT_EQ(t->item(accepted, kEvidenceColumn)->text().toStdString(),
            "angenommen: RMSE Validierung 4,08 → 0,262 µm (-94 %), RMSE Anpassung 1,64 → 0,262 µm, RMSE "
            "zurückgehalten 2,94 → 0,291 µm, τ 15,5 ± 0,2 min");
  EXPECT_EQ(
      page.result()->effects[static_cast<std::size_t>(accepted)].evidence,
      "accepted: validation rmse 4.08 -> 0.262 um (-94 %), fit rmse 1.64 -> 0.262 um, held-out rmse 2.94 -> "
      "0.291 um, tau 15.5 +- 0.2 min");
  // Every evidence line: no '.'-decimal number left (the English text has them).
  const QRegularExpression dotDecimal(QStringLiteral("\\d\\.\\d"));
  for (int r = 0; r < t->rowCount(); ++r) {
    const QString e = t->item(r, kEvidenceColumn)->text();
    EXPECT_FALSE(dotDecimal.match(e).hasMatch()) << e.toStdString();
    EXPECT_FALSE(dotDecimal.match(t->item(r, kParameterColumn)->text()).hasMatch())
        << t->item(r, kParameterColumn)->text().toStdString();
  }
  EXPECT_TRUE(t->item(accepted, kParameterColumn)->text().startsWith(QStringLiteral("time constant = 15,")))
      << t->item(accepted, kParameterColumn)->text().toStdString();
  // Notes: the declared model with ',' decimals; the status line too.
  EXPECT_TRUE(page.notesText().contains(QRegularExpression(QStringLiteral("\\d,\\d"))))
      << page.notesText().toStdString();
  EXPECT_FALSE(dotDecimal.match(page.notesText()).hasMatch()) << page.notesText().toStdString();
  EXPECT_FALSE(dotDecimal.match(page.statusText()).hasMatch()) << page.statusText().toStdString();
  // The residual plot's axis title went through the translator.
  EXPECT_EQ(page.residualPlot()->xAxisTitle(), QStringLiteral("Zeit (min)"));
}

TEST_F(DiagnosisLocaleTest, PolishPageHasNoDotDecimalsInAnyDomain) {
  const LocaleGuard locale(QLocale(QLocale::Polish, QLocale::Poland));
  // The application's Polish translation (the built one; METROFIT_TEST_QM_DIR may point elsewhere).
  QTranslator translator;
  const QString qmDir = qEnvironmentVariable("METROFIT_TEST_QM_DIR", QStringLiteral(METROFIT_QM_DIR));
  ASSERT_TRUE(translator.load(QDir(qmDir).filePath(QStringLiteral("metrofit_pl"))));
  QCoreApplication::installTranslator(&translator);
  struct Remove {
    QTranslator* t;
    ~Remove() { QCoreApplication::removeTranslator(t); }
  } remove{&translator};
  const QRegularExpression dotDecimal(QStringLiteral("\\d\\.\\d"));
  DiagnosisPage page(&document_);
  for (DiagnosisDomain d : kDiagnosisDomains) {
    page.setDomain(d);
    ASSERT_TRUE(page.runNow()) << page.statusText().toStdString();
    const QTableWidget* t = page.candidateTable();
    ASSERT_GT(t->rowCount(), 0);
    for (int r = 0; r < t->rowCount(); ++r) {
      for (int c : {kParameterColumn, kEvidenceColumn}) {
        const QString text = t->item(r, c)->text();
        // Names may contain dots (none in the demo); numbers must not.
        EXPECT_FALSE(dotDecimal.match(text).hasMatch())
            << diagnosisDomainKey(d) << ": " << text.toStdString();
      }
    }
    EXPECT_FALSE(dotDecimal.match(page.notesText()).hasMatch()) << page.notesText().toStdString();
    // The residual check: verdict and tables in Polish numbers.
    const ResidualCheckView* check = page.residualCheckView();
    EXPECT_FALSE(dotDecimal.match(check->verdictText()).hasMatch()) << check->verdictText().toStdString();
    for (const QTableWidget* table : {check->testTable(), check->structureTable(), check->outlierTable()})
      for (int r = 0; r < table->rowCount(); ++r)
        for (int c = 0; c < table->columnCount(); ++c)
          if (table->item(r, c)->data(Qt::UserRole).typeId() == QMetaType::Double) {  // the numbers
            EXPECT_FALSE(dotDecimal.match(table->item(r, c)->text()).hasMatch())      // (names may have dots)
                << diagnosisDomainKey(d) << ": " << table->item(r, c)->text().toStdString();
          }
    const auto* info = page.findChild<QLabel*>(QStringLiteral("diagnosisInfo"));
    ASSERT_NE(info, nullptr);
    EXPECT_FALSE(dotDecimal.match(info->text()).hasMatch()) << info->text().toStdString();  // tolerance 0,035
    EXPECT_TRUE(page.notesText().contains(QRegularExpression(QStringLiteral("\\d,\\d"))))
        << page.notesText().toStdString();
    const std::string shown = t->item(0, kEvidenceColumn)->text().toStdString();
    EXPECT_NE(shown, page.result()->effects.front().evidence) << "the English text, not the localized one";
    // A grab for people to look at: $METROFIT_TEST_OUT/diagnosis_locale/<domain>-pl.png.
    if (const QString out = qEnvironmentVariable("METROFIT_TEST_OUT"); !out.isEmpty()) {
      const QString dir = QDir(out).filePath(QStringLiteral("diagnosis_locale"));
      QDir().mkpath(dir);
      page.resize(1100, 720);
      page.grab().save(
          QDir(dir).filePath(QString::fromLatin1(diagnosisDomainKey(d)) + QStringLiteral("-pl.png")));
    }
  }
}

TEST_F(DiagnosisLocaleTest, EnglishPageKeepsCoresText) {
  const LocaleGuard locale(QLocale::c());
  DiagnosisPage page(&document_);
  page.setDomain(DiagnosisDomain::Setup);
  ASSERT_TRUE(page.runNow()) << page.statusText().toStdString();
  const diagnose::Diagnosis& d = *page.result();
  for (int r = 0; r < page.candidateTable()->rowCount(); ++r) {
    const QString shown = page.candidateTable()->item(r, kEvidenceColumn)->text();
    EXPECT_EQ(shown, displaySymbols(QString::fromStdString(d.effects[static_cast<std::size_t>(r)].evidence)));
  }
  EXPECT_EQ(page.residualPlot()->xAxisTitle(), QStringLiteral("part"));
}

// The English page in every domain: ±, → and µm, never core's ASCII "+-", "->" or "um".
TEST_F(DiagnosisLocaleTest, EnglishPageShowsSymbolsNotAscii) {
  const LocaleGuard locale(QLocale::c());
  const QRegularExpression ascii(QStringLiteral("\\+-|->|\\bum\\b"));
  DiagnosisPage page(&document_);
  int checked = 0;
  for (DiagnosisDomain d : kDiagnosisDomains) {
    page.setDomain(d);
    ASSERT_TRUE(page.runNow()) << page.statusText().toStdString();
    QStringList texts{page.notesText(), page.residualCheckView()->verdictText()};
    const QTableWidget* t = page.candidateTable();
    for (int r = 0; r < t->rowCount(); ++r)
      for (int c = 0; c < t->columnCount(); ++c)
        if (t->item(r, c)) texts << t->item(r, c)->text();
    for (const QLabel* label : page.findChildren<QLabel*>()) texts << label->text();
    for (const QString& text : texts) {
      EXPECT_FALSE(ascii.match(text).hasMatch()) << diagnosisDomainKey(d) << ": " << text.toStdString();
      ++checked;
    }
  }
  EXPECT_GT(checked, 20);
}

TEST(CoreTextTest, PhraseInPolishLocaleAndTerminationTexts) {
  const QLocale pl(QLocale::Polish, QLocale::Poland);
  const Phrase p(
      "rmse %1 -> %2 um (%3 %), dBIC %4, %5",
      {PhraseArg::numberOrNa(4.79, 3), PhraseArg::numberOrNa(0.707, 3), PhraseArg::numberOrNa(-85.2, 2),
       PhraseArg::numberOrNa(-54.98, 4), PhraseArg::text({Phrase("n/a")})});
  // Core's ASCII "->" and "um" in a template (an untranslated one here) are shown as → and µm.
  EXPECT_EQ(coreText(p, pl).toStdString(), "rmse 4,79 → 0,707 µm (-85 %), dBIC -54,98, n/a");
  EXPECT_EQ(
      coreText(Phrase("tau %1 +- %2 min", {PhraseArg::numberOrNa(4.5, 2), PhraseArg::numberOrNa(0.25, 2)}),
               pl)
          .toStdString(),
      "tau 4,5 ± 0,25 min");
  EXPECT_EQ(coreText(Phrase("%1 = c0", {PhraseArg::name("disp.z")}), pl), QStringLiteral("disp.z = c0"));
  EXPECT_EQ(coreText({Phrase("residual (%1)", {PhraseArg::unit("um")})}, pl),
            QStringLiteral("residual (µm)"));
  EXPECT_EQ(coreText(Phrase("%1 %", {PhraseArg::signedNumber(5.25, 3)}), pl), QStringLiteral("+5,25 %"));
  EXPECT_EQ(terminationText(Termination::Converged), QStringLiteral("converged"));
  EXPECT_EQ(parameterDisplayName("tau_min"), QStringLiteral("time constant"));
  EXPECT_EQ(parameterDisplayName("unknown_key"), QStringLiteral("unknown_key"));
}

#ifdef METROFIT_QM_DIR
// The built translations: before the lead merges core's texts into the .ts files none of them is
// translated (skipped); after that every one must be.
TEST(CoreTextTest, BuiltTranslationsCoverCoresTextsOnceTheyHaveThem) {
  for (const char* language : {"de", "pl"}) {
    QTranslator translator;
    ASSERT_TRUE(translator.load(QStringLiteral(METROFIT_QM_DIR "/metrofit_") + QLatin1String(language)));
    std::vector<std::string> missing;
    for (const char* s : coreTextSources())
      if (translator.translate(kCoreTextContext, s).isEmpty()) missing.push_back(s);
    EXPECT_TRUE(missing.empty()) << language << ": " << missing.size() << " untranslated, e.g. \""
                                 << missing.front() << "\"";
  }
}
#endif

}  // namespace
}  // namespace metrofit
