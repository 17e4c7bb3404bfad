// End-to-end tests of `metrofit-cli match` (docs/file-formats.md#match-result): JSON keys, exit codes,
// one-line stderr, reproducibility, locks, scale, machines, bad input.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "cli/cli_runner.h"
#include "core/io/csv.h"
#include "core/io/json_util.h"
#include "testsupport.h"

namespace metrofit {
namespace {

using test::cli;
using test::CliRun;
using test::lines;

nlohmann::json runJson(const std::string& args, const test::TempDir& tmp) {
  const CliRun r = cli(args + " --out r.json", tmp);
  EXPECT_EQ(r.code, 0) << args << ": " << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("match: ", 0), 0u) << r.err;
  EXPECT_TRUE(r.out.empty());
  return parseJson(test::readText(tmp.file("r.json")), "r.json");
}

class MatchCli : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_EQ(cli("simulate probe --seed 2 --out p.csv", tmp).code, 0); }
  test::TempDir tmp;
};

TEST_F(MatchCli, ClosedFormWritesTheContractJson) {
  const nlohmann::json j = runJson("match --data p.csv --method closed-form --tolerance 0.035", tmp);
  EXPECT_EQ(j.at("method"), "closed-form");
  // The simulator's default posture (core/sim/probe_sim.h): rx, ry, rz = 0.02, -0.015, 0.05 deg.
  const auto& rot = j.at("rotation_deg");
  ASSERT_EQ(rot.size(), 3u);
  EXPECT_NEAR(rot[0].get<double>(), 0.02, 0.002);
  EXPECT_NEAR(rot[1].get<double>(), -0.015, 0.002);
  EXPECT_NEAR(rot[2].get<double>(), 0.05, 0.002);
  const auto& t = j.at("translation_mm");
  ASSERT_EQ(t.size(), 3u);
  EXPECT_NEAR(t[0].get<double>(), 0.12, 0.01);
  EXPECT_NEAR(t[1].get<double>(), -0.08, 0.01);
  EXPECT_NEAR(t[2].get<double>(), 0.05, 0.01);
  EXPECT_LT(j.at("rmse_mm").get<double>(), 0.005);
  EXPECT_GT(j.at("max_abs_mm").get<double>(), 0.0);
  EXPECT_GT(j.at("out_of_tolerance").at("before").get<int>(), 0);
  EXPECT_EQ(j.at("out_of_tolerance").at("after").get<int>(), 0);
  EXPECT_FALSE(j.contains("scale"));
  const auto& m = j.at("machine");
  EXPECT_EQ(m.at("topology"), "xfyzba");
  for (const char* k : {"SX_mm", "SY_mm", "SZ_mm", "SA_deg", "SB_deg", "frame_rotation_deg", "definition"})
    EXPECT_TRUE(m.contains(k)) << k;
  EXPECT_EQ(j.at("after").at("surfaces").size(), 4u);
}

