// globe-bench-tileset-query: one collision probe (collision::probeSurface: QOTCD's broad phase,
// the narrow phase where it collides) over terrain alone against the same probe with a 3D Tiles
// tileset's height grids as the array's surface overlay (terrain/surface_overlay.hpp), at the
// same 4,096 random points over a block of six box buildings (25-70 m, made in a temporary
// folder as the tests make them) on a 65x65 terrain tile, a camera 20 m up (below most roofs: the
// probe then reads the roof). Also the surface height alone (collision::surfaceHeightAt).
// The issue's goal (55): the probe with a tileset within 1.5x terrain-only. Run with
// --benchmark_repetitions=5 and compare the medians of one run.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>
#include <random>
#include <vector>

#include "collision/surface_probe.hpp"
#include "geo/cartographic.hpp"
#include "geo/tiling_scheme.hpp"
#include "scene/tileset_overlay.hpp"
#include "terrain/rendering_tile_array.hpp"
#include "tests/tiles3d/box_tileset.hpp"
#include "tiles3d/drawn_surface.hpp"
#include "tiles3d/tileset.hpp"
#include "tiles3d/tileset_surface.hpp"

namespace {

using namespace globe;
namespace fs = std::filesystem;

constexpr double kLonDeg = 138.6, kLatDeg = 34.9;

struct Fixture {
  std::unique_ptr<terrain::HeightBlock> block;
  terrain::RenderingTileArray terrainOnly, withTileset;
  std::vector<geo::Cartographic> points;
};

// The six boxes as a frame draws them (tiles3d/drawn_surface.hpp): what collision reads.
std::shared_ptr<const tiles3d::DrawnSurface> boxBlock() {
  const fs::path dir = fs::temp_directory_path() / "globe-bench-tileset-query";
  fs::remove_all(dir);
  const double boxes[6][3] = {{0, 0, 40},  {60, 0, 70},  {120, 0, 25},
                              {0, 60, 55}, {60, 60, 30}, {120, 60, 65}};
  std::string children;
  for (int k = 0; k < 6; ++k) {
    const std::string name = "box" + std::to_string(k) + ".glb";
    tiles3d::testing::writeFile(dir / name, tiles3d::testing::boxGlb(15, 15, boxes[k][2]));
    children += std::string(k ? "," : "") +
                R"({"geometricError":0,"transform":[1,0,0,0,0,1,0,0,0,0,1,0,)" +
                std::to_string(boxes[k][0]) + "," + std::to_string(boxes[k][1]) +
                R"(,0,1],"content":{"uri":")" + name + R"("}})";
  }
  tiles3d::testing::writeFile(
      dir / "tileset.json",
      R"({"asset":{"version":"1.1"},"root":{"geometricError":10,"refine":"ADD","transform":)" +
          tiles3d::testing::transformJson(tiles3d::testing::eastNorthUp(kLonDeg, kLatDeg, 0)) +
          R"(,"children":[)" + children + "]}}");
  auto tileset = tiles3d::readTileset(dir);
  if (!tileset) std::abort();
  auto surface = tiles3d::TilesetSurface::load(*tileset, geo::Ellipsoid::wgs84());
  if (!surface) std::abort();
  fs::remove_all(dir);
  return std::make_shared<const tiles3d::DrawnSurface>(surface->drawnContents());
}

const Fixture& fixture() {
  static const Fixture made = [] {
    Fixture f;
    const auto tile = geo::GeographicTilingScheme::positionToTile(
        geo::degreesToRadians(kLonDeg), geo::degreesToRadians(kLatDeg), 12);
    if (!tile) std::abort();
    f.block = std::make_unique<terrain::HeightBlock>();
    f.block->verticesPerSide = 65;
    f.block->heights.assign(65 * 65, 3);  // flat land 3 m up
    f.terrainOnly.assign({terrain::makeArrayTile(*tile, *f.block)});
    f.withTileset.assign({terrain::makeArrayTile(*tile, *f.block)});
    f.withTileset.setOverlay(std::make_shared<scene::TilesetOverlay>(
        std::vector<std::shared_ptr<const tiles3d::DrawnSurface>>{boxBlock()}));
    std::mt19937 random(5);
    std::uniform_real_distribution<double> east(-30, 150), north(-30, 90);
    for (int i = 0; i < 4096; ++i) {
      f.points.push_back(geo::Cartographic::fromDegrees(kLonDeg + east(random) / 91343.0,
                                                        kLatDeg + north(random) / 110951.0, 20));
    }
    return f;
  }();
  return made;
}

void probe(benchmark::State& state, const terrain::RenderingTileArray& array) {
  const Fixture& f = fixture();
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  size_t i = 0, collided = 0;
  for (auto _ : state) {
    const auto p = collision::probeSurface(array, wgs84, f.points[i++ & 4095], 2.0,
                                           collision::SurfaceModel::Exact);
    collided += p.collided ? 1 : 0;
    benchmark::DoNotOptimize(p);
  }
  state.counters["collided"] = static_cast<double>(collided) / static_cast<double>(i);
}

void BM_ProbeTerrainOnly(benchmark::State& state) { probe(state, fixture().terrainOnly); }
BENCHMARK(BM_ProbeTerrainOnly);
void BM_ProbeWithTileset(benchmark::State& state) { probe(state, fixture().withTileset); }
BENCHMARK(BM_ProbeWithTileset);

void height(benchmark::State& state, const terrain::RenderingTileArray& array) {
  const Fixture& f = fixture();
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  size_t i = 0;
  for (auto _ : state) {
    const geo::Cartographic& p = f.points[i++ & 4095];
    const auto h = collision::surfaceHeightAt(array, wgs84, p.longitudeRadians, p.latitudeRadians,
                                              collision::SurfaceModel::Exact);
    benchmark::DoNotOptimize(h);
  }
}

void BM_HeightTerrainOnly(benchmark::State& state) { height(state, fixture().terrainOnly); }
BENCHMARK(BM_HeightTerrainOnly);
void BM_HeightWithTileset(benchmark::State& state) { height(state, fixture().withTileset); }
BENCHMARK(BM_HeightWithTileset);

}  // namespace

BENCHMARK_MAIN();
