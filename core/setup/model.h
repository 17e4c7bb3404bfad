#pragma once
// The setup model of the setup-correction paper: the relation graph PM = (M, W, T, F, D, R)
// (Stryczek 2016, "A metaheuristic for fast machining error compensation", J. Intell. Manuf. 27,
// section "The proposed compensation system"), stored as the JSON of docs/file-formats.md#setup-model:
//
//   {"name": "...", "axis": "Z", "step_mm": 0.001, "bounds_mm": [-0.1, 0.1],
//    "setup": [{"id": "W1", "kind": "wks"}, {"id": "T5", "kind": "tool"}],
//    "features": [{"id": "P1.F1"}],
//    "dimensions": [{"id": "P1.D1", "nominal": 42.0, "lower": -0.02, "upper": 0.02}],
//    "arcs": [{"from": "W1", "to": "P1.F1", "weight": 1},
//             {"from": "P1.F1", "to": "P1.D1", "weight": 1}]}
//
// Levels: machine points M (kind "machine", the paper's optional level 0), workpiece coordinate
// systems W (kind "wks") and tool code points T (kind "tool") are the SETUP DATA; every setup
// datum is a decision variable x_i (its correction, mm, on the grid lower_i + k * step_mm within
// bounds_mm). Features F and dimensions D are the upper levels. Arcs a -> z carry the weight of
// the paper's Eq. 3: +1 when an increase of a increases z, -1 when it decreases z (0 = no arc).
// Allowed arcs: machine -> wks (R_MW), machine / wks / tool -> feature (R_WF, R_TF and a direct
// machine -> feature shortcut), feature -> dimension (R_FD).
//
// Optional fields (documented there too): per setup datum "bounds_mm" (overrides the model's bounds)
// and "register" (the controller register number used by the exports, see export.h; default: the
// digits at the end of the id, W7 -> 7, T23 -> 23); per dimension "nominal" (checked against the
// CMM report when given) and "label" (the DMIS label it is reported under, default: the id).
//
// Gain matrix (paper Eq. 4-5). With row vectors of corrections x_M, x_W, x_T:
//   F = (x_M R_MW + x_W) R_WF + x_T R_TF (+ x_M R_MF),       D = F R_FD,
// so D = x G^T with the |D| x n gain matrix G, n = |M| + |W| + |T| in the order of "setup":
//   G[q][i] = sum over every directed path from setup datum i to dimension q of the product of
//             the arc weights on the path (a path of length 2 or 3).
// E.g. the paper's part: F3 = -W5 - T23, F4 = W1 + T23, D4 = F4 - F3 = W1 + W5 + 2 T23.
//
// Validation (checkModel) reports, with the JSON field path: empty sets, empty / duplicate ids
// (one namespace for all nodes), unknown kinds and axes, non-positive or non-finite step_mm,
// reversed or non-finite bounds, lower >= upper tolerance limits, unknown arc end points, weights
// other than +1 / -1, duplicate arcs, arcs closing a cycle, arcs in a direction other than the
// allowed ones, and (once the rest is valid) dimensions with no path to setup data.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace metrofit::setup {

enum class DatumKind { Machine, Wks, Tool };
/// "machine", "wks", "tool".
const char* toString(DatumKind kind);

struct SetupDatum {
  std::string id;
  DatumKind kind = DatumKind::Wks;
  std::optional<std::pair<double, double>> boundsMm;  ///< own correction bounds; else the model's
  int registerNumber = 0;                             ///< controller register; 0 = from the id
};

struct Feature {
  std::string id;
};

struct Dimension {
  std::string id;
  std::optional<double> nominal;  ///< nominal size (mm), checked against reports when given
  double lower = 0.0;             ///< lower tolerance limit relative to nominal (mm)
  double upper = 0.0;             ///< upper tolerance limit relative to nominal (mm)
  std::string label;              ///< DMIS label; empty = the id
  const std::string& dmisLabel() const { return label.empty() ? id : label; }
};

struct Arc {
  std::string from, to;
  double weight = 1.0;  ///< must be +1 or -1 (kept as read so that editors can show bad values)
};

/// One problem of a model, for the CLI (first one, as an error) and for editors (all of them).
struct ModelIssue {
  std::string field;               ///< JSON field path, e.g. "arcs[3].to"
  std::string message;             ///< what is wrong, one line
  std::vector<std::string> nodes;  ///< node ids involved (for highlighting in a graph editor)
};

struct Model {
  std::string source;  ///< file name for error messages (may be empty)
  std::string name;
  std::string axis = "Z";  ///< machine axis of the corrections: X, Y or Z
  double stepMm = 0.001;
  std::pair<double, double> boundsMm{-0.1, 0.1};
  std::vector<SetupDatum> setup;
  std::vector<Feature> features;
  std::vector<Dimension> dimensions;
  std::vector<Arc> arcs;

  /// Effective correction bounds of setup datum i.
  double lower(std::size_t i) const { return setup[i].boundsMm ? setup[i].boundsMm->first : boundsMm.first; }
  double upper(std::size_t i) const {
    return setup[i].boundsMm ? setup[i].boundsMm->second : boundsMm.second;
  }
  /// Index of a setup datum / dimension by id, or -1.
  int setupIndex(const std::string& id) const;
  int dimensionIndex(const std::string& id) const;
  std::vector<std::string> setupIds() const;
  std::vector<std::string> dimensionIds() const;
};

/// Every problem of the model, in a stable order (structure first, then arcs, then paths).
std::vector<ModelIssue> checkModel(const Model& model);
/// Throws ValidationError "source: field 'path': message" for the first issue of checkModel.
void validateModel(const Model& model);

/// Reads the JSON form (type errors name the field path) and validates it (validateModel).
Model modelFromJson(const nlohmann::json& json, const std::string& source);
/// Reads and validates a model file.
Model readModel(const std::string& path);
/// The JSON form (round-trips through modelFromJson).
nlohmann::json modelToJson(const Model& model);

/// The gain matrix G (|D| x |setup|, see above) of a valid model.
Eigen::MatrixXd gainMatrix(const Model& model);

}  // namespace metrofit::setup
