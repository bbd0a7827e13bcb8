// Stress test for GeographicTilingScheme::positionToTile over 10^7 points (a twentieth under the
// sanitizers): uniform points, exact poles, +-180 deg and one ulp around them, tile edges and
// corners of every level, wrapped longitudes; each looked up at 9 consecutive levels around the
// level it was made at (one point in 16 at all levels 0..kMaxLevel).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "geo/tiling_scheme.hpp"
#include "stress_scale.hpp"

namespace globe::geo {
namespace {

using Scheme = GeographicTilingScheme;
constexpr double kHalfPi = std::numbers::pi / 2.0;

TileId randomTile(std::mt19937_64& rng) {
  const uint32_t level = static_cast<uint32_t>(rng() % (kMaxLevel + 1));
  return {level, static_cast<uint32_t>(rng() % Scheme::tilesX(level)),
          static_cast<uint32_t>(rng() % Scheme::tilesY(level))};
}

double aroundUlp(std::mt19937_64& rng, double value) {
  switch (rng() % 4) {
    case 0:
      return std::nextafter(value, -4.0);
    case 1:
      return std::nextafter(value, 4.0);
    default:
      return value;
  }
}

struct Point {
  double longitudeRadians;
  double latitudeRadians;
  // When the point is a tile's west/north corner: that tile must own it at its level.
  std::optional<TileId> cornerOf;
  // The level of the tile the point was made from (random for the others).
  uint32_t level;
};

Point randomPoint(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double uniformLongitude = -std::numbers::pi + 2.0 * std::numbers::pi * unit(rng);
  const double uniformLatitude = std::asin(2.0 * unit(rng) - 1.0);
  const uint32_t randomLevel = static_cast<uint32_t>(rng() % (kMaxLevel + 1));
  switch (rng() % 10) {
    case 0:
    case 1:
    case 2:
      return {uniformLongitude, uniformLatitude, std::nullopt, randomLevel};
    case 3: {  // +-180 deg exactly or one ulp either side (beyond wraps), any latitude
      const double lon = aroundUlp(rng, (rng() & 1) ? std::numbers::pi : -std::numbers::pi);
      return {lon, (rng() & 1) ? uniformLatitude : aroundUlp(rng, 0.0), std::nullopt, randomLevel};
    }
    case 4: {  // a pole exactly or one ulp inside it, any longitude (+-180 deg included)
      const double pole = (rng() & 1) ? kHalfPi : -kHalfPi;
      const double lat = (rng() & 1) ? pole : std::nextafter(pole, 0.0);
      const double lon = (rng() & 1)
                             ? uniformLongitude
                             : aroundUlp(rng, (rng() & 1) ? std::numbers::pi : -std::numbers::pi);
      return {lon, lat, std::nullopt, randomLevel};
    }
    case 5:
    case 6: {  // a tile's west/north corner at any level: the tile itself owns it
      const TileId tile = randomTile(rng);
      const GlobeRectangle r = Scheme::tileRectangle(tile);
      return {r.westRadians, r.northRadians, tile, tile.level};
    }
    case 7:
    case 8: {  // any edge or corner of a tile at any level, exactly or one ulp either side
      const TileId tile = randomTile(rng);
      const GlobeRectangle r = Scheme::tileRectangle(tile);
      double lon = r.westRadians + unit(rng) * r.widthRadians();
      double lat = r.southRadians + unit(rng) * r.heightRadians();
      if (rng() % 3 != 0) lon = aroundUlp(rng, (rng() & 1) ? r.westRadians : r.eastRadians);
      if (rng() % 3 != 0) lat = aroundUlp(rng, (rng() & 1) ? r.southRadians : r.northRadians);
      return {lon, std::clamp(lat, -kHalfPi, kHalfPi), std::nullopt, tile.level};
    }
    default:  // longitudes outside [-pi, pi], a few turns away
      return {uniformLongitude +
                  2.0 * std::numbers::pi * static_cast<double>(static_cast<int>(rng() % 7) - 3),
              uniformLatitude, std::nullopt, randomLevel};
  }
}

TEST(StressTilingScheme, PositionToTileOverTenMillionPoints) {
  const stress::Stopwatch stopwatch;
  const uint64_t count = stress::stressCount(stress::kStressPoints);
  std::mt19937_64 rng(201);
  uint64_t lookups = 0, corners = 0, antimeridian = 0, poles = 0;
  std::array<uint64_t, kMaxLevel + 1> lookupsPerLevel{};
  for (uint64_t i = 0; i < count; ++i) {
    const Point p = randomPoint(rng);
    // The scheme wraps longitudes first; containment is checked on the wrapped value.
    const double lon = wrapLongitudeRadians(p.longitudeRadians);
    const double lat = p.latitudeRadians;
    antimeridian += std::abs(lon) == std::numbers::pi;
    poles += std::abs(lat) == kHalfPi;
    // 9 consecutive levels from up to 4 coarser than the point's (an edge of a level is an edge
    // of every finer one), or all of them.
    const bool allLevels = i % 16 == 0;
    const uint32_t first = allLevels ? 0 : p.level - std::min(p.level, 4u);
    const uint32_t last = allLevels ? kMaxLevel : std::min(first + 8, kMaxLevel);
    std::optional<TileId> parent;
    for (uint32_t level = first; level <= last; ++level) {
      const std::optional<TileId> tile = Scheme::positionToTile(p.longitudeRadians, lat, level);
      ++lookups;
      ++lookupsPerLevel[level];
      ASSERT_TRUE(tile.has_value()) << p.longitudeRadians << " " << lat << " level " << level;
      ASSERT_EQ(tile->level, level);
      ASSERT_LT(tile->x, Scheme::tilesX(level));
      ASSERT_LT(tile->y, Scheme::tilesY(level));
      // Half-open [west, east) x (south, north], closed at +180 deg and -90 deg: since the
      // rectangles partition the globe, this pins down the one right tile.
      const GlobeRectangle r = Scheme::tileRectangle(*tile);
      const bool lastColumn = tile->x + 1 == Scheme::tilesX(level);
      const bool lastRow = tile->y + 1 == Scheme::tilesY(level);
      const bool ownsLongitude =
          r.westRadians <= lon && (lon < r.eastRadians || (lastColumn && lon <= r.eastRadians));
      const bool ownsLatitude =
          lat <= r.northRadians && (lat > r.southRadians || (lastRow && lat >= r.southRadians));
      if (!ownsLongitude || !ownsLatitude) {
        FAIL() << "lon " << p.longitudeRadians << " (wrapped " << lon << ") lat " << lat
               << " level " << level << " -> x " << tile->x << " y " << tile->y << " ["
               << r.westRadians << ", " << r.eastRadians << "] x [" << r.southRadians << ", "
               << r.northRadians << "]";
      }
      // The tree: the tile one level up is this tile's parent.
      if (parent) {
        ASSERT_EQ(tile->parent(), *parent) << lon << " " << lat << " level " << level;
      }
      if (p.cornerOf && p.cornerOf->level == level) {
        ASSERT_EQ(*tile, *p.cornerOf);
        ++corners;
      }
      parent = tile;
    }
    // Beyond the deepest level there is no tile.
    ASSERT_FALSE(Scheme::positionToTile(p.longitudeRadians, lat,
                                        kMaxLevel + 1 + static_cast<uint32_t>(i % 3)));
  }
  char summary[240];
  std::snprintf(summary, sizeof summary,
                "%llu points, %llu lookups (at least %llu at each level 0..%u; %llu own-corner "
                "checks, %llu at +-180 deg, %llu at a pole), %s",
                static_cast<unsigned long long>(count), static_cast<unsigned long long>(lookups),
                static_cast<unsigned long long>(
                    *std::min_element(lookupsPerLevel.begin(), lookupsPerLevel.end())),
                kMaxLevel, static_cast<unsigned long long>(corners),
                static_cast<unsigned long long>(antimeridian),
                static_cast<unsigned long long>(poles), stopwatch.elapsed().c_str());
  stress::reportStress("positionToTile", summary);
  EXPECT_GT(corners, count / 10);
  for (const uint64_t n : lookupsPerLevel) EXPECT_GT(n, count / 10);
  EXPECT_GT(antimeridian, count / 100);
  EXPECT_GT(poles, count / 100);
}

// Non-finite input and latitudes beyond the poles (by one ulp or more) give no tile at any level.
TEST(StressTilingScheme, InvalidPositionsGiveNoTileAtAnyLevel) {
  const uint64_t count = stress::stressCount(stress::kStressPoints / 20);
  std::mt19937_64 rng(202);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const double badLatitudes[] = {nan,
                                 inf,
                                 -inf,
                                 std::nextafter(kHalfPi, 4.0),
                                 std::nextafter(-kHalfPi, -4.0),
                                 std::numbers::pi,
                                 -1e300,
                                 std::numeric_limits<double>::max()};
  const double badLongitudes[] = {nan, -nan, inf, -inf};
  for (uint64_t i = 0; i < count; ++i) {
    const uint32_t level = static_cast<uint32_t>(rng() % (kMaxLevel + 1));
    const double lon = -std::numbers::pi + 2.0 * std::numbers::pi * unit(rng);
    const double lat = -kHalfPi + std::numbers::pi * unit(rng);
    const double badLat = badLatitudes[rng() % std::size(badLatitudes)];
    const double badLon = badLongitudes[rng() % std::size(badLongitudes)];
    ASSERT_FALSE(Scheme::positionToTile(lon, badLat, level)) << lon << " " << badLat;
    ASSERT_FALSE(Scheme::positionToTile(badLon, lat, level)) << badLon << " " << lat;
  }
}

}  // namespace
}  // namespace globe::geo
