#pragma once
// The posture-matching study page: the project's probe point sets, the matching settings
// (method, tolerance, degree-of-freedom locks, scale), Run with progress and Cancel, and the results:
// two linked 3D views before and after matching side by side, the optimisation curve of SADE and
// GA-simplex, one table of rough / SADE / GA-simplex / closed-form / minimax, the machine adjustment
// values for the study's machine, the remeasure loop's rounds and the points with their deviations.
// The "Controller frame" tab shows the same posture as a frame of the control (HEIDENHAIN datum shift +
// PLANE SPATIAL, SINUMERIK TRANS + AROT, FANUC G68.2; core/machine/controller_frame.h): its blocks, and
// "Save frame…" writes the whole program as `metrofit-cli match --frame ... --frame-out` does. The
// control and the decimals are study settings (studies.matching.frame, .frame_decimals; undoable).
//
// A run computes every method (core/study/matching_study.h) in a worker thread; the method selector picks
// the posture shown "after" and used for the machine adjustment. Settings come from the project's
// studies.matching (dataset, tolerance_mm, method, allow_scale, locks, machine); edits of the method,
// tolerance, scale and locks are written back through the document's undo stack.
// Effects added with the diagnosis page's Apply (studies.diagnosis.matching.applied: scale,
// surface_offset:<surface>, distortion) are part of the study's model (core/study/matching_study.h
// studyModelSet): the views, the tables and the runs use the nominal points deformed by them, the
// info line names them, and undoing Apply brings the declared rigid model back.
#include <QWidget>
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "core/machine/controller_frame.h"
#include "core/matching/probe_points.h"
#include "core/project/project.h"
#include "core/study/matching_study.h"
#include "widgets/common/backgroundrun.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPlainTextEdit;
class QPushButton;
class QSpinBox;
class QSplitter;
class QStackedWidget;
class QTabWidget;
class QTableWidget;

namespace metrofit {
class MatchingCurveView;
class PointSetView;
class ProjectDocument;

class MatchingPage : public QWidget {
  Q_OBJECT
 public:
  explicit MatchingPage(ProjectDocument* document, QWidget* parent = nullptr);
  ~MatchingPage() override;

  /// Shows the probe point set with this dataset id (no effect for an unknown id).
  void selectDataset(const QString& id);
  QString currentDataset() const;
  /// The "before" view (kept under this name for the existing callers).
  PointSetView* pointView() const { return beforeView_; }
  PointSetView* beforeView() const { return beforeView_; }
  PointSetView* afterView() const { return afterView_; }
  QTableWidget* pointTable() const { return table_; }
  QTableWidget* methodsTable() const { return methodsTable_; }
  QTableWidget* machineTable() const { return machineTable_; }
  QTableWidget* remeasureTable() const { return remeasureTable_; }
  MatchingCurveView* curveView() const { return curve_; }
  QString errorMessage() const { return error_; }
  /// The info line above the views (points, surfaces, applied effects).
  QString infoText() const;
  /// What the project stores of the points shown (results.matching.<dataset>,
  /// core/project/stored_results.h), or "" when nothing is stored: the stored figures marked "From the
  /// saved project, computed <when>" when the settings and the points are those they came from, else
  /// "out of date" with why. Shown in the status line until the points are matched again.
  QString storedResultText() const;
  /// The status line under the views (the run's figures, "Not matched yet", a stored result).
  QString statusText() const;
  /// "Includes applied effects: ..." when studies.diagnosis.matching.applied is in use, else empty.
  QString appliedText() const { return appliedText_; }
  const std::optional<matching::MatchingStudyResult>& result() const { return result_; }
  bool isRunning() const;

  /// The controller frame of the shown result (tab "Controller frame").
  QComboBox* frameControlCombo() const { return frameControl_; }
  QSpinBox* frameDecimalsSpin() const { return frameDecimals_; }
  QPlainTextEdit* frameTextBox() const { return frameText_; }
  QPushButton* saveFrameButton() const { return saveFrame_; }
  /// "Machine…" (Ctrl+Shift+M): the project's machine (topology, geometry, travel, control).
  QPushButton* machineButton() const { return machineButton_; }
  QLabel* machineLabel() const { return machineLabel_; }
  /// Opens the machine dialog; on OK writes studies.matching.machine and .frame in one undo step.
  void editMachine();
  /// Writes the machine and the control as the dialog does (one undo step "Change the machine").
  void setMachine(const machine::MachineDefinition& definition, machine::FrameFormat controller);
  machine::FrameFormat frameFormat() const;
  void setFrameFormat(machine::FrameFormat format);
  /// The frame's blocks (controllerFrameBlocks) of the primary method's posture, one per line; empty
  /// without a result.
  QString frameText() const;
  /// Writes the frame program of the primary posture to `path` (atomically) as `metrofit-cli match
  /// --frame F --frame-out path --frame-decimals N --data <dataset file>` does. False with the message
  /// in *error (no result, or core's message).
  bool saveFrame(const QString& path, QString* error = nullptr) const;
  /// Writes each point's deviation after the fit as CSV (matching::perPointCsv, as `match --per-point`);
  /// false with a readable *error before a run or when the file cannot be written.
  bool savePerPointDeviations(const QString& path, QString* error = nullptr) const;

