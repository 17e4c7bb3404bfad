#include "app/gui/datasettable.h"

#include <QFileInfo>
#include <QHeaderView>
#include <QMenu>

#include "app/gui/datasetactions.h"

#include "core/project/project.h"
#include "widgets/common/tablecopy.h"
#include "widgets/document/projectdocument.h"
#include "widgets/document/studyinfo.h"

namespace metrofit {

namespace {
enum Column { ColId, ColKind, ColPath, ColLicence, ColumnCount };
}

DatasetTable::DatasetTable(QWidget* parent) : QTableWidget(parent) {
  enableTableCopy(this);
  setColumnCount(ColumnCount);
  setHorizontalHeaderLabels({tr("Id"), tr("Kind"), tr("Path"), tr("Licence")});
  setEditTriggers(QAbstractItemView::NoEditTriggers);
  setSelectionBehavior(QAbstractItemView::SelectRows);
  setAlternatingRowColors(true);
  verticalHeader()->hide();
  horizontalHeader()->setSectionResizeMode(ColId, QHeaderView::ResizeToContents);
  horizontalHeader()->setSectionResizeMode(ColKind, QHeaderView::ResizeToContents);
  horizontalHeader()->setSectionResizeMode(ColPath, QHeaderView::Stretch);
  horizontalHeader()->setSectionResizeMode(ColLicence, QHeaderView::Stretch);
}

void DatasetTable::enableEditing(ProjectDocument* document) {
  connect(this, &QTableWidget::cellDoubleClicked, this, [this, document](int row) {
    const QString id = datasetId(row);
    if (!id.isEmpty()) showDatasetData(document, id, this);
  });
  setContextMenuPolicy(Qt::CustomContextMenu);
  connect(this, &QWidget::customContextMenuRequested, this, [this, document](const QPoint& pos) {
    const QString id = datasetId(indexAt(pos).row());
    if (id.isEmpty()) return;
    QMenu menu(this);
    addDatasetActions(&menu, document, id, this);
    menu.exec(viewport()->mapToGlobal(pos));
  });
}

QString DatasetTable::datasetId(int row) const {
  const QTableWidgetItem* id = row >= 0 ? item(row, ColId) : nullptr;
  return id ? id->text() : QString();
}

void DatasetTable::setDatasets(const ProjectDocument& document, const std::vector<DatasetRef>& datasets) {
  setRowCount(static_cast<int>(datasets.size()));
  int row = 0;
  for (const DatasetRef& d : datasets) {
    const QString description = QString::fromStdString(d.description);
    auto cell = [&](int column, const QString& text) {
      auto* item = new QTableWidgetItem(text);
      item->setToolTip(description.isEmpty() ? text : description);
      setItem(row, column, item);
      return item;
    };
    cell(ColId, QString::fromStdString(d.id));
    cell(ColKind, datasetKindTitle(QString::fromStdString(d.kind)));
    QTableWidgetItem* path = cell(ColPath, QString::fromStdString(d.path));
    const QString resolved = document.datasetPath(d);
    if (!QFileInfo::exists(resolved)) {
      path->setForeground(Qt::red);
      path->setToolTip(tr("File not found: %1").arg(resolved));
    }
    cell(ColLicence, d.licence.empty() ? QStringLiteral("—") : QString::fromStdString(d.licence));
    ++row;
  }
}

}  // namespace metrofit
