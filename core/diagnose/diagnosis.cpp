#include "core/diagnose/diagnosis.h"

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
                        {"round", c.round}};
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
  return j;
}

}  // namespace metrofit::diagnose
