// Report section "Thermal": per thermal log, a summary, the trend chart as vector graphics and a
// table of the channels with their ranges; the hysteresis charts with loop areas and lags; the three
// models of Abdulshahed 2016, grey neural network thermal model (GNNMCI(1,N), GMC(1,N), MLP) fitted on the
// first part and compared on the rest (chart, residuals, Table 4); and, after the combined test of the
// modular case, the combined test predicted from models fitted on the Z and C tests (Section 4.3).
//
// Run time: the models are trained here (fixed seed, default budgets). Logs longer than
// kMaxModelRows rows are fitted on every k-th row (said in the section), unless the project stores the
// Thermal page's result for the log with the same settings and data (results.thermal.<log>,
// core/project/stored_results.h): then the report fits every row as the page did, so it chooses the
// same model with the same figures (and says so). The report is laid out
// twice (report.cpp: page numbers first), so results are kept in the report's memo (ReportContext)
// keyed by the log's content and the settings.
#include <QChart>
#include <QCoreApplication>
#include <QGraphicsLayout>
#include <QGraphicsScene>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <string>

#include "core/common/numformat.h"
#include "core/diagnose/thermal_applied.h"
#include "core/project/stored_results.h"
#include "core/study/thermal_comparison.h"
#include "core/study/thermal_result.h"
#include "core/study/trend_analysis.h"
#include "core/thermal/control_export.h"
#include "core/thermal/hysteresis.h"
#include "core/thermal/model_verdict.h"
#include "widgets/report/reportpainter.h"
#include "widgets/report/sections.h"
#include "widgets/thermal/thermalcharts.h"
#include "widgets/thermal/thermalmodelcharts.h"
#include "widgets/thermal/thermalverdict.h"

namespace metrofit {
namespace {

struct ReportText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::Report)
};

constexpr double kChartHeightMm = 108.0;
constexpr double kModelChartHeightMm = 80.0;
constexpr double kResidualChartHeightMm = 55.0;
constexpr double kHysteresisCellMm = 52.0;
constexpr std::size_t kMaxModelRows = 1500;      ///< longer logs are fitted on every k-th row
constexpr std::size_t kMaxHysteresisCharts = 9;  ///< small multiples in the report

/// What the report computes for one thermal log (cached across the two layout passes).
struct ThermalResults {
  ThermalModelSettings settings;
  std::size_t stride = 1;
  /// The project stores the Thermal page's result for this log, settings and data: every row is
  /// fitted, as the page did. `pageComputed` is when the page computed it, `pageBest` its best model.
  bool asPage = false;
  std::string pageComputed, pageBest;
  ThermalLog fitted;  ///< the log the models were fitted on (decimated when long)
  thermal::ThermalSeries hysteresisSeries;
  thermal::HysteresisAnalysis hysteresis;
  QString hysteresisError;
  std::shared_ptr<ThermalComparison> comparison;
  QString modelError;
};

std::uint64_t contentHash(const ThermalLog& log, const std::string& extra) {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&h](const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 1099511628211ull;
  };
  mix(log.timeMin.data(), log.timeMin.size() * sizeof(double));
  for (const ThermalChannel& c : log.channels) {
    mix(c.name.data(), c.name.size());
    mix(c.values.data(), c.values.size() * sizeof(double));
  }
  mix(extra.data(), extra.size());
  return h;
}

std::string settingsText(const ThermalModelSettings& s) {
  std::string t = s.target + "|" + num::toString(s.trainFraction) + "|" + std::to_string(s.seed);
  for (const auto& in : s.inputs) t += "," + in;
  return t + "|" + s.applied.dump();
}

/// Hysteresis and the three models for one log (kept in the report's memo, see the header comment).
std::shared_ptr<const ThermalResults> thermalResults(const ReportContext& context,
                                                     const ReportDataset& dataset,
                                                     const ThermalModelSettings& settings) {
  const ThermalLog& log = *dataset.thermal;
  const std::uint64_t key = contentHash(log, settingsText(settings));
  return context.memo.get<ThermalResults>(std::to_string(key), [&] {
    auto r = std::make_shared<ThermalResults>();
    r->settings = settings;
    DatasetRef resolved = dataset.ref;
    resolved.path = dataset.path.toStdString();  // absolute: no project path needed
    const StoredResult stored =
        storedResult(*context.project, {}, study::kThermal, resolved, thermalSettingsJson(settings));
    if (stored.state == StoredResultState::Current) {
      r->asPage = true;
      r->pageComputed = stored.computed;
      const nlohmann::json best = stored.entry.value("best_model", nlohmann::json());
      r->pageBest = best.is_string() ? best.get<std::string>() : std::string();
    }
    r->stride =
        !r->asPage && log.rows() > kMaxModelRows ? (log.rows() + kMaxModelRows - 1) / kMaxModelRows : 1;
    r->fitted = decimateThermalLog(log, r->stride);
    try {
      r->hysteresisSeries = thermal::selectThermalSeries(r->fitted, settings.target, settings.inputs);
      r->hysteresis = thermal::analyseHysteresis(r->hysteresisSeries);
    } catch (const std::exception& e) {
      r->hysteresisError = QString::fromStdString(e.what());
    }
    try {
      r->comparison = std::make_shared<ThermalComparison>(compareThermalModels(r->fitted, settings));
    } catch (const std::exception& e) {
      r->modelError = QString::fromStdString(e.what());
    }
    return std::shared_ptr<const ThermalResults>(std::move(r));
  });
}

