// QOTCD on TIN tiles (terrain/tin_tile.hpp) over real quantized-mesh tiles: at many points the
// conservative height is the paper's rule (the highest vertex of the triangle under the point,
// found by testing every triangle) and never below the exact height (the triangle's plane).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <vector>

#include "formats/quantized_mesh.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/tin_clip.hpp"
#include "terrain/tin_tile.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/quantized_mesh_file.hpp"

namespace globe::terrain {
namespace {

namespace fs = std::filesystem;
const fs::path kInterop = fs::path(GLOBE_SOURCE_DIR) / "tests/data/interop/quantized-mesh";

struct Loaded {
  std::vector<TinVertex> vertices;
  std::vector<uint32_t> triangles;
};

Loaded loadTile(const fs::path& path) {
  auto mesh = globe::testing::readQuantizedMeshFile(path);
  EXPECT_TRUE(mesh) << mesh.error();
  if (!mesh) return {};
  return {globe::testing::tinVertices(*mesh), mesh->triangles};
}

// The paper's rule by brute force: every triangle holding (u, v), its plane and highest vertex
// (vertices with a weight of about 0 left out, as on a grid's rows and columns).
struct Truth {
  bool found = false;
  double exact = 0, highest = -INFINITY, highestOfAll = -INFINITY;
};
Truth bruteForce(const Loaded& t, double u, double v) {
  Truth truth;
  for (size_t k = 0; k + 2 < t.triangles.size(); k += 3) {
    const TinVertex& a = t.vertices[t.triangles[k]];
    const TinVertex& b = t.vertices[t.triangles[k + 1]];
    const TinVertex& c = t.vertices[t.triangles[k + 2]];
    const double area = (b.u - a.u) * (c.v - a.v) - (c.u - a.u) * (b.v - a.v);
    if (area == 0) continue;
    const double wa = ((b.u - u) * (c.v - v) - (c.u - u) * (b.v - v)) / area;
    const double wb = ((c.u - u) * (a.v - v) - (a.u - u) * (c.v - v)) / area;
    const double wc = 1 - wa - wb;
    if (std::min({wa, wb, wc}) < -1e-9) continue;
    truth.found = true;
    truth.exact = wa * a.heightMeters + wb * b.heightMeters + wc * c.heightMeters;
    truth.highestOfAll = std::max({a.heightMeters, b.heightMeters, c.heightMeters});
    truth.highest = -INFINITY;
    for (auto [w, h] : {std::pair{wa, a.heightMeters}, std::pair{wb, b.heightMeters},
                        std::pair{wc, c.heightMeters}}) {
      if (w > 1e-9) truth.highest = std::max(truth.highest, h);
    }
    return truth;
  }
  return truth;
}

TEST(TinTile, QotcdIsThePapersRuleAndNeverBelowTheSurfaceOnRealTins) {
  const geo::GlobeRectangle rect = geo::GlobeRectangle::fromDegrees(4.2, 52.0, 4.21, 52.01);
  size_t checked = 0, interior = 0;
  for (const char* file :
       {"denhaag-ahn-octnormals/15/33550/25865.terrain",
        "denhaag-ahn-octnormals/15/33562/25866.terrain", "texel-ahn4/15/33634/26050.terrain"}) {
    SCOPED_TRACE(file);
    if (!fs::exists(kInterop / file)) {
      ADD_FAILURE() << "missing " << file;
      continue;
    }
    const Loaded loaded = loadTile(kInterop / file);
    auto tile = TinTile::build(rect, loaded.vertices, loaded.triangles, file);
    ASSERT_TRUE(tile) << tile.error();
    EXPECT_GT(tile->triangleCount(), 50U);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 3000; ++i) {
      const double u = unit(random), v = unit(random);
      const double lon = rect.westRadians + u * (rect.eastRadians - rect.westRadians);
      const double lat = rect.southRadians + v * (rect.northRadians - rect.southRadians);
      const TinHeight h = tile->heightAt(lon, lat);
      const Truth truth = bruteForce(loaded, u, v);
      ASSERT_TRUE(h.found && truth.found) << u << "," << v;
      EXPECT_NEAR(h.exactMeters, truth.exact, 1e-6);
      EXPECT_GE(h.conservativeMeters, h.exactMeters - 1e-9);
      EXPECT_NEAR(h.conservativeMeters, truth.highest, 1e-9);
      interior += h.conservativeMeters == truth.highestOfAll ? 1 : 0;
      ++checked;
    }
    // On every vertex: that vertex's height, both ways.
    for (const TinVertex& p : loaded.vertices) {
      const TinHeight h =
          tile->heightAt(rect.westRadians + p.u * (rect.eastRadians - rect.westRadians),
                         rect.southRadians + p.v * (rect.northRadians - rect.southRadians));
      ASSERT_TRUE(h.found);
      EXPECT_NEAR(h.exactMeters, p.heightMeters, 1e-6);
      EXPECT_NEAR(h.conservativeMeters, p.heightMeters, 1e-6);
    }
  }
  EXPECT_EQ(checked, 9000U);
  EXPECT_GT(interior, 8900U);  // random points lie inside a triangle, almost never on an edge
}

TEST(TinTile, OnAnEdgeTheHigherOfItsTwoVertices) {
  // Two triangles over the unit tile split along the diagonal (0,0)-(1,1); the corners at 10,
  // 50, 20 and 90 m.
  const std::vector<TinVertex> vertices = {{0, 0, 10}, {1, 0, 50}, {1, 1, 20}, {0, 1, 90}};
  auto tile = TinTile::build(geo::GlobeRectangle{0, 0, 1, 1}, vertices, {0, 1, 2, 0, 2, 3}, "t");
  ASSERT_TRUE(tile) << tile.error();
  const TinHeight diagonal = tile->heightAt(0.5, 0.5);
  EXPECT_DOUBLE_EQ(diagonal.conservativeMeters, 20.0);  // not 50 or 90: the edge's own vertices
  EXPECT_DOUBLE_EQ(diagonal.exactMeters, 15.0);
  EXPECT_DOUBLE_EQ(tile->heightAt(0.75, 0.25).conservativeMeters, 50.0);
  EXPECT_DOUBLE_EQ(tile->heightAt(0.25, 0.75).conservativeMeters, 90.0);
  EXPECT_FALSE(tile->heightAt(1.5, 0.5).found);  // outside the tile
}

// A missing child drawn from a TIN parent is the parent's TIN clipped to its quadrant: at random
// points of each of the four children the same surface as the parent's, every point covered, and
// far fewer triangles than a 65x65 grid.
TEST(TinTile, AChildsTinIsItsParentsQuadrant) {
  const geo::TileId parentId{15, 33550, 32767 - 25865};
  const Loaded loaded = loadTile(kInterop / "denhaag-ahn-octnormals/15/33550/25865.terrain");
  auto parent = TinTile::build(geo::GeographicTilingScheme::tileRectangle(parentId),
                               loaded.vertices, loaded.triangles, "parent");
  ASSERT_TRUE(parent) << parent.error();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const geo::TileId& id : parentId.children()) {
    const auto child = childTin(*parent, id);
    ASSERT_TRUE(child) << geo::tileName(id);
    EXPECT_LT(child->triangleCount(), parent->triangleCount() + 64);
    const geo::GlobeRectangle r = geo::GeographicTilingScheme::tileRectangle(id);
    for (int i = 0; i < 500; ++i) {
      const double lon = r.westRadians + unit(random) * (r.eastRadians - r.westRadians);
      const double lat = r.southRadians + unit(random) * (r.northRadians - r.southRadians);
      const TinHeight mine = child->heightAt(lon, lat), theirs = parent->heightAt(lon, lat);
      ASSERT_TRUE(mine.found && theirs.found);
      EXPECT_NEAR(mine.exactMeters, theirs.exactMeters, 1e-6);
      EXPECT_LE(mine.conservativeMeters, theirs.conservativeMeters + 1e-6);  // never above H
    }
  }
}

TEST(TinTile, BadTinsAreClearErrors) {
  const std::vector<TinVertex> vertices = {{0, 0, 10}, {1, 0, 50}, {1, 1, 20}};
  const geo::GlobeRectangle rect{0, 0, 1, 1};
  auto past = TinTile::build(rect, vertices, {0, 1, 3}, "bad.terrain");
  ASSERT_FALSE(past);
  EXPECT_NE(past.error().find("bad.terrain"), std::string::npos) << past.error();
  EXPECT_FALSE(TinTile::build(rect, vertices, {}, "empty.terrain"));
  EXPECT_FALSE(TinTile::build(rect, vertices, {0, 1}, "partial.terrain"));
  EXPECT_FALSE(TinTile::build(rect, {{0, 0, NAN}, {1, 0, 1}, {1, 1, 1}}, {0, 1, 2}, "nan.terrain"));
  EXPECT_FALSE(TinTile::build(rect, {{0, 0, 1}, {2, 0, 1}, {1, 1, 1}}, {0, 1, 2}, "off.terrain"));
}

}  // namespace
}  // namespace globe::terrain
