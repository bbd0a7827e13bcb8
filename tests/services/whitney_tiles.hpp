// The real USGS topo tiles over Mt Whitney read two ways (the interop PMTiles archive, its XYZ
// tree, an AVIF rewrite), compared level by level, 8 to 14, at the summit.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <numbers>

#include "geo/tiling_scheme.hpp"

namespace globe::services::testing {

// Fails where the two give different pixels or only one has a tile; the levels where both had one.
template <class Tiles>
size_t compareTilesAtWhitney(Tiles& a, Tiles& b) {
  size_t compared = 0;
  for (uint32_t level = 8; level <= 14; ++level) {
    const auto tile = geo::GeographicTilingScheme::positionToTile(
        -118.2920 * std::numbers::pi / 180, 36.5785 * std::numbers::pi / 180, level);
    EXPECT_TRUE(tile) << level;
    if (!tile) continue;
    auto imageA = a.loadImage(*tile);
    auto imageB = b.loadImage(*tile);
    EXPECT_TRUE(imageA && imageB) << (imageA ? imageB.error() : imageA.error());
    if (!imageA || !imageB) continue;
    EXPECT_EQ(imageA->has_value(), imageB->has_value()) << level;
    if (!*imageA || !*imageB) continue;
    EXPECT_EQ((*imageA)->pixels, (*imageB)->pixels) << "level " << level;
    ++compared;
  }
  return compared;
}

}  // namespace globe::services::testing
