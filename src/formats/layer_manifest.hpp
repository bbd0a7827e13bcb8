// layer.json of an imagery layer: tile size, pack size, levels and their packs, where the imagery
// came from and how its bands were read.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/result.hpp"
#include "formats/image_pack.hpp"
#include "formats/pack_format.hpp"
#include "formats/pyramid_manifest.hpp"
#include "transport/byte_source.hpp"

namespace globe::formats {

inline constexpr const char* kLayerManifestFileName = "layer.json";
// Version 2 added the edge-sample pixel grid (ImageryPixelGrid::Edges); version 1 layers are read
// as pixel-is-area.
inline constexpr uint32_t kLayerFormatVersion = 2;

// Where a tile's pixels sample the ground (S = tileSizePixels, w and h the tile's size).
enum class ImageryPixelGrid : uint8_t {
  // Pixel (r, c) covers lon [west + c·w/S, west + (c+1)·w/S] (TMS trees, version 1 layers):
  // two neighbouring tiles' textures meet between their edge pixels, which no filter blends.
  Area,
  // Pixel (r, c) is the sample at lon west + c·w/(S−1), lat north − r·h/(S−1): the first and last
  // rows and columns lie on the tile's edges, the same samples as the neighbour's, so bilinear
  // filtering is continuous from one tile's texture into the next (no colour step at tile edges).
  Edges,
};

// What a layer's tiles hold.
enum class LayerKind : uint8_t {
  Imagery,  // colour (JPEG or RGBA PNG), drawn over the terrain
  // The water fraction around each sample (8-bit grey+alpha PNG, 255 = water, 0 = land; alpha 0
  // where no input decides), from land polygons (globe-tiler water-mask): the viewer takes it as
  // the sea flag per fragment where the terrain's sources are coarser. Tiles whose descendants are
  // all water or all land end the tree: the viewer draws their ancestor, as for imagery.
  WaterMask,
};

struct ImageryLevelInfo {
  uint32_t level = 0;
  uint64_t tileCount = 0;
  BoundsDegrees bounds;       // union of the level's present tiles' rectangles
  std::vector<PackId> packs;  // the pack files of this level, sorted
};

struct ImagerySourceInfo {
  std::string path;
  std::string driver;  // GDAL's short name, or "TMS"
  int64_t columns = 0, rows = 0;
  std::string crs;          // "EPSG:32612", or the start of its WKT
  double pixelDegrees = 0;  // after warping to longitude/latitude
  BoundsDegrees bounds;     // after warping
  uint32_t finestLevel = 0;
  std::string bands;    // "RGB", "RGBA", "grey", "palette", ...
  std::string stretch;  // "" (8-bit as is), "linear MIN..MAX", "2-98% per band: ..."
  bool operator==(const ImagerySourceInfo&) const = default;
};

struct LayerManifest {
  uint32_t tileSizePixels = 256;
  uint32_t packTilesPerSide = 16;
  std::vector<ImageryLevelInfo> levels;  // levels[i].level == i, from 0 to the finest
  std::vector<ImagerySourceInfo> sources;
  BoundsDegrees bounds;         // of every level's tiles
  std::string planFingerprint;  // what globe-tiler imagery was asked to do (resume check)
  ImageryPixelGrid pixelGrid = ImageryPixelGrid::Area;
  LayerKind kind = LayerKind::Imagery;

  uint32_t maxLevel() const { return levels.empty() ? 0 : levels.back().level; }
  uint64_t tileCount() const;
};

std::string layerManifestToJson(const LayerManifest& manifest);
Result<LayerManifest> layerManifestFromJson(std::string_view text,
                                            const std::filesystem::path& path);
Result<LayerManifest> readLayerManifest(const std::filesystem::path& layerDir);
// The manifest of a layer in a directory or on a server.
Result<LayerManifest> readLayerManifest(transport::ByteSource& source);
// Through writeFileAtomically.
Result<void> writeLayerManifest(const std::filesystem::path& layerDir,
                                const LayerManifest& manifest);

}  // namespace globe::formats
