// Report section "Kinematic compensation and SPC" (IEEE Access, kinematic compensation algorithm): per
// circular test the identified actuator errors with their standard errors, the path and the ballbar-style
// polar plot (the same drawings as the GUI, kinematicplots.h), the compensation of the nominal circle
// (largest radial deviation before and after), the ballbar breakdown into named causes, the SPC charts and
// indices of the study's feature series, the paper's chain from the SPC regression offset angles to actuator
// errors and their compensation (studies.kinematics.from_spc) and the three-axis errors from circular tests
// in XY, YZ and ZX (studies.kinematics.planes).
#include <QCoreApplication>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <optional>

#include "core/common/error.h"
#include "core/study/kinematic_study.h"
#include "widgets/kinematics/ballbartext.h"
#include "widgets/kinematics/kinematicplots.h"
#include "widgets/report/reportpainter.h"
#include "widgets/report/sections.h"

namespace metrofit {
namespace {

struct ReportText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::Report)
};

QString um(double mm, int decimals = 3) {
  return QString::number(mm * 1000.0, 'f', decimals);
}

QString deg(double d) {
  return QString::number(d, 'f', 6);
}

void writeErrors(ReportPainter& out, const KinematicStudyData& s) {
  const IdentifyResult& r = s.identification;
  const auto& truth = s.settings.simulatedMachine;
  ReportTable t;
  t.header = {ReportText::tr("error"), ReportText::tr("identified"), ReportText::tr("standard error")};
  if (truth) t.header << ReportText::tr("simulated (true)");
  t.widths = truth ? QList<double>{2.2, 1.3, 1.3, 1.3} : QList<double>{2.2, 1.3, 1.3};
  t.alignment = {Qt::AlignLeft, Qt::AlignRight, Qt::AlignRight, Qt::AlignRight};
  auto row = [&](const QString& name, const QString& v, const QString& se, const QString& tv) {
    QStringList cells{name, v, se};
    if (truth) cells << tv;
    t.rows.push_back(cells);
  };
  row(ReportText::tr("origin x (µm)"), um(r.errors.originMm.x()), um(r.standardErrors.originMm.x()),
      truth ? um(truth->originMm.x()) : QString());
  row(ReportText::tr("origin y (µm)"), um(r.errors.originMm.y()), um(r.standardErrors.originMm.y()),
      truth ? um(truth->originMm.y()) : QString());
  row(ReportText::tr("X axis angle a (deg)"), deg(r.errors.xAxisAngleDeg),
      deg(r.standardErrors.xAxisAngleDeg), truth ? deg(truth->xAxisAngleDeg) : QString());
  row(ReportText::tr("Y axis angle b (deg)"), deg(r.errors.yAxisAngleDeg),
      deg(r.standardErrors.yAxisAngleDeg), truth ? deg(truth->yAxisAngleDeg) : QString());
  row(ReportText::tr("squareness b − a (deg)"), deg(r.errors.squarenessDeg()), deg(r.squarenessStdErrDeg),
      truth ? deg(truth->squarenessDeg()) : QString());
  row(ReportText::tr("RMS residual (µm)"), um(r.rmseMm), QString(), QString());
  out.table(t);
}

