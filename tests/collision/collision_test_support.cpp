// Synthetic and real (bundled pyramid) tile arrays and random query points for collision tests.
#include "tests/collision/collision_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "tests/support/imagery_test_layers.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::collision::testing {
namespace {

using Scheme = geo::GeographicTilingScheme;

template <class T>
T pick(std::mt19937_64& rng, const std::vector<T>& values) {
  return values[std::uniform_int_distribution<size_t>(0, values.size() - 1)(rng)];
}

geo::TileId randomSchemeTile(std::mt19937_64& rng, uint32_t maxLevel) {
  const uint32_t level = std::uniform_int_distribution<uint32_t>(0, maxLevel)(rng);
  return {level, std::uniform_int_distribution<uint32_t>(0, Scheme::tilesX(level) - 1)(rng),
          std::uniform_int_distribution<uint32_t>(0, Scheme::tilesY(level) - 1)(rng)};
}

// A point exactly on an edge (or, one time in three, a corner) of the tile.
LonLat onEdge(std::mt19937_64& rng, const geo::TileId& tile) {
  const geo::GlobeRectangle r = Scheme::tileRectangle(tile);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double lon = r.westRadians + unit(rng) * r.widthRadians();
  double lat = r.southRadians + unit(rng) * r.heightRadians();
  const auto choice = rng() % 6;
  if (choice == 0 || choice == 4) lon = (rng() & 1) ? r.westRadians : r.eastRadians;
  if (choice == 1 || choice == 4) lat = (rng() & 1) ? r.southRadians : r.northRadians;
  if (choice == 2) lon = r.westRadians;
  if (choice == 3) lat = r.northRadians;
  if (choice == 5) lon = r.eastRadians, lat = r.southRadians;
  return {lon, lat};
}

}  // namespace

terrain::HeightBlock makeBlock(uint32_t verticesPerSide,
                               const std::function<int16_t(uint32_t, uint32_t)>& height) {
  terrain::HeightBlock block;
  block.verticesPerSide = verticesPerSide;
  block.heights.resize(size_t{verticesPerSide} * verticesPerSide);
  for (uint32_t i = 0; i < verticesPerSide; ++i) {
    for (uint32_t j = 0; j < verticesPerSide; ++j) {
      block.heights[size_t{i} * verticesPerSide + j] = height(i, j);
    }
  }
  return block;
}

RenderingTileArray arrayOf(const std::vector<geo::TileId>& tiles,
                           const terrain::HeightBlock& block) {
  std::vector<ArrayTile> arrayTiles;
  for (const geo::TileId& tile : tiles) arrayTiles.push_back(makeArrayTile(tile, block));
  RenderingTileArray array;
  array.assign(std::move(arrayTiles));
  return array;
}

double gridLongitude(const geo::TileId& tile, uint32_t verticesPerSide, double column) {
  const geo::GlobeRectangle r = Scheme::tileRectangle(tile);
  if (column == verticesPerSide - 1) return r.eastRadians;
  return r.westRadians + column * (r.widthRadians() / (verticesPerSide - 1));
}

double gridLatitude(const geo::TileId& tile, uint32_t verticesPerSide, double row) {
  const geo::GlobeRectangle r = Scheme::tileRectangle(tile);
  if (row == verticesPerSide - 1) return r.southRadians;
  return r.northRadians - row * (r.heightRadians() / (verticesPerSide - 1));
}

double meshVertexLongitude(const geo::TileId& tile, uint32_t verticesPerSide, uint32_t column) {
  return geo::degreesToRadians(terrain::BlockGrid{tile, verticesPerSide}.longitudeDegrees(column));
}

double meshVertexLatitude(const geo::TileId& tile, uint32_t verticesPerSide, uint32_t row) {
  return geo::degreesToRadians(terrain::BlockGrid{tile, verticesPerSide}.latitudeDegrees(row));
}

RealPyramid& RealPyramid::bundled() {
  static RealPyramid* pyramid = [] {
    auto store = streaming::TileStore::open(globe::testing::bundledPyramid());
    if (!store) {
      ADD_FAILURE() << store.error();
      std::abort();
    }
    return new RealPyramid(std::move(*store));
  }();
  return *pyramid;
}

RealPyramid& RealPyramid::zion() {
  static RealPyramid* pyramid = [] {
    auto store = streaming::TileStore::open(globe::testing::zionPyramid());
    if (!store) {
      ADD_FAILURE() << store.error();
      std::abort();
    }
    return new RealPyramid(std::move(*store));
  }();
  return *pyramid;
}

bool RealPyramid::has(const geo::TileId& tile) {
  if (!Scheme::isValid(tile)) return false;
  const auto it = exists_.find(tile);
  if (it != exists_.end()) return it->second;
  auto entry = store_->entry(tile);
  if (!entry) ADD_FAILURE() << entry.error();
  const bool present = entry && entry->has_value();
  exists_.emplace(tile, present);
  return present;
}

const terrain::HeightBlock& RealPyramid::block(const geo::TileId& tile) {
  const auto it = blocks_.find(tile);
  if (it != blocks_.end()) return it->second;
  auto loaded = store_->loadBlock(tile);
  if (!loaded) {
    ADD_FAILURE() << loaded.error();
    return blocks_.emplace(tile, terrain::HeightBlock{}).first->second;
  }
  return blocks_.emplace(tile, std::move(*loaded)).first->second;
}

RenderingTileArray RealPyramid::array(const std::vector<geo::TileId>& tiles) {
  std::vector<ArrayTile> arrayTiles;
  for (const geo::TileId& tile : tiles) arrayTiles.push_back(arrayTile(tile));
  RenderingTileArray result;
  result.assign(std::move(arrayTiles));
  EXPECT_EQ(result.rejectedTileCount(), 0u);
  return result;
}

