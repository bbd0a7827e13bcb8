// The data's own resolution where a tile lies: the finest source of a pyramid (its sample step)
// or of an imagery layer (its texel) whose extent holds the tile's centre. It changes where the
// sources do, not with the level a tile is drawn at, so what depends on it (the relief weight,
// terrain/relief_shading.hpp) shows no step between neighbouring tiles of different levels.
#pragma once

#include <array>
#include <span>

#include "formats/layer_manifest.hpp"
#include "formats/pyramid_manifest.hpp"
#include "geo/tile_id.hpp"

namespace globe::scene {

// Degrees; NaN where no source (with a known positive step) holds the tile's centre (or the
// point). Extents are closed and may cross ±180° (west > east, or beyond ±180).
double finestStepDegreesAt(std::span<const formats::SourceInfo> sources, const geo::TileId& tile);
double finestStepDegreesAt(std::span<const formats::SourceInfo> sources, double longitudeDegrees,
                           double latitudeDegrees);
// At the tile's corners: north-west, north-east, south-west, south-east.
std::array<double, 4> finestStepDegreesAtCorners(std::span<const formats::SourceInfo> sources,
                                                 const geo::TileId& tile);
double finestTexelDegreesAt(std::span<const formats::ImagerySourceInfo> sources,
                            const geo::TileId& tile);

}  // namespace globe::scene
