#include "apps/globe-tiler/commands.hpp"

#include <CLI/CLI.hpp>
#include <cstdint>
#include <cstdio>
#include <string>

#include "tiling/export_block.hpp"

namespace globe::tiler_app {

int runExportCommand(int argc, char** argv) {
  CLI::App app{"Export one block of a pyramid as a standalone GTOPO30 .DEM/.HDR",
               "globe-tiler export"};
  std::string pyramid, stem;
  uint32_t level = 0, x = 0, y = 0;
  app.add_option("PYRAMID", pyramid, "pyramid directory")->required();
  app.add_option("L", level, "tile level")->required();
  app.add_option("X", x, "tile column (eastwards from -180)")->required();
  app.add_option("Y", y, "tile row (southwards from +90)")->required();
  app.add_option("OUT_STEM", stem, "output path without extension (writes .DEM .HDR .PRJ .STX)")
      ->required();
  CLI11_PARSE(app, argc, argv);
  if (auto done = tiling::exportBlock(pyramid, {level, x, y}, stem); !done) {
    std::fprintf(stderr, "globe-tiler export: %s\n", done.error().c_str());
    return 1;
  }
  std::printf("wrote %s.DEM and %s.HDR (tile %u/%u/%u)\n", stem.c_str(), stem.c_str(), level, x, y);
  return 0;
}

}  // namespace globe::tiler_app
