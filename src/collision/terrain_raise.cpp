// Hard floor at once, exponential approach with a maximum rate above it.
#include "collision/terrain_raise.hpp"

#include <algorithm>
#include <cmath>

#include "collision/collision_response.hpp"

namespace globe::collision {

RaiseResult raiseForNewTerrain(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                               const geo::Cartographic& position, double dtSeconds,
                               const ClearanceSettings& clearance, SurfaceModel model) {
  RaiseResult result;
  result.position = position;
  if (!std::isfinite(position.heightMeters)) return result;
  const auto surface =
      surfaceHeightAt(array, ellipsoid, position.longitudeRadians, position.latitudeRadians, model);
  if (!surface) return result;
  result.valid = true;
  result.surfaceHeightMeters = surface->heightMeters;
  const double desired = surface->heightMeters + clearance.eyeMeters;
  const double floor = surface->heightMeters + clearance.minimumEyeMeters;
  double height = position.heightMeters;
  if (height >= desired - kContactSkinMeters) return result;
  if (height < floor) {
    height = floor;
    result.floorApplied = true;
  }
  const double dt = std::isfinite(dtSeconds) ? std::max(dtSeconds, 0.0) : 0.0;
  const double gap = desired - height;
  if (gap > 0.0 && dt > 0.0) {
    const double tau = std::max(clearance.raiseTimeConstantSeconds, 1e-9);
    const double step = std::min((1.0 - std::exp(-dt / tau)) * gap,
                                 std::max(clearance.maxRaiseRateMetersPerSecond, 0.0) * dt);
    height = gap - step <= kContactSkinMeters ? desired : height + step;
  }
  result.raised = height != position.heightMeters;
  result.position.heightMeters = height;
  result.remainingMeters = std::max(desired - height, 0.0);
  return result;
}

}  // namespace globe::collision
