#pragma once
// The closed loop, written once for the four domains (diagnosis.h describes it):
//
//   repeat: the candidates of the round are the catalogue's named effects the domain still offers
//   and the generic effects `unexplained:<against>` of the current residual's strongest structures
//   (residual_check.h genericCandidates, with the search penalty 2 ln(tests)); the domain fits the
//   current model plus each candidate and decides whether it passes its test; the best passing one
//   is accepted (a named effect that passes is preferred to a generic one, unless a generic effect
//   of the same variable explains clearly more, below); until none passes.
//
// A name is not the nearest name for a shape no entry models. A named effect is not accepted in a
// round where a generic effect `unexplained:<v>` of one of its variables v (LoopDomain::
// namedVariables: e.g. kinematic cyclic on x: x; setup tool_wear:T and drift:T: datum:T; matching
// surface_offset:s: surface:s) explains clearly more:
//   score(generic) < score(named) - margin         (LoopDomain::clearMargin)
// The scores are the domains' criteria relative to the current model, dBIC = n ln(RSS1 / RSS0) +
// k ln n (+ the generic's search penalty 2 ln(tests)), so the generic's extra parameters and its
// search are paid for; the margin is the domain's own acceptance threshold (kinematic --bic-margin
// 10, setup and matching bicThreshold). In words: the data prefer the generic model to the named one
// by at least the evidence an effect needs to be accepted at all. The named effect is then marked
// "not taken" in this round (it may pass in a later one, when the generic effect has taken the
// shape); the generic effect competes as usual (it passes too: its dBIC is below the named one's,
// which passed) and, if it does not pass its gain test, the round takes neither and the final
// residual check reports the structure. Thermal applies the same rule in its own choose() with its
// criterion: a generic effect that validates better by the acceptance margin, (1 - minHeldoutGain)
// times the name's validation rmse.
//
// What differs between the domains is behind LoopDomain: how a model is fitted (linear least
// squares for setup, Gauss-Newton for matching and kinematic, blocked forward validation for
// thermal), which named effects exist, how a generic shape becomes model columns, and the few
// domain rules of the choice (thermal: a generic effect of a measured column displaces a name that
// validates worse; setup: tool wear over drift of the same datum when the data cannot tell them
// apart). LoopStyle keeps what the results of each domain have always looked like (which candidates
// are listed, how progress is reported), so that the JSON of docs/file-formats.md#diagnose-result stays as it
// was.
#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/diagnose/diagnosis.h"

namespace metrofit::diagnose {

/// One candidate of a round as the domain fitted it. `candidate` carries the name, parameters,
/// evidence, rmse before/after and score (lower is better: dBIC, or the relative validation change).
struct LoopTrial {
  Candidate candidate;
  bool estimable = false;  ///< fitted at all ("not estimable" / "not identifiable": never chosen)
  bool passes = false;     ///< the domain's acceptance test
  /// What accepting it adds to the run's criterion (k ln n plus the search penalty), LoopRun::bic.
  double complexity = 0.0;
};

/// The domain side of the loop. A domain object holds the current model; the loop asks it to try
/// candidates (each in a numbered slot of the round) and to adopt one.
class LoopDomain {
 public:
  virtual ~LoopDomain() = default;

  /// The variables of a named effect, in the `against` vocabulary of the residual check (the rule
  /// "a generic effect of the same variable explains clearly more", header comment). Empty: none.
  virtual std::vector<std::string> namedVariables(const Candidate& /*named*/) const { return {}; }
  /// The margin of that rule in score units (the domain's acceptance threshold).
  virtual double clearMargin() const { return 0.0; }

