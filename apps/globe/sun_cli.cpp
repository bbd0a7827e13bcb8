// `globe sun --time T --at LON,LAT [--height M] [--refraction]`: where the Sun stands for an
// observer, as the terrain is lit under --time: prints azimuth_deg,elevation_deg (azimuth
// clockwise from north; elevation geometric, or apparent with --refraction), so anyone can check
// it against another almanac.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/globe/camera_argument.hpp"
#include "apps/globe/subcommands.hpp"
#include "sun/solar_position.hpp"
#include "sun/utc_time.hpp"

namespace globe::app {
namespace {

struct SunArguments {
  std::string time;
  std::string at;
  std::string height = "0";
  bool refraction = false;
};

Result<sun::Observer> parseObserver(const SunArguments& arguments) {
  const size_t comma = arguments.at.find(',');
  if (comma == std::string::npos || arguments.at.find(',', comma + 1) != std::string::npos) {
    return makeError("--at '" + arguments.at + "': expected LON,LAT in degrees");
  }
  auto lon = parseNumberArgument("--at longitude", arguments.at.substr(0, comma), -180, 180);
  if (!lon) return Error{lon.error()};
  auto lat = parseNumberArgument("--at latitude", arguments.at.substr(comma + 1), -90, 90);
  if (!lat) return Error{lat.error()};
  auto height = parseNumberArgument("--height", arguments.height, -12000, 1e7);
  if (!height) return Error{height.error()};
  return sun::Observer{*lon, *lat, *height};
}

int runSunCommand(const SunArguments& arguments) {
  auto time = sun::parseUtcTime(arguments.time);
  if (!time) {
    std::fprintf(stderr, "globe sun: --%s\n", time.error().c_str());  // "--time '...': ..."
    return 2;
  }
  auto observer = parseObserver(arguments);
  if (!observer) {
    std::fprintf(stderr, "globe sun: %s\n", observer.error().c_str());
    return 2;
  }
  const sun::SolarPosition p = sun::solarPosition(*time, *observer);
  const double elevation =
      p.elevationDegrees + (arguments.refraction ? sun::refractionDegrees(p.elevationDegrees) : 0);
  std::printf("azimuth_deg,elevation_deg\n%.4f,%.4f\n", p.azimuthDegrees, elevation);
  return 0;
}

}  // namespace

Subcommand addSunCommand(CLI::App& app, CommonArguments&) {
  auto arguments = std::make_shared<SunArguments>();
  CLI::App* command = app.add_subcommand(
      "sun",
      "where the Sun stands at a time and place, as the terrain is lit under --time (NREL's Solar "
      "Position Algorithm): prints azimuth_deg,elevation_deg, azimuth clockwise from north, "
      "elevation geometric (no refraction) unless --refraction");
  command->add_option("--time", arguments->time,
                      "ISO-8601 with its zone: 2024-06-21T06:30:00Z, 2024-06-21T08:30+02:00")
      ->required();
  command->add_option("--at", arguments->at, "the observer: LON,LAT in degrees")->required();
  command->add_option("--height", arguments->height,
                      "the observer's height above the ellipsoid, metres (default 0)");
  command->add_flag("--refraction", arguments->refraction,
                    "the apparent elevation: add the atmosphere's refraction (1010 mbar, 10 °C)");
  return {command, [arguments](const CommandContext&) { return runSunCommand(*arguments); }};
}

}  // namespace globe::app
