// Report section "Closed loop: diagnosis": for every domain the project's diagnosis study
// configures (core/study/diagnosis_study.h), the loop step by step: the declared model's error,
// each candidate effect with its parameters, evidence and decision, the final error; the residual
// plot before / after of each accepted effect (painted like the GUI's, widgets/diagnose/residualplot.h),
// what is left unexplained (the residual check: verdict, structure with shares, generic effects,
// outliers excluded, in reader's words, widgets/diagnose/residualchecktext.h) with the final residual
// against the variable of the strongest structure, and a before / after table.
#include <QCoreApplication>
#include <QPainter>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <memory>
#include <string>

#include "core/io/csv.h"
#include "core/study/diagnosis_study.h"
#include "widgets/diagnose/residualchecktext.h"
#include "widgets/diagnose/residualcheckview.h"
#include "widgets/diagnose/residualplot.h"
#include "widgets/report/reportpainter.h"
#include "widgets/report/sections.h"

namespace metrofit {
namespace {

struct ReportText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::Report)
};

QString num(double v, int digits = 4) {
  return std::isfinite(v) ? QString::fromStdString(CsvWriter::formatNumber(v, digits))
                          : QStringLiteral("n/a");
}

QString domainTitle(DiagnosisDomain d) {
  switch (d) {
    case DiagnosisDomain::Thermal:
      return ReportText::tr("Thermal");
    case DiagnosisDomain::Kinematic:
      return ReportText::tr("Kinematic");
    case DiagnosisDomain::Setup:
      return ReportText::tr("Setup data");
    case DiagnosisDomain::Matching:
      return ReportText::tr("Posture matching");
  }
  return {};
}

/// The loop of one domain's settings, run once per report (the report is laid out twice).
std::shared_ptr<const diagnose::Diagnosis> memoDiagnosis(const ReportContext& context,
                                                         const DiagnosisSettings& s) {
  return context.memo.get<diagnose::Diagnosis>(
      diagnosisSettingsKey(s), [&] { return std::make_shared<const diagnose::Diagnosis>(runDiagnosis(s)); });
}

QString parameters(const diagnose::Candidate& c) {
  QStringList parts;
  const bool formGiven = std::any_of(c.parameters.begin(), c.parameters.end(),
                                     [](const diagnose::Parameter& p) { return p.name == "form"; });
  if (c.generic && !formGiven)
    parts << ReportText::tr("form %1").arg(dependenceFormLabel(*c.generic, QLocale::c()));
  for (const diagnose::Parameter& p : c.parameters) {
    QString s = QString::fromStdString(p.name) + QStringLiteral(" ") +
                QString::fromStdString(formatParameterValue(p));
    if (p.standardError) s += QStringLiteral(" ± ") + num(*p.standardError, 2);
    parts << s;
  }
  return parts.join(QStringLiteral("; "));
}

QString errorLine(const diagnose::ErrorSummary& e, const QString& u) {
  QString s = ReportText::tr("rmse %1 %2, max |e| %3 %2").arg(num(e.rmse), u, num(e.maxAbs));
  if (e.heldoutRmse) s += ReportText::tr(", held-out rmse %1 %2").arg(num(*e.heldoutRmse), u);
  return s;
}

/// The error in three significant digits, for page 1.
QString shortErrorLine(const diagnose::ErrorSummary& e, const QString& u) {
  QString s = ReportText::tr("rmse %1 %2").arg(num(e.rmse, 3), u);
  if (e.heldoutRmse) s += ReportText::tr(", held-out %1 %2").arg(num(*e.heldoutRmse, 3), u);
  return s;
}

