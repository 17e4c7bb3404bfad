// metrofit-bench: speed measured against a peer in the same run, reported as ratios (DESIGN.md
// "Performance"). Not a test: run it by hand or in a benchmark job.
//
//   metrofit-bench [--io] [--rng] [--optimizers [--quick]] [--matching] [--real-matching] [--thermal]
//   [--real-thermal] [--repeat N] [--json OUT]
//                                                               (no section flag: all sections)
//
// Sections now: --io (CSV reader on the real CAIVIAC log vs a naive getline/strtod reader that
// does no validation), --rng (our portable normal generator vs std::normal_distribution on
// mt19937_64), --optimizers (our metaheuristics and pagmo2's pso / sade side by side at equal
// budget, bench_optim.cpp; --quick: 5 seeds instead of 25), --matching / --real-matching (posture
// matching targets and the SDSS plug plates against their own fits, bench_matching.cpp). Later issues add
// --thermal, --diagnose, --real. --diagnose --open [--seeds N] [--quick] [--ratio R] [--domains
// thermal,setup]: the open-world detection study of the closed loop (bench_open_world.h).
// --kinematic-chain [--seeds N] (default 20): the kinematic-compensation paper's chain from SPC edges to
// compensation and the three-plane identification on simulated machines with known errors, against the
// circular-test identification and three separate 2-axis fits (bench_kinematic_chain.h).
// --cad: closest point on a triangle mesh, the k-d tree beside brute force, and one CAD match (bench_cad.h).
// --nist: the 27 NIST StRD nonlinear problems (../shared/data/real/nist-strd-nls) from both starts, our
// Levenberg-Marquardt beside Ceres Solver: LRE and time per problem and start (bench_nist.h).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench_cad.h"
#include "bench_diagnose.h"
#include "bench_diagnose_scale.h"
#include "bench_diagnose_sm.h"
#include "bench_kinematic.h"
#include "bench_kinematic_chain.h"
#include "bench_matching.h"
#include "bench_watch.h"
#ifdef METROFIT_HAVE_CERES
#include "bench_nist.h"
#endif
#include "bench_open_world.h"
#include "bench_optim.h"
#include "bench_setup.h"
#include "bench_thermal.h"
#include "core/common/rng.h"
#include "core/io/csv.h"
#include "core/io/file_io.h"
#include "core/io/json_util.h"
#include "metrofit/version.h"

