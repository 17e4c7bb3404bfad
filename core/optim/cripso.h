#pragma once
// CRIPSO — coral reefs inspired particle swarm optimisation.
// R. Stryczek, "A metaheuristic for fast machining error compensation", J. Intell. Manuf. 27(6),
// 2016, section "Coral reefs inspired particle swarm optimization", Fig. 3-4, Eq. 1,
// Eq. 11 and the settings of the section "Comparison between the proposed CRIPSO and other
// algorithms".
//
// A reef P of |P| stationary polyps (default 100). Every step is a contest between two polyps a, b
// drawn at random (distinct, uniform): the better one (lower objective; a on a tie) wins and stays
// (elitism), the loser is removed and replaced by the winner's planula, settled at (Eq. 1)
//
//   x'_i = x_i + w (plast_i - x_i) + c1 r1_i (pbest_i - x_i) + c2 r2_i (gbest_i - x_i)
//
// with x the winner, r1_i, r2_i ~ U(0,1) drawn per dimension i, w = 0.75 (constant, paper) and
// (Eq. 11)   c1 = c2 = cos(pi/2 * Li / L)
//
// Our reading of Eq. 11: L is the total number of solutions, i.e. the evaluation budget
// (CommonOptions::maxEvaluations), and Li the successive number of the solution being generated,
// i.e. the evaluations done before it (the initial reef included). c falls from ~1 to 0 over the run.
//
// The three directions (paper's rules I-III, Fig. 4) and what each polyp remembers:
//  I.  plast: the last planula the polyp generated. A new polyp has generated none; it inherits the
//      direction of its own settlement: plast(new) = x' + (x' - x_parent), so that w (plast - x')
//      continues the parent -> planula move, scaled by w (a PSO velocity with inertia w).
//      A polyp of the initial reef has no history either; it gets plast = a uniform random point of
//      the box (the analogue of PSO's random initial velocity) — with plast = x the best polyp would
//      only clone itself, since for it pbest = gbest = x.
//  II. pbest: "the descendant of the given polyp which has the best position so far" (nomenclature:
//      "the best planula"), read literally: the best of the planulas the polyp generated, which
//      may be worse than the polyp itself; before its first planula a polyp of the initial reef
//      uses its own position (the term vanishes). The new polyp inherits the parent's pbest ("polyp
//      best is inherited from the parent"), after the parent's pbest took the new planula into
//      account.
//  III. gbest: the best polyp of the reef now (elitism keeps it; it equals the best point evaluated).
// The winner's plast becomes the planula it just generated.
//
// Decision space: a polyp always IS a feasible solution ("each polyp stands for one solution in
// decision space"). A planula that lands outside the box is reflected back into it at the bound it
// crossed (mirror, folded for very long moves), then Tracker::evaluate rounds it to the grid in
// place. The paper does not say how bounds were handled; we reflect rather than clamp because
// clamping piles planulas onto the bound and the contest's strong selection then traps the reef
// there: with clamping, 3 of 200 Rosenbrock-10D runs (bounds [-5, 5], 20,000 evaluations) ended
// with the last variable stuck at +-5 (f = 200-2500); with reflection none did, and the sphere
// results did not change. plast may lie outside the box (it is only a direction).
//
// Known behaviour (measured, see tests/core/optim/cripso_test.cpp): the contest replaces a loser
// with the winner's offspring and, with c <= 1 and r ~ U(0,1), the pbest and gbest terms never
// overshoot their attractors; only the inertia does. The reef therefore contracts fast (the paper:
// "the optimal solution was reached after less than 2,000 iterations"). On continuous problems it
// contracts while still improving and converges to machine precision on the sphere; on a grid the
// contraction freezes once the moves fall below half a step (planulas round back onto their
// parents, the reef fills with clones): on a 10-D grid sphere (step 0.001, [-0.1, 0.1]) it ends
// one or two steps off the grid optimum in most runs, while in 2-D it finds it every time.
//
// Iterations (for the observer and the trace): iteration 0 is the evaluation of the initial reef;
// every following iteration is |P| contests, i.e. |P| evaluations (the paper plots against the
// number of solutions; one iteration = one reef's worth of new polyps). The last iteration may be
// shorter when the budget runs out.
#include <string>

#include "core/optim/algorithm.h"

namespace metrofit::optim {

class Cripso final : public Algorithm {
 public:
  struct Options {
    CommonOptions common;      ///< budget L (paper: 5000), seed, trace
    int populationSize = 100;  ///< |P|, number of polyps (paper: 100); >= 2
    double inertia = 0.75;     ///< w of Eq. 1 (paper: constant 0.75); in [0, 1]

    bool isValid(std::string* why) const;
  };

  Cripso();
  explicit Cripso(Options options);

  const Options& options() const { return options_; }
  std::string name() const override { return "cripso"; }
  /// Throws OptionsError (field "cripso options", with the reason) for invalid options or problem.
  Result optimise(const Problem& problem, Observer* observer = nullptr) const override;

 private:
  Options options_;
};

}  // namespace metrofit::optim
