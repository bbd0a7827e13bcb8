// The quantized-mesh exporter's TIN simplifier on real tiles, for bench_tin.sh to set beside
// martini and delatin: writes each tile's 65×65 grid of the pyramid's exact surface
// (grids.bin, float64 little-endian, rows from the north) and, per maximum error, globe's TINs
// (globe-E.json: vertices as [column, row] pairs, triangles) with the time taken.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "geo/ellipsoid.hpp"
#include "surface/pyramid_surface.hpp"
#include "publish/terrain_layer_writer.hpp"
#include "publish/tile_grid.hpp"
#include "publish/tin_simplifier.hpp"
#include "streaming/tile_store.hpp"

namespace {

constexpr uint32_t kSide = 65;

}  // namespace

int main(int argc, char** argv) {
  using namespace globe;
  CLI::App app{"Writes tiles' grids and globe's TINs of them for bench_tin.sh",
               "globe-bench-tin"};
  std::string pyramid, out, bounds = "-180,-90,180,90";
  uint32_t level = 10;
  std::vector<double> errors{1, 5, 20};
  app.add_option("PYRAMID", pyramid)->required();
  app.add_option("-o,--output", out)->required();
  app.add_option("--level", level, "the pyramid level of the 65×65 tiles (their samples from two deeper)");
  app.add_option("--bounds", bounds, "W,S,E,N degrees");
  app.add_option("--errors", errors, "maximum errors, metres")->delimiter(',');
  CLI11_PARSE(app, argc, argv);
  publish::ExportRegion region;
  if (std::sscanf(bounds.c_str(), "%lf,%lf,%lf,%lf", &region.westDegrees, &region.southDegrees,
                  &region.eastDegrees, &region.northDegrees) != 4) {
    std::fprintf(stderr, "globe-bench-tin: --bounds must be W,S,E,N\n");
    return 2;
  }
  auto store = streaming::TileStore::open(pyramid);
  if (!store) {
    std::fprintf(stderr, "globe-bench-tin: %s\n", store.error().c_str());
    return 1;
  }
  const geo::Ellipsoid ellipsoid = geo::Ellipsoid::wgs84();
  surface::PyramidSurface surface(**store, ellipsoid);
  std::filesystem::create_directories(out);
  std::ofstream grids(std::filesystem::path(out) / "grids.bin", std::ios::binary);
  std::vector<std::vector<double>> heights;
  nlohmann::json tiles = nlohmann::json::array();
  for (const geo::TileId& tile : publish::candidateTiles((*store)->manifest(), level, region)) {
    auto summary = (*store)->summary(tile);
    if (!summary || !*summary) continue;
    auto grid = publish::sampleTileGrid(surface, tile, kSide, level + 2);
    if (!grid) {
      std::fprintf(stderr, "globe-bench-tin: %s\n", grid.error().c_str());
      return 1;
    }
    grids.write(reinterpret_cast<const char*>(grid->heightsMeters.data()),
                static_cast<std::streamsize>(grid->heightsMeters.size() * sizeof(double)));
    heights.push_back(grid->heightsMeters);
    tiles.push_back({tile.level, tile.x, tile.y});
  }
  std::ofstream(std::filesystem::path(out) / "tiles.json") << tiles.dump();
  for (double error : errors) {
    nlohmann::json meshes = nlohmann::json::array();
    double seconds = 0;
    for (const auto& grid : heights) {
      const auto start = std::chrono::steady_clock::now();
      const publish::GridTin tin = publish::simplifyGrid(grid, kSide, error);
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      nlohmann::json vertices = nlohmann::json::array();
      for (uint32_t sample : tin.samples) vertices.push_back({sample % kSide, sample / kSide});
      meshes.push_back({{"vertices", vertices}, {"triangles", tin.triangles}});
    }
    char name[64];
    std::snprintf(name, sizeof name, "globe-%g.json", error);
    std::ofstream(std::filesystem::path(out) / name)
        << nlohmann::json{{"seconds", seconds}, {"meshes", meshes}}.dump();
  }
  std::printf("%zu tiles of level %u\n", heights.size(), level);
  return 0;
}
