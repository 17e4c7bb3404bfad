// The bad-input catalogue through metrofit-cli: every case of bad_input_cases.h must
// exit with code 2 and one line on stderr that names the file and the line/column or the field,
// print nothing on stdout, leave no output file (and an existing one unchanged), no temporary file,
// and finish within the timeout.
//
// The catalogue document docs/bad-input-catalogue.md is generated from the messages of a run:
//   METROFIT_WRITE_CATALOGUE=1 ctest --test-dir build -R bad_input_catalogue_test.BadInputCatalogue.Document
// (or METROFIT_WRITE_CATALOGUE=<path> to write elsewhere).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>

#include "bad_input_cases.h"
#include "cli/cli_runner.h"
#include "testsupport.h"

namespace metrofit::test::bad {
namespace {

const std::string kPrevious = "previous result\n";

struct Observed {
  CliResult run;
  std::vector<std::string> before, after;
};

Observed runCase(const Case& c, const TempDir& tmp) {
  const std::filesystem::path work = tmp.path() / "case";
  const std::filesystem::path capture = tmp.path() / "capture";
  std::filesystem::create_directories(work);
  std::filesystem::create_directories(capture);
  for (const auto& f : c.files) {
    std::filesystem::create_directories((work / f.name).parent_path());
    writeText((work / f.name).string(), f.content);
  }
  if (c.preexistingOut) {
    for (const auto& o : c.outs) writeText((work / o).string(), kPrevious);
  }
  Observed obs;
  obs.before = listFolder(work);
  obs.run = runCli(c.args, work, capture);
  obs.after = listFolder(work);
  return obs;
}

/// Markdown table cells: no '|' and no line ends.
std::string cell(std::string s) {
  std::string out;
  for (char ch : s) {
    if (ch == '|')
      out += "\\|";
    else if (ch == '\n' || ch == '\r')
      out += ' ';
    else
      out += ch;
  }
  return out;
}

/// One table row; the case folder (absolute in `demo`'s message) is left out so the document is stable.
std::string row(const Case& c, const CliResult& r, const std::filesystem::path& work) {
  std::string m = message(r.err);
  const std::string folder = work.string() + "/";
  for (auto at = m.find(folder); at != std::string::npos; at = m.find(folder)) m.erase(at, folder.size());
  return "| " + c.id + " | " + cell(c.reader) + ": " + cell(c.description) + " | `metrofit-cli " +
         cell(c.args) + "` | " + std::to_string(r.code) + " | " + cell(m) + " |";
}

class BadInput : public ::testing::TestWithParam<Case> {};

TEST_P(BadInput, ExitsTwoWithOneLineNamingFileAndPlace) {
  const Case& c = GetParam();
  TempDir tmp;
  const Observed obs = runCase(c, tmp);
  const CliResult& r = obs.run;
  std::printf("%s\n", row(c, r, tmp.path() / "case").c_str());
  SCOPED_TRACE("metrofit-cli " + c.args + "\nstderr: " + r.err);

  EXPECT_FALSE(r.timedOut) << "no answer within " << kTimeoutSeconds << " s";
  EXPECT_LT(r.seconds, 30.0);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << "exactly one line on stderr";
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.back(), '\n');
  EXPECT_EQ(r.err.rfind("metrofit-cli: ", 0), 0u);
  EXPECT_EQ(r.err.find("internal error"), std::string::npos);
  for (const auto& e : c.expect) EXPECT_NE(r.err.find(e), std::string::npos) << "expected '" << e << "'";
  EXPECT_EQ(r.out, "") << "no partial result on stdout";

  const std::filesystem::path work = tmp.path() / "case";
  for (const auto& o : c.outs) {
    if (c.preexistingOut) {
      EXPECT_EQ(readText((work / o).string()), kPrevious) << o << " was changed";
    } else {
      EXPECT_FALSE(std::filesystem::exists(work / o)) << o << " was written";
    }
  }
  EXPECT_EQ(obs.after, obs.before) << "files appeared or vanished (temporary files left behind?)";
}

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
  return info.param.id;
}

INSTANTIATE_TEST_SUITE_P(Catalogue, BadInput, ::testing::ValuesIn(cases()), caseName);

TEST(BadInputCatalogue, CoversTheIssueList) {
  const auto all = cases();
  EXPECT_GE(all.size(), 45u);
  std::set<std::string> ids;
  for (const auto& c : all) EXPECT_TRUE(ids.insert(c.id).second) << "duplicate id " << c.id;
  // Every reader and every subcommand of metrofit-cli appears at least once.
  for (const char* word : {"demo",
                           "report",
                           "setup",
                           "simulate setup",
                           "simulate thermal",
                           "simulate probe",
                           "simulate circular",
                           "simulate bores",
                           "match",
                           "kinematic identify",
                           "kinematic compensate",
                           "kinematic positioning",
                           "spc",
                           "thermal fit",
                           "thermal predict",
                           "thermal hysteresis",
                           "thermal modular",
                           "thermal simulate",
                           "diagnose thermal",
                           "diagnose kinematic",
                           "diagnose setup",
                           "diagnose matching",
                           "fit-element",
                           "--machine-def",
                           "p.dmo",
                           "holes.txt"}) {
    const bool found = std::any_of(all.begin(), all.end(), [&](const Case& c) {
      return (" " + c.args + " ").find(std::string(word) + " ") != std::string::npos;
    });
    EXPECT_TRUE(found) << "no case runs '" << word << "'";
  }
}

TEST(BadInputCatalogue, Document) {
  const std::string target = env("METROFIT_WRITE_CATALOGUE");
  if (target.empty()) GTEST_SKIP() << "set METROFIT_WRITE_CATALOGUE=1 (or a path) to write the document";
  const std::string path =
      target == "1" ? (sourceDir() / "docs" / "bad-input-catalogue.md").string() : target;
  const auto all = cases();
  std::string text =
      "# Bad input, catalogued\n\n"
      "Generated by `tests/hardening/bad_input_catalogue_test.cpp` from the messages of an actual run "
      "(do not edit by hand):\n\n"
      "    METROFIT_WRITE_CATALOGUE=1 ctest --test-dir build -R "
      "bad_input_catalogue_test.BadInputCatalogue.Document\n\n"
      "Every case runs `metrofit-cli` in a folder holding only the files of the case. The contract "
      "([docs/file-formats.md](file-formats.md#exit-status-and-output)): exit code 2, exactly one line on "
      "stderr naming the file and the "
      "line/column or the field, nothing on stdout, no output file written (an existing one is left "
      "unchanged), no temporary file left, no crash, no hang. The test asserts all of it for every "
      "row; `bad_input_gui_test` feeds a subset to the GUI and checks that it shows the same message "
      "and keeps the open project.\n\n" +
      std::to_string(all.size()) +
      " cases.\n\n"
      "| id | input | command | exit | message observed |\n"
      "| --- | --- | --- | --- | --- |\n";
  int failures = 0;
  for (const auto& c : all) {
    TempDir tmp;
    const Observed obs = runCase(c, tmp);
    text += row(c, obs.run, tmp.path() / "case") + "\n";
    if (obs.run.code != 2) ++failures;
  }
  std::printf("%s", text.c_str());
  ASSERT_EQ(failures, 0) << "cases without exit code 2: the document is not written";
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  writeText(path, text);
  std::printf("wrote %s\n", path.c_str());
}

}  // namespace
}  // namespace metrofit::test::bad