/// ISO 230-4 results of the test (core/kinematics/iso230_4.h), in µm.
void writeIso230(ReportPainter& out, const Iso230Result& iso) {
  if (iso.directions.empty()) return;
  out.subheading(ReportText::tr("ISO 230-4 results"), out.mm(30.0));
  out.paragraph(
      ReportText::tr("Per direction: the circular deviation G (radial range about the path's own "
                     "least-squares centre) and the radial deviation F (largest and smallest "
                     "deviation from the nominal radius about the nominal centre)."));
  ReportTable t;
  t.header = {ReportText::tr("direction"), ReportText::tr("G (µm)"), ReportText::tr("F max (µm)"),
              ReportText::tr("F min (µm)"), ReportText::tr("LSQ centre (mm)")};
  t.widths = {1.0, 1.0, 1.0, 1.0, 2.0};
  t.alignment = {Qt::AlignLeft, Qt::AlignRight, Qt::AlignRight, Qt::AlignRight, Qt::AlignRight};
  for (const Iso230Direction& d : iso.directions) {
    t.rows.push_back({d.counterClockwise ? ReportText::tr("CCW") : ReportText::tr("CW"),
                      um(d.circularDeviationMm, 2), um(d.radialDeviationMaxMm, 2),
                      um(d.radialDeviationMinMm, 2),
                      QStringLiteral("%1, %2").arg(QString::number(d.lsqCentreMm.x(), 'f', 4),
                                                   QString::number(d.lsqCentreMm.y(), 'f', 4))});
  }
  out.table(t);
  out.paragraph(
      iso.circularHysteresisMm
          ? ReportText::tr("Circular hysteresis H (largest radial difference between the CW and the "
                           "CCW path at the same angle, about one least-squares centre): %1 µm.")
                .arg(um(*iso.circularHysteresisMm, 2))
          : ReportText::tr("Circular hysteresis H: not available (the test has one direction only)."));
}

/// The ballbar breakdown of the test into named causes (core/kinematics/ballbar.h), ranked by share.
void writeBallbar(ReportPainter& out, const CircularAnalysis& a) {
  out.subheading(ReportText::tr("Ballbar breakdown"), out.mm(30.0));
  if (!a.ballbar) {
    out.paragraph(ReportText::tr("Not available: %1.").arg(QString::fromStdString(a.ballbarUnavailable)));
    return;
  }
  const BallbarBreakdown& b = *a.ballbar;
  out.paragraph(
      ReportText::tr("The radial deviation of %1 fitted by least squares to the signature of each cause, "
                     "after the centre and radius of each run; ranked by share, the part of the radial "
                     "deviation's variance the cause explains. A cause is above the noise when its value "
                     "exceeds three standard errors.")
          .arg(b.bothDirections ? ReportText::tr("both runs (CCW and CW)")
                                : ReportText::tr("the one run (without the reversal causes, which need both "
                                                 "directions)")));
  ReportTable t;
  t.header = {ReportText::tr("cause"), ReportText::tr("value (µm)"), ReportText::tr("± std. error (µm)"),
              ReportText::tr("share (%)"), ReportText::tr("above the noise")};
  t.widths = {2.0, 1.0, 1.2, 1.0, 1.2};
  t.alignment = {Qt::AlignLeft, Qt::AlignRight, Qt::AlignRight, Qt::AlignRight, Qt::AlignLeft};
  for (const BallbarCause& c : b.causes) {
    t.rows.push_back({ballbarCauseName(c.name), QString::number(c.valueUm, 'f', 3),
                      QString::number(c.stdErrorUm, 'f', 3), QString::number(c.share * 100.0, 'f', 1),
                      c.significant ? ReportText::tr("yes") : ReportText::tr("no")});
  }
  t.rows.push_back({ballbarCauseName("unexplained"), QString::number(b.residualRmsUm, 'f', 3), QString(),
                    QString::number(b.unexplainedShare * 100.0, 'f', 1), QString()});
  out.table(t);
}

