// Navigator: input events -> orbit controls, fly look and keys, fly-to; one proposal a frame.
#include "camera/navigator.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "geo/cartographic.hpp"
#include "geo/ecef.hpp"

namespace globe::camera {
namespace {

// Fly motion integrates at most this much time a frame, so a stalled frame is not a leap.
constexpr double kLongestFlyStepSeconds = 0.1;

}  // namespace

const char* toString(NavigationMode mode) { return mode == NavigationMode::Fly ? "FLY" : "ORBIT"; }

Navigator::Navigator(const geo::Ellipsoid& ellipsoid, const CameraPose& start, double fovYRadians,
                     TerrainHeightFunction terrainHeight)
    : ellipsoid_(ellipsoid),
      fovYRadians_(fovYRadians),
      terrainHeight_(std::move(terrainHeight)),
      controls_(ellipsoid, start, fovYRadians),
      current_(controls_.home()),
      flyLook_(controls_.home()) {}

void Navigator::setViewport(int widthPixels, int heightPixels) {
  widthPixels_ = std::max(widthPixels, 1);
  heightPixels_ = std::max(heightPixels, 1);
}

void Navigator::toggleMode() {
  mode_ = mode_ == NavigationMode::Orbit ? NavigationMode::Fly : NavigationMode::Orbit;
  grabbed_.reset();
  flyLook_ = current_;
  flyClearance_.reset();
  userMoved();
}

std::optional<glm::dvec3> Navigator::groundAt(const CameraPose& pose, glm::dvec2 pixel) const {
  if (!std::isfinite(pixel.x) || !std::isfinite(pixel.y)) return std::nullopt;
  const CameraFrame frame = cameraFrame(ellipsoid_, pose);
  const glm::dvec3 ray =
      pixelRayEcef(frame, pixel.x, pixel.y, widthPixels_, heightPixels_, fovYRadians_);
  return intersectTerrain(ellipsoid_, frame.positionEcefMeters, ray, terrainHeight_);
}

std::optional<glm::dvec3> Navigator::groundAt(glm::dvec2 pixel) const {
  return groundAt(current_, pixel);
}

double Navigator::metersPerPixelAtCentre() const {
  const auto ground = groundAt(centre());
  if (!ground) return std::nan("");
  const double distance =
      glm::distance(*ground, cameraFrame(ellipsoid_, current_).positionEcefMeters);
  return distance * fovYRadians_ / heightPixels_;
}

void Navigator::zoomAt(double notches, glm::dvec2 pixel) {
  if (mode_ != NavigationMode::Orbit || !std::isfinite(notches) || notches == 0 ||
      !std::isfinite(pixel.x) || !std::isfinite(pixel.y)) {
    return;
  }
  userMoved();
  if (const auto ground = groundAt(controls_.pose(), pixel)) {
    controls_.zoomToward(notches, *ground);
  } else {
    controls_.zoom(notches);  // sky under the cursor: along the view
  }
}

void Navigator::zoom(double notches) {
  if (mode_ != NavigationMode::Orbit) return;
  userMoved();
  controls_.zoom(notches);
}

void Navigator::grab(glm::dvec2 pixel) {
  if (mode_ != NavigationMode::Orbit) return;
  grabbed_ = groundAt(controls_.pose(), pixel);
}

void Navigator::dragTo(glm::dvec2 pixel, double dxPixels, double dyPixels) {
  if (mode_ != NavigationMode::Orbit) return;
  userMoved();
  const CameraFrame frame = cameraFrame(ellipsoid_, controls_.pose());
  const glm::dvec3 ray =
      pixelRayEcef(frame, pixel.x, pixel.y, widthPixels_, heightPixels_, fovYRadians_);
  if (!grabbed_ || !controls_.dragGrabbed(*grabbed_, ray)) {
    controls_.rotateByDrag(dxPixels, dyPixels, heightPixels_);  // off the globe
  }
}

void Navigator::panByKey(double dxPixels, double dyPixels) {
  if (mode_ != NavigationMode::Orbit) return;
  userMoved();
  controls_.rotateByDrag(dxPixels, dyPixels, heightPixels_);
}

void Navigator::beginTilt() {
  tiltDragging_ = true;
  tiltPivotChosen_ = false;
}

void Navigator::endTilt() { tiltDragging_ = tiltPivotChosen_ = false; }

void Navigator::tilt(double dxPixels, double dyPixels) {
  if (mode_ != NavigationMode::Orbit) return;
  userMoved();
  if (!tiltPivotChosen_) {
    tiltPivot_ = groundAt(controls_.pose(), centre());
    tiltPivotChosen_ = tiltDragging_;
  }
  if (tiltPivot_) {
    controls_.tiltAbout(dxPixels, dyPixels, *tiltPivot_);
  } else {
    controls_.tiltByDrag(dxPixels, dyPixels);  // no ground in view
  }
}

void Navigator::startFlyTo(const CameraPose& end, double seconds) {
  flyTo_.emplace(ellipsoid_, current_, end, seconds);
  flyToSeconds_ = 0;
}

bool Navigator::flyToPixel(glm::dvec2 pixel) {
  const auto target = groundAt(current_, pixel);
  if (!target) return false;
  startFlyTo(flyToEndPose(ellipsoid_, current_, *target), FlyToSettings{}.durationSeconds);
  return true;
}

double Navigator::goToSeconds(double wayMeters) {
  return std::clamp(1.0 + std::log10(std::max(wayMeters, 1.0) / 1e4), 1.0, 4.0);
}

void Navigator::goTo(double longitudeRadians, double latitudeRadians) {
  if (!std::isfinite(longitudeRadians) || !std::isfinite(latitudeRadians)) return;
  const auto ground =
      terrainHeight_ ? terrainHeight_(longitudeRadians, latitudeRadians) : std::optional<double>();
  const glm::dvec3 point = geo::cartographicToEcef(
      ellipsoid_, {longitudeRadians, latitudeRadians, ground ? *ground : 0.0});
  // Land ~15 km from the place, looking down at it at least 35 degrees.
  FlyToSettings settings;
  settings.distanceFraction = 0;
  settings.minimumDistanceMeters = 15000;
  settings.maximumPitchRadians = geo::degreesToRadians(-35);
  settings.durationSeconds =
      goToSeconds(glm::distance(point, cameraFrame(ellipsoid_, current_).positionEcefMeters));
  startFlyTo(flyToEndPose(ellipsoid_, current_, point, settings), settings.durationSeconds);
}

void Navigator::flyToPose(const CameraPose& end) {
  if (!end.isFinite()) return;
  const double way = glm::distance(cameraFrame(ellipsoid_, end).positionEcefMeters,
                                   cameraFrame(ellipsoid_, current_).positionEcefMeters);
  startFlyTo(end, goToSeconds(way));
}

void Navigator::northUp() {
  userMoved();
  if (mode_ == NavigationMode::Fly) {
    flyLook_.headingRadians = 0;
    flyLook_.pitchRadians = 0;
    flyLook_.rollRadians = 0;
    return;
  }
  controls_.northUp(groundAt(controls_.pose(), centre()));
}

void Navigator::reset() {
  userMoved();
  grabbed_.reset();
  resetPending_ = true;
}

void Navigator::setFlyKeys(const FlyKeys& keys) {
  if (mode_ == NavigationMode::Fly && keys.moving()) userMoved();
  flyKeys_ = keys;
}

void Navigator::look(double dxPixels, double dyPixels) {
  if (mode_ != NavigationMode::Fly) return;
  userMoved();
  flyLook_ = lookByPixels(flyLook_, dxPixels, dyPixels);
}

void Navigator::lookRadians(double headingRadians, double pitchRadians) {
  if (mode_ != NavigationMode::Fly) return;
  userMoved();
  flyLook_ = camera::lookByRadians(flyLook_, headingRadians, pitchRadians);
}

double Navigator::flySpeedMetersPerSecond() const {
  const double clearance =
      flyKeys_.moving() && flyClearance_.started() ? flyClearance_.value() : clearanceMeters_;
  return camera::flySpeedMetersPerSecond(clearance, flyKeys_.fast, speed_.factor());
}

std::optional<NavigationProposal> Navigator::update(double dtSeconds) {
  if (!std::isfinite(dtSeconds) || dtSeconds < 0) dtSeconds = 0;
  takeLook_ = mode_ != NavigationMode::Fly;
  if (resetPending_) {
    resetPending_ = false;
    takeLook_ = true;
    controls_.reset();
    return NavigationProposal{controls_.home()};
  }
  if (flyTo_) {
    takeLook_ = true;
    flyToSeconds_ += dtSeconds;
    const CameraPose pose = flyTo_->poseAt(flyToSeconds_);
    if (flyTo_->finishedAt(flyToSeconds_)) flyTo_.reset();
    return NavigationProposal{pose};
  }
  if (mode_ == NavigationMode::Fly) {
    CameraPose wanted = flyLook_;
    wanted.position = current_.position;
    if (flyKeys_.moving()) {
      const double dt = std::min(dtSeconds, kLongestFlyStepSeconds);
      const glm::dvec3 velocity =
          flyVelocityEcef(ellipsoid_, wanted, flyKeys_, flyClearance_.update(clearanceMeters_, dt),
                          speed_.factor());
      return NavigationProposal{flyStep(ellipsoid_, wanted, velocity, dt), MotionKind::Linear};
    }
    flyClearance_.reset();  // a new flight starts from the clearance then
    if (!samePose(wanted, current_)) return NavigationProposal{wanted};  // a turn
    return std::nullopt;
  }
  if (!samePose(controls_.pose(), current_)) return NavigationProposal{controls_.pose()};
  return std::nullopt;
}

void Navigator::adopt(const CameraPose& pose, const CollisionState& state) {
  current_ = pose;
  if (!samePose(controls_.pose(), pose)) controls_.adoptPose(pose);
  if (takeLook_) flyLook_ = pose;
  // Orbit zoom steps scale with the height above the terrain the controller found.
  if (state.terrainFound) controls_.setGroundHeight(state.terrainHeightMeters);
  clearanceMeters_ = state.clearanceMeters;
}

}  // namespace globe::camera
