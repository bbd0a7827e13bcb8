#include "collision/sun_visibility.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "collision/surface_probe.hpp"
#include "geo/ecef.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/tile_mesh.hpp"

namespace globe::collision {
namespace {

// Steps grow with the distance (the angle a missed bump could hide shrinks with it).
constexpr double kStepGrowth = 0.04;
// Above the drawn vertex, so that its own triangles do not shade it.
constexpr double kLiftMeters = 0.5;

}  // namespace

float sunVisibility(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                    const glm::dvec3& pointEcefMeters, const glm::dvec3& sunDirectionEcef,
                    double firstStepMeters, double highestMeters) {
  const glm::dvec3 up = glm::normalize(pointEcefMeters);
  if (glm::dot(up, sunDirectionEcef) <= 0.0) return 1.0f;
  double lowestAngle = kSunAngularRadiusRadians;  // above this: the whole disc shows
  const double step = std::max(firstStepMeters, 1.0);
  for (double d = step; d <= kShadowReachMeters; d += std::max(step, kStepGrowth * d)) {
    const auto at = geo::ecefToCartographic(ellipsoid, pointEcefMeters + d * sunDirectionEcef);
    if (!at || at->heightMeters > highestMeters) break;
    const auto ground = surfaceHeightAt(array, ellipsoid, at->longitudeRadians,
                                        at->latitudeRadians, SurfaceModel::Exact);
    if (!ground) break;
    lowestAngle = std::min(lowestAngle, (at->heightMeters - ground->heightMeters) / d);
    if (lowestAngle <= -kSunAngularRadiusRadians) return 0.0f;
  }
  return static_cast<float>(
      std::clamp(0.5 + 0.5 * lowestAngle / kSunAngularRadiusRadians, 0.0, 1.0));
}

std::vector<float> tileSunVisibility(const ArrayTile& tile, const RenderingTileArray& array,
                                     const geo::Ellipsoid& ellipsoid,
                                     const glm::dvec3& sunDirectionEcef) {
  if (!hasReadableBlock(tile)) return {};
  const terrain::HeightBlock& block = *tile.block;
  const uint32_t n = block.verticesPerSide;
  const terrain::BlockGrid grid{tile.id, n};
  // Half the tile's smaller cell side (along a parallel, cos(latitude) of the meridian's): a
  // ridge one vertex wide is not stepped over.
  const double middleLatitude = 0.5 * (tile.southRadians + tile.northRadians);
  const double step =
      0.5 * vertexSpacingMeters(tile, ellipsoid) * std::max(std::cos(middleLatitude), 0.05);
  const double highest = maximumSurfaceHeightMeters(array);
  std::vector<float> visibility(static_cast<size_t>(n) * n, 1.0f);
  for (uint32_t i = 0; i < n; ++i) {
    for (uint32_t j = 0; j < n; ++j) {
      const double height = block.surfaceHeightMetersAt(i, j) + kLiftMeters;
      const glm::dvec3 point = terrain::tileVertexEcefMeters(ellipsoid, grid, i, j, height);
      visibility[static_cast<size_t>(i) * n + j] =
          sunVisibility(array, ellipsoid, point, sunDirectionEcef, step, highest);
    }
  }
  return visibility;
}

}  // namespace globe::collision
