#include "app/gui/thermalpage.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QSignalBlocker>
#include <QStackedWidget>
#include <QVBoxLayout>
#include <exception>

#include "app/gui/notesedit.h"
#include "core/thermal/thermal_log.h"
#include "widgets/charts/thermaltrendview.h"
#include "widgets/document/projectdocument.h"
#include "widgets/document/studyinfo.h"

namespace metrofit {

ThermalPage::ThermalPage(ProjectDocument* document, QWidget* parent)
    : QWidget(parent),
      document_(document),
      combo_(new QComboBox(this)),
      info_(new QLabel(this)),
      stack_(new QStackedWidget(this)),
      trend_(new ThermalTrendView(this)),
      message_(new QLabel(this)) {
  auto* title = new QLabel(studyTitle(QString::fromLatin1(study::kThermal)), this);
  QFont titleFont = title->font();
  titleFont.setPointSizeF(titleFont.pointSizeF() * 1.4);
  titleFont.setBold(true);
  title->setFont(titleFont);
  title->setToolTip(studySummary(QString::fromLatin1(study::kThermal)));

  combo_->setObjectName(QStringLiteral("thermalLogCombo"));
  combo_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  combo_->setMinimumContentsLength(16);
  info_->setWordWrap(true);
  info_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  message_->setObjectName(QStringLiteral("thermalMessage"));
  message_->setWordWrap(true);
  message_->setAlignment(Qt::AlignCenter);
  message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  stack_->addWidget(trend_);
  stack_->addWidget(message_);

  auto* top = new QHBoxLayout;
  auto* comboLabel = new QLabel(tr("&Thermal log:"), this);
  comboLabel->setBuddy(combo_);
  top->addWidget(title);
  top->addSpacing(16);
  top->addWidget(comboLabel);
  top->addWidget(combo_);
  top->addStretch(1);

  auto* notes = new NotesEdit(document_, QString::fromLatin1(study::kThermal), this);
  notes->setMaximumHeight(60);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(top);
  layout->addWidget(info_);
  layout->addWidget(stack_, 1);
  layout->addWidget(notes);

  connect(combo_, &QComboBox::currentIndexChanged, this, &ThermalPage::showLog);
  connect(document_, &ProjectDocument::changed, this, &ThermalPage::refresh);
  refresh();
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
    if (d.kind == dataset_kind::kThermalLog) logs.push_back(d);
  }
  // Name or notes edits must not re-read the data.
  if (logs == logs_ && projectFile_ == document_->fileName() && combo_->count() > 0) return;
  logs_ = std::move(logs);
  projectFile_ = document_->fileName();
  const QString previous = currentDataset();
  {
    const QSignalBlocker blocker(combo_);
    combo_->clear();
    for (const DatasetRef& d : logs_) {
      const QString id = QString::fromStdString(d.id);
      combo_->addItem(id, id);
      combo_->setItemData(combo_->count() - 1, QString::fromStdString(d.description), Qt::ToolTipRole);
    }
    const int keep = combo_->findData(previous);
    combo_->setCurrentIndex(keep >= 0 ? keep : 0);
  }
  showLog(combo_->currentIndex());
}

void ThermalPage::showLog(int comboIndex) {
  error_.clear();
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
    const ThermalLog log = readThermalLog(path.toStdString());
    trend_->setLog(log);
    const QLocale locale;
    const double spanMin = log.rows() > 1 ? log.timeMin.back() - log.timeMin.front() : 0.0;
    QString info = tr("%1 rows, %2 channels, %3 h.")
                       .arg(log.rows())
                       .arg(log.channels.size())
                       .arg(locale.toString(spanMin / 60.0, 'f', 1));
    if (!dataset.licence.empty())
      info += QLatin1Char(' ') + tr("Licence: %1.").arg(QString::fromStdString(dataset.licence));
    if (!dataset.description.empty())
      info.prepend(QString::fromStdString(dataset.description) + QLatin1Char('\n'));
    info_->setText(info);
    stack_->setCurrentWidget(trend_);
  } catch (const std::exception& e) {
    error_ = QString::fromStdString(e.what());
    info_->clear();
    message_->setText(tr("Cannot show this thermal log:\n%1").arg(error_));
    stack_->setCurrentWidget(message_);
  }
}

}  // namespace metrofit
