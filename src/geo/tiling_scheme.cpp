// Tile counts, tile rectangles and position-to-tile lookup of the geographic tiling scheme.
#include "geo/tiling_scheme.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

namespace globe::geo {

namespace {

constexpr double kPi = std::numbers::pi;

// Tile extents per level: 2 pi / 2^(level+1) and pi / 2^level are exact (powers of two), so a
// table lookup gives the same bits as the division without paying one per edge.
constexpr auto kTileWidthRadians = [] {
  std::array<double, kMaxLevel + 1> widths{};
  for (uint32_t level = 0; level <= kMaxLevel; ++level) {
    widths[level] = 2.0 * kPi / static_cast<double>(uint64_t{2} << level);
  }
  return widths;
}();
constexpr auto kTileHeightRadians = [] {
  std::array<double, kMaxLevel + 1> heights{};
  for (uint32_t level = 0; level <= kMaxLevel; ++level) {
    heights[level] = kPi / static_cast<double>(uint64_t{1} << level);
  }
  return heights;
}();

// The single definition of tile edges; positionToTile must use these to agree bit for bit.
// Beyond kMaxLevel there are no tiles: NaN.
double westEdge(uint32_t x, uint32_t level) {
  if (level > kMaxLevel) return std::numeric_limits<double>::quiet_NaN();
  return -kPi + x * kTileWidthRadians[level];
}
double northEdge(uint32_t y, uint32_t level) {
  if (level > kMaxLevel) return std::numeric_limits<double>::quiet_NaN();
  return kPi / 2.0 - y * kTileHeightRadians[level];
}

// floor() of a value that may be slightly out of [0, count) through rounding, clamped into it.
uint32_t clampedIndex(double value, uint32_t count) {
  const double index = std::floor(value);
  if (index <= 0.0) return 0;
  if (index >= count - 1.0) return count - 1;
  return static_cast<uint32_t>(index);
}

}  // namespace

uint32_t GeographicTilingScheme::tilesX(uint32_t level) {
  return level > kMaxLevel ? 0 : uint32_t{2} << level;
}

uint32_t GeographicTilingScheme::tilesY(uint32_t level) {
  return level > kMaxLevel ? 0 : uint32_t{1} << level;
}

bool GeographicTilingScheme::isValid(const TileId& tile) {
  return tile.level <= kMaxLevel && tile.x < tilesX(tile.level) && tile.y < tilesY(tile.level);
}

GlobeRectangle GeographicTilingScheme::tileRectangle(const TileId& tile) {
  return {westEdge(tile.x, tile.level), northEdge(tile.y + 1, tile.level),
          westEdge(tile.x + 1, tile.level), northEdge(tile.y, tile.level)};
}

std::optional<TileId> GeographicTilingScheme::positionToTile(double longitudeRadians,
                                                             double latitudeRadians,
                                                             uint32_t level) {
  if (level > kMaxLevel || !std::isfinite(longitudeRadians) || !std::isfinite(latitudeRadians) ||
      std::abs(latitudeRadians) > kPi / 2.0) {
    return std::nullopt;
  }
  const double longitude = wrapLongitudeRadians(longitudeRadians);
  const uint32_t columns = tilesX(level);
  const uint32_t rows = tilesY(level);

  // The floor() guess can be one off where rounding puts the point on the wrong side of an edge;
  // fix it against the exact edge expressions. Columns are [west, east): +pi stays in the last.
  // The guesses multiply by reciprocals: the loops below make the answer exact whatever they say.
  constexpr double kInverseTwoPi = 1.0 / (2.0 * kPi);
  constexpr double kInversePi = 1.0 / kPi;
  uint32_t x = clampedIndex((longitude + kPi) * kInverseTwoPi * columns, columns);
  while (x > 0 && longitude < westEdge(x, level)) --x;
  while (x + 1 < columns && longitude >= westEdge(x + 1, level)) ++x;

  // Rows are (south, north]: a shared edge goes to the southern row; -pi/2 stays in the last.
  uint32_t y = clampedIndex((kPi / 2.0 - latitudeRadians) * kInversePi * rows, rows);
  while (y > 0 && latitudeRadians > northEdge(y, level)) --y;
  while (y + 1 < rows && latitudeRadians <= northEdge(y + 1, level)) ++y;

  return TileId{level, x, y};
}

}  // namespace globe::geo
