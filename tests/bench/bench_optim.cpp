// metrofit-bench --optimizers: our metaheuristics against pagmo2 2.19 in the same process
// (DESIGN.md "Performance": our PSO / SADE at least as good at equal budget and at least as fast per
// evaluation as pagmo2's pso / sade).
//
// Protocol
//  * Problems, all 10-D, identical objective code on both sides:
//      rosenbrock   optim::rosenbrock on [-5, 10]^10   (pagmo gets a UDP calling the same function)
//      rastrigin    optim::rastrigin  on [-5.12, 5.12]^10
//      cec2014-fN   pagmo::cec2014(N, 10), N = 1, 4, 6, 10, on [-100, 100]^10; ours calls that object's
//                   fitness through an optim::Problem adapter, pagmo runs it natively. The reported
//                   objective is the error f - 100 N (the known optimum value).
//  * Budget B evaluations per run (default 10000 at 10-D), seeds 1..25 (--quick: 1..5), the same
//    seeds for every method. A method and its pagmo peer share the population size and get the
//    same number of evaluations: NP * floor(B / NP) (pagmo: generation 0 plus gen = B/NP - 1
//    generations of NP evaluations; SADE NP 30 -> 9990, PSO 100 particles -> 10000). Methods
//    without a peer get B. pagmo's counts are read back from problem::get_fevals().
//  * Methods, each with its defaults: ours sade (Jiang 2018: DE/rand/1/bin, Eq. 10-11), sade-jde
//    (the same operator with jDE self-adaptation, Sade::Adaptation::SelfAdaptive), pso (Stryczek 2016
//    settings), pso-ring (Pso::Options::ring(): lbest ring, constriction values), ga-simplex, nelder-mead
//    (random start; it stops when converged), cripso, ga, coa. pagmo: sade with variant 7 = DE/rand/1/bin
//    (the same operator as ours) and variant_adptv 1 = jDE self-adaptation (Brest et al. 2006): the peer of
//    our sade; sade variant 2 (rand/1/exp, pagmo's default) as an extra row; pso with its defaults (omega
//    0.7298, eta1 = eta2 = 2.05, max_vel 0.5, variant 5, neighb_type 2, neighb_param 4) and our PSO's swarm
//    size (100): the peer of our pso. sade's ftol = xtol = 0 so that it never stops before the budget.
//  * Time: CPU time of the calling thread for the whole run (ours: optimise(); pagmo: population
//    construction, which evaluates generation 0, plus evolve(); both run entirely on the calling
//    thread) divided by the evaluations, summed over the seeds: the ns per evaluation include each
//    method's own overhead and the objective. Thread CPU time rather than wall clock, so that other
//    load on the machine (a parallel build) does not decide a ratio near 1 (CEC f6 costs ~1 us per
//    evaluation in both, so its ratio is the objective's own cost either way).
//  * setup-paper: the setup-correction paper's example (Stryczek 2016; resources/demo/setup), 10
//    corrections on the 0.001 mm grid, the paper's budget of 5000 solutions for every method; the
//    objective is -f = f2 - 10 f1, reported as the error f(exact) - f(x) against GLPK's exact
//    optimum, and "hits" counts runs whose f1 is within one grid step of the exact f1 (the
//    issue's CRIPSO target: at least 9 of 10). pagmo evaluates the same function with x snapped
//    to the same grid. coa-30000: our COA at the paper's own budget for COA (100 iterations,
//    "approximately 30,000 solutions"), on setup-paper only.
//  * pagmo is quiet: verbosity 0 (its default) for both algorithms.
#include "bench_optim.h"

#include "core/setup/exact.h"
#include "core/setup/methods.h"
#include "core/setup/model.h"
#include "core/setup/objective.h"
#include "core/setup/report.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <pagmo/algorithms/pso.hpp>
#include <pagmo/algorithms/sade.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/problems/cec2014.hpp>
#include <pagmo/types.hpp>

#include "core/optim/coa.h"
#include "core/optim/cripso.h"
#include "core/optim/ga.h"
#include "core/optim/gasimplex.h"
#include "core/optim/neldermead.h"
#include "core/optim/problem.h"
#include "core/optim/pso.h"
#include "core/optim/sade.h"

