// What a scene asks of a GPU: keep a mesh per terrain tile and a texture per imagery tile, and
// let them go. The scene decides what exists there; drawing is the caller's (the GL renderer's
// draw takes the scene's view, tiles and drapes). Implemented over the GL renderer by the app
// and, with no GL at all, by BookkeepingGpu.
#pragma once

#include <cstdint>
#include <span>

#include "core/result.hpp"
#include "geo/tile_id.hpp"
#include "terrain/tile_mesh.hpp"

namespace globe::scene {

class TileGpu {
 public:
  virtual ~TileGpu() = default;

  // Terrain meshes: prepare uploads (or replaces) one; release frees it (false: was not there).
  virtual bool hasTile(const geo::TileId& tile) const = 0;
  virtual Result<void> prepareTile(const geo::TileId& tile, const terrain::TileMesh& mesh) = 0;
  virtual bool releaseTile(const geo::TileId& tile) = 0;
  // Shadows (collision/sun_visibility.hpp) for a prepared tile: N² values, row-major. A GPU
  // that draws no shadows keeps the default.
  virtual Result<void> prepareTileSunlight(const geo::TileId& /*tile*/,
                                           std::span<const float> /*gridVisibility*/) {
    return {};
  }

  // Imagery textures per layer: RGBA8, straight alpha, rows top-down (north first).
  virtual bool hasImageryTile(uint32_t layer, const geo::TileId& tile) const = 0;
  virtual Result<void> prepareImageryTile(uint32_t layer, const geo::TileId& tile,
                                          std::span<const uint8_t> rgba, int widthPixels,
                                          int heightPixels) = 0;
  virtual bool releaseImageryTile(uint32_t layer, const geo::TileId& tile) = 0;
  // Bytes of imagery textures held, mip chains included: what the imagery budget bounds.
  virtual uint64_t imageryBytesResident() const = 0;
};

}  // namespace globe::scene
