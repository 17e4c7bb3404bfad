#pragma once
// metrofit-cli subcommands. main.cpp only builds the CLI11 parser and maps errors to exit codes:
//   0 success, 2 bad input (metrofit::InputError or a command-line error: one line naming the
//   file / line / field / option), 1 any other failure. Results go to --out (atomically) or stdout.
#include <chrono>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/run.h"
#include "core/io/csv.h"
#include "core/setup/report.h"
#include "core/thermal/thermal_log.h"

namespace CLI {
class App;
class Option;
class Validator;
}  // namespace CLI

namespace metrofit::cli {

/// Registers every subcommand on `app`. Each subcommand's callback stores its runner in `run`.
void registerCommands(CLI::App& app, int argc, char** argv);
/// Runs the selected subcommand (after a successful parse). Returns the exit code.
int runSelected();

/// Progress of a long run on stderr when stderr is a terminal (never in a pipe or a test): one line,
/// rewritten at most every 200 ms, erased when the object goes, before the summary line.
class TerminalProgress {
 public:
  /// `line` makes the progress line from an observer's summary ("diagnose thermal: 42 %").
  explicit TerminalProgress(std::function<std::string(const IterationSummary&)> line = {});
  ~TerminalProgress();
  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;
  /// An observer that shows `line` of each summary and never stops the run.
  Observer* observer() { return &observer_; }
  /// Shows a line directly (progress that does not come through an observer).
  void show(const std::string& line);

 private:
  bool tty_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point last_{};
  std::function<std::string(const IterationSummary&)> line_;
  FunctionObserver observer_;
};

/// Writes `text` to `outPath` atomically, or to stdout when outPath is empty.
void writeResult(const std::string& outPath, const std::string& text);

// ---- shared by the subcommand files (cmd_*.cpp) ----
/// A subcommand's parse callback hands its runner over with this; runSelected() calls it.
void selectRunner(std::function<int()> runner);
/// An existing file, or "-" (standard input).
CLI::Option* existingFile(CLI::Option* option);
/// A number > 0; says "--opt: must be a positive number, got '-1'" (CLI::PositiveNumber prints the
/// range up to DBL_MAX in full).
CLI::Validator positiveNumber();
void addOut(CLI::App* sub, std::string& out);
void addSeed(CLI::App* sub, std::uint64_t& seed);
/// --delimiter auto|,|;|tab and --decimal auto|.|, (docs/file-formats.md#csv-dialects-and-standard-input:
/// every subcommand that reads a CSV). One subcommand runs per process, so they share one setting;
/// csvOptions() returns it.
void addCsvOptions(CLI::App* sub);
/// --sample-interval <value><unit> (s, min, h): a thermal log without a time column.
void addSampleIntervalOption(CLI::App* sub);
/// addCsvOptions and addSampleIntervalOption: every subcommand that reads a thermal log.
void addThermalLogOptions(CLI::App* sub);
/// The dialect, and the sampling interval when given (an OptionsError when it does not parse).
CsvReadOptions csvOptions();
/// --ta-meaning auto|deviation|actual and --ta-sign plain|nominal: how a DMIS output file's
/// TA(label)=TOL/... is read when the file has no F and FA to compute the deviation from
/// (docs/file-formats.md#dmis-output); dmisOptions() returns the setting.
void addDmisOptions(CLI::App* sub);
setup::DmisOptions dmisOptions();
std::vector<std::string> splitList(const std::string& commaSeparated);
/// Reads a thermal log and checks that target and every input name a column (inputs != target).
ThermalLog readThermalArgs(const std::string& data, const std::string& target, const std::string& inputList,
                           const CsvReadOptions& csv = csvOptions());

// One registration function per subcommand family, each in its own cmd_*.cpp.
void registerSetupCommand(CLI::App& app);
/// `simulate setup` (in cmd_setup.cpp), registered inside the `simulate` family.
void registerSimulateSetupCommand(CLI::App& simulate);
void registerMatchCommand(CLI::App& app);
void registerKinematicCommands(CLI::App& app);
/// `simulate circular` and `simulate bores` (in cmd_kinematic.cpp), inside the `simulate` family.
void registerSimulateKinematicCommands(CLI::App& simulate);
void registerSpcCommand(CLI::App& app);
void registerThermalCommands(CLI::App& app);
void registerDiagnoseCommands(CLI::App& app);
/// `project new|add|list` (in cmd_project.cpp).
void registerProjectCommands(CLI::App& app);
/// `fit-element` (in cmd_fit.cpp).
void registerFitElementCommand(CLI::App& app);
/// `watch` (in cmd_watch.cpp): the live loop.
void registerWatchCommand(CLI::App& app);

}  // namespace metrofit::cli
