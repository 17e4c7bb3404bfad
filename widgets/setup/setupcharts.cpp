#include "widgets/setup/setupcharts.h"

#include <QChart>
#include <QCoreApplication>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLocale>
#include <QPen>
#include <QScatterSeries>
#include <QValueAxis>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "core/common/axis_ticks.h"
#include "core/study/setup_validation.h"
#include "widgets/common/palette.h"

namespace metrofit {

namespace {

struct SetupChartsText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::SetupCharts)
};

using Range = ticks::Range;

/// A range with round ends and a tick step of 1, 2 or 5 x 10^k; 5-8 ticks.
void setNiceRange(QValueAxis* axis, Range r) {
  if (!r.valid()) r = {0.0, 1.0};
  if (r.hi - r.lo < 1e-9) {
    r.lo -= 0.01;
    r.hi += 0.01;
  }
  const double raw = (r.hi - r.lo) / 6.0;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  double step = p;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * p;
    if (raw <= step) break;
  }
  const double lo = std::floor(r.lo / step + 1e-9) * step, hi = std::ceil(r.hi / step - 1e-9) * step;
  axis->setRange(lo, hi);
  axis->setTickType(QValueAxis::TicksDynamic);
  axis->setTickAnchor(0.0);
  axis->setTickInterval(step);
  const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
  axis->setLabelFormat(QStringLiteral("%.%1f").arg(decimals));
}

void hideMarker(QChart* chart, QAbstractSeries* series) {
  for (QLegendMarker* marker : chart->legend()->markers(series)) marker->setVisible(false);
}

}  // namespace

QString setupMethodTitle(const QString& method) {
  if (method == QLatin1String("exact")) return SetupChartsText::tr("exact");
  return method.toUpper();
}

QString setupRunLabel(const QString& method, std::uint64_t seed) {
  return SetupChartsText::tr("%1, seed %2").arg(setupMethodTitle(method)).arg(seed);
}

QColor setupRunColor(const QString& method, int indexOfMethod) {
  int hue = 0;
  if (method == QLatin1String("cripso"))
    hue = 210;
  else if (method == QLatin1String("pso"))
    hue = 25;
  else if (method == QLatin1String("ga"))
    hue = 125;
  else if (method == QLatin1String("coa"))
    hue = 285;
  else
    hue = 0;
  const int value = std::clamp(200 - 40 * (indexOfMethod % 4), 90, 230);
  return QColor::fromHsv(hue, method == QLatin1String("exact") ? 0 : 220, value);
}

QChart* makeSetupConvergenceChart(const std::vector<SetupConvergenceRun>& runs,
                                  const std::optional<setup::SetupScore>& exact, long budget, bool showF2,
                                  bool showF) {
  auto* chart = new QChart;
  chart->setAnimationOptions(QChart::NoAnimation);
  chart->setMargins(QMargins(6, 6, 6, 6));
  QStringList key{SetupChartsText::tr("solid: f1")};
  if (showF2) key << SetupChartsText::tr("dashed: f2 = |x|");
  if (showF) key << SetupChartsText::tr("dotted: f = 10 f1 − f2 (right axis)");
  chart->setTitle(key.join(QStringLiteral(" · ")));
  QFont titleFont = chart->titleFont();
  titleFont.setPointSizeF(titleFont.pointSizeF() * 0.9);
  titleFont.setBold(false);
  chart->setTitleFont(titleFont);

  auto* x = new QValueAxis;
  x->setTitleText(SetupChartsText::tr("solutions evaluated"));
  auto* left = new QValueAxis;
  left->setTitleText(showF2 ? SetupChartsText::tr("f1, f2 (mm)") : SetupChartsText::tr("f1 (mm)"));
  auto* right = new QValueAxis;
  right->setTitleText(SetupChartsText::tr("f = 10 f1 − f2 (mm)"));
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(left, Qt::AlignLeft);
  if (showF) chart->addAxis(right, Qt::AlignRight);

  Range rx, rl, rr;
  rx.add(0.0);
  rl.add(0.0);
  long maxEval = 0;
  for (const auto& run : runs)
    for (const auto& p : run.trace) maxEval = std::max(maxEval, p.evaluations);
  rx.add(static_cast<double>(maxEval > 0 ? maxEval : budget));
  std::map<QString, int> perMethod;
  for (const SetupConvergenceRun& run : runs) {
    const QColor color = setupRunColor(run.method, perMethod[run.method]++);
    auto* f1 = new QLineSeries;
    auto* f2 = new QLineSeries;
    auto* f = new QLineSeries;
    f1->setName(run.label);
    for (const auto& p : run.trace) {
      // The first iterations can be far off (random starts): clip what the chart shows, not the data.
      f1->append(static_cast<double>(p.evaluations), p.f1);
      f2->append(static_cast<double>(p.evaluations), p.f2);
      f->append(static_cast<double>(p.evaluations), p.f);
    }
    // Ranges from the second half of the run's first decile on, so that the converged part is legible.
    const std::size_t skip = run.trace.size() > 20 ? run.trace.size() / 20 : 0;
    for (std::size_t i = skip; i < run.trace.size(); ++i) {
      rl.add(run.trace[i].f1);
      if (showF2) rl.add(run.trace[i].f2);
      rr.add(run.trace[i].f);
    }
    QPen pen(color, 2.0);
    f1->setPen(pen);
    pen.setWidthF(1.5);
    pen.setStyle(Qt::DashLine);
    f2->setPen(pen);
    pen.setStyle(Qt::DotLine);
    f->setPen(pen);
    chart->addSeries(f1);
    f1->attachAxis(x);
    f1->attachAxis(left);
    if (showF2) {
      chart->addSeries(f2);
      f2->attachAxis(x);
      f2->attachAxis(left);
      hideMarker(chart, f2);
    } else {
      delete f2;
    }
    if (showF) {
      chart->addSeries(f);
      f->attachAxis(x);
      f->attachAxis(right);
      hideMarker(chart, f);
    } else {
      delete f;
    }
  }
  if (exact) {
    const double x1 = rx.valid() ? rx.hi : static_cast<double>(budget);
    auto* e1 = new QLineSeries;
    e1->setName(SetupChartsText::tr("exact optimum f1 = %1 mm").arg(QLocale().toString(exact->f1, 'f', 4)));
    e1->append(0.0, exact->f1);
    e1->append(x1, exact->f1);
    e1->setPen(QPen(palette::reference(), 1.5, Qt::DashDotLine));
    chart->addSeries(e1);
    e1->attachAxis(x);
    e1->attachAxis(left);
    rl.add(exact->f1);
    if (showF2) rl.add(exact->f2);
    if (showF) {
      auto* ef = new QLineSeries;
      ef->setName(SetupChartsText::tr("exact f = %1").arg(QLocale().toString(exact->f, 'f', 4)));
      ef->append(0.0, exact->f);
      ef->append(x1, exact->f);
      ef->setPen(QPen(QColor(0x70, 0x70, 0x70), 1.2, Qt::DotLine));
      chart->addSeries(ef);
      ef->attachAxis(x);
      ef->attachAxis(right);
      rr.add(exact->f);
    }
  }
  setNiceRange(x, rx);
  setNiceRange(left, rl);
  if (showF) {
    if (!rr.valid()) rr = rl;
    setNiceRange(right, rr);
  } else {
    delete right;
  }
  chart->legend()->setAlignment(Qt::AlignBottom);
  chart->legend()->setVisible(true);
  return chart;
}

