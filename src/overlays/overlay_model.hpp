// What an overlay file (KML/KMZ, GeoJSON, GPX) puts on the globe, as plain values: placemarks
// with their geometries and resolved styles, and ground overlays (an image over a box). The
// readers fill it (overlays/overlay_file.hpp); the draping raster, the labels and picking read it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "formats/image_io.hpp"

namespace globe::overlays {

// KML's altitudeMode (gx:altitudeMode clampToSeaFloor counts as clampToGround, relativeToSeaFloor
// as relativeToGround). GeoJSON and GPX are clampToGround.
enum class AltitudeMode : uint8_t { ClampToGround, RelativeToGround, Absolute };

struct Position {
  double longitudeDegrees = 0;
  double latitudeDegrees = 0;
  double heightMeters = 0;  // per the geometry's altitude mode; 0 when the file gives none
};

// Straight RGBA, 8 bits each (KML writes aabbggrr; readers convert).
struct Rgba {
  uint8_t r = 255, g = 255, b = 255, a = 255;
  bool operator==(const Rgba&) const = default;
};

// A placemark's style with StyleMaps resolved to their "normal" pair and inline styles merged
// over shared ones (KML's cascade); what a file does not say keeps Google Earth's defaults.
struct Style {
  Rgba lineColor{255, 255, 255, 255};
  double lineWidthPixels = 1.0;
  Rgba polygonColor{255, 255, 255, 255};
  bool fill = true;
  bool outline = true;
  // The icon as an absolute file path, "/vsizip/<absolute .kmz>/<entry>" for an image inside a
  // KMZ, an http(s) URL, or empty for the default pin.
  std::string iconHref;
  // The icon decoded by the reader when it is a local file or inside the KMZ (shared by every
  // style naming it); null for URLs, the default pin, or an image that is missing or undecodable
  // (callers warn and draw the default pin).
  std::shared_ptr<const formats::ImageRgba> iconImage;
  double iconScale = 1.0;
  Rgba iconColor{255, 255, 255, 255};
  Rgba labelColor{255, 255, 255, 255};
  double labelScale = 1.0;
};

enum class GeometryKind : uint8_t { Point, LineString, Polygon };

struct Geometry {
  GeometryKind kind = GeometryKind::Point;
  AltitudeMode altitudeMode = AltitudeMode::ClampToGround;
  bool extrude = false;     // a wall (or a stalk for a point) down to the ground
  bool tessellate = false;  // a non-clamped line follows the ground between vertices (KML)
  // Point: one position. LineString: the vertices in order. Polygon: rings[0] is the outer
  // boundary, the rest are holes; each ring closed (last == first) by the reader.
  std::vector<std::vector<Position>> rings;
};

struct Placemark {
  std::string name;
  std::string description;  // as the file gives it (KML may hold HTML)
  Style style;
  std::vector<Geometry> geometries;  // MultiGeometry flattened; a gx:Track as a LineString
  bool visible = true;               // its own <visibility> and every enclosing Folder's
  std::string folderPath;            // "Folder/Subfolder" for lists; empty at the top
};

// An image draped over a latitude/longitude box (KML GroundOverlay with LatLonBox).
struct GroundOverlay {
  std::string name;
  std::string description;
  std::shared_ptr<const formats::ImageRgba> image;  // decoded by the reader; null: not found
  std::string imageHref;                            // for messages
  double northDegrees = 0, southDegrees = 0, eastDegrees = 0, westDegrees = 0;
  double rotationDegrees = 0;      // counter-clockwise about the box's centre (KML)
  Rgba color{255, 255, 255, 255};  // modulates the image; its alpha is the overlay's opacity
  int drawOrder = 0;               // higher drawn above
  bool visible = true;
};

struct OverlayDocument {
  std::filesystem::path file;  // as given
  std::string name;            // <Document><name>, else the file's name
  std::vector<Placemark> placemarks;
  std::vector<GroundOverlay> groundOverlays;
  // What the reader left out and why, each once, naming the file (an image href outside the
  // file's folder or archive): for the program to say, never silently dropped.
  std::vector<std::string> warnings;
};

}  // namespace globe::overlays
