// surface::latticeHeightsMeters against PyramidSurface::heightMeters at every node: Web-Mercator
// pixel centres over Fuji's 3″ blocks, over their edge (where the finest level stops and the
// parents' surface answers), over Suruga Bay's water and the open sea, nodes exactly on block
// edges and corners, across ±180°, to a pole, and a pyramid with a gap of levels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "geo/tiling_scheme.hpp"
#include "geo/web_mercator.hpp"
#include "streaming/tile_store.hpp"
#include "surface/lattice_heights.hpp"
#include "surface/pyramid_surface.hpp"
#include "terrain/block_grid.hpp"
#include "tests/support/sea_test_pyramid.hpp"
#include "tests/support/test_io_util.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::surface::lattice_test {
namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180;
constexpr double kToleranceMeters = 0.005;

struct Lattice {
  std::vector<double> longitudesRadians, latitudesRadians;
};

// A Web-Mercator tile's 256 × 256 pixel centres, as the Terrarium exporter samples them.
Lattice pixelCentres(uint32_t zoom, double lonDegrees, double latDegrees) {
  const double tiles = std::ldexp(1.0, static_cast<int>(zoom));
  const auto x = static_cast<uint32_t>((lonDegrees + 180) / 360 * tiles);
  const double lat = latDegrees * kRadiansPerDegree;
  const auto y = static_cast<uint32_t>(
      (1 - std::log(std::tan(lat) + 1 / std::cos(lat)) / std::numbers::pi) / 2 * tiles);
  Lattice lattice;
  for (uint32_t i = 0; i < 256; ++i) {
    lattice.latitudesRadians.push_back(
        geo::webMercatorLatitudeRadiansOfRow(y + (i + 0.5) / 256, zoom));
    lattice.longitudesRadians.push_back(((x + (i + 0.5) / 256) / tiles * 360 - 180) *
                                        std::numbers::pi / 180);
  }
  return lattice;
}

// Evenly spaced nodes from (west, north) by a step (degrees), count per side.
Lattice evenNodes(double westDegrees, double northDegrees, double stepDegrees, int count) {
  Lattice lattice;
  for (int i = 0; i < count; ++i) {
    lattice.longitudesRadians.push_back((westDegrees + i * stepDegrees) * kRadiansPerDegree);
    constexpr double kHalfPi = std::numbers::pi / 2;  // degrees × π/180 may round past it
    lattice.latitudesRadians.push_back(
        std::clamp((northDegrees - i * stepDegrees) * kRadiansPerDegree, -kHalfPi, kHalfPi));
  }
  return lattice;
}

// The largest difference between the lattice's heights and heightMeters' at its nodes (each
// from its own PyramidSurface, so that neither reads the other's cache).
double maxDifferenceMeters(streaming::TerrainSource& source, const Lattice& lattice,
                           uint32_t maxLevel = kFinestLevel) {
  const auto ellipsoid = geo::Ellipsoid::wgs84();
  PyramidSurface latticeSurface(source, ellipsoid), pointSurface(source, ellipsoid);
  auto heights = latticeHeightsMeters(latticeSurface, lattice.longitudesRadians,
                                      lattice.latitudesRadians, maxLevel);
  EXPECT_TRUE(heights) << heights.error();
  if (!heights) return 1e9;
  const size_t columns = lattice.longitudesRadians.size();
  EXPECT_EQ(heights->size(), columns * lattice.latitudesRadians.size());
  double largest = 0;
  for (size_t r = 0; r < lattice.latitudesRadians.size(); ++r) {
    for (size_t c = 0; c < columns; ++c) {
      auto h = pointSurface.heightMeters(lattice.longitudesRadians[c], lattice.latitudesRadians[r],
                                         maxLevel);
      EXPECT_TRUE(h) << h.error();
      if (h) largest = std::max(largest, std::abs((*heights)[r * columns + c] - *h));
    }
  }
  return largest;
}

