// Raising a camera that did not move when the surface rises under it (a finer tile loaded): the
// hard floor at once, the rest of the way to the desired clearance smoothly over a few frames.
#pragma once

#include "collision/clearance_settings.hpp"
#include "collision/surface_probe.hpp"
#include "collision/terrain_array.hpp"
#include "geo/cartographic.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::collision {

struct RaiseResult {
  bool valid = false;                // false: position had no geodetic coordinates
  geo::Cartographic position{};      // the camera after this frame's raise
  bool raised = false;               // the height changed
  bool floorApplied = false;         // it was below surface + minimumEyeMeters
  double surfaceHeightMeters = 0.0;  // the model's surface under the camera
  double remainingMeters = 0.0;      // still to go to surface + eyeMeters
};

// With E the model's surface under the camera and h its height: nothing when h >= E + eye -
// kContactSkinMeters; else h' = max(h, E + minimum) (the hard floor, at once), then h' moves
// towards E + eye by min((1 - exp(-dt / timeConstant)) * gap, maxRate * dt), and snaps to it once
// less than kContactSkinMeters would be left (so it gets there, exactly, in finitely many frames).
// Longitude and latitude never change. dt <= 0 applies only the floor.
RaiseResult raiseForNewTerrain(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                               const geo::Cartographic& position, double dtSeconds,
                               const ClearanceSettings& clearance, SurfaceModel model);

}  // namespace globe::collision
