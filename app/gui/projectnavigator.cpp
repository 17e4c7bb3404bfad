#include "app/gui/projectnavigator.h"

#include <QAction>
#include <QFontMetrics>
#include <QHeaderView>
#include <QMenu>
#include <QRegularExpression>
#include <QSignalBlocker>
#include <QStyle>
#include <QStyledItemDelegate>

#include <algorithm>
#include <functional>

#include "app/gui/datasetactions.h"
#include "core/project/datasets.h"

#include "widgets/document/projectdocument.h"
#include "widgets/document/studyinfo.h"

namespace metrofit {
namespace {

/// Rows as high as their text wrapped to the column (the tree's own size hint does not wrap).
class WrappingDelegate : public QStyledItemDelegate {
 public:
  explicit WrappingDelegate(QTreeWidget* tree) : QStyledItemDelegate(tree), tree_(tree) {}
  QSize sizeHint(const QStyleOptionViewItem& option, const QModelIndex& index) const override {
    QSize size = QStyledItemDelegate::sizeHint(option, index);
    int depth = 0;
    for (QModelIndex p = index.parent(); p.isValid(); p = p.parent()) ++depth;
    QStyleOptionViewItem o = option;
    initStyleOption(&o, index);
    const int indent = (depth + (tree_->rootIsDecorated() ? 1 : 0)) * tree_->indentation();
    const int margin = 2 * (tree_->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, &o, tree_) + 1);
    const int available = std::max(20, tree_->columnWidth(0) - indent - margin);
    const QRect text =
        QFontMetrics(o.font).boundingRect(QRect(0, 0, available, 100000), Qt::TextWordWrap, o.text);
    size.setHeight(std::max(size.height(), text.height() + 4));
    return size;
  }

 private:
  QTreeWidget* tree_;
};

}  // namespace

ProjectNavigator::ProjectNavigator(ProjectDocument* document, QWidget* parent)
    : QTreeWidget(parent), document_(document) {
  setObjectName(QStringLiteral("projectNavigator"));
  setHeaderHidden(true);
  setColumnCount(1);
  setRootIsDecorated(true);
  // Long project names wrap onto more lines within the dock's width (nothing is cut to "…" or
  // scrolled out of sight); a dataset id without spaces that is wider than the dock still makes
  // the column wider and the tree scroll sideways.
  setUniformRowHeights(false);
  setWordWrap(true);
  setItemDelegate(new WrappingDelegate(this));
  setTextElideMode(Qt::ElideNone);
  header()->setStretchLastSection(false);
  header()->setSectionResizeMode(0, QHeaderView::Fixed);
  setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
  connect(this, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* current) {
    if (!current) return;
    emit pageActivated(static_cast<Page>(current->data(0, PageRole).toInt()),
                       current->data(0, DatasetRole).toString());
  });
  connect(document_, &ProjectDocument::changed, this, &ProjectNavigator::refresh);
  // A double click on a dataset shows its data (app/gui/datasetactions.h).
  connect(this, &QTreeWidget::itemDoubleClicked, this, [this](QTreeWidgetItem* item) {
    const QString id = item ? item->data(0, DatasetRole).toString() : QString();
    if (!id.isEmpty()) showDatasetData(document_, id, this);
  });
  // A dataset item's context menu: show data, rename, re-link, remove (through the document's undo
  // stack).
  setContextMenuPolicy(Qt::CustomContextMenu);
  connect(this, &QWidget::customContextMenuRequested, this, [this](const QPoint& pos) {
    const QTreeWidgetItem* item = itemAt(pos);
    const QString id = item ? item->data(0, DatasetRole).toString() : QString();
    if (id.isEmpty()) return;
    QMenu menu(this);
    addDatasetActions(&menu, document_, id, this);
    if (const DatasetRef* dataset = document_->project().dataset(id.toStdString());
        dataset && datasetKindServes(dataset_kind::kCmmReport, dataset->kind)) {
      // From the report to the setup study: a new model, or the features the study's model lacks.
      const bool hasModel = document_->project().firstOfKind(dataset_kind::kSetupModel) != nullptr;
      menu.addSeparator();
      QAction* fromReport = menu.addAction(
          hasModel ? tr("Add report features to setup model…") : tr("Create setup model from report…"), this,
          [this, id] { emit setupModelFromReportRequested(id); });
      fromReport->setObjectName(QStringLiteral("setupModelFromReport"));
    }
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
  // Keep a dataset child selected when it already belongs to the page. Only a dataset: the studies
  // are children of the root (the overview's item) too, and the overview must not stay on one.
  QTreeWidgetItem* current = currentItem();
  if (current && current->parent() == item && !current->data(0, DatasetRole).toString().isEmpty()) return;
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
  fitColumn();
}

void ProjectNavigator::resizeEvent(QResizeEvent* event) {
  QTreeWidget::resizeEvent(event);
  fitColumn();
}

void ProjectNavigator::fitColumn() {
  if (!root_) return;
  static const QRegularExpression space(QStringLiteral("\\s+"));
  // Widest word of an item at its depth: the indentation, the decoration and the text margins.
  int need = 0;
  const std::function<void(QTreeWidgetItem*, int)> visit = [&](QTreeWidgetItem* item, int depth) {
    const QFontMetrics fm(item->font(0));
    int word = 0;
    for (const QString& w : item->text(0).split(space, Qt::SkipEmptyParts))
      word = std::max(word, fm.horizontalAdvance(w));
    need = std::max(need,
                    (depth + (rootIsDecorated() ? 1 : 0)) * indentation() + word + 4 * fm.averageCharWidth());
    for (int i = 0; i < item->childCount(); ++i) visit(item->child(i), depth + 1);
  };
  visit(root_, 0);
  const int width = std::max(viewport()->width(), need);
  if (columnWidth(0) != width) {
    setColumnWidth(0, width);
    doItemsLayout();
  }
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
  fitColumn();
  updateGeometry();
}

}  // namespace metrofit
