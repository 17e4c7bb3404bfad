#include "app/gui/kinematicspage.h"

#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontMetrics>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QSplitter>
#include <QStackedWidget>
#include <QStyle>
#include <QTabWidget>
#include <QTableWidget>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <exception>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/gui/notesedit.h"
#include "app/gui/studysettingbinding.h"
#include "core/diagnose/applied_setup_matching.h"
#include "core/io/cmm_text_report.h"
#include "core/io/csv.h"
#include "core/io/dfq.h"
#include "core/io/file_io.h"
#include "core/kinematics/export.h"
#include "core/kinematics/iso230_4.h"
#include "core/project/datasets.h"
#include "core/project/stored_results.h"
#include "widgets/common/tablecopy.h"
#include "widgets/common/usernumber.h"
#include "widgets/diagnose/coretexts.h"
#include "widgets/document/projectdocument.h"
#include "widgets/document/storedresulttext.h"
#include "widgets/document/studyinfo.h"
#include "widgets/kinematics/ballbartext.h"
#include "widgets/kinematics/kinematicsviews.h"

namespace metrofit {
namespace {

/// Rows as high as their label (column 0) needs when it wraps at the column's width. (The item
/// delegate's own size hint can keep a label on one line that the painter then wraps and cuts.)
void fitRowsToLabels(QTableWidget* t) {
  const int padding = 2 * (t->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, t) + 1) + 2;
  const int rowHeight = t->verticalHeader()->defaultSectionSize();
  const int width = std::max(1, t->columnWidth(0) - padding);
  for (int r = 0; r < t->rowCount(); ++r) {
    const QTableWidgetItem* item = t->item(r, 0);
    if (item == nullptr) continue;
    const QFontMetrics fm(item->font());
    const QRect box = fm.boundingRect(QRect(0, 0, width, 10000), Qt::TextWordWrap, item->text());
    t->setRowHeight(r, std::max(rowHeight, box.height() + rowHeight - fm.height()));
  }
}

/// Fits the rows again whenever the table is shown or resized, once the stretched label column has
/// its new width (queued: the header resizes its sections after the viewport's resize event).
class RowFitter : public QObject {
 public:
  explicit RowFitter(QTableWidget* table) : QObject(table), table_(table) {
    table->installEventFilter(this);
    table->viewport()->installEventFilter(this);
    connect(table->horizontalHeader(), &QHeaderView::sectionResized, this, [this](int column) {
      if (column == 0) schedule();
    });
  }

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (event->type() == QEvent::Resize || event->type() == QEvent::Show) schedule();
    return QObject::eventFilter(watched, event);
  }

 private:
  void schedule() {
    QMetaObject::invokeMethod(
        this, [this] { fitRowsToLabels(table_); }, Qt::QueuedConnection);
  }
  QTableWidget* table_;
};

QTableWidget* makeTable(QWidget* parent, const QStringList& header, const QString& name) {
  auto* t = new QTableWidget(parent);
  t->setObjectName(name);
  t->setColumnCount(static_cast<int>(header.size()));
  t->setHorizontalHeaderLabels(header);
  t->verticalHeader()->hide();
  t->setEditTriggers(QAbstractItemView::NoEditTriggers);
  t->setSelectionBehavior(QAbstractItemView::SelectRows);
  t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  t->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  t->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  t->verticalHeader()->setDefaultSectionSize(t->fontMetrics().height() + 6);
  // The label column takes what is left: a long (translated) label wraps onto a second line
  // instead of being cut short.
  t->setWordWrap(true);
  t->setTextElideMode(Qt::ElideNone);
  new RowFitter(t);
  enableTableCopy(t);
  return t;
}

void setRow(QTableWidget* t, int row, const QStringList& cells, const QString& tip = {}) {
  for (int c = 0; c < cells.size(); ++c) {
    auto* item = new QTableWidgetItem(cells[c]);
    if (c > 0) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    if (!tip.isEmpty())
      item->setToolTip(tip);
    else if (c == 0)  // the label column stretches into what is left and may be cut short
      item->setToolTip(cells[c]);
    t->setItem(row, c, item);
  }
}

QString um(double mm, int decimals = 3) {
  return QLocale().toString(mm * 1000.0, 'f', decimals);
}

QString deg(double d) {
  return QLocale().toString(d, 'f', 6);
}

/// mm with 4 decimals, without "-0.0000".
QString mm4(double v) {
  return QLocale().toString(std::abs(v) < 5e-5 ? 0.0 : v, 'f', 4);
}

/// The dataset the diagnosis of `domain` ran on when effects were applied there and it is not
/// `datasetId` (the applied effects belong to that dataset), else empty.
/// The dataset whose diagnosis applied effects (not this one), or empty: core's rule, as a QString.
QString appliedElsewhere(const Project& project, const char* domain, const std::string& datasetId) {
  return QString::fromStdString(diagnose::appliedEffectsElsewhere(project, domain, datasetId));
}

/// The item data of a study value that is not a dataset id (a number, an empty text ...): the page
/// refuses such settings, and any choice of the chooser, "(none)" included, replaces it.
const QString kNotAnId = QStringLiteral("\u0001(not a dataset id)");

/// The dataset id a chooser shows for a study value: "" for none (no key), kNotAnId for a bad value.
QString pickerValue(const nlohmann::json& v) {
  if (v.is_null()) return {};
  if (!v.is_string() || v.get<std::string>().empty()) return kNotAnId;
  return QString::fromStdString(v.get<std::string>());
}

}  // namespace

