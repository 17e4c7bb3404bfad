#include "widgets/common/tablecopy.h"

#include <QAbstractItemModel>
#include <QAction>
#include <QClipboard>
#include <QCoreApplication>
#include <QGuiApplication>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QKeySequence>
#include <QTableView>
#include <algorithm>
#include <set>
#include <vector>

namespace metrofit {

namespace {

struct TableCopyText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::TableCopy)
};

const char* const kCopyActionName = "tableCopy";

/// A cell as one field of a tab-separated line (tabs and line breaks become spaces).
QString field(const QVariant& value) {
  QString text = value.toString();
  text.replace(QLatin1Char('\t'), QLatin1Char(' '));
  text.replace(QLatin1Char('\n'), QLatin1Char(' '));
  text.replace(QLatin1Char('\r'), QLatin1Char(' '));
  return text;
}

}  // namespace

QString tableSelectionText(const QTableView* table) {
  const QAbstractItemModel* model = table ? table->model() : nullptr;
  if (model == nullptr) return {};
  const QModelIndexList selected =
      table->selectionModel() ? table->selectionModel()->selectedIndexes() : QModelIndexList();
  std::set<int> rows;
  std::set<int> columns;
  std::set<std::pair<int, int>> cells;
  for (const QModelIndex& index : selected) {
    if (table->isRowHidden(index.row()) || table->isColumnHidden(index.column())) continue;
    rows.insert(index.row());
    columns.insert(index.column());
    cells.insert({index.row(), index.column()});
  }
  const bool all = cells.empty();
  if (all) {
    for (int r = 0; r < model->rowCount(); ++r)
      if (!table->isRowHidden(r)) rows.insert(r);
    for (int c = 0; c < model->columnCount(); ++c)
      if (!table->isColumnHidden(c)) columns.insert(c);
  }
  // Columns in the order shown (the user may have moved them), rows likewise.
  std::vector<int> cols(columns.begin(), columns.end());
  std::sort(cols.begin(), cols.end(), [table](int a, int b) {
    return table->horizontalHeader()->visualIndex(a) < table->horizontalHeader()->visualIndex(b);
  });
  std::vector<int> rowOrder(rows.begin(), rows.end());
  std::sort(rowOrder.begin(), rowOrder.end(), [table](int a, int b) {
    return table->verticalHeader()->visualIndex(a) < table->verticalHeader()->visualIndex(b);
  });

  QStringList lines;
  QStringList header;
  for (int c : cols) header << field(model->headerData(c, Qt::Horizontal, Qt::DisplayRole));
  lines << header.join(QLatin1Char('\t'));
  for (int r : rowOrder) {
    QStringList line;
    for (int c : cols)
      line << ((all || cells.count({r, c}) != 0) ? field(model->index(r, c).data(Qt::DisplayRole))
                                                 : QString());
    lines << line.join(QLatin1Char('\t'));
  }
  return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

void copyTableSelection(const QTableView* table) {
  QGuiApplication::clipboard()->setText(tableSelectionText(table));
}

void enableTableCopy(QTableView* table) {
  if (table == nullptr || table->findChild<QAction*>(QString::fromLatin1(kCopyActionName))) return;
  auto* copy = new QAction(TableCopyText::tr("&Copy"), table);
  copy->setObjectName(QString::fromLatin1(kCopyActionName));
  copy->setShortcut(QKeySequence::Copy);
  copy->setShortcutContext(Qt::WidgetShortcut);
  copy->setToolTip(TableCopyText::tr("Copy the selected cells with their column headers, tab-separated"));
  QObject::connect(copy, &QAction::triggered, table, [table] { copyTableSelection(table); });
  table->addAction(copy);
  auto* selectAll = new QAction(TableCopyText::tr("Select &all"), table);
  selectAll->setObjectName(QStringLiteral("tableSelectAll"));
  selectAll->setShortcut(QKeySequence::SelectAll);
  selectAll->setShortcutContext(Qt::WidgetShortcut);
  QObject::connect(selectAll, &QAction::triggered, table, &QTableView::selectAll);
  table->addAction(selectAll);
  table->setContextMenuPolicy(Qt::ActionsContextMenu);
}

}  // namespace metrofit