/// The modular case's comparison, or the error that stopped it.
struct ModularResults {
  std::shared_ptr<const ModularComparison> comparison;
  QString error;
};

/// The modular case of the project, or nullptr when it lacks one of the three tests (kept in the
/// report's memo).
std::shared_ptr<const ModularComparison> modularResults(const ReportContext& context, QString* error) {
  const ReportDataset* tests[3] = {nullptr, nullptr, nullptr};
  const char* ids[3] = {kModularZId, kModularCId, kModularCombinedId};
  for (const ReportDataset* d : context.ofKind(dataset_kind::kThermalLog)) {
    for (int i = 0; i < 3; ++i) {
      if (d->ref.id == ids[i] && d->thermal) tests[i] = d;
    }
  }
  if (!tests[0] || !tests[1] || !tests[2]) return nullptr;
  const ThermalLog& test = *tests[2]->thermal;
  const ThermalModelSettings s = defaultThermalModelSettings(test, nlohmann::json::object(), {});
  const std::vector<std::string> inputs = modularInputs(test);
  // The tests the thermal study names for the modules (studies.thermal.modules: a module identified
  // again on a new test of its drive on the Modular tab).
  const auto study = context.project->studies.find(study::kThermal);
  const nlohmann::json thermalStudy =
      study != context.project->studies.end() ? *study : nlohmann::json::object();
  const std::vector<std::string> moduleTests = studyModuleTests(thermalStudy, {kModularZId, kModularCId});
  const auto logOf = [&context](const std::string& id) -> const ThermalLog* {
    for (const ReportDataset* d : context.ofKind(dataset_kind::kThermalLog))
      if (d->ref.id == id && d->thermal) return &*d->thermal;
    return nullptr;
  };
  std::uint64_t key = contentHash(*tests[0]->thermal, "z") ^ (contentHash(*tests[1]->thermal, "c") * 3u) ^
                      (contentHash(test, s.target) * 7u);
  for (std::size_t i = 0; i < moduleTests.size(); ++i)
    if (const ThermalLog* log = logOf(moduleTests[i]))
      key ^= contentHash(*log, "module " + std::to_string(i) + " " + moduleTests[i]) * (11u + 2u * i);
  const std::shared_ptr<const ModularResults> r = context.memo.get<ModularResults>(std::to_string(key), [&] {
    auto m = std::make_shared<ModularResults>();
    try {
      auto c = std::make_shared<ModularComparison>(
          compareModularModels({&*tests[0]->thermal, &*tests[1]->thermal}, test, s.target, inputs, 1, {},
                               {kModularZId, kModularCId}));
      identifyModulesOnStudyTests(c->modules, thermalStudy, logOf, test, s.target, 1);
      m->comparison = std::move(c);
    } catch (const std::exception& e) {
      m->error = QString::fromStdString(e.what());
    }
    return std::shared_ptr<const ModularResults>(std::move(m));
  });
  if (!r->comparison && error) *error = r->error;
  return r->comparison;
}

/// Draws a chart into `target` (device units), laid out `designWidthPx` scene pixels wide; takes
/// ownership.
void renderChart(QPainter& painter, QChart* chart, const QRectF& target, double designWidthPx) {
  QGraphicsScene scene;
  scene.addItem(chart);
  chart->resize(designWidthPx, designWidthPx * target.height() / target.width());
  if (chart->layout() != nullptr) chart->layout()->activate();
  const QRectF source = chart->sceneBoundingRect();
  scene.setSceneRect(source);
  scene.render(&painter, target, source, Qt::KeepAspectRatio);
}

QString joined(const std::vector<std::string>& names) {
  QStringList l;
  for (const auto& n : names) l << QString::fromStdString(n);
  return l.join(QStringLiteral(", "));
}

QString metric(double v, int decimals) {
  if (!std::isfinite(v)) return QStringLiteral("—");
  return std::abs(v) >= 1e6 ? QString::number(v, 'g', 3) : QString::number(v, 'f', decimals);
}

/// "46.3 h" above 3 h, else "95 min".
QString formatDuration(double minutes) {
  return minutes > 180.0 ? ReportText::tr("%1 h").arg(minutes / 60.0, 0, 'f', 1)
                         : ReportText::tr("%1 min").arg(minutes, 0, 'f', minutes < 10.0 ? 1 : 0);
}

/// A value with as many decimals as the channel's range needs.
QString formatValue(double v, double range) {
  const int decimals = range >= 100.0 ? 1 : (range >= 1.0 ? 2 : 3);
  return QString::number(v, 'f', decimals);
}

double medianSpacingMin(const ThermalLog& log) {
  std::vector<double> dt;
  for (std::size_t i = 1; i < log.rows(); ++i) {
    dt.push_back(log.timeMin[i] - log.timeMin[i - 1]);
  }
  if (dt.empty()) {
    return 0.0;
  }
  std::nth_element(dt.begin(), dt.begin() + static_cast<std::ptrdiff_t>(dt.size() / 2), dt.end());
  return dt[dt.size() / 2];
}

