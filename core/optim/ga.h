#pragma once
// Elitist real-coded genetic algorithm, as R. Stryczek, J. Intell. Manuf. 27(6) 2016,
// section "Comparison ...", used it for comparison: "the variation of GA including the principle of
// elitism, as the winners of the competition qualify to the next population"; population 50,
// probability of gene mutation 0.1. The flow chart it cites (Stryczek 2009) is not in the seed;
// where the text is silent we chose as follows, and say so.
//
// One generation (= one iteration for the observer and the trace):
//  1. Tournament: the population is shuffled and split into pairs; in each pair the better
//     individual (lower objective) wins and qualifies unchanged for the next population (elitism:
//     the best individual always wins its pair, so it is never lost). With an odd population the
//     unpaired individual also qualifies.
//  2. Reproduction: the places of the losers are filled by children. Each child has two distinct
//     parents drawn uniformly from the winners and is made by crossover, then mutation:
//     * Crossover::Intermediate (default; Muehlenbein & Schlierkamp-Voosen 1993, extended
//       intermediate recombination): child_i = p1_i + a_i (p2_i - p1_i), a_i ~ U(-d, 1 + d),
//       d = 0.25, drawn per gene. On a grid the child is rounded to the grid by the tracker.
//     * Crossover::Uniform: child_i = p1_i or p2_i with probability 1/2 each (stays on the grid).
//     * Mutation: each gene mutates with probability pm = 0.1 (paper), by Michalewicz's
//       non-uniform mutation (Michalewicz 1996, b = 5 as there): with t = Li / L (evaluations so far /
//       budget) and r ~ U(0,1),
//         child_i += D(t, upper_i - child_i)  or  child_i -= D(t, child_i - lower_i)   (1/2 each)
//         D(t, y) = y (1 - r^((1 - t)^b)),  b = 5.
//       Early mutations can reach anywhere in the box; late ones are small, which gives the GA its
//       late fine tuning (the paper notes the GA "has a problem with improving" late; this is the
//       standard remedy and keeps the method comparable on continuous benchmarks).
//  3. Every child goes through Tracker::evaluate, which clamps it into the box and snaps it to the
//     grid, so every individual is feasible.
// Iteration 0 evaluates the random initial population; each later generation costs
// (populationSize - winners) evaluations (25 for the default 50).
#include <string>

#include "core/optim/algorithm.h"

namespace metrofit::optim {

class Ga final : public Algorithm {
 public:
  enum class Crossover { Intermediate, Uniform };

  struct Options {
    CommonOptions common;
    int populationSize = 50;           ///< individuals (paper: 50); >= 4
    double mutationProbability = 0.1;  ///< per gene (paper: 0.1); in [0, 1]
    Crossover crossover = Crossover::Intermediate;
    double intermediateExtension = 0.25;  ///< d of the extended intermediate crossover; in [0, 1]
    double mutationShape = 5.0;           ///< b of the non-uniform mutation; > 0

    bool isValid(std::string* why) const;
  };

  Ga();
  explicit Ga(Options options);

  const Options& options() const { return options_; }
  std::string name() const override { return "ga"; }
  /// Throws OptionsError (field "ga options", with the reason) for invalid options or problem.
  Result optimise(const Problem& problem, Observer* observer = nullptr) const override;

 private:
  Options options_;
};

}  // namespace metrofit::optim
