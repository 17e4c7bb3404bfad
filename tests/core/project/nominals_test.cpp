// Nominals for measured points (core/project/nominals.h): from an element fitted to them (checked against
// the Wenzel CMM's own per-point residuals of its sphere fit, ../shared/data/real/cmm-wenzel-lens-points,
// read here with a parser of the test's own), from a second measurement (paired by id or by order), the
// recipe in the project file, and `project add` with raw points in a German spreadsheet's conventions.
#include "core/project/nominals.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "core/common/error.h"
#include "core/geometry/point_table.h"
#include "core/io/json_util.h"
#include "core/project/dataset_content.h"
#include "core/project/datasets.h"
#include "testsupport.h"

namespace metrofit {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// The Wenzel file's `ID x y z Residues` columns, split on tabs by the test.
struct WenzelRow {
  std::string id;
  Eigen::Vector3d p;
  double residue = 0.0;
};
std::vector<WenzelRow> wenzel(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);  // header
  std::vector<WenzelRow> rows;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::istringstream s(line);
    s.imbue(std::locale::classic());
    WenzelRow r;
    s >> r.id >> r.p.x() >> r.p.y() >> r.p.z() >> r.residue;
    rows.push_back(r);
  }
  return rows;
}

std::string whatOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(Nominals, FromAFittedSphereTheDeviationsAreTheCmmResiduals) {
  for (const char* name : {"SPH1_1", "SPH1_2", "SPH2_3"}) {
    const auto file = test::realData(std::string("cmm-wenzel-lens-points/") + name);
    METROFIT_REQUIRE_PATH(file);
    const std::vector<WenzelRow> rows = wenzel(file);
    const geometry::PointSet measured = geometry::readPointTable(file.string(), {});
    ASSERT_EQ(measured.points.size(), rows.size());
    ASSERT_EQ(measured.ids.size(), rows.size()) << "the `ID` column names the points";
    NominalSource n;
    n.from = "element";
    n.element = "sphere";
    const NominalsOutcome out = nominalsFor(measured, n, nullptr);
    ASSERT_TRUE(out.set.hasNormals);
    ASSERT_TRUE(out.fit.has_value());
    double worst = 0.0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const ProbePoint& p = out.set.points[i];
      EXPECT_EQ(p.id, rows[i].id);
      EXPECT_LT((p.measured - rows[i].p).norm(), 1e-12);
      const double d = out.set.deviation(i, p.nominal, p.normal);
      worst = std::max(worst, std::abs(d - rows[i].residue));
    }
    // The CMM prints its residuals to 1 um; the two least-squares spheres are the same to below that.
    EXPECT_LE(worst, 1.0e-3 + 1e-9) << name;
    std::printf(
        "[ measured ] %s: deviation along the fitted sphere's normal vs the CMM's residual: max %.2g mm\n",
        name, worst);
  }
}

/// A cylinder of radius 10 along z through (5, 5, 0), 24 points on 3 heights, point k moved radially by
/// dev(k).
geometry::PointSet bore(double (*dev)(int)) {
  geometry::PointSet s;
  s.source = "bore.csv";
  for (int k = 0; k < 24; ++k) {
    const double a = 2.0 * kPi * (k % 8) / 8.0 + 0.1 * k, z = 5.0 * (k / 8);
    const double r = 10.0 + dev(k);
    s.points.emplace_back(5.0 + r * std::cos(a), 5.0 + r * std::sin(a), z);
    s.ids.push_back("B" + std::to_string(k));
  }
  return s;
}

TEST(Nominals, AnInnerElementTurnsTheNormalsInwards) {
  const geometry::PointSet s = bore([](int k) { return k == 5 ? 0.02 : 0.0; });
  NominalSource n;
  n.from = "element";
  n.element = "cylinder";
  n.radiusMm = 10.0;  // the drawing's bore
  const NominalsOutcome outer = nominalsFor(s, n, nullptr);
  n.inner = true;
  const NominalsOutcome inner = nominalsFor(s, n, nullptr);
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const ProbePoint& o = outer.set.points[i];
    const ProbePoint& b = inner.set.points[i];
    EXPECT_LT((o.normal + b.normal).norm(), 1e-12);
    EXPECT_LT((o.nominal - b.nominal).norm(), 1e-12);
    // Out of the material: towards the bore's axis.
    const Eigen::Vector3d towardsAxis = (Eigen::Vector3d(5.0, 5.0, b.nominal.z()) - b.nominal).normalized();
    EXPECT_GT(b.normal.dot(towardsAxis), 0.999);
  }
  // Point 5 lies 20 um outside the bore radius: the bore is bigger there, less material: negative, less
  // than 20 um because the fitted axis moves and tilts towards it; the sign is the outer one reversed.
  const double d5 = inner.set.deviation(5, inner.set.points[5].nominal, inner.set.points[5].normal);
  const double o5 = outer.set.deviation(5, outer.set.points[5].nominal, outer.set.points[5].normal);
  EXPECT_LT(d5, -0.010);
  EXPECT_GT(d5, -0.020);
  EXPECT_NEAR(d5, -o5, 1e-15);
  // Each deviation along the (inward) normal is the fitted cylinder's residual, reversed.
  for (std::size_t i = 0; i < s.points.size(); ++i)
    EXPECT_NEAR(inner.set.deviation(i, inner.set.points[i].nominal, inner.set.points[i].normal),
                -inner.fit->residualsMm[i], 1e-12);
}

