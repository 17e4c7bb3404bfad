#include "app/gui/matchingpage.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QFontMetrics>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeySequence>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QShortcut>
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
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>

#include "app/gui/machinedialog.h"
#include "app/gui/notesedit.h"
#include "app/gui/studysettingbinding.h"
#include "core/common/error.h"
#include "core/io/file_io.h"
#include "core/matching/cad_match.h"
#include "core/matching/evaluation.h"
#include "core/matching/fit_input.h"
#include "core/matching/hole_table.h"
#include "core/project/nominals.h"
#include "core/project/stored_results.h"
#include "core/study/study_settings.h"
#include "widgets/common/tablecopy.h"
#include "widgets/document/projectdocument.h"
#include "widgets/document/storedresulttext.h"
#include "widgets/document/studyinfo.h"
#include "widgets/matching/matchingcurveview.h"
#include "widgets/matching/pointsetview.h"

namespace metrofit {

namespace {

/// The one setting `key` of studies.matching read on its own (MatchingSettings::fromJson / isValid), so
/// that a bad value of another key does not hide it; nullopt when it is refused (the binding then
/// leaves its control as it is: refused, never replaced by a default).
std::optional<MatchingSettings> matchingSettingField(const Project& project, const char* key) {
  const auto study = project.studies.find(study::kMatching);
  nlohmann::json one = nlohmann::json::object();
  if (study != project.studies.end() && study->is_object() && study->contains(key)) one[key] = (*study)[key];
  try {
    MatchingSettings s = MatchingSettings::fromJson(one);
    if (!s.isValid(nullptr, nullptr)) return std::nullopt;
    return s;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

/// The study's settings (matchingStudySettings) when the page's controls can show them as they are: a
/// tolerance the spin box would clamp or round (0, 20 mm, 0.0355 mm; all valid for the study and the
/// report) is refused naming the field, never matched with the value the control shows instead.
matching::MatchingStudySettings readMatchingSettings(const Project& project, const QString& projectFile,
                                                     const QDoubleSpinBox* tolerance) {
  matching::MatchingStudySettings s = matching::matchingStudySettings(project, projectFile.toStdString());
  const double t = s.options.toleranceMm;
  const double scale = std::pow(10.0, tolerance->decimals());
  if (t < tolerance->minimum() || t > tolerance->maximum() ||
      std::abs(std::round(t * scale) / scale - t) > 1e-9 * std::max(1.0, t)) {
    throw std::runtime_error(
        MatchingPage::tr(
            "studies.matching.tolerance_mm: %1 mm cannot be set on the page (it takes %2 to %3 mm "
            "in steps of %4 mm)")
            .arg(QString::number(t, 'g', 12), QString::number(tolerance->minimum()),
                 QString::number(tolerance->maximum()), QString::number(1.0 / scale))
            .toStdString());
  }
  return s;
}

/// studies.diagnosis.matching.applied and .dataset as text ("" when absent), to notice Apply and its
/// undo.
std::string appliedKeyOf(const Project& project) {
  const auto s = project.studies.find(study::kDiagnosis);
  if (s == project.studies.end() || !s->is_object()) return {};
  const auto d = s->find(study::kMatching);
  if (d == s->end() || !d->is_object()) return {};
  const auto a = d->find("applied");
  return a == d->end() ? std::string() : a->dump() + '\n' + d->value("dataset", nlohmann::json()).dump();
}
enum Column { ColId, ColSurface, ColDeviation, ColAfter, ColumnCount };

using matching::MatchMethod;

constexpr MatchMethod kMethods[] = {MatchMethod::Sade, MatchMethod::GaSimplex, MatchMethod::ClosedForm,
                                    MatchMethod::Minimax};
constexpr const char* kDofNames[] = {"rx", "ry", "rz", "x", "y", "z"};

/// The controls of the frame tab, in the combo's order, with the names the user knows them by.
constexpr std::pair<machine::FrameFormat, const char*> kFrameControls[] = {
    {machine::FrameFormat::Heidenhain, "HEIDENHAIN"},
    {machine::FrameFormat::Siemens, "SINUMERIK"},
    {machine::FrameFormat::Fanuc, "FANUC"}};

QString methodTitle(MatchMethod m) {
  switch (m) {
    case MatchMethod::Sade:
      return MatchingPage::tr("SADE (rough + fine, paper settings)");
    case MatchMethod::GaSimplex:
      return MatchingPage::tr("GA-simplex (rough + fine)");
    case MatchMethod::ClosedForm:
      return MatchingPage::tr("Closed form (least-squares optimum)");
    case MatchMethod::Minimax:
      return MatchingPage::tr("Minimax (smallest largest deviation)");
  }
  return {};
}

QString methodShort(MatchMethod m) {
  switch (m) {
    case MatchMethod::Sade:
      return QStringLiteral("SADE");
    case MatchMethod::GaSimplex:
      return QStringLiteral("GA-simplex");
    case MatchMethod::ClosedForm:
      return MatchingPage::tr("closed form");
    case MatchMethod::Minimax:
      return MatchingPage::tr("minimax");
  }
  return {};
}

/// A column header on two lines so that the column takes the width of its numbers, not of its
/// (translated) title: the unit goes under the name ("rx\n(deg)"), a longer title without a unit
/// breaks at the space nearest its middle. The one-line title is the tooltip.
QTableWidgetItem* headerItem(const QString& title) {
  QString text = title;
  const qsizetype unit = title.lastIndexOf(QStringLiteral(" ("));
  if (unit > 0) {
    text = title.left(unit) + QLatin1Char('\n') + title.mid(unit + 1);
  } else if (title.size() > 8) {
    qsizetype best = -1;
    for (qsizetype i = 0; i < title.size(); ++i) {
      if (title[i] == QLatin1Char(' ') &&
          (best < 0 || std::abs(i - title.size() / 2) < std::abs(best - title.size() / 2)))
        best = i;
    }
    if (best > 0) text[best] = QLatin1Char('\n');
  }
  auto* item = new QTableWidgetItem(text);
  item->setToolTip(title);
  return item;
}

/// Column widths that fit the table's viewport, so that it does not scroll sideways at the default
/// window size in any language: every column gets the width of its content and (two-line) header;
/// when that is too wide, the text columns `wrap` (the method and axis names) get narrower, down to
/// their longest word, and their text wraps onto more lines; room left over goes to the last column.
/// Refits on every resize. With `holdMinimum` the table's minimum width is what it needs at least
/// (its splitter then gives it that much).
class ColumnFitter : public QObject {
 public:
  ColumnFitter(QTableWidget* table, QList<int> wrap, bool holdMinimum)
      : QObject(table),
        table_(table),
        viewport_(table->viewport()),
        wrap_(std::move(wrap)),
        holdMinimum_(holdMinimum) {
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    table->horizontalHeader()->setStretchLastSection(false);
    table->setWordWrap(true);
    table->installEventFilter(this);
    table->viewport()->installEventFilter(this);
  }
  /// The fitter of a table (not findChild: without Q_OBJECT that would match any QObject child).
  static ColumnFitter* of(QTableWidget* table) {
    for (QObject* child : table->children()) {
      if (auto* fitter = dynamic_cast<ColumnFitter*>(child)) return fitter;
    }
    return nullptr;
  }

  /// Fits; when the fit itself resizes the viewport (taller rows bring the vertical scroll bar,
  /// which takes its width from the viewport), fits again for the new width (at most 3 passes).
  void fit() {
    if (fitting_) {
      again_ = true;
      return;
    }
    for (int pass = 0; pass < 3; ++pass) {
      again_ = false;
      fitOnce();
      if (!again_) break;
    }
  }

 private:
  void fitOnce() {
    fitting_ = true;
    QTableWidget* t = table_;
    const QHeaderView* h = t->horizontalHeader();
    // The text margins of the item delegate (QCommonStyle: PM_FocusFrameHMargin + 1 each side).
    const int padding = 2 * (t->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, t) + 1) + 2;
    const int n = t->columnCount();
    std::vector<int> need(static_cast<std::size_t>(n), 0), least(need);
    int lastVisible = -1;
    for (int c = 0; c < n; ++c) {
      if (t->isColumnHidden(c)) continue;
      lastVisible = c;
      const auto k = static_cast<std::size_t>(c);
      int widest = 0, widestWord = 0;
      for (int r = 0; r < t->rowCount(); ++r) {
        const QTableWidgetItem* item = t->item(r, c);
        if (item == nullptr || t->columnSpan(r, c) > 1) continue;
        const QFontMetrics fm(item->font());
        widest = std::max(widest, fm.horizontalAdvance(item->text()));
        for (const QString& word : item->text().split(QLatin1Char(' '), Qt::SkipEmptyParts))
          widestWord = std::max(widestWord, fm.horizontalAdvance(word));
      }
      const int header = h->sectionSizeHint(c);
      need[k] = std::max(header, widest + padding);
      least[k] = wrap_.contains(c) ? std::max(header, widestWord + padding) : need[k];
    }
    int total = 0, atLeast = 0;
    for (int c = 0; c < n; ++c) {
      total += need[static_cast<std::size_t>(c)];
      atLeast += least[static_cast<std::size_t>(c)];
    }
    if (holdMinimum_) {
      const int scrollBar = t->style()->pixelMetric(QStyle::PM_ScrollBarExtent, nullptr, t);
      t->setMinimumWidth(atLeast + 2 * t->frameWidth() + scrollBar + 2);
    }
    std::vector<int> width = need;
    int deficit = total - t->viewport()->width();
    for (int c : wrap_) {
      if (deficit <= 0 || c >= n || t->isColumnHidden(c)) continue;
      const auto k = static_cast<std::size_t>(c);
      const int cut = std::min(deficit, need[k] - least[k]);
      width[k] -= cut;
      deficit -= cut;
    }
    if (deficit < 0 && lastVisible >= 0) width[static_cast<std::size_t>(lastVisible)] -= deficit;
    for (int c = 0; c < n; ++c) {
      if (!t->isColumnHidden(c)) t->setColumnWidth(c, width[static_cast<std::size_t>(c)]);
    }
    // Rows as high as their wrapped text.
    const int rowHeight = t->verticalHeader()->defaultSectionSize();
    for (int r = 0; r < t->rowCount(); ++r) {
      int height = rowHeight;
      for (int c : wrap_) {
        const QTableWidgetItem* item = c < n ? t->item(r, c) : nullptr;
        // Only a column made narrower than its text wraps.
        if (item == nullptr || t->isColumnHidden(c) ||
            width[static_cast<std::size_t>(c)] >= need[static_cast<std::size_t>(c)])
          continue;
        const QFontMetrics fm(item->font());
        const QRect box =
            fm.boundingRect(QRect(0, 0, std::max(1, width[static_cast<std::size_t>(c)] - padding), 10000),
                            Qt::TextWordWrap, item->text());
        height = std::max(height, box.height() + rowHeight - fm.height());
      }
      t->setRowHeight(r, height);
    }
    fitting_ = false;
  }

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override {
    // Compares pointers only: events also arrive while the table is being destroyed (its
    // QAbstractScrollArea part already gone), when calling table_->viewport() would be undefined
    // (UBSan: "member call ... does not point to an object of type 'QAbstractScrollArea'").
    if ((watched == table_ && event->type() == QEvent::Show) ||
        (watched == viewport_ && event->type() == QEvent::Resize))
      fit();
    return QObject::eventFilter(watched, event);
  }

 private:
  QTableWidget* table_;
  QWidget* viewport_;  ///< the table's viewport (the table never replaces it)
  QList<int> wrap_;
  bool holdMinimum_;
  bool fitting_ = false;
  bool again_ = false;  ///< the viewport was resized while fitting
};

QTableWidget* makeTable(QWidget* parent, const QStringList& header) {
  auto* t = new QTableWidget(parent);
  t->setColumnCount(static_cast<int>(header.size()));
  for (int c = 0; c < header.size(); ++c) t->setHorizontalHeaderItem(c, headerItem(header[c]));
  t->setEditTriggers(QAbstractItemView::NoEditTriggers);
  t->setSelectionBehavior(QAbstractItemView::SelectRows);
  t->setAlternatingRowColors(true);
  t->verticalHeader()->hide();
  t->verticalHeader()->setDefaultSectionSize(t->fontMetrics().height() + 6);
  t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  t->horizontalHeader()->setStretchLastSection(true);
  enableTableCopy(t);
  return t;
}

QTableWidgetItem* textItem(const QString& s) {
  return new QTableWidgetItem(s);
}

QTableWidgetItem* numberItem(double v, int decimals) {
  // A value that rounds to zero is shown as 0 (not "-0,0000", which reads as a sign to act on).
  const double shown = std::abs(v) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : v;
  auto* item = new QTableWidgetItem(QLocale().toString(shown, 'f', decimals));
  item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
  return item;
}

QTableWidgetItem* countItem(std::size_t n, std::size_t of, bool highlight) {
  auto* item = new QTableWidgetItem(QStringLiteral("%1 / %2").arg(n).arg(of));
  item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
  if (highlight) item->setForeground(n > 0 ? QColor(0xb2, 0x18, 0x2b) : QColor(0x1b, 0x7a, 0x1b));
  return item;
}

}  // namespace

MatchingPage::MatchingPage(ProjectDocument* document, QWidget* parent)
    : QWidget(parent),
      document_(document),
      combo_(new QComboBox(this)),
      methodCombo_(new QComboBox(this)),
      toleranceSpin_(new QDoubleSpinBox(this)),
      allowScale_(new QCheckBox(tr("Allow &scale"), this)),
      runButton_(new QPushButton(tr("&Run"), this)),
      cancelButton_(new QPushButton(tr("Cancel"), this)),
      progress_(new QProgressBar(this)),
      info_(new QLabel(this)),
      status_(new QLabel(this)),
      stack_(new QStackedWidget(this)),
      content_(new QSplitter(Qt::Vertical, this)),
      beforeView_(nullptr),
      afterView_(nullptr),
      tabs_(new QTabWidget(this)),
      methodsTable_(nullptr),
      machineLabel_(new QLabel(this)),
      machineTable_(nullptr),
      remeasureTable_(nullptr),
      remeasureLabel_(new QLabel(this)),
      curve_(nullptr),
      table_(nullptr),
      frameControl_(new QComboBox(this)),
      frameDecimals_(new QSpinBox(this)),
      frameText_(new QPlainTextEdit(this)),
      saveFrame_(new QPushButton(tr("Save fr&ame…"), this)),
      machineButton_(new QPushButton(tr("Mac&hine…"), this)),
      frameNote_(new QLabel(this)),
      frameTab_(nullptr),
      message_(new QLabel(this)),
      run_(new BackgroundRun<matching::MatchingStudyResult>(this)) {
  auto* title = new QLabel(studyTitle(QString::fromLatin1(study::kMatching)), this);
  QFont titleFont = title->font();
  titleFont.setPointSizeF(titleFont.pointSizeF() * 1.4);
  titleFont.setBold(true);
  title->setFont(titleFont);
  title->setToolTip(studySummary(QString::fromLatin1(study::kMatching)));

  combo_->setObjectName(QStringLiteral("probePointsCombo"));
  combo_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  combo_->setMinimumContentsLength(16);
  for (MatchMethod m : kMethods) methodCombo_->addItem(methodTitle(m), static_cast<int>(m));
  methodCombo_->setObjectName(QStringLiteral("matchingMethod"));
  methodCombo_->setToolTip(
      tr("The posture shown after matching and used for the machine adjustment (every method is run for "
         "the comparison table)"));
  toleranceSpin_->setObjectName(QStringLiteral("matchingTolerance"));
  toleranceSpin_->setDecimals(3);
  toleranceSpin_->setRange(0.001, 10.0);
  toleranceSpin_->setSingleStep(0.005);
  toleranceSpin_->setSuffix(tr(" mm"));
  toleranceSpin_->setToolTip(tr("Symmetric tolerance ±T of every point (mm)"));
  allowScale_->setToolTip(tr("Fit an isotropic scale too (e.g. thermal expansion of the part)"));
  runButton_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
  runButton_->setToolTip(tr("Run every matching method on these points (Ctrl+R)"));
  cancelButton_->setShortcut(QKeySequence(Qt::Key_Escape));
  cancelButton_->setToolTip(tr("Stop the running SADE / GA-simplex search (Esc)"));
  cancelButton_->setEnabled(false);
  progress_->setRange(0, 100);
  progress_->setValue(0);
  progress_->setMaximumWidth(160);
  progress_->setTextVisible(true);
  progress_->setVisible(false);
  info_->setWordWrap(true);
  info_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  status_->setObjectName(QStringLiteral("matchingStatus"));
  status_->setWordWrap(true);
  message_->setObjectName(QStringLiteral("matchingMessage"));
  message_->setWordWrap(true);
  message_->setAlignment(Qt::AlignCenter);

  // Before / after, side by side with one camera.
  auto* views = new QSplitter(Qt::Horizontal, content_);
  views->setObjectName(QStringLiteral("matchingViewsSplitter"));
  beforeView_ = new PointSetView(views);
  afterView_ = new PointSetView(views);
  beforeView_->setObjectName(QStringLiteral("beforeView"));
  afterView_->setObjectName(QStringLiteral("afterView"));
  beforeView_->setDisplay(PointSetView::Display::Before);
  afterView_->setDisplay(PointSetView::Display::After);
  afterView_->linkCamera(beforeView_);
  beforeView_->setMinimumSize(280, 240);
  afterView_->setMinimumSize(280, 240);
  views->addWidget(beforeView_);
  views->addWidget(afterView_);
  views->setChildrenCollapsible(false);

  // Results tabs.
  methodsTable_ = makeTable(tabs_, {tr("Method"), tr("rx (deg)"), tr("ry (deg)"), tr("rz (deg)"),
                                    tr("x (mm)"), tr("y (mm)"), tr("z (mm)"), tr("scale"), tr("RMSE (mm)"),
                                    tr("max |d| (mm)"), tr("out before"), tr("out after"), tr("time (ms)")});
  methodsTable_->setObjectName(QStringLiteral("matchingMethodsTable"));
  new ColumnFitter(methodsTable_, {0}, false);
  machineTable_ = makeTable(tabs_, {tr("Axis"), tr("Value"), tr("Unit")});
  machineTable_->setObjectName(QStringLiteral("matchingMachineTable"));
  new ColumnFitter(machineTable_, {0}, true);
  auto* machineBox = new QWidget(tabs_);
  auto* machineLayout = new QVBoxLayout(machineBox);
  machineLayout->setContentsMargins(4, 4, 4, 4);
  machineLabel_->setWordWrap(true);
  machineButton_->setObjectName(QStringLiteral("machineButton"));
  machineButton_->setToolTip(
      tr("The machine the adjustment values are for: topology, geometry, travel and control (Ctrl+Shift+M)"));
  connect(machineButton_, &QPushButton::clicked, this, &MatchingPage::editMachine);
  auto* machineShortcut = new QShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_M), this);
  machineShortcut->setContext(Qt::WidgetWithChildrenShortcut);
  connect(machineShortcut, &QShortcut::activated, this, &MatchingPage::editMachine);
  auto* machineRow = new QHBoxLayout;
  machineRow->addWidget(machineLabel_, 1);
  machineRow->addWidget(machineButton_, 0, Qt::AlignTop);
  machineLayout->addLayout(machineRow);
  machineLayout->addWidget(machineTable_, 1);
  auto* resultsTab = new QSplitter(Qt::Horizontal, tabs_);
  resultsTab->setObjectName(QStringLiteral("matchingResultsSplitter"));
  resultsTab->addWidget(methodsTable_);
  resultsTab->addWidget(machineBox);
  resultsTab->setStretchFactor(0, 3);
  resultsTab->setStretchFactor(1, 1);
  resultsTab->setChildrenCollapsible(false);

