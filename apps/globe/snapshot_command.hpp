// `globe snapshot`: renders one view headless through OSMesa once every tile it needs is loaded.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "camera/camera_pose.hpp"
#include "scene/terrain_scene.hpp"

namespace globe::app {

struct SnapshotOptions {
  std::filesystem::path pyramid;
  camera::CameraPose pose;
  bool heightAboveTerrain = false;  // the pose's height is above the terrain, not the ellipsoid
  int widthPixels = 1280, heightPixels = 720;
  std::filesystem::path output;
  std::optional<std::filesystem::path> imagery;  // equirectangular world image to drape
  scene::SceneOptions scene;
  int timeoutSeconds = 120;  // the longest updateUntilComplete waits for the view's tiles
  bool attribution = true;  // stamp the services' attributions at the bottom right
};

struct SnapshotReport {
  scene::FrameInfo frame;
  uint32_t tilesDrawn = 0;
  uint64_t triangles = 0;
  uint64_t tileLoads = 0;
  // Tiles the view wanted whose load or pack failed (each named once on the warnings): the
  // image, written all the same, draws coarser ground or imagery there.
  uint64_t failures = 0;
  // What the terrain under the camera was made from ("ETOPO20.DEM, 20' (~37 km)"; empty: unknown).
  std::string terrainData;
  std::vector<float> layerExposures;  // each --layer's exposure as drawn, bottom first
  double seconds = 0;
};

Result<SnapshotReport> runSnapshot(const SnapshotOptions& options);

}  // namespace globe::app
