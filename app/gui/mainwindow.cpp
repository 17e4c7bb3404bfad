#include "app/gui/mainwindow.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QSettings>
#include <QStackedWidget>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>
#include <QUndoGroup>
#include <QUndoStack>
#include <QUrl>
#include <QVBoxLayout>
#include <exception>

#include <Eigen/Core>

#include "app/gui/autosave.h"
#include "app/gui/diagnosispage.h"
#include "app/gui/filechangedbar.h"
#include "app/gui/kinematicspage.h"
#include "app/gui/manual.h"
#include "app/gui/matchingpage.h"
#include "app/gui/overviewpage.h"
#include "app/gui/preferencesdialog.h"
#include "app/gui/projectnavigator.h"
#include "app/gui/recentfiles.h"
#include "app/gui/reportexporter.h"
#include "app/gui/setuppage.h"
#include "app/gui/studyactions.h"
#include "app/gui/thermalpage.h"
#include "app/gui/windowlayout.h"
#include "core/setup/report.h"
#include "metrofit/version.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"
#include "widgets/document/studyinfo.h"
#include "widgets/importer/importdialog.h"
#include "widgets/setup/setupmodeleditor.h"

namespace metrofit {

namespace {
constexpr int kStatusTimeoutMs = 5000;
const char* const kProjectFilter =
    QT_TRANSLATE_NOOP("metrofit::MainWindow", "Metrofit projects (*.metrofit)");
}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      document_(new ProjectDocument(this)),
      navigator_(new ProjectNavigator(document_, this)),
      navigatorDock_(new QDockWidget(tr("Project"), this)),
      pages_(new QStackedWidget(this)),
      overview_(new OverviewPage(document_, pages_)),
      thermal_(new ThermalPage(document_, pages_)),
      matching_(new MatchingPage(document_, pages_)),
      fileChangedBar_(new FileChangedBar(this)),
      exporter_(new ReportExporter(this)),
      autosave_(new Autosave(document_, this)) {
  setObjectName(QStringLiteral("mainWindow"));
  // Pages in the order of metrofit::Page.
  pages_->addWidget(overview_);
  pages_->addWidget(new SetupPage(document_, pages_));
  pages_->addWidget(matching_);
  pages_->addWidget(new KinematicsPage(document_, pages_));
  pages_->addWidget(thermal_);
  pages_->addWidget(new DiagnosisPage(document_, pages_));

  auto* central = new QWidget(this);
  auto* layout = new QVBoxLayout(central);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  layout->addWidget(fileChangedBar_);
  layout->addWidget(pages_, 1);
  setCentralWidget(central);

  navigatorDock_->setObjectName(QStringLiteral("navigatorDock"));
  navigatorDock_->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetClosable);
  navigatorDock_->setWidget(navigator_);
  navigator_->setMinimumWidth(220);
  addDockWidget(Qt::LeftDockWidgetArea, navigatorDock_);