QChart* makeSetupValidationChart(const setup::ValidationResult& result) {
  auto* chart = new QChart;
  chart->setAnimationOptions(QChart::NoAnimation);
  chart->setMargins(QMargins(6, 6, 6, 6));
  auto* x = new QValueAxis;
  x->setTitleText(SetupChartsText::tr("measurement set, sorted by f1 before correction"));
  auto* y = new QValueAxis;
  y->setTitleText(SetupChartsText::tr("f1 (mm)"));
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);
  Range rx, ry;
  rx.add(0.0);
  ry.add(0.0);
  const std::vector<std::size_t> order = result.sortedByBefore();
  rx.add(static_cast<double>(std::max<std::size_t>(order.size(), 1)) + 1.0);

  auto* before = new QLineSeries;
  before->setName(SetupChartsText::tr("before correction"));
  before->setPen(QPen(palette::before(), 1.5));
  auto* exact = new QLineSeries;
  exact->setName(SetupChartsText::tr("exact optimum"));
  exact->setPen(QPen(palette::reference(), 1.5, Qt::DashLine));
  std::map<std::string, QScatterSeries*> trials;
  std::map<QString, int> perMethod;
  for (std::size_t rank = 0; rank < order.size(); ++rank) {
    const setup::ValidationSet& set = result.sets[order[rank]];
    const double xr = static_cast<double>(rank + 1);
    before->append(xr, set.f1Before);
    exact->append(xr, set.exactF1);
    ry.add(set.f1Before);
    ry.add(set.exactF1);
    for (const setup::ValidationTrial& t : set.trials) {
      QScatterSeries*& s = trials[t.method];
      if (s == nullptr) {
        s = new QScatterSeries;
        const QString method = QString::fromStdString(t.method);
        s->setName(SetupChartsText::tr("%1 trials").arg(setupMethodTitle(method)));
        s->setMarkerSize(5.0);
        s->setColor(setupRunColor(method, perMethod[method]++));
        s->setBorderColor(Qt::transparent);
      }
      s->append(xr, t.f1);
      ry.add(t.f1);
    }
  }
  for (QAbstractSeries* s : std::initializer_list<QAbstractSeries*>{before, exact}) {
    chart->addSeries(s);
    s->attachAxis(x);
    s->attachAxis(y);
  }
  for (auto& [method, s] : trials) {
    chart->addSeries(s);
    s->attachAxis(x);
    s->attachAxis(y);
  }
  setNiceRange(x, rx);
  setNiceRange(y, ry);
  chart->legend()->setAlignment(Qt::AlignBottom);
  return chart;
}

}  // namespace metrofit
