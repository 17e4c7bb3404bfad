// ThermalHysteresisView: hysteresis charts (thermalmodelcharts.h) and the loop / lag table.
#include "widgets/thermal/thermalhysteresisview.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QStackedWidget>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <optional>
#include <utility>

#include "core/thermal/hysteresis.h"
#include "core/thermal/thermal_data.h"
#include "core/thermal/thermal_log.h"
#include "widgets/common/backgroundrun.h"
#include "widgets/common/chartexport.h"
#include "widgets/common/chartnavigation.h"
#include "widgets/common/tablecopy.h"
#include "widgets/thermal/thermalcharts.h"
#include "widgets/thermal/thermalmodelcharts.h"

namespace metrofit {
namespace {
/// The narrowest small multiple whose title, axis titles and ticks Qt Charts does not cut.
constexpr int kSmallMultipleMinWidth = 215;

/// One analysis, made on any thread (no widgets).
struct Analysis {
  int generation = 0;  ///< which request it answers
  ThermalLog log;
  thermal::ThermalSeries series;
  thermal::HysteresisAnalysis analysis;
  QString error;
};

Analysis analyse(int generation, const ThermalLog& log, const std::string& target,
                 const std::vector<std::string>& inputs) {
  Analysis a;
  a.generation = generation;
  a.log = log;
  try {
    a.series = thermal::selectThermalSeries(log, target, inputs);
    a.analysis = thermal::analyseHysteresis(a.series);
  } catch (const std::exception& e) {
    a.error = QString::fromStdString(e.what());
    a.series = {};
    a.analysis = {};
  }
  return a;
}

}  // namespace

struct ThermalHysteresisView::Impl {
  ThermalLog log;
  thermal::ThermalSeries series;
  thermal::HysteresisAnalysis analysis;
  QString error;
  QString sensor;  ///< empty: all
  QComboBox* combo = nullptr;
  QStackedWidget* stack = nullptr;
  QScrollArea* scroll = nullptr;
  QWidget* grid = nullptr;
  QLabel* message = nullptr;
  QTableWidget* table = nullptr;
  QLabel* phases = nullptr;
  int charts = 0;
  BackgroundRun<Analysis>* run = nullptr;
  /// The latest request while an older one still runs (the analysis cannot stop midway): started when
  /// that one ends, whose result is then dropped.
  std::optional<BackgroundRun<Analysis>::Job> queued;
  int generation = 0;    ///< the latest request; older results are dropped
  bool pending = false;  ///< the latest request runs or waits in `queued`

  QChartView* chartView(QChart* chart, QWidget* parent, int minHeight) {
    auto* view = new QChartView(chart, parent);
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumHeight(minHeight);
    enableChartExport(view, QStringLiteral("thermal-hysteresis"));
    enableChartNavigation(view);
    return view;
  }

  void rebuild() {
    grid = new QWidget;
    auto* layout = new QGridLayout(grid);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(4);
    charts = 0;
    const int index =
        sensor.isEmpty()
            ? -1
            : static_cast<int>(std::distance(
                  series.inputNames.begin(),
                  std::find(series.inputNames.begin(), series.inputNames.end(), sensor.toStdString())));
    if (index >= 0 && index < static_cast<int>(series.inputNames.size())) {
      layout->addWidget(chartView(makeHysteresisChart(log, series, analysis, index), grid, 300), 0, 0);
      charts = 1;
    } else {
      const int n = static_cast<int>(series.inputNames.size());
      // Two columns at most: beside the table, three columns of small multiples were 130 px wide at
      // 1280 x 800 and Qt Charts cut their titles, axis titles and ticks ("t1_deg...", "2... 2...";
      // gui-run F14, clipping_test). The grid scrolls vertically instead.
      const int columns = n <= 1 ? 1 : 2;
      HysteresisChartOptions o;
      o.compactTitle = true;
      o.legend = false;
      o.maxPoints = 600;
      for (int i = 0; i < n; ++i) {
        o.legend = i == 0;  // the heating / cooling key once, on the first chart of the grid
        QChartView* view = chartView(makeHysteresisChart(log, series, analysis, i, o), grid, 230);
        view->setMinimumWidth(kSmallMultipleMinWidth);
        layout->addWidget(view, i / columns, i % columns);
      }
      charts = n;
    }
    scroll->setWidget(grid);  // deletes the previous grid
  }

  /// Shows an analysis (the latest request: nothing is pending afterwards).
  bool apply(const Analysis& a) {
    pending = false;
    log = a.log;
    series = a.series;
    analysis = a.analysis;
    error = a.error;
    {
      const QSignalBlocker blocker(combo);
      combo->clear();
      combo->addItem(ThermalHysteresisView::tr("All sensors"), QString());
      for (const std::string& name : series.inputNames) {
        combo->addItem(QString::fromStdString(name), QString::fromStdString(name));
      }
      const int keep = combo->findData(sensor);
      combo->setCurrentIndex(keep >= 0 ? keep : 0);
      sensor = combo->currentData().toString();
    }
    fillTable();
    if (!error.isEmpty()) {
      message->setText(ThermalHysteresisView::tr("No hysteresis analysis for this log:\n%1").arg(error));
      stack->setCurrentWidget(message);
      phases->clear();
      charts = 0;
      return false;
    }
    phases->setText(ThermalHysteresisView::tr(
                        "Target %1: %2 heating rows, %3 cooling rows (the target's change grows or shrinks).")
                        .arg(QString::fromStdString(analysis.target))
                        .arg(analysis.heatingRows)
                        .arg(analysis.coolingRows));
    rebuild();
    stack->setCurrentWidget(scroll);
    return true;
  }

