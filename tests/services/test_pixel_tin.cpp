// The TIN of a block's Web-Mercator pixels: the pixels' bilinear surface within the tolerance
// everywhere (cliffs, a tile's edge, ±180°), the pixel centres exact, the budget kept.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <random>

#include "geo/tiling_scheme.hpp"
#include "services/pixel_tin.hpp"

namespace globe::services {
namespace {

constexpr double kPi = std::numbers::pi;

// The window a block reads at `zoom`, each pixel from `height(column, row)`.
template <typename Height>
PixelWindow windowFor(const geo::GlobeRectangle& block, uint32_t zoom, Height height) {
  PixelWindow w;
  w.worldPixels = std::ldexp(256.0, static_cast<int>(zoom));
  const PixelRange r = pixelRangeOf(block, w.worldPixels);
  w.firstColumn = r.firstColumn;
  w.firstRow = r.firstRow;
  w.columns = r.lastColumn - r.firstColumn + 1;
  w.rows = r.lastRow - r.firstRow + 1;
  for (int64_t row = r.firstRow; row <= r.lastRow; ++row) {
    for (int64_t column = r.firstColumn; column <= r.lastColumn; ++column) {
      w.heightMeters.push_back(height(column, row));
    }
  }
  return w;
}

// The bilinear surface between pixel centres at a longitude and latitude, computed here from
// the Mercator formulas.
double bilinear(const PixelWindow& w, double lon, double lat) {
  const double x = (lon / (2 * kPi) + 0.5) * w.worldPixels - 0.5;
  const double y = (0.5 - std::log(std::tan(kPi / 4 + lat / 2)) / (2 * kPi)) * w.worldPixels - 0.5;
  const auto c = static_cast<int64_t>(std::floor(x)), r = static_cast<int64_t>(std::floor(y));
  const double tx = x - static_cast<double>(c), ty = y - static_cast<double>(r);
  return (1 - ty) * ((1 - tx) * w.at(c, r) + tx * w.at(c + 1, r)) +
         ty * ((1 - tx) * w.at(c, r + 1) + tx * w.at(c + 1, r + 1));
}

// Worst |TIN − bilinear| over random points of the block and its edges and corners.
double worstDifference(const terrain::TinTile& tin, const PixelWindow& w, int count) {
  const geo::GlobeRectangle& b = tin.rectangle();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0;
  for (int k = 0; k < count; ++k) {
    double u = unit(random), v = unit(random);
    if (k % 10 == 0) u = std::round(u);                     // on the west and east edges
    if (k % 10 == 1) v = std::round(v);                     // the south and north edges
    if (k % 10 == 2) u = std::round(u), v = std::round(v);  // the corners
    const double lon = b.westRadians + u * b.widthRadians();
    const double lat = b.southRadians + v * b.heightRadians();
    const terrain::TinHeight h = tin.heightAt(lon, lat);
    EXPECT_TRUE(h.found) << u << "," << v;
    worst = std::max(worst, std::fabs(h.exactMeters - bilinear(w, lon, lat)));
    EXPECT_GE(h.conservativeMeters, h.exactMeters - 1e-9);
  }
  return worst;
}

// Cliffs: a random field of 0 m and 400 m pixels (walls and twists everywhere).
double cliffs(int64_t column, int64_t row) {
  return ((column * 7919 + row * 104729) % 5 < 2) ? 400.0 : 3.0 * static_cast<double>(row % 4);
}

TEST(PixelTin, FollowsThePixelsBilinearSurfaceAtCliffs) {
  // The Grand Canyon's level-15 block at zoom 12 (16 x 20 pixels).
  const geo::TileId id{15, 12145, 9836};
  const auto block = geo::GeographicTilingScheme::tileRectangle(id);
  const PixelWindow w = windowFor(block, 12, cliffs);
  auto tin = buildPixelTin(block, w, 0.25, "cliffs");
  ASSERT_TRUE(tin) << tin.error();
  EXPECT_LE(worstDifference(**tin, w, 20000), 0.25 + 1e-3);
  // Two triangles per pixel square would miss by up to a quarter of the twist (hundreds of
  // metres here): the cut squares are what keeps it.
  const PixelRange r = pixelRangeOf(block, w.worldPixels);
  EXPECT_GT((*tin)->triangleCount(),
            static_cast<size_t>(8 * (r.lastColumn - r.firstColumn) * (r.lastRow - r.firstRow)));
}

// Squares cut into different numbers of parts side by side share every vertex on their common
// side: each edge is two triangles' (or one's on the block's edge), so no T-junction cracks.
TEST(PixelTin, NeighbouringCutSquaresMeetWithoutTJunctions) {
  const geo::TileId id{15, 12145, 9836};
  const auto block = geo::GeographicTilingScheme::tileRectangle(id);
  auto tin = buildPixelTin(block, windowFor(block, 12, cliffs), 0.25, "cliffs");
  ASSERT_TRUE(tin) << tin.error();
  const auto& triangles = (*tin)->triangles();
  const auto& vertices = (*tin)->vertices();
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (size_t t = 0; t < triangles.size(); t += 3) {
    for (int e = 0; e < 3; ++e) {
      const uint32_t a = triangles[t + e], b = triangles[t + (e + 1) % 3];
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  }
  size_t onEdge = 0;
  for (const auto& [edge, count] : edges) {
    const terrain::TinVertex& a = vertices[edge.first];
    const terrain::TinVertex& b = vertices[edge.second];
    const bool border =
        (a.u == b.u && (a.u == 0 || a.u == 1)) || (a.v == b.v && (a.v == 0 || a.v == 1));
    EXPECT_EQ(count, border ? 1 : 2) << a.u << "," << a.v << " - " << b.u << "," << b.v;
    onEdge += border;
    if (count != (border ? 1 : 2)) break;
  }
  EXPECT_GT(onEdge, 4u);
}

TEST(PixelTin, ThePixelCentresAreVerticesWithTheirHeights) {
  const geo::TileId id{13, 3036, 2480};
  const auto block = geo::GeographicTilingScheme::tileRectangle(id);
  const PixelWindow w = windowFor(block, 12, cliffs);
  auto tin = buildPixelTin(block, w, 0.25, "centres");
  ASSERT_TRUE(tin) << tin.error();
  size_t checked = 0;
  for (int64_t row = w.firstRow + 1; row < w.firstRow + w.rows - 1; ++row) {
    for (int64_t column = w.firstColumn + 1; column < w.firstColumn + w.columns - 1; ++column) {
      const double lon = ((static_cast<double>(column) + 0.5) / w.worldPixels - 0.5) * 2 * kPi;
      const double lat =
          std::atan(std::sinh(kPi * (1 - 2 * (static_cast<double>(row) + 0.5) / w.worldPixels)));
      if (!(lon > block.westRadians && lon < block.eastRadians && lat > block.southRadians &&
            lat < block.northRadians)) {
        continue;
      }
      EXPECT_NEAR(tin.value()->heightAt(lon, lat).exactMeters, w.at(column, row), 1e-6);
      ++checked;
    }
  }
  EXPECT_GT(checked, 300u);
}

TEST(PixelTin, ABlockAtTheAntimeridianReadsAcrossIt) {
  // The last block before 180° east: its window runs past the world's last column (the caller
  // wraps it); the TIN ends exactly on the block's east edge.
  const uint32_t level = 14;
  const geo::TileId id{level, geo::GeographicTilingScheme::tilesX(level) - 1, 5000};
  const auto block = geo::GeographicTilingScheme::tileRectangle(id);
  const PixelWindow w = windowFor(block, 12, [](int64_t column, int64_t row) {
    return static_cast<double>((column * 13 + row * 29) % 50);
  });
  auto tin = buildPixelTin(block, w, 0.25, "antimeridian");
  ASSERT_TRUE(tin) << tin.error();
  EXPECT_LE(worstDifference(**tin, w, 5000), 0.25 + 1e-3);
  EXPECT_TRUE((*tin)->heightAt(kPi, block.southRadians).found);
}

TEST(PixelTin, ABudgetWidensTheToleranceInsteadOfGrowing) {
  // Walls of 30 km on every pixel: at 0.25 m each square would be cut 64 x 64.
  const geo::TileId id{12, 1000, 1500};
  const auto block = geo::GeographicTilingScheme::tileRectangle(id);
  const PixelWindow w = windowFor(block, 10, [](int64_t column, int64_t row) {
    return (column + row) % 2 == 0 ? 30000.0 : -30000.0;
  });
  auto tin = buildPixelTin(block, w, 0.25, "walls");
  ASSERT_TRUE(tin) << tin.error();
  EXPECT_LE((*tin)->vertices().size(), kMaxPixelTinVertices);
  EXPECT_GT((*tin)->vertices().size(), kMaxPixelTinVertices / 8);  // still cut, just less
}

TEST(PixelTin, APixelWithoutAHeightIsAnError) {
  const auto block = geo::GeographicTilingScheme::tileRectangle({12, 1000, 1500});
  PixelWindow w = windowFor(block, 10, [](int64_t, int64_t) { return 5.0; });
  w.heightMeters[w.heightMeters.size() / 2] = std::numeric_limits<double>::quiet_NaN();
  auto tin = buildPixelTin(block, w, 0.25, "x");
  ASSERT_FALSE(tin);
  EXPECT_NE(tin.error().find("x: a pixel without a height"), std::string::npos) << tin.error();
}

}  // namespace
}  // namespace globe::services
