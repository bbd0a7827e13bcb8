// The common shots as keyframes, for path files that name a shot instead of listing keyframes:
// an orbit around a point (every frame looking at it) and a fly-to with Google Earth's arc
// (camera/fly_to.hpp's animation: a smooth start and stop, the height logarithmic with a hop for
// long ways). Both are smooth paths.
#pragma once

#include <vector>

#include "camera/camera_path_file.hpp"
#include "camera/camera_pose.hpp"

namespace globe::camera {

struct OrbitShot {
  PathTarget centre;            // the point circled and looked at
  double radiusMeters = 5000;   // the camera's distance from it along the ground
  double altitudeMeters = 2000; // the camera above the point's height
  double degrees = 360;         // the turn, clockwise seen from above when positive
  double durationSeconds = 30;
  double startBearingDegrees = 180;  // from the point to the camera at the start (south of it)
};
// One keyframe per 10° of the turn or less (at least 2), each with the centre as its target;
// the camera's height above the terrain where the centre's is.
std::vector<PathKeyframe> orbitKeyframes(const OrbitShot& shot);

struct FlyToShot {
  CameraPose from, to;  // radians
  double durationSeconds = 10;
};
// The animation sampled 4 times a second (at least 16 keyframes, at most 4,000).
std::vector<PathKeyframe> flyToKeyframes(const FlyToShot& shot);

// Google Earth's bounce fly-to mode (KML gx:flyToMode bounce, the default): the segment into
// each keyframe flagged in bounceInto starts and ends at rest (ease inOut), and one long enough
// for the fly-to to hop (its ground distance over twice the higher end) gets a keyframe at its
// middle, at the hop's height, easing in before it and out after it. Keyframes whose heights
// are not both of one kind (above the terrain or not) only ease.
std::vector<PathKeyframe> withBounceArcs(const std::vector<PathKeyframe>& keys,
                                         const std::vector<bool>& bounceInto);

}  // namespace globe::camera
