#pragma once
// SADE: the self-adaptive differential evolution of Jiang 2018 (L. Jiang et al., "Posture adjustment
// of workpiece based on stepwise matching by self-adaptive differential evolution algorithm",
// Mech. Sci. 9, 2018, Section 2.3.2), used there for the fine matching of probed point sets.
//
// Scheme: DE/rand/1/bin (Storn & Price 1997) with a population of NP vectors x_i (minimisation):
//   mutation   v_i = x_r1 + F(G) (x_r2 - x_r3),   r1, r2, r3 distinct, all != i, drawn uniformly
//   crossover  u_ij = v_ij if rand_j < CR(G) or j == j_rand, else x_ij          (binomial)
//   selection  x_i <- u_i if f(u_i) <= f(x_i)                                   (generational:
//              every mutant of generation G is built from the population of generation G-1)
// with the paper's generation-dependent operators, G = 1 .. Gm the current generation:
//   Eq. (10)  F(G)  = F0 * 2^lambda,  lambda = exp(1 - Gm / (Gm + 1 - G))
//   Eq. (11)  CR(G) = CRmin + G (CRmax - CRmin) / Gm
// F(1) = 2 F0 and F(Gm) = F0 * 2^(e^(1-Gm)) ~ F0: large steps (diversity) early, small late; CR
// rises linearly so that early generations keep diversity and late ones refine (the paper's text).
//
// Reading of Eq. (10): the extracted text "F = 2 e^{1 - Gm/(Gm+1-G)} F0" has lost its superscripts.
// Read as a product (F = 2 F0 e^(...)) it gives F(Gm) = 2 F0 e^(1-Gm) ~ 0, which contradicts the
// paper's own sentence that F starts at 2 F0 and "is close to F0 at the end"; the nested exponent
// F0 * 2^(e^(...)) (the usual adaptive mutation operator of the DE literature the paper cites) gives
// exactly that, so it is what is implemented. Both readings agree at G = 1 (F = 2 F0).
//
// Parameters (paper, Section 4.2): NP = 30 (5D-10D), F0 in [0.25, 0.4], Gm in [100, 500]. The paper
// does not state CRmin / CRmax; the defaults 0.1 / 0.9 are the conventional DE extremes (low CR:
// separable, diverse search; high CR: rotation-invariant refinement).
//
// Run length: the schedule uses Gm; the run stops after generation Gm (Termination::MaxIterations)
// or when the evaluation budget common.maxEvaluations is used up (BudgetExhausted, possibly in the
// middle of a generation), whichever comes first. maxGenerations = 0 derives Gm from the budget,
// Gm = ceil((maxEvaluations - NP) / NP), so that the schedule spans exactly the budget.
// Generation 0 is the random initial population (NP evaluations); the trace and the observer see
// one entry per generation: entry k is generation G = k.
//
// Bounds: a mutant coordinate outside [lower, upper] is moved to a uniform random point between the
// base vector x_r1 and the violated bound (bounce-back, keeps the search direction and the
// distribution inside the box); the tracker then snaps it onto the grid, if any.
//
// Adaptation::SelfAdaptive — beyond the paper (its title says "self-adaptive", its operators are a
// fixed schedule): jDE, Brest et al., IEEE TEC 10(6) 2006, the scheme pagmo2's sade uses by
// default. Every individual i carries its own F_i and CR_i, drawn at the start from U(0.1, 1) and
// U(0, 1). A trial for i uses F' = U(0.1, 1) with probability 0.1, else F_i, and CR' = U(0, 1) with
// probability 0.1, else CR_i; F' and CR' survive with the trial. In this mode a trial replaces its
// target as soon as it is not worse (steady state: later trials of the same generation already see
// it) and a mutant coordinate outside the box is re-drawn uniformly inside it. Gm only sets the run
// length here.
//
// Adaptation::SuccessHistory — beyond the paper: SHADE, Tanabe & Fukunaga, IEEE CEC 2013 (the line
// of DE that won CEC 2014 as L-SHADE). Mutation current-to-pbest/1 with an archive:
//   v_i = x_i + F_i (x_pbest - x_i) + F_i (x_r1 - x~_r2),
// x_pbest drawn from the best max(2, round(p NP)) vectors, p ~ U[2/NP, 0.2]; x_r1 from the
// population, x~_r2 from the population and the archive of replaced parents (at most NP, a random
// entry is overwritten when full); binomial crossover; a coordinate outside the box is set to the
// midpoint between the target's coordinate and the violated bound; generational selection. F_i ~
// Cauchy(M_F[k], 0.1) (re-drawn while <= 0, cut at 1), CR_i ~ N(M_CR[k], 0.1) clipped to [0, 1], k
// a random slot of a history of H = 6 (L-SHADE's H); after each generation one slot (round robin)
// takes the improvement-weighted Lehmer mean of the successful F and the weighted mean of their CR.
// Two additions, both measured on metrofit-bench --optimizers: (1) CR_i >= 0.5 during the first
// quarter of the budget (the floor of jSO, Brest et al. CEC 2017, who use 0.7 / 0.6 for the first
// quarter / half): without it CR drifts to ~0 on rotated problems (coordinate-wise search) and CEC
// f6 stalls; (2) a restart when the population has collapsed (fitness range <= 1e-8 of |best|): a
// fresh random population and history take the rest of the budget, the best point found so far is
// kept by the tracker (CEC f4's trap at 34.78 is left on a second attempt). Gm only limits the run
// length. metrofit-bench --optimizers compares all three modes with pagmo2's sade at equal budget.
#include <string>

#include "core/optim/algorithm.h"

namespace metrofit::optim {

class Sade final : public Algorithm {
 public:
  /// How F and CR change: the paper's generation schedule (Eq. 10-11, the default), jDE
  /// per-individual self-adaptation, or SHADE success history (both beyond the paper, see above).
  enum class Adaptation { Schedule, SelfAdaptive, SuccessHistory };

  struct Options {
    CommonOptions common;
    Adaptation adaptation = Adaptation::Schedule;
    int populationSize = 30;  ///< NP (>= 4: DE/rand/1 needs three partners besides the target)
    double f0 = 0.3;          ///< F0 of Eq. (10), in (0, 1]; F runs from 2 F0 down to ~F0
    int maxGenerations = 0;   ///< Gm of Eq. (10)-(11), >= 1; 0: derived from the budget (see above)
    double crMin = 0.1;       ///< CRmin of Eq. (11), in [0, 1]
    double crMax = 0.9;       ///< CRmax of Eq. (11), in [CRmin, 1]

    bool isValid(std::string* why) const;
    /// Gm actually used: maxGenerations, or derived from the budget when it is 0.
    long effectiveMaxGenerations() const;
  };

  Sade() = default;
  explicit Sade(Options options) : options_(std::move(options)) {}

  std::string name() const override { return "sade"; }
  const Options& options() const { return options_; }
  Result optimise(const Problem& problem, Observer* observer = nullptr) const override;

  /// Eq. (10): F at generation g (1 <= g <= gm) = f0 * 2^(exp(1 - gm / (gm + 1 - g))).
  static double mutationFactor(double f0, long g, long gm);
  /// Eq. (11): CR at generation g = crMin + g (crMax - crMin) / gm.
  static double crossoverRate(double crMin, double crMax, long g, long gm);

 private:
  Options options_;
};

}  // namespace metrofit::optim
