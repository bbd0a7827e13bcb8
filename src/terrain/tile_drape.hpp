// Which imagery textures a terrain tile is drawn with: up to kMaxDrapeLayers layers, bottom first,
// each an uploaded imagery tile (TerrainRenderer::uploadImageryTile) and a uv transform into it.
#pragma once

#include <array>
#include <cstdint>
#include <limits>

#include <glm/vec4.hpp>

#include "geo/tile_id.hpp"

namespace globe::terrain {

inline constexpr uint32_t kMaxDrapeLayers = 4;

struct TileDrape {
  uint32_t layer = 0;         // which layer (texture namespace), any small number
  geo::TileId imageryTile{};  // an uploaded imagery texture of that layer
  // imagery uv = xy + tile uv · zw; tile uv (0,0) is the terrain tile's north-west corner,
  // imagery uv (0,0) the imagery tile's (row 0 = v 0). A descendant terrain tile drawn with an
  // ancestor's imagery gets its sub-rectangle (e.g. the NE child of the imagery tile: 0.5, 0, 0.5,
  // 0.5).
  glm::vec4 uvTransform{0.0f, 0.0f, 1.0f, 1.0f};
  float opacity = 1.0f;  // multiplies the texel alpha
  float exposure = 1.0f;  // the photo's exposure curve (imagery_exposure.hpp): 1 none
  // A night-lights layer: drawn only where the Sun has set (added light, not lit, never covering
  // the layers below it).
  bool night = false;
  // The data's own resolutions: the layer's finest source texel where the tile is (its centre),
  // and the terrain's finest source step at the tile's corners (north-west, north-east,
  // south-west, south-east), in degrees. --lighting auto weighs the light by their ratio
  // (relief_shading.hpp), per corner, interpolated across the tile: it changes only where the
  // sources do, never from tile to tile with the levels drawn, and there over a tile rather than
  // at an edge. NaN: not known, the drawn tiles' texel and vertex spacing instead.
  double nativeTexelDegrees = std::numeric_limits<double>::quiet_NaN();
  std::array<double, 4> terrainStepDegrees{
      std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
      std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
};

// Per drawn terrain tile, bottom layer first; layers[count..] are ignored.
struct TileDrapes {
  std::array<TileDrape, kMaxDrapeLayers> layers{};
  uint32_t count = 0;
  // A water-mask layer's tile (formats::LayerKind::WaterMask), when one is given: not drawn as
  // colour, it decides land and water per fragment where the terrain's sources are coarser
  // (water_mask_weight.hpp); its opacity scales that weight.
  TileDrape waterMask{};
  bool hasWaterMask = false;
};

}  // namespace globe::terrain
