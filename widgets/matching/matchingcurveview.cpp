#include "widgets/matching/matchingcurveview.h"
#include "widgets/common/chartexport.h"
#include "widgets/common/chartnavigation.h"
#include "widgets/common/palette.h"

#include <QChart>
#include <QChartView>
#include <QLineSeries>
#include <QLocale>
#include <QLogValueAxis>
#include <QPen>
#include <QVBoxLayout>
#include <QValueAxis>
#include <algorithm>
#include <cmath>
#include <map>

namespace metrofit {

struct MatchingCurveView::Impl {
  QChartView* view = nullptr;
  QChart* chart = nullptr;
  std::map<QString, std::vector<std::pair<double, double>>> curves;
  double optimum = 0.0;
};

namespace {

QColor curveColour(const QString& method, int index) {
  if (method.contains(QLatin1String("SADE"), Qt::CaseInsensitive)) return palette::series(0);
  if (method.contains(QLatin1String("GA"), Qt::CaseInsensitive)) return palette::series(3);
  static const QColor others[] = {palette::series(2), palette::series(4)};
  return others[index % 2];
}

}  // namespace

MatchingCurveView::MatchingCurveView(QWidget* parent) : QWidget(parent), d(std::make_unique<Impl>()) {
  d->chart = new QChart;
  d->chart->setAnimationOptions(QChart::NoAnimation);
  d->chart->legend()->setAlignment(Qt::AlignTop);
  d->chart->setMargins(QMargins(4, 4, 4, 4));
  d->view = new QChartView(d->chart, this);
  enableChartExport(d->view, QStringLiteral("matching-optimisation"));
  enableChartNavigation(d->view);
  d->view->setRenderHint(QPainter::Antialiasing);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(d->view);
  rebuild();
}

MatchingCurveView::~MatchingCurveView() = default;

void MatchingCurveView::setCurve(const QString& method,
                                 const std::vector<std::pair<double, double>>& points) {
  d->curves[method] = points;
  rebuild();
}

void MatchingCurveView::setOptimum(double rmseMm) {
  d->optimum = rmseMm;
  rebuild();
}

void MatchingCurveView::clear() {
  d->curves.clear();
  d->optimum = 0.0;
  rebuild();
}

int MatchingCurveView::curveCount() const {
  return static_cast<int>(d->curves.size());
}

QStringList MatchingCurveView::curveNames() const {
  QStringList names;
  for (const auto& [name, points] : d->curves) names << name;
  return names;
}

QChart* MatchingCurveView::chart() const {
  return d->chart;
}

void MatchingCurveView::rebuild() {
  QChart* chart = d->chart;
  chart->removeAllSeries();
  for (QAbstractAxis* axis : chart->axes()) {
    chart->removeAxis(axis);
    delete axis;
  }
  auto* x = new QValueAxis;
  x->setTitleText(tr("generation"));
  x->setLabelFormat(QStringLiteral("%d"));
  auto* y = new QLogValueAxis;
  // Short: the tab is low at 1280 x 800 and Qt Charts cuts a longer title (clipping_test).
  y->setTitleText(tr("best RMS (mm)"));
  y->setLabelFormat(QStringLiteral("%.3g"));
  y->setBase(10.0);
  y->setMinorTickCount(-1);
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);
  chart->setTitle(d->curves.empty() ? tr("Optimisation curve: run SADE or GA-simplex")
                                    : tr("Optimisation curve of the fine matching"));

  double xMax = 1.0, yMin = INFINITY, yMax = 0.0;
  int index = 0;
  for (const auto& [name, points] : d->curves) {
    auto* series = new QLineSeries;
    series->setName(name);
    QList<QPointF> list;
    for (const auto& [g, v] : points) {
      if (!(v > 0.0) || !std::isfinite(v)) continue;
      list.append(QPointF(g, v));
      xMax = std::max(xMax, g);
      yMin = std::min(yMin, v);
      yMax = std::max(yMax, v);
    }
    series->replace(list);
    series->setPen(QPen(curveColour(name, index++), 2.0));
    chart->addSeries(series);
    series->attachAxis(x);
    series->attachAxis(y);
  }
  if (d->optimum > 0.0) {
    auto* ref = new QLineSeries;
    ref->setName(tr("least-squares optimum %1 mm").arg(QLocale().toString(d->optimum, 'f', 5)));
    ref->replace({QPointF(0.0, d->optimum), QPointF(xMax, d->optimum)});
    QPen pen(palette::reference(), 1.5, Qt::DashLine);
    ref->setPen(pen);
    chart->addSeries(ref);
    ref->attachAxis(x);
    ref->attachAxis(y);
    yMin = std::min(yMin, d->optimum);
    yMax = std::max(yMax, d->optimum);
  }
  if (!(yMax > 0.0) || !std::isfinite(yMin)) {
    yMin = 0.01;
    yMax = 10.0;
  }
  x->setRange(0.0, xMax);
  const double lo = std::pow(10.0, std::floor(std::log10(yMin * 0.95)));
  const double hi = std::pow(10.0, std::ceil(std::log10(yMax * 1.05)));
  y->setRange(lo, hi > lo ? hi : lo * 10.0);
}

}  // namespace metrofit
