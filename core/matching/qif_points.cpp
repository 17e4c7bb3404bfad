#include "core/matching/qif_points.h"

#include <string>

#include "core/common/error.h"
#include "core/io/qif.h"

namespace metrofit {

std::size_t qifPartIndex(const QifFile& file, int part, const std::string& field) {
  const std::size_t n = file.parts.size();
  if (part > 0 && static_cast<std::size_t>(part) <= n) return static_cast<std::size_t>(part - 1);
  if (part <= 0 && n == 1) return 0;
  std::string list;
  for (std::size_t k = 0; k < n && k < 12; ++k) {
    list += (k ? ", " : "") + std::to_string(k + 1);
    if (!file.parts[k].serial.empty()) list += " (" + file.parts[k].serial + ")";
  }
  if (n > 12) list += ", ...";
  const std::string count = std::to_string(n) + " measured part" + (n == 1 ? "" : "s");
  if (part <= 0)
    throw ValidationError(ErrorContext{file.source, 0, 0, field},
                          "the file holds " + count + "; choose one by its number: " + list);
  throw ValidationError(ErrorContext{file.source, 0, 0, field},
                        "part " + std::to_string(part) + " asked for, the file holds " + count + ": " + list);
}

ProbePointSet qifProbePoints(const QifFile& file, std::size_t part, QifPoints which) {
  if (part >= file.parts.size())
    throw ValidationError(ErrorContext{file.source, 0, 0, {}},
                          "part " + std::to_string(part + 1) + " asked for, the file has " +
                              std::to_string(file.parts.size()) + " measured part(s)");
  ProbePointSet set;
  set.source = file.source;
  bool allSurface = true;
  for (const QifFeatureMeasurement& m : file.parts[part].features) {
    const QifFeature& f = file.features.at(m.feature);
    if (!f.location || !m.location || f.set) continue;  // a Set feature was not measured
    const bool surface = f.hasSurfaceNormal() && f.direction.has_value();
    if (which == QifPoints::Surface && !surface) continue;
    if (which == QifPoints::Holes && f.hasSurfaceNormal()) continue;
    ProbePoint p;
    p.id = f.name;
    p.surface = f.type;
    p.nominal = *f.location;
    p.measured = *m.location;
    if (f.direction) {
      const double len = f.direction->norm();
      if (!(len > 0.0))
        throw ValidationError(ErrorContext{file.source, f.line, 0, {}},
                              "feature '" + f.name + "': nominal normal / direction is zero");
      const Eigen::Vector3d d = *f.direction / len;
      if (surface) p.normal = d;
      if (f.type == "Cylinder") p.measured -= (p.measured - p.nominal).dot(d) * d;
    }
    allSurface = allSurface && surface;
    set.points.push_back(std::move(p));
  }
  if (set.points.empty())
    throw ValidationError(ErrorContext{file.source, file.parts[part].line, 0, {}},
                          "part " + std::to_string(part + 1) +
                              " has no measured feature with nominal and actual " +
                              (which == QifPoints::Surface ? "surface point"
                               : which == QifPoints::Holes ? "hole location"
                                                           : "location"));
  set.hasNormals = which != QifPoints::Holes && allSurface;
  if (!set.hasNormals)
    for (ProbePoint& p : set.points) p.normal.setZero();
  return set;
}

}  // namespace metrofit
