#include "core/project/project.h"

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/io/json_util.h"
#include "testsupport.h"

namespace metrofit {
namespace {

Project sample() {
  Project p;
  p.name = "Cell 4 — Ø 12 bores";  // non-ASCII survives
  p.description = "two lines\nof text";
  p.datasets.push_back({"log", dataset_kind::kThermalLog, "data/log.csv", "8 h test", "", {}});
  p.datasets.push_back({"pts", dataset_kind::kProbePoints, "/abs/pts.csv", "", "MIT", {}});
  p.studies["thermal"] = {{"target", "disp_z_um"}, {"inputs", {"T1", "T2"}}, {"future_key", 3}};
  p.results["thermal"] = {{"heldout_rmse", 0.42}};
  return p;
}

std::string loadError(const std::string& text) {
  try {
    (void)Project::fromJson(parseJson(text, "p.metrofit"), "p.metrofit");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Project, SaveLoadRoundTrip) {
  test::TempDir dir;
  const Project p = sample();
  saveProject(p, dir.file("p.metrofit"));
  const Project q = loadProject(dir.file("p.metrofit"));
  EXPECT_EQ(p, q);
  EXPECT_EQ(q.studies["thermal"]["future_key"], 3);  // unknown keys preserved
  EXPECT_EQ(test::listFolder(dir.path()), (std::vector<std::string>{"p.metrofit"}));
  const std::string text = test::readText(dir.file("p.metrofit"));
  EXPECT_NE(text.find("\"format\": \"metrofit-project\""), std::string::npos);
  EXPECT_NE(text.find("\"version\": 1"), std::string::npos);
}

TEST(Project, LookupAndPaths) {
  const Project p = sample();
  ASSERT_NE(p.dataset("pts"), nullptr);
  EXPECT_EQ(p.dataset("nope"), nullptr);
  EXPECT_EQ(p.firstOfKind(dataset_kind::kThermalLog)->id, "log");
  EXPECT_EQ(resolveDatasetPath("/home/u/proj/p.metrofit", *p.dataset("log")), "/home/u/proj/data/log.csv");
  EXPECT_EQ(resolveDatasetPath("/home/u/proj/p.metrofit", *p.dataset("pts")), "/abs/pts.csv");
}

TEST(Project, InvalidFilesGiveOneLineErrors) {
  EXPECT_EQ(loadError("{\"format\": \"metrofit-project\", \"version\": 1,}"),
            "p.metrofit:1:45: invalid JSON: syntax error while parsing object key - unexpected '}'; expected "
            "string literal");
  EXPECT_EQ(loadError("[]"), "p.metrofit: field '(top level)': expected a JSON object, found array");
  EXPECT_EQ(loadError("{\"version\": 1}"), "p.metrofit: field 'format': missing");
  EXPECT_EQ(loadError("{\"format\": \"x\", \"version\": 1}"),
            "p.metrofit: field 'format': is 'x', expected 'metrofit-project' (not a Metrofit project)");
  EXPECT_EQ(loadError("{\"format\": \"metrofit-project\", \"version\": 9}"),
            "p.metrofit: field 'version': format version 9 was written by a newer Metrofit; this build reads "
            "up to 1");
  EXPECT_EQ(loadError("{\"format\": \"metrofit-project\", \"version\": \"1\"}"),
            "p.metrofit: field 'version': expected an integer, found string");
  EXPECT_EQ(loadError(R"({"format": "metrofit-project", "version": 1, "datasets": [
      {"id": "a", "kind": "thermal_log", "path": "a.csv"}, {"id": "a", "kind": "thermal_log", "path": "b.csv"}]})"),
            "p.metrofit: field 'datasets[1].id': duplicate dataset id 'a'");
  EXPECT_EQ(
      loadError(R"({"format": "metrofit-project", "version": 1, "datasets": [{"id": "a", "kind": "x"}]})"),
      "p.metrofit: field 'datasets[0].path': missing");
  EXPECT_EQ(loadError(R"({"format": "metrofit-project", "version": 1, "studies": []})"),
            "p.metrofit: field 'studies': expected an object, found array");
}

TEST(Project, DeeplyNestedJsonIsRejectedBeforeParsing) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  const std::string msg = loadError(deep);
  EXPECT_NE(msg.find("nested deeper than 64 levels"), std::string::npos) << msg;
  EXPECT_NE(msg.find("p.metrofit:1:65"), std::string::npos) << msg;
}

TEST(Project, NumbersBeyondADoubleAreAParseErrorWithTheirPlace) {
  // Found by fuzz/fuzz_project: nlohmann throws out_of_range (not parse_error) for 1e5554.
  const std::string msg = loadError("{\n  \"format\": \"metrofit-project\",\n  \"version\": 7777e5554}");
  EXPECT_NE(msg.find("p.metrofit:3:14"), std::string::npos) << msg;
  EXPECT_NE(msg.find("number overflow"), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << "one line";
}

TEST(Project, EmptyAndBinaryFiles) {
  EXPECT_NE(loadError("").find("invalid JSON"), std::string::npos);
  EXPECT_NE(loadError("\xFF\xFE{").find("UTF-16"), std::string::npos);
  test::TempDir dir;
  EXPECT_THROW((void)loadProject(dir.file("missing.metrofit")), FileError);
}

}  // namespace
}  // namespace metrofit