  // Before the menus: Edit › Undo / Redo are the group's actions.
  undoGroup_ = new QUndoGroup(this);
  undoGroup_->addStack(document_->undoStack());
  auto* setup = qobject_cast<SetupPage*>(page(Page::Setup));
  undoGroup_->addStack(setup->modelEditor()->undoStack());
  connect(pages_, &QStackedWidget::currentChanged, this, &MainWindow::updateActiveUndoStack);
  connect(setup->tabs(), &QTabWidget::currentChanged, this, &MainWindow::updateActiveUndoStack);
  connect(setup->modelEditor()->undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
  updateActiveUndoStack();

  createActions();
  createMenus();
  connect(overview_, &OverviewPage::openDemoRequested, this, &MainWindow::openDemo);
  connect(overview_, &OverviewPage::importRequested, this, [this] { importFiles({}); });
  setAcceptDrops(true);
  installStudyActions(this, pages_);  // Run menu: F5 / Esc on every page

  connect(navigator_, &ProjectNavigator::pageActivated, this, [this](Page page, const QString& dataset) {
    if (page == Page::Thermal && !dataset.isEmpty()) thermal_->selectDataset(dataset);
    if (page == Page::Matching && !dataset.isEmpty()) matching_->selectDataset(dataset);
    showPage(page);
  });
  connect(navigator_, &ProjectNavigator::setupModelFromReportRequested, this, [this](const QString& dataset) {
    showPage(Page::Setup);
    if (auto* setupPage = qobject_cast<SetupPage*>(page(Page::Setup))) setupPage->openReportDialog(dataset);
  });
  connect(document_, &ProjectDocument::changed, this, &MainWindow::updateTitle);
  connect(document_, &ProjectDocument::modifiedChanged, this, &MainWindow::updateTitle);
  connect(document_, &ProjectDocument::unsavedResultsChanged, this, &MainWindow::updateTitle);
  connect(document_, &ProjectDocument::fileChangedOnDisk, this,
          [this](const QString& file) { fileChangedBar_->showFor(file, document_->isModified()); });
  connect(fileChangedBar_, &FileChangedBar::reloadRequested, this, &MainWindow::reloadFromDisk);
  connect(autosave_, &Autosave::failed, this, [this](const QString& message) {
    statusBar()->showMessage(tr("Autosave failed: %1").arg(message), kStatusTimeoutMs);
  });
  connect(exporter_, &ReportExporter::finished, this,
          [this](ReportExporter::Outcome outcome, const QString& message) {
            exportAction_->setEnabled(true);
            if (outcome == ReportExporter::Outcome::Failed) {
              statusBar()->clearMessage();
              showError(tr("Cannot export the report"), message);
            } else {
              statusBar()->showMessage(message, kStatusTimeoutMs);
            }
          });

  resize(1280, 800);
  updateTitle();
  showPage(Page::Overview);
  statusBar()->showMessage(tr("Ready"), kStatusTimeoutMs);
}

MainWindow::~MainWindow() = default;

QWidget* MainWindow::page(Page page) const {
  return pages_->widget(static_cast<int>(page));
}

Page MainWindow::currentPage() const {
  return static_cast<Page>(pages_->currentIndex());
}

void MainWindow::createActions() {
  auto* group = new QActionGroup(this);
  for (int i = 0; i < kPageCount; ++i) {
    const QString study = studyForPage(static_cast<Page>(i));
    // '&' in a study title is text, not a mnemonic ("Kinematics & SPC").
    QAction* action =
        group->addAction(study.isEmpty() ? tr("&Overview")
                                         : studyTitle(study).replace(QLatin1Char('&'), QStringLiteral("&&")));
    action->setCheckable(true);
    action->setShortcut(QKeySequence(Qt::CTRL | static_cast<Qt::Key>(Qt::Key_1 + i)));
    action->setObjectName(QStringLiteral("showPage%1").arg(i + 1));
    connect(action, &QAction::triggered, this, [this, i] { showPage(static_cast<Page>(i)); });
    pageActions_[static_cast<std::size_t>(i)] = action;
  }
}

void MainWindow::createMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(tr("&New"), QKeySequence::New, this, &MainWindow::newProject);
  file->addAction(tr("&Open…"), QKeySequence::Open, this, &MainWindow::open);
  QAction* demo = file->addAction(tr("Open &demo project"), this, &MainWindow::openDemo);
  QAction* import = file->addAction(tr("&Import data…"), QKeySequence(Qt::CTRL | Qt::Key_I), this,
                                    [this] { importFiles({}); });
  import->setObjectName(QStringLiteral("importData"));
  import->setStatusTip(
      tr("Adds a file (thermal log, probe points, CMM report, …) to the project as a dataset"));
  recentMenu_ = file->addMenu(tr("&Recent files"));
  connect(recentMenu_, &QMenu::aboutToShow, this, &MainWindow::updateRecentMenu);
  updateRecentMenu();
  file->addSeparator();
  file->addAction(tr("&Save"), QKeySequence::Save, this, &MainWindow::save);
  file->addAction(tr("Save &As…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S), this, &MainWindow::saveAs);
  exportAction_ = file->addAction(tr("&Export report PDF…"), QKeySequence(Qt::CTRL | Qt::Key_E), this,
                                  &MainWindow::exportReport);
  file->addSeparator();
  QAction* quit = file->addAction(tr("&Quit"), QKeySequence(Qt::CTRL | Qt::Key_Q), this, &QWidget::close);
  quit->setMenuRole(QAction::QuitRole);

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  // The active document's stack (updateActiveUndoStack): the graph's edits on the setup page's
  // Graph tab, the project's everywhere else.
  QAction* undo = undoGroup_->createUndoAction(this, tr("&Undo"));
  undo->setObjectName(QStringLiteral("editUndo"));
  undo->setShortcuts(QKeySequence::Undo);
  QAction* redo = undoGroup_->createRedoAction(this, tr("&Redo"));
  redo->setObjectName(QStringLiteral("editRedo"));
  redo->setShortcuts(QKeySequence::Redo);
  // The whole text is translatable (word order differs between languages), not just a prefix.
  const auto undoText = [undo](const QString& text) {
    undo->setText(text.isEmpty() ? tr("&Undo") : tr("&Undo %1").arg(text));
  };
  const auto redoText = [redo](const QString& text) {
    redo->setText(text.isEmpty() ? tr("&Redo") : tr("&Redo %1").arg(text));
  };
  connect(undoGroup_, &QUndoGroup::undoTextChanged, undo, undoText);
  connect(undoGroup_, &QUndoGroup::redoTextChanged, redo, redoText);
  undoText(undoGroup_->activeStack()->undoText());
  redoText(undoGroup_->activeStack()->redoText());
  edit->addAction(undo);
  edit->addAction(redo);
  edit->addSeparator();
  edit->addAction(tr("&Preferences…"), this, &MainWindow::preferences)->setMenuRole(QAction::PreferencesRole);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  QAction* toggleNavigator = navigatorDock_->toggleViewAction();
  toggleNavigator->setText(tr("Project &navigator"));
  view->addAction(toggleNavigator);
  view->addSeparator();
  for (QAction* action : pageActions_) view->addAction(action);

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  QAction* manual = help->addAction(tr("&Manual"), QKeySequence(Qt::Key_F1), this, &MainWindow::showManual);
  manual->setObjectName(QStringLiteral("helpManual"));
  manual->setStatusTip(tr("Shows the documentation: file formats, results, references"));
  help->addSeparator();
  help->addAction(demo);
  help->addSeparator();
  help->addAction(tr("&About Metrofit"), this, &MainWindow::about)->setMenuRole(QAction::AboutRole);
  help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt)->setMenuRole(QAction::AboutQtRole);
}

void MainWindow::showPage(Page page) {
  const int index = static_cast<int>(page);
  pages_->setCurrentIndex(index);
  navigator_->selectPage(page);
  pageActions_[static_cast<std::size_t>(index)]->setChecked(true);
  const QString study = studyForPage(page);
  statusBar()->showMessage(study.isEmpty() ? tr("Project overview") : studyTitle(study), kStatusTimeoutMs);
}

void MainWindow::restoreLayout() {
  QSettings settings;
  const WindowLayout layout = WindowLayout::read(settings);
  applyWindowLayout(layout, *this, pages_);  // a refused state leaves the defaults: nothing to tell
  if (layout.page >= 0 && layout.page < kPageCount) showPage(static_cast<Page>(layout.page));
}

void MainWindow::saveLayout() const {
  QSettings settings;
  captureWindowLayout(*this, pages_, pages_->currentIndex()).write(settings);
}

void MainWindow::updateTitle() {
  setWindowTitle(tr("%1[*] — Metrofit").arg(document_->displayName()));
  auto* setup = qobject_cast<SetupPage*>(page(Page::Setup));
  setWindowModified(document_->isModified() || document_->hasUnsavedResults() ||
                    (setup && setup->modelEditor()->isModified()));
}

void MainWindow::updateActiveUndoStack() {
  auto* setup = qobject_cast<SetupPage*>(page(Page::Setup));
  const bool graph = setup && pages_->currentWidget() == setup && setup->tabs()->currentIndex() == 0;
  undoGroup_->setActiveStack(graph ? setup->modelEditor()->undoStack() : document_->undoStack());
}

bool MainWindow::saveSetupModel() {
  auto* setup = qobject_cast<SetupPage*>(page(Page::Setup));
  if (!setup || !setup->modelEditor()->isModified()) return true;
  QString error;
  if (setup->saveModel(&error)) return true;
  showError(tr("Cannot save the setup model"), error);
  return false;
}

void MainWindow::updateRecentMenu() {
  recentMenu_->clear();
  const QStringList files = recentFiles();
  int number = 1;
  for (const QString& path : files) {
    QAction* action =
        recentMenu_->addAction(QStringLiteral("&%1 %2").arg(number++).arg(QFileInfo(path).fileName()));
    action->setToolTip(QDir::toNativeSeparators(path));
    action->setStatusTip(QDir::toNativeSeparators(path));
    connect(action, &QAction::triggered, this, [this, path] {
      if (maybeSave()) openProject(path);
    });
  }
  if (files.isEmpty()) recentMenu_->addAction(tr("No recent files"))->setEnabled(false);
  recentMenu_->addSeparator();
  QAction* clear = recentMenu_->addAction(tr("&Clear list"), this, [] { clearRecentFiles(); });
  clear->setEnabled(!files.isEmpty());
}

void MainWindow::showError(const QString& title, const QString& message) {
  QMessageBox::critical(this, title, message);
}

bool MainWindow::openProject(const QString& path, QString* error) {
  try {
    autosave_->open(path);
  } catch (const std::exception& e) {
    const QString message = QString::fromStdString(e.what());
    if (error) {
      *error = message;
    } else {
      showError(tr("Cannot open the project"), message);
    }
    return false;
  }
  fileChangedBar_->hide();
  addRecentFile(document_->fileName());
  statusBar()->showMessage(tr("Opened %1").arg(QDir::toNativeSeparators(document_->fileName())),
                           kStatusTimeoutMs);
  return true;
}

void MainWindow::recoverUntitled() {
  if (autosave_->recoverUntitled() == RecoveryChoice::Recover)
    statusBar()->showMessage(tr("Recovered the autosaved project; save it to keep it."), kStatusTimeoutMs);
}

bool MainWindow::maybeSave() {
  // The setup model is its own file with its own undo stack (the graph editor): its unsaved edits
  // are asked about together with the project's.
  auto* setup = qobject_cast<SetupPage*>(page(Page::Setup));
  // A run's result is kept in the project (ProjectDocument::setStoredResult) without being an edit:
  // it is lost too when the project is not saved, so it is asked about as well.
  const bool modelEdited = setup && setup->modelEditor()->isModified();
  const bool projectUnsaved = document_->isModified() || document_->hasUnsavedResults();
  if (!projectUnsaved && !modelEdited) return true;
  switch (unsavedDecider_ ? unsavedDecider_() : askUnsavedChanges()) {
    case UnsavedChoice::Save:
      if (!saveSetupModel()) return false;
      return !projectUnsaved || save();
    case UnsavedChoice::Discard:
      autosave_->removeWritten();
      return true;
    case UnsavedChoice::Cancel:
      break;
  }
  return false;
}

QString MainWindow::unsavedChangesText() const {
  auto* setup = qobject_cast<SetupPage*>(page(Page::Setup));
  const bool modelEdited = setup && setup->modelEditor()->isModified();
  QString text =
      tr("The project \"%1\" has unsaved changes. Do you want to save them?").arg(document_->displayName());
  if (document_->hasUnsavedResults()) {
    // The results are in the project: saving it keeps them, with or without other changes.
    text = document_->isModified() || modelEdited
               ? tr("The project \"%1\" has unsaved changes, and the results of the last run are not saved "
                    "either. Do you want to save them?")
                     .arg(document_->displayName())
               : tr("The results of the last run are not saved in the project \"%1\" (they are lost when "
                    "it is closed without saving). Do you want to save them?")
                     .arg(document_->displayName());
  } else if (modelEdited && !document_->isModified()) {
    text = tr("The setup model (relation graph) has unsaved edits. Do you want to save them?");
  } else if (modelEdited) {
    text = tr("The project \"%1\" and the setup model (relation graph) have unsaved changes. Do you want to "
              "save them?")
               .arg(document_->displayName());
  }
  return text;
}

MainWindow::UnsavedChoice MainWindow::askUnsavedChanges() {
  const QString text = unsavedChangesText();
  QMessageBox box(QMessageBox::Warning, tr("Unsaved changes"), text,
                  QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, this);
  box.setObjectName(QStringLiteral("unsavedChangesBox"));
  box.button(QMessageBox::Save)->setText(tr("&Save"));
  box.button(QMessageBox::Discard)->setText(tr("&Discard"));
  box.button(QMessageBox::Cancel)->setText(tr("Cancel"));
  box.setDefaultButton(QMessageBox::Save);
  switch (box.exec()) {
    case QMessageBox::Save:
      return UnsavedChoice::Save;
    case QMessageBox::Discard:
      return UnsavedChoice::Discard;
    default:
      return UnsavedChoice::Cancel;
  }
}

void MainWindow::newProject() {
  if (!maybeSave()) return;
  document_->newProject();
  fileChangedBar_->hide();
  showPage(Page::Overview);
  statusBar()->showMessage(tr("New project"), kStatusTimeoutMs);
}

void MainWindow::open() {
  if (!maybeSave()) return;
  const QString start =
      document_->fileName().isEmpty() ? QDir::homePath() : QFileInfo(document_->fileName()).path();
  const QString path = QFileDialog::getOpenFileName(this, tr("Open project"), start, tr(kProjectFilter));
  if (!path.isEmpty()) openProject(path);
}

void MainWindow::openDemo() {
  if (!maybeSave()) return;
  // A demo saved with the user's edits is kept: then the demo goes into demo-2, demo-3, ...
  const QString folder = demoFolderFor(
      QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) + QStringLiteral("/demo"));
  QString path;
  try {
    path = extractDemoProject(folder);
  } catch (const std::exception& e) {
    showError(tr("Cannot open the demo project"), QString::fromStdString(e.what()));
    return;
  }
  if (openProject(path)) {
    statusBar()->showMessage(tr("Demo project copied to %1").arg(QDir::toNativeSeparators(folder)),
                             kStatusTimeoutMs);
  }
}

