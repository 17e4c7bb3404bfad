// ThermalTrendView: the trend chart (thermalcharts.h) beside a checkable channel list.
#include "widgets/charts/thermaltrendview.h"

#include <QChart>
#include <QChartView>
#include <QHBoxLayout>
#include <QIcon>
#include <QLabel>
#include <QListWidget>
#include <QPainter>
#include <QPixmap>
#include <QVBoxLayout>

#include "core/thermal/thermal_log.h"
#include "widgets/charts/thermalcharts.h"
#include "widgets/common/chartexport.h"

namespace metrofit {

struct ThermalTrendView::Impl {
  ThermalLog log;
  QChartView* chartView = nullptr;
  QListWidget* channelList = nullptr;
  QStringList visible;

  /// Replaces the chart by a new one of the visible channels (cheap: series are decimated).
  void rebuildChart() {
    ThermalChartOptions options;
    options.channelLegend = false;  // the channel list is the legend
    QChart* old = chartView->chart();
    chartView->setChart(makeThermalTrendChart(log, visible, options));
    delete old;
  }

  /// Visible channels in the log's order, from the check boxes.
  QStringList checkedChannels() const {
    QStringList names;
    for (int i = 0; i < channelList->count(); ++i) {
      const QListWidgetItem* item = channelList->item(i);
      if (item->checkState() == Qt::Checked) {
        names << item->data(Qt::UserRole).toString();
      }
    }
    return names;
  }

  void setChecks(const QStringList& names) {
    const QSignalBlocker blocker(channelList);
    for (int i = 0; i < channelList->count(); ++i) {
      QListWidgetItem* item = channelList->item(i);
      item->setCheckState(names.contains(item->data(Qt::UserRole).toString()) ? Qt::Checked : Qt::Unchecked);
    }
  }
};

namespace {

/// A small square of the channel's colour, dashed underline for channels drawn dashed.
QIcon swatch(const QColor& color, bool dashed) {
  QPixmap pixmap(14, 14);
  pixmap.fill(Qt::transparent);
  QPainter painter(&pixmap);
  if (dashed) {
    painter.fillRect(QRect(1, 5, 5, 4), color);
    painter.fillRect(QRect(8, 5, 5, 4), color);
  } else {
    painter.fillRect(QRect(1, 1, 12, 12), color);
  }
  return QIcon(pixmap);
}

}  // namespace

ThermalTrendView::ThermalTrendView(QWidget* parent) : QWidget(parent), d(std::make_unique<Impl>()) {
  d->chartView = new QChartView(this);
  enableChartExport(d->chartView, QStringLiteral("thermal-trend"));
  d->chartView->setObjectName(QStringLiteral("thermalTrendChart"));
  d->chartView->setRenderHint(QPainter::Antialiasing);
  d->chartView->setMinimumSize(360, 240);
  d->chartView->chart()->setAnimationOptions(QChart::NoAnimation);

  d->channelList = new QListWidget(this);
  d->channelList->setObjectName(QStringLiteral("thermalTrendChannels"));
  d->channelList->setToolTip(tr("Channels shown in the chart"));
  d->channelList->setMaximumWidth(190);
  d->channelList->setMinimumWidth(120);

  auto* side = new QVBoxLayout;
  side->setContentsMargins(0, 0, 0, 0);
  side->addWidget(new QLabel(tr("Channels"), this));
  side->addWidget(d->channelList, 1);

  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(d->chartView, 1);
  layout->addLayout(side);

  connect(d->channelList, &QListWidget::itemChanged, this, [this] {
    const QStringList names = d->checkedChannels();
    if (names == d->visible) {
      return;
    }
    d->visible = names;
    d->rebuildChart();
    emit visibleChannelsChanged(d->visible);
  });
}

ThermalTrendView::~ThermalTrendView() = default;

void ThermalTrendView::setLog(const ThermalLog& log) {
  d->log = log;
  {
    const QSignalBlocker blocker(d->channelList);
    d->channelList->clear();
    for (int i = 0; i < static_cast<int>(log.channels.size()); ++i) {
      const ThermalChannel& c = log.channels[i];
      const QString name = QString::fromStdString(c.name);
      auto* item =
          new QListWidgetItem(swatch(thermalChannelColor(log, i), channelKind(c) != ChannelKind::Temperature),
                              name, d->channelList);
      item->setData(Qt::UserRole, name);
      item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable | Qt::ItemIsSelectable);
      item->setToolTip(channelAxisTitle(c));
    }
  }
  d->visible = defaultThermalChannels(log);
  d->setChecks(d->visible);
  d->rebuildChart();
  emit visibleChannelsChanged(d->visible);
}

QStringList ThermalTrendView::visibleChannels() const {
  return d->visible;
}

void ThermalTrendView::setVisibleChannels(const QStringList& names) {
  d->setChecks(names);
  const QStringList checked = d->checkedChannels();
  if (checked == d->visible) {
    return;
  }
  d->visible = checked;
  d->rebuildChart();
  emit visibleChannelsChanged(d->visible);
}

}  // namespace metrofit
