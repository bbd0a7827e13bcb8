#include "apps/globe/ruler_overlay.hpp"

#include <string>
#include <utility>

namespace globe::app {

std::shared_ptr<const overlays::OverlayDocument> rulerDocument(const Ruler& ruler) {
  if (ruler.points().empty()) return nullptr;
  auto document = std::make_shared<overlays::OverlayDocument>();
  document->name = "Ruler";
  overlays::Style style;
  style.lineColor = kRulerColor;
  style.lineWidthPixels = kRulerLineWidthPixels;
  style.polygonColor = {kRulerColor.r, kRulerColor.g, kRulerColor.b, 60};
  style.outline = false;  // the line is the outline
  style.iconColor = kRulerColor;
  style.iconScale = 0.5;
  style.labelScale = 0;  // no text at the points

  std::vector<overlays::Position> positions;
  for (const measure::PathPoint& p : ruler.path()) {
    positions.push_back({p.longitudeDegrees, p.latitudeDegrees, 0});
  }
  const auto placemark = [&](std::string name, overlays::GeometryKind kind,
                             std::vector<overlays::Position> ring) {
    overlays::Geometry geometry;  // clamped to the ground
    geometry.kind = kind;
    geometry.rings.push_back(std::move(ring));
    overlays::Placemark mark;
    mark.name = std::move(name);
    mark.style = style;
    mark.geometries.push_back(std::move(geometry));
    return mark;
  };
  if (positions.size() >= 2) {
    overlays::Placemark path = placemark("Ruler", overlays::GeometryKind::LineString, positions);
    if (ruler.closed()) {
      path.geometries.insert(
          path.geometries.begin(),
          placemark({}, overlays::GeometryKind::Polygon, positions).geometries.front());
    }
    document->placemarks.push_back(std::move(path));
  }
  for (size_t i = 0; i < ruler.points().size(); ++i) {
    document->placemarks.push_back(placemark("Ruler point " + std::to_string(i + 1),
                                             overlays::GeometryKind::Point, {positions[i]}));
  }
  return document;
}

std::vector<std::shared_ptr<const overlays::OverlayDocument>> withRuler(
    std::vector<std::shared_ptr<const overlays::OverlayDocument>> documents,
    const std::shared_ptr<const overlays::OverlayDocument>& ruler) {
  if (ruler) documents.push_back(ruler);
  return documents;
}

}  // namespace globe::app
