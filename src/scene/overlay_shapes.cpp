#include "scene/overlay_shapes.hpp"

#include <cmath>

#include <glm/vec2.hpp>

#include "collision/height_service.hpp"
#include "geo/cartographic.hpp"
#include "geo/ecef.hpp"
#include "overlays/ring_triangulation.hpp"

namespace globe::scene {
namespace {

using overlays::AltitudeMode;
using overlays::Geometry;
using overlays::GeometryKind;

double groundMeters(const terrain::RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                    double lon, double lat) {
  const auto sample =
      collision::sampleHeight(array, ellipsoid, lon, lat, collision::HeightMode::Exact);
  return sample ? sample->heightMeters : 0.0;
}

struct Vertex {
  glm::dvec3 top, foot;
};

std::vector<Vertex> placed(const std::vector<overlays::Position>& ring, AltitudeMode mode,
                           const terrain::RenderingTileArray& array,
                           const geo::Ellipsoid& ellipsoid) {
  std::vector<Vertex> out;
  out.reserve(ring.size());
  for (const overlays::Position& p : ring) {
    const double lon = geo::degreesToRadians(p.longitudeDegrees);
    const double lat = geo::degreesToRadians(p.latitudeDegrees);
    const double ground = groundMeters(array, ellipsoid, lon, lat);
    const double height =
        mode == AltitudeMode::RelativeToGround ? ground + p.heightMeters : p.heightMeters;
    out.push_back({geo::cartographicToEcef(ellipsoid, {lon, lat, height}),
                   geo::cartographicToEcef(ellipsoid, {lon, lat, ground})});
  }
  return out;
}

void addWall(const std::vector<Vertex>& ring, const overlays::Rgba& color,
             OverlayShapes3d& shapes) {
  OverlayTriangles3d wall;
  wall.color = color;
  for (size_t i = 0; i + 1 < ring.size(); ++i) {
    const Vertex& a = ring[i];
    const Vertex& b = ring[i + 1];
    wall.ecefMeters.insert(wall.ecefMeters.end(), {a.top, a.foot, b.foot, a.top, b.foot, b.top});
  }
  if (!wall.ecefMeters.empty()) shapes.triangles.push_back(std::move(wall));
}

// A polygon's face at its altitude (a roof over extruded walls). Polygons with holes get none:
// ear clipping covers simple rings only.
void addTop(const std::vector<overlays::Position>& ring, const std::vector<Vertex>& vertices,
            const overlays::Rgba& color, OverlayShapes3d& shapes) {
  if (ring.size() < 4) return;
  std::vector<glm::dvec2> flat;
  for (size_t i = 0; i + 1 < ring.size(); ++i) {  // the closing point repeats the first
    double lon = ring[i].longitudeDegrees;
    if (!flat.empty()) lon -= 360.0 * std::round((lon - flat.back().x) / 360.0);
    flat.emplace_back(lon, ring[i].latitudeDegrees);
  }
  OverlayTriangles3d top;
  top.color = color;
  for (const size_t index : overlays::triangulateRing(flat)) {
    top.ecefMeters.push_back(vertices[index].top);
  }
  if (!top.ecefMeters.empty()) shapes.triangles.push_back(std::move(top));
}

void addLine(const std::vector<Vertex>& ring, const overlays::Style& style,
             OverlayShapes3d& shapes) {
  OverlayLine3d line;
  line.color = style.lineColor;
  line.widthPixels = style.lineWidthPixels;
  for (const Vertex& v : ring) line.ecefMeters.push_back(v.top);
  if (line.ecefMeters.size() >= 2) shapes.lines.push_back(std::move(line));
}

}  // namespace

bool hasShapes3d(std::span<const std::shared_ptr<const overlays::OverlayDocument>> documents) {
  for (const auto& document : documents) {
    if (!document) continue;
    for (const overlays::Placemark& placemark : document->placemarks) {
      if (!placemark.visible) continue;
      for (const Geometry& geometry : placemark.geometries) {
        if (geometry.altitudeMode == AltitudeMode::ClampToGround) continue;
        if (geometry.kind != GeometryKind::Point || geometry.extrude) return true;
      }
    }
  }
  return false;
}

OverlayShapes3d overlayShapes3d(
    std::span<const std::shared_ptr<const overlays::OverlayDocument>> documents,
    const terrain::RenderingTileArray& array, const geo::Ellipsoid& ellipsoid) {
  OverlayShapes3d shapes;
  for (const auto& document : documents) {
    if (!document) continue;
    for (const overlays::Placemark& placemark : document->placemarks) {
      if (!placemark.visible) continue;
      const overlays::Style& style = placemark.style;
      for (const Geometry& geometry : placemark.geometries) {
        if (geometry.altitudeMode == AltitudeMode::ClampToGround || geometry.rings.empty()) {
          continue;
        }
        if (geometry.kind == GeometryKind::Point) {
          if (!geometry.extrude || geometry.rings[0].empty()) continue;
          // A stalk from the ground up to the raised point, as Google Earth draws it.
          const auto point =
              placed({geometry.rings[0][0]}, geometry.altitudeMode, array, ellipsoid);
          shapes.lines.push_back({{point[0].foot, point[0].top}, style.lineColor, 1.0});
          continue;
        }
        const bool polygon = geometry.kind == GeometryKind::Polygon;
        if (polygon && style.fill && geometry.rings.size() == 1) {
          addTop(geometry.rings[0],
                 placed(geometry.rings[0], geometry.altitudeMode, array, ellipsoid),
                 style.polygonColor, shapes);
        }
        for (const auto& ring : geometry.rings) {
          const auto vertices = placed(ring, geometry.altitudeMode, array, ellipsoid);
          // An extruded line's wall and a polygon's sides take the polygon colour (KML).
          if (geometry.extrude && (!polygon || style.fill)) {
            addWall(vertices, style.polygonColor, shapes);
          }
          if (!polygon || style.outline) addLine(vertices, style, shapes);
        }
      }
    }
  }
  return shapes;
}

}  // namespace globe::scene
