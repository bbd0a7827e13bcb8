// Clearance in every direction, not only downwards: the eye's distance to the nearest drawn
// triangle. The vertical tests (QOTCD, the exact surface, the near plane's corners) keep the eye
// and the corners above the surface, but beside a steep wall "2 m above" is a few centimetres
// away from it, and the near plane (~0.6 m ahead) cuts into the wall. A ball around the eye that
// holds the whole near-plane rectangle, kept free of drawn triangles, keeps both out.
#pragma once

#include <optional>

#include <glm/vec3.hpp>

#include "collision/terrain_array.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::collision {

struct NearestTriangle {
  double distanceMeters = 0.0;  // from the eye to the nearest point of a drawn triangle
  glm::dvec3 awayEcef{0.0};     // unit direction from that point to the eye
  int trianglesTested = 0;
};

// The nearest point of the drawn mesh (the tiles' grid triangles as tile_mesh.hpp builds them,
// the same surface as the exact model) within radiusMeters of the eye, over every tile of the
// array the ball's footprint touches; nullopt when none is that near (or on invalid input).
std::optional<NearestTriangle> nearestDrawnTriangle(const RenderingTileArray& array,
                                                    const geo::Ellipsoid& ellipsoid,
                                                    const glm::dvec3& eyeEcefMeters,
                                                    double radiusMeters);

struct LateralPush {
  bool valid = false;
  glm::dvec3 eyeEcefMeters{0.0};  // after the push
  double pushMeters = 0.0;        // how far it moved (0: the ball was free)
  int trianglesTested = 0;
};

// Moves the eye straight away from the nearest drawn triangle until none is nearer than
// radiusMeters (plus 1 mm), re-testing after each step, at most 4 steps.
LateralPush pushAwayFromTerrain(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                                const glm::dvec3& eyeEcefMeters, double radiusMeters);

}  // namespace globe::collision