class BundledLattice : public ::testing::Test {
 protected:
  void SetUp() override {
    auto opened = streaming::TileStore::open(globe::testing::bundledPyramid());
    ASSERT_TRUE(opened) << opened.error();
    store_ = std::move(*opened);
  }
  void expectExact(const char* what, const Lattice& lattice, uint32_t maxLevel = kFinestLevel) {
    const double d = maxDifferenceMeters(*store_, lattice, maxLevel);
    std::printf("%s: max |lattice - heightMeters| = %.3g m\n", what, d);
    RecordProperty(what, std::to_string(d));
    EXPECT_LT(d, kToleranceMeters) << what;
  }
  std::unique_ptr<streaming::TileStore> store_;
};

TEST_F(BundledLattice, TerrariumPixelsEqualThePointSurface) {
  // Zoom 11 samples level 14 (Fuji's 3″), zoom 10 level 13: inside the DEM, over its west edge
  // at 138° (the parents' surface beyond), over Suruga Bay (water at 0 m).
  expectExact("fuji z11", pixelCentres(11, 138.73, 35.36), 14);
  expectExact("fuji z10", pixelCentres(10, 138.75, 35.35), 13);
  expectExact("fuji west edge z11", pixelCentres(11, 138.0, 35.5), 14);
  expectExact("suruga bay z11", pixelCentres(11, 138.6, 34.95), 14);
  // Zoom 3 samples level 6, ETOPO20's finest: the western Pacific, sea and land.
  expectExact("pacific z3", pixelCentres(3, 150.0, 30.0), 6);
  expectExact("finest everywhere z8", pixelCentres(8, 138.5, 35.5));
}

TEST_F(BundledLattice, NodesOnBlockEdgesAndCornersAcrossTheAntimeridianAndAtAPole) {
  // Level 14's vertex spacing (180° / 2^14 / 16): every 16th node lies on a block edge, the
  // rest on vertices; and half a spacing off, inside cells.
  const double spacing = terrain::vertexSpacingDegrees(14, 17);
  const double west = -180 + std::floor((138.5 + 180) / spacing / 16) * 16 * spacing;
  const double north = 90 - std::floor((90 - 35.5) / spacing / 16) * 16 * spacing;
  expectExact("block edges", evenNodes(west, north, spacing, 49), 14);
  expectExact("cell centres", evenNodes(west + spacing / 2, north - spacing / 2, spacing, 48), 14);
  // 179.5° to 180.5° (wrapped to -179.5°) around Fiji, and from 80° N to the north pole.
  expectExact("antimeridian", evenNodes(179.5, -16.0, 1.0 / 64, 65));
  expectExact("to the pole", evenNodes(-10.0, 90.0, 10.0 / 64, 65));
  expectExact("to the south pole", evenNodes(20.0, -80.0, 10.0 / 64, 65));
}

TEST(SeaLattice, WaterMixedTilesAndAGapOfLevels) {
  globe::testing::TempDir dir;
  ASSERT_TRUE(globe::testing::writeSeaTestPyramid(dir.path()));
  auto store = streaming::TileStore::open(dir.path());
  ASSERT_TRUE(store) << store.error();
  const auto rect = geo::GeographicTilingScheme::tileRectangle(globe::testing::kSeaTile);
  const double west = rect.westRadians / kRadiansPerDegree;
  const double north = rect.northRadians / kRadiansPerDegree;
  const double step = (rect.eastRadians - rect.westRadians) / kRadiansPerDegree / 40;
  // Both tiles of level 10 (open sea, mixed land and water) and around them level 0's.
  for (const uint32_t maxLevel : {kFinestLevel, 9u}) {
    const double d = maxDifferenceMeters(
        **store, evenNodes(west - 10 * step, north + 10 * step, step, 100), maxLevel);
    std::printf("sea pyramid, max level %u: max |lattice - heightMeters| = %.3g m\n", maxLevel, d);
    EXPECT_LT(d, kToleranceMeters) << maxLevel;
  }
}

}  // namespace
}  // namespace globe::surface::lattice_test