CompensationPreview writeCircularTest(ReportPainter& out, const KinematicStudyData& s) {
  out.subheading(ReportText::tr("Circular test “%1”").arg(QString::fromStdString(s.dataset.id)),
                 out.mm(60.0));
  if (!s.dataset.description.empty()) out.paragraph(QString::fromStdString(s.dataset.description));
  const auto mm4 = [](double v) {
    const QString t = QString::number(v, 'f', 4);
    return t == QLatin1String("-0.0000") ? QStringLiteral("0.0000") : t;
  };
  out.paragraph(
      ReportText::tr("%1 points; nominal circle R %2 mm about (%3, %4) mm; %5 loops (CCW, then CW). "
                     "The actuator errors of the Cartesian machine (%8, Eq. 9: P = o + ir·x + "
                     "jr·y, ir = (cos a, sin a), jr = (−sin b, cos b)) were identified by "
                     "Levenberg-Marquardt (%6, iterations: %7); standard errors from the residuals.")
          .arg(s.measured.size())
          .arg(s.analysis.radiusMm, 0, 'g', 6)
          .arg(mm4(s.analysis.centreMm.x()), mm4(s.analysis.centreMm.y()))
          .arg(s.analysis.loops.size())
          .arg(QString::fromLatin1(toString(s.identification.run.termination)))
          .arg(s.identification.run.iterations)
          .arg(citation(2)));
  writeErrors(out, s);
  if (!s.applied.empty()) {
    QString text = ReportText::tr(
                       "Includes applied effects: %1 (added with Apply on the diagnosis page). The errors "
                       "above were identified with them and the compensated references include their "
                       "corrections.")
                       .arg(QString::fromStdString(s.applied.text())
                                .replace(QStringLiteral(" um"), QStringLiteral(" µm")));
    if (s.declaredRmseMm)
      text += QLatin1Char(' ') +
              ReportText::tr("RMS residual of the declared model alone: %1 µm.").arg(um(*s.declaredRmseMm));
    out.paragraph(text);
  }

  const CompensationPreview c = compensateStudy(s);
  PathPlotData pd = circularPathData(s.measured, s.analysis, ReportText::tr("Path (XY)"));
  PolarPlotData polar = circularPolarData(s.analysis, ReportText::tr("Radial deviation (polar, magnified)"));
  addCompensationPreview(pd, polar, c, s.analysis);

  out.skip(out.mm(2.0));
  const QRectF box = out.reserve(out.mm(92.0));
  const double gap = out.mm(3.0);
  const QRectF left(box.left(), box.top(), (box.width() - gap) / 2.0, box.height());
  const QRectF right(left.right() + gap, box.top(), left.width(), box.height());
  PlotStyle style;
  style.fontPx = 10.0;
  style.lineWidth = 1.1;
  out.drawScaled(left, 400.0, [&](QPainter& p, const QRectF& r) { paintPathPlot(p, r, pd, style); });
  out.drawScaled(right, 400.0, [&](QPainter& p, const QRectF& r) { paintPolarPlot(p, r, polar, style); });
  writeIso230(out, s.analysis.iso);
  writeBallbar(out, s.analysis);

  out.subheading(ReportText::tr("Compensation"), out.mm(30.0));
  out.paragraph(
      ReportText::tr("Compensated references for the nominal circle (the commanded points of the "
                     "test) from the identified errors (Eq. 15), and the largest |radial deviation| "
                     "from the nominal circle before and after:"));
  ReportTable t;
  t.header = {ReportText::tr("path"), ReportText::tr("max. dev. (µm)")};
  t.widths = {3.4, 1.0};
  t.alignment = {Qt::AlignLeft, Qt::AlignRight};
  t.widthFraction = 0.8;
  t.rows.push_back({ReportText::tr("measured, before compensation"), um(c.maxBeforeMm)});
  if (c.maxSimulatedMm) {
    t.rows.push_back({ReportText::tr("after, through the simulated machine (true errors, noise free)"),
                      um(*c.maxSimulatedMm)});
  }
  t.rows.push_back(
      {ReportText::tr("after, expected from the measured residual (noise stays)"), um(c.maxExpectedMm)});
  t.rows.push_back({ReportText::tr("after, through the identified model"), um(c.maxModelMm, 6)});
  t.rows.push_back({ReportText::tr("largest correction |reference − nominal|"), um(c.largestCorrectionMm)});
  out.table(t);
  return c;
}

