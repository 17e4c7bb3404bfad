#include "core/diagnose/diagnosis.h"

namespace metrofit::diagnose {

std::vector<const Candidate*> Diagnosis::accepted() const {
  std::vector<const Candidate*> out;
  for (const Candidate& c : effects)
    if (c.accepted) out.push_back(&c);
  return out;
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
    effects.push_back(std::move(e));
  }
  nlohmann::json j = {{"domain", d.domain},
                      {"baseline", summaryJson(d.baseline)},
                      {"effects", effects},
                      {"final", summaryJson(d.final)}};
  if (!d.units.empty()) j["units"] = d.units;
  return j;
}

}  // namespace metrofit::diagnose
