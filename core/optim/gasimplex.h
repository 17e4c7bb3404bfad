#pragma once
// GA-simplex: the comparison method of Jiang 2018, posture adjustment by SADE (L. Jiang et al., Mech. Sci. 9,
// 2018, Section 4.2, "genetic algorithm-simplex (GAs)", after Yan et al. 2004): a genetic algorithm explores
// the box, then the Nelder-Mead simplex (neldermead.h) refines the GA's best point. The paper gives no
// settings for it; this is a standard real-coded GA:
//   * population NP (default 50), generation 0 uniform random feasible points;
//   * binary tournament selection (kTournamentSize = 2) of two parents;
//   * simulated binary crossover, SBX (Deb & Agrawal 1995), with probability crossoverProbability per
//     pair and 1/2 per gene, distribution index eta_c = kSbxEta = 15:
//       beta = (2u)^(1/(eta_c+1)) if u <= 1/2, else (1/(2(1-u)))^(1/(eta_c+1)),  u ~ U[0,1)
//       c1 = ((1+beta) p1 + (1-beta) p2) / 2,  c2 = ((1-beta) p1 + (1+beta) p2) / 2;
//   * polynomial mutation (Deb & Goyal 1996), per gene with probability mutationProbability
//     (0: 1/D), distribution index eta_m = kMutationEta = 20:
//       delta = (2u)^(1/(eta_m+1)) - 1 if u < 1/2, else 1 - (2(1-u))^(1/(eta_m+1)),
//       x <- x + delta (upper - lower);
//   * generational replacement with elitism: the best kElites = 1 individual survives unchanged.
// Children are clamped into the box and snapped onto the grid by the tracker.
//
// Budget split: the GA uses the first floor(gaFraction * maxEvaluations) evaluations (default 80 %,
// it stops in the middle of a generation if need be), then Nelder-Mead starts from the best point
// found (not evaluated again) with an initial simplex of simplexStep times each range and uses the
// rest (20 %); it may end earlier when the simplex converges (simplexTolerance, Termination::Converged).
// Trace: the GA's generations (entry 0 = initial population), then the simplex iterations (its initial
// simplex is one entry), all through one tracker.
#include <string>

#include "core/optim/algorithm.h"

namespace metrofit::optim {

class GaSimplex final : public Algorithm {
 public:
  static constexpr int kTournamentSize = 2;
  static constexpr int kElites = 1;
  static constexpr double kSbxEta = 15.0;
  static constexpr double kMutationEta = 20.0;

  struct Options {
    CommonOptions common;
    int populationSize = 50;            ///< NP of the GA, >= 2
    double crossoverProbability = 0.9;  ///< per pair of parents, [0, 1]
    double mutationProbability = 0.0;   ///< per gene, [0, 1]; 0: 1 / dimension
    double gaFraction = 0.8;            ///< share of the budget for the GA, (0, 1]; the rest for the simplex
    double simplexStep = 0.05;          ///< Nelder-Mead initial step, fraction of each range, (0, 1]
    double simplexTolerance = 1e-8;     ///< Nelder-Mead tolerance (see neldermead.h), >= 0

    bool isValid(std::string* why) const;
  };

  GaSimplex() = default;
  explicit GaSimplex(Options options) : options_(std::move(options)) {}

  std::string name() const override { return "ga-simplex"; }
  const Options& options() const { return options_; }
  Result optimise(const Problem& problem, Observer* observer = nullptr) const override;

  /// Evaluations given to the GA: floor(gaFraction * maxEvaluations), at least 1.
  long gaBudget() const;

 private:
  Options options_;
};

}  // namespace metrofit::optim
