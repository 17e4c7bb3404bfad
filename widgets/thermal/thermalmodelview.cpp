// ThermalModelView: the three thermal models side by side (see thermalmodelview.h).
#include "widgets/thermal/thermalmodelview.h"

#include "core/thermal/model_verdict.h"
#include "widgets/thermal/thermalverdict.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeySequence>
#include <QLabel>
#include <QListWidget>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <utility>
#include <vector>

#include "core/common/run.h"
#include "core/diagnose/thermal_applied.h"
#include "core/study/thermal_comparison.h"
#include "core/thermal/thermal_log.h"
#include "widgets/common/backgroundrun.h"
#include "widgets/common/chartexport.h"
#include "widgets/common/chartnavigation.h"
#include "widgets/common/tablecopy.h"
#include "widgets/thermal/thermalcharts.h"
#include "widgets/thermal/thermalmodelcharts.h"

namespace metrofit {
namespace {

constexpr int kProgressMax = 1000;

QString number(double v, int decimals) {
  if (!std::isfinite(v)) return QStringLiteral("—");
  const QLocale locale;
  return std::abs(v) >= 1e6 ? locale.toString(v, 'g', 3) : locale.toString(v, 'f', decimals);
}

/// Decimals for values of this size.
int decimalsFor(double scale) {
  return scale >= 100.0 ? 1 : (scale >= 1.0 ? 2 : 3);
}

/// Which models use the applied effects after a training, with the held-out RMSE of both variants:
/// "Applied effects lag:T2 (15.5 min): used by MLP; not used by GNNMCI(1,N), GMC(1,N) (held-out error
/// would rise: 0.39 → 0.46 µm, 0.48 → 17.5 µm)."
QString appliedChoiceText(const ThermalComparison& r, const QString& unit) {
  double scale = 0.0;
  for (double v : r.series.target) scale = std::max(scale, std::abs(v));
  const int dec = decimalsFor(scale);
  const QString u = unit.isEmpty() ? QString() : QLatin1Char(' ') + unit;
  QStringList used, usedChange, notUsed, notUsedChange;
  bool allRise = true;
  for (std::size_t i = 0; i < kThermalModelOrder.size(); ++i) {
    if (!r.fitted(i)) continue;  // not fitted: said in the table and the status
    const QString change =
        ThermalModelView::tr("%1 → %2%3")
            .arg(number(r.declaredHeldoutRmse[i], dec), number(r.appliedHeldoutRmse[i], dec), u);
    if (r.usesApplied[i]) {
      used << thermalModelName(kThermalModelOrder[i]);
      usedChange << change;
    } else {
      notUsed << thermalModelName(kThermalModelOrder[i]);
      notUsedChange << change;
      allRise = allRise && r.appliedHeldoutRmse[i] > r.declaredHeldoutRmse[i];
    }
  }
  const QString sep = QStringLiteral(", ");
  QStringList parts;
  if (!used.isEmpty()) {
    parts << ThermalModelView::tr("used by %1 (held-out error %2)").arg(used.join(sep), usedChange.join(sep));
  }
  if (!notUsed.isEmpty()) {
    parts << (allRise ? ThermalModelView::tr("not used by %1 (held-out error would rise: %2)")
                      : ThermalModelView::tr("not used by %1 (held-out error would not fall: %2)"))
                 .arg(notUsed.join(sep), notUsedChange.join(sep));
  }
  return ThermalModelView::tr("Applied effects %1: %2.")
      .arg(QString::fromStdString(r.appliedText), parts.join(QStringLiteral("; ")));
}

QChartView* newChartView(QWidget* parent, int minHeight) {
  auto* view = new QChartView(parent);
  view->setRenderHint(QPainter::Antialiasing);
  view->setMinimumHeight(minHeight);
  enableChartExport(view, QStringLiteral("thermal-models"));
  enableChartNavigation(view);
  return view;
}

void replaceChart(QChartView* view, QChart* chart) {
  QChart* old = view->chart();
  view->setChart(chart);
  delete old;
}

/// A table exactly as tall as its header and rows (no inner scroll bar): the header's size hint, as
/// its height is 0 until the table is laid out.
void fitRows(QTableWidget* table) {
  int h = table->horizontalHeader()->sizeHint().height() + 2 * table->frameWidth();
  for (int r = 0; r < table->rowCount(); ++r) h += table->rowHeight(r);
  table->setMinimumHeight(h);
  table->setMaximumHeight(h);
}

QTableWidgetItem* cell(const QString& text, bool left = false) {
  auto* item = new QTableWidgetItem(text);
  item->setTextAlignment(left ? (Qt::AlignLeft | Qt::AlignVCenter) : (Qt::AlignRight | Qt::AlignVCenter));
  return item;
}

}  // namespace

struct ThermalModelView::Impl {
  ThermalModelView* q = nullptr;
  ThermalLog log;
  std::shared_ptr<ThermalComparison> result;
  std::shared_ptr<const ModularComparison> modular;
  ThermalLog modularLog;

  // Controls.
  QComboBox* target = nullptr;
  QListWidget* inputs = nullptr;
  QDoubleSpinBox* fraction = nullptr;
  QSpinBox* seed = nullptr;
  QPushButton* trainButton = nullptr;
  QPushButton* cancelButton = nullptr;
  QProgressBar* progress = nullptr;
  QLabel* status = nullptr;
  QLabel* appliedLabel = nullptr;
  nlohmann::json applied = nlohmann::json::array();  ///< studies.diagnosis.thermal.applied for this log
  QChartView* trainingChart = nullptr;
  // Results.
  QChartView* comparisonChart = nullptr;
  QChartView* residualChart = nullptr;
  QTableWidget* metrics = nullptr;
  QGroupBox* modularGroup = nullptr;
  QLabel* modularHeadline = nullptr;
  QTabWidget* resultTabs = nullptr;
  QLabel* modularText = nullptr;
  QTableWidget* modularTable = nullptr;
  QLabel* modularModules = nullptr;
  QChartView* modularChart = nullptr;
  QTableWidget* modulesTable = nullptr;
  QPushButton* saveModules = nullptr;
  QPushButton* modulesCancel = nullptr;
  QProgressBar* modulesProgress = nullptr;
  QLabel* modulesMessage = nullptr;
  bool modulesRunning = false;

