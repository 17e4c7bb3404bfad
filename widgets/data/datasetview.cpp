#include "widgets/data/datasetview.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QFile>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLegend>
#include <QLineEdit>
#include <QLineSeries>
#include <QLocale>
#include <QPen>
#include <QPointF>
#include <QSignalBlocker>
#include <QSortFilterProxyModel>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>
#include <QValueAxis>
#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <utility>

#include "core/project/dataset_content.h"
#include "core/project/project.h"
#include "widgets/common/backgroundrun.h"
#include "widgets/common/chartexport.h"
#include "widgets/common/chartnavigation.h"
#include "widgets/common/palette.h"
#include "widgets/common/tablecopy.h"
#include "widgets/data/datasettablemodel.h"

namespace metrofit {

namespace {

/// Rows that contain the filter text in any cell (DatasetTableModel::rowContains).
class DatasetFilterProxy : public QSortFilterProxyModel {
 public:
  using QSortFilterProxyModel::QSortFilterProxyModel;
  void setText(const QString& text) {
    text_ = text;
    invalidateFilter();
  }

 protected:
  bool filterAcceptsRow(int row, const QModelIndex& parent) const override {
    const auto* model = static_cast<const DatasetTableModel*>(sourceModel());
    return text_.isEmpty() || (!parent.isValid() && model->rowContains(row, text_));
  }

 private:
  QString text_;
};

}  // namespace

struct DatasetView::Chart {
  QChart* chart = nullptr;
  QLineSeries* series = nullptr;
  QValueAxis* x = nullptr;
  QValueAxis* y = nullptr;
};

struct DatasetView::Reading {
  BackgroundRun<std::shared_ptr<const DatasetContent>> run;
  QString file;  ///< of the read going on
  /// A request made while a read was going on: done after it.
  struct Request {
    QString file;
    DatasetRef dataset;
    std::optional<DatasetRef> reference;
  };
  std::optional<Request> next;
};

DatasetView::DatasetView(QWidget* parent)
    : QWidget(parent),
      model_(new DatasetTableModel(this)),
      proxy_(new DatasetFilterProxy(this)),
      summary_(new QLabel(this)),
      error_(new QLabel(this)),
      filter_(new QLineEdit(this)),
      plotColumn_(new QComboBox(this)),
      plotAxis_(new QComboBox(this)),
      splitter_(new QSplitter(Qt::Vertical, this)),
      table_(new QTableView(splitter_)),
      chart_(std::make_unique<Chart>()),
      reading_(std::make_unique<Reading>()) {
  setObjectName(QStringLiteral("datasetView"));
  proxy_->setSourceModel(model_);
  proxy_->setSortRole(DatasetTableModel::SortRole);

  summary_->setObjectName(QStringLiteral("datasetSummary"));
  summary_->setWordWrap(true);
  error_->setObjectName(QStringLiteral("datasetError"));
  error_->setWordWrap(true);
  error_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  error_->setStyleSheet(QStringLiteral("color: %1;").arg(palette::badText().name()));
  error_->hide();

  filter_->setObjectName(QStringLiteral("datasetFilter"));
  filter_->setPlaceholderText(tr("Filter rows (text in any column)"));
  filter_->setClearButtonEnabled(true);
  connect(filter_, &QLineEdit::textChanged, this, [this](const QString& text) {
    static_cast<DatasetFilterProxy*>(proxy_)->setText(text);
    updateSummary();
  });
  plotColumn_->setObjectName(QStringLiteral("datasetPlotColumn"));
  plotColumn_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  plotAxis_->setObjectName(QStringLiteral("datasetPlotAxis"));
  plotAxis_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  connect(plotColumn_, &QComboBox::currentIndexChanged, this, [this] { updatePlot(); });
  connect(plotAxis_, &QComboBox::currentIndexChanged, this, [this] { updatePlot(); });

  table_->setObjectName(QStringLiteral("datasetTable"));
  table_->setModel(proxy_);
  table_->setSortingEnabled(true);
  table_->sortByColumn(-1, Qt::AscendingOrder);  // file order until a header is clicked
  table_->setAlternatingRowColors(true);
  table_->setSelectionBehavior(QAbstractItemView::SelectItems);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setWordWrap(false);
  table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 6);
  table_->horizontalHeader()->setStretchLastSection(false);
  enableTableCopy(table_);

