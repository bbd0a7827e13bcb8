#include "publish/terrarium_export.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "formats/image_io.hpp"
#include "formats/webp_lossless.hpp"
#include "surface/pyramid_surface.hpp"
#include "geo/web_mercator.hpp"

namespace globe::publish {
namespace {

constexpr uint32_t kTileSize = geo::kWebMercatorTileSizePixels;

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

Result<ExportReport> exportElevationPngs(streaming::TerrainSource& source,
                                         const ExportRegion& region,
                                         const std::filesystem::path& outDir,
                                         const geo::Ellipsoid& ellipsoid, PixelEncoding encode,
                                         ElevationTileFormat format) {
  const bool webp = format == ElevationTileFormat::WebpLossless;
  surface::PyramidSurface surface(source, ellipsoid);
  ExportReport report;
  const uint32_t lastZoom = std::min(region.maxLevel, 22U);
  for (uint32_t zoom = region.minLevel; zoom <= lastZoom; ++zoom) {
    const double tiles = std::ldexp(1.0, static_cast<int>(zoom));
    const geo::WebMercatorTileRange range = geo::webMercatorTilesOf(
        region.westDegrees, region.southDegrees, region.eastDegrees, region.northDegrees, zoom);
    const uint32_t x0 = range.firstX, x1 = range.lastX, y0 = range.firstY, y1 = range.lastY;
    const uint32_t level = levelForZoom(zoom, source.manifest().verticesPerSide);
    for (uint32_t y = y0; y <= y1; ++y) {
      for (uint32_t x = x0; x <= x1; ++x) {
        const std::filesystem::path path = outDir / std::to_string(zoom) / std::to_string(x) /
                                           (std::to_string(y) + (webp ? ".webp" : ".png"));
        auto written = writeTileOnce(
            path,
            [&]() -> Result<std::vector<std::byte>> {
              formats::ImageRgba image{static_cast<int>(kTileSize), static_cast<int>(kTileSize),
                                       std::vector<uint8_t>(kTileSize * kTileSize * 4, 255)};
              for (uint32_t r = 0; r < kTileSize; ++r) {
                const double lat =
                    geo::webMercatorLatitudeRadiansOfRow(y + (r + 0.5) / kTileSize, zoom);
                for (uint32_t c = 0; c < kTileSize; ++c) {
                  const double lon =
                      ((x + (c + 0.5) / kTileSize) / tiles * 360 - 180) * std::numbers::pi / 180;
                  auto h = surface.heightMeters(lon, lat, level);
                  if (!h) return Error{h.error()};
                  const auto pixel = encode(*h);
                  std::copy(pixel.begin(), pixel.end(), &image.pixels[(r * kTileSize + c) * 4]);
                }
              }
              return webp ? formats::encodeWebpLossless(image) : formats::encodePng(image);
            },
            report);
        if (!written) return Error{written.error()};
      }
    }
  }
  return report;
}

}  // namespace

Result<ExportReport> exportTerrarium(streaming::TerrainSource& source, const ExportRegion& region,
                                     const std::filesystem::path& outDir,
                                     const geo::Ellipsoid& ellipsoid, ElevationTileFormat format) {
  return exportElevationPngs(source, region, outDir, ellipsoid, terrariumPixel, format);
}

Result<ExportReport> exportTerrainRgb(streaming::TerrainSource& source, const ExportRegion& region,
                                      const std::filesystem::path& outDir,
                                      const geo::Ellipsoid& ellipsoid, ElevationTileFormat format) {
  return exportElevationPngs(source, region, outDir, ellipsoid, terrainRgbPixel, format);
}

}  // namespace globe::publish
