// Report section "Posture matching — before and after": for the matching study's probe
// points (studies.matching, core/study/matching_study.h) every method is run as in the GUI, and the section
// shows
//  - the 3D views before and after matching as images: the same oblique view as the GUI's linked 3D
//    views (camera direction (1, -1.4, 0.9), Z up), drawn with QPainter because the report is made by
//    `metrofit-cli report`, a process without a display (Debian's VTK has no offscreen context):
//    nominal points grey, deviation vectors magnified by one factor for both, the measured tip
//    coloured by deviation with the tolerance band (green within ±T), out-of-tolerance points larger
//    with a dark outline; planar sets are drawn from the top;
//  - the deviation table before / after per surface, the methods table (rough, SADE, GA-simplex,
//    closed form, minimax), the machine adjustment values and the remeasure loop's rounds.
#include <QCoreApplication>
#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include <Eigen/Geometry>

#include "core/common/axis_ticks.h"
#include "core/machine/controller_frame.h"
#include "core/matching/cad_match.h"
#include "core/project/nominals.h"
#include "core/study/matching_study.h"
#include "widgets/common/palette.h"
#include "widgets/report/reportpainter.h"
#include "widgets/report/sections.h"

namespace metrofit {
namespace {

struct ReportText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::Report)
};

using matching::MatchMethod;

constexpr double kViewHeightMm = 66.0;

QString methodName(MatchMethod m) {
  switch (m) {
    case MatchMethod::Sade:
      return ReportText::tr("SADE (paper settings)");
    case MatchMethod::GaSimplex:
      return ReportText::tr("GA-simplex");
    case MatchMethod::ClosedForm:
      return ReportText::tr("closed form (LS optimum)");
    case MatchMethod::Minimax:
      return ReportText::tr("minimax");
  }
  return {};
}

QString num(double v, int decimals) {
  return QString::number(std::abs(v) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : v, 'f', decimals);
}

QColor mix(const QColor& a, const QColor& b, double t) {
  t = std::clamp(t, 0.0, 1.0);
  return QColor::fromRgbF(static_cast<float>(a.redF() + (b.redF() - a.redF()) * t),
                          static_cast<float>(a.greenF() + (b.greenF() - a.greenF()) * t),
                          static_cast<float>(a.blueF() + (b.blueF() - a.blueF()) * t));
}

/// The GUI's colour map with the tolerance band (widgets/matching/pointsetview.cpp).
struct BandScale {
  double range = 1.0, tolerance = matching::kDefaultToleranceMm;
  QColor colour(double d) const {
    static const QColor green = palette::inTolerance();
    static const QColor coldLight = palette::coldLight(), coldEnd = palette::coldEnd();
    static const QColor warmLight = palette::warmLight(), warmEnd = palette::warmEnd();
    if (std::abs(d) <= tolerance) return green;
    const double t = (std::abs(d) - tolerance) / std::max(range - tolerance, 1e-12);
    return d > 0 ? mix(warmLight, warmEnd, t) : mix(coldLight, coldEnd, t);
  }
};

/// Projection of the GUI's default camera (or the top view for planar sets).
struct ViewProjection {
  Eigen::Vector3d right, up, depth;
  explicit ViewProjection(bool planar) {
    if (planar) {
      right = Eigen::Vector3d::UnitX();
      up = Eigen::Vector3d::UnitY();
      depth = -Eigen::Vector3d::UnitZ();
    } else {
      depth = -Eigen::Vector3d(1.0, -1.4, 0.9).normalized();  // direction of projection
      right = depth.cross(Eigen::Vector3d::UnitZ()).normalized();
      up = right.cross(depth);
    }
  }
  QPointF map(const Eigen::Vector3d& x) const { return QPointF(x.dot(right), x.dot(up)); }
};

struct ViewState {
  std::vector<Eigen::Vector3d> base;  ///< nominal (before) or transformed nominal (after)
  std::vector<Eigen::Vector3d> tip;   ///< base + k * displacement
  std::vector<double> deviation;
  /// A CAD nominal's part (moved by the view's posture) and each triangle's deviation (NaN: not probed
  /// near it; matching::triangleDeviations), drawn under the points.
  std::vector<std::array<Eigen::Vector3d, 3>> triangles;
  std::vector<double> triangleDeviation;
};

