// `globe path check PYRAMID PATH`: where a camera path would go under the terrain or nearer to it
// than the eye clearance (where playback's collision response takes over), found by sampling the
// path over the pyramid's exact surface (its finest tiles), without rendering anything.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "camera/camera_path.hpp"
#include "core/result.hpp"
#include "surface/pyramid_surface.hpp"
#include "terrain/tile_mesh.hpp"
#include "transport/network_settings.hpp"

namespace globe::app {

// A stretch of path time where the clearance (the path's height over the surface) stays below
// the limit: under the terrain when its lowest clearance is below 0.
struct PathStretch {
  double fromSeconds = 0, toSeconds = 0;
  double lowestClearanceMeters = 0;
  double lowestAtSeconds = 0;
  double longitudeDegrees = 0, latitudeDegrees = 0;  // where the lowest is
  bool under() const { return lowestClearanceMeters < 0; }
};

struct PathCheck {
  std::vector<PathStretch> stretches;
  size_t samples = 0;
  double durationSeconds = 0;
  double lowestClearanceMeters = 0;  // over the whole path
};

// The clearance of the path sampled `samplesPerSecond` times a second (and at its end), and the
// stretches where it is below clearanceMeters. Terrain heights come from `surface`.
Result<PathCheck> checkPath(const camera::CameraPath& path, surface::PyramidSurface& surface,
                            const geo::Ellipsoid& ellipsoid, double samplesPerSecond,
                            double clearanceMeters);

// "under the terrain: 11.40-12.97 s, deepest -389.2 m at 12.50 s (138.73600, 35.34300)" or
// "nearer than 2 m: ..., lowest 0.8 m at ...".
std::string describeStretch(const PathStretch& stretch, double clearanceMeters);

struct PathCheckOptions {
  std::filesystem::path pyramid;
  std::filesystem::path pathFile;
  double samplesPerSecond = 30;
  double clearanceMeters = 2.0;
  geo::GlobeModel globeModel = geo::GlobeModel::Wgs84;
  terrain::SeaSurface sea = terrain::SeaSurface::Water;
  std::shared_ptr<transport::Network> network;
};

// Reads the path and the pyramid and checks it; errors name the file.
Result<PathCheck> runPathCheck(const PathCheckOptions& options);

}  // namespace globe::app