/// The SPC charts and indices; `ownPage`: from the top of a new page (after the circular test).
void writeSpc(ReportPainter& out, const std::optional<KinematicSpcSeries>& spc, const std::string& spcError,
              bool ownPage = true) {
  if (!spc) {
    if (!spcError.empty()) {
      out.subheading(ReportText::tr("Statistical process control"));
      out.paragraph(
          ReportText::tr("The SPC series could not be charted: %1").arg(QString::fromStdString(spcError)));
    }
    return;
  }
  const KinematicSpcSeries& k = *spc;
  const SpcResult& r = k.result;
  const QString unit = QString::fromStdString(k.unit);
  const QString u = unit.isEmpty() ? QString() : QLatin1Char(' ') + unit;
  if (ownPage) out.newPage();
  out.subheading(ReportText::tr("Statistical process control of “%1” (%2)")
                     .arg(QString::fromStdString(k.column), QString::fromStdString(k.dataset.id)),
                 out.mm(60.0));
  if (!k.dataset.description.empty()) out.paragraph(QString::fromStdString(k.dataset.description));
  PlotStyle style;
  style.fontPx = 10.0;
  style.lineWidth = 1.1;
  style.pointRadius = 2.2;
  for (const ControlChartKind kind : {ControlChartKind::Mean, ControlChartKind::Range}) {
    const QRectF box = out.reserve(out.mm(48.0));
    out.drawScaled(box, 700.0, [&](QPainter& p, const QRectF& rr) {
      paintControlChart(p, rr, r.chart, kind, unit, style, r.rules);
    });
  }
  HistogramData h = spcHistogramData(r, k.values, unit, QString());
  h.title = ReportText::tr("Histogram of %1 (%2 values)")
                .arg(QString::fromStdString(k.column))
                .arg(h.values.size());
  const QRectF hbox = out.reserve(out.mm(48.0));
  out.drawScaled(hbox, 700.0, [&](QPainter& p, const QRectF& rr) { paintHistogram(p, rr, h, style); });

  ReportTable t;
  t.header = {ReportText::tr("index"), ReportText::tr("value")};
  t.widths = {1.6, 3.0};
  t.rows.push_back({ReportText::tr("subgroups × size"),
                    QStringLiteral("%1 × %2").arg(r.chart.subgroups()).arg(r.chart.subgroupSize)});
  t.rows.push_back({ReportText::tr("A2 / D3 / D4"), QStringLiteral("%1 / %2 / %3")
                                                        .arg(r.constants.A2, 0, 'f', 3)
                                                        .arg(r.constants.D3, 0, 'f', 3)
                                                        .arg(r.constants.D4, 0, 'f', 3)});
  t.rows.push_back({ReportText::tr("X-bar chart CL / UCL / LCL"), QStringLiteral("%1 / %2 / %3")
                                                                          .arg(r.chart.grandMean, 0, 'g', 8)
                                                                          .arg(r.chart.xbarUcl, 0, 'g', 8)
                                                                          .arg(r.chart.xbarLcl, 0, 'g', 8) +
                                                                      u});
  t.rows.push_back({ReportText::tr("R chart CL / UCL / LCL"), QStringLiteral("%1 / %2 / %3")
                                                                      .arg(r.chart.meanRange, 0, 'g', 4)
                                                                      .arg(r.chart.rUcl, 0, 'g', 4)
                                                                      .arg(r.chart.rLcl, 0, 'g', 4) +
                                                                  u});
  t.rows.push_back(
      {ReportText::tr("in control"), r.chart.inControl() ? ReportText::tr("yes") : ReportText::tr("no")});
  t.rows.push_back({ReportText::tr("Nelson rules (subgroups)"), nelsonRulesSummary(r)});
  t.rows.push_back(
      {ReportText::tr("σ within (R̄ / d2)"), QString::number(r.capability.sigmaWithin, 'g', 4) + u});
  if (r.capability.cp) {
    t.rows.push_back(
        {ReportText::tr("LSL / USL"),
         QStringLiteral("%1 / %2").arg(*r.options.lsl, 0, 'g', 8).arg(*r.options.usl, 0, 'g', 8) + u});
    t.rows.push_back(
        {ReportText::tr("Cp (Eq. 16) / Cpk"),
         QStringLiteral("%1 / %2").arg(*r.capability.cp, 0, 'f', 2).arg(*r.capability.cpk, 0, 'f', 2)});
  }
  t.rows.push_back({ReportText::tr("natural tolerance (Eq. 17)"),
                    QString::number(r.capability.naturalTolerance, 'g', 4) + u});
  if (r.systematic) {
    t.rows.push_back({ReportText::tr("systematic error (Eq. 20)"),
                      ReportText::tr("%1%2 ± %3 (%4)")
                          .arg(QString::number(r.systematic->error, 'g', 4), u,
                               QString::number(r.systematic->halfWidth, 'g', 2),
                               r.systematic->significant ? ReportText::tr("significant")
                                                         : ReportText::tr("not significant"))});
  }
  t.rows.push_back(
      {ReportText::tr("regression offset angle (Fig. 10)"),
       ReportText::tr("%1° (slope %2%3 per sample, r² %4)")
           .arg(QString::number(r.trend.angleDeg, 'g', 3), QString::number(r.trend.slope, 'g', 3), u,
                QString::number(r.trend.r2, 'f', 2))});
  out.table(t);
  out.paragraph(ReportText::tr("SPC-gated compensation: %1").arg(readerText(r.decision.reason)));
}