  // Training state.
  BackgroundRun<std::shared_ptr<ThermalComparison>>* run = nullptr;
  mutable std::mutex liveMutex;
  std::vector<double> liveBest;  ///< best fitness per PSO iteration, appended by the worker
  int liveCount = 0;
  QTimer* refresh = nullptr;
  QString targetUnit;

  ThermalModelSettings readControls() const {
    ThermalModelSettings s;
    s.target = target->currentData().toString().toStdString();
    for (int i = 0; i < inputs->count(); ++i) {
      const QListWidgetItem* item = inputs->item(i);
      if (item->checkState() == Qt::Checked && !item->isHidden())
        s.inputs.push_back(item->data(Qt::UserRole).toString().toStdString());
    }
    s.trainFraction = fraction->value();
    s.seed = static_cast<std::uint64_t>(seed->value());
    s.applied = applied;
    return s;
  }

  /// The line that says which applied effects the models use (hidden when none): before a training
  /// (or when the settings changed since) that each model will be fitted with and without them, after
  /// it which models keep them.
  void updateAppliedLabel() {
    if (!applied.is_array() || !applied.empty()) {
      const ThermalModelSettings s = readControls();
      try {
        const diagnose::AppliedThermalEffects a =
            diagnose::appliedThermalEffects(s.applied, log, s.target, s.inputs);
        if (result && !result->cancelled && result->settings == s && !result->appliedText.empty()) {
          appliedLabel->setText(appliedChoiceText(*result, targetUnit));
        } else {
          appliedLabel->setText(
              ThermalModelView::tr("Applied effects %1: Train (Ctrl+R) fits each model with "
                                   "and without them and keeps the lower held-out error.")
                  .arg(QString::fromStdString(a.text())));
        }
        appliedLabel->setToolTip(ThermalModelView::tr(
            "Effects added with Apply on the Diagnosis page (lagged inputs, extra input columns, a drift "
            "term, generic effects as the curve, step or levels the diagnosis fitted). Each model is fitted "
            "with the declared inputs and with the effects (same seed) and keeps "
            "the variant with the lower held-out error: an effect never makes a model worse on the held-out "
            "rows. Undo the Apply to fit the declared model only."));
      } catch (const std::exception& e) {
        appliedLabel->setText(
            ThermalModelView::tr("Applied effects cannot be used: %1").arg(QString::fromStdString(e.what())));
        appliedLabel->setToolTip(QString());
      }
      appliedLabel->setVisible(true);
    } else {
      appliedLabel->clear();
      appliedLabel->setVisible(false);
    }
  }

  void writeControls(const ThermalModelSettings& s) {
    const QSignalBlocker b1(target), b2(inputs), b3(fraction), b4(seed);
    const int t = target->findData(QString::fromStdString(s.target));
    target->setCurrentIndex(std::max(t, 0));
    const QString targetName = target->currentData().toString();
    for (int i = 0; i < inputs->count(); ++i) {
      QListWidgetItem* item = inputs->item(i);
      const std::string name = item->data(Qt::UserRole).toString().toStdString();
      item->setHidden(item->data(Qt::UserRole).toString() == targetName);
      item->setCheckState(
          std::find(s.inputs.begin(), s.inputs.end(), name) != s.inputs.end() ? Qt::Checked : Qt::Unchecked);
    }
    fraction->setValue(s.trainFraction);
    seed->setValue(static_cast<int>(std::min<std::uint64_t>(s.seed, std::numeric_limits<int>::max())));
    const int ti = log.indexOf(targetName.toStdString());
    targetUnit = ti >= 0 ? displayUnit(log.channels[static_cast<std::size_t>(ti)].unit) : QString();
    applied = s.applied;
    updateAppliedLabel();
  }

  void setRunning(bool running) {
    trainButton->setEnabled(!running);
    cancelButton->setEnabled(running);
    target->setEnabled(!running);
    inputs->setEnabled(!running);
    fraction->setEnabled(!running);
    seed->setEnabled(!running);
  }

  void clearResults() {
    result.reset();
    replaceChart(comparisonChart, new QChart);
    replaceChart(residualChart, new QChart);
    metrics->setRowCount(0);
  }

  void updateTrainingChart() {
    std::vector<double> best;
    {
      const std::lock_guard lock(liveMutex);
      best = liveBest;
    }
    const QString unit =
        targetUnit.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(targetUnit + QStringLiteral("²"));
    QChart* chart = makeTrainingChart(best, ThermalModelView::tr("fitness"));
    chart->setToolTip(
        ThermalModelView::tr("Best Eq. 2.9 fitness (sum of squared residuals%1) per PSO iteration")
            .arg(unit));
    replaceChart(trainingChart, chart);
  }

