#include "widgets/setup/setupvalidationview.h"

#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>
#include <cmath>
#include <exception>
#include <map>

#include "core/setup/exact.h"
#include "core/study/setup_validation.h"
#include "widgets/common/backgroundrun.h"
#include "widgets/common/chartexport.h"
#include "widgets/common/chartnavigation.h"
#include "widgets/setup/setupcharts.h"

namespace metrofit {

namespace {
struct Outcome {
  setup::ValidationResult result;
  setup::ValidationSummary summary;
};

/// Releases the worker thread's exact solver however the job ends.
struct ReleaseExactSolver {
  ReleaseExactSolver() = default;
  ReleaseExactSolver(const ReleaseExactSolver&) = delete;
  ReleaseExactSolver& operator=(const ReleaseExactSolver&) = delete;
  ~ReleaseExactSolver() { setup::releaseExactSolverThread(); }
};
}  // namespace

struct SetupValidationView::Impl {
  setup::Model model;
  bool hasModel = false;
  std::vector<std::vector<double>> measuredSets;  ///< per part, for the view's model (may be empty)
  QSpinBox* sets = nullptr;
  QSpinBox* trials = nullptr;
  QSpinBox* budget = nullptr;
  QDoubleSpinBox* w1 = nullptr;
  QDoubleSpinBox* w2 = nullptr;
  QSpinBox* seed = nullptr;
  std::map<std::string, QCheckBox*> methods;
  QPushButton* run = nullptr;
  QPushButton* cancel = nullptr;
  QProgressBar* progress = nullptr;
  QLabel* summary = nullptr;
  QChartView* chartView = nullptr;
  BackgroundRun<Outcome> runner;
  std::unique_ptr<setup::ValidationResult> result;
};

namespace {
QString introText() {
  return SetupValidationView::tr(
      "The paper's statistical validation: simulated measurement sets with setup-data and "
      "random errors (Eq. 12–13), each corrected by the exact method and by M trials of the "
      "chosen metaheuristics; the sets sorted by their budget before correction (Fig. 18).");
}
}  // namespace

SetupValidationView::SetupValidationView(QWidget* parent) : QWidget(parent), d(std::make_unique<Impl>()) {
  setObjectName(QStringLiteral("setupValidationView"));
  d->sets = new QSpinBox(this);
  d->sets->setRange(1, 10000);
  d->sets->setValue(static_cast<int>(setup::ValidationOptions{}.sets));  // the paper's 100
  d->sets->setToolTip(tr("Simulated measurement sets N (the paper: 100)"));
  d->trials = new QSpinBox(this);
  d->trials->setRange(1, 1000);
  d->trials->setValue(setup::ValidationOptions{}.trials);  // the paper's 10
  d->trials->setToolTip(tr("Trials M of every method on every set (the paper: 10)"));
  d->budget = new QSpinBox(this);
  d->budget->setRange(100, 10000000);
  d->budget->setSingleStep(1000);
  d->budget->setValue(static_cast<int>(setup::kPaperBudget));
  d->budget->setSuffix(tr(" solutions"));
  d->w1 = new QDoubleSpinBox(this);
  d->w2 = new QDoubleSpinBox(this);
  for (QDoubleSpinBox* w : {d->w1, d->w2}) {
    w->setDecimals(3);
    w->setRange(0.0, 10.0);
    w->setSingleStep(0.005);
    w->setSuffix(tr(" mm"));
  }
  d->w1->setValue(0.03);
  d->w2->setValue(0.02);
  d->w1->setToolTip(tr("Weight of the setup-data errors, Eq. 12: E = w1 (1 − 2r)"));
  d->w2->setToolTip(tr("Weight of the random errors, Eq. 13: E = w2 (1 − 2r)"));
  d->seed = new QSpinBox(this);
  d->seed->setRange(0, 1000000000);
  d->seed->setValue(1);
  // Two check boxes per row: four in one row do not fit the 380 px column (clipping_test).
  auto* methodRow = new QGridLayout;
  int methodIndex = 0;
  for (const std::string& m : setup::setupMetaheuristicNames()) {
    auto* box = new QCheckBox(setupMethodTitle(QString::fromStdString(m)), this);
    box->setChecked(m == "cripso");
    d->methods[m] = box;
    methodRow->addWidget(box, methodIndex / 2, methodIndex % 2);
    ++methodIndex;
  }
  methodRow->setColumnStretch(2, 1);
  d->run = new QPushButton(tr("Run &validation"), this);
  d->cancel = new QPushButton(tr("Cancel"), this);
  d->cancel->setEnabled(false);
  d->progress = new QProgressBar(this);
  d->progress->setObjectName(QStringLiteral("setupValidationProgress"));
  d->progress->setRange(0, 1);
  d->progress->setValue(0);
  d->summary = new QLabel(this);
  d->summary->setObjectName(QStringLiteral("setupValidationSummary"));
  d->summary->setWordWrap(true);
  d->summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
  d->summary->setText(introText());
  d->chartView = new QChartView(this);
  enableChartExport(d->chartView, QStringLiteral("setup-validation"));
  enableChartNavigation(d->chartView);
  d->chartView->setObjectName(QStringLiteral("setupValidationChart"));
  d->chartView->setRenderHint(QPainter::Antialiasing);
  d->chartView->setMinimumSize(360, 240);

  auto* form = new QFormLayout;
  form->addRow(tr("Measurement sets N:"), d->sets);
  form->addRow(tr("Trials per set M:"), d->trials);
  form->addRow(tr("Budget per trial:"), d->budget);
  form->addRow(tr("w1 (setup data):"), d->w1);
  form->addRow(tr("w2 (random):"), d->w2);
  form->addRow(tr("Seed:"), d->seed);
  form->addRow(tr("Methods:"), methodRow);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(d->run);
  buttons->addWidget(d->cancel);
  auto* controls = new QVBoxLayout;
  controls->addLayout(form);
  controls->addLayout(buttons);
  controls->addWidget(d->progress);
  controls->addWidget(d->summary);
  controls->addStretch(1);
  auto* controlsBox = new QWidget(this);
  controlsBox->setLayout(controls);
  controlsBox->setMaximumWidth(380);

  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(controlsBox);
  layout->addWidget(d->chartView, 1);

  connect(d->run, &QPushButton::clicked, this, [this] { start(); });
  connect(d->cancel, &QPushButton::clicked, this, &SetupValidationView::cancel);
  connect(&d->runner, &BackgroundRunBase::progress, this, [this](double fraction, const QString&) {
    d->progress->setValue(static_cast<int>(std::lround(fraction * d->progress->maximum())));
  });
  connect(&d->runner, &BackgroundRunBase::finished, this, [this] { onFinished({}); });
  connect(&d->runner, &BackgroundRunBase::cancelled, this, [this] { onFinished({}); });
  connect(&d->runner, &BackgroundRunBase::failed, this,
          [this](const QString& message) { onFinished(message); });
}

SetupValidationView::~SetupValidationView() {
  d->runner.disconnect(this);
  d->runner.cancel();
  d->runner.waitForWorker();
}

void SetupValidationView::setModel(const setup::Model& model) {
  d->model = model;
  d->measuredSets.clear();
  d->hasModel = setup::checkModel(model).empty();
  d->run->setEnabled(d->hasModel && !isRunning());
}

void SetupValidationView::setMeasurements(const setup::Model& measModel,
                                          const setup::Measurements* measurements) {
  d->measuredSets.clear();
  if (measurements == nullptr || !d->hasModel || measModel.dimensionIds() != d->model.dimensionIds()) return;
  d->measuredSets = setup::partDeviationSets(measModel, *measurements);
}

void SetupValidationView::setSets(int sets) {
  d->sets->setValue(sets);
}

void SetupValidationView::setTrials(int trials) {
  d->trials->setValue(trials);
}

void SetupValidationView::setBudget(long budget) {
  d->budget->setValue(static_cast<int>(budget));
}

int SetupValidationView::sets() const {
  return d->sets->value();
}

int SetupValidationView::trials() const {
  return d->trials->value();
}

bool SetupValidationView::isRunning() const {
  return d->runner.isRunning();
}

QProgressBar* SetupValidationView::progressBar() const {
  return d->progress;
}

void SetupValidationView::clearResult() {
  if (isRunning()) {
    d->runner.cancel();
    d->runner.waitForFinished();
  }
  d->result.reset();
  QChart* old = d->chartView->chart();
  d->chartView->setChart(new QChart);
  delete old;
  d->progress->setRange(0, 1);
  d->progress->setValue(0);
  d->summary->setText(introText());
}

const setup::ValidationResult* SetupValidationView::result() const {
  return d->result.get();
}

QString SetupValidationView::summaryText() const {
  return d->summary->text();
}

bool SetupValidationView::start() {
  if (isRunning() || !d->hasModel) return false;
  setup::ValidationOptions options;
  options.sets = static_cast<std::size_t>(d->sets->value());
  options.trials = d->trials->value();
  options.budget = d->budget->value();
  options.simulation.w1 = d->w1->value();
  options.simulation.w2 = d->w2->value();
  options.seed = static_cast<std::uint64_t>(d->seed->value());
  options.methods.clear();
  for (const auto& [name, box] : d->methods)
    if (box->isChecked()) options.methods.push_back(name);
  if (options.methods.empty()) {
    d->summary->setText(tr("Choose at least one method."));
    return false;
  }
  d->progress->setRange(0, static_cast<int>(options.sets));
  d->progress->setValue(0);
  d->run->setEnabled(false);
  d->cancel->setEnabled(true);
  d->summary->setText(tr("Running %1 sets x %2 trials…").arg(options.sets).arg(options.trials));
  const setup::Model model = d->model;
  d->runner.start([model, options](RunObserver& run) {
    const ReleaseExactSolver release;
    Outcome out;
    out.result =
        setup::runValidation(model, options, &run.cancelToken(), [&run](std::size_t done, std::size_t total) {
          run.report(total == 0 ? 1.0 : static_cast<double>(done) / static_cast<double>(total));
        });
    out.summary = setup::summarizeValidation(model, options, out.result);
    return out;
  });
  return true;
}

void SetupValidationView::cancel() {
  d->runner.cancel();
}

void SetupValidationView::waitForFinished() {
  d->runner.waitForFinished();
}

void SetupValidationView::onFinished(const QString& error) {
  d->run->setEnabled(d->hasModel);
  d->cancel->setEnabled(false);
  const std::optional<Outcome> taken = d->runner.takeResult();
  if (!error.isEmpty() || !taken) {
    d->summary->setText(tr("The validation failed: %1").arg(error));
    emit finished();
    return;
  }
  const Outcome& outcome = *taken;
  d->result = std::make_unique<setup::ValidationResult>(outcome.result);
  const setup::ValidationResult& r = *d->result;
  d->progress->setValue(static_cast<int>(r.sets.size()));
  QChart* old = d->chartView->chart();
  d->chartView->setChart(makeSetupValidationChart(r));
  delete old;

  const setup::ValidationSummary& sum = outcome.summary;
  const QLocale locale;
  auto mm = [&](double v) { return locale.toString(v, 'f', 4); };
  QStringList lines;
  lines << tr("%1 sets%2: f1 before correction from %3 to %4 mm.")
               .arg(r.sets.size())
               .arg(r.cancelled ? tr(" (cancelled)") : QString())
               .arg(mm(sum.f1BeforeMin), mm(sum.f1BeforeMax));
  if (sum.paperRangeApplies) {
    lines << (sum.paperRangeConsistent
                  ? tr("The paper's range %1 to %2 mm is consistent with the simulator (its minimum lies in "
                       "%3 to %4 mm, its maximum in %5 to %6 mm over 100 sets, 98 % bands).")
                  : tr("NOT consistent: the paper's range %1 to %2 mm lies outside the simulator's bands "
                       "(minimum %3 to %4 mm, maximum %5 to %6 mm over 100 sets, 98 %)."))
                 .arg(mm(setup::kPaperF1BeforeMinMm), mm(setup::kPaperF1BeforeMaxMm), mm(sum.minBandLo),
                      mm(sum.minBandHi), mm(sum.maxBandLo), mm(sum.maxBandHi));
  } else {
    lines << tr("The paper's range (%1 to %2 mm) is for w1 = 0.03 and w2 = 0.02 mm: not compared.")
                 .arg(mm(setup::kPaperF1BeforeMinMm), mm(setup::kPaperF1BeforeMaxMm));
  }
  for (const setup::ValidationMethodSummary& m : sum.methods) {
    lines << tr("%1: mean gap to the exact f1 %2 mm; %3 of %4 trials within one grid step.")
                 .arg(setupMethodTitle(QString::fromStdString(m.method)))
                 .arg(mm(m.meanGapF1))
                 .arg(m.withinStep)
                 .arg(m.trials);
  }
  const double configured =
      d->w1->value() + d->w2->value() > 0.0 ? d->w1->value() / (d->w1->value() + d->w2->value()) : 0.0;
  lines << tr("Share of the setup data in the dimension error, estimated from the sets: %1 % of the "
              "weights (configured %2 %), %3 % of the variance.")
               .arg(locale.toString(100.0 * sum.share.weightShare, 'f', 0))
               .arg(locale.toString(100.0 * configured, 'f', 0))
               .arg(locale.toString(100.0 * sum.share.varianceShare, 'f', 0));
  if (!d->measuredSets.empty()) {
    try {
      const setup::ShareEstimate data = setup::estimateSetupShare(d->model, d->measuredSets);
      lines << tr("In the project's measurements (%n part(s)): %1 % of the weights, %2 % of the variance.",
                  "", static_cast<int>(data.sets))
                   .arg(locale.toString(100.0 * data.weightShare, 'f', 0))
                   .arg(locale.toString(100.0 * data.varianceShare, 'f', 0));
    } catch (const std::exception& e) {
      lines << tr("The setup share of the measurements cannot be estimated: %1")
                   .arg(QString::fromStdString(e.what()));
    }
  }
  d->summary->setText(lines.join(QLatin1Char('\n')));
  emit finished();
}

}  // namespace metrofit
