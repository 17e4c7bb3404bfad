#pragma once
// The result of the closed loop (docs/file-formats.md#diagnose-result): the declared model's residual,
// every candidate effect tried with its parameters and evidence, and the error after the accepted
// effects were added. Shared by the four domains (thermal, kinematic, setup, matching), the CLI,
// the GUI's diagnosis view and the report.
//
// The loop has the same steps in every domain and is written once (loop.h runLoop; each domain's
// *_diagnosis.cpp supplies its LoopDomain: fit, candidates, residual variables): fit the declared
// model plus the effects accepted
// so far; try every remaining candidate (the catalogue's named effects and the generic effects
// `unexplained:<against>` of the current residual's strongest structures, residual_check.h);
// accept the best one only when its evidence passes the domain's test (out-of-sample improvement
// for thermal, an information criterion with a conservative threshold elsewhere) *and* it reduces
// the rmse by a practically relevant amount; repeat until nothing more is accepted. Gross errors
// are found on the declared model's residual and excluded first; the final residual's check
// (Diagnosis::residualCheck) says whether it is white and what it still depends on.
//
// Texts for people (evidence, notes, plot axis titles) are kept twice: as the English string of
// docs/file-formats.md (the JSON, the CLI and the report use it, unchanged) and as Phrases
// (core/common/text.h) from which that string is made, so that the GUI can show them translated
// with the user's number format. Set them with setEvidence / addEvidence / addNote / setLabels,
// which keep both forms equal (string == english(parts)).
#include <cstddef>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/common/run.h"
#include "core/common/text.h"
#include "core/diagnose/residual_check.h"

namespace metrofit::diagnose {

/// Error figures of one model state, in the data's own units (um for thermal, mm elsewhere).
struct ErrorSummary {
  double rmse = 0.0;                  ///< residual rms of the fitted data
  double maxAbs = 0.0;                ///< largest |residual| of the fitted data
  std::optional<double> heldoutRmse;  ///< residual rms on held-out rows (thermal)
};

/// One estimated parameter of an effect. Numbers carry a standard error when one is known.
struct Parameter {
  std::string name;  ///< key of docs/file-formats.md#effect-catalogue, e.g. "tau_min", "x_mm", "axis"
  std::variant<double, std::string> value;  ///< numeric, or text (e.g. cyclic "axis": "x")
  std::optional<double> standardError;      ///< 1-sigma, same unit as value
};

/// What explains a residual, for plotting (GUI diagnosis view, report): residual before and after
/// the effect against the explaining variable (time, path angle, part number, surface index...).
struct ResidualPlot {
  std::string xLabel;  ///< e.g. "time (min)", "path angle (deg)", "part"
  std::string yLabel;  ///< e.g. "residual (um)"
  std::vector<double> x;
  std::vector<double> before;  ///< residual of the model without this effect
  std::vector<double> after;   ///< residual with it
  /// For 2D vector-field plots (matching distortion): per point x, y, dx, dy (before).
  std::vector<std::vector<double>> vectors;
  /// Names of the categories when x is a category index 0, 1, ... (matching: the surfaces).
  std::vector<std::string> categories;
  Phrases xLabelParts;  ///< xLabel == english(xLabelParts)
  Phrases yLabelParts;  ///< yLabel == english(yLabelParts)

  /// Sets xLabel / yLabel and their phrases.
  void setLabels(Phrases x, Phrases y);
};

/// A candidate effect tried in one round.
struct Candidate {
  std::string name;  ///< name of docs/file-formats.md#effect-catalogue, e.g. "lag", "lag:T1", "backlash"
  bool accepted = false;
  std::vector<Parameter> parameters;
  double rmseBefore = 0.0;              ///< fit rmse of the model it was tried on
  double rmseAfter = 0.0;               ///< fit rmse with this effect added
  std::optional<double> heldoutBefore;  ///< held-out rmse (thermal)
  std::optional<double> heldoutAfter;
  double score = 0.0;                ///< the test statistic the decision used (e.g. delta BIC)
  std::string evidence;              ///< one line a person can read
  int round = 0;                     ///< loop round in which it was tried (0-based)
  std::optional<ResidualPlot> plot;  ///< filled for accepted effects (and may be for others)
  Phrases evidenceParts;             ///< evidence == english(evidenceParts)
  /// A generic effect (`unexplained:<against>`, docs/file-formats.md#generic-effects): its fixed shape.
  std::optional<GenericForm> generic;
  /// Kinematic, matching and setup generic effects: the coefficients w of genericBasis(*generic) from
  /// the final fit, so that a study can evaluate genericBasis(shape) w (Apply). Empty in thermal (its
  /// study refits the generic columns).
  std::vector<double> genericCoefficients;

