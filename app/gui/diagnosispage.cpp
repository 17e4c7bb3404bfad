#include "app/gui/diagnosispage.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeySequence>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSplitter>
#include <QStackedWidget>
#include <QTabWidget>
#include <QTableWidget>
#include <QToolButton>
#include <QUndoCommand>
#include <QUndoStack>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <set>

#include "app/gui/notesedit.h"
#include "app/gui/studysettingbinding.h"
#include "core/project/stored_results.h"
#include "core/study/study_settings.h"
#include "core/study/thermal_comparison.h"
#include "core/thermal/thermal_log.h"
#include "widgets/diagnose/coretexts.h"
#include "widgets/diagnose/residualchecktext.h"
#include "widgets/diagnose/residualcheckview.h"
#include "widgets/diagnose/residualplot.h"
#include "widgets/document/projectdocument.h"
#include "widgets/document/storedresulttext.h"
#include "widgets/document/studyinfo.h"

namespace metrofit {
namespace {

/// The settings' key with the paths cleaned: a Save As to another folder resolves the same files as
/// "<new folder>/../data/x.csv", which must not read as other data (the result stays).
std::string pageSettingsKey(DiagnosisSettings s) {
  s.datasetPath = QDir::cleanPath(QString::fromStdString(s.datasetPath)).toStdString();
  if (!s.modelPath.empty()) s.modelPath = QDir::cleanPath(QString::fromStdString(s.modelPath)).toStdString();
  return diagnosisSettingsKey(s);
}

/// Long parameter lists (cyclic: four values) must leave room for the evidence; tooltips show all.
constexpr int kMaxParameterColumnWidth = 280;

enum Column {
  ColRound,
  ColEffect,
  ColParameters,
  ColRmse,
  ColHeldout,
  ColEvidence,
  ColAccepted,
  ColumnCount
};

QString domainTitle(DiagnosisDomain d) {
  switch (d) {
    case DiagnosisDomain::Thermal:
      return DiagnosisPage::tr("Thermal");
    case DiagnosisDomain::Kinematic:
      return DiagnosisPage::tr("Kinematic");
    case DiagnosisDomain::Setup:
      return DiagnosisPage::tr("Setup");
    case DiagnosisDomain::Matching:
      return DiagnosisPage::tr("Matching");
  }
  return {};
}

/// "um" -> "µm" for display (core writes the ASCII unit names of docs/file-formats.md).
QString displayUnits(const std::string& units) {
  return displayUnit(QString::fromStdString(units));
}

/// A number in the user's locale ("n/a" when not finite), `digits` significant digits.
QString num(double v, int digits = 4) {
  return localNumber(v, digits);
}

/// Unit of a parameter from its name suffix (docs/file-formats.md#effect-catalogue) ("tau_min" -> "min").
QString unitOf(const std::string& name) {
  static const std::pair<const char*, const char*> kSuffixes[] = {
      {"mm_per_part", QT_TRANSLATE_NOOP("metrofit::DiagnosisPage", "mm/part")},
      {"mm_per_min", "mm/min"},
      {"um_per_min", "µm/min"},
      {"_min", "min"},
      {"_mm", "mm"},
      {"_um", "µm"},
      {"_ppm", "ppm"},
      {"_deg", "deg"},
      {"_s", "s"}};
  for (const auto& [suffix, unit] : kSuffixes) {
    const std::string s = suffix;
    if (name.size() >= s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0)
      return DiagnosisPage::tr(unit);  // only "mm/part" has a word to translate
  }
  if (name == "mm") return QStringLiteral("mm");
  if (name == "ppm") return QStringLiteral("ppm");
  return {};
}

QString parameterText(const diagnose::Candidate& c, const QString& units) {
  QStringList parts;
  for (const diagnose::Parameter& p : c.parameters) {
    if (c.generic && p.name == "form") continue;  // shown first, translated (fillTable)
    // Display name (translated) and the value in the user's locale (the JSON and the report keep the keys).
    const double* v = std::get_if<double>(&p.value);
    QString s = parameterDisplayName(p.name) + QStringLiteral(" = ") +
                (v ? num(*v) : QString::fromStdString(std::get<std::string>(p.value)));
    if (p.standardError) s += QStringLiteral(" ± ") + num(*p.standardError, 2);
    // A generic effect's sizes are in the data's units (residual_check.h summariseGeneric).
    const bool dataUnits =
        c.generic && (p.name == "rms" || p.name == "range" || p.name == "step" || p.name == "amplitude");
    const QString unit = p.name == "per_min" ? units + QStringLiteral("/min")
                         : dataUnits         ? units
                                             : unitOf(p.name);
    if (!unit.isEmpty() && std::holds_alternative<double>(p.value)) s += QLatin1Char(' ') + unit;
    parts << s;
  }
  return parts.join(QStringLiteral("; "));
}

/// The figures of a run as the status line shows them: "rmse a → b u, held-out rmse ..., max |e| ...
/// Accepted: x, y (N candidates tried)." The same for a run and for a stored result.
QString summaryText(double baseline, double after, std::optional<double> heldoutBaseline,
                    std::optional<double> heldoutFinal, double maxBaseline, double maxFinal,
                    const QStringList& accepted, int tried, const QString& u) {
  QString text = DiagnosisPage::tr("rmse %1 → %2 %3").arg(num(baseline), num(after), u);
  if (heldoutBaseline && heldoutFinal)
    text += DiagnosisPage::tr(", held-out rmse %1 → %2 %3").arg(num(*heldoutBaseline), num(*heldoutFinal), u);
  text += DiagnosisPage::tr(", max |e| %1 → %2 %3").arg(num(maxBaseline), num(maxFinal), u);
  if (accepted.empty())
    text += DiagnosisPage::tr(". No undeclared effect found (%1 candidates tried).").arg(tried);
  else
    text += DiagnosisPage::tr(". Accepted: %1 (%2 candidates tried).")
                .arg(accepted.join(QStringLiteral(", ")))
                .arg(tried);
  return text;
}

std::optional<double> storedOptional(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  if (it == j.end()) return std::nullopt;
  return it->is_number() ? it->get<double>() : std::nan("");
}

int domainIndex(DiagnosisDomain d) {
  for (int i = 0; i < 4; ++i)
    if (kDiagnosisDomains[i] == d) return i;
  return 0;
}

/// The dataset kind a key of the domain's block names (DiagnosisDomainSettings::fields).
std::string fieldKind(const std::string& domain, const std::string& key) {
  for (const SettingField& f : DiagnosisDomainSettings::fields(domain))
    if (f.key == key) return f.datasetKind;
  return {};
}

}  // namespace

DiagnosisPage::DiagnosisPage(ProjectDocument* document, QWidget* parent)
    : QWidget(parent),
      document_(document),
      domainCombo_(new QComboBox(this)),
      info_(new QLabel(this)),
      status_(new QLabel(this)),
      notes_(new QLabel(this)),
      runButton_(new QPushButton(tr("&Run"), this)),
      cancelButton_(new QPushButton(tr("Cancel"), this)),
      applyButton_(new QPushButton(tr("&Apply to model"), this)),
      progress_(new QProgressBar(this)),
      stack_(new QStackedWidget(this)),
      content_(new QSplitter(Qt::Vertical, this)),
      message_(new QLabel(this)),
      plotCombo_(new QComboBox(this)),
      plot_(nullptr),
      bars_(nullptr),
      table_(new QTableWidget(this)),
      tabs_(new QTabWidget(this)),
      check_(new ResidualCheckView(this)),
      controls_(new QStackedWidget(this)),
      trainFraction_(new QDoubleSpinBox(this)),
      feed_(new QDoubleSpinBox(this)),
      setupModel_(new QComboBox(this)),
      tolerance_(new QDoubleSpinBox(this)),
      thermalTarget_(new QComboBox(this)),
      thermalInputs_(new QToolButton(this)),
      thermalInputsMenu_(new QMenu(thermalInputs_)),
      run_(new BackgroundRun<diagnose::Diagnosis>(this)) {
  auto* title = new QLabel(studyTitle(QString::fromLatin1(study::kDiagnosis)), this);
  QFont titleFont = title->font();
  titleFont.setPointSizeF(titleFont.pointSizeF() * 1.4);
  titleFont.setBold(true);
  title->setFont(titleFont);
  title->setToolTip(studySummary(QString::fromLatin1(study::kDiagnosis)));

  domainCombo_->setObjectName(QStringLiteral("diagnosisDomain"));
  for (DiagnosisDomain d : kDiagnosisDomains) domainCombo_->addItem(domainTitle(d), static_cast<int>(d));
  domainCombo_->setToolTip(tr("The study whose declared model is diagnosed"));
  runButton_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
  runButton_->setToolTip(
      tr("Fit the declared model, try the candidate effects it lacks, accept those the evidence "
         "supports (Ctrl+R)"));
  cancelButton_->setShortcut(QKeySequence(Qt::Key_Escape));
  cancelButton_->setToolTip(tr("Stop the loop; the rounds done so far are shown (Esc)"));
  cancelButton_->setEnabled(false);
  applyButton_->setObjectName(QStringLiteral("diagnosisApply"));
  applyButton_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_A));
  applyButton_->setToolTip(
      tr("Add the accepted effects to the study's model in the project (undoable, Ctrl+Shift+A)"));
  applyButton_->setEnabled(false);
  progress_->setRange(0, 0);
  progress_->setMaximumWidth(160);
  progress_->setVisible(false);
  info_->setObjectName(QStringLiteral("diagnosisInfo"));
  info_->setWordWrap(true);
  info_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  status_->setObjectName(QStringLiteral("diagnosisStatus"));
  status_->setWordWrap(true);
  status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  notes_->setObjectName(QStringLiteral("diagnosisNotes"));
  notes_->setWordWrap(true);
  notes_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  notes_->setToolTip(tr("The declared model as fitted before any effect was added"));
  notes_->setVisible(false);
  message_->setObjectName(QStringLiteral("diagnosisMessage"));
  message_->setWordWrap(true);
  message_->setAlignment(Qt::AlignCenter);
  message_->setTextInteractionFlags(Qt::TextSelectableByMouse);

  // Plot (with the effect selector) and error bars side by side, the candidate table below.
  plot_ = new ResidualPlotView(this);
  plot_->setObjectName(QStringLiteral("diagnosisResidualPlot"));
  bars_ = new ErrorBarsView(this);
  bars_->setObjectName(QStringLiteral("diagnosisErrorBars"));
  plotCombo_->setObjectName(QStringLiteral("diagnosisPlotEffect"));
  plotCombo_->setToolTip(tr("The effect whose residual plot is shown"));
  auto* plotBox = new QWidget(this);
  auto* plotLayout = new QVBoxLayout(plotBox);
  plotLayout->setContentsMargins(0, 0, 0, 0);
  auto* plotTop = new QHBoxLayout;
  auto* plotLabel = new QLabel(tr("Residual &plot of:"), plotBox);
  plotLabel->setBuddy(plotCombo_);
  plotTop->addWidget(plotLabel);
  plotTop->addWidget(plotCombo_, 1);
  plotLayout->addLayout(plotTop);
  plotLayout->addWidget(plot_, 1);
  auto* charts = new QSplitter(Qt::Horizontal, content_);
  charts->setObjectName(QStringLiteral("diagnosisChartsSplitter"));
  charts->addWidget(plotBox);
  charts->addWidget(bars_);
  charts->setStretchFactor(0, 5);
  charts->setStretchFactor(1, 2);
  charts->setChildrenCollapsible(false);

  table_->setObjectName(QStringLiteral("diagnosisCandidates"));
  table_->setColumnCount(ColumnCount);
  table_->setHorizontalHeaderLabels({tr("Round"), tr("Effect"), tr("Parameters (± standard error)"),
                                     tr("rmse before → after"), tr("held-out rmse"), tr("Evidence"),
                                     tr("Accepted")});
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setAlternatingRowColors(true);
  // The evidence wraps onto higher rows instead of being cut short ("validation rmse 4.08 → 0....").
  table_->setWordWrap(true);
  table_->setTextElideMode(Qt::ElideNone);
  table_->verticalHeader()->hide();
  table_->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setSectionResizeMode(ColEvidence, QHeaderView::Stretch);
  table_->horizontalHeader()->setSectionResizeMode(ColParameters, QHeaderView::Interactive);
  // The stretched evidence column narrows when the window does: its rows grow again (once per change).
  connect(table_->horizontalHeader(), &QHeaderView::sectionResized, this, [this](int column) {
    if (column == ColEvidence || column == ColParameters)
      QMetaObject::invokeMethod(table_, &QTableWidget::resizeRowsToContents, Qt::QueuedConnection);
  });
  table_->setToolTip(
      tr("Every candidate effect tried, in the order tried (Ctrl+C copies the selected rows)"));
  auto* copy = new QAction(tr("&Copy"), table_);
  copy->setShortcut(QKeySequence::Copy);
  copy->setShortcutContext(Qt::WidgetShortcut);
  table_->addAction(copy);
  table_->setContextMenuPolicy(Qt::ActionsContextMenu);
  connect(copy, &QAction::triggered, this, &DiagnosisPage::copySelection);

  content_->addWidget(charts);
  content_->addWidget(table_);
  content_->setObjectName(QStringLiteral("diagnosisContentSplitter"));
  content_->setStretchFactor(0, 1);  // equal: the wrapped evidence rows are higher than one line
  content_->setStretchFactor(1, 1);
  content_->setChildrenCollapsible(false);
  check_->setObjectName(QStringLiteral("diagnosisResidualCheck"));
  tabs_->setObjectName(QStringLiteral("diagnosisTabs"));
  tabs_->addTab(content_, tr("&Effects"));
  tabs_->addTab(check_, tr("Residual chec&k"));
  tabs_->setTabToolTip(0,
                       tr("The candidate effects tried, their residual plots and the error before / after"));
  tabs_->setTabToolTip(1, tr("What the final residual still depends on: tests, structure, outliers and the "
                             "residual against the variable of the strongest structure"));
  stack_->addWidget(tabs_);
  stack_->addWidget(message_);

  auto* top = new QHBoxLayout;
  auto* domainLabel = new QLabel(tr("&Domain:"), this);
  domainLabel->setBuddy(domainCombo_);
  top->addWidget(title);
  top->addSpacing(16);
  top->addWidget(domainLabel);
  top->addWidget(domainCombo_);
  top->addStretch(1);
  top->addWidget(progress_);
  top->addWidget(runButton_);
  top->addWidget(cancelButton_);
  top->addWidget(applyButton_);

  auto* notes = new NotesEdit(document_, QString::fromLatin1(study::kDiagnosis), this);

  buildControls();

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(top);
  layout->addWidget(controls_);
  layout->addWidget(info_);
  layout->addWidget(status_);
  layout->addWidget(notes_);
  layout->addWidget(stack_, 1);
  layout->addWidget(notes);

  connect(domainCombo_, &QComboBox::currentIndexChanged, this, [this] {
    controls_->setCurrentIndex(domainIndex(domain()));
    result_.reset();
    settingsKey_.clear();
    refresh();
  });
  connect(plotCombo_, &QComboBox::currentIndexChanged, this, &DiagnosisPage::showPlot);
  connect(runButton_, &QPushButton::clicked, this, &DiagnosisPage::startRun);
  connect(cancelButton_, &QPushButton::clicked, this, &DiagnosisPage::cancelRun);
  connect(applyButton_, &QPushButton::clicked, this, [this] { applyAccepted(); });
  connect(run_, &BackgroundRunBase::progress, this, [this](double, const QString& text) {
    if (!text.isEmpty()) status_->setText(text);
  });
  const auto ended = [this] {
    setRunning(false);
    if (std::optional<diagnose::Diagnosis> r = run_->takeResult()) {
      result_ = std::move(*r);
      if (settings_) settingsKey_ = pageSettingsKey(*settings_);
      storeResult(runDatasetId_, runSettings_);
      showResult();
    }
    emit finished();
  };
  connect(run_, &BackgroundRunBase::finished, this, ended);
  connect(run_, &BackgroundRunBase::cancelled, this, ended);
  connect(run_, &BackgroundRunBase::failed, this, [this](const QString& message) {
    setRunning(false);
    status_->setText(tr("The diagnosis failed: %1").arg(message));
    emit finished();
  });
  connect(document_, &ProjectDocument::changed, this, &DiagnosisPage::refresh);
  refresh();
}

