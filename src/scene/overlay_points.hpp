// Where the overlays' point placemarks show in this frame: each placed on the surface the frame
// draws (clampToGround) or at its altitude, projected to the window, and dropped when off screen,
// behind the camera, or hidden by the terrain or the globe. Pure: the caller draws the labels.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "geo/ellipsoid.hpp"
#include "overlays/overlay_model.hpp"
#include "terrain/render_view.hpp"
#include "terrain/rendering_tile_array.hpp"

namespace globe::scene {

struct PointMark {
  size_t document = 0, placemark = 0;  // where it is in the documents given
  overlays::Position position;
  overlays::AltitudeMode altitudeMode = overlays::AltitudeMode::ClampToGround;
};

// Every visible placemark's points, in file order (the labels' priority).
std::vector<PointMark> pointMarks(
    std::span<const std::shared_ptr<const overlays::OverlayDocument>> documents);

struct ShownPoint {
  size_t mark = 0;            // index into the marks given
  glm::dvec2 anchorPixels{};  // window pixels, y down from the top-left
  glm::dvec3 ecefMeters{};
  double distanceMeters = 0;
};

// The marks to draw this frame, in the order given. A clamped mark whose ground the array does
// not hold (off screen) is not shown.
std::vector<ShownPoint> shownPoints(std::span<const PointMark> marks,
                                    const terrain::RenderView& view,
                                    const terrain::RenderingTileArray& array,
                                    const geo::Ellipsoid& ellipsoid);

// Whether the terrain drawn (or the globe) hides `targetEcefMeters` from the camera: the sight
// line is sampled more densely near the target, where grazing ridges hide it.
bool hiddenByTerrain(const glm::dvec3& cameraEcefMeters, const glm::dvec3& targetEcefMeters,
                     const terrain::RenderingTileArray& array, const geo::Ellipsoid& ellipsoid);

}  // namespace globe::scene
