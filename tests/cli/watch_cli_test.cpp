// End-to-end tests of `metrofit-cli watch` (core/study/watch.h, issue 29 item 5): the contract's keys,
// offsets equal to the batch `setup --method exact --export csv` on the same files in the same order,
// exactly-once reading across restarts and kills, rejected files, bad options, and a soak test.
//
// The reports are written here from the documented CSV format (docs/file-formats.md#cmm-report-series)
// for the bundled paper model: per dimension a systematic deviation plus a noise that alternates +-3 um
// from part to part with a jitter of +-1 um. Such a series stays inside the individuals and moving-range
// charts' limits whatever its length (every moving range is 4..8 um, the X limits are about +-5 sigma
// of its scatter), so the SPC gate releases the correction and the offsets can be compared with the
// batch run; random normal noise over 28 charts gives false alarms that hold the gate (tested too).
//
// Soak size: METROFIT_WATCH_SOAK_REPORTS (default 100), METROFIT_WATCH_SOAK_KILLS (default 2),
// METROFIT_WATCH_SOAK_MS (ms between drops, default 50 = 20 reports per second).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli_runner.h"
#include "testsupport.h"

namespace metrofit {
namespace {

namespace fs = std::filesystem;
using test::cli;
using test::CliRun;

struct Dim {
  std::string id;
  double nominal = 0, lower = 0, upper = 0;
};

std::vector<Dim> paperDims() {
  const auto j = nlohmann::json::parse(
      test::readText((test::sourceDir() / "resources/demo/setup/paper_example.json").string()));
  std::vector<Dim> out;
  for (const auto& d : j.at("dimensions"))
    out.push_back({d.at("id").get<std::string>(), d.value("nominal", 0.0), d.at("lower").get<double>(),
                   d.at("upper").get<double>()});
  return out;
}

std::string num(double v) {
  std::ostringstream s;
  s.imbue(std::locale::classic());
  s.precision(10);
  s << v;
  return s.str();
}

/// One measured part as a CMM report series CSV: deviation = systematic(q) + shift + alternating
/// noise (see the header comment), printed to 1 um as a CMM does.
std::string report(int part, const std::vector<Dim>& dims, double shift = 0.0) {
  std::string t = "part,time_min,dimension,nominal_mm,measured_mm,lower_tol_mm,upper_tol_mm\n";
  std::uint64_t s = 0x9E3779B97F4A7C15ull * static_cast<std::uint64_t>(part + 1);
  for (std::size_t q = 0; q < dims.size(); ++q) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    const double u = static_cast<double>(s >> 11) / 9007199254740992.0;  // [0,1)
    const double systematic = 0.02 * std::sin(1.7 * static_cast<double>(q) + 0.3);
    const double noise = ((part + static_cast<int>(q)) % 2 ? 0.003 : -0.003) + 0.002 * (u - 0.5);
    const double measured = std::round((dims[q].nominal + systematic + shift + noise) * 1000.0) / 1000.0;
    t += std::to_string(part) + "," + std::to_string(2 * part) + "," + dims[q].id + "," +
         num(dims[q].nominal) + "," + num(measured) + "," + num(dims[q].lower) + "," + num(dims[q].upper) +
         "\n";
  }
  return t;
}

std::string reportName(int part) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "report_%04d.csv", part);
  return buf;
}

/// Drops a report atomically (written as .tmp, then renamed), as a CMM's export usually does.
void drop(const fs::path& dir, int part, const std::vector<Dim>& dims) {
  const fs::path tmp = dir / (reportName(part) + ".tmp");
  test::writeText(tmp.string(), report(part, dims));
  fs::rename(tmp, dir / reportName(part));
}

/// A project with the paper's setup model, in `tmp`; the watched folder `in/`.
void makeProject(const test::TempDir& tmp) {
  fs::copy_file(test::sourceDir() / "resources/demo/setup/paper_example.json", tmp.path() / "model.json");
  ASSERT_EQ(cli("project new P.metrofit", tmp).code, 0);
  ASSERT_EQ(cli("project add P.metrofit setup-model model.json", tmp).code, 0);
  fs::create_directories(tmp.path() / "in");
}

std::vector<nlohmann::json> jsonLines(const std::string& text) {
  std::vector<nlohmann::json> out;
  std::istringstream s(text);
  std::string line;
  while (std::getline(s, line))
    if (!line.empty()) out.push_back(nlohmann::json::parse(line));
  return out;
}

