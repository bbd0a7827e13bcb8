// Where the viewer's, the query's and collision's terrain comes from: a pack pyramid on disk or
// a server (streaming/tile_store.hpp), or a standard terrain service resampled into the same
// blocks as they load (src/services: quantized-mesh, heightmap-1.0, Terrarium, Terrain-RGB).
// Everything above reads terrain through this, so a new kind of source is one new class.
#pragma once

#include <optional>
#include <string>

#include "core/result.hpp"
#include "formats/pack_format.hpp"
#include "formats/pyramid_manifest.hpp"
#include "geo/tile_id.hpp"
#include "streaming/tile_source.hpp"
#include "terrain/height_block.hpp"
#include "terrain/tile_catalog.hpp"

namespace globe::streaming {

class TerrainSource : public TileSource<terrain::HeightBlock> {
 public:
  // Levels, block size, sources and their steps (native resolution), as a pyramid's manifest
  // says them; a service's is made from what it publishes.
  virtual const formats::PyramidManifest& manifest() const = 0;
  // The directory, URL or service.
  virtual const std::string& location() const = 0;
  using TileSource<terrain::HeightBlock>::location;
  virtual bool remote() const = 0;
  virtual terrain::SeaSurface sea() const = 0;
  // Who the data is from, to show beside the picture; empty when it does not say.
  virtual std::string attribution() const { return {}; }
  // Whether what holds the tile (a pack) failed to open: peek() and summary() then answer as if
  // the tile were absent, so that its parent is drawn; a view that needed it is missing it.
  virtual bool failedAt(const geo::TileId& /*tile*/) { return false; }

  // For a render thread that must not wait on a server: the tile's summary without any I/O.
  // NotOpen: an index must be read first (summary() on a worker does).
  enum class Peek { Absent, Present, NotOpen };
  virtual Peek peek(const geo::TileId& tile, terrain::TileSummary* summary) = 0;
  // The tile's summary, reading what it needs; nullopt when the source has no such tile.
  virtual Result<std::optional<terrain::TileSummary>> summary(const geo::TileId& tile) = 0;
  // Tiles whose summaries one read brings (a pack): background reads are queued once per group.
  virtual formats::PackId summaryGroupOf(const geo::TileId& tile) const {
    return formats::packOf(tile, manifest().packTilesPerSide);
  }
  // The block of a tile summary() says exists (errors name the file or URL).
  virtual Result<terrain::HeightBlock> loadBlock(const geo::TileId& tile) = 0;
};

}  // namespace globe::streaming