  chart_->chart = new QChart();
  chart_->chart->legend()->hide();
  chart_->chart->setLocalizeNumbers(true);
  QLocale locale;
  locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
  chart_->chart->setLocale(locale);
  chart_->series = new QLineSeries(chart_->chart);
  QPen pen(palette::measured());
  pen.setWidthF(1.2);
  chart_->series->setPen(pen);
  chart_->series->setPointsVisible(false);
  chart_->chart->addSeries(chart_->series);
  chart_->x = new QValueAxis(chart_->chart);
  chart_->y = new QValueAxis(chart_->chart);
  chart_->x->setLabelFormat(QStringLiteral("%.6g"));
  chart_->y->setLabelFormat(QStringLiteral("%.6g"));
  chart_->chart->addAxis(chart_->x, Qt::AlignBottom);
  chart_->chart->addAxis(chart_->y, Qt::AlignLeft);
  chart_->series->attachAxis(chart_->x);
  chart_->series->attachAxis(chart_->y);
  chart_->chart->setMargins(QMargins(4, 4, 4, 4));
  auto* chartView = new QChartView(chart_->chart, splitter_);
  chartView->setObjectName(QStringLiteral("datasetChart"));
  chartView->setRenderHint(QPainter::Antialiasing);
  chartView->setMinimumHeight(220);
  chartView_ = chartView;
  enableChartExport(chartView_, QStringLiteral("dataset-plot"));
  enableChartNavigation(chartView_);
  splitter_->addWidget(table_);
  splitter_->addWidget(chartView_);
  splitter_->setStretchFactor(0, 3);
  splitter_->setStretchFactor(1, 2);
  splitter_->setChildrenCollapsible(false);
  splitter_->setSizes({360, 280});

  auto* controls = new QHBoxLayout();
  auto* filterLabel = new QLabel(tr("&Filter:"), this);
  filterLabel->setBuddy(filter_);
  auto* plotLabel = new QLabel(tr("&Plot:"), this);
  plotLabel->setBuddy(plotColumn_);
  auto* againstLabel = new QLabel(tr("&against"), this);
  againstLabel->setBuddy(plotAxis_);
  controls->addWidget(filterLabel);
  controls->addWidget(filter_, 1);
  controls->addSpacing(12);
  controls->addWidget(plotLabel);
  controls->addWidget(plotColumn_);
  controls->addWidget(againstLabel);
  controls->addWidget(plotAxis_);

  connect(&reading_->run, &BackgroundRunBase::finished, this, [this] { readingEnded(true, {}); });
  connect(&reading_->run, &BackgroundRunBase::cancelled, this, [this] { readingEnded(true, {}); });
  connect(&reading_->run, &BackgroundRunBase::failed, this,
          [this](const QString& message) { readingEnded(false, message); });

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(summary_);
  layout->addWidget(error_);
  layout->addLayout(controls);
  layout->addWidget(splitter_, 1);
}

DatasetView::~DatasetView() {
  reading_->run.waitForWorker();
}

bool DatasetView::isReading() const {
  return reading_->run.isRunning() || reading_->next.has_value();
}

void DatasetView::showDatasetInBackground(const QString& file, const DatasetRef& dataset,
                                          const std::optional<DatasetRef>& reference) {
  if (reading_->run.isRunning()) {
    reading_->next = Reading::Request{file, dataset, reference};
    return;
  }
  reading_->file = file;
  summary_->setText(tr("Reading %1…").arg(QFileInfo(file).fileName()));
  summary_->show();
  const std::string path = QFile::encodeName(file).toStdString();
  reading_->run.start([path, dataset, reference](RunObserver&) {
    return std::make_shared<const DatasetContent>(
        readDatasetContentFile(path, dataset, reference ? &*reference : nullptr));
  });
}

void DatasetView::readingEnded(bool ok, const QString& message) {
  if (auto next = std::exchange(reading_->next, std::nullopt)) {
    showDatasetInBackground(next->file, next->dataset, next->reference);  // the last request wins
    return;
  }
  if (ok) {
    if (auto content = reading_->run.takeResult()) setContent(*content);
  } else {
    showError(reading_->file, message);
  }
  emit datasetShown(ok);
}

bool DatasetView::showDataset(const QString& file, const DatasetRef& dataset,
                              const std::optional<DatasetRef>& reference) {
  try {
    setContent(std::make_shared<const DatasetContent>(readDatasetContentFile(
        QFile::encodeName(file).toStdString(), dataset, reference ? &*reference : nullptr)));
    return true;
  } catch (const std::exception& e) {
    showError(file, QString::fromStdString(e.what()));
    return false;
  }
}

void DatasetView::showError(const QString& file, const QString& message) {
  setContent(nullptr);
  QString line = message.simplified();
  error_->setText(tr("Cannot show %1: %2").arg(QFileInfo(file).fileName(), line));
  error_->setToolTip(file);
  error_->show();
  summary_->hide();
  splitter_->hide();
  filter_->setEnabled(false);
  plotColumn_->setEnabled(false);
  plotAxis_->setEnabled(false);
}

