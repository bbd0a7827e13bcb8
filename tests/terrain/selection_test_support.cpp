// Catalogs, views and brute-force selection checks shared by the tile selection tests.
#include "tests/terrain/selection_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <numbers>
#include <set>
#include <unordered_set>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::terrain::testing {

namespace {

uint64_t mix(uint64_t key) {
  key = (key ^ (key >> 30)) * 0xbf58476d1ce4e5b9ULL;
  key = (key ^ (key >> 27)) * 0x94d049bb133111ebULL;
  return key ^ (key >> 31);
}

bool insideFrustum(const geo::Frustum& frustum, const glm::dvec3& p, double toleranceMeters) {
  for (const geo::Plane& plane : frustum.planes) {
    if (glm::dot(plane.normal, p) + plane.distance < -toleranceMeters) return false;
  }
  return true;
}

// Closest approach of the segment camera -> p to the earth's centre.
double segmentClearanceMeters(const glm::dvec3& camera, const glm::dvec3& p) {
  const glm::dvec3 d = p - camera;
  const double lengthSquared = glm::dot(d, d);
  const double t =
      lengthSquared > 0.0 ? std::clamp(-glm::dot(camera, d) / lengthSquared, 0.0, 1.0) : 0.0;
  return glm::length(camera + t * d);
}

// Points of the tile's region: an n x n lattice at the given heights, plus the point nearest
// the camera in longitude/latitude/height (clamped), which is close to the true nearest point.
std::vector<glm::dvec3> regionSamples(const glm::dvec3& camera, const geo::TileId& tile,
                                      const HeightRange& range, const geo::Ellipsoid& ellipsoid,
                                      int n, const std::vector<double>& heightFractions) {
  const geo::GlobeRectangle r = geo::GeographicTilingScheme::tileRectangle(tile);
  const double low = range.minimumMeters;
  const double high = range.maximumMeters;
  std::vector<glm::dvec3> points;
  for (const double f : heightFractions) {
    const double h = low + f * (high - low);
    for (int i = 0; i < n; ++i) {
      const double lat =
          i == n - 1 ? r.northRadians : r.southRadians + i * r.heightRadians() / (n - 1);
      for (int j = 0; j < n; ++j) {
        const double lon =
            j == n - 1 ? r.eastRadians : r.westRadians + j * r.widthRadians() / (n - 1);
        points.push_back(geo::cartographicToEcef(ellipsoid, {lon, lat, h}));
      }
    }
  }
  if (const auto c = geo::ecefToCartographic(ellipsoid, camera)) {
    double lon = c->longitudeRadians;
    if (lon < r.westRadians || lon > r.eastRadians) {
      // The nearer edge in angle, going round the globe either way.
      const auto gap = [](double a, double b) {
        const double d = std::fmod(std::abs(a - b), 2 * std::numbers::pi);
        return std::min(d, 2 * std::numbers::pi - d);
      };
      lon = gap(lon, r.westRadians) < gap(lon, r.eastRadians) ? r.westRadians : r.eastRadians;
    }
    const double lat = std::clamp(c->latitudeRadians, r.southRadians, r.northRadians);
    const double h = std::clamp(c->heightMeters, low, high);
    points.push_back(geo::cartographicToEcef(ellipsoid, {lon, lat, h}));
  }
  return points;
}

std::optional<glm::dvec3> firstHit(const glm::dvec3& origin, const glm::dvec3& direction, double a,
                                   double b) {
  const glm::dvec3 scale{1.0 / a, 1.0 / a, 1.0 / b};
  const glm::dvec3 o = origin * scale;
  const glm::dvec3 d = direction * scale;
  const double qa = glm::dot(d, d);
  const double qb = 2.0 * glm::dot(o, d);
  const double qc = glm::dot(o, o) - 1.0;
  if (qc <= 0.0) return std::nullopt;  // the camera is inside this surface
  const double discriminant = qb * qb - 4.0 * qa * qc;
  if (discriminant < 0.0) return std::nullopt;
  // The nearer root, computed without cancellation.
  const double q = -0.5 * (qb - std::sqrt(discriminant));  // qb < 0 when the surface is ahead
  if (qb >= 0.0) return std::nullopt;
  const double t = qc / q;
  if (!(t > 0.0)) return std::nullopt;
  return origin + t * direction;
}

// Some catalog tile containing (lon, lat) has a height range that excludes h.
bool provablyOffTerrain(const TileCatalog& catalog, double lon, double lat, double h) {
  for (uint32_t level = 0; level <= geo::kMaxLevel; ++level) {
    const auto tile = geo::GeographicTilingScheme::positionToTile(lon, lat, level);
    if (!tile) return false;
    const auto summary = catalog.find(*tile);
    if (!summary) return false;
    if (h < summary->subtreeHeightRange.minimumMeters ||
        h > summary->subtreeHeightRange.maximumMeters) {
      return true;
    }
  }
  return false;
}

int failureCount() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return info ? info->result()->total_part_count() : 0;
}

}  // namespace

