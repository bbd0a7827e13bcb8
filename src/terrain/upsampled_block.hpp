// Terrain tiles beyond the pyramid's finest data, made from their parent's surface. Where an
// imagery layer is finer than the terrain, the terrain refines so that the imagery can (as
// CesiumJS's upsampled terrain tiles do), with exactly the parent's heights.
#pragma once

#include "geo/ellipsoid.hpp"
#include "geo/tile_id.hpp"
#include "terrain/height_block.hpp"

namespace globe::terrain {

// The block of `child` (level >= 1) from its parent's block. Every vertex of the child lies at a
// vertex of the parent, or halfway along an edge of the parent's triangles (a row, a column, or
// the north-west to south-east diagonal of tile_mesh.hpp's rule), and takes the height at which
// the ellipsoid normal there meets that triangle's plane: the exact surface that collision reads
// (collision/exact_surface.hpp), not the mean of the edge's ends, which would lift the surface by
// the chord's sag (metres under 20 km cells). The child's triangles, split by the same rule, lie
// on the parent's planes but for the slivers where a normal meets an edge's other triangle: the
// same surface for drawing and collision alike, to 0.5 m on 39 km cells with 40 % slopes and
// 0.03 mm at level 11 (tests/collision/test_upsampled_surface.cpp measures it). The
// apron is made the same way from the parent's apron (none when the parent has none), so two
// children of neighbouring parents compute the same heights for their shared edge.
// - exactSurfaceMeters (and exactApronSurfaceMeters) hold those heights;
// - `heights` (and `apron`) hold samples (for the water flag of queries): the mean of the two
//   ends where both are land (rounded) or both water (floors averaged), else the first end's
//   (north-west), so neighbours agree;
// - shadingNormals, colorMeters and waterFraction shade it as the parent's triangles shade that
//   ground: the parent mesh's vertex values, the mean of the two ends along an edge.
// - a parent with a TIN gives its child the TIN's quadrant (tin_clip.hpp), which it then draws.
// The parent's block size must be valid (isValidBlockSize) and its samples complete.
HeightBlock upsampleBlock(const HeightBlock& parent, const geo::TileId& child,
                          const geo::Ellipsoid& ellipsoid);

}  // namespace globe::terrain
