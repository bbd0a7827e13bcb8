// globe-bench-drape-index: one imagery tile of draped overlays drawn through the shapes' grid index
// against the same tile drawn by testing every shape's box (the drawing before the index), for
// 1,000 to 100,000 parcels over one degree square (a city's cadastre). Run with
// --benchmark_repetitions=5 and compare the medians of one run.
#include <benchmark/benchmark.h>

#include <memory>
#include <random>
#include <vector>

#include "geo/cartographic.hpp"
#include "geo/tiling_scheme.hpp"
#include "overlays/drape_index.hpp"
#include "overlays/drape_raster.hpp"
#include "overlays/drape_set.hpp"

namespace {

using namespace globe::overlays;

DrapeSet parcels(size_t n) {
  std::mt19937 random(42);
  std::uniform_real_distribution<double> offset(0.0, 1.0), size(0.0005, 0.002);
  DrapeSet set;
  set.bounds = {10.0, 45.0, 11.0, 46.0};
  for (size_t i = 0; i < n; ++i) {
    const double w = 10.0 + offset(random), s = 45.0 + offset(random), d = size(random);
    DrapedShape shape;
    shape.closed = true;
    shape.fill = true;
    shape.fillColor = {200, 120, 40, 128};
    shape.ringsLonLat = {{w, s, w + d, s, w + d, s + d, w, s + d, w, s}};
    shape.box = {w, s, w + d, s + d};
    set.shapes.push_back(std::move(shape));
  }
  set.shapeIndex = std::make_shared<const DrapeIndex>(set.shapes);
  return set;
}

void BM_DrapeTile(benchmark::State& state) {
  DrapeSet set = parcels(static_cast<size_t>(state.range(0)));
  if (state.range(1) == 0) set.shapeIndex.reset();
  // A level-14 tile inside the square (0.011 degrees on a side): the tiles a close view draws.
  const auto tile = globe::geo::GeographicTilingScheme::positionToTile(
      globe::geo::degreesToRadians(10.5), globe::geo::degreesToRadians(45.5), 14);
  // Both ways draw the same tile, or the comparison means nothing.
  DrapeSet other = set;
  other.shapeIndex = other.shapeIndex ? nullptr : std::make_shared<const DrapeIndex>(set.shapes);
  if (drawTile(set, *tile, 256).pixels != drawTile(other, *tile, 256).pixels) {
    state.SkipWithError("the indexed and the linear drawing differ");
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(drawTile(set, *tile, 256));
}
BENCHMARK(BM_DrapeTile)
    ->ArgNames({"parcels", "indexed"})
    ->ArgsProduct({{1000, 10000, 100000}, {0, 1}})
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