  /// Settings (also through the controls).
  void setMethod(matching::MatchMethod method);
  void setTolerance(double toleranceMm);
  /// Lock a degree of freedom: 0..5 = rx, ry, rz, x, y, z.
  void setLocked(int dof, bool locked);
  /// The "Lock … and run" button offered after a refusal for undetermined parameters (hidden otherwise).
  QPushButton* lockMissingButton() const { return lockMissing_; }

  /// Runs the study synchronously (tests, screenshots); returns false with errorMessage() set on
  /// bad input.
  bool runNow();
  /// Starts the run in a worker thread (the Run button); finished() when done.
  void startRun();
  void cancelRun();

  /// Switches to a view with results on it for the demo: "3d" (before / after), "convergence",
  /// "results", "machine", "remeasure", "points", "frame". Runs the study synchronously first if needed.
  Q_INVOKABLE void showView(const QString& view);

 signals:
  void finished();

 private:
  void refresh();
  void showPoints(int comboIndex);
  /// After a refusal: the locks that would make every method determinable, offered on lockMissing_.
  void offerMissingLocks();
  void lockMissingAndRun();
  void settingsChanged();
  /// The status line's text for settingsError_.
  QString settingsErrorText() const;
  /// Writes one studies.matching value (undoable); `typing` lets consecutive edits merge.
  void writeStudyValue(const QString& key, const nlohmann::json& value, const QString& text, bool typing);
  /// A run on probe points declares them as the study's dataset when the study names none yet
  /// (studies.matching.dataset, undoable), so that the report shows what the page shows.
  void declareStudyDataset();
  /// The settings a stored result is checked against (the study without notes and frame output, and
  /// the effects applied on the diagnosis page).
  nlohmann::json storedSettingsJson() const;
  /// The points shown (sets_, paths resolved), or nullptr.
  const DatasetRef* currentSetRef() const;
  /// Keeps the primary run's figures in the project (results.matching.<dataset>).
  void storeResult();
  /// Without a result: the status line says what is stored (storedResultText) or "Not matched yet".
  void showStoredStatus();
  /// Puts the study's settings (and studies.matching.locks) into the controls with their signals
  /// blocked; true when a control changed.
  bool syncSettingsFromStudy(const matching::MatchingStudySettings& settings);
  matching::MatchingStudyOptions currentOptions() const;
  void applyResult();
  void updateViews();
  void fillMethodsTable();
  void fillMachineTable();
  /// "Machine adjustment values for the project's machine ..." or the default machine's warning.
  void fillMachineLabel();
  bool hasProjectMachine() const;
  bool hasFrameSetting() const;
  void fillRemeasureTable();
  void fillPointTable();
  void fillFrame();
  void saveFrameDialog();
  void savePerPointDialog();
  void reevaluate();
  void setRunning(bool running);

  ProjectDocument* document_;
  QComboBox* combo_;
  QComboBox* methodCombo_;
  QDoubleSpinBox* toleranceSpin_;
  QCheckBox* allowScale_;
  std::array<QCheckBox*, 6> locks_{};
  QPushButton* runButton_;
  QPushButton* cancelButton_;
  QProgressBar* progress_;
  QLabel* info_;
  QLabel* status_;
  /// After a run refused for undetermined parameters: locks them (one undo step) and runs again.
  QPushButton* lockMissing_ = nullptr;
  std::array<bool, 6> missingLocks_{};
  QStackedWidget* stack_;
  QSplitter* content_;
  PointSetView* beforeView_;
  PointSetView* afterView_;
  QTabWidget* tabs_;
  QTableWidget* methodsTable_;
  QLabel* machineLabel_;
  QTableWidget* machineTable_;
  QTableWidget* remeasureTable_;
  QLabel* remeasureLabel_;
  MatchingCurveView* curve_;
  QTableWidget* table_;
  QComboBox* frameControl_;
  QSpinBox* frameDecimals_;
  QPlainTextEdit* frameText_;
  QPushButton* saveFrame_;
  QPushButton* machineButton_;
  QLabel* frameNote_;
  QWidget* frameTab_;
  QString datasetFile_;  ///< the shown probe points' file (the frame program's title)
  QLabel* message_;
  QString error_;
  /// Why studies.matching cannot be read (the page then uses the defaults and says so); empty when valid.
  QString settingsError_;
  std::vector<DatasetRef> sets_;
  QString projectFile_;
  quint64 generation_ = 0;  ///< the document's generation the page shows

  std::optional<ProbePointSet> set_;     ///< the study's model: rawSet_ with the applied effects
  std::optional<ProbePointSet> rawSet_;  ///< as read
  /// The CAD part the shown points' nominals come from ({"from": "cad"}), null otherwise.
  std::shared_ptr<const geometry::MeshSearch> cad_;
  std::string appliedKey_;  ///< studies.diagnosis.matching.applied as text
  QString appliedText_;
  matching::MatchingStudySettings settings_;
  bool writingStudy_ = false;  ///< the page's own edit of the document
  std::optional<matching::MatchingStudyResult> result_;
  BackgroundRun<matching::MatchingStudyResult>* run_;
};

}  // namespace metrofit