namespace metrofit::bench {
namespace {

/// CPU seconds used by the calling thread.
double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
constexpr unsigned kDim = 10;
volatile double g_optimSink = 0.0;

/// Our side of a CEC-2014 function: pagmo's implementation, error relative to the optimum 100 id.
/// Not thread-safe (pagmo::cec2014 keeps mutable work buffers, so does x_); the bench is sequential.
class Cec2014Problem final : public optim::Problem {
 public:
  Cec2014Problem(unsigned id, unsigned dim) : cec_(id, dim), id_(id), x_(dim) {
    const auto b = cec_.get_bounds();
    lower_ = b.first;
    upper_ = b.second;
  }
  std::string name() const override { return "cec2014-f" + std::to_string(id_); }
  std::size_t dimension() const override { return x_.size(); }
  double lower(std::size_t i) const override { return lower_[i]; }
  double upper(std::size_t i) const override { return upper_[i]; }
  double evaluate(std::span<const double> x, std::span<double>) const override {
    std::copy(x.begin(), x.end(), x_.begin());
    return cec_.fitness(x_)[0] - 100.0 * id_;
  }

 private:
  pagmo::cec2014 cec_;
  unsigned id_;
  mutable pagmo::vector_double x_;
  std::vector<double> lower_, upper_;
};

/// pagmo's side of a FunctionProblem: a user-defined problem calling the very same function.
struct FunctionUdp {
  optim::FunctionProblem::Fn fn = nullptr;
  double lo = 0.0, hi = 0.0;
  unsigned dim = kDim;
  pagmo::vector_double fitness(const pagmo::vector_double& x) const { return {fn(x)}; }
  std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
    return {pagmo::vector_double(dim, lo), pagmo::vector_double(dim, hi)};
  }
  std::string get_name() const { return "metrofit function"; }
};

struct BenchProblem {
  std::string name;
  std::shared_ptr<const optim::Problem> ours;
  pagmo::problem peer;
  double peerOffset = 0.0;  ///< subtracted from pagmo's objective (CEC: 100 id)
  double oursOffset = 0.0;  ///< subtracted from our objective (setup: -f of the exact optimum)
  long budget = 0;          ///< evaluations per run; 0: the section's budget
  /// When set: does a final x hit the known optimum? (setup: f1 within one grid step)
  std::function<bool(const std::vector<double>&)> hit;
};

/// pagmo's side of the setup problem: the same objective on the same grid (x is snapped to the
/// 0.001 mm grid before it is evaluated, as our Tracker does, so both sides search the same space).
struct SetupUdp {
  std::shared_ptr<const setup::SetupProblem> problem;
  pagmo::vector_double fitness(const pagmo::vector_double& x) const {
    std::vector<double> g = x, components(3);
    problem->snap(g);
    return {problem->evaluate(g, components)};
  }
  std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
    pagmo::vector_double lo(problem->dimension()), hi(problem->dimension());
    for (std::size_t i = 0; i < lo.size(); ++i) {
      lo[i] = problem->lower(i);
      hi[i] = problem->upper(i);
    }
    return {lo, hi};
  }
};

/// The setup-correction paper's example (Stryczek 2016, bundled demo data), 10 corrections on the
/// 0.001 mm grid, the paper's budget of 5000 solutions; error = f(exact optimum) - f(x) (>= 0);
/// a hit = f1 within one grid step (0.001 mm) of the exact optimum's f1.
BenchProblem setupPaperProblem(const std::string& sourceDir) {
  const std::string dir = sourceDir + "/resources/demo/setup/";
  const setup::Model model = setup::readModel(dir + "paper_example.json");
  setup::SetupInstance instance(model, setup::readCmmReport(dir + "paper_example_report.csv", model));
  const setup::ExactResult exact = setup::solveExact(instance);
  auto problem = std::make_shared<const setup::SetupProblem>(instance);
  const double fExact = exact.score.f, f1Exact = exact.score.f1, step = instance.step();
  BenchProblem p{"setup-paper",       problem, pagmo::problem(SetupUdp{problem}), -fExact, -fExact,
                 setup::kPaperBudget, {}};
  p.hit = [problem, f1Exact, step](const std::vector<double>& x) {
    return problem->instance().f1(x) >= f1Exact - step - 1e-12;
  };
  return p;
}