/// The kinematic-compensation paper's chain from SPC to compensation, and the three-axis identification (when
/// configured).
void writeActuators(ReportPainter& out, const KinematicStudyData& s) {
  if (s.fromSpc || !s.fromSpcError.empty()) {
    out.subheading(ReportText::tr("From the SPC offset angle to actuator errors"), out.mm(50.0));
    if (!s.fromSpc) {
      out.paragraph(ReportText::tr("The actuator errors could not be derived from the edges: %1")
                        .arg(QString::fromStdString(s.fromSpcError)));
    } else {
      const SpcActuatorResult& r = *s.fromSpc;
      const IdentifyResult& id = s.identification;
      out.paragraph(
          ReportText::tr(
              "The regression line of the deviation of an edge machined along X against the measured "
              "position (%1, Fig. 10, Table 2) has the offset angle atan(slope); by Eq. 9 it is the X "
              "actuator's orientation error a, minus the offset angle of the edge along Y is b, and the "
              "two intercepts give the actuator origin (Table 3). A slope or intercept within ± %2 "
              "standard errors counts as scatter. The circular test's identification is an "
              "independent estimate of the same errors.")
              .arg(citation(2))
              .arg(r.options.coverageFactor, 0, 'g', 3));
      ReportTable t;
      t.header = {ReportText::tr("error"), ReportText::tr("from SPC"), ReportText::tr("from circular test")};
      t.widths = {2.4, 1.3, 1.3};
      t.alignment = {Qt::AlignLeft, Qt::AlignRight, Qt::AlignRight};
      t.rows.push_back({ReportText::tr("offset angle, edge along X (deg)"),
                        ReportText::tr("%1 ± %2").arg(deg(r.x.line.angleDeg),
                                                      deg(r.x.line.slopeStdErr * 57.29577951308232)),
                        QString()});
      t.rows.push_back({ReportText::tr("offset angle, edge along Y (deg)"),
                        ReportText::tr("%1 ± %2").arg(deg(r.y.line.angleDeg),
                                                      deg(r.y.line.slopeStdErr * 57.29577951308232)),
                        QString()});
      t.rows.push_back(
          {ReportText::tr("origin x (µm)"), um(r.errors.originMm.x()), um(id.errors.originMm.x())});
      t.rows.push_back(
          {ReportText::tr("origin y (µm)"), um(r.errors.originMm.y()), um(id.errors.originMm.y())});
      t.rows.push_back({ReportText::tr("X axis angle a (deg)"), deg(r.errors.xAxisAngleDeg),
                        deg(id.errors.xAxisAngleDeg)});
      t.rows.push_back({ReportText::tr("Y axis angle b (deg)"), deg(r.errors.yAxisAngleDeg),
                        deg(id.errors.yAxisAngleDeg)});
      t.rows.push_back({ReportText::tr("squareness b − a (deg)"), deg(r.errors.squarenessDeg()),
                        deg(id.errors.squarenessDeg())});
      t.rows.push_back({ReportText::tr("systematic error, edge along X / Y (Eq. 20, µm)"),
                        QStringLiteral("%1 / %2").arg(um(r.x.systematicErrorMm), um(r.y.systematicErrorMm)),
                        QString()});
      out.table(t);
      out.paragraph(
          (r.apply
               ? ReportText::tr("Compensation applied (Eq. 15): the largest correction of the nominal circle "
                                "is %1 µm; the circular test's model gives a largest deviation of %2 µm "
                                "before and %3 µm with the references derived from SPC.")
                     .arg(um(s.fromSpcLargestCorrectionMm, 1), um(s.fromSpcModelBeforeMm, 1),
                          um(s.fromSpcModelAfterMm, 1))
               : ReportText::tr("Not compensated: %1").arg(QString::fromStdString(r.reason))));
    }
  }
  if (s.threeAxis || !s.threeAxisError.empty()) {
    out.subheading(ReportText::tr("Three axes: circular tests in XY, YZ and ZX"), out.mm(45.0));
    if (!s.threeAxis) {
      out.paragraph(ReportText::tr("The three-axis errors could not be identified: %1")
                        .arg(QString::fromStdString(s.threeAxisError)));
      return;
    }
    const Identify3Result& r = *s.threeAxis;
    const ActuatorErrors3& e = r.errors;
    out.paragraph(
        ReportText::tr("The three-axis Cartesian model P = o + [i j k]·Pr (%1, Eq. 9 in three axes) "
                       "fitted to the three tests together (%2 points, RMS residual %3 µm): origin "
                       "(%4, %5, %6) µm. In every plane (u, v) the u actuator moves along (cos a, "
                       "sin a), the v actuator along (−sin b, cos b); squareness b − a.")
            .arg(citation(2))
            .arg(r.points)
            .arg(um(r.rmseMm), um(e.originMm.x()), um(e.originMm.y()), um(e.originMm.z())));
    ReportTable t;
    t.header = {ReportText::tr("plane"), ReportText::tr("a (deg)"), ReportText::tr("b (deg)"),
                ReportText::tr("squareness (deg)"), ReportText::tr("RMS (µm)")};
    t.widths = {0.8, 1.3, 1.3, 1.8, 1.0};
    t.alignment = {Qt::AlignLeft, Qt::AlignRight, Qt::AlignRight, Qt::AlignRight, Qt::AlignRight};
    for (const TestPlane p : kTestPlanes) {
      const auto i = static_cast<std::size_t>(p);
      t.rows.push_back({QString::fromLatin1(planeName(p)).toUpper(), deg(e.uAngleDeg[i]), deg(e.vAngleDeg[i]),
                        ReportText::tr("%1 ± %2").arg(deg(e.squarenessDeg(p)), deg(r.squarenessStdErrDeg[i])),
                        um(r.planes[i].rmseMm)});
    }
    out.table(t);
  }
}