KinematicsPage::KinematicsPage(ProjectDocument* document, QWidget* parent)
    : QWidget(parent),
      document_(document),
      combo_(new QComboBox(this)),
      info_(new QLabel(this)),
      stack_(new QStackedWidget(this)),
      message_(new QLabel(this)),
      tabs_(new QTabWidget(this)),
      path_(new CircularPathView(this)),
      polar_(new PolarDeviationView(this)),
      errors_(nullptr),
      compensationTable_(nullptr),
      spc_(new SpcView(this)),
      identifyButton_(new QPushButton(tr("&Identify"), this)),
      compensateButton_(new QPushButton(tr("&Compensate"), this)),
      gcodeButton_(new QPushButton(tr("Export &G-code…"), this)),
      stepNcButton_(new QPushButton(tr("Export &STEP-NC…"), this)) {
  setObjectName(QStringLiteral("kinematicsPage"));
  auto* title = new QLabel(studyTitle(QString::fromLatin1(study::kKinematics)), this);
  QFont titleFont = title->font();
  titleFont.setPointSizeF(titleFont.pointSizeF() * 1.4);
  titleFont.setBold(true);
  title->setFont(titleFont);
  title->setToolTip(studySummary(QString::fromLatin1(study::kKinematics)));

  combo_->setObjectName(QStringLiteral("circularTestCombo"));
  combo_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  combo_->setMinimumContentsLength(14);
  info_->setObjectName(QStringLiteral("kinematicsInfo"));
  stored_ = new QLabel(this);
  stored_->setObjectName(QStringLiteral("kinematicsStored"));
  stored_->setWordWrap(true);
  stored_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  stored_->setVisible(false);
  info_->setWordWrap(true);
  info_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  message_->setObjectName(QStringLiteral("kinematicsMessage"));
  message_->setWordWrap(true);
  message_->setAlignment(Qt::AlignCenter);
  message_->setTextInteractionFlags(Qt::TextSelectableByMouse);

  identifyButton_->setShortcut(QKeySequence(Qt::Key_F5));
  identifyButton_->setToolTip(
      tr("Identify the actuator origin and orientation errors of the circular test "
         "(Levenberg-Marquardt, standard errors from the residuals) (F5)"));
  compensateButton_->setObjectName(QStringLiteral("compensateButton"));
  compensateButton_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_K));
  compensateButton_->setToolTip(
      tr("Compensated references for the nominal circle (Eq. 15 with the identified "
         "errors), and what they give (Ctrl+K)"));
  gcodeButton_->setToolTip(tr("Write the compensated references as G-code (G01 blocks)"));
  stepNcButton_->setToolTip(tr("Write the compensated references as a STEP-NC (ISO 10303-21) file"));

  errors_ = makeTable(this, {tr("error"), tr("identified"), tr("std. error"), tr("simulated")},
                      QStringLiteral("identifiedErrorTable"));
  compensationTable_ =
      makeTable(this, {tr("max radial deviation"), tr("µm")}, QStringLiteral("compensationTable"));

  auto* side = new QWidget(this);
  auto* sideLayout = new QVBoxLayout(side);
  sideLayout->setContentsMargins(0, 0, 0, 0);
  auto* errorsLabel = new QLabel(tr("<b>Identified errors</b> (origin in µm, angles in deg)"), side);
  applied_ = new QLabel(side);
  applied_->setObjectName(QStringLiteral("kinematicsApplied"));
  applied_->setWordWrap(true);
  applied_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  applied_->setToolTip(
      tr("Effects added with Apply on the Diagnosis page: the identification, the compensated references "
         "and their exports include them. Undo the Apply to use the declared model again."));
  applied_->setVisible(false);
  auto* compLabel = new QLabel(tr("<b>Compensation</b> of the nominal circle"), side);
  sideLayout->addWidget(applied_);
  sideLayout->addWidget(errorsLabel);
  sideLayout->addWidget(errors_, 3);
  sideLayout->addWidget(compLabel);
  sideLayout->addWidget(compensationTable_, 2);
  side->setMinimumWidth(340);

  auto* pathTab = new QSplitter(Qt::Horizontal, this);
  pathTab->setObjectName(QStringLiteral("kinematicsPathSplitter"));
  pathTab->addWidget(path_);
  pathTab->addWidget(polar_);
  pathTab->addWidget(side);
  pathTab->setStretchFactor(0, 3);
  pathTab->setStretchFactor(1, 3);
  pathTab->setStretchFactor(2, 2);
  pathTab->setChildrenCollapsible(false);
  pathTab->setSizes({330, 360, 360});
  tabs_->addTab(pathTab, tr("&Path"));
  spcTab_ = new QWidget(this);
  {
    auto* spcLayout = new QVBoxLayout(spcTab_);
    spcLayout->setContentsMargins(0, 0, 0, 0);
    // The series and its limits, chosen here (studies.kinematics.spc; no project file needed).
    auto* settingsRow = new QHBoxLayout;
    settingsRow->setContentsMargins(4, 4, 4, 0);
    const auto addLabelled = [&](const QString& caption, QWidget* w, const QString& tip) {
      w->setToolTip(tip);
      auto* l = new QLabel(caption, spcTab_);
      l->setBuddy(w);
      if (settingsRow->count() > 0) settingsRow->addSpacing(10);
      settingsRow->addWidget(l);
      settingsRow->addWidget(w);
    };
    spcSeries_ = new QComboBox(spcTab_);
    spcSeries_->setObjectName(QStringLiteral("spcSeries"));
    spcSeries_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    spcSeries_->setMinimumContentsLength(6);
    addLabelled(tr("Se&ries:"), spcSeries_,
                tr("The measured series charted (a feature series or a CMM report, one value per part; "
                   "studies.kinematics.spc.dataset)"));
    spcColumn_ = new QComboBox(spcTab_);
    spcColumn_->setObjectName(QStringLiteral("spcColumn"));
    spcColumn_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    spcColumn_->setMinimumContentsLength(8);
    addLabelled(tr("C&haracteristic:"), spcColumn_,
                tr("The column of the series charted (studies.kinematics.spc.column)"));
    spcSubgroup_ = new QSpinBox(spcTab_);
    spcSubgroup_->setObjectName(QStringLiteral("spcSubgroup"));
    spcSubgroup_->setRange(2, 25);
    addLabelled(tr("S&ubgroup:"), spcSubgroup_,
                tr("Consecutive parts per subgroup of the X-bar/R chart (studies.kinematics.spc.subgroup)"));
    const auto limitEdit = [&](const char* name, const QString& caption, const QString& tip) {
      auto* e = new QLineEdit(spcTab_);
      e->setObjectName(QString::fromLatin1(name));
      e->setPlaceholderText(tr("none"));
      e->setMaximumWidth(fontMetrics().horizontalAdvance(QStringLiteral("-0000.00000")) + 16);
      addLabelled(caption, e, tip);
      connect(e, &QLineEdit::editingFinished, this, &KinematicsPage::writeSpcLimits);
      return e;
    };
    spcLsl_ = limitEdit("spcLsl", tr("&LSL:"),
                        tr("Lower specification limit, in the series' unit (studies.kinematics.spc.lsl)"));
    spcUsl_ = limitEdit("spcUsl", tr("USL:"),
                        tr("Upper specification limit, in the series' unit (studies.kinematics.spc.usl)"));
    spcNominal_ = limitEdit("spcNominal", tr("&Nominal:"),
                            tr("The desired value, in the series' unit (studies.kinematics.spc.nominal)"));
    settingsRow->addStretch(1);
    spcLayout->addLayout(settingsRow);
    spcHint_ = new QLabel(spcTab_);
    spcHint_->setObjectName(QStringLiteral("spcHint"));
    spcHint_->setWordWrap(true);
    spcHint_->setVisible(false);
    spcLayout->addWidget(spcHint_);
    connect(spcSeries_, &QComboBox::currentIndexChanged, this,
            [this](int index) { chooseSpcSeries(spcSeries_->itemData(index).toString()); });
    connect(spcColumn_, &QComboBox::currentIndexChanged, this, [this](int index) {
      const QString column = spcColumn_->itemData(index).toString();
      if (column.isEmpty()) return;
      document_->setStudyValue(QString::fromLatin1(study::kKinematics), QStringLiteral("/spc/column"),
                               column.toStdString(), tr("Choose the SPC characteristic"));
    });
    bindStudySetting(
        document_, spcSubgroup_, QString::fromLatin1(study::kKinematics), QStringLiteral("/spc/subgroup"),
        [this]() -> qint64 {
          const nlohmann::json v =
              document_->studyValue(QString::fromLatin1(study::kKinematics), QStringLiteral("/spc/subgroup"));
          return v.is_number_integer() ? v.get<qint64>() : KinematicsSettings::Spc{}.subgroup;
        },
        false, tr("Change the SPC subgroup size"));
    spcLayout->addWidget(spc_, 1);
    // The export sits at the end of the settings row: the tab is no taller than before (1280x800).
    spcDfqButton_ = new QPushButton(tr("Export Q-DAS &DFQ…"), spcTab_);
    spcDfqButton_->setObjectName(QStringLiteral("spcDfq"));
    spcDfqButton_->setEnabled(false);
    settingsRow->addWidget(spcDfqButton_);
    // The boxes ask for little room (1280x800 in German and Polish) and take what is left, so that
    // dataset and column names are not cut where the window has room.
    settingsRow->setStretchFactor(spcSeries_, 1);
    settingsRow->setStretchFactor(spcColumn_, 1);
    connect(spcDfqButton_, &QPushButton::clicked, this, &KinematicsPage::onExportSpcDfq);
  }
  tabs_->addTab(spcTab_, tr("S&PC"));

  auto* actuators = new QWidget(this);
  auto* actLayout = new QVBoxLayout(actuators);
  fromSpcLabel_ = new QLabel(actuators);
  fromSpcLabel_->setObjectName(QStringLiteral("fromSpcLabel"));
  fromSpcLabel_->setWordWrap(true);
  fromSpcLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  fromSpcTable_ = makeTable(actuators, {tr("error"), tr("from SPC"), tr("from circular test")},
                            QStringLiteral("fromSpcTable"));
  threeAxisLabel_ = new QLabel(actuators);
  threeAxisLabel_->setObjectName(QStringLiteral("threeAxisLabel"));
  threeAxisLabel_->setWordWrap(true);
  threeAxisLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  threeAxisTable_ = makeTable(actuators,
                              {tr("plane"), tr("u axis angle a (°)"), tr("v axis angle b (°)"),
                               tr("squareness b − a (°)"), tr("± std. error (°)"), tr("RMS (µm)")},
                              QStringLiteral("threeAxisTable"));
  // The datasets of the chain and of the three-axis identification, chosen here (undoable edits of
  // the study's settings; the study is computed again on the change).
  const QStringList edgeKinds{QString::fromLatin1(dataset_kind::kFeatureSeries)};
  const QStringList planeKinds{QString::fromLatin1(dataset_kind::kCircularTest),
                               QString::fromLatin1(dataset_kind::kFeatureSeries)};
  pickers_ = {
      Picker{nullptr, QStringLiteral("/from_spc/x_dataset"), edgeKinds, tr("Choose the edge along X")},
      Picker{nullptr, QStringLiteral("/from_spc/y_dataset"), edgeKinds, tr("Choose the edge along Y")},
      Picker{nullptr, QStringLiteral("/planes/xy"), planeKinds, tr("Choose the XY circular test")},
      Picker{nullptr, QStringLiteral("/planes/yz"), planeKinds, tr("Choose the YZ circular test")},
      Picker{nullptr, QStringLiteral("/planes/zx"), planeKinds, tr("Choose the ZX circular test")}};
  const QString pickerNames[5] = {QStringLiteral("edgeXCombo"), QStringLiteral("edgeYCombo"),
                                  QStringLiteral("planeXyCombo"), QStringLiteral("planeYzCombo"),
                                  QStringLiteral("planeZxCombo")};
  const QString pickerLabels[5] = {tr("Edge along &X:"), tr("Edge along &Y:"), tr("XY circular &test:"),
                                   tr("Y&Z circular test:"), tr("ZX circ&ular test:")};
  const QString pickerTips[5] = {
      tr("The edge machined along X and measured (feature series, CSV position_mm,deviation_mm)"),
      tr("The edge machined along Y and measured (feature series, CSV position_mm,deviation_mm)"),
      tr("Circular test in the XY plane (CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm)"),
      tr("Circular test in the YZ plane (CSV y_cmd_mm,z_cmd_mm,y_meas_mm,z_meas_mm)"),
      tr("Circular test in the ZX plane (CSV z_cmd_mm,x_cmd_mm,z_meas_mm,x_meas_mm)")};
  QHBoxLayout* pickerRows[2] = {new QHBoxLayout, new QHBoxLayout};
  for (std::size_t i = 0; i < pickers_.size(); ++i) {
    Picker& p = pickers_[i];
    p.combo = new QComboBox(actuators);
    p.combo->setObjectName(pickerNames[i]);
    p.combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    p.combo->setMinimumContentsLength(12);
    p.combo->setToolTip(pickerTips[i]);
    auto* label = new QLabel(pickerLabels[i], actuators);
    label->setBuddy(p.combo);
    QHBoxLayout* row = pickerRows[i < 2 ? 0 : 1];
    if (i != 0 && i != 2) row->addSpacing(12);
    row->addWidget(label);
    row->addWidget(p.combo);
    // A choice is an undoable edit of the study; "(none)" removes the key.
    const QString key = p.key;
    bindStudyDatasetSetting(
        document_, p.combo, QString::fromLatin1(study::kKinematics), key,
        [this, key] {
          const nlohmann::json v = document_->studyValue(QString::fromLatin1(study::kKinematics), key);
          return pickerValue(v);
        },
        p.undoText);
  }
  edgesDfqButton_ = new QPushButton(tr("Save &DFQ…"), actuators);
  edgesDfqButton_->setObjectName(QStringLiteral("edgesDfq"));
  edgesDfqButton_->setEnabled(false);
  connect(edgesDfqButton_, &QPushButton::clicked, this, &KinematicsPage::onExportEdgesDfq);
  pickerRows[0]->addSpacing(12);
  pickerRows[0]->addWidget(edgesDfqButton_);
  pickerRows[0]->addStretch(1);
  pickerRows[1]->addStretch(1);
  actLayout->addLayout(pickerRows[0]);
  actLayout->addWidget(fromSpcLabel_);
  actLayout->addWidget(fromSpcTable_, 4);
  actLayout->addLayout(pickerRows[1]);
  actLayout->addWidget(threeAxisLabel_);
  actLayout->addWidget(threeAxisTable_, 1);
  // With both tables hidden (nothing chosen yet) the messages stay under their choosers and the space
  // left goes below them.
  for (QLabel* l : {fromSpcLabel_, threeAxisLabel_})
    l->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Maximum);
  actLayout->addStretch(0);
  // Tab order as shown: the edges, Save DFQ, their table, the plane tests, their table.
  QWidget* const order[] = {pickers_[0].combo, pickers_[1].combo, edgesDfqButton_,   fromSpcTable_,
                            pickers_[2].combo, pickers_[3].combo, pickers_[4].combo, threeAxisTable_};
  for (std::size_t i = 0; i + 1 < std::size(order); ++i) QWidget::setTabOrder(order[i], order[i + 1]);
  tabs_->addTab(actuators, tr("&Actuators"));

  // The ballbar breakdown of the test (core/kinematics/ballbar.h), ranked by share.
  auto* causes = new QWidget(this);
  auto* causesLayout = new QVBoxLayout(causes);
  ballbarLabel_ = new QLabel(causes);
  ballbarLabel_->setObjectName(QStringLiteral("ballbarLabel"));
  ballbarLabel_->setWordWrap(true);
  ballbarLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* causesNote = new QLabel(
      tr("The radial deviation of both runs fitted to the signature of each cause, after the centre and "
         "radius of each run (as metrofit-cli kinematic identify writes it under \"causes\"). Share: the "
         "part "
         "of the radial deviation's variance the cause explains. Grey: within the noise (at most three "
         "standard errors)."),
      causes);
  causesNote->setWordWrap(true);
  causesNote->setTextInteractionFlags(Qt::TextSelectableByMouse);
  ballbarTable_ = makeTable(causes, {tr("cause"), tr("value (µm)"), tr("± std. error (µm)"), tr("share (%)")},
                            QStringLiteral("ballbarTable"));
  causesLayout->addWidget(ballbarLabel_);
  causesLayout->addWidget(causesNote);
  causesLayout->addWidget(ballbarTable_, 1);
  tabs_->addTab(causes, tr("&Ballbar"));
  stack_->addWidget(tabs_);
  stack_->addWidget(message_);
  radialPage_ = new QWidget(this);
  radialLabel_ = new QLabel(radialPage_);
  radialLabel_->setObjectName(QStringLiteral("kinematicsRadialMessage"));
  radialLabel_->setWordWrap(true);
  radialLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  radialPolar_ = new PolarDeviationView(radialPage_);
  auto* radialLayout = new QVBoxLayout(radialPage_);
  radialLayout->addWidget(radialLabel_);
  radialLayout->addWidget(radialPolar_, 1);
  stack_->addWidget(radialPage_);

  auto* top = new QHBoxLayout;
  auto* comboLabel = new QLabel(tr("C&ircular test:"), this);
  comboLabel->setBuddy(combo_);
  top->addWidget(title);
  top->addSpacing(16);
  top->addWidget(comboLabel);
  top->addWidget(combo_);
  top->addSpacing(12);
  top->addWidget(identifyButton_);
  top->addWidget(compensateButton_);
  top->addWidget(gcodeButton_);
  top->addWidget(stepNcButton_);
  top->addStretch(1);

  auto* notes = new NotesEdit(document_, QString::fromLatin1(study::kKinematics), this);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(top);
  layout->addWidget(info_);
  layout->addWidget(stored_);
  layout->addWidget(stack_, 1);
  layout->addWidget(notes);

  connect(combo_, &QComboBox::currentIndexChanged, this, &KinematicsPage::onDatasetChosen);
  connect(identifyButton_, &QPushButton::clicked, this, [this] { identify(); });
  connect(compensateButton_, &QPushButton::clicked, this, [this] {
    if (!compensate()) QMessageBox::warning(this, tr("Compensate"), error_);
  });
  connect(gcodeButton_, &QPushButton::clicked, this, &KinematicsPage::onExportGcode);
  connect(stepNcButton_, &QPushButton::clicked, this, &KinematicsPage::onExportStepNc);
  connect(document_, &ProjectDocument::changed, this, &KinematicsPage::refresh);
  refresh();
}

