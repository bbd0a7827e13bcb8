// The line a user measures or profiles, from the files people have: a GPX track (the first <trk>
// of two points or more, every segment in order) or else route (<rte>, likewise), a KML
// LineString (the first, or gx:Track's coordinates), or a GeoJSON LineString or MultiLineString
// (the first feature that has one).
#pragma once

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "core/warnings.hpp"

namespace globe::measure {

struct PathPoint {
  double longitudeDegrees = 0;
  double latitudeDegrees = 0;
  // The file's own elevation (GPX <ele>, a KML or GeoJSON third coordinate), NaN without one.
  double elevationMeters = std::numeric_limits<double>::quiet_NaN();
};

// Errors name the file and what is wrong (not XML or JSON, no line in it, a coordinate out of
// range); a line needs two points. Elevations that are not finite or outside -12000..100000 m
// are read as not given, with a warning.
Result<std::vector<PathPoint>> readPathFile(const std::filesystem::path& file,
                                            const core::WarningSink& warnings = {});

}  // namespace globe::measure
