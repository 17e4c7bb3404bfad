#pragma once
// The live loop (issue 29 item 5, DESIGN.md "the live loop"): a folder the CMM writes its reports
// into, watched by polling; every complete new file is added to the project's setup study series
// and the setup correction, its SPC gate, the diagnosis's residual check and the next offsets file
// are recomputed. Qt-free, never prints: WatchSession::run hands one WatchEvent per file to a
// callback and asks an observer (CancelToken) whether to go on.
//
// Complete files. A file of the folder (not in a sub-folder) is taken when its size and mtime are
// the same in two consecutive polls (a file that appeared by rename is complete at once and is
// taken at the second poll it is seen in). Ignored: names starting with '.', names ending in
// ".tmp", ".part", ".partial", ".crdownload", "~" (a writer's temporary names), the journal, the
// sub-folders (rejected/ among them). New files of one poll are taken in arrival order: mtime, then
// name.
//
// The journal (the audit log): "<project stem>.watch.jsonl" in the project's folder, append-only,
// one JSON object per line, appended and fsync'ed after the outputs of the file are written:
//   {"v":1, "file", "size", "mtime_ns", "hash" (FNV-1a 64 of the bytes, hex), "status":
//    "accepted"|"rejected", "kind", "parts", "time" (UTC, ISO 8601), and for an accepted file
//    "measurements" (the file's rows as read against the model: the series is rebuilt from the
//    journal, so the watched files may be moved away once taken), for a rejected one "error"}.
// A file whose (name, size, mtime) or (name, hash) is in the journal is never read again; a file
// whose line is missing (the process was killed while processing it) is processed again at the
// next start (its outputs are written again, identically). A line cut short by a kill (no final
// newline) is dropped when the journal is opened.
//
// A file: its kind is guessed from name and content (guessDatasetKind). Kinds serving a CMM report
// (cmm-report CSV, DMIS, OGP / PC-DMIS text reports, DFQ, Calypso _chr, QIF) are read against the
// setup model (setup::readMeasurements, default CSV dialect and DMIS reading, as `metrofit-cli
// setup` without options) and appended to the series in arrival order (a file is normally one
// measured part; a file with several parts adds them all). Any other kind, a file that does not
// read, or a part measured twice is rejected: the file goes to <folder>/rejected/ with
// "<name>.error.txt" beside it holding the one-line error, the journal records it, the loop goes on.
//
// After each accepted file, on the whole series:
//   * correction: the exact optimum (setup::solveExact with default options) on the mean deviations
//     of the series (report.h), kept as running sums in row order -- the same numbers as `metrofit-cli setup
//     --method exact --data F1 F2 ...` on the same files in the same order, so the offsets files are
//     byte-identical;
//   * SPC per dimension: an individuals / moving-range chart (spc.h, n = 1) of the deviation
//     (measured - nominal) in arrival order (part by part), nominal 0, the tolerance limits as specification,
//     minimum correction the model's step; in_control = every chart in control (null until every dimension
//     has 2 values with a non-zero moving range);
//   * the gate: the correction is RELEASED (the offsets file is written) only when in_control is
//     true and at least one dimension's systematic deviation is significant (spc.h: |E| beyond
//     its k sigma / sqrt(N) interval and at least one step); otherwise it is HELD (the offsets file
//     keeps its last released content) and `gate` says why. The gate holds or releases the whole
//     correction rather than dropping single dimensions: the exact optimum couples every dimension
//     through the shared work and tool offsets, and what is released must equal the batch run;
//   * diagnosis: diagnoseSetup on the series (every `diagnoseEvery`-th file); residual_white = its residual
//   check's `white` (null while
//     the series is too short).
// The offsets file: <out>/offsets.<ext> for the control (setup::exportCorrections, default export
// options: wear registers, program number as `setup --export`), written atomically
// (writeFileAtomic). fanuc .nc, heidenhain .h, siemens .spf, csv .csv.
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/common/run.h"
#include "core/setup/export.h"
#include "core/setup/model.h"
#include "core/setup/report.h"

namespace metrofit {

struct WatchOptions {
  std::string projectPath;  ///< the .metrofit project (its setup study's model is used)
  std::string folder;       ///< the watched folder
  std::string outFolder;    ///< where offsets.<ext> goes; empty: "<project folder>/offsets"
  setup::ControllerFormat control = setup::ControllerFormat::Csv;
  int pollMs = 200;           ///< polling interval, ms (10..60000)
  int diagnoseEvery = 1;      ///< diagnosis every N-th file (>= 1)
  double coverageFactor = 2;  ///< k of the SPC gate's interval (> 0)

