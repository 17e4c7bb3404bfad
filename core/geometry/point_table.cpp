#include "core/geometry/point_table.h"

#include <cctype>
#include <cmath>
#include <unordered_map>

#include "core/common/error.h"
#include "core/io/csv.h"

namespace metrofit::geometry {

PointTableColumns pointTableColumns(const CsvTable& t) {
  for (const auto& [x, y, z, bare] :
       {std::tuple{"px", "py", "pz", false}, std::tuple{"x_mm", "y_mm", "z_mm", false},
        std::tuple{"x", "y", "z", true}}) {
    if (t.columnIndex(x) >= 0 || t.columnIndex(y) >= 0 || t.columnIndex(z) >= 0) return {x, y, z, bare};
  }
  throw ValidationError(ErrorContext{t.source(), t.headerLineNumber(), 0, {}},
                        "measured points need the columns px,py,pz, x_mm,y_mm,z_mm or x,y,z");
}

PointSet pointsFromTable(const CsvTable& t, double bareFactorMm) {
  const PointTableColumns c = pointTableColumns(t);
  const double f = c.bare ? bareFactorMm : 1.0;
  const std::size_t cx = t.requireColumn(c.x), cy = t.requireColumn(c.y), cz = t.requireColumn(c.z);
  // The id column: `id` in any case ("ID" as CMM exports write it).
  int cid = t.columnIndex("id");
  for (std::size_t k = 0; cid < 0 && k < t.header().size(); ++k) {
    std::string h = t.header()[k];
    for (char& ch : h) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (h == "id") cid = static_cast<int>(k);
  }
  PointSet set;
  set.source = t.source();
  std::unordered_map<std::string, std::size_t> seen;
  for (std::size_t r = 0; r < t.rowCount(); ++r) {
    const Eigen::Vector3d p(f * t.number(r, cx), f * t.number(r, cy), f * t.number(r, cz));
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(p(k))) t.failAt(r, k == 0 ? cx : k == 1 ? cy : cz, "is not a finite number");
    }
    set.points.push_back(p);
    set.lines.push_back(t.lineOf(r));
    if (cid >= 0) {
      const auto c = static_cast<std::size_t>(cid);
      const std::string& id = t.cell(r, c);
      if (id.empty()) t.failAt(r, c, "empty point id");
      if (auto [it, fresh] = seen.emplace(id, r); !fresh)
        t.failAt(
            r, c,
            "duplicate point id '" + id + "' (first on line " + std::to_string(t.lineOf(it->second)) + ")");
      set.ids.push_back(id);
    }
  }
  return set;
}

PointSet readPointTable(const std::string& path, const CsvReadOptions& csv, double bareFactorMm) {
  return pointsFromTable(readCsvFile(path, csv), bareFactorMm);
}

}  // namespace metrofit::geometry