bool MainWindow::save() {
  if (document_->fileName().isEmpty()) return saveAs();
  try {
    document_->save();
  } catch (const std::exception& e) {
    showError(tr("Cannot save the project"), QString::fromStdString(e.what()));
    return false;
  }
  if (!saveSetupModel()) return false;
  fileChangedBar_->hide();
  statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(document_->fileName())),
                           kStatusTimeoutMs);
  return true;
}

bool MainWindow::saveAs() {
  const QString suggested =
      document_->fileName().isEmpty()
          ? QDir::home().filePath(document_->displayName() + QLatin1String(Project::kFileSuffix))
          : document_->fileName();
  QString path = QFileDialog::getSaveFileName(this, tr("Save project as"), suggested, tr(kProjectFilter));
  if (path.isEmpty()) return false;
  if (!path.endsWith(QLatin1String(Project::kFileSuffix))) path += QLatin1String(Project::kFileSuffix);
  try {
    document_->saveAs(path);
  } catch (const std::exception& e) {
    showError(tr("Cannot save the project"), QString::fromStdString(e.what()));
    return false;
  }
  if (!saveSetupModel()) return false;
  fileChangedBar_->hide();
  addRecentFile(document_->fileName());
  statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(document_->fileName())),
                           kStatusTimeoutMs);
  return true;
}

