// An imagery layer's colour at any longitude/latitude, as the viewer drapes it: bilinear among
// the layer's samples at a level (pixel centres or tile-edge samples, as its pixel grid says),
// taken from the deepest ancestor the layer has where that level's tile is absent (the layer
// stops there and the viewer draws the parent), or transparent for layers whose absent tiles
// are empty. Decoded tiles are kept in a small cache: callers sweep tile by tile.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <unordered_map>

#include "core/result.hpp"
#include "formats/image_io.hpp"
#include "geo/tile_id.hpp"
#include "streaming/imagery_tiles.hpp"

namespace globe::publish {

// Straight (not premultiplied) 8-bit RGBA.
using Rgba8 = std::array<uint8_t, 4>;

class LayerSampler {
 public:
  explicit LayerSampler(streaming::ImageryTiles& layer, size_t cachedTiles = 192);

  // Errors (a damaged pack, an undecodable tile) name the tile's file.
  Result<Rgba8> sample(double longitudeDegrees, double latitudeDegrees, uint32_t level);

 private:
  // Colour premultiplied by alpha (0..1), so that no-data never darkens what it blends with.
  struct Premultiplied {
    double red = 0, green = 0, blue = 0, alpha = 0;
  };
  Result<Premultiplied> bilinear(double longitudeDegrees, double latitudeDegrees, uint32_t level);
  Result<Premultiplied> tap(uint32_t level, int64_t column, int64_t row);
  // The tile decoded; nullptr where the layer has none.
  Result<const formats::ImageRgba*> image(const geo::TileId& tile);
  // The deepest of `tile` and its ancestors that the layer has.
  Result<std::optional<uint32_t>> presentLevel(const geo::TileId& tile);

  streaming::ImageryTiles& layer_;
  const uint32_t tileSizePixels_;
  const bool edgeSamples_;
  const size_t cachedTiles_;
  std::unordered_map<geo::TileId, std::optional<formats::ImageRgba>> images_;
  std::deque<geo::TileId> imageOrder_;  // oldest first, for eviction
  std::unordered_map<geo::TileId, std::optional<uint32_t>> presentLevels_;
  // The last tile looked up: most taps fall in the same tile as the one before.
  std::optional<geo::TileId> lastTile_;
  const formats::ImageRgba* lastImage_ = nullptr;
};

}  // namespace globe::publish
