#pragma once
// The import dialog: adds a file to a project as a dataset of one kind, the way
// `metrofit-cli project add` does (core/project/datasets.h addDataset, the same checks and the same
// DatasetRef). It shows
//   * the kind (guessed from the extension and the content: guessKind),
//   * the dataset id (empty: the file's base name, made unique by core),
//   * for CSV kinds the delimiter and the decimal mark (detected, overridable), what detection found
//     (header line, comment lines, data rows), and a column-to-role mapping: each column of the file
//     can be read as a role the readers look for (time_s / time_min / time_h, disp_z_um, qx, x_cmd_mm,
//     nominal_mm, ...), stored as the dataset's CsvReadOptions::columnMap (the project keeps the
//     mapping, not a converted copy of the file),
//   * for CSV kinds the lines before the header and the comment prefix (detected, overridable: an
//     instrument's preamble that is not '#'-commented), and "skip unreadable rows",
//   * for DMIS files how TA(label) values are read (meaning auto / deviation / actual, sign plain /
//     nominal); with a setup model in the project the preview shows the deviations read with them,
//   * a preview of the first rows (the file's own column names, with the role they are read as) and,
//     under it, every row that cannot be read (line, row, column, why),
//   * the first problem as one line naming file, line and field (core's InputError), in which case
//     the Import button stays disabled (unreadable rows do not block when they are skipped),
//   * "copy into the project" (embed: data/<id>.<ext>, never overwriting), default: link the file,
//   * with several DMIS files selected (setSeriesFiles), "Read the N files as one DMIS series": one
//     dataset listing every file ("paths", core/project/project.h), one file per workpiece, as the setup
//     study reads a series (checked by default).
//   * for an MTConnect log (SHDR or Streams, kind mtconnect) the grid it is resampled to (seconds; the
//     dataset's sample interval) and, as the preview, its resampled table (time_min and one column per
//     numeric sample; an empty cell: no value), not its raw lines,
//   * for probe points whose file holds measured points only (raw CMM points: no nominal columns), where
//     their nominals come from (core/project/nominals.h): an element fitted to them (with a fixed radius,
//     least squares or minimum zone, stray points left out, a bore's inward normals), or a second
//     measurement of the part (another probe-point dataset of the project, paired by id or by order,
//     normals from an element fitted to it or none), or a CAD part of the project (a cad-model dataset:
//     the closest points of the part); the fit's size and form are shown,
// The dialog does not change the project: after accept() the caller adds dataset() through the
// document's undo stack (ProjectDocument::addDataset). An embedded file is copied on accept().
#include <QDialog>
#include <QMap>
#include <QString>
#include <QStringList>
#include <string>

#include "core/io/csv.h"
#include "core/project/project.h"

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QSpinBox;
class QTableWidget;

namespace metrofit {

class ImportDialog : public QDialog {
  Q_OBJECT
 public:
  /// Rows shown in the preview.
  static constexpr int kPreviewRows = 20;

  /// `project` is the project the dataset will be added to (its ids must stay unique) and
  /// `projectPath` the path its dataset paths are relative to (ProjectDocument::projectPathForDatasets).
  ImportDialog(const Project& project, const QString& projectPath, QWidget* parent = nullptr);

  /// Reads a file, guesses its kind and resets dialect and mapping.
  void setFile(const QString& path);
  QString file() const;
  /// The kind in the command line's spelling ("thermal-log", ..., core's datasetKindNames()).
  void setKind(const QString& kind);
  QString kind() const;
  void setDatasetId(const QString& id);
  /// ',', ';', '\t' or 0 (detect).
  void setDelimiter(char delimiter);
  /// '.', ',' or 0 (detect).
  void setDecimal(char decimal);
  /// Reads the file's column `column` as `role`; an empty role keeps the file's name.
  void setRole(const QString& column, const QString& role);
  QString role(const QString& column) const;
  /// Lines before the header (-1: detect).
  void setHeaderLines(int lines);
  /// The comment prefix (empty: "#").
  void setCommentPrefix(const QString& prefix);
  /// Leave out the rows that cannot be read instead of refusing the file.
  void setSkipBadRows(bool skip);
  /// Every row that cannot be read, one line each ("line 7 (row 5), column 'T1': ..."), as listed
  /// under the preview.
  QStringList rowProblems() const;
  /// Dialect, header settings and mapping as they will be stored in the dataset (the mapping sorted
  /// by role).
  CsvReadOptions csvOptions() const;
  /// True when the file is read as DMIS output (the TA controls are shown).
  bool isDmisFile() const;
  /// "auto", "deviation" or "actual".
  void setTaMeaning(const QString& meaning);
  /// "plain" or "nominal".
  void setTaSign(const QString& sign);
  setup::DmisOptions dmisOptions() const;
  /// Copy the file into the project's data/ folder on import (only for a saved project).
  void setEmbed(bool embed);
  bool embed() const;