DiagnosisPage::~DiagnosisPage() {
  run_->cancel();
  run_->waitForWorker();
}

void DiagnosisPage::setDomain(DiagnosisDomain domain) {
  const int index = domainCombo_->findData(static_cast<int>(domain));
  if (index >= 0) domainCombo_->setCurrentIndex(index);
}

DiagnosisDomain DiagnosisPage::domain() const {
  return static_cast<DiagnosisDomain>(domainCombo_->currentData().toInt());
}

QString DiagnosisPage::message() const {
  return stack_->currentWidget() == message_ ? message_->text() : QString();
}

QString DiagnosisPage::statusText() const {
  return status_->text();
}

QString DiagnosisPage::notesText() const {
  return notes_->text();
}

bool DiagnosisPage::isRunning() const {
  return run_->isRunning();
}

void DiagnosisPage::showMessage(const QString& text) {
  message_->setText(text);
  stack_->setCurrentWidget(message_);
  runButton_->setEnabled(false);
  applyButton_->setEnabled(false);
}

void DiagnosisPage::refresh() {
  if (isRunning()) return;
  if (generation_ != document_->generation()) {  // File › New, Open: nothing of the last project stays
    generation_ = document_->generation();
    result_.reset();
    settingsKey_.clear();
  }
  settings_.reset();
  settingsError_.clear();
  fillControls();
  const DiagnosisDomain d = domain();
  const QString key = QString::fromLatin1(diagnosisDomainKey(d));
  try {
    settings_ = diagnosisSettings(document_->project(), document_->fileName().toStdString(), d);
  } catch (const std::exception& e) {
    info_->clear();
    notes_->clear();
    notes_->setVisible(false);
    status_->clear();
    result_.reset();
    settingsKey_.clear();
    if (hasDiagnosisSettings(document_->project(), d)) {
      // Refused, not replaced: nothing runs with settings the study does not hold.
      settingsError_ = QString::fromUtf8(e.what());
      showMessage(tr("Diagnosis, %1: the settings are invalid; nothing runs until they are corrected "
                     "(above, Undo, or the project file under studies.diagnosis.%2):\n%3")
                      .arg(domainTitle(d), key, settingsError_));
    } else if (datasetCombos_[domainIndex(d)]->count() > 0) {
      showMessage(tr("Diagnosis, %1: choose the data to diagnose above (Data).").arg(domainTitle(d)));
    } else {
      showMessage(tr("Diagnosis, %1: the project has no data for it yet. Import it with File › Import data "
                     "(Ctrl+I).")
                      .arg(domainTitle(d)));
    }
    return;
  }
  const DiagnosisSettings& s = *settings_;
  QString info = tr("Data: %1").arg(QString::fromStdString(s.datasetId));
  switch (d) {
    case DiagnosisDomain::Thermal: {
      QStringList inputs;
      for (const auto& in : s.inputs) inputs << QString::fromStdString(in);
      info +=
          tr("; target %1; declared inputs %2; fitted on the first %3 % of the rows, held out on the rest.")
              .arg(QString::fromStdString(s.target), inputs.join(QStringLiteral(", ")))
              .arg(QLocale().toString(s.trainFraction * 100.0, 'g', 3));
      break;
    }
    case DiagnosisDomain::Kinematic:
      info += tr("; declared model: Cartesian actuator errors (origin, axis angles); feed %1 mm/min.")
                  .arg(QLocale().toString(s.feedMmPerMin, 'g', 6));
      break;
    case DiagnosisDomain::Setup:
      info += tr("; setup model %1; declared model: constant setup-data errors.")
                  .arg(QString::fromStdString(s.modelId));
      break;
    case DiagnosisDomain::Matching:
      info += tr("; declared model: rigid posture; tolerance ±%1 mm.")
                  .arg(QLocale().toString(s.toleranceMm, 'g', 4));
      break;
  }
  if (!s.applied.empty()) {
    QStringList names;
    for (const auto& e : s.applied) {
      if (e.is_object() && e.contains("name") && e["name"].is_string())
        names << QString::fromStdString(e["name"].get<std::string>());
    }
    info += QLatin1Char(' ') + tr("Applied to the model: %1.").arg(names.join(QStringLiteral(", ")));
  }
  info_->setText(info);
  stack_->setCurrentWidget(tabs_);
  runButton_->setEnabled(true);
  if (result_ && settingsKey_ == pageSettingsKey(s)) {
    showResult();
    return;
  }
  result_.reset();
  settingsKey_.clear();
  const QString stored = storedResultText();
  status_->setText(stored.isEmpty() ? tr("Not run yet: press Run (Ctrl+R).") : stored);
  notes_->clear();
  notes_->setVisible(false);
  plotCombo_->clear();
  plot_->clear();
  bars_->clear();
  check_->clear();
  tabs_->setTabText(1, tr("Residual chec&k"));
  table_->setRowCount(0);
  updateApplyButton();
}

