// Which imagery tile drapes a terrain tile, and where the terrain tile lies inside it. Both
// pyramids share the geographic quadtree, so a terrain tile lies inside exactly one imagery tile
// of each level at or above its own.
#pragma once

#include <cstdint>

#include <glm/vec4.hpp>

#include "geo/tile_id.hpp"

namespace globe::terrain {

// CesiumJS's rule (ImageryLayer._createTileImagerySkeletons): the coarsest imagery level whose
// texel spacing is no larger than the terrain tile's geometric error divided by the maximum
// screen-space error, so that where the terrain's error shows as maximumScreenSpaceErrorPixels,
// one texel shows as at most one pixel. The texel is (tile width) / imageryTileSizePixels and the
// error kTerrainQuality x (tile width) / (verticesPerSide - 1) at the same level (both at the
// equator), so the answer depends on the level only: with 17 vertices, 256-pixel imagery and
// 2 pixels it is terrainLevel - 1. Clamped to [0, min(terrainLevel, layerMaxLevel)]: one imagery
// tile per terrain tile.
uint32_t imageryLevelFor(uint32_t terrainLevel, uint32_t verticesPerSide,
                         uint32_t imageryTileSizePixels, double maximumScreenSpaceErrorPixels,
                         uint32_t layerMaxLevel);

// The tile's ancestor at `level` (the tile itself at its own level); level must be <= tile.level.
geo::TileId ancestorAt(const geo::TileId& tile, uint32_t level);

// Where `tile` lies inside `ancestor` (tile itself or one of its ancestors) in the ancestor's
// texture coordinates (u east, v south, (0,0) at the north-west corner): imagery uv = xy + tile
// uv · zw. Exact in float: offsets and scales are multiples of powers of two.
glm::vec4 uvTransformInAncestor(const geo::TileId& tile, const geo::TileId& ancestor);

// The same transform for a texture whose pixels are samples at the tile's edges
// (formats::ImageryPixelGrid::Edges): imagery uv u lies at texture coordinate
// (0.5 + u·(S−1)) / S, between the first and the last texel's centres, so the tile's edge is
// drawn from its edge samples, which the neighbour's texture has too.
glm::vec4 edgeSampledTransform(const glm::vec4& transform, uint32_t tileSizePixels);

}  // namespace globe::terrain
