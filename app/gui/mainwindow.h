#pragma once
// The main window: menus, actions and wiring between the project document, the navigator and the
// pages. It holds no algorithm code; pages live in their own classes.
#include <QMainWindow>
#include <array>

#include "app/gui/pageid.h"

class QAction;
class QDockWidget;
class QMenu;
class QStackedWidget;

namespace metrofit {
class FileChangedBar;
class MatchingPage;
class OverviewPage;
class ProjectDocument;
class ProjectNavigator;
class ReportExporter;
class ThermalPage;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  ProjectDocument* document() const { return document_; }
  ProjectNavigator* navigator() const { return navigator_; }
  OverviewPage* overviewPage() const { return overview_; }
  ThermalPage* thermalPage() const { return thermal_; }
  MatchingPage* matchingPage() const { return matching_; }
  FileChangedBar* fileChangedBar() const { return fileChangedBar_; }
  QWidget* page(Page page) const;
  Page currentPage() const;

  /// Opens a project without asking about unsaved changes. On failure shows the one-line error in
  /// a message box, or stores it in *error when given (then no box), and keeps the open project.
  bool openProject(const QString& path, QString* error = nullptr);
  /// Shows a page and selects it in the navigator.
  void showPage(Page page);

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  void createActions();
  void createMenus();
  void updateTitle();
  void updateRecentMenu();
  void showError(const QString& title, const QString& message);
  /// Asks to save unsaved changes; false when the user cancelled (or saving failed).
  bool maybeSave();

  void newProject();
  void open();
  void openDemo();
  bool save();
  bool saveAs();
  void exportReport();
  void preferences();
  void about();
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
  QMenu* recentMenu_ = nullptr;
  QAction* exportAction_ = nullptr;
  std::array<QAction*, kPageCount> pageActions_{};
};

}  // namespace metrofit
