// metrofit-cli: the headless front end (CONTRACT.md "Command line").
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
    std::fprintf(stderr, "metrofit-cli: %s (see metrofit-cli --help)\n", what.c_str());
    return 2;
  }
  try {
    return metrofit::cli::runSelected();
  } catch (const metrofit::InputError& e) {
    std::fprintf(stderr, "metrofit-cli: %s\n", e.what());
    return 2;
  } catch (const metrofit::cli::NotAvailable& e) {
    std::fprintf(stderr, "metrofit-cli: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "metrofit-cli: internal error: %s\n", e.what());
    return 1;
  }
}
