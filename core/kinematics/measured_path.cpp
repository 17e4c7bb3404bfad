#include "core/kinematics/measured_path.h"

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/kinematics/iso230_4.h"

namespace metrofit {
namespace {

std::string num(double v) {
  return CsvWriter::formatNumber(v);
}

}  // namespace

MeasuredPath measuredPathFromCsv(const CsvTable& t) {
  if (isRadialCircularTest(t)) {
    throw ValidationError(
        ErrorContext{t.source(), 0, 0, {}},
        "is a radial-only circular test (angle_deg, deviation): the kinematic identification "
        "needs the x/y columns x_cmd_mm, y_cmd_mm, x_meas_mm, y_meas_mm (`kinematic circular` "
        "gives its ISO 230-4 results)");
  }
  const std::size_t xc = t.requireColumn("x_cmd_mm"), yc = t.requireColumn("y_cmd_mm");
  const std::size_t xm = t.requireColumn("x_meas_mm"), ym = t.requireColumn("y_meas_mm");
  MeasuredPath p;
  p.source = t.source();
  p.command.reserve(t.rowCount());
  p.measured.reserve(t.rowCount());
  p.lines.reserve(t.rowCount());
  for (std::size_t r = 0; r < t.rowCount(); ++r) {
    p.command.emplace_back(t.number(r, xc), t.number(r, yc));
    p.measured.emplace_back(t.number(r, xm), t.number(r, ym));
    p.lines.push_back(t.lineOf(r));
  }
  return p;
}

MeasuredPath readMeasuredPath(const std::string& path, const CsvReadOptions& csv) {
  return measuredPathFromCsv(readCsvFile(path, csv));
}

std::string measuredPathToCsv(const MeasuredPath& p) {
  CsvWriter w;
  w.row({"x_cmd_mm", "y_cmd_mm", "x_meas_mm", "y_meas_mm"});
  for (std::size_t i = 0; i < p.size(); ++i) {
    w.row({num(p.command[i].x()), num(p.command[i].y()), num(p.measured[i].x()), num(p.measured[i].y())});
  }
  return w.text();
}

NominalPath nominalPathFromCsv(const CsvTable& t) {
  const std::size_t xc = t.requireColumn("x_mm"), yc = t.requireColumn("y_mm");
  t.requireRows(1);
  NominalPath p;
  p.source = t.source();
  p.points.reserve(t.rowCount());
  for (std::size_t r = 0; r < t.rowCount(); ++r) p.points.emplace_back(t.number(r, xc), t.number(r, yc));
  return p;
}

NominalPath readNominalPath(const std::string& path, const CsvReadOptions& csv) {
  return nominalPathFromCsv(readCsvFile(path, csv));
}

std::string nominalPathToCsv(const std::vector<Eigen::Vector2d>& points) {
  CsvWriter w;
  w.row({"x_mm", "y_mm"});
  for (const auto& p : points) w.row({num(p.x()), num(p.y())});
  return w.text();
}

std::string commandPathToCsv(const std::vector<Eigen::Vector2d>& commands) {
  CsvWriter w;
  w.row({"x_cmd_mm", "y_cmd_mm"});
  for (const auto& c : commands) w.row({num(c.x()), num(c.y())});
  return w.text();
}

}  // namespace metrofit