KinematicsPage::~KinematicsPage() = default;

QString KinematicsPage::currentDataset() const {
  return combo_->currentData().toString();
}

void KinematicsPage::selectDataset(const QString& id) {
  const int index = combo_->findData(id);
  if (index >= 0) combo_->setCurrentIndex(index);
}

void KinematicsPage::syncPickers() {
  const Project& project = document_->project();
  for (const Picker& p : pickers_) {
    const nlohmann::json value = document_->studyValue(QString::fromLatin1(study::kKinematics), p.key);
    const QString current = pickerValue(value);
    // (text, id, tooltip): none, the datasets of the picker's kinds, and the study's own choice when it
    // is not among them (another kind, or not in the project: the study then says why it cannot use it).
    std::vector<std::array<QString, 3>> items{{tr("(none)"), QString(), QString()}};
    bool found = current.isEmpty();
    for (const DatasetRef& d : project.datasets) {
      if (!p.kinds.contains(QString::fromStdString(d.kind))) continue;
      const QString id = QString::fromStdString(d.id);
      items.push_back({id, id, QString::fromStdString(d.description)});
      found = found || id == current;
    }
    if (current == kNotAnId) {
      items.push_back(
          {tr("%1 (not a dataset id)").arg(QString::fromStdString(value.dump())), current, QString()});
    } else if (!found) {
      items.push_back(
          {project.dataset(current.toStdString()) ? current : tr("%1 (not in the project)").arg(current),
           current, QString()});
    }
    const QSignalBlocker blocker(p.combo);
    bool same = p.combo->count() == static_cast<int>(items.size());
    for (int i = 0; same && i < p.combo->count(); ++i) {
      const auto& item = items[static_cast<std::size_t>(i)];
      same = p.combo->itemText(i) == item[0] && p.combo->itemData(i).toString() == item[1] &&
             p.combo->itemData(i, Qt::ToolTipRole).toString() == item[2];
    }
    if (!same) {
      p.combo->clear();
      for (const auto& item : items) {
        p.combo->addItem(item[0], item[1]);
        if (!item[2].isEmpty()) p.combo->setItemData(p.combo->count() - 1, item[2], Qt::ToolTipRole);
      }
    }
    p.combo->setCurrentIndex(p.combo->findData(current));
  }
}

