#pragma once
// Shared fixtures of the setup tests: a small valid model (two setup data, two features, two
// dimensions) whose numbers are easy to follow by hand, and the paper's example.
#include <string>

#include <nlohmann/json.hpp>

#include "core/setup/model.h"
#include "testsupport.h"

namespace metrofit::setup::test {

/// W1, T5; F1 = W1 + T5, F2 = -W1; D1 = F1, D2 = F1 - F2 = 2 W1 + T5.
inline nlohmann::json smallModelJson() {
  return nlohmann::json::parse(R"({
    "name": "small", "axis": "Z", "step_mm": 0.001, "bounds_mm": [-0.1, 0.1],
    "setup": [{"id": "W1", "kind": "wks"}, {"id": "T5", "kind": "tool"}],
    "features": [{"id": "F1"}, {"id": "F2"}],
    "dimensions": [{"id": "D1", "nominal": 42.0, "lower": -0.02, "upper": 0.02, "label": "POS_D1"},
                   {"id": "D2", "nominal": 18.5, "lower": -0.05, "upper": 0.03}],
    "arcs": [{"from": "W1", "to": "F1", "weight": 1}, {"from": "T5", "to": "F1", "weight": 1},
             {"from": "W1", "to": "F2", "weight": -1},
             {"from": "F1", "to": "D1", "weight": 1}, {"from": "F1", "to": "D2", "weight": 1},
             {"from": "F2", "to": "D2", "weight": -1}]})");
}

inline Model smallModel() {
  return modelFromJson(smallModelJson(), "m.json");
}

inline std::string paperModelPath() {
  return (metrofit::test::sourceDir() / "resources/demo/setup/paper_example.json").string();
}

/// The paper example's CMM report series (CSV): 3 parts x 28 dimensions.
inline std::string paperReportPath() {
  return (metrofit::test::sourceDir() / "resources/demo/setup/paper_example_report.csv").string();
}

}  // namespace metrofit::setup::test