QString formatSpacing(double minutes) {
  return minutes < 1.0 ? ReportText::tr("%1 s").arg(minutes * 60.0, 0, 'g', 3)
                       : ReportText::tr("%1 min").arg(minutes, 0, 'g', 3);
}

QString kindCounts(const ThermalLog& log) {
  std::map<ChannelKind, int> counts;
  for (const ThermalChannel& c : log.channels) {
    ++counts[channelKind(c)];
  }
  QStringList parts;
  const std::pair<ChannelKind, const char*> names[] = {
      {ChannelKind::Temperature, QT_TRANSLATE_N_NOOP("metrofit::Report", "%n temperature(s)")},
      {ChannelKind::Displacement, QT_TRANSLATE_N_NOOP("metrofit::Report", "%n displacement(s)")},
      {ChannelKind::Strain, QT_TRANSLATE_N_NOOP("metrofit::Report", "%n strain(s)")},
      {ChannelKind::Speed, QT_TRANSLATE_N_NOOP("metrofit::Report", "%n speed(s)")},
      {ChannelKind::Other, QT_TRANSLATE_N_NOOP("metrofit::Report", "%n other")}};
  for (const auto& [kind, text] : names) {
    if (counts[kind] > 0) {
      parts << ReportText::tr(text, nullptr, counts[kind]);
    }
  }
  return parts.join(QStringLiteral(", "));
}

QString phaseSummary(const PhaseDetection& detection) {
  const auto heating =
      std::count_if(detection.phases.begin(), detection.phases.end(),
                    [](const ThermalPhase& p) { return p.kind == ThermalPhaseKind::Heating; });
  const auto cooling = static_cast<qsizetype>(detection.phases.size()) - heating;
  switch (detection.source) {
    case PhaseSource::Speed:
      return ReportText::tr("%1 heating, %2 cooling, from the speed channel %3 (running = heating)")
          .arg(heating)
          .arg(cooling)
          .arg(QString::fromStdString(detection.channel));
    case PhaseSource::TemperatureSlope:
      if (detection.phases.empty()) {
        break;
      }
      return ReportText::tr("%1 heating, %2 cooling, from the slope of the mean temperature")
          .arg(heating)
          .arg(cooling);
    case PhaseSource::None:
      break;
  }
  return ReportText::tr("none detected");
}

void writeThermalLog(ReportPainter& out, const ReportDataset& dataset) {
  const ThermalLog& log = *dataset.thermal;
  out.subheading(ReportText::tr("Thermal log “%1”").arg(QString::fromStdString(dataset.ref.id)),
                 out.mm(40.0));
  if (!dataset.ref.description.empty()) {
    out.paragraph(QString::fromStdString(dataset.ref.description));
  }

  const QStringList shown = defaultThermalChannels(log);
  const PhaseDetection detection = detectThermalPhases(log);
  const double span = log.rows() > 1 ? log.timeMin.back() - log.timeMin.front() : 0.0;
  ReportTable facts;
  facts.widths = {1.0, 3.2};
  facts.widthFraction = 1.0;
  facts.rows = {
      {ReportText::tr("file"), QString::fromStdString(dataset.ref.path)},
      {ReportText::tr("rows"),
       ReportText::tr("%1, every %2 (median), time column %3")
           .arg(log.rows())
           .arg(formatSpacing(medianSpacingMin(log)), QString::fromStdString(log.timeColumn))},
      {ReportText::tr("duration"), formatDuration(span)},
      {ReportText::tr("channels"), kindCounts(log)},
      {ReportText::tr("phases"), phaseSummary(detection)},
      {ReportText::tr("chart"), ReportText::tr("%1 of %2 channels shown; the table lists all")
                                    .arg(shown.size())
                                    .arg(log.channels.size())},
  };
  out.table(facts);

  ThermalChartOptions chartOptions;
  chartOptions.channelLegend = true;
  out.chart(makeThermalTrendChart(log, shown, chartOptions), out.mm(kChartHeightMm));

  ReportTable channels;
  channels.header = {ReportText::tr("channel"), ReportText::tr("quantity"), ReportText::tr("min"),
                     ReportText::tr("max"), ReportText::tr("in chart")};
  channels.widths = {1.4, 1.8, 1.0, 1.0, 0.8};
  channels.alignment = {Qt::AlignLeft, Qt::AlignLeft, Qt::AlignRight, Qt::AlignRight, Qt::AlignHCenter};
  for (const ThermalChannel& c : log.channels) {
    if (c.values.empty()) {
      continue;
    }
    const auto [lo, hi] = std::minmax_element(c.values.begin(), c.values.end());
    const double range = std::max(std::abs(*lo), std::abs(*hi));
    const QString name = QString::fromStdString(c.name);
    channels.rows.push_back({name, channelAxisTitle(c), formatValue(*lo, range), formatValue(*hi, range),
                             shown.contains(name) ? ReportText::tr("yes") : QString()});
  }
  out.table(channels);
}

