#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>

#include "apps/globe-tiler/commands.hpp"
#include "buildings/buildings_export.hpp"
#include "geo/ellipsoid.hpp"
#include "streaming/tile_store.hpp"

namespace globe::tiler_app {

int runBuildingsCommand(int argc, char** argv) {
  CLI::App app{
      "Extrudes building footprints into a 3D Tiles 1.1 tileset (tileset.json and GLB tiles, "
      "ADD refinement over a quadtree of the footprints' extent) standing on a pyramid's "
      "surface.\n"
      "Inputs: polygon files OGR opens (GeoJSON, Shapefile, GeoPackage, KML, ...), any CRS. "
      "Height (the roof above the ground): --height-attribute's field, else `height` (metres, "
      "\"12\" or \"12 m\"), else `building:levels` x --level-height-meters. Footprints without "
      "any are skipped and counted; absurd heights (not above 0 m, or above 1000 m), vertices "
      "off the globe and footprints wider than 0.05 degrees are skipped with a warning.\n"
      "Placement: the base at the lowest ground of the pyramid at the footprint's vertices and "
      "centre (never floating), the roof at that base plus the height. Positions in ECEF "
      "(WGS84).",
      "globe-tiler buildings"};
  buildings::BuildingsOptions options;
  std::string pyramid;
  app.add_option("-o,--output", options.outputDir, "tileset folder to create (or write over)")
      ->required();
  app.add_option("FOOTPRINTS", options.inputs, "vector files of building footprints")->required();
  app.add_option("--pyramid", pyramid, "the pyramid whose surface the buildings stand on")
      ->required();
  app.add_option("--height-attribute", options.footprints.heightAttribute,
                 "field holding the height in metres (default: height, then building:levels)");
  app.add_option("--level-height-meters", options.footprints.levelHeightMeters,
                 "a storey's height for building:levels")
      ->capture_default_str()
      ->check(CLI::Range(0.5, 20.0));
  app.add_option("--tile-buildings", options.quadtree.maxItemsPerCell,
                 "buildings in a tile before it splits in four")
      ->capture_default_str()
      ->check(CLI::Range(size_t{1}, size_t{100000}));
  CLI11_PARSE(app, argc, argv);

  auto store = streaming::TileStore::open(pyramid);
  if (!store) {
    std::fprintf(stderr, "globe-tiler buildings: %s\n", store.error().c_str());
    return 1;
  }
  auto report = buildings::exportBuildings(options, **store, geo::Ellipsoid::wgs84());
  if (!report) {
    std::fprintf(stderr, "globe-tiler buildings: %s\n", report.error().c_str());
    return 1;
  }
  for (const std::string& warning : report->warnings) {
    std::fprintf(stderr, "globe-tiler buildings: warning: %s\n", warning.c_str());
  }
  if (report->warningsDropped > 0) {
    std::fprintf(stderr, "globe-tiler buildings: warning: %zu more warnings not shown\n",
                 report->warningsDropped);
  }
  std::printf(
      "%s: %zu buildings in %zu tiles (%zu with content, levels 0-%u), %zu triangles; bases "
      "%.1f m to roofs %.1f m; skipped: %zu without a height, %zu refused\n",
      options.outputDir.c_str(), report->buildings, report->tiles, report->contents, report->depth,
      report->triangles, report->lowestBaseMeters, report->highestRoofMeters, report->withoutHeight,
      report->refused);
  return 0;
}

}  // namespace globe::tiler_app