namespace {

using Clock = std::chrono::steady_clock;

template <class F>
double medianSeconds(int repeat, F&& f) {
  std::vector<double> t;
  for (int i = 0; i < repeat; ++i) {
    const auto a = Clock::now();
    f();
    t.push_back(std::chrono::duration<double>(Clock::now() - a).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

volatile double g_sink = 0.0;

/// The peer: what a quick script-like C++ reader does (no quoting, no validation, no locations).
double naiveCsvSum(const std::string& text) {
  std::istringstream in(text);
  std::string line, cell;
  std::getline(in, line);  // header
  double sum = 0.0;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    while (std::getline(ls, cell, ',')) sum += std::strtod(cell.c_str(), nullptr);
  }
  return sum;
}

nlohmann::json benchIo(const std::string& sourceDir, int repeat) {
  const std::string path = sourceDir + "/resources/demo/data/thermal_caiviac.csv";
  const std::string text = metrofit::readFile(path);
  std::size_t fields = 0;
  const double ours = medianSeconds(repeat, [&] {
    const metrofit::CsvTable t = metrofit::parseCsv(text, path);
    double s = 0.0;
    for (std::size_t c = 0; c < t.columnCount(); ++c)
      for (double v : t.numericColumn(c)) s += v;
    fields = t.rowCount() * t.columnCount();
    g_sink = s;
  });
  const double peer = medianSeconds(repeat, [&] { g_sink = naiveCsvSum(text); });
  std::printf(
      "io   CSV parse + numbers, CAIVIAC log (%zu fields, %.1f MB): metrofit %.1f ms (%.1f ns/field), "
      "naive getline/strtod %.1f ms; ratio metrofit/peer = %.2f\n",
      fields, static_cast<double>(text.size()) / 1e6, ours * 1e3, ours * 1e9 / static_cast<double>(fields),
      peer * 1e3, ours / peer);
  return {{"fields", fields}, {"metrofit_ms", ours * 1e3}, {"peer_ms", peer * 1e3}, {"ratio", ours / peer}};
}

nlohmann::json benchRng(int repeat) {
  const int n = 2'000'000;
  const double ours = medianSeconds(repeat, [&] {
    metrofit::Rng r(1);
    double s = 0;
    for (int i = 0; i < n; ++i) s += r.normal();
    g_sink = s;
  });
  const double peer = medianSeconds(repeat, [&] {
    std::mt19937_64 g(1);
    std::normal_distribution<double> d;
    double s = 0;
    for (int i = 0; i < n; ++i) s += d(g);
    g_sink = s;
  });
  std::printf(
      "rng  %d normals: metrofit::Rng %.2f ns each, std::normal_distribution<mt19937_64> %.2f ns; ratio = "
      "%.2f\n",
      n, ours * 1e9 / n, peer * 1e9 / n, ours / peer);
  return {{"n", n}, {"metrofit_ns", ours * 1e9 / n}, {"peer_ns", peer * 1e9 / n}, {"ratio", ours / peer}};
}

}  // namespace

int main(int argc, char** argv) {
  bool io = false, rng = false, optimizers = false, matching = false, realMatching = false;
  bool thermal = false, realThermal = false;    // --thermal, --real-thermal (bench_thermal.cpp)
  bool kinematic = false;                       // --kinematic (bench_kinematic.cpp)
  bool kinematicChain = false;                  // --kinematic-chain (bench_kinematic_chain.cpp)
  bool nist = false;                            // --nist (bench_nist.cpp)
  bool cad = false;                             // --cad (bench_cad.cpp)
  bool diagnose = false, realDiagnose = false;  // --diagnose, --real-diagnose (bench_diagnose.cpp)
  bool open = false;                            // --diagnose --open (bench_open_world.cpp)
  metrofit::bench::OpenBenchOptions openOptions;
  int explicitSeeds = 0;               // --seeds N wins over --quick
  std::vector<std::string> openCase;   // --open-case DOMAIN CASE SEED
  bool setupBench = false;             // --setup (bench_setup.cpp)
  std::vector<std::size_t> scaleRows;  // --diagnose-scale (bench_diagnose_scale.cpp)
  std::size_t watchFiles = 0;          // --watch [N] (bench_watch.cpp)
  metrofit::bench::DiagnoseBenchOptions diagnoseOptions;
  metrofit::bench::OptimBenchOptions optimOptions;
  int repeat = 5;
  std::string jsonOut;
  std::string sourceDir = METROFIT_SOURCE_DIR;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--io")
      io = true;
    else if (a == "--rng")
      rng = true;
    else if (a == "--optimizers")
      optimizers = true;
    else if (a == "--setup")
      setupBench = true;
    else if (a == "--kinematic")
      kinematic = true;
    else if (a == "--kinematic-chain")
      kinematicChain = true;
    else if (a == "--nist")
      nist = true;
    else if (a == "--cad")
      cad = true;
    else if (a == "--matching")
      matching = true;
    else if (a == "--real-matching")
      realMatching = true;
    else if (a == "--thermal")
      thermal = true;
    else if (a == "--real-thermal")
      realThermal = true;
    else if (a == "--diagnose")
      diagnose = true;
    else if (a == "--diagnose-scale") {  // [ROWS,ROWS,...]: default 10k to a week of 1 Hz data
      scaleRows = {10000, 50000, 100000, 300000, 604800};
      if (i + 1 < argc && argv[i + 1][0] != '-') {
        scaleRows.clear();
        std::stringstream list(argv[++i]);
        for (std::string item; std::getline(list, item, ',');) scaleRows.push_back(std::stoul(item));
      }
    } else if (a == "--watch") {  // [N]: reports dropped one at a time (default 500)
      watchFiles = 500;
      if (i + 1 < argc && argv[i + 1][0] != '-') watchFiles = std::stoul(argv[++i]);
    } else if (a == "--real-diagnose")
      realDiagnose = true;
    else if (a == "--open")
      open = diagnose = true;
    else if (a == "--open-case" && i + 3 < argc) {  // one data set of the open-world study, then exits
      openCase = {argv[i + 1], argv[i + 2], argv[i + 3]};
      i += 3;
    } else if (a == "--diagnose-demo" && i + 1 < argc) {  // writes the closed loop's demo data and exits
      for (const auto& line : metrofit::bench::writeDiagnoseDemo(argv[++i]))
        std::printf("%s\n", line.c_str());
      return 0;
    } else if (a == "--quick") {
      optimOptions.seeds = 5;
      diagnoseOptions.seeds = 10;
      diagnoseOptions.cleanSeeds = 20;
      openOptions.seeds = 20;
    } else if ((a == "--only" || a == "--methods" || a == "--domains") && i + 1 < argc) {
      std::vector<std::string>& list = a == "--only"      ? optimOptions.problems
                                       : a == "--methods" ? optimOptions.methods
                                                          : openOptions.domains;
      std::string item;
      for (const char* c = argv[++i];; ++c) {
        if (*c == ',' || *c == '\0') {
          if (!item.empty()) list.push_back(item);
          item.clear();
          if (*c == '\0') break;
        } else {
          item += *c;
        }
      }
    } else if (a == "--seeds" && i + 1 < argc) {
      optimOptions.seeds = std::max(1, std::atoi(argv[++i]));
      explicitSeeds = optimOptions.seeds;
    } else if (a == "--ratio" && i + 1 < argc) {  // --diagnose --open: effect-to-noise ratio (default 5)
      openOptions.ratio = std::atof(argv[++i]);
      if (!(openOptions.ratio > 0.0)) {
        std::fprintf(stderr, "metrofit-bench: --ratio needs a number > 0\n");
        return 2;
      }
    } else if (a == "--first-seed" && i + 1 < argc) {
      optimOptions.firstSeed = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--repeat" && i + 1 < argc)
      repeat = std::max(1, std::atoi(argv[++i]));
    else if (a == "--json" && i + 1 < argc)
      jsonOut = argv[++i];
    else if (a == "--source-dir" && i + 1 < argc)
      sourceDir = argv[++i];
    else if (a == "--help" || a == "-h") {
      std::printf(
          "usage: metrofit-bench [--io] [--rng] [--optimizers [--quick] [--only PROBLEMS] [--methods "
          "METHODS]] [--matching] [--real-matching] [--cad] "
          "[--thermal] [--real-thermal] [--kinematic] [--kinematic-chain [--seeds N]] [--nist] [--setup] "
          "[--diagnose "
          "[--quick]] [--diagnose --open "
          "[--seeds N] [--quick] [--domains LIST]] [--real-diagnose] [--diagnose-scale [ROWS,...]] [--watch "
          "[N]] "
          "[--repeat N] "
          "[--json OUT] "
          "[--source-dir DIR]\n");
      return 0;
    } else {
      std::fprintf(stderr, "metrofit-bench: unknown option '%s' (see --help)\n", a.c_str());
      return 2;
    }
  }
  if (!io && !rng && !optimizers && !matching && !realMatching && !thermal && !realThermal && !kinematic &&
      !kinematicChain && !nist && !cad && !diagnose && !realDiagnose && !setupBench && scaleRows.empty() &&
      watchFiles == 0)
    io = rng = optimizers = true;
  if (explicitSeeds > 0) openOptions.seeds = explicitSeeds;
  if (!openCase.empty()) {
    openOptions.sourceDir = sourceDir;
    try {
      const nlohmann::json j = metrofit::bench::benchOpenCase(
          openOptions, openCase[0], openCase[1], std::strtoull(openCase[2].c_str(), nullptr, 10));
      if (!jsonOut.empty()) metrofit::writeFileAtomic(jsonOut, metrofit::dumpJson(j));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "metrofit-bench: %s\n", e.what());
      return 1;
    }
    return 0;
  }
  nlohmann::json result{{"version", metrofit::kVersion}, {"repeat", repeat}};
  try {
    if (io) result["io"] = benchIo(sourceDir, repeat);
    if (rng) result["rng"] = benchRng(repeat);
    optimOptions.sourceDir = sourceDir;
    if (optimizers) result["optimizers"] = metrofit::bench::benchOptimizers(optimOptions);
    if (setupBench) result["setup"] = metrofit::bench::benchSetup(sourceDir, repeat);
    if (kinematic) result["kinematic"] = metrofit::bench::benchKinematic(repeat);
    if (kinematicChain) {
      // The paper's chain from SPC and the three-plane identification on simulated machines (default 20).
      metrofit::bench::KinematicChainBenchOptions o;
      if (explicitSeeds > 0) o.seeds = explicitSeeds;
      o.repeat = repeat;
      result["kinematic_chain"] = metrofit::bench::benchKinematicChain(o);
    }
    if (nist) {
#ifdef METROFIT_HAVE_CERES
      result["nist"] = metrofit::bench::benchNist(sourceDir + "/../shared/data/real/nist-strd-nls", repeat);
#else
      throw std::runtime_error("--nist needs Ceres Solver, which this build did not find (libceres-dev)");
#endif
    }
    // --matching: the matching targets (bench_matching.cpp); --real-matching: the SDSS plug plates in
    // ../shared/data/real/cmm-plugplate-sdss (not in the repository: no licence) against their own fits.
    if (matching) result["matching"] = metrofit::bench::benchMatching({});
    if (cad) result["cad"] = metrofit::bench::benchCad(repeat);
    if (realMatching)
      result["real_matching"] =
          metrofit::bench::benchRealMatching(sourceDir + "/../shared/data/real/cmm-plugplate-sdss");
    if (thermal)
      result["thermal"] = metrofit::bench::benchThermal(sourceDir + "/resources/demo/data", repeat);
    if (realThermal)
      result["real_thermal"] = metrofit::bench::benchRealThermal(
          sourceDir + "/resources/demo/data/thermal_caiviac.csv",
          sourceDir + "/../shared/data/real/thermal-spindle-sjtu/thermal_expansion_error_original.csv");
    if (diagnose && open) {
      // The open-world study (effects no catalogue entry models, gross errors,
      // clean data with heavy-tailed noise); --quick: 20 seeds per case.
      openOptions.sourceDir = sourceDir;
      result["diagnose_open"] = metrofit::bench::benchDiagnoseOpen(openOptions);
    } else if (diagnose) {
      std::vector<metrofit::bench::DomainRunner> runners = metrofit::bench::thermalKinematicRunners();
      // setup / matching runners are appended here.
      for (auto& r : metrofit::bench::setupMatchingRunners(sourceDir)) runners.push_back(std::move(r));
      result["diagnose"] = metrofit::bench::benchDiagnose(runners, diagnoseOptions);
    }
    if (realDiagnose) {
      result["real_diagnose"] =
          metrofit::bench::benchRealDiagnose(sourceDir + "/resources/demo/data/thermal_caiviac.csv");
      result["real_diagnose_caiviac"] =
          metrofit::bench::benchRealDiagnoseCaiviac(sourceDir + "/resources/demo/data/thermal_caiviac.csv");
      result["real_diagnose_sdss"] =
          metrofit::bench::benchRealDiagnoseSdss(sourceDir + "/../shared/data/real/cmm-plugplate-sdss");
    }
    if (!scaleRows.empty()) result["diagnose_scale"] = metrofit::bench::benchDiagnoseScale(scaleRows);
    if (watchFiles > 0) result["watch"] = metrofit::bench::benchWatch(watchFiles, sourceDir);
    if (!jsonOut.empty()) metrofit::writeFileAtomic(jsonOut, metrofit::dumpJson(result));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "metrofit-bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
