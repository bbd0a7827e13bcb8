// An imagery layer (globe-tiler imagery, or any ImageryTiles) as the Web-Mercator tiles web maps
// read: an XYZ tree with tilejson.json (MapLibre, Leaflet, OpenLayers), a TMS tree with
// tilemapresource.xml (CesiumJS's TileMapServiceImageryProvider, GDAL), or one PMTiles v3 archive.
// Each 256×256 tile's pixel is the layer's colour at its centre, bilinear among the samples of
// the layer level whose texel first is no wider than the pixel at the equator (coarser where the
// layer stops, as the viewer drapes it). Tiles with no imagery are not written.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "core/result.hpp"
#include "publish/export_writes.hpp"
#include "publish/imagery_tile_encoding.hpp"
#include "streaming/imagery_tiles.hpp"

namespace globe::publish {

enum class ImageryTreeScheme { Xyz, Tms };

struct ImageryExportOptions {
  ImageryTileFormat tileFormat = ImageryTileFormat::Png;
  int quality = 85;         // JPEG and WebP
  std::string name;         // TileJSON / TMS title / PMTiles metadata; default the output's name
  std::string attribution;  // default the layer's
};

struct ImageryExportReport : ExportReport {
  uint64_t tilesEmpty = 0;     // inside the bounds but without imagery: not written
  uint64_t tilesDistinct = 0;  // PMTiles: tiles stored once however often they repeat
  uint64_t archiveBytes = 0;   // PMTiles
  uint32_t minZoom = 0, maxZoom = 0;
};

// The layer level a zoom's tiles are drawn from: the first whose texel (180° / 2^L / S) is no
// wider than the zoom's pixel at the equator (360° / 2^z / 256).
uint32_t layerLevelForZoom(uint32_t zoom, uint32_t tileSizePixels);
// The deepest zoom whose level the layer has: zooms beyond only magnify.
uint32_t finestZoomOfLayer(uint32_t maxLevel, uint32_t tileSizePixels);

// region's levels are zooms, clamped to the layer's finest (an error when none remains); its
// bounds are met with the layer's. Resumable: tiles already in `outDir` are kept; tilejson.json
// (and TMS's tilemapresource.xml) cover every run's zooms and bounds.
Result<ImageryExportReport> exportImageryTree(streaming::ImageryTiles& layer,
                                              const ExportRegion& region,
                                              const std::filesystem::path& outDir,
                                              ImageryTreeScheme scheme,
                                              const ImageryExportOptions& options);

// The same tiles as one archive, written whole (temporary, then renamed).
Result<ImageryExportReport> exportImageryPmtiles(streaming::ImageryTiles& layer,
                                                 const ExportRegion& region,
                                                 const std::filesystem::path& archive,
                                                 const ImageryExportOptions& options);

}  // namespace globe::publish
