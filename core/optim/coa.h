#pragma once
// Cuckoo optimisation algorithm (COA): R. Rajabioun, "Cuckoo optimization algorithm", Applied Soft
// Computing 11 (2011) 5508-5518, with the settings R. Stryczek, J. Intell. Manuf. 27(6) 2016
// (Stryczek 2016, fast machining error compensation), section "Comparison ...", found best for the setup
// problem: at most 40 habitats, 5-10 eggs per cuckoo. Not to be confused with Yang & Deb's cuckoo search
// (Levy flights).
//
// Population: cuckoos, each at a habitat x (a feasible point) with its objective f (minimised;
// Rajabioun maximises the profit -f). Iteration 0 evaluates initialPopulation random habitats.
// One iteration (one "egg laying + immigration" cycle of Rajabioun's flow chart) then does:
//  1. Egg laying. Cuckoo k lays E_k ~ U{minEggs..maxEggs} eggs (Stryczek 2016: 5-10) within its egg
//     laying radius (Rajabioun's ELR formula)
//        ELR_k = alpha * E_k / sum_j E_j * (varhi - varlow),
//     per variable i: ELR_k,i = alpha E_k / sum E * (upper_i - lower_i). Our reading of "lays eggs
//     randomly within her ELR" in n dimensions: egg = x_k + rho * ELR_k (.) u, with u a uniform
//     random unit direction (normalised Gaussian vector, in coordinates scaled by the ranges) and
//     rho ~ U(0, 1) — the radius uniform in [0, ELR] as in Rajabioun's reference code, which puts
//     more eggs near the habitat than a uniform ball would. Every egg is evaluated (Tracker snaps it
//     onto the box / grid). alpha ("an integer that handles the maximum ELR") is not given for the
//     setup problem; we take alpha = 1: with 40 cuckoos an egg lands within about 1/40 of the
//     range (5 grid steps on [-0.1, 0.1] at 0.001), and of 1, 2 and 5 it refined best on the
//     10-D sphere.
//  2. The eggs least like the host's are found and killed: the worst killFraction (paper: 10 %) of
//     this iteration's eggs, by objective.
//  3. The surviving eggs hatch and grow into cuckoos; parents and young together are capped at
//     maxPopulation (Stryczek 2016: 40): the worst are killed.
//  4. Immigration. The cuckoos are grouped by k-means (k = clusters, paper: 3-5; Lloyd's algorithm
//     with k-means++ seeding from the run's Rng, in range-scaled coordinates). The group with the
//     best mean objective is the goal group, its best habitat the goal point. Every cuckoo except
//     the best of the population (which "lives longer", as in Rajabioun's code; elitism) flies
//     towards the goal:
//       Immigration::DeviationAngle (default; Rajabioun's immigration figure and text): it flies
//         lambda of the way, lambda ~ U(0, motionCoefficient) (paper: U(0,1), motionCoefficient = 1), with a
//         deviation phi ~ U(-omega, omega), omega = pi/6: the step lambda * (goal - x) is rotated
//         by phi in a random plane containing it (n-D reading of the 2-D figure):
//           x <- x + lambda (cos(phi) d + sin(phi) |d| e),  d = goal - x,  e a random unit vector
//           orthogonal to d (in range-scaled coordinates).
//       Immigration::PerDimension (Rajabioun's MATLAB code): x_i <- x_i + F_i (goal_i - x_i),
//         F_i ~ U(0, motionCoefficient) per dimension (the code's default motionCoeff is 2).
//     The new habitat is evaluated (snapped onto the box / grid).
// An iteration thus costs about sum_k E_k + (population - 1) evaluations (~340 with the defaults;
// Stryczek 2016: "100 iterations correspond to approximately 30,000 solutions"). When the budget runs
// out mid-iteration the iteration ends there.
#include <numbers>
#include <string>

#include "core/optim/algorithm.h"

namespace metrofit::optim {

class Coa final : public Algorithm {
 public:
  enum class Immigration { DeviationAngle, PerDimension };

  struct Options {
    CommonOptions common;
    int initialPopulation = 40;      ///< habitats evaluated at the start; >= 2
    int maxPopulation = 40;          ///< cap on living cuckoos (Stryczek 2016: 40); >= 2
    int minEggs = 5;                 ///< eggs per cuckoo, lower bound (Stryczek 2016: 5); >= 1
    int maxEggs = 10;                ///< eggs per cuckoo, upper bound (Stryczek 2016: 10); >= minEggs
    double radiusCoefficient = 1.0;  ///< alpha of the egg laying radius; > 0
    double killFraction = 0.1;       ///< share of eggs killed each iteration (paper: 10 %); [0, 1)
    int clusters = 3;                ///< k of the k-means grouping (paper: 3-5); >= 1
    Immigration immigration = Immigration::DeviationAngle;
    double motionCoefficient = 1.0;                  ///< upper bound of lambda (or F); in (0, 2]
    double deviationAngle = std::numbers::pi / 6.0;  ///< omega in radians (paper: pi/6); [0, pi/2]

    bool isValid(std::string* why) const;
  };

  Coa();
  explicit Coa(Options options);

  const Options& options() const { return options_; }
  std::string name() const override { return "coa"; }
  /// Throws OptionsError (field "coa options", with the reason) for invalid options or problem.
  Result optimise(const Problem& problem, Observer* observer = nullptr) const override;

 private:
  Options options_;
};

}  // namespace metrofit::optim