// per_point (CONTRACT, issue 28 item 4) recomputed here from the file's q, n, p and the result's
// posture with the convention docs/file-formats.md#match-result states (p = R q + t, R = Rz Ry Rx of
// rotation_deg = [rx, ry, rz]), and the --per-point CSV holds the same numbers.
TEST_F(MatchCli, PerPointDeviationsFollowThePostureAndGoToCsv) {
  const nlohmann::json j =
      runJson("match --data p.csv --method closed-form --tolerance 0.035 --per-point pp.csv", tmp);
  const auto& rot = j.at("rotation_deg");
  const double deg = 3.14159265358979323846 / 180.0;
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(rot[2].get<double>() * deg, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(rot[1].get<double>() * deg, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(rot[0].get<double>() * deg, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  const auto& tj = j.at("translation_mm");
  const Eigen::Vector3d t(tj[0].get<double>(), tj[1].get<double>(), tj[2].get<double>());
  const CsvTable points = readCsvFile(tmp.file("p.csv"));
  const auto& perPoint = j.at("per_point");
  ASSERT_EQ(perPoint.size(), points.rowCount());
  const CsvTable csv = readCsvFile(tmp.file("pp.csv"));
  ASSERT_EQ(csv.rowCount(), points.rowCount());
  double sumSquares = 0.0;
  for (std::size_t i = 0; i < points.rowCount(); ++i) {
    const auto col = [&](const char* name) { return points.number(i, points.requireColumn(name)); };
    const Eigen::Vector3d q(col("qx"), col("qy"), col("qz")), n(col("nx"), col("ny"), col("nz")),
        p(col("px"), col("py"), col("pz"));
    const Eigen::Vector3d e = p - (R * q + t);
    const nlohmann::json& pp = perPoint[i];
    EXPECT_EQ(pp.at("id"), points.cell(i, points.requireColumn("id")));
    EXPECT_NEAR(pp.at("dx_mm").get<double>(), e.x(), 1e-9) << i;
    EXPECT_NEAR(pp.at("dy_mm").get<double>(), e.y(), 1e-9) << i;
    EXPECT_NEAR(pp.at("dz_mm").get<double>(), e.z(), 1e-9) << i;
    EXPECT_NEAR(pp.at("d_mm").get<double>(), e.dot(R * n), 1e-9) << i;
    sumSquares += e.squaredNorm();
    // The CSV: the same numbers ('.' decimals under every locale of the matrix).
    EXPECT_EQ(csv.cell(i, csv.requireColumn("id")), pp.at("id").get<std::string>());
    for (const char* key : {"d_mm", "dx_mm", "dy_mm", "dz_mm"})
      EXPECT_DOUBLE_EQ(csv.number(i, csv.requireColumn(key)), pp.at(key).get<double>()) << key << " " << i;
  }
  EXPECT_NEAR(std::sqrt(sumSquares / static_cast<double>(points.rowCount())), j.at("rmse_mm").get<double>(),
              1e-12);
}

TEST_F(MatchCli, SadeIsReproducibleBySeedAndHasATrace) {
  const CliRun a = cli("match --data p.csv --seed 5", tmp);
  const CliRun b = cli("match --data p.csv --seed 5", tmp);
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_EQ(a.out, b.out);  // stdout when --out is omitted
  const nlohmann::json j = parseJson(a.out, "stdout");
  EXPECT_EQ(j.at("method"), "sade");
  EXPECT_EQ(j.at("trace").size(), 201u);
  EXPECT_GT(j.at("evaluations").get<long>(), 6000);
  EXPECT_EQ(j.at("seed"), 5);
  const nlohmann::json cf = runJson("match --data p.csv --method closed-form", tmp);
  EXPECT_LE(j.at("rmse_mm").get<double>() - cf.at("rmse_mm").get<double>(), 1e-6);
}

TEST_F(MatchCli, MinimaxIsNeverWorseThanClosedForm) {
  const nlohmann::json cf = runJson("match --data p.csv --method closed-form", tmp);
  const nlohmann::json mm = runJson("match --data p.csv --method minimax", tmp);
  EXPECT_EQ(mm.at("method"), "minimax");
  EXPECT_LE(mm.at("max_abs_mm").get<double>(), cf.at("max_abs_mm").get<double>());
  EXPECT_GE(mm.at("minimax").at("active_points").size(), 7u);
}

TEST_F(MatchCli, LocksScaleAndMachines) {
  const nlohmann::json l = runJson("match --data p.csv --method closed-form --lock rx,ry,z", tmp);
  EXPECT_EQ(l.at("rotation_deg")[0].get<double>(), 0.0);
  EXPECT_EQ(l.at("rotation_deg")[1].get<double>(), 0.0);
  EXPECT_EQ(l.at("translation_mm")[2].get<double>(), 0.0);
  EXPECT_EQ(l.at("locked"), nlohmann::json({"rx", "ry", "z"}));
  const nlohmann::json s = runJson("match --data p.csv --method closed-form --allow-scale", tmp);
  ASSERT_TRUE(s.contains("scale"));
  EXPECT_NEAR(s.at("scale").get<double>(), 1.0, 1e-4);
  const nlohmann::json ac = runJson("match --data p.csv --method closed-form --machine ac-table", tmp);
  EXPECT_EQ(ac.at("machine").at("topology"), "ac-table");
  EXPECT_TRUE(ac.at("machine").contains("SC_deg"));
  test::writeText(tmp.file("m.json"), R"({"LZ_mm": -250, "LAB_mm": -80})");
  const nlohmann::json d = runJson("match --data p.csv --method closed-form --machine-def m.json", tmp);
  EXPECT_EQ(d.at("machine").at("definition").at("LZ_mm").get<double>(), -250.0);
  const nlohmann::json ht = runJson("match --data p.csv --method closed-form --machine head-table", tmp);
  EXPECT_EQ(ht.at("machine").at("topology"), "head-table");
  EXPECT_TRUE(ht.at("machine").contains("SB_deg"));
  EXPECT_TRUE(ht.at("machine").contains("SC_deg"));
  // A project as the machine definition: its matching study's machine (what the GUI's dialog writes).
  test::writeText(tmp.file("cell.metrofit"),
                  R"({"format": "metrofit-project", "version": 1, "name": "cell", "datasets": [],
                      "studies": {"matching": {"machine": {"topology": "head-table", "pivot_mm": 300,
                                                           "linear_travel_mm": [[null, null], [-0.01, 0.01], [null, null]]}}}})");
  const nlohmann::json pr =
      runJson("match --data p.csv --method closed-form --machine-def cell.metrofit", tmp);
  EXPECT_EQ(pr.at("machine").at("topology"), "head-table");
  EXPECT_EQ(pr.at("machine").at("definition").at("pivot_mm").get<double>(), 300.0);
  EXPECT_EQ(pr.at("machine").at("definition").at("linear_travel_mm")[1][0].get<double>(), -0.01);
  // Same values as the same machine given as a machine file.
  test::writeText(tmp.file("ht.json"), pr.at("machine").at("definition").dump());
  const nlohmann::json file = runJson("match --data p.csv --method closed-form --machine-def ht.json", tmp);
  EXPECT_EQ(file.at("machine"), pr.at("machine"));
}

TEST_F(MatchCli, RemeasureLoopReportsItsOutcome) {
  // The simulated part is where the probe found it: it ends in tolerance at +-0.035 mm ...
  const nlohmann::json ok =
      runJson("match --data p.csv --method closed-form --tolerance 0.035 --remeasure", tmp);
  const auto& r = ok.at("remeasure");
  EXPECT_EQ(r.at("outcome"), "in_tolerance") << r.at("message");
  EXPECT_TRUE(r.at("in_tolerance").get<bool>());
  EXPECT_GE(r.at("rounds").size(), 2u);
  EXPECT_EQ(r.at("true_remaining").at("out_of_tolerance").get<int>(), 0);
  EXPECT_NEAR(r.at("rounds")[0].at("true").at("max_abs_mm").get<double>(),
              ok.at("before").at("max_abs_mm").get<double>(), 1e-12);
  // ... fails when the tolerance is tighter than what the best fit leaves (form error and noise) ...
  const double left = ok.at("max_abs_mm").get<double>();
  const std::string tight = std::to_string(0.5 * left);
  CliRun run = cli("match --data p.csv --method closed-form --remeasure --tolerance " + tight, tmp);
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.err.find("FAILED"), std::string::npos) << run.err;
  const nlohmann::json form = parseJson(run.out, "stdout");
  EXPECT_EQ(form.at("remeasure").at("outcome"), "form_error");
  EXPECT_GT(form.at("remeasure").at("true_remaining").at("out_of_tolerance").get<int>(), 0);
  // ... and when the machine cannot tilt far enough (A travel +-0.001 deg): the WCS stays, so the true
  // remaining error is the data's own before any adjustment.
  test::writeText(tmp.file("narrow.json"), R"({"rotary_travel_deg": [[-0.001, 0.001], [-360, 360]]})");
  const nlohmann::json travel = runJson(
      "match --data p.csv --method closed-form --tolerance 0.035 --remeasure --machine-def narrow.json", tmp);
  EXPECT_EQ(travel.at("remeasure").at("outcome"), "beyond_travel");
  EXPECT_EQ(travel.at("remeasure").at("rounds").size(), 1u);
  EXPECT_NEAR(travel.at("remeasure").at("true_remaining").at("max_abs_mm").get<double>(),
              travel.at("before").at("max_abs_mm").get<double>(), 1e-12);
}

TEST_F(MatchCli, BadInputExits2WithOneLine) {
  struct Case {
    std::string args, needle;
  };
  test::writeText(tmp.file("line.csv"),
                  "id,qx,qy,qz,px,py,pz\nA,0,0,0,0,0,0\nB,1,1,1,1,1,1\nC,2,2,2,2,2,2\n");
  test::writeText(tmp.file("two.csv"), "id,qx,qy,qz,px,py,pz\nA,0,0,0,0,0,0\nB,1,0,0,1,0,0\n");
  test::writeText(tmp.file("bad.json"), R"({"topology": "hexapod"})");
  test::writeText(tmp.file("nomachine.metrofit"),
                  R"({"format": "metrofit-project", "version": 1, "datasets": [], "studies": {}})");
  for (const Case& c :
       {Case{"match --data p.csv --lock rx,w", "--lock"},
        Case{"match --data p.csv --reference P001,P002", "--reference"},
        Case{"match --data p.csv --reference P001,P002,Q9", "no point with id 'Q9'"},
        Case{"match --data line.csv --method closed-form", "line.csv: the nominal points are collinear"},
        Case{"match --data two.csv", "two.csv: has 2 points"},
        Case{"match --data p.csv --machine hexapod", "--machine"},
        Case{"match --data p.csv --machine-def bad.json", "bad.json"},
        Case{"match --data p.csv --machine-def nomachine.metrofit",
             "nomachine.metrofit: field 'studies.matching.machine': the project defines no machine"},
        Case{"match --data p.csv --method icp", "--method"},
        Case{"match --data p.csv --frame fanuc", "field '--frame': needs --frame-out FILE"},
        Case{"match --data p.csv --frame-out f.nc",
             "field '--frame-out': needs --frame heidenhain|siemens|fanuc"},
        Case{"match --data p.csv --frame haas --frame-out f.nc", "--frame"},
        Case{"match --data p.csv --frame siemens --frame-out f.spf --frame-decimals 13",
             "--frame-decimals"}}) {
    const CliRun r = cli(c.args + " --out r.json", tmp);
    EXPECT_EQ(r.code, 2) << c.args << ": " << r.err;
    EXPECT_EQ(lines(r.err), 1) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(tmp.file("r.json"))) << c.args;
  }
}

