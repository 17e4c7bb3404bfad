// The setup model (core/setup/model.h): validation messages and the gain matrix (paper Eq. 4-5).
#include <gtest/gtest.h>

#include <map>

#include "core/common/error.h"
#include "core/setup/model.h"
#include "setup_fixtures.h"

namespace metrofit::setup {
namespace {

using nlohmann::json;

/// what() of the error modelFromJson throws for `j`, or "no error".
std::string errorOf(const json& j) {
  try {
    (void)modelFromJson(j, "m.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SetupModel, SmallModelIsValid) {
  const Model m = test::smallModel();
  EXPECT_EQ(m.setup.size(), 2u);
  EXPECT_EQ(m.dimensions[0].dmisLabel(), "POS_D1");
  EXPECT_EQ(m.dimensions[1].dmisLabel(), "D2");
  EXPECT_TRUE(checkModel(m).empty());
}

TEST(SetupModel, EmptySetsAreNamed) {
  for (const char* key : {"setup", "features", "dimensions", "arcs"}) {
    json j = test::smallModelJson();
    j[key] = json::array();
    const std::string e = errorOf(j);
    EXPECT_EQ(e.rfind(std::string("m.json: field '") + key + "': is empty: the model needs", 0), 0u) << e;
  }
}

TEST(SetupModel, IdErrors) {
  json j = test::smallModelJson();
  j["features"][1]["id"] = "W1";
  EXPECT_EQ(errorOf(j), "m.json: field 'features[1].id': duplicate id 'W1' (already used by setup[0])");
  j = test::smallModelJson();
  j["setup"][1]["id"] = "";
  EXPECT_EQ(errorOf(j), "m.json: field 'setup[1].id': empty id");
  j = test::smallModelJson();
  j["setup"][1]["kind"] = "spindle";
  EXPECT_EQ(errorOf(j),
            "m.json: field 'setup[1].kind': unknown kind 'spindle' (expected machine, wks or tool)");
  j = test::smallModelJson();
  j["dimensions"][0].erase("lower");
  EXPECT_EQ(errorOf(j), "m.json: field 'dimensions[0].lower': missing");
  j = test::smallModelJson();
  j["axis"] = "Q";
  EXPECT_EQ(errorOf(j), "m.json: field 'axis': unknown axis 'Q' (expected X, Y or Z)");
}

TEST(SetupModel, StepBoundsAndLimits) {
  json j = test::smallModelJson();
  j["step_mm"] = 0;
  EXPECT_EQ(errorOf(j), "m.json: field 'step_mm': the grid step must be positive (got 0)");
  j["step_mm"] = -0.001;
  EXPECT_EQ(errorOf(j), "m.json: field 'step_mm': the grid step must be positive (got -0.001)");
  j = test::smallModelJson();
  j["bounds_mm"] = {0.1, -0.1};
  EXPECT_EQ(errorOf(j), "m.json: field 'bounds_mm': lower bound 0.1 is above upper bound -0.1");
  j["bounds_mm"] = {0.1};
  EXPECT_EQ(errorOf(j), "m.json: field 'bounds_mm': expected [lower, upper], found 1 values");
  j = test::smallModelJson();
  j["setup"][0]["bounds_mm"] = {0.05, 0.01};
  EXPECT_EQ(errorOf(j), "m.json: field 'setup[0].bounds_mm': lower bound 0.05 is above upper bound 0.01");
  j = test::smallModelJson();
  j["dimensions"][0]["lower"] = 0.02;
  EXPECT_EQ(errorOf(j),
            "m.json: field 'dimensions[0]': lower limit 0.02 is not below upper limit 0.02 (dimension 'D1')");
  j["dimensions"][0]["lower"] = 0.03;
  EXPECT_EQ(errorOf(j),
            "m.json: field 'dimensions[0]': lower limit 0.03 is not below upper limit 0.02 (dimension 'D1')");
}

TEST(SetupModel, ArcErrors) {
  json j = test::smallModelJson();
  j["arcs"][0]["to"] = "F9";
  EXPECT_EQ(
      errorOf(j),
      "m.json: field 'arcs[0].to': unknown node 'F9' (not a setup datum, feature or dimension of the model)");
  j = test::smallModelJson();
  j["arcs"][1]["weight"] = 2;
  EXPECT_EQ(errorOf(j), "m.json: field 'arcs[1].weight': weight 2 is not +1 or -1");
  j["arcs"][1]["weight"] = 0;
  EXPECT_EQ(errorOf(j), "m.json: field 'arcs[1].weight': weight 0 is not +1 or -1");
  j = test::smallModelJson();
  j["arcs"].push_back({{"from", "W1"}, {"to", "F1"}, {"weight", -1}});
  EXPECT_EQ(errorOf(j), "m.json: field 'arcs[6]': duplicate arc W1 -> F1 (first at arcs[0])");
  j = test::smallModelJson();
  j["arcs"].push_back({{"from", "F1"}, {"to", "W1"}, {"weight", 1}});
  EXPECT_EQ(errorOf(j), "m.json: field 'arcs[6]': arc F1 -> W1 closes a cycle W1 -> F1 -> W1");
  j = test::smallModelJson();
  j["arcs"].push_back({{"from", "D1"}, {"to", "F2"}, {"weight", 1}});
  EXPECT_EQ(errorOf(j),
            "m.json: field 'arcs[6]': arc D1 -> F2 goes from dimension to feature; allowed: machine -> wks, "
            "machine/wks/tool -> feature, feature -> dimension");
  j = test::smallModelJson();
  j["arcs"].push_back({{"from", "W1"}, {"to", "D1"}, {"weight", 1}});
  EXPECT_EQ(errorOf(j),
            "m.json: field 'arcs[6]': arc W1 -> D1 goes from wks to dimension; allowed: machine -> wks, "
            "machine/wks/tool -> feature, feature -> dimension");
  j = test::smallModelJson();
  j["arcs"].push_back({{"from", "T5"}, {"to", "W1"}, {"weight", 1}});
  EXPECT_EQ(errorOf(j),
            "m.json: field 'arcs[6]': arc T5 -> W1 goes from tool to wks; allowed: machine -> wks, "
            "machine/wks/tool -> feature, feature -> dimension");
}

TEST(SetupModel, DimensionsNeedAPathToSetupData) {
  json j = test::smallModelJson();
  j["dimensions"].push_back({{"id", "D3"}, {"lower", -0.1}, {"upper", 0.1}});
  EXPECT_EQ(
      errorOf(j),
      "m.json: field 'dimensions[2]': dimension 'D3' has no path to setup data (no arc from a feature)");
  j["features"].push_back({{"id", "F3"}});
  j["arcs"].push_back({{"from", "F3"}, {"to", "D3"}, {"weight", 1}});
  EXPECT_EQ(
      errorOf(j),
      "m.json: field 'dimensions[2]': dimension 'D3' has no path to setup data (its features have no arc "
      "from a setup datum)");
  j["arcs"].push_back({{"from", "T5"}, {"to", "F3"}, {"weight", -1}});
  EXPECT_EQ(errorOf(j), "no error");
}

TEST(SetupModel, CheckModelListsEveryIssueWithItsNodes) {
  Model m = test::smallModel();
  m.arcs[1].weight = 3;
  m.dimensions[1].upper = -1.0;
  m.stepMm = 0.0;
  const auto issues = checkModel(m);
  ASSERT_EQ(issues.size(), 3u);
  EXPECT_EQ(issues[0].field, "step_mm");
  EXPECT_EQ(issues[1].field, "dimensions[1]");
  EXPECT_EQ(issues[1].nodes, std::vector<std::string>{"D2"});
  EXPECT_EQ(issues[2].field, "arcs[1].weight");
  EXPECT_EQ(issues[2].nodes, (std::vector<std::string>{"T5", "F1"}));
  EXPECT_THROW(validateModel(m), ValidationError);
}

TEST(SetupModel, JsonRoundTrip) {
  json j = test::smallModelJson();
  j["setup"][0]["bounds_mm"] = {-0.05, 0.02};
  j["setup"][1]["register"] = 12;
  const Model a = modelFromJson(j, "m.json");
  const Model b = modelFromJson(modelToJson(a), "again.json");
  EXPECT_EQ(modelToJson(a), modelToJson(b));
  EXPECT_DOUBLE_EQ(b.lower(0), -0.05);
  EXPECT_DOUBLE_EQ(b.upper(1), 0.1);
  EXPECT_EQ(b.setup[1].registerNumber, 12);
  EXPECT_FALSE(b.dimensions[1].label.size());
  EXPECT_EQ(gainMatrix(a), gainMatrix(b));
}

TEST(SetupModel, GainMatrixOfTheSmallModel) {
  const Eigen::MatrixXd g = gainMatrix(test::smallModel());
  Eigen::MatrixXd expected(2, 2);
  expected << 1, 1,  // D1 = W1 + T5
      2, 1;          // D2 = F1 - F2 = (W1 + T5) - (-W1)
  EXPECT_EQ(g, expected);
}

// The paper's formulas of the practical example (section "Practical example"), for every part:
// D1 = D2 = W1 + T5, D3 = -W5 - T23, D4 = W1 + W5 + 2 T23, D5 = D6 = D7 = -W5 - T5, and parts
// 2..4 with W2/W6, W3/W7, W4/W8.
TEST(SetupModel, GainMatrixOfThePaperExample) {
  const Model m = readModel(test::paperModelPath());
  ASSERT_EQ(m.setup.size(), 10u);
  ASSERT_EQ(m.dimensions.size(), 28u);
  const Eigen::MatrixXd g = gainMatrix(m);
  auto col = [&](const std::string& id) { return m.setupIndex(id); };
  for (int p = 1; p <= 4; ++p) {
    const std::string a = "W" + std::to_string(p), b = "W" + std::to_string(p + 4);
    std::vector<std::map<std::string, double>> rows = {
        {{a, 1}, {"T5", 1}},   {{a, 1}, {"T5", 1}},   {{b, -1}, {"T23", -1}}, {{a, 1}, {b, 1}, {"T23", 2}},
        {{b, -1}, {"T5", -1}}, {{b, -1}, {"T5", -1}}, {{b, -1}, {"T5", -1}}};
    for (int d = 1; d <= 7; ++d) {
      const int q = m.dimensionIndex("P" + std::to_string(p) + ".D" + std::to_string(d));
      ASSERT_GE(q, 0);
      Eigen::RowVectorXd expected = Eigen::RowVectorXd::Zero(10);
      for (const auto& [id, w] : rows[static_cast<std::size_t>(d - 1)]) expected(col(id)) = w;
      EXPECT_EQ(g.row(q), expected) << "P" << p << ".D" << d;
    }
  }
}

// Level 0 (machine points): the paper's first example F1 = -M1 + W1 + T1, F2 = -M1 + W2 - T1,
// D1 = F1, D2 = F1 - F2. Note: the paper's last line "= W1 + W2 + 2 T1" has a sign slip; the
// difference of its own F1 and F2 is W1 - W2 + 2 T1, which is what Eq. 4-5 give.
TEST(SetupModel, GainMatrixWithMachinePoints) {
  const json j = json::parse(R"({
    "step_mm": 0.001, "bounds_mm": [-0.1, 0.1],
    "setup": [{"id": "M1", "kind": "machine"}, {"id": "W1", "kind": "wks"}, {"id": "W2", "kind": "wks"},
              {"id": "T1", "kind": "tool"}],
    "features": [{"id": "F1"}, {"id": "F2"}],
    "dimensions": [{"id": "D1", "lower": -0.1, "upper": 0.1}, {"id": "D2", "lower": -0.1, "upper": 0.1}],
    "arcs": [{"from": "M1", "to": "W1", "weight": -1}, {"from": "M1", "to": "W2", "weight": -1},
             {"from": "W1", "to": "F1", "weight": 1}, {"from": "T1", "to": "F1", "weight": 1},
             {"from": "W2", "to": "F2", "weight": 1}, {"from": "T1", "to": "F2", "weight": -1},
             {"from": "F1", "to": "D1", "weight": 1}, {"from": "F1", "to": "D2", "weight": 1},
             {"from": "F2", "to": "D2", "weight": -1}]})");
  const Eigen::MatrixXd g = gainMatrix(modelFromJson(j, "machine.json"));
  Eigen::MatrixXd expected(2, 4);
  expected << -1, 1, 0, 1,  // D1 = -M1 + W1 + T1
      0, 1, -1, 2;          // D2 = W1 - W2 + 2 T1
  EXPECT_EQ(g, expected);
}

}  // namespace
}  // namespace metrofit::setup
