// Paths on the WGS84 ellipsoid through GeographicLib: a polyline's geodesic length, points along
// it at most a spacing apart (every vertex kept), and a closed ring's area.
#pragma once

#include <vector>

#include "measure/path_files.hpp"

namespace globe::measure {

struct PathSample {
  double distanceMeters = 0;  // along the path from its first point
  double longitudeDegrees = 0;
  double latitudeDegrees = 0;
  double sourceElevationMeters = 0;  // the file's, interpolated by distance; NaN without
};

// The sum of the geodesic distances between consecutive points.
double geodesicLengthMeters(const std::vector<PathPoint>& path);
// The path's vertices and, on each geodesic between two, equally spaced points no more than
// maxSpacingMeters apart (> 0).
std::vector<PathSample> sampleGeodesic(const std::vector<PathPoint>& path, double maxSpacingMeters);
// The area inside the ring the points make (closed back to the first), square metres.
double ringAreaSquareMeters(const std::vector<PathPoint>& ring);

}  // namespace globe::measure
