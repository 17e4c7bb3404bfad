#include "core/geometry/point_table.h"

#include <cctype>
#include <cmath>
#include <set>

#include "core/common/error.h"
#include "core/io/csv.h"

namespace metrofit::geometry {

PointTableColumns pointTableColumns(const CsvTable& t) {
  for (const auto& [x, y, z, bare] : {std::tuple{"x_mm", "y_mm", "z_mm", false},
                                      std::tuple{"px", "py", "pz", false}, std::tuple{"x", "y", "z", true}}) {
    if (t.columnIndex(x) >= 0) return {x, y, z, bare};
  }
  throw InputError(ErrorContext{t.source(), 0, 0, "x_mm"},
                   "has no point columns: expected x_mm,y_mm,z_mm, px,py,pz or x,y,z");
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
  std::set<std::string> seen;
  for (std::size_t r = 0; r < t.rowCount(); ++r) {
    const Eigen::Vector3d p(f * t.number(r, cx), f * t.number(r, cy), f * t.number(r, cz));
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(p(k)))
        throw ValidationError(ErrorContext{t.source(), t.lineOf(r), 0,
                                           k == 0   ? c.x
                                           : k == 1 ? c.y
                                                    : c.z},
                              "is not a finite number");
    }
    set.points.push_back(p);
    set.lines.push_back(t.lineOf(r));
    if (cid >= 0) {
      const std::string& id = t.cell(r, static_cast<std::size_t>(cid));
      if (!seen.insert(id).second)
        throw ValidationError(ErrorContext{t.source(), t.lineOf(r), 0, "id"},
                              "repeats the point id '" + id + "'");
      set.ids.push_back(id);
    }
  }
  return set;
}

}  // namespace metrofit::geometry
