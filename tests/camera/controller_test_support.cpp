// Real arrays over Fuji and the globe, tangent-plane offsets and the per-frame surface audit.
#include "tests/camera/controller_test_support.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "collision/exact_surface.hpp"
#include "geo/ecef.hpp"
#include "geo/globe_rectangle.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/tile_containment.hpp"
#include "tests/collision/collision_test_support.hpp"
#include "tests/collision/mesh_ray_cast.hpp"

namespace globe::camera::testing {
namespace {

using collision::testing::RealPyramid;
using Scheme = geo::GeographicTilingScheme;

bool intersectsDegrees(const geo::TileId& id, double west, double south, double east,
                       double north) {
  return Scheme::tileRectangle(id).intersects(
      geo::GlobeRectangle::fromDegrees(west, south, east, north));
}

bool intersectsFuji(const geo::TileId& id) {
  return intersectsDegrees(id, 138.55, 35.22, 138.90, 35.50);
}

}  // namespace

geo::Cartographic fujiSummit(double heightMeters) {
  return geo::Cartographic::fromDegrees(kFujiSummitLongitudeDegrees, kFujiSummitLatitudeDegrees,
                                        heightMeters);
}

uint32_t finestLevel() { return RealPyramid::bundled().maxLevel(); }

const terrain::RenderingTileArray& fuji() { return fujiArray(finestLevel()); }

double drawn(const geo::Cartographic& position) {
  return drawnHeight(fuji(), position.longitudeRadians, position.latitudeRadians);
}

const terrain::RenderingTileArray& fujiArray(uint32_t level) {
  static std::map<uint32_t, terrain::RenderingTileArray> arrays;
  const auto it = arrays.find(level);
  if (it != arrays.end()) return it->second;
  RealPyramid& pyramid = RealPyramid::bundled();
  const auto tiles = collision::testing::quadtreeCut(pyramid, [level](const geo::TileId& id) {
    return id.level < 2 || (id.level < level && intersectsFuji(id));
  });
  return arrays.emplace(level, pyramid.array(tiles)).first->second;
}

const terrain::RenderingTileArray& globalArray() {
  static const terrain::RenderingTileArray array = [] {
    RealPyramid& pyramid = RealPyramid::bundled();
    const auto tiles = collision::testing::quadtreeCut(pyramid, [](const geo::TileId& id) {
      if (id.level < 2) return true;
      const geo::GlobeRectangle r = Scheme::tileRectangle(id);
      const double limit = geo::degreesToRadians(80.0);
      const double meridian = geo::degreesToRadians(175.0);
      return r.northRadians >= limit || r.southRadians <= -limit || r.westRadians <= -meridian ||
             r.eastRadians >= meridian;
    });
    return pyramid.array(tiles);
  }();
  return array;
}

double drawnHeight(const terrain::RenderingTileArray& array, double longitudeRadians,
                   double latitudeRadians) {
  const auto sample = collision::exactSurfaceHeight(array, geo::Ellipsoid::wgs84(),
                                                    longitudeRadians, latitudeRadians);
  return sample ? sample->heightMeters : 0.0;
}

geo::Cartographic offsetPosition(const geo::Cartographic& origin, double bearingRadians,
                                 double distanceMeters, double heightMeters) {
  const geo::Ellipsoid ellipsoid = geo::Ellipsoid::wgs84();
  const EastNorthUp enu = eastNorthUp(ellipsoid, origin);
  const glm::dvec3 base =
      geo::cartographicToEcef(ellipsoid, {origin.longitudeRadians, origin.latitudeRadians, 0.0});
  const glm::dvec3 moved = base + distanceMeters * (std::sin(bearingRadians) * enu.east +
                                                    std::cos(bearingRadians) * enu.north);
  geo::Cartographic result = *geo::ecefToCartographic(ellipsoid, moved);
  result.heightMeters = heightMeters;
  return result;
}

glm::dvec3 direction(const geo::Cartographic& position, double headingRadians,
                     double pitchRadians) {
  return cameraFrame(geo::Ellipsoid::wgs84(), {position, headingRadians, pitchRadians, 0.0})
      .forward;
}

namespace {

// The drawn surface by the brute-force oracle; -infinity where no tile holds the point.
double oracleHeight(const terrain::RenderingTileArray& array, const geo::Cartographic& p) {
  const auto point = terrain::makeQueryPoint(p.longitudeRadians, p.latitudeRadians);
  if (!point) return -std::numeric_limits<double>::infinity();
  const terrain::ArrayTile* tile =
      array.findIndexed(point->longitudeRadians, point->latitudeRadians);
  if (tile == nullptr) return -std::numeric_limits<double>::infinity();
  const auto hit = collision::testing::castOntoTileMesh(
      *tile, geo::Ellipsoid::wgs84(), point->longitudeRadians, point->latitudeRadians);
  return hit ? hit->heightMeters : -std::numeric_limits<double>::infinity();
}

}  // namespace

double deepestInsideView(const CameraPose& pose, const NearPlane& nearPlane,
                         const terrain::RenderingTileArray& array) {
  const geo::Ellipsoid ellipsoid = geo::Ellipsoid::wgs84();
  const CameraFrame frame = cameraFrame(ellipsoid, pose);
  const auto c = nearPlaneCornerOffsets(frame, nearPlane);
  double deepest = -std::numeric_limits<double>::infinity();
  const auto sample = [&](const glm::dvec3& offset) {
    const auto p = geo::ecefToCartographic(ellipsoid, frame.positionEcefMeters + offset);
    if (!p) return;
    deepest = std::max(deepest, oracleHeight(array, *p) - p->heightMeters);
  };
  sample(glm::dvec3(0.0));
  for (int a = 0; a <= 4; ++a) {
    for (int b = 0; b <= 4; ++b) {
      const double u = a / 4.0, v = b / 4.0;
      // Bilinear over the corners (+-up, +-right in some order: the grid spans the rectangle).
      const glm::dvec3 point =
          (1 - u) * ((1 - v) * c[0] + v * c[1]) + u * ((1 - v) * c[2] + v * c[3]);
      for (const double t : {0.25, 0.5, 0.75, 1.0}) sample(t * point);
    }
  }
  return deepest;
}

bool FrameAudit::check(const CameraPose& pose, const NearPlane& nearPlane,
                       const terrain::RenderingTileArray& array) {
  ++frames;
  if (!pose.isFinite()) {
    ++nonFinite;
    ++violations;
    return false;
  }
  const geo::Ellipsoid ellipsoid = geo::Ellipsoid::wgs84();
  const double eye = pose.position.heightMeters - drawnHeight(array, pose.position.longitudeRadians,
                                                              pose.position.latitudeRadians);
  lowestEyeClearanceMeters = std::min(lowestEyeClearanceMeters, eye);
  const CameraFrame frame = cameraFrame(ellipsoid, pose);
  double corner = std::numeric_limits<double>::infinity();
  for (const glm::dvec3& offset : nearPlaneCornerOffsets(frame, nearPlane)) {
    const auto point = geo::ecefToCartographic(ellipsoid, frame.positionEcefMeters + offset);
    if (!point) {
      corner = -std::numeric_limits<double>::infinity();
      continue;
    }
    corner = std::min(corner, point->heightMeters - drawnHeight(array, point->longitudeRadians,
                                                                point->latitudeRadians));
  }
  lowestCornerClearanceMeters = std::min(lowestCornerClearanceMeters, corner);
  const bool ok = eye >= 0.0 && corner >= 0.0;
  if (!ok) ++violations;
  return ok;
}

void FrameAudit::add(const FrameAudit& other) {
  frames += other.frames;
  violations += other.violations;
  nonFinite += other.nonFinite;
  lowestEyeClearanceMeters = std::min(lowestEyeClearanceMeters, other.lowestEyeClearanceMeters);
  lowestCornerClearanceMeters =
      std::min(lowestCornerClearanceMeters, other.lowestCornerClearanceMeters);
}

}  // namespace globe::camera::testing
