#pragma once
// Remove, rename and re-link of a project's datasets from the GUI (the datasets table on the overview
// and the navigator's context menu share them). Each asks what it needs (a confirmation, a new id, the
// moved file), then changes the project through the document's undo stack (ProjectDocument::
// removeDataset / renameDataset / relinkDataset); a refused change (a duplicate id, a file that cannot
// be read as the dataset's kind) is a message box with core's one-line error and changes nothing.
// "Show data" opens the dataset's table (showDatasetData).
#include <QString>

class QMenu;
class QWidget;

namespace metrofit {
class ProjectDocument;

/// Adds "Show data", "Rename…", "Re-link…" and "Remove" for the dataset `id` to `menu`.
void addDatasetActions(QMenu* menu, ProjectDocument* document, const QString& id, QWidget* parent);

/// "Show data": the dataset's table and plot (widgets/data/datasetview.h) in a window of its own,
/// non-modal and beside the main window (the pages are a stack with no room for a second view, and a
/// dock would narrow the pages at 1280x800), one per dataset: asked again, the open window is read
/// again and raised. The file is read off the GUI thread (a log of 100 000 rows takes a second). It
/// follows the document: a re-linked or re-mapped dataset is read again, a
/// removed one closes the window. Returns the window.
QWidget* showDatasetData(ProjectDocument* document, const QString& id, QWidget* parent);

/// Asks for confirmation (naming the study settings that name the dataset), then removes it.
bool removeDatasetAsking(ProjectDocument* document, const QString& id, QWidget* parent);
/// Asks for the new id, then renames the dataset and the study settings that name it.
bool renameDatasetAsking(ProjectDocument* document, const QString& id, QWidget* parent);
/// Asks for the file (a moved file), then points the dataset at it.
bool relinkDatasetAsking(ProjectDocument* document, const QString& id, QWidget* parent);

}  // namespace metrofit
