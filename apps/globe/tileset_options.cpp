#include "apps/globe/tileset_options.hpp"

#include <cstdio>
#include <sstream>

#include <glm/mat4x4.hpp>

#include "camera/camera_pose.hpp"
#include "geo/ecef.hpp"
#include "tiles3d/tileset.hpp"

namespace globe::app {
namespace {

// "LON,LAT,HEIGHT[,SCALE]" (degrees, metres, metres a unit) as the placement of a tileset's own
// frame: x east, y north, z up there; nullopt when it does not parse.
std::optional<glm::dmat4> placementOf(const std::string& text, const geo::Ellipsoid& ellipsoid) {
  std::vector<double> numbers;
  std::stringstream fields(text);
  for (std::string field; std::getline(fields, field, ',');) {
    try {
      size_t used = 0;
      numbers.push_back(std::stod(field, &used));
      if (used != field.size() || !std::isfinite(numbers.back())) return std::nullopt;
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }
  if (numbers.size() < 3 || numbers.size() > 4 || std::abs(numbers[1]) > 90) return std::nullopt;
  const double scale = numbers.size() == 4 ? numbers[3] : 1.0;
  if (!(scale > 0)) return std::nullopt;
  const geo::Cartographic at = geo::Cartographic::fromDegrees(numbers[0], numbers[1], numbers[2]);
  const camera::EastNorthUp frame = camera::eastNorthUp(ellipsoid, at);
  glm::dmat4 m(1.0);
  m[0] = glm::dvec4(frame.east * scale, 0);
  m[1] = glm::dvec4(frame.north * scale, 0);
  m[2] = glm::dvec4(frame.up * scale, 0);
  m[3] = glm::dvec4(geo::cartographicToEcef(ellipsoid, at), 1);
  return m;
}

}  // namespace

void addTilesetOptions(CLI::App& command, CommonArguments& arguments) {
  command
      .add_option("--tileset", arguments.tilesets,
                  "3D Tiles tileset (its tileset.json or folder, a path or http(s) URL) streamed "
                  "over the terrain by screen-space error, the camera kept above what it draws "
                  "as above the terrain; repeat for more")
      ->type_name("DIR|URL");
  command
      .add_option("--tileset-at", arguments.tilesetAt,
                  "place the tilesets' own frame at LON,LAT,HEIGHT, x east, y north, z up, "
                  "SCALE metres a unit (1 by default): for tilesets made in a local frame")
      ->type_name("LON,LAT,H[,SCALE]");
  command.add_flag("--tileset-clamp", arguments.tilesetClamp,
                   "set each tileset on the terrain: moved along its centre's vertical so that "
                   "height 0 there sits on the ground (for models made at height 0); without it, "
                   "heights are above the ellipsoid as 3D Tiles says");
  command
      .add_option("--tileset-error", arguments.tilesetErrorPixels,
                  "the screen-space error (pixels) past which a tileset's tiles refine")
      ->check(CLI::Range(0.1, 1000.0))
      ->type_name("PIXELS");
}

bool applyTilesetArguments(const char* command, const CommonArguments& arguments,
                           scene::SceneOptions& scene) {
  const geo::Ellipsoid ellipsoid = geo::ellipsoidFor(scene.globeModel);
  std::optional<glm::dmat4> placement;
  if (!arguments.tilesetAt.empty()) {
    placement = placementOf(arguments.tilesetAt, ellipsoid);
    if (!placement) {
      std::fprintf(stderr, "globe %s: --tileset-at must be LON,LAT,HEIGHT[,SCALE], not '%s'\n",
                   command, arguments.tilesetAt.c_str());
      return false;
    }
  }
  for (const std::string& given : arguments.tilesets) {
    auto tileset = tiles3d::openTileset(given, scene.network.get(), ellipsoid);
    if (!tileset) {
      std::fprintf(stderr, "globe %s: --tileset %s\n", command, tileset.error().c_str());
      return false;
    }
    for (const std::string& warning : tileset->warnings) {
      std::fprintf(stderr, "globe %s: warning: %s\n", command, warning.c_str());
    }
    if (placement) tiles3d::placeTileset(*tileset, *placement);
    scene.tilesets.push_back(std::make_shared<const tiles3d::Tileset>(std::move(*tileset)));
  }
  scene.clampTilesets = arguments.tilesetClamp;
  scene.tilesetScreenSpaceErrorPixels = arguments.tilesetErrorPixels;
  return true;
}

}  // namespace globe::app
