#pragma once
// The path files of the kinematic domain (docs/file-formats.md#input-files):
//   measured path / circular test  x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm  (rows in path order)
//   nominal path                   x_mm,y_mm
//   compensated references         x_cmd_mm,y_cmd_mm                       (what compensate writes)
// Readers name file, line and field of every bad cell (CsvTable); unknown extra columns are ignored.
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/io/csv.h"

namespace metrofit {
class CsvTable;

/// Commanded (joint) positions and the positions the tool actually reached, in mm.
struct MeasuredPath {
  std::string source;                     ///< file name (or "simulated circular test") for messages
  std::vector<Eigen::Vector2d> command;   ///< Pr: x_cmd_mm, y_cmd_mm
  std::vector<Eigen::Vector2d> measured;  ///< P: x_meas_mm, y_meas_mm
  std::vector<long> lines;                ///< physical line of each row (empty when not from a file)

  std::size_t size() const { return command.size(); }
};

MeasuredPath measuredPathFromCsv(const CsvTable& table);
MeasuredPath readMeasuredPath(const std::string& path, const CsvReadOptions& csv = {});
/// CSV text with the header x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm (shortest round-trip numbers).
std::string measuredPathToCsv(const MeasuredPath& path);

/// A nominal path (x_mm, y_mm); ValidationError when it has no rows.
struct NominalPath {
  std::string source;
  std::vector<Eigen::Vector2d> points;
};

NominalPath nominalPathFromCsv(const CsvTable& table);
NominalPath readNominalPath(const std::string& path, const CsvReadOptions& csv = {});
std::string nominalPathToCsv(const std::vector<Eigen::Vector2d>& points);

/// CSV text x_cmd_mm,y_cmd_mm of compensated references (shortest round-trip numbers).
std::string commandPathToCsv(const std::vector<Eigen::Vector2d>& commands);

}  // namespace metrofit