  curve_ = new MatchingCurveView(tabs_);
  curve_->setObjectName(QStringLiteral("matchingCurve"));

  remeasureTable_ =
      makeTable(tabs_, {tr("Round"), tr("max |d| measured (mm)"), tr("out of tolerance"), tr("RMSE (mm)"),
                        tr("true max |d| (mm)"), tr("true out of tolerance"), tr("SX (mm)"), tr("SY (mm)"),
                        tr("SZ (mm)"), tr("rotary 1 (deg)"), tr("rotary 2 (deg)"), tr("frame rot. (deg)")});
  remeasureTable_->setObjectName(QStringLiteral("matchingRemeasureTable"));
  new ColumnFitter(remeasureTable_, {}, false);
  auto* remeasureTab = new QWidget(tabs_);
  auto* remeasureLayout = new QVBoxLayout(remeasureTab);
  remeasureLayout->setContentsMargins(4, 4, 4, 4);
  remeasureLabel_->setWordWrap(true);
  remeasureLayout->addWidget(remeasureLabel_);
  remeasureLayout->addWidget(remeasureTable_, 1);

  table_ =
      makeTable(tabs_, {tr("Point"), tr("Surface"), tr("Deviation before (mm)"), tr("Deviation after (mm)")});
  new ColumnFitter(table_, {1}, false);
  {
    // The per-point deviations after the fit as CSV (as `match --per-point` writes them).
    auto* exportPoints = new QAction(tr("&Export deviations after matching (CSV)…"), table_);
    exportPoints->setObjectName(QStringLiteral("exportPerPoint"));
    exportPoints->setToolTip(
        tr("Each point's signed deviation along its normal and its deviation vector "
           "after the fit: id, surface, d_mm, dx_mm, dy_mm, dz_mm"));
    connect(exportPoints, &QAction::triggered, this, &MatchingPage::savePerPointDialog);
    table_->addAction(exportPoints);
  }