void writeDomain(ReportPainter& out, const ReportContext& context, DiagnosisDomain domain) {
  DiagnosisSettings s;
  std::shared_ptr<const diagnose::Diagnosis> d;
  QString failure;
  try {
    s = diagnosisSettings(*context.project, std::string(), domain);
    // Paths as the report resolved them (against the project file's folder).
    for (const ReportDataset& rd : context.datasets) {
      if (rd.ref.id == s.datasetId) {
        s.datasetPath = rd.path.toStdString();
        s.datasetPaths = rd.paths;  // a DMIS series: every file; empty: the one file above
      }
      if (!s.modelId.empty() && rd.ref.id == s.modelId) s.modelPath = rd.path.toStdString();
      if (!s.nominals.reference.empty() && rd.ref.id == s.nominals.reference)
        s.referencePath = rd.path.toStdString();
    }
    d = memoDiagnosis(context, s);
  } catch (const std::exception& e) {
    failure = QString::fromUtf8(e.what());
  }
  out.subheading(ReportText::tr("%1: %2").arg(domainTitle(domain), QString::fromStdString(s.datasetId)),
                 out.mm(40.0));
  if (!d) {
    out.paragraph(ReportText::tr("The diagnosis could not run: %1").arg(failure));
    SectionFinding f;
    f.study = ReportText::tr("Closed loop: %1").arg(domainTitle(domain).toLower());
    f.found = ReportText::tr("The diagnosis could not run: %1").arg(failure);
    f.unexplained = ReportText::tr("not checked");
    f.recommendation = ReportText::tr("Correct the diagnosis settings of this study.");
    concludeSection(out, context, f);
    return;
  }
  const QString u = d->units == "um" ? QStringLiteral("µm") : QString::fromStdString(d->units);
  QString declared;
  switch (domain) {
    case DiagnosisDomain::Thermal: {
      QStringList in;
      for (const auto& i : s.inputs) in << QString::fromStdString(i);
      declared = ReportText::tr(
                     "Declared model: %1 a static linear function of %2, fitted on the first %3 % of "
                     "the rows and held out on the rest.")
                     .arg(QString::fromStdString(s.target), in.join(QStringLiteral(", ")))
                     .arg(s.trainFraction * 100.0, 0, 'g', 3);
      break;
    }
    case DiagnosisDomain::Kinematic:
      declared =
          ReportText::tr("Declared model: the Cartesian machine's actuator errors (origin, axis angles).");
      break;
    case DiagnosisDomain::Setup:
      declared = ReportText::tr(
                     "Declared model: constant setup-data errors acting through the relation graph "
                     "of %1.")
                     .arg(QString::fromStdString(s.modelId));
      break;
    case DiagnosisDomain::Matching:
      declared = ReportText::tr(
                     "Declared model: a rigid posture error (rotation and translation); tolerance "
                     "±%1 mm.")
                     .arg(s.toleranceMm, 0, 'g', 4);
      break;
  }
  out.paragraph(declared);
  for (const std::string& note : d->notes) out.paragraph(readerText(note), ReportPainter::Font::Small);
  out.paragraph(ReportText::tr("Step 0, the declared model: %1.").arg(errorLine(d->baseline, u)));

  const bool heldout = d->baseline.heldoutRmse.has_value();
  ReportTable t;
  t.header = {ReportText::tr("#"), ReportText::tr("effect"), ReportText::tr("parameters ± standard error"),
              ReportText::tr("rmse (%1)").arg(u)};
  if (heldout) t.header << ReportText::tr("held-out (%1)").arg(u);
  t.header << ReportText::tr("accepted");
  t.widths =
      heldout ? QList<double>{0.35, 2.0, 3.2, 1.5, 1.5, 1.05} : QList<double>{0.35, 2.0, 4.0, 1.8, 1.05};
  t.alignment = {Qt::AlignRight, Qt::AlignLeft, Qt::AlignLeft, Qt::AlignRight};
  if (heldout) t.alignment << Qt::AlignRight;
  t.alignment << Qt::AlignHCenter;
  for (const diagnose::Candidate& c : d->effects) {
    QStringList row{QString::number(c.round + 1), QString::fromStdString(c.name), parameters(c),
                    QStringLiteral("%1 → %2").arg(num(c.rmseBefore, 3), num(c.rmseAfter, 3))};
    if (heldout) {
      row << (c.heldoutBefore && c.heldoutAfter
                  ? QStringLiteral("%1 → %2").arg(num(*c.heldoutBefore, 3), num(*c.heldoutAfter, 3))
                  : QStringLiteral("–"));
    }
    row << (c.accepted ? ReportText::tr("yes") : ReportText::tr("no"));
    t.rows.push_back(row);
  }
  out.table(t);
  out.paragraph(ReportText::tr("Evidence, per candidate (# = loop round):"), ReportPainter::Font::Small);
  for (const diagnose::Candidate& c : d->effects) {
    out.paragraph(
        QStringLiteral("%1 %2: %3")
            .arg(QString::number(c.round + 1), QString::fromStdString(c.name), readerText(c.evidence)),
        ReportPainter::Font::Small);
  }
  const auto accepted = d->accepted();
  if (accepted.empty()) {
    out.paragraph(ReportText::tr("No candidate passed the evidence test: the declared model is kept. %1.")
                      .arg(errorLine(d->final, u)));
  } else {
    QStringList names;
    for (const auto* c : accepted) names << QString::fromStdString(c->name);
    out.paragraph(ReportText::tr("Accepted: %1. Final model: %2.")
                      .arg(names.join(QStringLiteral(", ")), errorLine(d->final, u)));
  }
  for (const diagnose::Candidate* c : accepted) {
    if (!c->plot) continue;
    const diagnose::ResidualPlot& plot = *c->plot;
    const QString title = ReportText::tr("Residual before and after %1").arg(QString::fromStdString(c->name));
    out.skip(out.mm(2.0));
    const QRectF box = out.reserve(out.mm(hasVectorField(plot) ? 95.0 : 70.0));
    if (hasVectorField(plot)) {
      const QRectF left(box.left() + box.width() * 0.15, box.top(), box.width() * 0.7, box.height());
      out.drawScaled(left, 480.0,
                     [&](QPainter& p, const QRectF& r) { paintResidualVectors(p, r, plot, title, 11.0); });
    } else {
      out.drawScaled(box, 700.0,
                     [&](QPainter& p, const QRectF& r) { paintResidualScatter(p, r, plot, title, 11.0); });
    }
  }
  if (d->residualCheck) writeResidualCheck(out, *d);
  ReportTable ba;
  ba.header = {ReportText::tr("error (%1)").arg(u), ReportText::tr("declared model"),
               ReportText::tr("with accepted effects")};
  ba.widths = {1.6, 1.2, 1.5};
  ba.alignment = {Qt::AlignLeft, Qt::AlignRight, Qt::AlignRight};
  ba.widthFraction = 0.8;
  ba.rows.push_back({ReportText::tr("rmse (fitted data)"), num(d->baseline.rmse), num(d->final.rmse)});
  ba.rows.push_back({ReportText::tr("max |e| (fitted data)"), num(d->baseline.maxAbs), num(d->final.maxAbs)});
  if (d->baseline.heldoutRmse && d->final.heldoutRmse)
    ba.rows.push_back(
        {ReportText::tr("rmse (held-out rows)"), num(*d->baseline.heldoutRmse), num(*d->final.heldoutRmse)});
  out.skip(out.mm(2.0));
  out.table(ba);

  // Conclusion of this domain.
  SectionFinding f;
  f.study = ReportText::tr("Closed loop: %1").arg(domainTitle(domain).toLower());
  QStringList names;
  for (const auto* c : accepted) names << QString::fromStdString(c->name);
  f.found = accepted.empty()
                ? ReportText::tr("%1: no effect beyond the declared model is supported by the data.")
                      .arg(QString::fromStdString(s.datasetId))
                : ReportText::tr("%1: the declared model lacks %2.")
                      .arg(QString::fromStdString(s.datasetId), names.join(QStringLiteral(", ")));
  f.before = shortErrorLine(d->baseline, u);
  f.after = accepted.empty()
                ? QString()
                : ReportText::tr("%1 → %2").arg(shortErrorLine(d->baseline, u), shortErrorLine(d->final, u));
  const QStringList sentences = d->residualCheck ? residualCheckSentences(*d, QLocale::c()) : QStringList();
  const bool white = d->residualCheck && d->residualCheck->white;
  // The verdict without its lead-in ("What is left unexplained: ..."), the summary's column says it.
  QString verdict = sentences.isEmpty() ? QString() : sentences.front();
  if (const qsizetype colon = verdict.indexOf(QStringLiteral(": ")); colon > 0 && colon < 40)
    verdict = verdict.mid(colon + 2);
  if (!verdict.isEmpty()) verdict[0] = verdict[0].toUpper();
  // Page 1 takes the verdict's first sentence; the section gives the whole of it.
  if (const qsizetype stop = verdict.indexOf(QStringLiteral(". ")); stop > 0)
    verdict = verdict.left(stop + 1);
  f.unexplained = verdict.isEmpty() ? ReportText::tr("not checked") : verdict;
  f.conclusion = f.found;
  if (!verdict.isEmpty())
    f.conclusion += QLatin1Char(' ') +
                    ReportText::tr("Still unexplained: %1").arg(verdict.left(1).toLower() + verdict.mid(1));
  if (!accepted.empty())
    f.recommendation = white ? ReportText::tr("Add %1 to the model (Apply on the Diagnosis page).")
                                   .arg(names.join(QStringLiteral(", ")))
                             : ReportText::tr(
                                   "Add %1 to the model (Apply on the Diagnosis page), then look for "
                                   "the cause of what is still unexplained before trusting the "
                                   "compensation further.")
                                   .arg(names.join(QStringLiteral(", ")));
  else
    f.recommendation = white ? ReportText::tr("Keep the declared model: its residual is noise.")
                             : ReportText::tr(
                                   "Keep the declared model, and look for the cause of what is still "
                                   "unexplained (a variable not recorded, a change in the process).");
  concludeSection(out, context, f);
}

}  // namespace

