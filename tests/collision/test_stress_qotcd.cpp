// Stress test for QOTCD on the real bundled pyramid: 10^7 queries (a twentieth under the
// sanitizers) against three real rendering tile arrays (a quadtree cut over levels 0..14, the
// same under whole coarse levels, the cut with holes), on both globe models. Points: uniform,
// inside tiles, exactly on tile edges and corners of every level 0..30 and one ulp off them, on
// mesh vertices, at +-180 deg and at the exact poles; heights from -430 m to 4e7 m; cameras near
// the geocentre; non-finite and out-of-range input. Checks that the result is finite, that the
// tile holds the point by the tiling scheme's rectangles and is the finest one, that H bounds the
// exact drawn surface E up to the row-sliver allowance, and that bad input is rejected.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "collision/exact_surface.hpp"
#include "collision/height_service.hpp"
#include "collision/qotcd.hpp"
#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "tests/collision/collision_test_support.hpp"
#include "tests/collision/surface_bounds.hpp"
#include "tests/geo/stress_scale.hpp"

namespace globe::collision {
namespace {

using geo::TileId;
using Scheme = geo::GeographicTilingScheme;
using testing::RealPyramid;
constexpr double kHalfPi = std::numbers::pi / 2.0;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr uint32_t kVerticesPerSide = 17;

uint64_t tileHash(const TileId& id, uint64_t salt) { return std::hash<TileId>{}(id) ^ salt; }

bool touchesDegrees(const TileId& id, double west, double south, double east, double north) {
  return Scheme::tileRectangle(id).intersects(
      geo::GlobeRectangle::fromDegrees(west, south, east, north));
}

// Coarse everywhere, random refinement to level 6, level 6 along +-180 deg and the polar rows
// (ETOPO20's finest level), full depth over small areas of Fuji (level 14) and England (11).
std::vector<TileId> stressCut(RealPyramid& pyramid) {
  return testing::quadtreeCut(pyramid, [](const TileId& id) {
    if (id.level < 2) return true;
    const geo::GlobeRectangle r = Scheme::tileRectangle(id);
    const bool singular = r.westRadians == -std::numbers::pi || r.eastRadians == std::numbers::pi ||
                          r.northRadians == kHalfPi || r.southRadians == -kHalfPi;
    if (id.level < 6 && (singular || tileHash(id, 3) % 100 < 40)) return true;
    return touchesDegrees(id, 138.70, 35.33, 138.76, 35.39) ||
           touchesDegrees(id, -1.05, 52.95, -0.95, 53.05);
  });
}

struct StressArray {
  std::string name;
  std::vector<TileId> tiles;
  bool coversGlobe = false;
  RenderingTileArray array;
  std::vector<double> lowestMeters;  // per array tile (same order): its lowest surface height
  double lowest(const ArrayTile& tile) const { return lowestMeters[&tile - array.tiles().data()]; }
  // Counters.
  uint64_t queries = 0, found = 0, edgeNeighbours = 0, earlyOuts = 0, collided = 0;
};

std::vector<StressArray> stressArrays(RealPyramid& pyramid) {
  std::vector<StressArray> arrays(3);
  arrays[0].name = "quadtree cut";
  arrays[0].tiles = stressCut(pyramid);
  arrays[0].coversGlobe = true;
  // Every tile of levels 0..2 under the cut: the finest must win over the coarse ones.
  arrays[1].name = "levels 0-2 + cut";
  for (uint32_t level = 0; level <= 2; ++level) {
    for (const TileId& id : testing::tilesOfLevel(pyramid, level, -180, -90, 180, 90)) {
      arrays[1].tiles.push_back(id);
    }
  }
  for (const TileId& id : arrays[0].tiles) {
    if (id.level > 2) arrays[1].tiles.push_back(id);
  }
  arrays[1].coversGlobe = true;
  // A quarter of the cut removed: owners are often missing, edge neighbours or nothing answer.
  arrays[2].name = "cut with holes";
  for (const TileId& id : arrays[0].tiles) {
    if (tileHash(id, 9) % 4 != 0) arrays[2].tiles.push_back(id);
  }
  for (StressArray& a : arrays) {
    a.array = pyramid.array(a.tiles);
    for (const ArrayTile& tile : a.array.tiles()) {
      a.lowestMeters.push_back(terrain::surfaceHeightRange(*tile.block).minimumMeters);
    }
  }
  return arrays;
}

// Closed containment by the scheme's own rectangle; +-180 deg are one meridian, a pole is in
// every tile of the polar row.
bool holds(const TileId& id, double longitudeRadians, double latitudeRadians) {
  const geo::GlobeRectangle r = Scheme::tileRectangle(id);
  if (latitudeRadians < r.southRadians || latitudeRadians > r.northRadians) return false;
  if (std::abs(latitudeRadians) == kHalfPi) return true;
  const double lon = longitudeRadians == -std::numbers::pi && r.eastRadians == std::numbers::pi
                         ? std::numbers::pi
                         : longitudeRadians;
  return r.westRadians <= lon && lon <= r.eastRadians;
}

bool onEdge(const TileId& id, double longitudeRadians, double latitudeRadians) {
  const geo::GlobeRectangle r = Scheme::tileRectangle(id);
  const double lon =
      std::abs(longitudeRadians) == std::numbers::pi && r.eastRadians == std::numbers::pi
          ? std::numbers::pi
          : longitudeRadians;
  return lon == r.westRadians || lon == r.eastRadians || latitudeRadians == r.southRadians ||
         latitudeRadians == r.northRadians;
}

bool allFinite(const QotcdResult& r) {
  return std::isfinite(r.terrainHeightMeters) && std::isfinite(r.cameraHeightMeters) &&
         std::isfinite(r.longitudeRadians) && std::isfinite(r.latitudeRadians);
}

// The documented invalid result: everything false / 0 / None.
bool isRejected(const QotcdResult& r) {
  return !r.valid && !r.found && !r.collided && !r.earlyOut && r.terrainHeightMeters == 0.0 &&
         r.cameraHeightMeters == 0.0 && r.longitudeRadians == 0.0 && r.latitudeRadians == 0.0 &&
         r.heightCase == HeightCase::None;
}
bool isRejected(const ExactSurfaceResult& r) {
  return !r.valid && !r.found && !r.collided && r.surfaceHeightMeters == 0.0 &&
         r.cameraHeightMeters == 0.0 && r.triangle == SurfaceTriangle::None;
}

// A point of testing::randomQueryPoint (edges and corners of array tiles and of any tile up to
// the level given, mesh vertices, +-180 deg, poles), one time in eight moved by one ulp.
testing::LonLat stressPoint(std::mt19937_64& rng, const StressArray& a, uint32_t edgeLevel) {
  testing::LonLat p = testing::randomQueryPoint(rng, a.tiles, edgeLevel, kVerticesPerSide);
  if (rng() % 8 == 0) {
    const double direction = (rng() & 1) ? 4.0 : -4.0;
    if (rng() & 1) {
      p.longitudeRadians = std::nextafter(p.longitudeRadians, direction);
    } else {
      p.latitudeRadians =
          std::clamp(std::nextafter(p.latitudeRadians, direction), -kHalfPi, kHalfPi);
    }
  }
  return p;
}

// -430 m .. 4e7 m: log-uniform above 1 m, uniform near the ground, exact extremes, and within a
// few metres of the exact surface plus clearance (where the decision flips).
double cameraHeight(std::mt19937_64& rng, std::optional<double> surfaceMeters,
                    double clearanceMeters) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  switch (rng() % 8) {
    case 0:
    case 1:
      return std::pow(10.0, std::log10(4e7) * unit(rng));
    case 2:
    case 3:
      return -430.0 + 9430.0 * unit(rng);
    case 4: {
      const double extremes[] = {-430.0, 4e7, 0.0, 8848.0};
      return extremes[rng() % 4];
    }
    default:
      return surfaceMeters.value_or(0.0) + clearanceMeters + 6.0 * (unit(rng) - 0.5);
  }
}

struct SurfaceStats {
  uint64_t compared = 0;
  uint64_t belowSurface = 0;  // H < E - 1e-6 m
  uint64_t sliverMisses = 0;  // D <= E + clearance but QOTCD said no collision
  double minHMinusE = 0.0;
  double worstSliverRatio = 0.0;  // of an underestimate to its allowance
  double worstSagRatio = 0.0;     // of E below the tile's lowest vertex to the sag bound
  uint64_t poles = 0, antimeridian = 0, ecefQueries = 0, geocentre = 0, rejected = 0;
  double maxEcefHeightError = 0.0;
};

// H against the exact surface E of the same tile: H >= E - allowance, E above the sag bound.
void compareWithSurface(const ArrayTile& tile, double lowestMeters, const geo::Ellipsoid& ellipsoid,
                        double lat, double heightMeters, double surfaceMeters,
                        SurfaceStats& stats) {
  ++stats.compared;
  const double over = heightMeters - surfaceMeters;
  stats.minHMinusE = std::min(stats.minHMinusE, over);
  if (over < -1e-6) {
    const double allowance = testing::rowSliverAllowanceMeters(tile, lat, ellipsoid);
    ASSERT_GE(over, -allowance) << "tile " << tile.id.level << "/" << tile.id.x << "/" << tile.id.y
                                << " lat " << lat << " H " << heightMeters << " E "
                                << surfaceMeters;
    ++stats.belowSurface;
    stats.worstSliverRatio = std::max(stats.worstSliverRatio, -over / allowance);
  }
  const double sag = testing::chordSagBoundMeters(tile, ellipsoid);
  ASSERT_GE(surfaceMeters, lowestMeters - sag)
      << "tile " << tile.id.level << "/" << tile.id.x << "/" << tile.id.y << " lat " << lat;
  stats.worstSagRatio = std::max(stats.worstSagRatio, (lowestMeters - surfaceMeters) / sag);
}

void regularQuery(std::mt19937_64& rng, StressArray& a, const geo::Ellipsoid& ellipsoid,
                  uint32_t edgeLevel, bool viaEcef, bool checkFinest, bool alsoLinear,
                  SurfaceStats& stats) {
  const testing::LonLat p = stressPoint(rng, a, edgeLevel);
  const double lon = p.longitudeRadians, lat = p.latitudeRadians;
  stats.poles += std::abs(lat) == kHalfPi;
  stats.antimeridian += std::abs(lon) == std::numbers::pi;
  const std::optional<ExactSurfaceSample> surface =
      exactSurfaceHeight(a.array, ellipsoid, lon, lat);
  const double clearance = static_cast<double>(rng() % 3) * 25.0;
  const double d =
      cameraHeight(rng, surface ? std::optional(surface->heightMeters) : std::nullopt, clearance);
  const QotcdResult r = qotcdIndexed(a.array, {lon, lat, d}, clearance);
  ++a.queries;
  ASSERT_TRUE(r.valid && allFinite(r)) << lon << " " << lat << " " << d;
  ASSERT_EQ(r.cameraHeightMeters, d);
  ASSERT_EQ(r.latitudeRadians, lat);
  ASSERT_TRUE(-std::numbers::pi <= r.longitudeRadians && r.longitudeRadians < std::numbers::pi)
      << r.longitudeRadians;
  ASSERT_EQ(r.found, surface.has_value()) << lon << " " << lat;
  if (a.coversGlobe) {
    ASSERT_TRUE(r.found) << a.name << " lon " << lon << " lat " << lat;
  }
  ASSERT_EQ(r.collided, d <= r.terrainHeightMeters + clearance);
  if (!r.found) {
    ASSERT_EQ(r.terrainHeightMeters, 0.0);
    ASSERT_EQ(r.heightCase, HeightCase::None);
    ASSERT_FALSE(r.earlyOut);
    return;
  }
  ++a.found;
  a.earlyOuts += r.earlyOut;
  a.collided += r.collided;
  ASSERT_EQ(r.tile, surface->tile);
  // The tile holds the point by the scheme's rectangle; when it is not the scheme's owner at
  // its level, the point is on its edge; no finer tile of the array owns the point (checked on
  // a quarter of the queries: a hash probe per finer level).
  ASSERT_TRUE(holds(r.tile, r.longitudeRadians, lat))
      << a.name << " lon " << lon << " lat " << lat << " tile " << r.tile.level << "/" << r.tile.x
      << "/" << r.tile.y;
  const double canonicalLon = r.longitudeRadians;
  const std::optional<TileId> owner = Scheme::positionToTile(canonicalLon, lat, r.tile.level);
  ASSERT_TRUE(owner.has_value());
  if (*owner != r.tile) {
    ASSERT_TRUE(onEdge(r.tile, r.longitudeRadians, lat)) << lon << " " << lat;
    ++a.edgeNeighbours;
  }
  for (const uint32_t level : a.array.levelsFinestFirst()) {
    if (level <= r.tile.level || !checkFinest) break;
    ASSERT_EQ(a.array.find(*Scheme::positionToTile(canonicalLon, lat, level)), nullptr)
        << a.name << " lon " << lon << " lat " << lat << ": a finer owner at level " << level;
  }
  if (alsoLinear) {
    const ArrayTile* linear = a.array.findLinear(lon, lat);
    ASSERT_NE(linear, nullptr);
    ASSERT_EQ(linear->id, r.tile);
  }
  const ArrayTile& tile = *a.array.find(r.tile);
  const double tileMaximum = tile.maximumHeightMeters;
  if (r.earlyOut) {
    ASSERT_GT(d, tileMaximum + clearance);
    ASSERT_EQ(r.terrainHeightMeters, tileMaximum);
    ASSERT_EQ(r.heightCase, HeightCase::TileMaximum);
  } else {
    ASSERT_LE(r.terrainHeightMeters, tileMaximum);
    ASSERT_TRUE(r.heightCase == HeightCase::Vertex || r.heightCase == HeightCase::RowOrColumn ||
                r.heightCase == HeightCase::Quad);
    if (std::abs(lat) == kHalfPi) {  // one pole height, the same in both
      ASSERT_EQ(r.terrainHeightMeters, surface->heightMeters);
    }
  }
  ASSERT_TRUE(std::isfinite(surface->heightMeters));
  compareWithSurface(tile, a.lowest(tile), ellipsoid, lat, r.terrainHeightMeters,
                     surface->heightMeters, stats);
  if (d <= surface->heightMeters + clearance && !r.collided) ++stats.sliverMisses;

  if (!viaEcef) return;
  // The same camera through ECEF: D survives the round trip, the exact test finds the same tile.
  ++stats.ecefQueries;
  const glm::dvec3 camera = geo::cartographicToEcef(ellipsoid, {lon, lat, d});
  const QotcdResult e = qotcdIndexed(a.array, ellipsoid, camera, clearance);
  const ExactSurfaceResult x = exactSurfaceTest(a.array, ellipsoid, camera, clearance);
  ASSERT_TRUE(e.valid && x.valid && allFinite(e) && std::isfinite(x.surfaceHeightMeters));
  const double heightError = std::abs(e.cameraHeightMeters - d);
  stats.maxEcefHeightError = std::max(stats.maxEcefHeightError, heightError);
  ASSERT_LE(heightError, 1e-6) << lon << " " << lat << " " << d;
  ASSERT_EQ(e.found, x.found);
  if (a.coversGlobe) {
    ASSERT_TRUE(e.found);
  }
  if (!e.found) return;
  ASSERT_EQ(e.tile, x.tile);
  ASSERT_TRUE(holds(e.tile, e.longitudeRadians, e.latitudeRadians));
  const ArrayTile& ecefTile = *a.array.find(e.tile);
  compareWithSurface(ecefTile, a.lowest(ecefTile), ellipsoid, e.latitudeRadians,
                     e.terrainHeightMeters, x.surfaceHeightMeters, stats);
}

// Cameras at or within ~5 km of the geocentre: rejected at the centre, else deep below (collided).
void geocentreQuery(std::mt19937_64& rng, const StressArray& a, const geo::Ellipsoid& ellipsoid,
                    SurfaceStats& stats) {
  ++stats.geocentre;
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double radius = rng() % 4 == 0     ? 0.0
                        : (rng() & 1) != 0 ? 5000.0 * unit(rng)
                                           : std::pow(10.0, -12.0 + 15.7 * unit(rng));
  glm::dvec3 direction{gauss(rng), gauss(rng), gauss(rng)};
  if (rng() & 1) direction.x = direction.y = 0.0;  // on the polar axis
  const glm::dvec3 camera = direction / glm::length(direction) * radius;
  const QotcdResult indexed = qotcdIndexed(a.array, ellipsoid, camera, 2.0);
  const QotcdResult linear = qotcdLinear(a.array, ellipsoid, camera, 2.0);
  const ExactSurfaceResult exact = exactSurfaceTest(a.array, ellipsoid, camera, 2.0);
  if (glm::length(camera) < geo::kGeocentreThresholdMeters) {
    ASSERT_TRUE(isRejected(indexed) && isRejected(linear) && isRejected(exact)) << radius;
    ++stats.rejected;
    return;
  }
  ASSERT_TRUE(indexed.valid && linear.valid && exact.valid) << radius;
  ASSERT_TRUE(allFinite(indexed) && allFinite(linear) && std::isfinite(exact.surfaceHeightMeters));
  ASSERT_LT(indexed.cameraHeightMeters, 5100.0 - ellipsoid.semiMinorAxisMeters);
  ASSERT_TRUE(indexed.collided && linear.collided && exact.collided);
  ASSERT_EQ(indexed.tile, linear.tile);
  if (a.coversGlobe) {
    ASSERT_TRUE(indexed.found && exact.found);
  }
}

// Non-finite components, latitudes beyond the poles and non-finite clearances.
void badQuery(std::mt19937_64& rng, const StressArray& a, const geo::Ellipsoid& ellipsoid,
              SurfaceStats& stats) {
  ++stats.rejected;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double bad[] = {kNaN, -kNaN, kInf, -kInf};
  const double badValue = bad[rng() % 4];
  const double lon = -std::numbers::pi + 2.0 * std::numbers::pi * unit(rng);
  const double lat = std::asin(2.0 * unit(rng) - 1.0);
  const double d = 9000.0 * unit(rng);
  switch (rng() % 4) {
    case 0: {  // ECEF with one bad component
      glm::dvec3 camera = geo::cartographicToEcef(ellipsoid, {lon, lat, d});
      camera[static_cast<int>(rng() % 3)] = badValue;
      ASSERT_TRUE(isRejected(qotcdIndexed(a.array, ellipsoid, camera, 2.0)));
      ASSERT_TRUE(isRejected(qotcdLinear(a.array, ellipsoid, camera, 2.0)));
      ASSERT_TRUE(isRejected(exactSurfaceTest(a.array, ellipsoid, camera, 2.0)));
      return;
    }
    case 1: {  // geodetic with one bad component
      geo::Cartographic camera{lon, lat, d};
      const uint64_t which = rng() % 3;
      (which == 0   ? camera.longitudeRadians
       : which == 1 ? camera.latitudeRadians
                    : camera.heightMeters) = badValue;
      ASSERT_TRUE(isRejected(qotcdIndexed(a.array, camera, 2.0)));
      ASSERT_TRUE(isRejected(qotcdLinear(a.array, camera, 2.0)));
      if (which < 2) {
        ASSERT_FALSE(exactSurfaceHeight(a.array, ellipsoid, camera.longitudeRadians,
                                        camera.latitudeRadians));
        ASSERT_FALSE(sampleHeight(a.array, ellipsoid, camera.longitudeRadians,
                                  camera.latitudeRadians, HeightMode::Qotcd));
        ASSERT_EQ(a.array.lookupIndexed(camera.longitudeRadians, camera.latitudeRadians).tile,
                  nullptr);
      }
      return;
    }
    case 2: {  // a latitude beyond a pole, by one ulp or more
      const double pole = (rng() & 1) ? kHalfPi : -kHalfPi;
      const double beyond =
          (rng() & 1) != 0 ? std::nextafter(pole, 2.0 * pole) : pole * (1.0 + unit(rng));
      ASSERT_TRUE(isRejected(qotcdIndexed(a.array, {lon, beyond, d}, 2.0))) << beyond;
      ASSERT_TRUE(isRejected(qotcdLinear(a.array, {lon, beyond, d}, 2.0))) << beyond;
      ASSERT_FALSE(sampleHeight(a.array, ellipsoid, lon, beyond, HeightMode::Exact));
      return;
    }
    default: {  // a non-finite clearance counts as 0
      const QotcdResult r = qotcdIndexed(a.array, {lon, lat, d}, badValue);
      const QotcdResult zero = qotcdIndexed(a.array, {lon, lat, d}, 0.0);
      ASSERT_TRUE(r.valid && allFinite(r));
      ASSERT_EQ(r.collided, zero.collided);
      ASSERT_EQ(r.earlyOut, zero.earlyOut);
      ASSERT_EQ(r.terrainHeightMeters, zero.terrainHeightMeters);
      const ExactSurfaceResult x = exactSurfaceTest(
          a.array, ellipsoid, geo::cartographicToEcef(ellipsoid, {lon, lat, d}), badValue);
      ASSERT_TRUE(x.valid && std::isfinite(x.surfaceHeightMeters));
      ASSERT_EQ(x.collided, x.cameraHeightMeters <= x.surfaceHeightMeters);
    }
  }
}

TEST(StressQotcd, TenMillionQueriesOnTheRealPyramid) {
  RealPyramid& pyramid = RealPyramid::bundled();
  const stress::Stopwatch stopwatch;
  std::vector<StressArray> arrays = stressArrays(pyramid);
  const uint32_t maxLevel = pyramid.maxLevel();
  ASSERT_GE(maxLevel, 14u);
  const uint64_t count = stress::stressCount(stress::kStressPoints);
  std::mt19937_64 rng(301);
  SurfaceStats stats;
  for (uint64_t q = 0; q < count; ++q) {
    StressArray& a = arrays[q % arrays.size()];
    const geo::Ellipsoid ellipsoid =
        (q / arrays.size()) % 2 == 0 ? geo::Ellipsoid::wgs84() : geo::Ellipsoid::sphere();
    const uint64_t kind = rng() % 64;
    if (kind == 0) {
      geocentreQuery(rng, a, ellipsoid, stats);
    } else if (kind == 1) {
      badQuery(rng, a, ellipsoid, stats);
    } else {
      // Edges of tiles up to the pyramid's deepest level, or of any level up to 30.
      const uint32_t edgeLevel = kind % 2 == 0 ? maxLevel : geo::kMaxLevel;
      regularQuery(rng, a, ellipsoid, edgeLevel, kind % 4 == 1, kind % 4 == 2, kind == 2, stats);
    }
    if (::testing::Test::HasFatalFailure()) return;
  }
  for (const StressArray& a : arrays) {
    char line[240];
    std::snprintf(
        line, sizeof line,
        "%zu tiles: %llu queries, %llu found, %llu by an edge neighbour, %llu "
        "early-outs, %llu collided",
        a.tiles.size(), static_cast<unsigned long long>(a.queries),
        static_cast<unsigned long long>(a.found), static_cast<unsigned long long>(a.edgeNeighbours),
        static_cast<unsigned long long>(a.earlyOuts), static_cast<unsigned long long>(a.collided));
    stress::reportStress("QOTCD " + a.name, line);
    EXPECT_GT(a.edgeNeighbours, a.queries / 1000) << a.name;
    EXPECT_GT(a.earlyOuts, a.queries / 10) << a.name;
    EXPECT_GT(a.collided, a.queries / 10) << a.name;
  }
  char summary[400];
  std::snprintf(summary, sizeof summary,
                "%llu queries (%llu at a pole, %llu at +-180 deg, %llu via ECEF, %llu near the "
                "geocentre, %llu rejected): H vs exact surface E on %llu: min H-E %.3g m, %llu "
                "below -1e-6 m (at most %.2f of the row-sliver allowance), %llu collisions "
                "missed by the sliver; E below the lowest vertex at most %.3f of the sag bound; "
                "max ECEF height error %.3g m; %s",
                static_cast<unsigned long long>(count),
                static_cast<unsigned long long>(stats.poles),
                static_cast<unsigned long long>(stats.antimeridian),
                static_cast<unsigned long long>(stats.ecefQueries),
                static_cast<unsigned long long>(stats.geocentre),
                static_cast<unsigned long long>(stats.rejected),
                static_cast<unsigned long long>(stats.compared), stats.minHMinusE,
                static_cast<unsigned long long>(stats.belowSurface), stats.worstSliverRatio,
                static_cast<unsigned long long>(stats.sliverMisses), stats.worstSagRatio,
                stats.maxEcefHeightError, stopwatch.elapsed().c_str());
  stress::reportStress("QOTCD", summary);
  EXPECT_GT(stats.poles, count / 100);
  EXPECT_GT(stats.antimeridian, count / 100);
}

}  // namespace
}  // namespace globe::collision
