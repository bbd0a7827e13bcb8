#include "camera/terrain_glide.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "collision/surface_probe.hpp"
#include "geo/ecef.hpp"

namespace globe::camera {
namespace {

// The drawn surface's height under a point (0 m where no tile holds it, as QOTCD says). Not
// QOTCD's H ahead: on the coarse tiles far ahead a quad's highest vertex can stand hundreds of
// metres above the drawn surface and would lift the camera for nothing.
std::optional<double> groundUnder(const terrain::RenderingTileArray& array,
                                  const geo::Ellipsoid& ellipsoid, const geo::Cartographic& point) {
  const auto surface =
      collision::surfaceHeightAt(array, ellipsoid, point.longitudeRadians, point.latitudeRadians,
                                 collision::SurfaceModel::Exact);
  if (!surface) return std::nullopt;
  return surface->heightMeters;
}

bool isFinite(const geo::Cartographic& p) {
  return std::isfinite(p.longitudeRadians) && std::isfinite(p.latitudeRadians) &&
         std::isfinite(p.heightMeters);
}

// The critically damped spring x'' = omega^2 (target - x) - 2 omega x', integrated exactly over
// dt: stable for any dt, never overshooting the target.
void springTowards(double target, double omega, double dt, double& x, double& v) {
  const double c1 = x - target;
  const double c2 = v + omega * c1;
  const double decay = std::exp(-omega * dt);
  x = target + (c1 + c2 * dt) * decay;
  v = (c2 - omega * (c1 + c2 * dt)) * decay;
}

// The camera keeping its velocity: where it is at settings.samples times up to the look-ahead,
// stepped in longitude and latitude by the velocity's east and north parts (no iterative
// geodetic conversion per point: guidance needs metres, not millimetres, over a few km).
std::vector<GlidePoint> extrapolate(const geo::Ellipsoid& ellipsoid,
                                    const geo::Cartographic& proposed, const glm::dvec3& velocity,
                                    const GlideSettings& settings) {
  const double lat = proposed.latitudeRadians, lon = proposed.longitudeRadians;
  const glm::dvec3 east(-std::sin(lon), std::cos(lon), 0.0);
  const glm::dvec3 north(-std::sin(lat) * std::cos(lon), -std::sin(lat) * std::sin(lon),
                         std::cos(lat));
  const glm::dvec3 up = glm::cross(east, north);
  const double radius = ellipsoid.semiMajorAxisMeters + proposed.heightMeters;
  const double eastRate = glm::dot(velocity, east) / (radius * std::max(std::cos(lat), 1e-6));
  const double northRate = glm::dot(velocity, north) / radius;
  const double climb = glm::dot(velocity, up);
  std::vector<GlidePoint> points;
  const int samples = std::max(settings.samples, 1);
  for (int k = 1; k <= samples; ++k) {
    const double t = settings.lookAheadSeconds * k / samples;
    const double latitude =
        std::clamp(lat + northRate * t, -std::numbers::pi / 2, std::numbers::pi / 2);
    points.push_back({{std::remainder(lon + eastRate * t, 2 * std::numbers::pi), latitude,
                       proposed.heightMeters + climb * t},
                      t});
  }
  return points;
}

}  // namespace

GlideResult TerrainGlide::update(const terrain::RenderingTileArray& array,
                                 const geo::Ellipsoid& ellipsoid, const geo::Cartographic& proposed,
                                 const glm::dvec3& displacementEcefMeters,
                                 std::span<const GlidePoint> ahead, double dtSeconds,
                                 double eyeMeters) {
  GlideResult result;
  result.liftMeters = lift_;
  const glm::dvec3 velocity = displacementEcefMeters / dtSeconds;
  if (!(dtSeconds > 0.0) || !std::isfinite(dtSeconds) || !std::isfinite(glm::length(velocity)) ||
      !isFinite(proposed) || !std::isfinite(eyeMeters)) {
    return result;
  }
  const auto under = groundUnder(array, ellipsoid, proposed);
  if (!under) return result;
  const double speed = glm::length(velocity);
  const double margin = settings_.marginMeters + std::min(speed * settings_.speedMarginSeconds,
                                                          settings_.maximumMarginMeters);
  std::vector<GlidePoint> extrapolated;
  if (ahead.empty()) {
    extrapolated = extrapolate(ellipsoid, proposed, velocity, settings_);
    ahead = extrapolated;
  }
  result.hardLiftMeters = std::max(0.0, *under + eyeMeters - proposed.heightMeters);
  double target = *under + eyeMeters + margin - proposed.heightMeters;
  for (const GlidePoint& point : ahead) {
    const auto ground = groundUnder(array, ellipsoid, point.position);
    if (!ground || !isFinite(point.position) || !(point.secondsAhead >= 0.0)) continue;
    const double t = point.secondsAhead;
    const double climb = 0.25 * settings_.climbAccelerationMetersPerSecondSquared * t * t;
    target = std::max(target, *ground + eyeMeters + margin - point.position.heightMeters - climb);
  }
  result.samples = static_cast<int>(ahead.size()) + 1;
  result.targetLiftMeters = std::max(result.hardLiftMeters, target);
  springTowards(result.targetLiftMeters, 1.0 / settings_.settleSeconds, dtSeconds, lift_, rate_);
  if (lift_ < result.hardLiftMeters) {
    // The ground under the camera rose faster than the spring (a cliff the look-ahead could not
    // see, a finer tile): the floor is exact, at once; the spring goes on from there.
    lift_ = result.hardLiftMeters;
    rate_ = std::max(rate_, 0.0);
  }
  if (lift_ <= 0.0) {
    lift_ = 0.0;
    rate_ = std::max(rate_, 0.0);
  }
  result.liftMeters = lift_;
  return result;
}

}  // namespace globe::camera