  void show(std::shared_ptr<ThermalComparison> c) {
    result = std::move(c);
    const ThermalComparison& r = *result;
    ModelChartOptions o;  // no titles: the axes say what is drawn, and the space is needed
    replaceChart(comparisonChart, makeModelComparisonChart(log, r, o));
    o.legend = false;
    replaceChart(residualChart, makeResidualChart(log, r, o));
    {
      const std::lock_guard lock(liveMutex);
      liveBest.clear();
      for (const IterationSummary& s : r.models[0].training.run.trace) liveBest.push_back(s.best);
    }
    updateTrainingChart();

    double scale = 0.0;
    for (double v : r.series.target) scale = std::max(scale, std::abs(v));
    const int dec = decimalsFor(scale);
    metrics->clearSpans();
    metrics->setRowCount(0);
    // A row across the columns must not widen its first column: its text is set after the sizing.
    std::vector<std::pair<QTableWidgetItem*, QString>> notFittedRows;
    for (std::size_t i = 0; i < kThermalModelOrder.size(); ++i) {
      const thermal::ThermalEvaluation& ev = r.models[i];
      if (!r.failed[i].empty()) {
        // One row: the model's name and why it could not be fitted, across the figures' columns.
        const int row = metrics->rowCount();
        metrics->insertRow(row);
        metrics->setItem(row, 0, cell(thermalModelName(kThermalModelOrder[i]), true));
        const QString reason = QString::fromStdString(r.failed[i]);
        QTableWidgetItem* why = cell(QString(), true);  // the text after the columns are sized
        why->setToolTip(reason);
        why->setForeground(QColor(0xb0, 0x20, 0x20));
        metrics->setItem(row, 1, why);
        metrics->setSpan(row, 1, 1, metrics->columnCount() - 1);
        notFittedRows.push_back({why, ThermalModelView::tr("not fitted: %1").arg(reason)});
        continue;
      }
      if (!r.fitted(i)) continue;
      for (int part = 0; part < 2; ++part) {
        const thermal::ThermalMetrics& m = part == 0 ? ev.fit : ev.heldout;
        const int row = metrics->rowCount();
        metrics->insertRow(row);
        metrics->setItem(row, 0, cell(part == 0 ? thermalModelName(kThermalModelOrder[i]) : QString(), true));
        metrics->setItem(row, 1,
                         cell(part == 0 ? ThermalModelView::tr("fit (%1)").arg(m.n)
                                        : ThermalModelView::tr("held out (%1)").arg(m.n),
                              true));
        // A model whose output runs away (an unstable GMC) gets "diverges" instead of numbers
        // like 1e+68 that nobody can read; the tooltip gives the reason.
        const bool runaway = thermal::diverges(m, scale);
        if (runaway) {
          for (int c = 2; c <= 5; ++c) metrics->setItem(row, c, cell(ThermalModelView::tr("diverges")));
        } else {
          metrics->setItem(row, 2, cell(number(m.r, 4)));
          metrics->setItem(row, 3, cell(number(m.rmse, dec)));
          metrics->setItem(row, 4, cell(number(m.e, 4)));
          metrics->setItem(row, 5, cell(QStringLiteral("±") + number(m.residualBand, dec)));
        }
        // The verdict (core/thermal/model_verdict.h) on the held-out row: usable for compensation or not,
        // and why not.
        if (part == 1) {
          const thermal::ModelVerdict v = thermal::judgeThermalModel(ev.heldout, scale);
          const QString reason = thermalVerdictReason(v, ev.heldout);
          // The label in the cell (a table cell would elide a long reason); the reason in the tooltip
          // and in full in the status text below the Train button.
          QTableWidgetItem* verdict = cell(thermalVerdictLabel(v), true);
          verdict->setToolTip(reason);
          if (v != thermal::ModelVerdict::Usable) verdict->setForeground(QColor(0xb0, 0x20, 0x20));
          metrics->setItem(row, 6, verdict);
        }
        if (i == 1 && ev.training.model.grey.b1 <= 0.0) {
          metrics->item(row, 0)->setToolTip(
              ThermalModelView::tr("Least squares gave an unstable GMC(1,N): b1 = %1 ≤ 0; its output grows "
                                   "without bound on the held-out rows")
                  .arg(QLocale().toString(ev.training.model.grey.b1, 'g', 4)));
        }
      }
    }
    const QString u = targetUnit.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(targetUnit);
    metrics->setHorizontalHeaderLabels({ThermalModelView::tr("model"), ThermalModelView::tr("rows"),
                                        ThermalModelView::tr("R"), ThermalModelView::tr("RMSE") + u,
                                        ThermalModelView::tr("E"), ThermalModelView::tr("band") + u,
                                        ThermalModelView::tr("verdict")});
    metrics->resizeColumnsToContents();
    for (const auto& [item, text] : notFittedRows) item->setText(text);

    QStringList parts, notFitted;
    for (std::size_t i = 0; i < kThermalModelOrder.size(); ++i) {
      const thermal::ThermalEvaluation& ev = r.models[i];
      if (!r.failed[i].empty()) {
        notFitted << ThermalModelView::tr("%1 not fitted: %2.")
                         .arg(thermalModelName(kThermalModelOrder[i]), QString::fromStdString(r.failed[i]));
        continue;
      }
      if (!r.fitted(i)) continue;
      QString p = ThermalModelView::tr("%1 %2 s")
                      .arg(thermalModelName(kThermalModelOrder[i]))
                      .arg(QLocale().toString(r.seconds[i], 'f', 2));
      if (i == 1 && ev.training.model.grey.b1 <= 0.0) p += ThermalModelView::tr(" (unstable: b1 ≤ 0)");
      parts << p;
    }
    // The best usable model by held-out RMSE, named; or none.
    int best = -1;
    QStringList notUsable;
    for (std::size_t i = 0; i < kThermalModelOrder.size(); ++i) {
      const thermal::ThermalEvaluation& ev = r.models[i];
      if (!r.fitted(i)) continue;  // never the best: it has no figures
      const thermal::ModelVerdict v = thermal::judgeThermalModel(ev.heldout, scale);
      if (v != thermal::ModelVerdict::Usable) {
        notUsable << thermalModelName(kThermalModelOrder[i]) + QStringLiteral(" ") + thermalVerdictLabel(v) +
                         QStringLiteral(": ") + thermalVerdictReason(v, ev.heldout) + QLatin1Char('.');
        continue;
      }
      if (best < 0 || ev.heldout.rmse < r.models[static_cast<std::size_t>(best)].heldout.rmse)
        best = static_cast<int>(i);
    }
    const QString bestText =
        best >= 0 ? ThermalModelView::tr("Best usable model: %1.")
                        .arg(thermalModelName(kThermalModelOrder[static_cast<std::size_t>(best)]))
                  : ThermalModelView::tr(
                        "No model is usable for compensation: record a longer test or add "
                        "the inputs the diagnosis finds.");
    status->setText(ThermalModelView::tr("%1 fit rows, %2 held out; %3.")
                        .arg(r.fitRows)
                        .arg(r.heldoutRows)
                        .arg(parts.join(QStringLiteral(", "))) +
                    QLatin1Char(' ') + bestText +
                    (notUsable.isEmpty() ? QString() : QLatin1Char(' ') + notUsable.join(QLatin1Char(' '))) +
                    (notFitted.isEmpty() ? QString() : QLatin1Char(' ') + notFitted.join(QLatin1Char(' '))));
    progress->setValue(kProgressMax);
    updateAppliedLabel();
  }

