#include "core/setup/validation.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

#include "core/setup/exact.h"
#include "core/setup/objective.h"

namespace metrofit::setup {

bool ValidationOptions::isValid(std::string* why) const {
  auto no = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (sets < 1 || sets > 1000000) return no("the number of sets must be in 1..1000000");
  if (trials < 0 || trials > 100000) return no("the number of trials must be in 0..100000");
  if (budget < 1) return no("the budget must be positive");
  if (threads < 0 || threads > 1024) return no("threads must be in 0..1024");
  const auto names = setupMetaheuristicNames();
  for (const auto& m : methods)
    if (std::find(names.begin(), names.end(), m) == names.end()) return no("unknown method '" + m + "'");
  std::string simWhy;
  if (!simulation.isValid(&simWhy)) return no(simWhy);
  return true;
}

std::vector<std::size_t> ValidationResult::sortedByBefore() const {
  std::vector<std::size_t> order(sets.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return sets[a].f1Before < sets[b].f1Before; });
  return order;
}

std::uint64_t trialSeed(std::uint64_t seed, std::size_t set, std::size_t method, int trial) {
  std::uint64_t h = seed;
  h ^= 0x9E3779B97F4A7C15ULL * (static_cast<std::uint64_t>(set) + 1);
  h = (h ^ (h >> 31)) * 0xBF58476D1CE4E5B9ULL;
  h ^= 0xC2B2AE3D27D4EB4FULL * (static_cast<std::uint64_t>(method) + 1);
  h = (h ^ (h >> 29)) * 0x94D049BB133111EBULL;
  h ^= 0x165667B19E3779F9ULL * (static_cast<std::uint64_t>(trial) + 1);
  return h ^ (h >> 32);
}

ValidationResult runValidation(const Model& model, const ValidationOptions& options, CancelToken* cancel,
                               const std::function<void(std::size_t, std::size_t)>& progress) {
  requireValid(options, "validation options");
  validateModel(model);
  std::vector<ValidationSet> done(options.sets);
  std::vector<char> complete(options.sets, 0);
  std::atomic<std::size_t> next{0};
  std::size_t finished = 0;
  std::mutex mutex;
  std::exception_ptr failure;
  std::atomic<bool> abort{false};

  auto work = [&] {
    try {
      for (;;) {
        if (abort || (cancel && cancel->isCancelled())) break;
        const std::size_t j = next.fetch_add(1);
        if (j >= options.sets) break;
        const SetupMeasurementSet data = simulateSetupSet(model, options.simulation, j);
        const SetupInstance inst(model, data.deviationMm);
        ValidationSet s;
        s.index = j;
        s.f1Before = inst.f1Before();
        ExactOptions eo;
        eo.keepTrace = false;
        const ExactResult exact = solveExact(inst, eo);
        s.exactF1 = exact.score.f1;
        s.exactF2 = exact.score.f2;
        s.exactProven = exact.certificate.f1Optimal && exact.certificate.f2Optimal;
        const SetupProblem problem(inst);
        bool stopped = false;
        for (std::size_t m = 0; m < options.methods.size() && !stopped; ++m) {
          for (int t = 0; t < options.trials; ++t) {
            if (cancel && cancel->isCancelled()) {
              stopped = true;
              break;
            }
            ValidationTrial trial;
            trial.method = options.methods[m];
            trial.trial = t;
            trial.seed = trialSeed(options.seed, j, m, t);
            const auto algorithm = makeSetupAlgorithm(trial.method, options.budget, trial.seed, false);
            const optim::Result r = algorithm->optimise(problem, cancel);
            if (r.run.termination == Termination::Cancelled) {
              stopped = true;
              break;
            }
            const SetupScore sc = inst.score(r.bestX);
            trial.f1 = sc.f1;
            trial.f2 = sc.f2;
            trial.f = sc.f;
            trial.gapF1 = s.exactF1 - sc.f1;
            s.trials.push_back(trial);
          }
        }
        if (stopped) break;
        std::lock_guard<std::mutex> lock(mutex);
        done[j] = std::move(s);
        complete[j] = 1;
        ++finished;
        if (progress) progress(finished, options.sets);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!failure) failure = std::current_exception();
      abort = true;
    }
    releaseExactSolverThread();
  };

  int threads = options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::clamp(threads, 1, static_cast<int>(std::min<std::size_t>(options.sets, 1024)));
  // Worker threads only: each frees its own GLPK environment at the end (exact.h); the calling
  // thread's GLPK state is left alone.
  std::vector<std::thread> pool;
  for (int i = 0; i < threads; ++i) pool.emplace_back(work);
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);

  ValidationResult result;
  result.cancelled = cancel && cancel->isCancelled();
  for (std::size_t j = 0; j < options.sets; ++j)
    if (complete[j]) result.sets.push_back(std::move(done[j]));
  return result;
}

}  // namespace metrofit::setup
