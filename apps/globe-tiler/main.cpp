// globe-tiler: builds a lat/long quadtree pyramid of GTOPO30-encoded blocks from elevation rasters
// (the default command), imagery layers (`imagery`), water masks from land polygons
// (`water-mask`), 3D Tiles buildings from footprints (`buildings`), exports single blocks back to
// GTOPO30 or pyramids as web tile trees (`export`), and imagery layers as web tiles
// (`export-imagery`).
#include <string>

#include "apps/globe-tiler/commands.hpp"

int main(int argc, char** argv) {
  const std::string command = argc > 1 ? argv[1] : "";
  if (command == "export") return globe::tiler_app::runExportCommand(argc - 1, argv + 1);
  if (command == "export-imagery") {
    return globe::tiler_app::runExportImageryCommand(argc - 1, argv + 1);
  }
  if (command == "imagery") return globe::tiler_app::runImageryCommand(argc - 1, argv + 1);
  if (command == "water-mask") return globe::tiler_app::runWaterMaskCommand(argc - 1, argv + 1);
  if (command == "buildings") return globe::tiler_app::runBuildingsCommand(argc - 1, argv + 1);
  using globe::tiler_app::TileCommandKind;
  if (command == "merge") {
    return globe::tiler_app::runTileCommand(argc - 1, argv + 1, TileCommandKind::Merge);
  }
  if (command == "plan") {
    return globe::tiler_app::runTileCommand(argc - 1, argv + 1, TileCommandKind::Plan);
  }
  return globe::tiler_app::runTileCommand(argc, argv);
}
