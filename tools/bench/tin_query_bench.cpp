// globe-bench-tin-query: one QOTCD height query on a TIN tile (terrain/tin_tile.hpp: the cell
// grid, the triangle under the point, its highest vertex) against the same query on a 65x65 grid
// tile (collision/qotcd_height.hpp, the paper's RSG case), both over the same real quantized-mesh
// tile (two of the Hague's AHN z15 tiles; the grid sampled from its surface) at the same 4,096
// random points.
// The goal: the TIN query within 1.5x the grid's. Run with --benchmark_repetitions=5 and
// compare the medians of one run.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>
#include <random>
#include <vector>

#include "collision/qotcd_height.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/rendering_tile_array.hpp"
#include "terrain/tin_tile.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/quantized_mesh_file.hpp"

namespace {

using namespace globe;

// Two of the Hague's z15 tiles (TMS rows from the south): 172 and ~1,000 triangles.
struct Source {
  const char* path;
  geo::TileId tile;
};
const Source kSources[] = {
    {"denhaag-ahn-octnormals/15/33550/25865.terrain", {15, 33550, 32767 - 25865}},
    {"denhaag-ahn-octnormals/15/33562/25866.terrain", {15, 33562, 32767 - 25866}},
};

struct Fixture {
  std::unique_ptr<terrain::TinTile> tin;
  std::unique_ptr<terrain::HeightBlock> block;  // where the grid tile points (never moves)
  terrain::ArrayTile grid;
  std::vector<std::pair<double, double>> points;  // radians
  size_t triangles = 0;
};

Fixture makeFixture(const Source& source) {
  Fixture made;
  const geo::TileId kTile = source.tile;
  const std::filesystem::path path =
      std::filesystem::path(GLOBE_SOURCE_DIR) / "tests/data/interop/quantized-mesh" / source.path;
  auto mesh = testing::readQuantizedMeshFile(path);
  if (!mesh) std::abort();
  const geo::GlobeRectangle rect = geo::GeographicTilingScheme::tileRectangle(kTile);
  auto tin =
      terrain::TinTile::build(rect, testing::tinVertices(*mesh), mesh->triangles, path.string());
  if (!tin) std::abort();
  made.tin = std::make_unique<terrain::TinTile>(std::move(*tin));
  made.triangles = made.tin->triangleCount();
  constexpr uint32_t kSide = 65;
  made.block = std::make_unique<terrain::HeightBlock>();
  made.block->verticesPerSide = kSide;
  for (uint32_t row = 0; row < kSide; ++row) {
    for (uint32_t column = 0; column < kSide; ++column) {
      const double lon = rect.westRadians + column * (rect.eastRadians - rect.westRadians) / 64;
      const double lat = rect.northRadians - row * (rect.northRadians - rect.southRadians) / 64;
      const auto h = made.tin->heightAt(lon, lat);
      made.block->heights.push_back(static_cast<int16_t>(std::lround(h.exactMeters)));
    }
  }
  made.grid = terrain::makeArrayTile(kTile, *made.block);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 4096; ++i) {
    made.points.emplace_back(
        rect.westRadians + u(random) * (rect.eastRadians - rect.westRadians),
        rect.southRadians + u(random) * (rect.northRadians - rect.southRadians));
  }
  return made;
}

const Fixture& fixture(int64_t index) {
  static const std::vector<Fixture> fixtures = [] {
    std::vector<Fixture> made;
    for (const Source& source : kSources) made.push_back(makeFixture(source));
    return made;
  }();
  return fixtures[static_cast<size_t>(index)];
}

void BM_GridQuery(benchmark::State& state) {
  const Fixture& f = fixture(state.range(0));
  size_t i = 0, missed = 0;
  for (auto _ : state) {
    const auto& [lon, lat] = f.points[i++ & 4095];
    const auto h = collision::qotcdTileHeight(f.grid, lon, lat);
    missed += h.heightCase == collision::HeightCase::None ? 1 : 0;
    benchmark::DoNotOptimize(h);
  }
  if (missed > 0) state.SkipWithError("the grid query read no height");
}
BENCHMARK(BM_GridQuery)->Arg(0)->Arg(1);

void BM_TinQuery(benchmark::State& state) {
  const Fixture& f = fixture(state.range(0));
  size_t i = 0, missed = 0;
  for (auto _ : state) {
    const auto& [lon, lat] = f.points[i++ & 4095];
    const auto h = f.tin->heightAt(lon, lat);
    missed += h.found ? 0 : 1;
    benchmark::DoNotOptimize(h);
  }
  if (missed > 0) state.SkipWithError("the TIN query found no triangle");
  state.counters["triangles"] = static_cast<double>(f.triangles);
  state.counters["cells_per_side"] = f.tin->cellsPerSide();
}
BENCHMARK(BM_TinQuery)->Arg(0)->Arg(1);

}  // namespace

BENCHMARK_MAIN();
