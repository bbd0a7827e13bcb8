#include "publish/terrarium_export.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "formats/image_io.hpp"
#include "formats/png_encoder.hpp"
#include "formats/webp_lossless.hpp"
#include "geo/web_mercator.hpp"
#include "publish/terrain_layer_writer.hpp"
#include "publish/tile_workers.hpp"
#include "surface/lattice_heights.hpp"
#include "surface/pyramid_surface.hpp"

namespace globe::publish {
namespace {

constexpr uint32_t kTileSize = geo::kWebMercatorTileSizePixels;
constexpr uint32_t kDeepestZoom = 22;

// The pyramid level whose vertex spacing (180° / 2^L / (N−1)) is no wider than a pixel at the
// equator (360° / 2^z / 256).
uint32_t levelForZoom(uint32_t zoom, uint32_t verticesPerSide) {
  uint32_t level = 0;
  while (180.0 / std::ldexp(1.0, static_cast<int>(level)) / (verticesPerSide - 1) >
         360.0 / std::ldexp(1.0, static_cast<int>(zoom)) / kTileSize) {
    ++level;
  }
  return level;
}

}  // namespace

std::array<uint8_t, 3> terrariumPixel(double heightMeters) {
  const double value =
      std::clamp(std::round((heightMeters + 32768.0) * 256.0), 0.0, 256.0 * 65536.0 - 1.0);
  const auto v = static_cast<uint32_t>(value);
  return {static_cast<uint8_t>(v >> 16), static_cast<uint8_t>((v >> 8) & 0xFFU),
          static_cast<uint8_t>(v & 0xFFU)};
}

std::array<uint8_t, 3> terrainRgbPixel(double heightMeters) {
  const double value =
      std::clamp(std::round((heightMeters + 10000.0) * 10.0), 0.0, 256.0 * 65536.0 - 1.0);
  const auto v = static_cast<uint32_t>(value);
  return {static_cast<uint8_t>(v >> 16), static_cast<uint8_t>((v >> 8) & 0xFFU),
          static_cast<uint8_t>(v & 0xFFU)};
}

namespace {

using PixelEncoding = std::array<uint8_t, 3> (*)(double heightMeters);

struct ElevationTile {
  uint32_t zoom = 0, x = 0, y = 0, level = 0;  // level: the pyramid level its pixels sample
  auto operator<=>(const ElevationTile&) const = default;
};

// The zoom's tiles over the pyramid's tiles of the level it samples, within the region. Where
// the pyramid has no tile that fine a client draws the zoom above (MapLibre's terrain reads a
// tile's parent where it has none), so a sparse pyramid makes a sparse tree, not the world at
// every zoom; past the pyramid's finest level nothing.
Result<std::set<ElevationTile>> zoomTiles(streaming::TerrainSource& source,
                                          const ExportRegion& region, uint32_t zoom,
                                          uint32_t level) {
  // Shrunk a little so that a tile's shared edge does not pull in the neighbour beyond it.
  constexpr double kInsetDegrees = 1e-9;
  std::set<ElevationTile> tiles;
  const double tileDegrees = 180.0 / std::ldexp(1.0, static_cast<int>(level));
  for (const geo::TileId& tile : candidateTiles(source.manifest(), level, region)) {
    auto summary = source.summary(tile);
    if (!summary) return Error{summary.error()};
    if (!*summary) continue;
    const double west = std::max(region.westDegrees, -180.0 + tile.x * tileDegrees);
    const double east = std::min(region.eastDegrees, -180.0 + (tile.x + 1) * tileDegrees);
    const double north = std::min(
        {region.northDegrees, 90.0 - tile.y * tileDegrees, geo::kWebMercatorMaxLatitudeDegrees});
    const double south = std::max({region.southDegrees, 90.0 - (tile.y + 1) * tileDegrees,
                                   -geo::kWebMercatorMaxLatitudeDegrees});
    if (!(east - west > 2 * kInsetDegrees && north - south > 2 * kInsetDegrees)) continue;
    const geo::WebMercatorTileRange range =
        geo::webMercatorTilesOf(west + kInsetDegrees, south + kInsetDegrees, east - kInsetDegrees,
                                north - kInsetDegrees, zoom);
    for (uint32_t y = range.firstY; y <= range.lastY; ++y) {
      for (uint32_t x = range.firstX; x <= range.lastX; ++x) tiles.insert({zoom, x, y, level});
    }
  }
  return tiles;
}

// A Terrarium pixel's low byte is 1/256 m, noise to deflate: the Up filter on every row and
// deflate level 1 write tiles within 1 % of the size of the adaptive filters at level 6 (119 KB
// against 118 on Fuji) in a third of the time.
constexpr formats::PngEncoding kPngEncoding{1, false};

// The tile's pixels, each the exact surface at its centre from the tile's level: RGB (a PNG
// without alpha, every pixel being opaque), RGBA for WebP's encoder.
Result<std::vector<std::byte>> makeElevationTile(surface::PyramidSurface& surface,
                                                 const ElevationTile& t, PixelEncoding encode,
                                                 bool webp) {
  const double tiles = std::ldexp(1.0, static_cast<int>(t.zoom));
  std::array<double, kTileSize> longitudes{}, latitudes{};
  for (uint32_t i = 0; i < kTileSize; ++i) {
    latitudes[i] = geo::webMercatorLatitudeRadiansOfRow(t.y + (i + 0.5) / kTileSize, t.zoom);
    longitudes[i] = ((t.x + (i + 0.5) / kTileSize) / tiles * 360 - 180) * std::numbers::pi / 180;
  }
  auto heights = surface::latticeHeightsMeters(surface, longitudes, latitudes, t.level);
  if (!heights) return Error{heights.error()};
  const size_t channels = webp ? 4 : 3;
  std::vector<uint8_t> pixels(heights->size() * channels, 255);
  for (size_t i = 0; i < heights->size(); ++i) {
    const auto pixel = encode((*heights)[i]);
    std::copy(pixel.begin(), pixel.end(), &pixels[i * channels]);
  }
  constexpr int kSide = static_cast<int>(kTileSize);
  if (!webp) return formats::encodePngRgb(pixels, kSide, kSide, kPngEncoding);
  return formats::encodeWebpLossless(formats::ImageRgba{kSide, kSide, std::move(pixels)});
}

Result<ExportReport> exportElevationPngs(streaming::TerrainSource& source,
                                         const ExportRegion& region,
                                         const std::filesystem::path& outDir,
                                         const geo::Ellipsoid& ellipsoid, PixelEncoding encode,
                                         ElevationTileFormat format, const ExportWork& work) {
  const bool webp = format == ElevationTileFormat::WebpLossless;
  const uint32_t verticesPerSide = source.manifest().verticesPerSide;
  std::vector<ElevationTile> tiles;
  for (uint32_t zoom = region.minLevel; zoom <= std::min(region.maxLevel, kDeepestZoom); ++zoom) {
    const uint32_t level = levelForZoom(zoom, verticesPerSide);
    if (level > source.manifest().maxLevel()) break;  // pixels finer than the data
    auto found = zoomTiles(source, region, zoom, level);
    if (!found) return Error{found.error()};
    tiles.insert(tiles.end(), found->begin(), found->end());
  }
  std::vector<std::unique_ptr<surface::PyramidSurface>> surfaces;
  for (unsigned w = 0; w < tileWorkerCount(tiles.size(), work.threads); ++w) {
    surfaces.push_back(std::make_unique<surface::PyramidSurface>(source, ellipsoid));
  }
  return runTileJobs(
      tiles.size(), work.threads,
      [&](unsigned worker, size_t i, ExportReport& counts) {
        const ElevationTile& t = tiles[i];
        const std::filesystem::path path = outDir / std::to_string(t.zoom) / std::to_string(t.x) /
                                           (std::to_string(t.y) + (webp ? ".webp" : ".png"));
        return writeTileOnce(
            path, [&] { return makeElevationTile(*surfaces[worker], t, encode, webp); }, counts);
      },
      work.progress);
}

}  // namespace

Result<ExportReport> exportTerrarium(streaming::TerrainSource& source, const ExportRegion& region,
                                     const std::filesystem::path& outDir,
                                     const geo::Ellipsoid& ellipsoid, ElevationTileFormat format,
                                     const ExportWork& work) {
  return exportElevationPngs(source, region, outDir, ellipsoid, terrariumPixel, format, work);
}

Result<ExportReport> exportTerrainRgb(streaming::TerrainSource& source, const ExportRegion& region,
                                      const std::filesystem::path& outDir,
                                      const geo::Ellipsoid& ellipsoid, ElevationTileFormat format,
                                      const ExportWork& work) {
  return exportElevationPngs(source, region, outDir, ellipsoid, terrainRgbPixel, format, work);
}

}  // namespace globe::publish