void DiagnosisPage::setResult(diagnose::Diagnosis result) {
  if (isRunning()) return;
  result_ = std::move(result);
  settingsKey_ = settings_ ? pageSettingsKey(*settings_) : std::string();
  showResult();
}

bool DiagnosisPage::runNow() {
  if (isRunning()) return false;
  if (!settings_) {
    status_->setText(message_->text());
    return false;
  }
  try {
    const nlohmann::json stored = storedSettings();
    result_ = runDiagnosis(*settings_);
    settingsKey_ = pageSettingsKey(*settings_);
    storeResult(settings_->datasetId, stored);
    showResult();
    return true;
  } catch (const std::exception& e) {
    status_->setText(tr("The diagnosis failed: %1").arg(QString::fromUtf8(e.what())));
    return false;
  }
}

void DiagnosisPage::startRun() {
  if (!settings_ || isRunning()) return;
  setRunning(true);
  status_->setText(tr("Diagnosing …"));
  const DiagnosisSettings settings = *settings_;
  runSettings_ = storedSettings();
  runDatasetId_ = settings.datasetId;
  run_->start([settings](RunObserver& run) {
    long steps = 0;
    // The loops report no fraction: the text names the step and the current rmse.
    FunctionObserver observer([&](const IterationSummary& s) {
      ++steps;
      run.report(-1.0, tr("Diagnosing … step %1, current rmse %2").arg(steps).arg(num(s.best, 3)));
      return run.onIteration(s);
    });
    return runDiagnosis(settings, &observer);
  });
}

