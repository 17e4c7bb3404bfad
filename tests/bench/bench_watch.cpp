#include "bench_watch.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "core/io/file_io.h"
#include "core/project/project.h"
#include "core/setup/exact.h"
#include "core/setup/model.h"
#include "core/setup/objective.h"
#include "core/setup/report.h"
#include "core/sim/setup_sim.h"
#include "core/study/watch.h"

namespace metrofit::bench {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point a) {
  return std::chrono::duration<double, std::milli>(Clock::now() - a).count();
}

/// The simulated series split into one report per part (header + that part's rows).
std::vector<std::string> splitByPart(const std::string& csv, std::size_t parts) {
  std::istringstream in(csv);
  std::string header, line;
  while (std::getline(in, header) && (header.empty() || header[0] == '#')) {
  }  // the simulator's comment line
  std::vector<std::string> out(parts, header + "\n");
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::size_t part = std::stoul(line.substr(0, line.find(',')));
    if (part >= 1 && part <= parts) out[part - 1] += line + "\n";
  }
  return out;
}

}  // namespace

nlohmann::json benchWatch(std::size_t files, const std::string& sourceDir) {
  files = std::max<std::size_t>(files, 10);
  const fs::path root = fs::temp_directory_path() / ("metrofit-bench-watch-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "in");
  fs::create_directories(root / "pool");
  fs::copy_file(fs::path(sourceDir) / "resources/demo/setup/paper_example.json", root / "model.json");
  const setup::Model model = setup::readModel((root / "model.json").string());
  Project p;
  p.name = "watch bench";
  p.datasets.push_back({"model", dataset_kind::kSetupModel, "model.json", "", "", {}});
  p.studies["setup"] = {{"model", "model"}};
  saveProject(p, (root / "P.metrofit").string());

  SetupSimOptions sim;
  sim.parts = static_cast<int>(files);
  sim.seed = 11;
  const std::vector<std::string> reports = splitByPart(simulateSetupReport(model, sim), files);
  std::vector<std::string> names;
  for (std::size_t k = 0; k < files; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "report_%05zu.csv", k + 1);
    names.push_back(name);
    writeFileAtomic((root / "pool" / name).string(), reports[k]);
  }

  WatchOptions o;
  o.projectPath = (root / "P.metrofit").string();
  o.folder = (root / "in").string();
  WatchSession session(o);

  std::vector<std::size_t> checkpoints;
  // The last checkpoint leaves one file for the diagnosis's timing.
  for (std::size_t c : {10u, 50u, 100u, 200u, 500u, 1000u, 2000u})
    if (c < files) checkpoints.push_back(c);
  if (checkpoints.back() != files - 1) checkpoints.push_back(files - 1);

  std::printf("watch: one CMM report per part (paper model, %zu dimensions), dropped one at a time\n",
              model.dimensions.size());
  std::printf("%8s %12s %16s %12s %12s %10s\n", "parts", "watch_ms", "watch+diag_ms", "batch_ms",
              "batch/watch", "same_x");
  nlohmann::json rows = nlohmann::json::array();
  std::vector<std::string> dropped;
  for (std::size_t k = 0; k < files; ++k) {
    fs::rename(root / "pool" / names[k], root / "in" / names[k]);
    dropped.push_back((root / "in" / names[k]).string());
    const bool checkpoint = std::find(checkpoints.begin(), checkpoints.end(), k + 1) != checkpoints.end();
    // Every file without the diagnosis (as `watch --diagnose-every N` runs between diagnoses); at a
    // checkpoint the next file is processed with it, to show what the diagnosis costs at that size.
    const auto t0 = Clock::now();
    const WatchEvent e = session.process(names[k], /*runDiagnosis=*/false);
    const double watchMs = msSince(t0);
    if (!e.error.empty()) throw std::runtime_error("watch bench: " + names[k] + ": " + e.error);
    if (!checkpoint) continue;

    // The peer: the batch run on the same files, from the files (no process start).
    const auto t1 = Clock::now();
    const setup::Measurements m = setup::readMeasurements(dropped, model);
    const setup::ExactResult batch = setup::solveExact(setup::SetupInstance(model, m));
    const double batchMs = msSince(t1);
    bool same = batch.x.size() == e.correction.size();
    for (std::size_t i = 0; same && i < batch.x.size(); ++i) same = batch.x[i] == e.correction[i].second;

    // The diagnosis's cost at this size: the next file with it (then taken out of the timing above).
    double diagMs = -1.0;
    if (k + 1 < files) {
      fs::rename(root / "pool" / names[k + 1], root / "in" / names[k + 1]);
      dropped.push_back((root / "in" / names[k + 1]).string());
      const auto t2 = Clock::now();
      const WatchEvent d = session.process(names[k + 1], /*runDiagnosis=*/true);
      diagMs = msSince(t2);
      if (!d.error.empty()) throw std::runtime_error("watch bench: " + names[k + 1] + ": " + d.error);
      ++k;
    }
    std::printf("%8zu %12.2f %16.1f %12.2f %12.1f %10s\n", dropped.size() - (diagMs >= 0 ? 1 : 0), watchMs,
                diagMs, batchMs, batchMs / std::max(watchMs, 1e-6), same ? "yes" : "NO");
    rows.push_back({{"parts", dropped.size() - (diagMs >= 0 ? 1 : 0)},
                    {"watch_ms", watchMs},
                    {"watch_with_diagnosis_ms", diagMs >= 0 ? nlohmann::json(diagMs) : nlohmann::json()},
                    {"batch_ms", batchMs},
                    {"same_correction", same}});
  }
  std::printf(
      "a report every 50 ms is kept up with while watch_ms < 50 (the diagnosis: every N-th file, "
      "--diagnose-every)\n");
  fs::remove_all(root);
  return {{"rows", rows}};
}

}  // namespace metrofit::bench