namespace {

/// A limit typed in a field (widgets/common/usernumber.h); empty for none, `ok` false for a text that is
/// no number.
std::optional<double> typedNumber(const QString& text, bool* ok) {
  *ok = true;
  if (text.trimmed().isEmpty()) return std::nullopt;
  const std::optional<double> v = parseUserNumber(text);
  *ok = v.has_value();
  return v;
}

QString shownNumber(const nlohmann::json& v) {
  return v.is_number() ? QLocale().toString(v.get<double>(), 'g', 12) : QString();
}

}  // namespace

QStringList KinematicsPage::spcColumns(const std::string& datasetId) {
  const DatasetRef* dataset = document_->project().dataset(datasetId);
  if (!dataset) return {};
  const std::string path = document_->datasetPath(*dataset).toStdString();
  const QFileInfo info(QString::fromStdString(path));
  const nlohmann::json key = {path,
                              info.lastModified().toMSecsSinceEpoch(),
                              info.size(),
                              nlohmann::json(dataset->csv.columnMap),
                              dataset->csv.headerLines,
                              static_cast<int>(dataset->csv.dialect.delimiter),
                              static_cast<int>(dataset->csv.dialect.decimal),
                              dataset->csv.commentPrefix};
  if (key.dump() == spcColumnsKey_) return spcColumnsCache_;
  spcColumnsKey_ = key.dump();
  spcColumnsCache_.clear();
  spcCounterColumns_.clear();
  try {
    const CsvTable table = readFeatureTable(path, dataset->csv);
    for (const std::string& column : table.header()) {
      if (column == "run" || column == "date") continue;
      try {
        const std::vector<double> v = table.numericColumn(column);
        spcColumnsCache_ << QString::fromStdString(column);
        // A counter (part, sample number): consecutive integers.
        bool counter = v.size() > 1;
        for (std::size_t i = 1; counter && i < v.size(); ++i)
          counter = v[i] - v[i - 1] == 1.0 && v[i] == std::floor(v[i]);
        if (counter) spcCounterColumns_ << QString::fromStdString(column);
      } catch (const std::exception&) {
        // Not numbers in every row: not a characteristic to chart.
      }
    }
  } catch (const std::exception&) {
    // Unreadable: nothing to offer; the SPC view says why when the study reads it.
  }
  return spcColumnsCache_;
}

void KinematicsPage::syncSpcControls() {
  const QString study = QString::fromLatin1(study::kKinematics);
  const nlohmann::json block = document_->studyValue(study, QStringLiteral("/spc"));
  const QString current = block.is_object() && block.contains("dataset") && block["dataset"].is_string()
                              ? QString::fromStdString(block["dataset"].get<std::string>())
                              : QString();
  {
    const QSignalBlocker blocker(spcSeries_);
    spcSeries_->clear();
    spcSeries_->addItem(tr("(none)"), QString());
    std::vector<std::string> kinds = datasetKindsServing(dataset_kind::kCmmReport);
    kinds.push_back(dataset_kind::kFeatureSeries);
    for (const DatasetRef& d : document_->project().datasets) {
      if (std::find(kinds.begin(), kinds.end(), d.kind) == kinds.end()) continue;
      spcSeries_->addItem(QString::fromStdString(d.id), QString::fromStdString(d.id));
    }
    if (!current.isEmpty() && spcSeries_->findData(current) < 0) spcSeries_->addItem(current, current);
    spcSeries_->setCurrentIndex(std::max(0, spcSeries_->findData(current)));
  }
  const bool chosen = !current.isEmpty();
  {
    const QSignalBlocker blocker(spcColumn_);
    spcColumn_->clear();
    const QStringList columns = chosen ? spcColumns(current.toStdString()) : QStringList();
    for (const QString& c : columns) spcColumn_->addItem(c, c);
    const QString column = block.is_object() && block.contains("column") && block["column"].is_string()
                               ? QString::fromStdString(block["column"].get<std::string>())
                               : QString();
    if (!column.isEmpty() && spcColumn_->findData(column) < 0) spcColumn_->addItem(column, column);
    spcColumn_->setCurrentIndex(spcColumn_->findData(column));
  }
  // Subgroup and limits edit a block that names its series: without one they would make the study
  // unreadable (dataset and column are required), so they wait for the series.
  for (QWidget* w : std::initializer_list<QWidget*>{spcColumn_, spcSubgroup_, spcLsl_, spcUsl_, spcNominal_})
    w->setEnabled(chosen);
  const auto show = [](QLineEdit* e, const nlohmann::json& v) {
    if (e->hasFocus()) return;  // typing is not disturbed; editingFinished writes it
    const QSignalBlocker blocker(e);
    e->setText(shownNumber(v));
  };
  const auto value = [&](const char* key) {
    return block.is_object() && block.contains(key) ? block[key] : nlohmann::json();
  };
  {
    // The study's subgroup (the binding writes edits; showing the study's value is the page's).
    const nlohmann::json sub = value("subgroup");
    const int shown = sub.is_number_integer() ? sub.get<int>() : KinematicsSettings::Spc{}.subgroup;
    if (!spcSubgroup_->hasFocus() && shown >= spcSubgroup_->minimum() && shown <= spcSubgroup_->maximum()) {
      const QSignalBlocker blocker(spcSubgroup_);
      spcSubgroup_->setValue(shown);
    }
  }
  // Limits being typed (one given, the hint shown) stay as typed until both are there.
  if (!spcHint_->isVisibleTo(spcTab_)) {
    show(spcLsl_, value("lsl"));
    show(spcUsl_, value("usl"));
  }
  show(spcNominal_, value("nominal"));
}

QString KinematicsPage::spcLimitsHint() const {
  return spcHint_->isHidden() ? QString() : spcHint_->text();
}

void KinematicsPage::chooseSpcSeries(const QString& id) {
  const QString study = QString::fromLatin1(study::kKinematics);
  const nlohmann::json block = document_->studyValue(study, QStringLiteral("/spc"));
  if (id.isEmpty()) {
    document_->setStudyValue(study, QStringLiteral("/spc"), nlohmann::json(), tr("Remove the SPC series"));
    return;
  }
  const QStringList columns = spcColumns(id.toStdString());
  QString column = block.is_object() && block.contains("column") && block["column"].is_string()
                       ? QString::fromStdString(block["column"].get<std::string>())
                       : QString();
  if (!columns.contains(column)) {
    // The first deviation column of a report (".dev"), else the first numeric column.
    column.clear();
    for (const QString& c : columns)
      if (c.endsWith(QLatin1String(".dev"))) {
        column = c;
        break;
      }
    if (column.isEmpty() && !columns.isEmpty()) column = columns.front();
    // Not a counter (spcColumns marks them) when the series has another column.
    if (!column.isEmpty() && !column.endsWith(QLatin1String(".dev")))
      for (const QString& c : columns)
        if (!spcCounterColumns_.contains(c)) {
          column = c;
          break;
        }
  }
  if (column.isEmpty()) {
    spcHint_->setText(tr("“%1” has no column of numbers to chart.").arg(id));
    spcHint_->setVisible(true);
    syncSpcControls();
    return;
  }
  spcHint_->clear();
  spcHint_->setVisible(false);
  QUndoStack* stack = document_->undoStack();
  stack->beginMacro(tr("Choose the SPC series"));
  document_->setStudyValue(study, QStringLiteral("/spc/dataset"), id.toStdString(),
                           tr("Choose the SPC series"));
  document_->setStudyValue(study, QStringLiteral("/spc/column"), column.toStdString(),
                           tr("Choose the SPC series"));
  stack->endMacro();
}

