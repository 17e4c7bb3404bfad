#include "app/gui/projectnavigator.h"

#include <QHeaderView>
#include <QMenu>
#include <QSignalBlocker>

#include "app/gui/datasetactions.h"

#include "widgets/document/projectdocument.h"
#include "widgets/document/studyinfo.h"

namespace metrofit {

ProjectNavigator::ProjectNavigator(ProjectDocument* document, QWidget* parent)
    : QTreeWidget(parent), document_(document) {
  setObjectName(QStringLiteral("projectNavigator"));
  setHeaderHidden(true);
  setColumnCount(1);
  setRootIsDecorated(true);
  setUniformRowHeights(true);
  // Long project names and dataset ids: the column is as wide as its longest item and scrolls;
  // nothing is cut to "…".
  setTextElideMode(Qt::ElideNone);
  header()->setStretchLastSection(false);
  header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
  setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
  connect(this, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* current) {
    if (!current) return;
    emit pageActivated(static_cast<Page>(current->data(0, PageRole).toInt()),
                       current->data(0, DatasetRole).toString());
  });
  connect(document_, &ProjectDocument::changed, this, &ProjectNavigator::refresh);
  // A dataset item's context menu: rename, re-link, remove (through the document's undo stack).
  setContextMenuPolicy(Qt::CustomContextMenu);
  connect(this, &QWidget::customContextMenuRequested, this, [this](const QPoint& pos) {
    const QTreeWidgetItem* item = itemAt(pos);
    const QString id = item ? item->data(0, DatasetRole).toString() : QString();
    if (id.isEmpty()) return;
    QMenu menu(this);
    addDatasetActions(&menu, document_, id, this);
    menu.exec(viewport()->mapToGlobal(pos));
  });
  rebuild();
}

QTreeWidgetItem* ProjectNavigator::itemForPage(Page page) const {
  if (page == Page::Overview) return root_;
  for (int i = 0; i < root_->childCount(); ++i) {
    QTreeWidgetItem* item = root_->child(i);
    if (item->data(0, PageRole).toInt() == static_cast<int>(page)) return item;
  }
  return root_;
}

void ProjectNavigator::selectPage(Page page) {
  QTreeWidgetItem* item = itemForPage(page);
  // Keep a dataset child selected when it already belongs to the page.
  QTreeWidgetItem* current = currentItem();
  if (current && current->parent() == item) return;
  const QSignalBlocker blocker(this);
  setCurrentItem(item);
}

void ProjectNavigator::refresh() {
  if (shown_ != document_->project().datasets) {
    rebuild();
    return;
  }
  root_->setText(0, document_->displayName());
  root_->setToolTip(0, tr("%1: project overview (Ctrl+1)").arg(document_->displayName()));
}

void ProjectNavigator::rebuild() {
  const Page page =
      currentItem() ? static_cast<Page>(currentItem()->data(0, PageRole).toInt()) : Page::Overview;
  const QSignalBlocker blocker(this);
  clear();
  shown_ = document_->project().datasets;
  root_ = new QTreeWidgetItem(this, {document_->displayName()});
  root_->setData(0, PageRole, static_cast<int>(Page::Overview));
  root_->setToolTip(0, tr("%1: project overview (Ctrl+1)").arg(document_->displayName()));
  QFont bold = root_->font(0);
  bold.setBold(true);
  root_->setFont(0, bold);
  int shortcut = 2;
  for (const QString& study : studyKeys()) {
    const Page studyPage = pageForStudy(study);
    auto* item = new QTreeWidgetItem(root_, {studyTitle(study)});
    item->setData(0, PageRole, static_cast<int>(studyPage));
    item->setToolTip(0, tr("%1 (Ctrl+%2)").arg(studyTitle(study)).arg(shortcut++));
    const QStringList kinds = studyDatasetKinds(study);
    for (const DatasetRef& d : shown_) {
      if (!kinds.contains(QString::fromStdString(d.kind))) continue;
      auto* child = new QTreeWidgetItem(item, {QString::fromStdString(d.id)});
      child->setData(0, PageRole, static_cast<int>(studyPage));
      child->setData(0, DatasetRole, QString::fromStdString(d.id));
      const QString description = QString::fromStdString(d.description);
      child->setToolTip(0, description.isEmpty() ? QString::fromStdString(d.path) : description);
    }
  }
  expandAll();
  setCurrentItem(itemForPage(page));
  updateGeometry();
}

}  // namespace metrofit
