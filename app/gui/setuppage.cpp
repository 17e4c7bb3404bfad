#include "app/gui/setuppage.h"

#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QTimer>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>

#include "app/gui/autosave.h"
#include "app/gui/notesedit.h"
#include "app/gui/studysettingbinding.h"
#include "core/io/file_io.h"
#include "core/io/json_util.h"
#include "core/project/datasets.h"
#include "core/project/report_model.h"
#include "core/project/stored_results.h"
#include "core/setup/exact.h"
#include "core/setup/export.h"
#include "core/setup/methods.h"
#include "core/setup/objective.h"
#include "core/study/setup_study.h"
#include "core/study/study_settings.h"
#include "widgets/common/backgroundrun.h"
#include "widgets/document/projectdocument.h"
#include "widgets/document/storedresulttext.h"
#include "widgets/document/studyinfo.h"
#include "widgets/setup/reportmodeldialog.h"
#include "widgets/setup/setupcharts.h"
#include "widgets/setup/setupconvergenceview.h"
#include "widgets/setup/setupgrapheditor.h"
#include "widgets/setup/setupmodeleditor.h"
#include "widgets/setup/setupresultsview.h"
#include "widgets/setup/setupvalidationview.h"

namespace metrofit {

namespace {

constexpr int kFlushMs = 100;

/// studies.diagnosis.setup.applied and .dataset as text ("" when absent), to notice Apply and its
/// undo.
std::string appliedKeyOf(const Project& project) {
  const auto s = project.studies.find(study::kDiagnosis);
  if (s == project.studies.end() || !s->is_object()) return {};
  const auto d = s->find(study::kSetup);
  if (d == s->end() || !d->is_object()) return {};
  const auto a = d->find("applied");
  return a == d->end() ? std::string() : a->dump() + '\n' + d->value("dataset", nlohmann::json()).dump();
}

constexpr int kProgressSteps = 1000;

/// studies.setup as the project holds it (an empty object when there is none).
nlohmann::json setupStudyJson(const Project& project) {
  const auto s = project.studies.find(study::kSetup);
  return s == project.studies.end() ? nlohmann::json::object() : *s;
}

/// The one run setting `key` of studies.setup read on its own (SetupSettings::fromJson / isValid), so
/// that a bad budget does not hide a good method; nullopt when it is refused.
std::optional<SetupSettings> setupSettingField(const Project& project, const char* key) {
  const nlohmann::json study = setupStudyJson(project);
  nlohmann::json one = nlohmann::json::object();
  if (study.is_object() && study.contains(key)) one[key] = study[key];
  try {
    SetupSettings s = SetupSettings::fromJson(one);
    if (!s.isValid(nullptr, nullptr)) return std::nullopt;
    return s;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

/// FNV-1a 64 of a text as "fnv1a64:<16 hex>" (the model a stored run was computed on).
std::string fnv1a64(const std::string& text) {
  std::uint64_t h = 14695981039346656037ULL;
  for (const unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  static const char* hex = "0123456789abcdef";
  std::string out = "fnv1a64:";
  for (int shift = 60; shift >= 0; shift -= 4) out += hex[(h >> shift) & 0xF];
  return out;
}

/// The convergence points the worker collects for the chart while a run goes on.
/// The dimensions' ids and report labels: a change means the report must be read again.
std::string mappingKey(const setup::Model& model) {
  std::string key = model.axis;
  for (const setup::Dimension& d : model.dimensions) key += '\n' + d.id + '\t' + d.label;
  return key;
}

struct LiveTrace {
  std::mutex mutex;
  std::vector<SetupTracePoint> pending;
};

}  // namespace

struct SetupPage::Impl {
  SetupStudyFiles files;
  QString loadedKey;
  bool loaded = false;
  setup::Model measModel;                              ///< the model the measurements were read against
  std::optional<setup::Measurements> measurements;     ///< with the applied effects
  std::optional<setup::Measurements> rawMeasurements;  ///< as read
  std::string appliedKey;                              ///< studies.diagnosis.setup.applied as text
  std::string studyKey;                                ///< studies.setup as text (readSettings)
  std::vector<diagnose::AppliedSetupEffect> applied;
  std::optional<diagnose::SetupPrediction> prediction, declared;
  QString dataError;     ///< model or report could not be read
  QString appliedError;  ///< studies.diagnosis.setup.applied is invalid (also in dataError)
  std::optional<setup::SetupInstance> instance;
  std::optional<SetupRunOutcome> exact;
  // The running run.
  BackgroundRun<SetupRunOutcome> runner;
  std::shared_ptr<LiveTrace> live;
  std::optional<setup::SetupInstance> runInstance;
  int chartRun = -1;
  QTimer flush;
  QPointer<AutosaveExtras> extras;
  std::optional<ReportFeatures> reportFeatures;  ///< of the study's report (readReportFeatures)
};

SetupPage::SetupPage(ProjectDocument* document, QWidget* parent)
    : QWidget(parent),
      d(std::make_unique<Impl>()),
      document_(document),
      editor_(new SetupModelEditor(this)),
      info_(new QLabel(this)),
      tabs_(new QTabWidget(this)),
      graph_(new SetupGraphEditor(editor_, this)),
      saveModel_(new QPushButton(tr("&Save model"), this)),
      revertModel_(new QPushButton(tr("Re&vert"), this)),
      method_(new QComboBox(this)),
      budget_(new QSpinBox(this)),
      seed_(new QSpinBox(this)),
      run_(new QPushButton(tr("&Run"), this)),
      cancel_(new QPushButton(tr("Cancel"), this)),
      clearRuns_(new QPushButton(tr("C&lear chart"), this)),
      progress_(new QProgressBar(this)),
      runStatus_(new QLabel(this)),
      convergence_(new SetupConvergenceView(this)),
      results_(new SetupResultsView(this)),
      validation_(new SetupValidationView(this)) {
  setObjectName(QStringLiteral("setupPage"));
  auto* title = new QLabel(studyTitle(QString::fromLatin1(study::kSetup)), this);
  QFont titleFont = title->font();
  titleFont.setPointSizeF(titleFont.pointSizeF() * 1.4);
  titleFont.setBold(true);
  title->setFont(titleFont);
  title->setToolTip(studySummary(QString::fromLatin1(study::kSetup)));
  info_->setObjectName(QStringLiteral("setupInfo"));
  info_->setWordWrap(true);
  info_->setTextInteractionFlags(Qt::TextSelectableByMouse);

  // ---- Graph tab ----
  auto* graphTab = new QWidget(this);
  auto* graphLayout = new QVBoxLayout(graphTab);
  graphLayout->setContentsMargins(4, 4, 4, 4);
  graphLayout->addWidget(graph_, 1);
  saveModel_->setToolTip(tr("Write the edited model to its dataset file"));
  revertModel_->setToolTip(tr("Read the model file again (one undo step: Ctrl+Z brings the edits back)"));
  // Revert / Save model at the right of the tab bar (the model's file, whichever tab is shown): on the
  // graph's tool bar they were pushed into its overflow menu in German.
  auto* modelButtons = new QWidget(this);
  auto* modelButtonsLayout = new QHBoxLayout(modelButtons);
  modelButtonsLayout->setContentsMargins(0, 0, 0, 2);
  modelButtonsLayout->addWidget(revertModel_);
  modelButtonsLayout->addWidget(saveModel_);
  tabs_->setCornerWidget(modelButtons, Qt::TopRightCorner);
  connect(saveModel_, &QPushButton::clicked, this, [this] {
    QString error;
    if (!saveModel(&error)) QMessageBox::critical(this, tr("Cannot save the setup model"), error);
  });
  connect(revertModel_, &QPushButton::clicked, this, [this] {
    QString error;
    if (!revertModel(&error)) QMessageBox::critical(this, tr("Cannot revert the setup model"), error);
  });

  // ---- Run tab ----
  for (const std::string& m : setup::setupMethodNames()) {
    const QString name = QString::fromStdString(m);
    method_->addItem(setupMethodTitle(name), name);
  }
  method_->setToolTip(tr("exact: the LP/MILP optimum (GLPK); the metaheuristics with the paper's settings"));
  // Every budget and seed the study accepts up to what a spin box holds; a larger one is refused by
  // readSettings (never clamped).
  budget_->setRange(1, std::numeric_limits<int>::max());
  budget_->setSingleStep(1000);
  budget_->setValue(static_cast<int>(setup::kPaperBudget));
  budget_->setSuffix(tr(" solutions"));
  budget_->setToolTip(tr("Solutions a metaheuristic evaluates (the paper: 5000)"));
  seed_->setRange(0, std::numeric_limits<int>::max());
  seed_->setValue(1);
  seed_->setToolTip(tr("Seed of the metaheuristic: the same seed gives the same run"));
  run_->setToolTip(tr("Run the method (Ctrl+R)"));
  cancel_->setEnabled(false);
  progress_->setObjectName(QStringLiteral("setupRunProgress"));
  progress_->setRange(0, kProgressSteps);
  progress_->setValue(0);
  progress_->setTextVisible(false);
  progress_->setMaximumWidth(220);
  progress_->setVisible(false);  // while a run goes on (updateControls)
  runStatus_->setObjectName(QStringLiteral("setupRunStatus"));
  runStatus_->setWordWrap(true);
  auto* panel = new QHBoxLayout;
  auto* methodLabel = new QLabel(tr("&Method:"), this);
  methodLabel->setBuddy(method_);
  auto* budgetLabel = new QLabel(tr("&Budget:"), this);
  budgetLabel->setBuddy(budget_);
  auto* seedLabel = new QLabel(tr("S&eed:"), this);
  seedLabel->setBuddy(seed_);
  panel->addWidget(methodLabel);
  panel->addWidget(method_);
  panel->addWidget(budgetLabel);
  panel->addWidget(budget_);
  panel->addWidget(seedLabel);
  panel->addWidget(seed_);
  panel->addWidget(run_);
  panel->addWidget(cancel_);
  panel->addWidget(progress_);
  panel->addWidget(clearRuns_);
  panel->addStretch(1);
  auto* runTab = new QWidget(this);
  runTab->setObjectName(QStringLiteral("setupRunTab"));
  auto* runLayout = new QVBoxLayout(runTab);
  runLayout->setContentsMargins(4, 4, 4, 4);
  runLayout->addLayout(panel);
  runLayout->addWidget(runStatus_);
  runLayout->addWidget(convergence_, 1);
  auto* resultsTab = new QWidget(this);
  auto* resultsLayout = new QVBoxLayout(resultsTab);
  resultsLayout->setContentsMargins(4, 4, 4, 4);
  resultsLayout->addWidget(results_);
  auto* validationTab = new QWidget(this);
  auto* validationLayout = new QVBoxLayout(validationTab);
  validationLayout->setContentsMargins(4, 4, 4, 4);
  validationLayout->addWidget(validation_);

  tabs_->addTab(graphTab, tr("&Graph"));
  tabs_->addTab(runTab, tr("R&un"));
  tabs_->addTab(resultsTab, tr("Res&ults"));
  tabs_->addTab(validationTab, tr("Va&lidation"));

  auto* runAction = new QAction(tr("Run"), this);
  runAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
  runAction->setShortcutContext(Qt::WindowShortcut);  // only while the page is shown
  addAction(runAction);
  connect(runAction, &QAction::triggered, this, [this] {
    if (!isRunning()) {
      tabs_->setCurrentIndex(1);
      startRun();
    }
  });
  connect(run_, &QPushButton::clicked, this, [this] { startRun(); });
  connect(cancel_, &QPushButton::clicked, this, &SetupPage::cancelRun);
  connect(clearRuns_, &QPushButton::clicked, this, [this] { convergence_->clearRuns(); });
  connect(budget_, &QSpinBox::valueChanged, this, [this](int v) { convergence_->setBudget(v); });
  // The run settings are studies.setup.method / budget / seed (undoable edits; undo moves the controls).
  // A refused value leaves its control as it is (the info line names the field); choosing a value
  // writes it, which corrects the study.
  const auto field = [this](const char* key) { return setupSettingField(document_->project(), key); };
  bindStudySetting(
      document_, method_, QString::fromLatin1(study::kSetup), QStringLiteral("/method"),
      [field] {
        const auto s = field("method");
        return s ? QString::fromStdString(s->method) : QString();
      },
      tr("Change the setup method"));
  bindStudySetting(
      document_, budget_, QString::fromLatin1(study::kSetup), QStringLiteral("/budget"),
      [field] {
        const auto s = field("budget");
        return s ? static_cast<qint64>(s->budget) : std::numeric_limits<qint64>::min();
      },
      false, tr("Change the setup budget"));
  bindStudySetting(
      document_, seed_, QString::fromLatin1(study::kSetup), QStringLiteral("/seed"),
      [field] {
        const auto s = field("seed");
        return s && s->seed <= static_cast<std::uint64_t>(std::numeric_limits<qint64>::max())
                   ? static_cast<qint64>(s->seed)
                   : std::numeric_limits<qint64>::min();
      },
      true, tr("Change the setup seed"));

  fromReport_ = new QPushButton(tr("From &report…"), this);
  fromReport_->setObjectName(QStringLiteral("setupFromReport"));
  fromReport_->setToolTip(
      tr("Create the setup model from a CMM report of the project, or add the report's "
         "features the model lacks"));
  connect(fromReport_, &QPushButton::clicked, this, [this] { openReportDialog(); });
  auto* top = new QHBoxLayout;
  top->addWidget(title);
  top->addStretch(1);
  top->addWidget(fromReport_);
  auto* notes = new NotesEdit(document_, QString::fromLatin1(study::kSetup), this);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(top);
  layout->addWidget(info_);
  layout->addWidget(tabs_, 1);
  layout->addWidget(notes);

  d->flush.setInterval(kFlushMs);
  connect(&d->flush, &QTimer::timeout, this, &SetupPage::flushTrace);
  connect(&d->runner, &BackgroundRunBase::progress, this, [this](double fraction, const QString&) {
    progress_->setValue(static_cast<int>(fraction * kProgressSteps));
  });
  connect(&d->runner, &BackgroundRunBase::finished, this, [this] { onRunFinished({}); });
  connect(&d->runner, &BackgroundRunBase::cancelled, this, [this] { onRunFinished({}); });
  connect(&d->runner, &BackgroundRunBase::failed, this,
          [this](const QString& message) { onRunFinished(message); });
  connect(editor_, &SetupModelEditor::modelChanged, this, &SetupPage::onModelEdited);
  connect(editor_->undoStack(), &QUndoStack::cleanChanged, this, [this] {
    updateInfo();
    updateControls();
  });
  connect(document_, &ProjectDocument::changed, this, &SetupPage::refresh);

  // Unsaved model edits go into the project's autosave side file and come back on recovery.
  d->extras = AutosaveExtras::of(document_);
  d->extras->add(QStringLiteral("setup_model"), this,
                 {[this] { return editor_->isModified(); },
                  [this] {
                    return nlohmann::json{{"dataset", d->files.modelId},
                                          {"model", setup::modelToJson(editor_->model())}};
                  },
                  [this](const nlohmann::json& unsaved) { restoreUnsavedModel(unsaved); }});
  connect(editor_, &SetupModelEditor::modelChanged, d->extras, &AutosaveExtras::notifyChanged);
  connect(editor_->undoStack(), &QUndoStack::cleanChanged, d->extras, &AutosaveExtras::notifyModifiedChanged);
  refresh();
}

SetupPage::~SetupPage() {
  if (d->extras) {
    d->extras->remove(this);
    disconnect(editor_, nullptr, d->extras, nullptr);
    disconnect(editor_->undoStack(), nullptr, d->extras, nullptr);
  }
  d->runner.disconnect(this);
  d->runner.cancel();
  d->runner.waitForWorker();
  // The editor (a child) outlives this object's members: no more calls back into them.
  disconnect(editor_, nullptr, this, nullptr);
  disconnect(editor_->undoStack(), nullptr, this, nullptr);
}

void SetupPage::refresh() {
  const SetupStudyFiles files = setupStudyFiles(document_->project(), document_->fileName().toStdString());
  // The generation, not the file name: Save As keeps every result, File › New and Open drop them.
  const QString key = QString::number(document_->generation()) + QLatin1Char('\n') +
                      QDir::cleanPath(QString::fromStdString(files.modelPath)) + QLatin1Char('\n') +
                      QDir::cleanPath(QString::fromStdString(files.reportPath));
  if (d->loaded && key == d->loadedKey) {
    // An edit of the run settings (or its undo): refused or accepted again, the stored result's state.
    if (const std::string study = setupStudyJson(document_->project()).dump(); study != d->studyKey) {
      d->studyKey = study;
      const QString settingsBefore = settingsError_;
      readSettings();
      if (settingsBefore != settingsError_) {
        updateInfo();
        updateControls();
      }
      showStoredResult();
    }
    // Apply on the diagnosis page (or its undo): the same files, another model of the deviations.
    const std::string applied = appliedKeyOf(document_->project());
    if (applied == d->appliedKey) return;
    if (isRunning()) {
      cancelRun();
      waitForRun();
    }
    d->appliedKey = applied;
    applyEffects();
    onModelEdited();
    return;
  }
  const bool otherProject =
      !d->loaded || !d->loadedKey.startsWith(QString::number(document_->generation()) + QLatin1Char('\n'));
  d->loadedKey = key;
  reload();
  if (otherProject) validation_->clearResult();  // File › New, Open: nothing of the last project stays
}

void SetupPage::applyEffects() {
  d->measurements.reset();
  d->applied.clear();
  d->prediction.reset();
  d->declared.reset();
  if (!d->rawMeasurements) return;
  if (d->dataError == d->appliedError) d->dataError.clear();
  d->appliedError.clear();
  try {
    setup::Measurements m = *d->rawMeasurements;
    diagnose::SetupPrediction prediction, declared;
    d->applied = applyStudyEffects(document_->project(), document_->fileName().toStdString(),
                                   d->files.reportId, d->measModel, m, &prediction, &declared);
    d->measurements = std::move(m);
    d->prediction = prediction;
    d->declared = declared;
  } catch (const std::exception& e) {
    d->appliedError = tr("The applied effects cannot be used: %1").arg(QString::fromStdString(e.what()));
    d->dataError = d->appliedError;
  }
}

QString SetupPage::infoText() const {
  return info_->text();
}

const std::vector<diagnose::AppliedSetupEffect>& SetupPage::appliedEffects() const {
  return d->applied;
}

std::optional<diagnose::SetupPrediction> SetupPage::prediction() const {
  return d->prediction;
}

std::optional<diagnose::SetupPrediction> SetupPage::declaredPrediction() const {
  return d->declared;
}

const setup::SetupInstance* SetupPage::instance() const {
  return d->instance ? &*d->instance : nullptr;
}

void SetupPage::reload() {
  if (isRunning()) {
    cancelRun();
    waitForRun();
  }
  d->loaded = true;
  d->files = setupStudyFiles(document_->project(), document_->fileName().toStdString());
  d->dataError.clear();
  d->appliedError.clear();
  d->measurements.reset();
  d->rawMeasurements.reset();
  d->appliedKey = appliedKeyOf(document_->project());
  // The controls show the study's values; a refused one is not replaced by a default (readSettings
  // names it, Run stays disabled).
  readSettings();
  if (const auto s = setupSettingField(document_->project(), "method")) {
    const int methodIndex = method_->findData(QString::fromStdString(s->method));
    if (methodIndex >= 0) method_->setCurrentIndex(methodIndex);
  }
  if (const auto s = setupSettingField(document_->project(), "budget");
      s && s->budget >= budget_->minimum() && s->budget <= budget_->maximum())
    budget_->setValue(static_cast<int>(s->budget));
  if (const auto s = setupSettingField(document_->project(), "seed");
      s && s->seed <= static_cast<std::uint64_t>(seed_->maximum()))
    seed_->setValue(static_cast<int>(s->seed));
  setup::Model model;
  if (d->files.modelPath.empty()) {
    d->dataError =
        d->files.reportPath.empty()
            ? tr("This project has no setup model and no CMM report. Import a CMM report (File › Import), "
                 "then create the model from it with “From report…”.")
            : tr("This project has no setup model yet. Create it from the CMM report “%1” with “From "
                 "report…” (or the report's context menu in the project navigator).")
                  .arg(QString::fromStdString(d->files.reportId));
  } else {
    try {
      model = setup::readModel(d->files.modelPath);
      readReport(model);
    } catch (const std::exception& e) {
      d->dataError = QString::fromStdString(e.what());
    }
  }
  editor_->setModel(model);
  validation_->setModel(model);
  validation_->setMeasurements(d->measModel, d->rawMeasurements ? &*d->rawMeasurements : nullptr);
  results_->setMeasurements(d->measModel, d->rawMeasurements ? &*d->rawMeasurements : nullptr,
                            QString::fromStdString(d->files.modelPath));
  convergence_->clearRuns();
  readReportFeatures();
  updateControls();
}

void SetupPage::readReportFeatures() {
  d->reportFeatures.reset();
  QStringList labels;
  QString format;
  if (const DatasetRef* report = document_->project().dataset(d->files.reportId)) {
    try {
      d->reportFeatures = datasetReportFeatures(document_->projectPathForDatasets().toStdString(), *report);
      format = QString::fromStdString(d->reportFeatures->format);
      for (const ReportCharacteristic& c : d->reportFeatures->characteristics)
        if (c.usable && !c.label.empty()) labels << QString::fromStdString(c.label);
    } catch (const std::exception&) {
      // The report's own error is on the info line (readReport).
    }
  }
  graph_->setReportFeatures(labels, format);
}

QStringList SetupPage::reportDatasets() const {
  QStringList out;
  for (const DatasetRef& dataset : document_->project().datasets)
    if (datasetKindServes(dataset_kind::kCmmReport, dataset.kind)) out << QString::fromStdString(dataset.id);
  return out;
}

ReportModelDialog* SetupPage::makeReportDialog(const QString& reportId, QString* error) {
  const QString id = reportId.isEmpty() ? QString::fromStdString(d->files.reportId) : reportId;
  const DatasetRef* report = document_->project().dataset(id.toStdString());
  if (!report || !datasetKindServes(dataset_kind::kCmmReport, report->kind)) {
    if (error)
      *error = id.isEmpty()
                   ? tr("The project has no CMM report: import one first (File › Import).")
                   : tr("“%1” is not a CMM report (OGP, PC-DMIS, DMIS, DFQ, Calypso, QIF) of the project.")
                         .arg(id);
    return nullptr;
  }
  ReportFeatures features;
  try {
    features = datasetReportFeatures(document_->projectPathForDatasets().toStdString(), *report);
  } catch (const std::exception& e) {
    if (error) *error = QString::fromStdString(e.what());
    return nullptr;
  }
  const bool creates = d->files.modelPath.empty();
  return new ReportModelDialog(features, id, creates ? nullptr : &editor_->model(), this);
}

bool SetupPage::applyReportDialog(const ReportModelDialog& dialog, const QString& reportId, QString* error) {
  auto fail = [&](const QString& message) {
    if (error) *error = message;
    return false;
  };
  const QString id = reportId.isEmpty() ? QString::fromStdString(d->files.reportId) : reportId;
  if (!document_->project().dataset(id.toStdString()))
    return fail(tr("“%1” is not a dataset of the project.").arg(id));
  QString why;
  const std::optional<setup::Model> model = dialog.resultModel(&why);
  if (!model) return fail(why);
  if (isRunning()) {
    cancelRun();
    waitForRun();
  }
  if (!dialog.creates()) {
    if (d->files.modelPath.empty()) return fail(tr("The project has no setup model to add features to."));
    if (id.toStdString() != d->files.reportId) {
      // Another report: the study reads it from now on (a project edit that reloads the page).
      if (editor_->isModified())
        return fail(
            tr("Save or revert the edits of the setup model before you add the features of another "
               "report."));
      document_->setStudyValue(QString::fromLatin1(study::kSetup), QStringLiteral("/dataset"),
                               id.toStdString(), tr("Use the report %1 for the setup study").arg(id));
    }
    if (!editor_->replaceModel(*model, tr("Add report features to the setup model")))
      return fail(tr("The model reads every checked characteristic already."));
    return true;
  }
  // A new model: written beside the project as data/<id>.json, then one undo step of the project adds the
  // dataset and makes it (and the report) the study's.
  std::string modelId = id.toStdString() + "-model";
  for (int n = 2; document_->project().dataset(modelId) != nullptr; ++n)
    modelId = id.toStdString() + "-model-" + std::to_string(n);
  const QDir folder = QFileInfo(document_->projectPathForDatasets()).absoluteDir();
  QString relative = QStringLiteral("data/%1.json").arg(QString::fromStdString(modelId));
  for (int n = 2; QFileInfo::exists(folder.absoluteFilePath(relative)); ++n)
    relative = QStringLiteral("data/%1-%2.json").arg(QString::fromStdString(modelId)).arg(n);
  const QString file = folder.absoluteFilePath(relative);
  try {
    if (!QDir().mkpath(QFileInfo(file).absolutePath()))
      return fail(tr("Cannot create the folder %1 for the setup model.").arg(QFileInfo(file).absolutePath()));
    setup::Model saved = *model;
    saved.source = file.toStdString();
    setup::validateModel(saved);
    writeFileAtomic(file.toStdString(), dumpJson(setup::modelToJson(saved)));
  } catch (const std::exception& e) {
    return fail(QString::fromStdString(e.what()));
  }
  DatasetRef dataset;
  dataset.id = modelId;
  dataset.kind = dataset_kind::kSetupModel;
  dataset.path = relative.toStdString();
  dataset.description = tr("Setup model made from the CMM report %1").arg(id).toStdString();
  std::vector<DatasetRef> datasets = document_->project().datasets;
  datasets.push_back(dataset);
  nlohmann::json studies = document_->project().studies;
  if (!studies.contains(study::kSetup) || !studies[study::kSetup].is_object())
    studies[study::kSetup] = nlohmann::json::object();
  studies[study::kSetup]["model"] = modelId;
  studies[study::kSetup]["dataset"] = id.toStdString();
  document_->endEditSequence();
  document_->undoStack()->push(new ChangeDatasets(
      document_, std::move(datasets), std::move(studies),
      tr("Create setup model %1 from report %2").arg(QString::fromStdString(modelId), id)));
  return true;
}

void SetupPage::openReportDialog(const QString& reportId) {
  QString error;
  QString id = reportId;
  if (id.isEmpty()) {
    const QStringList reports = reportDatasets();
    if (reports.size() > 1 && !reports.contains(QString::fromStdString(d->files.reportId)))
      id = reports.front();
  }
  std::unique_ptr<ReportModelDialog> dialog(makeReportDialog(id, &error));
  if (!dialog) {
    QMessageBox::critical(this, tr("Cannot read the CMM report"), error);
    return;
  }
  if (dialog->exec() != QDialog::Accepted) return;
  if (!applyReportDialog(*dialog, id, &error))
    QMessageBox::critical(this, dialog->windowTitle(), error);
  else
    tabs_->setCurrentIndex(0);
}

void SetupPage::readReport(const setup::Model& model) {
  d->measModel = model;
  d->dataError.clear();
  d->appliedError.clear();
  d->measurements.reset();
  d->rawMeasurements.reset();
  if (d->files.reportPath.empty()) {
    d->dataError =
        tr("This project has no CMM report for the setup study (a dataset of kind \"cmm_report\").");
    return;
  }
  try {
    d->rawMeasurements =
        setup::readMeasurements(d->files.reportPaths, model, d->files.reportCsv, d->files.reportDmis);
    applyEffects();
  } catch (const std::exception& e) {
    d->dataError = QString::fromStdString(e.what());
  }
}

bool SetupPage::revertModel(QString* error) {
  if (isRunning()) {
    cancelRun();
    waitForRun();
  }
  if (d->files.modelPath.empty()) {
    if (error) *error = tr("The project has no setup model dataset to revert to.");
    return false;
  }
  setup::Model model;
  try {
    model = setup::readModel(d->files.modelPath);
  } catch (const std::exception& e) {
    if (error) *error = QString::fromStdString(e.what());
    return false;
  }
  readReport(model);
  // One undo step (the model as on disk, not modified); without a change onModelEdited still shows
  // the report as read now.
  if (!editor_->revertTo(model, tr("Revert the setup model"))) onModelEdited();
  return true;
}

void SetupPage::restoreUnsavedModel(const nlohmann::json& unsaved) {
  const std::string dataset = unsaved.at("dataset").get<std::string>();
  if (dataset != d->files.modelId) {
    throw std::runtime_error("the autosaved edits belong to the setup model '" + dataset +
                             "', the setup study now uses '" + d->files.modelId + "'");
  }
  editor_->replaceModel(SetupModelEditor::modelFromEditJson(unsaved.at("model"), d->files.modelPath),
                        tr("Recover autosaved model edits"));
}

void SetupPage::onModelEdited() {
  // A changed report mapping (dimension ids, labels, axis) is read against the report at once, so that the
  // mapping can be tried before the model is saved; tolerance edits keep the report as read against the
  // model file.
  if (editor_->isValid() && !d->files.reportPath.empty() && !d->files.modelPath.empty() &&
      mappingKey(editor_->model()) != mappingKey(d->measModel)) {
    readReport(editor_->model());
  }
  // The runs, the exact optimum and the result belong to the previous model.
  d->instance.reset();
  d->exact.reset();
  convergence_->setExact(std::nullopt);
  convergence_->clearRuns();
  results_->clear(tr("No result for this model yet: choose a method and press Run (Ctrl+R)."));
  validation_->setModel(editor_->model());
  validation_->setMeasurements(d->measModel, d->rawMeasurements ? &*d->rawMeasurements : nullptr);
  results_->setMeasurements(d->measModel, d->rawMeasurements ? &*d->rawMeasurements : nullptr,
                            QString::fromStdString(d->files.modelPath));
  error_.clear();
  if (!d->dataError.isEmpty()) {
    error_ = d->dataError;
  } else if (!editor_->isValid()) {
    const auto& issue = editor_->issues().front();
    error_ = tr("The edited model has %n problem(s), the first: %1", nullptr,
                static_cast<int>(editor_->issues().size()))
                 .arg(QString::fromStdString(issue.field + ": " + issue.message));
  } else {
    try {
      d->instance.emplace(editor_->model(), deviationsFor(editor_->model(), d->measModel, *d->measurements));
    } catch (const std::exception& e) {
      error_ = QString::fromStdString(e.what());
    }
  }
  updateInfo();
  updateControls();
  showStoredResult();
}

void SetupPage::readSettings() {
  settingsError_.clear();
  const nlohmann::json study = setupStudyJson(document_->project());
  d->studyKey = study.dump();
  try {
    const SetupSettings s = SetupSettings::fromJson(study, document_->fileName().toStdString());
    std::string field, why;
    if (!s.isValid(&field, &why)) {
      settingsError_ = QString::fromStdString(field + ": " + why);
    } else if (const auto b = study.find("budget");
               b != study.end() && b->is_number_float() && std::floor(b->get<double>()) != b->get<double>()) {
      settingsError_ = tr("studies.setup.budget: must be a whole number of solutions");
    } else if (s.budget > budget_->maximum()) {
      settingsError_ = tr("studies.setup.budget: more solutions than the page can run (at most %1)")
                           .arg(budget_->maximum());
    } else if (s.seed > static_cast<std::uint64_t>(seed_->maximum())) {
      settingsError_ =
          tr("studies.setup.seed: larger than the page can use (at most %1)").arg(seed_->maximum());
    }
  } catch (const std::exception& e) {
    settingsError_ = QString::fromStdString(e.what());
  }
}

void SetupPage::updateInfo() {
  const setup::Model& m = editor_->model();
  const QLocale locale;
  if (m.setup.empty() && m.features.empty() && m.dimensions.empty() && !d->dataError.isEmpty()) {
    info_->setText(d->dataError);
    info_->setStyleSheet(QStringLiteral("color: #b01818;"));
    return;
  }
  int wks = 0, tools = 0, machine = 0;
  for (const auto& s : m.setup) {
    wks += s.kind == setup::DatumKind::Wks ? 1 : 0;
    tools += s.kind == setup::DatumKind::Tool ? 1 : 0;
    machine += s.kind == setup::DatumKind::Machine ? 1 : 0;
  }
  QString text =
      tr("Model “%1” (%2): %3 setup data (%4 work offsets, %5 tools, %6 machine points), %7 features, "
         "%8 dimensions, %9 arcs; axis %10, grid %11 mm, bounds [%12, %13] mm.")
          .arg(QString::fromStdString(m.name), QString::fromStdString(d->files.modelId))
          .arg(m.setup.size())
          .arg(wks)
          .arg(tools)
          .arg(machine)
          .arg(m.features.size())
          .arg(m.dimensions.size())
          .arg(m.arcs.size())
          .arg(QString::fromStdString(m.axis), locale.toString(m.stepMm, 'g', 6),
               locale.toString(m.boundsMm.first, 'f', 3), locale.toString(m.boundsMm.second, 'f', 3));
  if (editor_->isModified()) text += QLatin1Char(' ') + tr("Edited, not saved.");
  if (d->measurements) {
    text += QLatin1Char('\n') + tr("Report “%1”: %2 parts, %3 rows.")
                                    .arg(QString::fromStdString(d->files.reportId))
                                    .arg(d->measurements->parts.size())
                                    .arg(d->measurements->rows.size());
    if (d->instance)
      text += QLatin1Char(' ') + tr("Smallest error budget before correction f1 = %1 mm.")
                                     .arg(locale.toString(d->instance->f1Before(), 'f', 4));
  }
  if (!d->applied.empty() && d->prediction && d->declared) {
    const diagnose::SetupPrediction& p = *d->prediction;
    const diagnose::SetupPrediction& q = *d->declared;
    QString figures = tr("deviations predicted for part %1; residual rms %2 mm (declared model %3 mm)")
                          .arg(locale.toString(p.nextPart, 'g', 6), locale.toString(p.rmseMm, 'f', 4),
                               locale.toString(q.rmseMm, 'f', 4));
    if (p.nextPartRmseMm && q.nextPartRmseMm)
      figures +=
          tr(", last part predicted from the others %1 mm (declared %2 mm)")
              .arg(locale.toString(*p.nextPartRmseMm, 'f', 4), locale.toString(*q.nextPartRmseMm, 'f', 4));
    text += QLatin1Char('\n') + tr("Includes applied effects: %1 — %2.")
                                    .arg(QString::fromStdString(diagnose::describe(d->applied)), figures);
  }
  if (const std::string elsewhere =
          diagnose::appliedEffectsElsewhere(document_->project(), study::kSetup, d->files.reportId);
      d->measurements && !elsewhere.empty()) {
    text += QLatin1Char('\n') + tr("Effects applied on the Diagnosis page belong to the report %1 (the one "
                                   "the diagnosis ran on); this report uses the declared model.")
                                    .arg(QString::fromStdString(elsewhere));
  }
  if (!error_.isEmpty()) text += QLatin1Char('\n') + error_;
  if (!settingsError_.isEmpty())
    text +=
        QLatin1Char('\n') + tr("The setup study's run settings are invalid, nothing is run until they are "
                               "corrected (choose a value, Undo, or the project file): %1")
                                .arg(settingsError_);
  info_->setText(text);
  info_->setStyleSheet(error_.isEmpty() && settingsError_.isEmpty() ? QString()
                                                                    : QStringLiteral("color: #b01818;"));
}

void SetupPage::updateControls() {
  const bool running = isRunning();
  run_->setEnabled(!running && d->instance.has_value() && settingsError_.isEmpty());
  cancel_->setEnabled(running);
  method_->setEnabled(!running);
  budget_->setEnabled(!running);
  seed_->setEnabled(!running);
  graph_->setEnabled(!running);
  progress_->setVisible(running);
  saveModel_->setEnabled(!running && editor_->isModified());
  if (fromReport_) fromReport_->setEnabled(!running && !reportDatasets().isEmpty());
  revertModel_->setEnabled(!running && editor_->isModified());
}

bool SetupPage::ensureExact() {
  if (!d->instance) {
    if (error_.isEmpty()) error_ = tr("The setup study has no model or report to run on.");
    return false;
  }
  if (d->exact) return true;
  try {
    d->exact = runSetupMethod(*d->instance, "exact", 0, 0);
  } catch (const std::exception& e) {
    error_ = QString::fromStdString(e.what());
    updateInfo();
    return false;
  }
  convergence_->setExact(d->exact->score);
  return true;
}

bool SetupPage::isRunning() const {
  return d->runner.isRunning();
}

bool SetupPage::startRun() {
  if (!settingsError_.isEmpty()) {  // refused, not replaced by a default
    runStatus_->setText(tr("Not run: %1").arg(settingsError_));
    return false;
  }
  if (isRunning() || !ensureExact()) return false;
  const std::string method = method_->currentData().toString().toStdString();
  const long budget = budget_->value();
  const auto seed = static_cast<std::uint64_t>(seed_->value());
  if (method == "exact") {
    showOutcome(*d->exact);
    storeResult(*d->exact);
    runStatus_->setText(tr("Exact optimum: %1 solver calls in %2 ms.")
                            .arg(d->exact->evaluations)
                            .arg(QLocale().toString(d->exact->seconds * 1e3, 'f', 2)));
    progress_->setValue(kProgressSteps);
    emit runFinished();
    return true;
  }
  d->live = std::make_shared<LiveTrace>();
  d->runInstance = d->instance;
  d->chartRun = convergence_->addRun(QString::fromStdString(method), seed);
  progress_->setValue(0);
  runStatus_->setText(tr("Running %1…").arg(setupRunLabel(QString::fromStdString(method), seed)));
  const setup::SetupInstance instance = *d->instance;
  std::shared_ptr<LiveTrace> live = d->live;
  d->runner.start([instance, method, budget, seed, live](RunObserver& run) {
    FunctionObserver observer([&](const IterationSummary& s) {
      {
        const std::lock_guard<std::mutex> lock(live->mutex);
        live->pending.push_back(tracePoint(s));
      }
      return run.onIteration(s);
    });
    return runSetupMethod(instance, method, budget, seed, &observer);
  });
  updateControls();
  d->flush.start();
  return true;
}

bool SetupPage::runSynchronously(const QString& method, long budget, unsigned long long seed) {
  if (isRunning() || !ensureExact()) return false;
  if (method == QLatin1String("exact")) {
    showOutcome(*d->exact);
    storeResult(*d->exact);
    return true;
  }
  try {
    const SetupRunOutcome outcome = runSetupMethod(*d->instance, method.toStdString(), budget, seed);
    const int run = convergence_->addRun(method, seed);
    convergence_->appendPoints(run, outcome.trace);
    showOutcome(outcome);
    storeResult(outcome);
    progress_->setValue(kProgressSteps);
  } catch (const std::exception& e) {
    error_ = QString::fromStdString(e.what());
    updateInfo();
    return false;
  }
  return true;
}

void SetupPage::cancelRun() {
  d->runner.cancel();
}

void SetupPage::waitForRun() {
  d->runner.waitForFinished();
}

void SetupPage::flushTrace() {
  if (!d->live) return;
  std::vector<SetupTracePoint> points;
  {
    const std::lock_guard<std::mutex> lock(d->live->mutex);
    points.swap(d->live->pending);
  }
  convergence_->appendPoints(d->chartRun, points);
}

void SetupPage::onRunFinished(const QString& error) {
  d->flush.stop();
  flushTrace();
  d->live.reset();
  const std::optional<SetupRunOutcome> outcome = d->runner.takeResult();
  if (!error.isEmpty() || !outcome) {
    runStatus_->setText(tr("The run failed: %1").arg(error));
  } else {
    const SetupRunOutcome& o = *outcome;
    const bool cancelled = o.termination == Termination::Cancelled;
    progress_->setValue(cancelled ? progress_->value() : kProgressSteps);
    QString text = tr("%1: f1 %2 mm after %3 solutions in %4 ms")
                       .arg(setupRunLabel(QString::fromStdString(o.method), o.seed))
                       .arg(QLocale().toString(o.score.f1, 'f', 4))
                       .arg(o.evaluations)
                       .arg(QLocale().toString(o.seconds * 1e3, 'f', 1));
    if (d->exact)
      text += tr(", gap to the exact optimum %1 mm")
                  .arg(QLocale().toString(d->exact->score.f1 - o.score.f1, 'f', 4));
    text += cancelled ? tr(" — cancelled.") : QStringLiteral(".");
    runStatus_->setText(text);
    if (d->runInstance && d->instance) {
      showOutcome(o);
      if (!cancelled) storeResult(o);
    }
  }
  d->runInstance.reset();
  updateControls();
  emit runFinished();
}

void SetupPage::showOutcome(const SetupRunOutcome& outcome) {
  if (!d->instance || !d->measurements) return;
  const SetupPartsSummary parts = partsSummary(*d->instance, d->measModel, *d->measurements, outcome.x);
  results_->setResult(editor_->model(), *d->instance, outcome,
                      d->exact ? std::optional<setup::SetupScore>(d->exact->score) : std::nullopt, parts);
}

bool SetupPage::saveModel(QString* error) {
  auto fail = [&](const QString& message) {
    if (error) *error = message;
    return false;
  };
  if (d->files.modelPath.empty()) return fail(tr("The project has no setup model dataset to save to."));
  if (!editor_->isValid()) {
    const auto& issue = editor_->issues().front();
    return fail(tr("The model has %n problem(s); fix them before saving. The first: %1", nullptr,
                   static_cast<int>(editor_->issues().size()))
                    .arg(QString::fromStdString(issue.field + ": " + issue.message)));
  }
  setup::Model saved = editor_->model();
  saved.source = d->files.modelPath;
  try {
    writeFileAtomic(d->files.modelPath, dumpJson(setup::modelToJson(saved)));
  } catch (const std::exception& e) {
    return fail(QString::fromStdString(e.what()));
  }
  editor_->markSaved();
  // The report is checked against the saved model from now on, when it still matches it.
  if (!d->files.reportPath.empty()) {
    try {
      setup::Measurements m =
          setup::readMeasurements(d->files.reportPaths, saved, d->files.reportCsv, d->files.reportDmis);
      d->rawMeasurements = std::move(m);
      d->measModel = saved;
      d->dataError.clear();
      applyEffects();
      results_->setMeasurements(d->measModel, &*d->rawMeasurements,
                                QString::fromStdString(d->files.modelPath));
    } catch (const std::exception& e) {
      error_ = tr("The model was saved, but the CMM report does not match it any more (the runs use the "
                  "report as read against the previous model): %1")
                   .arg(QString::fromStdString(e.what()));
    }
  }
  updateInfo();
  updateControls();
  return true;
}

void SetupPage::showView(const QString& view) {
  if (view == QLatin1String("graph")) {
    tabs_->setCurrentIndex(0);
    graph_->setFocus();
  } else if (view == QLatin1String("convergence")) {
    tabs_->setCurrentIndex(1);
    if (convergence_->runs().empty() && settingsError_.isEmpty() && ensureExact()) {
      runSynchronously(QStringLiteral("cripso"), setup::kPaperBudget, 1);
      runSynchronously(QStringLiteral("pso"), setup::kPaperBudget, 1);
      runStatus_->setText(tr("CRIPSO and PSO, seed 1, %1 solutions each, against the exact optimum.")
                              .arg(setup::kPaperBudget));
    }
  } else if (view == QLatin1String("results")) {
    tabs_->setCurrentIndex(2);
    if (!results_->hasResult() && settingsError_.isEmpty()) runSynchronously(QStringLiteral("exact"), 0, 0);
  } else if (view == QLatin1String("validation")) {
    tabs_->setCurrentIndex(3);
    if (validation_->result() == nullptr && !validation_->isRunning()) {
      validation_->setSets(20);
      validation_->setTrials(3);
      if (validation_->start()) validation_->waitForFinished();
    }
  }
}

nlohmann::json SetupPage::storedSettingsJson() const {
  // What decides the figures: the run settings, the model as edited (its tolerances, bounds, arcs)
  // and the effects applied on the diagnosis page (they change the deviations).
  nlohmann::json settings = nlohmann::json::object();
  try {
    settings["study"] = SetupSettings::fromJson(setupStudyJson(document_->project())).toJson();
  } catch (const std::exception&) {
    settings["study"] = nullptr;  // refused: nothing stored matches
  }
  // Without the study's dataset ids: they name the data, whose hash the envelope keeps.
  if (settings["study"].is_object()) {
    settings["study"].erase("model");
    settings["study"].erase("dataset");
  }
  settings["model"] = fnv1a64(setup::modelToJson(editor_->model()).dump());
  settings["diagnosis"] =
      document_->studyValue(QString::fromLatin1(study::kDiagnosis), QStringLiteral("/setup/applied"));
  return settings;
}

void SetupPage::storeResult(const SetupRunOutcome& o) {
  if (!settingsError_.isEmpty() || !d->instance || !d->measurements || d->files.reportId.empty()) return;
  if (o.termination == Termination::Cancelled) return;
  // Only a run of the study's own settings is the study's result (showView's demo runs are not).
  SetupSettings s;
  try {
    s = SetupSettings::fromJson(setupStudyJson(document_->project()));
  } catch (const std::exception&) {
    return;
  }
  if (o.method != s.method) return;
  if (o.method != "exact" && (o.budget != s.budget || o.seed != s.seed)) return;
  const DatasetRef* report = document_->project().dataset(d->files.reportId);
  if (!report) return;
  const setup::Model& model = editor_->model();
  nlohmann::json corrections = nlohmann::json::array();
  for (std::size_t i = 0; i < model.setup.size() && i < o.x.size(); ++i) {
    nlohmann::json c = {{"datum", model.setup[i].id},
                        {"correction_mm", std::abs(o.x[i]) < 5e-10 ? 0.0 : o.x[i]}};
    try {
      c["register"] = setup::registerOf(model, i);
    } catch (const std::exception&) {
    }
    corrections.push_back(std::move(c));
  }
  const SetupPartsSummary parts = partsSummary(*d->instance, d->measModel, *d->measurements, o.x);
  nlohmann::json figures = {{"method", o.method},
                            {"f1_before", o.f1Before},
                            {"f1", o.score.f1},
                            {"f2", o.score.f2},
                            {"f", o.score.f},
                            {"evaluations", o.evaluations},
                            {"termination", toString(o.termination)},
                            {"corrections", std::move(corrections)},
                            {"parts",
                             {{"parts", parts.parts},
                              {"in_tolerance_before", parts.inToleranceBefore},
                              {"in_tolerance_after", parts.inToleranceAfter},
                              {"rescued", parts.rescued},
                              {"lost", parts.lost}}}};
  if (o.method == "exact") {
    figures["f1_optimal"] = o.f1Optimal;
    figures["f2_optimal"] = o.f2Optimal;
  } else {
    figures["budget"] = o.budget;
    figures["seed"] = o.seed;
  }
  if (d->exact)
    figures["exact"] = {{"f1", d->exact->score.f1}, {"f2", d->exact->score.f2}, {"f", d->exact->score.f}};
  try {
    document_->setStoredResult(QString::fromLatin1(study::kSetup), QString::fromStdString(d->files.reportId),
                               makeStoredResult(document_->projectPathForDatasets().toStdString(), *report,
                                                storedSettingsJson(), std::move(figures)));
  } catch (const std::exception&) {
    // The report cannot be read any more: nothing is stored, the page shows the run.
  }
}

QString SetupPage::storedResultText() const {
  if (d->files.reportId.empty() || !settingsError_.isEmpty()) return {};
  const DatasetRef* report = document_->project().dataset(d->files.reportId);
  if (!report) return {};
  const StoredResult stored =
      storedResult(document_->project(), document_->projectPathForDatasets().toStdString(), study::kSetup,
                   *report, storedSettingsJson());
  if (const std::optional<QString> state = storedStateText(
          stored,
          {tr("The stored result (computed %1) is out of date: the run settings, the model or the applied "
              "effects changed since. Not run with these yet: press Run (Ctrl+R)."),
           tr("The stored result (computed %1) is out of date: the CMM report changed since. Press Run "
              "(Ctrl+R) to correct the setup for the report as it is now."),
           tr("The stored result (computed %1) cannot be checked: the CMM report cannot be read.")}))
    return *state;
  const QString when = storedTimeText(stored.computed);
  const nlohmann::json& e = stored.entry;
  const auto number = [&e](const char* key) { return storedFigure(e, key, 0.0); };
  const QLocale locale;
  const auto mm = [&locale](double v) { return locale.toString(v, 'f', 4); };
  QStringList corrections;
  if (e.contains("corrections") && e["corrections"].is_array()) {
    for (const nlohmann::json& c : e["corrections"]) {
      if (!c.is_object() || !c.value("datum", nlohmann::json()).is_string()) continue;
      const nlohmann::json v = c.value("correction_mm", nlohmann::json());
      corrections << QStringLiteral("%1 %2").arg(
          QString::fromStdString(c["datum"].get<std::string>()),
          locale.toString(v.is_number() ? v.get<double>() : 0.0, 'f', 3));
    }
  }
  const nlohmann::json parts = e.value("parts", nlohmann::json::object());
  const auto count = [&parts](const char* key) { return storedCount(parts, key); };
  const QString method = QString::fromStdString(e.value("method", std::string()));
  return tr("From the saved project (computed %1 with these settings, this model and this report): %2: f1 %3 "
            "→ "
            "%4 mm, |x| = f2 %5 mm, f %6; corrections (mm) %7; %8 of %9 parts in tolerance before, %10 "
            "after. "
            "Press Run (Ctrl+R) to see the tables and exports.")
      .arg(when, setupMethodTitle(method), mm(number("f1_before")), mm(number("f1")), mm(number("f2")),
           mm(number("f")), corrections.join(QStringLiteral(", ")))
      .arg(count("in_tolerance_before"))
      .arg(count("parts"))
      .arg(count("in_tolerance_after"));
}

void SetupPage::showStoredResult() {
  if (results_->hasResult() || isRunning()) return;
  QString text;
  if (!settingsError_.isEmpty()) {
    text = tr("Nothing is run while the setup study's run settings are invalid: %1").arg(settingsError_);
  } else {
    text = storedResultText();
    if (text.isEmpty()) text = tr("No result for this model yet: choose a method and press Run (Ctrl+R).");
  }
  results_->clear(text);
}

}  // namespace metrofit
