#include "core/diagnose/diagnosis.h"

#include <algorithm>

namespace metrofit::diagnose {

std::vector<const Candidate*> Diagnosis::accepted() const {
  std::vector<const Candidate*> out;
  for (const Candidate& c : effects)
    if (c.accepted) out.push_back(&c);
  return out;
}

void ResidualPlot::setLabels(Phrases x, Phrases y) {
  xLabel = english(x);
  yLabel = english(y);
  xLabelParts = std::move(x);
  yLabelParts = std::move(y);
}

void Candidate::setEvidence(Phrases parts) {
  evidence = english(parts);
  evidenceParts = std::move(parts);
}

void Candidate::addEvidence(Phrases parts) {
  evidence += english(parts);
  for (Phrase& p : parts) evidenceParts.push_back(std::move(p));
}

void Candidate::prependEvidence(Phrase part) {
  evidence = part.english() + evidence;
  evidenceParts.insert(evidenceParts.begin(), std::move(part));
}

void Diagnosis::addNote(Phrases parts) {
  notes.push_back(english(parts));
  notesParts.push_back(std::move(parts));
}

bool LoopProgress::afterCandidate(int round, std::size_t index, std::size_t count, double current,
                                  const char* component) {
  IterationSummary s;
  s.iteration = step_;
  s.evaluations = ++step_;
  s.best = current;
  s.components = {{"round", static_cast<double>(round)}, {component, current}};
  s.progress = static_cast<double>(index + 1) / static_cast<double>(count);
  if (notify(observer_, run_, s, false)) {
    stopped_ = true;
    perRound_ = false;
    round_ = round;
  }
  return stopped_;
}

bool LoopProgress::afterRound(int round, long evaluations, double rmse, std::size_t accepted) {
  if (!observer_) return false;
  IterationSummary s;
  s.iteration = round;
  s.evaluations = evaluations;
  s.best = rmse;
  s.components = {{"rmse", s.best}, {"accepted", static_cast<double>(accepted)}};
  if (observer_->onIteration(s) == ObserverDecision::Stop) {
    stopped_ = true;
    perRound_ = true;
    round_ = round;
    return true;
  }
  return false;
}

void LoopProgress::addNote(Diagnosis& d) const {
  if (!stopped_) return;
  if (perRound_)
    d.addNote({Phrase("stopped by the observer after round %1", {PhraseArg::integer(round_)})});
  else
    d.addNote({Phrase("cancelled")});
}

Diagnosis keepNamedOnlyWhenNeeded(const std::function<LoopRun(const std::set<std::string>& excluded)>& run,
                                  double margin, bool genericDependsOnNamed) {
  LoopRun cur = run({});
  const Diagnosis& d = cur.diagnosis;
  bool named = false, generic = false;
  for (const Candidate* c : d.accepted()) (c->generic ? generic : named) = true;
  if (cur.stopped || !(named || genericDependsOnNamed) ||
      !(generic || (d.residualCheck && !d.residualCheck->white)))
    return std::move(cur.diagnosis);
  std::vector<std::set<std::string>> alternatives;
  for (const Candidate* c : d.accepted())
    if (!c->generic) alternatives.push_back({c->name});
  alternatives.push_back({kEveryNamedEffect});
  std::optional<LoopRun> best;
  for (const auto& ex : alternatives) {
    LoopRun alt = run(ex);
    if (alt.stopped) return std::move(cur.diagnosis);
    if (alt.bic < (best ? best->bic : cur.bic + margin)) best = std::move(alt);
  }
  if (!best) return std::move(cur.diagnosis);
  std::vector<Candidate> dropped;
  for (const Candidate* c : cur.diagnosis.accepted()) {
    if (c->generic) continue;
    const auto still = std::find_if(best->diagnosis.effects.begin(), best->diagnosis.effects.end(),
                                    [&](const Candidate& x) { return x.accepted && x.name == c->name; });
    if (still != best->diagnosis.effects.end()) continue;
    Candidate x = *c;
    x.accepted = false;
    x.plot.reset();
    x.setEvidence(
        {Phrase("rejected: does not explain what it was chosen for; without it the generic effects "
                "explain the data as well (BIC %1 without, %2 with, needed %3 lower)",
                {PhraseArg::fixed(best->bic, 1), PhraseArg::fixed(cur.bic, 1), PhraseArg::number(margin)})});
    dropped.push_back(std::move(x));
  }
  for (Candidate& c : dropped) best->diagnosis.effects.push_back(std::move(c));
  return std::move(best->diagnosis);
}

void attachOutliers(Diagnosis& d, std::vector<Outlier> outliers, double threshold,
                    const std::function<Phrase(const Outlier&)>& describe) {
  if (!outliers.empty()) {
    Phrases note = {Phrase("%1 gross errors excluded before the fit (robust z above the outlier threshold):",
                           {PhraseArg::integer(static_cast<long long>(outliers.size()))})};
    for (const Outlier& o : outliers) note.push_back(describe(o));
    d.addNote(std::move(note));
  }
  if (d.residualCheck) {
    d.residualCheck->outliers = std::move(outliers);
    d.residualCheck->outlierThreshold = threshold;
  }
}

namespace {

nlohmann::json summaryJson(const ErrorSummary& s) {
  nlohmann::json j = {{"rmse", s.rmse}, {"max_abs", s.maxAbs}};
  if (s.heldoutRmse) j["heldout_rmse"] = *s.heldoutRmse;
  return j;
}

}  // namespace

nlohmann::json toJson(const Diagnosis& d) {
  nlohmann::json effects = nlohmann::json::array();
  for (const Candidate& c : d.effects) {
    nlohmann::json parameters = nlohmann::json::object();
    nlohmann::json uncertainty = nlohmann::json::object();
    for (const Parameter& p : c.parameters) {
      if (const double* v = std::get_if<double>(&p.value))
        parameters[p.name] = *v;
      else
        parameters[p.name] = std::get<std::string>(p.value);
      if (p.standardError) uncertainty[p.name] = *p.standardError;
    }
    nlohmann::json e = {{"name", c.name},
                        {"accepted", c.accepted},
                        {"parameters", parameters},
                        {"rmse_before", c.rmseBefore},
                        {"rmse_after", c.rmseAfter},
                        {"evidence", c.evidence},
                        {"score", c.score},
                        {"round", c.round + 1}};  // 1-based, as the GUI and the report number rounds
    if (!uncertainty.empty()) e["uncertainty"] = uncertainty;
    if (c.heldoutBefore) e["heldout_rmse_before"] = *c.heldoutBefore;
    if (c.heldoutAfter) e["heldout_rmse_after"] = *c.heldoutAfter;
    if (c.generic) {
      e["form"] = formName(c.generic->form);
      e["against"] = c.generic->against;
    }
    effects.push_back(std::move(e));
  }
  nlohmann::json j = {{"domain", d.domain},
                      {"baseline", summaryJson(d.baseline)},
                      {"effects", effects},
                      {"final", summaryJson(d.final)}};
  if (!d.units.empty()) j["units"] = d.units;
  if (d.residualCheck) j["residual_check"] = toJson(*d.residualCheck);
  if (d.heldoutCheck) j["heldout_check"] = toJson(*d.heldoutCheck);
  return j;
}

}  // namespace metrofit::diagnose
