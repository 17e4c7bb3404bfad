// Reading settings of a dataset in the project file (docs/file-formats.md#own-data-in-a-project):
// "header_lines", "comment", "skip_bad_rows" and "dmis" {"ta_meaning", "ta_sign"}, and embedding a file
// (data/<id>.<ext>). The files are written here from the formats' own descriptions (CSV: RFC 4180 with
// a preamble; DMIS: the statement syntax of the standard), not by Metrofit's writers.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/io/json_util.h"
#include "core/project/datasets.h"
#include "core/project/project.h"
#include "core/setup/model.h"
#include "core/setup/report.h"
#include "core/study/setup_study.h"
#include "testsupport.h"

namespace metrofit {
namespace {

namespace fs = std::filesystem;

std::string loadError(const std::string& text) {
  try {
    (void)Project::fromJson(parseJson(text, "p.metrofit"), "p.metrofit");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string withDataset(const std::string& entry) {
  return R"({"format": "metrofit-project", "version": 1, "datasets": [)" + entry + "]}";
}

// A log as an instrument writes it: two preamble lines that are not comments, a '//' comment, then
// the header and the rows. Rows 2 and 4 cannot be read ('n/a' and a missing field).
const char* kPreambleLog =
    "Thermal test rig 3\n"
    "Operator: K.\n"
    "// sensors calibrated\n"
    "time_min,T1,disp_z_um\n"
    "0,20.0,0.0\n"
    "10,n/a,1.5\n"
    "20,21.0,2.5\n"
    "30,21.5\n"
    "40,22.0,4.0\n";

TEST(DatasetOptions, NewKeysRoundTripAndAreWrittenOnlyWhenSet) {
  test::TempDir dir;
  Project p;
  DatasetRef log{"log", dataset_kind::kThermalLog, "log.csv", "", "", {}};
  log.csv.headerLines = 2;
  log.csv.commentPrefix = "//";
  log.csv.skipBadRows = true;
  DatasetRef dmis{"holes", dataset_kind::kDmis, "holes.dmi", "", "", {}};
  dmis.dmis.taMeaning = setup::DmisTaMeaning::Actual;
  dmis.dmis.signFollowsNominal = true;
  DatasetRef plain{"plain", dataset_kind::kDmis, "plain.dmi", "", "", {}};
  p.datasets = {log, dmis, plain};
  saveProject(p, dir.file("p.metrofit"));
  EXPECT_EQ(loadProject(dir.file("p.metrofit")), p);
  const nlohmann::json j = readJsonFile(dir.file("p.metrofit"));
  EXPECT_EQ(j["datasets"][0]["header_lines"], 2);
  EXPECT_EQ(j["datasets"][0]["comment"], "//");
  EXPECT_EQ(j["datasets"][0]["skip_bad_rows"], true);
  EXPECT_EQ(j["datasets"][1]["dmis"], (nlohmann::json{{"ta_meaning", "actual"}, {"ta_sign", "nominal"}}));
  // Defaults are not written: the entry has only the keys of the format before these settings.
  EXPECT_EQ(j["datasets"][2], (nlohmann::json{{"id", "plain"}, {"kind", "dmis"}, {"path", "plain.dmi"}}));
}

TEST(DatasetOptions, OldProjectFilesLoadUnchanged) {
  // A project file as written before these keys: dialect and mapping only.
  const std::string text = withDataset(
      R"({"id": "t", "kind": "thermal_log", "path": "t.csv", "delimiter": ";", "decimal": ",",
          "map": {"time_min": "Zeit"}})");
  const Project p = Project::fromJson(parseJson(text, "old.metrofit"), "old.metrofit");
  ASSERT_EQ(p.datasets.size(), 1u);
  const DatasetRef& d = p.datasets[0];
  EXPECT_EQ(d.csv.headerLines, -1);
  EXPECT_EQ(d.csv.commentPrefix, "");
  EXPECT_FALSE(d.csv.skipBadRows);
  EXPECT_EQ(d.dmis.taMeaning, setup::DmisTaMeaning::Auto);
  EXPECT_FALSE(d.dmis.signFollowsNominal);
  // Saved again it has the same dataset keys as before.
  const nlohmann::json back = p.toJson()["datasets"][0];
  EXPECT_EQ(back, (nlohmann::json{{"id", "t"},
                                  {"kind", "thermal_log"},
                                  {"path", "t.csv"},
                                  {"delimiter", ";"},
                                  {"decimal", ","},
                                  {"map", {{"time_min", "Zeit"}}}}));
}

TEST(DatasetOptions, BadValuesNameTheDatasetAndTheField) {
  EXPECT_EQ(loadError(withDataset(R"({"id": "holes", "kind": "dmis", "path": "h.dmi",
                                     "dmis": {"ta_meaning": "measured"}})")),
            "p.metrofit: field 'datasets[0].dmis.ta_meaning': dataset 'holes': 'measured' is not auto, "
            "deviation or actual");
  EXPECT_EQ(loadError(withDataset(R"({"id": "holes", "kind": "dmis", "path": "h.dmi",
                                     "dmis": {"ta_sign": "minus"}})")),
            "p.metrofit: field 'datasets[0].dmis.ta_sign': dataset 'holes': 'minus' is not plain or nominal");
  EXPECT_EQ(
      loadError(withDataset(R"({"id": "holes", "kind": "dmis", "path": "h.dmi",
                                     "dmis": {"meaning": "actual"}})")),
      "p.metrofit: field 'datasets[0].dmis.meaning': dataset 'holes': unknown key (dmis takes ta_meaning "
      "and ta_sign)");
  EXPECT_EQ(
      loadError(withDataset(R"({"id": "log", "kind": "thermal_log", "path": "t.csv", "header_lines": -2})")),
      "p.metrofit: field 'datasets[0].header_lines': dataset 'log': must be a number of lines from 0 to "
      "10000");
  EXPECT_EQ(
      loadError(withDataset(R"({"id": "log", "kind": "thermal_log", "path": "t.csv", "comment": ""})")),
      "p.metrofit: field 'datasets[0].comment': dataset 'log': must be 1 to 16 characters, not starting "
      "with a blank, without quotes or line breaks");
  EXPECT_NE(
      loadError(withDataset(R"({"id": "log", "kind": "thermal_log", "path": "t.csv", "skip_bad_rows": 1})"))
          .find("datasets[0].skip_bad_rows"),
      std::string::npos);
}

TEST(DatasetOptions, HeaderLinesAndCommentPrefixAreHonouredByTheReader) {
  CsvReadOptions o;
  // Detected: the first preamble line is taken for the header and the rows are ragged.
  EXPECT_THROW((void)parseCsv(kPreambleLog, "log.csv", o), ParseError);
  o.headerLines = 2;
  o.commentPrefix = "//";
  o.skipBadRows = true;
  const CsvTable t = parseCsv(kPreambleLog, "log.csv", o);
  EXPECT_EQ(t.header(), (std::vector<std::string>{"time_min", "T1", "disp_z_um"}));
  EXPECT_EQ(t.headerLineNumber(), 4);
  EXPECT_EQ(t.comments(), (std::vector<std::string>{" sensors calibrated"}));
  EXPECT_EQ(t.numericColumn("time_min"), (std::vector<double>{0, 20, 40}));
  EXPECT_EQ(t.numericColumn("disp_z_um"), (std::vector<double>{0.0, 2.5, 4.0}));
  // The two unreadable rows: file lines 6 and 8, data rows 2 and 4.
  ASSERT_EQ(t.skippedRows().size(), 2u);
  EXPECT_EQ(describeRowProblem(t.skippedRows()[0]), "line 6 (row 2), column 'T1': 'n/a' is not a number");
  EXPECT_EQ(describeRowProblem(t.skippedRows()[1]),
            "line 8 (row 4): row has 2 fields, the header (line 4) has 3");
  EXPECT_EQ(csvRowProblems(kPreambleLog, "log.csv", o), t.skippedRows());
  // Strict (the default): the ragged row is an error when the file is parsed, the 'n/a' when T1 is read.
  o.skipBadRows = false;
  try {
    (void)parseCsv(kPreambleLog, "log.csv", o);
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), "log.csv:8:3: row has 2 fields, the header (line 4) has 3");
  }
  std::string firstFour(kPreambleLog);
  firstFour.erase(firstFour.find("30,21.5\n"), 8);
  try {
    (void)parseCsv(firstFour, "log.csv", o).numericColumn("T1");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), "log.csv:6:2: field 'T1': 'n/a' is not a number");
  }
  // Without the comment prefix, the '//' line is the header.
  o.commentPrefix.clear();
  o.skipBadRows = true;
  EXPECT_EQ(parseCsv(kPreambleLog, "log.csv", o).header().at(0), "// sensors calibrated");
}