void KinematicsPage::writeSpcLimits() {
  const QString study = QString::fromLatin1(study::kKinematics);
  if (!document_->studyValue(study, QStringLiteral("/spc/dataset")).is_string()) return;
  bool okL = true, okU = true, okN = true;
  const std::optional<double> lsl = typedNumber(spcLsl_->text(), &okL);
  const std::optional<double> usl = typedNumber(spcUsl_->text(), &okU);
  const std::optional<double> nominal = typedNumber(spcNominal_->text(), &okN);
  QString hint;
  if (!okL || !okU || !okN)
    hint = tr("Not a number: %1").arg(!okL ? spcLsl_->text() : !okU ? spcUsl_->text() : spcNominal_->text());
  else if (lsl.has_value() != usl.has_value())
    hint = tr("Give both specification limits (LSL and USL), or neither; nothing is written until then.");
  else if (lsl && !(*lsl < *usl))
    hint = tr("The lower specification limit must be below the upper one.");
  spcHint_->setText(hint);
  spcHint_->setVisible(!hint.isEmpty());
  std::vector<std::pair<QString, nlohmann::json>> edits;
  if (hint.isEmpty()) {
    edits.push_back({QStringLiteral("/spc/lsl"), lsl ? nlohmann::json(*lsl) : nlohmann::json()});
    edits.push_back({QStringLiteral("/spc/usl"), usl ? nlohmann::json(*usl) : nlohmann::json()});
  }
  if (okN)
    edits.push_back({QStringLiteral("/spc/nominal"), nominal ? nlohmann::json(*nominal) : nlohmann::json()});
  std::vector<std::pair<QString, nlohmann::json>> changed;
  for (const auto& e : edits)
    if (document_->studyValue(study, e.first) != e.second) changed.push_back(e);
  if (changed.empty()) return;
  QUndoStack* stack = document_->undoStack();
  if (changed.size() > 1) stack->beginMacro(tr("Change the SPC limits"));
  for (const auto& e : changed)
    document_->setStudyValue(study, e.first, e.second, tr("Change the SPC limits"));
  if (changed.size() > 1) stack->endMacro();
}

void KinematicsPage::refresh() {
  syncPickers();
  syncSpcControls();
  std::vector<DatasetRef> sets = circularTestDatasets(document_->project());
  // Resolved paths: a Save As to another folder (which rewrites relative paths) keeps the results.
  for (DatasetRef& d : sets) d = document_->resolvedDataset(d);
  const auto it = document_->project().studies.find(study::kKinematics);
  nlohmann::json settings = it != document_->project().studies.end() ? *it : nlohmann::json();
  if (settings.is_object()) settings.erase("notes");  // notes edits must not re-run the study
  std::string json = settings.dump();
  // The applied effects (Apply / undo on the diagnosis page) change the model: identify again.
  if (const auto diag = document_->project().studies.find(study::kDiagnosis);
      diag != document_->project().studies.end() && diag->is_object() && diag->contains("kinematic"))
    json += (*diag)["kinematic"].dump();
  for (const DatasetRef& d : document_->project().datasets)
    json += d.id + d.kind + document_->datasetPath(d).toStdString();
  if (sets == datasets_ && json == studyJson_ && generation_ == document_->generation() &&
      combo_->count() > 0) {
    projectFile_ = document_->fileName();
    return;
  }
  datasets_ = std::move(sets);
  studyJson_ = std::move(json);
  projectFile_ = document_->fileName();
  generation_ = document_->generation();
  QString select = currentDataset();
  // Settings that cannot be read are refused (identify() shows why, naming the field): never a default
  // in place of a bad value.
  settingsError_.clear();
  QString studyDataset;
  try {
    studyDataset = QString::fromStdString(kinematicStudySettings(document_->project()).dataset);
  } catch (const std::exception& e) {
    settingsError_ = QString::fromStdString(e.what());
  }
  const auto has = [&](const QString& id) {
    return std::any_of(datasets_.begin(), datasets_.end(),
                       [&](const DatasetRef& d) { return QString::fromStdString(d.id) == id; });
  };
  if (!has(select)) select = studyDataset;
  onDatasetChosen(fillDatasetCombo(combo_, datasets_, select));
}

void KinematicsPage::onDatasetChosen(int) {
  study_.reset();
  compensation_.reset();
  identify();
}

void KinematicsPage::showSettingsError() {
  error_ = settingsError_;
  info_->clear();
  stored_->setVisible(false);
  message_->setText(tr("The kinematics study's settings are invalid; nothing is run until they are "
                       "corrected (Undo, or the project file):\n%1")
                        .arg(settingsError_));
  stack_->setCurrentWidget(message_);
  updateButtons();
}

bool KinematicsPage::identify() {
  error_.clear();
  study_.reset();
  compensation_.reset();
  stored_->setVisible(false);
  if (!settingsError_.isEmpty()) {
    showSettingsError();
    return false;
  }
  for (int i = 0; i < tabs_->count(); ++i) tabs_->setTabEnabled(i, true);
  const QString id = currentDataset();
  if (id.isEmpty()) {
    info_->clear();
    error_ =
        tr("This project has no circular test. Add a dataset of kind \"circular_test\" (CSV "
           "x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm, one loop CCW then one CW), e.g. made by "
           "metrofit-cli simulate circular.");
    // A shop's part series is charted without a circular test: the SPC tab alone, when the project has
    // a series to chart.
    if (spcSeries_->count() > 1) {
      info_->setText(
          tr("No circular test in this project: only the SPC tab is available. %1")
              .arg(tr("Import a circular test (Ctrl+I) for the path, actuators and ballbar tabs.")));
      for (int i = 0; i < tabs_->count(); ++i) tabs_->setTabEnabled(i, tabs_->widget(i) == spcTab_);
      tabs_->setCurrentWidget(spcTab_);
      stack_->setCurrentWidget(tabs_);
      spcDfqButton_->setEnabled(false);
      std::string spcError;
      std::optional<KinematicSpcSeries> series;
      try {
        const KinematicStudySettings settings = kinematicStudySettings(document_->project());
        if (settings.spc) {
          const ProjectDocument* doc = document_;
          series = chartKinematicSpc(
              document_->project(), *settings.spc,
              [doc](const DatasetRef& d) { return doc->datasetPath(d).toStdString(); }, &spcError);
        }
      } catch (const std::exception& e) {
        spcError = e.what();
      }
      if (series) {
        spc_->setResult(series->result, series->values, QString::fromStdString(series->column),
                        QString::fromStdString(series->unit));
      } else if (!spcError.empty()) {
        spc_->setMessage(tr("Cannot chart the SPC series:\n%1").arg(QString::fromStdString(spcError)));
      } else {
        spc_->setMessage(
            tr("No SPC series is chosen: choose the measured series and its characteristic above "
               "(a feature series or a CMM report, imported with File › Import data, Ctrl+I)."));
      }
      updateButtons();
      return false;
    }
    message_->setText(error_);
    stack_->setCurrentWidget(message_);
    updateButtons();
    return false;
  }
  try {
    const ProjectDocument* doc = document_;
    study_ = loadKinematicStudy(
        document_->project(), [doc](const DatasetRef& d) { return doc->datasetPath(d).toStdString(); },
        id.toStdString());
  } catch (const std::exception& e) {
    error_ = QString::fromStdString(e.what());
    info_->clear();
    QString text = tr("Cannot identify this circular test:\n%1").arg(error_);
    // A radial-only (ballbar) test cannot be identified, but it has its ISO 230-4 results and polar plot.
    if (const DatasetRef* ref = document_->project().dataset(id.toStdString())) {
      try {
        const CircularTrace trace = readCircularTrace(document_->datasetPath(*ref).toStdString(), ref->csv);
        if (trace.radialOnly) {
          const CircularAnalysis a = analyseCircularTrace(trace);
          if (const QString iso = isoText(a.iso); !iso.isEmpty()) text += QLatin1Char('\n') + iso;
          radialPolar_->setData(radialTestPolarData(trace, a, tr("Radial deviation (polar, magnified)")));
          radialLabel_->setText(text);
          message_->setText(text);
          stack_->setCurrentWidget(radialPage_);
          updateButtons();
          return false;
        }
      } catch (const std::exception&) {
        // The message above names the problem.
      }
    }
    message_->setText(text);
    stack_->setCurrentWidget(message_);
    updateButtons();
    return false;
  }
  showStudy();
  updateButtons();
  showStoredResult();
  return true;
}

QWidget* KinematicsPage::currentView() const {
  return stack_->currentWidget();
}

/// One line of ISO 230-4 results (core/kinematics/iso230_4.h) in µm: G and F per direction, H.
QString KinematicsPage::isoText(const Iso230Result& iso) {
  QStringList parts;
  const QLocale locale;  // the UI language's decimal mark, as every other number on the page
  for (const Iso230Direction& d : iso.directions) {
    parts << tr("%1: G %2 µm, F %3 … %4 µm")
                 .arg(d.counterClockwise ? tr("CCW") : tr("CW"))
                 .arg(locale.toString(d.circularDeviationMm * 1000.0, 'f', 2))
                 .arg(locale.toString(d.radialDeviationMinMm * 1000.0, 'f', 2))
                 .arg(locale.toString(d.radialDeviationMaxMm * 1000.0, 'f', 2));
  }
  if (iso.circularHysteresisMm)
    parts << tr("H %1 µm").arg(locale.toString(*iso.circularHysteresisMm * 1000.0, 'f', 2));
  return parts.isEmpty() ? QString() : tr("ISO 230-4: %1").arg(parts.join(QStringLiteral("; ")));
}