TEST_F(MatchCli, FrameFileRebuildsThePosture) {
  // The G68.2 block of --frame fanuc, read back here with Fanuc's Euler convention (I about Z, J about
  // the new X, K about the new Z: R = Rz(I) Rx(J) Rz(K)), gives the rotation of the JSON's
  // rotation_deg (CONTRACT: R = Rz(rz) Ry(ry) Rx(rx)) and its translation.
  const nlohmann::json j = runJson(
      "match --data p.csv --method closed-form --frame fanuc --frame-out f.nc --frame-decimals 10", tmp);
  EXPECT_EQ(j.at("frame").at("format"), "fanuc");
  EXPECT_EQ(j.at("frame").at("file"), "f.nc");
  const std::string text = test::readText(tmp.file("f.nc"));
  double x, y, z, i, jj, k;
  const auto at = text.find("\nG68.2 ");
  ASSERT_NE(at, std::string::npos) << text;
  ASSERT_EQ(std::sscanf(text.c_str() + at, "\nG68.2 X%lf Y%lf Z%lf I%lf J%lf K%lf", &x, &y, &z, &i, &jj, &k),
            6)
      << text;
  const double d = 3.14159265358979323846 / 180.0;
  auto rz = [&](double a) {
    Eigen::Matrix3d m;
    m << std::cos(a * d), -std::sin(a * d), 0, std::sin(a * d), std::cos(a * d), 0, 0, 0, 1;
    return m;
  };
  auto ry = [&](double a) {
    Eigen::Matrix3d m;
    m << std::cos(a * d), 0, std::sin(a * d), 0, 1, 0, -std::sin(a * d), 0, std::cos(a * d);
    return m;
  };
  auto rx = [&](double a) {
    Eigen::Matrix3d m;
    m << 1, 0, 0, 0, std::cos(a * d), -std::sin(a * d), 0, std::sin(a * d), std::cos(a * d);
    return m;
  };
  const auto& r = j.at("rotation_deg");
  const Eigen::Matrix3d R = rz(r[2].get<double>()) * ry(r[1].get<double>()) * rx(r[0].get<double>());
  EXPECT_LT((rz(i) * rx(jj) * rz(k) - R).cwiseAbs().maxCoeff(), 1e-9) << text;
  const auto& t = j.at("translation_mm");
  EXPECT_NEAR(x, t[0].get<double>(), 1e-9);
  EXPECT_NEAR(y, t[1].get<double>(), 1e-9);
  EXPECT_NEAR(z, t[2].get<double>(), 1e-9);
  EXPECT_EQ(text.rfind("%\nO7101 (METROFIT POSTURE FRAME)\n", 0), 0u) << text;

  // HEIDENHAIN: the datum shift is t, PLANE SPATIAL rebuilds R as Rz(SPC) Ry(SPB) Rx(SPA).
  (void)runJson(
      "match --data p.csv --method closed-form --frame heidenhain --frame-out f.h --frame-decimals 10", tmp);
  const std::string h = test::readText(tmp.file("f.h"));
  EXPECT_EQ(h.rfind("0 BEGIN PGM f MM\n", 0), 0u) << h;  // the program is named after its file
  EXPECT_NE(h.find(" END PGM f MM\n"), std::string::npos) << h;
  double spa, spb, spc;
  const auto p = h.find("PLANE SPATIAL SPA");
  ASSERT_NE(p, std::string::npos) << h;
  ASSERT_EQ(std::sscanf(h.c_str() + p, "PLANE SPATIAL SPA%lf SPB%lf SPC%lf", &spa, &spb, &spc), 3) << h;
  EXPECT_LT((rz(spc) * ry(spb) * rx(spa) - R).cwiseAbs().maxCoeff(), 1e-9) << h;
}