/// The journal's accepted files in journal order; every name checked to appear once.
std::vector<std::string> journalFiles(const test::TempDir& tmp,
                                      std::map<std::string, int>* counts = nullptr) {
  std::vector<std::string> files;
  for (const auto& j : jsonLines(test::readText(tmp.file("P.watch.jsonl")))) {
    if (counts) ++(*counts)[j.at("file").get<std::string>()];
    if (j.at("status") == "accepted") files.push_back(j.at("file").get<std::string>());
  }
  return files;
}

/// The batch run's offsets on `files` (in that order) in in/.
std::string batchOffsets(const test::TempDir& tmp, const std::vector<std::string>& files) {
  std::string data;
  for (const auto& f : files) data += " 'in/" + f + "'";
  const CliRun r =
      cli("setup --model model.json --method exact --export csv --export-out batch.csv --data" + data, tmp);
  EXPECT_EQ(r.code, 0) << r.err;
  return test::readText(tmp.file("batch.csv"));
}

/// Starts `metrofit-cli <args>` in `tmp` in the background, stdout appended to `out`.
pid_t startCli(const test::TempDir& tmp, const std::string& args, const std::string& out) {
  const std::string cmd = "cd '" + tmp.path().string() + "' && exec '" +
                          (test::binDir() / "metrofit-cli").string() + "' " + args + " >>'" + out + "' 2>>'" +
                          out + ".err'";
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

int waitExit(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

int envInt(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::atoi(v) : fallback;
}

TEST(WatchCli, OnceGivesOneLinePerFileAndTheBatchOffsets) {
  test::TempDir tmp;
  makeProject(tmp);
  const auto dims = paperDims();
  for (int p = 1; p <= 5; ++p) {
    drop(tmp.path() / "in", p, dims);
    fs::last_write_time(tmp.path() / "in" / reportName(p),
                        fs::file_time_type::clock::now() - std::chrono::seconds(10 - p));
  }
  test::writeText(tmp.file("in/.hidden.csv"), "x\n");
  test::writeText(tmp.file("in/report_0099.csv.part"), "part,time_min\n");
  const CliRun r = cli("watch in --project P.metrofit --once --poll-ms 50", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = jsonLines(r.out);
  ASSERT_EQ(lines.size(), 5u) << r.out;
  for (int i = 0; i < 5; ++i) {
    const auto& j = lines[i];
    for (const char* key : {"file", "kind", "part", "in_control", "correction", "residual_white", "error"})
      EXPECT_TRUE(j.contains(key)) << key << " missing in " << j.dump();
    EXPECT_EQ(j["file"], reportName(i + 1));
    EXPECT_EQ(j["kind"], "cmm-report");
    EXPECT_EQ(j["part"], std::to_string(i + 1));
    EXPECT_TRUE(j["error"].is_null());
    EXPECT_TRUE(j["correction"].is_object());
    EXPECT_EQ(j["correction"].size(), 10u);  // W1..W8, T5, T23
  }
  EXPECT_TRUE(lines[0]["in_control"].is_null());  // one value per chart: nothing to chart yet
  EXPECT_EQ(lines[4]["in_control"], true);
  EXPECT_EQ(lines[4]["released"], true) << lines[4]["gate"];
  EXPECT_TRUE(lines[4]["residual_white"].is_boolean());
  // The offsets equal the batch run's on the same files in the same order, byte for byte.
  const auto files = journalFiles(tmp);
  ASSERT_EQ(files.size(), 5u);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(files[i], reportName(i + 1));
  const std::string offsets = test::readText(tmp.file("offsets/offsets.csv"));
  EXPECT_FALSE(offsets.empty());
  EXPECT_EQ(offsets, batchOffsets(tmp, files));
  // And the JSON correction is the batch JSON's.
  std::string data;
  for (const auto& f : files) data += " in/" + f;
  const CliRun b = cli("setup --model model.json --method exact --data" + data, tmp);
  ASSERT_EQ(b.code, 0);
  EXPECT_EQ(lines[4]["correction"], nlohmann::json::parse(b.out)["corrections_mm"]);
  // The temporary and hidden files were left alone.
  EXPECT_TRUE(fs::exists(tmp.path() / "in/report_0099.csv.part"));

  // Restart: nothing is read twice.
  const CliRun again = cli("watch in --project P.metrofit --once --poll-ms 50", tmp);
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_EQ(again.out, "");
  // A sixth report: exactly one line, and the offsets follow the batch run on all six.
  drop(tmp.path() / "in", 6, dims);
  const CliRun six = cli("watch in --project P.metrofit --once --poll-ms 50 --control fanuc --out nc", tmp);
  ASSERT_EQ(six.code, 0) << six.err;
  const auto sixLines = jsonLines(six.out);
  ASSERT_EQ(sixLines.size(), 1u) << six.out;
  EXPECT_EQ(sixLines[0]["file"], reportName(6));
  EXPECT_EQ(sixLines[0]["series_parts"], 6);
  const auto files6 = journalFiles(tmp);
  ASSERT_EQ(files6.size(), 6u);
  batchOffsets(tmp, files6);
  std::string data6;
  for (const auto& f : files6) data6 += " in/" + f;
  ASSERT_EQ(
      cli("setup --model model.json --method exact --export fanuc --export-out batch.nc --data" + data6, tmp)
          .code,
      0);
  EXPECT_EQ(test::readText(tmp.file("nc/offsets.nc")), test::readText(tmp.file("batch.nc")));

  // A part with a special cause (every dimension 40 um off): out of control, the gate holds, the
  // offsets file keeps its last released content.
  const std::string before = test::readText(tmp.file("offsets/offsets.csv"));
  test::writeText(tmp.file("in/report_0007.csv"), report(7, dims, 0.04));
  const CliRun seven = cli("watch in --project P.metrofit --once --poll-ms 50", tmp);
  ASSERT_EQ(seven.code, 0) << seven.err;
  const auto sevenLines = jsonLines(seven.out);
  ASSERT_EQ(sevenLines.size(), 1u) << seven.out;
  EXPECT_EQ(sevenLines[0]["in_control"], false);
  EXPECT_EQ(sevenLines[0]["released"], false);
  EXPECT_TRUE(sevenLines[0]["offsets"].is_null());
  EXPECT_NE(sevenLines[0]["gate"].get<std::string>().find("out of control"), std::string::npos);
  EXPECT_EQ(test::readText(tmp.file("offsets/offsets.csv")), before);
}

TEST(WatchCli, MalformedFilesAreSetAsideAndTheLoopGoesOn) {
  test::TempDir tmp;
  makeProject(tmp);
  const auto dims = paperDims();
  for (int p = 1; p <= 3; ++p) drop(tmp.path() / "in", p, dims);
  // A report naming a dimension the model lacks, and a file that is no report at all.
  std::string bad = report(4, dims);
  bad.replace(bad.find("P2.D3"), 5, "P9.D9");
  test::writeText(tmp.file("in/unknown_dim.csv"), bad);
  test::writeText(tmp.file("in/notes.txt"), "Operator notes: coffee machine broken\n");
  // The same part twice (part 2 again in another file).
  test::writeText(tmp.file("in/twice.csv"), report(2, dims));
  const CliRun r = cli("watch in --project P.metrofit --once --poll-ms 50", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = jsonLines(r.out);
  ASSERT_EQ(lines.size(), 6u) << r.out;
  int accepted = 0;
  std::map<std::string, std::string> errors;
  for (const auto& j : lines) {
    if (j["error"].is_null())
      ++accepted;
    else
      errors[j["file"]] = j["error"];
  }
  EXPECT_EQ(accepted, 3);
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_NE(errors["unknown_dim.csv"].find("P9.D9"), std::string::npos) << errors["unknown_dim.csv"];
  EXPECT_NE(errors["twice.csv"].find("measured twice"), std::string::npos) << errors["twice.csv"];
  for (const auto& [file, error] : errors) {
    EXPECT_FALSE(fs::exists(tmp.path() / "in" / file)) << file;
    EXPECT_TRUE(fs::exists(tmp.path() / "in/rejected" / file)) << file;
    const std::string text = test::readText((tmp.path() / "in/rejected" / (file + ".error.txt")).string());
    EXPECT_EQ(text, error + "\n");
    EXPECT_EQ(test::lines(text), 1);
  }
  // The three good reports are the series, and a restart reads nothing again.
  EXPECT_EQ(journalFiles(tmp).size(), 3u);
  EXPECT_EQ(cli("watch in --project P.metrofit --once --poll-ms 50", tmp).out, "");
}

TEST(WatchCli, BadOptionsAndProjectsAreOneLineExit2) {
  test::TempDir tmp;
  makeProject(tmp);
  CliRun r = cli("watch in --project missing.metrofit --once", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(test::lines(r.err), 1) << r.err;
  r = cli("watch nowhere --project P.metrofit --once", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(test::lines(r.err), 1) << r.err;
  r = cli("watch in --project P.metrofit --poll-ms 0 --once", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(test::lines(r.err), 1) << r.err;
  r = cli("watch in --project P.metrofit --control okuma --once", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(test::lines(r.err), 1) << r.err;
  ASSERT_EQ(cli("project new Empty.metrofit", tmp).code, 0);
  r = cli("watch in --project Empty.metrofit --once", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(test::lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("setup model"), std::string::npos) << r.err;
}

/// Drops `reports` reports every `gapMs` into a running `watch`, SIGKILLs it `kills` times at evenly
/// spaced points (restarting it at once), ends it with SIGTERM (exit 0), finishes with --once, and
/// checks: every report in the journal exactly once, in drop order, and the offsets equal the batch.
void killAndRestart(int reports, int kills, int gapMs) {
  test::TempDir tmp;
  makeProject(tmp);
  const auto dims = paperDims();
  const std::string out = tmp.file("watch.out");
  const std::string args = "watch in --project P.metrofit --poll-ms 20 --diagnose-every 25";
  pid_t pid = startCli(tmp, args, out);
  int killed = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int p = 1; p <= reports; ++p) {
    drop(tmp.path() / "in", p, dims);
    std::this_thread::sleep_for(std::chrono::milliseconds(gapMs));
    if (killed < kills && p == (killed + 1) * reports / (kills + 1)) {
      ::kill(pid, SIGKILL);
      EXPECT_EQ(waitExit(pid), -SIGKILL);
      ++killed;
      pid = startCli(tmp, args, out);
    }
  }
  // Let the running loop catch up a little, then stop it as a service manager would.
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(pid, SIGTERM);
  EXPECT_EQ(waitExit(pid), 0) << test::readText(out + ".err");
  const double dropSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double stopSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const CliRun rest = cli("watch in --project P.metrofit --once --poll-ms 20 --diagnose-every 25", tmp);
  ASSERT_EQ(rest.code, 0) << rest.err;
  const double totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::size_t caughtUpLater = jsonLines(rest.out).size();

  std::map<std::string, int> counts;
  const auto files = journalFiles(tmp, &counts);
  ASSERT_EQ(files.size(), static_cast<std::size_t>(reports));
  for (int p = 1; p <= reports; ++p) {
    EXPECT_EQ(files[p - 1], reportName(p));
    EXPECT_EQ(counts[reportName(p)], 1) << reportName(p);
  }
  // Every report was reported on stdout at least once (twice only when killed between its outputs
  // and its journal line), and every line is whole JSON.
  std::map<std::string, int> printed;
  for (const auto& j : jsonLines(test::readText(out) + rest.out)) ++printed[j.at("file").get<std::string>()];
  for (int p = 1; p <= reports; ++p) EXPECT_GE(printed[reportName(p)], 1) << reportName(p);
  EXPECT_EQ(test::readText(tmp.file("offsets/offsets.csv")), batchOffsets(tmp, files));
  ::testing::Test::RecordProperty("reports", reports);
  ::testing::Test::RecordProperty("kills", kills);
  ::testing::Test::RecordProperty("drop_seconds", std::to_string(dropSeconds));
  double maxSeconds = 0.0;
  for (const auto& j : jsonLines(test::readText(out)))
    maxSeconds = std::max(maxSeconds, j.value("seconds", 0.0));
  std::fprintf(
      stderr,
      "watch soak: %d reports every %d ms, %d kills: dropped in %.1f s, SIGTERM done at %.1f s, all in "
      "the journal at %.1f s (%zu left for the final --once); slowest file %.3f s\n",
      reports, gapMs, kills, dropSeconds, stopSeconds, totalSeconds, caughtUpLater, maxSeconds);
}

TEST(WatchCli, KilledMidWayLosesNothingAndReadsNothingTwice) {
  killAndRestart(12, 3, 60);
}

TEST(WatchCli, Soak) {
  killAndRestart(envInt("METROFIT_WATCH_SOAK_REPORTS", 100), envInt("METROFIT_WATCH_SOAK_KILLS", 2),
                 envInt("METROFIT_WATCH_SOAK_MS", 50));
}

}  // namespace
}  // namespace metrofit
