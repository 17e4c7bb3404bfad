#pragma once
// The kinematics & SPC study page (IEEE Access, kinematic compensation algorithm): the circular test of the
// study, identified on load (Levenberg-Marquardt of core/kinematics, milliseconds) with the errors and their
// standard errors; Compensate makes the compensated references for the nominal circle and shows what they
// give; Export writes them as G-code or STEP-NC. Views: "path" (path view, polar deviation plot,
// tables), "spc" (X-bar / R charts, histogram, indices of the study's feature series), "ballbar" (the
// ballbar breakdown of the test into named causes, core/kinematics/ballbar.h) and
// "actuators": the paper's chain from the SPC regression offset angles to actuator errors and their
// compensation (studies.kinematics.from_spc), and the three-axis errors from circular tests in XY,
// YZ and ZX (studies.kinematics.planes). The actuators view chooses those datasets (the edges among the
// feature series, the plane tests among the circular tests and feature series, or none): a choice is an
// undoable edit of the study setting, and the view shows the study computed again; "Save DFQ…" writes
// the two edges as `metrofit-cli kinematic from-spc --dfq` does.
// Effects applied on the diagnosis page (studies.diagnosis.kinematic.applied) are part of the model
// (kinematic_study.h): a line names them, and Apply / undo identifies again.
#include <QStringList>
#include <QWidget>

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "core/project/project.h"
#include "core/study/kinematic_study.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;
class QPushButton;
class QStackedWidget;
class QTabWidget;
class QTableWidget;

namespace metrofit {
class CircularPathView;
class PolarDeviationView;
class ProjectDocument;
class SpcView;
struct Iso230Result;

class KinematicsPage : public QWidget {
  Q_OBJECT
 public:
  explicit KinematicsPage(ProjectDocument* document, QWidget* parent = nullptr);
  ~KinematicsPage() override;

  /// "path", "spc", "actuators" or "ballbar": switches to that view with results on it (compensates when not
  /// done yet).
  Q_INVOKABLE void showView(const QString& view);

  /// Identifies the circular test shown (again). False with errorMessage() when it cannot.
  bool identify();
  /// Compensated references for the nominal circle; identifies first when needed.
  bool compensate();
  /// Write the compensated references (compensating first when needed). False with `error`.
  bool exportGcode(const QString& path, QString* error = nullptr);
  bool exportStepNc(const QString& path, QString* error = nullptr);
  /// Writes the SPC tab's feature series as a Q-DAS DFQ file (atomically), as `metrofit-cli spc --data
  /// <its file> --column C --subgroup N [--lsl --usl] [--nominal] --dfq path` does. False with `error`
  /// when the study has no SPC series or core refuses.
  bool exportSpcDfq(const QString& path, QString* error = nullptr);
  QPushButton* spcDfqButton() const { return spcDfqButton_; }
  /// The SPC tab's settings of studies.kinematics.spc, each an undoable edit: the series (feature series
  /// or CMM report datasets; items carry the id, "" for none), its characteristic (the numeric columns of
  /// the series' feature table), the subgroup size, the specification limits and the nominal (empty:
  /// none; the limits are written together when both are numbers, in the UI's or C number format).
  QComboBox* spcSeriesCombo() const { return spcSeries_; }
  QComboBox* spcColumnCombo() const { return spcColumn_; }
  QSpinBox* spcSubgroupBox() const { return spcSubgroup_; }
  QLineEdit* spcLslEdit() const { return spcLsl_; }
  QLineEdit* spcUslEdit() const { return spcUsl_; }
  QLineEdit* spcNominalEdit() const { return spcNominal_; }
  /// Why the limits typed are not written ("" when they are).
  QString spcLimitsHint() const;
  /// Writes the from-SPC edges' deviations as a Q-DAS DFQ file (atomically), the file `metrofit-cli
  /// kinematic from-spc --dfq` writes for the same edges. False with `error` when the chain has no result.
  bool exportEdgesDfq(const QString& path, QString* error = nullptr);
  QPushButton* edgesDfqButton() const { return edgesDfqButton_; }
  /// The actuators view's dataset choosers (item data: the dataset id, "" for none): the edge along X
  /// (axis 0) or Y (axis 1) of studies.kinematics.from_spc, the circular test of a plane of
  /// studies.kinematics.planes.
  QComboBox* edgeCombo(int axis) const { return pickers_[static_cast<std::size_t>(axis)].combo; }
  QComboBox* planeCombo(TestPlane plane) const { return pickers_[2 + static_cast<std::size_t>(plane)].combo; }

  void selectDataset(const QString& id);
  QString currentDataset() const;
  /// The study as identified, or nullptr.
  const KinematicStudyData* study() const { return study_ ? &*study_ : nullptr; }
  const CompensationPreview* compensation() const { return compensation_ ? &*compensation_ : nullptr; }
  QString errorMessage() const { return error_; }

