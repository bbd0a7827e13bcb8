// The per-tile transform the renderer hands the GPU, made so that two tiles of one level compute
// bit-identical positions for the vertices they share (a watertight seam without skirts or
// overlap). A mesh's vertices lie on its level's quantum and its centre on a coarser one
// (tile_mesh.hpp: vertexQuantumMeters, originQuantumMeters), so its float offsets are exact; the
// eye rounded to the centre's quantum makes the centre's offset from it exact in float too, and
// the view matrix the same for the whole level. The GPU then forms origin + offset (one exact operand pair per vertex, correctly
// rounded: the same sum in every tile) and multiplies it by the same matrices.
#pragma once

#include <cstdint>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "terrain/render_view.hpp"

namespace globe::terrain {

struct TileTransform {
  glm::mat4 levelView{1.0f};  // view · translate(eye rounded to the level's quantum), from double
  glm::vec3 origin{0.0f};     // tile centre − that eye
  // origin is exact in float (within 2^24 quanta of the eye); when not, the tile is so far away
  // that its seams are below a pixel, and the renderer hangs its skirts anyway.
  bool exact = false;
};

TileTransform tileTransform(const RenderView& view, uint32_t level,
                            const glm::dvec3& centerEcefMeters);

}  // namespace globe::terrain
