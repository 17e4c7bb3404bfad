#include "widgets/diagnose/coretexts.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>
#include <algorithm>
#include <cmath>
#include <map>

namespace metrofit {
namespace {

// Every template of core/diagnose (evidence, notes, axis titles, the loop's stop notes, the
// acceptance reasons of linear_evidence.cpp) and core/common/run.cpp (termination reasons). Keep in
// step with core: diagnosis_locale_test fails when core produces a template that is not here.
// Placeholders %1 to %99 are numbers, names or units (see core/common/text.h); "+-" may be written
// "±" in a translation.
const char* const kCoreTexts[] = {
    // Shared
    QT_TRANSLATE_NOOP("metrofit::core", "n/a"),
    QT_TRANSLATE_NOOP("metrofit::core", "%1 %"),
    QT_TRANSLATE_NOOP("metrofit::core", "accepted: "),
    QT_TRANSLATE_NOOP("metrofit::core", "; passed, but %1 explains more"),
    QT_TRANSLATE_NOOP("metrofit::core", "cancelled"),
    QT_TRANSLATE_NOOP("metrofit::core", "stopped by the observer after round %1"),
    QT_TRANSLATE_NOOP("metrofit::core", "time (min)"),
    QT_TRANSLATE_NOOP("metrofit::core", "radial residual (mm)"),
    // Thermal
    QT_TRANSLATE_NOOP("metrofit::core", "too few fit rows (%1) for %2 coefficients"),
    QT_TRANSLATE_NOOP("metrofit::core", "column '%1' is constant on the fit rows"),
    QT_TRANSLATE_NOOP("metrofit::core", "the columns are linearly dependent on the fit rows"),
    QT_TRANSLATE_NOOP("metrofit::core", "drift %1 +- %2%3/min"),
    QT_TRANSLATE_NOOP("metrofit::core", "coefficient %1 +- %2%3 per unit"),
    QT_TRANSLATE_NOOP("metrofit::core", "coefficient %1 +- %2%3 per %4"),
    QT_TRANSLATE_NOOP("metrofit::core", "tau %1 +- %2 min"),
    QT_TRANSLATE_NOOP("metrofit::core", "tau %1 min"),
    QT_TRANSLATE_NOOP("metrofit::core", "%1 = c0"),
    QT_TRANSLATE_NOOP("metrofit::core", " + %1 %2"),
    QT_TRANSLATE_NOOP("metrofit::core", "declared model (static, fitted on the first %1 of %2 rows): %3"),
    QT_TRANSLATE_NOOP("metrofit::core", "noise level (first differences of the fit residual): %1%2"),
    QT_TRANSLATE_NOOP("metrofit::core", "not estimable: %1"),
    QT_TRANSLATE_NOOP("metrofit::core",
                      "validation rmse %1 -> %2%3 (%4), fit rmse %5 -> %6%3, held-out rmse %7 -> %8%3"),
    QT_TRANSLATE_NOOP("metrofit::core",
                      "validation rmse %1 -> %2%3 (%4), fit rmse %5 -> %6%3, held-out rmse %7 -> %8%3, %9"),
    QT_TRANSLATE_NOOP("metrofit::core", "; rejected: validation error worse"),
    QT_TRANSLATE_NOOP("metrofit::core", "; rejected: validation gain below %1 %"),
    QT_TRANSLATE_NOOP("metrofit::core", "; rejected: explains %1%2, below %3 x the noise level %4%2"),
    QT_TRANSLATE_NOOP("metrofit::core", "; rejected: no in-sample evidence (fit dBIC %1 >= 0)"),
    QT_TRANSLATE_NOOP("metrofit::core", "; rejected: the validation folds cannot fit it"),
    QT_TRANSLATE_NOOP("metrofit::core", "%1 gross errors excluded before the fit (robust z above %2):"),
    QT_TRANSLATE_NOOP("metrofit::core", " row %1 (%2%3)"),
    QT_TRANSLATE_NOOP("metrofit::core", "; rejected: the generic %1 validates better (%2 against %3%4)"),
    QT_TRANSLATE_NOOP("metrofit::core", "; not taken: the generic %1 validates better (%2 against %3%4)"),
    QT_TRANSLATE_NOOP("metrofit::core", "; rejected: the residual still depends on %1 after it (%2, p = %3)"),
    QT_TRANSLATE_NOOP("metrofit::core",
                      "; rejected: the fit rows do not determine tau (standard error above half of it)"),
    QT_TRANSLATE_NOOP(
        "metrofit::core",
        "effects chosen on the fit rows by blocked forward validation (%1 folds, validation rmse "
        "%2%3); the held-out rows only report the error"),
    QT_TRANSLATE_NOOP(
        "metrofit::core",
        "declared model %1 of %2 (fitted on the first %3 of %4 rows as thermal fit does; alone: fit "
        "rmse %5, held-out rmse %6%7); the loop fits the target on its prediction (coefficient %8) "
        "and the candidate effects"),
    QT_TRANSLATE_NOOP("metrofit::core",
                      "accepted together with %1: validation rmse %2 -> %3%4 (%5), fit rmse %6 -> %7%4, "
                      "held-out rmse %8 -> %9%4, %10"),
    QT_TRANSLATE_NOOP("metrofit::core", "residual"),
    QT_TRANSLATE_NOOP("metrofit::core", "residual (%1)"),
    // Kinematic
    QT_TRANSLATE_NOOP("metrofit::core", "path angle (deg)"),
    QT_TRANSLATE_NOOP("metrofit::core",
                      "declared model: origin (%1, %2) um, x axis %3 deg, y axis %4 deg, squareness %5 deg"),
    QT_TRANSLATE_NOOP("metrofit::core", "not estimable: no period range to search on this path"),
    QT_TRANSLATE_NOOP("metrofit::core",
                      "not estimable from this path: its parameters are not observable together with the "
                      "declared ones"),
    QT_TRANSLATE_NOOP("metrofit::core", "backlash x %1 +- %2 um, y %3 +- %4 um"),
    QT_TRANSLATE_NOOP("metrofit::core", "scale x %1 +- %2 ppm, y %3 +- %4 ppm"),
    QT_TRANSLATE_NOOP("metrofit::core", "servo lag tau %1 +- %2 s at %3 mm/min (%4 um)"),
    QT_TRANSLATE_NOOP("metrofit::core", "cyclic on %1: period %2 +- %3 mm, amplitude %4 +- %5 um"),
    QT_TRANSLATE_NOOP("metrofit::core", "rmse %1 -> %2 um (%3 %), dBIC %4, %5"),
    QT_TRANSLATE_NOOP("metrofit::core", "; rejected: dBIC above -%1"),
    QT_TRANSLATE_NOOP("metrofit::core", "; rejected: rmse gain below %1 %"),
    // Setup
    QT_TRANSLATE_NOOP(
        "metrofit::core",
        "declared model: constant errors of the %1 setup data through the relation graph, least "
        "squares over %2 rows of %3 parts; rank %4 of %5"),
    QT_TRANSLATE_NOOP("metrofit::core", " (rank deficient: minimum-norm solution)"),
    QT_TRANSLATE_NOOP("metrofit::core", "declared fit (minimum norm), setup errors mm:"),
    QT_TRANSLATE_NOOP("metrofit::core", " %1=%2"),
    QT_TRANSLATE_NOOP("metrofit::core", "not identifiable: %1 (one part only?)"),
    QT_TRANSLATE_NOOP("metrofit::core", "not identifiable: %1 (time does not vary?)"),
    QT_TRANSLATE_NOOP("metrofit::core", "%1 +- %2 mm/part (t = %3); "),
    QT_TRANSLATE_NOOP("metrofit::core", "%1 +- %2 mm/min (t = %3); "),
    QT_TRANSLATE_NOOP("metrofit::core", "part"),
    QT_TRANSLATE_NOOP("metrofit::core", "apparent error of %1 (mm)"),
    QT_TRANSLATE_NOOP(
        "metrofit::core",
        "; preferred to %1 (its dBIC is %2 lower, below the threshold: the data cannot tell them "
        "apart)"),
    QT_TRANSLATE_NOOP("metrofit::core", "; indistinguishable from %1 with these data"),
    // Matching
    QT_TRANSLATE_NOOP("metrofit::core", "distance from the centroid (mm)"),
    QT_TRANSLATE_NOOP("metrofit::core", "deviation along the normal (mm)"),
    QT_TRANSLATE_NOOP("metrofit::core", "surface"),
    QT_TRANSLATE_NOOP("metrofit::core", "polar angle (deg)"),
    QT_TRANSLATE_NOOP("metrofit::core", "%1 = %2 +- %3"),
    QT_TRANSLATE_NOOP("metrofit::core", "%1 = %2"),
    QT_TRANSLATE_NOOP("metrofit::core", ", %1 = %2 +- %3"),
    QT_TRANSLATE_NOOP("metrofit::core", ", %1 = %2"),
    QT_TRANSLATE_NOOP("metrofit::core", "declared model: rigid posture p = R q + t fitted to %1, %2 points"),
    QT_TRANSLATE_NOOP("metrofit::core", "the deviations along the nominal normals"),
    QT_TRANSLATE_NOOP("metrofit::core", "the in-plane residuals (planar, position-only)"),
    QT_TRANSLATE_NOOP("metrofit::core", "the residual vectors (position-only)"),
    QT_TRANSLATE_NOOP("metrofit::core",
                      "declared fit: rotation_deg [%1, %2, %3], translation_mm [%4, %5, %6]"),
    QT_TRANSLATE_NOOP("metrofit::core",
                      "not identifiable: %1 (the rigid posture explains it with these points)"),
    QT_TRANSLATE_NOOP("metrofit::core", "%1; %2"),
    QT_TRANSLATE_NOOP("metrofit::core", "; indistinguishable from %1 with these points"),
    // linear_evidence.cpp: acceptance reasons and why an effect is not identifiable
    QT_TRANSLATE_NOOP("metrofit::core", "dBIC = %1 < -%2, rmse %3 -> %4 %5 (-%6 %)"),
    QT_TRANSLATE_NOOP("metrofit::core", "dBIC = %1 not below -%2, rmse %3 -> %4 %5 (-%6 %)"),
    QT_TRANSLATE_NOOP("metrofit::core", "dBIC = %1 < -%2, rmse %3 -> %4 %5 (-%6 %, below the relevant %7 %)"),
    QT_TRANSLATE_NOOP("metrofit::core",
                      "dBIC = %1 < -%2, rmse %3 -> %4 %5 (-%6 %, below the relevant %7 %5)"),
    QT_TRANSLATE_NOOP("metrofit::core", "absorbed by the declared model"),
    QT_TRANSLATE_NOOP("metrofit::core", "its parameters are not separable with these data"),
    QT_TRANSLATE_NOOP("metrofit::core", "too few data for the parameters"),
    // core/diagnose/residual_check.cpp: the residual check's summary, forms, generic effects
    QT_TRANSLATE_NOOP("metrofit::core", "linear"),
    QT_TRANSLATE_NOOP("metrofit::core", "smooth"),
    QT_TRANSLATE_NOOP("metrofit::core", "step"),
    QT_TRANSLATE_NOOP("metrofit::core", "periodic"),
    QT_TRANSLATE_NOOP("metrofit::core", "per level"),
    QT_TRANSLATE_NOOP("metrofit::core", "spike"),
    QT_TRANSLATE_NOOP("metrofit::core", "%1"),
    QT_TRANSLATE_NOOP("metrofit::core", ", "),
    QT_TRANSLATE_NOOP("metrofit::core", "too few observations (%1) to test the residual"),
    QT_TRANSLATE_NOOP("metrofit::core",
                      "white: no test finds structure at the %1 % family-wise level (%2 tests)"),
    QT_TRANSLATE_NOOP("metrofit::core", "not white: still depends on "),
    QT_TRANSLATE_NOOP("metrofit::core", "%1 (%2, %3 % of the residual variance)"),
    QT_TRANSLATE_NOOP("metrofit::core", " and %1 more"),
    QT_TRANSLATE_NOOP("metrofit::core", "not white: serially correlated in %1 order (Ljung-Box p = %2)"),
    QT_TRANSLATE_NOOP("metrofit::core", "%1 in %2, rms %3%4, range %5%4"),
    QT_TRANSLATE_NOOP("metrofit::core", ", step %1%2 at %3"),
    QT_TRANSLATE_NOOP("metrofit::core", ", strongest harmonic %1 (amplitude %2%3)"),
    QT_TRANSLATE_NOOP("metrofit::core", ", period %1, amplitude %2%3"),
    // the open world in the loops: outliers excluded first, residual variables' axis titles, a named
    // effect that does not explain what it was chosen for (diagnosis.cpp keepNamedOnlyWhenNeeded)
    QT_TRANSLATE_NOOP("metrofit::core",
                      "%1 gross errors excluded before the fit (robust z above the outlier threshold):"),
    QT_TRANSLATE_NOOP("metrofit::core", " row %1 (%2 um)"),
    QT_TRANSLATE_NOOP("metrofit::core", " row %1 (part %2, %3, %4 mm)"),
    QT_TRANSLATE_NOOP("metrofit::core", " point %1 (row %2, %3 mm)"),
    QT_TRANSLATE_NOOP("metrofit::core", "; "),
    QT_TRANSLATE_NOOP("metrofit::core", "not identifiable: %1"),
    QT_TRANSLATE_NOOP(
        "metrofit::core",
        "rejected: does not explain what it was chosen for; without it the generic effects explain "
        "the data as well (BIC %1 without, %2 with, needed %3 lower)"),
    QT_TRANSLATE_NOOP("metrofit::core", "data row"),
    QT_TRANSLATE_NOOP("metrofit::core", "dimension"),
    QT_TRANSLATE_NOOP("metrofit::core", "loop direction"),
    QT_TRANSLATE_NOOP("metrofit::core", "samples since an axis reversed (signed, log scale)"),
    QT_TRANSLATE_NOOP("metrofit::core", "part number (%1)"),
    QT_TRANSLATE_NOOP("metrofit::core", "position along surface %1 (mm)"),
    QT_TRANSLATE_NOOP("metrofit::core", "normal x"),
    QT_TRANSLATE_NOOP("metrofit::core", "normal y"),
    QT_TRANSLATE_NOOP("metrofit::core", "normal z"),
    QT_TRANSLATE_NOOP("metrofit::core", "x (mm)"),
    QT_TRANSLATE_NOOP("metrofit::core", "y (mm)"),
    QT_TRANSLATE_NOOP("metrofit::core", "z (mm)"),
    // core/common/run.cpp toString(Termination)
    QT_TRANSLATE_NOOP("metrofit::core", "converged"),
    QT_TRANSLATE_NOOP("metrofit::core", "budget exhausted"),
    QT_TRANSLATE_NOOP("metrofit::core", "iteration limit"),
    QT_TRANSLATE_NOOP("metrofit::core", "failed"),
    QT_TRANSLATE_NOOP("metrofit::core", "unknown"),
    // core/spc/spc.cpp gateCompensation (the SPC compensation decision)
    QT_TRANSLATE_NOOP("metrofit::core", "no nominal value given: nothing to compensate against"),
    QT_TRANSLATE_NOOP("metrofit::core", "subgroup %1 beyond the X-bar limits"),
    QT_TRANSLATE_NOOP("metrofit::core", "subgroups %1 beyond the X-bar limits"),
    QT_TRANSLATE_NOOP("metrofit::core", "subgroup %1 beyond the R limits"),
    QT_TRANSLATE_NOOP("metrofit::core", "subgroups %1 beyond the R limits"),
    QT_TRANSLATE_NOOP("metrofit::core", "; subgroup %1 beyond the R limits"),
    QT_TRANSLATE_NOOP("metrofit::core", "; subgroups %1 beyond the R limits"),
    QT_TRANSLATE_NOOP(
        "metrofit::core",
        "not compensated: the process is out of control (%1); remove the special causes first, a "
        "correction would chase them"),
    QT_TRANSLATE_NOOP("metrofit::core",
                      "not compensated: the systematic error %1 is within its interval +-%2 (k = %3): random "
                      "scatter, not a systematic error"),
    QT_TRANSLATE_NOOP("metrofit::core",
                      "not compensated: the systematic error %1 is below the smallest correction %2"),
    QT_TRANSLATE_NOOP(
        "metrofit::core",
        "compensate %1: the systematic error (nominal - mean, Eq. 20) is beyond its interval +-%2 "
        "(k = %3) and the process is in control (%4 subgroups of %5)"),
};

// Display names of the diagnosis parameters (keys of docs/file-formats.md#effect-catalogue); the unit is
// shown with the value.
const std::map<std::string, const char*>& parameterNames() {
  static const std::map<std::string, const char*> names = {
      {"tau_min", QT_TRANSLATE_NOOP("metrofit::core", "time constant")},
      {"coefficient", QT_TRANSLATE_NOOP("metrofit::core", "coefficient")},
      {"per_min", QT_TRANSLATE_NOOP("metrofit::core", "drift rate")},
      {"x_mm", QT_TRANSLATE_NOOP("metrofit::core", "x")},
      {"y_mm", QT_TRANSLATE_NOOP("metrofit::core", "y")},
      {"x_ppm", QT_TRANSLATE_NOOP("metrofit::core", "x")},
      {"y_ppm", QT_TRANSLATE_NOOP("metrofit::core", "y")},
      {"axis", QT_TRANSLATE_NOOP("metrofit::core", "axis")},
      {"period_mm", QT_TRANSLATE_NOOP("metrofit::core", "period")},
      {"amplitude_mm", QT_TRANSLATE_NOOP("metrofit::core", "amplitude")},
      {"phase_deg", QT_TRANSLATE_NOOP("metrofit::core", "phase")},
      {"tau_s", QT_TRANSLATE_NOOP("metrofit::core", "time constant")},
      {"lag_mm", QT_TRANSLATE_NOOP("metrofit::core", "lag")},
      {"mm_per_part", QT_TRANSLATE_NOOP("metrofit::core", "change per part")},
      {"mm_per_min", QT_TRANSLATE_NOOP("metrofit::core", "drift rate")},
      {"ppm", QT_TRANSLATE_NOOP("metrofit::core", "scale")},
      {"mm", QT_TRANSLATE_NOOP("metrofit::core", "offset")},
      {"angle_deg", QT_TRANSLATE_NOOP("metrofit::core", "angle")},
      // generic effects `unexplained:<against>` (residual_check.h summariseGeneric), in the data's units
      {"form", QT_TRANSLATE_NOOP("metrofit::core", "form")},
      {"rms", QT_TRANSLATE_NOOP("metrofit::core", "rms")},
      {"range", QT_TRANSLATE_NOOP("metrofit::core", "range")},
      {"at", QT_TRANSLATE_NOOP("metrofit::core", "at")},
      {"step", QT_TRANSLATE_NOOP("metrofit::core", "step")},
      {"harmonic", QT_TRANSLATE_NOOP("metrofit::core", "harmonic")},
      {"amplitude", QT_TRANSLATE_NOOP("metrofit::core", "amplitude")},
  };
  return names;
}

QString translated(const std::string& source) {
  return displaySymbols(QCoreApplication::translate(kCoreTextContext, source.c_str()));
}

/// Replaces %1 to %99 by args in one pass: core's substitutePlaceholders on UTF-8 (the
/// placeholders are ASCII, so byte positions are safe).
QString substitute(const QString& format, const QStringList& args) {
  std::vector<std::string> utf8;
  utf8.reserve(static_cast<std::size_t>(args.size()));
  for (const QString& a : args) utf8.push_back(a.toStdString());
  return QString::fromStdString(substitutePlaceholders(format.toStdString(), utf8));
}

QString argText(const PhraseArg& a, const QLocale& locale) {
  switch (a.kind) {
    case PhraseArg::Kind::Number: {
      if (!std::isfinite(a.value)) return a.naIfNotFinite ? translated("n/a") : QString::number(a.value);
      QString s = a.style == 'd' ? locale.toString(static_cast<qlonglong>(a.value))
                                 : locale.toString(a.value, a.style == 'f' ? 'f' : 'g', a.precision);
      if (a.plusSign && a.value >= 0.0) s.prepend(locale.positiveSign());
      return s;
    }
    case PhraseArg::Kind::Name:
      return QString::fromStdString(a.verbatim);
    case PhraseArg::Kind::Unit:
      return displayUnit(QString::fromStdString(a.verbatim));
    case PhraseArg::Kind::Text:
      return coreText(a.nested, locale);
  }
  return {};
}

}  // namespace

const std::vector<const char*>& coreTextSources() {
  static const std::vector<const char*> list(std::begin(kCoreTexts), std::end(kCoreTexts));
  return list;
}

bool isCoreTextSource(const std::string& format) {
  const auto& list = coreTextSources();
  return std::any_of(list.begin(), list.end(), [&](const char* s) { return format == s; });
}

QString coreText(const Phrase& phrase, const QLocale& locale) {
  QStringList args;
  for (const PhraseArg& a : phrase.args) args << argText(a, locale);
  return substitute(translated(phrase.format), args);
}

QString coreText(const Phrases& text, const QLocale& locale) {
  QString out;
  for (const Phrase& p : text) out += coreText(p, locale);
  return out;
}

QString coreText(const Phrases& text, const std::string& english, const QLocale& locale) {
  return text.empty() ? displaySymbols(QString::fromStdString(english)) : coreText(text, locale);
}

QString localNumber(double value, int precision, char style, const QLocale& locale) {
  if (!std::isfinite(value)) return translated("n/a");
  return locale.toString(value, style == 'f' ? 'f' : 'g', precision);
}

QString displayUnit(const QString& units) {
  QString s = units;
  static const QRegularExpression um(QStringLiteral("\\bum\\b"));
  s.replace(um, QStringLiteral("µm"));
  return s;
}

QString displaySymbols(const QString& text) {
  QString s = displayUnit(text);
  s.replace(QStringLiteral("+-"), QStringLiteral("±"));
  s.replace(QStringLiteral("->"), QStringLiteral("→"));
  return s;
}

QString parameterDisplayName(const std::string& key) {
  const auto& names = parameterNames();
  const auto it = names.find(key);
  return it == names.end() ? QString::fromStdString(key) : translated(it->second);
}

bool hasParameterDisplayName(const std::string& key) {
  return parameterNames().count(key) > 0;
}

QString terminationText(Termination termination) {
  return translated(toString(termination));
}

}  // namespace metrofit
