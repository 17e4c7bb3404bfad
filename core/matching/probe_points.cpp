#include "core/matching/probe_points.h"

#include <cmath>
#include <unordered_map>

#include "core/common/error.h"
#include "core/io/csv.h"

namespace metrofit {

double ProbePointSet::deviation(std::size_t i, const Eigen::Vector3d& q, const Eigen::Vector3d& n) const {
  const Eigen::Vector3d r = points[i].measured - q;
  return hasNormals ? r.dot(n) : r.norm();
}

std::vector<double> ProbePointSet::deviations() const {
  std::vector<double> out(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) out[i] = deviation(i, points[i].nominal, points[i].normal);
  return out;
}

ProbePointSet probePointsFromCsv(const CsvTable& t, std::size_t minPoints) {
  ProbePointSet set;
  set.source = t.source();
  const bool hasZ = t.columnIndex("qz") >= 0 || t.columnIndex("pz") >= 0;
  const int nCols = (t.columnIndex("nx") >= 0) + (t.columnIndex("ny") >= 0) + (t.columnIndex("nz") >= 0);
  set.planar = !hasZ;
  set.hasNormals = nCols > 0;
  if (set.hasNormals) {
    // A normal needs all its components present (nz may be absent only in planar data).
    t.requireColumn("nx");
    t.requireColumn("ny");
    if (hasZ) t.requireColumn("nz");
  }
  const std::size_t id = t.requireColumn("id");
  const int surface = t.columnIndex("surface");
  const std::size_t qx = t.requireColumn("qx"), qy = t.requireColumn("qy");
  const std::size_t px = t.requireColumn("px"), py = t.requireColumn("py");
  const int qz = hasZ ? static_cast<int>(t.requireColumn("qz")) : -1;
  const int pz = hasZ ? static_cast<int>(t.requireColumn("pz")) : -1;
  const int nx = t.columnIndex("nx"), ny = t.columnIndex("ny"), nz = t.columnIndex("nz");

  std::unordered_map<std::string, std::size_t> seen;
  set.points.reserve(t.rowCount());
  for (std::size_t r = 0; r < t.rowCount(); ++r) {
    ProbePoint p;
    p.id = t.cell(r, id);
    if (p.id.empty()) t.failAt(r, id, "empty point id");
    if (auto [it, fresh] = seen.emplace(p.id, r); !fresh) {
      t.failAt(
          r, id,
          "duplicate point id '" + p.id + "' (first on line " + std::to_string(t.lineOf(it->second)) + ")");
    }
    p.surface = surface >= 0 ? t.cell(r, static_cast<std::size_t>(surface)) : std::string();
    p.nominal = {t.number(r, qx), t.number(r, qy), qz >= 0 ? t.number(r, static_cast<std::size_t>(qz)) : 0.0};
    p.measured = {t.number(r, px), t.number(r, py),
                  pz >= 0 ? t.number(r, static_cast<std::size_t>(pz)) : 0.0};
    if (set.hasNormals) {
      p.normal = {t.number(r, static_cast<std::size_t>(nx)), t.number(r, static_cast<std::size_t>(ny)),
                  nz >= 0 ? t.number(r, static_cast<std::size_t>(nz)) : 0.0};
      const double len = p.normal.norm();
      if (len == 0.0)
        t.failAt(r, static_cast<std::size_t>(nx), "zero normal vector; every point needs a unit normal");
      if (std::abs(len - 1.0) > 1e-3) {
        t.failAt(r, static_cast<std::size_t>(nx),
                 "normal is not a unit vector (length " + CsvWriter::formatNumber(len, 6) + ")");
      }
    }
    set.points.push_back(std::move(p));
  }
  if (set.points.size() < minPoints) {
    throw ValidationError(ErrorContext{t.source(), 0, 0, {}}, "has " + std::to_string(set.points.size()) +
                                                                  " points, at least " +
                                                                  std::to_string(minPoints) + " needed");
  }
  return set;
}

ProbePointSet readProbePoints(const std::string& path, std::size_t minPoints, const CsvReadOptions& csv) {
  return probePointsFromCsv(readCsvFile(path, csv), minPoints);
}

std::string probePointsToCsv(const ProbePointSet& set) {
  CsvWriter w;
  std::vector<std::string> header{"id", "surface", "qx", "qy"};
  if (!set.planar) header.push_back("qz");
  if (set.hasNormals) {
    header.insert(header.end(), {"nx", "ny"});
    if (!set.planar) header.push_back("nz");
  }
  header.insert(header.end(), {"px", "py"});
  if (!set.planar) header.push_back("pz");
  w.row(header);
  auto f = [](double v) { return CsvWriter::formatNumber(std::round(v * 1e6) / 1e6); };
  for (const auto& p : set.points) {
    std::vector<std::string> row{p.id, p.surface, f(p.nominal.x()), f(p.nominal.y())};
    if (!set.planar) row.push_back(f(p.nominal.z()));
    if (set.hasNormals) {
      row.insert(row.end(),
                 {CsvWriter::formatNumber(p.normal.x(), 9), CsvWriter::formatNumber(p.normal.y(), 9)});
      if (!set.planar) row.push_back(CsvWriter::formatNumber(p.normal.z(), 9));
    }
    row.insert(row.end(), {f(p.measured.x()), f(p.measured.y())});
    if (!set.planar) row.push_back(f(p.measured.z()));
    w.row(row);
  }
  return w.text();
}

}  // namespace metrofit
