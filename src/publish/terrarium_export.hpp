// A pyramid as elevation PNG tiles: DIR/{z}/{x}/{y}.png (or lossless .webp), 256×256 Web-Mercator
// XYZ, each pixel the exact surface at its centre, from the pyramid level whose vertex spacing
// first matches the pixel's; a zoom's tiles only where the pyramid has that level (a client
// draws the zoom above elsewhere), no zoom finer than the pyramid's finest level. Terrarium
// encodes (R·256 + G + B/256) − 32768 m, Mapbox's Terrain-RGB −10000 + (R·65536 + G·256 + B)·0.1 m.
// What MapLibre's raster-dem (encoding "terrarium" or "mapbox") and globe's terrarium: and
// terrain-rgb: sources read.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>

#include "core/result.hpp"
#include "geo/ellipsoid.hpp"
#include "publish/export_writes.hpp"
#include "streaming/terrain_source.hpp"

namespace globe::publish {

// The tiles' file format: WebP only lossless, since a lossy colour is another height.
enum class ElevationTileFormat { Png, WebpLossless };

// region's levels are Web-Mercator zooms here; its latitudes are clamped to the projection's.
Result<ExportReport> exportTerrarium(streaming::TerrainSource& source, const ExportRegion& region,
                                     const std::filesystem::path& outDir,
                                     const geo::Ellipsoid& ellipsoid,
                                     ElevationTileFormat format = ElevationTileFormat::Png,
                                     const ExportWork& work = {});

Result<ExportReport> exportTerrainRgb(streaming::TerrainSource& source, const ExportRegion& region,
                                      const std::filesystem::path& outDir,
                                      const geo::Ellipsoid& ellipsoid,
                                      ElevationTileFormat format = ElevationTileFormat::Png,
                                     const ExportWork& work = {});

// The Terrarium pixel of a height, rounded to 1/256 m and clamped to what the encoding holds.
std::array<uint8_t, 3> terrariumPixel(double heightMeters);
// The Terrain-RGB pixel of a height, rounded to 0.1 m and clamped to what the encoding holds.
std::array<uint8_t, 3> terrainRgbPixel(double heightMeters);

}  // namespace globe::publish
