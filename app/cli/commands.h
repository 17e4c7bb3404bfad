#pragma once
// metrofit-cli subcommands. main.cpp only builds the CLI11 parser and maps errors to exit codes:
//   0 success, 2 bad input (metrofit::InputError or a command-line error: one line naming the
//   file / line / field / option), 1 any other failure. Results go to --out (atomically) or stdout.
#include <stdexcept>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace metrofit::cli {

/// A subcommand whose method has not landed yet (exit code 1, message without "internal error").
class NotAvailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Registers every subcommand on `app`. Each subcommand's callback stores its runner in `run`.
void registerCommands(CLI::App& app, int argc, char** argv);
/// Runs the selected subcommand (after a successful parse). Returns the exit code.
int runSelected();

/// Writes `text` to `outPath` atomically, or to stdout when outPath is empty.
void writeResult(const std::string& outPath, const std::string& text);

}  // namespace metrofit::cli
