#include "terrain/skirt_edges.hpp"

#include "geo/tiling_scheme.hpp"

namespace globe::terrain {

std::optional<geo::TileId> sameLevelNeighbour(const geo::TileId& tile, TileEdge edge) {
  const uint32_t columns = geo::GeographicTilingScheme::tilesX(tile.level);
  const uint32_t rows = geo::GeographicTilingScheme::tilesY(tile.level);
  switch (edge) {
    case TileEdge::North:
      if (tile.y == 0) return std::nullopt;
      return geo::TileId{tile.level, tile.x, tile.y - 1};
    case TileEdge::South:
      if (tile.y + 1 >= rows) return std::nullopt;
      return geo::TileId{tile.level, tile.x, tile.y + 1};
    case TileEdge::West:
      return geo::TileId{tile.level, tile.x == 0 ? columns - 1 : tile.x - 1, tile.y};
    case TileEdge::East:
      return geo::TileId{tile.level, tile.x + 1 == columns ? 0 : tile.x + 1, tile.y};
  }
  return std::nullopt;
}

SkirtEdgeMask neededSkirtEdges(const geo::TileId& tile,
                               const std::unordered_set<geo::TileId>& drawn) {
  SkirtEdgeMask mask = 0;
  for (uint32_t edge = 0; edge < 4; ++edge) {
    const auto neighbour = sameLevelNeighbour(tile, static_cast<TileEdge>(edge));
    if (!neighbour || !drawn.contains(*neighbour)) mask |= SkirtEdgeMask{1} << edge;
  }
  return mask;
}

SkirtEdgeMask mismatchedEdges(const geo::TileId& tile, const EdgeHeightHashes& own,
                              const DrawnEdgeHashes& hashesOf) {
  // The neighbour's edge facing each of ours: North↔South, West↔East.
  static constexpr uint32_t kFacing[4] = {1, 0, 3, 2};
  SkirtEdgeMask mask = 0;
  for (uint32_t edge = 0; edge < 4; ++edge) {
    const auto neighbour = sameLevelNeighbour(tile, static_cast<TileEdge>(edge));
    if (!neighbour) continue;
    const EdgeHeightHashes* theirs = hashesOf(*neighbour);
    if (theirs != nullptr && (*theirs)[kFacing[edge]] != own[edge]) {
      mask |= SkirtEdgeMask{1} << edge;
    }
  }
  return mask;
}

SkirtEdgeMask coarserNeighbourEdges(const geo::TileId& tile,
                                    const std::unordered_set<geo::TileId>& drawn) {
  SkirtEdgeMask mask = 0;
  for (uint32_t edge = 0; edge < 4; ++edge) {
    const auto neighbour = sameLevelNeighbour(tile, static_cast<TileEdge>(edge));
    if (!neighbour || drawn.contains(*neighbour)) continue;
    for (geo::TileId up = *neighbour; up.level > 0;) {
      up = up.parent();
      if (drawn.contains(up)) {
        mask |= SkirtEdgeMask{1} << edge;
        break;
      }
    }
  }
  return mask;
}

uint32_t skirtedIndexRanges(uint32_t verticesPerSide, SkirtEdgeMask edges,
                            std::span<IndexRange, 3> out) {
  if (verticesPerSide < 2) return 0;
  const uint32_t cells = verticesPerSide - 1;
  const uint32_t gridCount = cells * cells * 6;
  const uint32_t edgeCount = cells * 6;
  uint32_t used = 0;
  out[used++] = {0, gridCount};
  for (uint32_t edge = 0; edge < 4; ++edge) {
    if ((edges & (SkirtEdgeMask{1} << edge)) == 0) continue;
    const uint32_t first = gridCount + edge * edgeCount;
    IndexRange& last = out[used - 1];
    if (last.first + last.count == first) {
      last.count += edgeCount;
    } else {
      out[used++] = {first, edgeCount};
    }
  }
  return used;
}

}  // namespace globe::terrain