void MainWindow::exportReport() {
  if (exporter_->isRunning()) return;
  const QString base = document_->fileName().isEmpty()
                           ? QDir::home().filePath(document_->displayName())
                           : QFileInfo(document_->fileName()).path() + QLatin1Char('/') +
                                 QFileInfo(document_->fileName()).completeBaseName();
  QString path = QFileDialog::getSaveFileName(this, tr("Export report"), base + QStringLiteral(".pdf"),
                                              tr("PDF documents (*.pdf)"));
  if (path.isEmpty()) return;
  if (!path.endsWith(QLatin1String(".pdf"), Qt::CaseInsensitive)) path += QStringLiteral(".pdf");
  if (exporter_->start(*document_, path)) {
    exportAction_->setEnabled(false);
    statusBar()->showMessage(tr("Writing the report…"));
  }
}

void MainWindow::preferences() {
  PreferencesDialog dialog(this);
  if (dialog.exec() != QDialog::Accepted) return;
  const bool languageChanged = dialog.apply();
  autosave_->setIntervalMs(Autosave::intervalSetting() * 60 * 1000);
  if (languageChanged)
    statusBar()->showMessage(tr("The new language is applied at the next start."), kStatusTimeoutMs);
}

void MainWindow::about() {
  QMessageBox::about(
      this, tr("About Metrofit"),
      tr("<h3>Metrofit %1</h3>"
         "<p>A workbench for machining error compensation: setup-data correction, posture matching, "
         "kinematic "
         "compensation with SPC, thermal error models, and the closed-loop diagnosis of what a model "
         "lacks.</p>"
         "<p>Licensed under the GNU General Public License, version 3 or later (GPL-3.0-or-later).</p>"
         "<p>Built with Qt %2 (Qt Widgets, Qt Charts), VTK, Eigen %3 and GLPK.</p>"
         "<p>The real thermal log of the demo project comes from the CAIVIAC data set and is used under the "
         "MIT "
         "licence.</p>")
          .arg(QString::fromLatin1(kVersion), QString::fromLatin1(qVersion()),
               QStringLiteral("%1.%2.%3")
                   .arg(EIGEN_WORLD_VERSION)
                   .arg(EIGEN_MAJOR_VERSION)
                   .arg(EIGEN_MINOR_VERSION)));
}

