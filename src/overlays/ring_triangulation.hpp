// Triangles covering a simple polygon ring (ear clipping), for a KML polygon's top face at an
// altitude: the draped ones are filled by the tile raster instead.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

namespace globe::overlays {

// Indices into `ring` (not repeating its first point at the end), three per triangle, covering
// it when it is simple (no self-crossing), in either winding; O(n²). Fewer triangles (down to
// none) when it is not simple or degenerate.
std::vector<size_t> triangulateRing(std::span<const glm::dvec2> ring);

}  // namespace globe::overlays
