// Swept collision tests along one frame's motion (the paper tests only where the camera ends):
// the path is sampled at a fraction of the vertex spacing under it, so no speed tunnels a ridge.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "collision/surface_probe.hpp"
#include "collision/terrain_array.hpp"
#include "geo/cartographic.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::collision {

// Sampling of a path. The step at a sample is spacingFraction times the vertex spacing of the
// tile under it (vertexSpacingMeters; 1 km over no tile), or, when larger, the sample's height
// above the highest surface of the array plus the clearance: geodetic height changes by at most
// the distance moved, so no point of such a step can reach any surface. Within a step the path is
// also probed where its ground track crosses a row or column line or a quad diagonal of the
// sample's tile: the drawn surface is planar between those crossings and the path nearly straight,
// so with the Exact model no ridge or crease is cut between probes (to within the chord's
// curvature, micrometres). Near a pole, where the columns converge, a step crossing more lines
// than are probed falls back to its samples. The Qotcd model's H is constant per quad, not per
// triangle; its sweep is as fine but lines are probed on them, not on both sides.
struct SweepSettings {
  double spacingFraction = 0.5;
  double minimumStepMeters = 0.01;
  uint32_t maximumSamples = 65536;  // a longer path gets proportionally longer steps
};

struct SegmentSweep {
  bool valid = false;  // false: a sample had no geodetic coordinates (non-finite input)
  bool hit = false;
  // The path is free on [0, freeFraction]; with a hit the contact is refined by bisection to
  // within 1 mm of the path beyond it.
  double freeFraction = 1.0;
  glm::dvec3 freeEcefMeters{0.0};  // the point at freeFraction
  geo::Cartographic contact{};     // hit: the first colliding point; its nadir is what was hit
  uint32_t samples = 0;
  uint32_t tilesExamined = 0;
};

// A straight segment (linear motion), collided where the point is below the model's surface +
// clearance (probeSurface). A start that already collides is a hit at fraction 0.
SegmentSweep sweepSegment(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                          const glm::dvec3& fromEcefMeters, const glm::dvec3& toEcefMeters,
                          double clearanceMeters, SurfaceModel model,
                          const SweepSettings& settings);

// The arc of an angular motion about the geocentre: the geodetic normal (the direction of the
// Oriented Ray) turns at a constant rate about n(from) x n(to) while the height goes linearly
// from from.heightMeters to to.heightMeters. t = 0 and t = 1 return from and to exactly.
geo::Cartographic arcPoint(const geo::Ellipsoid& ellipsoid, const geo::Cartographic& from,
                           const geo::Cartographic& to, double t);

struct ArcSweep {
  bool valid = false;
  // How far the camera must be raised (carried along the rest of the arc) so that every sample
  // of (0, 1] keeps the clearance: max(surface + clearance - height), 0 when the arc is free.
  double liftMeters = 0.0;
  geo::Cartographic deepest{};  // the sample that set the lift
  uint32_t samples = 0;
  uint32_t tilesExamined = 0;
};
ArcSweep sweepArc(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                  const geo::Cartographic& from, const geo::Cartographic& to,
                  double clearanceMeters, SurfaceModel model, const SweepSettings& settings);

}  // namespace globe::collision