TEST(DatasetOptions, AProjectDatasetIsReadWithItsSettings) {
  test::TempDir dir;
  test::writeText(dir.file("log.csv"), kPreambleLog);
  Project p;
  AddDatasetRequest r{"thermal-log", dir.file("log.csv"), "", {}, ""};
  try {
    (void)addDataset(p, dir.file("p.metrofit"), r);
    FAIL() << "strict: the first bad row is an error";
  } catch (const InputError& e) {
    // The header is detected below the preamble (names above numbers), so the error is the ragged row.
    EXPECT_NE(std::string(e.what()).find("log.csv:8:3: row has 2 fields, the header (line 4) has 3"),
              std::string::npos)
        << e.what();
  }
  r.csv.headerLines = 2;
  r.csv.commentPrefix = "//";
  r.csv.skipBadRows = true;
  const DatasetRef ref = addDataset(p, dir.file("p.metrofit"), r);
  saveProject(p, dir.file("p.metrofit"));
  const Project q = loadProject(dir.file("p.metrofit"));
  const DatasetSummary s = summarizeDataset(dir.file("p.metrofit"), *q.dataset(ref.id));
  EXPECT_EQ(s.rows, 3);
  EXPECT_EQ(s.skipped.size(), 2u);
  const nlohmann::json list = datasetListJson(q, dir.file("p.metrofit"));
  EXPECT_EQ(list[0]["skipped_rows"], 2);
  EXPECT_EQ(readDatasetTable(dir.file("p.metrofit"), *q.dataset(ref.id)).rowCount(), 3u);
  // Header options on a kind that is not CSV are refused.
  AddDatasetRequest dm{"dmis", dir.file("log.csv"), "x", {}, ""};
  dm.csv.headerLines = 1;
  EXPECT_THROW((void)addDataset(p, dir.file("p.metrofit"), dm), ValidationError);
}

