#include "core/study/setup_validation.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <Eigen/SVD>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

#include "core/common/error.h"
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

ShareEstimate estimateSetupShare(const Model& model, const std::vector<std::vector<double>>& sets) {
  const Eigen::MatrixXd G = gainMatrix(model);
  const auto n = static_cast<std::size_t>(G.rows());
  // The column space of G from its SVD: setup data that act alike (a work offset and a tool offset on
  // the same dimensions) make G rank deficient, and n - k must count the independent ones only.
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(G, Eigen::ComputeThinU);
  const Eigen::VectorXd& sv = svd.singularValues();
  std::size_t k = 0;
  for (Eigen::Index i = 0; i < sv.size(); ++i)
    if (sv(i) > 1e-9 * std::max(1.0, sv(0))) ++k;
  const Eigen::MatrixXd U = svd.matrixU().leftCols(static_cast<Eigen::Index>(k));
  if (n <= k)
    throw OptionsError(ErrorContext{model.name, 0, 0, "dimensions"},
                       "the share of the setup data needs more dimensions (" + std::to_string(n) +
                           ") than independent setup data (" + std::to_string(k) + ")");
  ShareEstimate est;
  double rss = 0.0, total = 0.0;
  for (const auto& e : sets) {
    if (e.size() != n)
      throw OptionsError(ErrorContext{model.name, 0, 0, "deviations"},
                         "a deviation set has " + std::to_string(e.size()) + " values for " +
                             std::to_string(n) + " dimensions");
    const Eigen::Map<const Eigen::VectorXd> v(e.data(), static_cast<Eigen::Index>(n));
    rss += (v - U * (U.transpose() * v)).squaredNorm();
    total += v.squaredNorm();
    ++est.sets;
  }
  if (est.sets == 0) return est;
  const double m = static_cast<double>(est.sets);
  const double w2sq = 3.0 * rss / (m * static_cast<double>(n - k));
  const double g2 = G.squaredNorm();
  const double w1sq = g2 > 0.0 ? std::max(0.0, (3.0 * total / m - static_cast<double>(n) * w2sq) / g2) : 0.0;
  est.w1Mm = std::sqrt(w1sq);
  est.w2Mm = std::sqrt(w2sq);
  est.weightShare = est.w1Mm + est.w2Mm > 0.0 ? est.w1Mm / (est.w1Mm + est.w2Mm) : 0.0;
  const double setupVar = w1sq * g2, randomVar = static_cast<double>(n) * w2sq;
  est.varianceShare = setupVar + randomVar > 0.0 ? setupVar / (setupVar + randomVar) : 0.0;
  return est;
}

std::vector<std::vector<double>> partDeviationSets(const Model& model, const Measurements& meas) {
  const std::size_t n = model.dimensions.size();
  std::map<std::string, std::pair<std::vector<double>, std::vector<int>>> byPart;
  for (const auto& row : meas.rows) {
    auto& [sum, count] = byPart[row.part];
    if (sum.empty()) {
      sum.assign(n, 0.0);
      count.assign(n, 0);
    }
    sum[row.dimension] += row.deviationMm;
    ++count[row.dimension];
  }
  std::vector<std::vector<double>> sets;
  for (const std::string& part : meas.parts) {
    const auto it = byPart.find(part);
    if (it == byPart.end()) continue;
    auto [sum, count] = it->second;
    if (std::find(count.begin(), count.end(), 0) != count.end()) continue;
    for (std::size_t q = 0; q < n; ++q) sum[q] /= count[q];
    sets.push_back(std::move(sum));
  }
  if (sets.empty() && meas.deviationMm.size() == n) sets.push_back(meas.deviationMm);
  return sets;
}

double foreseenF1(const ValidationResult& result, double f1Before) {
  const double n = static_cast<double>(result.sets.size());
  double sx = 0.0, sy = 0.0;
  for (const ValidationSet& s : result.sets) {
    sx += s.f1Before;
    sy += s.exactF1;
  }
  if (result.sets.size() < 2) return std::nan("");
  const double mx = sx / n, my = sy / n;
  double sxx = 0.0, sxy = 0.0;
  for (const ValidationSet& s : result.sets) {
    sxx += (s.f1Before - mx) * (s.f1Before - mx);
    sxy += (s.f1Before - mx) * (s.exactF1 - my);
  }
  if (!(sxx > 0.0)) return std::nan("");
  return my + sxy / sxx * (f1Before - mx);
}