QString unitOf(const ThermalLog& log, const std::string& column) {
  const int i = log.indexOf(column);
  return i >= 0 ? displayUnit(log.channels[static_cast<std::size_t>(i)].unit) : QString();
}

/// One sentence on the applied effects: which models keep them, with the held-out RMSE of both
/// variants (each model keeps the lower one, core/study/thermal_comparison.h).
QString appliedChoice(const ThermalLog& log, const ThermalComparison& c) {
  double scale = 0.0;
  for (double v : c.series.target) scale = std::max(scale, std::abs(v));
  const int dec = scale >= 100.0 ? 1 : (scale >= 1.0 ? 2 : 3);
  const QString unit = unitOf(log, c.settings.target);
  const QString u = unit.isEmpty() ? QString() : QLatin1Char(' ') + unit;
  QStringList used, usedChange, notUsed, notUsedChange;
  bool allRise = true;
  for (std::size_t i = 0; i < kThermalModelOrder.size(); ++i) {
    if (!c.fitted(i)) continue;  // not fitted: its row in the table says why
    const QString change =
        ReportText::tr("%1 → %2%3")
            .arg(metric(c.declaredHeldoutRmse[i], dec), metric(c.appliedHeldoutRmse[i], dec), u);
    if (c.usesApplied[i]) {
      used << thermalModelName(kThermalModelOrder[i]);
      usedChange << change;
    } else {
      notUsed << thermalModelName(kThermalModelOrder[i]);
      notUsedChange << change;
      allRise = allRise && c.appliedHeldoutRmse[i] > c.declaredHeldoutRmse[i];
    }
  }
  const QString sep = QStringLiteral(", ");
  QStringList parts;
  if (!used.isEmpty())
    parts << ReportText::tr("used by %1 (held-out error %2)").arg(used.join(sep), usedChange.join(sep));
  if (!notUsed.isEmpty()) {
    parts << (allRise ? ReportText::tr("not used by %1 (held-out error would rise: %2)")
                      : ReportText::tr("not used by %1 (held-out error would not fall: %2)"))
                 .arg(notUsed.join(sep), notUsedChange.join(sep));
  }
  return ReportText::tr(
             "Applied effects %1 (added with Apply on the diagnosis page; each model is fitted with and "
             "without them and keeps the lower held-out error): %2.")
      .arg(QString::fromStdString(c.appliedText), parts.join(QStringLiteral("; ")));
}

void writeHysteresis(ReportPainter& out, const ThermalResults& r) {
  out.subheading(ReportText::tr("Hysteresis"), out.mm(60.0));
  if (!r.hysteresisError.isEmpty()) {
    out.paragraph(ReportText::tr("No hysteresis analysis: %1").arg(r.hysteresisError));
    return;
  }
  const thermal::HysteresisAnalysis& h = r.hysteresis;
  const std::size_t shown = std::min(h.sensors.size(), kMaxHysteresisCharts);
  out.paragraph(
      ReportText::tr(
          "%1 against each sensor (Fig. 9 of %5): heating runs (the change of %1 grows, %2 "
          "rows) and cooling runs (%3 rows) in the colours of the trend chart's phases. Loop area by "
          "the shoelace formula; lag: the time constant of a first-order lag between sensor and "
          "displacement (> 0: the sensor lags).%4")
          .arg(QString::fromStdString(h.target))
          .arg(h.heatingRows)
          .arg(h.coolingRows)
          .arg(shown < h.sensors.size()
                   ? QLatin1Char(' ') +
                         ReportText::tr("Charts of the first %1 of %2 sensors; the table lists all.")
                             .arg(shown)
                             .arg(h.sensors.size())
                   : QString())
          .arg(citation(4)));
  const int columns = 3;
  const int rows = static_cast<int>((shown + columns - 1) / columns);
  for (int row = 0; row < rows; ++row) {
    const QRectF band = out.reserve(out.mm(kHysteresisCellMm));
    const double w = band.width() / columns;
    for (int col = 0; col < columns; ++col) {
      const std::size_t i = static_cast<std::size_t>(row * columns + col);
      if (i >= shown) break;
      HysteresisChartOptions o;
      o.compactTitle = true;
      o.legend = i == 0;
      o.maxPoints = 800;
      renderChart(out.painter(), makeHysteresisChart(r.fitted, r.hysteresisSeries, h, static_cast<int>(i), o),
                  QRectF(band.left() + col * w, band.top(), w - out.mm(1.5), band.height()), 300.0);
    }
  }
  out.skip(out.mm(2.0));
  ReportTable t;
  const QString yUnit = unitOf(r.fitted, h.target);
  t.header = {ReportText::tr("sensor"),      ReportText::tr("loop area"),   ReportText::tr("loop / ranges"),
              ReportText::tr("lag τ (min)"), ReportText::tr("R² with lag"), ReportText::tr("R² static")};
  t.widths = {1.2, 1.6, 1.1, 1.0, 1.0, 1.0};
  t.alignment = {Qt::AlignLeft,  Qt::AlignRight, Qt::AlignRight,
                 Qt::AlignRight, Qt::AlignRight, Qt::AlignRight};
  for (const thermal::SensorHysteresis& s : h.sensors) {
    const QString unit = unitOf(r.fitted, s.sensor);
    t.rows.push_back(
        {QString::fromStdString(s.sensor), QStringLiteral("%1 %2·%3").arg(metric(s.loopArea, 2), unit, yUnit),
         metric(s.normalisedLoopArea, 3), metric(s.tauMin, 1), metric(s.r2, 3), metric(s.r2Static, 3)});
  }
  out.table(t);
}