void DiagnosisPage::cancelRun() {
  run_->cancel();
}

void DiagnosisPage::setRunning(bool running) {
  runButton_->setEnabled(!running && settings_.has_value());
  cancelButton_->setEnabled(running);
  progress_->setVisible(running);
  domainCombo_->setEnabled(!running);
  controls_->setEnabled(!running);
  updateApplyButton();
}

void DiagnosisPage::updateApplyButton() {
  const QString normal =
      tr("Add the accepted effects to the study's model in the project (undoable, Ctrl+Shift+A)");
  QStringList applicable, left;
  if (result_) {
    for (const diagnose::Candidate* c : result_->accepted())
      (canApplyEffect(result_->domain, *c) ? applicable : left) << QString::fromStdString(c->name);
  }
  applyButton_->setEnabled(!isRunning() && !applicable.isEmpty());
  if (left.isEmpty()) {
    applyButton_->setToolTip(normal);
    return;
  }
  // Only setup leaves effects out: a generic effect of the row, the part or the dimension category
  // says nothing about the next part the setup study predicts.
  const QString why =
      tr("%1: a generic effect of the data row, the part or the dimension says nothing about the next part, "
         "so the study (%2) cannot include it; it is reported here and in the residual check, not applied")
          .arg(left.join(QStringLiteral(", ")), domainTitle(domain()));
  applyButton_->setToolTip(
      applicable.isEmpty() ? tr("Nothing to apply. %1.").arg(why)
                           : normal + QLatin1Char('\n') +
                                 tr("Applies %1 only. %2.").arg(applicable.join(QStringLiteral(", ")), why));
}

void DiagnosisPage::showResult() {
  if (!result_) return;
  const diagnose::Diagnosis& d = *result_;
  const QString u = displayUnits(d.units);
  QStringList names;
  for (const auto* c : d.accepted()) names << QString::fromStdString(c->name);
  QString text = summaryText(d.baseline.rmse, d.final.rmse, d.baseline.heldoutRmse, d.final.heldoutRmse,
                             d.baseline.maxAbs, d.final.maxAbs, names, static_cast<int>(d.effects.size()), u);
  // The loops' stop notes (diagnose::LoopProgress): per candidate "cancelled", per round "stopped by ...".
  if (std::any_of(d.notes.begin(), d.notes.end(), [](const std::string& n) {
        return n == "cancelled" || n.starts_with("stopped by the observer");
      }))
    text += QLatin1Char(' ') + tr("Cancelled: the rounds done so far.");
  status_->setText(text);
  QStringList notes;
  for (std::size_t i = 0; i < d.notes.size(); ++i)
    notes << coreText(i < d.notesParts.size() ? d.notesParts[i] : Phrases{}, d.notes[i]);
  notes_->setText(notes.join(QLatin1Char('\n')));
  notes_->setVisible(!notes.isEmpty());
  fillTable();
  bars_->setDiagnosis(d);
  check_->setDiagnosis(d);
  if (d.residualCheck) {
    text += QLatin1Char(' ') + tr("Residual check: %1.").arg(residualCheckVerdict(*d.residualCheck));
    status_->setText(text);
  }
  tabs_->setTabText(1, !d.residualCheck         ? tr("Residual chec&k")
                       : d.residualCheck->white ? tr("Residual chec&k: white")
                                                : tr("Residual chec&k: structure left"));
  {
    const QSignalBlocker blocker(plotCombo_);
    plotCombo_->clear();
    for (std::size_t i = 0; i < d.effects.size(); ++i) {
      const diagnose::Candidate& c = d.effects[i];
      if (!c.plot) continue;
      plotCombo_->addItem(QString::fromStdString(c.name) + (c.accepted ? tr(" (accepted)") : QString()),
                          static_cast<int>(i));
    }
  }
  showPlot(plotCombo_->currentIndex());
  updateApplyButton();
}

void DiagnosisPage::showPlot(int comboIndex) {
  if (!result_ || comboIndex < 0) {
    plot_->clear();
    return;
  }
  const int i = plotCombo_->itemData(comboIndex).toInt();
  if (i < 0 || i >= static_cast<int>(result_->effects.size()) ||
      !result_->effects[static_cast<std::size_t>(i)].plot) {
    plot_->clear();
    return;
  }
  const diagnose::Candidate& c = result_->effects[static_cast<std::size_t>(i)];
  plot_->setPlot(*c.plot, tr("Residual before and after %1").arg(QString::fromStdString(c.name)));
}

