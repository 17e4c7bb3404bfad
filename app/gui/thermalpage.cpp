#include "app/gui/thermalpage.h"

#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalBlocker>
#include <QStackedWidget>
#include <QTabWidget>
#include <QVBoxLayout>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <utility>

#include "app/gui/notesedit.h"
#include "app/gui/studysettingbinding.h"
#include "core/diagnose/applied_setup_matching.h"
#include "core/diagnose/thermal_applied.h"
#include "core/io/file_io.h"
#include "core/project/datasets.h"
#include "core/project/stored_results.h"
#include "core/study/thermal_result.h"
#include "core/thermal/control_export.h"
#include "core/thermal/thermal_log.h"
#include "widgets/document/projectdocument.h"
#include "widgets/document/storedresulttext.h"
#include "widgets/document/studyinfo.h"
#include "widgets/thermal/thermalcharts.h"
#include "widgets/thermal/thermalhysteresisview.h"
#include "widgets/thermal/thermalmodelview.h"
#include "widgets/thermal/thermaltrendview.h"

namespace metrofit {
namespace {

/// A file suffix for each control form.
QString exportSuffix(thermal::ControlFormat f) {
  switch (f) {
    case thermal::ControlFormat::St:
      return QStringLiteral("st");
    case thermal::ControlFormat::Siemens:
      return QStringLiteral("ini");
    case thermal::ControlFormat::Csv:
      return QStringLiteral("csv");
    default:
      return QStringLiteral("txt");
  }
}

/// Model i of the comparison can go to a control: fitted, and on the declared inputs (not on the applied
/// effects' columns, which Metrofit computes and a control does not have).
bool exportable(const ThermalComparison& c, std::size_t i) {
  return c.fitted(i) && !c.usesApplied[i];
}

enum Tab { kTrendTab = 0, kHysteresisTab = 1, kModelsTab = 2 };

QString settingsKey(const QString& id, const ThermalModelSettings& s) {
  QString key = id + QLatin1Char('|') + QString::fromStdString(s.target);
  for (const std::string& in : s.inputs) key += QLatin1Char(',') + QString::fromStdString(in);
  return key;
}

/// The dataset the diagnosis of `domain` ran on when effects were applied there and it is not
/// `datasetId` (the applied effects belong to that dataset), else empty.
/// The dataset whose diagnosis applied effects (not this one), or empty: core's rule, as a QString.
QString appliedElsewhere(const Project& project, const char* domain, const std::string& datasetId) {
  return QString::fromStdString(diagnose::appliedEffectsElsewhere(project, domain, datasetId));
}

}  // namespace

ThermalPage::ThermalPage(ProjectDocument* document, QWidget* parent)
    : QWidget(parent),
      document_(document),
      combo_(new QComboBox(this)),
      info_(new QLabel(this)),
      stack_(new QStackedWidget(this)),
      tabs_(new QTabWidget(this)),
      trend_(new ThermalTrendView(this)),
      hysteresis_(new ThermalHysteresisView(this)),
      models_(new ThermalModelView(this)),
      message_(new QLabel(this)),
      modular_(new BackgroundRun<ModularRun>(this)) {
  auto* title = new QLabel(studyTitle(QString::fromLatin1(study::kThermal)), this);
  QFont titleFont = title->font();
  titleFont.setPointSizeF(titleFont.pointSizeF() * 1.4);
  titleFont.setBold(true);
  title->setFont(titleFont);
  title->setToolTip(studySummary(QString::fromLatin1(study::kThermal)));

  combo_->setObjectName(QStringLiteral("thermalLogCombo"));
  combo_->setSizeAdjustPolicy(QComboBox::AdjustToContents);  // the longest id shows in full
  combo_->setMinimumContentsLength(16);
  info_->setObjectName(QStringLiteral("thermalInfo"));
  info_->setWordWrap(true);
  info_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  message_->setObjectName(QStringLiteral("thermalMessage"));
  message_->setWordWrap(true);
  message_->setAlignment(Qt::AlignCenter);
  message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  tabs_->setObjectName(QStringLiteral("thermalTabs"));
  tabs_->addTab(trend_, tr("T&rend"));
  tabs_->addTab(hysteresis_, tr("&Hysteresis"));
  tabs_->addTab(models_, tr("&Models"));
  tabs_->setTabToolTip(kTrendTab, tr("Temperatures, strains and displacement against time"));
  tabs_->setTabToolTip(kHysteresisTab, tr("Displacement against each sensor over heating and cooling"));
  tabs_->setTabToolTip(kModelsTab, tr("GNNMCI(1,N), GMC(1,N) and MLP fitted and compared (Table 4)"));
  stack_->addWidget(tabs_);
  stack_->addWidget(message_);

  auto* top = new QHBoxLayout;
  auto* comboLabel = new QLabel(tr("&Thermal log:"), this);
  comboLabel->setBuddy(combo_);
  top->addWidget(title);
  top->addSpacing(16);
  top->addWidget(comboLabel);
  top->addWidget(combo_);
  top->addStretch(1);
  auto* exportButton = new QPushButton(tr("Export compensation…"), this);
  exportButton->setObjectName(QStringLiteral("thermalExportCompensation"));
  exportButton->setToolTip(
      tr("Write a trained model in a form the machine control runs: an IEC 61131-3 function block, SINUMERIK "
         "or Heidenhain data, ISG axis parameters or a table (metrofit-cli thermal export)"));
  top->addWidget(exportButton);

  auto* notes = new NotesEdit(document_, QString::fromLatin1(study::kThermal), this);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(top);
  layout->addWidget(info_);
  layout->addWidget(stack_, 1);
  layout->addWidget(notes);

  connect(exportButton, &QPushButton::clicked, this, [this] {
    const ThermalComparison* c = models_->comparison();
    if (c == nullptr) {
      QMessageBox::information(this, tr("Export compensation"),
                               tr("Train the models first (Models tab): the export writes a trained model."));
      return;
    }
    QStringList labels;
    std::vector<std::size_t> index;
    int best = -1;
    for (std::size_t i = 0; i < kThermalModelCount; ++i) {
      if (!exportable(*c, i)) continue;
      const QString kind = QString::fromLatin1(thermal::toString(kThermalModelOrder[i]));
      labels << tr("%1 (held-out RMSE %2)").arg(kind, QLocale().toString(c->models[i].heldout.rmse, 'g', 4));
      if (best < 0 ||
          c->models[i].heldout.rmse < c->models[index[static_cast<std::size_t>(best)]].heldout.rmse)
        best = static_cast<int>(index.size());
      index.push_back(i);
    }
    if (index.empty()) {
      QMessageBox::warning(
          this, tr("Export compensation"),
          tr("No trained model can be exported (a model that takes the applied effects' columns cannot: "
             "the control does not have them)."));
      return;
    }
    bool ok = false;
    const QString chosen = QInputDialog::getItem(this, tr("Export compensation"), tr("Model:"), labels,
                                                 std::max(0, best), false, &ok);
    if (!ok) return;
    const std::size_t i = index[static_cast<std::size_t>(std::max<qsizetype>(0, labels.indexOf(chosen)))];
    const thermal::ThermalModel& model = c->models[i].training.model;
    QStringList forms;
    for (thermal::ControlFormat f : thermal::kAllControlFormats)
      if (thermal::controlExportRefusal(model, f).empty()) forms << QString::fromLatin1(thermal::toString(f));
    if (forms.isEmpty()) {
      QMessageBox::warning(
          this, tr("Export compensation"),
          QString::fromStdString(thermal::controlExportRefusal(model, thermal::ControlFormat::St)));
      return;
    }
    const QString form = QInputDialog::getItem(
        this, tr("Export compensation"),
        tr("Form (st: IEC 61131-3 function block; siemens, heidenhain, isg: the control's temperature "
           "compensation; csv: a table):"),
        forms, 0, false, &ok);
    if (!ok) return;
    const thermal::ControlFormat format = thermal::controlFormat(form.toStdString());
    const QString suggested = QFileInfo(document_->fileName()).absolutePath() + QLatin1Char('/') + logId_ +
                              QLatin1Char('_') + QString::fromLatin1(thermal::toString(model.kind)) +
                              QLatin1Char('.') + exportSuffix(format);
    const QString path = QFileDialog::getSaveFileName(this, tr("Export compensation"), suggested);
    if (path.isEmpty()) return;
    try {
      thermal::ControlExportOptions o;
      o.source = logId_.toStdString();
      writeFileAtomic(path.toStdString(), thermal::exportControl(model, format, o));
    } catch (const std::exception& e) {
      QMessageBox::warning(this, tr("Export compensation"),
                           tr("Cannot export the compensation: %1").arg(QString::fromStdString(e.what())));
    }
  });
  connect(combo_, &QComboBox::currentIndexChanged, this, &ThermalPage::showLog);
  connect(document_, &ProjectDocument::changed, this, &ThermalPage::refresh);
  connect(tabs_, &QTabWidget::currentChanged, this, &ThermalPage::onTabChanged);
  // The view's controls (target, inputs, train fraction, seed) are bound to studies.thermal through the
  // shared binding (app/gui/studysettingbinding.h), with the dataset they belong to in the same undo
  // step; refresh() puts them back on undo / redo / load (syncSettingsFromStudy), as it also re-reads
  // the log when the datasets change.
  const QString thermal = QString::fromLatin1(study::kThermal);
  writeSettings_ = bindStudySettings(
      document_, models_, thermal,
      [this, thermal]() -> std::optional<std::vector<StudyEdit>> {
        if (logId_.isEmpty()) return std::nullopt;
        const nlohmann::json dataset = document_->studyValue(thermal, QStringLiteral("/dataset"));
        // The study has one dataset: settings of other logs stay in this session.
        if (!dataset.is_null() && dataset != nlohmann::json(logId_.toStdString())) return std::nullopt;
        const ThermalModelSettings& s = settings_[logId_];
        std::vector<StudyEdit> edits;
        if (dataset.is_null())
          edits.push_back({QStringLiteral("/dataset"), logId_.toStdString(), tr("Choose the thermal log")});
        edits.push_back({QStringLiteral("/target"), s.target, tr("Change the thermal target")});
        edits.push_back({QStringLiteral("/inputs"), s.inputs, tr("Change the thermal inputs")});
        edits.push_back(
            {QStringLiteral("/train_fraction"), s.trainFraction, tr("Change the train fraction")});
        edits.push_back({QStringLiteral("/seed"), s.seed, tr("Change the training seed")});
        return edits;
      },
      {QStringLiteral("/train_fraction"), QStringLiteral("/seed")}, {},
      tr("Change the thermal model settings"));
  connect(models_, &ThermalModelView::settingsEdited, this, &ThermalPage::writeStudySettings);
  // Training the models on a log declares the thermal study on it (when the project has none yet), so
  // that the report of a project built from imported files has its thermal section (undoable).
  connect(models_->trainButton(), &QPushButton::clicked, this, &ThermalPage::writeStudySettings);
  connect(models_, &ThermalModelView::trainingFinished, this, [this](bool completed) {
    if (completed) storeResult();
  });
  connect(models_, &ThermalModelView::settingsEdited, this, &ThermalPage::showStoredResult);
  connect(modular_, &BackgroundRunBase::finished, this, [this] {
    if (std::optional<ModularRun> run = modular_->takeResult()) applyModular(*run);
  });
  connect(modular_, &BackgroundRunBase::failed, this, [this](const QString& message) {
    if (moduleRunActive_) {  // the modules shown stay
      moduleRunActive_ = false;
      models_->setModulesRunning(false);
      models_->setModulesMessage(tr("The module could not be identified again: %1").arg(message));
      return;
    }
    ModularRun run;
    run.error = message;
    applyModular(run);
  });
  connect(modular_, &BackgroundRunBase::cancelled, this, [this] {
    modular_->takeResult();
    if (!moduleRunActive_) return;
    moduleRunActive_ = false;
    models_->setModulesRunning(false);
    models_->setModulesMessage(tr("Cancelled: the modules shown are unchanged."));
  });
  connect(modular_, &BackgroundRunBase::progress, this, [this](double fraction, const QString& text) {
    if (moduleRunActive_) models_->setModulesProgress(fraction, text);
  });
  connect(models_, &ThermalModelView::identifyModuleRequested, this, &ThermalPage::askIdentifyModuleAgain);
  connect(models_, &ThermalModelView::saveModulesRequested, this, &ThermalPage::askSaveModuleModels);
  connect(models_, &ThermalModelView::modulesCancelRequested, this, [this] {
    if (moduleRunActive_) modular_->cancel();
  });
  refresh();
}

ThermalPage::~ThermalPage() {
  modular_->disconnect(this);
  modular_->waitForWorker();
}

QString ThermalPage::currentDataset() const {
  return combo_->currentData().toString();
}

void ThermalPage::selectDataset(const QString& id) {
  const int index = combo_->findData(id);
  if (index >= 0) combo_->setCurrentIndex(index);
}

void ThermalPage::refresh() {
  std::vector<DatasetRef> logs;
  for (const DatasetRef& d : document_->project().datasets) {
    if (datasetKindServes(dataset_kind::kThermalLog, d.kind)) logs.push_back(document_->resolvedDataset(d));
  }
  // Name or notes edits must not re-read the data; nor must a Save As (the same files under paths
  // relative to another folder): the trained models stay. File › New and Open drop everything.
  if (logs == logs_ && generation_ == document_->generation() && combo_->count() > 0) {
    if (modularKey_ == projectFile_) modularKey_ = document_->fileName();
    projectFile_ = document_->fileName();
    if (!writingStudy_) {
      syncSettingsFromStudy();  // undo / redo of a settings edit
      syncModulesFromStudy();   // undo / redo of a module's test
    }
    updateInfo();  // Apply / undo on the diagnosis page
    return;
  }
  logs_ = std::move(logs);
  projectFile_ = document_->fileName();
  generation_ = document_->generation();
  settings_.clear();
  modularDone_ = false;
  modularResult_.reset();
  modularTestLog_.reset();
  models_->setModular(nullptr, nullptr, QString());
  models_->setModulesMessage(QString());
  const QString previous = currentDataset();
  showLog(fillDatasetCombo(combo_, logs_, previous));
}

QString ThermalPage::unshownSetting(const ThermalModelSettings& s) const {
  // The controls would round or clamp these: fitted with what they show, the page would use another
  // value than the study holds (the report uses the study's). Refused like a bad value instead.
  const ThermalModelSettings shown = models_->settings();
  if (std::abs(shown.trainFraction - s.trainFraction) > 1e-9)
    return tr("studies.thermal.train_fraction: %1 cannot be set on the page (it takes 0.01 to 0.99 in steps "
              "of 0.01)")
        .arg(QString::number(s.trainFraction, 'g', 12));
  if (shown.seed != s.seed)
    return tr("studies.thermal.seed: %1 is larger than the page can use (at most %2)")
        .arg(s.seed)
        .arg(std::numeric_limits<int>::max());
  return {};
}

void ThermalPage::showSettingsError(const QString& message) {
  // Refused, not replaced: nothing is fitted with settings the study does not hold.
  settingsInvalid_ = true;
  error_ = message;
  settings_.remove(logId_);
  message_->setText(tr("The thermal study's settings are invalid, nothing is fitted until they are "
                       "corrected (Undo, or the project file):\n%1")
                        .arg(message));
  stack_->setCurrentWidget(message_);
}

void ThermalPage::showLog(int comboIndex) {
  settingsInvalid_ = false;
  error_.clear();
  logId_.clear();
  hysteresisKey_.clear();
  if (comboIndex < 0 || comboIndex >= static_cast<int>(logs_.size())) {
    info_->clear();
    message_->setText(
        tr("This project has no thermal log. Add a dataset of kind \"thermal_log\" to the project "
           "file (a time column, sensor columns and the displacement)."));
    stack_->setCurrentWidget(message_);
    return;
  }
  const DatasetRef& dataset = logs_[static_cast<std::size_t>(comboIndex)];
  const QString path = document_->datasetPath(dataset);
  try {
    log_ = readThermalLog(path.toStdString(), 3, dataset.csv);  // with its dialect, map and interval
    logId_ = QString::fromStdString(dataset.id);
    trend_->setLog(log_);
    const QLocale locale;
    const double spanMin = log_.rows() > 1 ? log_.timeMin.back() - log_.timeMin.front() : 0.0;
    QString info = tr("%1 rows, %2 channels, %3 h.")
                       .arg(log_.rows())
                       .arg(log_.channels.size())
                       .arg(locale.toString(spanMin / 60.0, 'f', 1));
    if (!dataset.licence.empty())
      info += QLatin1Char(' ') + tr("Licence: %1.").arg(QString::fromStdString(dataset.licence));
    if (!dataset.description.empty())
      info.prepend(QString::fromStdString(dataset.description) + QLatin1Char('\n'));
    infoBase_ = info;
    updateInfo();
    if (!settings_.contains(logId_)) {
      const auto study = document_->project().studies.find(study::kThermal);
      try {
        settings_[logId_] = defaultThermalModelSettings(
            log_, study != document_->project().studies.end() ? *study : nlohmann::json::object(),
            dataset.id);
      } catch (const std::exception& e) {
        showSettingsError(QString::fromUtf8(e.what()));
        return;
      }
    }
    settings_[logId_].applied = diagnose::projectThermalApplied(document_->project(), dataset.id);
    models_->setLog(log_, settings_[logId_]);
    if (const QString unshown = unshownSetting(settings_[logId_]); !unshown.isEmpty()) {
      showSettingsError(unshown);
      return;
    }
    showStoredResult();
    stack_->setCurrentWidget(tabs_);
    onTabChanged(tabs_->currentIndex());
  } catch (const std::exception& e) {
    error_ = QString::fromStdString(e.what());
    info_->clear();
    message_->setText(tr("Cannot show this thermal log:\n%1").arg(error_));
    stack_->setCurrentWidget(message_);
  }
}

void ThermalPage::updateInfo() {
  if (logId_.isEmpty()) return;
  const QString elsewhere = appliedElsewhere(document_->project(), "thermal", logId_.toStdString());
  info_->setText(elsewhere.isEmpty()
                     ? infoBase_
                     : infoBase_ + QLatin1Char('\n') +
                           tr("Effects applied on the Diagnosis page belong to the log %1 (the "
                              "one the diagnosis ran on); the models of this log do not include "
                              "them.")
                               .arg(elsewhere));
}

void ThermalPage::writeStudySettings() {
  if (logId_.isEmpty()) return;
  settings_[logId_] = models_->settings();
  writingStudy_ = true;  // refresh() leaves the controls and the modules as they are
  writeSettings_();
  writingStudy_ = false;
}

void ThermalPage::syncSettingsFromStudy() {
  if (logId_.isEmpty()) return;
  const nlohmann::json study = document_->studyValue(QString::fromLatin1(study::kThermal), QString());
  const nlohmann::json dataset =
      study.is_object() ? study.value("dataset", nlohmann::json()) : nlohmann::json();
  // Only the study's dataset (or any log while the study names none) follows the study; the applied
  // effects (Apply / undo on the diagnosis page) follow the project for every log they apply to.
  if (settingsInvalid_) {  // corrected (or still not): show the log again or the error again
    showLog(combo_->currentIndex());
    return;
  }
  ThermalModelSettings s = models_->settings();
  if (dataset.is_null() || dataset == nlohmann::json(logId_.toStdString())) {
    try {
      s = defaultThermalModelSettings(log_, study.is_object() ? study : nlohmann::json::object(),
                                      logId_.toStdString());
    } catch (const std::exception& e) {
      showSettingsError(QString::fromUtf8(e.what()));
      return;
    }
  }
  s.applied = diagnose::projectThermalApplied(document_->project(), logId_.toStdString());
  if (s == models_->settings()) return;
  settings_[logId_] = s;
  models_->setSettings(s);
  if (const QString unshown = unshownSetting(s); !unshown.isEmpty()) {
    showSettingsError(unshown);
    return;
  }
  if (tabs_->currentIndex() == kHysteresisTab) updateHysteresis();
  showStoredResult();
}

const DatasetRef* ThermalPage::currentLogRef() const {
  for (const DatasetRef& d : logs_)
    if (QString::fromStdString(d.id) == logId_) return &d;
  return nullptr;
}

void ThermalPage::storeResult() {
  const ThermalComparison* c = models_->comparison();
  const DatasetRef* dataset = currentLogRef();
  if (!c || c->cancelled || !dataset) return;
  try {
    document_->setStoredResult(QString::fromLatin1(study::kThermal), logId_,
                               makeStoredResult(document_->projectPathForDatasets().toStdString(), *dataset,
                                                thermalSettingsJson(c->settings), thermalResultJson(*c)));
  } catch (const std::exception&) {
    // The log cannot be read any more (moved while training): nothing is stored, the page shows the run.
  }
}

QString ThermalPage::storedResultText() const {
  const DatasetRef* dataset = currentLogRef();
  if (!dataset) return {};
  const StoredResult stored =
      storedResult(document_->project(), document_->projectPathForDatasets().toStdString(), study::kThermal,
                   *dataset, thermalSettingsJson(models_->settings()));
  if (const std::optional<QString> state = storedStateText(
          stored, {tr("The stored result (computed %1) is out of date: the model settings changed since. Not "
                      "trained with these settings yet: Train (Ctrl+R)."),
                   tr("The stored result (computed %1) is out of date: the data file changed since. Train "
                      "(Ctrl+R) to fit the models on the data as it is now."),
                   tr("The stored result (computed %1) cannot be checked: the data file cannot be read.")}))
    return *state;
  const QString when = storedTimeText(stored.computed);
  const nlohmann::json& e = stored.entry;
  const int ti = log_.indexOf(models_->settings().target);
  const QString unit =
      ti >= 0 ? QLatin1Char(' ') + displayUnit(log_.channels[static_cast<std::size_t>(ti)].unit) : QString();
  const QLocale locale;
  QStringList models;
  QString bestFigure;
  const std::string best = e.value("best_model", nlohmann::json()).is_string()
                               ? e["best_model"].get<std::string>()
                               : std::string();
  if (e.contains("models") && e["models"].is_array()) {
    for (const nlohmann::json& m : e["models"]) {
      if (!m.is_object() || !m.value("model", nlohmann::json()).is_string()) continue;
      const std::string name = m["model"].get<std::string>();
      const nlohmann::json h = m.value("heldout_rmse", nlohmann::json());
      const QString figure =
          h.is_number() ? locale.toString(h.get<double>(), 'f', 2) + unit : tr("not fitted");
      models << QStringLiteral("%1 %2").arg(QString::fromStdString(name), figure);
      if (name == best) bestFigure = figure;
    }
  }
  const QString bestText =
      best.empty()
          ? tr("no model usable for compensation")
          : tr("best usable model %1 (held-out RMSE %2)").arg(QString::fromStdString(best), bestFigure);
  return tr("From the saved project, computed %1 with these settings on this data: %2. Held-out RMSE: %3. "
            "Train (Ctrl+R) to see the charts.")
      .arg(when, bestText, models.join(QStringLiteral(", ")));
}

void ThermalPage::showStoredResult() {
  if (models_->comparison() || models_->isRunning()) return;
  const QString text = storedResultText();
  if (!text.isEmpty()) models_->setStatusText(text);
}

void ThermalPage::onTabChanged(int index) {
  if (logId_.isEmpty()) return;
  if (index == kHysteresisTab) updateHysteresis();
  if (index == kModelsTab) updateModular(false);
}

void ThermalPage::updateHysteresis() {
  const ThermalModelSettings s = models_->settings();
  const QString key = settingsKey(logId_, s);
  if (key == hysteresisKey_) return;
  hysteresisKey_ = key;
  hysteresis_->analyseLater(log_, s.target, s.inputs);  // shown when the worker is done
}

void ThermalPage::updateModular(bool now) {
  if (modularDone_ && modularKey_ == projectFile_) return;
  if (modular_->isRunning()) {
    if (now) modular_->waitForFinished();  // applies it
    return;
  }
  const DatasetRef* z = document_->project().dataset(kModularZId);
  const DatasetRef* c = document_->project().dataset(kModularCId);
  const DatasetRef* h = document_->project().dataset(kModularCombinedId);
  if (!z || !c || !h) return;
  const std::string paths[3] = {document_->datasetPath(*z).toStdString(),
                                document_->datasetPath(*c).toStdString(),
                                document_->datasetPath(*h).toStdString()};
  const CsvReadOptions csv[3] = {z->csv, c->csv, h->csv};  // each log's dialect and mapping
  modularKey_ = projectFile_;
  modularDone_ = true;
  // The modules on the tests the study names for them (studies.thermal.modules): every thermal log.
  std::map<std::string, std::pair<std::string, CsvReadOptions>> sources;
  for (const DatasetRef& d : document_->project().datasets)
    if (datasetKindServes(dataset_kind::kThermalLog, d.kind))
      sources[d.id] = {document_->datasetPath(d).toStdString(), d.csv};
  const nlohmann::json study = document_->studyValue(QString::fromLatin1(study::kThermal), QString());
  // A read error or a failed fit arrives as failed(message) and is shown in the info line.
  moduleRunActive_ = false;
  modular_->setSynchronous(now);
  modular_->start([paths, csv, sources, study](RunObserver&) -> ModularRun {
    ModularRun run;
    const ThermalLog zl = readThermalLog(paths[0], 3, csv[0]);
    const ThermalLog cl = readThermalLog(paths[1], 3, csv[1]);
    run.testLog = std::make_shared<ThermalLog>(readThermalLog(paths[2], 3, csv[2]));
    const ThermalModelSettings s = defaultThermalModelSettings(*run.testLog, nlohmann::json::object(), {});
    run.result = std::make_shared<ModularComparison>(compareModularModels(
        {&zl, &cl}, *run.testLog, s.target, modularInputs(*run.testLog), 1, {}, {kModularZId, kModularCId}));
    std::map<std::string, ThermalLog> logs;
    const auto logOf = [&](const std::string& id) -> const ThermalLog* {
      const auto source = sources.find(id);
      if (source == sources.end()) return nullptr;
      auto it = logs.find(id);
      if (it == logs.end())
        it = logs.emplace(id, readThermalLog(source->second.first, 3, source->second.second)).first;
      return &it->second;
    };
    ModularModules modules = run.result->modules;
    try {
      if (identifyModulesOnStudyTests(modules, study, logOf, *run.testLog, s.target, 1))
        run.result->modules = std::move(modules);
    } catch (const std::exception& e) {
      run.moduleError = QString::fromStdString(e.what());
    }
    return run;
  });
}

QString ThermalPage::modularDescription(const ModularComparison& m) const {
  QStringList inputs;
  for (const std::string& s : m.inputs) inputs << QString::fromStdString(s);
  if (!m.fitted(0)) {
    return tr("Fitted on %1 and %2 together, predicting %3 (target %4; inputs %5; seed 1): GNNMCI(1,N) "
              "not fitted: %6")
        .arg(QString::fromLatin1(kModularZId), QString::fromLatin1(kModularCId),
             QString::fromLatin1(kModularCombinedId), QString::fromStdString(m.target),
             inputs.join(QStringLiteral(", ")), QString::fromStdString(m.failed[0]));
  }
  const double reduction = 100.0 * m.models[0].reductionPeak;
  return tr("Fitted on %1 and %2 together, predicting %3 (target %4; inputs %5; seed 1): "
            "GNNMCI(1,N) reduces the "
            "combined test's error by %6 %.")
      .arg(QString::fromLatin1(kModularZId), QString::fromLatin1(kModularCId),
           QString::fromLatin1(kModularCombinedId), QString::fromStdString(m.target),
           inputs.join(QStringLiteral(", ")))
      .arg(QLocale().toString(reduction, 'f', 1));
}

void ThermalPage::applyModular(const ModularRun& run) {
  const bool moduleRun = std::exchange(moduleRunActive_, false);
  if (moduleRun) models_->setModulesRunning(false);
  if (!run.error.isEmpty() || !run.result) {
    if (moduleRun) return;  // the modules shown stay
    modularResult_.reset();
    modularTestLog_.reset();
    models_->setModular(nullptr, nullptr, QString());
    if (!run.error.isEmpty())
      info_->setText(info_->text() + QLatin1Char('\n') + tr("Modular case: %1").arg(run.error));
    return;
  }
  modularResult_ = run.result;
  modularTestLog_ = run.testLog;
  models_->setModular(run.result, run.testLog.get(), modularDescription(*run.result));
  const ModularModules& mm = run.result->modules;
  if (!run.moduleError.isEmpty()) {
    models_->setModulesMessage(tr("The modules' tests of the thermal study cannot be used (%1); the modules "
                                  "are identified on their own tests.")
                                   .arg(run.moduleError));
  } else if (moduleRun && mm.evaluation) {
    const int ti = run.testLog ? run.testLog->indexOf(run.result->target) : -1;
    const QString unit =
        ti >= 0 ? QLatin1Char(' ') + displayUnit(run.testLog->channels[static_cast<std::size_t>(ti)].unit)
                : QString();
    models_->setModulesMessage(
        tr("Modules identified on %1; the others kept their models. The modules' sum: RMSE %2%3 on %4.")
            .arg(run.storeDataset.isEmpty() ? tr("the tests of the thermal study") : run.storeDataset,
                 QLocale().toString(mm.evaluation->test.rmse, 'f', 2), unit,
                 QString::fromLatin1(kModularCombinedId)));
  } else {
    models_->setModulesMessage(QString());
  }
  if (moduleRun && !run.storeModule.isEmpty()) {
    // The module's test as a project setting (one undoable step); the modules shown already follow it.
    writingStudy_ = true;
    document_->endEditSequence();
    document_->setStudyValue(QString::fromLatin1(study::kThermal),
                             QStringLiteral("/modules/%1/dataset").arg(run.storeModule),
                             run.storeDataset.toStdString(),
                             tr("Identify module %1 again on %2").arg(run.storeModule, run.storeDataset));
    document_->endEditSequence();
    writingStudy_ = false;
  }
  syncModulesFromStudy();  // an undo / redo while the run was going on
}

bool ThermalPage::startModulesRun(const nlohmann::json& thermalStudy, const QString& storeModule,
                                  const QString& storeDataset, bool now) {
  if (!modularResult_ || !modularTestLog_ || !modularResult_->modules.evaluation || modular_->isRunning())
    return false;
  std::map<std::string, std::pair<std::string, CsvReadOptions>> sources;
  for (const DatasetRef& d : document_->project().datasets)
    if (datasetKindServes(dataset_kind::kThermalLog, d.kind))
      sources[d.id] = {document_->datasetPath(d).toStdString(), d.csv};
  const std::shared_ptr<const ModularComparison> base = modularResult_;
  const std::shared_ptr<ThermalLog> testLog = modularTestLog_;
  moduleRunActive_ = true;
  models_->setModulesRunning(true);
  models_->setModulesMessage(tr("Identifying…"));
  modular_->setSynchronous(now);
  modular_->start([base, testLog, sources, thermalStudy, storeModule, storeDataset](RunObserver& observer) {
    ModularRun run;
    run.moduleRun = true;
    run.storeModule = storeModule;
    run.storeDataset = storeDataset;
    run.testLog = testLog;
    // Only the modules: the pooled models and every other module are copied as they are.
    auto result = std::make_shared<ModularComparison>(*base);
    std::map<std::string, ThermalLog> logs;
    const auto logOf = [&](const std::string& id) -> const ThermalLog* {
      const auto source = sources.find(id);
      if (source == sources.end()) return nullptr;
      observer.report(0.1, tr("Reading %1…").arg(QString::fromStdString(id)));
      auto it = logs.find(id);
      if (it == logs.end())
        it = logs.emplace(id, readThermalLog(source->second.first, 3, source->second.second)).first;
      observer.report(0.3, tr("Identifying on %1…").arg(QString::fromStdString(id)));
      return &it->second;
    };
    if (identifyModulesOnStudyTests(result->modules, thermalStudy, logOf, *testLog, result->target, 1,
                                    &observer) &&
        !observer.isCancelled())
      run.result = std::move(result);
    observer.report(1.0);
    return run;
  });
  return true;
}

void ThermalPage::syncModulesFromStudy() {
  if (!modularResult_ || !modularResult_->modules.evaluation || modular_->isRunning()) return;
  const nlohmann::json study = document_->studyValue(QString::fromLatin1(study::kThermal), QString());
  const ModularModules& mm = modularResult_->modules;
  if (studyModuleTests(study, mm.names) == mm.tests) return;
  startModulesRun(study, QString(), QString(), modular_->isSynchronous());
}

bool ThermalPage::identifyModuleAgain(int module, const QString& datasetId, bool now) {
  if (!modularResult_ || module < 0 ||
      static_cast<std::size_t>(module) >= modularResult_->modules.names.size())
    return false;
  const DatasetRef* d = document_->project().dataset(datasetId.toStdString());
  if (d == nullptr || !datasetKindServes(dataset_kind::kThermalLog, d->kind)) return false;
  const std::string name = modularResult_->modules.names[static_cast<std::size_t>(module)];
  nlohmann::json study = document_->studyValue(QString::fromLatin1(study::kThermal), QString());
  if (!study.is_object()) study = nlohmann::json::object();
  study["modules"][name]["dataset"] = datasetId.toStdString();
  return startModulesRun(study, QString::fromStdString(name), datasetId, now);
}

bool ThermalPage::saveModuleModels(const QString& folder) {
  if (!modularResult_ || !modularResult_->modules.evaluation) return false;
  try {
    thermal::saveThermalModules(modularResult_->modules.fitted, folder.toStdString());
    QStringList files;
    for (const thermal::ThermalModule& m : modularResult_->modules.fitted)
      files << QString::fromStdString(m.name) + QStringLiteral(".json");
    models_->setModulesMessage(
        tr("Saved %1 to %2.").arg(files.join(QStringLiteral(", ")), QDir::toNativeSeparators(folder)));
    return true;
  } catch (const std::exception& e) {
    models_->setModulesMessage(tr("Cannot save the module models: %1").arg(QString::fromStdString(e.what())));
    return false;
  }
}

void ThermalPage::askIdentifyModuleAgain(int module) {
  if (!modularResult_ || module < 0 ||
      static_cast<std::size_t>(module) >= modularResult_->modules.names.size())
    return;
  const ModularModules& mm = modularResult_->modules;
  const QString name = QString::fromStdString(mm.names[static_cast<std::size_t>(module)]);
  QStringList ids;
  for (const DatasetRef& d : document_->project().datasets)
    if (datasetKindServes(dataset_kind::kThermalLog, d.kind) && d.id != kModularCombinedId)
      ids << QString::fromStdString(d.id);
  if (ids.isEmpty()) return;
  const QString current = static_cast<std::size_t>(module) < mm.tests.size()
                              ? QString::fromStdString(mm.tests[static_cast<std::size_t>(module)])
                              : name;
  bool ok = false;
  const QString id = QInputDialog::getItem(
      this, tr("Identify %1 again").arg(name),
      tr("The test to identify module %1 on (a new test of its drive; now %2). The other modules keep "
         "their models.")
          .arg(name, current),
      ids, std::max<qsizetype>(0, ids.indexOf(current)), false, &ok);
  if (ok && !id.isEmpty()) identifyModuleAgain(module, id);
}

void ThermalPage::askSaveModuleModels() {
  const QString folder = QFileDialog::getExistingDirectory(this, tr("Save module models to"),
                                                           QFileInfo(document_->fileName()).absolutePath());
  if (!folder.isEmpty()) saveModuleModels(folder);
}

void ThermalPage::showView(const QString& view) {
  if (view == QLatin1String("trend")) {
    tabs_->setCurrentIndex(kTrendTab);
  } else if (view == QLatin1String("hysteresis")) {
    tabs_->setCurrentIndex(kHysteresisTab);
    if (logId_.isEmpty()) return;
    updateHysteresis();
    hysteresis_->finishAnalysis();
  } else if (view == QLatin1String("models")) {
    tabs_->setCurrentIndex(kModelsTab);
    if (logId_.isEmpty()) return;
    updateModular(true);
    if (!models_->comparison() && !models_->isRunning()) models_->trainNow();
  }
}

}  // namespace metrofit