void writeModels(ReportPainter& out, const ThermalLog& log, const ThermalResults& r) {
  out.subheading(ReportText::tr("Thermal error models"), out.mm(90.0));
  const ThermalModelSettings& s = r.settings;
  QString text =
      ReportText::tr(
          "GNNMCI(1,N) (PSO, 90 particles, 100 iterations, seed %1), GMC(1,N) (least squares) and "
          "the MLP (%2-10-1, Levenberg-Marquardt, seed %1) predict %3 from %4; each is fitted on the "
          "first %5 % of the rows and tested on the rest (held out, shaded).")
          .arg(s.seed)
          .arg(s.inputs.size())
          .arg(QString::fromStdString(s.target), joined(s.inputs))
          .arg(100.0 * s.trainFraction, 0, 'f', 0);
  if (r.asPage) {
    text += QLatin1Char(' ') + ReportText::tr(
                                   "Every row of the log is fitted, as on the Thermal page (trained there "
                                   "%1, stored in the project with these settings and this data), so the "
                                   "report chooses the page's model with the page's figures.")
                                   .arg(QString::fromStdString(r.pageComputed));
  } else if (r.stride > 1) {
    text += QLatin1Char(' ') +
            ReportText::tr(
                "To keep the report's run time short, this %1-row log is fitted on every %2th row "
                "(%3 rows); the GUI and metrofit-cli fit all rows and may choose another model. Train the "
                "models on the Thermal page and save the project: the report then fits every row and "
                "shows the page's choice.")
                .arg(log.rows())
                .arg(r.stride)
                .arg(r.fitted.rows());
  }
  if (r.comparison && !r.comparison->appliedText.empty())
    text += QLatin1Char(' ') + appliedChoice(log, *r.comparison);
  out.paragraph(text);
  if (!r.comparison) {
    out.paragraph(ReportText::tr("The models could not be fitted: %1").arg(r.modelError));
    return;
  }
  const ThermalComparison& c = *r.comparison;
  ModelChartOptions o;
  out.chart(makeModelComparisonChart(r.fitted, c, o), out.mm(kModelChartHeightMm));
  o.legend = false;
  o.title = ReportText::tr("residual = measured − model");
  out.chart(makeResidualChart(r.fitted, c, o), out.mm(kResidualChartHeightMm));

  const QString unit = unitOf(log, s.target);
  double scale = 0.0;
  for (double v : c.series.target) scale = std::max(scale, std::abs(v));
  const int dec = scale >= 100.0 ? 1 : (scale >= 1.0 ? 2 : 3);
  ReportTable t;
  t.header = {ReportText::tr("model"),  ReportText::tr("rows"),
              ReportText::tr("R"),      ReportText::tr("RMSE (%1)").arg(unit),
              ReportText::tr("E"),      ReportText::tr("band (%1)").arg(unit),
              ReportText::tr("verdict")};
  t.widths = {1.3, 1.3, 0.9, 1.0, 0.9, 1.0, 2.2};
  t.alignment = {Qt::AlignLeft,  Qt::AlignLeft,  Qt::AlignRight, Qt::AlignRight,
                 Qt::AlignRight, Qt::AlignRight, Qt::AlignLeft};
  QStringList trainingNotes;
  for (std::size_t i = 0; i < kThermalModelOrder.size(); ++i) {
    const thermal::ThermalEvaluation& ev = c.models[i];
    if (!c.failed[i].empty()) {
      // The model could not be fitted on this log (the others are): one row with the reason.
      t.rows.push_back({thermalModelName(kThermalModelOrder[i]), QStringLiteral("—"), QString(), QString(),
                        QString(), QString(),
                        ReportText::tr("not fitted: %1").arg(QString::fromStdString(c.failed[i]))});
      trainingNotes << ReportText::tr("%1: not fitted").arg(thermalModelName(kThermalModelOrder[i]));
      continue;
    }
    if (!c.fitted(i)) continue;
    QString training;
    switch (kThermalModelOrder[i]) {
      case thermal::ThermalModelKind::Gnnmci:
        training = ReportText::tr("%1 PSO iterations, Eq. 2.9 %2 → %3")
                       .arg(ev.training.run.iterations)
                       .arg(ev.training.firstFitness, 0, 'g', 4)
                       .arg(ev.training.fitness, 0, 'g', 4);
        break;
      case thermal::ThermalModelKind::Gmc:
        training = ev.training.model.grey.b1 > 0.0
                       ? ReportText::tr("least squares, b1 = %1").arg(ev.training.model.grey.b1, 0, 'g', 4)
                       : ReportText::tr("least squares, unstable: b1 = %1 ≤ 0")
                             .arg(ev.training.model.grey.b1, 0, 'g', 4);
        break;
      case thermal::ThermalModelKind::Mlp:
        training = ReportText::tr("%1 LM epochs (%2)")
                       .arg(ev.training.run.iterations)
                       .arg(QString::fromLatin1(toString(ev.training.run.termination)));
        break;
      case thermal::ThermalModelKind::Linear:
      case thermal::ThermalModelKind::Lag:
      case thermal::ThermalModelKind::DistributedLag:
        training = QString::fromStdString(ev.training.run.message);
        break;
    }
    trainingNotes << thermalModelName(kThermalModelOrder[i]) + QStringLiteral(": ") + training +
                         ReportText::tr(" (%1 s)").arg(c.seconds[i], 0, 'f', 2);
    for (int part = 0; part < 2; ++part) {
      const thermal::ThermalMetrics& m = part == 0 ? ev.fit : ev.heldout;
      // A model whose output runs away (an unstable GMC) is reported as such, not as 1e+68.
      const bool runaway = thermal::diverges(m, scale);
      const QString diverges = ReportText::tr("diverges");
      QString verdict;
      if (part == 1) {
        const thermal::ModelVerdict v = thermal::judgeThermalModel(ev.heldout, scale);
        verdict = thermalVerdictLabel(v);
        if (v != thermal::ModelVerdict::Usable)
          verdict += QStringLiteral(": ") + thermalVerdictReason(v, ev.heldout, QLocale::c());
      }
      t.rows.push_back({part == 0 ? thermalModelName(kThermalModelOrder[i]) : QString(),
                        (part == 0 ? ReportText::tr("fit, %1") : ReportText::tr("held out, %1")).arg(m.n),
                        runaway ? diverges : metric(m.r, 4), runaway ? diverges : metric(m.rmse, dec),
                        runaway ? diverges : metric(m.e, 4),
                        runaway ? diverges : QStringLiteral("±") + metric(m.residualBand, dec), verdict});
    }
  }
  out.paragraph(ReportText::tr("Performance indices (Table 4 of %1): R correlation, RMSE, E "
                               "Nash-Sutcliffe efficiency, band = largest |residual|. A model is usable for "
                               "compensation only when on the held-out rows it does not diverge (RMSE at "
                               "most %2 × the largest error), E ≥ %3 and R ≥ %4.")
                    .arg(citation(4))
                    .arg(thermal::kDivergenceFactor, 0, 'f', 0)
                    .arg(thermal::kMinEfficiency, 0, 'f', 0)
                    .arg(thermal::kMinCorrelation, 0, 'f', 1),
                ReportPainter::Font::Small);
  out.table(t);
  out.paragraph(ReportText::tr("Training: %1.").arg(trainingNotes.join(QStringLiteral("; "))),
                ReportPainter::Font::Small);
}

