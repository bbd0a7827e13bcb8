#include "publish/heightmap_export.hpp"

#include <algorithm>
#include <array>
#include <memory>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "compression/deflate_bytes.hpp"
#include "compression/gzip_bytes.hpp"
#include "formats/quantized_mesh.hpp"
#include "geo/tiling_scheme.hpp"
#include "publish/terrain_layer_writer.hpp"
#include "publish/tile_workers.hpp"
#include "surface/lattice_heights.hpp"
#include "surface/pyramid_surface.hpp"
#include "terrain/block_grid.hpp"
#include "transport/atomic_file.hpp"

namespace globe::publish {
// Named apart from the other exporters' helpers, which unity builds compile in one unit.
namespace heightmap_tiles {
namespace {

constexpr uint32_t kSide = formats::HeightmapTile::kSide;
constexpr uint32_t kWaterMaskSide = 256;
// Bumped when the tiles' making changes: their URLs change with it.
constexpr int kExporterRevision = 1;
constexpr uint64_t kMaxTileBytes = uint64_t{1} << 20;

constexpr double kRadiansPerDegree = std::numbers::pi / 180;

// heightmap-1.0's child bits in TileId::children()'s order (NW, NE, SW, SE).
constexpr std::array<uint8_t, 4> kChildBits = {4, 8, 1, 2};

bool onDisk(const std::filesystem::path& outDir, const geo::TileId& tile) {
  std::error_code error;
  return std::filesystem::is_regular_file(terrainTilePath(outDir, tile), error);
}

// The children of `tile` in the tree: those this run writes or keeps, and those on disk.
uint8_t childMask(const std::filesystem::path& outDir, const geo::TileId& tile,
                  const std::set<geo::TileId>& runTiles) {
  uint8_t mask = 0;
  const auto children = tile.children();
  for (size_t k = 0; k < children.size(); ++k) {
    if (runTiles.contains(children[k]) || onDisk(outDir, children[k])) mask |= kChildBits[k];
  }
  return mask;
}

// 256×256 water flags, rows from the north, each of the pixel's centre; one byte where uniform.
Result<std::vector<uint8_t>> waterMask(surface::PyramidSurface& surface, const geo::TileId& tile,
                                       uint32_t level) {
  const auto rect = geo::GeographicTilingScheme::tileRectangle(tile);
  std::vector<uint8_t> mask(size_t{kWaterMaskSide} * kWaterMaskSide);
  for (uint32_t row = 0; row < kWaterMaskSide; ++row) {
    const double lat =
        rect.northRadians - (row + 0.5) / kWaterMaskSide * (rect.northRadians - rect.southRadians);
    for (uint32_t column = 0; column < kWaterMaskSide; ++column) {
      const double lon = rect.westRadians +
                         (column + 0.5) / kWaterMaskSide * (rect.eastRadians - rect.westRadians);
      auto water = surface.isWater(lon, lat, level);
      if (!water) return Error{water.error()};
      mask[size_t{row} * kWaterMaskSide + column] = *water ? 255 : 0;
    }
  }
  if (std::all_of(mask.begin(), mask.end(), [&](uint8_t m) { return m == mask[0]; })) {
    mask.resize(1);
  }
  return mask;
}

Result<std::vector<std::byte>> makeTile(surface::PyramidSurface& surface, const geo::TileId& tile,
                                        uint32_t sampleLevel, uint8_t children) {
  formats::HeightmapTile made;
  made.childMask = children;
  const terrain::BlockGrid grid{tile, kSide};
  std::array<double, kSide> longitudes{}, latitudes{};
  for (uint32_t i = 0; i < kSide; ++i) {
    longitudes[i] = grid.longitudeDegrees(i) * kRadiansPerDegree;
    latitudes[i] = grid.latitudeDegrees(i) * kRadiansPerDegree;
  }
  // The posts make a lattice: the exact surface at each, computed per block, not per post.
  auto heights = surface::latticeHeightsMeters(surface, longitudes, latitudes, sampleLevel);
  if (!heights) return Error{heights.error()};
  made.heightMeters = std::move(*heights);
  auto water = waterMask(surface, tile, sampleLevel);
  if (!water) return Error{water.error()};
  made.waterMask = std::move(*water);
  return compression::gzipCompress(formats::encodeHeightmapTile(made), 9);
}

// A tile kept from an earlier run whose children changed since (this run added some): its
// child mask byte rewritten, the rest as it was.
Result<void> fixChildMask(const std::filesystem::path& outDir, const geo::TileId& tile,
                          const std::set<geo::TileId>& runTiles) {
  const std::filesystem::path path = terrainTilePath(outDir, tile);
  auto bytes = transport::readWholeFile(path, kMaxTileBytes);
  if (!bytes) return Error{bytes.error()};
  auto inflated = compression::gunzipIfNeeded(*bytes, path.string(), kMaxTileBytes);
  if (!inflated) return Error{inflated.error()};
  constexpr size_t kMaskAt = size_t{kSide} * kSide * 2;
  if (inflated->size() <= kMaskAt) {
    return makeError(path.string() + ": not a heightmap-1.0 tile (" +
                     std::to_string(inflated->size()) + " bytes)");
  }
  const auto mask = static_cast<std::byte>(childMask(outDir, tile, runTiles));
  if ((*inflated)[kMaskAt] == mask) return {};
  (*inflated)[kMaskAt] = mask;
  return writeFileReplacing(path, compression::gzipCompress(*inflated, 9));
}

Result<ExportReport> exportTree(streaming::TerrainSource& source, const ExportRegion& region,
                                const std::filesystem::path& outDir,
                                const geo::Ellipsoid& ellipsoid, const ExportWork& work) {
  const formats::PyramidManifest& manifest = source.manifest();
  // A tile's grid holds the pyramid's level `extra` deeper (17-vertex blocks: 2 levels), so the
  // tree stops that much sooner (as the quantized-mesh tree).
  uint32_t extra = 0;
  while ((manifest.verticesPerSide - 1) << extra < kSide - 1) ++extra;
  const uint32_t deepest = manifest.maxLevel() > extra ? manifest.maxLevel() - extra : 0;
  const uint32_t last = std::min(region.maxLevel, deepest);
  // The run's tiles of the present pyramid, every level's known before any is written, so that
  // a tile's child mask names its children and the progress its total.
  std::vector<std::vector<geo::TileId>> runTiles;
  uint64_t total = 0;
  for (uint32_t level = region.minLevel; level <= last + 1; ++level) {
    std::vector<geo::TileId>& tiles = runTiles.emplace_back();
    if (level > last) break;
    for (const geo::TileId& tile : candidateTiles(manifest, level, region)) {
      auto summary = source.summary(tile);
      if (!summary) return Error{summary.error()};
      if (*summary) tiles.push_back(tile);
    }
    total += tiles.size();
  }
  std::vector<std::unique_ptr<surface::PyramidSurface>> surfaces;
  for (unsigned w = 0; w < std::max(1U, work.threads); ++w) {
    surfaces.push_back(std::make_unique<surface::PyramidSurface>(source, ellipsoid));
  }
  ExportReport report;
  uint64_t doneBefore = 0;
  std::set<geo::TileId> writtenAbove;  // the tiles this run wrote one level up
  for (uint32_t level = region.minLevel; level <= last; ++level) {
    const std::vector<geo::TileId>& current = runTiles[level - region.minLevel];
    const std::set<geo::TileId> below(runTiles[level + 1 - region.minLevel].begin(),
                                      runTiles[level + 1 - region.minLevel].end());
    std::vector<uint8_t> wrote(current.size(), 0);
    auto levelReport = runTileJobs(
        current.size(), work.threads,
        [&](unsigned worker, size_t i, ExportReport& counts) -> Result<void> {
          const geo::TileId& tile = current[i];
          const uint64_t before = counts.tilesWritten;
          auto done = writeTileOnce(
              terrainTilePath(outDir, tile),
              [&] {
                return makeTile(*surfaces[worker], tile, tile.level + extra,
                                childMask(outDir, tile, below));
              },
              counts);
          if (done && counts.tilesWritten > before) wrote[i] = 1;
          return done;
        },
        [&](uint64_t done, uint64_t) {
          if (work.progress) work.progress(doneBefore + done, total);
        });
    if (!levelReport) return Error{levelReport.error()};
    doneBefore += current.size();
    report.tilesWritten += levelReport->tilesWritten;
    report.tilesKept += levelReport->tilesKept;
    report.bytesWritten += levelReport->bytesWritten;
    // Parents this run did not write (kept from an earlier run, or above its levels) learn of
    // their children: runs over other regions or levels add to a tree.
    std::set<geo::TileId> written, parents;
    for (size_t i = 0; i < current.size(); ++i) {
      if (wrote[i] != 0) written.insert(current[i]);
      if (level > 0 && !writtenAbove.contains(current[i].parent())) {
        parents.insert(current[i].parent());
      }
    }
    const std::set<geo::TileId> currentSet(current.begin(), current.end());
    for (const geo::TileId& parent : parents) {
      if (!onDisk(outDir, parent)) continue;
      if (auto fixed = fixChildMask(outDir, parent, currentSet); !fixed) {
        return Error{fixed.error()};
      }
    }
    writtenAbove = std::move(written);
  }
  // layer.json last and always rewritten: it lists what this and earlier runs wrote.
  if (auto done = writeTerrainLayerJson(
          outDir, "heightmap-1.0", treeVersion(manifest, kExporterRevision, "heightmap"), source);
      !done) {
    return Error{done.error()};
  }
  return report;
}

}  // namespace
}  // namespace heightmap_tiles

Result<ExportReport> exportHeightmap(streaming::TerrainSource& source, const ExportRegion& region,
                                     const std::filesystem::path& outDir,
                                     const geo::Ellipsoid& ellipsoid, const ExportWork& work) {
  return heightmap_tiles::exportTree(source, region, outDir, ellipsoid, work);
}

}  // namespace globe::publish
