// End-to-end tests of metrofit-cli kinematic identify|compensate and spc
// (docs/file-formats.md#kinematic-identify-result): results, one-line summaries, atomic outputs, and every
// bad input (exit 2, one line naming the file / line / field).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/cli_runner.h"
#include "cli/dfq_fields.h"
#include "core/io/csv.h"
#include "core/io/json_util.h"
#include "core/kinematics/cartesian_model.h"
#include "core/kinematics/identification.h"
#include "core/kinematics/iso230_2.h"
#include "core/kinematics/measured_path.h"
#include "core/kinematics/part21.h"
#include "core/sim/circular_sim.h"
#include "core/study/study_settings.h"
#include "testsupport.h"

namespace metrofit {
namespace {

using test::cli;
using test::CliRun;
using test::lines;

CircularSimOptions demoMachine() {
  CircularSimOptions o;
  o.seed = 4;
  o.errors.originMm = Eigen::Vector2d(0.012, -0.008);
  o.errors.xAxisAngleDeg = 0.003;
  o.errors.yAxisAngleDeg = -0.004;
  return o;
}

void writeCircularTest(const test::TempDir& tmp, const std::string& name) {
  test::writeText(tmp.file(name), measuredPathToCsv(simulateCircularTest(demoMachine())));
}

std::string circleCsv(int n, double r) {
  std::vector<Eigen::Vector2d> pts;
  for (int k = 0; k < n; ++k) {
    const double t = 2.0 * std::numbers::pi * k / n;
    pts.emplace_back(r * std::cos(t), r * std::sin(t));
  }
  return nominalPathToCsv(pts);
}

/// Expects exit 2, exactly one stderr line equal to "metrofit-cli: " + message, and no new files.
void expectBadInput(const std::string& args, const std::string& message, const test::TempDir& tmp) {
  const auto before = test::listFolder(tmp.path());
  const CliRun r = cli(args, tmp);
  EXPECT_EQ(r.code, 2) << args << ": " << r.err;
  EXPECT_EQ(r.err, "metrofit-cli: " + message + "\n") << args;
  EXPECT_EQ(lines(r.err), 1) << args;
  EXPECT_EQ(test::listFolder(tmp.path()), before) << args;
}

TEST(KinematicCli, IdentifyWritesTheContractJson) {
  test::TempDir tmp;
  writeCircularTest(tmp, "c.csv");
  const CliRun r = cli("kinematic identify --data c.csv --out e.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("kinematic identify: 720 points, origin (", 0), 0u) << r.err;
  EXPECT_TRUE(r.out.empty());
  const nlohmann::json j = readJsonFile(tmp.file("e.json"));
  const CircularSimOptions o = demoMachine();
  ASSERT_TRUE(j["origin_mm"].is_array());
  EXPECT_NEAR(j["origin_mm"][0].get<double>(), o.errors.originMm.x(), 1e-3);
  EXPECT_NEAR(j["origin_mm"][1].get<double>(), o.errors.originMm.y(), 1e-3);
  EXPECT_NEAR(j["x_axis_angle_deg"].get<double>(), 0.003, 1e-3);
  EXPECT_NEAR(j["y_axis_angle_deg"].get<double>(), -0.004, 1e-3);
  EXPECT_NEAR(j["rmse_mm"].get<double>(), 0.0005 * std::sqrt(2.0), 2e-4);
  EXPECT_NEAR(j["squareness_deg"].get<double>(), -0.007, 1e-3);
  EXPECT_EQ(j["points"], 720);
  EXPECT_TRUE(j["standard_errors"].contains("x_axis_angle_deg"));
  EXPECT_GE(j["iterations"].get<long>(), 1);
  // Without --out the JSON goes to stdout.
  const CliRun s = cli("kinematic identify --data c.csv", tmp);
  ASSERT_EQ(s.code, 0);
  EXPECT_EQ(parseJson(s.out, "stdout"), j);
  EXPECT_EQ(test::listFolder(tmp.path()), (std::vector<std::string>{"c.csv", "e.json"}));
}

/// A circular test written here (docs/file-formats.md#circular-test), commands on a circle of radius 50 about
/// the origin, one loop CCW then one CW (1 deg steps); the measured radius about c0 = (0.01, 0) is
/// 50 + A cos 3 theta (+ h on the CW loop). Radial form: angle_deg,deviation_um,direction of the same points.
std::string lobedCircle(bool radial, double amp, double h) {
  std::string text =
      radial ? "angle_deg,deviation_um,direction\n" : "x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm\n";
  char buf[160];
  for (int loop = 0; loop < 2; ++loop) {
    for (int k = 0; k < 360; ++k) {
      const double th = (loop == 0 ? k : 360 - k) * std::numbers::pi / 180.0;
      const double r = 50.0 + amp * std::cos(3.0 * th) + (loop == 1 ? h : 0.0);
      const double x = 0.01 + r * std::cos(th), y = r * std::sin(th);
      if (radial) {
        std::snprintf(buf, sizeof buf, "%.12f,%.9f,%s\n", std::atan2(y, x) * 180.0 / std::numbers::pi,
                      (std::hypot(x, y) - 50.0) * 1000.0, loop == 0 ? "ccw" : "cw");
      } else {
        std::snprintf(buf, sizeof buf, "%.12f,%.12f,%.12f,%.12f\n", 50.0 * std::cos(th), 50.0 * std::sin(th),
                      x, y);
      }
      text += buf;
    }
  }
  return text;
}

TEST(KinematicCli, CircularWritesTheIso230ResultsOfBothForms) {
  test::TempDir tmp;
  // G = 2A = 6 um about the LSQ centre (0.01, 0); H = h = 2 um; F about the nominal centre (0, 0) adds
  // the offset of 10 um.
  test::writeText(tmp.file("xy.csv"), lobedCircle(false, 0.003, 0.002));
  test::writeText(tmp.file("ballbar.csv"), lobedCircle(true, 0.003, 0.002));
  for (const char* name : {"xy.csv", "ballbar.csv"}) {
    const CliRun r = cli(std::string("kinematic circular --data ") + name, tmp);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("kinematic circular: 720 points", 0), 0u) << r.err;
    const nlohmann::json j = parseJson(r.out, "stdout");
    const bool radial = std::string(name) == "ballbar.csv";
    EXPECT_EQ(j["form"], radial ? "radial" : "xy");
    EXPECT_EQ(j["points"], 720);
    const nlohmann::json& iso = j["iso230_4"];
    // The radial form without radius_mm uses the linearised circle: O(e^2/R) = 1e-6 um here, within the
    // 9 digits written.
    EXPECT_EQ(iso["linearised"], radial);
    for (const char* dir : {"ccw", "cw"}) {
      ASSERT_TRUE(iso[dir].is_object()) << name << " " << dir;
      EXPECT_EQ(iso[dir]["points"], 360);
      EXPECT_NEAR(iso[dir]["circular_deviation_g_um"].get<double>(), 6.0, 1e-3) << name << " " << dir;
      EXPECT_NEAR(iso[dir]["lsq_centre_mm"][0].get<double>(), 0.01, 1e-6) << name;
      EXPECT_NEAR(iso[dir]["lsq_centre_mm"][1].get<double>(), 0.0, 1e-6) << name;
      // About the nominal centre the deviation is 10 cos t + 3 cos 3t (+ 2 on CW) + O(e^2/R = 0.001 um):
      // largest at t = 0, smallest at t = 180 deg.
      const double shift = std::string(dir) == "cw" ? 2.0 : 0.0;
      EXPECT_NEAR(iso[dir]["radial_deviation_f_max_um"].get<double>(), 13.0 + shift, 0.01) << name;
      EXPECT_NEAR(iso[dir]["radial_deviation_f_min_um"].get<double>(), -13.0 + shift, 0.01) << name;
    }
    EXPECT_NEAR(iso["circular_hysteresis_h_um"].get<double>(), 2.0, 1e-3) << name;
    EXPECT_EQ(iso["f_about"], "nominal centre");
  }
  // identify writes the same results under iso230_4, besides its own keys.
  const CliRun id = cli("kinematic identify --data xy.csv", tmp);
  ASSERT_EQ(id.code, 0) << id.err;
  const nlohmann::json j = parseJson(id.out, "stdout");
  EXPECT_TRUE(j.contains("origin_mm"));
  EXPECT_NEAR(j["iso230_4"]["cw"]["circular_deviation_g_um"].get<double>(), 6.0, 1e-3);
  EXPECT_NEAR(j["iso230_4"]["circular_hysteresis_h_um"].get<double>(), 2.0, 1e-3);
  // A radial-only test cannot be identified: one line naming the file.
  expectBadInput(
      "kinematic identify --data ballbar.csv",
      "ballbar.csv: is a radial-only circular test (angle_deg, deviation): the kinematic identification "
      "needs the x/y columns x_cmd_mm, y_cmd_mm, x_meas_mm, y_meas_mm (`kinematic circular` gives its "
      "ISO 230-4 results)",
      tmp);
  test::writeText(tmp.file("bad.csv"), "angle_deg,deviation_um,direction\n0,1,ccw\n1,2,up\n2,3,ccw\n");
  expectBadInput("kinematic circular --data bad.csv",
                 "bad.csv:3:3: field 'direction': 'up' is not a direction (ccw or cw)", tmp);
}

TEST(KinematicCli, IdentifyBreaksTheDemoTestDownIntoBallbarCauses) {
  // The diagnosis demo test (README: backlash X 8 um, Y 5 um on the default machine, R = 100 mm): the
  // breakdown (core/kinematics/ballbar.h) ranks the two backlashes and the squareness first, the squareness
  // value being identify's squareness_deg as the shear over the radius; each entry has exactly the
  // contract's keys and the shares with "unexplained" add up to 1.
  test::TempDir tmp;
  const std::string demo =
      "'" + (test::sourceDir() / "resources/demo/data/diagnose_circular.csv").string() + "'";
  const CliRun r = cli("kinematic identify --data " + demo + " --out e.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(", top cause backlash_x 8."), std::string::npos) << r.err;
  const std::string text = test::readText(tmp.file("e.json"));
  const nlohmann::json j = parseJson(text, "e.json");
  const nlohmann::json& causes = j.at("causes");
  ASSERT_TRUE(causes.is_array());
  ASSERT_EQ(causes.size(), 12u);  // 11 causes (no --screw-pitch: no cyclic error) and unexplained
  EXPECT_EQ(causes[0]["name"], "backlash_x");
  EXPECT_NEAR(causes[0]["value_um"].get<double>(), 8.0, 0.5);
  EXPECT_EQ(causes[1]["name"], "backlash_y");
  EXPECT_NEAR(causes[1]["value_um"].get<double>(), 5.0, 0.5);
  EXPECT_EQ(causes[2]["name"], "squareness");
  EXPECT_NEAR(causes[2]["value_um"].get<double>(),
              j["squareness_deg"].get<double>() * std::numbers::pi / 180.0 * 100.0 * 1000.0, 0.05);
  EXPECT_EQ(causes.back()["name"], "unexplained");
  double sum = 0.0;
  for (std::size_t i = 0; i < causes.size(); ++i) {
    const nlohmann::json& c = causes[i];
    EXPECT_EQ(c.size(), 3u) << c;
    EXPECT_TRUE(c["name"].is_string() && c["value_um"].is_number() && c["share"].is_number()) << c;
    EXPECT_GE(c["share"].get<double>(), 0.0) << c;
    if (i > 0 && i + 1 < causes.size()) {
      EXPECT_LE(c["share"].get<double>(), causes[i - 1]["share"].get<double>());
    }
    sum += c["share"].get<double>();
  }
  EXPECT_NEAR(sum, 1.0, 1e-9);
  // Byte for byte the same file whatever the process locale.
  for (const char* locale : {"C.UTF-8", "de_DE.UTF-8", "pl_PL.UTF-8"}) {
    const std::string cmd = "cd '" + tmp.path().string() + "' && LC_ALL=" + locale + " '" +
                            (test::binDir() / "metrofit-cli").string() + "' kinematic identify --data " +
                            demo + " --out l.json 2>/dev/null";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << locale;
    EXPECT_EQ(test::readText(tmp.file("l.json")), text) << locale;
  }
  // --screw-pitch adds the cyclic errors of that pitch (none in the demo: below the other causes).
  const CliRun p = cli("kinematic identify --data " + demo + " --screw-pitch 10", tmp);
  ASSERT_EQ(p.code, 0) << p.err;
  const nlohmann::json jp = parseJson(p.out, "stdout");
  std::set<std::string> names;
  for (const auto& c : jp.at("causes")) names.insert(c.at("name").get<std::string>());
  EXPECT_TRUE(names.count("cyclic_error_x") && names.count("cyclic_error_y"));
  EXPECT_EQ(jp.at("causes")[0]["name"], "backlash_x");
  expectBadInput(
      "kinematic identify --data " + demo + " --screw-pitch 0",
      "--screw-pitch: must be a positive number, got '0' (see metrofit-cli kinematic identify --help)", tmp);
}

TEST(KinematicCli, IdentifyOfAPathThatIsNoCircleHasNoCauses) {
  // A grid of commands identifies the actuator errors as before; the ballbar breakdown needs a circle.
  test::TempDir tmp;
  std::vector<Eigen::Vector2d> commands;
  for (int i = 0; i < 6; ++i) {
    for (int k = 0; k < 6; ++k) commands.emplace_back(20.0 * i, 20.0 * (i % 2 ? 5 - k : k));
  }
  MeasuredPath path;
  path.command = commands;
  path.measured = simulateMachine(demoMachine().errors, commands, 0.0005, 3);
  test::writeText(tmp.file("grid.csv"), measuredPathToCsv(path));
  const CliRun r = cli("kinematic identify --data grid.csv", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(", no ballbar breakdown: the commanded points are not on one circle ("),
            std::string::npos)
      << r.err;
  const nlohmann::json j = parseJson(r.out, "stdout");
  ASSERT_TRUE(j.contains("causes"));
  EXPECT_TRUE(j["causes"].is_null());
  EXPECT_NEAR(j["squareness_deg"].get<double>(), -0.007, 1e-3);
}

TEST(KinematicCli, CompensateWritesReferencesGcodeAndStepNc) {
  test::TempDir tmp;
  writeCircularTest(tmp, "c.csv");
  ASSERT_EQ(cli("kinematic identify --data c.csv --out e.json", tmp).code, 0);
  test::writeText(tmp.file("n.csv"), circleCsv(72, 100.0));
  const CliRun r =
      cli("kinematic compensate --errors e.json --path n.csv --out f.csv --gcode f.nc --step-nc f.p21", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("kinematic compensate: 72 points of n.csv, largest correction ", 0), 0u) << r.err;

  const CsvTable t = readCsvFile(tmp.file("f.csv"));
  EXPECT_EQ(t.header(), (std::vector<std::string>{"x_cmd_mm", "y_cmd_mm"}));
  ASSERT_EQ(t.rowCount(), 72u);
  // The references are Eq. 15 of the identified machine, and through the true machine they land
  // on the nominal circle within 2 um.
  const ActuatorErrors2 e = readActuatorErrors(tmp.file("e.json"));
  const NominalPath nominal = readNominalPath(tmp.file("n.csv"));
  const auto expected = compensatePath(CartesianMachine2::fromErrors(e), nominal.points);
  std::vector<Eigen::Vector2d> refs;
  for (std::size_t k = 0; k < t.rowCount(); ++k) refs.emplace_back(t.number(k, 0), t.number(k, 1));
  const auto landed = simulateMachine(demoMachine().errors, refs, 0.0, 1);
  for (std::size_t k = 0; k < refs.size(); ++k) {
    EXPECT_EQ(refs[k], expected[k]) << k;
    EXPECT_LT((landed[k] - nominal.points[k]).norm(), 0.002) << k;
  }
  const std::string g = test::readText(tmp.file("f.nc"));
  EXPECT_EQ(g.rfind("%\n(Metrofit ", 0), 0u);
  EXPECT_NE(g.find("(points: 72, mm, absolute)\nG21 G90 G17\nG01 X"), std::string::npos);
  EXPECT_EQ(std::count(g.begin(), g.end(), '\n'), 72 + 11);  // %, 7 comments, G21, blocks, M30, %
  const StepNcToolpath tp = stepNcToolpath(readPart21(tmp.file("f.p21")));
  ASSERT_EQ(tp.points.size(), 72u);
  for (std::size_t k = 0; k < refs.size(); ++k) {
    EXPECT_EQ(tp.points[k].x(), refs[k].x());
    EXPECT_EQ(tp.points[k].y(), refs[k].y());
  }
  // CSV to stdout without --out.
  const CliRun s = cli("kinematic compensate --errors e.json --path n.csv", tmp);
  ASSERT_EQ(s.code, 0);
  EXPECT_EQ(s.out, test::readText(tmp.file("f.csv")));
}

TEST(KinematicCli, SpcWritesLimitsAndIndices) {
  test::TempDir tmp;
  std::string csv = "# feature D1 of 20 parts\npart,d_mm\n";
  const double values[] = {10.0, 10.2, 9.9, 10.1, 9.8, 10.1, 10.3, 10.0,
                           10.2, 9.9,  9.9, 10.1, 9.8, 10.0, 9.7};
  for (int i = 0; i < 15; ++i) csv += std::to_string(i + 1) + "," + CsvWriter::formatNumber(values[i]) + "\n";
  test::writeText(tmp.file("f.csv"), csv);
  const CliRun r = cli(
      "spc --data f.csv --column d_mm --subgroup 5 --lsl 9.4 --usl 10.8 --nominal 10.2 --out s.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("spc: column 'd_mm', 3 subgroups of 5, in control, sigma 0.172, Cp 1.36, Cpk 1.16; "
                        "compensate +0.2",
                        0),
            0u)
      << r.err;
  const nlohmann::json j = readJsonFile(tmp.file("s.json"));
  EXPECT_NEAR(j["xbar_chart"]["ucl"].get<double>(), 10.2308, 2e-4);
  EXPECT_NEAR(j["xbar_chart"]["lcl"].get<double>(), 9.7692, 2e-4);
  EXPECT_NEAR(j["r_chart"]["ucl"].get<double>(), 0.8456, 2e-4);
  EXPECT_NEAR(j["cp"].get<double>(), 1.3568, 1e-3);
  EXPECT_NEAR(j["cpk"].get<double>(), 1.1630, 1e-3);
  EXPECT_TRUE(j["compensation"]["apply"].get<bool>());
  const CliRun plain = cli("spc --data f.csv --column d_mm --subgroup 5", tmp);
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_FALSE(parseJson(plain.out, "stdout").contains("cp"));
}

TEST(KinematicCli, IdentifyBadInputExits2WithOneLine) {
  test::TempDir tmp;
  test::writeText(tmp.file("nocol.csv"), "x_cmd_mm,y_cmd_mm,x_meas_mm\n0,0,0\n1,0,1\n0,1,0\n");
  expectBadInput("kinematic identify --data nocol.csv",
                 "nocol.csv: field 'y_meas_mm': missing column (the file has: x_cmd_mm, y_cmd_mm, x_meas_mm)",
                 tmp);
  test::writeText(tmp.file("text.csv"),
                  "x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm\n0,0,0,0\n1,abc,1,0\n0,1,0,1\n");
  expectBadInput("kinematic identify --data text.csv --out e.json",
                 "text.csv:3:2: field 'y_cmd_mm': 'abc' is not a number", tmp);
  test::writeText(tmp.file("few.csv"), "x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm\n0,0,0,0\n1,0,1,0\n");
  expectBadInput(
      "kinematic identify --data few.csv --out e.json",
      "few.csv: has 2 points, at least 3 not on one line are needed to identify origin and both axis "
      "angles",
      tmp);
  test::writeText(tmp.file("line.csv"),
                  "x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm\n0,0,0,0\n1,0,1,0\n2,0,2,0.001\n");
  expectBadInput(
      "kinematic identify --data line.csv",
      "line.csv: field 'x_cmd_mm,y_cmd_mm': all 3 command points lie on one line: the path must span "
      "both axes (a circular test does)",
      tmp);
  test::writeText(tmp.file("nan.csv"),
                  "x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm\n0,0,0,0\n1,0,nan,0\n0,1,0,1\n");
  expectBadInput("kinematic identify --data nan.csv",
                 "nan.csv:3:3: field 'x_meas_mm': 'nan' is not a finite number", tmp);
  const CliRun missing = cli("kinematic identify --data missing.csv", tmp);
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("missing.csv"), std::string::npos) << missing.err;
  EXPECT_EQ(lines(missing.err), 1);
}

TEST(KinematicCli, CompensateBadInputExits2WithOneLine) {
  test::TempDir tmp;
  test::writeText(tmp.file("n.csv"), circleCsv(8, 10.0));
  const std::string good = R"({"origin_mm": [0.01, 0], "x_axis_angle_deg": 0.001, "y_axis_angle_deg": 0})";
  test::writeText(tmp.file("good.json"), good);
  test::writeText(tmp.file("syntax.json"), "{\"origin_mm\": [0, 0],\n \"x_axis_angle_deg\": }");
  expectBadInput(
      "kinematic compensate --errors syntax.json --path n.csv --out f.csv",
      "syntax.json:2:22: invalid JSON: syntax error while parsing value - unexpected '}'; expected '[', "
      "'{', or a literal",
      tmp);
  test::writeText(tmp.file("nofield.json"), R"({"origin_mm": [0, 0], "x_axis_angle_deg": 0})");
  expectBadInput("kinematic compensate --errors nofield.json --path n.csv --out f.csv",
                 "nofield.json: field 'y_axis_angle_deg': missing", tmp);
  test::writeText(tmp.file("origin.json"),
                  R"({"origin_mm": [0, "x"], "x_axis_angle_deg": 0, "y_axis_angle_deg": 0})");
  expectBadInput("kinematic compensate --errors origin.json --path n.csv",
                 "origin.json: field 'origin_mm[1]': expected a number, found string", tmp);
  test::writeText(tmp.file("short.json"),
                  R"({"origin_mm": [0], "x_axis_angle_deg": 0, "y_axis_angle_deg": 0})");
  expectBadInput("kinematic compensate --errors short.json --path n.csv",
                 "short.json: field 'origin_mm': expected 2 numbers [x, y], found 1 element", tmp);
  test::writeText(tmp.file("angle.json"),
                  R"({"origin_mm": [0, 0], "x_axis_angle_deg": 90, "y_axis_angle_deg": 0})");
  expectBadInput(
      "kinematic compensate --errors angle.json --path n.csv",
      "angle.json: field 'x_axis_angle_deg': 90 deg is beyond +-45 deg (an actuator orientation error)", tmp);
  test::writeText(tmp.file("nocol.csv"), "x_mm,z_mm\n0,0\n");
  expectBadInput("kinematic compensate --errors good.json --path nocol.csv",
                 "nocol.csv: field 'y_mm': missing column (the file has: x_mm, z_mm)", tmp);
  test::writeText(tmp.file("text.csv"), "x_mm,y_mm\n0,0\n1,1..5\n");
  expectBadInput("kinematic compensate --errors good.json --path text.csv --out f.csv",
                 "text.csv:3:2: field 'y_mm': '1..5' is not a number", tmp);
  test::writeText(tmp.file("empty.csv"), "x_mm,y_mm\n");
  expectBadInput("kinematic compensate --errors good.json --path empty.csv",
                 "empty.csv: has 0 data rows, at least 1 needed", tmp);
  test::writeText(tmp.file("one.csv"), "x_mm,y_mm\n1,2\n");
  expectBadInput("kinematic compensate --errors good.json --path one.csv --out f.csv --step-nc f.p21",
                 "one.csv: has 1 point: a STEP-NC toolpath (--step-nc) needs at least 2", tmp);
  // An unwritable output leaves nothing behind.
  const auto before = test::listFolder(tmp.path());
  const CliRun w = cli("kinematic compensate --errors good.json --path n.csv --gcode no/such/dir/f.nc", tmp);
  EXPECT_EQ(w.code, 2) << w.err;
  EXPECT_EQ(lines(w.err), 1);
  EXPECT_NE(w.err.find("no/such/dir/f.nc"), std::string::npos) << w.err;
  EXPECT_EQ(test::listFolder(tmp.path()), before);
}

TEST(KinematicCli, SpcBadInputExits2WithOneLine) {
  test::TempDir tmp;
  std::string csv = "part,d_mm\n";
  for (int i = 0; i < 12; ++i)
    csv += std::to_string(i + 1) + "," + std::to_string(10.0 + 0.01 * (i % 3)) + "\n";
  test::writeText(tmp.file("f.csv"), csv);
  expectBadInput(
      "spc --data f.csv --column d_mm --subgroup 0",
      "field '--subgroup': must be between 1 (individuals and moving range) and 25 (the range of the "
      "A2/D3/D4 table), got 0",
      tmp);
  expectBadInput(
      "spc --data f.csv --column d_mm --subgroup 26 --out s.json",
      "field '--subgroup': must be between 1 (individuals and moving range) and 25 (the range of the "
      "A2/D3/D4 table), got 26",
      tmp);
  expectBadInput("spc --data f.csv --column d_mm --subgroup 5 --lsl 10.5 --usl 10.5",
                 "field '--lsl': lower specification limit 10.5 is not below --usl 10.5", tmp);
  expectBadInput("spc --data f.csv --column d_mm --subgroup 5 --lsl 9",
                 "field '--usl': missing: give --lsl and --usl together (Cp and Cpk need both limits)", tmp);
  expectBadInput("spc --data f.csv --column D1 --subgroup 5",
                 "f.csv: field 'D1': missing column (the file has: part, d_mm)", tmp);
  expectBadInput("spc --data f.csv --column d_mm --subgroup 7 --out s.json",
                 "f.csv: field 'd_mm': has 12 values: at least 2 subgroups of 7 (14 values) are needed", tmp);
  test::writeText(tmp.file("text.csv"), "part,d_mm\n1,10\n2,10.1\n3,ten\n4,10\n");
  expectBadInput("spc --data text.csv --column d_mm --subgroup 2",
                 "text.csv:4:2: field 'd_mm': 'ten' is not a number", tmp);
  test::writeText(tmp.file("flat.csv"), "d_mm\n5\n5\n5\n5\n");
  expectBadInput(
      "spc --data flat.csv --column d_mm --subgroup 2",
      "flat.csv: field 'd_mm': every subgroup has a range of 0: no within-subgroup variation to set "
      "control limits from (is the measurement resolution too coarse?)",
      tmp);
  const CliRun notNumber = cli("spc --data f.csv --column d_mm --subgroup 5 --usl abc --lsl 1", tmp);
  EXPECT_EQ(notNumber.code, 2);
  EXPECT_NE(notNumber.err.find("--usl"), std::string::npos) << notNumber.err;
  EXPECT_EQ(lines(notNumber.err), 1);
}

// ---- simulate circular / simulate bores --------------------------------------------------------

/// The documented commands of the bundled demo data (resources/demo/README.md, demo.metrofit).
const char* const kDemoCircular =
    "simulate circular --radius 50 --points 360 --x-angle 0.01 --y-angle -0.02 --origin 0.004,-0.003 "
    "--noise 0.0005 --seed 7";
const char* const kDemoBores =
    "simulate bores --parts 25 --radius 50 --points 90 --x-angle 0.01 --y-angle -0.02 --origin 0.004,-0.003 "
    "--noise 0.0005 --scatter 0.002 --drift 0.0001 --seed 7";

TEST(KinematicCli, SimulateCircularWritesTheCircularTestOfTheSimulator) {
  test::TempDir tmp;
  const CliRun r =
      cli("simulate circular --radius 50 --centre 10,-5 --points 36 --x-angle 0.01 --y-angle -0.02 --origin "
          "0.004,-0.003 --noise 0 --seed 7 --out c.csv",
          tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err,
            "simulate circular: 72 points (36 CCW, then 36 CW), R 50 mm, squareness -0.03 deg, noise 0 mm, "
            "seed 7\n");
  EXPECT_TRUE(r.out.empty());
  const std::string text = test::readText(tmp.file("c.csv"));
  EXPECT_EQ(text.rfind("# metrofit-cli simulate circular: R 50 mm about (10, -5) mm, 36 points per loop", 0),
            0u)
      << text.substr(0, 200);
  const MeasuredPath path = readMeasuredPath(tmp.file("c.csv"));
  CircularSimOptions o;
  o.radiusMm = 50.0;
  o.centreMm = Eigen::Vector2d(10.0, -5.0);
  o.pointsPerLoop = 36;
  o.errors.originMm = Eigen::Vector2d(0.004, -0.003);
  o.errors.xAxisAngleDeg = 0.01;
  o.errors.yAxisAngleDeg = -0.02;
  o.noiseMm = 0.0;
  o.seed = 7;
  const MeasuredPath expected = simulateCircularTest(o);
  ASSERT_EQ(path.size(), 72u);
  for (std::size_t i = 0; i < path.size(); ++i) {
    EXPECT_EQ(path.command[i], expected.command[i]) << i;  // shortest round-trip numbers: exact
    EXPECT_EQ(path.measured[i], expected.measured[i]) << i;
  }
  // CCW first (the angle grows), then CW.
  EXPECT_NEAR(path.command[1].y() - (-5.0), 50.0 * std::sin(2.0 * std::numbers::pi / 36), 1e-12);
  EXPECT_NEAR(path.command[37].y() - (-5.0), -50.0 * std::sin(2.0 * std::numbers::pi / 36), 1e-12);
  // Noise free: identification recovers the errors to rounding.
  const IdentifyResult id = identifyActuatorErrors(path);
  EXPECT_NEAR(id.errors.xAxisAngleDeg, 0.01, 1e-9);
  EXPECT_NEAR(id.errors.yAxisAngleDeg, -0.02, 1e-9);
  EXPECT_NEAR(id.errors.originMm.x(), 0.004, 1e-9);
  EXPECT_NEAR(id.errors.originMm.y(), -0.003, 1e-9);
}

TEST(KinematicCli, SimulateCircularIsDeterministicBySeedAndDefaultsToStdout) {
  test::TempDir tmp;
  const CliRun a = cli("simulate circular --seed 3", tmp);
  const CliRun b = cli("simulate circular --seed 3", tmp);
  const CliRun c = cli("simulate circular --seed 4", tmp);
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_NE(a.out, c.out);
  const MeasuredPath path = measuredPathFromCsv(parseCsv(a.out, "stdout"));
  CircularSimOptions o;
  o.seed = 3;
  const MeasuredPath expected = simulateCircularTest(o);  // the simulator's defaults
  ASSERT_EQ(path.size(), expected.size());
  for (std::size_t i = 0; i < path.size(); ++i) EXPECT_EQ(path.measured[i], expected.measured[i]) << i;
  EXPECT_EQ(test::listFolder(tmp.path()), std::vector<std::string>{});
}

TEST(KinematicCli, SimulateBadOptionsExit2WithOneLineAndNoFile) {
  test::TempDir tmp;
  for (const std::string args :
       {"simulate circular --radius 0 --out c.csv", "simulate circular --points 2 --out c.csv",
        "simulate circular --x-angle 50 --out c.csv", "simulate circular --y-angle -46 --out c.csv",
        "simulate circular --noise -1 --out c.csv", "simulate circular --centre 1 --out c.csv",
        "simulate circular --origin 1,2,3 --out c.csv", "simulate circular --radius abc --out c.csv",
        "simulate bores --parts 0 --out b.csv", "simulate bores --scatter -0.1 --out b.csv"}) {
    const CliRun r = cli(args, tmp);
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_EQ(lines(r.err), 1) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("metrofit-cli: ", 0), 0u) << r.err;
    const std::string option =
        args.substr(args.find("--"), args.find(' ', args.find("--")) - args.find("--"));
    EXPECT_NE(r.err.find(option), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(test::listFolder(tmp.path()), std::vector<std::string>{}) << args;
  }
}

TEST(KinematicCli, SimulateBoresIsTheLeastSquaresDiameterPlusTheToolError) {
  test::TempDir tmp;
  // A round machine (origin error only), no noise, no scatter: every bore is the nominal circle
  // shifted by the origin error, diameter 2 R.
  const CliRun r =
      cli("simulate bores --parts 4 --radius 50 --points 90 --x-angle 0 --y-angle 0 --origin 0.004,-0.003 "
          "--noise 0 "
          "--scatter 0 --drift 0 --out b.csv",
          tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.rfind("simulate bores: 4 parts, nominal diameter 100 mm, mean 100 mm", 0), 0u) << r.err;
  const CsvTable t = readCsvFile(tmp.file("b.csv"));
  ASSERT_EQ(t.rowCount(), 4u);
  const auto d = t.numericColumn("diameter_mm");
  const auto cx = t.numericColumn("centre_x_mm");
  const auto cy = t.numericColumn("centre_y_mm");
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(d[i], 100.0, 1e-9) << i;
    EXPECT_NEAR(cx[i], 0.004, 1e-9) << i;
    EXPECT_NEAR(cy[i], -0.003, 1e-9) << i;
  }
  // A drift of 1 um per part widens the bore by 2 um per part.
  ASSERT_EQ(
      cli("simulate bores --parts 4 --x-angle 0 --y-angle 0 --noise 0 --scatter 0 --drift 0.001 --out c.csv",
          tmp)
          .code,
      0);
  const auto dd = readCsvFile(tmp.file("c.csv")).numericColumn("diameter_mm");
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(dd[i], 100.0 + 0.002 * static_cast<double>(i), 1e-9) << i;
}

/// Edge CSV made here from Eq. 9 written out (not the simulator): commands (u, c) along X or (c, u)
/// along Y on the machine o + x (cos a, sin a) + y (-sin b, cos b), noise-free.
std::string edgeCsv(char axis, double ox, double oy, double aDeg, double bDeg, int n) {
  const double a = aDeg * std::numbers::pi / 180.0, b = bDeg * std::numbers::pi / 180.0;
  std::string csv = "position_mm,deviation_mm\n";
  for (int k = 0; k < n; ++k) {
    const double u = -100.0 + 200.0 * k / (n - 1);
    const double x = axis == 'x' ? u : 0.0, y = axis == 'x' ? 0.0 : u;
    const double px = ox + x * std::cos(a) - y * std::sin(b), py = oy + x * std::sin(a) + y * std::cos(b);
    // a tiny deterministic scatter so the residual charts have ranges
    const double e = 1e-4 * std::sin(1.7 * k * k);
    char line[96];
    std::snprintf(line, sizeof line, "%.15g,%.15g\n", axis == 'x' ? px : py, (axis == 'x' ? py : px) + e);
    csv += line;
  }
  return csv;
}

using test::DfqFields;
using test::readDfq;

TEST(KinematicCli, SpcAndFromSpcWriteQdasDfq) {
  test::TempDir tmp;
  // A German spreadsheet export with times: ';' and decimal commas.
  test::writeText(tmp.file("bores.csv"),
                  "timestamp;diameter_mm\n2024-05-03T10:15:00;20,003\n2024-05-03T10:16:00;19,998\n"
                  "2024-05-03T10:17:00;20,001\n2024-05-03T10:18:00;20,004\n2024-05-03 10:19;19,997\n"
                  "2024-05-03T10:20:00;20,000\n");
  const CliRun r =
      cli("spc --data bores.csv --column diameter_mm --subgroup 2 --lsl 19.95 --usl 20.05 "
          "--nominal 20 --dfq b.dfq --dfq-part P-17",
          tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const DfqFields d = readDfq(test::readText(tmp.file("b.dfq")));
  EXPECT_EQ(d.fields.at("K0100"), "1");
  EXPECT_EQ(d.fields.at("K1001/1"), "P-17");
  EXPECT_EQ(d.fields.at("K2001/1"), "diameter_mm");
  EXPECT_EQ(std::stod(d.fields.at("K2101/1")), 20.0);
  EXPECT_EQ(std::stod(d.fields.at("K2110/1")), 19.95);
  EXPECT_EQ(std::stod(d.fields.at("K2111/1")), 20.05);
  EXPECT_EQ(d.fields.at("K2142/1"), "mm");
  EXPECT_EQ(d.values.at(1), (std::vector<double>{20.003, 19.998, 20.001, 20.004, 19.997, 20.0}));
  ASSERT_EQ(d.times.at(1).size(), 6u);
  EXPECT_EQ(d.times.at(1).front(), "03.05.2024/10:15:00");
  EXPECT_EQ(d.times.at(1)[4], "03.05.2024/10:19:00");

  // A bad time: exit 2, one line naming the cell, no DFQ file.
  test::writeText(
      tmp.file("badtime.csv"),
      "timestamp,d_mm\n2024-05-03T10:15:00,1\nyesterday,2\n2024-05-03T10:17:00,3\n2024-05-03T10:18:00,2\n");
  expectBadInput("spc --data badtime.csv --column d_mm --subgroup 2 --dfq x.dfq",
                 "badtime.csv:3:1: field 'timestamp': 'yesterday' is not a date-time YYYY-MM-DDTHH:MM[:SS]",
                 tmp);

  // from-spc: the two edges' deviations as two characteristics.
  test::writeText(tmp.file("ex.csv"), edgeCsv('x', 0.012, -0.008, 0.03, -0.05, 40));
  test::writeText(tmp.file("ey.csv"), edgeCsv('y', 0.012, -0.008, 0.03, -0.05, 30));
  const CliRun f = cli("kinematic from-spc --x-data ex.csv --y-data ey.csv --dfq e.dfq --out e.json", tmp);
  ASSERT_EQ(f.code, 0) << f.err;
  const DfqFields e = readDfq(test::readText(tmp.file("e.dfq")));
  EXPECT_EQ(e.fields.at("K0100"), "2");
  EXPECT_EQ(e.fields.at("K2001/1"), "X edge deviation_mm");
  EXPECT_EQ(e.fields.at("K2001/2"), "Y edge deviation_mm");
  EXPECT_EQ(e.fields.at("K2142/2"), "mm");
  EXPECT_EQ(std::stod(e.fields.at("K2101/1")), 0.0);
  EXPECT_EQ(e.fields.count("K2110/1"), 0u);
  const auto xs = readCsvFile(tmp.file("ex.csv")).numericColumn("deviation_mm");
  const auto ys = readCsvFile(tmp.file("ey.csv")).numericColumn("deviation_mm");
  EXPECT_EQ(e.values.at(1), xs);
  EXPECT_EQ(e.values.at(2), ys);
  EXPECT_EQ(e.values.at(2).size(), 30u);
  EXPECT_TRUE(e.times.empty());
}

TEST(KinematicCli, FromSpcTurnsTheOffsetAnglesIntoActuatorErrorsAndReferences) {
  test::TempDir tmp;
  test::writeText(tmp.file("ex.csv"), edgeCsv('x', 0.012, -0.008, 0.03, -0.05, 40));
  test::writeText(tmp.file("ey.csv"), edgeCsv('y', 0.012, -0.008, 0.03, -0.05, 40));
  test::writeText(tmp.file("n.csv"), circleCsv(36, 50.0));
  const CliRun r = cli(
      "kinematic from-spc --x-data ex.csv --y-data ey.csv --path n.csv --references f.csv --out e.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("kinematic from-spc: offset angles X ", 0), 0u) << r.err;
  const nlohmann::json j = readJsonFile(tmp.file("e.json"));
  // se of the slope ~ 1e-4 mm / sqrt(Sxx) ~ 1e-6 rad: 1e-3 deg is far outside it
  EXPECT_NEAR(j["x_axis_angle_deg"].get<double>(), 0.03, 2e-4);
  EXPECT_NEAR(j["y_axis_angle_deg"].get<double>(), -0.05, 2e-4);
  EXPECT_NEAR(j["features"]["x"]["offset_angle_deg"].get<double>(), 0.03, 2e-4);
  EXPECT_NEAR(j["features"]["y"]["offset_angle_deg"].get<double>(), 0.05, 2e-4);
  EXPECT_NEAR(j["origin_mm"][0].get<double>(), 0.012, 1e-4);
  EXPECT_NEAR(j["origin_mm"][1].get<double>(), -0.008, 1e-4);
  EXPECT_NEAR(j["squareness_deg"].get<double>(), -0.08, 3e-4);
  EXPECT_TRUE(j["compensation"]["apply"].get<bool>()) << j["compensation"]["reason"];
  // The references put the (test's own) true machine back on the nominal circle.
  const auto refs = readCsvFile(tmp.file("f.csv"));
  const auto xc = refs.numericColumn("x_cmd_mm"), yc = refs.numericColumn("y_cmd_mm");
  ASSERT_EQ(xc.size(), 36u);
  const double a = 0.03 * std::numbers::pi / 180.0, b = -0.05 * std::numbers::pi / 180.0;
  for (std::size_t k = 0; k < 36; ++k) {
    const double t = 2.0 * std::numbers::pi * static_cast<double>(k) / 36.0;
    const double px = 0.012 + xc[k] * std::cos(a) - yc[k] * std::sin(b);
    const double py = -0.008 + xc[k] * std::sin(a) + yc[k] * std::cos(b);
    EXPECT_NEAR(std::hypot(px - 50.0 * std::cos(t), py - 50.0 * std::sin(t)), 0.0, 2e-4) << k;
  }
  // The chain goes on: compensate reads the from-spc JSON as identify's.
  test::writeText(tmp.file("n.csv"), circleCsv(36, 50.0));
  const CliRun c = cli("kinematic compensate --errors e.json --path n.csv --out g.csv", tmp);
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_EQ(test::readText(tmp.file("g.csv")), test::readText(tmp.file("f.csv")));
}

TEST(KinematicCli, FromSpcBadInputExits2WithOneLine) {
  test::TempDir tmp;
  test::writeText(tmp.file("ex.csv"), edgeCsv('x', 0.0, 0.0, 0.01, 0.0, 20));
  test::writeText(tmp.file("ey.csv"), edgeCsv('y', 0.0, 0.0, 0.01, 0.0, 20));
  test::writeText(tmp.file("bad.csv"), "pos,dev\n1,2\n3,4\n5,6\n");
  test::writeText(tmp.file("n.csv"), circleCsv(8, 10.0));
  expectBadInput("kinematic from-spc --x-data ex.csv --y-data bad.csv",
                 "bad.csv: field 'position_mm': missing column (the file has: pos, dev)", tmp);
  expectBadInput("kinematic from-spc --x-data ex.csv --y-data ey.csv --path n.csv",
                 "field '--references': missing: give --path and --references together (the nominal path and "
                 "where its compensated references go)",
                 tmp);
  test::writeText(tmp.file("two.csv"), "position_mm,deviation_mm\n1,0\n2,0\n");
  expectBadInput(
      "kinematic from-spc --x-data two.csv --y-data ey.csv",
      "two.csv: the X feature has 2 points, at least 3 are needed for a regression line with a scatter", tmp);
  test::writeText(tmp.file("nan.csv"), "position_mm,deviation_mm\n1,0\n2,x\n3,0\n");
  const CliRun r = cli("kinematic from-spc --x-data nan.csv --y-data ey.csv", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("nan.csv:3"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("deviation_mm"), std::string::npos) << r.err;
}

TEST(KinematicCli, Identify3RecoversTheSimulatedThreeAxisMachine) {
  test::TempDir tmp;
  ASSERT_EQ(cli("simulate circular --plane xy --errors3 e3in.json --out xy.csv", tmp).code,
            2);  // no file yet
  test::writeText(tmp.file("e3in.json"), R"({"origin_mm": [0.01, -0.02, 0.03],
    "planes": {"xy": {"x_axis_angle_deg": 0.002, "y_axis_angle_deg": -0.003},
               "yz": {"y_axis_angle_deg": 0.004, "z_axis_angle_deg": 0.001},
               "zx": {"z_axis_angle_deg": -0.002, "x_axis_angle_deg": 0.005}}})");
  ASSERT_EQ(cli("simulate circular --plane xy --errors3 e3in.json --seed 1 --out xy.csv", tmp).code, 0);
  ASSERT_EQ(cli("simulate circular --plane yz --errors3 e3in.json --seed 2 --out yz.csv", tmp).code, 0);
  ASSERT_EQ(cli("simulate circular --plane zx --errors3 e3in.json --seed 3 --out zx.csv", tmp).code, 0);
  EXPECT_NE(test::readText(tmp.file("yz.csv")).find("\ny_cmd_mm,z_cmd_mm,y_meas_mm,z_meas_mm\n"),
            std::string::npos);
  EXPECT_NE(test::readText(tmp.file("zx.csv")).find("\nz_cmd_mm,x_cmd_mm,z_meas_mm,x_meas_mm\n"),
            std::string::npos);
  const CliRun r = cli("kinematic identify3 --xy xy.csv --yz yz.csv --zx zx.csv --out e3.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("kinematic identify3: 2160 points in 3 planes", 0), 0u) << r.err;
  const nlohmann::json j = readJsonFile(tmp.file("e3.json"));
  // 0.5 um noise, R 100 mm, 720 points per plane: se ~ 2e-5 deg for the angles, ~3e-5 mm for the origin.
  EXPECT_NEAR(j["origin_mm"][0].get<double>(), 0.01, 2e-4);
  EXPECT_NEAR(j["origin_mm"][1].get<double>(), -0.02, 2e-4);
  EXPECT_NEAR(j["origin_mm"][2].get<double>(), 0.03, 2e-4);
  EXPECT_NEAR(j["squareness_deg"]["xy"].get<double>(), -0.005, 1.5e-4);
  EXPECT_NEAR(j["squareness_deg"]["yz"].get<double>(), -0.003, 1.5e-4);
  EXPECT_NEAR(j["squareness_deg"]["zx"].get<double>(), 0.007, 1.5e-4);
  EXPECT_NEAR(j["planes"]["zx"]["x_axis_angle_deg"].get<double>(), 0.005, 1.5e-4);
  EXPECT_NEAR(j["planes"]["yz"]["z_axis_angle_deg"].get<double>(), 0.001, 1.5e-4);
  EXPECT_EQ(j["termination"], "converged");
  // The identified machine simulates again (identify3's JSON is --errors3's input).
  EXPECT_EQ(cli("simulate circular --plane yz --errors3 e3.json --out again.csv", tmp).code, 0);
  // ... and compensates in three axes: the references, run through the true machine (written here from
  // the injected projection angles), land on the nominal points within the identification's scatter.
  test::writeText(tmp.file("n3.csv"), "x_mm,y_mm,z_mm\n100,0,0\n0,100,0\n0,0,100\n50,-50,80\n");
  const CliRun c = cli("kinematic compensate3 --errors3 e3.json --path n3.csv --out f3.csv", tmp);
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_EQ(c.err.rfind("kinematic compensate3: 4 points of n3.csv, largest correction ", 0), 0u) << c.err;
  const auto f = readCsvFile(tmp.file("f3.csv"));
  const auto xs = f.numericColumn("x_cmd_mm"), ys = f.numericColumn("y_cmd_mm"),
             zs = f.numericColumn("z_cmd_mm");
  const double d = std::numbers::pi / 180.0;
  const Eigen::Vector3d i = Eigen::Vector3d(1.0, std::tan(0.002 * d), -std::tan(0.005 * d)).normalized();
  const Eigen::Vector3d jj = Eigen::Vector3d(std::tan(0.003 * d), 1.0, std::tan(0.004 * d)).normalized();
  const Eigen::Vector3d k = Eigen::Vector3d(std::tan(-0.002 * d), -std::tan(0.001 * d), 1.0).normalized();
  const Eigen::Vector3d o(0.01, -0.02, 0.03);
  const Eigen::Vector3d nominal[4] = {{100, 0, 0}, {0, 100, 0}, {0, 0, 100}, {50, -50, 80}};
  for (std::size_t n = 0; n < 4; ++n) {
    const Eigen::Vector3d p = o + i * xs[n] + jj * ys[n] + k * zs[n];
    EXPECT_LT((p - nominal[n]).norm(), 5e-4) << n;  // identified within ~1e-4 deg, 0.1 um
    EXPECT_GT((o + i * 100.0 - Eigen::Vector3d(100, 0, 0)).norm(), 0.02);  // uncompensated: > 20 um
  }
}

TEST(KinematicCli, Identify3BadInputExits2WithOneLine) {
  test::TempDir tmp;
  ASSERT_EQ(cli("simulate circular --plane xy --out xy.csv", tmp).code, 0);
  ASSERT_EQ(cli("simulate circular --plane yz --out yz.csv", tmp).code, 0);
  ASSERT_EQ(cli("simulate circular --plane zx --out zx.csv", tmp).code, 0);
  expectBadInput("kinematic identify3 --xy xy.csv --yz yz.csv",
                 "--zx is required (see metrofit-cli kinematic identify3 --help)", tmp);
  expectBadInput(
      "kinematic identify3 --xy xy.csv --yz xy.csv --zx zx.csv",
      "xy.csv: field 'z_cmd_mm': missing column (the file has: x_cmd_mm, y_cmd_mm, x_meas_mm, y_meas_mm)",
      tmp);
  expectBadInput(
      "kinematic identify3 --xy xy.csv --yz yz.csv --zx yz.csv",
      "yz.csv: field 'x_cmd_mm': missing column (the file has: y_cmd_mm, z_cmd_mm, y_meas_mm, z_meas_mm)",
      tmp);
  expectBadInput("simulate circular --plane xz --out p.csv",
                 "--plane: xz not in {xy,yz,zx} (see metrofit-cli simulate circular --help)", tmp);
}

TEST(KinematicCli, DemoDataIsWhatTheDocumentedCommandsWrite) {
  test::TempDir tmp;
  ASSERT_EQ(cli(std::string(kDemoCircular) + " --out c.csv", tmp).code, 0);
  ASSERT_EQ(cli(std::string(kDemoBores) + " --out b.csv", tmp).code, 0);
  const auto data = test::sourceDir() / "resources/demo/data";
  EXPECT_EQ(test::readText(tmp.file("c.csv")), test::readText((data / "circular_demo.csv").string()))
      << "regenerate with: metrofit-cli " << kDemoCircular << " --out resources/demo/data/circular_demo.csv";
  EXPECT_EQ(test::readText(tmp.file("b.csv")), test::readText((data / "bores_demo.csv").string()))
      << "regenerate with: metrofit-cli " << kDemoBores << " --out resources/demo/data/bores_demo.csv";
  // The demo meets the issue's identification targets (0.5 um noise).
  const IdentifyResult id = identifyActuatorErrors(readMeasuredPath((data / "circular_demo.csv").string()));
  EXPECT_NEAR(id.errors.xAxisAngleDeg, 0.01, 1e-3);
  EXPECT_NEAR(id.errors.yAxisAngleDeg, -0.02, 1e-3);
  EXPECT_NEAR(id.errors.originMm.x(), 0.004, 1e-3);
  EXPECT_NEAR(id.errors.originMm.y(), -0.003, 1e-3);
}

// The option defaults are the project study's (KinematicsSettings, the one owner of studies.kinematics):
// `spc` as studies.kinematics.spc, `kinematic from-spc` as studies.kinematics.from_spc.
TEST(KinematicCli, OptionDefaultsAreTheStudysDefaults) {
  test::TempDir tmp;
  const auto shown = [](double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  };
  const test::CliRun fromSpc = test::cli("kinematic from-spc --help", tmp);
  ASSERT_EQ(fromSpc.code, 0) << fromSpc.err;
  const KinematicsSettings::FromSpc f;
  for (const std::string& option :
       {"--position-column TEXT=" + f.positionColumn, "--deviation-column TEXT=" + f.deviationColumn,
        "--x-nominal-y FLOAT=" + shown(f.xNominalY), "--y-nominal-x FLOAT=" + shown(f.yNominalX),
        "--subgroup INT:INT in [2 - 25]=" + std::to_string(f.subgroup),
        "--coverage FLOAT:POSITIVE=" + shown(f.coverage)})
    EXPECT_NE(fromSpc.out.find(option), std::string::npos) << option << "\n" << fromSpc.out;
  const test::CliRun spc = test::cli("spc --help", tmp);
  ASSERT_EQ(spc.code, 0) << spc.err;
  const std::string coverage = "--coverage FLOAT:POSITIVE=" + shown(KinematicsSettings::Spc{}.coverage);
  EXPECT_NE(spc.out.find(coverage), std::string::npos) << spc.out;
  EXPECT_NE(spc.out.find("--subgroup INT REQUIRED"), std::string::npos) << "the contract: --subgroup N";
}

// ---- kinematic positioning (ISO 230-2) ----

/// metrofit-cli run in `tmp` under LC_ALL=locale; the exit code.
int cliUnderLocale(const std::string& locale, const std::string& args, const test::TempDir& tmp) {
  const std::string cmd = "cd '" + tmp.path().string() + "' && LC_ALL=" + locale + " '" +
                          (test::binDir() / "metrofit-cli").string() + "' " + args + " >/dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(KinematicCli, PositioningOfTheRealEssAxis) {
  const auto ess = test::realData("axis-positioning-ess/example_data_ISO230_2.dat");
  METROFIT_REQUIRE_PATH(ess);
  test::TempDir tmp;
  const CliRun r = cli("kinematic positioning --data '" + ess.string() + "' --out r.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("kinematic positioning: 5 targets, 50 approaches: A ", 0), 0u) << r.err;
  const nlohmann::json j = readJsonFile(tmp.file("r.json"));
  const PositioningResult core = evaluateIso230_2(readPositioningTest(ess.string()));
  EXPECT_DOUBLE_EQ(j["A_mm"].get<double>(), core.A);
  EXPECT_DOUBLE_EQ(j["R_mm"].get<double>(), core.R);
  ASSERT_EQ(j["targets"].size(), 5u);
  EXPECT_DOUBLE_EQ(j["targets"][0]["target_mm"].get<double>(), 15.0);
  EXPECT_EQ(j.size(), 13u);
}

TEST(KinematicCli, PositioningTablesAreByteIdenticalUnderEveryLocale) {
  test::TempDir tmp;
  std::string csv = "target_mm,direction,cycle,measured_mm\n";
  const double dev[] = {0.0021, -0.0042, 0.0063, 0.0013, -0.0007};
  for (int c = 1; c <= 3; ++c)
    for (int i = 0; i < 5; ++i)
      for (const char* d : {"+", "-"})
        csv += std::to_string(100 * i) + "," + d + "," + std::to_string(c) + "," +
               CsvWriter::formatNumber(100 * i + dev[i] + 0.0001 * c + (d[0] == '+' ? 0.002 : 0.0)) + "\n";
  test::writeText(tmp.file("p.csv"), csv);
  for (const char* form : {"fanuc", "siemens", "heidenhain", "csv"}) {
    std::string first;
    for (const char* loc : {"C.UTF-8", "de_DE.UTF-8", "pl_PL.UTF-8"}) {
      ASSERT_EQ(cliUnderLocale(loc,
                               std::string("kinematic positioning --data p.csv --compensation ") + form +
                                   " --out-table t.txt --out r.json",
                               tmp),
                0)
          << form << " " << loc;
      const std::string table = test::readText(tmp.file("t.txt")) + test::readText(tmp.file("r.json"));
      if (first.empty())
        first = table;
      else
        EXPECT_EQ(table, first) << form << " under " << loc;
    }
    EXPECT_FALSE(first.empty());
  }
  // The CSV table is minus the mean bidirectional deviation (0.001 mm of backlash each side).
  ASSERT_EQ(cliUnderLocale("de_DE.UTF-8",
                           "kinematic positioning --data p.csv --compensation csv --out-table t.csv", tmp),
            0);
  const CsvTable t = parseCsv(test::readText(tmp.file("t.csv")), "t.csv");
  ASSERT_EQ(t.rowCount(), 5u);
  EXPECT_NEAR(t.number(1, 1), -(-0.0042 + 0.0002 + 0.001), 1e-6);
}

TEST(KinematicCli, PositioningBadInput) {
  test::TempDir tmp;
  test::writeText(tmp.file("d.csv"), "target_mm,direction,cycle,deviation_mm\n0,+,1,0.001\n0,up,2,0.002\n");
  expectBadInput("kinematic positioning --data d.csv --out r.json",
                 "d.csv:3:2: field 'direction': 'up' is not a direction (+ or -)", tmp);
  test::writeText(tmp.file("k.dat"), "UNIT=mm\nTGT_DATA[1]=1O\n");
  expectBadInput("kinematic positioning --data k.dat --out r.json",
                 "k.dat:2: field 'TGT_DATA[1]': '1O' is not a number", tmp);
  test::writeText(tmp.file("ok.csv"),
                  "target_mm,direction,cycle,deviation_mm\n0,+,1,0\n0,+,2,0\n0,-,1,0\n0,-,2,0\n");
  expectBadInput("kinematic positioning --data ok.csv --compensation siemens --out r.json",
                 "field '--out-table': --compensation and --out-table go together", tmp);
  expectBadInput(
      "kinematic positioning --data ok.csv --compensation fanuc --out-table t.txt",
      "ok.csv: field 'target_mm': a compensation table needs at least 2 targets (an interval), got 1", tmp);
}

// ---- spc --base K (phase I / phase II), --subgroup 1 (individuals and moving range), Nelson rules ----

/// A one-column CSV `name` of `values` (with '.' decimals whatever the locale).
void writeSeries(const test::TempDir& tmp, const std::string& file, const std::string& name,
                 const std::vector<double>& values) {
  std::string csv = "part," + name + "\n";
  for (std::size_t i = 0; i < values.size(); ++i)
    csv += std::to_string(i + 1) + "," + CsvWriter::formatNumber(values[i]) + "\n";
  test::writeText(tmp.file(file), csv);
}

// The series of tests/core/spc/spc_test.cpp, where the limits and the rules are worked out by hand:
// six subgroups of 4, the first four the base (xbarbar 10.00625, Rbar 0.325, UCL 10.243175), the sixth
// shifted to a mean of 10.4; and ten individuals, the first eight the base (mean 10.1875, MRbar 1.2 / 7),
// the ninth 11.0.
const std::vector<double> kPhaseSeries = {10.0, 10.2, 9.9,  10.1, 10.1, 9.9,  10.0, 10.2,
                                          9.8,  10.0, 10.1, 9.9,  10.0, 9.8,  10.2, 9.9,
                                          10.1, 10.0, 9.9,  10.0, 10.4, 10.3, 10.5, 10.4};
const std::vector<double> kIndividualSeries = {10.0, 10.2, 10.1, 10.4, 10.2, 10.3, 10.1, 10.2, 11.0, 10.2};

TEST(KinematicCli, SpcBaseIndividualsAndNelsonRules) {
  test::TempDir tmp;
  writeSeries(tmp, "p.csv", "d_mm", kPhaseSeries);
  writeSeries(tmp, "i.csv", "x_mm", kIndividualSeries);
  const std::string phases = "spc --data p.csv --column d_mm --subgroup 4 --base 4 --lsl 9.5 --usl 10.8";
  CliRun r = cli(phases + " --out p.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(
      r.err.rfind("spc: column 'd_mm', 6 subgroups of 4, limits from the first 4, OUT OF CONTROL (rules "
                  "broken: xbar nelson1), sigma ",
                  0),
      0u)
      << r.err;
  nlohmann::json j = readJsonFile(tmp.file("p.json"));
  EXPECT_EQ(j["chart_type"], "xbar-r");
  EXPECT_EQ(j["base_subgroups"], 4);
  EXPECT_EQ(j["subgroups"], 6);
  EXPECT_NEAR(j["xbar_chart"]["center"].get<double>(), 10.00625, 1e-12);
  EXPECT_NEAR(j["r_chart"]["center"].get<double>(), 0.325, 1e-12);
  EXPECT_NEAR(j["xbar_chart"]["ucl"].get<double>(), 10.00625 + 0.729 * 0.325, 2e-4);
  EXPECT_EQ(j["rules"], nlohmann::json::parse(R"([{"chart": "xbar", "rule": "nelson1", "subgroups": [6]}])"));
  EXPECT_FALSE(j["in_control"].get<bool>());
  EXPECT_TRUE(j.contains("pp"));
  EXPECT_TRUE(j.contains("ppk"));
  // Without --base the limits are those of all six subgroups and the key says so.
  r = cli("spc --data p.csv --column d_mm --subgroup 4", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(parseJson(r.out, "stdout")["base_subgroups"], 6);
  EXPECT_NEAR(parseJson(r.out, "stdout")["xbar_chart"]["center"].get<double>(), 60.425 / 6.0, 1e-12);

  r = cli("spc --data i.csv --column x_mm --subgroup 1 --base 8 --out i.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(
      r.err.rfind("spc: column 'x_mm', 10 individual values (X-MR), limits from the first 8, OUT OF CONTROL "
                  "(rules broken: xbar nelson1; r nelson1; r nelson5), sigma ",
                  0),
      0u)
      << r.err;
  j = readJsonFile(tmp.file("i.json"));
  EXPECT_EQ(j["chart_type"], "x-mr");
  EXPECT_EQ(j["subgroup_size"], 1);
  EXPECT_EQ(j["r_chart"]["first_subgroup"], 2);
  EXPECT_NEAR(j["r_chart"]["center"].get<double>(), 1.2 / 7.0, 1e-12);
  EXPECT_NEAR(j["r_chart"]["ucl"].get<double>(), 3.267 * 1.2 / 7.0, 1e-4);
  EXPECT_NEAR(j["xbar_chart"]["ucl"].get<double>(), 10.1875 + 2.66 * 1.2 / 7.0, 3e-4);
  EXPECT_EQ(j["rules"], nlohmann::json::parse(R"([
      {"chart": "xbar", "rule": "nelson1", "subgroups": [9]},
      {"chart": "r", "rule": "nelson1", "subgroups": [9, 10]},
      {"chart": "r", "rule": "nelson5", "subgroups": [10]}])"));

  // The same inputs give the same bytes under every locale of the matrix ('.' decimals).
  for (const std::string& args :
       {phases + " --out q.json",
        std::string("spc --data i.csv --column x_mm --subgroup 1 --base 8 --out q.json")}) {
    std::string first;
    for (const char* loc : {"C.UTF-8", "de_DE.UTF-8", "pl_PL.UTF-8"}) {
      ASSERT_EQ(cliUnderLocale(loc, args, tmp), 0) << args << " under " << loc;
      const std::string text = test::readText(tmp.file("q.json"));
      if (first.empty())
        first = text;
      else
        EXPECT_EQ(text, first) << args << " under " << loc;
    }
    EXPECT_NE(first.find("\"center\": 10."), std::string::npos) << first.substr(0, 400);
  }

  // --base outside 2 .. the number of subgroups: exit 2, one line naming --base.
  expectBadInput(
      "spc --data p.csv --column d_mm --subgroup 4 --base 1",
      "field '--base': must be at least 2 subgroups (the limits need ranges to be set from), got 1", tmp);
  expectBadInput("spc --data p.csv --column d_mm --subgroup 4 --base 7 --out x.json",
                 "p.csv: field '--base': is 7 subgroups but column 'd_mm' has 6 complete subgroups of 4",
                 tmp);
  expectBadInput("spc --data i.csv --column x_mm --subgroup 1 --base 11 --out x.json",
                 "i.csv: field '--base': is 11 subgroups but column 'x_mm' has 10 values", tmp);
}

}  // namespace
}  // namespace metrofit