Residency randomResidency(uint64_t seed, double probability, bool rootsResident) {
  return [=](const geo::TileId& tile) {
    if (tile.level == 0) return rootsResident;
    const uint64_t h = mix(std::hash<geo::TileId>{}(tile) ^ mix(seed));
    return static_cast<double>(h >> 11) * 0x1.0p-53 < probability;
  };
}

PyramidCatalog& PyramidCatalog::bundled() {
  static PyramidCatalog* catalog = [] {
    auto store = streaming::TileStore::open(globe::testing::bundledPyramid());
    if (!store) {
      ADD_FAILURE() << store.error();
      std::abort();
    }
    return new PyramidCatalog(std::move(*store));
  }();
  catalog->residency_ = nullptr;
  return *catalog;
}

std::optional<TileSummary> PyramidCatalog::find(const geo::TileId& tile) const {
  if (!geo::GeographicTilingScheme::isValid(tile)) return std::nullopt;
  auto entry = store_->entry(tile);
  if (!entry) {
    ADD_FAILURE() << entry.error();
    return std::nullopt;
  }
  if (!*entry) return std::nullopt;
  return TileSummary{(*entry)->subtreeRange, (*entry)->geometricErrorMeters};
}

bool PyramidCatalog::isResident(const geo::TileId& tile) const {
  return !residency_ || residency_(tile);
}

std::optional<TileSummary> SyntheticCatalog::find(const geo::TileId& tile) const {
  if (!geo::GeographicTilingScheme::isValid(tile) || tile.level > maxLevel_) return std::nullopt;
  return TileSummary{range_};
}

TestView cameraView(double longitudeDegrees, double latitudeDegrees, double heightMeters,
                    double pitchDegrees, double headingDegrees, const std::string& name) {
  const geo::Ellipsoid ellipsoid = geo::Ellipsoid::wgs84();
  const geo::Cartographic where =
      geo::Cartographic::fromDegrees(longitudeDegrees, latitudeDegrees, heightMeters);
  const glm::dvec3 eye = geo::cartographicToEcef(ellipsoid, where);
  const glm::dvec3 up = geo::geodeticSurfaceNormal(ellipsoid, where);
  const glm::dvec3 east{-std::sin(where.longitudeRadians), std::cos(where.longitudeRadians), 0.0};
  const glm::dvec3 north = glm::cross(up, east);
  const double pitch = geo::degreesToRadians(pitchDegrees);
  const double heading = geo::degreesToRadians(headingDegrees);
  const glm::dvec3 horizontal = std::cos(heading) * north + std::sin(heading) * east;
  const glm::dvec3 forward = -std::cos(pitch) * up + std::sin(pitch) * horizontal;
  const glm::dvec3 cameraUp = std::cos(pitch) * horizontal + std::sin(pitch) * up;

  TestView v;
  v.name = name;
  v.view.cameraEcefMeters = eye;
  v.view.viewportHeightPixels = 1080.0;
  v.view.fovYRadians = std::numbers::pi / 3.0;
  v.view.ellipsoid = ellipsoid;
  const double nearMeters = std::clamp(0.05 * heightMeters, 0.1, 1000.0);
  const double farMeters = 1e8;
  v.viewProjection = glm::perspective(v.view.fovYRadians, 16.0 / 9.0, nearMeters, farMeters) *
                     glm::lookAt(eye, eye + forward, cameraUp);
  v.view.frustum = geo::Frustum::fromViewProjection(v.viewProjection);
  return v;
}

