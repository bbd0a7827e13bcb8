// The tilings of imagery services in one model (OGC's TileMatrixSet): per zoom, a grid of tiles
// from a top-left corner in the CRS's units (metres in Web Mercator, degrees in lon/lat), a
// resolution in those units per pixel, a tile size and the grid's extent. XYZ, TMS and WMTS
// tilings are all one of these; a quadtree tile's pixels are mapped through it exactly.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geo/web_mercator.hpp"

namespace globe::services {

enum class TileCrs { WebMercator, Geographic };

// Web Mercator's square world ends at geo::kWebMercatorMaxLatitudeDegrees, north and south.
using geo::kWebMercatorMaxLatitudeDegrees;

struct TileMatrix {
  std::string id;                   // the zoom's name in URLs (WMTS's TileMatrix)
  double originX = 0, originY = 0;  // top-left corner, CRS units (x east, y north)
  double unitsPerPixel = 0;
  uint32_t tileWidth = 256, tileHeight = 256;
  uint64_t columns = 1, rows = 1;  // the grid's tiles
};

struct TileMatrixSet {
  TileCrs crs = TileCrs::WebMercator;
  std::vector<TileMatrix> matrices;  // coarse to fine
};

// Google's XYZ tiling (EPSG:3857, one 256-pixel tile at zoom 0) up to maxZoom.
TileMatrixSet webMercatorQuad(uint32_t minZoom, uint32_t maxZoom, uint32_t tileSize = 256);
// The geographic tiling with two tiles at zoom 0 (TMS global-geodetic, EPSG:4326 XYZ).
TileMatrixSet geographicQuad(uint32_t minZoom, uint32_t maxZoom, uint32_t tileSize = 256);

// A longitude/latitude (degrees) in the set's CRS; nullopt beyond Web Mercator's latitudes.
std::optional<std::pair<double, double>> toCrs(TileCrs crs, double lonDegrees, double latDegrees);
// The CRS units a degree of longitude spans at a latitude (for choosing a zoom).
double crsUnitsPerDegree(TileCrs crs, double latDegrees);

// The coarsest matrix whose pixels are no larger than `unitsPerPixel`, else the finest.
size_t matrixFor(const TileMatrixSet& set, double unitsPerPixel);

}  // namespace globe::services