  // The posture as a controller frame: the group of settings left, the blocks right.
  frameTab_ = new QWidget(tabs_);
  {
    for (const auto& [format, name] : kFrameControls)
      frameControl_->addItem(QString::fromLatin1(name), static_cast<int>(format));
    frameControl_->setObjectName(QStringLiteral("frameControl"));
    frameControl_->setToolTip(
        tr("The control the frame is written for: HEIDENHAIN datum shift and PLANE SPATIAL, SINUMERIK "
           "TRANS and AROT, FANUC G68.2"));
    frameDecimals_->setObjectName(QStringLiteral("frameDecimals"));
    frameDecimals_->setRange(0, 12);
    frameDecimals_->setValue(machine::FrameOptions{}.decimals);
    frameDecimals_->setToolTip(tr("Decimals of the values in mm and ° (FANUC IS-B takes 3)"));
    frameText_->setObjectName(QStringLiteral("frameText"));
    frameText_->setReadOnly(true);
    frameText_->setLineWrapMode(QPlainTextEdit::NoWrap);
    frameText_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    frameText_->setToolTip(
        tr("The blocks that set the frame; the saved program adds its frame and comments"));
    saveFrame_->setObjectName(QStringLiteral("saveFrame"));
    frameNote_->setObjectName(QStringLiteral("frameNote"));
    frameNote_->setWordWrap(true);
    frameNote_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // One group: the settings and Save in a row (the tab is low), the blocks and the note under it.
    auto* group = new QGroupBox(tr("Controller frame"), frameTab_);
    auto* controlLabel = new QLabel(tr("Contro&l:"), group);
    controlLabel->setBuddy(frameControl_);
    auto* decimalsLabel = new QLabel(tr("&Decimals:"), group);
    decimalsLabel->setBuddy(frameDecimals_);
    auto* row = new QHBoxLayout;
    row->addWidget(controlLabel);
    row->addWidget(frameControl_);
    row->addSpacing(12);
    row->addWidget(decimalsLabel);
    row->addWidget(frameDecimals_);
    row->addStretch(1);
    row->addWidget(saveFrame_);
    auto* body = new QHBoxLayout;
    body->addWidget(frameText_, 3);
    body->addWidget(frameNote_, 2, Qt::AlignTop);
    auto* groupLayout = new QVBoxLayout(group);
    groupLayout->setContentsMargins(6, 4, 6, 6);
    groupLayout->addLayout(row);
    groupLayout->addLayout(body, 1);
    auto* frameLayout = new QVBoxLayout(frameTab_);
    frameLayout->setContentsMargins(4, 4, 4, 4);
    frameLayout->addWidget(group);
  }

  tabs_->addTab(resultsTab, tr("Methods and &machine"));
  tabs_->addTab(curve_, tr("&Optimisation curve"));
  tabs_->addTab(remeasureTab, tr("Re&measure loop"));
  tabs_->addTab(table_, tr("&Points"));
  tabs_->addTab(frameTab_, tr("&Controller frame"));

  content_->addWidget(views);
  content_->addWidget(tabs_);
  content_->setObjectName(QStringLiteral("matchingContentSplitter"));
  content_->setStretchFactor(0, 3);
  content_->setStretchFactor(1, 1);
  content_->setChildrenCollapsible(false);
  // The tabs get the room their tables and texts need at 1280 x 800 (the machine's six axes under
  // its wrapped title, the five lines of a frame: clipping_test); the 3D views take the rest and
  // every extra pixel of a larger window.
  content_->setSizes({300, 300});
  tabs_->setMinimumHeight(290);
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

  auto* controls = new QHBoxLayout;
  auto* methodLabel = new QLabel(tr("M&ethod:"), this);
  methodLabel->setBuddy(methodCombo_);
  auto* toleranceLabel = new QLabel(tr("&Tolerance ±"), this);
  toleranceLabel->setBuddy(toleranceSpin_);
  controls->addWidget(methodLabel);
  controls->addWidget(methodCombo_);
  controls->addSpacing(8);
  controls->addWidget(toleranceLabel);
  controls->addWidget(toleranceSpin_);
  controls->addSpacing(8);
  controls->addWidget(allowScale_);
  controls->addSpacing(8);
  top->addWidget(new QLabel(tr("Lock:"), this));  // on the first row: the page fits 1280 px in German too
  for (int k = 0; k < 6; ++k) {
    locks_[static_cast<std::size_t>(k)] = new QCheckBox(QString::fromLatin1(kDofNames[k]), this);
    locks_[static_cast<std::size_t>(k)]->setToolTip(
        tr("Hold %1 at 0 (a constrained optimum over the other parameters)")
            .arg(QLatin1String(kDofNames[k])));
    top->addWidget(locks_[static_cast<std::size_t>(k)]);
  }
  controls->addStretch(1);
  controls->addWidget(progress_);
  controls->addWidget(runButton_);
  controls->addWidget(cancelButton_);

  auto* notes = new NotesEdit(document_, QString::fromLatin1(study::kMatching), this);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(top);
  layout->addLayout(controls);
  layout->addWidget(info_);
  lockMissing_ = new QPushButton(this);
  lockMissing_->setObjectName(QStringLiteral("matchingLockMissing"));
  lockMissing_->setVisible(false);
  connect(lockMissing_, &QPushButton::clicked, this, &MatchingPage::lockMissingAndRun);
  auto* statusRow = new QHBoxLayout;
  statusRow->addWidget(status_, 1);
  statusRow->addWidget(lockMissing_, 0, Qt::AlignTop);
  layout->addLayout(statusRow);
  layout->addWidget(stack_, 1);
  layout->addWidget(notes);