void KinematicsPage::showStudy() {
  const KinematicStudyData& s = *study_;
  const IdentifyResult& r = s.identification;
  QString info = tr("%1 points, nominal circle R %2 mm about (%3, %4) mm; %n loop(s).", nullptr,
                    static_cast<int>(s.analysis.loops.size()))
                     .arg(s.measured.size())
                     .arg(QLocale().toString(s.analysis.radiusMm, 'g', 6))
                     .arg(mm4(s.analysis.centreMm.x()), mm4(s.analysis.centreMm.y()));
  if (!s.dataset.description.empty())
    info.prepend(QString::fromStdString(s.dataset.description) + QLatin1Char('\n'));
  if (const QString iso = isoText(s.analysis.iso); !iso.isEmpty()) info += QLatin1Char('\n') + iso;
  if (const QString elsewhere = appliedElsewhere(document_->project(), "kinematic", s.dataset.id);
      !elsewhere.isEmpty()) {
    info += QLatin1Char('\n') +
            tr("Effects applied on the Diagnosis page belong to the circular test %1 (the one "
               "the diagnosis ran on); this test uses the declared model.")
                .arg(elsewhere);
  }
  info_->setText(info);

  const std::optional<ActuatorErrors2>& truth = s.settings.simulatedMachine;
  auto sim = [&](double v, bool micro) {
    if (!truth) return QStringLiteral("—");
    return micro ? um(v) : deg(v);
  };
  const bool withEffects = !s.applied.empty();
  applied_->setVisible(withEffects);
  applied_->setText(withEffects ? tr("Includes applied effects: %1")
                                      .arg(QString::fromStdString(s.applied.text())
                                               .replace(QStringLiteral(" um"), QStringLiteral(" µm")))
                                : QString());
  errors_->setRowCount(withEffects && s.declaredRmseMm ? 8 : 7);
  setRow(errors_, 0,
         {tr("origin x (µm)"), um(r.errors.originMm.x()), um(r.standardErrors.originMm.x()),
          sim(truth ? truth->originMm.x() : 0.0, true)},
         tr("Where the tool is at command 0 (Oyr of Eq. 9), x"));
  setRow(errors_, 1,
         {tr("origin y (µm)"), um(r.errors.originMm.y()), um(r.standardErrors.originMm.y()),
          sim(truth ? truth->originMm.y() : 0.0, true)},
         tr("Where the tool is at command 0 (Oyr of Eq. 9), y"));
  setRow(errors_, 2,
         {tr("X axis angle a (deg)"), deg(r.errors.xAxisAngleDeg), deg(r.standardErrors.xAxisAngleDeg),
          sim(truth ? truth->xAxisAngleDeg : 0.0, false)},
         tr("The X actuator moves along (cos a, sin a); counter-clockwise positive"));
  setRow(errors_, 3,
         {tr("Y axis angle b (deg)"), deg(r.errors.yAxisAngleDeg), deg(r.standardErrors.yAxisAngleDeg),
          sim(truth ? truth->yAxisAngleDeg : 0.0, false)},
         tr("The Y actuator moves along (-sin b, cos b); counter-clockwise positive"));
  setRow(errors_, 4,
         {tr("squareness b − a (deg)"), deg(r.errors.squarenessDeg()), deg(r.squarenessStdErrDeg),
          sim(truth ? truth->squarenessDeg() : 0.0, false)},
         tr("The angle between the axes is 90° + (b − a)"));
  setRow(errors_, 5, {tr("RMS residual (µm)"), um(r.rmseMm), QString(), QString()},
         withEffects ? tr("Root mean square of the residual distances after identification, with the "
                          "applied effects")
                     : tr("Root mean square of the residual distances after identification"));
  setRow(
      errors_, 6,
      {tr("iterations"), QString::number(r.run.iterations), terminationText(r.run.termination), QString()});
  if (withEffects && s.declaredRmseMm) {
    setRow(errors_, 7, {tr("RMS, declared model only (µm)"), um(*s.declaredRmseMm), QString(), QString()},
           tr("The residual of the declared model (origin and axis angles, no applied effects)"));
  }
  errors_->setColumnHidden(3, !truth);
  fitRowsToLabels(errors_);

  // Measured path and its radial deviations.
  path_->setData(circularPathData(s.measured, s.analysis, tr("Path (XY)")));
  polar_->setData(circularPolarData(s.analysis, tr("Radial deviation (polar, magnified)")));

  compensationTable_->setRowCount(1);
  setRow(compensationTable_, 0, {tr("measured"), um(s.analysis.maxAbsDeviationMm)});
  showBallbar();

  spcDfqButton_->setEnabled(s.spc.has_value());
  spcDfqButton_->setToolTip(
      s.spc ? tr("Write the feature series with its limits as a Q-DAS DFQ file (the K-field file SPC "
                 "packages import)")
            : tr("The kinematics study names no SPC series to export"));
  if (s.spc) {
    spc_->setResult(s.spc->result, s.spc->values, QString::fromStdString(s.spc->column),
                    QString::fromStdString(s.spc->unit));
  } else if (!s.spcError.empty()) {
    spc_->setMessage(tr("Cannot chart the SPC series:\n%1").arg(QString::fromStdString(s.spcError)));
  } else {
    spc_->setMessage(
        tr("No SPC series is chosen: choose the measured series and its characteristic above "
           "(a feature series or a CMM report, imported with File › Import data, Ctrl+I)."));
  }
  showActuators();
  stack_->setCurrentWidget(tabs_);
}

void KinematicsPage::showBallbar() {
  const CircularAnalysis& a = study_->analysis;
  if (!a.ballbar) {
    ballbarLabel_->setText(tr("<b>Ballbar breakdown</b>: not available (%1)")
                               .arg(QString::fromStdString(a.ballbarUnavailable).toHtmlEscaped()));
    ballbarTable_->setRowCount(0);
    ballbarTable_->setVisible(false);
    return;
  }
  const BallbarBreakdown& b = *a.ballbar;
  ballbarLabel_->setText(b.bothDirections ? tr("<b>Ballbar breakdown</b> (ranked by share)")
                                          : tr("<b>Ballbar breakdown</b> (ranked by share; one direction: "
                                               "no reversal causes)"));
  ballbarTable_->setVisible(true);
  const int n = static_cast<int>(b.causes.size());
  ballbarTable_->setRowCount(n + 1);
  const QLocale locale;
  const QColor grey = palette().color(QPalette::Disabled, QPalette::Text);
  for (int i = 0; i < n; ++i) {
    const BallbarCause& c = b.causes[static_cast<std::size_t>(i)];
    QString tip = ballbarCauseTip(c.name);
    if (!c.significant) {
      tip += QLatin1Char('\n') +
             tr("Within the noise: |%1 µm| is at most three standard errors (%2 µm)")
                 .arg(locale.toString(c.valueUm, 'f', 3), locale.toString(c.stdErrorUm, 'f', 3));
    }
    setRow(ballbarTable_, i,
           {ballbarCauseName(c.name), locale.toString(c.valueUm, 'f', 3),
            locale.toString(c.stdErrorUm, 'f', 3), locale.toString(c.share * 100.0, 'f', 1)},
           tip);
    if (!c.significant) {
      for (int col = 0; col < 4; ++col) ballbarTable_->item(i, col)->setForeground(grey);
    }
  }
  setRow(ballbarTable_, n,
         {ballbarCauseName("unexplained"), locale.toString(b.residualRmsUm, 'f', 3), QString(),
          locale.toString(b.unexplainedShare * 100.0, 'f', 1)},
         ballbarCauseTip("unexplained"));
  fitRowsToLabels(ballbarTable_);
}

