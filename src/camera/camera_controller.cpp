// update(dt): the raise for new terrain, the frame's move and its response, the near plane.
#include "camera/camera_controller.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "collision/lateral_clearance.hpp"
#include "collision/near_plane_clearance.hpp"
#include "collision/surface_probe.hpp"
#include "collision/terrain_raise.hpp"
#include "geo/ecef.hpp"

namespace globe::camera {
namespace {

// The responses accept a camera up to the contact skin below the clearance they are given (so a
// camera placed at it does not collide again at once). Asked for the eye clearances plus the
// skin, they never leave the eye nearer the surface than the settings say.
collision::ClearanceSettings responseClearance(collision::ClearanceSettings clearance) {
  clearance.eyeMeters += collision::kContactSkinMeters;
  clearance.minimumEyeMeters += collision::kContactSkinMeters;
  return clearance;
}

bool isFinite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool isValidPose(const CameraPose& pose) {
  return pose.isFinite() && std::abs(pose.position.latitudeRadians) <= std::numbers::pi / 2;
}

CameraPose withPosition(CameraPose pose, const geo::Cartographic& position) {
  pose.position = position;
  return pose;
}

// The motion's response wins over the raise, the raise over the near-plane push.
void report(CollisionState& state, collision::Response response) {
  if (response == collision::Response::None) return;
  state.collided = true;
  const bool motion = response == collision::Response::Stopped ||
                      response == collision::Response::Slid ||
                      response == collision::Response::Heightened;
  if (state.response == collision::Response::None || motion ||
      (response == collision::Response::RaisedForNewTerrain &&
       state.response == collision::Response::NearPlanePushed)) {
    state.response = response;
  }
}

void count(CollisionState& state, const collision::MotionResult& result) {
  state.tilesExamined += static_cast<int>(result.tilesExamined);
  state.surfaceProbes += static_cast<int>(result.samples);
}

}  // namespace

CameraController::CameraController(const CameraPose& initialPose,
                                   const ControllerSettings& settings)
    : settings_(settings), glide_(settings.glide), pose_(initialPose) {
  if (!isValidPose(initialPose)) {
    pose_ = CameraPose::fromDegrees(0.0, 0.0, 1.0e7, 0.0, -90.0, 0.0);
    rejected_ = true;
  }
  pose_.position.longitudeRadians = geo::wrapLongitudeRadians(pose_.position.longitudeRadians);
}

bool CameraController::propose(const CameraPose& pose, MotionKind kind,
                               std::span<const GlidePoint> ahead) {
  if (!isValidPose(pose)) {
    rejected_ = true;
    return false;
  }
  queued_ = Move{pose, kind, {ahead.begin(), ahead.end()}};
  return true;
}

bool CameraController::setTargetPose(const CameraPose& pose) {
  return propose(pose, MotionKind::Jump);
}

bool CameraController::setVelocity(const glm::dvec3& metersPerSecond) {
  if (!isFinite(metersPerSecond)) return rejected_ = true, false;
  velocity_ = metersPerSecond;
  return true;
}

bool CameraController::setAcceleration(const glm::dvec3& metersPerSecondSquared) {
  if (!isFinite(metersPerSecondSquared)) return rejected_ = true, false;
  acceleration_ = metersPerSecondSquared;
  return true;
}

bool CameraController::setAngularVelocity(const glm::dvec3& radiansPerSecond) {
  if (!isFinite(radiansPerSecond)) return rejected_ = true, false;
  angularVelocity_ = radiansPerSecond;
  return true;
}

bool CameraController::setAngularAcceleration(const glm::dvec3& radiansPerSecondSquared) {
  if (!isFinite(radiansPerSecondSquared)) return rejected_ = true, false;
  angularAcceleration_ = radiansPerSecondSquared;
  return true;
}

void CameraController::stop() {
  velocity_ = acceleration_ = angularVelocity_ = angularAcceleration_ = glm::dvec3(0.0);
  queued_.reset();
}

bool CameraController::setNearPlane(const NearPlane& nearPlane) {
  if (!(std::isfinite(nearPlane.nearMeters) && nearPlane.nearMeters > 0.0 &&
        std::isfinite(nearPlane.fovYRadians) && nearPlane.fovYRadians > 0.0 &&
        nearPlane.fovYRadians < std::numbers::pi && std::isfinite(nearPlane.aspect) &&
        nearPlane.aspect > 0.0)) {
    return rejected_ = true, false;
  }
  settings_.nearPlane = nearPlane;
  return true;
}

const CollisionState& CameraController::update(double dtSeconds,
                                               const terrain::RenderingTileArray& array,
                                               const geo::Ellipsoid& ellipsoid) {
  CollisionState state;
  state.inputRejected = rejected_;
  rejected_ = false;
  const collision::ClearanceSettings clearance = responseClearance(settings_.clearance);
  const collision::SurfaceModel model = settings_.response.surface;
  if (!(std::isfinite(dtSeconds) && dtSeconds >= 0.0)) {
    state.inputRejected = true;
    queued_.reset();
    describeTerrain(array, ellipsoid, state);
    return state_ = state;
  }

  // (1) The frame's move: the queued one, else the velocities. While the camera is being raised
  // (below the eye clearance since finer terrain appeared), a move keeps the clearance it has:
  // it collides below it (clearance + skin - skin), so it neither skips the raise nor undoes it.
  const double floor = std::min(clearance.minimumEyeMeters, clearance.eyeMeters);
  double moveClearance = clearance.eyeMeters;
  if (const auto surface =
          collision::surfaceHeightAt(array, ellipsoid, pose_.position.longitudeRadians,
                                     pose_.position.latitudeRadians, model)) {
    const double now = pose_.position.heightMeters - surface->heightMeters;
    moveClearance = std::clamp(now + collision::kContactSkinMeters, floor, clearance.eyeMeters);
  }
  if (queued_) {
    const Move move = std::move(*queued_);
    queued_.reset();
    moveBy(move, dtSeconds, array, ellipsoid, moveClearance, state);
  } else {
    moveByVelocities(dtSeconds, array, ellipsoid, moveClearance, state);
  }

  // (2) The surface may have risen under the camera (a finer tile): raise it.
  const collision::RaiseResult raise =
      collision::raiseForNewTerrain(array, ellipsoid, pose_.position, dtSeconds, clearance, model);
  if (raise.valid && raise.raised) {
    pose_.position = raise.position;
    state.raisedForNewTerrain = true;
    report(state, collision::Response::RaisedForNewTerrain);
  }

  // (3) The near plane's corners at the final pose.
  if (settings_.nearPlaneCheck) {
    const auto corners = nearPlaneCornerOffsets(cameraFrame(ellipsoid, pose_), settings_.nearPlane);
    const collision::NearPlaneResult push = collision::pushAboveNearPlane(
        array, ellipsoid, pose_.position, corners, clearance.nearPlaneMeters, model);
    if (push.valid && push.pushMeters > 0.0) {
      pose_.position = push.position;
      state.nearPlanePushed = true;
      report(state, collision::Response::NearPlanePushed);
    }
  }
  // (4) Beside a steep wall "above the surface" can be centimetres from it: the ball around the
  // eye that holds the near-plane rectangle (and the view between them) is kept free of drawn
  // triangles by moving the eye straight away from the nearest one.
  if (settings_.nearPlaneCheck && settings_.lateralCheck) {
    const auto corners = nearPlaneCornerOffsets(cameraFrame(ellipsoid, pose_), settings_.nearPlane);
    double radius = 0.0;
    for (const glm::dvec3& corner : corners) radius = std::max(radius, glm::length(corner));
    radius += clearance.lateralMarginMeters;
    const collision::LateralPush push = collision::pushAwayFromTerrain(
        array, ellipsoid, geo::cartographicToEcef(ellipsoid, pose_.position), radius);
    state.surfaceProbes += push.trianglesTested;
    if (push.valid && push.pushMeters > 0.0) {
      if (const auto moved = geo::ecefToCartographic(ellipsoid, push.eyeEcefMeters)) {
        pose_.position = *moved;
        state.nearPlanePushed = true;
        report(state, collision::Response::NearPlanePushed);
      }
    }
  }
  describeTerrain(array, ellipsoid, state);
  return state_ = state;
}

void CameraController::moveBy(const Move& move, double dtSeconds,
                              const terrain::RenderingTileArray& array,
                              const geo::Ellipsoid& ellipsoid, double clearanceMeters,
                              CollisionState& state) {
  const geo::Cartographic from = pose_.position;
  geo::Cartographic to = move.pose.position;
  MotionKind kind = move.kind;
  if (kind == MotionKind::Auto) {
    kind = classifyMotion(ellipsoid, from, to, settings_.jumpDistanceMeters);
  } else if (kind == MotionKind::None) {
    kind = MotionKind::Jump;
  }
  // The glide lifts a moving camera's proposal over the ground ahead before the response tests
  // it; a jump starts afresh.
  if (settings_.glide.enabled && (kind == MotionKind::Linear || kind == MotionKind::Angular)) {
    // The motion the proposal asks of the camera as it is lifted now: from the proposal less
    // the lift the camera carries (else a held script reads as the lift's whole height each
    // frame, thousands of m/s, and the speed margin holds a stopped camera 50 m up).
    geo::Cartographic carried = to;
    carried.heightMeters += glide_.liftMeters();
    const glm::dvec3 motion =
        geo::cartographicToEcef(ellipsoid, carried) - geo::cartographicToEcef(ellipsoid, from);
    const GlideResult glide = glide_.update(array, ellipsoid, to, motion, move.ahead, dtSeconds,
                                            responseClearance(settings_.clearance).eyeMeters);
    to.heightMeters += glide.liftMeters;
    state.glideLiftMeters = glide.liftMeters;
    state.surfaceProbes += glide.samples;
  } else {
    glide_.reset();
  }
  const bool samePosition = isSamePosition(ellipsoid, from, to);
  if (kind == MotionKind::Jump && samePosition) {
    // Only the orientation changes: nothing to test (the near plane is checked below).
    state.motion = kind;
    pose_ = withPosition(move.pose, from);
    return;
  }
  collision::MotionResult result;
  switch (kind) {
    case MotionKind::Linear: {
      const glm::dvec3 displacement =
          geo::cartographicToEcef(ellipsoid, to) - geo::cartographicToEcef(ellipsoid, from);
      result = collision::respondLinear(array, ellipsoid, from, displacement, clearanceMeters,
                                        settings_.response);
      break;
    }
    case MotionKind::Angular:
      result = collision::respondAngular(array, ellipsoid, from, to, clearanceMeters,
                                         settings_.response);
      break;
    default:
      // A jump is tested at the full eye clearance: it does not continue a raise.
      result = collision::respondStatic(array, ellipsoid, from, to,
                                        responseClearance(settings_.clearance).eyeMeters,
                                        settings_.response);
      break;
  }
  count(state, result);
  state.motion = kind;
  if (!result.valid) {
    state.inputRejected = true;
    return;
  }
  report(state, result.response);
  // A refused jump keeps the whole last valid pose, orientation included.
  if (result.response != collision::Response::Stopped) {
    pose_ = withPosition(move.pose, result.position);
  }
}

void CameraController::moveByVelocities(double dtSeconds, const terrain::RenderingTileArray& array,
                                        const geo::Ellipsoid& ellipsoid, double clearanceMeters,
                                        CollisionState& state) {
  const glm::dvec3 angularVelocity = angularVelocity_ + angularAcceleration_ * dtSeconds;
  const glm::dvec3 rotation = 0.5 * (angularVelocity_ + angularVelocity) * dtSeconds;
  const glm::dvec3 velocity = velocity_ + acceleration_ * dtSeconds;
  const glm::dvec3 displacement = 0.5 * (velocity_ + velocity) * dtSeconds;
  if (!isFinite(angularVelocity) || !isFinite(rotation) || !isFinite(velocity) ||
      !isFinite(displacement)) {
    state.inputRejected = true;
    return;
  }
  if (glm::length(rotation) > 0.0) {
    const glm::dvec3 turned =
        rotateAboutGeocentre(geo::cartographicToEcef(ellipsoid, pose_.position), rotation);
    const auto to = geo::ecefToCartographic(ellipsoid, turned);
    const collision::MotionResult result =
        to ? collision::respondAngular(array, ellipsoid, pose_.position, *to, clearanceMeters,
                                       settings_.response)
           : collision::MotionResult{};
    count(state, result);
    state.motion = MotionKind::Angular;
    if (!result.valid) {
      state.inputRejected = true;
      return;
    }
    report(state, result.response);
    pose_.position = result.position;
  }
  if (glm::length(displacement) > 0.0) {
    const collision::MotionResult result = collision::respondLinear(
        array, ellipsoid, pose_.position, displacement, clearanceMeters, settings_.response);
    count(state, result);
    state.motion = MotionKind::Linear;
    if (!result.valid) {
      state.inputRejected = true;
      return;
    }
    report(state, result.response);
    pose_.position = result.position;
  }
  angularVelocity_ = angularVelocity;
  velocity_ = velocity;
}

void CameraController::describeTerrain(const terrain::RenderingTileArray& array,
                                       const geo::Ellipsoid& ellipsoid,
                                       CollisionState& state) const {
  const auto surface =
      collision::surfaceHeightAt(array, ellipsoid, pose_.position.longitudeRadians,
                                 pose_.position.latitudeRadians, collision::SurfaceModel::Exact);
  if (surface) {
    state.terrainFound = surface->found;
    state.terrainHeightMeters = surface->heightMeters;
    if (surface->tile != nullptr) state.tile = surface->tile->id;
  }
  state.clearanceMeters = pose_.position.heightMeters - state.terrainHeightMeters;
  const auto corners = nearPlaneCornerOffsets(cameraFrame(ellipsoid, pose_), settings_.nearPlane);
  state.nearPlaneClearanceMeters =
      collision::lowestPointClearance(array, ellipsoid, pose_.position, corners,
                                      collision::SurfaceModel::Exact)
          .value_or(0.0);
}

}  // namespace globe::camera