void writeModular(ReportPainter& out, const ReportContext& context, const ThermalLog& testLog) {
  QString error;
  const std::shared_ptr<const ModularComparison> m = modularResults(context, &error);
  out.subheading(ReportText::tr("Modular models (%1, Section 4.3)").arg(citation(4)), out.mm(80.0));
  if (!m) {
    out.paragraph(ReportText::tr("The modular case could not be computed: %1").arg(error));
    return;
  }
  out.paragraph(ReportText::tr("Each model is fitted on the Z-heating test (%1) and the C-heating test (%2) "
                               "together and predicts the combined helical test (%3), which it has not seen. "
                               "Target %4, inputs %5, seed 1. Error reduction as the paper states it: "
                               "1 − max|residual| / max|error|, and by RMS.")
                    .arg(QString::fromLatin1(kModularZId), QString::fromLatin1(kModularCId),
                         QString::fromLatin1(kModularCombinedId), QString::fromStdString(m->target),
                         joined(m->inputs)));
  ModelChartOptions o;
  out.chart(makeModularChart(testLog, *m, o), out.mm(kModelChartHeightMm));
  const QString unit = unitOf(testLog, m->target);
  ReportTable t;
  t.header = {ReportText::tr("model"),
              ReportText::tr("error (%1)").arg(unit),
              ReportText::tr("band (%1)").arg(unit),
              ReportText::tr("less, peak"),
              ReportText::tr("RMSE (%1)").arg(unit),
              ReportText::tr("less, RMS"),
              ReportText::tr("R"),
              ReportText::tr("E")};
  t.alignment = {Qt::AlignLeft,  Qt::AlignRight, Qt::AlignRight, Qt::AlignRight,
                 Qt::AlignRight, Qt::AlignRight, Qt::AlignRight, Qt::AlignRight};
  QStringList notFitted;
  for (std::size_t i = 0; i < kThermalModelOrder.size(); ++i) {
    const thermal::ModularEvaluation& ev = m->models[i];
    if (!m->fitted(i)) {
      t.rows.push_back({thermalModelName(kThermalModelOrder[i]), ReportText::tr("not fitted"), QString(),
                        QString(), QString(), QString(), QString(), QString()});
      notFitted << ReportText::tr("%1 not fitted: %2.")
                       .arg(thermalModelName(kThermalModelOrder[i]), QString::fromStdString(m->failed[i]));
      continue;
    }
    if (thermal::diverges(ev.test, ev.errorPeak)) {  // a runaway prediction: no 1e+305 figures
      const QString d = ReportText::tr("diverges");
      t.rows.push_back({thermalModelName(kThermalModelOrder[i]), metric(ev.errorPeak, 1), d, d, d, d, d, d});
      continue;
    }
    t.rows.push_back({thermalModelName(kThermalModelOrder[i]), metric(ev.errorPeak, 1),
                      QStringLiteral("±") + metric(ev.residualPeak, 1),
                      metric(100.0 * ev.reductionPeak, 1) + QStringLiteral(" %"), metric(ev.test.rmse, 2),
                      metric(100.0 * ev.reductionRms, 1) + QStringLiteral(" %"), metric(ev.test.r, 4),
                      metric(ev.test.e, 4)});
  }
  if (const auto& ev = m->modules.evaluation) {
    t.rows.push_back({ReportText::tr("modules, summed (distributed lag)"), metric(ev->errorPeak, 1),
                      QStringLiteral("±") + metric(ev->residualPeak, 1),
                      metric(100.0 * ev->reductionPeak, 1) + QStringLiteral(" %"), metric(ev->test.rmse, 2),
                      metric(100.0 * ev->reductionRms, 1) + QStringLiteral(" %"), metric(ev->test.r, 4),
                      metric(ev->test.e, 4)});
  }
  out.table(t);
  if (!notFitted.isEmpty()) out.paragraph(notFitted.join(QLatin1Char(' ')), ReportPainter::Font::Small);
  // The same case module by module: each module on its own test, the combined test their sum.
  if (const auto& ev = m->modules.evaluation) {
    QStringList parts;
    for (std::size_t i = 0; i < m->modules.names.size() && i < ev->contributions.size(); ++i) {
      const double peak = ev->contributionPeaks[i];
      QString part = ReportText::tr("%1 with inputs %2, up to %3 %4")
                         .arg(QString::fromStdString(m->modules.names[i]), joined(m->modules.inputs[i]),
                              metric(peak, 1), unit);
      if (i < m->modules.tests.size() && m->modules.tests[i] != m->modules.names[i])
        part += ReportText::tr(" (identified again on %1)").arg(QString::fromStdString(m->modules.tests[i]));
      parts << part;
    }
    out.paragraph(
        ReportText::tr("Module by module (the last row and the dotted curves): each module is identified "
                       "on its own test alone, with the channels its own heating moves at least twice "
                       "as much as the other test's, by the distributed-lag model, and the combined test "
                       "is predicted as the sum of the modules, so that one module can be identified "
                       "again without the others: %1.")
            .arg(parts.join(QStringLiteral("; "))));
  } else if (!m->modules.why.empty()) {
    out.paragraph(
        ReportText::tr("Module by module: not identified (%1).").arg(QString::fromStdString(m->modules.why)));
  }
}