void KinematicsPage::showActuators() {
  const KinematicStudyData& s = *study_;
  const IdentifyResult& id = s.identification;
  if (s.fromSpc) {
    const SpcActuatorResult& r = *s.fromSpc;
    const QString verdict =
        r.apply ? tr("compensation applied: %n of 4 line parameters beyond ± k standard errors "
                     "(k = %1), residuals in control",
                     nullptr,
                     int(r.x.slopeSignificant) + int(r.y.slopeSignificant) + int(r.x.interceptSignificant) +
                         int(r.y.interceptSignificant))
                      .arg(QLocale().toString(r.options.coverageFactor))
                : (r.reason.rfind("not compensated: the residuals", 0) == 0
                       ? tr("not compensated: the residuals about a regression line are out "
                            "of control (special causes first)")
                       : tr("not compensated: no slope or intercept beyond ± k standard "
                            "errors (random scatter)"));
    fromSpcLabel_->setText(
        tr("<b>From SPC to compensation</b> (IEEE Access, kinematic compensation algorithm): the offset "
           "angle of the regression line of the edge "
           "along X is the X actuator's angle a, minus that of the edge along Y is b (Eq. 9), the intercepts "
           "give the origin; %1.")
            .arg(verdict.toHtmlEscaped()));
    fromSpcTable_->setVisible(true);
    fromSpcTable_->setRowCount(9);
    int row = 0;
    setRow(fromSpcTable_, row++,
           {tr("offset angle, edge along X (°)"), deg(r.x.line.angleDeg), QStringLiteral("—")},
           tr("atan(slope) of the deviation against the position (Fig. 10); ± %1°")
               .arg(deg(r.x.line.slopeStdErr * 180.0 / 3.141592653589793)));
    setRow(fromSpcTable_, row++,
           {tr("offset angle, edge along Y (°)"), deg(r.y.line.angleDeg), QStringLiteral("—")},
           tr("atan(slope) of the deviation against the position (Fig. 10); ± %1°")
               .arg(deg(r.y.line.slopeStdErr * 180.0 / 3.141592653589793)));
    setRow(fromSpcTable_, row++,
           {tr("origin x (µm)"), um(r.errors.originMm.x()), um(id.errors.originMm.x())});
    setRow(fromSpcTable_, row++,
           {tr("origin y (µm)"), um(r.errors.originMm.y()), um(id.errors.originMm.y())});
    setRow(fromSpcTable_, row++,
           {tr("X axis angle a (deg)"), deg(r.errors.xAxisAngleDeg), deg(id.errors.xAxisAngleDeg)});
    setRow(fromSpcTable_, row++,
           {tr("Y axis angle b (deg)"), deg(r.errors.yAxisAngleDeg), deg(id.errors.yAxisAngleDeg)});
    setRow(fromSpcTable_, row++,
           {tr("squareness b − a (deg)"), deg(r.errors.squarenessDeg()), deg(id.errors.squarenessDeg())});
    setRow(fromSpcTable_, row++, {tr("largest correction (µm)"), um(s.fromSpcLargestCorrectionMm), QString()},
           tr("Largest |reference − nominal point| of the Eq. 15 references for the nominal circle"));
    setRow(fromSpcTable_, row++,
           {tr("circular test model: before → after (µm)"),
            tr("%1 → %2").arg(um(s.fromSpcModelBeforeMm), um(s.fromSpcModelAfterMm)), QString()},
           tr("The machine identified from the circular test (an independent estimate) on the nominal "
              "circle and on the references derived from SPC: largest distance from the nominal points"));
    fitRowsToLabels(fromSpcTable_);
  } else {
    fromSpcTable_->setVisible(false);
    fromSpcLabel_->setText(
        s.fromSpcError.empty()
            ? tr("<b>From SPC to compensation</b>: choose the edges machined along X and along Y above "
                 "(feature series, CSV position_mm,deviation_mm in mm, e.g. made by metrofit-cli simulate "
                 "edge).")
            : tr("<b>From SPC to compensation</b>: cannot derive the actuator errors:<br>%1")
                  .arg(QString::fromStdString(s.fromSpcError).toHtmlEscaped()));
  }

  if (s.threeAxis) {
    const Identify3Result& r = *s.threeAxis;
    const ActuatorErrors3& e = r.errors;
    threeAxisLabel_->setText(
        tr("<b>Three axes</b> from circular tests in XY, YZ and ZX: origin (%1, %2, %3) µm ± %4 µm, "
           "RMS residual %5 µm, %6 points.")
            .arg(um(e.originMm.x()), um(e.originMm.y()), um(e.originMm.z()),
                 um(r.standardErrors.originMm.maxCoeff()), um(r.rmseMm))
            .arg(r.points));
    threeAxisTable_->setVisible(true);
    threeAxisTable_->setRowCount(3);
    for (const TestPlane p : kTestPlanes) {
      const auto i = static_cast<std::size_t>(p);
      setRow(
          threeAxisTable_, static_cast<int>(i),
          {QString::fromLatin1(planeName(p)).toUpper(), deg(e.uAngleDeg[i]), deg(e.vAngleDeg[i]),
           deg(e.squarenessDeg(p)), deg(r.squarenessStdErrDeg[i]), um(r.planes[i].rmseMm)},
          tr("In the plane (u, v) the u actuator moves along (cos a, sin a), the v actuator along (−sin b, "
             "cos b); the angle between them is 90° + (b − a)"));
    }
    fitRowsToLabels(threeAxisTable_);
    // Its three rows in full, without a scroll bar (the from-SPC table above takes what is left).
    int height = threeAxisTable_->horizontalHeader()->sizeHint().height() + 2 * threeAxisTable_->frameWidth();
    for (int r = 0; r < threeAxisTable_->rowCount(); ++r) height += threeAxisTable_->rowHeight(r);
    threeAxisTable_->setMinimumHeight(height);
  } else {
    threeAxisTable_->setVisible(false);
    threeAxisLabel_->setText(
        s.threeAxisError.empty()
            ? tr("<b>Three axes</b>: choose the circular tests in the XY, YZ and ZX planes above (made "
                 "e.g. by metrofit-cli simulate circular --plane yz).")
            : tr("<b>Three axes</b>: cannot identify:<br>%1")
                  .arg(QString::fromStdString(s.threeAxisError).toHtmlEscaped()));
  }
}

bool KinematicsPage::compensate() {
  if (!study_ && !identify()) return false;
  try {
    compensation_ = compensateStudy(*study_);
  } catch (const std::exception& e) {
    error_ = QString::fromStdString(e.what());
    updateButtons();
    return false;
  }
  showCompensation();
  updateButtons();
  storeResult();
  showStoredResult();
  return true;
}

void KinematicsPage::storeResult() {
  if (!study_ || !compensation_) return;
  try {
    const DatasetRef dataset = document_->resolvedDataset(study_->dataset);
    document_->setStoredResult(QString::fromLatin1(study::kKinematics), QString::fromStdString(dataset.id),
                               makeStoredResult(document_->projectPathForDatasets().toStdString(), dataset,
                                                kinematicStoredSettings(document_->project(), dataset.id),
                                                kinematicResultJson(*study_, *compensation_)));
  } catch (const std::exception&) {
    // The test cannot be read any more: nothing is stored, the page shows the result.
  }
}

QString KinematicsPage::storedResultText() const {
  const QString id = currentDataset();
  const auto it = std::find_if(datasets_.begin(), datasets_.end(),
                               [&](const DatasetRef& d) { return QString::fromStdString(d.id) == id; });
  if (id.isEmpty() || it == datasets_.end() || !settingsError_.isEmpty()) return {};
  StoredResult stored;
  try {
    stored = storedResult(document_->project(), document_->projectPathForDatasets().toStdString(),
                          study::kKinematics, *it, kinematicStoredSettings(document_->project(), it->id));
  } catch (const std::exception&) {
    return {};
  }
  if (const std::optional<QString> state = storedStateText(
          stored,
          {tr("The stored result (computed %1) is out of date: the kinematics settings changed since. "
              "Compensate (Ctrl+K) to compute it with these settings."),
           tr("The stored result (computed %1) is out of date: the circular test's file changed since. "
              "Compensate (Ctrl+K) to compute it on the test as it is now."),
           tr("The stored result (computed %1) cannot be checked: the circular test's file cannot be "
              "read.")}))
    return *state;
  const QString when = storedTimeText(stored.computed);
  const nlohmann::json& e = stored.entry;
  const nlohmann::json identified = e.value("identified", nlohmann::json());
  const nlohmann::json comp = e.value("compensation", nlohmann::json());
  QString text =
      tr("From the saved project, computed %1 with these settings on this test: identified origin (%2, %3) "
         "µm, X axis angle a %4°, Y axis angle b %5°, squareness b − a %6°, RMS residual %7 µm. "
         "Compensation: max radial deviation %8 µm measured, %9 µm expected after (RMS %10 µm), largest "
         "correction %11 µm.")
          .arg(when, um(storedFigure(identified, "origin_x_mm")), um(storedFigure(identified, "origin_y_mm")),
               deg(storedFigure(identified, "x_axis_angle_deg")),
               deg(storedFigure(identified, "y_axis_angle_deg")),
               deg(storedFigure(identified, "squareness_deg")), um(storedFigure(identified, "rmse_mm")),
               um(storedFigure(comp, "max_before_mm")), um(storedFigure(comp, "max_expected_mm")))
          .arg(um(storedFigure(comp, "rms_expected_mm")), um(storedFigure(comp, "largest_correction_mm")));
  if (comp.is_object() && comp.contains("max_simulated_mm"))
    text += QLatin1Char(' ') +
            tr("Simulated machine after: %1 µm.").arg(um(storedFigure(comp, "max_simulated_mm")));
  return text + QLatin1Char(' ') + tr("Compensate (Ctrl+K) to see the compensated path.");
}