  void showModular() {
    const bool visible = modular && !modular->cancelled;
    resultTabs->setTabVisible(1, visible);
    modularHeadline->setVisible(visible);
    if (!visible) return;
    const ModularComparison& m = *modular;
    // A model that could not be fitted on the tests says so instead of a reduction.
    const auto reduction = [&m](std::size_t i) {
      return m.fitted(i)
                 ? QLocale().toString(m.models[i].reductionPeak * 100.0, 'f', 1) + QStringLiteral(" %")
                 : ThermalModelView::tr("not fitted");
    };
    modularHeadline->setText(ThermalModelView::tr("<b>Modular case:</b> GNNMCI(1,N) fitted on the Z and C "
                                                  "tests reduces the combined test's error by %1 (GMC(1,N) "
                                                  "%2, MLP %3).")
                                 .arg(reduction(0), reduction(1), reduction(2)));
    modularTable->clearSpans();
    modularTable->setRowCount(0);
    std::vector<std::pair<QTableWidgetItem*, QString>> notFittedRows;
    QString unit;
    if (const int ti = modularLog.indexOf(m.target); ti >= 0)
      unit = displayUnit(modularLog.channels[static_cast<std::size_t>(ti)].unit);
    for (std::size_t i = 0; i < kThermalModelOrder.size(); ++i) {
      const thermal::ModularEvaluation& ev = m.models[i];
      const int row = modularTable->rowCount();
      modularTable->insertRow(row);
      modularTable->setItem(row, 0, cell(thermalModelName(kThermalModelOrder[i]), true));
      if (!m.failed[i].empty() || !m.fitted(i)) {
        const QString reason = QString::fromStdString(m.failed[i]);
        QTableWidgetItem* why = cell(QString(), true);  // the text after the columns are sized
        why->setToolTip(reason);
        why->setForeground(QColor(0xb0, 0x20, 0x20));
        modularTable->setItem(row, 1, why);
        modularTable->setSpan(row, 1, 1, modularTable->columnCount() - 1);
        notFittedRows.push_back({why, ThermalModelView::tr("not fitted: %1").arg(reason)});
        continue;
      }
      if (thermal::diverges(ev.test, ev.errorPeak)) {  // a runaway prediction: no 1e+305 figures
        for (int c = 1; c <= 5; ++c) modularTable->setItem(row, c, cell(ThermalModelView::tr("diverges")));
        continue;
      }
      modularTable->setItem(
          row, 1, cell(number(ev.errorPeak, 1) + QStringLiteral(" → ±") + number(ev.residualPeak, 1)));
      modularTable->setItem(row, 2, cell(number(100.0 * ev.reductionPeak, 1)));
      modularTable->setItem(row, 3, cell(number(ev.test.rmse, 2)));
      modularTable->setItem(row, 4, cell(number(100.0 * ev.reductionRms, 1)));
      modularTable->setItem(row, 5, cell(number(ev.test.e, 4)));
    }
    // The same case module by module: each identified on its own test, the combined test their sum.
    QStringList parts;
    if (const auto& ev = m.modules.evaluation) {
      const int row = modularTable->rowCount();
      modularTable->insertRow(row);
      modularTable->setItem(row, 0, cell(ThermalModelView::tr("modules, summed (distributed lag)"), true));
      modularTable->setItem(
          row, 1, cell(number(ev->errorPeak, 1) + QStringLiteral(" → ±") + number(ev->residualPeak, 1)));
      modularTable->setItem(row, 2, cell(number(100.0 * ev->reductionPeak, 1)));
      modularTable->setItem(row, 3, cell(number(ev->test.rmse, 2)));
      modularTable->setItem(row, 4, cell(number(100.0 * ev->reductionRms, 1)));
      modularTable->setItem(row, 5, cell(number(ev->test.e, 4)));
      for (std::size_t i = 0; i < m.modules.names.size() && i < ev->contributions.size(); ++i) {
        const double peak = ev->contributionPeaks[i];
        QStringList inputs;
        for (const std::string& in : m.modules.inputs[i]) inputs << QString::fromStdString(in);
        parts << ThermalModelView::tr("%1 (inputs %2) contributes up to %3 %4")
                     .arg(QString::fromStdString(m.modules.names[i]), inputs.join(QStringLiteral(", ")),
                          number(peak, 1), unit);
      }
    }
    modularModules->setText(
        m.modules.evaluation ? ThermalModelView::tr("Module by module, each identified on its own test: %1.")
                                   .arg(parts.join(QStringLiteral("; ")))
                             : ThermalModelView::tr("Module by module: not identified (%1).")
                                   .arg(QString::fromStdString(m.modules.why)));
    updateModulesTable(m, unit);
    modularTable->setHorizontalHeaderLabels(
        {ThermalModelView::tr("model"), ThermalModelView::tr("error → band (%1)").arg(unit),
         ThermalModelView::tr("less (peak, %)"), ThermalModelView::tr("RMSE (%1)").arg(unit),
         ThermalModelView::tr("less (RMS, %)"), ThermalModelView::tr("E")});
    modularTable->resizeColumnsToContents();
    for (const auto& [item, text] : notFittedRows) item->setText(text);
    // Every row visible (the pooled models and the modules' row), no inner scroll bar.
    fitRows(modularTable);
    ModelChartOptions o;
    o.legend = true;
    replaceChart(modularChart, makeModularChart(modularLog, m, o));
  }

