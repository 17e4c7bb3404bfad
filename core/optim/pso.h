#pragma once
// Particle swarm optimisation, the classic Kennedy & Eberhart (1995) swarm with an inertia weight
// (Shi & Eberhart 1998), in the two forms our seed papers used it:
//
//   v_i <- w v_i + c1 r1_i (pbest_i - x_i) + c2 r2_i (gbest_i - x_i)     (Abdulshahed 2016 Eq. 2.7)
//   x_i <- x_i + v_i                                                      (Abdulshahed 2016 Eq. 2.8)
//
// r1_i, r2_i ~ U(0,1) drawn per particle and per dimension i (Abdulshahed 2016 writes one symbol R; the
// per-dimension draw is the usual reading and the one of Kennedy & Eberhart).
//
// (a) Options::stryczek2016() — the default. R. Stryczek, J. Intell. Manuf. 27(6) 2016,
//     section "Comparison ...": "the basic pattern of PSO", 100 particles, "globally the best
//     position of a particle was updated each time after generating a new solution" — i.e. the
//     ASYNCHRONOUS swarm: particles move one after the other and each sees the gbest that includes
//     the moves before it. "c1 and c2 were calculated identically as in CRIPSO": c1 = c2 =
//     cos(pi/2 * Li / L) (Stryczek 2016 Eq. 11; Li = evaluations so far, L = budget). The paper does not
//     give w for PSO; we take CRIPSO's constant 0.75.
// (b) Options::abdulshahed2016() — A. M. Abdulshahed et al., J. Manuf. Syst. 41, 2016,
//     Eq. 2.7-2.8 and section 3: 90 particles, c1 = 1.5, c2 = 2, w decreasing linearly from 0.9 to
//     0.4 with the iteration index; SYNCHRONOUS swarm: all particles move with the gbest of the
//     previous iteration, then pbest and gbest are updated.
//
// Schedules: with s = Li / L in [0, 1) (evaluations before the move / budget; for the synchronous
// swarm taken at the start of the iteration, so it is the same for the whole sweep and linear in
// the iteration index k: s = (k * M) / L for a swarm of M particles)
//   w(s) = inertiaStart + (inertiaEnd - inertiaStart) s
//   c1(s) = c1 * g(s), c2(s) = c2 * g(s), g(s) = 1 (Constant) or cos(pi/2 s) (Cosine, Eq. 11).
//
// Velocity clamping (neither paper states one; Eberhart & Shi's Vmax): |v_i| <= maxVelocity *
// (upper_i - lower_i), default 0.5 of the range (pagmo's default). Initial velocities are uniform
// in [-Vmax_i, Vmax_i] (Abdulshahed 2016: "randomly initialised by uniformly distributed variables"),
// initial positions uniform in the box.
// Bounds and grid: the moved position goes through Tracker::evaluate, which clamps it into the box
// and rounds it to the grid in place; the particle lives on at the snapped point. A component that
// had left the box gets v_i = 0 (absorbing wall), so that the particle does not keep pushing into it.
//
// (c) Options::ring() — beyond the papers: the local-best ("lbest") swarm of Kennedy & Mendes
//     (2002): particles sit on a ring and each follows the best pbest among itself and its
//     `neighbours` nearest particles on each side instead of the swarm's gbest (information spreads
//     slowly, so the swarm explores longer), with Clerc & Kennedy's (2002) constriction values as
//     inertia form, w = 0.7298, c1 = c2 = 1.49618, scaled by Stryczek 2016's cosine schedule, updated
//     asynchronously like (a). It is the library's general-purpose PSO; metrofit-bench --optimizers
//     measures all three presets against pagmo2's pso (which is also an lbest swarm by default).
//     Swarm size 60 (not the papers' 100): at the bench budget of 10^4 evaluations a particle
//     moves 166 instead of 100 times. Measured with 101 seeds (1-101 and 1001-1101) on the bench's
//     six 10-D problems: every median better than with 100 particles, e.g. CEC f4 8.4 / 6.9 (100:
//     9.7) against pagmo's pso 11.5 / 14.5, f10 224 / 238 against 261 / 265; 40-50 particles lose
//     on f10, 70-80 on f4.
//     With neighbours > 0, the guide of particle k is read when k moves, so in the asynchronous
//     swarm it includes every move before it; in the synchronous swarm it is taken from the
//     pbests of the previous iteration.
//
// Iterations: iteration 0 evaluates the initial swarm; every following iteration moves each
// particle once (M evaluations; the last one may be cut short by the budget).
#include <string>

#include "core/optim/algorithm.h"

namespace metrofit::optim {

class Pso final : public Algorithm {
 public:
  /// When gbest is updated: after every particle (Stryczek 2016) or after the whole sweep (Abdulshahed 2016).
  enum class Update { Asynchronous, Synchronous };
  /// How c1 and c2 change over the run: constant, or scaled by cos(pi/2 * Li/L) (Stryczek 2016 Eq. 11).
  enum class Acceleration { Constant, Cosine };

  struct Options {
    CommonOptions common;
    int swarmSize = 100;         ///< M particles; >= 2
    double inertiaStart = 0.75;  ///< w at the start of the run; in [0, 1.2]
    double inertiaEnd = 0.75;    ///< w at the end of the run (linear in between); in [0, 1.2]
    double c1 = 1.0;             ///< cognitive (self-confidence) coefficient; >= 0
    double c2 = 1.0;             ///< social (swarm-confidence) coefficient; >= 0
    Acceleration acceleration = Acceleration::Cosine;
    Update update = Update::Asynchronous;
    double maxVelocity = 0.5;  ///< Vmax as a fraction of each variable's range; in (0, 1]
    /// 0: every particle follows the swarm's gbest (both papers). k > 0: ring topology, a particle
    /// follows the best pbest among itself and k particles on each side (2k + 1 <= swarmSize).
    int neighbours = 0;

    bool isValid(std::string* why) const;

    /// Stryczek 2016, fast machining error compensation: 100 particles, asynchronous, w = 0.75, c1 = c2 =
    /// cos(pi/2 Li/L).
    static Options stryczek2016();
    /// Abdulshahed 2016, grey neural network thermal model: 90 particles, synchronous, w 0.9 -> 0.4, c1
    /// = 1.5, c2 = 2.
    static Options abdulshahed2016();
    /// Beyond the papers: lbest ring with 2 neighbours each side, w = 0.7298, c1 = c2 = 1.49618
    /// with the cosine schedule, asynchronous, 60 particles (see (c) above).
    static Options ring();
  };

  Pso();
  explicit Pso(Options options);

  const Options& options() const { return options_; }
  std::string name() const override { return "pso"; }
  /// Throws OptionsError (field "pso options", with the reason) for invalid options or problem.
  Result optimise(const Problem& problem, Observer* observer = nullptr) const override;

 private:
  Options options_;
};

}  // namespace metrofit::optim