/// The part of a CAD nominal for a view: its triangles moved by `pose`, coloured by the deviations of
/// the points `closest` (the part's closest points the deviations are of).
void addPart(ViewState& s, const geometry::TriangleMesh& mesh, const matching::Pose& pose,
             const ProbePointSet& closest, const std::vector<double>& deviations) {
  for (const geometry::Triangle& t : mesh.triangles)
    s.triangles.push_back({pose.apply(t.v[0]), pose.apply(t.v[1]), pose.apply(t.v[2])});
  s.triangleDeviation = matching::triangleDeviations(mesh, closest, deviations);
}

ViewState viewState(const ProbePointSet& set, const matching::Pose& pose, const std::vector<double>& dev,
                    double factor) {
  ViewState s;
  for (std::size_t i = 0; i < set.points.size(); ++i) {
    const ProbePoint& p = set.points[i];
    const Eigen::Vector3d base = pose.apply(p.nominal);
    const Eigen::Vector3d displacement =
        set.hasNormals ? Eigen::Vector3d(dev[i] * p.normal) : (p.measured - base);
    s.base.push_back(base);
    s.tip.push_back(base + factor * displacement);
    s.deviation.push_back(dev[i]);
  }
  return s;
}

void drawView(ReportPainter& out, const QRectF& panel, const ViewProjection& proj, const ViewState& s,
              const QRectF& bounds, const BandScale& scale, const QString& title, const QString& subtitle) {
  QPainter& p = out.painter();
  p.save();
  p.setPen(QPen(QColor(0xbb, 0xbb, 0xbb), out.mm(0.2)));
  p.setBrush(Qt::white);
  p.drawRect(panel);
  p.setFont(out.font(ReportPainter::Font::Bold));
  p.setPen(Qt::black);
  const QFontMetricsF fm(out.font(ReportPainter::Font::Bold), p.device());
  p.drawText(
      QRectF(panel.left() + out.mm(2), panel.top() + out.mm(1), panel.width() - out.mm(4), fm.height()),
      Qt::AlignLeft | Qt::AlignVCenter, title);
  p.setFont(out.font(ReportPainter::Font::Small));
  const QFontMetricsF fs(out.font(ReportPainter::Font::Small), p.device());
  p.drawText(QRectF(panel.left() + out.mm(2), panel.top() + out.mm(1) + fm.height(),
                    panel.width() - out.mm(4), fs.height()),
             Qt::AlignLeft | Qt::AlignVCenter, subtitle);
  const QRectF plot =
      panel.adjusted(out.mm(4), out.mm(3) + fm.height() + fs.height(), -out.mm(4), -out.mm(4));
  // Uniform scale from the common bounds (both views share one camera, as in the GUI).
  const double k = std::min(plot.width() / bounds.width(), plot.height() / bounds.height());
  const QPointF offset(plot.center().x() - k * bounds.center().x(),
                       plot.center().y() + k * bounds.center().y());
  auto map = [&](const Eigen::Vector3d& x) {
    const QPointF q = proj.map(x);
    return QPointF(offset.x() + k * q.x(), offset.y() - k * q.y());
  };
  p.setClipRect(panel);
  // The part (a CAD nominal), far triangles first, light where it was not probed, under the points.
  if (!s.triangles.empty()) {
    std::vector<std::size_t> tri(s.triangles.size());
    std::iota(tri.begin(), tri.end(), std::size_t{0});
    const auto depthOf = [&](std::size_t t) {
      return (s.triangles[t][0] + s.triangles[t][1] + s.triangles[t][2]).dot(proj.depth);
    };
    std::stable_sort(tri.begin(), tri.end(),
                     [&](std::size_t a, std::size_t b) { return depthOf(a) > depthOf(b); });
    p.setPen(QPen(QColor(0x9a, 0x9a, 0x9a), out.mm(0.08)));
    for (std::size_t t : tri) {
      const double d = t < s.triangleDeviation.size() ? s.triangleDeviation[t] : std::nan("");
      QColor fill = std::isnan(d) ? QColor(0xdc, 0xdc, 0xdc) : scale.colour(d);
      fill.setAlphaF(0.55);
      p.setBrush(fill);
      const QPointF poly[3] = {map(s.triangles[t][0]), map(s.triangles[t][1]), map(s.triangles[t][2])};
      p.drawPolygon(poly, 3);
    }
  }
  // Far points first.
  std::vector<std::size_t> order(s.base.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return s.base[a].dot(proj.depth) > s.base[b].dot(proj.depth);
  });
  const double rIn = out.mm(0.9), rOut = out.mm(1.5), rNominal = out.mm(0.45);
  for (std::size_t i : order) {
    const QPointF b = map(s.base[i]);
    const QPointF t = map(s.tip[i]);
    p.setPen(QPen(QColor(0x55, 0x55, 0x55), out.mm(0.15)));
    p.drawLine(b, t);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0x80, 0x80, 0x80));
    p.drawEllipse(b, rNominal, rNominal);
    const bool outside = std::abs(s.deviation[i]) > scale.tolerance;
    p.setPen(outside ? QPen(QColor(0x20, 0x20, 0x20), out.mm(0.25))
                     : QPen(QColor(0x40, 0x40, 0x40), out.mm(0.08)));
    p.setBrush(scale.colour(s.deviation[i]));
    p.drawEllipse(t, outside ? rOut : rIn, outside ? rOut : rIn);
  }
  p.restore();
}