TEST(Nominals, ASecondMeasurementPairsByIdInAnyOrder) {
  // The reference: points exactly on a sphere (centre (1, 2, 3), r 30); the second measurement: the
  // same points in reverse order, moved by 5 um along x, one point 40 um off.
  geometry::PointSet ref;
  ref.source = "first.csv";
  for (int k = 0; k < 12; ++k) {
    const double th = 0.3 + 0.9 * (k % 3) / 2.0, ph = 2.0 * kPi * k / 12.0;
    ref.points.emplace_back(1.0 + 30.0 * std::sin(th) * std::cos(ph),
                            2.0 + 30.0 * std::sin(th) * std::sin(ph), 3.0 + 30.0 * std::cos(th));
    ref.ids.push_back("P" + std::to_string(k + 1));
  }
  geometry::PointSet second;
  second.source = "second.csv";
  for (int k = 11; k >= 0; --k) {
    Eigen::Vector3d p = ref.points[static_cast<std::size_t>(k)] + Eigen::Vector3d(0.005, 0.0, 0.0);
    if (k == 4) p += 0.040 * (ref.points[4] - Eigen::Vector3d(1, 2, 3)).normalized();
    second.points.push_back(p);
    second.ids.push_back(ref.ids[static_cast<std::size_t>(k)]);
  }
  NominalSource n;
  n.from = "reference";
  n.reference = "first";
  const NominalsOutcome plain = nominalsFor(second, n, &ref);
  EXPECT_FALSE(plain.set.hasNormals);
  for (std::size_t i = 0; i < second.points.size(); ++i) {
    const std::size_t k = 11 - i;
    EXPECT_EQ(plain.set.points[i].id, ref.ids[k]);
    EXPECT_LT((plain.set.points[i].nominal - ref.points[k]).norm(), 1e-15);
  }
  // With the normals of a sphere fitted to the reference: radial at each reference point.
  n.element = "sphere";
  const NominalsOutcome withNormals = nominalsFor(second, n, &ref);
  ASSERT_TRUE(withNormals.set.hasNormals);
  for (std::size_t i = 0; i < second.points.size(); ++i) {
    const ProbePoint& p = withNormals.set.points[i];
    EXPECT_LT((p.normal - (p.nominal - Eigen::Vector3d(1, 2, 3)).normalized()).norm(), 1e-6);
  }
  // Point P5 (index 7 in the second file) is 40 um out along its normal (+ 5 um of x shift projected).
  const ProbePoint& p5 = withNormals.set.points[7];
  ASSERT_EQ(p5.id, "P5");
  EXPECT_NEAR(withNormals.set.deviation(7, p5.nominal, p5.normal), 0.040 + 0.005 * p5.normal.x(), 1e-9);
  // By order the pairs are others (the files are in reverse order): P12 is paired with P1.
  n.pair = "order";
  const NominalsOutcome byOrder = nominalsFor(second, n, &ref);
  EXPECT_LT((byOrder.set.points[0].nominal - ref.points[0]).norm(), 1e-15);
}

