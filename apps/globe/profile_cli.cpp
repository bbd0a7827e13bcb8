// `globe profile PYRAMID PATH -o OUT.csv --png OUT.png`: the elevation profile of a GPX, KML or
// GeoJSON line over a pyramid or terrain service: distance_m,lon,lat,height_m,slope_deg (and the
// file's own elevations as path_elevation_m when it has them), sampled at least at the terrain's
// resolution along the WGS84 geodesics, heights from the exact surface (globe query --mode
// exact's); and as a chart. Each written to a temporary name, then renamed.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "apps/globe/subcommands.hpp"
#include "measure/elevation_profile.hpp"
#include "measure/profile_chart.hpp"
#include "services/terrain_services.hpp"
#include "transport/atomic_file.hpp"

namespace globe::app {
namespace {

struct ProfileArguments {
  std::string pyramid;
  std::string path;
  std::string output;
  std::string png;
  std::string pngSize = "1000x400";
  double spacingMeters = 0;
};

// "WIDTHxHEIGHT" within the chart's limits, checked before the profile is computed.
bool parseChartSize(const std::string& text, int& width, int& height) {
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &extra) != 3 ||
      (x != 'x' && x != 'X')) {
    std::fprintf(stderr,
                 "globe profile: --png-size wants WIDTHxHEIGHT in pixels (1000x400), "
                 "not \"%s\"\n",
                 text.c_str());
    return false;
  }
  if (width < measure::kMinChartWidthPixels || height < measure::kMinChartHeightPixels ||
      width > measure::kMaxChartSidePixels || height > measure::kMaxChartSidePixels) {
    std::fprintf(stderr,
                 "globe profile: --png-size %s is out of range: at least %dx%d, at most %d on "
                 "a side\n",
                 text.c_str(), measure::kMinChartWidthPixels, measure::kMinChartHeightPixels,
                 measure::kMaxChartSidePixels);
    return false;
  }
  return true;
}

int runProfileCommand(const ProfileArguments& arguments, const CommandContext& context) {
  if (arguments.output.empty() && arguments.png.empty()) {
    std::fprintf(stderr,
                 "globe profile: nothing to write: give -o OUT.csv, --png OUT.png or both\n");
    return 1;
  }
  int chartWidth = 0, chartHeight = 0;
  if (!parseChartSize(arguments.pngSize, chartWidth, chartHeight)) return 1;
  auto path = measure::readPathFile(arguments.path, context.warnings);
  if (!path) {
    std::fprintf(stderr, "globe profile: %s\n", path.error().c_str());
    return 1;
  }
  auto source = services::openTerrainSource(arguments.pyramid, context.sea, context.network);
  if (!source) {
    std::fprintf(stderr, "globe profile: %s\n", source.error().c_str());
    return 1;
  }
  measure::ProfileOptions options;
  options.maxSpacingMeters = arguments.spacingMeters;
  const geo::Ellipsoid ellipsoid = geo::ellipsoidFor(context.globeModel);
  auto rows = measure::elevationProfile(**source, *path, ellipsoid, options);
  if (!rows) {
    std::fprintf(stderr, "globe profile: %s\n", rows.error().c_str());
    return 1;
  }
  const double spacing = options.maxSpacingMeters > 0
                             ? options.maxSpacingMeters
                             : measure::terrainSpacingMeters(**source, *path);
  const double length = rows->back().sample.distanceMeters;
  if (!arguments.png.empty()) {
    auto drawn = measure::writeProfileChartPng(*rows, arguments.png, chartWidth, chartHeight);
    if (!drawn) {
      std::fprintf(stderr, "globe profile: %s\n", drawn.error().c_str());
      return 1;
    }
    std::printf("%s: a %dx%d chart of %.1f m\n", arguments.png.c_str(), chartWidth, chartHeight,
                length);
  }
  if (arguments.output.empty()) return 0;
  const bool withElevations = !std::isnan((*path)[0].elevationMeters);
  std::string csv = "distance_m,lon,lat,height_m,slope_deg";
  csv += withElevations ? ",path_elevation_m\n" : "\n";
  char line[200];
  for (const measure::ProfileRow& r : *rows) {
    std::snprintf(line, sizeof line, "%.3f,%.7f,%.7f,%.3f,%.3f", r.sample.distanceMeters,
                  r.sample.longitudeDegrees, r.sample.latitudeDegrees, r.heightMeters,
                  r.slopeDegrees);
    csv += line;
    if (withElevations) {
      std::snprintf(line, sizeof line, ",%.3f", r.sample.sourceElevationMeters);
      csv += line;
    }
    csv += "\n";
  }
  if (auto written = transport::writeFileAtomically(arguments.output, csv); !written) {
    std::fprintf(stderr, "globe profile: %s\n", written.error().c_str());
    return 1;
  }
  std::printf("%s: %zu samples over %.1f m (WGS84 geodesics, every %.1f m at most)\n",
              arguments.output.c_str(), rows->size(), length, spacing);
  return 0;
}

}  // namespace

Subcommand addProfileCommand(CLI::App& app, CommonArguments& common) {
  auto arguments = std::make_shared<ProfileArguments>();
  CLI::App* profile = app.add_subcommand(
      "profile",
      "the elevation profile of a GPX track or route, a KML or GeoJSON line over a pyramid: "
      "CSV distance_m,lon,lat,height_m,slope_deg (and path_elevation_m, the file's own), and a "
      "PNG chart of it");
  addPyramidArgument(*profile, arguments->pyramid, common);
  profile->add_option("PATH", arguments->path, "a .gpx, .kml or .geojson file with a line")
      ->required();
  profile->add_option("-o,--output", arguments->output, "the CSV file to write");
  profile->add_option("--png", arguments->png,
                      "a PNG chart to write: height against distance, lowest and highest points, "
                      "the file's own elevations when it has them");
  profile->add_option("--png-size", arguments->pngSize, "the chart's WIDTHxHEIGHT in pixels")
      ->capture_default_str();
  profile
      ->add_option("--spacing", arguments->spacingMeters,
                   "metres between samples at most (default: the pyramid's finest vertex "
                   "spacing)")
      ->check(CLI::PositiveNumber);
  addGlobeOption(*profile, common);
  addNetworkOptions(*profile, common);
  addSeaFloorOption(*profile, common);
  return {profile, [arguments](const CommandContext& context) {
            return runProfileCommand(*arguments, context);
          }};
}

}  // namespace globe::app
