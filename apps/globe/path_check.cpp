// Sampling a camera path's clearance over the pyramid's exact surface (path_check.hpp).
#include "apps/globe/path_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "apps/globe/path_conversion.hpp"
#include "camera/camera_path_file.hpp"
#include "services/terrain_services.hpp"

namespace globe::app {

Result<PathCheck> checkPath(const camera::CameraPath& path, surface::PyramidSurface& surface,
                            const geo::Ellipsoid& ellipsoid, double samplesPerSecond,
                            double clearanceMeters) {
  PathCheck check;
  check.durationSeconds = path.endSeconds() - path.startSeconds();
  check.lowestClearanceMeters = std::numeric_limits<double>::infinity();
  std::optional<std::string> failure;
  const camera::TerrainHeightAt terrain = [&](double lon, double lat) {
    auto height = surface.heightMeters(lon, lat);
    if (!height && !failure) failure = height.error();
    return height ? *height : 0.0;
  };
  // Every 1/samplesPerSecond from the start, and the end itself.
  std::vector<double> times;
  const auto regular = static_cast<size_t>(std::floor(check.durationSeconds * samplesPerSecond));
  for (size_t i = 0; i <= regular; ++i) {
    times.push_back(path.startSeconds() + static_cast<double>(i) / samplesPerSecond);
  }
  if (times.back() < path.endSeconds()) times.push_back(path.endSeconds());
  std::optional<PathStretch> open;
  for (const double t : times) {
    const camera::CameraPose pose = camera::samplePath(path, t, ellipsoid, terrain);
    auto ground = surface.heightMeters(pose.position.longitudeRadians, pose.position.latitudeRadians);
    if (!ground) return Error{ground.error()};
    if (failure) return makeError(*failure);
    ++check.samples;
    const double clearance = pose.position.heightMeters - *ground;
    check.lowestClearanceMeters = std::min(check.lowestClearanceMeters, clearance);
    if (!(clearance < clearanceMeters)) {
      if (open) check.stretches.push_back(*open);
      open.reset();
      continue;
    }
    if (!open) open = PathStretch{t, t, clearance, t, 0, 0};
    open->toSeconds = t;
    if (clearance <= open->lowestClearanceMeters) {
      open->lowestClearanceMeters = clearance;
      open->lowestAtSeconds = t;
      open->longitudeDegrees = pose.position.longitudeDegrees();
      open->latitudeDegrees = pose.position.latitudeDegrees();
    }
  }
  if (open) check.stretches.push_back(*open);
  return check;
}

std::string describeStretch(const PathStretch& s, double clearanceMeters) {
  char what[64];
  if (s.under()) {
    std::snprintf(what, sizeof what, "under the terrain");
  } else {
    std::snprintf(what, sizeof what, "nearer than %g m", clearanceMeters);
  }
  char text[256];
  std::snprintf(text, sizeof text, "%s: %.2f-%.2f s, %s %.1f m at %.2f s (%.5f, %.5f)", what,
                s.fromSeconds, s.toSeconds, s.under() ? "deepest" : "lowest",
                s.lowestClearanceMeters, s.lowestAtSeconds, s.longitudeDegrees,
                s.latitudeDegrees);
  return text;
}

Result<PathCheck> runPathCheck(const PathCheckOptions& options) {
  auto file = camera::readCameraPath(options.pathFile);
  if (!file) return Error{file.error()};
  auto store = services::openTerrainSource(options.pyramid, options.sea, options.network);
  if (!store) return Error{store.error()};
  const geo::Ellipsoid ellipsoid = geo::ellipsoidFor(options.globeModel);
  surface::PyramidSurface surface(**store, ellipsoid);
  auto path = toCameraPath(
      *file, [&](double lon, double lat) { return surface.heightMeters(lon, lat); }, ellipsoid);
  if (!path) return makeError(options.pathFile.string() + ": " + path.error());
  return checkPath(*path, surface, ellipsoid, options.samplesPerSecond, options.clearanceMeters);
}

}  // namespace globe::app
