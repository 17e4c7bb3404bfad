#include "widgets/setup/setupresultsview.h"

#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QStyle>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <exception>

#include "core/io/dfq.h"
#include "core/io/file_io.h"
#include "core/setup/measurements_dfq.h"
#include "widgets/common/tablecopy.h"
#include "widgets/setup/setupcharts.h"
#include "widgets/setup/setupmargins.h"

namespace metrofit {

namespace {
enum Column { ColId, ColKind, ColRegister, ColCorrection, ColumnCount };

QString kindTitle(setup::DatumKind kind) {
  switch (kind) {
    case setup::DatumKind::Machine:
      return SetupResultsView::tr("machine point");
    case setup::DatumKind::Wks:
      return SetupResultsView::tr("work offset");
    case setup::DatumKind::Tool:
      return SetupResultsView::tr("tool length");
  }
  return {};
}

QString mm(double v, int decimals = 4) {
  return QLocale().toString(v, 'f', decimals);
}
}  // namespace

SetupResultsView::SetupResultsView(QWidget* parent)
    : QWidget(parent),
      summary_(new QLabel(this)),
      table_(new QTableWidget(this)),
      margins_(new SetupMarginsWidget(this)),
      parts_(new QLabel(this)),
      toolOffset_(new QComboBox(this)),
      dfqButton_(new QPushButton(tr("Export Q-DAS &DFQ…"), this)) {
  summary_->setObjectName(QStringLiteral("setupResultSummary"));
  summary_->setWordWrap(true);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  parts_->setObjectName(QStringLiteral("setupParts"));
  parts_->setWordWrap(true);

  table_->setObjectName(QStringLiteral("setupCorrectionsTable"));
  enableTableCopy(table_);
  table_->setColumnCount(ColumnCount);
  table_->setHorizontalHeaderLabels({tr("Setup datum"), tr("Kind"), tr("Register"), tr("Correction (mm)")});
  table_->horizontalHeaderItem(ColCorrection)
      ->setToolTip(tr("Increment to add to the register along the model's axis (see the export headers)"));
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setAlternatingRowColors(true);
  table_->verticalHeader()->hide();
  table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 6);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);
  fitTableWidth();

  auto* exports = new QHBoxLayout;
  exports->addWidget(new QLabel(tr("Export the corrections:"), this));
  const std::pair<setup::ControllerFormat, QString> formats[] = {
      {setup::ControllerFormat::Fanuc, tr("&Fanuc…")},
      {setup::ControllerFormat::Heidenhain, tr("&Heidenhain…")},
      {setup::ControllerFormat::Siemens, tr("&Siemens…")},
      {setup::ControllerFormat::Csv, tr("&CSV…")}};
  for (const auto& [format, text] : formats) {
    auto* button = new QPushButton(text, this);
    button->setObjectName(QStringLiteral("export_%1").arg(QString::fromLatin1(setup::toString(format))));
    button->setEnabled(false);
    connect(button, &QPushButton::clicked, this, [this, f = format] { exportDialog(f); });
    exports->addWidget(button);
    exportButtons_ << button;
  }
  auto* table = new QPushButton(tr("Update HEIDENHAIN &table…"), this);
  table->setObjectName(QStringLiteral("export_heidenhain_table"));
  table->setToolTip(
      tr("Add the corrections to the control's current preset table (.PR) or tool table (.T), saved from the "
         "control, and write the result to a new file for import; the rows are the registers of the model"));
  table->setEnabled(false);
  connect(table, &QPushButton::clicked, this, &SetupResultsView::tableDialog);
  exportButtons_ << table;
  auto* toolLabel = new QLabel(tr("Tool re&gister:"), this);
  toolLabel->setBuddy(toolOffset_);
  toolOffset_->setObjectName(QStringLiteral("exportToolOffset"));
  toolOffset_->addItem(tr("wear (DL)"), static_cast<int>(setup::ToolOffset::Wear));
  toolOffset_->addItem(tr("geometry (L)"), static_cast<int>(setup::ToolOffset::Geometry));
  toolOffset_->setToolTip(
      tr("The register the tool-length corrections go to in every export: the wear "
         "(DL, Fanuc H wear) or the geometry (L)"));
  exports->addSpacing(8);
  exports->addWidget(toolLabel);
  exports->addWidget(toolOffset_);
  exports->addStretch(1);
  // A second row: the page must fit 1280 px in German and Polish too.
  auto* more = new QHBoxLayout;
  more->addWidget(table);
  more->addStretch(1);
  dfqButton_->setObjectName(QStringLiteral("export_dfq"));
  dfqButton_->setEnabled(false);
  dfqButton_->setToolTip(tr("There is no measurement report to export"));
  connect(dfqButton_, &QPushButton::clicked, this, &SetupResultsView::dfqDialog);
  more->addWidget(dfqButton_);

  auto* left = new QWidget(this);
  auto* leftLayout = new QVBoxLayout(left);
  leftLayout->setContentsMargins(0, 0, 0, 0);
  leftLayout->addWidget(table_, 1);
  leftLayout->addWidget(parts_);

  auto* scroll = new QScrollArea(this);
  scroll->setWidget(margins_);
  scroll->setWidgetResizable(true);
  scroll->setMinimumWidth(440);

  auto* splitter = new QSplitter(Qt::Horizontal, this);
  splitter->setObjectName(QStringLiteral("setupResultsSplitter"));
  splitter->addWidget(left);
  splitter->addWidget(scroll);
  splitter->setStretchFactor(0, 1);
  splitter->setStretchFactor(1, 2);
  splitter->setChildrenCollapsible(false);
  splitter->setSizes({380, 820});

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(summary_);
  layout->addWidget(splitter, 1);
  layout->addLayout(exports);
  layout->addLayout(more);
  clear(tr("No result yet: choose a method and press Run (Ctrl+R)."));
}