void DiagnosisPage::fillTable() {
  const diagnose::Diagnosis& d = *result_;
  const QString u = displayUnits(d.units);
  table_->setRowCount(static_cast<int>(d.effects.size()));
  for (int r = 0; r < static_cast<int>(d.effects.size()); ++r) {
    const diagnose::Candidate& c = d.effects[static_cast<std::size_t>(r)];
    auto set = [&](int col, const QString& text, Qt::Alignment align = Qt::AlignLeft | Qt::AlignVCenter) {
      auto* item = new QTableWidgetItem(text);
      item->setTextAlignment(align);
      item->setToolTip(text);
      table_->setItem(r, col, item);
    };
    const Qt::Alignment right = Qt::AlignRight | Qt::AlignVCenter;
    set(ColRound, QString::number(c.round + 1), right);
    set(ColEffect, QString::fromStdString(c.name));
    QString parameters = parameterText(c, u);
    if (c.generic) {
      // A generic effect: its form first ("form: smooth"), then whatever parameters core gave it.
      const QString form = tr("form: %1").arg(dependenceFormLabel(*c.generic, QLocale()));
      parameters = parameters.isEmpty() ? form : form + QStringLiteral("; ") + parameters;
      table_->item(r, ColEffect)
          ->setToolTip(
              tr("A generic effect: %1 in %2, for structure no catalogue effect explains")
                  .arg(dependenceFormName(c.generic->form), residualVariableName(c.generic->against)));
    }
    set(ColParameters, parameters);
    set(ColRmse, QStringLiteral("%1 → %2 %3").arg(num(c.rmseBefore), num(c.rmseAfter), u), right);
    set(ColHeldout,
        c.heldoutBefore && c.heldoutAfter
            ? QStringLiteral("%1 → %2 %3").arg(num(*c.heldoutBefore), num(*c.heldoutAfter), u)
            : QStringLiteral("–"),
        right);
    set(ColEvidence, coreText(c.evidenceParts, c.evidence));
    set(ColAccepted, c.accepted ? QStringLiteral("✓") : QStringLiteral("✗"), Qt::AlignCenter);
    QTableWidgetItem* acc = table_->item(r, ColAccepted);
    acc->setForeground(c.accepted ? QColor(0x1b, 0x7a, 0x1b) : QColor(0xb2, 0x18, 0x2b));
    acc->setData(Qt::UserRole, c.accepted);
    if (c.accepted) {
      for (int col = 0; col < ColumnCount; ++col) {
        QFont f = table_->item(r, col)->font();
        f.setBold(true);
        table_->item(r, col)->setFont(f);
      }
    }
  }
  table_->resizeColumnToContents(ColParameters);
  table_->setColumnWidth(ColParameters,
                         std::min(table_->columnWidth(ColParameters), kMaxParameterColumnWidth));
}

void DiagnosisPage::copySelection() {
  std::set<int> rows;
  for (const QModelIndex& index : table_->selectionModel()->selectedIndexes()) rows.insert(index.row());
  if (rows.empty())
    for (int r = 0; r < table_->rowCount(); ++r) rows.insert(r);
  QStringList lines;
  QStringList header;
  for (int c = 0; c < table_->columnCount(); ++c) header << table_->horizontalHeaderItem(c)->text();
  lines << header.join(QLatin1Char('\t'));
  for (int r : rows) {
    QStringList cells;
    for (int c = 0; c < table_->columnCount(); ++c)
      cells << (table_->item(r, c) ? table_->item(r, c)->text() : QString());
    lines << cells.join(QLatin1Char('\t'));
  }
  QApplication::clipboard()->setText(lines.join(QLatin1Char('\n')) + QLatin1Char('\n'));
}

bool DiagnosisPage::applyAccepted() {
  if (!result_ || result_->accepted().empty() || isRunning()) return false;
  nlohmann::json applied = appliedEffects(*result_);
  if (applied.empty()) return false;  // only generic effects: none the study can include
  const std::string key = diagnosisDomainKey(domain());
  const auto& studies = document_->project().studies;
  if (const auto s = studies.find(study::kDiagnosis); s != studies.end() && s->is_object()) {
    if (const auto b = s->find(key);
        b != s->end() && b->is_object() && b->value("applied", nlohmann::json()) == applied) {
      status_->setText(status_->text() + QLatin1Char(' ') + tr("(Already applied.)"));
      return false;
    }
  }
  // Apply: sets studies.diagnosis.<domain>.applied; undo restores the study's JSON exactly.
  document_->endEditSequence();
  document_->setStudyValue(QString::fromLatin1(study::kDiagnosis),
                           QStringLiteral("/%1/applied").arg(QString::fromStdString(key)), applied,
                           tr("Apply diagnosed effects (%1)").arg(QString::fromStdString(key)));
  document_->endEditSequence();
  return true;
}

void DiagnosisPage::showView(const QString& view) {
  std::vector<DiagnosisDomain> order = {DiagnosisDomain::Thermal, DiagnosisDomain::Setup,
                                        DiagnosisDomain::Matching, DiagnosisDomain::Kinematic};
  for (DiagnosisDomain d : kDiagnosisDomains) {
    if (view == QLatin1String(diagnosisDomainKey(d))) order = {d};
  }
  const bool residual = view == QLatin1String("residual");
  tabs_->setCurrentIndex(residual ? 1 : 0);
  // "residual": the first domain whose result has a residual check (a loop without one shows only
  // "no residual check"), else the first that runs.
  const auto good = [&] { return result_ && (!residual || result_->residualCheck.has_value()); };
  if (good() && std::find(order.begin(), order.end(), domain()) != order.end()) return;
  std::optional<DiagnosisDomain> ran;
  for (DiagnosisDomain d : order) {
    setDomain(d);
    if (settings_ && runNow()) {
      if (!ran) ran = d;
      if (good()) {
        tabs_->setCurrentIndex(residual ? 1 : 0);
        return;
      }
    }
  }
  if (ran) {
    setDomain(*ran);
    runNow();
    tabs_->setCurrentIndex(residual ? 1 : 0);
  } else if (!order.empty()) {
    setDomain(order.front());
  }
}

QComboBox* DiagnosisPage::datasetCombo(DiagnosisDomain domain) const {
  return datasetCombos_[domainIndex(domain)];
}

