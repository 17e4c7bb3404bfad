#pragma once
// "Run the study" (F5) and "Cancel the run" (Esc) at the end of the main window's View menu (the one
// with the page actions, Ctrl+1 ... Ctrl+6) act on the page shown.
// Each page keeps its own controls and keys (Ctrl+R runs, Esc cancels); these actions press the page's
// visible, enabled control with that key, so the keys are the same on every page and visible in a
// menu. Where a page already uses F5 or Esc itself, the menu action leaves the key to it (no
// ambiguous shortcut). With nothing to run or cancel, the status bar says so.
class QAction;
class QMainWindow;
class QStackedWidget;

namespace metrofit {

struct StudyActions {
  QAction* run = nullptr;
  QAction* cancel = nullptr;
};

/// Adds the actions to the menu holding the page actions (objectName "showPage1"; a new "Run" menu
/// when there is none) and keeps their keys in step with the page shown.
StudyActions installStudyActions(QMainWindow* window, QStackedWidget* pages);

}  // namespace metrofit
