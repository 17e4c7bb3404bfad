// Report section "Setup-data correction": the relation-graph model, the CMM report, the
// settings, the convergence of CRIPSO and PSO against the exact optimum (run here with fixed
// seeds: the paper's size takes milliseconds), the comparison of the methods, the corrections, the
// margins before / after per dimension and the Fanuc export of the exact corrections.
#include <QCoreApplication>
#include <QFontDatabase>
#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>

#include "core/setup/export.h"
#include "core/setup/methods.h"
#include "core/setup/model.h"
#include "core/setup/objective.h"
#include "core/setup/report.h"
#include "core/study/setup_study.h"
#include "widgets/report/reportpainter.h"
#include "widgets/report/sections.h"
#include "widgets/setup/setupcharts.h"
#include "widgets/setup/setupmargins.h"

namespace metrofit {
namespace {

struct ReportText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::Report)
};

constexpr double kChartHeightMm = 95.0;
constexpr std::uint64_t kSeed = 1;

QString mm(double v, int decimals = 4) {
  const double r = std::abs(v) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : v;
  return QString::number(r, 'f', decimals);
}

const ReportDataset* byId(const ReportContext& context, const std::string& id) {
  for (const ReportDataset& d : context.datasets)
    if (d.ref.id == id) return &d;
  return nullptr;
}

QString kindTitle(setup::DatumKind kind) {
  switch (kind) {
    case setup::DatumKind::Machine:
      return ReportText::tr("machine point");
    case setup::DatumKind::Wks:
      return ReportText::tr("work offset");
    case setup::DatumKind::Tool:
      return ReportText::tr("tool length");
  }
  return {};
}

/// Monospaced lines (an NC program); breaks between lines across pages.
void codeBlock(ReportPainter& out, const QString& text) {
  QFont font(QFontDatabase::hasFamily(QStringLiteral("DejaVu Sans Mono")) ? QStringLiteral("DejaVu Sans Mono")
                                                                          : QStringLiteral("monospace"));
  font.setStyleHint(QFont::Monospace);
  font.setPointSizeF(7.5);
  QPainter& p = out.painter();
  const QFontMetricsF fm(font, p.device());
  const double line = fm.lineSpacing();
  const double width = out.content().width() - out.mm(6.0);
  for (QString l : text.split(QLatin1Char('\n'))) {
    // A line wider than the page continues on the next one, indented: nothing is cut off.
    bool continuation = false;
    do {
      const double indent = out.mm(continuation ? 6.0 : 3.0);
      int n = static_cast<int>(l.size());
      while (n > 1 && fm.horizontalAdvance(l.left(n)) > width - indent + out.mm(3.0)) --n;
      const QRectF r = out.reserve(line);
      p.save();
      p.setFont(font);
      p.setPen(QColor(0x20, 0x20, 0x20));
      p.drawText(r.adjusted(indent, 0, 0, 0), Qt::AlignLeft | Qt::AlignVCenter, l.left(n));
      p.restore();
      l = l.mid(n);
      continuation = true;
    } while (!l.isEmpty());
  }
  out.skip(out.mm(2.0));
}

}  // namespace

QString setupSectionTitle() {
  return ReportText::tr("Setup-data correction");
}

