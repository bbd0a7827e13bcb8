#include "tiling/export_block.hpp"

#include "rasters/gtopo30.hpp"
#include "streaming/tile_store.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/height_block.hpp"

namespace globe::tiling {

Result<void> exportBlock(const std::filesystem::path& pyramidDir, const geo::TileId& tile,
                         const std::filesystem::path& outputStem) {
  auto store = streaming::TileStore::open(pyramidDir);
  if (!store) return Error{store.error()};
  auto block = (*store)->loadBlock(tile);
  if (!block) return Error{block.error()};
  const uint32_t n = block->verticesPerSide;
  const terrain::BlockGrid grid{tile, n};
  rasters::Gtopo30Raster raster;
  rasters::Gtopo30Header& h = raster.header;
  h.rows = h.cols = n;
  h.bandRowBytes = h.totalRowBytes = int64_t{n} * 2;
  // The block's vertices are the samples: ULXMAP/ULYMAP name the centre of vertex (0, 0).
  h.ulxMapDegrees = grid.longitudeDegrees(0);
  h.ulyMapDegrees = grid.latitudeDegrees(0);
  h.xDimDegrees = h.yDimDegrees = terrain::vertexSpacingDegrees(tile.level, n);
  // Strict GTOPO30: water is no data (-9999), its sea floor (band-coded in blocks) is dropped.
  raster.heights = std::move(block->heights);
  for (int16_t& sample : raster.heights) {
    if (terrain::isWater(sample)) sample = terrain::kNoDataHeight;
  }
  return rasters::writeGtopo30(outputStem, raster);
}

}  // namespace globe::tiling