void DatasetView::setContent(std::shared_ptr<const DatasetContent> content) {
  const bool ok = content != nullptr;
  model_->setContent(std::move(content));
  table_->sortByColumn(-1, Qt::AscendingOrder);
  proxy_->sort(-1);
  error_->clear();
  error_->setVisible(false);
  summary_->setVisible(ok);
  splitter_->setVisible(ok);
  filter_->setEnabled(ok);
  plotColumn_->setEnabled(ok);
  plotAxis_->setEnabled(ok);

  const QSignalBlocker b1(plotColumn_), b2(plotAxis_);
  plotColumn_->clear();
  plotAxis_->clear();
  plotColumn_->addItem(tr("(none)"), -1);
  plotAxis_->addItem(tr("row number"), -1);
  int first = -1, deviation = -1;
  for (int c = 0; c < model_->columnCount(); ++c) {
    if (!model_->isNumeric(c)) continue;
    const QString header = model_->headerData(c, Qt::Horizontal).toString();
    plotColumn_->addItem(header, c);
    if (model_->isFeatureTable() && model_->columnName(c) == tr("Deviation")) deviation = c;
    // Any numeric column of a log can be the x axis (y_meas against x_meas draws a circular test).
    if (!model_->isFeatureTable()) plotAxis_->addItem(header, c);
    if (c != model_->timeColumn() && first < 0) first = c;
  }
  // A report plots its deviations against the row, a log its first column that is not the time
  // against the time (the row when it has none).
  const int shown = deviation >= 0 ? deviation : first;
  plotColumn_->setCurrentIndex(std::max(0, plotColumn_->findData(shown)));
  plotAxis_->setCurrentIndex(std::max(0, plotAxis_->findData(model_->timeColumn())));

  table_->horizontalHeader()->resizeSections(QHeaderView::ResizeToContents);
  updateSummary();
  updatePlot();
}

QString DatasetView::errorText() const {
  return error_->text();
}

QString DatasetView::summaryText() const {
  return summary_->text();
}

void DatasetView::updateSummary() {
  const DatasetContent* c = model_->content();
  if (!c) {
    summary_->clear();
    return;
  }
  QString text = tr("%1, %2 rows").arg(QString::fromStdString(c->format)).arg(model_->rowCount());
  if (model_->isFeatureTable()) {
    int oot = 0;
    for (int r = 0; r < model_->rowCount(); ++r) oot += model_->outOfTolerance(r) ? 1 : 0;
    text += QStringLiteral(", ") + tr("%n out of tolerance", nullptr, oot);
  }
  if (proxy_->rowCount() != model_->rowCount())
    text += QStringLiteral(", ") + tr("%1 shown").arg(proxy_->rowCount());
  summary_->setText(text);
  summary_->setToolTip(QString::fromStdString(c->file));
}

void DatasetView::setPlot(int column, int xColumn) {
  plotColumn_->setCurrentIndex(std::max(0, plotColumn_->findData(column)));
  plotAxis_->setCurrentIndex(std::max(0, plotAxis_->findData(xColumn)));
  updatePlot();
}

std::vector<QPointF> DatasetView::plottedPoints() const {
  const QList<QPointF> points = chart_->series->points();
  return {points.begin(), points.end()};
}

void DatasetView::updatePlot() {
  const int column = plotColumn_->currentData().isValid() ? plotColumn_->currentData().toInt() : -1;
  const int xColumn = plotAxis_->currentData().isValid() ? plotAxis_->currentData().toInt() : -1;
  QList<QPointF> points;
  if (column >= 0) {
    const int rows = model_->rowCount();
    points.reserve(rows);
    for (int r = 0; r < rows; ++r) {
      const double y = model_->number(r, column);
      const double x = xColumn >= 0 ? model_->number(r, xColumn) : r + 1.0;
      if (std::isfinite(x) && std::isfinite(y)) points.append(QPointF(x, y));
    }
  }
  chart_->series->replace(points);
  chart_->series->setName(column >= 0 ? model_->headerData(column, Qt::Horizontal).toString() : QString());
  // A few points (a report's features) are drawn as markers on the line.
  chart_->series->setPointsVisible(points.size() <= 200);
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  if (!points.isEmpty()) {
    x0 = x1 = points.front().x();
    y0 = y1 = points.front().y();
    for (const QPointF& p : points) {
      x0 = std::min(x0, p.x());
      x1 = std::max(x1, p.x());
      y0 = std::min(y0, p.y());
      y1 = std::max(y1, p.y());
    }
  }
  if (x1 <= x0) x1 = x0 + 1.0;
  if (y1 <= y0) {
    const double pad = y0 == 0.0 ? 1.0 : std::abs(y0) * 0.01;
    y0 -= pad;
    y1 += pad;
  }
  chart_->x->setRange(x0, x1);
  chart_->y->setRange(y0, y1);
  chart_->x->applyNiceNumbers();
  chart_->y->applyNiceNumbers();
  chart_->x->setTitleText(xColumn >= 0 ? plotAxis_->currentText() : tr("row"));
  chart_->y->setTitleText(column >= 0 ? plotColumn_->currentText() : QString());
}

}  // namespace metrofit
