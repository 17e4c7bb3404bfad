#pragma once
// The effects the user accepted on the diagnosis page and added with Apply (stored in
// studies.diagnosis.<domain>.applied = [{"name": EFFECT, "parameters": {NAME: VALUE}}]), read back
// into the setup-correction and the posture-matching studies, so that later runs, corrections and
// adjustments include them. The effect models are the diagnosis's own (setup_diagnosis.h,
// matching_diagnosis.h), with the parameters as estimated there (not refitted).
//
// Setup (names of docs/file-formats.md#effect-catalogue; setup_diagnosis.h):
//   tool_wear:<tool>   {"mm_per_part": r}   e_T(p) = e_T + r p     (p the part number)
//   drift:<datum>      {"mm_per_min": r}    e_i(t) = e_i + r t     (t the report's time_min)
// The study's deviation of dimension q becomes the PREDICTION for the next part instead of the mean
// over the measured parts:
//   c_q        = mean over the rows r of q of (y_r - sum_k G[q][i_k] r_k x_k(r))   (the constant part)
//   e_q(next)  = c_q + sum_k G[q][i_k] r_k x_k(next)
// with x_k the part number (tool wear) or the time (drift); a generic effect `unexplained:<against>`
// {"shape": ..., "coefficients": w} (docs/file-formats.md#generic-effects) adds B(v) w, B its shape's
// basis and v the variable it was fitted against: the time (unexplained:time, every dimension), the
// part number weighted by the datum's gain G[q][i] (unexplained:datum:<id>) or the part number on one
// dimension only (unexplained:dimension:<id>); the others (row, part, dimension) say nothing about
// the next part and cannot be applied. The next part is the largest measured
// part number + 1, its time the last part's mean time + the mean time between parts. Without
// effects e_q(next) is the mean deviation (the declared model of the study). Part numbers follow
// setup_diagnosis.h: the numbers of the "part" column when every part name is a number, else 1, 2,
// ... in order of appearance.
// Figures (mm): rmse / max_abs of the rows against the model at their own part and time (what the
// correction leaves if it cancels the predicted deviation), and the next-part error: the last part
// (largest number) predicted from the other parts, rms over its rows.
//
// Matching (matching_diagnosis.h): scale {"ppm"}, surface_offset:<surface> {"mm"}, distortion
// {"ppm", "angle_deg"} deform the part in its own frame, d(q) as core/sim/effects_matching.h with
// scale and distortion about the centroid of the nominal points (as the diagnosis fits them). The
// study's model of the part is q' = q + d(q): the nominal points are moved by d before matching,
// so the posture (and the machine adjustments computed from it) is that of the part with the effect.
// A generic effect `unexplained:<against>` {"shape": ..., "coefficients": [...]} moves the nominal
// points by matchingGenericDisplacement (its deformation without a rigid part).
//
// Validation: every entry must be an object with a known "name" whose datum / tool / surface exists
// and a "parameters" object with every numeric parameter of the effect finite. Errors are
// ValidationError naming `source` and the field, e.g. "studies.diagnosis.setup.applied[1].name" or
// "studies.diagnosis.matching.applied[0].parameters.ppm".
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/diagnose/residual_check.h"
#include "core/matching/effects.h"
#include "core/matching/probe_points.h"
#include "core/setup/model.h"
#include "core/setup/report.h"

namespace metrofit {
class Project;
}