void writeResidualCheck(ReportPainter& out, const diagnose::Diagnosis& d) {
  if (!d.residualCheck) return;
  const diagnose::ResidualCheck& c = *d.residualCheck;
  out.skip(out.mm(2.0));
  const QStringList sentences = residualCheckSentences(d, QLocale::c());
  for (int i = 0; i < sentences.size(); ++i)
    out.paragraph(sentences[i], i == 0 ? ReportPainter::Font::Body : ReportPainter::Font::Small);
  if (!c.plot) return;
  const QString units = d.units == "um" ? QStringLiteral("µm") : QString::fromStdString(d.units);
  const auto strongest =
      std::find_if(c.structure.begin(), c.structure.end(),
                   [&](const diagnose::StructureItem& s) { return s.against == c.plot->against; });
  const QString variable = residualVariableName(c.plot->against);
  const QString title = strongest == c.structure.end()
                            ? ReportText::tr("Final residual against %1").arg(variable)
                            : ReportText::tr("Final residual against %1 with the generic fit (%2)")
                                  .arg(variable, dependenceFormLabel(*strongest, QLocale::c()));
  out.skip(out.mm(2.0));
  const QRectF box = out.reserve(out.mm(70.0));
  const diagnose::ResidualCheck::Plot& plot = *c.plot;
  out.drawScaled(box, 700.0,
                 [&](QPainter& p, const QRectF& r) { paintResidualCheck(p, r, plot, units, title, 11.0); });
}

QString diagnosisSectionTitle() {
  return ReportText::tr("Closed loop: diagnosis");
}

bool hasDiagnosisStudy(const ReportContext& context) {
  if (!context.project) return false;
  for (DiagnosisDomain d : kDiagnosisDomains) {
    if (hasDiagnosisSettings(*context.project, d)) return true;
  }
  return false;
}

void writeDiagnosisSection(ReportPainter& out, const ReportContext& context) {
  out.paragraph(ReportText::tr(
      "For each study the declared model is fitted and its residual computed; candidate effects "
      "the model lacks are tried one by one, each estimated with its parameters and their "
      "standard errors. An effect is accepted only on evidence (out-of-sample improvement for "
      "thermal, an information criterion with a conservative threshold elsewhere) and when it "
      "reduces the error by a practically relevant amount; the model is refitted with it and "
      "the search repeated until nothing more is found."));
  for (DiagnosisDomain d : kDiagnosisDomains) {
    if (hasDiagnosisSettings(*context.project, d)) writeDomain(out, context, d);
  }
}

}  // namespace metrofit
