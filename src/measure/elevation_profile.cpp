#include "measure/elevation_profile.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "surface/pyramid_surface.hpp"

namespace globe::measure {

double terrainSpacingMeters(const streaming::TerrainSource& source,
                            const std::vector<PathPoint>& path) {
  const auto& manifest = source.manifest();
  const double degrees = 180.0 / std::ldexp(1.0, static_cast<int>(manifest.maxLevel())) /
                         (manifest.verticesPerSide - 1);
  double highest = 0;
  for (const PathPoint& p : path) highest = std::max(highest, std::fabs(p.latitudeDegrees));
  const double metresPerDegree = 6378137.0 * std::numbers::pi / 180;
  return degrees * metresPerDegree * std::cos(std::min(highest, 80.0) * std::numbers::pi / 180);
}

Result<std::vector<ProfileRow>> elevationProfile(streaming::TerrainSource& source,
                                                 const std::vector<PathPoint>& path,
                                                 const geo::Ellipsoid& ellipsoid,
                                                 const ProfileOptions& options) {
  if (path.size() < 2) return makeError("a profile needs a path of two points or more");
  const double spacing =
      options.maxSpacingMeters > 0 ? options.maxSpacingMeters : terrainSpacingMeters(source, path);
  const double length = geodesicLengthMeters(path);
  if (length / spacing + static_cast<double>(path.size()) >
      static_cast<double>(options.maxSamples)) {
    return makeError("a path of " + std::to_string(static_cast<long long>(length / 1000)) +
                     " km sampled every " + std::to_string(spacing) + " m would take more than " +
                     std::to_string(options.maxSamples) + " samples");
  }
  surface::PyramidSurface surface(source, ellipsoid);
  std::vector<ProfileRow> rows;
  for (const PathSample& s : sampleGeodesic(path, spacing)) {
    auto h = surface.heightMeters(s.longitudeDegrees * std::numbers::pi / 180,
                                  s.latitudeDegrees * std::numbers::pi / 180,
                                  source.manifest().maxLevel());
    if (!h) return Error{h.error()};
    rows.push_back({s, *h, 0});
  }
  for (size_t i = 0; i < rows.size(); ++i) {
    const size_t a = i + 1 < rows.size() ? i : i - 1;
    const double run = rows[a + 1].sample.distanceMeters - rows[a].sample.distanceMeters;
    const double rise = rows[a + 1].heightMeters - rows[a].heightMeters;
    rows[i].slopeDegrees = run > 0 ? std::atan2(rise, run) * 180 / std::numbers::pi : 0.0;
  }
  return rows;
}

}  // namespace globe::measure