TEST(DatasetOptions, EmbedCopiesIntoTheDataFolderAndNeverOverwrites) {
  test::TempDir dir;
  fs::create_directories(dir.file("proj"));
  test::writeText(dir.file("elsewhere.CSV"), "x,y\n1,2\n3,4\n");
  const std::string projectPath = dir.file("proj/p.metrofit");
  Project p;
  AddDatasetRequest r{"feature-series", dir.file("elsewhere.CSV"), "bores", {}, ""};
  r.embed = true;
  const DatasetRef ref = addDataset(p, projectPath, r);
  EXPECT_EQ(ref.path, "data/bores.csv");
  EXPECT_EQ(test::readText(dir.file("proj/data/bores.csv")), "x,y\n1,2\n3,4\n");
  EXPECT_EQ(test::readText(resolveDatasetPath(projectPath, ref)), "x,y\n1,2\n3,4\n");
  // Another project in the same folder adding the same id: the copy exists, nothing is overwritten.
  test::writeText(dir.file("other.csv"), "x,y\n9,9\n");
  Project p2;
  AddDatasetRequest r2{"feature-series", dir.file("other.csv"), "bores", {}, ""};
  r2.embed = true;
  try {
    (void)addDataset(p2, projectPath, r2);
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("bores.csv: already exists; an embedded copy never overwrites"),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(p2.datasets.empty());
  EXPECT_EQ(test::readText(dir.file("proj/data/bores.csv")), "x,y\n1,2\n3,4\n");
  // Default: linked, not copied.
  r2.embed = false;
  const DatasetRef linked = addDataset(p2, projectPath, r2);
  EXPECT_EQ(linked.path, "../other.csv");
}

// DMIS output written from the statement syntax: POS_D1 as nominal and actual feature (the deviation
// is FA - F along z: 0.008), D2 as a tolerance actual only (18.52, the actual diameter; nominal 18.5).
const char* kModel = R"({"name": "small", "step_mm": 0.001, "bounds_mm": [-0.1, 0.1],
  "setup": [{"id": "W1", "kind": "wks"}, {"id": "T5", "kind": "tool"}],
  "features": [{"id": "F1"}, {"id": "F2"}],
  "dimensions": [{"id": "D1", "nominal": 42.0, "lower": -0.02, "upper": 0.02, "label": "POS_D1"},
                 {"id": "D2", "nominal": 18.5, "lower": -0.05, "upper": 0.03}],
  "arcs": [{"from": "W1", "to": "F1", "weight": 1}, {"from": "T5", "to": "F1", "weight": 1},
           {"from": "W1", "to": "F2", "weight": -1}, {"from": "F1", "to": "D1", "weight": 1},
           {"from": "F1", "to": "D2", "weight": 1}, {"from": "F2", "to": "D2", "weight": -1}]})";
