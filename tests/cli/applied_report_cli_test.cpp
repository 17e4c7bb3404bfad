// `metrofit-cli report --project` with effects applied on the diagnosis page: the setup and
// matching sections include them (the run succeeds), and a bad entry in
// studies.diagnosis.<setup|matching>.applied ends with exit 2 and one line naming the project file and
// the field.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "testsupport.h"

namespace metrofit::test {
namespace {

/// The bundled demo project in `tmp`, its setup and matching studies on `setupReport` /
/// `matchingPoints` (by default the diagnosis data, the datasets the diagnosis ran on), with
/// `setupApplied` / `matchingApplied` as the applied effects.
void writeProject(const TempDir& tmp, const nlohmann::json& setupApplied,
                  const nlohmann::json& matchingApplied,
                  const std::string& setupReport = "diagnose_setup_report",
                  const std::string& matchingPoints = "diagnose_probe") {
  namespace fs = std::filesystem;
  const fs::path demo = sourceDir() / "resources/demo";
  fs::create_directories(tmp.path() / "data");
  for (const char* f : {"diagnose_setup_report.csv", "diagnose_probe.csv", "probe_s_piece.csv"})
    fs::copy_file(demo / "data" / f, tmp.path() / "data" / f, fs::copy_options::overwrite_existing);
  for (const char* f : {"paper_example.json", "paper_example_report.csv"})
    fs::copy_file(demo / "setup" / f, tmp.path() / "data" / f, fs::copy_options::overwrite_existing);
  nlohmann::json p = nlohmann::json::parse(readText((demo / "demo.metrofit").string()));
  // Only the setup model, its reports and the probe points: the report has the setup, matching and
  // diagnosis sections.
  nlohmann::json datasets = nlohmann::json::array();
  for (const auto& d : p["datasets"]) {
    const std::string id = d["id"];
    if (id == "setup_model" || id == "setup_report" || id == "diagnose_setup_report" ||
        id == "diagnose_probe" || id == "probe_s_piece")
      datasets.push_back(d);
  }
  p["datasets"] = datasets;
  p["studies"] = {
      {"setup", {{"model", "setup_model"}, {"dataset", setupReport}, {"method", "exact"}}},
      {"matching", {{"dataset", matchingPoints}, {"tolerance_mm", 0.035}, {"method", "closed-form"}}},
      {"diagnosis",
       {{"setup",
         {{"model", "setup_model"}, {"dataset", "diagnose_setup_report"}, {"applied", setupApplied}}},
        {"matching",
         {{"dataset", "diagnose_probe"}, {"tolerance_mm", 0.035}, {"applied", matchingApplied}}}}}};
  writeText(tmp.file("p.metrofit"), p.dump(2));
}

const nlohmann::json kWear = {{{"name", "tool_wear:T23"}, {"parameters", {{"mm_per_part", 0.0021}}}}};
const nlohmann::json kScale = {{{"name", "scale"}, {"parameters", {{"ppm", 94.0}}}}};

TEST(AppliedReportCli, ReportWithAppliedEffectsIsWritten) {
  const TempDir tmp;
  writeProject(tmp, kWear, kScale);
  const CliRun r = cli("report --project p.metrofit --out r.pdf", tmp);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.rfind("report: r.pdf, ", 0), 0u) << r.err;
  ASSERT_TRUE(std::filesystem::exists(tmp.file("r.pdf")));
  EXPECT_GT(std::filesystem::file_size(tmp.file("r.pdf")), 10000u);
  // The sections' text, where poppler's pdftotext is installed.
  if (std::system("command -v pdftotext > /dev/null 2>&1") == 0) {
    const std::string cmd = "pdftotext -layout '" + tmp.file("r.pdf") + "' '" + tmp.file("r.txt") + "'";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    const std::string text = readText(tmp.file("r.txt"));
    EXPECT_NE(text.find("predicted for part 13"), std::string::npos);
    EXPECT_NE(text.find("tool_wear:T23 (0.0021 mm/part) (diagnosis, Apply)"), std::string::npos);
    EXPECT_NE(text.find("rms 0.0056 mm (declared model 0.0083 mm)"), std::string::npos);
    EXPECT_NE(text.find("rms 0.0051 mm from the other parts (declared model 0.0116 mm)"), std::string::npos);
    EXPECT_NE(text.find("Includes applied effects: scale (+94 ppm)"), std::string::npos);
  }
}

TEST(AppliedReportCli, StudiesOnOtherDatasetsKeepTheDeclaredModel) {
  // The effects were estimated on diagnose_setup_report / diagnose_probe: the studies of the other
  // report and the other part's points give the report of the declared model (E0), the same as
  // without any applied effect.
  const TempDir other, none;
  writeProject(other, kWear, kScale, "setup_report", "probe_s_piece");
  writeProject(none, nlohmann::json::array(), nlohmann::json::array(), "setup_report", "probe_s_piece");
  for (const TempDir* tmp : {&other, &none}) {
    const CliRun r = cli("report --project p.metrofit --out r.pdf", *tmp);
    ASSERT_EQ(r.code, 0) << r.err;
    ASSERT_TRUE(std::filesystem::exists(tmp->file("r.pdf")));
  }
  if (std::system("command -v pdftotext > /dev/null 2>&1") == 0) {
    auto text = [](const TempDir& tmp) {
      const std::string cmd = "pdftotext -layout '" + tmp.file("r.pdf") + "' '" + tmp.file("r.txt") + "'";
      EXPECT_EQ(std::system(cmd.c_str()), 0);
      // The report's date (yyyy-MM-dd HH:mm) may differ by a minute between the two runs.
      static const std::regex date(R"(\d{4}-\d{2}-\d{2} \d{2}:\d{2})");
      return std::regex_replace(readText(tmp.file("r.txt")), date, "DATE");
    };
    const std::string withEffects = text(other), declared = text(none);
    EXPECT_EQ(withEffects.find("(diagnosis, Apply)"), std::string::npos);
    EXPECT_EQ(withEffects.find("Includes applied effects"), std::string::npos);
    EXPECT_NE(withEffects.find("mean over its rows"), std::string::npos);
    EXPECT_EQ(withEffects, declared);
  }
}

TEST(AppliedReportCli, ReportSpeaksTheLanguageAskedFor) {
  // The GUI's Export report passes its own language (--lang); the numbers keep the decimal point.
  const TempDir tmp;
  writeProject(tmp, kWear, kScale);
  for (const auto& [lang, heading] :
       {std::pair<std::string, std::string>{"de", "Was an der Maschine zu ändern ist"},
        {"pl", "Co zmienić na maszynie"},
        {"en", "What to change on the machine"}}) {
    SCOPED_TRACE(lang);
    const CliRun r = cli("report --project p.metrofit --out r_" + lang + ".pdf --lang " + lang, tmp);
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string cmd =
        "pdftotext -layout '" + tmp.file("r_" + lang + ".pdf") + "' '" + tmp.file("r_" + lang + ".txt") + "'";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << "pdftotext (poppler-utils) is a test dependency";
    const std::string text = readText(tmp.file("r_" + lang + ".txt"));
    EXPECT_NE(text.find(heading), std::string::npos);
    if (lang != "en") {
      EXPECT_EQ(text.find("What to change on the machine"), std::string::npos);
      EXPECT_EQ(text.find("Includes applied effects"), std::string::npos);
    }
    if (lang == "de") {
      // Table columns are at least as wide as their longest word: German study names are not broken
      // inside ("Lageausrichtun" / "g" in the summary tables).
      EXPECT_TRUE(std::regex_search(text, std::regex("Lageausrichtung")));
      EXPECT_FALSE(std::regex_search(text, std::regex("Lageausrichtun(?!g)"))) << text;
      EXPECT_FALSE(std::regex_search(text, std::regex("Einrichtdatenkorrek(?!tur)"))) << text;
    }
    EXPECT_NE(text.find("0.0021 mm"), std::string::npos) << "numbers keep the decimal point";
    EXPECT_EQ(text.find("0,0021"), std::string::npos);
  }
  // A project nobody named: core's "Untitled" is written in the report's language.
  nlohmann::json unnamed = nlohmann::json::parse(readText(tmp.file("p.metrofit")));
  unnamed.erase("name");
  writeText(tmp.file("unnamed.metrofit"), unnamed.dump(2));
  const CliRun u = cli("report --project unnamed.metrofit --out u.pdf --lang de", tmp);
  ASSERT_EQ(u.code, 0) << u.err;
  ASSERT_EQ(
      std::system(("pdftotext -layout '" + tmp.file("u.pdf") + "' '" + tmp.file("u.txt") + "'").c_str()), 0);
  const std::string unnamedText = readText(tmp.file("u.txt"));
  EXPECT_NE(unnamedText.find("Projekt „Unbenannt“"), std::string::npos);
  EXPECT_EQ(unnamedText.find("Untitled"), std::string::npos);

  const CliRun bad = cli("report --project p.metrofit --out r_fr.pdf --lang fr", tmp);
  EXPECT_EQ(bad.code, 2) << bad.err;
  EXPECT_EQ(lines(bad.err), 1) << bad.err;
  EXPECT_NE(bad.err.find("--lang"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.file("r_fr.pdf")));
}

TEST(AppliedReportCli, BadSetupEntryNamesTheField) {
  const TempDir tmp;
  writeProject(tmp, {{{"name", "tool_wear:T99"}, {"parameters", {{"mm_per_part", 0.0021}}}}}, kScale);
  const CliRun r = cli("report --project p.metrofit --out r.pdf", tmp);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("studies.diagnosis.setup.applied[0].name"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.file("r.pdf")));
}

TEST(AppliedReportCli, BadMatchingEntryNamesTheField) {
  const TempDir tmp;
  writeProject(tmp, kWear, {{{"name", "scale"}, {"parameters", {{"ppm", "warm"}}}}});
  const CliRun r = cli("report --project p.metrofit --out r.pdf", tmp);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("studies.diagnosis.matching.applied[0].parameters.ppm"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.file("r.pdf")));
}

}  // namespace
}  // namespace metrofit::test
