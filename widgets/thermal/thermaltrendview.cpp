// ThermalTrendView: the trend chart (thermalcharts.h) beside its legend, a checkable channel tree:
// one branch per group (temperatures (°C), displacements (µm), speed (rpm), ...) whose check box
// shows or hides the whole group, one leaf per channel with its colour and line style.
#include "widgets/thermal/thermaltrendview.h"

#include <QChart>
#include <QChartView>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QIcon>
#include <QLabel>
#include <QPainter>
#include <QPixmap>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>

#include "core/thermal/thermal_log.h"
#include "widgets/common/chartexport.h"
#include "widgets/common/chartnavigation.h"
#include "widgets/thermal/thermalcharts.h"

namespace metrofit {

struct ThermalTrendView::Impl {
  ThermalLog log;
  QChartView* chartView = nullptr;
  QTreeWidget* channelList = nullptr;
  QStringList visible;

  /// Replaces the chart by a new one of the visible channels (cheap: series are decimated).
  void rebuildChart() {
    ThermalChartOptions options;
    options.channelLegend = false;  // the channel list is the legend
    QChart* old = chartView->chart();
    chartView->setChart(makeThermalTrendChart(log, visible, options));
    delete old;
  }

  /// The channel leaves, in tree order.
  QList<QTreeWidgetItem*> leaves() const {
    QList<QTreeWidgetItem*> items;
    for (int g = 0; g < channelList->topLevelItemCount(); ++g) {
      QTreeWidgetItem* group = channelList->topLevelItem(g);
      for (int i = 0; i < group->childCount(); ++i) items << group->child(i);
    }
    return items;
  }

  /// Visible channels in the log's order, from the check boxes.
  QStringList checkedChannels() const {
    QStringList names;
    for (const ThermalChannel& c : log.channels) {
      const QString name = QString::fromStdString(c.name);
      for (const QTreeWidgetItem* item : leaves()) {
        if (item->data(0, Qt::UserRole).toString() == name && item->checkState(0) == Qt::Checked) {
          names << name;
        }
      }
    }
    return names;
  }

  void setChecks(const QStringList& names) {
    const QSignalBlocker blocker(channelList);
    for (QTreeWidgetItem* item : leaves()) {
      item->setCheckState(
          0, names.contains(item->data(0, Qt::UserRole).toString()) ? Qt::Checked : Qt::Unchecked);
    }
    updateGroupChecks();
  }

  /// A group's box: ticked when all its channels are shown, partly when some are.
  void updateGroupChecks() {
    const QSignalBlocker blocker(channelList);
    for (int g = 0; g < channelList->topLevelItemCount(); ++g) {
      QTreeWidgetItem* group = channelList->topLevelItem(g);
      int checked = 0;
      for (int i = 0; i < group->childCount(); ++i)
        checked += group->child(i)->checkState(0) == Qt::Checked ? 1 : 0;
      group->setCheckState(0, checked == 0                     ? Qt::Unchecked
                              : checked == group->childCount() ? Qt::Checked
                                                               : Qt::PartiallyChecked);
    }
  }

  /// Wide enough for every entry: the legend is never elided.
  void fitWidth() {
    channelList->resizeColumnToContents(0);
    const int width = channelList->columnWidth(0) + 2 * channelList->frameWidth() + 24;
    channelList->setMinimumWidth(std::max(120, width));
    channelList->setMaximumWidth(std::max(120, width));
  }
};

namespace {

/// A short line of the channel's colour and style, as it is drawn in the chart.
QIcon swatch(const QColor& color, Qt::PenStyle style) {
  QPixmap pixmap(24, 14);
  pixmap.fill(Qt::transparent);
  QPainter painter(&pixmap);
  QPen pen(color, 3.0);
  pen.setStyle(style);
  pen.setCapStyle(Qt::FlatCap);
  painter.setPen(pen);
  painter.drawLine(QPointF(0.0, 7.0), QPointF(24.0, 7.0));
  return QIcon(pixmap);
}

}  // namespace

ThermalTrendView::ThermalTrendView(QWidget* parent) : QWidget(parent), d(std::make_unique<Impl>()) {
  d->chartView = new QChartView(this);
  enableChartExport(d->chartView, QStringLiteral("thermal-trend"));
  enableChartNavigation(d->chartView);
  d->chartView->setObjectName(QStringLiteral("thermalTrendChart"));
  d->chartView->setRenderHint(QPainter::Antialiasing);
  d->chartView->setMinimumSize(360, 240);
  d->chartView->chart()->setAnimationOptions(QChart::NoAnimation);

  d->channelList = new QTreeWidget(this);
  d->channelList->setObjectName(QStringLiteral("thermalTrendChannels"));
  d->channelList->setToolTip(tr("Channels shown in the chart: tick a group to show all of it"));
  d->channelList->setHeaderHidden(true);
  d->channelList->setColumnCount(1);
  d->channelList->setRootIsDecorated(true);
  d->channelList->setIconSize(QSize(24, 14));
  d->channelList->setTextElideMode(Qt::ElideNone);
  d->channelList->header()->setStretchLastSection(false);
  d->channelList->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
  d->channelList->setMinimumWidth(120);

  auto* side = new QVBoxLayout;
  side->setContentsMargins(0, 0, 0, 0);
  side->addWidget(new QLabel(tr("Channels"), this));
  side->addWidget(d->channelList, 1);

  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(d->chartView, 1);
  layout->addLayout(side);

  connect(d->channelList, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item) {
    if (item->childCount() > 0) {
      // A group's box: all of its channels on or off (a partly ticked group goes to all on).
      const Qt::CheckState state = item->checkState(0) == Qt::Unchecked ? Qt::Unchecked : Qt::Checked;
      const QSignalBlocker blocker(d->channelList);
      item->setCheckState(0, state);
      for (int i = 0; i < item->childCount(); ++i) item->child(i)->setCheckState(0, state);
    }
    d->updateGroupChecks();
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
    for (const ThermalChannelGroup& g : thermalChannelGroups(log)) {
      auto* group = new QTreeWidgetItem(d->channelList, QStringList{g.title});
      group->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
      group->setCheckState(0, Qt::Unchecked);
      QFont bold = group->font(0);
      bold.setBold(true);
      group->setFont(0, bold);
      group->setToolTip(0, tr("Show or hide all %1").arg(g.title));
      for (int i : g.channels) {
        const ThermalChannel& c = log.channels[i];
        const QString name = QString::fromStdString(c.name);
        auto* item = new QTreeWidgetItem(group, QStringList{name});
        item->setIcon(0, swatch(thermalChannelColor(log, i), thermalChannelPenStyle(log, i)));
        item->setData(0, Qt::UserRole, name);
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable | Qt::ItemIsSelectable);
        item->setCheckState(0, Qt::Unchecked);
        item->setToolTip(0, channelLegendName(c));
      }
    }
    d->channelList->expandAll();
  }
  d->visible = defaultThermalChannels(log);
  d->setChecks(d->visible);
  d->fitWidth();
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