bool checkCoverage(const TestView& view, const TileCatalog& catalog, const SelectionResult& result,
                   CoverageStats* stats, int columns, int rows) {
  const geo::Ellipsoid& e = view.view.ellipsoid;
  const glm::dvec3 camera = view.view.cameraEcefMeters;
  const glm::dmat4 inverse = glm::inverse(view.viewProjection);
  std::unordered_set<geo::TileId> selected(result.tiles.begin(), result.tiles.end());
  uint32_t deepest = 0;
  for (const geo::TileId& t : result.tiles) deepest = std::max(deepest, t.level);
  std::vector<geo::GlobeRectangle> rectangles;
  for (const geo::TileId& t : result.tiles) {
    rectangles.push_back(geo::GeographicTilingScheme::tileRectangle(t));
  }
  const auto covered = [&](double lon, double lat) {
    for (uint32_t level = 0; level <= deepest; ++level) {
      const auto tile = geo::GeographicTilingScheme::positionToTile(lon, lat, level);
      if (tile && selected.contains(*tile)) return true;
    }
    // On a shared edge (or a pole) positionToTile picks one side; any closed rectangle will do.
    return std::any_of(rectangles.begin(), rectangles.end(),
                       [&](const geo::GlobeRectangle& r) { return r.contains(lon, lat); });
  };

  CoverageStats local;
  int failures = 0;
  for (const double raise : {-6000.0, -1000.0, 0.0, 400.0, 1200.0, 2200.0, 3000.0, 3600.0}) {
    for (int row = 0; row < rows; ++row) {
      for (int column = 0; column < columns; ++column) {
        const double x = (column + 0.5) / columns * 2.0 - 1.0;
        const double y = (row + 0.5) / rows * 2.0 - 1.0;
        const glm::dvec4 nearPoint = inverse * glm::dvec4{x, y, -1.0, 1.0};
        const glm::dvec4 farPoint = inverse * glm::dvec4{x, y, 1.0, 1.0};
        const glm::dvec3 direction =
            glm::normalize(glm::dvec3{farPoint} / farPoint.w - glm::dvec3{nearPoint} / nearPoint.w);
        const auto hit = firstHit(camera, direction, e.semiMajorAxisMeters + raise,
                                  e.semiMinorAxisMeters + raise);
        if (!hit || !insideFrustum(view.view.frustum, *hit, 0.0)) continue;
        const auto where = geo::ecefToCartographic(e, *hit);
        if (!where) continue;
        if (covered(where->longitudeRadians, where->latitudeRadians)) {
          ++local.hitsCovered;
        } else if (provablyOffTerrain(catalog, where->longitudeRadians, where->latitudeRadians,
                                      where->heightMeters)) {
          ++local.hitsOffTerrain;
        } else if (++failures <= 5) {
          ADD_FAILURE() << view.name << ": hole at lon " << where->longitudeDegrees() << " lat "
                        << where->latitudeDegrees() << " height " << where->heightMeters
                        << " (pixel " << column << "," << row << ")";
        }
      }
    }
  }
  if (stats) *stats = local;
  if (failures > 0) ADD_FAILURE() << view.name << ": " << failures << " uncovered hits";
  return failures == 0;
}

