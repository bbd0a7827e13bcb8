// Sampling of segments and arcs with spacing tied to the terrain's vertex spacing under them.
#include "collision/swept_test.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "collision/grid_location.hpp"
#include "collision/terrain_array.hpp"
#include "geo/ecef.hpp"

namespace globe::collision {
namespace {

constexpr double kStepOverNoTileMeters = 1000.0;
constexpr double kRefineMeters = 1e-3;
constexpr int kMaximumRefinements = 64;

// The step in metres after a free sample at `probe`, whose height is raised by liftMeters.
double stepMeters(const SurfaceProbe& probe, const geo::Ellipsoid& ellipsoid,
                  double highestSurfaceMeters, double clearanceMeters, double liftMeters,
                  const SweepSettings& settings) {
  const double spacing =
      probe.tile != nullptr ? vertexSpacingMeters(*probe.tile, ellipsoid) : kStepOverNoTileMeters;
  const double margin =
      probe.position.heightMeters + liftMeters - (highestSurfaceMeters + clearanceMeters);
  return std::max({settings.spacingFraction * spacing, margin, settings.minimumStepMeters});
}

// The next parameter: the step in metres over a path of lengthMeters, at least an even share of
// the samples left.
double nextFraction(double t, double stepMeters, double lengthMeters, uint32_t samples,
                    const SweepSettings& settings) {
  const uint32_t left = settings.maximumSamples > samples ? settings.maximumSamples - samples : 1;
  const double share = (1.0 - t) / static_cast<double>(left);
  const double next = std::min(1.0, t + std::max(stepMeters / lengthMeters, share));
  return next > t ? next : 1.0;
}

// Where, strictly between t0 and t1, the ground track from a to b crosses a row or column line
// or a quad diagonal of the tile's grid (grid coordinates interpolated linearly), sorted. The
// surface along the track is linear between consecutive crossings, so probing them and the ends
// finds its highest points. Empty when there would be more than fit (a long step far above the
// terrain, or near a pole where the columns converge).
struct Crossings {
  std::array<double, 48> t{};
  size_t count = 0;
};
Crossings gridCrossings(const ArrayTile* tile, const geo::Cartographic& a,
                        const geo::Cartographic& b, double t0, double t1) {
  Crossings crossings;
  if (tile == nullptr || !hasReadableBlock(*tile)) return crossings;
  const double cells = tile->block->verticesPerSide - 1.0;
  const double cellLongitude = (tile->eastRadians - tile->westRadians) / cells;
  const double cellLatitude = (tile->northRadians - tile->southRadians) / cells;
  const double lonA = longitudeInTile(*tile, a.longitudeRadians);
  const double lonB = lonA + geo::wrapLongitudeRadians(b.longitudeRadians - a.longitudeRadians);
  const double colA = (lonA - tile->westRadians) / cellLongitude;
  const double colB = (lonB - tile->westRadians) / cellLongitude;
  const double rowA = (tile->northRadians - a.latitudeRadians) / cellLatitude;
  const double rowB = (tile->northRadians - b.latitudeRadians) / cellLatitude;
  const std::array<std::array<double, 2>, 3> lines{
      {{colA, colB}, {rowA, rowB}, {rowA - colA, rowB - colB}}};
  double total = 0.0;
  for (const auto& [x0, x1] : lines) {
    if (!std::isfinite(x0) || !std::isfinite(x1)) return crossings;
    total += std::max(0.0, std::ceil(std::max(x0, x1)) - std::floor(std::min(x0, x1)) - 1.0);
  }
  if (total > static_cast<double>(crossings.t.size() - 1)) return crossings;
  for (const auto& [x0, x1] : lines) {
    if (x0 == x1) continue;
    const double last = std::ceil(std::max(x0, x1)) - 1.0;
    for (double k = std::floor(std::min(x0, x1)) + 1.0; k <= last; k += 1.0) {
      crossings.t[crossings.count++] = t0 + (k - x0) / (x1 - x0) * (t1 - t0);
    }
  }
  std::sort(crossings.t.begin(),
            crossings.t.begin() + static_cast<std::ptrdiff_t>(crossings.count));
  return crossings;
}

glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& unitAxis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + glm::cross(unitAxis, v) * s + unitAxis * glm::dot(unitAxis, v) * (1.0 - c);
}

}  // namespace