/// What the SPC of the part series found, in the section's finding: "SPC of <column>: in control. Cpk x."
QString spcFound(const KinematicSpcSeries& spc) {
  const SpcResult& r = spc.result;
  QString found =
      ReportText::tr("SPC of %1: %2.")
          .arg(QString::fromStdString(spc.column),
               r.chart.inControl() ? ReportText::tr("in control") : ReportText::tr("out of control"));
  if (r.capability.cpk)
    found += QLatin1Char(' ') + ReportText::tr("Cpk %1.").arg(*r.capability.cpk, 0, 'f', 2);
  return found;
}

/// The section's conclusion: the identified errors, the compensation and the SPC decision.
void concludeKinematics(ReportPainter& out, const ReportContext& context, const KinematicStudyData& s,
                        const CompensationPreview& c) {
  const ActuatorErrors2& e = s.identification.errors;
  SectionFinding f;
  f.study = kinematicSectionTitle();
  f.found = ReportText::tr(
                "Circular test %1: actuator origin offset (%2, %3) µm, squareness error %4°; "
                "largest radial deviation %5 µm.")
                .arg(QString::fromStdString(s.dataset.id), um(e.originMm.x(), 1), um(e.originMm.y(), 1))
                .arg(e.squarenessDeg(), 0, 'f', 4)
                .arg(um(c.maxBeforeMm, 1));
  const QString file = QString::fromStdString(s.dataset.id) + QStringLiteral("_compensated.nc");
  f.changes.push_back({ReportText::tr("compensated references (G-code)"),
                       ReportText::tr("up to %1 µm").arg(um(c.largestCorrectionMm, 1)),
                       ReportText::tr("file %1 (Kinematics page, Export G-code)").arg(file)});
  f.before = ReportText::tr("largest radial deviation %1 µm").arg(um(c.maxBeforeMm, 1));
  f.after = ReportText::tr("%1 µm expected with the compensated references").arg(um(c.maxExpectedMm, 1));
  f.conclusion = ReportText::tr(
                     "The identified actuator errors explain the measured path; with the "
                     "compensated references the largest radial deviation falls from %1 µm to "
                     "about %2 µm (the measuring noise stays).")
                     .arg(um(c.maxBeforeMm, 1), um(c.maxExpectedMm, 1));
  f.recommendation =
      c.maxExpectedMm < c.maxBeforeMm
          ? ReportText::tr("Run the compensated references (%1) and repeat the circular test.").arg(file)
          : ReportText::tr("Do not compensate: the references would not reduce the deviation.");
  if (s.spc) {
    const SpcResult& r = s.spc->result;
    f.found += QLatin1Char(' ') + spcFound(*s.spc);
    f.conclusion +=
        QLatin1Char(' ') + ReportText::tr("SPC-gated compensation: %1").arg(readerText(r.decision.reason));
  }
  if (s.fromSpc) {
    const ActuatorErrors2& g = s.fromSpc->errors;
    f.found +=
        QLatin1Char(' ') + ReportText::tr("From the SPC offset angles: origin (%1, %2) µm, squareness %3°.")
                               .arg(um(g.originMm.x(), 1), um(g.originMm.y(), 1))
                               .arg(g.squarenessDeg(), 0, 'f', 4);
  }
  if (s.threeAxis) {
    const ActuatorErrors3& g = s.threeAxis->errors;
    f.found +=
        QLatin1Char(' ') + ReportText::tr("Squareness XY %1°, YZ %2°, ZX %3° (three-plane circular tests).")
                               .arg(g.squarenessDeg(TestPlane::XY), 0, 'f', 4)
                               .arg(g.squarenessDeg(TestPlane::YZ), 0, 'f', 4)
                               .arg(g.squarenessDeg(TestPlane::ZX), 0, 'f', 4);
  }
  concludeSection(out, context, f);
}

}  // namespace

