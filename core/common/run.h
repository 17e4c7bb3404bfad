#pragma once
// The conventions every iterative method in Metrofit follows (STYLE.md §3-5).
//
//  * Options: a plain struct with defaults and `bool isValid(std::string* why) const`.
//    `requireValid(options)` turns a "no" into an OptionsError. Nobody re-invents defaults.
//  * Observer: called after every iteration with an IterationSummary; returns Continue or Stop.
//    Progress bars, live convergence charts, cancellation and the stored trace hang off it.
//  * RunInfo: part of every Result — why the run ended, a message, iterations, evaluations, trace.
//  * Seeds: every stochastic method takes `std::uint64_t seed` in its Options; see rng.h.
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/common/error.h"

namespace metrofit {

/// Why an iterative run ended.
enum class Termination {
  Converged,        ///< the method's own convergence test was met
  BudgetExhausted,  ///< the evaluation budget was used up
  MaxIterations,    ///< the iteration limit was reached
  Cancelled,        ///< an observer asked to stop
  Failed,           ///< numerical failure (message says why)
};

const char* toString(Termination t);

/// A named scalar reported with an iteration, e.g. {"f1", 0.071}.
struct NamedValue {
  std::string name;
  double value = 0.0;
};

/// What an iterative method reports after every iteration.
struct IterationSummary {
  long iteration = 0;                  ///< 0-based iteration (generation) index
  long evaluations = 0;                ///< objective evaluations so far
  double best = 0.0;                   ///< best objective so far (method's own sense, see Result)
  std::vector<NamedValue> components;  ///< e.g. f1, f2 for the setup problem
  std::vector<double> bestX;           ///< best decision vector so far (may be empty if large)
  double progress = -1.0;              ///< fraction done in [0,1], or -1 if unknown
};

enum class ObserverDecision { Continue, Stop };

/// Observer of an iterative run. Implementations must be cheap; they run on the worker thread.
class Observer {
 public:
  virtual ~Observer() = default;
  virtual ObserverDecision onIteration(const IterationSummary& summary) = 0;
};

/// Adapts any callable `ObserverDecision(const IterationSummary&)` (or returning void) to Observer.
class FunctionObserver final : public Observer {
 public:
  using Fn = std::function<ObserverDecision(const IterationSummary&)>;
  explicit FunctionObserver(Fn fn) : fn_(std::move(fn)) {}
  ObserverDecision onIteration(const IterationSummary& s) override {
    return fn_ ? fn_(s) : ObserverDecision::Continue;
  }

 private:
  Fn fn_;
};

/// A cancellation flag another thread may raise; an observer that stops once it is raised.
class CancelToken final : public Observer {
 public:
  void cancel() noexcept { cancelled_.store(true, std::memory_order_relaxed); }
  bool isCancelled() const noexcept { return cancelled_.load(std::memory_order_relaxed); }
  ObserverDecision onIteration(const IterationSummary&) override {
    return isCancelled() ? ObserverDecision::Stop : ObserverDecision::Continue;
  }

 private:
  std::atomic<bool> cancelled_{false};
};

/// How a run ended plus its trace. Every method's Result has one (`Result::run`).
struct RunInfo {
  Termination termination = Termination::Converged;
  std::string message;
  long iterations = 0;
  long evaluations = 0;
  std::vector<IterationSummary> trace;  ///< one entry per iteration when Options::keepTrace
};

/// Calls the observer (if any), appends to the trace (if asked) and returns true when the run
/// must stop. Methods use this so that all of them treat observers and traces alike.
inline bool notify(Observer* observer, RunInfo& run, const IterationSummary& s, bool keepTrace) {
  run.iterations = s.iteration + 1;
  run.evaluations = s.evaluations;
  if (keepTrace) run.trace.push_back(s);
  if (observer && observer->onIteration(s) == ObserverDecision::Stop) {
    run.termination = Termination::Cancelled;
    run.message = "stopped by observer";
    return true;
  }
  return false;
}

/// Throws OptionsError naming `what` (e.g. "pso options") when options.isValid() says no.
template <class Options>
void requireValid(const Options& options, const std::string& what) {
  std::string why;
  if (!options.isValid(&why)) throw OptionsError(ErrorContext{{}, 0, 0, what}, why);
}

}  // namespace metrofit
