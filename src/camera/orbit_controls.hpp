// Orbit-style camera controls for `globe view`: drag rotates the globe under the camera, tilt and
// turn change pitch and heading, zoom scales the height above the terrain. Pure math, no GLFW.
#pragma once

#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "camera/camera_pose.hpp"
#include "geo/cartographic.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::camera {

struct OrbitLimits {
  double minimumClearanceMeters = 1;  // lowest height above the terrain zoom may reach
  double maximumHeightMeters = 4e7;   // above the ellipsoid
  double maximumLatitudeRadians = geo::degreesToRadians(89);  // lon/lat motion avoids the poles
  double minimumPitchRadians = -std::numbers::pi / 2;         // straight down
  double maximumPitchRadians = 0;                             // the horizon
};

// Every input must be finite: a NaN or infinite drag, zoom or ground height is ignored (a
// non-finite home pose is replaced by the default view), so the pose stays finite.
class OrbitControls {
 public:
  OrbitControls(const geo::Ellipsoid& ellipsoid, const CameraPose& home, double fovYRadians,
                const OrbitLimits& limits = {});

  const CameraPose& pose() const { return pose_; }
  const CameraPose& home() const { return home_; }
  double groundHeightMeters() const { return groundHeightMeters_; }
  double clearanceMeters() const { return pose_.position.heightMeters - groundHeightMeters_; }

  // Moves the camera over the globe so the ground under the cursor roughly follows a drag of
  // (dx, dy) window pixels (y down) in a viewport this many pixels high.
  void rotateByDrag(double dxPixels, double dyPixels, int viewportHeightPixels);
  // Turns the heading (dx) and tilts the pitch (dy, dragging up raises the view to the horizon).
  void tiltByDrag(double dxPixels, double dyPixels);
  // Multiplies the clearance above the terrain by factor^notches (notches > 0 zooms in).
  void zoom(double notches);
  // Zooms toward (notches > 0) or away from a ground point, Google Earth's way: the camera moves
  // to 1 - factor^notches of its distance from the point and keeps its heading and pitch (north
  // up stays up), placed so the point stays under the same pixel (the cursor). Not nearer than
  // the minimum clearance; a non-finite target is ignored.
  void zoomToward(double notches, const glm::dvec3& targetEcefMeters);
  // Drags the globe so the grabbed ground point comes under the ray `rayEcef` (the unit direction
  // through the cursor from the camera now): the camera turns about the polar axis and about its
  // own east axis through the globe's centre (CesiumJS's rotate3D with the Z axis constrained),
  // so the heading is kept and north stays where it was on screen. False (the pose unchanged)
  // when the ray misses the grabbed point's sphere (the cursor left the globe).
  bool dragGrabbed(const glm::dvec3& grabbedEcefMeters, const glm::dvec3& rayEcef);
  // Turns the view to face north about the ground point at the centre (it stays there) or, with
  // no ground there, in place; the pitch is kept.
  void northUp(const std::optional<glm::dvec3>& pivotEcefMeters);
  // Turns (dx) and tilts (dy) the camera about a ground point at the centre of the view, at the
  // same distance, so that point stays at the centre (the pitch as seen from the point stays
  // between straight down and level).
  void tiltAbout(double dxPixels, double dyPixels, const glm::dvec3& pivotEcefMeters);
  void reset() { pose_ = home_; }
  // Takes the pose the collision response settled on, as it is (no clamping, so the two agree).
  void adoptPose(const CameraPose& pose) { pose_ = pose; }
  // The terrain height under the camera as the scene knows it now; lifts the camera when it is
  // less than the minimum clearance above it. Returns whether the pose changed.
  bool setGroundHeight(double groundHeightMeters);

  static constexpr double kZoomFactorPerNotch = 0.8;
  static constexpr double kTiltRadiansPerPixel = 0.005;

 private:
  void clampPose();
  // Puts the camera `distanceMeters` from the target, about along `direction` (unit, camera to
  // target), its heading and pitch kept, where it sees the target at `seen` (camera right and up
  // components of its unit direction); roll 0.
  void seeFromDistance(const glm::dvec3& targetEcefMeters, glm::dvec2 seen, double distanceMeters,
                       const glm::dvec3& direction);
  // The pose at `positionEcefMeters` looking along the unit `forward` with `up` (the unit screen
  // up, which gives the heading looking straight down) and roll 0; false (the pose unchanged)
  // when it is not finite or the position is not on the globe.
  bool lookFrom(const glm::dvec3& positionEcefMeters, const glm::dvec3& forward,
                const glm::dvec3& up);

  geo::Ellipsoid ellipsoid_;
  CameraPose home_;
  CameraPose pose_;
  double fovYRadians_;
  OrbitLimits limits_;
  double groundHeightMeters_ = 0;
};

// What the orbit limits changed in a start pose (`asked` → `started`, OrbitControls::home()), one
// sentence per field naming the value asked for and the value used; empty when nothing changed.
std::vector<std::string> describeStartClamp(const CameraPose& asked, const CameraPose& started);

}  // namespace globe::camera
