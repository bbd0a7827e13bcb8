// Land polygons from any vector file OGR opens (GeoPackage, Shapefile, FlatGeobuf, GeoJSON, ...),
// in any CRS: every polygon ring of every areal layer, in longitude/latitude.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "mask_tiling/ring_clip.hpp"

namespace globe::mask_tiling {

struct LandPolygonLayer {
  std::string path;         // the file
  std::string name;         // the layer's
  std::string driver;       // OGR's short name
  std::string crs;          // "EPSG:4326", or the start of its WKT
  std::vector<Ring> rings;  // outer and inner alike: land is their even-odd fill
  RectangleDegrees extent;  // of every ring: where this layer says what is land
  uint64_t vertices = 0;
  double medianEdgeDegrees = 0;  // the shoreline's detail (edge length, longitude · cos lat)
};

// Every layer with polygons (points and lines are skipped); errors name the file and, for bad
// coordinates, the layer and feature. A file without any polygon is an error.
Result<std::vector<LandPolygonLayer>> readLandPolygons(const std::string& path);

}  // namespace globe::mask_tiling
