#include "scene/overlay_points.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "collision/height_service.hpp"
#include "geo/cartographic.hpp"
#include "geo/ecef.hpp"

namespace globe::scene {
namespace {

constexpr int kSightSamples = 32;
// Deeper than any sea floor: a sight line this far under the ellipsoid passes through the globe.
constexpr double kInsideGlobeMeters = -12000.0;

std::optional<double> surfaceHeight(const terrain::RenderingTileArray& array,
                                    const geo::Ellipsoid& ellipsoid, double longitudeRadians,
                                    double latitudeRadians) {
  const auto sample = collision::sampleHeight(array, ellipsoid, longitudeRadians, latitudeRadians,
                                              collision::HeightMode::Exact);
  if (!sample) return std::nullopt;
  return sample->heightMeters;
}

}  // namespace

std::vector<PointMark> pointMarks(
    std::span<const std::shared_ptr<const overlays::OverlayDocument>> documents) {
  std::vector<PointMark> marks;
  for (size_t d = 0; d < documents.size(); ++d) {
    if (!documents[d]) continue;
    const auto& placemarks = documents[d]->placemarks;
    for (size_t p = 0; p < placemarks.size(); ++p) {
      if (!placemarks[p].visible) continue;
      for (const overlays::Geometry& geometry : placemarks[p].geometries) {
        if (geometry.kind != overlays::GeometryKind::Point || geometry.rings.empty() ||
            geometry.rings[0].empty()) {
          continue;
        }
        marks.push_back({d, p, geometry.rings[0][0], geometry.altitudeMode});
      }
    }
  }
  return marks;
}

bool hiddenByTerrain(const glm::dvec3& cameraEcefMeters, const glm::dvec3& targetEcefMeters,
                     const terrain::RenderingTileArray& array, const geo::Ellipsoid& ellipsoid) {
  const glm::dvec3 toCamera = cameraEcefMeters - targetEcefMeters;
  const double length = glm::length(toCamera);
  if (!(length > 0)) return false;
  for (int i = 1; i <= kSightSamples; ++i) {
    // Distances from the target grow quadratically: fine steps where grazing ridges hide it.
    const double fraction = static_cast<double>(i) / kSightSamples;
    const double fromTargetMeters = length * fraction * fraction;
    if (fromTargetMeters < 0.5) continue;
    const glm::dvec3 point = targetEcefMeters + toCamera * (fromTargetMeters / length);
    const auto cartographic = geo::ecefToCartographic(ellipsoid, point);
    if (!cartographic) continue;
    if (cartographic->heightMeters < kInsideGlobeMeters) return true;
    const auto ground = surfaceHeight(array, ellipsoid, cartographic->longitudeRadians,
                                      cartographic->latitudeRadians);
    // A tolerance that grows with the distance from the target: the target itself lies on the
    // drawn surface, and the surface's own slope near it must not hide it.
    if (ground && cartographic->heightMeters < *ground - (0.5 + 0.01 * fromTargetMeters)) {
      return true;
    }
  }
  return false;
}

std::vector<ShownPoint> shownPoints(std::span<const PointMark> marks,
                                    const terrain::RenderView& view,
                                    const terrain::RenderingTileArray& array,
                                    const geo::Ellipsoid& ellipsoid) {
  std::vector<ShownPoint> shown;
  const glm::dmat4 viewProjection = view.projection * view.viewMatrix;
  for (size_t i = 0; i < marks.size(); ++i) {
    const PointMark& mark = marks[i];
    const double lon = geo::degreesToRadians(mark.position.longitudeDegrees);
    const double lat = geo::degreesToRadians(mark.position.latitudeDegrees);
    double heightMeters = mark.position.heightMeters;
    if (mark.altitudeMode != overlays::AltitudeMode::Absolute) {
      const auto ground = surfaceHeight(array, ellipsoid, lon, lat);
      if (!ground) continue;
      heightMeters = *ground + (mark.altitudeMode == overlays::AltitudeMode::RelativeToGround
                                    ? mark.position.heightMeters
                                    : 0.0);
    }
    const glm::dvec3 ecef =
        geo::cartographicToEcef(ellipsoid, geo::Cartographic{lon, lat, heightMeters});
    const glm::dvec4 clip = viewProjection * glm::dvec4(ecef, 1.0);
    if (!(clip.w > 0)) continue;
    const double ndcX = clip.x / clip.w, ndcY = clip.y / clip.w;
    if (std::abs(ndcX) > 1.1 || std::abs(ndcY) > 1.1) continue;
    if (hiddenByTerrain(view.cameraEcefMeters, ecef, array, ellipsoid)) continue;
    ShownPoint point;
    point.mark = i;
    point.anchorPixels = {(ndcX + 1.0) * 0.5 * view.widthPixels,
                          (1.0 - ndcY) * 0.5 * view.heightPixels};
    point.ecefMeters = ecef;
    point.distanceMeters = glm::length(ecef - view.cameraEcefMeters);
    shown.push_back(point);
  }
  return shown;
}

}  // namespace globe::scene