std::vector<BenchProblem> makeProblems() {
  std::vector<BenchProblem> out;
  auto fn = [&](const char* name, optim::FunctionProblem::Fn f, double lo, double hi) {
    out.push_back({name,
                   std::make_shared<optim::FunctionProblem>(name, std::vector<double>(kDim, lo),
                                                            std::vector<double>(kDim, hi), f),
                   pagmo::problem(FunctionUdp{f, lo, hi, kDim}),
                   0.0,
                   0.0,
                   0,
                   {}});
  };
  fn("rosenbrock", optim::rosenbrock, -5.0, 10.0);
  fn("rastrigin", optim::rastrigin, -5.12, 5.12);
  for (unsigned id : {1u, 4u, 6u, 10u}) {
    out.push_back({"cec2014-f" + std::to_string(id),
                   std::make_shared<Cec2014Problem>(id, kDim),
                   pagmo::problem(pagmo::cec2014(id, kDim)),
                   100.0 * id,
                   0.0,
                   0,
                   {}});
  }
  return out;
}

struct Stats {
  std::vector<double> finals;
  int hits = -1;  ///< runs that hit the known optimum (-1: the problem has no hit test)
  double seconds = 0.0;
  long evaluations = 0;

  double median() const {
    std::vector<double> v = finals;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  }
  double best() const { return *std::min_element(finals.begin(), finals.end()); }
  double worst() const { return *std::max_element(finals.begin(), finals.end()); }
  double nsPerEval() const { return seconds * 1e9 / static_cast<double>(std::max(1L, evaluations)); }
  long evaluationsPerRun() const {
    return evaluations / static_cast<long>(std::max<std::size_t>(1, finals.size()));
  }
};

/// One of our methods: runs it on a problem with a seed and a budget.
struct OurMethod {
  std::string name;
  int populationForBudget = 1;  ///< budget is rounded down to a multiple of this (the peer's NP)
  std::string peer;             ///< pagmo peer method name, or empty
  std::function<optim::Result(const optim::Problem&, std::uint64_t, long)> run;
  long fixedBudget = 0;     ///< > 0: this budget whatever the section's or the problem's
  std::string onlyProblem;  ///< non-empty: run on this problem only
};

template <class Algo>
OurMethod ours(std::string name, int population = 1, std::string peer = {},
               typename Algo::Options preset = {}) {
  return {std::move(name),
          population,
          std::move(peer),
          [preset](const optim::Problem& p, std::uint64_t seed, long budget) {
            typename Algo::Options o = preset;
            o.common.seed = seed;
            o.common.maxEvaluations = budget;
            return Algo(o).optimise(p);
          },
          0,
          {}};
}

struct PeerMethod {
  std::string name;
  unsigned population = 30;
  std::function<pagmo::population(pagmo::population, unsigned gen, unsigned seed)> evolve;
};

Stats runOurs(const BenchProblem& p, const OurMethod& m, int firstSeed, int seeds, long budget) {
  Stats s;
  if (p.budget > 0) budget = p.budget;
  if (m.fixedBudget > 0) budget = m.fixedBudget;
  const long b = std::max(1L, budget / m.populationForBudget * m.populationForBudget);
  for (int seed = firstSeed; seed < firstSeed + seeds; ++seed) {
    const double t0 = threadCpuSeconds();
    const optim::Result r = m.run(*p.ours, static_cast<std::uint64_t>(seed), b);
    s.seconds += threadCpuSeconds() - t0;
    s.finals.push_back(r.bestObjective - p.oursOffset);
    if (p.hit) s.hits = std::max(0, s.hits) + (p.hit(r.bestX) ? 1 : 0);
    s.evaluations += r.run.evaluations;
    g_optimSink = g_optimSink + r.bestObjective;
  }
  return s;
}

Stats runPeer(const BenchProblem& p, const PeerMethod& m, int firstSeed, int seeds, long budget) {
  Stats s;
  if (p.budget > 0) budget = p.budget;
  const unsigned gen = static_cast<unsigned>(std::max(0L, budget / static_cast<long>(m.population) - 1));
  for (int seed = firstSeed; seed < firstSeed + seeds; ++seed) {
    pagmo::problem prob = p.peer;  // fresh copy (fevals 0), made outside the timing
    const double t0 = threadCpuSeconds();
    pagmo::population pop(std::move(prob), m.population, static_cast<unsigned>(seed));
    pop = m.evolve(std::move(pop), gen, static_cast<unsigned>(seed));
    s.seconds += threadCpuSeconds() - t0;
    s.finals.push_back(pop.champion_f()[0] - p.peerOffset);
    if (p.hit) {
      // pagmo's champion snapped to the grid, as its fitness saw it.
      std::vector<double> x = pop.champion_x();
      p.ours->snap(x);
      s.hits = std::max(0, s.hits) + (p.hit(x) ? 1 : 0);
    }
    s.evaluations += static_cast<long>(pop.get_problem().get_fevals());
    g_optimSink = g_optimSink + pop.champion_f()[0];
  }
  return s;
}

