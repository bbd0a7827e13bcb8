#include "publish/quantized_mesh_export.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "compression/deflate_bytes.hpp"
#include "formats/pyramid_manifest.hpp"
#include "publish/block_mesh.hpp"
#include "surface/pyramid_surface.hpp"
#include "publish/terrain_layer_writer.hpp"
#include "publish/tile_workers.hpp"
#include "publish/tile_grid.hpp"
#include "publish/tin_simplifier.hpp"
#include "terrain/block_grid.hpp"

namespace globe::publish {
namespace {

// Vertices per side of every tile: CesiumJS (and globe's reader) estimate a quantized-mesh
// tile's geometric error as a 65×65 heightmap's, so a coarser grid would be refined too little.
constexpr uint32_t kGridVertices = 65;

// CesiumJS's estimate of a tile's geometric error at level 0 (a 65-sample heightmap over each of
// the 2 root tiles, TerrainProvider.getEstimatedLevelZeroGeometricErrorForAHeightmap), halved
// with each level: what the client refines by, so what a tile's TIN may deviate by.
double levelGeometricErrorMeters(const geo::Ellipsoid& ellipsoid, uint32_t level) {
  constexpr double kHeightmapTerrainQuality = 0.25;
  const double levelZero = ellipsoid.semiMajorAxisMeters * 2 * std::numbers::pi *
                           kHeightmapTerrainQuality / (kGridVertices * 2);
  return std::ldexp(levelZero, -static_cast<int>(level));
}

// The water mask (extension 2) from the sea classification at the grid's samples: one byte where
// the tile is all land or all water, else 256×256 (rows from the north), each texel the nearest
// sample's class. The grid's samples are the pyramid's finest where it has them.
Result<std::vector<uint8_t>> waterMask(surface::PyramidSurface& surface, const geo::TileId& tile,
                                       uint32_t level) {
  const terrain::BlockGrid grid{tile, kGridVertices};
  std::vector<uint8_t> water;
  water.reserve(size_t{kGridVertices} * kGridVertices);
  size_t wet = 0;
  for (uint32_t row = 0; row < kGridVertices; ++row) {
    const double lat = grid.latitudeDegrees(row) * std::numbers::pi / 180;
    for (uint32_t column = 0; column < kGridVertices; ++column) {
      auto isWater =
          surface.isWater(grid.longitudeDegrees(column) * std::numbers::pi / 180, lat, level);
      if (!isWater) return Error{isWater.error()};
      water.push_back(*isWater ? 255 : 0);
      wet += *isWater ? 1 : 0;
    }
  }
  if (wet == 0) return std::vector<uint8_t>{0};
  if (wet == water.size()) return std::vector<uint8_t>{255};
  constexpr uint32_t kMaskSide = 256;
  std::vector<uint8_t> mask(size_t{kMaskSide} * kMaskSide);
  const auto nearest = [](uint32_t texel) {
    return static_cast<uint32_t>(
        std::lround((texel + 0.5) * (kGridVertices - 1) / double{kMaskSide}));
  };
  for (uint32_t row = 0; row < kMaskSide; ++row) {
    for (uint32_t column = 0; column < kMaskSide; ++column) {
      mask[size_t{row} * kMaskSide + column] =
          water[size_t{nearest(row)} * kGridVertices + nearest(column)];
    }
  }
  return mask;
}

// Extension 4: which of the tile's children the tree holds, as a layer.json `available` level.
std::string childrenMetadata(streaming::TerrainSource& source, const geo::TileId& tile,
                             uint32_t lastLevel) {
  nlohmann::json ranges = nlohmann::json::array();
  if (tile.level < lastLevel) {
    for (uint32_t child = 0; child < 4; ++child) {
      const geo::TileId c{tile.level + 1, tile.x * 2 + (child & 1), tile.y * 2 + (child >> 1)};
      auto summary = source.summary(c);
      if (!summary || !*summary) continue;
      ranges.push_back(
          {{"startX", c.x}, {"startY", tmsRow(c)}, {"endX", c.x}, {"endY", tmsRow(c)}});
    }
  }
  return nlohmann::json{{"available", nlohmann::json::array({ranges})}}.dump();
}

// One tile: the grid's TIN within the tile's error, with normals, water mask and metadata.
Result<std::vector<std::byte>> makeTile(surface::PyramidSurface& surface, streaming::TerrainSource& source,
                                        const geo::TileId& tile, uint32_t sampleLevel,
                                        uint32_t lastLevel, double errorFraction,
                                        const geo::Ellipsoid& ellipsoid) {
  auto grid = sampleTileGrid(surface, tile, kGridVertices, sampleLevel);
  if (!grid) return Error{grid.error()};
  // 0: the whole grid, split as globe draws it, so that the tile is globe's surface exactly.
  // Between the samples and under the globe's curve too: what a client draws of the TIN.
  const GridTin tin =
      errorFraction > 0
          ? simplifyTileGrid(grid->heightsMeters, grid->apronMeters,
                             gridPositionsEcefMeters(*grid, ellipsoid), kGridVertices,
                             errorFraction * levelGeometricErrorMeters(ellipsoid, tile.level))
          : wholeGridTin(kGridVertices);
  BlockMesh mesh = quantizedMeshOfTin(tile, kGridVertices, grid->heightsMeters, tin, ellipsoid);
  for (uint32_t sample : tin.samples) {
    mesh.mesh.normals.push_back(gridNormal(*grid, ellipsoid,
                                           static_cast<int>(sample / kGridVertices),
                                           static_cast<int>(sample % kGridVertices)));
  }
  auto water = waterMask(surface, tile, sampleLevel);
  if (!water) return Error{water.error()};
  mesh.mesh.waterMask = std::move(*water);
  mesh.mesh.metadataJson = childrenMetadata(source, tile, lastLevel);
  return compression::gzipCompress(formats::encodeQuantizedMesh(mesh.mesh, mesh.culling), 9);
}

// Bumped when the tiles' making changes: their URLs change with it.
constexpr int kExporterRevision = 2;  // 2: simplified TINs, normals, water, metadata

}  // namespace

Result<ExportReport> exportQuantizedMesh(streaming::TerrainSource& source,
                                         const ExportRegion& region,
                                         const std::filesystem::path& outDir,
                                         const geo::Ellipsoid& ellipsoid, double errorFraction,
                                         const ExportWork& work) {
  const formats::PyramidManifest& manifest = source.manifest();
  // A tile's grid holds the pyramid's level `extra` deeper (17-vertex blocks: 2 levels), so the
  // tree stops that much sooner.
  uint32_t extra = 0;
  while ((manifest.verticesPerSide - 1) << extra < kGridVertices - 1) ++extra;
  const auto sampleLevel = [&](uint32_t level) { return level + extra; };
  const uint32_t deepest = manifest.maxLevel() > extra ? manifest.maxLevel() - extra : 0;
  const uint32_t last = std::min(region.maxLevel, deepest);
  // The present tiles first (their packs' indexes), then the tiles made by the workers, each
  // with its own surface (it caches blocks).
  std::vector<geo::TileId> tiles;
  for (uint32_t level = region.minLevel; level <= last; ++level) {
    for (const geo::TileId& tile : candidateTiles(manifest, level, region)) {
      auto summary = source.summary(tile);
      if (!summary) return Error{summary.error()};
      if (*summary) tiles.push_back(tile);
    }
  }
  std::vector<std::unique_ptr<surface::PyramidSurface>> surfaces;
  for (unsigned w = 0; w < tileWorkerCount(tiles.size(), work.threads); ++w) {
    surfaces.push_back(std::make_unique<surface::PyramidSurface>(source, ellipsoid));
  }
  auto report = runTileJobs(
      tiles.size(), work.threads,
      [&](unsigned worker, size_t i, ExportReport& counts) {
        const geo::TileId& tile = tiles[i];
        return writeTileOnce(
            terrainTilePath(outDir, tile),
            [&]() -> Result<std::vector<std::byte>> {
              return makeTile(*surfaces[worker], source, tile, sampleLevel(tile.level), last,
                              errorFraction, ellipsoid);
            },
            counts);
      },
      work.progress);
  if (!report) return Error{report.error()};
  // layer.json last and always rewritten: it lists what this and earlier runs wrote.
  if (auto written = writeTerrainLayerJson(outDir, "quantized-mesh-1.0",
                                           treeVersion(manifest, kExporterRevision), source,
                                           {"octvertexnormals", "watermask", "metadata"});
      !written) {
    return Error{written.error()};
  }
  return *report;
}

}  // namespace globe::publish
