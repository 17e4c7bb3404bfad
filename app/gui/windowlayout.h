#pragma once
// The main window's layout kept between runs (QSettings group "window"): the window's geometry, the
// docks and toolbars (QMainWindow::saveState), the sizes of every named splitter on the pages and the
// page last shown. Splitters are found by object name below a root widget, so a page only has to name
// its splitters to have them kept; an unnamed splitter keeps its default sizes.
#include <QByteArray>
#include <QHash>
#include <QString>

class QMainWindow;
class QSettings;
class QSplitter;
class QWidget;

namespace metrofit {

/// What is kept of a window between runs.
struct WindowLayout {
  QByteArray geometry;                   ///< QWidget::saveGeometry
  QByteArray state;                      ///< QMainWindow::saveState (docks)
  QHash<QString, QByteArray> splitters;  ///< splitterKey() -> QSplitter::saveState
  int page = -1;                         ///< the page last shown; -1: none stored

  /// Reads the group "window" of `settings`; missing keys stay empty (-1 for the page).
  static WindowLayout read(QSettings& settings);
  /// Writes the group "window" of `settings`, replacing the splitters stored before.
  void write(QSettings& settings) const;
};

/// The key of a named splitter below `root`: the object names of its named ancestors up to (not
/// including) `root` and its own, joined by '/' ("setupPage/setupResultsSplitter"). Empty for an
/// unnamed splitter.
QString splitterKey(const QWidget* root, const QSplitter* splitter);
/// The named splitters below `root` by splitterKey().
QHash<QString, QSplitter*> namedSplitters(QWidget* root);

/// The layout of `window` with the splitters below `pagesRoot` and `page`.
WindowLayout captureWindowLayout(const QMainWindow& window, QWidget* pagesRoot, int page);
/// Restores geometry, docks and splitters (not the page: the window shows it). Stored states that
/// Qt refuses (another version, a screen that is gone) leave the defaults; returns false then.
bool applyWindowLayout(const WindowLayout& layout, QMainWindow& window, QWidget* pagesRoot);

/// The version passed to QMainWindow::saveState / restoreState; raise it when the docks change.
inline constexpr int kWindowStateVersion = 1;

}  // namespace metrofit