void MainWindow::showManual() {
  const QString appDir = QCoreApplication::applicationDirPath();
  const QString path = findManual(appDir);
  if (path.isEmpty()) {
    QStringList searched;
    for (const QString& candidate : manualCandidates(appDir)) searched << QDir::toNativeSeparators(candidate);
    showError(
        tr("Cannot show the manual"),
        tr("The documentation is not installed; looked for:\n%1").arg(searched.join(QLatin1Char('\n'))));
    return;
  }
  if (manualOpener_) {
    if (!manualOpener_(path)) showError(tr("Cannot show the manual"), QDir::toNativeSeparators(path));
    return;
  }
  if (manualWindow_ == nullptr) manualWindow_ = new ManualWindow(this);
  if (!manualWindow_->openPage(path)) {
    showError(tr("Cannot show the manual"), tr("Cannot read %1").arg(QDir::toNativeSeparators(path)));
    return;
  }
  manualWindow_->show();
  manualWindow_->raise();
  manualWindow_->activateWindow();
}

void MainWindow::importFiles(const QStringList& files) {
  QStringList paths = files;
  if (paths.isEmpty()) {
    const QString start =
        document_->fileName().isEmpty() ? QDir::homePath() : QFileInfo(document_->fileName()).path();
    // All files first (ImportDialog::fileFilter): files without an extension are shown.
    paths = QFileDialog::getOpenFileNames(this, tr("Import data"), start, ImportDialog::fileFilter());
  }
  // Several DMIS files, one per workpiece: offered as one series (one dataset), else one dialog each.
  bool allDmis = paths.size() > 1;
  for (const QString& path : paths) {
    QFile file(path);
    if (!allDmis || !file.open(QIODevice::ReadOnly) || !setup::looksLikeDmis(file.read(4096).toStdString()))
      allDmis = false;
  }
  for (int k = 0; k < paths.size(); ++k) {
    const QString& path = paths[k];
    ImportDialog dialog(document_->project(), document_->projectPathForDatasets(), this);
    dialog.setFile(path);
    if (allDmis && k == 0) dialog.setSeriesFiles(paths.mid(1));
    if (dialog.exec() != QDialog::Accepted) continue;
    if (dialog.readsSeries()) k = static_cast<int>(paths.size());  // the other files are in the series
    try {
      document_->addDataset(dialog.dataset());
    } catch (const std::exception& e) {
      showError(tr("Cannot import the data"), QString::fromStdString(e.what()));
      continue;
    }
    const QString id = QString::fromStdString(dialog.dataset().id);
    // Show the data where it is used: the first study page that reads its kind.
    const QString kind = QString::fromStdString(dialog.dataset().kind);
    for (const QString& study : studyKeys()) {
      if (study == QLatin1String(study::kDiagnosis) || !studyDatasetKinds(study).contains(kind)) continue;
      const Page page = pageForStudy(study);
      if (page == Page::Thermal) thermal_->selectDataset(id);
      if (page == Page::Matching) matching_->selectDataset(id);
      showPage(page);
      break;
    }
    statusBar()->showMessage(tr("Imported %1 as “%2”").arg(QFileInfo(path).fileName(), id), kStatusTimeoutMs);
  }
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  const QMimeData* mime = event->mimeData();
  if (!mime->hasUrls()) return;
  for (const QUrl& url : mime->urls())
    if (!url.isLocalFile()) return;
  event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  QStringList data;
  QString project;
  for (const QUrl& url : event->mimeData()->urls()) {
    const QString path = url.toLocalFile();
    if (path.endsWith(QLatin1String(Project::kFileSuffix)))
      project = path;
    else
      data << path;
  }
  event->acceptProposedAction();
  // A dropped project is opened; dropped data files are imported into the open project. Both after
  // the drop has finished (the dialogs are modal; the program the files came from must not wait).
  if (!project.isEmpty() && data.isEmpty()) {
    QTimer::singleShot(0, this, [this, project] {
      if (maybeSave()) openProject(project);
    });
    return;
  }
  if (!data.isEmpty()) QTimer::singleShot(0, this, [this, data] { importFiles(data); });
}

void MainWindow::reloadFromDisk() {
  const QString file = document_->fileName();
  if (!file.isEmpty()) openProject(file);
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!maybeSave()) {
    event->ignore();
    return;
  }
  exporter_->waitForFinished();
  // A clean close (saved, unchanged or discarded) leaves no autosaved copy behind.
  autosave_->setIntervalMs(0);
  autosave_->removeWritten();
  saveLayout();
  event->accept();
}

}  // namespace metrofit
