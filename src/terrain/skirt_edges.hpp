// Which skirts a drawn tile needs: the edges where the neighbour is not drawn at the same level,
// and those where it is but draws the shared edge at other heights (edge_heights.hpp: a tile made
// from its parent's surface beside one read from the pyramid, or one morphing). Two tiles of one
// level with the same edge heights draw the same edge vertices, bit-identical on the GPU
// (tile_transform.hpp), so no crack opens between them. Skirt triangles cost llvmpipe as much as
// grid triangles (vertex shading and set-up run on one thread), so drawing only the needed ones
// matters.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <unordered_set>

#include "geo/tile_id.hpp"
#include "terrain/edge_heights.hpp"
#include "terrain/tile_mesh.hpp"

namespace globe::terrain {

// Bit (1 << TileEdge) set: that edge needs its skirt.
using SkirtEdgeMask = uint32_t;
constexpr SkirtEdgeMask kAllSkirtEdges = 0xF;

// The tile across `edge` at the same level: longitude wraps at ±180°; none beyond the poles.
std::optional<geo::TileId> sameLevelNeighbour(const geo::TileId& tile, TileEdge edge);

// The edges of `tile` whose same-level neighbour is not in `drawn`.
SkirtEdgeMask neededSkirtEdges(const geo::TileId& tile,
                               const std::unordered_set<geo::TileId>& drawn);

// The edges of `tile` whose same-level neighbour is drawn with a different hash for the shared
// edge than `own` (the tile's EdgeHeightHashes). hashesOf(neighbour): its hashes, or nullptr
// when it is not drawn.
using DrawnEdgeHashes = std::function<const EdgeHeightHashes*(const geo::TileId&)>;
SkirtEdgeMask mismatchedEdges(const geo::TileId& tile, const EdgeHeightHashes& own,
                              const DrawnEdgeHashes& hashesOf);

// The edges of `tile` whose neighbour is drawn coarser: the same-level neighbour is not in
// `drawn` but one of its ancestors is. Lit with its coarse normals there (tile_mesh.hpp), the
// tile's edge shades like that neighbour's.
SkirtEdgeMask coarserNeighbourEdges(const geo::TileId& tile,
                                    const std::unordered_set<geo::TileId>& drawn);

// One index range of the shared index buffer (in indices, not bytes).
struct IndexRange {
  uint32_t first = 0;
  uint32_t count = 0;
};

// The index ranges to draw for a tile with the given skirt edges, in buildGridIndices' layout
// (grid, then the N, S, W, E skirts), adjacent ranges merged: at most 3 (grid, S, E). Returns how
// many of `out` it filled.
uint32_t skirtedIndexRanges(uint32_t verticesPerSide, SkirtEdgeMask edges,
                            std::span<IndexRange, 3> out);

}  // namespace globe::terrain