namespace {

/// The section of a radial-only circular test (no identification): the polar plot and the ISO 230-4 results.
void writeRadialTest(ReportPainter& out, const ReportContext& context, const RadialStudyTest& t) {
  const CircularAnalysis& a = t.analysis;
  out.subheading(ReportText::tr("Circular test “%1”").arg(QString::fromStdString(t.dataset.id)),
                 out.mm(60.0));
  if (!t.dataset.description.empty()) out.paragraph(QString::fromStdString(t.dataset.description));
  out.paragraph(ReportText::tr("%1 points of a radial-only circular test (angle and radial deviation, as "
                               "ballbar software exports it); %2 loops. It has no commanded and measured x/y "
                               "coordinates, so the actuator errors cannot be identified from it and no "
                               "compensation is computed; its ISO 230-4 results follow.")
                    .arg(t.trace.size())
                    .arg(a.loops.size()));
  PolarPlotData polar =
      radialTestPolarData(t.trace, a, ReportText::tr("Radial deviation (polar, magnified)"));
  polar.autoScale();
  out.skip(out.mm(2.0));
  const QRectF box = out.reserve(out.mm(92.0));
  const QRectF plot(box.left() + box.width() / 4.0, box.top(), box.width() / 2.0, box.height());
  PlotStyle style;
  style.fontPx = 10.0;
  style.lineWidth = 1.1;
  out.drawScaled(plot, 400.0, [&](QPainter& p, const QRectF& r) { paintPolarPlot(p, r, polar, style); });
  writeIso230(out, a.iso);
  double g = 0.0;
  for (const Iso230Direction& d : a.iso.directions) g = std::max(g, d.circularDeviationMm);
  SectionFinding f;
  f.study = kinematicSectionTitle();
  f.found = ReportText::tr("Circular test %1 (radial only): largest circular deviation G %2 µm.")
                .arg(QString::fromStdString(t.dataset.id), um(g, 1));
  if (a.iso.circularHysteresisMm)
    f.found += QLatin1Char(' ') +
               ReportText::tr("Circular hysteresis H %1 µm.").arg(um(*a.iso.circularHysteresisMm, 1));
  f.conclusion = ReportText::tr(
      "The test gives the ISO 230-4 results only: a radial-only test cannot identify "
      "the actuator errors.");
  f.recommendation = ReportText::tr(
      "To identify and compensate the actuator errors, record the circular test "
      "with commanded and measured x/y coordinates.");
  concludeSection(out, context, f);
}

}  // namespace

