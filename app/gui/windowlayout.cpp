#include "app/gui/windowlayout.h"

#include <QMainWindow>
#include <QSettings>
#include <QSplitter>
#include <QStringList>

namespace metrofit {

namespace {
const QString kGroup = QStringLiteral("window");
const QString kGeometry = QStringLiteral("geometry");
const QString kState = QStringLiteral("state");
const QString kPage = QStringLiteral("page");
const QString kSplitters = QStringLiteral("splitters");
}  // namespace

WindowLayout WindowLayout::read(QSettings& settings) {
  WindowLayout layout;
  settings.beginGroup(kGroup);
  layout.geometry = settings.value(kGeometry).toByteArray();
  layout.state = settings.value(kState).toByteArray();
  bool ok = false;
  const int page = settings.value(kPage).toInt(&ok);
  layout.page = ok ? page : -1;
  settings.beginGroup(kSplitters);
  // Keys hold '/', which QSettings reads as groups: the whole subtree is walked.
  for (const QString& key : settings.allKeys())
    layout.splitters.insert(key, settings.value(key).toByteArray());
  settings.endGroup();
  settings.endGroup();
  return layout;
}

void WindowLayout::write(QSettings& settings) const {
  settings.beginGroup(kGroup);
  settings.setValue(kGeometry, geometry);
  settings.setValue(kState, state);
  if (page >= 0) {
    settings.setValue(kPage, page);
  } else {
    settings.remove(kPage);
  }
  settings.remove(kSplitters);
  settings.beginGroup(kSplitters);
  for (auto it = splitters.cbegin(); it != splitters.cend(); ++it) settings.setValue(it.key(), it.value());
  settings.endGroup();
  settings.endGroup();
}

QString splitterKey(const QWidget* root, const QSplitter* splitter) {
  if (splitter == nullptr || splitter->objectName().isEmpty()) return {};
  QStringList names;
  for (const QObject* o = splitter; o != nullptr && o != root; o = o->parent())
    // Qt's own inner widgets ("qt_tabwidget_stackedwidget", "qt_scrollarea_viewport") add nothing.
    if (!o->objectName().isEmpty() && !o->objectName().startsWith(QLatin1String("qt_")))
      names.prepend(o->objectName());
  return names.join(QLatin1Char('/'));
}

QHash<QString, QSplitter*> namedSplitters(QWidget* root) {
  QHash<QString, QSplitter*> result;
  if (root == nullptr) return result;
  for (QSplitter* splitter : root->findChildren<QSplitter*>()) {
    const QString key = splitterKey(root, splitter);
    if (!key.isEmpty()) result.insert(key, splitter);
  }
  return result;
}

WindowLayout captureWindowLayout(const QMainWindow& window, QWidget* pagesRoot, int page) {
  WindowLayout layout;
  layout.geometry = window.saveGeometry();
  layout.state = window.saveState(kWindowStateVersion);
  layout.page = page;
  const QHash<QString, QSplitter*> splitters = namedSplitters(pagesRoot);
  for (auto it = splitters.cbegin(); it != splitters.cend(); ++it)
    layout.splitters.insert(it.key(), it.value()->saveState());
  return layout;
}

bool applyWindowLayout(const WindowLayout& layout, QMainWindow& window, QWidget* pagesRoot) {
  bool ok = true;
  if (!layout.geometry.isEmpty()) ok = window.restoreGeometry(layout.geometry) && ok;
  if (!layout.state.isEmpty()) ok = window.restoreState(layout.state, kWindowStateVersion) && ok;
  const QHash<QString, QSplitter*> splitters = namedSplitters(pagesRoot);
  for (auto it = layout.splitters.cbegin(); it != layout.splitters.cend(); ++it) {
    QSplitter* splitter = splitters.value(it.key());
    if (splitter != nullptr) ok = splitter->restoreState(it.value()) && ok;
  }
  return ok;
}

}  // namespace metrofit
