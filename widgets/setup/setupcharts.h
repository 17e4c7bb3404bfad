#pragma once
// Charts of the setup correction, built without a widget so that the GUI views and the PDF report
// draw the same thing (Qt Charts stays out of this header):
//
//  * convergence (the paper's Fig. 12-17): for each run the best f1 (solid), f2 (dashed) and
//    f = 10 f1 - f2 (dotted, right axis) against the number of solutions evaluated; one colour per
//    run, the legend names the runs (method, seed); the exact optimum's f1 and f as horizontal
//    reference lines.
//  * validation (the paper's Fig. 18): the measurement sets sorted by the budget before correction
//    (x: rank), f1 before, the exact optimum and every trial of every method (points).
#include <QColor>
#include <QString>
#include <optional>
#include <vector>

#include "core/setup/objective.h"
#include "core/study/setup_study.h"

QT_BEGIN_NAMESPACE
class QChart;
QT_END_NAMESPACE

namespace metrofit::setup {
struct ValidationResult;
}

namespace metrofit {

struct SetupConvergenceRun {
  QString label;  ///< legend text, e.g. "CRIPSO, seed 1"
  QString method;
  std::vector<SetupTracePoint> trace;
};

/// Legend text of a run: "CRIPSO, seed 3".
QString setupRunLabel(const QString& method, std::uint64_t seed);
/// Display name of a method: "exact", "CRIPSO", "PSO", "GA", "COA".
QString setupMethodTitle(const QString& method);
/// Colour of run number `index` of a method (methods have their own hue, seeds vary its shade).
QColor setupRunColor(const QString& method, int indexOfMethod);

/// A new chart (owned by the caller). `budget` sets the x range when there is no run yet.
QChart* makeSetupConvergenceChart(const std::vector<SetupConvergenceRun>& runs,
                                  const std::optional<setup::SetupScore>& exact,
                                  long budget = setup::kPaperBudget, bool showF2 = true, bool showF = true);

/// A new chart of a validation result (owned by the caller).
QChart* makeSetupValidationChart(const setup::ValidationResult& result);

}  // namespace metrofit
