#include "overlays/drape_set.hpp"

#include "overlays/drape_index.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace globe::overlays {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

DegreesBox emptyBox() { return {kInf, kInf, -kInf, -kInf}; }

void grow(DegreesBox& box, double lon, double lat) {
  box.west = std::min(box.west, lon);
  box.east = std::max(box.east, lon);
  box.south = std::min(box.south, lat);
  box.north = std::max(box.north, lat);
}

void grow(DegreesBox& box, const DegreesBox& other) {
  if (other.west > other.east) return;
  grow(box, other.west, other.south);
  grow(box, other.east, other.north);
}

// Each step takes the shorter way round: a jump of more than 180° is a crossing of ±180°.
std::vector<double> unwrappedRing(const std::vector<Position>& ring, DegreesBox& box) {
  std::vector<double> lonLat;
  lonLat.reserve(ring.size() * 2);
  double previous = 0;
  for (size_t i = 0; i < ring.size(); ++i) {
    double lon = ring[i].longitudeDegrees;
    if (i > 0) lon -= 360.0 * std::round((lon - previous) / 360.0);
    previous = lon;
    lonLat.push_back(lon);
    lonLat.push_back(ring[i].latitudeDegrees);
    grow(box, lon, ring[i].latitudeDegrees);
  }
  return lonLat;
}

// The rotated LatLonBox's corners, rotated in degrees about its centre as Google Earth does.
DegreesBox rotatedBox(const GroundOverlay& overlay) {
  const double centreLon = 0.5 * (overlay.westDegrees + overlay.eastDegrees);
  const double centreLat = 0.5 * (overlay.southDegrees + overlay.northDegrees);
  const double angle = overlay.rotationDegrees * M_PI / 180.0;
  DegreesBox box = emptyBox();
  for (const double lon : {overlay.westDegrees, overlay.eastDegrees}) {
    for (const double lat : {overlay.southDegrees, overlay.northDegrees}) {
      const double x = lon - centreLon, y = lat - centreLat;
      grow(box, centreLon + x * std::cos(angle) - y * std::sin(angle),
           std::clamp(centreLat + x * std::sin(angle) + y * std::cos(angle), -90.0, 90.0));
    }
  }
  return box;
}

uint32_t premultiplied(const uint8_t* rgba) {
  const uint32_t a = rgba[3];
  const auto scale = [a](uint32_t c) { return (c * a + 127) / 255; };
  return (a << 24) | (scale(rgba[0]) << 16) | (scale(rgba[1]) << 8) | scale(rgba[2]);
}

std::optional<DrapedImage> drapedImage(const GroundOverlay& overlay) {
  if (!overlay.visible || !overlay.image || overlay.image->widthPixels <= 0 ||
      overlay.image->heightPixels <= 0 || !(overlay.eastDegrees > overlay.westDegrees) ||
      !(overlay.northDegrees > overlay.southDegrees)) {
    return std::nullopt;
  }
  DrapedImage image;
  image.widthPixels = overlay.image->widthPixels;
  image.heightPixels = overlay.image->heightPixels;
  const size_t count = static_cast<size_t>(image.widthPixels) * image.heightPixels;
  image.premultipliedArgb.resize(count);
  for (size_t i = 0; i < count; ++i) {
    image.premultipliedArgb[i] = premultiplied(&overlay.image->pixels[i * 4]);
  }
  image.north = overlay.northDegrees;
  image.south = overlay.southDegrees;
  image.east = overlay.eastDegrees;
  image.west = overlay.westDegrees;
  image.rotationDegrees = overlay.rotationDegrees;
  image.opacity = overlay.color.a / 255.0;
  image.box = rotatedBox(overlay);
  return image;
}

}  // namespace

bool isDraped(const Geometry& geometry) {
  return geometry.kind != GeometryKind::Point &&
         geometry.altitudeMode == AltitudeMode::ClampToGround;
}

DrapeSet makeDrapeSet(std::span<const std::shared_ptr<const OverlayDocument>> documents) {
  DrapeSet set;
  set.bounds = emptyBox();
  std::vector<DrapedShape> lines;
  std::vector<std::pair<int, DrapedImage>> images;
  for (const auto& document : documents) {
    if (!document) continue;
    for (const Placemark& placemark : document->placemarks) {
      if (!placemark.visible) continue;
      for (const Geometry& geometry : placemark.geometries) {
        if (!isDraped(geometry) || geometry.rings.empty() || geometry.rings[0].size() < 2) {
          continue;
        }
        DrapedShape shape;
        shape.closed = geometry.kind == GeometryKind::Polygon;
        shape.box = emptyBox();
        for (const auto& ring : geometry.rings) {
          if (ring.size() >= 2) shape.ringsLonLat.push_back(unwrappedRing(ring, shape.box));
        }
        shape.lineColor = placemark.style.lineColor;
        shape.lineWidthPixels = placemark.style.lineWidthPixels;
        shape.fillColor = placemark.style.polygonColor;
        shape.fill = shape.closed && placemark.style.fill;
        shape.outline = !shape.closed || placemark.style.outline;
        grow(set.bounds, shape.box);
        set.widestLinePixels = std::max(set.widestLinePixels, shape.lineWidthPixels);
        (shape.closed ? set.shapes : lines).push_back(std::move(shape));
      }
    }
    for (const GroundOverlay& overlay : document->groundOverlays) {
      if (auto image = drapedImage(overlay)) {
        grow(set.bounds, image->box);
        images.emplace_back(overlay.drawOrder, std::move(*image));
      }
    }
  }
  for (DrapedShape& line : lines) set.shapes.push_back(std::move(line));
  std::stable_sort(images.begin(), images.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& [order, image] : images) set.images.push_back(std::move(image));
  if (set.empty()) set.bounds = {};
  if (!set.shapes.empty()) set.shapeIndex = std::make_shared<const DrapeIndex>(set.shapes);
  return set;
}

}  // namespace globe::overlays
