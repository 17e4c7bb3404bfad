#include "app/gui/matchingpage.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QSignalBlocker>
#include <QSplitter>
#include <QStackedWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <exception>
#include <set>

#include "app/gui/notesedit.h"
#include "core/matching/probe_points.h"
#include "widgets/document/projectdocument.h"
#include "widgets/document/studyinfo.h"
#include "widgets/pointview/pointsetview.h"

namespace metrofit {

namespace {
enum Column { ColId, ColSurface, ColDeviation, ColumnCount };
}

MatchingPage::MatchingPage(ProjectDocument* document, QWidget* parent)
    : QWidget(parent),
      document_(document),
      combo_(new QComboBox(this)),
      info_(new QLabel(this)),
      stack_(new QStackedWidget(this)),
      content_(new QSplitter(Qt::Horizontal, this)),
      view_(new PointSetView(content_)),
      table_(new QTableWidget(content_)),
      message_(new QLabel(this)) {
  auto* title = new QLabel(studyTitle(QString::fromLatin1(study::kMatching)), this);
  QFont titleFont = title->font();
  titleFont.setPointSizeF(titleFont.pointSizeF() * 1.4);
  titleFont.setBold(true);
  title->setFont(titleFont);
  title->setToolTip(studySummary(QString::fromLatin1(study::kMatching)));

  combo_->setObjectName(QStringLiteral("probePointsCombo"));
  combo_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  combo_->setMinimumContentsLength(16);
  info_->setWordWrap(true);
  info_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  message_->setObjectName(QStringLiteral("matchingMessage"));
  message_->setWordWrap(true);
  message_->setAlignment(Qt::AlignCenter);

  table_->setColumnCount(ColumnCount);
  table_->setHorizontalHeaderLabels({tr("Point"), tr("Surface"), tr("Deviation before (mm)")});
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setAlternatingRowColors(true);
  table_->verticalHeader()->hide();
  table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 6);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);

  content_->addWidget(view_);
  content_->addWidget(table_);
  content_->setStretchFactor(0, 3);
  content_->setStretchFactor(1, 1);
  content_->setChildrenCollapsible(false);
  content_->setSizes({760, 300});
  view_->setMinimumSize(320, 240);
  table_->setMinimumWidth(260);
  stack_->addWidget(content_);
  stack_->addWidget(message_);

  auto* top = new QHBoxLayout;
  auto* comboLabel = new QLabel(tr("&Probe points:"), this);
  comboLabel->setBuddy(combo_);
  top->addWidget(title);
  top->addSpacing(16);
  top->addWidget(comboLabel);
  top->addWidget(combo_);
  top->addStretch(1);

  auto* notes = new NotesEdit(document_, QString::fromLatin1(study::kMatching), this);
  notes->setMaximumHeight(60);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(top);
  layout->addWidget(info_);
  layout->addWidget(stack_, 1);
  layout->addWidget(notes);

  connect(combo_, &QComboBox::currentIndexChanged, this, &MatchingPage::showPoints);
  connect(document_, &ProjectDocument::changed, this, &MatchingPage::refresh);
  refresh();
}

QString MatchingPage::currentDataset() const {
  return combo_->currentData().toString();
}

void MatchingPage::selectDataset(const QString& id) {
  const int index = combo_->findData(id);
  if (index >= 0) combo_->setCurrentIndex(index);
}

void MatchingPage::refresh() {
  std::vector<DatasetRef> sets;
  for (const DatasetRef& d : document_->project().datasets) {
    if (d.kind == dataset_kind::kProbePoints) sets.push_back(d);
  }
  if (sets == sets_ && projectFile_ == document_->fileName() && combo_->count() > 0) return;
  sets_ = std::move(sets);
  projectFile_ = document_->fileName();
  const QString previous = currentDataset();
  {
    const QSignalBlocker blocker(combo_);
    combo_->clear();
    for (const DatasetRef& d : sets_) {
      const QString id = QString::fromStdString(d.id);
      combo_->addItem(id, id);
      combo_->setItemData(combo_->count() - 1, QString::fromStdString(d.description), Qt::ToolTipRole);
    }
    const int keep = combo_->findData(previous);
    combo_->setCurrentIndex(keep >= 0 ? keep : 0);
  }
  showPoints(combo_->currentIndex());
}

void MatchingPage::showPoints(int comboIndex) {
  error_.clear();
  if (comboIndex < 0 || comboIndex >= static_cast<int>(sets_.size())) {
    info_->clear();
    message_->setText(
        tr("This project has no probe points. Add a dataset of kind \"probe_points\" to the "
           "project file (id, surface, nominal point, normal, measured point)."));
    stack_->setCurrentWidget(message_);
    return;
  }
  const DatasetRef& dataset = sets_[static_cast<std::size_t>(comboIndex)];
  try {
    const ProbePointSet points = readProbePoints(document_->datasetPath(dataset).toStdString());
    const std::vector<double> deviations = points.deviations();
    view_->setPoints(points);

    const QLocale locale;
    table_->setRowCount(static_cast<int>(points.points.size()));
    std::set<std::string> surfaces;
    double sumSquares = 0.0;
    double maxAbs = 0.0;
    for (std::size_t i = 0; i < points.points.size(); ++i) {
      const ProbePoint& p = points.points[i];
      const int row = static_cast<int>(i);
      surfaces.insert(p.surface);
      table_->setItem(row, ColId, new QTableWidgetItem(QString::fromStdString(p.id)));
      table_->setItem(row, ColSurface, new QTableWidgetItem(QString::fromStdString(p.surface)));
      auto* deviation = new QTableWidgetItem(locale.toString(deviations[i], 'f', 4));
      deviation->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      table_->setItem(row, ColDeviation, deviation);
      sumSquares += deviations[i] * deviations[i];
      maxAbs = std::max(maxAbs, std::abs(deviations[i]));
    }
    const double rms =
        points.points.empty() ? 0.0 : std::sqrt(sumSquares / static_cast<double>(points.points.size()));
    QString info = tr("%1 points on %2 surfaces, %3. Before matching: RMS deviation %4 mm, largest %5 mm.")
                       .arg(points.points.size())
                       .arg(surfaces.size())
                       .arg(points.hasNormals ? tr("with normals") : tr("positions only"))
                       .arg(locale.toString(rms, 'f', 4), locale.toString(maxAbs, 'f', 4));
    if (!dataset.licence.empty())
      info += QLatin1Char(' ') + tr("Licence: %1.").arg(QString::fromStdString(dataset.licence));
    if (!dataset.description.empty())
      info.prepend(QString::fromStdString(dataset.description) + QLatin1Char('\n'));
    info_->setText(info);
    stack_->setCurrentWidget(content_);
  } catch (const std::exception& e) {
    error_ = QString::fromStdString(e.what());
    info_->clear();
    message_->setText(tr("Cannot show these probe points:\n%1").arg(error_));
    stack_->setCurrentWidget(message_);
  }
}

}  // namespace metrofit