TEST_F(MatchCli, GaSimplexIsThePapersComparison) {
  const nlohmann::json g = runJson("match --data p.csv --method ga-simplex --seed 3", tmp);
  EXPECT_EQ(g.at("method"), "ga-simplex");
  EXPECT_FALSE(g.at("trace").empty());
  EXPECT_EQ(g.at("out_of_tolerance").at("after").get<int>(), 0);
  EXPECT_EQ(g.at("rough").at("reference_ids").size(), 3u);
}

TEST_F(MatchCli, HoleTableReportIsReadByContent) {
  // A PC-DMIS hole table (the layout of the plug-plate reports), no extension: planar, position-only.
  std::string text =
      "Plug Plate: 9003\r\nDate: 2021-01-01\r\n\r\n"
      "    Meas X    Meas Y     Nom X     Nom Y     Err X     Err Y  Meas D   Nom D   Round\r\n";
  const double nominal[][2] = {{-250, -100}, {-120, 240}, {0, 0}, {60, -280}, {200, 150}, {290, -40}};
  for (const auto& q : nominal) {
    // Shifted by (0.04, -0.02) mm and rotated by 0.01 deg (x' = x - y th, y' = y + x th).
    const double th = 0.01 * 3.14159265358979 / 180.0;
    const double mx = std::round((q[0] - q[1] * th + 0.04) * 1000) / 1000;
    const double my = std::round((q[1] + q[0] * th - 0.02) * 1000) / 1000;
    char line[200];
    std::snprintf(line, sizeof line, "%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f%8.3f%8.3f%8.3f\r\n", mx, my, q[0],
                  q[1], mx - q[0], my - q[1], 2.170, 2.167, 0.004);
    text += line;
  }
  test::writeText(tmp.file("D9003_1"), text);
  const nlohmann::json j = runJson("match --data D9003_1 --method closed-form --tolerance 0.009", tmp);
  EXPECT_EQ(j.at("points"), 6);
  EXPECT_EQ(j.at("planar"), true);
  EXPECT_EQ(j.at("normals"), false);
  EXPECT_NEAR(j.at("rotation_deg")[2].get<double>(), 0.01, 2e-4);
  EXPECT_EQ(j.at("rotation_deg")[0].get<double>(), 0.0);
  EXPECT_NEAR(j.at("translation_mm")[0].get<double>(), 0.04, 1e-3);
  EXPECT_NEAR(j.at("translation_mm")[1].get<double>(), -0.02, 1e-3);
  EXPECT_EQ(j.at("after").at("surfaces")[0].at("surface"), "hole D2.167");

  // A bad value: exit 2, one line naming file, line and column.
  text.replace(text.find("2.170"), 5, "2.1x0");
  test::writeText(tmp.file("D9003_2"), text);
  const CliRun bad = cli("match --data D9003_2 --method closed-form", tmp);
  EXPECT_EQ(bad.code, 2);
  EXPECT_EQ(lines(bad.err), 1) << bad.err;
  EXPECT_NE(bad.err.find("D9003_2:5:7: field 'Meas D': '2.1x0' is not a finite number"), std::string::npos)
      << bad.err;
}

