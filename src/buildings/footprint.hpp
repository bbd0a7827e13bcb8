// A building footprint as read from a vector file: its rings in longitude/latitude degrees (the
// outer ring first, then its holes; none repeats its first point at the end) and the height of
// its roof above the ground (m).
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

namespace globe::buildings {

using RingDegrees = std::vector<glm::dvec2>;  // x: longitude, y: latitude

struct Footprint {
  std::vector<RingDegrees> rings;  // outer first, then holes
  double heightMeters = 0;         // roof above the ground under it
  std::string name;                // "FILE: layer L: feature F", for messages
};

// West, south, east, north of a footprint's outer ring (degrees).
struct ExtentDegrees {
  double west = 0, south = 0, east = 0, north = 0;
  bool contains(const ExtentDegrees& other) const {
    return other.west >= west && other.east <= east && other.south >= south && other.north <= north;
  }
};

inline ExtentDegrees extentOf(const Footprint& footprint) {
  ExtentDegrees e{1e300, 1e300, -1e300, -1e300};
  for (const glm::dvec2& p : footprint.rings.front()) {
    e.west = std::min(e.west, p.x), e.east = std::max(e.east, p.x);
    e.south = std::min(e.south, p.y), e.north = std::max(e.north, p.y);
  }
  return e;
}

}  // namespace globe::buildings
