// samplePath: slerp / cubic Hermite of the up direction, the height and the ECEF orientation.
#include "camera/camera_path.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>

#include "camera/camera_orientation.hpp"
#include "camera/look_at.hpp"
#include "geo/ecef.hpp"

namespace globe::camera {
namespace {

// A keyframe as the interpolation sees it: the geodetic up direction, the height, the orientation.
struct Key {
  double timeSeconds;
  glm::dvec3 up;
  double heightMeters;
  glm::dquat orientation;
};

Key keyAt(const CameraPath& path, size_t k, const geo::Ellipsoid& ellipsoid) {
  const CameraKeyframe& key = path.keyframes[k];
  geo::Cartographic surface = key.pose.position;
  surface.heightMeters = 0;
  return {key.timeSeconds, geo::geodeticSurfaceNormal(ellipsoid, surface),
          key.pose.position.heightMeters, orientationEcef(ellipsoid, key.pose)};
}

// The geodetic up direction's longitude and latitude (atan2 throughout: a pole gives lon 0).
geo::Cartographic positionFromUp(const glm::dvec3& up, double heightMeters) {
  return {std::atan2(up.y, up.x), std::atan2(up.z, std::sqrt(up.x * up.x + up.y * up.y)),
          heightMeters};
}

// Along the great circle from a to b (unit vectors); antipodal ends turn about a fixed axis.
glm::dvec3 slerpDirection(const glm::dvec3& a, const glm::dvec3& b, double u) {
  const glm::dvec3 normal = glm::cross(a, b);
  const double sine = glm::length(normal);
  const double angle = std::atan2(sine, glm::dot(a, b));
  glm::dvec3 axis;
  if (sine > 1e-12) {
    axis = normal / sine;
  } else if (glm::dot(a, b) > 0) {
    return glm::normalize(a + u * (b - a));
  } else {
    axis = glm::normalize(
        glm::cross(a, std::abs(a.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0)));
  }
  const double turn = u * angle;
  return std::cos(turn) * a + std::sin(turn) * glm::cross(axis, a);
}

// At most this many times the slower neighbouring segment's speed at a key: a short slow segment
// next to a long fast one would otherwise swing far out (Catmull-Rom's overshoot). Below 3, a
// straight run of keys never goes backwards (Fritsch-Carlson).
constexpr double kMaximumKeySpeedRatio = 2.0;

template <class V>
V limited(const V& velocity, double slowerSpeed) {
  const double speed = glm::length(velocity);
  const double limit = kMaximumKeySpeedRatio * slowerSpeed;
  return speed > limit ? velocity * (limit / speed) : velocity;
}

// Three-point (Bessel) velocity at the middle of (prev, at, next) values, limited to twice the
// slower neighbouring segment's speed; zero at a hold.
glm::dvec3 besselVelocity(const glm::dvec3& prev, const glm::dvec3& at, const glm::dvec3& next,
                          double hPrev, double hNext) {
  if (prev == at || at == next) return glm::dvec3(0.0);
  const glm::dvec3 before = (at - prev) / hPrev, after = (next - at) / hNext;
  return limited((hNext * before + hPrev * after) / (hPrev + hNext),
                 std::min(glm::length(before), glm::length(after)));
}

// Fritsch-Butland slope for a monotone cubic: zero at a local extremum or a flat neighbour.
double monotoneSlope(double prev, double at, double next, double hPrev, double hNext) {
  const double slopePrev = (at - prev) / hPrev, slopeNext = (next - at) / hNext;
  if (!(slopePrev * slopeNext > 0)) return 0;
  const double w1 = 2 * hNext + hPrev, w2 = hNext + 2 * hPrev;
  return (w1 + w2) / (w1 / slopePrev + w2 / slopeNext);
}

// Body-frame angular velocity (rotation vector per second) at the middle key, limited like
// besselVelocity; zero at a hold.
glm::dvec3 angularVelocity(const glm::dquat& prev, const glm::dquat& at, const glm::dquat& next,
                           double hPrev, double hNext) {
  if (prev == at || at == next) return glm::dvec3(0.0);
  const glm::dvec3 before = logRotation(glm::conjugate(prev) * at) / hPrev;
  const glm::dvec3 after = logRotation(glm::conjugate(at) * next) / hNext;
  return limited((hNext * before + hPrev * after) / (hPrev + hNext),
                 std::min(glm::length(before), glm::length(after)));
}

template <class T>
T hermite(const T& p0, const T& p1, const T& m0, const T& m1, double u) {
  const double u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * m0 + (-2 * u3 + 3 * u2) * p1 +
         (u3 - u2) * m1;
}

// Kim-Kim-Shin cumulative cubic: from q0 with body velocity w0 (per unit u) to q3 with w3.
glm::dquat quaternionHermite(const glm::dquat& q0, const glm::dquat& q3, const glm::dvec3& w0,
                             const glm::dvec3& w3, double u) {
  const glm::dvec3 w1 = w0 / 3.0, w3third = w3 / 3.0;
  const glm::dquat q1 = q0 * expRotation(w1);
  const glm::dquat q2 = q3 * expRotation(-w3third);
  const glm::dvec3 w2 = logRotation(glm::conjugate(q1) * q2);
  const double v = 1 - u;
  const double b1 = 1 - v * v * v, b2 = 3 * u * u - 2 * u * u * u, b3 = u * u * u;
  return q0 * expRotation(b1 * w1) * expRotation(b2 * w2) * expRotation(b3 * w3third);
}

}  // namespace

std::optional<PathInterpolation> parsePathInterpolation(std::string_view text) {
  if (text == "linear") return PathInterpolation::Linear;
  if (text == "smooth") return PathInterpolation::Smooth;
  return std::nullopt;
}

std::string_view toString(PathInterpolation interpolation) {
  return interpolation == PathInterpolation::Linear ? "linear" : "smooth";
}

namespace {

// A logarithmic-altitude step: the height at u (geometric between two heights above 0 m) and
// the share of the ground covered by then, the height's share of its change (u where the heights
// are equal). None where a height is not above 0 m: the segment is interpolated as it is.
struct LogarithmicStep {
  double heightMeters;
  double groundShare;
};

std::optional<LogarithmicStep> logarithmicStep(double fromMeters, double toMeters, double u) {
  if (!(fromMeters > 0.0) || !(toMeters > 0.0)) return std::nullopt;
  const double height = fromMeters * std::pow(toMeters / fromMeters, u);
  const double change = toMeters - fromMeters;
  const double share = std::abs(change) > 1e-9 * fromMeters ? (height - fromMeters) / change : u;
  return LogarithmicStep{height, share};
}

// The pose with the keyframes' heights as stored (above the terrain for some).
CameraPose sampleStoredHeights(const CameraPath& path, double timeSeconds,
                               const geo::Ellipsoid& ellipsoid) {
  const std::vector<CameraKeyframe>& keys = path.keyframes;
  if (keys.empty()) return {};
  if (!(timeSeconds > keys.front().timeSeconds)) return keys.front().pose;
  if (timeSeconds >= keys.back().timeSeconds) return keys.back().pose;
  const auto after =
      std::upper_bound(keys.begin(), keys.end(), timeSeconds,
                       [](double t, const CameraKeyframe& key) { return t < key.timeSeconds; });
  const size_t k = static_cast<size_t>(after - keys.begin()) - 1;
  if (timeSeconds == keys[k].timeSeconds) return keys[k].pose;

  const Key a = keyAt(path, k, ellipsoid), b = keyAt(path, k + 1, ellipsoid);
  const double h = b.timeSeconds - a.timeSeconds;
  const double u = (timeSeconds - a.timeSeconds) / h;
  const std::optional<LogarithmicStep> logarithmic =
      path.logarithmicAltitude ? logarithmicStep(a.heightMeters, b.heightMeters, u) : std::nullopt;
  const double along = logarithmic ? logarithmic->groundShare : u;
  glm::dvec3 up;
  double heightMeters;
  glm::dquat orientation;
  if (path.interpolation == PathInterpolation::Linear) {
    up = slerpDirection(a.up, b.up, along);
    heightMeters = a.heightMeters + u * (b.heightMeters - a.heightMeters);
    orientation =
        a.orientation * expRotation(u * logRotation(glm::conjugate(a.orientation) * b.orientation));
  } else {
    glm::dvec3 upVelocityA(0.0), upVelocityB(0.0), spinA(0.0), spinB(0.0);
    double climbA = 0, climbB = 0;  // m/s
    if (k > 0) {
      const Key p = keyAt(path, k - 1, ellipsoid);
      const double hp = a.timeSeconds - p.timeSeconds;
      upVelocityA = besselVelocity(p.up, a.up, b.up, hp, h);
      climbA = monotoneSlope(p.heightMeters, a.heightMeters, b.heightMeters, hp, h);
      spinA = angularVelocity(p.orientation, a.orientation, b.orientation, hp, h);
    }
    if (k + 2 < keys.size()) {
      const Key n = keyAt(path, k + 2, ellipsoid);
      const double hn = n.timeSeconds - b.timeSeconds;
      upVelocityB = besselVelocity(a.up, b.up, n.up, h, hn);
      climbB = monotoneSlope(a.heightMeters, b.heightMeters, n.heightMeters, h, hn);
      spinB = angularVelocity(a.orientation, b.orientation, n.orientation, h, hn);
    }
    const glm::dvec3 curve = hermite(a.up, b.up, upVelocityA * h, upVelocityB * h, along);
    const double length = glm::length(curve);
    up = length > 1e-9 ? curve / length : slerpDirection(a.up, b.up, along);
    heightMeters = hermite(a.heightMeters, b.heightMeters, climbA * h, climbB * h, u);
    orientation = quaternionHermite(a.orientation, b.orientation, spinA * h, spinB * h, u);
  }
  if (logarithmic) heightMeters = logarithmic->heightMeters;
  return poseFromOrientation(ellipsoid, positionFromUp(up, heightMeters), orientation);
}

// How much of the terrain height the sampled height stands on: each keyframe's 0 or 1, linear
// in time between them.
double terrainWeight(const CameraPath& path, double timeSeconds) {
  const std::vector<CameraKeyframe>& keys = path.keyframes;
  const auto weight = [](const CameraKeyframe& key) { return key.heightAboveTerrain ? 1.0 : 0.0; };
  if (!(timeSeconds > keys.front().timeSeconds)) return weight(keys.front());
  if (timeSeconds >= keys.back().timeSeconds) return weight(keys.back());
  const auto after =
      std::upper_bound(keys.begin(), keys.end(), timeSeconds,
                       [](double t, const CameraKeyframe& key) { return t < key.timeSeconds; });
  const CameraKeyframe& a = *(after - 1);
  const CameraKeyframe& b = *after;
  const double u = (timeSeconds - a.timeSeconds) / (b.timeSeconds - a.timeSeconds);
  return weight(a) + u * (weight(b) - weight(a));
}

}  // namespace

namespace {

// The segment a time falls in: keys k and k + 1 and the time fraction u between them; none
// before the first key, after the last, or for a non-finite time.
struct Segment {
  size_t k = 0;
  double u = 0;
  bool inside = false;
};

Segment segmentAt(const CameraPath& path, double timeSeconds) {
  const std::vector<CameraKeyframe>& keys = path.keyframes;
  if (keys.size() < 2 || !(timeSeconds > keys.front().timeSeconds) ||
      !(timeSeconds < keys.back().timeSeconds)) {
    return {};
  }
  const auto after =
      std::upper_bound(keys.begin(), keys.end(), timeSeconds,
                       [](double t, const CameraKeyframe& key) { return t < key.timeSeconds; });
  const size_t k = static_cast<size_t>(after - keys.begin()) - 1;
  const double span = keys[k + 1].timeSeconds - keys[k].timeSeconds;
  return {k, (timeSeconds - keys[k].timeSeconds) / span, true};
}

// The time the un-eased interpolation is sampled at: the segment's eased fraction (held within
// the segment: a curve that overshoots stops at its keys).
double easedTime(const CameraPath& path, double timeSeconds) {
  const Segment segment = segmentAt(path, timeSeconds);
  if (!segment.inside) return timeSeconds;
  const CameraKeyframe& a = path.keyframes[segment.k];
  if (!a.ease) return timeSeconds;
  const double progress = std::clamp(easeProgress(*a.ease, segment.u), 0.0, 1.0);
  return a.timeSeconds + progress * (path.keyframes[segment.k + 1].timeSeconds - a.timeSeconds);
}

}  // namespace

CameraPose samplePath(const CameraPath& path, double timeSeconds, const geo::Ellipsoid& ellipsoid,
                      const TerrainHeightAt& terrain) {
  const double at = easedTime(path, timeSeconds);
  CameraPose pose = sampleStoredHeights(path, at, ellipsoid);
  if (path.keyframes.empty()) return pose;
  if (terrain) {
    const double weight = terrainWeight(path, at);
    if (weight > 0.0) {
      pose.position.heightMeters +=
          weight * terrain(pose.position.longitudeRadians, pose.position.latitudeRadians);
    }
  }
  // Between two keyframes with targets the camera looks at the point between them.
  const Segment segment = segmentAt(path, at);
  if (segment.inside) {
    const CameraKeyframe& a = path.keyframes[segment.k];
    const CameraKeyframe& b = path.keyframes[segment.k + 1];
    if (a.targetEcefMeters && b.targetEcefMeters) {
      const glm::dvec3 target =
          *a.targetEcefMeters + segment.u * (*b.targetEcefMeters - *a.targetEcefMeters);
      pose = lookingAt(ellipsoid, pose, target);
      // Roll as the keyframes give it (the orientation's own would drift with the turn).
      const double turn = std::remainder(b.pose.rollRadians - a.pose.rollRadians,
                                         2.0 * std::numbers::pi);
      pose.rollRadians = a.pose.rollRadians + segment.u * turn;
    }
  }
  return pose;
}

namespace {

// A keyframe value that only some keyframes have, linear in time between those that do; the
// first's before it and the last's after it.
std::optional<double> sampleSparse(const CameraPath& path, double timeSeconds,
                                   std::optional<double> CameraKeyframe::*member) {
  const CameraKeyframe* before = nullptr;
  for (const CameraKeyframe& key : path.keyframes) {
    if (!(key.*member)) continue;
    if (!(key.timeSeconds < timeSeconds)) {
      if (before == nullptr) return key.*member;  // at or before the first
      const double f = (timeSeconds - before->timeSeconds) / (key.timeSeconds - before->timeSeconds);
      return *(before->*member) + f * (*(key.*member) - *(before->*member));
    }
    before = &key;
  }
  return before != nullptr ? before->*member : std::nullopt;
}

}  // namespace

std::optional<double> sampleFovY(const CameraPath& path, double timeSeconds) {
  return sampleSparse(path, easedTime(path, timeSeconds), &CameraKeyframe::fovYRadians);
}

std::optional<double> sampleSunTime(const CameraPath& path, double timeSeconds) {
  return sampleSparse(path, timeSeconds, &CameraKeyframe::sunUnixSeconds);
}

}  // namespace globe::camera