/// The section's conclusion: the verdict on each model and the best usable one.
void concludeThermal(ReportPainter& out, const ReportContext& context, const ReportDataset& dataset,
                     const ThermalResults& r) {
  SectionFinding f;
  f.study = thermalSectionTitle();
  const ThermalLog& log = *dataset.thermal;
  const QString target = QString::fromStdString(r.settings.target);
  if (!r.comparison) {
    f.conclusion = ReportText::tr("The thermal models could not be fitted: %1").arg(r.modelError);
    f.found = f.conclusion;
    f.recommendation = ReportText::tr("Check the thermal study's target and inputs against the log.");
    concludeSection(out, context, f);
    return;
  }
  const ThermalComparison& c = *r.comparison;
  const double scale = thermal::targetScale(c.series.target);
  const int dec = scale >= 100.0 ? 1 : (scale >= 1.0 ? 2 : 3);
  const QString unit = unitOf(log, r.settings.target);
  const QString u = unit.isEmpty() ? QString() : QLatin1Char(' ') + unit;
  int best = -1;
  QStringList rejected;
  for (std::size_t i = 0; i < kThermalModelOrder.size(); ++i) {
    const thermal::ThermalEvaluation& ev = c.models[i];
    if (!c.failed[i].empty()) {
      rejected << ReportText::tr("%1 could not be fitted (%2)")
                      .arg(thermalModelName(kThermalModelOrder[i]), QString::fromStdString(c.failed[i]));
      continue;
    }
    if (!c.fitted(i)) continue;
    const thermal::ModelVerdict v = thermal::judgeThermalModel(ev.heldout, scale);
    if (v != thermal::ModelVerdict::Usable) {
      rejected << ReportText::tr("%1 is not usable (%2)")
                      .arg(thermalModelName(kThermalModelOrder[i]),
                           thermalVerdictReason(v, ev.heldout, QLocale::c()));
    } else if (best < 0 || ev.heldout.rmse < c.models[static_cast<std::size_t>(best)].heldout.rmse) {
      best = static_cast<int>(i);
    }
  }
  // The error without compensation on the held-out rows: the measured displacement about its mean.
  const std::size_t rows = c.series.rows();
  const std::size_t first = static_cast<std::size_t>(r.settings.trainFraction * static_cast<double>(rows));
  double mean = 0.0, ss = 0.0, peak = 0.0;
  for (std::size_t k = first; k < rows; ++k) mean += c.series.target[k];
  mean /= std::max<std::size_t>(1, rows - first);
  for (std::size_t k = first; k < rows; ++k) {
    ss += (c.series.target[k] - mean) * (c.series.target[k] - mean);
    peak = std::max(peak, std::abs(c.series.target[k] - mean));
  }
  const double rmsBefore = std::sqrt(ss / static_cast<double>(std::max<std::size_t>(1, rows - first)));
  f.before = ReportText::tr("%1 varies by RMS %2%3 (peak %4%3) on the held-out rows")
                 .arg(target, metric(rmsBefore, dec), u, metric(peak, dec));
  const QString rejectedText =
      rejected.isEmpty() ? QString() : rejected.join(QStringLiteral("; ")) + QLatin1Char('.');
  if (best >= 0) {
    const thermal::ThermalEvaluation& ev = c.models[static_cast<std::size_t>(best)];
    const QString name = thermalModelName(kThermalModelOrder[static_cast<std::size_t>(best)]);
    f.found = ReportText::tr("Best usable model of %1: %2, held-out RMSE %3%4, residual band ±%5%4.")
                  .arg(target, name, metric(ev.heldout.rmse, dec), u, metric(ev.heldout.residualBand, dec));
    if (!rejectedText.isEmpty()) f.found += QLatin1Char(' ') + rejectedText;
    f.after = ReportText::tr("RMS %1%2 (band ±%3%2) left with %4")
                  .arg(metric(ev.heldout.rmse, dec), u, metric(ev.heldout.residualBand, dec), name);
    // How the compensation reaches the control: the forms the model can take (core/thermal/control_export.h).
    const thermal::ThermalModel& chosen = ev.training.model;
    QStringList forms;
    for (thermal::ControlFormat form : thermal::kAllControlFormats)
      if (thermal::controlExportRefusal(chosen, form).empty())
        forms << QString::fromLatin1(thermal::toString(form));
    const QString how =
        forms.isEmpty()
            ? ReportText::tr(
                  "model fitted on %1; a grey model has no form a control runs: fit linear, lag or "
                  "dlag to export it")
                  .arg(QString::fromStdString(dataset.ref.id))
            : ReportText::tr(
                  "model fitted on %1; export it for the control on the Thermal page (Export compensation) "
                  "or "
                  "with metrofit-cli thermal export --format %2")
                  .arg(QString::fromStdString(dataset.ref.id), forms.join(QLatin1Char('|')));
    f.changes.push_back({ReportText::tr("thermal compensation of %1").arg(target), name, how});
    f.conclusion = ReportText::tr(
                       "%1 predicts %2 on rows it was not fitted on to RMS %3%4, from RMS %5%4 "
                       "without compensation.")
                       .arg(name, target, metric(ev.heldout.rmse, dec), u, metric(rmsBefore, dec));
    if (!rejectedText.isEmpty()) f.conclusion += QLatin1Char(' ') + rejectedText;
    f.recommendation =
        ReportText::tr("Compensate %1 with %2; do not use the models marked not usable.").arg(target, name);
  } else {
    f.found = ReportText::tr("No model of %1 passes the held-out test.").arg(target) + QLatin1Char(' ') +
              rejectedText;
    f.conclusion = f.found;
    f.recommendation = ReportText::tr(
        "Do not compensate with these models. Record a longer test covering "
        "heating and cooling, add sensors near the heat sources, and use the "
        "closed loop (diagnosis) to find the lag or inputs the model lacks.");
  }
  concludeSection(out, context, f);
}

}  // namespace