const char* kDmis =
    "DMISMN/'part 7',05.3\n"
    "UNITS/MM,ANGDEG\n"
    "F(POS_D1)=FEAT/POINT,CART,10,20,42,0,0,1\n"
    "FA(POS_D1)=FEAT/POINT,CART,10,20,42.008,0,0,1\n"
    "TA(D2)=TOL/DIAM,18.52,INTOL\n"
    "ENDFIL\n";

TEST(DatasetOptions, TheSetupStudyReadsADmisDatasetWithItsSetting) {
  test::TempDir dir;
  test::writeText(dir.file("m.json"), kModel);
  test::writeText(dir.file("part7.dmi"), kDmis);
  Project p;
  (void)addDataset(p, dir.file("p.metrofit"), {"setup-model", dir.file("m.json"), "model", {}, ""});
  AddDatasetRequest r{"dmis", dir.file("part7.dmi"), "part7", {}, ""};
  r.dmis.taMeaning = setup::DmisTaMeaning::Deviation;
  (void)addDataset(p, dir.file("p.metrofit"), r);
  saveProject(p, dir.file("p.metrofit"));
  SetupStudyFiles files = setupStudyFiles(loadProject(dir.file("p.metrofit")), dir.file("p.metrofit"));
  EXPECT_EQ(files.reportDmis.taMeaning, setup::DmisTaMeaning::Deviation);
  const setup::Model model = setup::readModel(files.modelPath);
  // Read as a deviation, 18.52 mm is far outside the band of D2: the reader refuses it.
  EXPECT_THROW((void)setup::readMeasurements({files.reportPath}, model, files.reportCsv, files.reportDmis),
               ValidationError);
  p.datasets[1].dmis.taMeaning = setup::DmisTaMeaning::Actual;
  saveProject(p, dir.file("p.metrofit"));
  files = setupStudyFiles(loadProject(dir.file("p.metrofit")), dir.file("p.metrofit"));
  const setup::Measurements m =
      setup::readMeasurements({files.reportPath}, model, files.reportCsv, files.reportDmis);
  EXPECT_NEAR(m.deviationMm[0], 0.008, 1e-12);
  EXPECT_NEAR(m.deviationMm[1], 18.52 - 18.5, 1e-12);
  // DMIS settings on a CSV dataset are refused.
  test::writeText(dir.file("s.csv"), "x\n1\n");
  AddDatasetRequest csv{"feature-series", dir.file("s.csv"), "", {}, ""};
  csv.dmis.signFollowsNominal = true;
  EXPECT_THROW((void)addDataset(p, dir.file("p.metrofit"), csv), ValidationError);
}

}  // namespace
}  // namespace metrofit
