#include "measure/geodesic_path.hpp"

#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/GeodesicLine.hpp>
#include <GeographicLib/PolygonArea.hpp>

#include <cmath>

namespace globe::measure {

double geodesicLengthMeters(const std::vector<PathPoint>& path) {
  const GeographicLib::Geodesic& wgs84 = GeographicLib::Geodesic::WGS84();
  double total = 0;
  for (size_t i = 1; i < path.size(); ++i) {
    double s12 = 0;
    wgs84.Inverse(path[i - 1].latitudeDegrees, path[i - 1].longitudeDegrees,
                  path[i].latitudeDegrees, path[i].longitudeDegrees, s12);
    total += s12;
  }
  return total;
}

std::vector<PathSample> sampleGeodesic(const std::vector<PathPoint>& path,
                                       double maxSpacingMeters) {
  const GeographicLib::Geodesic& wgs84 = GeographicLib::Geodesic::WGS84();
  std::vector<PathSample> samples;
  if (path.empty()) return samples;
  double along = 0;
  samples.push_back(
      {0, path[0].longitudeDegrees, path[0].latitudeDegrees, path[0].elevationMeters});
  for (size_t i = 1; i < path.size(); ++i) {
    const PathPoint& a = path[i - 1];
    const PathPoint& b = path[i];
    const GeographicLib::GeodesicLine line = wgs84.InverseLine(
        a.latitudeDegrees, a.longitudeDegrees, b.latitudeDegrees, b.longitudeDegrees);
    const double length = line.Distance();
    const auto steps =
        static_cast<size_t>(std::max(1.0, std::ceil(length / std::max(maxSpacingMeters, 1e-3))));
    for (size_t k = 1; k <= steps; ++k) {
      const double s = length * static_cast<double>(k) / static_cast<double>(steps);
      double lat = b.latitudeDegrees, lon = b.longitudeDegrees;
      if (k < steps) line.Position(s, lat, lon);
      const double t = length > 0 ? s / length : 1.0;
      samples.push_back(
          {along + s, lon, lat, a.elevationMeters + t * (b.elevationMeters - a.elevationMeters)});
    }
    along += length;
  }
  return samples;
}

double ringAreaSquareMeters(const std::vector<PathPoint>& ring) {
  GeographicLib::PolygonArea polygon(GeographicLib::Geodesic::WGS84());
  for (const PathPoint& p : ring) polygon.AddPoint(p.latitudeDegrees, p.longitudeDegrees);
  double perimeter = 0, area = 0;
  polygon.Compute(false, true, perimeter, area);
  return std::fabs(area);
}

}  // namespace globe::measure
