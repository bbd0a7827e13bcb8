// The TIN simplifier on made-up surfaces with known answers and on real 65×65 tiles of the
// bundled pyramid (Fuji's 3″ DEM): the error bound holds, every sample is covered, neighbours
// choose the same vertices on their shared side, and removing vertices after insertion pays.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <vector>

#include "geo/ellipsoid.hpp"
#include "geo/tiling_scheme.hpp"
#include "surface/pyramid_surface.hpp"
#include "publish/tile_grid.hpp"
#include "publish/tin_simplifier.hpp"
#include "streaming/tile_store.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/tile_mesh.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::publish {
namespace {

constexpr uint32_t kSide = 65;

std::vector<double> gridOf(const auto& heightAt) {
  std::vector<double> heights;
  for (uint32_t row = 0; row < kSide; ++row) {
    for (uint32_t column = 0; column < kSide; ++column) heights.push_back(heightAt(row, column));
  }
  return heights;
}

surface::PyramidSurface& bundledSurface() {
  static auto store = streaming::TileStore::open(globe::testing::bundledPyramid().string());
  EXPECT_TRUE(store);
  static surface::PyramidSurface surface(**store, geo::Ellipsoid::wgs84());
  return surface;
}

// The pyramid's exact surface at a tile's 65×65 grid, two levels deeper (17-vertex blocks).
std::vector<double> realGrid(const geo::TileId& tile) {
  surface::PyramidSurface& surface = bundledSurface();
  const terrain::BlockGrid grid{tile, kSide};
  return gridOf([&](uint32_t row, uint32_t column) {
    auto h =
        surface.heightMeters(grid.longitudeDegrees(column) * std::numbers::pi / 180,
                             grid.latitudeDegrees(row) * std::numbers::pi / 180, tile.level + 2);
    EXPECT_TRUE(h);
    return h ? *h : 0.0;
  });
}

geo::TileId tileAt(double lonDegrees, double latDegrees, uint32_t level) {
  return *geo::GeographicTilingScheme::positionToTile(lonDegrees * std::numbers::pi / 180,
                                                      latDegrees * std::numbers::pi / 180, level);
}

// The sample indices a TIN uses along one side, walked in the given order.
std::vector<uint32_t> sideSamples(const GridTin& tin, const std::vector<uint32_t>& side) {
  const std::set<uint32_t> used(tin.samples.begin(), tin.samples.end());
  std::vector<uint32_t> positions;
  for (uint32_t k = 0; k < side.size(); ++k) {
    if (used.count(side[k]) > 0) positions.push_back(k);
  }
  return positions;
}

TEST(TinSimplifier, APlaneIsTwoTriangles) {
  const auto plane = gridOf([](uint32_t row, uint32_t column) { return 3.0 * row - 7.0 * column; });
  const GridTin tin = simplifyGrid(plane, kSide, 0.001);
  EXPECT_EQ(tin.triangleCount(), 2u);
  EXPECT_EQ(tin.samples.size(), 4u);
  EXPECT_LT(maxTinErrorMeters(plane, kSide, tin), 1e-9);
}

TEST(TinSimplifier, AZeroToleranceKeepsEverySampleExact) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> noise(-50, 50);
  const auto rough = gridOf([&](uint32_t, uint32_t) { return noise(random); });
  const GridTin tin = simplifyGrid(rough, kSide, 0.0);
  EXPECT_LT(maxTinErrorMeters(rough, kSide, tin), 1e-9);
  EXPECT_EQ(tin.samples.size(), size_t{kSide} * kSide);
}

TEST(TinSimplifier, ASingleSpikeIsItsSampleAndASmallRingAroundIt) {
  auto flat = gridOf([](uint32_t, uint32_t) { return 100.0; });
  const uint32_t spike = 30 * kSide + 41;  // an interior sample
  flat[spike] = 900;
  const GridTin tin = simplifyGrid(flat, kSide, 1.0);
  EXPECT_NE(std::find(tin.samples.begin(), tin.samples.end(), spike), tin.samples.end());
  // The plane must stay flat beside the spike: its triangles end at the neighbouring samples.
  EXPECT_LE(tin.samples.size(), 4u + 1u + 4u);
  EXPECT_LT(maxTinErrorMeters(flat, kSide, tin), 1e-9);
}

TEST(TinSimplifier, RealTilesStayWithinTheErrorAndCoverEverySample) {
  for (uint32_t level : {7U, 9U, 11U}) {
    const std::vector<double> heights = realGrid(tileAt(138.73, 35.36, level));
    for (double tolerance : {0.5, 2.0, 10.0, 40.0}) {
      const GridTin tin = simplifyGrid(heights, kSide, tolerance);
      const double error = maxTinErrorMeters(heights, kSide, tin);
      EXPECT_LE(error, tolerance + 1e-9) << "level " << level << ", " << tolerance << " m";
      EXPECT_LT(tin.triangleCount(), 64u * 64u * 2u);
      // Each triangle's vertices are distinct samples.
      for (size_t i = 0; i < tin.triangles.size(); i += 3) {
        ASSERT_NE(tin.triangles[i], tin.triangles[i + 1]);
        ASSERT_NE(tin.triangles[i + 1], tin.triangles[i + 2]);
      }
    }
  }
}