TEST(Nominals, UnpairedPointsAndBadRecipesAreNamed) {
  geometry::PointSet ref, meas;
  ref.source = "first.csv";
  meas.source = "second.csv";
  for (int k = 0; k < 4; ++k) {
    ref.points.emplace_back(k, k * k, 1.0);
    ref.ids.push_back("P" + std::to_string(k));
    meas.points.emplace_back(k, k * k, 1.01);
    meas.ids.push_back(k == 2 ? "Q7" : "P" + std::to_string(k));
  }
  NominalSource n;
  n.from = "reference";
  n.reference = "first";
  EXPECT_NE(whatOf([&] { nominalsFor(meas, n, &ref); })
                .find("1 point(s) have no point of the same id in "
                      "first.csv: Q7"),
            std::string::npos);
  ref.points.pop_back();
  ref.ids.pop_back();
  n.pair = "order";
  EXPECT_NE(whatOf([&] { nominalsFor(meas, n, &ref); }).find("pairing by order needs the same number"),
            std::string::npos);
  meas.ids.clear();
  n.pair = "id";
  EXPECT_NE(whatOf([&] { nominalsFor(meas, n, &ref); }).find("has no id column"), std::string::npos);

  const auto check = [](NominalSource s) { return whatOf([&] { checkNominalSource(s); }); };
  NominalSource e;
  e.from = "element";
  EXPECT_NE(check(e).find("nominals.element"), std::string::npos);
  e.element = "torus";
  EXPECT_NE(check(e).find("must be plane, line, circle, sphere, cylinder or cone"), std::string::npos);
  e.element = "plane";
  e.radiusMm = 5.0;
  EXPECT_NE(check(e).find("a fixed radius is for a sphere, circle or cylinder"), std::string::npos);
  e.element = "sphere";
  e.radiusMm = std::nan("");
  EXPECT_NE(check(e).find("nominals.radius_mm"), std::string::npos);
  e.radiusMm = 0.0;
  e.criterion = "chebyshev";
  EXPECT_NE(check(e).find("must be 'ls' or 'minimax'"), std::string::npos);
  e.criterion = "minimax";
  EXPECT_EQ(check(e), "no error");
  e.from = "scan";
  EXPECT_NE(check(e).find("must be 'element', 'reference' or 'cad'"), std::string::npos);
  // A CAD part is the whole nominal: no element or fit options with it.
  e.from = "cad";
  e.cad = "part";
  EXPECT_NE(check(e).find("take no element, fit or reference options"), std::string::npos);
  NominalSource c;
  c.from = "cad";
  EXPECT_NE(check(c).find("nominals.cad"), std::string::npos);
  c.cad = "part";
  EXPECT_EQ(check(c), "no error");
  NominalSource r;
  r.from = "reference";
  EXPECT_NE(check(r).find("nominals.reference"), std::string::npos);
  r.reference = "x";
  r.pair = "nearest";
  EXPECT_NE(check(r).find("must be 'id' or 'order'"), std::string::npos);
}

TEST(Nominals, TheRecipeIsKeptInTheProjectFile) {
  Project p;
  DatasetRef a;
  a.id = "first";
  a.kind = dataset_kind::kProbePoints;
  a.path = "first.csv";
  a.nominals.from = "element";
  a.nominals.element = "cylinder";
  a.nominals.radiusMm = 6.0;
  a.nominals.inner = true;
  a.nominals.robust = true;
  a.nominals.criterion = "minimax";
  DatasetRef b = a;
  b.id = "second";
  b.path = "second.csv";
  b.nominals = {};
  b.nominals.from = "reference";
  b.nominals.reference = "first";
  b.nominals.pair = "order";
  p.datasets = {a, b};
  const nlohmann::json j = p.toJson();
  EXPECT_EQ(j["datasets"][0]["nominals"],
            nlohmann::json::parse(R"({"from":"element","element":"cylinder","criterion":"minimax",
                                      "radius_mm":6.0,"robust":true,"inner":true})"));
  EXPECT_EQ(j["datasets"][1]["nominals"],
            nlohmann::json::parse(R"({"from":"reference","reference":"first","pair":"order"})"));
  EXPECT_EQ(Project::fromJson(j, "p.metrofit"), p);

  nlohmann::json bad = j;
  bad["datasets"][0]["kind"] = "thermal_log";
  EXPECT_NE(whatOf([&] { Project::fromJson(bad, "p.metrofit"); }).find("only a probe-point dataset"),
            std::string::npos);
  bad = j;
  bad["datasets"][0]["nominals"]["radius"] = 6.0;
  EXPECT_NE(whatOf([&] { Project::fromJson(bad, "p.metrofit"); }).find("unknown key"), std::string::npos);
  bad = j;
  bad["datasets"][0]["nominals"]["element"] = "torus";
  const std::string w = whatOf([&] { Project::fromJson(bad, "p.metrofit"); });
  EXPECT_NE(w.find("p.metrofit"), std::string::npos) << w;
  EXPECT_NE(w.find("dataset 'first'"), std::string::npos) << w;
}