  QTabWidget* tabs() const { return tabs_; }
  QTableWidget* errorTable() const { return errors_; }
  QTableWidget* compensationTable() const { return compensationTable_; }
  /// The Ballbar tab: the breakdown of the test (core/kinematics/ballbar.h), ranked by share: cause, value
  /// (µm), ± std. error (µm), share (%); the last row "Unexplained (RMS)"; causes within the noise greyed.
  /// Hidden with the reason in ballbarLabel() when the test has none.
  QTableWidget* ballbarTable() const { return ballbarTable_; }
  QLabel* ballbarLabel() const { return ballbarLabel_; }
  /// "Includes applied effects: ..." when the model includes effects applied on the diagnosis page.
  QLabel* appliedLabel() const { return applied_; }
  CircularPathView* pathView() const { return path_; }
  PolarDeviationView* polarView() const { return polar_; }
  SpcView* spcView() const { return spc_; }
  /// The actuators tab: errors derived from SPC (with the circular test's for comparison), and the
  /// three-axis errors; each table is hidden with a message in its label when not configured.
  QTableWidget* fromSpcTable() const { return fromSpcTable_; }
  QTableWidget* threeAxisTable() const { return threeAxisTable_; }
  QLabel* fromSpcLabel() const { return fromSpcLabel_; }
  QLabel* threeAxisLabel() const { return threeAxisLabel_; }
  QPushButton* compensateButton() const { return compensateButton_; }
  /// The test's summary above the tabs (points, nominal circle, loops, ISO 230-4 results).
  QLabel* infoLabel() const { return info_; }
  /// The message shown instead of the tabs when the test cannot be identified.
  QLabel* messageLabel() const { return message_; }
  /// The result stored in the project for the test shown (results.kinematics.<dataset>, computed by
  /// Compensate): "From the saved project, computed …: …" with its figures, or why it is out of date;
  /// hidden when nothing is stored or the page shows the compensation it computed.
  QLabel* storedLabel() const { return stored_; }
  QString storedResultText() const;
  /// Why the study's settings are refused (the field named), empty when they are good.
  QString settingsError() const { return settingsError_; }
  /// A radial-only (ballbar) test: its polar plot, shown with the message instead of the tabs.
  PolarDeviationView* radialPolarView() const { return radialPolar_; }
  /// The page the stack shows: the tabs, the message, or the radial-only test's message and plot.
  QWidget* currentView() const;
  /// "ISO 230-4: CCW: G … µm, F … … … µm; CW: …; H … µm" (empty without a direction).
  static QString isoText(const Iso230Result& iso);

 private:
  void refresh();
  void onDatasetChosen(int index);
  void showStudy();
  void showCompensation();
  void showActuators();
  void showBallbar();
  void onExportGcode();
  void onExportStepNc();
  void onExportSpcDfq();
  void onExportEdgesDfq();
  void updateButtons();
  /// Puts the dataset choosers on the datasets and settings of the project (signals blocked).
  void syncPickers();
  /// Keeps the compensated study's figures in the project (results.kinematics.<dataset>).
  void storeResult();
  void showStoredResult();
  /// Refuses to run with settings that cannot be read: the message names the field.
  void showSettingsError();
  /// The SPC settings row from the study (signals blocked).
  void syncSpcControls();
  /// Chooses the SPC series (one undo step with a characteristic of it; "" removes the block).
  void chooseSpcSeries(const QString& id);
  /// Writes the limits and the nominal typed (one undo step; nothing while only one limit is given).
  void writeSpcLimits();
  /// The numeric columns of a dataset's feature table (read once per file state).
  QStringList spcColumns(const std::string& datasetId);

  /// A dataset chooser of the actuators view and the study setting it edits.
  struct Picker {
    QComboBox* combo = nullptr;
    QString key;        ///< JSON pointer in the kinematics study: "/from_spc/x_dataset", "/planes/xy", ...
    QStringList kinds;  ///< the dataset kinds it offers
    QString undoText;
  };

  ProjectDocument* document_;
  QComboBox* combo_;
  QLabel* info_;
  QLabel* applied_ = nullptr;  ///< "Includes applied effects: ..." (hidden when none)
  QLabel* stored_ = nullptr;   ///< the stored result (storedLabel)
  QString settingsError_;      ///< studies.kinematics cannot be read: nothing runs
  QStackedWidget* stack_;
  QLabel* message_;
  QTabWidget* tabs_;
  CircularPathView* path_;
  PolarDeviationView* polar_;
  QWidget* radialPage_ = nullptr;
  QLabel* radialLabel_ = nullptr;
  PolarDeviationView* radialPolar_ = nullptr;
  QTableWidget* errors_;
  QTableWidget* compensationTable_;
  QTableWidget* ballbarTable_ = nullptr;
  QLabel* ballbarLabel_ = nullptr;
  SpcView* spc_;
  QTableWidget* fromSpcTable_ = nullptr;
  QTableWidget* threeAxisTable_ = nullptr;
  QLabel* fromSpcLabel_ = nullptr;
  QLabel* threeAxisLabel_ = nullptr;
  QPushButton* identifyButton_;
  QPushButton* compensateButton_;
  QPushButton* gcodeButton_;
  QPushButton* stepNcButton_;
  QPushButton* spcDfqButton_ = nullptr;
  QPushButton* edgesDfqButton_ = nullptr;
  std::array<Picker, 5> pickers_;  ///< edge X, edge Y, planes XY, YZ, ZX
  QWidget* spcTab_ = nullptr;
  QComboBox* spcSeries_ = nullptr;
  QComboBox* spcColumn_ = nullptr;
  QSpinBox* spcSubgroup_ = nullptr;
  QLineEdit* spcLsl_ = nullptr;
  QLineEdit* spcUsl_ = nullptr;
  QLineEdit* spcNominal_ = nullptr;
  QLabel* spcHint_ = nullptr;
  std::string spcColumnsKey_;  ///< the file state spcColumnsCache_ was read from
  QStringList spcColumnsCache_;
  QStringList spcCounterColumns_;  ///< those of spcColumnsCache_ that count parts (consecutive integers)
  std::optional<KinematicStudyData> study_;
  std::optional<CompensationPreview> compensation_;
  QString error_;
  std::vector<DatasetRef> datasets_;
  QString projectFile_;
  quint64 generation_ = 0;  ///< the document's generation the page shows
  std::string studyJson_;
};

}  // namespace metrofit