  connect(combo_, &QComboBox::currentIndexChanged, this, &MatchingPage::showPoints);
  // Every control is bound to studies.matching through the shared binding
  // (app/gui/studysettingbinding.h: one undo step per edit, typing merged; undo / redo / load put the
  // control back); the page's own reactions stay here.
  const auto field = [this](const char* key) { return matchingSettingField(document_->project(), key); };
  bindStudySetting(
      document_, methodCombo_, QString::fromLatin1(study::kMatching), QStringLiteral("/method"),
      [field] {
        const auto s = field("method");
        return s ? QString::fromLatin1(matching::toString(s->method)) : QString();
      },
      tr("Change the matching method"),
      [](const QVariant& data) {
        return QString::fromLatin1(matching::toString(static_cast<MatchMethod>(data.toInt())));
      });
  connect(methodCombo_, &QComboBox::currentIndexChanged, this, [this] {
    if (result_) {
      result_->primary = static_cast<MatchMethod>(methodCombo_->currentData().toInt());
      applyResult();
    }
    showStoredStatus();
  });
  bindStudySetting(
      document_, toleranceSpin_, QString::fromLatin1(study::kMatching), QStringLiteral("/tolerance_mm"),
      [field]() -> std::optional<double> {
        const auto s = field("tolerance_mm");
        return s ? std::optional<double>(s->toleranceMm) : std::nullopt;
      },
      tr("Change the matching tolerance"));
  bindStudySetting(
      document_, allowScale_, QString::fromLatin1(study::kMatching), QStringLiteral("/allow_scale"),
      [field]() -> std::optional<bool> {
        const auto s = field("allow_scale");
        return s ? std::optional<bool>(s->allowScale) : std::nullopt;
      },
      tr("Change the matching scale"));
  bindStudySetting(
      document_, frameDecimals_, QString::fromLatin1(study::kMatching), QStringLiteral("/frame_decimals"),
      [field] {
        const auto s = field("frame_decimals");
        return s ? static_cast<qint64>(s->frameDecimals) : std::numeric_limits<qint64>::min();
      },
      false, tr("Change the decimals of the frame"));
  connect(toleranceSpin_, &QDoubleSpinBox::valueChanged, this, [this] {
    reevaluate();
    if (!writingStudy_) showStoredStatus();
  });
  connect(allowScale_, &QCheckBox::toggled, this, [this] {
    settingsChanged();
    if (!writingStudy_) showStoredStatus();
  });
  bindStudySetting(
      document_, QList<QCheckBox*>(locks_.begin(), locks_.end()), QString::fromLatin1(study::kMatching),
      QStringLiteral("/locks"),
      [this] {
        const std::string list = currentOptions().locks.toString();
        return list.empty() ? nlohmann::json() : nlohmann::json(list);
      },
      [field]() -> std::optional<QList<bool>> {
        const auto s = field("locks");  // nullopt when refused: the boxes stay, the status names it
        if (!s) return std::nullopt;
        const matching::DofLocks locks = matching::DofLocks::parse(s->locks, "locks");  // checked
        return QList<bool>(locks.locked.begin(), locks.locked.end());
      },
      tr("Change the matching locks"));
  for (QCheckBox* box : locks_) {
    connect(box, &QCheckBox::toggled, this, [this] {
      settingsChanged();
      showStoredStatus();
    });
  }
  bindStudySetting(
      document_, frameControl_, QString::fromLatin1(study::kMatching), QStringLiteral("/frame"),
      [field] {
        const auto s = field("frame");
        return s ? QString::fromLatin1(machine::toString(s->frame)) : QString();
      },
      tr("Change the control of the frame"),
      [](const QVariant& data) {
        return QString::fromLatin1(machine::toString(static_cast<machine::FrameFormat>(data.toInt())));
      });
  connect(frameControl_, &QComboBox::currentIndexChanged, this, [this] { fillFrame(); });
  connect(frameDecimals_, &QSpinBox::valueChanged, this, [this] { fillFrame(); });
  connect(saveFrame_, &QPushButton::clicked, this, &MatchingPage::saveFrameDialog);
  connect(runButton_, &QPushButton::clicked, this, &MatchingPage::startRun);
  connect(cancelButton_, &QPushButton::clicked, this, &MatchingPage::cancelRun);
  // The observer's progress of the method running now (rough, SADE, GA-simplex, minimax, remeasure).
  connect(run_, &BackgroundRunBase::progress, this, [this](double fraction, const QString&) {
    progress_->setValue(static_cast<int>(fraction * 100.0));
  });
  const auto ended = [this] {
    setRunning(false);
    if (std::optional<matching::MatchingStudyResult> r = run_->takeResult()) {
      result_ = std::move(*r);
      error_.clear();
      applyResult();
      storeResult();
    }
    emit finished();
  };
  connect(run_, &BackgroundRunBase::finished, this, ended);
  connect(run_, &BackgroundRunBase::cancelled, this, ended);
  connect(run_, &BackgroundRunBase::failed, this, [this](const QString& message) {
    setRunning(false);
    error_ = message;
    status_->setText(tr("Matching failed: %1").arg(error_));
    offerMissingLocks();
    emit finished();
  });
  connect(document_, &ProjectDocument::changed, this, &MatchingPage::refresh);
  refresh();
}

MatchingPage::~MatchingPage() {
  run_->cancel();
  run_->waitForWorker();
}

QString MatchingPage::currentDataset() const {
  return combo_->currentData().toString();
}

void MatchingPage::selectDataset(const QString& id) {
  const int index = combo_->findData(id);
  if (index >= 0) combo_->setCurrentIndex(index);
}

bool MatchingPage::isRunning() const {
  return run_->isRunning();
}

void MatchingPage::setMethod(MatchMethod method) {
  const int index = methodCombo_->findData(static_cast<int>(method));
  if (index >= 0) methodCombo_->setCurrentIndex(index);
}

void MatchingPage::setTolerance(double toleranceMm) {
  toleranceSpin_->setValue(toleranceMm);
}

void MatchingPage::setLocked(int dof, bool locked) {
  if (dof >= 0 && dof < 6) locks_[static_cast<std::size_t>(dof)]->setChecked(locked);
}

void MatchingPage::refresh() {
  std::vector<DatasetRef> sets;
  for (const DatasetRef& d : document_->project().datasets) {
    // A hole-table report is read as probe points too (readProbePointsAnyFormat).
    if (d.kind == dataset_kind::kProbePoints || d.kind == dataset_kind::kHoleTable)
      sets.push_back(document_->resolvedDataset(d));
  }
  // A Save As (the same files under paths relative to another folder) keeps the result; File › New
  // and Open (another generation) drop it.
  if (sets == sets_ && generation_ == document_->generation() && combo_->count() > 0) {
    projectFile_ = document_->fileName();
    if (writingStudy_) return;
    // Apply on the diagnosis page (or its undo): the same points, another model of the part.
    if (appliedKeyOf(document_->project()) != appliedKey_) {
      if (isRunning()) cancelRun();
      try {
        settings_ = readMatchingSettings(document_->project(), projectFile_, toleranceSpin_);
        settingsError_.clear();
      } catch (const std::exception& e) {
        // showPoints says what is wrong with the applied effects, the status line any other setting.
        settings_.options.applied = {};
        settingsError_ = QString::fromUtf8(e.what());
      }
      showPoints(combo_->currentIndex());
      return;
    }
    // Undo / redo of a settings edit: the controls follow the study. Invalid settings are refused: the
    // status line names the field and nothing runs until they are corrected (no default substituted).
    const bool hadError = !settingsError_.isEmpty();
    try {
      const matching::MatchingStudySettings settings =
          readMatchingSettings(document_->project(), projectFile_, toleranceSpin_);
      settingsError_.clear();
      // The machine has no control on the page: the adjustment values follow it without a new run.
      const bool machineChanged = settings.options.machine.toJson() != settings_.options.machine.toJson();
      settings_.options.machine = settings.options.machine;
      if (machineChanged && result_) result_->machine = settings.options.machine;
      const bool changed = syncSettingsFromStudy(settings);
      if (hadError) {
        runButton_->setEnabled(set_.has_value());
        status_->setText(result_ ? tr("Settings changed: press Run (Ctrl+R) to match again.")
                                 : tr("Not matched yet: press Run (Ctrl+R)."));
      }
      if (!changed) {
        if (machineChanged && result_)
          applyResult();
        else if (machineChanged)
          fillMachineLabel();
        return;
      }
    } catch (const std::exception& e) {
      settingsError_ = QString::fromUtf8(e.what());
      status_->setText(settingsErrorText());
      runButton_->setEnabled(false);
      return;
    }
    if (result_) result_->primary = static_cast<MatchMethod>(methodCombo_->currentData().toInt());
    reevaluate();
    settingsChanged();
    showStoredStatus();
    return;
  }
  sets_ = std::move(sets);
  const bool newProject = generation_ != document_->generation() || combo_->count() == 0;
  projectFile_ = document_->fileName();
  generation_ = document_->generation();
  QString previous = currentDataset();
  try {
    settings_ = readMatchingSettings(document_->project(), projectFile_, toleranceSpin_);
    settingsError_.clear();
  } catch (const std::exception& e) {
    settings_ = {};
    settingsError_ = QString::fromUtf8(e.what());  // in the status line (showPoints)
  }
  if (newProject) {
    previous = QString::fromStdString(settings_.datasetId);
    syncSettingsFromStudy(settings_);
  }
  showPoints(fillDatasetCombo(combo_, sets_, previous));
}

void MatchingPage::showPoints(int comboIndex) {
  error_.clear();
  result_.reset();
  set_.reset();
  rawSet_.reset();
  cad_.reset();
  appliedText_.clear();
  appliedKey_ = appliedKeyOf(document_->project());
  if (comboIndex < 0 || comboIndex >= static_cast<int>(sets_.size())) {
    info_->clear();
    message_->setText(
        tr("This project has no probe points. Import them with File › Import data… (Ctrl+I): probe "
           "points with their nominals, a hole table or a CMM report, or raw measured points whose "
           "nominals come from a fitted element or a second measurement."));
    stack_->setCurrentWidget(message_);
    runButton_->setEnabled(false);
    return;
  }
  const DatasetRef& dataset = sets_[static_cast<std::size_t>(comboIndex)];
  try {  // invalid applied effects: no run on a model that is not the study's
    // The effects of the points shown: only those estimated on them (the diagnosis's dataset).
    settings_.options.applied = diagnose::parseAppliedMatchingEffects(
        diagnose::projectAppliedEffects(document_->project(), study::kMatching, dataset.id,
                                        projectFile_.toStdString()),
        projectFile_.toStdString());
  } catch (const std::exception& e) {
    settings_.options.applied = {};
    error_ = QString::fromUtf8(e.what());
    info_->clear();
    message_->setText(tr("The effects applied to the matching model are invalid:\n%1").arg(error_));
    stack_->setCurrentWidget(message_);
    runButton_->setEnabled(false);
    return;
  }
  try {
    datasetFile_ = document_->datasetPath(dataset);
    // With its nominals from an element or a second measurement where the dataset says so
    // (core/project/nominals.h): the reference resolved the way the document resolves paths.
    std::optional<DatasetRef> reference;
    if (const DatasetRef* r = nominalReference(document_->project(), dataset))
      reference = document_->resolvedDataset(*r);
    rawSet_ = readProbePointDataset(dataset, reference ? &*reference : nullptr, 3);
    // A CAD part: the study re-projects the points onto it at each posture (core/matching/cad_match.h).
    if (dataset.nominals.from == "cad" && reference) cad_ = readCadModel(*reference);
    set_ = matching::studyModelSet(*rawSet_, settings_.options, projectFile_.toStdString());
    const ProbePointSet& points = *set_;
    std::set<std::string> surfaces;
    for (const ProbePoint& p : points.points) surfaces.insert(p.surface);
    QString info = tr("%1 points on %2 surfaces, %3%4.")
                       .arg(points.points.size())
                       .arg(surfaces.size())
                       .arg(points.hasNormals ? tr("with normals") : tr("positions only"))
                       .arg(points.planar ? tr(", planar") : QString());
    if (!dataset.licence.empty())
      info += QLatin1Char(' ') + tr("Licence: %1.").arg(QString::fromStdString(dataset.licence));
    if (!settings_.options.applied.empty()) {
      appliedText_ =
          tr("Includes applied effects: %1 (the nominal points are deformed by them before matching).")
              .arg(QString::fromStdString(settings_.options.applied.describe()));
      info += QLatin1Char('\n') + appliedText_;
    }
    if (const std::string elsewhere =
            diagnose::appliedEffectsElsewhere(document_->project(), study::kMatching, dataset.id);
        !elsewhere.empty()) {
      info += QLatin1Char('\n') + tr("Effects applied on the Diagnosis page belong to the probe points %1 "
                                     "(the ones the diagnosis ran on); these points use the declared "
                                     "model.")
                                      .arg(QString::fromStdString(elsewhere));
    }
    info_->setText(info);
    info_->setToolTip(QString::fromStdString(dataset.description));
    status_->setText(settingsError_.isEmpty() ? tr("Not matched yet: press Run (Ctrl+R).")
                                              : settingsErrorText());
    if (settingsError_.isEmpty()) {
      if (const QString stored = storedResultText(); !stored.isEmpty()) status_->setText(stored);
    }
    runButton_->setEnabled(settingsError_.isEmpty());  // invalid settings: refused, not replaced
    stack_->setCurrentWidget(content_);
  } catch (const std::exception& e) {
    error_ = QString::fromUtf8(e.what());
    info_->clear();
    message_->setText(tr("Cannot show these probe points:\n%1").arg(error_));
    stack_->setCurrentWidget(message_);
    runButton_->setEnabled(false);
    return;
  }
  curve_->clear();
  methodsTable_->setRowCount(0);
  machineTable_->setRowCount(0);
  remeasureTable_->setRowCount(0);
  remeasureLabel_->clear();
  fillMachineLabel();
  updateViews();
  fillPointTable();
  fillFrame();
}

