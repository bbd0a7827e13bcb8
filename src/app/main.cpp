// globe: the virtual-globe viewer's command line. Subcommands wire the libraries together.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>

#include "app/info_command.hpp"
#include "geo/ellipsoid.hpp"
#include "io/pyramid_manifest.hpp"

int main(int argc, char** argv) {
  CLI::App app{"globe: a virtual-globe terrain viewer with real-time camera-terrain collision",
               "globe"};
  app.require_subcommand(1);
  std::string globeName = "wgs84";
  auto addGlobe = [&](CLI::App* command) {
    command
        ->add_option("--globe", globeName,
                     "globe model: wgs84 (default) | sphere (the paper's, r = 6,371,000 m)")
        ->capture_default_str();
  };

  CLI::App* info =
      app.add_subcommand("info", "print a pyramid's levels, tile counts, bounds and heights");
  std::string pyramid;
  bool json = false;
  info->add_option("PYRAMID", pyramid, "pyramid directory made by globe-tiler")->required();
  info->add_flag("--json", json, "machine-readable output");
  addGlobe(info);

  CLI11_PARSE(app, argc, argv);
  if (!globe::geo::parseGlobeModel(globeName)) {
    std::fprintf(stderr, "globe: --globe must be wgs84 or sphere, not '%s'\n", globeName.c_str());
    return 2;
  }

  if (info->parsed()) {
    auto manifest = globe::io::readManifest(pyramid);
    if (!manifest) {
      std::fprintf(stderr, "globe info: %s\n", manifest.error().c_str());
      return 1;
    }
    const std::string text = json ? globe::app::formatPyramidInfoJson(*manifest, pyramid)
                                  : globe::app::formatPyramidInfoText(*manifest, pyramid);
    std::fputs(text.c_str(), stdout);
  }
  return 0;
}