QString SetupResultsView::summaryText() const {
  return summary_->text();
}

QString SetupResultsView::partsText() const {
  return parts_->text();
}

void SetupResultsView::fitTableWidth() {
  constexpr int kMinimumWidth = 320;
  int need =
      2 * table_->frameWidth() + table_->style()->pixelMetric(QStyle::PM_ScrollBarExtent, nullptr, table_);
  constexpr int kCellMargins = 12;  // the cell's text margins and focus frame
  for (int c = 0; c < table_->columnCount(); ++c) {
    int column = table_->horizontalHeader()->sectionSizeHint(c);
    for (int r = 0; r < table_->rowCount(); ++r)
      if (const QTableWidgetItem* item = table_->item(r, c))
        column = std::max(column, QFontMetrics(item->font()).horizontalAdvance(item->text()) + kCellMargins);
    need += column;
  }
  table_->setMinimumWidth(std::max(kMinimumWidth, need));
}

void SetupResultsView::clear(const QString& message) {
  result_.reset();
  summary_->setText(message);
  table_->setRowCount(0);
  margins_->setRows({});
  parts_->clear();
  for (QPushButton* b : exportButtons_) b->setEnabled(false);
}

void SetupResultsView::setResult(const setup::Model& model, const setup::SetupInstance& instance,
                                 const SetupRunOutcome& outcome,
                                 const std::optional<setup::SetupScore>& exact,
                                 const SetupPartsSummary& parts) {
  model_ = model;
  result_ = outcome;
  const QString method = setupMethodTitle(QString::fromStdString(outcome.method));
  const bool exactRun = outcome.method == "exact";
  const QString work = exactRun
                           ? tr("%n LP / MILP solver call(s)", nullptr, static_cast<int>(outcome.evaluations))
                           : tr("%n solution(s) evaluated", nullptr, static_cast<int>(outcome.evaluations));
  QString text =
      tr("%1: f1 %2 → %3 mm (bonus %4 mm), |x| = f2 %5 mm, f %6; %7 in %8 ms.")
          .arg(exactRun ? method : setupRunLabel(QString::fromStdString(outcome.method), outcome.seed))
          .arg(mm(outcome.f1Before), mm(outcome.score.f1), mm(outcome.score.f1 - outcome.f1Before),
               mm(outcome.score.f2), mm(outcome.score.f), work,
               QLocale().toString(outcome.seconds * 1e3, 'f', 1));
  if (outcome.method == "exact") {
    text += QLatin1Char(' ') +
            (outcome.f1Optimal ? tr("f1 proven optimal on the grid") : tr("f1 NOT proven optimal")) +
            QStringLiteral(", ") +
            (outcome.f2Optimal ? tr("|x| proven minimal.") : tr("|x| not proven minimal."));
  } else if (exact) {
    text += QLatin1Char(' ') + tr("Gap to the exact optimum: f1 %1 mm, f2 %2 mm.")
                                   .arg(mm(exact->f1 - outcome.score.f1), mm(outcome.score.f2 - exact->f2));
  }
  if (outcome.termination == Termination::Cancelled)
    text += QLatin1Char(' ') + tr("(cancelled: best so far)");
  summary_->setText(text);

  table_->setRowCount(static_cast<int>(model.setup.size()));
  for (std::size_t i = 0; i < model.setup.size() && i < outcome.x.size(); ++i) {
    const int row = static_cast<int>(i);
    table_->setItem(row, ColId, new QTableWidgetItem(QString::fromStdString(model.setup[i].id)));
    table_->setItem(row, ColKind, new QTableWidgetItem(kindTitle(model.setup[i].kind)));
    QString reg, regError;
    try {
      reg = QString::number(setup::registerOf(model, i));
    } catch (const std::exception& e) {
      reg = QStringLiteral("—");  // the reason in the cell's tooltip and under the summary
      regError = QString::fromStdString(e.what());
      summary_->setText(summary_->text() + QLatin1Char('\n') + regError);
    }
    auto* r = new QTableWidgetItem(reg);
    r->setToolTip(regError);
    r->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    table_->setItem(row, ColRegister, r);
    const double x = std::abs(outcome.x[i]) < 5e-10 ? 0.0 : outcome.x[i];
    auto* c = new QTableWidgetItem(QLocale().toString(x, 'f', 3));
    c->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    c->setData(Qt::UserRole, x);
    table_->setItem(row, ColCorrection, c);
  }
  fitTableWidth();

  std::vector<SetupMarginRow> rows;
  const std::vector<double> after = instance.deviationsAfter(outcome.x);
  for (std::size_t q = 0; q < instance.dimensions(); ++q) {
    rows.push_back({QString::fromStdString(instance.dimensionIds()[q]), instance.lowerLimit(q),
                    instance.upperLimit(q), instance.deviation(q), after[q]});
  }
  margins_->setRows(std::move(rows));

  if (parts.parts > 0) {
    parts_->setText(tr("Parts of the report in tolerance: %1 of %2 before, %3 of %2 after the correction; "
                       "parts rescued: %4.")
                        .arg(parts.inToleranceBefore)
                        .arg(parts.parts)
                        .arg(parts.inToleranceAfter)
                        .arg(parts.rescued) +
                    (parts.lost > 0
                         ? QLatin1Char(' ') + tr("Parts that would leave the tolerance: %1.").arg(parts.lost)
                         : QString()));
  } else {
    parts_->clear();
  }
  for (QPushButton* b : exportButtons_) b->setEnabled(true);
}

