// The line a user measures or profiles, from the files people have: a GPX track (its first
// <trk>, every segment in order) or route (<rte>), a KML LineString (the first, or gx:Track's
// coordinates), or a GeoJSON LineString or MultiLineString (the first feature that has one).
#pragma once

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "core/result.hpp"

namespace globe::measure {

struct PathPoint {
  double longitudeDegrees = 0;
  double latitudeDegrees = 0;
  // The file's own elevation (GPX <ele>, a KML or GeoJSON third coordinate), NaN without one.
  double elevationMeters = std::numeric_limits<double>::quiet_NaN();
};

// Errors name the file and what is wrong (not XML or JSON, no line in it, a coordinate out of
// range); a line needs two points.
Result<std::vector<PathPoint>> readPathFile(const std::filesystem::path& file);

}  // namespace globe::measure
