// The camera controller: a small manipulator advanced by an explicit update(dt) against this
// frame's rendering tile array (Filament camutils' model), applying the collision responses.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "camera/camera_motion.hpp"
#include "camera/camera_pose.hpp"
#include "camera/terrain_glide.hpp"
#include "collision/clearance_settings.hpp"
#include "collision/collision_response.hpp"
#include "geo/ellipsoid.hpp"
#include "geo/tile_id.hpp"
#include "terrain/rendering_tile_array.hpp"

namespace globe::camera {

struct ControllerSettings {
  collision::ClearanceSettings clearance;  // 2 m eye and floor, 0.5 m near-plane corners
  collision::ResponseSettings response;    // exact surface, swept tests, 4 slide contacts
  NearPlane nearPlane;                     // the renderer's near plane; its corners are checked
  bool nearPlaneCheck = true;
  // The ball around the eye holding the near plane is kept free of drawn triangles (with
  // nearPlaneCheck; collision/lateral_clearance.hpp).
  bool lateralCheck = true;
  double jumpDistanceMeters = 1.0e6;  // Auto proposals moving farther than this are teleports
  // Proposed moves (Linear, Angular) lifted over a smooth envelope of the ground ahead
  // (terrain_glide.hpp). For absolute proposals, as a scripted path makes: a proposal made from
  // the controller's own pose would carry the lift into the next one. Off by default; globe play
  // and the soak turn it on.
  GlideSettings glide{.enabled = false};
};

// What the last update did, for the HUD and logs.
struct CollisionState {
  bool collided = false;  // a response changed the motion or the pose
  // The motion's response when there was one (Stopped, Slid, Heightened), else
  // RaisedForNewTerrain, else NearPlanePushed, else None; the flags below tell all that happened.
  collision::Response response = collision::Response::None;
  double terrainHeightMeters = 0.0;  // the drawn surface under the eye (0 m where no tile)
  double clearanceMeters = 0.0;      // the eye's height above it
  geo::TileId tile{};                // the tile under the eye, when terrainFound
  int tilesExamined = 0;             // QOTCD hash probes this update
  bool terrainFound = false;
  bool inputRejected = false;  // a non-finite pose, velocity, dt or motion was refused
  bool raisedForNewTerrain = false;
  bool nearPlanePushed = false;
  double nearPlaneClearanceMeters = 0.0;  // the lowest near-plane corner above the drawn surface
  MotionKind motion = MotionKind::None;   // what moved the camera this update
  int surfaceProbes = 0;                  // points tested (sweeps included)
  double glideLiftMeters = 0.0;           // the glide's lift over the proposed height
};

class CameraController {
 public:
  // A non-finite initial pose (or |latitude| > 90 deg) is replaced by one 10,000 km above
  // (0 deg, 0 deg) looking down, and the next update reports inputRejected.
  explicit CameraController(const CameraPose& initialPose, const ControllerSettings& settings = {});

  // This frame's move, applied by the next update instead of the velocities: propose for
  // interactive moves (kind Auto: classifyMotion), setTargetPose for a jump (a static camera set
  // to a pose: refused if it collides; a pose at the same position only turns the camera). The
  // last move queued before an update wins. false, with nothing queued and the rejection reported
  // by the next update, for a non-finite pose or |latitude| > 90 deg; the last valid pose is kept.
  // `ahead`: where a script will take the camera next, for the glide (empty: its velocity).
  bool propose(const CameraPose& pose, MotionKind kind = MotionKind::Auto,
               std::span<const GlidePoint> ahead = {});
  bool setTargetPose(const CameraPose& pose);

  // Motion state, ECEF: linear velocity (m/s) and acceleration (m/s^2); angular velocity about
  // the geocentre as a rotation vector (axis * rad/s, right hand) and its acceleration (rad/s^2).
  // Responses never change them (the paper: heighten "without changing the angular velocity").
  // false, nothing changed, for non-finite input.
  bool setVelocity(const glm::dvec3& metersPerSecond);
  bool setAcceleration(const glm::dvec3& metersPerSecondSquared);
  bool setAngularVelocity(const glm::dvec3& radiansPerSecond);
  bool setAngularAcceleration(const glm::dvec3& radiansPerSecondSquared);
  void stop();  // all four set to zero, a queued move dropped

  // false, nothing changed, for a non-finite or non-positive near distance, fovY or aspect.
  bool setNearPlane(const NearPlane& nearPlane);

  // One frame, in this order: (1) the queued move, classified and answered (Jump: respondStatic
  // at the eye clearance; Linear: respondLinear; Angular: respondAngular), or else the velocities
  // integrated with their accelerations (trapezoid) as an angular then a linear move; moves keep
  // the eye clearance, or, while the camera is being raised, the clearance it has (at least the
  // minimum), so a move neither skips the smooth raise nor undoes it; (2) raiseForNewTerrain at
  // the position reached (the surface may have risen under it: a finer tile); (3)
  // pushAboveNearPlane with the near plane's corners at the final pose. A non-finite or negative
  // dt changes nothing.
  const CollisionState& update(double dtSeconds, const terrain::RenderingTileArray& array,
                               const geo::Ellipsoid& ellipsoid);

  const CameraPose& pose() const { return pose_; }
  const CollisionState& state() const { return state_; }
  const ControllerSettings& settings() const { return settings_; }
  const glm::dvec3& velocity() const { return velocity_; }
  const glm::dvec3& acceleration() const { return acceleration_; }
  const glm::dvec3& angularVelocity() const { return angularVelocity_; }
  const glm::dvec3& angularAcceleration() const { return angularAcceleration_; }

 private:
  struct Move {
    CameraPose pose;
    MotionKind kind;
    std::vector<GlidePoint> ahead;
  };
  void moveBy(const Move& move, double dtSeconds, const terrain::RenderingTileArray& array,
              const geo::Ellipsoid& ellipsoid, double clearanceMeters, CollisionState& state);
  void moveByVelocities(double dtSeconds, const terrain::RenderingTileArray& array,
                        const geo::Ellipsoid& ellipsoid, double clearanceMeters,
                        CollisionState& state);
  void describeTerrain(const terrain::RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                       CollisionState& state) const;

  ControllerSettings settings_;
  TerrainGlide glide_;
  CameraPose pose_;
  CollisionState state_;
  std::optional<Move> queued_;
  bool rejected_ = false;
  glm::dvec3 velocity_{0.0};
  glm::dvec3 acceleration_{0.0};
  glm::dvec3 angularVelocity_{0.0};
  glm::dvec3 angularAcceleration_{0.0};
};

}  // namespace globe::camera
