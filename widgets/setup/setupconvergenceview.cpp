#include "widgets/setup/setupconvergenceview.h"
#include "core/setup/methods.h"
#include "widgets/common/chartexport.h"
#include "widgets/common/chartnavigation.h"

#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLegendMarker>
#include <QVBoxLayout>

namespace metrofit {

struct SetupConvergenceView::Impl {
  std::vector<SetupConvergenceRun> runs;
  std::optional<setup::SetupScore> exact;
  long budget = setup::kPaperBudget;
  QChartView* chartView = nullptr;
  QCheckBox* showF2 = nullptr;
  QCheckBox* showF = nullptr;
};

SetupConvergenceView::SetupConvergenceView(QWidget* parent) : QWidget(parent), d(std::make_unique<Impl>()) {
  d->chartView = new QChartView(this);
  enableChartExport(d->chartView, QStringLiteral("setup-convergence"));
  enableChartNavigation(d->chartView);
  d->chartView->setObjectName(QStringLiteral("setupConvergenceChart"));
  d->chartView->setRenderHint(QPainter::Antialiasing);
  d->chartView->setMinimumSize(360, 240);
  d->showF2 = new QCheckBox(tr("Show f&2 = |x|"), this);
  d->showF = new QCheckBox(tr("Show f = &10 f1 − f2"), this);
  d->showF2->setChecked(true);
  d->showF->setChecked(true);
  d->showF2->setToolTip(tr("The size of the correction vector, mm (minimised among the f1-optimal)"));
  d->showF->setToolTip(tr("The single objective the metaheuristics maximise (right axis)"));
  auto* options = new QHBoxLayout;
  options->addWidget(new QLabel(tr("Best solution so far against the number of solutions evaluated."), this));
  options->addStretch(1);
  options->addWidget(d->showF2);
  options->addWidget(d->showF);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addLayout(options);
  layout->addWidget(d->chartView, 1);
  connect(d->showF2, &QCheckBox::toggled, this, &SetupConvergenceView::rebuild);
  connect(d->showF, &QCheckBox::toggled, this, &SetupConvergenceView::rebuild);
  rebuild();
}

SetupConvergenceView::~SetupConvergenceView() = default;

int SetupConvergenceView::addRun(const QString& method, std::uint64_t seed) {
  d->runs.push_back({setupRunLabel(method, seed), method, {}});
  rebuild();
  return static_cast<int>(d->runs.size()) - 1;
}

void SetupConvergenceView::appendPoints(int index, const std::vector<SetupTracePoint>& points) {
  if (index < 0 || index >= static_cast<int>(d->runs.size()) || points.empty()) return;
  auto& trace = d->runs[static_cast<std::size_t>(index)].trace;
  trace.insert(trace.end(), points.begin(), points.end());
  rebuild();
}

void SetupConvergenceView::setExact(const std::optional<setup::SetupScore>& exact) {
  d->exact = exact;
  rebuild();
}

void SetupConvergenceView::setBudget(long budget) {
  d->budget = budget;
  if (d->runs.empty()) rebuild();
}

void SetupConvergenceView::clearRuns() {
  d->runs.clear();
  rebuild();
}

const std::vector<SetupConvergenceRun>& SetupConvergenceView::runs() const {
  return d->runs;
}

bool SetupConvergenceView::hasExact() const {
  return d->exact.has_value();
}

int SetupConvergenceView::seriesCount() const {
  return static_cast<int>(d->chartView->chart()->series().size());
}

QStringList SetupConvergenceView::legendLabels() const {
  QStringList labels;
  for (QLegendMarker* marker : d->chartView->chart()->legend()->markers())
    if (marker->isVisible()) labels << marker->label();
  return labels;
}

void SetupConvergenceView::rebuild() {
  QChart* old = d->chartView->chart();
  d->chartView->setChart(
      makeSetupConvergenceChart(d->runs, d->exact, d->budget, d->showF2->isChecked(), d->showF->isChecked()));
  delete old;
}

}  // namespace metrofit