TEST_F(MatchCli, SimulatedSPieceIsThePapersCase) {
  const CliRun sim = cli("simulate probe --shape s-piece --seed 7 --out s.csv", tmp);
  ASSERT_EQ(sim.code, 0) << sim.err;
  EXPECT_EQ(test::readText(tmp.file("s.csv")),
            test::readText((test::sourceDir() / "resources/demo/data/probe_s_piece.csv").string()));
  const nlohmann::json j = runJson("match --data s.csv --method sade --tolerance 0.035", tmp);
  EXPECT_EQ(j.at("points"), 40);
  EXPECT_EQ(j.at("out_of_tolerance").at("before"), 40);
  EXPECT_EQ(j.at("out_of_tolerance").at("after"), 0);
  EXPECT_NEAR(j.at("before").at("mean_over_tolerance_mm").get<double>(), 1.88, 0.05);
  EXPECT_EQ(cli("simulate probe --shape cube", tmp).code, 2);
}

/// The Wenzel file's `Residues` column (the CMM's own residuals of its sphere fit), split by the test.
std::map<std::string, double> wenzelResidues(const std::filesystem::path& file) {
  std::map<std::string, double> out;
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::istringstream s(line);
    s.imbue(std::locale::classic());
    std::string id;
    double x, y, z, res;
    if (s >> id >> x >> y >> z >> res) out[id] = res;
  }
  return out;
}

