// metrofit-cli watch: the live loop (issue 29 item 5; core/study/watch.h).
//
//   watch DIR --project P.metrofit [--out DIR2] [--control fanuc|heidenhain|siemens|csv]
//         [--poll-ms N] [--diagnose-every N] [--once]
//
// Every complete new file in DIR (size and mtime unchanged across two polls) is added to the
// project's setup study series; the exact correction, its SPC gate, the diagnosis's residual check
// and the offsets file <DIR2>/offsets.<ext> (default DIR2: the project's folder/offsets) are
// recomputed. One JSON line per file on stdout, flushed after each line, keys of CONTRACT.md
// (file, kind, part, in_control, correction, residual_white, error) and more (WatchEvent::toJson).
// The journal <project stem>.watch.jsonl in the project's folder makes the reading exactly-once
// across restarts. SIGTERM / SIGINT: the current file is finished, then exit 0. --once: what is
// there (once complete) is processed, then exit 0. One summary line on stderr at the end.
#include <CLI/CLI.hpp>

#include <csignal>
#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "app/cli/commands.h"
#include "core/common/error.h"
#include "core/common/run.h"
#include "core/setup/export.h"
#include "core/study/watch.h"

namespace metrofit::cli {
namespace {

volatile std::sig_atomic_t gStop = 0;

extern "C" void onStopSignal(int) {
  gStop = 1;
}

struct WatchArgs {
  std::string folder, project, out, control = "csv";
  int pollMs = WatchOptions{}.pollMs;
  int diagnoseEvery = WatchOptions{}.diagnoseEvery;
  bool once = false;
};

int runWatch(const WatchArgs& a) {
  WatchOptions o;
  o.projectPath = a.project;
  o.folder = a.folder;
  o.outFolder = a.out;
  o.control = setup::parseControllerFormat(a.control, "--control");
  o.pollMs = a.pollMs;
  o.diagnoseEvery = a.diagnoseEvery;
  std::string why;
  if (!o.isValid(&why)) throw OptionsError(ErrorContext{}, why);
  WatchSession session(o);

  struct sigaction sa {};
  sa.sa_handler = onStopSignal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGINT, &sa, nullptr);

  std::size_t rejected = 0;
  FunctionObserver stop(
      [](const IterationSummary&) { return gStop ? ObserverDecision::Stop : ObserverDecision::Continue; });
  const std::size_t n = session.run(
      [&rejected](const WatchEvent& e) {
        if (!e.error.empty()) ++rejected;
        const std::string line = e.toJson().dump() + "\n";
        std::fwrite(line.data(), 1, line.size(), stdout);
        std::fflush(stdout);
      },
      &stop, a.once);
  std::fprintf(stderr, "watch: %zu file(s) processed (%zu rejected), series of %zu file(s); journal %s%s\n",
               n, rejected, session.seriesFiles(), session.journalPath().c_str(),
               gStop ? "; stopped by a signal" : "");
  return 0;
}

}  // namespace

void registerWatchCommand(CLI::App& app) {
  auto a = std::make_shared<WatchArgs>();
  auto* sub = app.add_subcommand(
      "watch",
      "Live loop: each complete new report in DIR updates the setup correction and the offsets file");
  sub->add_option("DIR", a->folder, "The watched folder (where the CMM writes its reports)")
      ->required()
      ->check(CLI::ExistingDirectory);
  existingFile(sub->add_option("--project", a->project, "The project (.metrofit) whose setup model is used")
                   ->required());
  sub->add_option("--out", a->out,
                  "Folder of the offsets file offsets.<ext> (default: offsets/ beside the project)");
  sub->add_option("--control", a->control, "Offsets file format: fanuc|heidenhain|siemens|csv")
      ->check(CLI::IsMember({"fanuc", "heidenhain", "siemens", "csv"}))
      ->capture_default_str();
  sub->add_option("--poll-ms", a->pollMs,
                  "Polling interval, ms; a file is taken when unchanged over two polls")
      ->check(CLI::Range(10, 60000))
      ->capture_default_str();
  sub->add_option("--diagnose-every", a->diagnoseEvery,
                  "Run the diagnosis's residual check every N-th file (it is the slow step)")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  sub->add_flag("--once", a->once, "Process the files that are there (once complete) and exit");
  sub->callback([a] { selectRunner([a]() -> int { return runWatch(*a); }); });
}

}  // namespace metrofit::cli