  /// One row per module: its name, the test it is identified on, its inputs, its contribution and
  /// "Identify again…"; Save module models… when every module is identified.
  void updateModulesTable(const ModularComparison& m, const QString& unit) {
    const ModularModules& mm = m.modules;
    modulesTable->setRowCount(0);
    for (std::size_t i = 0; i < mm.names.size(); ++i) {
      const int row = modulesTable->rowCount();
      modulesTable->insertRow(row);
      modulesTable->setItem(row, 0, cell(QString::fromStdString(mm.names[i]), true));
      modulesTable->setItem(
          row, 1, cell(QString::fromStdString(i < mm.tests.size() ? mm.tests[i] : mm.names[i]), true));
      QStringList inputs;
      if (i < mm.inputs.size())
        for (const std::string& in : mm.inputs[i]) inputs << QString::fromStdString(in);
      modulesTable->setItem(row, 2, cell(inputs.join(QStringLiteral(", ")), true));
      const bool identified = mm.evaluation && i < mm.evaluation->contributionPeaks.size();
      modulesTable->setItem(
          row, 3,
          cell(identified ? number(mm.evaluation->contributionPeaks[i], 1) + QLatin1Char(' ') + unit
                          : ThermalModelView::tr("not identified")));
      auto* again = new QPushButton(ThermalModelView::tr("Identify again…"), modulesTable);
      again->setObjectName(QStringLiteral("thermalModuleIdentify%1").arg(row));
      again->setToolTip(
          ThermalModelView::tr("Identify this module again on another test of its drive (a "
                               "thermal log of the project); the other modules keep their "
                               "models"));
      again->setEnabled(identified && !modulesRunning);
      QObject::connect(again, &QPushButton::clicked, q,
                       [this, row] { emit q->identifyModuleRequested(row); });
      modulesTable->setCellWidget(row, 4, again);
    }
    modulesTable->setHorizontalHeaderLabels(
        {ThermalModelView::tr("module"), ThermalModelView::tr("identified on"),
         ThermalModelView::tr("inputs"), ThermalModelView::tr("contribution (peak)"), QString()});
    modulesTable->resizeColumnsToContents();
    modulesTable->horizontalHeader()->setSectionResizeMode(2, QHeaderView::Stretch);
    fitRows(modulesTable);
    saveModules->setEnabled(mm.evaluation.has_value() && !modulesRunning);
  }

