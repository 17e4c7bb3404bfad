// metrofit-bench --setup: see bench_setup.h.
//
// The large model is the paper's part pattern (Stryczek 2016, "Practical example") repeated: 480
// work offsets (pairs A/B = table at 0 / 180 deg) and 20 tools; part p sits at WKS pair p mod 240
// and uses two tools Ta != Tb drawn with a fixed seed; its 7 features and dimensions follow the
// paper's formulas (D1 = D2 = A + Ta, D3 = -B - Tb, D4 = A + B + 2 Tb, D5..D7 = -B - Ta) with the
// demo's tolerances; parts are added until there are 5000 dimensions. The deviations are the
// simulator's measurement set 0 (Eq. 12-13, w1 = 0.03, w2 = 0.02 mm).
#include "bench_setup.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "core/common/rng.h"
#include "core/setup/exact.h"
#include "core/setup/methods.h"
#include "core/setup/model.h"
#include "core/setup/objective.h"
#include "core/setup/report.h"
#include "core/sim/setup_sim.h"

namespace metrofit::bench {
namespace {

using Clock = std::chrono::steady_clock;

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Median wall time and median CPU time of the calling thread, s (the CPU time stays meaningful on a
/// loaded machine, where the wall time also counts the waits for a core).
struct Timing {
  double wall = 0.0, cpu = 0.0;
};
template <class F>
Timing medianSeconds(int repeat, F&& f) {
  std::vector<double> wall, cpu;
  for (int i = 0; i < repeat; ++i) {
    const auto a = Clock::now();
    const double c = threadCpuSeconds();
    f();
    cpu.push_back(threadCpuSeconds() - c);
    wall.push_back(std::chrono::duration<double>(Clock::now() - a).count());
  }
  std::sort(wall.begin(), wall.end());
  std::sort(cpu.begin(), cpu.end());
  return {wall[wall.size() / 2], cpu[cpu.size() / 2]};
}

constexpr int kWks = 480, kTools = 20, kDimensions = 5000;
constexpr double kPaperSeconds = 0.58;  ///< the paper: 5000 CRIPSO solutions in 0.58 s
constexpr double kTargetPaperMs = 1.0, kTargetLargeMs = 1000.0;

setup::Model largeModel() {
  using nlohmann::json;
  json j{{"name", "500 setup data x 5000 dimensions (paper pattern)"},
         {"axis", "Z"},
         {"step_mm", 0.001},
         {"bounds_mm", {-0.1, 0.1}}};
  j["setup"] = json::array();
  for (int w = 1; w <= kWks; ++w) j["setup"].push_back({{"id", "W" + std::to_string(w)}, {"kind", "wks"}});
  for (int t = 1; t <= kTools; ++t) j["setup"].push_back({{"id", "T" + std::to_string(t)}, {"kind", "tool"}});
  j["features"] = json::array();
  j["dimensions"] = json::array();
  j["arcs"] = json::array();
  const double lower[] = {-0.10, -0.08, -0.12, -0.10, -0.10, -0.10, -0.12};
  const double upper[] = {0.10, 0.08, 0.08, 0.15, 0.10, 0.10, 0.12};
  Rng rng(2016);
  int dims = 0;
  for (int p = 1; dims < kDimensions; ++p) {
    const int pair = (p - 1) % (kWks / 2);
    const std::string a = "W" + std::to_string(2 * pair + 1), b = "W" + std::to_string(2 * pair + 2);
    const int ta = 1 + static_cast<int>(rng.below(kTools));
    const int tb = 1 + static_cast<int>((static_cast<std::uint64_t>(ta) + rng.below(kTools - 1)) % kTools);
    const std::string tA = "T" + std::to_string(ta), tB = "T" + std::to_string(tb);
    const std::string part = "P" + std::to_string(p) + ".";
    auto f = [&](int k) { return part + "F" + std::to_string(k); };
    auto arc = [&](const std::string& from, const std::string& to, int w) {
      j["arcs"].push_back({{"from", from}, {"to", to}, {"weight", w}});
    };
    for (int k = 1; k <= 7; ++k) j["features"].push_back({{"id", f(k)}});
    arc(a, f(1), 1), arc(tA, f(1), 1);
    arc(a, f(2), 1), arc(tA, f(2), 1);
    arc(b, f(3), -1), arc(tB, f(3), -1);
    arc(a, f(4), 1), arc(tB, f(4), 1);
    for (int k = 5; k <= 7; ++k) arc(b, f(k), -1), arc(tA, f(k), -1);
    for (int k = 1; k <= 7 && dims < kDimensions; ++k, ++dims) {
      const std::string d = part + "D" + std::to_string(k);
      j["dimensions"].push_back({{"id", d}, {"lower", lower[k - 1]}, {"upper", upper[k - 1]}});
      if (k == 4) {
        arc(f(4), d, 1);
        arc(f(3), d, -1);
      } else {
        arc(f(k), d, 1);
      }
    }
  }
  return setup::modelFromJson(j, "generated");
}

}  // namespace

nlohmann::json benchSetup(const std::string& sourceDir, int repeat) {
  nlohmann::json out;
  // ---- the paper's example with the demo report ----
  {
    const setup::Model model = setup::readModel(sourceDir + "/resources/demo/setup/paper_example.json");
    const setup::Measurements meas =
        setup::readMeasurements({sourceDir + "/resources/demo/setup/paper_example_report.csv"}, model);
    const setup::SetupInstance inst(model, meas);
    setup::ExactOptions o;
    o.keepTrace = false;
    setup::ExactResult r = setup::solveExact(inst, o);  // warm-up (GLPK environment)
    const int n = std::max(repeat, 21);
    const Timing t = medianSeconds(n, [&] { r = setup::solveExact(inst, o); });
    std::printf(
        "setup exact, paper example (%zu setup data x %zu dimensions): %.3f ms wall, %.3f ms CPU (median of "
        "%d; "
        "target < %.0f ms), f1 %.4f mm, f1 %s, |x| %s\n",
        inst.variables(), inst.dimensions(), t.wall * 1e3, t.cpu * 1e3, n, kTargetPaperMs, r.score.f1,
        r.certificate.f1Optimal ? "optimal" : "NOT proven",
        r.certificate.f2Optimal ? "minimal" : "not proven");
    out["paper"] = {{"setup_data", inst.variables()},
                    {"dimensions", inst.dimensions()},
                    {"exact_ms", t.wall * 1e3},
                    {"exact_cpu_ms", t.cpu * 1e3},
                    {"target_ms", kTargetPaperMs},
                    {"f1_mm", r.score.f1},
                    {"f1_optimal", r.certificate.f1Optimal},
                    {"f2_minimal", r.certificate.f2Optimal},
                    {"solver_calls", r.certificate.solverCalls}};

    // ---- CRIPSO solutions per second on the same problem, vs the paper ----
    const setup::SetupProblem problem(inst);
    const auto cripso = setup::makeSetupAlgorithm("cripso", setup::kPaperBudget, 1, false);
    double f1 = 0.0;
    const Timing c = medianSeconds(std::max(repeat, 11), [&] {
      const optim::Result res = cripso->optimise(problem);
      f1 = res.bestComponents.empty() ? 0.0 : res.bestComponents[0];
    });
    const double perSecond = static_cast<double>(setup::kPaperBudget) / c.cpu;
    const double paperPerSecond = static_cast<double>(setup::kPaperBudget) / kPaperSeconds;
    std::printf(
        "setup CRIPSO, paper example: %ld solutions in %.2f ms CPU (%.2f ms wall) = %.0f solutions/s; paper "
        "%ld in "
        "%.2f s = %.0f/s; ratio metrofit/paper = %.0f (f1 %.4f mm, seed 1)\n",
        setup::kPaperBudget, c.cpu * 1e3, c.wall * 1e3, perSecond, setup::kPaperBudget, kPaperSeconds,
        paperPerSecond, perSecond / paperPerSecond, f1);
    out["cripso"] = {{"budget", setup::kPaperBudget},
                     {"seconds", c.wall},
                     {"cpu_seconds", c.cpu},
                     {"solutions_per_s", perSecond},
                     {"paper_seconds", kPaperSeconds},
                     {"paper_solutions_per_s", paperPerSecond},
                     {"ratio", perSecond / paperPerSecond},
                     {"f1_mm", f1}};
  }
  // ---- the generated large model ----
  {
    const setup::Model model = largeModel();
    const SetupMeasurementSet set = simulateSetupSet(model, SetupSimOptions{}, 0);
    const setup::SetupInstance inst(model, set.deviationMm);
    setup::ExactOptions o;
    o.keepTrace = false;
    setup::ExactResult r;
    const int n = std::max(1, std::min(repeat, 5));
    const Timing t = medianSeconds(n, [&] { r = setup::solveExact(inst, o); });
    std::printf(
        "setup exact, generated %zu setup data x %zu dimensions (%zu arcs): %.1f ms wall, %.1f ms CPU "
        "(median of "
        "%d; target < %.0f ms), f1 %.4f mm (before %.4f), f1 %s, |x| %s, %ld solver calls\n",
        inst.variables(), inst.dimensions(), model.arcs.size(), t.wall * 1e3, t.cpu * 1e3, n, kTargetLargeMs,
        r.score.f1, inst.f1Before(), r.certificate.f1Optimal ? "optimal" : "NOT proven",
        r.certificate.f2Optimal ? "minimal" : "not proven", r.certificate.solverCalls);
    out["large"] = {{"setup_data", inst.variables()},
                    {"dimensions", inst.dimensions()},
                    {"arcs", model.arcs.size()},
                    {"exact_ms", t.wall * 1e3},
                    {"exact_cpu_ms", t.cpu * 1e3},
                    {"target_ms", kTargetLargeMs},
                    {"f1_mm", r.score.f1},
                    {"f1_before_mm", inst.f1Before()},
                    {"f1_optimal", r.certificate.f1Optimal},
                    {"f2_minimal", r.certificate.f2Optimal},
                    {"solver_calls", r.certificate.solverCalls},
                    {"least_norm_rounds", r.certificate.normRounds}};
  }
  return out;
}

}  // namespace metrofit::bench