void KinematicsPage::showStoredResult() {
  // The compensation computed here is the result; a stored one is shown until then.
  const QString text = compensation_ ? QString() : storedResultText();
  stored_->setText(text);
  stored_->setVisible(!text.isEmpty());
}

void KinematicsPage::showCompensation() {
  const CompensationPreview& c = *compensation_;
  PathPlotData pd = path_->data();
  PolarPlotData polar = polar_->data();
  addCompensationPreview(pd, polar, c, study_->analysis);
  path_->setData(pd);
  polar_->setData(polar);

  int rows = 5 + (c.maxSimulatedMm ? 1 : 0);
  compensationTable_->setRowCount(rows);
  int row = 0;
  setRow(compensationTable_, row++, {tr("measured (before)"), um(c.maxBeforeMm)},
         tr("Largest |radial deviation| of the measured path from the nominal circle"));
  setRow(compensationTable_, row++, {tr("identified model, after"), um(c.maxModelMm, 6)},
         tr("The compensated references run through the identified model (Eq. 9): on the circle up to "
            "rounding"));
  setRow(compensationTable_, row++, {tr("expected after (measured residual)"), um(c.maxExpectedMm)},
         tr("The measured path moved by what the references change: the residual the model does not explain "
            "(noise, unmodelled effects) stays"));
  setRow(compensationTable_, row++, {tr("expected after, RMS distance"), um(c.rmsExpectedMm)},
         tr("Root mean square distance of the expected path from the nominal points (before: %1 µm)")
             .arg(um(c.rmsBeforeMm)));
  if (c.maxSimulatedMm) {
    setRow(compensationTable_, row++, {tr("simulated machine, after"), um(*c.maxSimulatedMm)},
           tr("The references run through the simulated machine (the true errors of the study), noise free"));
  }
  setRow(compensationTable_, row++, {tr("largest correction"), um(c.largestCorrectionMm)},
         tr("Largest |reference − nominal point|"));
  fitRowsToLabels(compensationTable_);
}

void KinematicsPage::updateButtons() {
  const bool ok = study_.has_value();
  identifyButton_->setEnabled(!currentDataset().isEmpty() && settingsError_.isEmpty());
  compensateButton_->setEnabled(ok);
  gcodeButton_->setEnabled(ok);
  stepNcButton_->setEnabled(ok);
  edgesDfqButton_->setEnabled(ok && study_->fromSpc.has_value());
  edgesDfqButton_->setToolTip(ok && study_->fromSpc
                                  ? tr("Write the two edges' deviations (mm) as a Q-DAS DFQ file, two "
                                       "characteristics")
                                  : tr("Choose the edges machined along X and Y first"));
}

void KinematicsPage::showView(const QString& view) {
  if (!study_) identify();
  if (view == QLatin1String("spc")) {
    tabs_->setCurrentIndex(1);
  } else if (view == QLatin1String("actuators")) {
    tabs_->setCurrentIndex(2);
  } else if (view == QLatin1String("ballbar")) {
    tabs_->setCurrentIndex(3);
  } else {
    tabs_->setCurrentIndex(0);
    if (study_ && !compensation_) compensate();
  }
}

bool KinematicsPage::exportGcode(const QString& path, QString* error) {
  if (!compensation_ && !compensate()) {
    if (error) *error = error_;
    return false;
  }
  try {
    GcodeOptions o;
    o.programName = "compensated " + study_->dataset.id;
    if (!study_->applied.empty()) o.programName += " with applied effects " + study_->applied.text();
    writeFileAtomic(path.toStdString(),
                    compensatedPathToGcode(compensation_->references, study_->identification.errors, o));
  } catch (const std::exception& e) {
    if (error) *error = QString::fromStdString(e.what());
    return false;
  }
  return true;
}

bool KinematicsPage::exportStepNc(const QString& path, QString* error) {
  if (!compensation_ && !compensate()) {
    if (error) *error = error_;
    return false;
  }
  try {
    StepNcOptions o;
    o.fileName = QFileInfo(path).fileName().toStdString();
    o.timestamp = QDateTime::currentDateTimeUtc().toString(Qt::ISODate).chopped(1).toStdString();
    o.projectName = "Metrofit compensated " + study_->dataset.id;
    if (!study_->applied.empty()) o.projectName += " with applied effects " + study_->applied.text();
    writeFileAtomic(path.toStdString(),
                    compensatedPathToStepNc(compensation_->references, study_->identification.errors, o));
  } catch (const std::exception& e) {
    if (error) *error = QString::fromStdString(e.what());
    return false;
  }
  return true;
}

void KinematicsPage::onExportGcode() {
  const QString dir = QFileInfo(document_->fileName()).absolutePath();
  const QString file =
      QFileDialog::getSaveFileName(this, tr("Export compensated path as G-code"),
                                   QDir(dir).filePath(currentDataset() + QStringLiteral("_compensated.nc")),
                                   tr("G-code (*.nc *.ngc *.gcode)"));
  if (file.isEmpty()) return;
  QString error;
  if (!exportGcode(file, &error)) QMessageBox::warning(this, tr("Export G-code"), error);
}

bool KinematicsPage::exportSpcDfq(const QString& path, QString* error) {
  if (!study_ || !study_->spc || !study_->settings.spc) {
    if (error) *error = tr("The kinematics study names no SPC series to export.");
    return false;
  }
  try {
    const KinematicSpcSeries& series = *study_->spc;
    const SpcOptions& o = study_->settings.spc->options;
    const std::string file = document_->datasetPath(series.dataset).toStdString();
    const CsvTable table = readFeatureTable(file, series.dataset.csv);
    const std::vector<double> values = table.numericColumn(series.column);
    writeFileAtomic(path.toStdString(), writeDfq(seriesDfqPart(table, series.column, values, o.nominal, o.lsl,
                                                               o.usl, file, {}, displayPath(file))));
  } catch (const std::exception& e) {
    if (error) *error = QString::fromUtf8(e.what());
    return false;
  }
  return true;
}

void KinematicsPage::onExportSpcDfq() {
  const QString dir = QFileInfo(document_->fileName()).absolutePath();
  const QString name =
      study_ && study_->spc ? QString::fromStdString(study_->spc->dataset.id) : QStringLiteral("spc");
  const QString file = QFileDialog::getSaveFileName(this, tr("Export Q-DAS DFQ"),
                                                    QDir(dir).filePath(name + QStringLiteral(".dfq")),
                                                    tr("Q-DAS DFQ files (*.dfq);;All files (*)"));
  if (file.isEmpty()) return;
  QString error;
  if (!exportSpcDfq(file, &error)) QMessageBox::warning(this, tr("Export Q-DAS DFQ"), error);
}

bool KinematicsPage::exportEdgesDfq(const QString& path, QString* error) {
  if (!study_ || !study_->fromSpc || !study_->settings.fromSpc || study_->fromSpcEdges.size() != 2) {
    if (error) *error = tr("Choose the edges machined along X and Y first.");
    return false;
  }
  try {
    const AxisFeatureSeries& x = study_->fromSpcEdges[0];
    const AxisFeatureSeries& y = study_->fromSpcEdges[1];
    const auto fileName = [](const AxisFeatureSeries& s) {
      return QFileInfo(QString::fromStdString(s.source)).fileName().toStdString();
    };
    writeFileAtomic(path.toStdString(),
                    edgesDfq(x, y, study_->settings.fromSpc->deviationColumn, fileName(x), fileName(y)));
  } catch (const std::exception& e) {
    if (error) *error = QString::fromUtf8(e.what());
    return false;
  }
  return true;
}

void KinematicsPage::onExportEdgesDfq() {
  const QString dir = QFileInfo(document_->fileName()).absolutePath();
  const QString file = QFileDialog::getSaveFileName(this, tr("Save the edges as Q-DAS DFQ"),
                                                    QDir(dir).filePath(QStringLiteral("edges.dfq")),
                                                    tr("Q-DAS DFQ files (*.dfq);;All files (*)"));
  if (file.isEmpty()) return;
  QString error;
  if (!exportEdgesDfq(file, &error)) QMessageBox::warning(this, tr("Save DFQ"), error);
}

void KinematicsPage::onExportStepNc() {
  const QString dir = QFileInfo(document_->fileName()).absolutePath();
  const QString file =
      QFileDialog::getSaveFileName(this, tr("Export compensated path as STEP-NC"),
                                   QDir(dir).filePath(currentDataset() + QStringLiteral("_compensated.p21")),
                                   tr("STEP-NC Part 21 (*.p21 *.stp)"));
  if (file.isEmpty()) return;
  QString error;
  if (!exportStepNc(file, &error)) QMessageBox::warning(this, tr("Export STEP-NC"), error);
}

}  // namespace metrofit