SegmentSweep sweepSegment(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                          const glm::dvec3& fromEcefMeters, const glm::dvec3& toEcefMeters,
                          double clearanceMeters, SurfaceModel model,
                          const SweepSettings& settings) {
  SegmentSweep sweep;
  const glm::dvec3 delta = toEcefMeters - fromEcefMeters;
  const double length = glm::length(delta);
  if (!std::isfinite(length)) return sweep;
  const auto pointAt = [&](double t) {
    return t >= 1.0 ? toEcefMeters : fromEcefMeters + t * delta;
  };
  const auto probeAt = [&](double t) -> std::optional<SurfaceProbe> {
    const auto position = geo::ecefToCartographic(ellipsoid, pointAt(t));
    if (!position) return std::nullopt;
    SurfaceProbe probe = probeSurface(array, ellipsoid, *position, clearanceMeters, model);
    ++sweep.samples;
    sweep.tilesExamined += probe.tilesExamined;
    if (!probe.valid) return std::nullopt;
    return probe;
  };
  const double highest = maximumSurfaceHeightMeters(array);

  std::optional<SurfaceProbe> previous = probeAt(0.0);
  if (!previous) return sweep;
  sweep.valid = true;
  if (previous->collided) {
    sweep.hit = true;
    sweep.freeFraction = 0.0;
    sweep.freeEcefMeters = fromEcefMeters;
    sweep.contact = previous->position;
    return sweep;
  }
  double tFree = 0.0;
  while (tFree < 1.0 && length > 0.0) {
    const double step = stepMeters(*previous, ellipsoid, highest, clearanceMeters, 0.0, settings);
    const double tNext = nextFraction(tFree, step, length, sweep.samples, settings);
    const auto next = geo::ecefToCartographic(ellipsoid, pointAt(tNext));
    if (!next) {
      sweep.valid = false;
      return sweep;
    }
    Crossings visits = gridCrossings(previous->tile, previous->position, *next, tFree, tNext);
    visits.t[visits.count++] = tNext;  // room is always left: at most size() - 1 crossings
    for (size_t k = 0; k < visits.count; ++k) {
      double tHit = visits.t[k];
      std::optional<SurfaceProbe> probe = probeAt(tHit);
      if (!probe) {
        sweep.valid = false;
        return sweep;
      }
      if (!probe->collided) {
        tFree = tHit;
        previous = probe;
        continue;
      }
      // Bisection between the last free point and the first colliding one.
      geo::Cartographic contact = probe->position;
      for (int r = 0; r < kMaximumRefinements && (tHit - tFree) * length > kRefineMeters; ++r) {
        const double middle = 0.5 * (tFree + tHit);
        const std::optional<SurfaceProbe> between = probeAt(middle);
        if (!between) break;
        if (between->collided) {
          tHit = middle;
          contact = between->position;
        } else {
          tFree = middle;
        }
      }
      sweep.hit = true;
      sweep.freeFraction = tFree;
      sweep.freeEcefMeters = pointAt(tFree);
      sweep.contact = contact;
      return sweep;
    }
  }
  sweep.freeFraction = 1.0;
  sweep.freeEcefMeters = toEcefMeters;
  return sweep;
}

geo::Cartographic arcPoint(const geo::Ellipsoid& ellipsoid, const geo::Cartographic& from,
                           const geo::Cartographic& to, double t) {
  if (t <= 0.0) return from;
  if (t >= 1.0) return to;
  const glm::dvec3 n0 = geo::geodeticSurfaceNormal(ellipsoid, from);
  const glm::dvec3 n1 = geo::geodeticSurfaceNormal(ellipsoid, to);
  const glm::dvec3 cross = glm::cross(n0, n1);
  const double sine = glm::length(cross);
  const double angle = std::atan2(sine, glm::dot(n0, n1));
  glm::dvec3 axis = sine > 0.0 ? cross / sine : glm::dvec3(0.0);
  if (!(sine > 1e-12)) {
    // Parallel or antiparallel normals: any axis perpendicular to n0 will do.
    const glm::dvec3 other = std::abs(n0.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    axis = glm::normalize(glm::cross(n0, other));
  }
  const glm::dvec3 d = rotate(n0, axis, t * angle);
  const double height = from.heightMeters + t * (to.heightMeters - from.heightMeters);
  return {std::atan2(d.y, d.x), std::atan2(d.z, std::hypot(d.x, d.y)), height};
}

ArcSweep sweepArc(const RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                  const geo::Cartographic& from, const geo::Cartographic& to,
                  double clearanceMeters, SurfaceModel model, const SweepSettings& settings) {
  ArcSweep sweep;
  const glm::dvec3 n0 = geo::geodeticSurfaceNormal(ellipsoid, from);
  const glm::dvec3 n1 = geo::geodeticSurfaceNormal(ellipsoid, to);
  const double angle = std::atan2(glm::length(glm::cross(n0, n1)), glm::dot(n0, n1));
  const double length = angle * (ellipsoid.semiMajorAxisMeters +
                                 std::max(std::abs(from.heightMeters), std::abs(to.heightMeters))) +
                        std::abs(to.heightMeters - from.heightMeters);
  if (!std::isfinite(length)) return sweep;
  const double highest = maximumSurfaceHeightMeters(array);
  // The start only sets the first step; the motion's path is (0, 1].
  SurfaceProbe previous = probeSurface(array, ellipsoid, from, clearanceMeters, model);
  sweep.tilesExamined += previous.tilesExamined;
  if (!previous.valid) return sweep;
  sweep.valid = true;
  double lift = 0.0;  // carried: a sample is tested at its height + the lift so far
  double t = 0.0;
  while (t < 1.0) {
    const double step = stepMeters(previous, ellipsoid, highest, clearanceMeters, lift, settings);
    const double tNext =
        length > 0.0 ? nextFraction(t, step, length, sweep.samples, settings) : 1.0;
    const geo::Cartographic next = arcPoint(ellipsoid, from, to, tNext);
    Crossings visits = gridCrossings(previous.tile, previous.position, next, t, tNext);
    visits.t[visits.count++] = tNext;
    for (size_t k = 0; k < visits.count; ++k) {
      t = visits.t[k];
      geo::Cartographic point = arcPoint(ellipsoid, from, to, t);
      const double height = point.heightMeters;
      point.heightMeters += lift;
      const SurfaceProbe probe = probeSurface(array, ellipsoid, point, clearanceMeters, model);
      ++sweep.samples;
      sweep.tilesExamined += probe.tilesExamined;
      if (!probe.valid) {
        sweep.valid = false;
        return sweep;
      }
      if (probe.collided) {
        lift = probe.surfaceHeightMeters + clearanceMeters - height;
        sweep.deepest = probe.position;
      }
      previous = probe;
    }
  }
  sweep.liftMeters = lift;
  return sweep;
}

}  // namespace globe::collision
