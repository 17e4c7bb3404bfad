#include "app/gui/studyactions.h"

#include <QAbstractButton>
#include <QAction>
#include <QCoreApplication>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QStackedWidget>
#include <QStatusBar>

namespace metrofit {

namespace {

struct StudyActionsText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::StudyActions)
};

constexpr int kStatusTimeoutMs = 5000;

/// A button or action on `page` with shortcut `key`; with `usable`, only one that is enabled and shown.
QObject* controlWithKey(QWidget* page, const QKeySequence& key, bool usable) {
  if (page == nullptr) return nullptr;
  for (QAbstractButton* b : page->findChildren<QAbstractButton*>())
    if (b->shortcut() == key && (!usable || (b->isVisible() && b->isEnabled()))) return b;
  for (QAction* a : page->findChildren<QAction*>()) {
    if (!a->shortcuts().contains(key)) continue;
    if (!usable) return a;
    if (!a->isEnabled()) continue;
    for (QObject* o : a->associatedObjects())
      if (auto* w = qobject_cast<QWidget*>(o); w && w->isVisible()) return a;
  }
  return nullptr;
}

void activate(QObject* control) {
  if (auto* b = qobject_cast<QAbstractButton*>(control)) b->click();
  if (auto* a = qobject_cast<QAction*>(control)) a->trigger();
}

}  // namespace

StudyActions installStudyActions(QMainWindow* window, QStackedWidget* pages) {
  const QKeySequence runKey(Qt::Key_F5), pageRunKey(Qt::CTRL | Qt::Key_R), cancelKey(Qt::Key_Escape);
  QMenu* menu = nullptr;
  for (QAction* top : window->menuBar()->actions()) {
    if (top->menu() == nullptr) continue;
    for (QAction* a : top->menu()->actions())
      if (a->objectName() == QLatin1String("showPage1")) menu = top->menu();
  }
  if (menu == nullptr) menu = window->menuBar()->addMenu(StudyActionsText::tr("&Run"));
  menu->addSeparator();

  StudyActions actions;
  actions.run = menu->addAction(StudyActionsText::tr("&Run the study"));
  actions.run->setObjectName(QStringLiteral("runStudy"));
  actions.run->setStatusTip(
      StudyActionsText::tr("Runs the method of the page shown (its Run button, Ctrl+R)"));
  actions.cancel = menu->addAction(StudyActionsText::tr("&Cancel the run"));
  actions.cancel->setObjectName(QStringLiteral("cancelRun"));
  actions.cancel->setStatusTip(StudyActionsText::tr("Stops the running method of the page shown"));

  QObject::connect(actions.run, &QAction::triggered, window, [window, pages, runKey, pageRunKey] {
    QWidget* page = pages->currentWidget();
    QObject* control = controlWithKey(page, pageRunKey, true);
    if (control == nullptr) control = controlWithKey(page, runKey, true);
    if (control != nullptr)
      activate(control);
    else
      window->statusBar()->showMessage(StudyActionsText::tr("Nothing to run on this page"), kStatusTimeoutMs);
  });
  QObject::connect(actions.cancel, &QAction::triggered, window, [window, pages, cancelKey] {
    if (QObject* control = controlWithKey(pages->currentWidget(), cancelKey, true))
      activate(control);
    else
      window->statusBar()->showMessage(StudyActionsText::tr("Nothing is running"), kStatusTimeoutMs);
  });

  // A page with its own F5 / Esc keeps it; elsewhere the menu actions take the key.
  const auto updateKeys = [pages, actions, runKey, cancelKey] {
    QWidget* page = pages->currentWidget();
    actions.run->setShortcut(controlWithKey(page, runKey, false) ? QKeySequence() : runKey);
    actions.cancel->setShortcut(controlWithKey(page, cancelKey, false) ? QKeySequence() : cancelKey);
  };
  QObject::connect(pages, &QStackedWidget::currentChanged, window, updateKeys);
  updateKeys();
  return actions;
}

}  // namespace metrofit