namespace {

/// The section of a project whose kinematics study charts a part series and has no circular test: the
/// SPC charts, indices and decision, and their conclusion.
void writeSpcOnly(ReportPainter& out, const ReportContext& context,
                  const std::function<std::string(const DatasetRef&)>& resolve) {
  const KinematicStudySettings settings = kinematicStudySettings(*context.project);
  std::string error;
  const std::optional<KinematicSpcSeries> spc =
      settings.spc ? chartKinematicSpc(*context.project, *settings.spc, resolve, &error) : std::nullopt;
  out.paragraph(
      ReportText::tr("The project has no circular test: the study charts its part series only; "
                     "no actuator errors are identified and no compensation is computed."));
  writeSpc(out, spc, error, false);
  SectionFinding f;
  f.study = kinematicSectionTitle();
  if (!spc) {
    f.conclusion =
        error.empty()
            ? ReportText::tr("No SPC series is chosen.")
            : ReportText::tr("The SPC series could not be charted: %1").arg(QString::fromStdString(error));
    f.recommendation = ReportText::tr("Choose the series and its column on the Kinematics page, SPC tab.");
    concludeSection(out, context, f);
    return;
  }
  const SpcResult& r = spc->result;
  f.found = spcFound(*spc);
  f.conclusion = ReportText::tr("SPC-gated compensation: %1").arg(readerText(r.decision.reason));
  f.recommendation = r.chart.inControl()
                         ? ReportText::tr("Keep charting the series; act when a point leaves the limits.")
                         : ReportText::tr(
                               "Find the assignable cause of the out-of-control points before "
                               "compensating.");
  concludeSection(out, context, f);
}

}  // namespace

QString kinematicSectionTitle() {
  return ReportText::tr("Kinematic compensation and SPC");
}

void writeKinematicSection(ReportPainter& out, const ReportContext& context) {
  const Project& project = *context.project;
  auto resolve = [&context](const DatasetRef& ref) {
    for (const ReportDataset& d : context.datasets) {
      if (d.ref.id == ref.id) return d.path.toStdString();
    }
    return ref.path;
  };
  // A part series without a circular test (a shop charting its parts): the SPC charts alone.
  if (circularTestDatasets(project).empty()) {
    writeSpcOnly(out, context, resolve);
    return;
  }
  // A radial-only test (a ballbar export) cannot be identified: its ISO 230-4 results and polar plot.
  if (const std::optional<RadialStudyTest> radial = radialStudyTest(project, resolve)) {
    writeRadialTest(out, context, *radial);
    return;
  }
  // Only the study's circular test (the report shows the studies the project declares).
  try {
    const KinematicStudyData s = loadKinematicStudy(project, resolve);
    const CompensationPreview c = writeCircularTest(out, s);
    writeSpc(out, s.spc, s.spcError);
    writeActuators(out, s);
    concludeKinematics(out, context, s, c);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    out.paragraph(
        ReportText::tr("Cannot analyse the circular test: %1").arg(QString::fromStdString(e.what())));
    SectionFinding f;
    f.study = kinematicSectionTitle();
    f.conclusion =
        ReportText::tr("The circular test could not be analysed: %1").arg(QString::fromStdString(e.what()));
    f.recommendation = ReportText::tr("Repeat the circular test and check its file.");
    concludeSection(out, context, f);
  }
}

}  // namespace metrofit