/// Raw points as a German spreadsheet writes them: `;`, decimal commas, "Punkt", "X [mm]".
std::string germanRawPoints(double dx, bool reverse) {
  std::string s = "Punkt;X [mm];Y [mm];Z [mm]\n";
  std::vector<std::string> lines;
  for (int k = 0; k < 10; ++k) {
    const double ph = 2.0 * kPi * k / 10.0, th = 0.4 + 0.3 * (k % 2);
    char buf[128];
    std::snprintf(buf, sizeof buf, "K%d;%.6f;%.6f;%.6f\n", k + 1, 20.0 * std::sin(th) * std::cos(ph) + dx,
                  20.0 * std::sin(th) * std::sin(ph), 20.0 * std::cos(th));
    std::string line = buf;
    for (char& c : line)
      if (c == '.') c = ',';
    lines.push_back(line);
  }
  if (reverse) std::reverse(lines.begin(), lines.end());
  for (const std::string& l : lines) s += l;
  return s;
}

TEST(Nominals, ProjectAddTakesRawPointsWithAnElementOrAReference) {
  test::TempDir tmp;
  test::writeText(tmp.file("first.csv"), germanRawPoints(0.0, false));
  test::writeText(tmp.file("second.csv"), germanRawPoints(0.003, true));
  const std::string projectPath = tmp.file("p.metrofit");
  Project p;
  AddDatasetRequest r;
  r.kind = "probe-points";
  r.file = tmp.file("first.csv");
  r.guessRoles = true;
  // Without nominals the raw points are not probe points: the error says what is missing.
  EXPECT_NE(whatOf([&] {
              Project copy = p;
              addDataset(copy, projectPath, r);
            }).find("qx"),
            std::string::npos);
  r.nominals.from = "element";
  r.nominals.element = "sphere";
  const DatasetRef first = addDataset(p, projectPath, r);
  EXPECT_EQ(first.nominals.element, "sphere");
  const ProbePointSet a = readProjectProbePoints(p, projectPath, first);
  ASSERT_EQ(a.points.size(), 10u);
  EXPECT_EQ(a.points[0].id, "K1");
  EXPECT_TRUE(a.hasNormals);
  for (std::size_t i = 0; i < a.points.size(); ++i)
    EXPECT_NEAR(a.deviation(i, a.points[i].nominal, a.points[i].normal), 0.0, 2e-6);  // on the sphere

  AddDatasetRequest second = r;
  second.file = tmp.file("second.csv");
  second.nominals = {};
  second.nominals.from = "reference";
  second.nominals.reference = "nowhere";
  EXPECT_NE(whatOf([&] {
              Project copy = p;
              addDataset(copy, projectPath, second);
            }).find("'nowhere' is not another probe-point dataset"),
            std::string::npos);
  second.nominals.reference = "first";
  const DatasetRef ds = addDataset(p, projectPath, second);
  const ProbePointSet b = readProjectProbePoints(p, projectPath, ds);
  ASSERT_EQ(b.points.size(), 10u);
  EXPECT_EQ(b.points[0].id, "K10");
  EXPECT_FALSE(b.hasNormals);
  // K10's nominal is the first measurement's K10, 3 um away along x.
  const ProbePoint& k10 = b.points[0];
  EXPECT_LT((k10.measured - k10.nominal - Eigen::Vector3d(0.003, 0, 0)).norm(), 2e-6);
  // The project file keeps it and reads back equal.
  saveProject(p, projectPath);
  EXPECT_EQ(loadProject(projectPath), p);
  EXPECT_EQ(summarizeDataset(projectPath, ds).rows, 10);

  // The data view shows the points as the studies read them, with each deviation before matching.
  const DatasetContent content = readDatasetContent(projectPath, ds, &p);
  EXPECT_EQ(content.format, "measured points, nominals from 'first'");
  const CsvTable& t = content.table;
  ASSERT_EQ(t.rowCount(), 10u);
  const std::size_t d = t.requireColumn("d_mm"), qx = t.requireColumn("qx"), px = t.requireColumn("px");
  EXPECT_EQ(t.cell(0, t.requireColumn("id")), "K10");
  for (std::size_t r = 0; r < t.rowCount(); ++r) {
    // Position-only points: the distance, here the 3 um shift along x (to the file's 6 decimals).
    EXPECT_NEAR(t.number(r, d), 0.003, 2e-6);
    EXPECT_NEAR(t.number(r, px) - t.number(r, qx), 0.003, 2e-6);
  }
  EXPECT_EQ(content.units[d], "mm");
  const DatasetContent sphere = readDatasetContent(projectPath, first, &p);
  EXPECT_EQ(sphere.format, "measured points, nominals on the fitted sphere");
  EXPECT_GE(sphere.table.columnIndex("nz"), 0);
}

}  // namespace
}  // namespace metrofit