/// Vertical-free horizontal colour bar with the tolerance band.
void drawBandBar(ReportPainter& out, const QRectF& box, const BandScale& scale, bool signedScale,
                 const QString& title) {
  QPainter& p = out.painter();
  const QFont small = out.font(ReportPainter::Font::Small);
  const QFontMetricsF fm(small, p.device());
  const double barWidth = std::min(out.mm(120.0), 0.85 * box.width());
  const QRectF titleBox(box.center().x() - barWidth / 2, box.top(), barWidth, fm.height() * 1.2);
  const QRectF bar(titleBox.left(), titleBox.bottom(), barWidth, out.mm(4.0));
  const double lo = signedScale ? -scale.range : 0.0, hi = scale.range;
  constexpr int kSlices = 240;
  for (int i = 0; i < kSlices; ++i) {
    const double v = lo + (hi - lo) * (i + 0.5) / kSlices;
    p.fillRect(QRectF(bar.left() + bar.width() * i / kSlices, bar.top(), bar.width() / kSlices + out.mm(0.05),
                      bar.height()),
               scale.colour(v));
  }
  p.setPen(QPen(Qt::black, out.mm(0.15)));
  p.setBrush(Qt::NoBrush);
  p.drawRect(bar);
  p.setFont(small);
  p.drawText(titleBox, Qt::AlignHCenter | Qt::AlignTop, title);
  // Ends and zero always; the tolerance limits when they are far enough from zero to be labelled.
  const int decimals =
      std::clamp(static_cast<int>(1 - std::floor(std::log10(std::max(scale.range, 1e-6)))), 0, 4);
  std::vector<std::pair<double, QString>> ticks{{lo, num(lo, decimals)}, {hi, num(hi, decimals)}};
  if (signedScale) ticks.emplace_back(0.0, QStringLiteral("0"));
  const bool labelBand = scale.tolerance / (hi - lo) * bar.width() > out.mm(9.0);
  for (double t : {scale.tolerance, -scale.tolerance}) {
    if (t < lo) continue;
    ticks.emplace_back(t, labelBand ? num(t, 3) : QString());
  }
  for (const auto& [t, label] : ticks) {
    const double x = bar.left() + (t - lo) / (hi - lo) * bar.width();
    p.drawLine(QPointF(x, bar.bottom()), QPointF(x, bar.bottom() + out.mm(1.0)));
    if (!label.isEmpty())
      p.drawText(QRectF(x - out.mm(9), bar.bottom() + out.mm(1.4), out.mm(18), fm.height()),
                 Qt::AlignHCenter | Qt::AlignTop, label);
  }
}

QString countText(std::size_t n, std::size_t of) {
  return QStringLiteral("%1 / %2").arg(n).arg(of);
}

