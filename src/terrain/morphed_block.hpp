// A block on its way from one surface to another. Where a finer tile arrives in place of the
// coarser one drawn there, the viewer draws (and collides with) the finer block rising out of
// the coarser surface over a few frames, so a camera standing on it is lifted with the ground
// instead of popping up in one frame (scene/tile_morphs.hpp).
#pragma once

#include "terrain/height_block.hpp"

namespace globe::terrain {

// The surface `fraction` of the way from `from` to `to` (0: from's surface, 1: to's), both
// blocks of the same tile and size (`from` is typically the coarser surface, upsampleBlock'ed
// to this tile). The samples, the sea surface and the apron samples are to's (water stays
// water); exactSurfaceMeters holds the blended heights, and exactApronSurfaceMeters the blended
// apron where both blocks have one (else to's apron is read as it is). No shading fields: the
// mesh shades the blended surface itself. fraction is clamped to [0, 1]; NaN counts as 1.
HeightBlock morphBlock(const HeightBlock& from, const HeightBlock& to, double fraction);

}  // namespace globe::terrain