bool SetupResultsView::exportTo(setup::ControllerFormat format, const QString& path, QString* error) const {
  if (!result_) {
    if (error) *error = tr("There are no corrections to export yet.");
    return false;
  }
  try {
    setup::ExportOptions options;
    options.toolOffset = toolOffset();
    const std::string text = setup::exportCorrections(model_, result_->x, format, options);
    writeFileAtomic(path.toStdString(), text);
  } catch (const std::exception& e) {
    if (error) *error = QString::fromStdString(e.what());
    return false;
  }
  return true;
}

void SetupResultsView::exportDialog(setup::ControllerFormat format) {
  const QString suffix = format == setup::ControllerFormat::Fanuc        ? QStringLiteral(".nc")
                         : format == setup::ControllerFormat::Heidenhain ? QStringLiteral(".txt")
                         : format == setup::ControllerFormat::Siemens    ? QStringLiteral(".mpf")
                                                                         : QStringLiteral(".csv");
  const QString name =
      QStringLiteral("corrections-%1%2").arg(QString::fromLatin1(setup::toString(format)), suffix);
  const QString path = QFileDialog::getSaveFileName(this, tr("Export corrections"), name);
  if (path.isEmpty()) return;
  QString error;
  if (!exportTo(format, path, &error))
    QMessageBox::critical(this, tr("Cannot export the corrections"), error);
}

setup::ToolOffset SetupResultsView::toolOffset() const {
  return static_cast<setup::ToolOffset>(toolOffset_->currentData().toInt());
}

void SetupResultsView::setToolOffset(setup::ToolOffset offset) {
  toolOffset_->setCurrentIndex(std::max(0, toolOffset_->findData(static_cast<int>(offset))));
}

