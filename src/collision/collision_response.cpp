// Stop, slide and heighten, with the swept test and the contact skin.
#include "collision/collision_response.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"

namespace globe::collision {
namespace {

// A contact's triangle opposes the motion when it takes more than this fraction of it.
constexpr double kFacingTolerance = 1e-9;
// How far past a step's contact a climbing motion goes on from.
constexpr double kStepPastMeters = 0.01;

bool isFinite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool isValidPosition(const geo::Cartographic& c) {
  return std::isfinite(c.longitudeRadians) && std::isfinite(c.latitudeRadians) &&
         std::isfinite(c.heightMeters) && std::abs(c.latitudeRadians) <= std::numbers::pi / 2;
}

geo::Cartographic canonical(const geo::Cartographic& c) {
  double longitude = geo::wrapLongitudeRadians(c.longitudeRadians);
  if (longitude >= std::numbers::pi) longitude = -std::numbers::pi;
  return {longitude, c.latitudeRadians, c.heightMeters};
}

// The probe of a position against clearance - skin; where it collides, the position raised to
// surface + clearance.
struct Clamp {
  SurfaceProbe probe;
  geo::Cartographic position;
  bool raised = false;
};
Clamp clampAbove(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                 const geo::Cartographic& position, double clearanceMeters, SurfaceModel model) {
  Clamp clamp{probeSurface(array, ellipsoid, position, clearanceMeters - kContactSkinMeters, model),
              position};
  if (clamp.probe.valid) clamp.position = clamp.probe.position;
  if (clamp.probe.collided) {
    clamp.position.heightMeters = clamp.probe.surfaceHeightMeters + clearanceMeters;
    clamp.raised = true;
  }
  return clamp;
}

}  // namespace

std::string_view toString(Response response) {
  switch (response) {
    case Response::None:
      return "none";
    case Response::Stopped:
      return "stopped";
    case Response::Slid:
      return "slid";
    case Response::Heightened:
      return "heightened";
    case Response::RaisedForNewTerrain:
      return "raised-for-new-terrain";
    case Response::NearPlanePushed:
      return "near-plane-pushed";
  }
  return "unknown";
}

MotionResult respondStatic(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                           const geo::Cartographic& from, const geo::Cartographic& to,
                           double clearanceMeters, const ResponseSettings& settings) {
  MotionResult result;
  result.position = from;
  if (!isValidPosition(from) || !isValidPosition(to)) return result;
  const SurfaceProbe probe =
      probeSurface(array, ellipsoid, to, clearanceMeters - kContactSkinMeters, settings.surface);
  result.samples = 1;
  result.tilesExamined = probe.tilesExamined;
  if (!probe.valid) return result;
  result.valid = true;
  if (probe.collided) {
    result.response = Response::Stopped;
  } else {
    result.position = canonical(to);
  }
  return result;
}

MotionResult respondLinear(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                           const geo::Cartographic& from, const glm::dvec3& displacementEcefMeters,
                           double clearanceMeters, const ResponseSettings& settings) {
  MotionResult result;
  result.position = from;
  if (!isValidPosition(from) || !isFinite(displacementEcefMeters)) return result;
  const double contactClearance = clearanceMeters - kContactSkinMeters;
  const glm::dvec3 start = geo::cartographicToEcef(ellipsoid, from);
  glm::dvec3 position = start;
  bool slid = false;
  if (settings.sweep) {
    glm::dvec3 remaining = displacementEcefMeters;
    for (int k = 0; k < settings.maxSlideIterations && glm::length(remaining) > 0.0; ++k) {
      const SegmentSweep sweep =
          sweepSegment(array, ellipsoid, position, position + remaining, contactClearance,
                       settings.surface, settings.sweepSettings);
      result.samples += sweep.samples;
      result.tilesExamined += sweep.tilesExamined;
      if (!sweep.valid) return result;
      if (!sweep.hit) {
        position += remaining;
        remaining = glm::dvec3(0.0);
        break;
      }
      slid = true;
      ++result.slideIterations;
      // Stop at the contact, raised to the clearance; slide the rest along the triangle hit.
      const auto free = geo::ecefToCartographic(ellipsoid, sweep.freeEcefMeters);
      if (!free) return result;
      Clamp contact = clampAbove(array, ellipsoid, *free, clearanceMeters, settings.surface);
      result.samples += 1;
      result.tilesExamined += contact.probe.tilesExamined;
      // Back to the full clearance: the contact lies within the skin, and a slide starting there
      // touches again at once (a 20-degree descent at 10 km a frame over Angels Landing then
      // made 0.2 % of its way in a frame, tests/camera/test_wall_drive.cpp).
      if (contact.probe.valid) {
        contact.position.heightMeters = std::max(
            contact.position.heightMeters, contact.probe.surfaceHeightMeters + clearanceMeters);
      }
      position = geo::cartographicToEcef(ellipsoid, contact.position);
      if (result.slideIterations == 1) result.firstContact = contact.position;
      const glm::dvec3 normal = surfaceNormalAt(array, ellipsoid, sweep.contact.longitudeRadians,
                                                sweep.contact.latitudeRadians);
      remaining *= 1.0 - sweep.freeFraction;
      const double into = glm::dot(remaining, normal);
      result.contactNormal = normal;
      if (into < -kFacingTolerance * glm::length(remaining)) {
        remaining -= into * normal;
        continue;
      }
      // The triangle hit does not face the motion: the surface steps up there (a tile edge
      // between levels drawn at different heights, a crease finer than the sweep): climb it,
      // going on from just past the contact at the clearance there, the rest of the motion kept.
      // (Clipping against that triangle changed nothing and stopped a 10 km a frame flight for
      // good at a tile edge, tests/camera/test_wall_drive.cpp.)
      const glm::dvec3 past = geo::cartographicToEcef(ellipsoid, sweep.contact) +
                              glm::normalize(remaining) * kStepPastMeters;
      const auto pastPosition = geo::ecefToCartographic(ellipsoid, past);
      if (!pastPosition) return result;
      Clamp climbed =
          clampAbove(array, ellipsoid, *pastPosition, clearanceMeters, settings.surface);
      result.samples += 1;
      result.tilesExamined += climbed.probe.tilesExamined;
      if (climbed.probe.valid) {
        climbed.position.heightMeters = std::max(
            climbed.position.heightMeters, climbed.probe.surfaceHeightMeters + clearanceMeters);
      }
      const glm::dvec3 onTop = geo::cartographicToEcef(ellipsoid, climbed.position);
      const double along = glm::dot(onTop - position, glm::normalize(remaining));
      remaining *= std::max(0.0, 1.0 - along / glm::length(remaining));
      position = onTop;
    }
  } else {
    // The paper: test the end only; project the motion on the triangle under a colliding end.
    glm::dvec3 motion = displacementEcefMeters;
    for (int k = 0; k < settings.maxSlideIterations; ++k) {
      const auto end = geo::ecefToCartographic(ellipsoid, start + motion);
      if (!end) return result;
      const SurfaceProbe probe =
          probeSurface(array, ellipsoid, *end, contactClearance, settings.surface);
      result.samples += 1;
      result.tilesExamined += probe.tilesExamined;
      if (!probe.collided) break;
      slid = true;
      ++result.slideIterations;
      const glm::dvec3 normal = surfaceNormalAt(array, ellipsoid, probe.position.longitudeRadians,
                                                probe.position.latitudeRadians);
      result.contactNormal = normal;
      const double into = glm::dot(motion, normal);
      if (!(into < 0.0)) break;
      motion -= into * normal;
    }
    position = start + motion;
  }
  const auto end = geo::ecefToCartographic(ellipsoid, position);
  if (!end) return result;
  const Clamp clamp = clampAbove(array, ellipsoid, *end, clearanceMeters, settings.surface);
  result.samples += 1;
  result.tilesExamined += clamp.probe.tilesExamined;
  if (!clamp.probe.valid) return result;
  result.valid = true;
  result.position = clamp.position;
  if (slid || clamp.raised) result.response = Response::Slid;
  return result;
}

MotionResult respondAngular(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                            const geo::Cartographic& from, const geo::Cartographic& to,
                            double clearanceMeters, const ResponseSettings& settings) {
  MotionResult result;
  result.position = from;
  if (!isValidPosition(from) || !isValidPosition(to)) return result;
  const double contactClearance = clearanceMeters - kContactSkinMeters;
  double lift = 0.0;
  if (settings.sweep) {
    const ArcSweep sweep = sweepArc(array, ellipsoid, from, to, contactClearance, settings.surface,
                                    settings.sweepSettings);
    result.samples = sweep.samples;
    result.tilesExamined = sweep.tilesExamined;
    if (!sweep.valid) return result;
    // The sample that set the lift ends at the clearance itself, not at clearance - skin.
    if (sweep.liftMeters > 0.0) lift = sweep.liftMeters + kContactSkinMeters;
  } else {
    const SurfaceProbe probe =
        probeSurface(array, ellipsoid, to, contactClearance, settings.surface);
    result.samples = 1;
    result.tilesExamined = probe.tilesExamined;
    if (!probe.valid) return result;
    if (probe.collided) lift = probe.surfaceHeightMeters + clearanceMeters - to.heightMeters;
  }
  result.valid = true;
  result.position = canonical(to);
  if (lift > 0.0) {
    result.position.heightMeters += lift;
    result.liftMeters = lift;
    result.response = Response::Heightened;
  }
  return result;
}

}  // namespace globe::collision