nlohmann::json hitRate(const Stats& s) {
  if (s.hits < 0 || s.finals.empty()) return nullptr;
  return static_cast<double>(s.hits) / static_cast<double>(s.finals.size());
}

nlohmann::json nullable(double v, bool present) {
  return present ? nlohmann::json(v) : nlohmann::json(nullptr);
}

}  // namespace

nlohmann::json benchOptimizers(const OptimBenchOptions& options) {
  const int seeds = std::max(1, options.seeds);
  const long budget = std::max(1L, options.budget);
  std::vector<BenchProblem> problems = makeProblems();
  problems.push_back(setupPaperProblem(options.sourceDir));
  const auto wanted = [](const std::vector<std::string>& list, const std::string& name) {
    return list.empty() || std::find(list.begin(), list.end(), name) != list.end();
  };
  std::erase_if(problems, [&](const BenchProblem& p) { return !wanted(options.problems, p.name); });

  const int psoSwarm = optim::Pso::Options{}.swarmSize;
  const int sadeNp = optim::Sade::Options{}.populationSize;
  optim::Sade::Options sadeJde;
  sadeJde.adaptation = optim::Sade::Adaptation::SelfAdaptive;
  optim::Sade::Options sadeShade;
  sadeShade.adaptation = optim::Sade::Adaptation::SuccessHistory;
  std::vector<OurMethod> ourMethods = {
      ours<optim::Sade>("sade", sadeNp, "pagmo-sade"),
      ours<optim::Sade>("sade-jde", sadeNp, "pagmo-sade", sadeJde),
      ours<optim::Sade>("sade-shade", sadeNp, "pagmo-sade", sadeShade),
      ours<optim::Pso>("pso", psoSwarm, "pagmo-pso"),
      ours<optim::Pso>("pso-ring", psoSwarm, "pagmo-pso", optim::Pso::Options::ring()),
      ours<optim::GaSimplex>("ga-simplex"),
      ours<optim::NelderMead>("nelder-mead"),
      ours<optim::Cripso>("cripso"),
      ours<optim::Ga>("ga"),
      ours<optim::Coa>("coa"),
  };
  // COA at the setup paper's own budget for it (100 iterations, ~30000 solutions; the other methods
  // had 5000): the paper's Fig. 16-17 comparison, on its example only.
  OurMethod coaPaper = ours<optim::Coa>("coa-30000");
  coaPaper.fixedBudget = setup::kCoaPaperBudget;
  coaPaper.onlyProblem = "setup-paper";
  ourMethods.push_back(coaPaper);
  std::erase_if(ourMethods, [&](const OurMethod& m) { return !wanted(options.methods, m.name); });
  const std::vector<PeerMethod> peers = {
      {"pagmo-sade", static_cast<unsigned>(sadeNp),
       [](pagmo::population pop, unsigned gen, unsigned seed) {
         // variant 7 = DE/rand/1/bin, variant_adptv 1 = jDE; ftol = xtol = 0: never stop early.
         return pagmo::sade(gen, 7u, 1u, 0.0, 0.0, false, seed).evolve(std::move(pop));
       }},
      {"pagmo-sade-exp", static_cast<unsigned>(sadeNp),
       [](pagmo::population pop, unsigned gen, unsigned seed) {
         // variant 2 = DE/rand/1/exp (pagmo's default variant), jDE.
         return pagmo::sade(gen, 2u, 1u, 0.0, 0.0, false, seed).evolve(std::move(pop));
       }},
      {"pagmo-pso", static_cast<unsigned>(psoSwarm),
       [](pagmo::population pop, unsigned gen, unsigned seed) {
         return pagmo::pso(gen, 0.7298, 2.05, 2.05, 0.5, 5u, 2u, 4u, false, seed).evolve(std::move(pop));
       }},
  };

  std::printf(
      "optimizers: %u-D, budget %ld evaluations per run (a method and its pagmo peer: NP * floor(B/NP)), "
      "%d seeds (%d..%d); objective = error to the known optimum (minimised)\n",
      kDim, budget, seeds, options.firstSeed, options.firstSeed + seeds - 1);
  std::printf("%-14s %-15s %6s %11s %11s %11s %9s   %-11s %11s %9s %7s\n", "problem", "method", "evals",
              "median", "best", "worst", "ns/eval", "peer", "peer median", "peer ns", "ns/peer");

  nlohmann::json rows = nlohmann::json::array(), targets = nlohmann::json::array();
  for (const BenchProblem& p : problems) {
    std::vector<std::pair<std::string, Stats>> peerStats;
    for (const PeerMethod& m : peers)
      peerStats.emplace_back(m.name, runPeer(p, m, options.firstSeed, seeds, budget));
    const auto findPeer = [&](const std::string& name) -> const Stats* {
      for (const auto& [n, s] : peerStats)
        if (n == name) return &s;
      return nullptr;
    };
    for (const OurMethod& m : ourMethods) {
      if (!m.onlyProblem.empty() && m.onlyProblem != p.name) continue;
      const Stats s = runOurs(p, m, options.firstSeed, seeds, budget);
      const Stats* ps = m.peer.empty() ? nullptr : findPeer(m.peer);
      std::printf("%-14s %-15s %6ld %11.4g %11.4g %11.4g %9.1f", p.name.c_str(), m.name.c_str(),
                  s.evaluationsPerRun(), s.median(), s.best(), s.worst(), s.nsPerEval());
      if (ps) {
        std::printf("   %-11s %11.4g %9.1f %7.2f", m.peer.c_str(), ps->median(), ps->nsPerEval(),
                    s.nsPerEval() / ps->nsPerEval());
        const bool qualityMet = s.median() <= ps->median();
        const double ratio = s.nsPerEval() / ps->nsPerEval();
        targets.push_back({{"problem", p.name},
                           {"method", m.name},
                           {"peer", m.peer},
                           {"median_best", s.median()},
                           {"peer_median_best", ps->median()},
                           {"quality_met", qualityMet},
                           {"ns_ratio", ratio},
                           {"speed_met", ratio <= 1.0}});
      }
      if (s.hits >= 0) std::printf("   hits %d/%zu", s.hits, s.finals.size());
      std::printf("\n");
      rows.push_back({{"problem", p.name},
                      {"method", m.name},
                      {"median_best", s.median()},
                      {"best", s.best()},
                      {"worst", s.worst()},
                      {"ns_per_eval", s.nsPerEval()},
                      {"peer", ps ? nlohmann::json(m.peer) : nlohmann::json(nullptr)},
                      {"peer_median_best", nullable(ps ? ps->median() : 0.0, ps != nullptr)},
                      {"peer_ns_per_eval", nullable(ps ? ps->nsPerEval() : 0.0, ps != nullptr)},
                      {"hit_rate", hitRate(s)}});
    }
    for (const auto& [name, s] : peerStats) {
      std::printf("%-14s %-15s %6ld %11.4g %11.4g %11.4g %9.1f", p.name.c_str(), name.c_str(),
                  s.evaluationsPerRun(), s.median(), s.best(), s.worst(), s.nsPerEval());
      if (s.hits >= 0) std::printf("   hits %d/%zu", s.hits, s.finals.size());
      std::printf("\n");
      rows.push_back({{"problem", p.name},
                      {"method", name},
                      {"median_best", s.median()},
                      {"best", s.best()},
                      {"worst", s.worst()},
                      {"ns_per_eval", s.nsPerEval()},
                      {"peer", nullptr},
                      {"peer_median_best", nullptr},
                      {"peer_ns_per_eval", nullptr},
                      {"hit_rate", hitRate(s)}});
    }
  }

  std::printf("targets (median <= peer median at equal budget; ns/eval ratio <= 1.0):\n");
  int missed = 0;
  for (const auto& t : targets) {
    const bool q = t["quality_met"].get<bool>(), sp = t["speed_met"].get<bool>();
    missed += !q + !sp;
    std::printf("  %-14s %-5s vs %-11s median %11.4g vs %11.4g %-6s  ns ratio %5.2f %s\n",
                t["problem"].get<std::string>().c_str(), t["method"].get<std::string>().c_str(),
                t["peer"].get<std::string>().c_str(), t["median_best"].get<double>(),
                t["peer_median_best"].get<double>(), q ? "met" : "MISSED", t["ns_ratio"].get<double>(),
                sp ? "met" : "MISSED");
  }
  std::printf("  %d of %zu target checks missed\n", missed, 2 * targets.size());
  return {{"dimension", kDim}, {"budget", budget},  {"seeds", seeds}, {"first_seed", options.firstSeed},
          {"rows", rows},      {"targets", targets}};
}

}  // namespace metrofit::bench