bool checkInvariants(const TestView& view, const TileCatalog& catalog,
                     const SelectionOptions& options, const SelectionResult& result) {
  const int before = failureCount();
  const SelectionCounters& c = result.counters;
  const std::string& name = view.name;
  EXPECT_EQ(c.visited, c.culledByFrustum + c.culledByHorizon + c.refined + c.selected +
                           c.wantedNotResident + c.waitingForSiblings)
      << name;
  EXPECT_EQ(c.selected, result.tiles.size()) << name;
  EXPECT_EQ(c.wantedNotResident, result.requests.size()) << name;
  EXPECT_EQ(result.complete(), result.requests.empty()) << name;

  // No duplicates and no tile inside another: quadtree tiles overlap in area only then.
  std::set<geo::TileId> tiles(result.tiles.begin(), result.tiles.end());
  EXPECT_EQ(tiles.size(), result.tiles.size()) << name << ": duplicate tiles";
  for (const geo::TileId& t : result.tiles) {
    for (geo::TileId a = t; a.level > 0;) {
      a = a.parent();
      EXPECT_FALSE(tiles.contains(a)) << name << ": " << tileName(t) << " inside " << tileName(a);
    }
    EXPECT_TRUE(catalog.find(t).has_value()) << name << ": " << tileName(t);
    EXPECT_TRUE(catalog.isResident(t)) << name << ": " << tileName(t) << " not resident";
    EXPECT_LE(t.level, options.maximumLevel) << name;
  }
  // And independently of the quadtree: no two rectangles share interior area.
  if (result.tiles.size() <= 4000) {
    for (size_t i = 0; i < result.tiles.size(); ++i) {
      const auto a = geo::GeographicTilingScheme::tileRectangle(result.tiles[i]);
      for (size_t j = i + 1; j < result.tiles.size(); ++j) {
        const auto b = geo::GeographicTilingScheme::tileRectangle(result.tiles[j]);
        const bool overlap = a.westRadians < b.eastRadians && b.westRadians < a.eastRadians &&
                             a.southRadians < b.northRadians && b.southRadians < a.northRadians;
        EXPECT_FALSE(overlap) << name << ": " << tileName(result.tiles[i]) << " overlaps "
                              << tileName(result.tiles[j]);
      }
    }
  }

  std::set<geo::TileId> requested;
  for (size_t i = 0; i < result.requests.size(); ++i) {
    const TileRequest& r = result.requests[i];
    EXPECT_TRUE(requested.insert(r.tile).second)
        << name << ": requested twice " << tileName(r.tile);
    EXPECT_TRUE(catalog.find(r.tile).has_value()) << name << ": " << tileName(r.tile);
    EXPECT_FALSE(catalog.isResident(r.tile)) << name << ": " << tileName(r.tile);
    if (i > 0) {
      EXPECT_GE(result.requests[i - 1].priority, r.priority) << name;
    }
    EXPECT_TRUE(r.tile.level == 0 || tiles.contains(r.tile.parent()))
        << name << ": requested " << tileName(r.tile) << " but its parent is not drawn";
    EXPECT_LE(r.tile.level, options.maximumLevel) << name;
    EXPECT_GT(r.priority, 0.0) << name;
  }

  // Every drawn or requested tile has a point of its region near the visible part of the view.
  const auto plausiblyVisible = [&](const geo::TileId& t) {
    const auto summary = catalog.find(t);
    if (!summary) return false;
    const HeightRange& range = summary->subtreeHeightRange;
    const glm::dvec3 camera = view.view.cameraEcefMeters;
    const auto points = regionSamples(camera, t, range, view.view.ellipsoid, 9, {0.0, 1.0});
    glm::dvec3 centre{0.0};
    for (const glm::dvec3& p : points) centre += p;
    centre /= static_cast<double>(points.size());
    double radius = 0.0;
    for (const glm::dvec3& p : points) radius = std::max(radius, glm::distance(p, centre));
    const double tolerance = radius / 3.0 + 1.0;
    const double occluder =
        view.view.ellipsoid.semiMinorAxisMeters +
        std::min(geo::kLowestTerrainHeightMeters, static_cast<double>(range.minimumMeters));
    return std::any_of(points.begin(), points.end(), [&](const glm::dvec3& p) {
      return insideFrustum(view.view.frustum, p, tolerance) &&
             segmentClearanceMeters(camera, p) >= occluder - tolerance;
    });
  };
  for (const geo::TileId& t : result.tiles) {
    EXPECT_TRUE(plausiblyVisible(t)) << name << ": drew invisible " << tileName(t);
  }
  for (const TileRequest& r : result.requests) {
    EXPECT_TRUE(plausiblyVisible(r.tile)) << name << ": requested invisible " << tileName(r.tile);
  }
  return failureCount() == before;
}

double sampledDistanceMeters(const glm::dvec3& cameraEcefMeters, const geo::TileId& tile,
                             const HeightRange& range, const geo::Ellipsoid& ellipsoid) {
  double best = std::numeric_limits<double>::infinity();
  for (const glm::dvec3& p :
       regionSamples(cameraEcefMeters, tile, range, ellipsoid, 9, {0.0, 0.5, 1.0})) {
    best = std::min(best, glm::distance(p, cameraEcefMeters));
  }
  return best;
}

double independentScreenSpaceErrorPixels(const TestView& view, const geo::TileId& tile,
                                         const HeightRange& range, uint32_t verticesPerSide) {
  const double spacingRadians =
      std::numbers::pi / (std::pow(2.0, tile.level) * (verticesPerSide - 1.0));
  const double error = 0.25 * view.view.ellipsoid.semiMajorAxisMeters * spacingRadians;
  const double distance = std::max(
      1.0, sampledDistanceMeters(view.view.cameraEcefMeters, tile, range, view.view.ellipsoid));
  return error * view.view.viewportHeightPixels /
         (2.0 * distance * std::tan(view.view.fovYRadians / 2.0));
}

std::vector<geo::TileId> ancestorsOf(const std::vector<geo::TileId>& tiles) {
  std::set<geo::TileId> out;
  for (const geo::TileId& t : tiles) {
    for (geo::TileId a = t; a.level > 0;) {
      a = a.parent();
      if (!out.insert(a).second) break;
    }
  }
  return {out.begin(), out.end()};
}

}  // namespace globe::terrain::testing