void DiagnosisPage::buildControls() {
  const QString study = QString::fromLatin1(study::kDiagnosis);
  // The value the project holds for a key of a domain's block, or the type's default: the controls show
  // what the study holds (an invalid value is refused above the results, not replaced).
  const auto number = [this, study](const char* domain, const char* key, double fallback) {
    // The study's value, the default when there is none, nullopt for a value the page refuses.
    return [this, study, domain, key, fallback]() -> std::optional<double> {
      const nlohmann::json v = document_->studyValue(
          study, QStringLiteral("/%1/%2").arg(QLatin1String(domain), QLatin1String(key)));
      if (v.is_null()) return fallback;
      if (v.is_number()) return v.get<double>();
      return std::nullopt;
    };
  };
  const auto text = [this, study](const char* domain, const char* key) {
    return [this, study, domain, key] {
      const nlohmann::json v = document_->studyValue(
          study, QStringLiteral("/%1/%2").arg(QLatin1String(domain), QLatin1String(key)));
      return v.is_string() ? QString::fromStdString(v.get<std::string>()) : QString();
    };
  };
  const DiagnosisDomainSettings defaults;
  for (int i = 0; i < 4; ++i) {
    const DiagnosisDomain d = kDiagnosisDomains[i];
    const char* key = diagnosisDomainKey(d);
    auto* page = new QWidget(controls_);
    auto* row = new QHBoxLayout(page);
    row->setContentsMargins(0, 0, 0, 0);
    auto* combo = new QComboBox(page);
    combo->setObjectName(QStringLiteral("diagnosisData_%1").arg(QLatin1String(key)));
    combo->setToolTip(tr("The dataset the %1 diagnosis runs on (studies.diagnosis.%2.dataset)")
                          .arg(domainTitle(d).toLower(), QLatin1String(key)));
    combo->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    datasetCombos_[i] = combo;
    auto* label = new QLabel(tr("Da&ta:"), page);
    label->setBuddy(combo);
    row->addWidget(label);
    row->addWidget(combo);
    if (d == DiagnosisDomain::Thermal) {
      // The data with the target and inputs the loop needs, in one undo step (chooseThermalData).
      connect(combo, &QComboBox::currentIndexChanged, this,
              [this, combo](int index) { chooseThermalData(combo->itemData(index).toString()); });
    } else {
      bindStudySetting(document_, combo, study, QStringLiteral("/%1/dataset").arg(QLatin1String(key)),
                       text(key, "dataset"),
                       tr("Choose the %1 diagnosis data").arg(domainTitle(d).toLower()));
    }
    const auto addBox = [&](QDoubleSpinBox* box, const QString& caption, const QString& tip) {
      box->setToolTip(tip);
      box->setParent(page);
      auto* l = new QLabel(caption, page);
      l->setBuddy(box);
      row->addSpacing(12);
      row->addWidget(l);
      row->addWidget(box);
    };
    switch (d) {
      case DiagnosisDomain::Thermal:
        trainFraction_->setObjectName(QStringLiteral("diagnosisTrainFraction"));
        trainFraction_->setRange(0.05, 0.95);
        trainFraction_->setDecimals(2);
        trainFraction_->setSingleStep(0.05);
        trainFraction_->setValue(defaults.trainFraction);
        addBox(trainFraction_, tr("Train &fraction:"),
               tr("The share of the rows (from the start) the model is fitted on; the rest is held out "
                  "(studies.diagnosis.thermal.train_fraction)"));
        bindStudySetting(document_, trainFraction_, study, QStringLiteral("/thermal/train_fraction"),
                         number("thermal", "train_fraction", defaults.trainFraction),
                         tr("Change the diagnosis train fraction"));
        {
          thermalTarget_->setObjectName(QStringLiteral("diagnosisTarget"));
          thermalTarget_->setParent(page);
          thermalTarget_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
          thermalTarget_->setToolTip(
              tr("The log's column the declared model predicts, whose residual is "
                 "diagnosed (studies.diagnosis.thermal.target)"));
          auto* l = new QLabel(tr("Tar&get:"), page);
          l->setBuddy(thermalTarget_);
          row->addSpacing(12);
          row->addWidget(l);
          row->addWidget(thermalTarget_);
          connect(thermalTarget_, &QComboBox::currentIndexChanged, this, [this](int index) {
            const QString name = thermalTarget_->itemData(index).toString();
            if (name.isEmpty()) return;
            document_->setStudyValue(QString::fromLatin1(study::kDiagnosis),
                                     QStringLiteral("/thermal/target"), name.toStdString(),
                                     tr("Change the diagnosis target"));
          });
          thermalInputs_->setObjectName(QStringLiteral("diagnosisInputs"));
          thermalInputs_->setParent(page);
          thermalInputs_->setPopupMode(QToolButton::InstantPopup);
          thermalInputs_->setMenu(thermalInputsMenu_);
          thermalInputs_->setToolButtonStyle(Qt::ToolButtonTextOnly);
          thermalInputs_->setToolTip(
              tr("The declared model's inputs: the loop looks for what the residual "
                 "of a model of these inputs still depends on "
                 "(studies.diagnosis.thermal.inputs)"));
          auto* il = new QLabel(tr("&Inputs:"), page);
          il->setBuddy(thermalInputs_);
          row->addSpacing(12);
          row->addWidget(il);
          row->addWidget(thermalInputs_);
        }
        break;
      case DiagnosisDomain::Kinematic:
        feed_->setObjectName(QStringLiteral("diagnosisFeed"));
        feed_->setRange(1.0, 1e6);
        feed_->setDecimals(0);
        feed_->setSingleStep(100.0);
        feed_->setSuffix(QStringLiteral(" mm/min"));
        feed_->setValue(defaults.feedMmPerMin);
        addBox(feed_, tr("&Feed:"),
               tr("The feed of the circular test, for the servo lag's time constant "
                  "(studies.diagnosis.kinematic.feed_mm_per_min)"));
        bindStudySetting(document_, feed_, study, QStringLiteral("/kinematic/feed_mm_per_min"),
                         number("kinematic", "feed_mm_per_min", defaults.feedMmPerMin),
                         tr("Change the diagnosis feed"));
        break;
      case DiagnosisDomain::Setup: {
        setupModel_->setObjectName(QStringLiteral("diagnosisSetupModel"));
        setupModel_->setParent(page);
        setupModel_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
        setupModel_->setToolTip(
            tr("The setup model whose setup data are diagnosed (studies.diagnosis.setup.model)"));
        auto* l = new QLabel(tr("&Model:"), page);
        l->setBuddy(setupModel_);
        row->addSpacing(12);
        row->addWidget(l);
        row->addWidget(setupModel_);
        bindStudySetting(document_, setupModel_, study, QStringLiteral("/setup/model"),
                         text("setup", "model"), tr("Choose the diagnosis setup model"));
        break;
      }
      case DiagnosisDomain::Matching:
        tolerance_->setObjectName(QStringLiteral("diagnosisTolerance"));
        tolerance_->setRange(0.0001, 100.0);
        tolerance_->setDecimals(4);
        tolerance_->setSingleStep(0.005);
        tolerance_->setSuffix(QStringLiteral(" mm"));
        tolerance_->setValue(defaults.toleranceMm);
        addBox(tolerance_, tr("&Tolerance ±:"),
               tr("The symmetric tolerance an effect must matter against "
                  "(studies.diagnosis.matching.tolerance_mm)"));
        bindStudySetting(document_, tolerance_, study, QStringLiteral("/matching/tolerance_mm"),
                         number("matching", "tolerance_mm", defaults.toleranceMm),
                         tr("Change the diagnosis tolerance"));
        break;
    }
    row->addStretch(1);
    controls_->addWidget(page);
  }
  controls_->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Maximum);
  controls_->setCurrentIndex(domainIndex(domain()));
}

