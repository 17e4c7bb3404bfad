#include "core/diagnose/loop.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace metrofit::diagnose {

LoopRun runLoop(LoopDomain& domain, const LoopStyle& style, const std::set<std::string>& excluded,
                Observer* observer, Diagnosis d) {
  const bool perCandidate = style.candidateComponent != nullptr;
  std::vector<std::string> genericTaken;
  std::vector<Candidate> accepted, lastRound;
  double complexity = 0.0;
  long tried = 0;
  LoopProgress progress(observer);
  bool cancelled = false;
  bool stopNote = true;
  for (int round = 0; !cancelled; ++round) {
    if (style.stopAtMaxRounds && round >= style.maxRounds) break;
    if (!domain.beginRound(round)) {
      cancelled = true;
      break;
    }
    // The round's candidates: the named ones, then the generic ones of the current residual.
    const std::vector<std::string> names = domain.namedCandidates(excluded);
    const ResidualCheck check = domain.roundCheck();
    const double penalty = genericSearchPenalty(check);
    std::vector<GenericForm> generics;
    for (const GenericForm& g : genericCandidates(check, genericTaken))
      if (std::optional<GenericForm> p = domain.prepareGeneric(g)) generics.push_back(std::move(*p));
    const std::size_t count = names.size() + generics.size();
    if (perCandidate && count == 0) break;

    std::vector<LoopTrial> trials;
    trials.reserve(count);
    const bool acceptable = style.stopAtMaxRounds || round < style.maxRounds;
    for (std::size_t i = 0; i < count && !cancelled; ++i) {
      std::optional<LoopTrial> t = i < names.size()
                                       ? domain.tryNamed(names[i], round, i)
                                       : domain.tryGeneric(generics[i - names.size()], penalty, round, i);
      if (!t) {  // stopped inside the candidate: not listed
        cancelled = true;
        break;
      }
      ++tried;
      t->candidate.round = round;
      t->candidate.accepted = false;
      if (!acceptable) t->passes = false;
      trials.push_back(std::move(*t));
      if (perCandidate &&
          progress.afterCandidate(round, i, count, domain.currentError(), style.candidateComponent))
        cancelled = true;
    }

    // The choice: the domain's rule, or the best score among the passing trials, a named one first.
    std::optional<std::size_t> best;
    if (!cancelled) {
      if (std::optional<long> own = domain.choose(trials)) {
        if (*own >= 0) best = static_cast<std::size_t>(*own);
      } else {
        dropNamesAGenericBeats(domain, trials);
        std::optional<std::size_t> named, generic;
        for (std::size_t i = 0; i < trials.size(); ++i) {
          if (!trials[i].passes || !trials[i].estimable) continue;
          std::optional<std::size_t>& slot = trials[i].candidate.generic ? generic : named;
          if (!slot || trials[i].candidate.score < trials[*slot].candidate.score) slot = i;
        }
        best = named ? named : generic;
      }
    }
    Phrases preferredOver;
    if (best)
      if (std::optional<std::size_t> p = domain.prefer(trials, *best, &preferredOver)) best = p;

    std::vector<Candidate> extra;  // accepted by the domain's last attempt (thermal: a pair)
    if (!best && !cancelled) extra = domain.whenNoneChosen(trials, round);

    if (best) {
      const std::size_t b = *best;
      Candidate& win = trials[b].candidate;
      if (style.markAccepted) {
        for (std::size_t i = 0; i < trials.size(); ++i)
          if (i != b && trials[i].passes && trials[i].estimable)
            trials[i].candidate.addEvidence(
                {Phrase("; passed, but %1 explains more", {PhraseArg::name(win.name)})});
        win.prependEvidence(Phrase("accepted: "));
      } else {
        win.addEvidence(std::move(preferredOver));
        // Ties (e.g. time proportional to part number): the first listed wins, the evidence says so.
        for (std::size_t j = 0; j < trials.size(); ++j) {
          if (j == b || !trials[j].estimable) continue;
          if (std::abs(trials[j].candidate.score - win.score) <= 1e-6 * std::abs(win.score) + 1e-9)
            win.addEvidence({Phrase(style.tiesWithPoints ? "; indistinguishable from %1 with these points"
                                                         : "; indistinguishable from %1 with these data",
                                    {PhraseArg::name(trials[j].candidate.name)})});
        }
      }
      win.accepted = true;
      domain.accept(b, win);
      if (win.generic) genericTaken.push_back(win.generic->against);
      complexity += trials[b].complexity;
      accepted.push_back(win);
    }
    for (Candidate& c : extra) {
      if (c.generic) genericTaken.push_back(c.generic->against);
      accepted.push_back(c);
    }
    const bool any = best || !extra.empty();
    if (style.listEveryRound) {
      for (LoopTrial& t : trials) d.effects.push_back(std::move(t.candidate));
      for (Candidate& c : extra) d.effects.push_back(std::move(c));
    } else if (!any) {
      for (LoopTrial& t : trials) lastRound.push_back(std::move(t.candidate));
    }
    if (!perCandidate && progress.afterRound(round, tried, domain.currentError(), accepted.size())) {
      cancelled = true;
      stopNote = any;  // a stop after the last round (nothing accepted) ends the loop as it would anyway
    }
    if (!any) break;
  }
  if (stopNote) progress.addNote(d);
  if (style.listEveryRound) {
    std::vector<Candidate*> acc;
    for (Candidate& c : d.effects)
      if (c.accepted) acc.push_back(&c);
    domain.finish(d, acc, cancelled);
  } else {
    std::vector<Candidate*> acc;
    for (Candidate& c : accepted) acc.push_back(&c);
    domain.finish(d, acc, cancelled);
    std::vector<Candidate> effects = std::move(accepted);
    for (Candidate& c : lastRound) effects.push_back(std::move(c));
    d.effects = std::move(effects);
  }
  LoopRun out;
  out.bic = domain.dataCriterion() + complexity;
  out.stopped = progress.stopped();
  out.diagnosis = std::move(d);
  return out;
}

std::size_t dropNamesAGenericBeats(const LoopDomain& domain, std::vector<LoopTrial>& trials) {
  const double margin = domain.clearMargin();
  std::size_t dropped = 0;
  for (LoopTrial& named : trials) {
    if (named.candidate.generic || !named.passes || !named.estimable) continue;
    const std::vector<std::string> vars = domain.namedVariables(named.candidate);
    const LoopTrial* beats = nullptr;
    for (const LoopTrial& g : trials) {
      if (!g.candidate.generic || !g.estimable) continue;
      if (std::find(vars.begin(), vars.end(), g.candidate.generic->against) == vars.end()) continue;
      if (!(g.candidate.score < named.candidate.score - margin)) continue;
      if (!beats || g.candidate.score < beats->candidate.score) beats = &g;
    }
    if (!beats) continue;
    named.passes = false;
    named.candidate.addEvidence({Phrase(
        "; not taken: the generic %1 of the same variable explains clearly more (score %2 against %3)",
        {PhraseArg::name(beats->candidate.name), PhraseArg::number(beats->candidate.score, 4),
         PhraseArg::number(named.candidate.score, 4)})});
    ++dropped;
  }
  return dropped;
}

std::vector<std::string> openNamedEffects(const std::vector<std::string>& names,
                                          const std::vector<bool>& accepted,
                                          const std::set<std::string>& excluded) {
  std::vector<std::string> out;
  if (excluded.count(kEveryNamedEffect)) return out;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (!(i < accepted.size() && accepted[i]) && !excluded.count(names[i])) out.push_back(names[i]);
  return out;
}

}  // namespace metrofit::diagnose
