// A small pyramid written straight from packs for the sea-surface tests: open sea with a known
// floor, and one tile mixing band-coded water, water of unknown depth and land below and above
// sea level. Written with io::encodePack, so it needs no tiler.
#pragma once

#include <cstdint>
#include <filesystem>

#include "core/result.hpp"
#include "formats/pack_format.hpp"
#include "geo/tile_id.hpp"
#include "terrain/height_block.hpp"

namespace globe::testing {

// Level 0: both tiles water of unknown depth (-9999). Level 10 (levels 1..9 have no tiles): the
// 2x2 tiles kSeaTiles..+1 over the Atlantic (about 30°W 10°N), all water over a floor at
// kSeaFloorMeters but for the south-east tile (kMixedTile), whose vertices are, by column c:
//   c 0..3   water, floor at kSeaFloorMeters     c 4..7    water, depth unknown (-9999)
//   c 8..11  land at -400 m (below sea level)    c 12..16  land at 250 m
// except three vertices: (14, 2) water over the deepest floor encodable (-12767 m), (2, 14) land
// at -9998 m and (14, 14) land at -10000 m (neither is -9999: both land).
inline constexpr uint32_t kSeaTestVerticesPerSide = 17;
inline constexpr uint32_t kSeaTestLevel = 10;
inline constexpr double kSeaFloorMeters = -200.0;
inline constexpr double kMixedLandBelowSeaLevelMeters = -400.0;
inline constexpr double kMixedLandMeters = 250.0;
inline constexpr geo::TileId kSeaTile{kSeaTestLevel, 852, 454};    // north-west: open sea
inline constexpr geo::TileId kMixedTile{kSeaTestLevel, 853, 455};  // south-east: mixed

// The sample of vertex (row, column) of a level-10 tile (the same rule on every tile, so shared
// edge vertices agree).
int16_t seaTestSample(const geo::TileId& tile, uint32_t row, uint32_t column);
terrain::HeightBlock seaTestBlock(const geo::TileId& tile);

// Writes the pyramid (manifest.json and two packs) into `dir`; its packs carry `packVersion` in
// their header (a valid CRC either way), to make a pyramid of an older format.
Result<void> writeSeaTestPyramid(const std::filesystem::path& dir,
                                 uint32_t packVersion = formats::kPackFormatVersion);

// The degrees of the centre of grid cell (row + 0.5, column + 0.5) of `tile`.
struct CellCentreDegrees {
  double longitude = 0, latitude = 0;
};
CellCentreDegrees cellCentreDegrees(const geo::TileId& tile, uint32_t row, uint32_t column);

}  // namespace globe::testing
