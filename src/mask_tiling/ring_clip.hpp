// Polygon rings in longitude/latitude and their clipping to a tile's rectangle (Sutherland–
// Hodgman, one side at a time). A land mask is the even-odd fill of every ring (holes, lakes and
// islands in lakes included), so each ring is clipped alone: inside the rectangle the clipped
// ring encloses exactly what the ring did. Where a ring runs outside, the clipped one runs along
// the rectangle's sides, twice in opposite directions where it leaves and comes back, which adds
// nothing to an even-odd fill.
#pragma once

#include <vector>

#include <glm/vec2.hpp>

namespace globe::mask_tiling {

// x = longitude, y = latitude, degrees; the closing vertex is not repeated.
using Ring = std::vector<glm::dvec2>;

struct RectangleDegrees {
  double west = 0, south = 0, east = 0, north = 0;
  bool intersects(const RectangleDegrees& other) const {
    return west <= other.east && other.west <= east && south <= other.north && other.south <= north;
  }
  bool contains(double longitude, double latitude) const {
    return longitude >= west && longitude <= east && latitude >= south && latitude <= north;
  }
};

RectangleDegrees boundsOf(const Ring& ring);

// The ring clipped to the rectangle; empty when nothing of it is left.
Ring clipRing(const Ring& ring, const RectangleDegrees& rectangle);

// Whether the clipped ring only runs along the rectangle's sides (every edge on one side): it
// then fills the whole rectangle or none of it, and does not make a tile's mask vary.
bool runsAlongSides(const Ring& clipped, const RectangleDegrees& rectangle);

}  // namespace globe::mask_tiling