  /// The worker's observer: records the PSO trace, reports progress (the first model to 80 %, the
  /// second at 80 %, the third from 85 %) with the model's name, honours Cancel.
  ThermalComparisonObserver observer(RunObserver& run) {
    return [this, &run](int model, const IterationSummary& s) {
      if (model == 0) {
        const std::lock_guard lock(liveMutex);
        liveBest.push_back(s.best);
        ++liveCount;
      }
      const double fraction = s.progress >= 0.0 ? s.progress : 0.0;
      const double overall = model == 0 ? 0.8 * fraction : model == 1 ? 0.8 : 0.85 + 0.15 * fraction;
      run.report(overall, ThermalModelView::tr("%1: %p%").arg(thermalModelName(kThermalModelOrder[model])));
      return run.isCancelled() ? ObserverDecision::Stop : ObserverDecision::Continue;
    };
  }
};

ThermalModelView::ThermalModelView(QWidget* parent) : QWidget(parent), d(std::make_unique<Impl>()) {
  d->q = this;
  d->target = new QComboBox(this);
  d->target->setObjectName(QStringLiteral("thermalModelTarget"));
  d->target->setToolTip(tr("The column the models predict (the thermal error)"));
  d->inputs = new QListWidget(this);
  d->inputs->setObjectName(QStringLiteral("thermalModelInputs"));
  d->inputs->setToolTip(tr("Sensor columns the models take as inputs"));
  d->fraction = new QDoubleSpinBox(this);
  d->fraction->setObjectName(QStringLiteral("thermalModelTrainFraction"));
  d->fraction->setRange(0.01, 0.99);  // the study takes (0, 1); the page refuses what this cannot show
  d->fraction->setSingleStep(0.05);
  d->fraction->setDecimals(2);
  d->fraction->setValue(ThermalModelSettings{}.trainFraction);
  d->fraction->setToolTip(tr("The first fraction of the rows fits the models; the rest is held out"));
  d->seed = new QSpinBox(this);
  d->seed->setObjectName(QStringLiteral("thermalModelSeed"));
  d->seed->setRange(0, std::numeric_limits<int>::max());
  d->seed->setValue(1);
  d->seed->setToolTip(tr("Seed of the PSO swarm and of the MLP's initial weights (same seed, same result)"));
  d->trainButton = new QPushButton(tr("&Train"), this);
  d->trainButton->setObjectName(QStringLiteral("thermalModelTrain"));
  d->trainButton->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
  d->trainButton->setToolTip(
      tr("Fit GNNMCI(1,N) (PSO), GMC(1,N) (least squares) and the MLP (Levenberg-Marquardt) "
         "(Ctrl+R)"));
  d->cancelButton = new QPushButton(tr("Cancel"), this);
  d->cancelButton->setObjectName(QStringLiteral("thermalModelCancel"));
  d->cancelButton->setShortcut(QKeySequence(Qt::Key_Escape));
  d->cancelButton->setEnabled(false);
  d->cancelButton->setToolTip(tr("Stop the training (Esc)"));
  d->progress = new QProgressBar(this);
  d->progress->setRange(0, kProgressMax);
  d->progress->setValue(0);
  d->status = new QLabel(this);
  d->status->setObjectName(QStringLiteral("thermalModelStatus"));
  d->status->setWordWrap(true);
  d->status->setTextInteractionFlags(Qt::TextSelectableByMouse);
  d->appliedLabel = new QLabel(this);
  d->appliedLabel->setObjectName(QStringLiteral("thermalModelApplied"));
  d->appliedLabel->setWordWrap(true);
  d->appliedLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
  d->appliedLabel->setVisible(false);
  d->trainingChart = newChartView(this, 150);
  d->trainingChart->setToolTip(tr("Best fitness of the GNNMCI(1,N) swarm (Eq. 2.9) per PSO iteration"));
  d->refresh = new QTimer(this);
  d->refresh->setSingleShot(true);
  d->refresh->setInterval(100);
  connect(d->refresh, &QTimer::timeout, this, [this] { d->updateTrainingChart(); });

  auto* form = new QFormLayout;
  form->setContentsMargins(0, 0, 0, 0);
  form->addRow(tr("T&arget:"), d->target);
  form->addRow(tr("Train &fraction:"), d->fraction);
  form->addRow(tr("S&eed:"), d->seed);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(d->trainButton);
  buttons->addWidget(d->cancelButton);
  auto* controls = new QWidget(this);
  auto* side = new QVBoxLayout(controls);
  side->setContentsMargins(0, 0, 0, 0);
  side->addLayout(form);
  auto* inputsLabel = new QLabel(tr("&Inputs:"), controls);
  inputsLabel->setBuddy(d->inputs);
  side->addWidget(inputsLabel);
  side->addWidget(d->inputs, 1);
  side->addWidget(d->appliedLabel);
  side->addLayout(buttons);
  side->addWidget(d->progress);
  side->addWidget(d->status);
  side->addWidget(d->trainingChart, 1);
  controls->setMinimumWidth(220);
  controls->setMaximumWidth(280);

  d->comparisonChart = newChartView(this, 200);
  d->comparisonChart->setObjectName(QStringLiteral("thermalModelComparisonChart"));
  d->residualChart = newChartView(this, 130);
  d->residualChart->setObjectName(QStringLiteral("thermalModelResidualChart"));
  d->metrics = new QTableWidget(0, 7, this);
  enableTableCopy(d->metrics);
  d->metrics->setObjectName(QStringLiteral("thermalModelMetrics"));
  d->metrics->setHorizontalHeaderLabels(
      {tr("model"), tr("rows"), tr("R"), tr("RMSE"), tr("E"), tr("band"), tr("verdict")});
  d->metrics->horizontalHeaderItem(2)->setToolTip(tr("Correlation coefficient of measured and predicted"));
  d->metrics->horizontalHeaderItem(3)->setToolTip(
      tr("Root mean square of the residual, in the target's unit"));
  d->metrics->horizontalHeaderItem(4)->setToolTip(tr("Nash-Sutcliffe efficiency coefficient (1: perfect)"));
  d->metrics->horizontalHeaderItem(5)->setToolTip(tr("Largest |residual|, in the target's unit"));
  d->metrics->horizontalHeaderItem(6)->setToolTip(
      tr("Usable for compensation when on the held-out rows it does not diverge, E ≥ %1 and R ≥ %2")
          .arg(QLocale().toString(thermal::kMinEfficiency, 'f', 0),
               QLocale().toString(thermal::kMinCorrelation, 'f', 1)));
  d->metrics->verticalHeader()->setVisible(false);
  d->metrics->setEditTriggers(QAbstractItemView::NoEditTriggers);

  d->modularGroup = new QGroupBox(tr("Modular models (Section 4.3)"), this);
  d->modularGroup->setObjectName(QStringLiteral("thermalModularGroup"));
  d->modularText = new QLabel(d->modularGroup);
  d->modularText->setWordWrap(true);
  d->modularTable = new QTableWidget(0, 6, d->modularGroup);
  enableTableCopy(d->modularTable);
  d->modularTable->setObjectName(QStringLiteral("thermalModularTable"));
  d->modularTable->verticalHeader()->setVisible(false);
  d->modularTable->setEditTriggers(QAbstractItemView::NoEditTriggers);
  d->modularTable->verticalHeader()->setDefaultSectionSize(22);
  d->modularTable->setMaximumHeight(5 * 22 + 8);
  d->modularModules = new QLabel(d->modularGroup);
  d->modularModules->setObjectName(QStringLiteral("thermalModularModules"));
  d->modularModules->setWordWrap(true);
  d->modularTable->horizontalHeader()->setStretchLastSection(true);
  d->modularChart = newChartView(d->modularGroup, 220);
  d->modulesTable = new QTableWidget(0, 5, d->modularGroup);
  enableTableCopy(d->modulesTable);
  d->modulesTable->setObjectName(QStringLiteral("thermalModulesTable"));
  d->modulesTable->verticalHeader()->setVisible(false);
  d->modulesTable->verticalHeader()->setDefaultSectionSize(26);
  d->modulesTable->setEditTriggers(QAbstractItemView::NoEditTriggers);
  d->modulesTable->horizontalHeader()->setStretchLastSection(false);
  d->modulesTable->setMaximumHeight(3 * 26 + 8);
  d->saveModules = new QPushButton(tr("Save module models…"), d->modularGroup);
  d->saveModules->setObjectName(QStringLiteral("thermalSaveModules"));
  d->saveModules->setToolTip(
      tr("Write each module's fitted model to a folder as NAME.json (the files of metrofit-cli thermal "
         "modular --save-modules)"));
  d->saveModules->setEnabled(false);
  d->modulesCancel = new QPushButton(tr("Cancel"), d->modularGroup);
  d->modulesCancel->setObjectName(QStringLiteral("thermalModulesCancel"));
  d->modulesCancel->setToolTip(tr("Stop identifying the module; the modules shown stay"));
  d->modulesCancel->setEnabled(false);
  d->modulesProgress = new QProgressBar(d->modularGroup);
  d->modulesProgress->setObjectName(QStringLiteral("thermalModulesProgress"));
  d->modulesProgress->setRange(0, kProgressMax);
  d->modulesProgress->setValue(0);
  d->modulesProgress->setVisible(false);
  d->modulesMessage = new QLabel(d->modularGroup);
  d->modulesMessage->setObjectName(QStringLiteral("thermalModulesMessage"));
  d->modulesMessage->setWordWrap(true);
  d->modulesMessage->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* modulesActions = new QHBoxLayout;
  modulesActions->addWidget(d->saveModules);
  modulesActions->addWidget(d->modulesProgress, 1);
  modulesActions->addWidget(d->modulesCancel);
  modulesActions->addWidget(d->modulesMessage, 2);
  auto* modularLayout = new QVBoxLayout(d->modularGroup);
  modularLayout->setContentsMargins(4, 4, 4, 4);
  modularLayout->addWidget(d->modularText);
  modularLayout->addWidget(d->modularTable);
  modularLayout->addWidget(d->modularModules);
  modularLayout->addWidget(d->modulesTable);
  modularLayout->addLayout(modulesActions);
  modularLayout->addWidget(d->modularChart, 1);
  connect(d->saveModules, &QPushButton::clicked, this, &ThermalModelView::saveModulesRequested);
  connect(d->modulesCancel, &QPushButton::clicked, this, &ThermalModelView::modulesCancelRequested);
  d->modularHeadline = new QLabel(this);
  d->modularHeadline->setObjectName(QStringLiteral("thermalModularHeadline"));
  d->modularHeadline->setWordWrap(true);
  d->modularHeadline->setVisible(false);
  side->insertWidget(side->indexOf(d->trainingChart), d->modularHeadline);

  d->metrics->verticalHeader()->setDefaultSectionSize(20);
  d->metrics->horizontalHeader()->setStretchLastSection(true);
  auto* bottom = new QWidget(this);
  auto* metricsBox = new QVBoxLayout(bottom);
  metricsBox->setContentsMargins(0, 0, 0, 0);
  metricsBox->addWidget(new QLabel(tr("Performance indices (Table 4)"), bottom));
  metricsBox->addWidget(d->metrics, 1);

  auto* splitter = new QSplitter(Qt::Vertical, this);
  splitter->setObjectName(QStringLiteral("thermalModelsSplitter"));
  splitter->addWidget(d->comparisonChart);
  splitter->addWidget(d->residualChart);
  splitter->addWidget(bottom);
  splitter->setStretchFactor(0, 5);
  splitter->setStretchFactor(1, 3);
  splitter->setStretchFactor(2, 3);
  splitter->setChildrenCollapsible(false);
  splitter->setSizes({280, 210, 160});

  d->resultTabs = new QTabWidget(this);
  d->resultTabs->setObjectName(QStringLiteral("thermalModelResultTabs"));
  d->resultTabs->addTab(splitter, tr("Comparison"));
  d->resultTabs->addTab(d->modularGroup, tr("Modular (Z + C → combined)"));
  d->resultTabs->setTabVisible(1, false);

  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(controls);
  layout->addWidget(d->resultTabs, 1);

  d->run = new BackgroundRun<std::shared_ptr<ThermalComparison>>(this);
  connect(d->run, &BackgroundRunBase::progress, this, [this](double fraction, const QString& text) {
    d->progress->setValue(static_cast<int>(fraction * kProgressMax));
    if (!text.isEmpty()) d->progress->setFormat(text);
    if (!d->refresh->isActive()) d->refresh->start();
  });
  const auto ended = [this] {
    d->setRunning(false);
    d->refresh->stop();
    const std::optional<std::shared_ptr<ThermalComparison>> r = d->run->takeResult();
    if (!r || !*r || (*r)->cancelled) {
      d->updateTrainingChart();
      d->status->setText(
          tr("Training cancelled after %1 PSO iterations; the results shown are the previous ones.")
              .arg(liveIterations()));
      d->progress->setValue(0);
      emit trainingFinished(false);
      return;
    }
    d->show(*r);
    emit trainingFinished(true);
  };
  connect(d->run, &BackgroundRunBase::finished, this, ended);
  connect(d->run, &BackgroundRunBase::cancelled, this, ended);
  connect(d->run, &BackgroundRunBase::failed, this, [this](const QString& message) {
    d->setRunning(false);
    d->refresh->stop();
    d->status->setText(tr("Training failed: %1").arg(message));
    d->progress->setValue(0);
    emit trainingFinished(false);
  });

  auto edited = [this] {
    d->updateAppliedLabel();
    if (d->result) d->status->setText(tr("Settings changed: Train (Ctrl+R) to update the results."));
    emit settingsEdited();
  };
  connect(d->target, &QComboBox::currentIndexChanged, this, [this, edited] {
    const QString name = d->target->currentData().toString();
    const QSignalBlocker blocker(d->inputs);
    for (int i = 0; i < d->inputs->count(); ++i) {
      QListWidgetItem* item = d->inputs->item(i);
      item->setHidden(item->data(Qt::UserRole).toString() == name);
    }
    const int ti = d->log.indexOf(name.toStdString());
    d->targetUnit = ti >= 0 ? displayUnit(d->log.channels[static_cast<std::size_t>(ti)].unit) : QString();
    edited();
  });
  connect(d->inputs, &QListWidget::itemChanged, this, edited);
  connect(d->fraction, &QDoubleSpinBox::valueChanged, this, edited);
  connect(d->seed, &QSpinBox::valueChanged, this, edited);
  connect(d->trainButton, &QPushButton::clicked, this, &ThermalModelView::train);
  connect(d->cancelButton, &QPushButton::clicked, this, &ThermalModelView::cancel);
}

ThermalModelView::~ThermalModelView() {
  d->run->disconnect(this);
  d->run->cancel();
  d->run->waitForWorker();
}

void ThermalModelView::setLog(const ThermalLog& log, const ThermalModelSettings& settings) {
  if (isRunning()) {
    d->run->cancel();
    d->run->waitForFinished();
  }
  d->log = log;
  {
    const QSignalBlocker b1(d->target), b2(d->inputs);
    d->target->clear();
    d->inputs->clear();
    for (const ThermalChannel& c : log.channels) {
      const QString name = QString::fromStdString(c.name);
      if (channelKind(c) != ChannelKind::Speed) d->target->addItem(name, name);
      auto* item = new QListWidgetItem(name, d->inputs);
      item->setData(Qt::UserRole, name);
      item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable | Qt::ItemIsSelectable);
      item->setCheckState(Qt::Unchecked);
      item->setToolTip(channelAxisTitle(c));
    }
  }
  d->writeControls(settings);
  d->clearResults();
  d->updateAppliedLabel();
  {
    const std::lock_guard lock(d->liveMutex);
    d->liveBest.clear();
  }
  d->updateTrainingChart();
  d->progress->setValue(0);
  d->progress->resetFormat();
  d->status->setText(tr("Not trained yet: Train (Ctrl+R) fits the three models."));
}

