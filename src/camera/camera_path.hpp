// Scripted camera paths: keyframed poses and their interpolation in time, on the globe (ECEF
// directions and quaternions, so ±180° and the poles need no special cases).
#pragma once

#include <functional>
#include <optional>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "camera/camera_pose.hpp"
#include "camera/path_easing.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::camera {

// Linear: positions along the great circle (slerp of the geodetic up directions) with the height
// linear in time, orientations by shortest-arc quaternion slerp; continuous, corners at keys.
// Smooth: C1 everywhere: the up direction by a cubic Hermite curve in R^3 renormalised, the
// height by a monotone cubic (Fritsch-Butland: never overshoots its keys, so a path never dips
// below both neighbouring keyframes' heights), the orientation by a cumulative quaternion Hermite
// curve (Kim-Kim-Shin) with shortest-arc steps. Interior velocities are the three-point (Bessel)
// estimates limited to twice the slower neighbouring segment's speed (a short, slow segment next
// to a long, fast one does not swing out: no Catmull-Rom overshoot); the path starts and ends at
// rest, and a repeated keyframe (a hold) stops it there.
enum class PathInterpolation { Linear, Smooth };
std::optional<PathInterpolation> parsePathInterpolation(std::string_view text);  // linear|smooth
std::string_view toString(PathInterpolation interpolation);

struct CameraKeyframe {
  double timeSeconds = 0;
  CameraPose pose;
  // pose.position.heightMeters is above the terrain, not the ellipsoid: samplePath adds the
  // terrain under the sampled position, so between two such keyframes the height above the
  // ground is what is interpolated and the path follows the terrain (a mountain between them
  // is flown over, not into).
  bool heightAboveTerrain = false;
  std::optional<double> sunUnixSeconds{};  // the Sun's instant here (camera_path_file.hpp "time")
  // The segment leaving this keyframe runs by this curve in time (path_easing.hpp): the pose at
  // t is the un-eased pose at t_k + ease(u)·(t_k+1 − t_k), u the segment's time fraction.
  std::optional<CubicBezierEase> ease{};
  // Where the camera looks (ECEF, resolved); the keyframe's pose already looks there. Between
  // two keyframes that have one, every sampled pose looks at the point between them (at the
  // segment's eased fraction), roll kept.
  std::optional<glm::dvec3> targetEcefMeters{};
  std::optional<double> fovYRadians{};  // the vertical field of view here ("fov")
};

// The terrain height (m above the ellipsoid) under a longitude and latitude in radians.
using TerrainHeightAt = std::function<double(double, double)>;

// At least one keyframe, times strictly increasing, poses finite with |latitude| <= 90°
// (io's path readers check all of it; samplePath returns a default pose for an empty path).
struct CameraPath {
  std::vector<CameraKeyframe> keyframes;
  PathInterpolation interpolation = PathInterpolation::Smooth;
  // Logarithmic altitude ("altitude": "logarithmic"): within a segment whose keys are both above
  // 0 m the height goes geometrically (the same ratio every frame: a dive from space slows as it
  // nears the ground) and the position along the ground by the height's share of its change, so
  // the ground moves evenly on screen (its speed over the height stays the same).
  bool logarithmicAltitude = false;

  double startSeconds() const { return keyframes.empty() ? 0 : keyframes.front().timeSeconds; }
  double endSeconds() const { return keyframes.empty() ? 0 : keyframes.back().timeSeconds; }
};

// The pose at a time: a keyframe's pose exactly (as given) at its time, the first before the
// start (and for a non-finite time), the last after the end. Between keys the heading is in
// (-180°, 180°] and the longitude in [-180°, 180°]; looking straight down the roll is folded into
// the heading (the same view).
// Keyframes above the terrain: the interpolated height plus w(t) x terrain(position), w the
// keyframes' 0 (absolute) or 1 (above the terrain) interpolated linearly in time, so a path
// mixing both changes over from one to the other along the segment between them; without
// `terrain` (or without such keyframes) the heights are taken as they are.
CameraPose samplePath(const CameraPath& path, double timeSeconds, const geo::Ellipsoid& ellipsoid,
                      const TerrainHeightAt& terrain = {});

// The Sun's instant at a path time: linear between the keyframes that have one (a day passes in
// a minute of flight if the keyframes say so), the first one's before it and the last one's
// after it; nullopt when no keyframe has one.
std::optional<double> sampleSunTime(const CameraPath& path, double timeSeconds);

// The vertical field of view at a path time: linear between the keyframes that have one, by the
// segment's eased share where it is eased; the first one's before it, the last one's after it;
// nullopt when no keyframe has one.
std::optional<double> sampleFovY(const CameraPath& path, double timeSeconds);

}  // namespace globe::camera
