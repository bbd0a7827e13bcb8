// Double-click "fly to": the ray through a window pixel, where it first meets the terrain, and the
// ~1 s animation that takes the camera there. Pure math; the caller supplies the terrain height.
#pragma once

#include <functional>
#include <optional>

#include <glm/vec3.hpp>

#include "camera/camera_pose.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::camera {

// The unit ECEF direction through window pixel (x, y) (y down, pixel centres at +0.5) of a view
// `widthPixels` x `heightPixels` with this vertical field of view.
glm::dvec3 pixelRayEcef(const CameraFrame& frame, double xPixels, double yPixels, int widthPixels,
                        int heightPixels, double fovYRadians);

// The terrain height (metres above the ellipsoid) at a longitude and latitude (radians);
// nullopt where unknown (then the ellipsoid, 0 m, is used).
using TerrainHeightFunction = std::function<std::optional<double>(double, double)>;

// The first point where the ray from `originEcefMeters` along the unit `direction` meets the
// terrain: marched in steps of a fraction of the height above the terrain, then bisected to
// `toleranceMeters`. nullopt when it misses the globe (passes the horizon going up).
std::optional<glm::dvec3> intersectTerrain(const geo::Ellipsoid& ellipsoid,
                                           const glm::dvec3& originEcefMeters,
                                           const glm::dvec3& direction,
                                           const TerrainHeightFunction& terrainHeight,
                                           double toleranceMeters = 0.01);

// Where a fly to `targetEcefMeters` ends: `distanceFraction` of the way's length short of the
// target (at least minimumDistanceMeters from it), looking at it with the current heading and
// the pitch at most maximumPitchRadians (down), so it is at the centre of the view.
struct FlyToSettings {
  double distanceFraction = 0.3;
  double minimumDistanceMeters = 50.0;
  double maximumPitchRadians = geo::degreesToRadians(-20);
  double durationSeconds = 1.0;
};
CameraPose flyToEndPose(const geo::Ellipsoid& ellipsoid, const CameraPose& from,
                        const glm::dvec3& targetEcefMeters, const FlyToSettings& settings = {});

// The animation from one pose to another: smooth start and stop, longitude and heading the short
// way round, height interpolated logarithmically with a hop for long ways.
class FlyToAnimation {
 public:
  FlyToAnimation(const geo::Ellipsoid& ellipsoid, const CameraPose& from, const CameraPose& to,
                 double durationSeconds);
  CameraPose poseAt(double elapsedSeconds) const;
  // A non-finite time ends the animation (at its target), so it never runs on with NaN.
  bool finishedAt(double elapsedSeconds) const { return !(elapsedSeconds < durationSeconds_); }
  const CameraPose& to() const { return to_; }

 private:
  CameraPose from_, to_;
  double durationSeconds_;
  double hopMeters_;
};

}  // namespace globe::camera
