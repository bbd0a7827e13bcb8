// Terrain shadows from the real Sun, on the CPU and against the surface collision reads: from a
// point on the drawn ground a ray is marched towards the Sun over the rendering tile array
// (surfaceHeightAt, the exact drawn surface, O(1) a step), and the lowest angle between the ray
// and the ground it passes over says how much of the Sun's disc (0.53°) shows: 1 in full sun, 0
// in a mountain's shadow, in between across the penumbra. The same ground for drawing, shadows and
// collision, deterministic on any GL. Only the tiles of the array cast shadows (those the frame
// holds): a ridge outside the view casts none into it.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "collision/terrain_array.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::collision {

// The Sun's angular radius (radians): the penumbra spans twice this.
inline constexpr double kSunAngularRadiusRadians = 0.00466;
// How far rays are marched (metres): a 9 km peak's shadow at a 2.5° Sun reaches ~200 km.
inline constexpr double kShadowReachMeters = 200000.0;

// 0..1 of the Sun's disc seen from `pointEcefMeters` (on the ground) over the array; 1 where the
// Sun is below the point's horizon plane (the night's darkness is the shader's, not a shadow's).
// The march starts `firstStepMeters` out and steps by the larger of that and 4 % of the distance;
// it ends above `highestMeters` (the array's highest surface) or at kShadowReachMeters.
float sunVisibility(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                    const glm::dvec3& pointEcefMeters, const glm::dvec3& sunDirectionEcef,
                    double firstStepMeters, double highestMeters);

// sunVisibility at every grid vertex of `tile` (row-major, N×N), at the tile's drawn heights, in
// steps of half its smaller cell side.
std::vector<float> tileSunVisibility(const ArrayTile& tile, const RenderingTileArray& array,
                                     const geo::Ellipsoid& ellipsoid,
                                     const glm::dvec3& sunDirectionEcef);

}  // namespace globe::collision
