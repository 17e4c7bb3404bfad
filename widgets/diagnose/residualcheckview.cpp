#include "widgets/diagnose/residualcheckview.h"

#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QCoreApplication>
#include <QFontInfo>
#include <QHeaderView>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QPainter>
#include <QPainterPath>
#include <QScatterSeries>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QValueAxis>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "core/common/axis_ticks.h"
#include "widgets/common/chartexport.h"
#include "widgets/common/chartnavigation.h"
#include "widgets/common/palette.h"
#include "widgets/common/tablecopy.h"
#include "widgets/diagnose/coretexts.h"
#include "widgets/diagnose/residualchecktext.h"

namespace metrofit {
namespace {

QColor residualColour() {
  return palette::after();
}
/// The fit curve of coordinate `k` (vector residuals have one per coordinate).
QColor fitColour(int k = 0) {
  switch (k) {
    case 0:
      return palette::measuredSecond();
    case 1:
      return palette::predicted();
    default:
      return palette::compensated();
  }
}

/// The name of coordinate k of a vector residual ("x", "y", "z").
QString componentName(int k) {
  return QString(QLatin1Char(static_cast<char>('x' + std::min(k, 2))));
}
QColor outlierColour() {
  return palette::outOfTolerance();
}

/// Categories with more levels than this are shown by index (their names would overlap).
constexpr int kMaxCategoryLabels = 25;

struct Series {
  std::vector<QPointF> residual, outliers;
  std::vector<std::vector<QPointF>> fits;  ///< one curve per coordinate
  std::size_t fitPoints() const {
    std::size_t n = 0;
    for (const auto& f : fits) n += f.size();
    return n;
  }
};

/// Every k-th point so that at most kMaxResidualCheckChartPoints remain.
std::vector<QPointF> thinned(std::vector<QPointF> points) {
  const std::size_t n = points.size();
  const std::size_t max = static_cast<std::size_t>(kMaxResidualCheckChartPoints);
  if (n <= max) return points;
  const std::size_t stride = (n + max - 1) / max;
  std::vector<QPointF> out;
  out.reserve(n / stride + 1);
  for (std::size_t i = 0; i < n; i += stride) out.push_back(points[i]);
  return out;
}

/// The chart's series from the plot: finite points only; the fit as a line through the distinct x
/// values in increasing order (the fit is a function of x), one per coordinate of a vector residual
/// (observation i is coordinate i % components).
Series seriesOf(const diagnose::ResidualCheck::Plot& plot) {
  Series s;
  const std::size_t components = static_cast<std::size_t>(std::clamp(plot.components, 1, 3));
  std::vector<std::vector<QPointF>> fits(components);
  for (std::size_t i = 0; i < plot.x.size(); ++i) {
    const double x = plot.x[i];
    if (!std::isfinite(x)) continue;
    if (i < plot.residual.size() && std::isfinite(plot.residual[i]))
      s.residual.emplace_back(x, plot.residual[i]);
    if (i < plot.fit.size() && std::isfinite(plot.fit[i])) fits[i % components].emplace_back(x, plot.fit[i]);
  }
  for (auto& fit : fits) {
    std::stable_sort(fit.begin(), fit.end(),
                     [](const QPointF& a, const QPointF& b) { return a.x() < b.x(); });
    fit.erase(std::unique(fit.begin(), fit.end(),
                          [](const QPointF& a, const QPointF& b) { return a.x() == b.x(); }),
              fit.end());
    s.fits.push_back(thinned(std::move(fit)));
  }
  for (std::size_t i = 0; i < plot.outlierX.size() && i < plot.outlierResidual.size(); ++i) {
    if (std::isfinite(plot.outlierX[i]) && std::isfinite(plot.outlierResidual[i]))
      s.outliers.emplace_back(plot.outlierX[i], plot.outlierResidual[i]);
  }
  s.residual = thinned(std::move(s.residual));
  s.outliers = thinned(std::move(s.outliers));
  return s;
}

QString chartTitleOf(const diagnose::ResidualCheck& c) {
  if (!c.plot) return {};
  const auto it = std::find_if(c.structure.begin(), c.structure.end(), [&](const diagnose::StructureItem& s) {
    return s.against == c.plot->against;
  });
  const QString variable = residualVariableName(c.plot->against);
  if (it == c.structure.end()) return ResidualCheckView::tr("Final residual against %1").arg(variable);
  return ResidualCheckView::tr("Final residual against %1 with the generic fit (%2)")
      .arg(variable, dependenceFormLabel(*it, QLocale()));
}

QString yTitle(const QString& units) {
  return units.isEmpty() ? ResidualCheckView::tr("residual")
                         : ResidualCheckView::tr("residual (%1)").arg(units);
}

QString xTitle(const diagnose::ResidualCheck::Plot& plot) {
  return plot.xLabel.empty() ? residualVariableName(plot.against) : coreText(plot.xLabel);
}

using Range = ticks::Range;

/// A read-only table; column `stretch` takes the width left over.
QTableWidget* makeTable(QWidget* parent, const QString& objectName, const QStringList& header, int stretch) {
  auto* t = new QTableWidget(parent);
  t->setObjectName(objectName);
  t->setColumnCount(static_cast<int>(header.size()));
  t->setHorizontalHeaderLabels(header);
  t->setEditTriggers(QAbstractItemView::NoEditTriggers);
  t->setSelectionBehavior(QAbstractItemView::SelectRows);
  t->setAlternatingRowColors(true);
  t->setWordWrap(false);
  t->verticalHeader()->hide();
  t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  t->horizontalHeader()->setSectionResizeMode(stretch, QHeaderView::Stretch);
  enableTableCopy(t);
  return t;
}

/// Caps a table's height at its header and `maxRows` rows (at least one), so short lists leave the
/// room to the tests table.
void fitHeight(QTableWidget* t, int maxRows) {
  const int rows = std::clamp(t->rowCount(), 1, maxRows);
  const int h = t->horizontalHeader()->sizeHint().height() +
                rows * t->verticalHeader()->defaultSectionSize() + 2 * t->frameWidth() + 2;
  t->setMaximumHeight(h);
}

void setCell(QTableWidget* t, int row, int col, const QString& text, Qt::Alignment align = Qt::AlignLeft) {
  auto* item = new QTableWidgetItem(text);
  item->setTextAlignment(align | Qt::AlignVCenter);
  item->setToolTip(text);
  t->setItem(row, col, item);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
void paintResidualCheck(QPainter& p, const QRectF& rect, const diagnose::ResidualCheck::Plot& plot,
                        const QString& units, const QString& title, double fontPx, const QLocale& locale) {
  const Series s = seriesOf(plot);
  Range xr, yr;
  std::vector<const std::vector<QPointF>*> all = {&s.residual, &s.outliers};
  for (const auto& f : s.fits) all.push_back(&f);
  for (const auto* v : all) {
    for (const QPointF& pt : *v) {
      xr.add(pt.x());
      yr.add(pt.y());
    }
  }
  yr.add(0.0);
  const bool categories = !plot.categories.empty();
  const Range xp = categories ? Range{-0.5, static_cast<double>(plot.categories.size()) - 0.5} : xr.padded();
  const Range yp = yr.padded();

  p.save();
  p.setRenderHint(QPainter::Antialiasing, true);
  QFont f = p.font();
  f.setPixelSize(std::max(1, static_cast<int>(std::lround(fontPx))));
  p.setFont(f);
  const QFontMetricsF fm(f);
  const double line = fm.height();
  const double yStep = ticks::niceStep(yp.hi - yp.lo, 5);
  std::vector<double> yTicks;
  for (double v = std::ceil(yp.lo / yStep) * yStep; v <= yp.hi + 1e-9 * yStep; v += yStep)
    yTicks.push_back(std::abs(v) < 1e-12 * yStep ? 0.0 : v);
  double tickWidth = 0.0;
  for (double v : yTicks) tickWidth = std::max(tickWidth, fm.horizontalAdvance(locale.toString(v, 'g', 4)));
  QRectF area(rect.left() + line * 1.4 + tickWidth + 6.0, rect.top() + line * 1.6, 0.0, 0.0);
  area.setRight(rect.right() - fm.horizontalAdvance(QStringLiteral("0000")) / 2.0);
  area.setBottom(rect.bottom() - line * 2.6);
  const auto map = [&](double x, double y) {
    return QPointF(area.left() + (x - xp.lo) / (xp.hi - xp.lo) * area.width(),
                   area.bottom() - (y - yp.lo) / (yp.hi - yp.lo) * area.height());
  };

  // Title, grid, frame, ticks, axis titles.
  QFont bold = f;
  bold.setBold(true);
  p.setFont(bold);
  p.setPen(QPen(Qt::black, 0));
  p.drawText(QRectF(rect.left(), rect.top(), rect.width(), line * 1.4), Qt::AlignCenter, title);
  p.setFont(f);
  p.setPen(QPen(palette::grid(), 0));
  for (double v : yTicks) p.drawLine(map(xp.lo, v), map(xp.hi, v));
  p.setPen(QPen(Qt::black, 0));
  p.drawRect(area);
  for (double v : yTicks) {
    const double y = map(xp.lo, v).y();
    p.drawText(QRectF(area.left() - tickWidth - 6.0, y - line / 2, tickWidth + 3.0, line),
               Qt::AlignRight | Qt::AlignVCenter, locale.toString(v, 'g', 4));
  }
  if (categories) {
    const int count = static_cast<int>(plot.categories.size());
    const int every = std::max(1, count / kMaxCategoryLabels + (count % kMaxCategoryLabels ? 1 : 0));
    for (int i = 0; i < count; i += every) {
      const double x = map(i, yp.lo).x();
      const double w = std::max(20.0, area.width() / count * every);
      p.drawText(QRectF(x - w / 2, area.bottom() + 2.0, w, line), Qt::AlignHCenter | Qt::AlignTop,
                 fm.elidedText(QString::fromStdString(plot.categories[static_cast<std::size_t>(i)]),
                               Qt::ElideRight, w));
    }
  } else {
    const double xStep = ticks::niceStep(xp.hi - xp.lo, 6);
    for (double v = std::ceil(xp.lo / xStep) * xStep; v <= xp.hi + 1e-9 * xStep; v += xStep) {
      const double x = map(v, yp.lo).x();
      p.drawLine(QPointF(x, area.bottom()), QPointF(x, area.bottom() + 3.0));
      p.drawText(QRectF(x - 40.0, area.bottom() + 2.0, 80.0, line), Qt::AlignHCenter | Qt::AlignTop,
                 locale.toString(std::abs(v) < 1e-12 * xStep ? 0.0 : v, 'g', 5));
    }
  }
  p.drawText(QRectF(area.left(), area.bottom() + line * 1.2, area.width(), line * 1.3), Qt::AlignCenter,
             displayUnit(xTitle(plot)));
  p.save();
  p.translate(rect.left() + line * 0.7, area.center().y());
  p.rotate(-90.0);
  p.drawText(QRectF(-area.height() / 2, -line * 0.7, area.height(), line * 1.4), Qt::AlignCenter,
             yTitle(units));
  p.restore();

  // Data: zero line, residual points, fit line, outlier triangles.
  p.setClipRect(area);
  p.setPen(QPen(Qt::black, 0, Qt::DashLine));
  p.drawLine(map(xp.lo, 0.0), map(xp.hi, 0.0));
  const double r = std::max(
      0.8,
      std::min(2.5, area.width() / std::max(1.0, std::sqrt(static_cast<double>(s.residual.size())) * 12.0)));
  p.setPen(Qt::NoPen);
  p.setBrush(residualColour());
  for (const QPointF& pt : s.residual) p.drawEllipse(map(pt.x(), pt.y()), r, r);
  for (std::size_t k = 0; k < s.fits.size(); ++k) {
    const auto& fit = s.fits[k];
    if (fit.size() < 2) continue;
    QPainterPath path(map(fit.front().x(), fit.front().y()));
    for (std::size_t i = 1; i < fit.size(); ++i) path.lineTo(map(fit[i].x(), fit[i].y()));
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(fitColour(static_cast<int>(k)), std::max(1.0, fontPx / 6.0)));
    p.drawPath(path);
  }
  const double t = std::max(3.0, fontPx * 0.45);
  const auto triangle = [&](const QPointF& c) {
    QPainterPath tri;
    tri.moveTo(c + QPointF(0.0, -t));
    tri.lineTo(c + QPointF(t * 0.87, t * 0.5));
    tri.lineTo(c + QPointF(-t * 0.87, t * 0.5));
    tri.closeSubpath();
    return tri;
  };
  p.setPen(QPen(Qt::black, 0));
  p.setBrush(outlierColour());
  for (const QPointF& pt : s.outliers) p.drawPath(triangle(map(pt.x(), pt.y())));
  p.setClipping(false);

  // Legend (top right inside the plot).
  // Kinds: -1 residual, -2 outliers, k >= 0 the fit of coordinate k.
  QList<QPair<int, QString>> entries = {{-1, ResidualCheckView::tr("residual")}};
  for (std::size_t k = 0; k < s.fits.size(); ++k) {
    if (s.fits[k].size() < 2) continue;
    entries.append({static_cast<int>(k),
                    s.fits.size() == 1
                        ? ResidualCheckView::tr("generic fit")
                        : ResidualCheckView::tr("generic fit, %1").arg(componentName(static_cast<int>(k)))});
  }
  if (!s.outliers.empty()) entries.append({-2, ResidualCheckView::tr("excluded outliers")});
  double w = 0.0;
  for (const auto& e : entries) w = std::max(w, fm.horizontalAdvance(e.second));
  const QRectF box(area.right() - w - line * 1.8 - 4.0, area.top() + 4.0, w + line * 1.8,
                   line * static_cast<double>(entries.size()) + 4.0);
  p.fillRect(box, QColor(255, 255, 255, 220));
  for (int i = 0; i < entries.size(); ++i) {
    const double y = box.top() + 2.0 + line * i + line / 2;
    const QPointF c(box.left() + line * 0.7, y);
    if (entries[i].first == -1) {
      p.setPen(Qt::NoPen);
      p.setBrush(residualColour());
      p.drawEllipse(c, line * 0.22, line * 0.22);
    } else if (entries[i].first >= 0) {
      p.setPen(QPen(fitColour(entries[i].first), std::max(1.0, fontPx / 6.0)));
      p.drawLine(c - QPointF(line * 0.45, 0.0), c + QPointF(line * 0.45, 0.0));
    } else {
      p.setPen(QPen(Qt::black, 0));
      p.setBrush(outlierColour());
      p.drawPath(triangle(c));
    }
    p.setPen(Qt::black);
    p.drawText(QRectF(box.left() + line * 1.4, y - line / 2, w + 4.0, line), Qt::AlignLeft | Qt::AlignVCenter,
               entries[i].second);
  }
  p.restore();
}

// ---------------------------------------------------------------------------------------------
class ResidualCheckView::Charts {
 public:
  QChartView* view = nullptr;
  QScatterSeries* residual = nullptr;
  QList<QLineSeries*> fits;  ///< one per coordinate
  QScatterSeries* outliers = nullptr;
  QString xTitle;
};

ResidualCheckView::ResidualCheckView(QWidget* parent)
    : QWidget(parent),
      verdict_(new QLabel(this)),
      structureLabel_(new QLabel(tr("What the residual still depends on (strongest first):"), this)),
      outlierLabel_(new QLabel(tr("Outliers excluded from the fit:"), this)),
      testLabel_(new QLabel(tr("Tests of the final residual:"), this)),
      structure_(nullptr),
      outliers_(nullptr),
      tests_(nullptr),
      charts_(new Charts) {
  verdict_->setObjectName(QStringLiteral("residualCheckVerdict"));
  verdict_->setWordWrap(true);
  verdict_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  QFont bold = verdict_->font();
  bold.setBold(true);
  verdict_->setFont(bold);
  verdict_->setToolTip(
      tr("The final residual (after every accepted effect, outliers excluded) is white when no test finds "
         "structure at the family-wise level (Holm's procedure over all tests)"));

  structure_ = makeTable(this, QStringLiteral("residualCheckStructure"),
                         {tr("Variable"), tr("Form"), tr("Share (%)"), tr("p-value")}, 0);
  structure_->setToolTip(
      tr("Per variable with a rejected test its strongest form; share = part of the "
         "residual variance the form explains"));
  outliers_ =
      makeTable(this, QStringLiteral("residualCheckOutliers"),
                {tr("Row"), tr("Part"), tr("Dimension"), tr("Id"), tr("Residual"), tr("Robust z")}, 2);
  outliers_->setToolTip(
      tr("Observations whose robust z (|r - median| / (1.4826 MAD)) is above the "
         "threshold: gross errors, excluded and the model refitted without them"));
  tests_ = makeTable(this, QStringLiteral("residualCheckTests"),
                     {tr("Test"), tr("Order / variable"), tr("Form"), tr("Statistic"), tr("df"),
                      tr("p-value"), tr("Rejected")},
                     1);
  tests_->setToolTip(
      tr("Ljung-Box: serial correlation of the residual in that order (chi-square); F test: "
         "the residual against the variable in that form (nested models). Rejected: by Holm's "
         "procedure at the family-wise level"));
  for (QLabel* l : {structureLabel_, outlierLabel_, testLabel_}) l->setWordWrap(true);

  charts_->view = new QChartView(this);
  charts_->view->setObjectName(QStringLiteral("residualCheckChart"));
  charts_->view->setRenderHint(QPainter::Antialiasing);
  charts_->view->setMinimumSize(300, 220);
  enableChartExport(charts_->view, QStringLiteral("diagnosis-residual-check"));
  enableChartNavigation(charts_->view);

  auto* tables = new QWidget(this);
  auto* tl = new QVBoxLayout(tables);
  tl->setContentsMargins(0, 0, 0, 0);
  tl->addWidget(structureLabel_);
  tl->addWidget(structure_);
  tl->addWidget(outlierLabel_);
  tl->addWidget(outliers_);
  tl->addWidget(testLabel_);
  tl->addWidget(tests_, 1);

  auto* split = new QSplitter(Qt::Horizontal, this);
  split->setObjectName(QStringLiteral("residualCheckSplitter"));
  split->addWidget(charts_->view);
  split->addWidget(tables);
  split->setStretchFactor(0, 1);
  split->setStretchFactor(1, 1);
  split->setChildrenCollapsible(false);

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(verdict_);
  layout->addWidget(split, 1);
  clear();
}

ResidualCheckView::~ResidualCheckView() {
  delete charts_;
}

QString ResidualCheckView::verdictText() const {
  return verdict_->text();
}

int ResidualCheckView::residualPointCount() const {
  return charts_->residual ? static_cast<int>(charts_->residual->count()) : 0;
}
int ResidualCheckView::fitLineCount() const {
  return static_cast<int>(charts_->fits.size());
}
int ResidualCheckView::fitPointCount() const {
  int n = 0;
  for (const QLineSeries* f : charts_->fits) n += static_cast<int>(f->count());
  return n;
}
int ResidualCheckView::outlierPointCount() const {
  return charts_->outliers ? static_cast<int>(charts_->outliers->count()) : 0;
}

bool ResidualCheckView::chartShown() const {
  return !charts_->view->isHidden();
}

QString ResidualCheckView::chartTitle() const {
  return charts_->view->chart()->title();
}

QString ResidualCheckView::xAxisTitle() const {
  return charts_->xTitle;
}

void ResidualCheckView::clear() {
  hasCheck_ = false;
  verdict_->setText(tr("Residual check: run the diagnosis (Ctrl+R)."));
  for (QTableWidget* t : {structure_, outliers_, tests_}) t->setRowCount(0);
  fitHeight(structure_, 6);
  fitHeight(outliers_, 5);
  auto* chart = new QChart;
  chart->setTitle(tr("Final residual: run the diagnosis (Ctrl+R)"));
  chart->legend()->hide();
  QChart* old = charts_->view->chart();
  charts_->view->setChart(chart);
  delete old;
  charts_->residual = nullptr;
  charts_->fits.clear();
  charts_->outliers = nullptr;
  charts_->xTitle.clear();
  charts_->view->setVisible(true);
}

void ResidualCheckView::setDiagnosis(const diagnose::Diagnosis& d) {
  clear();
  if (!d.residualCheck) {
    verdict_->setText(tr("This diagnosis has no residual check."));
    charts_->view->chart()->setTitle(tr("This diagnosis has no residual check."));
    return;
  }
  hasCheck_ = true;
  const diagnose::ResidualCheck& c = *d.residualCheck;
  const QLocale locale;
  const QString u = displayUnit(QString::fromStdString(d.units));
  const QString level = locale.toString(100.0 * c.level, 'g', 3);
  verdict_->setText(residualCheckVerdict(c));
  QPalette pal = verdict_->palette();
  pal.setColor(QPalette::WindowText, c.white ? palette::goodText() : palette::badText());
  verdict_->setPalette(pal);

  const Qt::Alignment right = Qt::AlignRight;
  structureLabel_->setText(c.structure.empty() ? tr("What the residual still depends on: nothing found.")
                                               : tr("What the residual still depends on (strongest first):"));
  structure_->setRowCount(static_cast<int>(c.structure.size()));
  for (int r = 0; r < structure_->rowCount(); ++r) {
    const diagnose::StructureItem& s = c.structure[static_cast<std::size_t>(r)];
    setCell(structure_, r, 0, residualVariableName(s.against));
    structure_->item(r, 0)->setData(Qt::UserRole, QString::fromStdString(s.against));
    setCell(structure_, r, 1, dependenceFormLabel(s, locale));
    setCell(structure_, r, 2, locale.toString(100.0 * s.share, 'f', 1), right);
    structure_->item(r, 2)->setData(Qt::UserRole, s.share);
    setCell(structure_, r, 3, formatPValue(s.p, locale), right);
    structure_->item(r, 3)->setData(Qt::UserRole, s.p);
  }

  outlierLabel_->setText(c.outliers.empty() ? (c.outlierThreshold > 0.0
                                                   ? tr("Outliers: none (robust z threshold %1).")
                                                         .arg(locale.toString(c.outlierThreshold, 'g', 3))
                                                   : tr("Outliers: none."))
                                            : tr("Outliers excluded from the fit (robust z above %1):")
                                                  .arg(locale.toString(c.outlierThreshold, 'g', 3)));
  outliers_->setHorizontalHeaderItem(
      4, new QTableWidgetItem(u.isEmpty() ? tr("Residual") : tr("Residual (%1)").arg(u)));
  outliers_->setRowCount(static_cast<int>(c.outliers.size()));
  const QString none = QStringLiteral("–");
  for (int r = 0; r < outliers_->rowCount(); ++r) {
    const diagnose::Outlier& o = c.outliers[static_cast<std::size_t>(r)];
    setCell(outliers_, r, 0, o.row ? locale.toString(static_cast<qlonglong>(*o.row)) : none, right);
    setCell(outliers_, r, 1, o.part ? QString::fromStdString(*o.part) : none);
    setCell(outliers_, r, 2, o.dimension ? QString::fromStdString(*o.dimension) : none);
    setCell(outliers_, r, 3, o.id ? QString::fromStdString(*o.id) : none);
    setCell(outliers_, r, 4,
            u.isEmpty() ? localNumber(o.residual, 4) : localNumber(o.residual, 4) + QLatin1Char(' ') + u,
            right);
    outliers_->item(r, 4)->setData(Qt::UserRole, o.residual);
    setCell(outliers_, r, 5, localNumber(o.robustZ, 3), right);
    outliers_->item(r, 5)->setData(Qt::UserRole, o.robustZ);
  }
  outliers_->setVisible(!c.outliers.empty());
  fitHeight(structure_, 6);
  fitHeight(outliers_, 5);

  testLabel_->setText(
      tr("Tests of the final residual (%n test(s), %1 observations; rejected by Holm at the %2 % "
         "family-wise level):",
         nullptr, static_cast<int>(c.tests.size()))
          .arg(locale.toString(static_cast<qulonglong>(c.observations)), level));
  tests_->setHorizontalHeaderItem(6, new QTableWidgetItem(tr("Rejected at %1 %").arg(level)));
  tests_->setRowCount(static_cast<int>(c.tests.size()));
  for (int r = 0; r < tests_->rowCount(); ++r) {
    const diagnose::ResidualTest& t = c.tests[static_cast<std::size_t>(r)];
    setCell(tests_, r, 0, residualTestName(t.name));
    setCell(tests_, r, 1, residualVariableName(t.against));
    setCell(tests_, r, 2, t.form.empty() ? none : dependenceFormName(t.form));
    setCell(tests_, r, 3, localNumber(t.statistic, 4), right);
    tests_->item(r, 3)->setData(Qt::UserRole, t.statistic);
    setCell(tests_, r, 4, locale.toString(t.dof), right);
    setCell(tests_, r, 5, formatPValue(t.p, locale), right);
    tests_->item(r, 5)->setData(Qt::UserRole, t.p);
    setCell(tests_, r, 6, t.rejected ? QStringLiteral("✓") : QStringLiteral("–"), Qt::AlignHCenter);
    QTableWidgetItem* rej = tests_->item(r, 6);
    rej->setData(Qt::UserRole, t.rejected);
    if (t.rejected) {
      rej->setForeground(palette::badText());
      for (int col = 0; col < tests_->columnCount(); ++col) {
        QFont f = tests_->item(r, col)->font();
        f.setBold(true);
        tests_->item(r, col)->setFont(f);
      }
    }
  }
  showChart(c, u);
}

void ResidualCheckView::showChart(const diagnose::ResidualCheck& c, const QString& units) {
  QChart* chart = charts_->view->chart();
  if (!c.plot) {
    // Nothing to draw: the tables get the width (the title says why, for the chart's export).
    chart->setTitle(c.white ? tr("The final residual is white: nothing left to plot")
                            : tr("No single variable explains the structure left"));
    charts_->view->setVisible(false);
    return;
  }
  charts_->view->setVisible(true);
  const diagnose::ResidualCheck::Plot& plot = *c.plot;
  const Series s = seriesOf(plot);
  chart->setLocale(QLocale());
  chart->setLocalizeNumbers(true);
  chart->setTitle(chartTitleOf(c));
  chart->legend()->show();
  chart->legend()->setAlignment(Qt::AlignBottom);

  charts_->residual = new QScatterSeries;
  charts_->residual->setName(tr("residual"));
  charts_->residual->setColor(residualColour());
  charts_->residual->setBorderColor(residualColour());
  charts_->residual->setMarkerSize(5.0);
  const QString form = c.structure.empty() ? dependenceFormName(std::string())
                                           : dependenceFormLabel(c.structure.front(), QLocale());
  for (std::size_t k = 0; k < s.fits.size(); ++k) {
    auto* fit = new QLineSeries;
    fit->setName(s.fits.size() == 1
                     ? tr("generic fit (%1)").arg(form)
                     : tr("generic fit (%1), %2").arg(form, componentName(static_cast<int>(k))));
    fit->setPen(QPen(fitColour(static_cast<int>(k)), 2.5));
    charts_->fits.append(fit);
  }
  charts_->outliers = new QScatterSeries;
  charts_->outliers->setName(tr("excluded outliers"));
  charts_->outliers->setMarkerShape(QScatterSeries::MarkerShapeTriangle);
  charts_->outliers->setColor(outlierColour());
  charts_->outliers->setBorderColor(Qt::black);
  charts_->outliers->setMarkerSize(11.0);

  Range xr, yr;
  const QList<QPointF> residual(s.residual.begin(), s.residual.end());
  const QList<QPointF> outliers(s.outliers.begin(), s.outliers.end());
  std::vector<const std::vector<QPointF>*> all = {&s.residual, &s.outliers};
  for (const auto& f : s.fits) all.push_back(&f);
  for (const auto* v : all) {
    for (const QPointF& p : *v) {
      xr.add(p.x());
      yr.add(p.y());
    }
  }
  yr.add(0.0);
  charts_->residual->replace(residual);
  for (int k = 0; k < charts_->fits.size(); ++k)
    charts_->fits[k]->replace(QList<QPointF>(s.fits[static_cast<std::size_t>(k)].begin(),
                                             s.fits[static_cast<std::size_t>(k)].end()));
  charts_->outliers->replace(outliers);
  chart->addSeries(charts_->residual);
  for (QLineSeries* f : charts_->fits) chart->addSeries(f);
  chart->addSeries(charts_->outliers);

  charts_->xTitle = displayUnit(xTitle(plot));
  QAbstractAxis* ax = nullptr;
  const int categories = static_cast<int>(plot.categories.size());
  if (categories > 0 && categories <= kMaxCategoryLabels) {
    auto* cat = new QCategoryAxis;
    cat->setStartValue(-0.5);
    for (int i = 0; i < categories; ++i)
      cat->append(QString::fromStdString(plot.categories[static_cast<std::size_t>(i)]), i + 0.5);
    cat->setLabelsPosition(QCategoryAxis::AxisLabelsPositionCenter);
    cat->setRange(-0.5, categories - 0.5);
    ax = cat;
  } else {
    auto* v = new QValueAxis;
    if (categories > 0) {
      v->setRange(-0.5, categories - 0.5);
      v->setLabelFormat(QStringLiteral("%d"));
      charts_->xTitle += QLatin1Char(' ') + tr("(index of %n level(s))", nullptr, categories);
    } else {
      const Range xp = xr.valid() && xr.hi > xr.lo ? xr : xr.padded();
      v->setRange(xp.lo, xp.hi);
      v->applyNiceNumbers();
    }
    ax = v;
  }
  auto* ay = new QValueAxis;
  const Range yp = yr.padded();
  ay->setRange(yp.lo, yp.hi);
  ay->applyNiceNumbers();
  ax->setTitleText(charts_->xTitle);
  ay->setTitleText(yTitle(units));
  chart->addAxis(ax, Qt::AlignBottom);
  chart->addAxis(ay, Qt::AlignLeft);
  QList<QAbstractSeries*> attached = {charts_->residual, charts_->outliers};
  for (QLineSeries* f : charts_->fits) attached.append(f);
  for (QAbstractSeries* series : attached) {
    series->attachAxis(ax);
    series->attachAxis(ay);
  }
  if (outliers.isEmpty()) {
    // No outlier: keep the series (count 0) but not its legend entry.
    const auto markers = chart->legend()->markers(charts_->outliers);
    for (auto* m : markers) m->setVisible(false);
  }
}

}  // namespace metrofit
