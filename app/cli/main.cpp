// metrofit-cli: the headless front end (docs/file-formats.md#command-line).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>

#include "app/cli/commands.h"
#include "core/common/error.h"
#include "metrofit/version.h"

int main(int argc, char** argv) {
  CLI::App app{"Metrofit: machining error compensation from measured data (headless).", "metrofit-cli"};
  app.set_version_flag("--version", std::string("metrofit ") + metrofit::kVersion,
                       "Print the version and exit");
  app.require_subcommand(1);
  app.fallthrough(false);
  // Set before the subcommands are added: CLI11 copies the footer into each of them.
  app.footer(
      "Results go to --out FILE (JSON, or CSV where the result is a table; written atomically) or to\n"
      "stdout; a one-line summary goes to stderr. --seed N makes stochastic methods reproducible.\n"
      "Exit status: 0 success, 2 bad input (one line naming the file, line or field, or the option),\n"
      "1 any other failure. 'metrofit-cli SUBCOMMAND --help' lists the options of a subcommand;\n"
      "man metrofit-cli is the manual. File formats and JSON results:\n"
      "/usr/share/doc/metrofit/file-formats.md (docs/file-formats.md in the source tree).");
  metrofit::cli::registerCommands(app, argc, argv);
  // CLI11 reports a stray word as "A subcommand is required"; name it instead.
  if (argc > 1 && argv[1][0] != '-') {
    bool known = false;
    std::string names;
    for (const CLI::App* sub : app.get_subcommands({})) {
      known |= sub->get_name() == argv[1];
      names += (names.empty() ? "" : ", ") + sub->get_name();
    }
    if (!known) {
      std::fprintf(stderr, "metrofit-cli: unknown subcommand '%s' (one of: %s; see metrofit-cli --help)\n",
                   argv[1], names.c_str());
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string what = e.what();
    for (auto& c : what) {
      if (c == '\n') c = ' ';
    }
    // "A subcommand is required" after `kinematic`: name the family and its subcommands, and the
    // word that was given instead ("thermal fti").
    const CLI::App* deepest = &app;
    std::string path;  // "thermal fit": the subcommands given, for the pointer to their --help
    int depth = 0;
    while (!deepest->get_subcommands().empty()) {
      deepest = deepest->get_subcommands().front();
      path += " " + deepest->get_name();
      ++depth;
    }
    if (deepest != &app && what.rfind("A subcommand is required", 0) == 0) {
      std::string names;
      for (const CLI::App* sub : deepest->get_subcommands({}))
        names += (names.empty() ? "" : ", ") + sub->get_name();
      const bool given = depth + 1 < argc && argv[depth + 1][0] != '-';
      what = given ? deepest->get_name() + ": unknown subcommand '" + argv[depth + 1] +
                         "' (one of: " + names + ")"
                   : deepest->get_name() + ": a subcommand is required (one of: " + names + ")";
    }
    std::fprintf(stderr, "metrofit-cli: %s (see metrofit-cli%s --help)\n", what.c_str(), path.c_str());
    return 2;
  }
  try {
    return metrofit::cli::runSelected();
  } catch (const metrofit::InputError& e) {
    std::fprintf(stderr, "metrofit-cli: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "metrofit-cli: internal error: %s\n", e.what());
    return 1;
  }
}