ThermalModelSettings ThermalModelView::settings() const {
  return d->readControls();
}

void ThermalModelView::setSettings(const ThermalModelSettings& settings) {
  const bool appliedChanged = settings.applied != d->applied;
  d->writeControls(settings);
  // Apply / undo on the diagnosis page: the results shown were fitted with the other model.
  if (appliedChanged && d->result)
    d->status->setText(tr("Applied effects changed: Train (Ctrl+R) to update the results."));
}

void ThermalModelView::train() {
  if (isRunning()) return;
  const ThermalModelSettings s = d->readControls();
  if (s.inputs.empty()) {
    d->status->setText(tr("Choose at least one input."));
    return;
  }
  {
    const std::lock_guard lock(d->liveMutex);
    d->liveBest.clear();
    d->liveCount = 0;
  }
  d->updateTrainingChart();
  d->setRunning(true);
  d->progress->setValue(0);
  d->status->setText(tr("Training…"));
  const ThermalLog log = d->log;
  Impl* impl = d.get();  // outlives the run: the destructor waits for it
  d->run->start([impl, log, s](RunObserver& run) {
    return std::make_shared<ThermalComparison>(compareThermalModels(log, s, impl->observer(run)));
  });
}

bool ThermalModelView::trainNow() {
  if (isRunning()) return false;
  const ThermalModelSettings s = d->readControls();
  if (s.inputs.empty()) {
    d->status->setText(tr("Choose at least one input."));
    return false;
  }
  try {
    d->show(std::make_shared<ThermalComparison>(compareThermalModels(d->log, s)));
    {
      const std::lock_guard lock(d->liveMutex);
      d->liveCount = 0;
    }
    emit trainingFinished(true);
    return true;
  } catch (const std::exception& e) {
    d->status->setText(tr("Training failed: %1").arg(QString::fromStdString(e.what())));
    return false;
  }
}

