#pragma once
// The residual check of the closed loop (core/diagnose/residual_check.h, docs/file-formats.md#residual_check)
// in words, for the diagnosis page's "Residual check" tab (residualcheckview.h) and the report's diagnosis
// section. Core writes the identifiers of docs/file-formats.md (`ljung_box`, `f_test`, the variable names
// `time`, `angle`, `surface:S1`, the forms `smooth`, `level`); here they become the words a person reads,
// translated in the context "metrofit::ResidualCheck":
//   * short names for table cells: "Ljung-Box", "path angle", "surface S1", "per level";
//   * reader's words for sentences (the report): "the path angle", "a smooth curve", and the
//     sentences saying what the final residual still depends on, which outliers were excluded and
//     which generic effects were added, without internal identifiers (no `unexplained:T1`).
// A column of the user's file is shown by its own name. Numbers in the given locale (the report:
// QLocale::c(), the page: the user's); "um" is written "µm".
#include <QLocale>
#include <QString>
#include <QStringList>
#include <string>

#include "core/diagnose/diagnosis.h"

namespace metrofit {

/// "ljung_box" -> "Ljung-Box", "f_test" -> "F test"; others as they are.
QString residualTestName(const std::string& name);
/// A variable for a table cell: "time", "file row", "path angle", "dimension", "surface",
/// "normal x", "surface S1", "dimension P1.D1", a column's own name.
QString residualVariableName(const std::string& against);
/// A variable in a sentence: "time", "the order of the rows in the file", "the path angle",
/// "the points of surface S1", "column T1".
QString residualVariableWords(const std::string& against);
/// A form for a table cell: "linear", "smooth", "step", "periodic", "per level", "spike".
QString dependenceFormName(const std::string& form);
QString dependenceFormName(diagnose::DependenceForm form);
/// A form with its shape for a table cell or a legend: dependenceFormName, and for a form periodic
/// in time (or another ordered variable) its period: "periodic, period 47.0 min".
QString dependenceFormLabel(const diagnose::GenericForm& shape, const QLocale& locale);
QString dependenceFormLabel(const diagnose::StructureItem& item, const QLocale& locale);
/// The period of a shape periodic in an ordered variable: "47.0 min" for time (minutes), else the
/// number alone; empty for other shapes (a path angle's period is 360 deg).
QString periodText(const diagnose::GenericForm& shape, const QLocale& locale);
/// A form in a sentence: "a linear trend", "a smooth curve", "a step" ("a step at 12.5" when the
/// change point is known), "a periodic pattern" ("a cycle with a period of 47.0 min" when periodic in
/// time), "a different level per group", "isolated spikes".
QString dependenceFormWords(const diagnose::StructureItem& item, const QLocale& locale);
QString dependenceFormWords(const diagnose::GenericForm& form, const QLocale& locale);

/// A p-value: 3 significant digits down to 0.001, below in exponent notation ("3.1e-12"), "< 1e-300"
/// when it underflowed to 0.
QString formatPValue(double p, const QLocale& locale);

/// The verdict on one line: "not white: still depends on T1 (smooth, 62 % of the residual variance),
/// path angle (...)" (at most three variables, then "and n more") with the variables and forms as
/// residualVariableName / dependenceFormName and numbers in the user's locale; without structure
/// core's summary translated (coretexts.h).
QString residualCheckVerdict(const diagnose::ResidualCheck& check);

/// What is left unexplained, in reader's words (the report): one paragraph per item
///   * the verdict: "The final residual shows no structure: ..." or "The final residual still
///     depends on the path angle (a periodic pattern, 62 % of the residual variance, p = 1e-9) and ...";
///   * the generic effects accepted for what no catalogue effect explains;
///   * the outliers excluded (up to `maxOutliers` listed) or that none was.
/// Empty when the diagnosis has no residual check.
QStringList residualCheckSentences(const diagnose::Diagnosis& diagnosis, const QLocale& locale,
                                   int maxOutliers = 8);

/// Where an outlier is: "row 412, part 37, dimension P1.D2" (whichever the data have).
QString outlierWhere(const diagnose::Outlier& outlier, const QLocale& locale);

}  // namespace metrofit