geo::TileId RealPyramid::randomTile(std::mt19937_64& rng, uint32_t level) {
  std::vector<formats::SourceInfo> sources;
  for (const formats::SourceInfo& source : store_->manifest().sources) {
    if (source.finestLevel >= level) sources.push_back(source);
  }
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int attempt = 0; attempt < 10000 && !sources.empty(); ++attempt) {
    const formats::BoundsDegrees b = pick(rng, sources).bounds;
    const double lon = b.west + unit(rng) * (b.east - b.west);
    const double lat = std::clamp(b.south + unit(rng) * (b.north - b.south), -90.0, 90.0);
    const auto tile =
        Scheme::positionToTile(geo::degreesToRadians(lon), geo::degreesToRadians(lat), level);
    if (tile && has(*tile)) return *tile;
  }
  ADD_FAILURE() << "no tile found at level " << level;
  return {0, 0, 0};
}

std::vector<geo::TileId> tilesOfLevel(RealPyramid& pyramid, uint32_t level, double westDegrees,
                                      double southDegrees, double eastDegrees,
                                      double northDegrees) {
  const geo::GlobeRectangle area =
      geo::GlobeRectangle::fromDegrees(westDegrees, southDegrees, eastDegrees, northDegrees);
  std::vector<geo::TileId> tiles;
  for (uint32_t y = 0; y < Scheme::tilesY(level); ++y) {
    for (uint32_t x = 0; x < Scheme::tilesX(level); ++x) {
      const geo::TileId tile{level, x, y};
      if (Scheme::tileRectangle(tile).intersects(area) && pyramid.has(tile)) tiles.push_back(tile);
    }
  }
  return tiles;
}

std::vector<geo::TileId> quadtreeCut(RealPyramid& pyramid,
                                     const std::function<bool(const geo::TileId&)>& refine) {
  std::vector<geo::TileId> tiles;
  std::function<void(const geo::TileId&)> visit = [&](const geo::TileId& tile) {
    const auto children = tile.children();
    if (tile.level < geo::kMaxLevel && refine(tile) && pyramid.has(children[0])) {
      for (const geo::TileId& child : children) visit(child);
    } else {
      tiles.push_back(tile);
    }
  };
  visit({0, 0, 0});
  visit({0, 1, 0});
  return tiles;
}

LonLat randomQueryPoint(std::mt19937_64& rng, const std::vector<geo::TileId>& tiles,
                        uint32_t maxLevel, uint32_t verticesPerSide) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const uint32_t cells = verticesPerSide - 1;
  switch (rng() % 10) {
    case 0:
    case 1:  // uniform over the sphere
      return {-std::numbers::pi + 2.0 * std::numbers::pi * unit(rng),
              std::asin(2.0 * unit(rng) - 1.0)};
    case 2:
    case 3: {  // inside an array tile
      const geo::GlobeRectangle r = Scheme::tileRectangle(pick(rng, tiles));
      return {r.westRadians + unit(rng) * r.widthRadians(),
              r.southRadians + unit(rng) * r.heightRadians()};
    }
    case 4:  // edge or corner of an array tile
      return onEdge(rng, pick(rng, tiles));
    case 5:  // edge or corner of any tile, present or not
      return onEdge(rng, randomSchemeTile(rng, maxLevel));
    case 6: {  // on a mesh vertex, or on one of its grid lines
      const geo::TileId tile = pick(rng, tiles);
      const uint32_t i = static_cast<uint32_t>(rng() % (cells + 1));
      const uint32_t j = static_cast<uint32_t>(rng() % (cells + 1));
      double lon = meshVertexLongitude(tile, verticesPerSide, j);
      double lat = meshVertexLatitude(tile, verticesPerSide, i);
      if (rng() % 3 == 0)
        lon = gridLongitude(tile, verticesPerSide, std::min(j, cells - 1) + unit(rng));
      if (rng() % 3 == 0)
        lat = gridLatitude(tile, verticesPerSide, std::min(i, cells - 1) + unit(rng));
      return {lon, lat};
    }
    case 7: {  // +-180 deg, at any latitude or on an edge latitude
      const double lon = (rng() & 1) ? std::numbers::pi : -std::numbers::pi;
      if (rng() & 1) return {lon, onEdge(rng, randomSchemeTile(rng, maxLevel)).latitudeRadians};
      return {lon, std::asin(2.0 * unit(rng) - 1.0)};
    }
    case 8: {  // a pole, at any longitude (+-180 deg included)
      const double lat = (rng() & 1) ? std::numbers::pi / 2.0 : -std::numbers::pi / 2.0;
      const auto choice = rng() % 4;
      if (choice == 0) return {(rng() & 1) ? std::numbers::pi : -std::numbers::pi, lat};
      if (choice == 1) return {onEdge(rng, randomSchemeTile(rng, maxLevel)).longitudeRadians, lat};
      return {-std::numbers::pi + 2.0 * std::numbers::pi * unit(rng), lat};
    }
    default: {  // an array tile's corner, +-180 deg written either way
      const geo::GlobeRectangle r = Scheme::tileRectangle(pick(rng, tiles));
      double lon = (rng() & 1) ? r.westRadians : r.eastRadians;
      if (std::abs(lon) == std::numbers::pi && (rng() & 1)) lon = -lon;
      return {lon, (rng() & 1) ? r.southRadians : r.northRadians};
    }
  }
}

}  // namespace globe::collision::testing