matching::MatchingStudyOptions MatchingPage::currentOptions() const {
  matching::MatchingStudyOptions o = settings_.options;
  o.toleranceMm = toleranceSpin_->value();
  o.allowScale = allowScale_->isChecked();
  o.primary = static_cast<MatchMethod>(methodCombo_->currentData().toInt());
  std::string list;
  for (int k = 0; k < 6; ++k) {
    if (locks_[static_cast<std::size_t>(k)]->isChecked())
      list += std::string(list.empty() ? "" : ",") + kDofNames[k];
  }
  o.locks = matching::DofLocks::parse(list, "lock");
  o.cad = cad_;
  return o;
}

void MatchingPage::writeStudyValue(const QString& key, const nlohmann::json& value, const QString& text,
                                   bool typing) {
  if (writingStudy_) return;
  writingStudy_ = true;
  if (!typing) document_->endEditSequence();
  document_->setStudyValue(QString::fromLatin1(study::kMatching), key, value, text);
  if (!typing) document_->endEditSequence();
  writingStudy_ = false;
  showStoredStatus();
}

void MatchingPage::showStoredStatus() {
  if (result_ || !set_ || isRunning() || !settingsError_.isEmpty()) return;
  const QString stored = storedResultText();
  status_->setText(stored.isEmpty() ? tr("Not matched yet: press Run (Ctrl+R).") : stored);
}

bool MatchingPage::syncSettingsFromStudy(const matching::MatchingStudySettings& settings) {
  const matching::DofLocks& locks = settings.options.locks;  // checked by matchingStudySettings
  bool changed = false;
  {
    const QSignalBlocker b1(toleranceSpin_), b2(methodCombo_), b3(allowScale_);
    const double tolerance = toleranceSpin_->value();
    toleranceSpin_->setValue(settings.options.toleranceMm);
    changed |= toleranceSpin_->value() != tolerance;
    const int method = std::max(0, methodCombo_->findData(static_cast<int>(settings.options.primary)));
    changed |= methodCombo_->currentIndex() != method;
    methodCombo_->setCurrentIndex(method);
    changed |= allowScale_->isChecked() != settings.options.allowScale;
    allowScale_->setChecked(settings.options.allowScale);
  }
  for (std::size_t k = 0; k < locks_.size(); ++k) {
    const QSignalBlocker blocker(locks_[k]);
    changed |= locks_[k]->isChecked() != locks.locked[k];
    locks_[k]->setChecked(locks.locked[k]);
  }
  // The frame's control and decimals (no effect on the run: only the frame tab changes).
  const machine::FrameFormat format = settings.frame;
  const int decimals = settings.frameDecimals;
  {
    const QSignalBlocker b1(frameControl_), b2(frameDecimals_);
    frameControl_->setCurrentIndex(std::max(0, frameControl_->findData(static_cast<int>(format))));
    frameDecimals_->setValue(decimals);
  }
  fillFrame();
  return changed;
}

QString MatchingPage::settingsErrorText() const {
  return tr("The matching study's settings are invalid, nothing is run until they are corrected (Undo, or "
            "the project file): %1")
      .arg(settingsError_);
}

void MatchingPage::settingsChanged() {
  if (result_) status_->setText(tr("Settings changed: press Run (Ctrl+R) to match again."));
}

QString MatchingPage::statusText() const {
  return status_->text();
}

QString MatchingPage::infoText() const {
  return info_->text();
}

bool MatchingPage::runNow() {
  if (!set_ || !rawSet_ || isRunning()) return false;
  if (!settingsError_.isEmpty()) {
    status_->setText(settingsErrorText());
    return false;
  }
  try {
    const matching::MatchingStudyOptions options = currentOptions();
    declareStudyDataset();
    result_ = matching::runMatchingStudy(*rawSet_, options);
    error_.clear();
    applyResult();
    storeResult();
    return true;
  } catch (const std::exception& e) {
    error_ = QString::fromUtf8(e.what());
    status_->setText(tr("Matching failed: %1").arg(error_));
    offerMissingLocks();
    return false;
  }
}

void MatchingPage::offerMissingLocks() {
  lockMissing_->setVisible(false);
  missingLocks_ = {};
  if (!set_) return;
  try {
    const matching::MatchingStudyOptions o = currentOptions();
    // Every method of the study must be able to run: the minimax fit along the normals is the strictest,
    // the least-squares fits need the positions to fix the rest.
    std::optional<matching::DofLocks> locks =
        matching::locksToDetermine(*set_, o.locks, o.allowScale, matching::FitKind::Minimax);
    if (locks)
      locks = matching::locksToDetermine(*set_, *locks, o.allowScale, matching::FitKind::LeastSquares);
    if (!locks) return;
    QStringList names;
    for (int d = 0; d < matching::kDofCount; ++d) {
      missingLocks_[static_cast<std::size_t>(d)] = locks->locked[d] && !o.locks.locked[d];
      if (missingLocks_[static_cast<std::size_t>(d)]) names << QString::fromLatin1(matching::dofName(d));
    }
    if (names.isEmpty()) return;
    lockMissing_->setText(tr("Lock %1 and run").arg(names.join(QStringLiteral(", "))));
    lockMissing_->setToolTip(
        tr("The points cannot determine %1 (a sphere fixes no rotation, parallel normals "
           "fix no rotation about them): hold them at 0 and run again. Undo gives the "
           "locks back.")
            .arg(names.join(QStringLiteral(", "))));
    lockMissing_->setVisible(true);
  } catch (const std::exception&) {
    // The settings themselves are refused: the status says so already.
  }
}

void MatchingPage::lockMissingAndRun() {
  lockMissing_->setVisible(false);
  QStringList names;
  for (int d = 0; d < matching::kDofCount; ++d)
    if (missingLocks_[static_cast<std::size_t>(d)]) names << QString::fromLatin1(matching::dofName(d));
  if (names.isEmpty()) return;
  document_->undoStack()->beginMacro(tr("Lock %1").arg(names.join(QStringLiteral(", "))));
  for (int d = 0; d < matching::kDofCount; ++d)
    if (missingLocks_[static_cast<std::size_t>(d)]) locks_[static_cast<std::size_t>(d)]->setChecked(true);
  document_->undoStack()->endMacro();
  missingLocks_ = {};
  startRun();
}

void MatchingPage::startRun() {
  if (!set_ || !rawSet_ || isRunning()) return;
  if (!settingsError_.isEmpty()) {
    status_->setText(settingsErrorText());
    return;
  }
  matching::MatchingStudyOptions options;
  try {
    options = currentOptions();
  } catch (const std::exception& e) {
    error_ = QString::fromUtf8(e.what());
    status_->setText(tr("Matching failed: %1").arg(error_));
    offerMissingLocks();
    return;
  }
  lockMissing_->setVisible(false);
  declareStudyDataset();
  setRunning(true);
  status_->setText(tr("Matching …"));
  const ProbePointSet set = *rawSet_;  // runMatchingStudy adds the applied effects itself
  run_->start(
      [set, options](RunObserver& observer) { return matching::runMatchingStudy(set, options, &observer); });
}

void MatchingPage::declareStudyDataset() {
  const QString id = currentDataset();
  // The study's dataset is a probe_points one (core/project/study_check.h); a hole table is matched
  // on the page but cannot be the study's.
  const DatasetRef* set = currentSetRef();
  if (id.isEmpty() || !set || set->kind != dataset_kind::kProbePoints) return;
  const nlohmann::json current =
      document_->studyValue(QString::fromLatin1(study::kMatching), QStringLiteral("/dataset"));
  // Only a study without points gets them: a run on other points must not re-point the study (nor
  // push an undo step between the user's own edits).
  if (!current.is_null()) return;
  writeStudyValue(QStringLiteral("/dataset"), id.toStdString(), tr("Match the probe points %1").arg(id),
                  false);
}