void ThermalModelView::cancel() {
  d->run->cancel();
}

bool ThermalModelView::isRunning() const {
  return d->run->isRunning();
}

const ThermalComparison* ThermalModelView::comparison() const {
  return d->result.get();
}

void ThermalModelView::setStatusText(const QString& text) {
  d->status->setText(text);
}

QString ThermalModelView::statusText() const {
  return d->status->text();
}

int ThermalModelView::liveIterations() const {
  const std::lock_guard lock(d->liveMutex);
  return d->liveCount;
}

void ThermalModelView::setModular(std::shared_ptr<const ModularComparison> modular, const ThermalLog* testLog,
                                  const QString& description) {
  d->modular = std::move(modular);
  d->modularLog = testLog ? *testLog : ThermalLog{};
  d->modularText->setText(description);
  d->showModular();
}

QProgressBar* ThermalModelView::progressBar() const {
  return d->progress;
}
QPushButton* ThermalModelView::trainButton() const {
  return d->trainButton;
}
QPushButton* ThermalModelView::cancelButton() const {
  return d->cancelButton;
}
QTableWidget* ThermalModelView::metricsTable() const {
  return d->metrics;
}
QTableWidget* ThermalModelView::modularTable() const {
  return d->modularTable;
}
QLabel* ThermalModelView::modularModulesLabel() const {
  return d->modularModules;
}
QTableWidget* ThermalModelView::modulesTable() const {
  return d->modulesTable;
}
QPushButton* ThermalModelView::saveModulesButton() const {
  return d->saveModules;
}
QPushButton* ThermalModelView::modulesCancelButton() const {
  return d->modulesCancel;
}
QProgressBar* ThermalModelView::modulesProgressBar() const {
  return d->modulesProgress;
}

void ThermalModelView::setModulesRunning(bool running) {
  d->modulesRunning = running;
  d->modulesCancel->setEnabled(running);
  d->modulesProgress->setVisible(running);
  if (running) {
    d->modulesProgress->setValue(0);
    d->modulesProgress->resetFormat();
  }
  const bool identified = d->modular && d->modular->modules.evaluation.has_value();
  d->saveModules->setEnabled(identified && !running);
  for (int row = 0; row < d->modulesTable->rowCount(); ++row)
    if (QWidget* w = d->modulesTable->cellWidget(row, 4)) w->setEnabled(identified && !running);
}

void ThermalModelView::setModulesProgress(double fraction, const QString& text) {
  d->modulesProgress->setValue(static_cast<int>(std::clamp(fraction, 0.0, 1.0) * kProgressMax));
  if (!text.isEmpty()) d->modulesProgress->setFormat(text);
}

void ThermalModelView::setModulesMessage(const QString& text) {
  d->modulesMessage->setText(text);
}

QString ThermalModelView::modulesMessage() const {
  return d->modulesMessage->text();
}

}  // namespace metrofit