void DiagnosisPage::fillControls() {
  const Project& project = document_->project();
  const QString study = QString::fromLatin1(study::kDiagnosis);
  // Refilled from the project (datasets added or removed) without edits; the bindings keep them in step
  // with the study afterwards.
  const auto fill = [&](QComboBox* combo, const std::string& kind, const QString& key) {
    const QSignalBlocker blocker(combo);
    combo->clear();
    for (const DatasetRef& ds : project.datasets) {
      if (ds.kind != kind) continue;
      combo->addItem(QString::fromStdString(ds.id), QString::fromStdString(ds.id));
      if (!ds.description.empty())
        combo->setItemData(combo->count() - 1, QString::fromStdString(ds.description), Qt::ToolTipRole);
    }
    const nlohmann::json v = document_->studyValue(study, key);
    combo->setCurrentIndex(v.is_string() ? combo->findData(QString::fromStdString(v.get<std::string>()))
                                         : -1);
  };
  for (int i = 0; i < 4; ++i) {
    const std::string key = diagnosisDomainKey(kDiagnosisDomains[i]);
    fill(datasetCombos_[i], fieldKind(key, "dataset"),
         QStringLiteral("/%1/dataset").arg(QString::fromStdString(key)));
  }
  fill(setupModel_, fieldKind("setup", "model"), QStringLiteral("/setup/model"));
  fillThermalColumns();
  // The numbers: what the study holds (clamped to the box), else the default.
  const auto show = [&](QDoubleSpinBox* box, const char* key, double fallback) {
    const nlohmann::json v = document_->studyValue(study, QString::fromLatin1(key));
    const double shown =
        std::clamp(v.is_number() ? v.get<double>() : fallback, box->minimum(), box->maximum());
    // Unchanged: left alone, so that typing in the box is not disturbed by its own edit.
    if (std::abs(box->value() - shown) < 0.5 * std::pow(10.0, -box->decimals())) return;
    const QSignalBlocker blocker(box);
    box->setValue(shown);
  };
  const DiagnosisDomainSettings defaults;
  show(trainFraction_, "/thermal/train_fraction", defaults.trainFraction);
  show(feed_, "/kinematic/feed_mm_per_min", defaults.feedMmPerMin);
  show(tolerance_, "/matching/tolerance_mm", defaults.toleranceMm);
}

std::vector<std::string> DiagnosisPage::thermalColumns(const std::string& datasetId) {
  const DatasetRef* dataset = document_->project().dataset(datasetId);
  if (!dataset) return {};
  const std::string projectPath = document_->projectPathForDatasets().toStdString();
  std::string path;
  try {
    path = resolveDatasetPath(projectPath, *dataset);
  } catch (const std::exception&) {
    return {};
  }
  const QFileInfo info(QString::fromStdString(path));
  nlohmann::json key = {path,
                        info.lastModified().toMSecsSinceEpoch(),
                        info.size(),
                        nlohmann::json(dataset->csv.columnMap),
                        dataset->csv.headerLines,
                        static_cast<int>(dataset->csv.dialect.delimiter),
                        static_cast<int>(dataset->csv.dialect.decimal),
                        dataset->csv.commentPrefix};
  if (key.dump() == columnsKey_) return columnsCache_;
  columnsKey_ = key.dump();
  columnsCache_.clear();
  try {
    for (const ThermalChannel& c : readThermalLog(path, 3, dataset->csv).channels)
      columnsCache_.push_back(c.name);
  } catch (const std::exception&) {
    // Unreadable: no columns to offer; the page names the error when it reads the settings.
  }
  return columnsCache_;
}

void DiagnosisPage::fillThermalColumns() {
  const QString study = QString::fromLatin1(study::kDiagnosis);
  const nlohmann::json dataset = document_->studyValue(study, QStringLiteral("/thermal/dataset"));
  const std::vector<std::string> columns =
      dataset.is_string() ? thermalColumns(dataset.get<std::string>()) : std::vector<std::string>{};
  const nlohmann::json target = document_->studyValue(study, QStringLiteral("/thermal/target"));
  const nlohmann::json inputs = document_->studyValue(study, QStringLiteral("/thermal/inputs"));
  {
    const QSignalBlocker blocker(thermalTarget_);
    thermalTarget_->clear();
    for (const std::string& c : columns)
      thermalTarget_->addItem(QString::fromStdString(c), QString::fromStdString(c));
    thermalTarget_->setCurrentIndex(
        target.is_string() ? thermalTarget_->findData(QString::fromStdString(target.get<std::string>()))
                           : -1);
    thermalTarget_->setEnabled(!columns.empty());
  }
  std::set<std::string> chosen;
  if (inputs.is_array())
    for (const auto& i : inputs)
      if (i.is_string()) chosen.insert(i.get<std::string>());
  // The actions are kept while the columns stay (a click's own write refreshes the page: the action it
  // came from must not be deleted inside its signal); only their check marks follow the study.
  QStringList names;
  for (const std::string& c : columns) names << QString::fromStdString(c);
  QStringList shown;
  for (QAction* a : thermalInputsMenu_->actions()) shown << a->data().toString();
  if (shown != names) {
    for (QAction* a : thermalInputsMenu_->actions()) {
      thermalInputsMenu_->removeAction(a);
      a->deleteLater();
    }
    for (const QString& c : names) {
      QAction* a = thermalInputsMenu_->addAction(c);
      a->setData(c);
      a->setCheckable(true);
      connect(a, &QAction::triggered, this, &DiagnosisPage::writeThermalInputs);
    }
  }
  for (QAction* a : thermalInputsMenu_->actions()) {
    const QSignalBlocker blocker(a);
    a->setChecked(chosen.count(a->data().toString().toStdString()) > 0);
  }
  thermalInputs_->setEnabled(!columns.empty());
  thermalInputs_->setText(tr("%n column(s)", nullptr, static_cast<int>(chosen.size())));
}