namespace metrofit::diagnose {

/// "studies.diagnosis.<domain>.applied".
std::string appliedField(const std::string& domain);
/// studies.diagnosis.<domain>.applied of the project when it applies to the dataset `datasetId` the
/// study runs on (the setup study's CMM report, the matching study's probe points): the effects and
/// their parameters were estimated on the dataset the diagnosis ran on
/// (studies.diagnosis.<domain>.dataset), so only a study of that dataset includes them, as for the
/// thermal and kinematic effects. An empty array when absent or when the diagnosis ran on another
/// dataset (that study keeps the declared model). ValidationError when present but not a list.
nlohmann::json projectAppliedEffects(const Project& project, const std::string& domain,
                                     const std::string& datasetId, const std::string& source = {});
/// The dataset the diagnosis of `domain` ran on when effects were applied there (a non-empty list)
/// and it is not `datasetId` (the effects belong to that dataset), else empty.
std::string appliedEffectsElsewhere(const Project& project, const std::string& domain,
                                    const std::string& datasetId);

// ---- setup ----

struct AppliedSetupEffect {
  std::string name;       ///< "tool_wear:T23", "drift:W1", "unexplained:datum:W1"
  std::size_t datum = 0;  ///< index into the model's setup data (tool wear, drift, unexplained:datum:)
  bool perPart = true;    ///< tool wear (rate per part) or drift (rate per minute); generic: part number
  double rate = 0.0;      ///< mm_per_part or mm_per_min
  /// A generic effect: its shape (against time, datum:<id> or dimension:<id>) and coefficients (mm).
  std::optional<GenericForm> shape;
  std::vector<double> coefficients;
  std::optional<std::size_t> dimension;  ///< unexplained:dimension:<id>: the one dimension it acts on
};

/// Whether a setup generic effect fitted against `against` can be applied (it predicts the next part):
/// time, datum:<id> and dimension:<id>.
bool setupGenericPredictsNextPart(const std::string& against);

/// Reads the list against the model (see above). `field` prefixes the error fields.
std::vector<AppliedSetupEffect> parseAppliedSetupEffects(const nlohmann::json& applied,
                                                         const setup::Model& model,
                                                         const std::string& source = {},
                                                         const std::string& field = appliedField("setup"));

/// One line per effect: "tool_wear:T23 (0.0021 mm/part)".
std::string describe(const AppliedSetupEffect& effect);
std::string describe(const std::vector<AppliedSetupEffect>& effects);

struct SetupPrediction {
  std::vector<double> deviationMm;  ///< per model dimension: e_q(next)
  double nextPart = 0.0;
  double nextTimeMin = 0.0;
  double rmseMm = 0.0;                   ///< rows against the model at their own part and time
  double maxAbsMm = 0.0;                 ///< largest |row - model|
  std::optional<double> nextPartRmseMm;  ///< last part predicted from the others (>= 2 parts)
  std::size_t rows = 0, parts = 0;
};

/// The prediction of the header for measurements read against `model` (the model they belong to).
/// ValidationError when a dimension has no row.
SetupPrediction predictSetupDeviations(const setup::Model& model, const setup::Measurements& measurements,
                                       const std::vector<AppliedSetupEffect>& effects);

/// Sets measurements.deviationMm to the prediction (no change without effects) and returns it.
SetupPrediction applySetupEffects(const setup::Model& model, setup::Measurements& measurements,
                                  const std::vector<AppliedSetupEffect>& effects);

// ---- matching ----

/// An applied generic effect `unexplained:<against>`: its shape and the diagnosis's coefficients
/// (matching_diagnosis.h matchingGenericDisplacement).
struct AppliedMatchingGeneric {
  GenericForm shape;
  std::vector<double> coefficients;
  std::size_t entry = 0;  ///< index in the applied list (for errors)
};

struct AppliedMatchingEffects {
  MatchingEffects effects;  ///< the parameters (core/sim/effects_matching.h)
  std::vector<AppliedMatchingGeneric> generic;
  std::vector<std::string> names;         ///< as applied, in order
  std::vector<std::string> descriptions;  ///< "scale (+92.4 ppm)"
  std::vector<std::size_t> surfaceEntry;  ///< entry index of each effects.surfaceOffsetsMm
  bool empty() const { return names.empty(); }
  std::string describe() const;  ///< descriptions joined with ", "
};

/// Reads the list (surfaces are checked against the point set in applyMatchingEffects).
AppliedMatchingEffects parseAppliedMatchingEffects(const nlohmann::json& applied,
                                                   const std::string& source = {},
                                                   const std::string& field = appliedField("matching"));

/// The point set of the study's model: nominal points moved by d(q) (see above). ValidationError
/// naming the field of the entry when a surface offset names a surface the set does not have, or
/// the set has no normals.
ProbePointSet applyMatchingEffects(const ProbePointSet& set, const AppliedMatchingEffects& applied,
                                   const std::string& source = {},
                                   const std::string& field = appliedField("matching"));

}  // namespace metrofit::diagnose
