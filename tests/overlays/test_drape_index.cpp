// The draped shapes' grid index: it finds every shape whose box meets a query (world-wide, across
// the antimeridian where rings run past ±180°, huge shapes and tiny ones), and tiles drawn through
// it are the tiles drawn by looking at every shape, byte for byte.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "geo/tiling_scheme.hpp"
#include "overlays/drape_index.hpp"
#include "overlays/drape_raster.hpp"
#include "overlays/drape_set.hpp"

namespace globe::overlays {
namespace {

// n shapes: small squares, a few long lines and continent-sized polygons, some past ±180°.
std::vector<DrapedShape> shapes(size_t n, uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> lon(-200.0, 200.0), lat(-89.0, 89.0), size(1e-4, 0.5);
  std::vector<DrapedShape> out;
  for (size_t i = 0; i < n; ++i) {
    const double w = lon(random), s = std::clamp(lat(random), -89.0, 88.0);
    const double d = i % 97 == 0 ? 60.0 : size(random);  // now and then a huge one
    DrapedShape shape;
    shape.closed = i % 3 != 0;
    shape.fill = shape.closed;
    shape.fillColor = {static_cast<uint8_t>(i * 37), static_cast<uint8_t>(i * 11), 200, 160};
    shape.lineColor = {20, 20, static_cast<uint8_t>(i * 5), 255};
    shape.lineWidthPixels = 1 + static_cast<double>(i % 4);
    shape.ringsLonLat = {
        {w, s, w + d, s, w + d, std::min(89.9, s + d), w, std::min(89.9, s + d), w, s}};
    shape.box = {w, s, w + d, std::min(89.9, s + d)};
    out.push_back(std::move(shape));
  }
  return out;
}

TEST(DrapeIndex, FindsEveryShapeWhoseBoxMeetsTheQuery) {
  const std::vector<DrapedShape> all = shapes(20000, 7);
  const DrapeIndex index(all);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> lon(-220.0, 220.0), lat(-90.0, 90.0), size(0.0, 20.0);
  size_t queries = 0, found = 0, looked = 0;
  for (int q = 0; q < 2000; ++q) {
    const double w = lon(random), s = lat(random),
                 d = q % 10 == 0 ? size(random) * 10 : size(random) / 50;
    const DegreesBox box{w, s, w + d, s + d};
    const std::vector<uint32_t> near = index.near(box);
    ASSERT_TRUE(std::is_sorted(near.begin(), near.end()));
    ASSERT_EQ(std::adjacent_find(near.begin(), near.end()), near.end()) << "listed twice";
    for (uint32_t i = 0; i < all.size(); ++i) {
      if (all[i].box.intersects(box)) {
        ASSERT_TRUE(std::binary_search(near.begin(), near.end(), i)) << "shape " << i << " missed";
        ++found;
      }
    }
    looked += near.size();
    ++queries;
  }
  EXPECT_GT(found, 1000u);
  // And it is an index: a query looks at a small part of the 20,000.
  EXPECT_LT(static_cast<double>(looked) / static_cast<double>(queries), 2000.0) << looked;
}

TEST(DrapeIndex, TilesDrawnThroughItEqualTilesDrawnFromEveryShape) {
  DrapeSet indexed;
  indexed.shapes = shapes(3000, 3);
  indexed.bounds = indexed.shapes.front().box;
  for (const DrapedShape& shape : indexed.shapes) {
    indexed.bounds = {std::min(indexed.bounds.west, shape.box.west),
                      std::min(indexed.bounds.south, shape.box.south),
                      std::max(indexed.bounds.east, shape.box.east),
                      std::max(indexed.bounds.north, shape.box.north)};
    indexed.widestLinePixels = std::max(indexed.widestLinePixels, shape.lineWidthPixels);
  }
  indexed.shapeIndex = std::make_shared<const DrapeIndex>(indexed.shapes);
  DrapeSet linear = indexed;
  linear.shapeIndex.reset();
  int touched = 0;
  for (const geo::TileId tile :
       {geo::TileId{0, 0, 0}, geo::TileId{0, 1, 0}, geo::TileId{3, 0, 3}, geo::TileId{3, 15, 3},
        geo::TileId{5, 63, 10}, geo::TileId{5, 0, 20}, geo::TileId{8, 300, 100},
        geo::TileId{8, 511, 128}, geo::TileId{12, 4000, 1000}}) {
    ASSERT_EQ(touchesTile(indexed, tile, 128), touchesTile(linear, tile, 128))
        << geo::tileName(tile);
    touched += touchesTile(indexed, tile, 128);
    EXPECT_EQ(drawTile(indexed, tile, 128).pixels, drawTile(linear, tile, 128).pixels)
        << geo::tileName(tile);
  }
  EXPECT_GE(touched, 5);
}

TEST(DrapeIndex, NoShapesAndShapesWithoutAreaAreHandled) {
  const DrapeIndex none(std::span<const DrapedShape>{});
  EXPECT_TRUE(none.near({-180, -90, 180, 90}).empty());
  std::vector<DrapedShape> points(3);
  for (size_t i = 0; i < points.size(); ++i) {
    points[i].box = {10.0, 20.0, 10.0, 20.0};  // all at one point: a grid of no extent
  }
  points[2].box = {NAN, 0, 1, 1};
  const DrapeIndex index(points);
  const std::vector<uint32_t> near = index.near({9.0, 19.0, 11.0, 21.0});
  EXPECT_TRUE(std::binary_search(near.begin(), near.end(), 0u));
  EXPECT_TRUE(std::binary_search(near.begin(), near.end(), 1u));
}

}  // namespace
}  // namespace globe::overlays
