#include "terrain/imagery_level.hpp"

#include <algorithm>
#include <cmath>

#include "terrain/screen_space_error.hpp"

namespace globe::terrain {

uint32_t imageryLevelFor(uint32_t terrainLevel, uint32_t verticesPerSide,
                         uint32_t imageryTileSizePixels, double maximumScreenSpaceErrorPixels,
                         uint32_t layerMaxLevel) {
  const double cells = verticesPerSide < 2 ? 1.0 : static_cast<double>(verticesPerSide - 1);
  const double sse =
      maximumScreenSpaceErrorPixels > 0 && std::isfinite(maximumScreenSpaceErrorPixels)
          ? maximumScreenSpaceErrorPixels
          : 2.0;
  // texel(k) <= error(L) / sse  <=>  2^(L-k) / size <= quality / (cells · sse)
  //                              <=>  k >= L + log2(cells · sse / (quality · size)).
  const double offset = std::ceil(
      std::log2(cells * sse / (kTerrainQuality * std::max<uint32_t>(imageryTileSizePixels, 1))) -
      1e-9);
  const double level = std::clamp(static_cast<double>(terrainLevel) + offset, 0.0,
                                  static_cast<double>(std::min(terrainLevel, layerMaxLevel)));
  return static_cast<uint32_t>(level);
}

geo::TileId ancestorAt(const geo::TileId& tile, uint32_t level) {
  if (level >= tile.level) return tile;
  const uint32_t shift = tile.level - level;
  return {level, tile.x >> shift, tile.y >> shift};
}

glm::vec4 uvTransformInAncestor(const geo::TileId& tile, const geo::TileId& ancestor) {
  const uint32_t shift = tile.level - std::min(ancestor.level, tile.level);
  const float scale = std::ldexp(1.0f, -static_cast<int>(shift));
  const uint32_t mask = (shift >= 32) ? ~0u : ((1u << shift) - 1u);
  return {static_cast<float>(tile.x & mask) * scale, static_cast<float>(tile.y & mask) * scale,
          scale, scale};
}

glm::vec4 edgeSampledTransform(const glm::vec4& transform, uint32_t tileSizePixels) {
  const float size = static_cast<float>(std::max<uint32_t>(tileSizePixels, 2));
  const float inner = (size - 1.0f) / size;
  return {0.5f / size + transform.x * inner, 0.5f / size + transform.y * inner, transform.z * inner,
          transform.w * inner};
}

}  // namespace globe::terrain
