// The volume a tile can occupy (its rectangle times a height range), a precomputed conservative
// hull of it for culling, and horizon culling. Frustum culling is in frustum.hpp.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "geo/ellipsoid.hpp"
#include "geo/globe_rectangle.hpp"

namespace globe::geo {

// Deepest terrain anywhere on earth (Challenger Deep, ~-10,935 m) rounded down: horizon culling
// assumes nothing between the camera and a region is lower than this.
inline constexpr double kLowestTerrainHeightMeters = -11000.0;

struct BoundingRegion {
  GlobeRectangle rectangle;
  double minimumHeightMeters;
  double maximumHeightMeters;

  // Finite, west <= east within [-pi, pi], south <= north within [-pi/2, pi/2], and
  // -1e6 m <= minimum <= maximum height (so that the surfaces stay convex).
  bool isValid() const;
};

// A BoundingRegion prepared for repeated culling (build once per tile, reuse every frame).
// Holds ECEF points on a lattice over the rectangle at the minimum and maximum heights, and a
// margin: every point of the region lies within marginMeters of the convex hull of the points.
// The margin bounds the bulge of parallels and meridians between lattice points: for a convex
// arc turning by angle t with radius of curvature <= R, the arc stays within R (1 - cos(t/2))
// of its chord. Any linear test (planes, the horizon cone) on the points +- margin is therefore
// conservative for the whole region.
struct RegionVolume {
  BoundingRegion region;
  std::vector<glm::dvec3> pointsEcefMeters;
  double marginMeters = 0.0;
  // A sphere enclosing the whole region (margin included), for quick accept/reject.
  glm::dvec3 centerEcefMeters{0.0};
  double radiusMeters = 0.0;
  // Radius of the sphere that horizon culling treats as opaque (see isBelowHorizon).
  double occluderRadiusMeters = 0.0;
  // False for an invalid region: it is then never culled.
  bool bounded = false;

  static RegionVolume fromRegion(const BoundingRegion& region, const Ellipsoid& ellipsoid);
};

// True only if the whole region is hidden behind the globe as seen from the camera. The globe is
// modelled by a sphere of radius b + min(kLowestTerrainHeightMeters, region minimum height),
// which lies inside the solid earth; a point is hidden if the segment from the camera to it
// passes through that sphere. Conservative: each hull point must lie, by at least the margin,
// inside the part of the sphere's shadow cone beyond its horizon circle. A camera inside the
// occluding sphere (or non-finite) culls nothing.
bool isBelowHorizon(const glm::dvec3& cameraEcefMeters, const RegionVolume& volume);
bool isBelowHorizon(const glm::dvec3& cameraEcefMeters, const BoundingRegion& region,
                    const Ellipsoid& ellipsoid);

}  // namespace globe::geo