ValidationSummary summarizeValidation(const Model& model, const ValidationOptions& options,
                                      const ValidationResult& result) {
  ValidationSummary sum;
  sum.sets = result.sets.size();
  for (const std::string& m : options.methods) sum.methods.push_back(ValidationMethodSummary{m});
  std::vector<std::vector<double>> deviations;
  for (std::size_t i = 0; i < result.sets.size(); ++i) {
    const ValidationSet& s = result.sets[i];
    sum.f1BeforeMin = i == 0 ? s.f1Before : std::min(sum.f1BeforeMin, s.f1Before);
    sum.f1BeforeMax = i == 0 ? s.f1Before : std::max(sum.f1BeforeMax, s.f1Before);
    sum.f1BeforeMean += s.f1Before;
    sum.exactF1Mean += s.exactF1;
    sum.bonusMean += s.exactF1 - s.f1Before;
    if (s.exactProven) ++sum.exactProven;
    for (const ValidationTrial& t : s.trials) {
      for (ValidationMethodSummary& m : sum.methods) {
        if (m.method != t.method) continue;
        ++m.trials;
        m.meanF1 += t.f1;
        m.meanGapF1 += t.gapF1;
        m.maxGapF1 = std::max(m.maxGapF1, t.gapF1);
        if (t.gapF1 <= model.stepMm + 1e-9) ++m.withinStep;
      }
    }
    deviations.push_back(simulateSetupSet(model, options.simulation, s.index).deviationMm);
  }
  if (sum.sets > 0) {
    const double n = static_cast<double>(sum.sets);
    sum.f1BeforeMean /= n;
    sum.exactF1Mean /= n;
    sum.bonusMean /= n;
  }
  for (ValidationMethodSummary& m : sum.methods) {
    if (m.trials == 0) continue;
    m.meanF1 /= static_cast<double>(m.trials);
    m.meanGapF1 /= static_cast<double>(m.trials);
  }
  sum.paperRangeApplies = std::abs(options.simulation.w1 - kPaperW1Mm) < 1e-12 &&
                          std::abs(options.simulation.w2 - kPaperW2Mm) < 1e-12 && sum.sets > 0;
  if (sum.paperRangeApplies) {
    std::vector<double> mins, maxs;
    for (int b = 0; b < kPaperRangeReplicates; ++b) {
      SetupSimOptions sim = options.simulation;
      sim.seed = trialSeed(options.simulation.seed, static_cast<std::size_t>(b), 1000003, 0);
      double lo = 0.0, hi = 0.0;
      for (std::size_t j = 0; j < kPaperSets; ++j) {
        const double f = SetupInstance(model, simulateSetupSet(model, sim, j).deviationMm).f1Before();
        lo = j == 0 ? f : std::min(lo, f);
        hi = j == 0 ? f : std::max(hi, f);
      }
      mins.push_back(lo);
      maxs.push_back(hi);
    }
    std::sort(mins.begin(), mins.end());
    std::sort(maxs.begin(), maxs.end());
    auto quantile = [](const std::vector<double>& v, double p) {
      const double pos = p * static_cast<double>(v.size() - 1);
      const auto i = static_cast<std::size_t>(pos);
      const double frac = pos - static_cast<double>(i);
      return i + 1 < v.size() ? v[i] + frac * (v[i + 1] - v[i]) : v[i];
    };
    sum.minBandLo = quantile(mins, 0.01);
    sum.minBandHi = quantile(mins, 0.99);
    sum.maxBandLo = quantile(maxs, 0.01);
    sum.maxBandHi = quantile(maxs, 0.99);
    sum.paperRangeConsistent = kPaperF1BeforeMinMm >= sum.minBandLo && kPaperF1BeforeMinMm <= sum.minBandHi &&
                               kPaperF1BeforeMaxMm >= sum.maxBandLo && kPaperF1BeforeMaxMm <= sum.maxBandHi;
  }
  if (!deviations.empty()) sum.share = estimateSetupShare(model, deviations);
  return sum;
}

}  // namespace metrofit::setup