TEST(MatchCliNominals, RawPointsTakeTheirNominalsFromAFittedSphere) {
  const auto file = test::realData("cmm-wenzel-lens-points/SPH1_1");
  METROFIT_REQUIRE_PATH(file);
  test::TempDir tmp;
  const CliRun r =
      cli("match --data " + file.string() + " --nominal-element sphere --per-point pp.csv --out m.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = readJsonFile(tmp.file("m.json"));
  EXPECT_EQ(j["points"], 18);
  EXPECT_EQ(j["normals"], true);
  // After the fit, each point's deviation along the sphere's normal is the CMM's residual to its print
  // resolution (1 um): the nominals are the feet on the least-squares sphere, as the CMM's are.
  const std::map<std::string, double> cmm = wenzelResidues(file);
  ASSERT_EQ(j["per_point"].size(), cmm.size());
  for (const auto& p : j["per_point"]) {
    const std::string id = p["id"].get<std::string>();
    ASSERT_TRUE(cmm.count(id)) << id;
    EXPECT_NEAR(p["d_mm"].get<double>(), cmm.at(id), 1.0e-3 + 1e-9) << id;
  }
  const CsvTable csv = readCsvFile(tmp.file("pp.csv"));
  EXPECT_EQ(csv.rowCount(), cmm.size());
  EXPECT_EQ(csv.cell(0, csv.requireColumn("surface")), "sphere");
}

TEST(MatchCliNominals, RawPointsTakeTheirNominalsFromASecondMeasurement) {
  const auto first = test::realData("cmm-wenzel-lens-points/SPH1_1");
  const auto second = test::realData("cmm-wenzel-lens-points/SPH1_2");
  METROFIT_REQUIRE_PATH(first);
  METROFIT_REQUIRE_PATH(second);
  test::TempDir tmp;
  CliRun r = cli("match --data " + second.string() + " --nominal-reference " + first.string() +
                     " --nominal-element sphere --out m.json",
                 tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = readJsonFile(tmp.file("m.json"));
  EXPECT_EQ(j["points"], 18);
  EXPECT_EQ(j["normals"], true);
  // The same program measured the lens twice: after matching, the repeat agrees to tens of um.
  EXPECT_LT(j["max_abs_mm"].get<double>(), 0.1) << j.dump();
  // Without an element the points are position-only.
  r = cli("match --data " + second.string() + " --nominal-reference " + first.string() + " --out p.json",
          tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(readJsonFile(tmp.file("p.json"))["normals"], false);
  // Options that need an element, and pairs that do not exist, exit 2 with one line.
  r = cli("match --data " + second.string() + " --nominal-radius 5 --out x.json", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("--nominal-element"), std::string::npos) << r.err;
  test::writeText(tmp.file("other.csv"), "id,x,y,z\nA,0,0,0\nB,1,0,0\nC,0,1,0\n");
  r = cli("match --data other.csv --nominal-reference " + first.string() + " --out x.json", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("3 point(s) have no point of the same id"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.file("x.json")));
}

}  // namespace
}  // namespace metrofit
