// What of the overlays lies on the ground: clamped lines and polygons and ground overlays,
// prepared once for drawing into imagery tiles (overlays/drape_raster.hpp). Longitudes are
// unwrapped along each ring, so a line across the antimeridian stays continuous (it may run past
// ±180°); each item keeps its bounding box in those unwrapped degrees.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "overlays/overlay_model.hpp"

namespace globe::overlays {

struct DegreesBox {
  double west = 0, south = 0, east = 0, north = 0;
  bool intersects(const DegreesBox& other) const {
    return west <= other.east && other.west <= east && south <= other.north && other.south <= north;
  }
};

struct DrapedShape {
  bool closed = false;  // a polygon (filled even-odd over all rings), else a line
  std::vector<std::vector<double>> ringsLonLat;  // per ring: lon0, lat0, lon1, lat1, ...
  Rgba lineColor;
  double lineWidthPixels = 1;
  Rgba fillColor;
  bool fill = false;
  bool outline = true;
  DegreesBox box;
};

// A ground overlay's image premultiplied for drawing (BGRA in native byte order, as cairo wants).
struct DrapedImage {
  std::vector<uint32_t> premultipliedArgb;
  int widthPixels = 0, heightPixels = 0;
  double north = 0, south = 0, east = 0, west = 0, rotationDegrees = 0;
  double opacity = 1;
  DegreesBox box;  // of the rotated image
};

class DrapeIndex;  // drape_index.hpp

struct DrapeSet {
  std::vector<DrapedShape> shapes;               // in drawing order: polygons first, then lines
  std::shared_ptr<const DrapeIndex> shapeIndex;  // over `shapes` (none: every shape is looked at)
  std::vector<DrapedImage> images;               // by drawOrder, drawn under the shapes
  DegreesBox bounds;                             // of everything (may run past ±180°)
  double widestLinePixels = 1;  // how far any line spills past a tile's edge, doubled
  bool empty() const { return shapes.empty() && images.empty(); }
};

// Whether a geometry is drawn on the ground: a line or polygon clamped to it (KML's default),
// whatever its tessellate flag. Lines and polygons at an altitude are drawn in 3D instead.
bool isDraped(const Geometry& geometry);

// The visible placemarks' draped geometries and the visible ground overlays with an image.
DrapeSet makeDrapeSet(std::span<const std::shared_ptr<const OverlayDocument>> documents);

}  // namespace globe::overlays
