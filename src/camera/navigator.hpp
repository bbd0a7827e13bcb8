// `globe view`'s navigation with no window in it: plain input events (a zoom at a pixel, a drag,
// the fly keys held) change what the user wants; once a frame update(dt) turns that into the pose
// to propose to the collision controller, and adopt() takes back the pose the controller kept.
// The ground under a pixel is found by marching the pixel's ray through a terrain height
// function (the drawn tiles in the viewer, anything in tests).
#pragma once

#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "camera/camera_controller.hpp"
#include "camera/camera_motion.hpp"
#include "camera/camera_pose.hpp"
#include "camera/fly_controls.hpp"
#include "camera/fly_to.hpp"
#include "camera/orbit_controls.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::camera {

enum class NavigationMode { Orbit, Fly };
const char* toString(NavigationMode mode);

// What update() asks the controller to do this frame.
struct NavigationProposal {
  CameraPose pose;
  MotionKind kind = MotionKind::Auto;
};

class Navigator {
 public:
  Navigator(const geo::Ellipsoid& ellipsoid, const CameraPose& start, double fovYRadians,
            TerrainHeightFunction terrainHeight);

  // The window's size in the pixels events come in (y down).
  void setViewport(int widthPixels, int heightPixels);
  NavigationMode mode() const { return mode_; }
  void toggleMode();

  // Orbit mode. Scroll: toward the ground under the pixel (that point stays under it), along the
  // view where the pixel shows sky. Keys: toward the ground at the centre.
  void zoomAt(double notches, glm::dvec2 pixel);
  void zoom(double notches);
  // Left-drag: the press grabs the ground under the pixel; each move brings it under the cursor
  // (a rotation of the globe where nothing was grabbed, as off the globe).
  void grab(glm::dvec2 pixel);
  void dragTo(glm::dvec2 pixel, double dxPixels, double dyPixels);
  void release() { grabbed_.reset(); }
  void panByKey(double dxPixels, double dyPixels);  // arrow keys: a drag of that many pixels
  // Right- or Shift-drag: tilt (dy) and turn (dx) about the ground at the centre of the view.
  // Between beginTilt (the press) and endTilt (the release) the pivot is the one the drag's first
  // step found, so the camera turns about one point however the view's centre moves over the
  // ground (near a slope it can leave it for a point kilometres away); without them each step
  // finds its own.
  void beginTilt();
  void endTilt();
  void tilt(double dxPixels, double dyPixels);

  // Both modes. A double-click flies to the ground under the pixel (false: sky there); go to
  // flies to a place (radians) and ends ~15 km away looking at it; north up turns the heading to 0
  // about the centre's ground (orbit) or levels the view facing north (fly); reset goes home.
  bool flyToPixel(glm::dvec2 pixel);
  void goTo(double longitudeRadians, double latitudeRadians);
  // Flies to a pose as it is (a saved view), taking as long as a go-to of that way.
  void flyToPose(const CameraPose& end);
  void northUp();
  void reset();

  // Fly mode: the movement keys held, mouse and arrow-key look, the speed factor.
  void setFlyKeys(const FlyKeys& keys);
  const FlyKeys& flyKeys() const { return flyKeys_; }
  void look(double dxPixels, double dyPixels);
  void lookRadians(double headingRadians, double pitchRadians);
  void changeSpeed(double notches) { speed_.change(notches); }
  const SpeedSteps& speed() const { return speed_; }

  // This frame's proposal after dtSeconds (nullopt: nothing to move), then the controller's pose.
  std::optional<NavigationProposal> update(double dtSeconds);
  void adopt(const CameraPose& pose, const CollisionState& state);

  // A fly-to or a flight is under way: keep updating.
  bool animating() const {
    return flyingTo() || (mode_ == NavigationMode::Fly && flyKeys_.moving());
  }
  bool flyingTo() const { return flyTo_.has_value(); }
  // Fly mode's speed now (the smoothed clearance while flying).
  double flySpeedMetersPerSecond() const;

  // The ground under a pixel of the current pose, and the ground distance a pixel spans at the
  // centre of the view (NaN: sky there).
  std::optional<glm::dvec3> groundAt(glm::dvec2 pixel) const;
  double metersPerPixelAtCentre() const;

  const CameraPose& pose() const { return current_; }
  const CameraPose& home() const { return controls_.home(); }
  const OrbitControls& orbit() const { return controls_; }

  // Seconds a go-to takes for a way of this length: 1 s, +1 s a decade beyond 10 km, at most 4 s.
  static double goToSeconds(double wayMeters);

 private:
  std::optional<glm::dvec3> groundAt(const CameraPose& pose, glm::dvec2 pixel) const;
  glm::dvec2 centre() const { return {widthPixels_ / 2.0, heightPixels_ / 2.0}; }
  void userMoved() { flyTo_.reset(); }
  void startFlyTo(const CameraPose& end, double seconds);

  const geo::Ellipsoid& ellipsoid_;
  double fovYRadians_;
  TerrainHeightFunction terrainHeight_;
  OrbitControls controls_;
  NavigationMode mode_ = NavigationMode::Orbit;
  int widthPixels_ = 1, heightPixels_ = 1;
  CameraPose current_;  // the controller's pose, as last adopted
  CameraPose flyLook_;  // fly mode's wanted orientation: kept when a move is stopped
  FlyKeys flyKeys_;
  SpeedSteps speed_;
  SmoothedClearance flyClearance_;  // what fly speed follows: no lurch at cliff edges
  double clearanceMeters_ = 0;      // the controller's last
  std::optional<glm::dvec3> grabbed_;
  bool tiltDragging_ = false;            // between beginTilt and endTilt
  bool tiltPivotChosen_ = false;         // the drag's first step has chosen tiltPivot_
  std::optional<glm::dvec3> tiltPivot_;  // nullopt: no ground at the centre (tilt by drag)
  std::optional<FlyToAnimation> flyTo_;
  double flyToSeconds_ = 0;  // since the fly-to started
  bool resetPending_ = false, takeLook_ = true;
};

}  // namespace globe::camera
