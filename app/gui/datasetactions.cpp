#include "app/gui/datasetactions.h"

#include <QAction>
#include <QCoreApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QFont>
#include <QInputDialog>
#include <QMenu>
#include <QMessageBox>
#include <QVBoxLayout>
#include <exception>
#include <optional>

#include "core/project/nominals.h"
#include "core/project/project.h"
#include "widgets/data/datasetview.h"
#include "widgets/document/projectdocument.h"

namespace metrofit {

namespace {

struct DatasetActionsText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::DatasetActions)
};

/// The window of one dataset's data: reads it again when the document changes the dataset, closes
/// when the dataset is removed.
class DatasetWindow : public QWidget {
 public:
  DatasetWindow(ProjectDocument* document, const QString& id, QWidget* parent)
      : QWidget(parent, Qt::Window), document_(document), id_(id), view_(new DatasetView(this)) {
    setObjectName(QStringLiteral("datasetWindow"));
    setAttribute(Qt::WA_DeleteOnClose);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(view_);
    resize(1000, 640);
    connect(document_, &ProjectDocument::changed, this, [this] {
      const DatasetRef* d = document_->project().dataset(id_.toStdString());
      if (!d) {
        close();
      } else if (!(*d == shown_)) {
        reload();
      }
    });
  }
  const QString& id() const { return id_; }
  DatasetView* view() const { return view_; }
  void reload() {
    const DatasetRef* d = document_->project().dataset(id_.toStdString());
    if (!d) return;
    shown_ = *d;
    setWindowTitle(DatasetActionsText::tr("%1 — data").arg(id_));
    // Measured points whose nominals are another dataset's points: that one resolved too.
    std::optional<DatasetRef> reference;
    try {
      if (const DatasetRef* r = nominalReference(document_->project(), *d))
        reference = document_->resolvedDataset(*r);
    } catch (const std::exception&) {
      // A reference that is not there: the view's read names it.
    }
    view_->showDatasetInBackground(document_->datasetPath(*d), *d, reference);
  }

 private:
  ProjectDocument* document_;
  QString id_;
  DatasetView* view_;
  DatasetRef shown_;
};

}  // namespace

QWidget* showDatasetData(ProjectDocument* document, const QString& id, QWidget* parent) {
  if (!document || !document->project().dataset(id.toStdString())) return nullptr;
  QWidget* owner = parent ? parent->window() : nullptr;
  DatasetWindow* window = nullptr;
  if (owner)
    for (QWidget* child :
         owner->findChildren<QWidget*>(QStringLiteral("datasetWindow"), Qt::FindDirectChildrenOnly))
      if (auto* w = dynamic_cast<DatasetWindow*>(child); w && w->id() == id) window = w;
  if (!window) window = new DatasetWindow(document, id, owner);
  window->reload();
  window->show();
  window->raise();
  window->activateWindow();
  return window;
}

void addDatasetActions(QMenu* menu, ProjectDocument* document, const QString& id, QWidget* parent) {
  QAction* show = menu->addAction(DatasetActionsText::tr("&Show data"), parent,
                                  [document, id, parent] { showDatasetData(document, id, parent); });
  show->setObjectName(QStringLiteral("showDatasetData"));
  QFont bold = show->font();
  bold.setBold(true);  // what a double click does
  show->setFont(bold);
  menu->addSeparator();
  QAction* rename = menu->addAction(DatasetActionsText::tr("&Rename dataset…"), parent,
                                    [document, id, parent] { renameDatasetAsking(document, id, parent); });
  rename->setObjectName(QStringLiteral("renameDataset"));
  QAction* relink = menu->addAction(DatasetActionsText::tr("Re-&link to a moved file…"), parent,
                                    [document, id, parent] { relinkDatasetAsking(document, id, parent); });
  relink->setObjectName(QStringLiteral("relinkDataset"));
  menu->addSeparator();
  QAction* remove = menu->addAction(DatasetActionsText::tr("Re&move dataset"), parent,
                                    [document, id, parent] { removeDatasetAsking(document, id, parent); });
  remove->setObjectName(QStringLiteral("removeDataset"));
}

bool removeDatasetAsking(ProjectDocument* document, const QString& id, QWidget* parent) {
  const QStringList references = document->datasetReferences(id);
  QString text =
      DatasetActionsText::tr("Remove the dataset “%1” from the project? The file itself stays where it is.")
          .arg(id);
  if (!references.isEmpty())
    text +=
        QLatin1Char('\n') + DatasetActionsText::tr("These study settings name it and are removed with it: %1")
                                .arg(references.join(QStringLiteral(", ")));
  if (QMessageBox::question(parent, DatasetActionsText::tr("Remove dataset"), text) != QMessageBox::Yes)
    return false;
  try {
    document->removeDataset(id);
  } catch (const std::exception& e) {
    QMessageBox::critical(parent, DatasetActionsText::tr("Cannot remove the dataset"),
                          QString::fromStdString(e.what()));
    return false;
  }
  return true;
}

bool renameDatasetAsking(ProjectDocument* document, const QString& id, QWidget* parent) {
  bool ok = false;
  const QString newId = QInputDialog::getText(
      parent, DatasetActionsText::tr("Rename dataset"),
      DatasetActionsText::tr("New id of “%1” (study settings that name it follow):").arg(id),
      QLineEdit::Normal, id, &ok);
  if (!ok || newId.trimmed() == id) return false;
  try {
    document->renameDataset(id, newId);
  } catch (const std::exception& e) {
    QMessageBox::critical(parent, DatasetActionsText::tr("Cannot rename the dataset"),
                          QString::fromStdString(e.what()));
    return false;
  }
  return true;
}

bool relinkDatasetAsking(ProjectDocument* document, const QString& id, QWidget* parent) {
  const DatasetRef* dataset = document->project().dataset(id.toStdString());
  if (!dataset) return false;
  const QString current = document->datasetPath(*dataset);
  QString start = QFileInfo(current).path();
  if (!QFileInfo(start).isDir()) start = QFileInfo(document->projectPathForDatasets()).path();
  // A DMIS series: its files are chosen again together (one per workpiece); else one file.
  QStringList files;
  if (dataset->paths.size() > 1) {
    files = QFileDialog::getOpenFileNames(
        parent,
        DatasetActionsText::tr("Re-link the %1 files of the series “%2”").arg(dataset->paths.size()).arg(id),
        start, DatasetActionsText::tr("All files (*)"));
  } else {
    const QString file =
        QFileDialog::getOpenFileName(parent, DatasetActionsText::tr("Re-link dataset “%1”").arg(id), start,
                                     DatasetActionsText::tr("All files (*)"));
    if (!file.isEmpty()) files << file;
  }
  if (files.isEmpty()) return false;
  try {
    document->relinkDataset(id, files);
  } catch (const std::exception& e) {
    QMessageBox::critical(parent, DatasetActionsText::tr("Cannot re-link the dataset"),
                          QString::fromStdString(e.what()));
    return false;
  }
  return true;
}

}  // namespace metrofit