void DiagnosisPage::writeThermalInputs() {
  std::vector<std::string> inputs;
  for (QAction* a : thermalInputsMenu_->actions())
    if (a->isChecked()) inputs.push_back(a->data().toString().toStdString());
  document_->setStudyValue(QString::fromLatin1(study::kDiagnosis), QStringLiteral("/thermal/inputs"),
                           inputs.empty() ? nlohmann::json() : nlohmann::json(inputs),
                           tr("Change the diagnosis inputs"));
}

void DiagnosisPage::chooseThermalData(const QString& datasetId) {
  const QString study = QString::fromLatin1(study::kDiagnosis);
  const std::string id = datasetId.toStdString();
  if (id.empty()) return;
  std::vector<StudyEdit> edits;
  edits.push_back({QStringLiteral("/thermal/dataset"), id, tr("Choose the thermal diagnosis data")});
  const DatasetRef* dataset = document_->project().dataset(id);
  if (dataset) {
    try {
      const ThermalLog log = readThermalLog(
          resolveDatasetPath(document_->projectPathForDatasets().toStdString(), *dataset), 3, dataset->csv);
      // Kept when the study's target and inputs are columns of this log.
      const nlohmann::json target = document_->studyValue(study, QStringLiteral("/thermal/target"));
      const nlohmann::json inputs = document_->studyValue(study, QStringLiteral("/thermal/inputs"));
      bool keep = target.is_string() && log.indexOf(target.get<std::string>()) >= 0 && inputs.is_array() &&
                  !inputs.empty();
      if (keep)
        for (const auto& i : inputs) keep = keep && i.is_string() && log.indexOf(i.get<std::string>()) >= 0;
      if (!keep) {
        const nlohmann::json thermal = document_->studyValue(QString::fromLatin1(study::kThermal), QString());
        ThermalModelSettings s;
        try {
          s = defaultThermalModelSettings(log, thermal, id);  // the thermal study's, on the same log
        } catch (const std::exception&) {
          s = defaultThermalModelSettings(log, nlohmann::json(), id);  // it is refused there: the defaults
        }
        if (!s.target.empty()) edits.push_back({QStringLiteral("/thermal/target"), s.target, QString()});
        if (!s.inputs.empty()) edits.push_back({QStringLiteral("/thermal/inputs"), s.inputs, QString()});
      }
    } catch (const std::exception&) {
      // An unreadable log: the dataset alone; the page names the error.
    }
  }
  std::vector<StudyEdit> changed;
  for (const StudyEdit& e : edits)
    if (document_->studyValue(study, e.key) != e.value) changed.push_back(e);
  if (changed.empty()) return;
  QUndoStack* stack = document_->undoStack();
  if (changed.size() > 1) stack->beginMacro(tr("Choose the thermal diagnosis data"));
  for (const StudyEdit& e : changed)
    document_->setStudyValue(study, e.key, e.value, tr("Choose the thermal diagnosis data"));
  if (changed.size() > 1) stack->endMacro();
}

nlohmann::json DiagnosisPage::storedSettings() const {
  if (!settings_) return nullptr;
  const std::string key = diagnosisDomainKey(settings_->domain);
  const nlohmann::json block = document_->studyValue(QString::fromLatin1(study::kDiagnosis),
                                                     QStringLiteral("/") + QString::fromStdString(key));
  try {
    nlohmann::json j = DiagnosisDomainSettings::fromJson(block, key).toJson();
    j.erase("applied");  // the loop fits the declared model; Apply does not change what it computes
    j["domain"] = key;
    if (!settings_->modelId.empty()) {
      if (const DatasetRef* model = document_->project().dataset(settings_->modelId)) {
        try {
          j["model_hash"] = datasetDataHash(document_->projectPathForDatasets().toStdString(), *model);
        } catch (const std::exception&) {
          j["model_hash"] = nullptr;  // unreadable now: never equal to a stored hash
        }
      }
    }
    return j;
  } catch (const std::exception&) {
    return nullptr;
  }
}

void DiagnosisPage::storeResult(const std::string& datasetId, const nlohmann::json& settings) {
  if (!result_ || settings.is_null()) return;
  // A cancelled run holds only the rounds done so far: not a result of these settings.
  if (std::any_of(result_->notes.begin(), result_->notes.end(), [](const std::string& n) {
        return n == "cancelled" || n.starts_with("stopped by the observer");
      }))
    return;
  const DatasetRef* dataset = document_->project().dataset(datasetId);
  if (!dataset) return;
  try {
    document_->setStoredResult(QString::fromLatin1(study::kDiagnosis), QString::fromStdString(datasetId),
                               makeStoredResult(document_->projectPathForDatasets().toStdString(), *dataset,
                                                settings, diagnose::toJson(*result_)));
  } catch (const std::exception&) {
    // The data cannot be read any more (moved during the run): nothing is stored, the page shows the run.
  }
}

QString DiagnosisPage::storedResultText() const {
  if (!settings_) return {};
  const DatasetRef* dataset = document_->project().dataset(settings_->datasetId);
  const nlohmann::json settings = storedSettings();
  if (!dataset || settings.is_null()) return {};
  const StoredResult stored =
      storedResult(document_->project(), document_->projectPathForDatasets().toStdString(), study::kDiagnosis,
                   *dataset, settings);
  if (const std::optional<QString> state = storedStateText(
          stored,
          {tr("The stored result (computed %1) is out of date: the settings changed since. Not run with "
              "these settings yet: press Run (Ctrl+R)."),
           tr("The stored result (computed %1) is out of date: the data file changed since. Run (Ctrl+R) "
              "on the data as it is now."),
           tr("The stored result (computed %1) cannot be checked: the data file cannot be read.")}))
    return *state;
  const QString when = storedTimeText(stored.computed);
  const nlohmann::json& e = stored.entry;
  const nlohmann::json baseline = e.value("baseline", nlohmann::json::object());
  const nlohmann::json after = e.value("final", nlohmann::json::object());
  QStringList accepted;
  int tried = 0;
  if (const auto effects = e.find("effects"); effects != e.end() && effects->is_array()) {
    tried = static_cast<int>(effects->size());
    for (const nlohmann::json& c : *effects)
      if (c.is_object() && c.value("accepted", false) && c.value("name", nlohmann::json()).is_string())
        accepted << QString::fromStdString(c["name"].get<std::string>());
  }
  const std::string units =
      e.value("units", nlohmann::json()).is_string() ? e["units"].get<std::string>() : "";
  const QString figures = summaryText(
      storedFigure(baseline, "rmse"), storedFigure(after, "rmse"), storedOptional(baseline, "heldout_rmse"),
      storedOptional(after, "heldout_rmse"), storedFigure(baseline, "max_abs"),
      storedFigure(after, "max_abs"), accepted, tried, displayUnits(units));
  return tr("From the saved project (computed %1 with these settings on this data): %2 Run (Ctrl+R) for "
            "the plots, the candidate table and the residual check.")
      .arg(when, figures);
}

}  // namespace metrofit