  void fillTable() {
    table->setRowCount(static_cast<int>(analysis.sensors.size()));
    const QString targetUnit = displayUnit(series.hasTarget() && log.indexOf(series.targetName) >= 0
                                               ? log.channel(series.targetName).unit
                                               : std::string());
    for (int r = 0; r < table->rowCount(); ++r) {
      const thermal::SensorHysteresis& h = analysis.sensors[static_cast<std::size_t>(r)];
      const QString unit = log.indexOf(h.sensor) >= 0 ? channelUnit(log.channel(h.sensor)) : QString();
      const QStringList cells = {QString::fromStdString(h.sensor),
                                 QLocale().toString(h.loopArea, 'f', 2),
                                 QLocale().toString(h.normalisedLoopArea, 'f', 3),
                                 QLocale().toString(h.tauMin, 'f', 1),
                                 QLocale().toString(h.r2, 'f', 3),
                                 QLocale().toString(h.r2Static, 'f', 3)};
      for (int c = 0; c < cells.size(); ++c) {
        auto* item = new QTableWidgetItem(cells[c]);
        item->setTextAlignment(c == 0 ? (Qt::AlignLeft | Qt::AlignVCenter)
                                      : (Qt::AlignRight | Qt::AlignVCenter));
        if (c == 1) item->setToolTip(ThermalHysteresisView::tr("loop area in %1 × %2").arg(unit, targetUnit));
        if (c == 3)
          item->setToolTip(h.tauMin >= 0.0 ? ThermalHysteresisView::tr("the sensor lags the displacement")
                                           : ThermalHysteresisView::tr("the displacement lags the sensor"));
        table->setItem(r, c, item);
      }
    }
    // Fit the width: the sensor column to its names, the five numbers share the rest (headers
    // elide, their tooltips give the full text); no sideways scrolling.
    table->resizeColumnToContents(0);
  }
};

ThermalHysteresisView::ThermalHysteresisView(QWidget* parent) : QWidget(parent), d(std::make_unique<Impl>()) {
  d->combo = new QComboBox(this);
  d->combo->setObjectName(QStringLiteral("hysteresisSensorCombo"));
  d->combo->setToolTip(tr("Sensor plotted against the displacement, or all sensors side by side"));
  d->combo->setSizeAdjustPolicy(QComboBox::AdjustToContents);  // filled after the first show (worker)
  d->scroll = new QScrollArea(this);
  d->scroll->setWidgetResizable(true);
  d->scroll->setFrameShape(QFrame::NoFrame);
  d->grid = new QWidget;
  d->scroll->setWidget(d->grid);
  d->message = new QLabel(this);
  d->message->setWordWrap(true);
  d->message->setAlignment(Qt::AlignCenter);
  d->stack = new QStackedWidget(this);
  d->stack->addWidget(d->scroll);
  d->stack->addWidget(d->message);

  d->table = new QTableWidget(0, 6, this);
  enableTableCopy(d->table);
  d->table->setObjectName(QStringLiteral("hysteresisTable"));
  d->table->setHorizontalHeaderLabels(
      {tr("sensor"), tr("loop area"), tr("loop / ranges"), tr("lag τ (min)"), tr("R² lag"), tr("R² static")});
  d->table->horizontalHeaderItem(1)->setToolTip(
      tr("Area enclosed by the trajectory (shoelace formula), sensor "
         "unit × displacement unit"));
  d->table->horizontalHeaderItem(2)->setToolTip(
      tr("Loop area divided by the product of the two ranges: 0 for a line, 0.785 for a circle"));
  d->table->horizontalHeaderItem(3)->setToolTip(
      tr("Time constant of a first-order lag between sensor and displacement; > 0: the sensor lags"));
  for (int c = 0; c < d->table->columnCount(); ++c) {
    QTableWidgetItem* header = d->table->horizontalHeaderItem(c);
    if (header->toolTip().isEmpty()) header->setToolTip(header->text());
    // Two lines, broken at the space nearest the middle: the translated headers are wider than the
    // five equal columns (German 'Schleife / Spannweiten' needs about 150 px of about 95).
    QString text = header->text();
    qsizetype best = -1;
    for (qsizetype i = text.indexOf(QLatin1Char(' ')); i >= 0; i = text.indexOf(QLatin1Char(' '), i + 1))
      if (best < 0 || std::abs(i - text.size() / 2) < std::abs(best - text.size() / 2)) best = i;
    if (best > 0) {
      text[best] = QLatin1Char('\n');
      header->setText(text);
    }
    d->table->horizontalHeader()->setSectionResizeMode(c, QHeaderView::ResizeToContents);
  }
  d->table->horizontalHeader()->setTextElideMode(Qt::ElideRight);
  d->table->horizontalHeader()->setStretchLastSection(true);
  d->table->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  d->table->verticalHeader()->setVisible(false);
  d->table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  d->table->setSelectionBehavior(QAbstractItemView::SelectRows);
  d->table->setMinimumWidth(480);
  d->table->setMaximumWidth(560);
  d->phases = new QLabel(this);
  d->phases->setWordWrap(true);

  auto* top = new QHBoxLayout;
  auto* label = new QLabel(tr("&Sensor:"), this);
  label->setBuddy(d->combo);
  top->addWidget(label);
  top->addWidget(d->combo);
  top->addStretch(1);

  auto* side = new QVBoxLayout;
  side->addWidget(new QLabel(tr("Loop area and lag per sensor"), this));
  side->addWidget(d->table, 1);
  side->addWidget(d->phases);

  auto* body = new QHBoxLayout;
  body->addWidget(d->stack, 1);
  body->addLayout(side);

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addLayout(top);
  layout->addLayout(body, 1);

  connect(d->combo, &QComboBox::currentIndexChanged, this,
          [this](int) { setSensor(d->combo->currentData().toString()); });
  d->run = new BackgroundRun<Analysis>(this);
  connect(d->run, &BackgroundRunBase::finished, this, [this] {
    const std::optional<Analysis> a = d->run->takeResult();
    if (d->queued) {  // a later request waited for this one: its result is not shown
      d->run->start(*std::exchange(d->queued, std::nullopt));
      return;
    }
    if (!d->pending || !a || a->generation != d->generation) return;  // replaced by setLog meanwhile
    emit analysisFinished(d->apply(*a));
  });
  // analyse() catches what the core throws; anything else is shown as the analysis' error.
  connect(d->run, &BackgroundRunBase::failed, this, [this](const QString& message) {
    if (d->queued) {
      d->run->start(*std::exchange(d->queued, std::nullopt));
      return;
    }
    if (!d->pending) return;
    Analysis a;
    a.generation = d->generation;
    a.error = message;
    emit analysisFinished(d->apply(a));
  });
  connect(d->table, &QTableWidget::cellDoubleClicked, this, [this](int row, int) {
    if (row >= 0 && row < static_cast<int>(d->analysis.sensors.size()))
      setSensor(QString::fromStdString(d->analysis.sensors[static_cast<std::size_t>(row)].sensor));
  });
}

ThermalHysteresisView::~ThermalHysteresisView() {
  d->queued.reset();
  d->run->disconnect(this);
  d->run->waitForWorker();
}

bool ThermalHysteresisView::setLog(const ThermalLog& log, const std::string& target,
                                   const std::vector<std::string>& inputs) {
  d->queued.reset();  // a running analysis ends unseen (its generation is old)
  return d->apply(analyse(++d->generation, log, target, inputs));
}

void ThermalHysteresisView::analyseLater(const ThermalLog& log, const std::string& target,
                                         const std::vector<std::string>& inputs) {
  const int generation = ++d->generation;
  d->pending = true;
  d->message->setText(tr("Analysing the hysteresis of %1…").arg(QString::fromStdString(target)));
  d->stack->setCurrentWidget(d->message);
  d->table->setRowCount(0);
  d->phases->clear();
  d->charts = 0;
  BackgroundRun<Analysis>::Job job = [generation, log, target, inputs](RunObserver&) {
    return analyse(generation, log, target, inputs);
  };
  if (d->run->isRunning())
    d->queued = std::move(job);
  else
    d->run->start(std::move(job));
}

bool ThermalHysteresisView::isAnalysing() const {
  return d->run->isRunning();
}

bool ThermalHysteresisView::finishAnalysis() {
  if (!d->pending) return d->error.isEmpty();
  // Each wait ends a run now (its signal shows the result, or starts the queued request).
  while (d->run->isRunning()) d->run->waitForFinished();
  return d->error.isEmpty();
}

void ThermalHysteresisView::setSensor(const QString& sensor) {
  const int index = d->combo->findData(sensor);
  const QString value = index >= 0 ? sensor : QString();
  {
    const QSignalBlocker blocker(d->combo);
    d->combo->setCurrentIndex(std::max(index, 0));
  }
  if (value == d->sensor && d->charts > 0) return;
  d->sensor = value;
  if (d->error.isEmpty() && !d->pending) d->rebuild();
  emit sensorChanged(d->sensor);
}

QString ThermalHysteresisView::sensor() const {
  return d->sensor;
}

const thermal::HysteresisAnalysis& ThermalHysteresisView::analysis() const {
  return d->analysis;
}

int ThermalHysteresisView::chartCount() const {
  return d->charts;
}

QString ThermalHysteresisView::errorMessage() const {
  return d->error;
}

}  // namespace metrofit
