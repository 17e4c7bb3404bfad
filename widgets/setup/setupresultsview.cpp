#include "widgets/setup/setupresultsview.h"

#include <QFileDialog>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <exception>

#include "core/io/file_io.h"
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
      parts_(new QLabel(this)) {
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
  table_->setMinimumWidth(320);

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
  exports->addStretch(1);

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
  clear(tr("No result yet: choose a method and press Run (Ctrl+R)."));
}

QString SetupResultsView::summaryText() const {
  return summary_->text();
}

QString SetupResultsView::partsText() const {
  return parts_->text();
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
    const std::string text = setup::exportCorrections(model_, result_->x, format);
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

}  // namespace metrofit
