// globe-tiler export-imagery: an imagery layer as Web-Mercator tiles for web maps (XYZ, TMS or
// one PMTiles archive).
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

#include "apps/globe-tiler/commands.hpp"
#include "publish/imagery_export.hpp"
#include "streaming/imagery_store.hpp"

namespace globe::tiler_app {
namespace {

constexpr const char* kExportImageryCommand = "globe-tiler export-imagery";

}  // namespace

int runExportImageryCommand(int argc, char** argv) {
  CLI::App app{
      "Export an imagery layer as 256x256 Web-Mercator (EPSG:3857) tiles for web maps: an XYZ "
      "tree with tilejson.json (MapLibre, Leaflet, OpenLayers), a TMS tree with "
      "tilemapresource.xml (CesiumJS, GDAL), or one PMTiles v3 archive. Each zoom is resampled "
      "(bilinear) from the layer level whose texel first is no wider than its pixel; tiles "
      "without imagery are not written. Trees resume (tiles already there are kept); the "
      "archive is written whole or not at all.",
      kExportImageryCommand};
  std::string format, out, layer, levels, bounds, tileFormat = "png";
  publish::ImageryExportOptions options;
  app.add_option("--format", format, "xyz | tms | pmtiles")
      ->required()
      ->check(CLI::IsMember({"xyz", "tms", "pmtiles"}));
  app.add_option("-o,--output", out, "the tree's directory, or the .pmtiles file")->required();
  app.add_option("LAYER", layer, "an imagery layer directory (globe-tiler imagery)")->required();
  app.add_option("--levels", levels,
                 "A-B or A: Web-Mercator zooms (default 0 to the zoom of the layer's finest "
                 "level)");
  app.add_option("--bounds", bounds, "W,S,E,N degrees: the region exported (default the layer's)");
  app.add_option("--tile-format", tileFormat, "png (with alpha) | jpeg | webp")
      ->check(CLI::IsMember({"png", "jpeg", "jpg", "webp"}))
      ->capture_default_str();
  app.add_option("--quality", options.quality, "JPEG and WebP quality (1..100)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  app.add_option("--name", options.name, "the tileset's name (default the output's)");
  app.add_option("--attribution", options.attribution,
                 "who the imagery is from, for the map to show (default the layer's)");
  CLI11_PARSE(app, argc, argv);

  publish::ExportRegion region;
  if (!levels.empty() && !publish::parseExportLevels(levels, region)) {
    std::fprintf(stderr, "%s: --levels must be A-B or A (zooms, A <= B), not '%s'\n",
                 kExportImageryCommand, levels.c_str());
    return 2;
  }
  if (!bounds.empty() && !publish::parseExportBounds(bounds, region)) {
    std::fprintf(stderr, "%s: --bounds must be W,S,E,N in degrees (W < E, S < N), not '%s'\n",
                 kExportImageryCommand, bounds.c_str());
    return 2;
  }
  options.tileFormat = *publish::imageryTileFormatNamed(tileFormat);
  auto store = streaming::ImageryStore::open(layer);
  if (!store) {
    std::fprintf(stderr, "%s: %s\n", kExportImageryCommand, store.error().c_str());
    return 1;
  }
  const auto start = std::chrono::steady_clock::now();
  auto report = format == "pmtiles"
                    ? publish::exportImageryPmtiles(**store, region, out, options)
                    : publish::exportImageryTree(**store, region, out,
                                                 format == "tms" ? publish::ImageryTreeScheme::Tms
                                                                 : publish::ImageryTreeScheme::Xyz,
                                                 options);
  if (!report) {
    std::fprintf(stderr, "%s: %s\n", kExportImageryCommand, report.error().c_str());
    return 1;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto n = [](uint64_t v) { return static_cast<unsigned long long>(v); };
  if (format == "pmtiles") {
    std::printf(
        "%s: %llu %s tiles, zooms %u-%u (%llu distinct), %.1f MB archive; %llu without imagery "
        "skipped, in %.1f s\n",
        out.c_str(), n(report->tilesWritten), tileFormat.c_str(), report->minZoom, report->maxZoom,
        n(report->tilesDistinct), static_cast<double>(report->archiveBytes) / 1e6,
        n(report->tilesEmpty), seconds);
  } else {
    std::printf(
        "%s: %llu %s tiles written (%.1f MB), zooms %u-%u, %llu kept from an earlier run, %llu "
        "without imagery skipped, in %.1f s\n",
        out.c_str(), n(report->tilesWritten), tileFormat.c_str(),
        static_cast<double>(report->bytesWritten) / 1e6, report->minZoom, report->maxZoom,
        n(report->tilesKept), n(report->tilesEmpty), seconds);
  }
  return 0;
}

}  // namespace globe::tiler_app