  /// Replaces the evidence (string and phrases).
  void setEvidence(Phrases parts);
  /// Appends to the evidence (string and phrases).
  void addEvidence(Phrases parts);
  /// Puts `part` in front of the evidence (e.g. "accepted: ").
  void prependEvidence(Phrase part);
};

struct Diagnosis {
  std::string domain;  ///< "thermal", "kinematic", "setup", "matching"
  std::string units;   ///< units of rmse / max_abs, e.g. "um", "mm"
  ErrorSummary baseline;
  std::vector<Candidate> effects;  ///< every candidate tried, in the order tried
  ErrorSummary final;
  /// The declared model's description and its fitted parameters, for the report (free text).
  std::vector<std::string> notes;
  std::vector<Phrases> notesParts;  ///< notes[i] == english(notesParts[i])
  /// The final residual's check (docs/file-formats.md#residual_check); every domain fills it.
  std::optional<ResidualCheck> residualCheck;
  /// Thermal: the same check of the held-out rows' residual (JSON `heldout_check`, additive). It is
  /// reported only: the held-out rows chose nothing; its outliers are excluded from heldout_rmse.
  std::optional<ResidualCheck> heldoutCheck;

  std::vector<const Candidate*> accepted() const;
  /// Appends a note (string and phrases).
  void addNote(Phrases parts);
};

/// The progress and cancel handling the four loops share. Thermal and kinematic report after every
/// candidate (afterCandidate: notify() with iteration = step, evaluations = steps so far, progress
/// within the round; the note of a stop is "cancelled"); setup and matching after every round
/// (afterRound: only when there is an observer, iteration = round, evaluations = candidates so
/// far; the note is "stopped by the observer after round N").
class LoopProgress {
 public:
  explicit LoopProgress(Observer* observer) : observer_(observer) {}

  /// After candidate `index` (0-based) of `count` in `round`; `current` is the current model's error
  /// (IterationSummary::best), also reported as the component `component`. True when the observer
  /// stopped the loop.
  bool afterCandidate(int round, std::size_t index, std::size_t count, double current, const char* component);
  /// After round `round`: `evaluations` candidates fitted so far, the current rmse and the number of
  /// accepted effects. True when the observer stopped the loop.
  bool afterRound(int round, long evaluations, double rmse, std::size_t accepted);
  bool stopped() const { return stopped_; }
  /// Adds the note of a stop to `d` (nothing when the loop was not stopped).
  void addNote(Diagnosis& d) const;

 private:
  Observer* observer_;
  RunInfo run_;
  long step_ = 0;
  bool stopped_ = false;
  bool perRound_ = false;
  int round_ = 0;
};

/// One run of a domain's loop, for keepNamedOnlyWhenNeeded: its diagnosis and the information
/// criterion of its final model, n ln(RSS / n) + (parameters of the accepted effects) ln n + the
/// search penalties of the accepted generic and searched effects (the declared model's parameters
/// are the same in every run and left out).
struct LoopRun {
  Diagnosis diagnosis;
  double bic = 0.0;
  bool stopped = false;  ///< the observer stopped the loop: no further run
};

/// In the `excluded` set of keepNamedOnlyWhenNeeded: every named effect (generic effects only).
inline constexpr const char* kEveryNamedEffect = "*";

/// "A named effect must explain what it was chosen for" (docs/file-formats.md#generic-effects). The loops
/// prefer a named effect to a generic one in a round; afterwards, when the result accepted a named
/// effect and still needed a generic effect or left a non-white residual, the names are checked:
/// the loop is run again without each accepted named effect N (`run({N})`) and once with generic
/// effects only (`run({kEveryNamedEffect})`); the first run is kept unless an alternative's
/// criterion is within `margin` of it or lower (the domain's acceptance threshold: a name survives
/// only when, beside the generic alternative, it still has the evidence it was accepted on), else
/// the alternative with the lowest criterion wins. Names accepted first and not in the winner are listed with
/// accepted = false and the comparison as evidence. At most 1 + (accepted names) + 1 runs.
/// `genericDependsOnNamed`: the domain's generic bases depend on the named effects open in the run
/// (matching projects them off the named effects, so a generic effect cannot trade against a name);
/// then the generic-only run is also tried when the first run accepted no name but a generic effect
/// or left a non-white residual (a generic effect of the first run may have lost the part of its
/// shape that a name's column also has).
Diagnosis keepNamedOnlyWhenNeeded(const std::function<LoopRun(const std::set<std::string>& excluded)>& run,
                                  double margin, bool genericDependsOnNamed = false);

/// Puts the outliers excluded before the fit into d.residualCheck (with the threshold used) and,
/// when there are any, the note "<k> gross errors excluded before the fit ...:" followed by
/// describe(outlier) for each.
void attachOutliers(Diagnosis& d, std::vector<Outlier> outliers, double threshold,
                    const std::function<Phrase(const Outlier&)>& describe);

/// The JSON of docs/file-formats.md#diagnose-result: {"domain", "baseline":
/// {"rmse","max_abs"[,"heldout_rmse"]}, "effects": [{"name","accepted","parameters":{name:
/// value},"rmse_before","rmse_after", "evidence", ...}], "final": {...}}. Additive keys: "units",
/// "uncertainty" per effect
/// ({name: standard error}), "heldout_rmse_before/after", "score", "round".
nlohmann::json toJson(const Diagnosis& d);

}  // namespace metrofit::diagnose