  bool isValid(std::string* why) const;
};

/// What one processed file produced (the CLI prints it as one JSON line, toJson()).
struct WatchEvent {
  std::string file;                       ///< name in the watched folder
  std::string kind;                       ///< guessed kind (command-line spelling), "" when unreadable
  std::vector<std::string> parts;         ///< measured parts the file added
  std::size_t seriesParts = 0;            ///< parts in the series after it
  std::optional<bool> inControl;          ///< null: too few parts to chart every dimension
  std::vector<std::string> outOfControl;  ///< dimensions whose chart has points beyond its limits
  std::vector<std::string> significant;   ///< dimensions with a significant systematic deviation
  std::vector<std::pair<std::string, double>> correction;  ///< datum id -> mm (the exact optimum)
  std::vector<std::string> changed;  ///< datums whose correction differs from the previous file's
  double f1BeforeMm = 0.0, f1Mm = 0.0;
  bool released = false;              ///< the offsets file was written with `correction`
  std::string gate;                   ///< why it was released or held
  std::optional<bool> residualWhite;  ///< null: not run for this file or the series is too short
  std::string residual;               ///< the residual check's summary line (what it depends on)
  std::string offsetsFile;            ///< written (released) offsets file
  std::string error;                  ///< non-empty: the file was rejected
  std::string rejectedTo;             ///< where the rejected file went
  double seconds = 0.0;               ///< processing time

  /// {"file", "kind", "part" (the parts joined by ", "; null when none), "parts", "series_parts",
  ///  "in_control", "out_of_control", "significant", "correction" {datum: mm} (null when rejected),
  ///  "changed", "f1_before_mm", "f1_mm", "released", "gate", "offsets", "residual_white",
  ///  "residual", "error" (null when accepted), "rejected_to", "seconds"}
  nlohmann::json toJson() const;
};

class WatchSession {
 public:
  /// Loads the project, its setup model and the journal (and the series it holds). ValidationError
  /// / FileError naming the project when it cannot be read or has no setup model; OptionsError for
  /// invalid options; FileError when the folder does not exist.
  explicit WatchSession(WatchOptions options);
  ~WatchSession();
  WatchSession(const WatchSession&) = delete;
  WatchSession& operator=(const WatchSession&) = delete;

  /// One poll of the folder: the names of the files found complete and not yet journaled, in
  /// arrival order. Also finishes a reject that a kill interrupted (journaled, not yet moved).
  std::vector<std::string> poll();
  /// Processes one file of the folder (see the header comment); never throws for a bad file (the
  /// event carries the error); FileError when the journal or the offsets cannot be written.
  WatchEvent process(const std::string& name, bool runDiagnosis = true);

  /// Polls and processes until the observer says stop (it is asked after every file and about every
  /// 20 ms while waiting; IterationSummary: iteration = files processed, evaluations = polls) or, with
  /// `once`, until a poll finds nothing new and nothing settling. Returns the number of files processed.
  std::size_t run(const std::function<void(const WatchEvent&)>& onEvent, Observer* observer, bool once);

  const std::string& journalPath() const { return journalPath_; }
  const std::string& offsetsPath() const { return offsetsPath_; }
  std::size_t seriesFiles() const { return seriesFiles_; }

  /// The journal file of a project: "<folder>/<stem>.watch.jsonl".
  static std::string journalPathFor(const std::string& projectPath);
  /// "offsets.nc" / ".h" / ".spf" / ".csv".
  static std::string offsetsFileName(setup::ControllerFormat control);

 private:
  struct Seen {
    std::uintmax_t size = 0;
    std::int64_t mtimeNs = 0;
  };
  struct Done {
    std::uintmax_t size = 0;
    std::int64_t mtimeNs = 0;
    std::string hash;
    bool rejected = false;
  };
  void loadJournal();
  void appendJournal(const std::string& line);
  bool journaled(const std::string& name, std::uintmax_t size, std::int64_t mtimeNs) const;
  WatchEvent reject(WatchEvent e, const std::string& name, std::uintmax_t size, std::int64_t mtimeNs,
                    const std::string& hash, const std::string& error);

  /// ValidationError when a (part, dimension) of `m` is in the series already (mergeMeasurements's).
  void checkNew(const setup::Measurements& m) const;
  /// Appends an accepted file to the series: rows, parts, running sums in row order (so the means
  /// are bit for bit those of mergeMeasurements / `setup --data F1 F2 ...`), the charts' values.
  void append(setup::Measurements m);

  WatchOptions options_;
  setup::Model model_;
  std::string journalPath_, offsetsPath_;
  setup::Measurements series_;  ///< the accepted files merged, in arrival order
  std::size_t seriesFiles_ = 0;
  std::vector<double> sumMm_;                     ///< per dimension, sum of deviations in row order
  std::vector<std::vector<double>> chartValues_;  ///< per dimension, deviations in arrival order
  std::map<std::pair<std::string, std::size_t>, std::pair<std::string, long>> measured_;  ///< -> source, line
  std::multimap<std::string, Done> done_;  ///< journal entries by file name
  std::map<std::string, Seen> seen_;       ///< last poll's candidates
  std::vector<double> lastCorrection_;
  long polls_ = 0;
};

}  // namespace metrofit