nlohmann::json MatchingPage::storedSettingsJson() const {
  // What decides the figures: the study's settings (not its notes nor how a frame is written) and the
  // effects applied on the diagnosis page.
  nlohmann::json study = document_->studyValue(QString::fromLatin1(study::kMatching), QString());
  if (!study.is_object()) study = nlohmann::json::object();
  for (const char* key : {"notes", "frame", "frame_decimals", "dataset"}) study.erase(key);
  nlohmann::json applied =
      document_->studyValue(QString::fromLatin1(study::kDiagnosis), QStringLiteral("/matching"));
  return {{"study", study}, {"diagnosis", applied}};
}

const DatasetRef* MatchingPage::currentSetRef() const {
  const int index = combo_->currentIndex();
  if (index < 0 || index >= static_cast<int>(sets_.size())) return nullptr;
  return &sets_[static_cast<std::size_t>(index)];
}

void MatchingPage::storeResult() {
  const DatasetRef* dataset = currentSetRef();
  if (!result_ || !set_ || !dataset) return;
  const matching::MatchResult& primary = result_->primaryRun();
  if (primary.run.termination == Termination::Cancelled) return;  // not the result of these settings
  nlohmann::json figures = matching::toJson(primary, *set_);
  figures.erase("trace");
  try {
    document_->setStoredResult(QString::fromLatin1(study::kMatching), QString::fromStdString(dataset->id),
                               makeStoredResult(document_->projectPathForDatasets().toStdString(), *dataset,
                                                storedSettingsJson(), std::move(figures)));
  } catch (const std::exception&) {
    // The points cannot be read any more: nothing is stored.
  }
}

QString MatchingPage::storedResultText() const {
  const DatasetRef* dataset = currentSetRef();
  if (!dataset) return {};
  const StoredResult stored =
      storedResult(document_->project(), document_->projectPathForDatasets().toStdString(), study::kMatching,
                   *dataset, storedSettingsJson());
  if (const std::optional<QString> state = storedStateText(
          stored,
          {tr("The stored result (computed %1) is out of date: the matching settings changed since. Not "
              "matched with these settings yet: press Run (Ctrl+R)."),
           tr("The stored result (computed %1) is out of date: the points file changed since. Press Run "
              "(Ctrl+R) to match the points as they are now."),
           tr("The stored result (computed %1) cannot be checked: the points file cannot be read.")}))
    return *state;
  const QString when = storedTimeText(stored.computed);
  const nlohmann::json& e = stored.entry;
  const auto number = [&e](const char* key) { return storedFigure(e, key, 0.0); };
  const nlohmann::json oot = e.value("out_of_tolerance", nlohmann::json::object());
  const auto count = [&oot](const char* key) { return storedCount(oot, key); };
  const QLocale locale;
  return tr("From the saved project, computed %1 with these settings on these points: %2: %3 of %4 points "
            "out of ±%5 mm before, %6 after; RMSE %7 mm, max |d| %8 mm. Press Run (Ctrl+R) to see the "
            "views.")
      .arg(when, QString::fromStdString(e.value("method", std::string())))
      .arg(count("before"))
      .arg(e.value("points", 0LL))
      .arg(locale.toString(number("tolerance_mm"), 'f', 3))
      .arg(count("after"))
      .arg(locale.toString(number("rmse_mm"), 'f', 4), locale.toString(number("max_abs_mm"), 'f', 4));
}

void MatchingPage::cancelRun() {
  run_->cancel();
}

void MatchingPage::setRunning(bool running) {
  runButton_->setEnabled(!running && set_.has_value());
  cancelButton_->setEnabled(running);
  progress_->setVisible(running);
  progress_->setValue(0);
  combo_->setEnabled(!running);
}

void MatchingPage::reevaluate() {
  if (!result_ || !set_) {
    updateViews();
    return;
  }
  const double tol = toleranceSpin_->value();
  for (matching::MatchResult& r : result_->runs) {
    r.before = matching::evaluateTolerance(*set_, matching::Pose{}, tol);
    r.after = matching::evaluateTolerance(*set_, r.pose, tol);
    if (r.rough) r.roughEvaluation = matching::evaluateTolerance(*set_, r.rough->posture, tol);
  }
  applyResult();
  if (result_->remeasure)
    remeasureLabel_->setText(remeasureLabel_->text() + QLatin1Char(' ') +
                             tr("(The loop ran with the previous tolerance: Run again.)"));
}

void MatchingPage::applyResult() {
  if (!result_) return;
  const matching::MatchResult& primary = result_->primaryRun();
  result_->adjustment =
      machine::adjustmentFor(result_->machine, primary.pose.rotation, primary.pose.translation);
  const bool cancelled = primary.run.termination == Termination::Cancelled;
  status_->setText(tr("%1: %2 of %3 points out of ±%4 mm before, %5 after; RMSE %6 mm, max |d| %7 mm.%8")
                       .arg(methodShort(primary.method))
                       .arg(primary.before.overall.outOfTolerance)
                       .arg(primary.before.overall.points)
                       .arg(QLocale().toString(primary.after.toleranceMm, 'f', 3))
                       .arg(primary.after.overall.outOfTolerance)
                       .arg(QLocale().toString(primary.after.overall.rmseMm, 'f', 4),
                            QLocale().toString(primary.after.overall.maxAbsMm, 'f', 4),
                            cancelled ? tr(" Cancelled: the best posture found so far.") : QString()));
  if (!settingsError_.isEmpty()) status_->setText(status_->text() + QLatin1Char('\n') + settingsErrorText());
  updateViews();
  fillMethodsTable();
  fillMachineTable();
  fillRemeasureTable();
  fillPointTable();
  fillFrame();
  std::vector<std::pair<double, double>> optimum;
  curve_->clear();
  for (const matching::MatchResult& r : result_->runs) {
    if (r.method != MatchMethod::Sade && r.method != MatchMethod::GaSimplex) continue;
    std::vector<std::pair<double, double>> points;
    for (const IterationSummary& s : r.run.trace)
      points.emplace_back(static_cast<double>(s.iteration), s.best);
    curve_->setCurve(methodShort(r.method), points);
  }
  if (const matching::MatchResult* cf = result_->of(MatchMethod::ClosedForm))
    curve_->setOptimum(cf->after.overall.rmseMm);
}

void MatchingPage::updateViews() {
  if (!set_) return;
  const ProbePointSet& set = *set_;
  const double tol = toleranceSpin_->value();
  const std::vector<double> before = set.deviations();
  double maxBefore = 0.0;
  std::size_t outBefore = 0;
  for (double v : before) {
    maxBefore = std::max(maxBefore, std::abs(v));
    outBefore += std::abs(v) > tol;
  }
  // The same magnification of the deviation vectors in both views, and as in the report.
  const double factor = matching::deviationMagnification(set, maxBefore);
  const QLocale locale;
  for (PointSetView* v : {beforeView_, afterView_}) {
    v->setTolerance(tol);
    v->setExaggeration(factor);
  }
  beforeView_->setPoints(set);
  // A CAD nominal: the part itself, coloured by the deviation measured on it (before: where it is;
  // after: moved by the posture), under the points.
  const auto partTriangles = [this](const matching::Pose& pose) {
    std::vector<std::array<std::array<double, 3>, 3>> out;
    out.reserve(cad_->mesh().triangles.size());
    for (const geometry::Triangle& t : cad_->mesh().triangles) {
      std::array<std::array<double, 3>, 3> moved{};
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d v = pose.apply(t.v[static_cast<std::size_t>(k)]);
        moved[static_cast<std::size_t>(k)] = {v.x(), v.y(), v.z()};
      }
      out.push_back(moved);
    }
    return out;
  };
  if (cad_)
    beforeView_->setSurface(partTriangles({}), matching::triangleDeviations(cad_->mesh(), set, before));
  else
    beforeView_->clearSurface();
  beforeView_->setTitle(tr("BEFORE matching\n%1 of %2 out of ±%3 mm, max |d| %4 mm")
                            .arg(outBefore)
                            .arg(set.points.size())
                            .arg(locale.toString(tol, 'f', 3), locale.toString(maxBefore, 'f', 3)));
  if (!result_) {
    afterView_->clearSurface();
    afterView_->setPoints(ProbePointSet{});
    afterView_->setTitle(tr("AFTER matching\nnot run yet: press Run (Ctrl+R)"));
    return;
  }
  const matching::MatchResult& r = result_->primaryRun();
  // With a CAD part the nominals after matching are the part's closest points at the final posture.
  const ProbePointSet* afterSet = &set;
  for (std::size_t k = 0; k < result_->cadAfter.size() && k < result_->runs.size(); ++k)
    if (result_->runs[k].method == r.method) afterSet = &result_->cadAfter[k];
  std::vector<std::array<double, 3>> transformed;
  transformed.reserve(afterSet->points.size());
  for (const ProbePoint& p : afterSet->points) {
    const Eigen::Vector3d q = r.pose.apply(p.nominal);
    transformed.push_back({q.x(), q.y(), q.z()});
  }
  afterView_->setPoints(*afterSet);
  afterView_->setAfter(transformed, r.after.deviations);
  if (cad_)
    afterView_->setSurface(partTriangles(r.pose),
                           matching::triangleDeviations(cad_->mesh(), *afterSet, r.after.deviations));
  else
    afterView_->clearSurface();
  afterView_->setTitle(
      tr("AFTER matching (%1)\n%2 of %3 out of ±%4 mm, max |d| %5 mm")
          .arg(methodShort(r.method))
          .arg(r.after.overall.outOfTolerance)
          .arg(set.points.size())
          .arg(locale.toString(tol, 'f', 3), locale.toString(r.after.overall.maxAbsMm, 'f', 3)));
}