  /// Further DMIS files selected with the file: offered as one series with it (see the header comment).
  void setSeriesFiles(const QStringList& more);
  /// Read the file and setSeriesFiles() as one series (the check box; false when there are none).
  void setReadsSeries(bool series);
  bool readsSeries() const;

  /// True when the file is read as probe points of measured points only (the nominals box is shown).
  bool needsNominals() const;
  /// Where the nominals of measured points only come from (used when needsNominals()).
  void setNominals(const NominalSource& nominals);
  NominalSource nominals() const;
  /// What the nominals came out as ("sphere fitted to 18 points: radius 487.31 mm, form 0.004 mm"),
  /// empty when there are none.
  QString nominalsSummary() const { return nominalsSummary_; }

  /// A QIF file of several measured parts read as probe points: the parts ("1 · SN5802801 · PASS"), the
  /// chosen one (1-based) and the choice. Empty / 0 for every other file.
  QStringList qifParts() const { return qifParts_; }
  int qifPart() const;
  void setQifPart(int part);

  /// True when the file is an MTConnect log read as one (kind mtconnect, or a thermal log by content):
  /// the sample-interval box is shown and the preview is the resampled table.
  bool isMtconnectLog() const;
  /// The grid of an MTConnect log in seconds (> 0; stored as the dataset's sample interval).
  void setSampleIntervalS(double seconds);
  double sampleIntervalS() const;

  /// True when the file can be read as the chosen kind (the Import button is enabled).
  bool canImport() const { return problem_.isEmpty(); }
  /// The problem that keeps the file from being imported (one line), empty when there is none.
  QString problem() const { return problem_; }
  /// The dataset as it will be added (valid when canImport()).
  const DatasetRef& dataset() const { return dataset_; }

  /// The kind a file most likely is, from its extension and its first bytes (command-line spelling).
  static QString guessKind(const QString& path, const QByteArray& head);
  /// The open-file dialogs' filter of data files, "All files" first (CMM exports and data loggers write
  /// files without an extension, a Wenzel point file "SPH1_1"): one list for File › Import data and
  /// the dialog's Browse.
  static QString fileFilter();
  /// Roles the readers of a kind look for (command-line spelling of the kind).
  static QStringList rolesForKind(const QString& kind);

 private:
  void browse();
  void rebuildMapping(const std::vector<std::string>& header);
  void guessRoles();
  /// Guesses the kind again with the dialect and header lines shown, unless the user chose one.
  void reguessKind();
  void revalidate();
  void showRawPreview();
  void fillPreview(const CsvTable& table);
  void previewDmis();
  /// The resampled table of an MTConnect log as the preview; its summary in the detection line.
  void previewMtconnect();
  /// The preview of a file that is no CSV, read as the dataset (DatasetContent: features or rows).
  void previewContent(const std::string& file);
  void importNow();
  void buildNominalsBox();
  /// Shows the element / reference controls that apply to the chosen source.
  void updateNominalControls();

  Project project_;
  QString projectPath_;
  QString file_;
  std::string text_;  ///< the file's content (read once per setFile)
  QString readError_;
  std::vector<std::string> header_;  ///< the file's own columns as the mapping table shows them
  QMap<QString, QString> roles_;     ///< file column -> role
  QString problem_;
  DatasetRef dataset_;
  bool updating_ = false;
  bool kindChosen_ = false;  ///< the user chose the kind: it is not guessed again

  QLineEdit* fileEdit_;
  QComboBox* kind_;
  QLineEdit* id_;
  QComboBox* delimiter_;
  QComboBox* decimal_;
  QSpinBox* headerLines_;
  QLineEdit* comment_;
  QCheckBox* skipBadRows_;
  QGroupBox* dmisBox_;
  QComboBox* taMeaning_;
  QComboBox* taSign_;
  QCheckBox* embed_;
  QCheckBox* series_ = nullptr;
  QGroupBox* nominalsBox_ = nullptr;
  QComboBox* nominalFrom_ = nullptr;
  QComboBox* nominalElement_ = nullptr;
  QDoubleSpinBox* nominalRadius_ = nullptr;
  QComboBox* nominalCriterion_ = nullptr;
  QCheckBox* nominalInner_ = nullptr;
  QCheckBox* nominalRobust_ = nullptr;
  QComboBox* nominalReference_ = nullptr;
  QComboBox* nominalPair_ = nullptr;
  QComboBox* nominalCad_ = nullptr;
  QComboBox* qifPart_ = nullptr;              ///< "Measured part" of a QIF file read as probe points
  QDoubleSpinBox* sampleInterval_ = nullptr;  ///< an MTConnect log's grid, seconds
  QStringList qifParts_;
  QFormLayout* form_ = nullptr;
  QString nominalsSummary_;
  QStringList seriesFiles_;
  QListWidget* rowProblems_;
  QLabel* detected_;
  QTableWidget* mapping_;
  QTableWidget* preview_;
  QLabel* problemLabel_;
  QDialogButtonBox* buttons_;
};

}  // namespace metrofit