  /// The named candidates still open in this round (not accepted yet, not in `excluded`; the set
  /// may hold kEveryNamedEffect: none). In the order they are listed.
  virtual std::vector<std::string> namedCandidates(const std::set<std::string>& excluded) = 0;
  /// The residual check of the current model (to find the round's generic candidates).
  virtual ResidualCheck roundCheck() = 0;
  /// The domain's form of a generic candidate (e.g. one set of columns per coordinate, the part a
  /// model's Jacobian cannot absorb, a column's curvature only), or nullopt to skip it.
  virtual std::optional<GenericForm> prepareGeneric(const GenericForm& g) { return g; }
  /// Starts a round: slots of the previous round may be forgotten. False: the observer stopped the
  /// loop (thermal polls it here).
  virtual bool beginRound(int /*round*/) { return true; }
  /// Fits the current model plus the named effect (slot: its index in the round). nullopt: the
  /// observer stopped the fit inside the candidate (it is not listed).
  virtual std::optional<LoopTrial> tryNamed(const std::string& name, int round, std::size_t slot) = 0;
  /// The same for a generic effect (prepared by prepareGeneric) with its search penalty.
  virtual std::optional<LoopTrial> tryGeneric(const GenericForm& g, double penalty, int round,
                                              std::size_t slot) = 0;
  /// The domain's choice among the trials (indices = slots), when it has its own rules; nullopt:
  /// the loop's rule (a passing named effect that a generic effect of the same variable explains
  /// clearly more is not taken; then the best score among the passing ones, a passing named effect
  /// first). May edit
  /// the trials' evidence and `passes`. Return {-1}: nothing is chosen.
  virtual std::optional<long> choose(std::vector<LoopTrial>& /*trials*/) { return std::nullopt; }
  /// After the loop's rule chose `best`: an earlier trial the domain prefers (setup: tool wear over
  /// drift of the same datum when the data cannot tell them apart) and the words why.
  virtual std::optional<std::size_t> prefer(const std::vector<LoopTrial>& /*trials*/, std::size_t /*best*/,
                                            Phrases* /*why*/) {
    return std::nullopt;
  }
  /// Nothing was chosen in the round: a last attempt of the domain (thermal: two effects together).
  /// Returns the candidates it accepted (empty: none; the domain has adopted them).
  virtual std::vector<Candidate> whenNoneChosen(const std::vector<LoopTrial>& /*trials*/, int /*round*/) {
    return {};
  }
  /// Adopts the model of `slot` as the current one; may complete the accepted candidate (a plot).
  virtual void accept(std::size_t slot, Candidate& accepted) = 0;
  /// The current model's error for progress reports.
  virtual double currentError() const = 0;
  /// After the loop: the accepted effects' parameters from the final joint fit (when the domain
  /// refits them), `final`, the residual check and any closing notes.
  virtual void finish(Diagnosis& d, std::vector<Candidate*> accepted, bool stopped) = 0;
  /// The data term of the run's criterion, n ln(RSS / n) (thermal: its validation criterion).
  virtual double dataCriterion() const = 0;
};

/// How a domain's results have always looked (kept so the JSON and the texts stay the same).
struct LoopStyle {
  int maxRounds = 10;
  /// true: rounds stop at maxRounds (kinematic, thermal); false: a round maxRounds is still tried and
  /// listed, but nothing accepted in it (setup, matching).
  bool stopAtMaxRounds = false;
  /// true: every round's candidates are listed (kinematic, thermal); false: the accepted ones and the
  /// last round's (setup, matching).
  bool listEveryRound = false;
  /// true: the accepted candidate's evidence starts with "accepted: " and other passing ones get
  /// "; passed, but X explains more" (kinematic, thermal); false: ties are named instead.
  bool markAccepted = false;
  /// Ties (false markAccepted): "; indistinguishable from %1 with these data" or "... points".
  bool tiesWithPoints = false;
  /// Progress after every candidate (component name, e.g. "rmse_mm") or, when null, after every round.
  const char* candidateComponent = nullptr;

  /// The style of the loops that list every round (kinematic, thermal): rounds stop at `maxRounds`,
  /// the accepted candidate is marked, progress after every candidate under `component`.
  static LoopStyle everyRound(int maxRounds, const char* component) {
    LoopStyle s;
    s.maxRounds = maxRounds;
    s.stopAtMaxRounds = true;
    s.listEveryRound = true;
    s.markAccepted = true;
    s.candidateComponent = component;
    return s;
  }
};

/// LoopDomain::namedCandidates of a domain whose named effects are `names`: those not accepted yet
/// (`accepted[i]`) and not in `excluded`, in the order of `names`; none when `excluded` holds
/// kEveryNamedEffect.
std::vector<std::string> openNamedEffects(const std::vector<std::string>& names,
                                          const std::vector<bool>& accepted,
                                          const std::set<std::string>& excluded);

/// The rule of the header comment on the trials of a round: every passing named trial that an
/// estimable generic trial of one of its variables explains clearly more gets passes = false and the
/// evidence "; not taken: the generic <g> of the same variable explains clearly more (score <s_g>
/// against <s_n>)". Returns the number of names not taken.
std::size_t dropNamesAGenericBeats(const LoopDomain& domain, std::vector<LoopTrial>& trials);

/// One run of the loop (for keepNamedOnlyWhenNeeded, diagnosis.h). `d` carries the domain, units,
/// baseline and notes set by the caller; the loop adds the effects and the domain finishes it.
LoopRun runLoop(LoopDomain& domain, const LoopStyle& style, const std::set<std::string>& excluded,
                Observer* observer, Diagnosis d);

}  // namespace metrofit::diagnose