void MatchingPage::fillMethodsTable() {
  const matching::MatchingStudyResult& res = *result_;
  methodsTable_->setRowCount(0);
  auto addRow = [&](const QString& name, const QString& tooltip, const matching::Pose& pose,
                    const matching::ToleranceEvaluation& before, const matching::ToleranceEvaluation& after,
                    double seconds, bool primary) {
    const int row = methodsTable_->rowCount();
    methodsTable_->insertRow(row);
    auto* nameItem = textItem(name);
    nameItem->setToolTip(tooltip);
    if (primary) {
      QFont f = nameItem->font();
      f.setBold(true);
      nameItem->setFont(f);
      nameItem->setToolTip(tooltip + QLatin1Char('\n') +
                           tr("Shown after matching and used for the machine adjustment"));
    }
    methodsTable_->setItem(row, 0, nameItem);
    const Eigen::Vector3d a = pose.anglesDeg();
    for (int k = 0; k < 3; ++k) methodsTable_->setItem(row, 1 + k, numberItem(a[k], 4));
    for (int k = 0; k < 3; ++k) methodsTable_->setItem(row, 4 + k, numberItem(pose.translation[k], 4));
    methodsTable_->setItem(row, 7, numberItem(pose.scale, 7));
    methodsTable_->setItem(row, 8, numberItem(after.overall.rmseMm, 5));
    methodsTable_->setItem(row, 9, numberItem(after.overall.maxAbsMm, 5));
    methodsTable_->setItem(row, 10, countItem(before.overall.outOfTolerance, before.overall.points, false));
    methodsTable_->setItem(row, 11, countItem(after.overall.outOfTolerance, after.overall.points, true));
    methodsTable_->setItem(row, 12, seconds >= 0.0 ? numberItem(seconds * 1e3, 1) : textItem(QString()));
  };
  for (std::size_t i = 0; i < res.runs.size(); ++i) {
    const matching::MatchResult& r = res.runs[i];
    if (r.rough && r.roughEvaluation && r.method == MatchMethod::Sade) {
      addRow(tr("Rough"), tr("Rough matching: 3-point local frames, Eq. 3–7"), r.rough->posture, r.before,
             *r.roughEvaluation, -1.0, false);
      // Three points span a whole rigid frame: the rough stage cannot hold a lock. Its value of a locked
      // parameter is only the start the fine stage moves to the lock value; greyed and said so.
      const int row = methodsTable_->rowCount() - 1;
      for (int d = 0; d < matching::kDofCount; ++d) {
        if (!r.locks.isLocked(static_cast<matching::Dof>(d))) continue;
        QTableWidgetItem* cell = methodsTable_->item(row, 1 + d);
        cell->setForeground(palette().color(QPalette::Disabled, QPalette::Text));
        cell->setToolTip(tr("%1 is locked at %2: the rough stage's three-point frames cannot hold a lock, "
                            "the fine stage (SADE) holds it.")
                             .arg(QString::fromLatin1(matching::dofName(d)))
                             .arg(QLocale().toString(r.locks.value[d], 'f', 4)));
      }
    }
    addRow(methodShort(r.method), methodTitle(r.method), r.pose, r.before, r.after, res.seconds[i],
           r.method == res.primary);
  }
  methodsTable_->setColumnHidden(7, !allowScale_->isChecked());
  ColumnFitter::of(methodsTable_)->fit();
}

namespace {
QString topologyDescription(machine::Topology t) {
  switch (t) {
    case machine::Topology::Xfyzba:
      return MatchingPage::tr("head-head, Eq. 12–13");
    case machine::Topology::AcTable:
    case machine::Topology::BcTable:
      return MatchingPage::tr("table-table trunnion");
    case machine::Topology::HeadTable:
      return MatchingPage::tr("B swivel head, C rotary table");
  }
  return {};
}
}  // namespace

bool MatchingPage::hasProjectMachine() const {
  return !document_->studyValue(QString::fromLatin1(study::kMatching), QStringLiteral("/machine")).is_null();
}

void MatchingPage::fillMachineLabel() {
  const machine::Topology t = settings_.options.machine.topology;
  const QString which =
      hasProjectMachine()
          ? tr("the project's machine %1 (%2)")
                .arg(QString::fromLatin1(machine::topologyName(t)), topologyDescription(t))
          : tr("the default machine %1 (%2): no machine is defined for this project; enter yours with "
               "Machine… (Ctrl+Shift+M) before using these values at the control")
                .arg(QString::fromLatin1(machine::topologyName(t)), topologyDescription(t));
  if (!result_) {
    machineLabel_->setText(tr("Adjustment values will be for %1.").arg(which));
    return;
  }
  const machine::Adjustment& a = result_->adjustment;
  machineLabel_->setText(
      tr("Machine adjustment values for %1, posture of %2. %3")
          .arg(which)
          .arg(methodShort(result_->primary))
          .arg(a.withinTravel ? tr("Within travel.")
                              : tr("OUTSIDE TRAVEL: %1").arg(QString::fromStdString(a.travelMessage))));
}

void MatchingPage::editMachine() {
  MachineDialog dialog(settings_.options.machine, frameFormat(), this);
  if (dialog.exec() != QDialog::Accepted || !dialog.isDefinitionValid()) return;
  setMachine(dialog.definition(), dialog.controller());
}

void MatchingPage::setMachine(const machine::MachineDefinition& definition, machine::FrameFormat controller) {
  std::string why;
  if (!definition.isValid(&why)) return;
  document_->endEditSequence();
  document_->undoStack()->beginMacro(tr("Change the machine"));
  document_->setStudyValue(QString::fromLatin1(study::kMatching), QStringLiteral("/machine"),
                           definition.toJson(), tr("Change the machine"));
  if (controller != frameFormat() || hasFrameSetting())
    document_->setStudyValue(QString::fromLatin1(study::kMatching), QStringLiteral("/frame"),
                             machine::toString(controller), tr("Change the controller frame"));
  document_->undoStack()->endMacro();
  document_->endEditSequence();
}

bool MatchingPage::hasFrameSetting() const {
  return !document_->studyValue(QString::fromLatin1(study::kMatching), QStringLiteral("/frame")).is_null();
}

void MatchingPage::fillMachineTable() {
  const machine::Adjustment& a = result_->adjustment;
  const auto names = machine::rotaryAxisNames(a.topology);
  fillMachineLabel();
  machineTable_->setRowCount(0);
  auto addRow = [&](const QString& axis, double value, const QString& unit, int decimals) {
    const int row = machineTable_->rowCount();
    machineTable_->insertRow(row);
    machineTable_->setItem(row, 0, textItem(axis));
    machineTable_->setItem(row, 1, numberItem(value, decimals));
    machineTable_->setItem(row, 2, textItem(unit));
  };
  addRow(QStringLiteral("SX"), a.linearMm.x(), tr("mm"), 4);
  addRow(QStringLiteral("SY"), a.linearMm.y(), tr("mm"), 4);
  addRow(QStringLiteral("SZ"), a.linearMm.z(), tr("mm"), 4);
  addRow(QStringLiteral("S") + QLatin1String(names[0]), a.rotaryDeg[0], tr("deg"), 5);
  addRow(QStringLiteral("S") + QLatin1String(names[1]), a.rotaryDeg[1], tr("deg"), 5);
  addRow(tr("frame rotation"), a.frameRotationDeg, tr("deg"), 5);
  ColumnFitter::of(machineTable_)->fit();
}

void MatchingPage::fillRemeasureTable() {
  remeasureTable_->setRowCount(0);
  if (!result_->remeasure) {
    remeasureLabel_->setText(tr("The remeasure loop did not run."));
    return;
  }
  const matching::RemeasureResult& loop = *result_->remeasure;
  const auto names = machine::rotaryAxisNames(result_->machine.topology);
  constexpr int kAdjust = 6;  // first adjustment column (after the measured and the true error)
  remeasureTable_->setHorizontalHeaderItem(kAdjust + 3,
                                           headerItem(tr("S%1 (deg)").arg(QLatin1String(names[0]))));
  remeasureTable_->setHorizontalHeaderItem(kAdjust + 4,
                                           headerItem(tr("S%1 (deg)").arg(QLatin1String(names[1]))));
  QString outcome;
  const matching::ToleranceEvaluation* remaining = loop.trueRemaining();
  const QString trueMax =
      remaining ? QLocale().toString(remaining->overall.maxAbsMm, 'f', 4) : QStringLiteral("?");
  switch (loop.outcome) {
    case matching::RemeasureOutcome::InTolerance:
      outcome = tr("Every point is inside the tolerance after %n adjustment(s); the true remaining error "
                   "is %1 mm at most.",
                   "", static_cast<int>(loop.rounds.size()) - 1)
                    .arg(trueMax);
      break;
    case matching::RemeasureOutcome::FormError:
      outcome = tr("FAILED: the best fit leaves points out of tolerance (form error larger than the "
                   "tolerance); no WCS adjustment can bring them in. True remaining error %1 mm, %2 "
                   "point(s) out.")
                    .arg(trueMax)
                    .arg(remaining ? static_cast<qulonglong>(remaining->overall.outOfTolerance) : 0ULL);
      break;
    case matching::RemeasureOutcome::BeyondTravel: {
      QString travel;
      for (const auto& r : loop.rounds)
        if (r.adjustment && !r.adjustment->withinTravel)
          travel = QString::fromStdString(r.adjustment->travelMessage);
      outcome = tr("FAILED: the adjustment is beyond the machine's travel (%1); the WCS was not moved. "
                   "True remaining error %2 mm.")
                    .arg(travel, trueMax);
      break;
    }
    case matching::RemeasureOutcome::NotConverged:
      outcome = tr("FAILED: still out of tolerance after the last adjustment. True remaining error %1 mm.")
                    .arg(trueMax);
      break;
    case matching::RemeasureOutcome::Cancelled:
      outcome = tr("Stopped before the end.");
      break;
  }
  remeasureLabel_->setText(
      tr("Step 7 with the simulator as machine and CMM (the part where the probe found it, with its "
         "form error; the %1 fit does not place it; probing noise %2 mm): measure, match, adjust the "
         "WCS, remeasure. %3")
          .arg(methodShort(result_->primary))
          .arg(QLocale().toString(settings_.options.remeasureNoiseMm, 'f', 3))
          .arg(outcome));
  remeasureLabel_->setStyleSheet(loop.inTolerance ? QString() : QStringLiteral("color: #b00020;"));
  for (const matching::RemeasureRound& r : loop.rounds) {
    const int row = remeasureTable_->rowCount();
    remeasureTable_->insertRow(row);
    remeasureTable_->setItem(row, 0, numberItem(r.round, 0));
    remeasureTable_->setItem(row, 1, numberItem(r.measured.overall.maxAbsMm, 4));
    remeasureTable_->setItem(row, 2,
                             countItem(r.measured.overall.outOfTolerance, r.measured.overall.points, true));
    remeasureTable_->setItem(row, 3, numberItem(r.measured.overall.rmseMm, 4));
    if (r.truth) {
      remeasureTable_->setItem(row, 4, numberItem(r.truth->overall.maxAbsMm, 4));
      remeasureTable_->setItem(row, 5,
                               countItem(r.truth->overall.outOfTolerance, r.truth->overall.points, true));
    }
    if (r.adjustment) {
      for (int k = 0; k < 3; ++k)
        remeasureTable_->setItem(row, kAdjust + k, numberItem(r.adjustment->linearMm[k], 4));
      remeasureTable_->setItem(row, kAdjust + 3, numberItem(r.adjustment->rotaryDeg[0], 5));
      remeasureTable_->setItem(row, kAdjust + 4, numberItem(r.adjustment->rotaryDeg[1], 5));
      remeasureTable_->setItem(row, kAdjust + 5, numberItem(r.adjustment->frameRotationDeg, 5));
    } else {
      remeasureTable_->setItem(
          row, kAdjust,
          textItem(r.measured.overall.outOfTolerance == 0
                       ? tr("in tolerance: no adjustment")
                       : tr("stopped: %1").arg(QString::fromLatin1(toString(loop.outcome)))));
      remeasureTable_->setSpan(row, kAdjust, 1, 6);
    }
  }
  ColumnFitter::of(remeasureTable_)->fit();
}

