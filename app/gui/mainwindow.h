#pragma once
// The main window: menus, actions and wiring between the project document, the navigator and the
// pages. It holds no algorithm code; pages live in their own classes.
#include <QMainWindow>
#include <QStringList>
#include <array>
#include <functional>

#include "app/gui/pageid.h"

class QAction;
class QDockWidget;
class QMenu;
class QStackedWidget;
class QUndoGroup;

namespace metrofit {
class Autosave;
class FileChangedBar;
class ManualWindow;
class MatchingPage;
class OverviewPage;
class ProjectDocument;
class ProjectNavigator;
class ReportExporter;
class ThermalPage;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  /// The answer to "save the unsaved changes?" (close, New, Open).
  enum class UnsavedChoice { Save, Discard, Cancel };
  using UnsavedDecider = std::function<UnsavedChoice()>;
  /// Shows the manual's first page (app/gui/manual.h); false when it cannot.
  using ManualOpener = std::function<bool(const QString& path)>;

  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  ProjectDocument* document() const { return document_; }
  ProjectNavigator* navigator() const { return navigator_; }
  OverviewPage* overviewPage() const { return overview_; }
  ThermalPage* thermalPage() const { return thermal_; }
  MatchingPage* matchingPage() const { return matching_; }
  FileChangedBar* fileChangedBar() const { return fileChangedBar_; }
  Autosave* autosave() const { return autosave_; }
  /// Replaces the unsaved-changes question (default: a message box); tests inject the answer.
  void setUnsavedChangesDecider(UnsavedDecider decider) { unsavedDecider_ = std::move(decider); }
  /// Replaces the manual window of Help › Manual (F1); tests record the page instead.
  void setManualOpener(ManualOpener opener) { manualOpener_ = std::move(opener); }
  /// The question asked before unsaved changes are lost: names the project's edits, the setup model's
  /// unsaved edits and results of a run that are not saved yet (ProjectDocument::hasUnsavedResults).
  QString unsavedChangesText() const;
  QWidget* page(Page page) const;
  Page currentPage() const;

  /// Opens a project without asking about unsaved changes; offers to recover its autosaved copy when
  /// that is newer (Autosave::open). On failure shows the one-line error in
  /// a message box, or stores it in *error when given (then no box), and keeps the open project.
  bool openProject(const QString& path, QString* error = nullptr);
  /// At a start without a project: offers to recover an untitled project left by a crash.
  void recoverUntitled();
  /// Shows a page and selects it in the navigator.
  void showPage(Page page);
  /// Restores the layout kept by saveLayout() (geometry, docks, splitters, last page) from the
  /// settings; main() calls it before show(). A window that is never restored starts with the default
  /// layout on the overview (as the tests expect).
  void restoreLayout();
  /// Keeps the layout in the settings (WindowLayout); done by an accepted close.
  void saveLayout() const;
  /// File › Import data…: opens the import dialog for each file (a file dialog first when `files` is
  /// empty) and adds each accepted dataset through the undo stack, then shows the study page that
  /// reads its kind with the dataset selected. Dropped files come here too.
  void importFiles(const QStringList& files);

 protected:
  void closeEvent(QCloseEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  void createActions();
  void createMenus();
  void updateTitle();
  /// The Edit menu's stack: the setup model's while the setup page shows its graph, else the project's.
  void updateActiveUndoStack();
  /// Saves the setup model when it has unsaved edits (Save writes both documents); false on failure.
  bool saveSetupModel();
  void updateRecentMenu();
  void showError(const QString& title, const QString& message);
  /// Asks to save unsaved changes; false when the user cancelled (or saving failed).
  bool maybeSave();
  UnsavedChoice askUnsavedChanges();

  void newProject();
  void open();
  void openDemo();
  bool save();
  bool saveAs();
  void exportReport();
  void preferences();
  void about();
  /// Help › Manual (F1): the installed documentation, in a build folder the source tree's.
  void showManual();
  void reloadFromDisk();

  ProjectDocument* document_;
  ProjectNavigator* navigator_;
  QDockWidget* navigatorDock_;
  QStackedWidget* pages_;
  OverviewPage* overview_;
  ThermalPage* thermal_;
  MatchingPage* matching_;
  FileChangedBar* fileChangedBar_;
  ReportExporter* exporter_;
  Autosave* autosave_;
  UnsavedDecider unsavedDecider_;
  ManualOpener manualOpener_;
  ManualWindow* manualWindow_ = nullptr;
  QMenu* recentMenu_ = nullptr;
  QAction* exportAction_ = nullptr;
  /// One undo stack per document (the project, the setup model file); Edit › Undo / Redo act on the
  /// active one.
  QUndoGroup* undoGroup_ = nullptr;
  std::array<QAction*, kPageCount> pageActions_{};
};

}  // namespace metrofit