bool SetupResultsView::updateHeidenhainTable(const QString& tablePath, const QString& outPath, QString* error,
                                             setup::TableUpdate* update) const {
  if (!result_) {
    if (error) *error = tr("There are no corrections to export yet.");
    return false;
  }
  const QFileInfo in(tablePath), out(outPath);
  if (in.absoluteFilePath() == out.absoluteFilePath() ||
      (out.exists() && in.canonicalFilePath() == out.canonicalFilePath())) {
    if (error)
      *error = tr("The updated table must go to a new file: %1 is the table read from the control.")
                   .arg(QDir::toNativeSeparators(outPath));
    return false;
  }
  try {
    setup::ExportOptions options;
    options.toolOffset = toolOffset();
    const std::string source = tablePath.toStdString();
    const setup::TableUpdate u =
        setup::updateHeidenhainTable(model_, result_->x, readFile(source), source, options);
    writeFileAtomic(outPath.toStdString(), u.text);
    if (update) *update = u;
  } catch (const std::exception& e) {
    if (error) *error = QString::fromUtf8(e.what());
    return false;
  }
  return true;
}

void SetupResultsView::tableDialog() {
  const QString table = QFileDialog::getOpenFileName(
      this, tr("The control's current table (saved from the control)"), QString(),
      tr("HEIDENHAIN preset and tool tables (*.PR *.pr *.T *.t);;All files (*)"));
  if (table.isEmpty()) return;
  const QFileInfo in(table);
  const QString proposal =
      in.dir().filePath(in.completeBaseName() + QStringLiteral("_corrected.") + in.suffix());
  const QString out = QFileDialog::getSaveFileName(this, tr("Write the updated table to"), proposal);
  if (out.isEmpty()) return;
  QString error;
  setup::TableUpdate update;
  if (!updateHeidenhainTable(table, out, &error, &update)) {
    QMessageBox::critical(this, tr("Cannot update the HEIDENHAIN table"), error);
    return;
  }
  QStringList written, skipped;
  for (const std::string& id : update.written) written << QString::fromStdString(id);
  for (const std::string& id : update.notWritten) skipped << QString::fromStdString(id);
  QString text = tr("%1 written to %2. Cells updated: %3.")
                     .arg(QString::fromStdString(update.table), QDir::toNativeSeparators(out),
                          written.isEmpty() ? tr("none") : written.join(QStringLiteral(", ")));
  if (!skipped.isEmpty())
    text += QLatin1Char(' ') + tr("Not in this table: %1.").arg(skipped.join(QStringLiteral(", ")));
  text += QLatin1Char(' ') + tr("Import it with no NC program running, then activate the preset again or "
                                "call the tool again.");
  QMessageBox::information(this, tr("HEIDENHAIN table updated"), text);
}

void SetupResultsView::setMeasurements(const setup::Model& model, const setup::Measurements* measurements,
                                       const QString& modelFile) {
  measModel_ = model;
  modelFile_ = modelFile;
  if (measurements)
    measurements_ = *measurements;
  else
    measurements_.reset();
  dfqButton_->setEnabled(measurements_.has_value());
  dfqButton_->setToolTip(measurements_ ? tr("Write the measured features of the report as a Q-DAS DFQ file "
                                            "(one characteristic per measured dimension)")
                                       : tr("There is no measurement report to export"));
}

bool SetupResultsView::exportDfq(const QString& path, QString* error) const {
  if (!measurements_) {
    if (error) *error = tr("There is no measurement report to export.");
    return false;
  }
  try {
    const std::string part = QFileInfo(modelFile_).completeBaseName().toStdString();
    writeFileAtomic(path.toStdString(),
                    writeDfq(setup::measurementsDfqPart(measModel_, *measurements_, part)));
  } catch (const std::exception& e) {
    if (error) *error = QString::fromUtf8(e.what());
    return false;
  }
  return true;
}

void SetupResultsView::dfqDialog() {
  const QString name = QFileInfo(modelFile_).completeBaseName() + QStringLiteral(".dfq");
  const QString path = QFileDialog::getSaveFileName(this, tr("Export Q-DAS DFQ"), name,
                                                    tr("Q-DAS DFQ files (*.dfq);;All files (*)"));
  if (path.isEmpty()) return;
  QString error;
  if (!exportDfq(path, &error)) QMessageBox::critical(this, tr("Cannot export the DFQ file"), error);
}

}  // namespace metrofit