void writeSetupSection(ReportPainter& out, const ReportContext& context) {
  const SetupStudyFiles files = setupStudyFiles(*context.project, {});
  const ReportDataset* modelSet = byId(context, files.modelId);
  const ReportDataset* reportSet = byId(context, files.reportId);
  if (modelSet == nullptr) return;
  const setup::Model model = setup::readModel(modelSet->path.toStdString());

  // ---- model ----
  out.subheading(ReportText::tr("Model “%1”").arg(QString::fromStdString(modelSet->ref.id)), out.mm(30.0));
  if (!modelSet->ref.description.empty()) out.paragraph(QString::fromStdString(modelSet->ref.description));
  int wks = 0, tools = 0, machine = 0;
  for (const auto& s : model.setup) {
    wks += s.kind == setup::DatumKind::Wks ? 1 : 0;
    tools += s.kind == setup::DatumKind::Tool ? 1 : 0;
    machine += s.kind == setup::DatumKind::Machine ? 1 : 0;
  }
  ReportTable facts;
  facts.widths = {1.0, 3.2};
  facts.rows = {
      {ReportText::tr("file"), QString::fromStdString(modelSet->ref.path)},
      {ReportText::tr("name"), QString::fromStdString(model.name)},
      {ReportText::tr("setup data"), ReportText::tr("%1: %2 work offsets, %3 tools, %4 machine points")
                                         .arg(model.setup.size())
                                         .arg(wks)
                                         .arg(tools)
                                         .arg(machine)},
      {ReportText::tr("features"), QString::number(model.features.size())},
      {ReportText::tr("dimensions"), QString::number(model.dimensions.size())},
      {ReportText::tr("arcs"), QString::number(model.arcs.size())},
      {ReportText::tr("decision space"), ReportText::tr("axis %1, grid %2 mm, bounds [%3, %4] mm")
                                             .arg(QString::fromStdString(model.axis))
                                             .arg(model.stepMm)
                                             .arg(mm(model.boundsMm.first, 3), mm(model.boundsMm.second, 3))},
  };
  out.table(facts);

  if (reportSet == nullptr) {
    out.paragraph(ReportText::tr("The project has no CMM report for this model: nothing to correct."));
    return;
  }
  // A DMIS series: every file of it.
  const std::vector<std::string> reportFiles =
      reportSet->paths.empty() ? std::vector<std::string>{reportSet->path.toStdString()} : reportSet->paths;
  setup::Measurements measurements =
      setup::readMeasurements(reportFiles, model, reportSet->ref.csv, reportSet->ref.dmis);
  // The effects added with the diagnosis page's Apply: the deviations become the next part's prediction.
  diagnose::SetupPrediction prediction, declared;
  const std::vector<diagnose::AppliedSetupEffect> applied =
      applyStudyEffects(*context.project, {}, files.reportId, model, measurements, &prediction, &declared);
  const setup::SetupInstance instance(model, measurements);

  // ---- report data ----
  out.subheading(ReportText::tr("Report data “%1”").arg(QString::fromStdString(reportSet->ref.id)),
                 out.mm(25.0));
  if (!reportSet->ref.description.empty()) out.paragraph(QString::fromStdString(reportSet->ref.description));
  int outBefore = 0;
  for (std::size_t q = 0; q < instance.dimensions(); ++q)
    outBefore +=
        (instance.deviation(q) < instance.lowerLimit(q) || instance.deviation(q) > instance.upperLimit(q));
  ReportTable data;
  data.widths = {1.0, 3.2};
  data.rows = {
      {ReportText::tr("file"), QString::fromStdString(reportSet->ref.path)},
      {ReportText::tr("parts"), QString::number(measurements.parts.size())},
      {ReportText::tr("rows"),
       ReportText::tr("%1 (deviation of a dimension: mean over its rows)").arg(measurements.rows.size())},
      {ReportText::tr("before correction"),
       ReportText::tr("f1 = %1 mm; %2 of %3 mean deviations out of tolerance")
           .arg(mm(instance.f1Before()))
           .arg(outBefore)
           .arg(instance.dimensions())},
  };
  if (!applied.empty()) {
    data.rows[2][1] = ReportText::tr("%1 (deviation of a dimension: predicted for part %2)")
                          .arg(measurements.rows.size())
                          .arg(prediction.nextPart);
    data.rows.push_back(
        {ReportText::tr("applied effects"),
         ReportText::tr("%1 (diagnosis, Apply)").arg(QString::fromStdString(diagnose::describe(applied)))});
    data.rows.push_back(
        {ReportText::tr("model residual"),
         ReportText::tr("rms %1 mm (declared model %2 mm)").arg(mm(prediction.rmseMm), mm(declared.rmseMm))});
    if (prediction.nextPartRmseMm && declared.nextPartRmseMm)
      data.rows.push_back({ReportText::tr("last part predicted"),
                           ReportText::tr("rms %1 mm from the other parts (declared model %2 mm)")
                               .arg(mm(*prediction.nextPartRmseMm), mm(*declared.nextPartRmseMm))});
  }
  out.table(data);

  // ---- settings and runs ----
  const SetupRunOutcome exact = runSetupMethod(instance, "exact", 0, 0);
  const SetupRunOutcome cripso = runSetupMethod(instance, "cripso", setup::kPaperBudget, kSeed);
  const SetupRunOutcome pso = runSetupMethod(instance, "pso", setup::kPaperBudget, kSeed);
  out.subheading(ReportText::tr("Settings"), out.mm(25.0));
  out.paragraph(
      ReportText::tr(
          "Objectives as in %4, Eq. 6–10: f1 = the smallest unilateral error budget over "
          "all dimensions after correction (maximised), f2 = |x| (minimised among the f1-optimal), "
          "f = 10 f1 − f2. Exact: LP / MILP on the %1 mm grid (GLPK), then the least-norm correction. "
          "CRIPSO: 100 polyps, w = 0.75, c1 = c2 = cos(π/2 Li/L); PSO: 100 particles, asynchronous "
          "gbest, same coefficients. Budget %2 solutions, seed %3.")
          .arg(model.stepMm)
          .arg(setup::kPaperBudget)
          .arg(kSeed)
          .arg(citation(0)));

  out.subheading(ReportText::tr("Convergence"), out.mm(kChartHeightMm + 10.0));
  std::vector<SetupConvergenceRun> runs = {
      {setupRunLabel(QStringLiteral("cripso"), kSeed), QStringLiteral("cripso"), cripso.trace},
      {setupRunLabel(QStringLiteral("pso"), kSeed), QStringLiteral("pso"), pso.trace}};
  out.chart(makeSetupConvergenceChart(runs, exact.score, setup::kPaperBudget), out.mm(kChartHeightMm));

  // ---- comparison ----
  out.subheading(ReportText::tr("Comparison"), out.mm(25.0));
  ReportTable comparison;
  comparison.header = {ReportText::tr("method"),     ReportText::tr("f1 (mm)"),
                       ReportText::tr("f2 (mm)"),    ReportText::tr("f"),
                       ReportText::tr("bonus (mm)"), ReportText::tr("gap f1 (mm)"),
                       ReportText::tr("solutions")};
  comparison.widths = {1.5, 1.0, 1.0, 1.0, 1.0, 1.4, 1.0};
  comparison.alignment = {Qt::AlignLeft,  Qt::AlignRight, Qt::AlignRight, Qt::AlignRight,
                          Qt::AlignRight, Qt::AlignRight, Qt::AlignRight};
  for (const SetupRunOutcome* o : {&exact, &cripso, &pso}) {
    const QString method = QString::fromStdString(o->method);
    comparison.rows.push_back(
        {o->method == "exact" ? setupMethodTitle(method) : setupRunLabel(method, o->seed), mm(o->score.f1),
         mm(o->score.f2), mm(o->score.f), mm(o->score.f1 - o->f1Before), mm(exact.score.f1 - o->score.f1),
         o->method == "exact" ? QStringLiteral("—") : QString::number(o->evaluations)});
  }
  out.table(comparison);
  out.paragraph(
      ReportText::tr(
          "Exact certificate: f1 %1 on the grid, |x| %2 among the f1-optimal corrections (%3 LP / MILP "
          "solver calls). Gap f1: the exact f1 minus the method's.")
          .arg(exact.f1Optimal ? ReportText::tr("proven optimal") : ReportText::tr("NOT proven optimal"),
               exact.f2Optimal ? ReportText::tr("proven minimal") : ReportText::tr("not proven minimal"))
          .arg(exact.evaluations),
      ReportPainter::Font::Small);

  // ---- corrections ----
  out.subheading(ReportText::tr("Corrections (mm, to add to the registers along %1)")
                     .arg(QString::fromStdString(model.axis)),
                 out.mm(30.0));
  ReportTable corrections;
  corrections.header = {ReportText::tr("setup datum"),
                        ReportText::tr("kind"),
                        ReportText::tr("register"),
                        ReportText::tr("exact"),
                        setupMethodTitle(QStringLiteral("cripso")),
                        setupMethodTitle(QStringLiteral("pso"))};
  corrections.widths = {1.0, 1.2, 0.8, 1.0, 1.0, 1.0};
  corrections.alignment = {Qt::AlignLeft,  Qt::AlignLeft,  Qt::AlignRight,
                           Qt::AlignRight, Qt::AlignRight, Qt::AlignRight};
  QStringList registerErrors;  // a datum without a register number: "—" in the table, the reason below it
  for (std::size_t i = 0; i < model.setup.size(); ++i) {
    QString reg = QStringLiteral("—");
    try {
      reg = QString::number(setup::registerOf(model, i));
    } catch (const std::exception& e) {
      registerErrors << QString::fromStdString(e.what());
    }
    corrections.rows.push_back({QString::fromStdString(model.setup[i].id), kindTitle(model.setup[i].kind),
                                reg, mm(exact.x[i], 3), mm(cripso.x[i], 3), mm(pso.x[i], 3)});
  }
  out.table(corrections);
  for (const QString& error : registerErrors)
    out.paragraph(
        ReportText::tr("Error in the setup model of the study %1: %2").arg(setupSectionTitle(), error));

  // ---- margins ----
  const double rowHeight = out.mm(4.4);
  out.subheading(ReportText::tr("Margins per dimension, before and after the exact correction"),
                 setupMarginsHeight(std::min<std::size_t>(8, instance.dimensions()), rowHeight));
  std::vector<SetupMarginRow> rows;
  const std::vector<double> after = instance.deviationsAfter(exact.x);
  for (std::size_t q = 0; q < instance.dimensions(); ++q)
    rows.push_back({QString::fromStdString(instance.dimensionIds()[q]), instance.lowerLimit(q),
                    instance.upperLimit(q), instance.deviation(q), after[q]});
  const QFont small = out.font(ReportPainter::Font::Small);
  // Split long lists over pages: as many rows as fit, at least 8 per block.
  std::size_t first = 0;
  while (first < rows.size()) {
    const double fixed = setupMarginsHeight(0, rowHeight);
    std::size_t fit = static_cast<std::size_t>(std::max(0.0, (out.remaining() - fixed) / rowHeight));
    if (fit < 8 && fit < rows.size() - first) {
      out.newPage();
      fit = static_cast<std::size_t>(std::max(0.0, (out.remaining() - fixed) / rowHeight));
    }
    const std::size_t n = std::min(std::max<std::size_t>(fit, 1), rows.size() - first);
    const std::vector<SetupMarginRow> block(rows.begin() + static_cast<std::ptrdiff_t>(first),
                                            rows.begin() + static_cast<std::ptrdiff_t>(first + n));
    const QRectF r = out.reserve(setupMarginsHeight(n, rowHeight));
    paintSetupMargins(out.painter(), r, block, small, rowHeight, QLocale::c());
    first += n;
  }
  out.skip(out.mm(2.0));

  // ---- export ----
  out.subheading(ReportText::tr("Export for the controller (Fanuc, exact corrections)"), out.mm(40.0));
  out.paragraph(
      ReportText::tr("metrofit-cli setup --export fanuc writes the same text; Heidenhain, Siemens and CSV "
                     "are the other formats (see the sign convention in the header)."),
      ReportPainter::Font::Small);
  codeBlock(out,
            QString::fromStdString(setup::exportCorrections(model, exact.x, setup::ControllerFormat::Fanuc)));

  // ---- conclusion ----
  int outAfter = 0;
  for (std::size_t q = 0; q < instance.dimensions(); ++q)
    outAfter += (after[q] < instance.lowerLimit(q) || after[q] > instance.upperLimit(q));
  const double bonus = exact.score.f1 - exact.f1Before;
  SectionFinding f;
  f.study = setupSectionTitle();
  f.found = ReportText::tr(
                "The exact correction of %1 setup data raises the smallest error budget f1 from "
                "%2 mm to %3 mm%4; CRIPSO and PSO reach %5 mm and %6 mm.")
                .arg(model.setup.size())
                .arg(mm(exact.f1Before, 3), mm(exact.score.f1, 3))
                .arg(exact.f1Optimal ? ReportText::tr(" (proven optimal)") : QString())
                .arg(mm(cripso.score.f1, 3), mm(pso.score.f1, 3));
  const QString file = QStringLiteral("corrections-fanuc.nc");
  if (bonus > 0.0) {
    // One line per kind of register: "W1 +0.013, W2 +0.027 mm".
    for (const setup::DatumKind kind :
         {setup::DatumKind::Wks, setup::DatumKind::Tool, setup::DatumKind::Machine}) {
      QStringList values;
      for (std::size_t i = 0; i < model.setup.size(); ++i) {
        if (model.setup[i].kind != kind || std::abs(exact.x[i]) < 0.5 * model.stepMm) continue;
        values << QStringLiteral("%1 %2%3").arg(QString::fromStdString(model.setup[i].id),
                                                exact.x[i] > 0 ? QStringLiteral("+") : QString(),
                                                mm(exact.x[i], 3));
      }
      if (values.isEmpty()) continue;
      const QString what = kind == setup::DatumKind::Wks    ? ReportText::tr("work offsets")
                           : kind == setup::DatumKind::Tool ? ReportText::tr("tool lengths")
                                                            : ReportText::tr("machine points");
      f.changes.push_back({what, values.join(QStringLiteral(", ")) + QStringLiteral(" mm"),
                           ReportText::tr("add along %1; file %2 (program O7001)")
                               .arg(QString::fromStdString(model.axis), file)});
    }
  }
  f.before = ReportText::tr("f1 %1 mm; %2 of %3 dimensions out of tolerance")
                 .arg(mm(exact.f1Before, 3))
                 .arg(outBefore)
                 .arg(instance.dimensions());
  f.after = ReportText::tr("f1 %1 mm; %2 of %3 dimensions out of tolerance")
                .arg(mm(exact.score.f1, 3))
                .arg(outAfter)
                .arg(instance.dimensions());
  f.conclusion = bonus > 0.0 ? ReportText::tr(
                                   "The correction widens the smallest margin to the tolerance limits "
                                   "by %1 mm; %2 of %3 dimensions stay out of tolerance.")
                                   .arg(mm(bonus, 3))
                                   .arg(outAfter)
                                   .arg(instance.dimensions())
                             : ReportText::tr(
                                   "No correction widens the smallest margin: the registers are as "
                                   "good as the measurements allow.");
  f.recommendation = bonus > 0.0
                         ? ReportText::tr(
                               "Add the exact corrections to the offset registers (%1, Setup page, Export; "
                               "Heidenhain and Siemens formats there too), then measure the next part.")
                               .arg(file)
                         : ReportText::tr("Leave the offset registers as they are.");
  concludeSection(out, context, f);
}

}  // namespace metrofit
