// The sea-surface tests' pyramid: packs encoded directly, a manifest listing them.
#include "tests/support/sea_test_pyramid.hpp"

#include <algorithm>
#include <vector>

#include "core/big_endian.hpp"
#include "core/crc32.hpp"
#include "formats/pyramid_manifest.hpp"
#include "geo/cartographic.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "transport/atomic_file.hpp"

namespace globe::testing {
namespace {

constexpr uint32_t kN = kSeaTestVerticesPerSide;
constexpr uint32_t kPackTiles = 64;

std::vector<geo::TileId> levelTenTiles() {
  std::vector<geo::TileId> tiles;
  for (uint32_t dy = 0; dy < 2; ++dy) {
    for (uint32_t dx = 0; dx < 2; ++dx) {
      tiles.push_back({kSeaTestLevel, kSeaTile.x + dx, kSeaTile.y + dy});
    }
  }
  return tiles;
}

formats::BoundsDegrees boundsOf(const std::vector<geo::TileId>& tiles) {
  formats::BoundsDegrees bounds{180, 90, -180, -90};
  for (const geo::TileId& tile : tiles) {
    const auto r = geo::GeographicTilingScheme::tileRectangle(tile);
    bounds.west = std::min(bounds.west, geo::radiansToDegrees(r.westRadians));
    bounds.south = std::min(bounds.south, geo::radiansToDegrees(r.southRadians));
    bounds.east = std::max(bounds.east, geo::radiansToDegrees(r.eastRadians));
    bounds.north = std::max(bounds.north, geo::radiansToDegrees(r.northRadians));
  }
  return bounds;
}

// Encodes the tiles (all of one pack) and writes the pack with `version` in its header.
Result<formats::LevelInfo> writeLevel(const std::filesystem::path& dir, uint32_t level,
                                      const std::vector<geo::TileId>& tiles, uint32_t version) {
  const formats::PackId id = formats::packOf(tiles.front(), kPackTiles);
  // Version 2 has its own layout (no aprons, shorter entries); others are written as the current
  // one with `version` in the header.
  formats::Pack pack =
      formats::Pack::empty(id, {kPackTiles, kN, version == 2 ? 2 : formats::kPackFormatVersion});
  formats::LevelInfo info{level, tiles.size(), boundsOf(tiles), {INT16_MAX, INT16_MIN}, {id}};
  for (const geo::TileId& tile : tiles) {
    const size_t slot = formats::slotOf(tile, kPackTiles);
    const terrain::HeightBlock block = seaTestBlock(tile);
    std::copy(block.heights.begin(), block.heights.end(), pack.block(slot).begin());
    const terrain::HeightRange range = terrain::surfaceHeightRange(block);
    pack.entries[slot] = {1, range, range};  // any non-zero offset marks the tile present
    info.heightRange.include(range);
  }
  std::vector<std::byte> bytes = formats::encodePack(pack);
  core::storeBigEndian32(&bytes[8], version);
  const size_t body = bytes.size() - 4;
  core::storeBigEndian32(&bytes[body], core::crc32(std::span(bytes).first(body)));
  const std::filesystem::path path = formats::packPath(dir, id);
  std::filesystem::create_directories(path.parent_path());
  if (auto written = transport::writeFileAtomically(path, bytes); !written)
    return Error{written.error()};
  return info;
}

}  // namespace

int16_t seaTestSample(const geo::TileId& tile, uint32_t row, uint32_t column) {
  const terrain::BlockGrid grid{tile, kN};
  const int64_t r = static_cast<int64_t>(grid.globalRow(row)) - int64_t{kSeaTile.y + 1} * (kN - 1);
  const int64_t c =
      static_cast<int64_t>(grid.globalColumn(column)) - int64_t{kSeaTile.x + 1} * (kN - 1);
  if (tile.level != kSeaTestLevel) return terrain::kNoDataHeight;
  if (r < 0 || c < 0) return terrain::encodeWater(kSeaFloorMeters);  // the open sea
  if (r == 14 && c == 2) return terrain::encodeWater(terrain::kDeepestSeaFloorMeters);
  if (r == 2 && c == 14) return -9998;
  if (r == 14 && c == 14) return -10000;
  if (c <= 3) return terrain::encodeWater(kSeaFloorMeters);
  if (c <= 7) return terrain::kNoDataHeight;
  if (c <= 11) return static_cast<int16_t>(kMixedLandBelowSeaLevelMeters);
  return static_cast<int16_t>(kMixedLandMeters);
}

terrain::HeightBlock seaTestBlock(const geo::TileId& tile) {
  terrain::HeightBlock block{kN, std::vector<int16_t>(size_t{kN} * kN)};
  for (uint32_t i = 0; i < kN; ++i) {
    for (uint32_t j = 0; j < kN; ++j) block.heights[size_t{i} * kN + j] = seaTestSample(tile, i, j);
  }
  return block;
}

Result<void> writeSeaTestPyramid(const std::filesystem::path& dir, uint32_t packVersion) {
  formats::PyramidManifest manifest;
  manifest.verticesPerSide = kN;
  manifest.packTilesPerSide = kPackTiles;
  for (uint32_t level = 0; level <= kSeaTestLevel; ++level) {
    std::vector<geo::TileId> tiles;
    if (level == 0) tiles = {{0, 0, 0}, {0, 1, 0}};
    if (level == kSeaTestLevel) tiles = levelTenTiles();
    if (tiles.empty()) {
      manifest.levels.push_back({level, 0, {}, {}, {}});
      continue;
    }
    auto info = writeLevel(dir, level, tiles, packVersion);
    if (!info) return Error{info.error()};
    manifest.levels.push_back(std::move(*info));
  }
  return transport::writeFileAtomically(dir / formats::kManifestFileName,
                                        formats::manifestToJson(manifest));
}

CellCentreDegrees cellCentreDegrees(const geo::TileId& tile, uint32_t row, uint32_t column) {
  const terrain::BlockGrid grid{tile, kN};
  return {0.5 * (grid.longitudeDegrees(column) + grid.longitudeDegrees(column + 1)),
          0.5 * (grid.latitudeDegrees(row) + grid.latitudeDegrees(row + 1))};
}

}  // namespace globe::testing