void MatchingPage::fillPointTable() {
  if (!set_) return;
  const ProbePointSet& points = *set_;
  const std::vector<double> deviations = points.deviations();
  const matching::MatchResult* r = result_ ? &result_->primaryRun() : nullptr;
  const double tol = toleranceSpin_->value();
  table_->setRowCount(static_cast<int>(points.points.size()));
  for (std::size_t i = 0; i < points.points.size(); ++i) {
    const ProbePoint& p = points.points[i];
    const int row = static_cast<int>(i);
    table_->setItem(row, ColId, textItem(QString::fromStdString(p.id)));
    table_->setItem(row, ColSurface, textItem(QString::fromStdString(p.surface)));
    auto* before = numberItem(deviations[i], 4);
    if (std::abs(deviations[i]) > tol) before->setForeground(QColor(0xb2, 0x18, 0x2b));
    table_->setItem(row, ColDeviation, before);
    if (r != nullptr) {
      const double after = r->after.deviations[i];
      auto* item = numberItem(after, 4);
      if (std::abs(after) > tol) item->setForeground(QColor(0xb2, 0x18, 0x2b));
      table_->setItem(row, ColAfter, item);
    } else {
      table_->setItem(row, ColAfter, textItem(QString()));
    }
  }
  ColumnFitter::of(table_)->fit();
}

machine::FrameFormat MatchingPage::frameFormat() const {
  return static_cast<machine::FrameFormat>(frameControl_->currentData().toInt());
}

void MatchingPage::setFrameFormat(machine::FrameFormat format) {
  const int index = frameControl_->findData(static_cast<int>(format));
  if (index >= 0) frameControl_->setCurrentIndex(index);
}

QString MatchingPage::frameText() const {
  return frameText_->toPlainText();
}

void MatchingPage::fillFrame() {
  frameText_->clear();
  if (!result_) {
    frameText_->setPlaceholderText(tr("No posture yet: press Run (Ctrl+R)."));
    frameNote_->clear();
    saveFrame_->setEnabled(false);
    saveFrame_->setToolTip(tr("There is no posture to write yet: run the matching first (Ctrl+R)"));
    return;
  }
  const matching::MatchResult& primary = result_->primaryRun();
  QString note;
  switch (frameFormat()) {
    case machine::FrameFormat::Heidenhain:
      note =
          tr("Datum shift (CYCL DEF 7) to the origin t, then PLANE SPATIAL with R = Rz(SPC) Ry(SPB) "
             "Rx(SPA) about the non-tilted axes; STAY: no axis moves. Call the saved program (CALL PGM) "
             "once the part's preset is active.");
      break;
    case machine::FrameFormat::Siemens:
      note =
          tr("TRANS to the origin t on top of the active settable frame (G54 …), then AROT about Z, Y', "
             "X'': R = Rz(Z) Ry(Y) Rx(X). The tool is not oriented: use CYCLE800 or TRAORI for that.");
      break;
    case machine::FrameFormat::Fanuc:
      note =
          tr("G68.2 with the origin t and the Euler angles R = Rz(I) Rx(J) Rz(K), cancelled with G69. "
             "G53.1 is not written: it moves the rotary axes, program it at a safe position.");
      break;
  }
  note = tr("Posture of %1 as a controller frame (mm, °).").arg(methodShort(primary.method)) +
         QLatin1Char(' ') + note;
  if (std::abs(primary.pose.scale - 1.0) > 1e-12)
    note += QLatin1Char(' ') + tr("The fitted scale %1 is not applied: no control frame scales.")
                                   .arg(QLocale().toString(primary.pose.scale, 'f', 7));
  try {
    QStringList lines;
    for (const std::string& b : machine::controllerFrameBlocks(
             primary.pose.rotation, primary.pose.translation, frameFormat(), frameDecimals_->value()))
      lines << QString::fromStdString(b);
    frameText_->setPlainText(lines.join(QLatin1Char('\n')));
    saveFrame_->setEnabled(true);
    saveFrame_->setToolTip(
        tr("Write the frame program for the control to a file (as metrofit-cli match --frame does)"));
  } catch (const std::exception& e) {
    note = tr("Cannot write the posture as a frame: %1").arg(QString::fromUtf8(e.what()));
    saveFrame_->setEnabled(false);
    saveFrame_->setToolTip(note);
  }
  frameNote_->setText(note);
}

bool MatchingPage::saveFrame(const QString& path, QString* error) const {
  if (!result_) {
    if (error) *error = tr("There is no posture to write yet: run the matching first.");
    return false;
  }
  try {
    const matching::MatchResult& primary = result_->primaryRun();
    machine::FrameOptions fo;
    fo.decimals = frameDecimals_->value();
    fo.title = datasetFile_.toStdString();
    fo.programName = machine::frameProgramName(path.toStdString());
    writeFileAtomic(
        path.toStdString(),
        machine::writeControllerFrame(primary.pose.rotation, primary.pose.translation, frameFormat(), fo));
  } catch (const std::exception& e) {
    if (error) *error = QString::fromUtf8(e.what());
    return false;
  }
  return true;
}

bool MatchingPage::savePerPointDeviations(const QString& path, QString* error) const {
  if (!result_ || !set_) {
    if (error) *error = tr("There are no deviations after matching yet: run the matching first.");
    return false;
  }
  try {
    writeFileAtomic(path.toStdString(), matching::perPointCsv(result_->primaryRun().after, *set_));
  } catch (const std::exception& e) {
    if (error) *error = QString::fromUtf8(e.what());
    return false;
  }
  return true;
}

void MatchingPage::savePerPointDialog() {
  const QString dir =
      document_->fileName().isEmpty() ? QString() : QFileInfo(document_->fileName()).absolutePath();
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Export the deviations after matching"), QDir(dir).filePath(QStringLiteral("deviations.csv")),
      tr("CSV files (*.csv)") + QStringLiteral(";;") + tr("All files (*)"));
  if (path.isEmpty()) return;
  QString error;
  if (!savePerPointDeviations(path, &error))
    QMessageBox::critical(this, tr("Cannot export the deviations"), error);
}

void MatchingPage::saveFrameDialog() {
  const machine::FrameFormat format = frameFormat();
  const QString suffix = format == machine::FrameFormat::Heidenhain ? QStringLiteral(".h")
                         : format == machine::FrameFormat::Siemens  ? QStringLiteral(".spf")
                                                                    : QStringLiteral(".nc");
  const QString filter = format == machine::FrameFormat::Heidenhain ? tr("HEIDENHAIN programs (*.h)")
                         : format == machine::FrameFormat::Siemens  ? tr("SINUMERIK subprograms (*.spf)")
                                                                    : tr("FANUC programs (*.nc)");
  const QString dir =
      document_->fileName().isEmpty() ? QString() : QFileInfo(document_->fileName()).absolutePath();
  const QString start = QDir(dir).filePath(QStringLiteral("POSTURE_FRAME") + suffix);
  const QString path = QFileDialog::getSaveFileName(this, tr("Save the controller frame"), start,
                                                    filter + QStringLiteral(";;") + tr("All files (*)"));
  if (path.isEmpty()) return;
  QString error;
  if (!saveFrame(path, &error)) QMessageBox::critical(this, tr("Cannot save the frame"), error);
}

void MatchingPage::showView(const QString& view) {
  if (set_ && !result_) runNow();
  if (view == QLatin1String("convergence") || view == QLatin1String("curve")) {
    tabs_->setCurrentWidget(curve_);
  } else if (view == QLatin1String("remeasure")) {
    tabs_->setCurrentIndex(2);
  } else if (view == QLatin1String("points")) {
    tabs_->setCurrentWidget(table_);
  } else if (view == QLatin1String("frame")) {
    tabs_->setCurrentWidget(frameTab_);
  } else {  // "3d", "matching", "results", "machine"
    tabs_->setCurrentIndex(0);
  }
  beforeView_->resetCamera();
}

}  // namespace metrofit