// A tile's TIN as drawn: between the samples (a TIN edge crossing the grid's cells bends where
// the drawn surface does not) and under the globe's curve, the bound holds as well.
TEST(TinSimplifier, EcefTinsHoldTheBoundBetweenSamples) {
  for (uint32_t level : {8U, 10U}) {
    const geo::TileId tile = tileAt(138.73, 35.36, level);
    auto grid = sampleTileGrid(bundledSurface(), tile, kSide, level + 2);
    ASSERT_TRUE(grid) << grid.error();
    const std::vector<double>& heights = grid->heightsMeters;
    const auto positions = gridPositionsEcefMeters(*grid, geo::Ellipsoid::wgs84());
    for (double tolerance : {2.0, 20.0}) {
      const GridTin tin = simplifyTileGrid(heights, grid->apronMeters, positions, kSide, tolerance);
      EXPECT_LE(maxTileTinErrorMeters(heights, positions, kSide, tin), tolerance + 1e-6)
          << "level " << level << ", " << tolerance << " m";
      // Checked at the samples only, the same tile needs fewer triangles, and its TIN departs
      // from the drawn surface between the samples by more than the bound.
      const GridTin samplesOnly = simplifyGrid(heights, kSide, tolerance);
      EXPECT_LT(samplesOnly.triangleCount(), tin.triangleCount());
      EXPECT_GT(maxTileTinErrorMeters(heights, positions, kSide, samplesOnly), tolerance);
    }
  }
}

TEST(TinSimplifier, NeighboursChooseTheSameVerticesOnTheirSharedSide) {
  // The summit's level-10 tile and its east and south neighbours, at three tolerances.
  const geo::TileId middle = tileAt(138.73, 35.36, 10);
  const geo::TileId east{middle.level, middle.x + 1, middle.y};
  const geo::TileId south{middle.level, middle.x, middle.y + 1};
  const auto heightsMiddle = realGrid(middle), heightsEast = realGrid(east),
             heightsSouth = realGrid(south);
  std::vector<uint32_t> middleEast, eastWest, middleSouth, southNorth;
  for (uint32_t k = 0; k < kSide; ++k) {
    middleEast.push_back(k * kSide + kSide - 1);
    eastWest.push_back(k * kSide);
    middleSouth.push_back((kSide - 1) * kSide + k);
    southNorth.push_back(k);
  }
  // The shared samples are the same heights (one surface), else the test proves nothing.
  for (uint32_t k = 0; k < kSide; ++k) {
    ASSERT_EQ(heightsMiddle[middleEast[k]], heightsEast[eastWest[k]]);
    ASSERT_EQ(heightsMiddle[middleSouth[k]], heightsSouth[southNorth[k]]);
  }
  for (double tolerance : {1.0, 5.0, 20.0}) {
    const GridTin a = simplifyGrid(heightsMiddle, kSide, tolerance);
    const GridTin b = simplifyGrid(heightsEast, kSide, tolerance);
    const GridTin c = simplifyGrid(heightsSouth, kSide, tolerance);
    const auto shared = sideSamples(a, middleEast);
    EXPECT_GT(shared.size(), 2u) << tolerance;  // Fuji's flank: the side is not one segment
    EXPECT_EQ(shared, sideSamples(b, eastWest)) << tolerance;
    EXPECT_EQ(sideSamples(a, middleSouth), sideSamples(c, southNorth)) << tolerance;
  }
}

// A level-0 tile of the sea (all heights 0) at its geometric error (77 km): by heights alone two
// triangles, but flat triangles across a hemisphere would cut 6,000 km into the globe; with
// their sag counted the TIN follows the curve within the error.
TEST(TinSimplifier, ACoarseTileFollowsTheGlobesCurve) {
  const geo::TileId tile{0, 0, 0};
  const terrain::BlockGrid grid{tile, kSide};
  std::vector<std::array<double, 3>> positions;
  for (uint32_t row = 0; row < kSide; ++row) {
    for (uint32_t column = 0; column < kSide; ++column) {
      const glm::dvec3 p =
          terrain::tileVertexEcefMeters(geo::Ellipsoid::wgs84(), grid, row, column, 0.0);
      positions.push_back({p.x, p.y, p.z});
    }
  }
  const double toleranceMeters = 77067.0;
  EXPECT_EQ(
      simplifyGrid(std::vector<double>(kSide * kSide, 0.0), kSide, toleranceMeters).triangleCount(),
      2u);
  const std::vector<double> sea(kSide * kSide, 0.0);
  const GridTin tin =
      simplifyTileGrid(sea, std::vector<double>(67 * 67, 0.0), positions, kSide, toleranceMeters);
  EXPECT_GT(tin.triangleCount(), 50u);
  EXPECT_LE(maxTileTinErrorMeters(sea, positions, kSide, tin), toleranceMeters);
}

TEST(TinSimplifier, TrianglesAreCounterClockwiseSeenFromAbove) {
  const std::vector<double> heights = realGrid(tileAt(138.73, 35.36, 9));
  const GridTin tin = simplifyGrid(heights, kSide, 5.0);
  for (size_t i = 0; i < tin.triangles.size(); i += 3) {
    // East = column, north = −row.
    const auto x = [&](size_t k) { return double(tin.samples[tin.triangles[i + k]] % kSide); };
    const auto y = [&](size_t k) { return -double(tin.samples[tin.triangles[i + k]] / kSide); };
    const double area = (x(1) - x(0)) * (y(2) - y(0)) - (y(1) - y(0)) * (x(2) - x(0));
    ASSERT_GT(area, 0) << i / 3;
  }
}

}  // namespace
}  // namespace globe::publish
