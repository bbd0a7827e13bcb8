// Triangles covering a flat roof: a polygon with holes in a plane (metres east and north, say).
// A polygon without holes goes to overlays::triangulateRing; holes are first joined to the outer
// ring by bridges (each hole, rightmost first, to the nearest vertex it sees), then the one ring
// is ear-clipped. O(n²) and more: callers bound the vertex count (footprint_reader.hpp).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

namespace globe::buildings {

using PlaneRing = std::vector<glm::dvec2>;

// Indices into the rings' vertices taken in order (the outer ring's, then each hole's), three
// per triangle, counter-clockwise. `rings`: the outer ring first, then its holes, in any winding,
// none repeating its first vertex. Fewer triangles (down to none) where the rings are not simple.
std::vector<uint32_t> triangulatePolygon(std::span<const PlaneRing> rings);

// A ring's area, positive where it runs counter-clockwise (m²).
double signedAreaSquareMeters(const PlaneRing& ring);

// The area the rings enclose (outer minus holes, m²): what the triangles must cover.
double polygonAreaSquareMeters(std::span<const PlaneRing> rings);

}  // namespace globe::buildings
