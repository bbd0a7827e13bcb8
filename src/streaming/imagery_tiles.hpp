// Where an imagery layer's tiles come from: a layer of image packs made by globe-tiler
// (streaming/imagery_store.hpp), or a standard tile service reprojected onto the quadtree as its
// tiles load (src/services: XYZ, TMS, WMTS, PMTiles). The scene's layers read through this.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "formats/image_io.hpp"
#include "formats/layer_manifest.hpp"
#include "formats/pack_format.hpp"
#include "geo/tile_id.hpp"

namespace globe::streaming {

class ImageryTiles {
 public:
  virtual ~ImageryTiles() = default;
  // Tile size, pixel grid, levels, sources and their texel sizes.
  virtual const formats::LayerManifest& manifest() const = 0;
  // The layer's directory, URL or service.
  virtual const std::string& location() const = 0;
  virtual bool remote() const = 0;
  // Who the imagery is from, to show beside the picture; empty when it does not say.
  virtual std::string attribution() const { return {}; }

  // Whether a tile the layer lacks is empty (nothing to draw there) rather than not made at that
  // level (draw the ancestor's): the overlays' draped layer, whose untouched tiles are clear.
  virtual bool emptyWhereAbsent() const { return false; }

  // Whether the layer has this tile (may read an index). Thread-safe.
  virtual Result<bool> hasTile(const geo::TileId& tile) = 0;
  // The same without any I/O, for a render thread; NotOpen: hasTile (on a worker) must read an
  // index first.
  enum class Peek { Absent, Present, NotOpen };
  virtual Peek peekTile(const geo::TileId& tile) = 0;
  // Tiles whose presence one read brings (a pack): background reads are queued once per group.
  virtual formats::PackId tileGroupOf(const geo::TileId& tile) const {
    return formats::packOf(tile, manifest().packTilesPerSide);
  }
  // The tile decoded to RGBA8 at the layer's tile size; nullopt when the layer has no such tile.
  virtual Result<std::optional<formats::ImageRgba>> loadImage(const geo::TileId& tile) = 0;
  // The file or URL a tile comes from, for messages.
  virtual std::string tileLocation(const geo::TileId& tile) const = 0;
  // Problems with a whole file or server, each once since the last call.
  virtual std::vector<std::string> takeNewSourceErrors() { return {}; }
  // Lets what failed be tried again.
  virtual void forgetSourceFailures() {}
};

}  // namespace globe::streaming
