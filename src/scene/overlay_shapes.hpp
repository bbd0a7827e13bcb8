// The overlays' parts that are not on the ground, in ECEF for this frame: lines and polygon
// outlines at an altitude (KML absolute, relativeToGround), the walls `extrude` drops from them
// to the ground, and a raised point's stalk. Heights relative to the ground and the walls' feet
// follow the surface this frame draws (the rendering tile array), as clamped points do.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "geo/ellipsoid.hpp"
#include "overlays/overlay_model.hpp"
#include "terrain/rendering_tile_array.hpp"

namespace globe::scene {

struct OverlayLine3d {
  std::vector<glm::dvec3> ecefMeters;
  overlays::Rgba color;
  double widthPixels = 1;
};

struct OverlayTriangles3d {
  std::vector<glm::dvec3> ecefMeters;  // three per triangle
  overlays::Rgba color;
};

struct OverlayShapes3d {
  std::vector<OverlayLine3d> lines;
  std::vector<OverlayTriangles3d> triangles;
  bool empty() const { return lines.empty() && triangles.empty(); }
};

// Whether any visible placemark has something drawn in 3D (so callers can skip the work).
bool hasShapes3d(std::span<const std::shared_ptr<const overlays::OverlayDocument>> documents);

// Where the array does not hold the ground under a vertex (off screen), the ground is taken as
// 0 m: such a vertex is not seen this frame.
OverlayShapes3d overlayShapes3d(
    std::span<const std::shared_ptr<const overlays::OverlayDocument>> documents,
    const terrain::RenderingTileArray& array, const geo::Ellipsoid& ellipsoid);

}  // namespace globe::scene