void writeStudy(ReportPainter& out, const ReportContext& context, const ReportDataset& dataset,
                const matching::MatchingStudySettings& settings) {
  matching::MatchingStudyOptions o = settings.options;
  // Nominals from a CAD part: the study re-projects the points onto it (core/matching/cad_match.h).
  if (dataset.ref.nominals.from == "cad") {
    for (const ReportDataset& rd : context.datasets) {
      if (rd.ref.id != dataset.ref.nominals.cad) continue;
      DatasetRef part = rd.ref;
      part.path = rd.path.toStdString();
      o.cad = readCadModel(part);
    }
  }
  // The study's model: the probe points with the effects added by the diagnosis page's Apply.
  const ProbePointSet set = matching::studyModelSet(*dataset.probes, o);
  const matching::MatchingStudyResult res = matching::runMatchingStudy(*dataset.probes, o);
  const matching::MatchResult& primary = res.primaryRun();
  const double tol = o.toleranceMm;

  out.subheading(ReportText::tr("Probe points “%1”, tolerance ±%2 mm")
                     .arg(QString::fromStdString(dataset.ref.id), num(tol, 3)),
                 out.mm(60.0));
  if (o.cad)
    out.paragraph(
        ReportText::tr("Closed form and minimax were run on the %1 points, each re-projected onto the "
                       "CAD part at every posture until the posture stopped changing. The posture "
                       "after matching is that of %2; the machine adjustment values are for the "
                       "study's %3 machine. Deviation: along the part's normal at the closest point.")
            .arg(set.points.size())
            .arg(methodName(res.primary))
            .arg(QString::fromLatin1(machine::topologyName(o.machine.topology))));
  else
    out.paragraph(
        ReportText::tr(
            "Every method was run on the %1 points (%2). The posture after matching is that of %3; the "
            "machine adjustment values are for the study's %4 machine. Deviation: %5. Rough matching, "
            "SADE, GA-simplex and the machine adjustment as in %6.")
            .arg(set.points.size())
            .arg(set.hasNormals ? ReportText::tr("with normals") : ReportText::tr("positions only"))
            .arg(methodName(res.primary))
            .arg(QString::fromLatin1(machine::topologyName(o.machine.topology)))
            .arg(set.hasNormals ? ReportText::tr("along the nominal normal")
                                : ReportText::tr("distance |p − (sRq + t)|"))
            .arg(citation(1)));
  if (!o.applied.empty())
    out.paragraph(ReportText::tr("Includes applied effects: %1 (diagnosis, Apply). The nominal points were "
                                 "deformed by them before matching, so the deviations and the machine "
                                 "adjustments below are those of the model with these effects.")
                      .arg(QString::fromStdString(o.applied.describe())));

  // The 3D views.
  double maxBefore = 0.0;
  for (double d : primary.before.deviations) maxBefore = std::max(maxBefore, std::abs(d));
  double maxAfter = 0.0;
  for (double d : primary.after.deviations) maxAfter = std::max(maxAfter, std::abs(d));
  const double factor = matching::deviationMagnification(set, maxBefore);  // as on the page
  const ViewProjection proj(set.planar);
  ViewState before = viewState(set, matching::Pose{}, primary.before.deviations, factor);
  // With a CAD part: the after state's nominals are the part's closest points at the posture.
  const ProbePointSet* afterSet = &set;
  for (std::size_t k = 0; k < res.cadAfter.size() && k < res.runs.size(); ++k)
    if (res.runs[k].method == res.primary) afterSet = &res.cadAfter[k];
  ViewState after = viewState(*afterSet, primary.pose, primary.after.deviations, factor);
  if (o.cad) {
    addPart(before, o.cad->mesh(), matching::Pose{}, set, primary.before.deviations);
    addPart(after, o.cad->mesh(), primary.pose, *afterSet, primary.after.deviations);
  }
  QRectF bounds;
  bool first = true;
  for (const ViewState* s : {&before, &after}) {
    for (const auto* v : {&s->base, &s->tip})
      for (const Eigen::Vector3d& x : *v) {
        const QPointF q = proj.map(x);
        if (first) bounds = QRectF(q, QSizeF(1e-9, 1e-9));
        bounds = bounds.united(QRectF(q, QSizeF(1e-9, 1e-9)));
        first = false;
      }
    for (const auto& t : s->triangles)
      for (const Eigen::Vector3d& x : t) bounds = bounds.united(QRectF(proj.map(x), QSizeF(1e-9, 1e-9)));
  }
  bounds = bounds.adjusted(-0.03 * bounds.width(), -0.03 * bounds.height(), 0.03 * bounds.width(),
                           0.03 * bounds.height());
  BandScale beforeScale{ticks::niceCeil(std::max(maxBefore, 2.0 * tol)), tol};
  BandScale afterScale{ticks::niceCeil(std::max(maxAfter, 2.0 * tol)), tol};
  const QRectF figure = out.reserve(out.mm(kViewHeightMm));
  const double gap = out.mm(4.0);
  const double w = (figure.width() - gap) / 2;
  const QRectF left(figure.left(), figure.top(), w, figure.height());
  const QRectF right(figure.left() + w + gap, figure.top(), w, figure.height());
  drawView(out, left, proj, before, bounds, beforeScale, ReportText::tr("Before matching"),
           ReportText::tr("%1 of %2 out of ±%3 mm, max |d| %4 mm")
               .arg(primary.before.overall.outOfTolerance)
               .arg(set.points.size())
               .arg(num(tol, 3), num(maxBefore, 3)));
  drawView(out, right, proj, after, bounds, afterScale,
           ReportText::tr("After %1").arg(methodName(res.primary)),
           ReportText::tr("%1 of %2 out of ±%3 mm, max |d| %4 mm")
               .arg(primary.after.overall.outOfTolerance)
               .arg(set.points.size())
               .arg(num(tol, 3), num(maxAfter, 3)));
  out.paragraph(
      ReportText::tr("%1; grey: nominal points; lines: deviation vectors ×%2 (both views); large "
                     "outlined points: out of tolerance.")
          .arg(set.planar ? ReportText::tr("Top view") : ReportText::tr("Oblique view as in the program"))
          .arg(factor, 0, 'g', 4),
      ReportPainter::Font::Small);
  if (o.cad)
    out.paragraph(
        ReportText::tr("The nominal is the CAD part “%1” (%2 triangles): the points were matched to "
                       "its surface, re-projected at each posture. The part is coloured as the "
                       "nearest probed point, light grey where none is near.")
            .arg(QString::fromStdString(dataset.ref.nominals.cad))
            .arg(o.cad->mesh().triangles.size()),
        ReportPainter::Font::Small);
  {
    const QRectF bars = out.reserve(out.mm(16.0));
    drawBandBar(out, QRectF(bars.left(), bars.top(), bars.width() / 2, bars.height()), beforeScale,
                set.hasNormals,
                ReportText::tr("before: deviation (mm), green = within ±%1").arg(num(tol, 3)));
    drawBandBar(out, QRectF(bars.center().x(), bars.top(), bars.width() / 2, bars.height()), afterScale,
                set.hasNormals, ReportText::tr("after: deviation (mm), green = within ±%1").arg(num(tol, 3)));
  }

  // Deviations per surface, before / after.
  ReportTable dev;
  dev.header = {ReportText::tr("surface"),    ReportText::tr("points"),     ReportText::tr("RMSE before"),
                ReportText::tr("max before"), ReportText::tr("out before"), ReportText::tr("RMSE after"),
                ReportText::tr("max after"),  ReportText::tr("out after")};
  dev.widths = {0.9, 0.7, 1.2, 1.1, 1.1, 1.1, 1.1, 1.1};
  dev.alignment = {Qt::AlignLeft,  Qt::AlignRight, Qt::AlignRight, Qt::AlignRight,
                   Qt::AlignRight, Qt::AlignRight, Qt::AlignRight, Qt::AlignRight};
  auto devRow = [&](const QString& name, const matching::DeviationStats& b,
                    const matching::DeviationStats& a) {
    dev.rows.push_back({name, QString::number(b.points), num(b.rmseMm, 4), num(b.maxAbsMm, 4),
                        countText(b.outOfTolerance, b.points), num(a.rmseMm, 4), num(a.maxAbsMm, 4),
                        countText(a.outOfTolerance, a.points)});
  };
  for (std::size_t i = 0; i < primary.before.surfaces.size() && i < primary.after.surfaces.size(); ++i) {
    const auto& s = primary.before.surfaces[i];
    devRow(s.surface.empty() ? ReportText::tr("(none)") : QString::fromStdString(s.surface), s.stats,
           primary.after.surfaces[i].stats);
  }
  devRow(ReportText::tr("all"), primary.before.overall, primary.after.overall);
  out.subheading(ReportText::tr("Deviations before and after %1 (mm)").arg(methodName(res.primary)),
                 out.mm(30.0));
  out.table(dev);

  // Methods.
  ReportTable methods;
  methods.header = {ReportText::tr("method"),       ReportText::tr("rx, ry, rz (deg)"),
                    ReportText::tr("x, y, z (mm)"), ReportText::tr("RMSE"),
                    ReportText::tr("max |d|"),      ReportText::tr("out"),
                    ReportText::tr("evals")};
  methods.widths = {1.2, 2.3, 2.3, 1.0, 1.1, 0.9, 1.0};
  methods.alignment = {Qt::AlignLeft,  Qt::AlignRight, Qt::AlignRight, Qt::AlignRight,
                       Qt::AlignRight, Qt::AlignRight, Qt::AlignRight};
  auto poseRow = [&](const QString& name, const matching::Pose& pose, const matching::ToleranceEvaluation& ev,
                     const QString& evaluations) {
    const Eigen::Vector3d a = pose.anglesDeg();
    methods.rows.push_back(
        {name, QStringLiteral("%1, %2, %3").arg(num(a.x(), 4), num(a.y(), 4), num(a.z(), 4)),
         QStringLiteral("%1, %2, %3")
             .arg(num(pose.translation.x(), 4), num(pose.translation.y(), 4), num(pose.translation.z(), 4)),
         num(ev.overall.rmseMm, 5), num(ev.overall.maxAbsMm, 5),
         countText(ev.overall.outOfTolerance, ev.overall.points), evaluations});
  };
  for (const matching::MatchResult& r : res.runs) {
    if (r.rough && r.roughEvaluation && r.method == MatchMethod::Sade)
      poseRow(ReportText::tr("rough"), r.rough->posture, *r.roughEvaluation, QStringLiteral("–"));
    poseRow(QString::fromLatin1(matching::toString(r.method)), r.pose, r.after,
            QString::number(r.run.evaluations));
  }
  out.subheading(ReportText::tr("Methods (RMSE and max |d| in mm)"), out.mm(30.0));
  out.table(methods);
  // The rough frames are a whole rigid frame: with rotation locks their angles are only SADE's start.
  if (primary.locks.anyRotation() &&
      std::any_of(res.runs.begin(), res.runs.end(), [](const matching::MatchResult& r) {
        return r.rough.has_value() && r.method == MatchMethod::Sade;
      }))
    out.paragraph(ReportText::tr("Locked: %1. The rough stage's three-point frames cannot hold a lock; its "
                                 "angles are only the start the fine stage moves to the lock values.")
                      .arg(QString::fromStdString(primary.locks.toString())),
                  ReportPainter::Font::Small);

  // Machine adjustment values.
  const machine::Adjustment& adj = res.adjustment;
  const auto names = machine::rotaryAxisNames(adj.topology);
  ReportTable machineTable;
  machineTable.header = {ReportText::tr("axis"), ReportText::tr("value"), ReportText::tr("unit")};
  machineTable.widths = {1.2, 1.0, 0.6};
  machineTable.widthFraction = 0.5;
  machineTable.alignment = {Qt::AlignLeft, Qt::AlignRight, Qt::AlignLeft};
  machineTable.rows = {
      {QStringLiteral("SX"), num(adj.linearMm.x(), 4), QStringLiteral("mm")},
      {QStringLiteral("SY"), num(adj.linearMm.y(), 4), QStringLiteral("mm")},
      {QStringLiteral("SZ"), num(adj.linearMm.z(), 4), QStringLiteral("mm")},
      {QStringLiteral("S") + QLatin1String(names[0]), num(adj.rotaryDeg[0], 5), QStringLiteral("°")},
      {QStringLiteral("S") + QLatin1String(names[1]), num(adj.rotaryDeg[1], 5), QStringLiteral("°")},
      {ReportText::tr("frame rotation"), num(adj.frameRotationDeg, 5), QStringLiteral("°")}};
  out.subheading(ReportText::tr("Machine adjustment values (%1%2)")
                     .arg(QString::fromLatin1(machine::topologyName(adj.topology)))
                     .arg(adj.withinTravel ? QString() : ReportText::tr(", OUTSIDE TRAVEL")),
                 out.mm(40.0));
  out.table(machineTable);

  // The same posture as a controller frame (core/machine/controller_frame.h; metrofit-cli match
  // --frame): the blocks that set it, for a control that rotates the working plane instead of
  // taking axis adjustment values.
  {
    const matching::Pose& pose = res.primaryRun().pose;
    ReportTable frames;
    frames.header = {ReportText::tr("control"), ReportText::tr("blocks (mm, °)")};
    frames.widths = {0.8, 3.2};
    frames.alignment = {Qt::AlignLeft, Qt::AlignLeft};
    // The study's control (studies.matching.frame, the page's Controller frame tab) first and marked,
    // then the others; every one with the study's decimals (studies.matching.frame_decimals).
    std::vector<std::pair<machine::FrameFormat, QString>> controls = {
        {machine::FrameFormat::Heidenhain, QStringLiteral("HEIDENHAIN")},
        {machine::FrameFormat::Siemens, QStringLiteral("SINUMERIK")},
        {machine::FrameFormat::Fanuc, QStringLiteral("FANUC")}};
    std::stable_partition(controls.begin(), controls.end(),
                          [&](const auto& c) { return c.first == settings.frame; });
    for (const auto& [format, name] : controls) {
      QStringList blocks;
      for (const std::string& b :
           machine::controllerFrameBlocks(pose.rotation, pose.translation, format, settings.frameDecimals))
        blocks << QString::fromStdString(b);
      frames.rows.push_back(
          {format == settings.frame ? ReportText::tr("%1 (the study's control)").arg(name) : name,
           blocks.join(QStringLiteral("; "))});
    }
    out.subheading(ReportText::tr("The same posture as a controller frame (instead of the axis values; "
                                  "decimals: %1)")
                       .arg(settings.frameDecimals),
                   out.mm(30.0));
    out.table(frames);
    out.paragraph(
        ReportText::tr("Datum shift then rotation of the working plane; no axis moves (STAY). The "
                       "whole programs: metrofit-cli match --frame heidenhain|siemens|fanuc."));
  }

  // Remeasure loop.
  if (res.remeasure) {
    ReportTable loop;
    loop.header = {ReportText::tr("round"), ReportText::tr("max |d| (mm)"), ReportText::tr("out of tol."),
                   ReportText::tr("SX, SY, SZ (mm)"),
                   ReportText::tr("S%1, S%2 (deg)").arg(QLatin1String(names[0]), QLatin1String(names[1]))};
    loop.widths = {0.6, 1.1, 1.0, 2.4, 1.8};
    loop.alignment = {Qt::AlignRight, Qt::AlignRight, Qt::AlignRight, Qt::AlignRight, Qt::AlignRight};
    for (const matching::RemeasureRound& r : res.remeasure->rounds) {
      loop.rows.push_back(
          {QString::number(r.round), num(r.measured.overall.maxAbsMm, 4),
           countText(r.measured.overall.outOfTolerance, r.measured.overall.points),
           r.adjustment ? QStringLiteral("%1, %2, %3")
                              .arg(num(r.adjustment->linearMm.x(), 4), num(r.adjustment->linearMm.y(), 4),
                                   num(r.adjustment->linearMm.z(), 4))
                        : (r.measured.overall.outOfTolerance == 0 ? ReportText::tr("in tolerance")
                                                                  : ReportText::tr("stopped")),
           r.adjustment ? QStringLiteral("%1, %2").arg(num(r.adjustment->rotaryDeg[0], 5),
                                                       num(r.adjustment->rotaryDeg[1], 5))
                        : QString()});
    }
    out.subheading(ReportText::tr("Remeasure loop (simulated machine and CMM)"), out.mm(30.0));
    out.table(loop);
    // The loop's outcome in the report's language (core's run.message is English).
    const int adjustments = std::max(0, static_cast<int>(res.remeasure->rounds.size()) - 1);
    QString outcome;
    switch (res.remeasure->outcome) {
      case matching::RemeasureOutcome::InTolerance:
        outcome = ReportText::tr("Every point within tolerance after %n adjustment(s).", "", adjustments);
        break;
      case matching::RemeasureOutcome::FormError:
        outcome = ReportText::tr(
            "FAILED: the best fit leaves points out of tolerance (form error larger than "
            "the tolerance); no WCS adjustment can bring them in.");
        break;
      case matching::RemeasureOutcome::BeyondTravel:
        outcome =
            ReportText::tr("FAILED: the adjustment is beyond the machine's travel; the WCS was not moved.");
        break;
      case matching::RemeasureOutcome::NotConverged:
        outcome = ReportText::tr("FAILED: still out of tolerance after the last adjustment.");
        break;
      case matching::RemeasureOutcome::Cancelled:
        outcome = ReportText::tr("Stopped before the end.");
        break;
    }
    if (const matching::ToleranceEvaluation* t = res.remeasure->trueRemaining())
      outcome += QLatin1Char(' ') + ReportText::tr(
                                        "True remaining error of the simulated part: %1 mm at most, "
                                        "%2 point(s) out of tolerance.")
                                        .arg(num(t->overall.maxAbsMm, 4))
                                        .arg(static_cast<qulonglong>(t->overall.outOfTolerance));
    out.paragraph(outcome);
  }

  // Conclusion.
  const std::size_t n = set.points.size();
  const Eigen::Vector3d angles = primary.pose.anglesDeg();
  SectionFinding f;
  f.study = matchingSectionTitle();
  f.found = ReportText::tr(
                "The workpiece %1 sits rotated by (%2, %3, %4)° and shifted by (%5, %6, %7) mm; "
                "%8 of %9 probed points are out of ±%10 mm before matching, %11 after.")
                .arg(QString::fromStdString(dataset.ref.id))
                .arg(num(angles.x(), 3), num(angles.y(), 3), num(angles.z(), 3))
                .arg(num(primary.pose.translation.x(), 3), num(primary.pose.translation.y(), 3),
                     num(primary.pose.translation.z(), 3))
                .arg(primary.before.overall.outOfTolerance)
                .arg(n)
                .arg(num(tol, 3))
                .arg(primary.after.overall.outOfTolerance);
  const QString where = ReportText::tr("%1 machine, enter at the control")
                            .arg(QString::fromLatin1(machine::topologyName(adj.topology)));
  f.changes.push_back({ReportText::tr("linear axes"),
                       QStringLiteral("SX %1, SY %2, SZ %3 mm")
                           .arg(num(adj.linearMm.x(), 4), num(adj.linearMm.y(), 4), num(adj.linearMm.z(), 4)),
                       where});
  f.changes.push_back({ReportText::tr("rotary axes"),
                       QStringLiteral("S%1 %2°, S%3 %4°")
                           .arg(QLatin1String(names[0]), num(adj.rotaryDeg[0], 4), QLatin1String(names[1]),
                                num(adj.rotaryDeg[1], 4)),
                       where});
  if (std::abs(adj.frameRotationDeg) > 0.0)
    f.changes.push_back(
        {ReportText::tr("frame rotation"), num(adj.frameRotationDeg, 4) + QStringLiteral("°"), where});
  f.before = ReportText::tr("max |deviation| %1 mm; %2 of %3 points out of tolerance")
                 .arg(num(maxBefore, 3))
                 .arg(primary.before.overall.outOfTolerance)
                 .arg(n);
  f.after = ReportText::tr("max |deviation| %1 mm; %2 of %3 points out of tolerance")
                .arg(num(maxAfter, 3))
                .arg(primary.after.overall.outOfTolerance)
                .arg(n);
  const bool fits = primary.after.overall.outOfTolerance == 0;
  f.conclusion =
      fits ? ReportText::tr("After the posture adjustment every probed point lies within the tolerance.")
           : ReportText::tr(
                 "Even after the best posture %1 of %2 points stay out of tolerance: the part "
                 "itself deviates, not only its posture.")
                 .arg(primary.after.overall.outOfTolerance)
                 .arg(n);
  if (!adj.withinTravel)
    f.recommendation = ReportText::tr("Do not apply: the adjustment lies outside the axis travel (%1).")
                           .arg(QString::fromStdString(adj.travelMessage));
  else
    f.recommendation = fits ? ReportText::tr(
                                  "Enter the adjustment values at the control, probe the part again "
                                  "and machine when it is within tolerance.")
                            : ReportText::tr(
                                  "Enter the adjustment values, probe again, and check the surfaces "
                                  "that stay out of tolerance before machining.");
  concludeSection(out, context, f);
}

}  // namespace

QString matchingSectionTitle() {
  return ReportText::tr("Posture matching — before and after");
}

bool hasMatchingStudy(const ReportContext& context) {
  if (context.project == nullptr || context.ofKind(dataset_kind::kProbePoints).empty()) return false;
  const auto it = context.project->studies.find(study::kMatching);
  return it != context.project->studies.end() && it->is_object() && !it->empty();
}

void writeMatchingSection(ReportPainter& out, const ReportContext& context) {
  const matching::MatchingStudySettings settings = matching::matchingStudySettings(*context.project);
  for (const ReportDataset* dataset : context.ofKind(dataset_kind::kProbePoints)) {
    if (dataset->ref.id == settings.datasetId && dataset->probes) {
      writeStudy(out, context, *dataset, settings);
      return;
    }
  }
  out.paragraph(ReportText::tr("The matching study's probe points could not be found."));
}

}  // namespace metrofit
