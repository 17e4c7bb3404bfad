#pragma once
// A QIF 3 Results file (core/io/qif.h) as contact-probed point pairs (core/matching/probe_points.h): one
// point per measured feature of one part that has a nominal and an actual location (features whose
// DeterminationMode is Set are given, not measured, and left out), id = FeatureName,
// surface = the feature type ("Point", "Circle", ...), nominal = the nominal Location (Axis/AxisPoint for
// a cylinder), measured = the actual Location. A cylinder's actual axis point is moved along the nominal
// axis into the plane through the nominal axis point (an axis point is anywhere on its axis), so the
// pair's difference is the axis offset.
//
// Normals: a ProbePointSet has normals for all its points or for none. Surface features (Point,
// EdgePoint, Plane: QifFeature::hasSurfaceNormal) have a surface normal; circles and cylinders carry an
// axis, which is not a direction to measure a deviation along, so they are position-only.
//   * QifPoints::All: every feature with locations; normals (unit, from the nominal Normal) when every
//     such feature has a surface normal, else the set is position-only (normals zero);
//   * QifPoints::Surface: the surface features with a nominal normal only, with their normals;
//   * QifPoints::Holes: the other features (circles, cylinders, ...) only, position-only.
// ValidationError (naming the file and the feature's line) for a part index out of range, a zero
// nominal normal, and when no point is left.
#include <cstddef>
#include <string>

#include "core/matching/probe_points.h"

namespace metrofit {

struct QifFile;

enum class QifPoints { All, Surface, Holes };

ProbePointSet qifProbePoints(const QifFile& file, std::size_t part, QifPoints which = QifPoints::All);

/// The index into file.parts of measured part `part` (1-based, as `match --part` and a dataset's "part"
/// key give it); `part` 0: the file's only part. ValidationError (field `field`) naming the parts (their
/// serial numbers where they have one) when the file holds several and none is chosen, or `part` is out
/// of range.
std::size_t qifPartIndex(const QifFile& file, int part, const std::string& field = "--part");

}  // namespace metrofit