QString thermalSectionTitle() {
  return ReportText::tr("Thermal");
}

void writeThermalSection(ReportPainter& out, const ReportContext& context) {
  const auto study = context.project->studies.find(study::kThermal);
  const nlohmann::json thermalStudy =
      study != context.project->studies.end() ? *study : nlohmann::json::object();
  // Only the study's log (the report shows the studies the project declares); a study without a
  // dataset means the project's only thermal log (validated: reportstudies.cpp).
  const std::vector<const ReportDataset*> logs = context.ofKind(dataset_kind::kThermalLog);
  const std::string id = thermalStudy.value("dataset", logs.empty() ? std::string() : logs.front()->ref.id);
  for (const ReportDataset* dataset : logs) {
    if (dataset->ref.id != id) continue;
    writeThermalLog(out, *dataset);
    const ThermalLog& log = *dataset->thermal;
    ThermalModelSettings settings = defaultThermalModelSettings(log, thermalStudy, dataset->ref.id);
    settings.applied = diagnose::projectThermalApplied(*context.project, dataset->ref.id);
    const std::shared_ptr<const ThermalResults> results = thermalResults(context, *dataset, settings);
    writeHysteresis(out, *results);
    writeModels(out, log, *results);
    if (dataset->ref.id == kModularCombinedId) {
      writeModular(out, context, log);
    }
    concludeThermal(out, context, *dataset, *results);
  }
}

}  // namespace metrofit
