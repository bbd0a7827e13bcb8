#include "apps/globe/snapshot_command.hpp"
#include "apps/globe/model_drawing.hpp"

#include <chrono>
#include <cstdio>

#include "apps/globe/attribution_stamp.hpp"
#include "apps/globe/hud_text.hpp"
#include "apps/globe/imagery.hpp"
#include "apps/globe/overlay_drawing.hpp"
#include "apps/globe/renderer_gpu.hpp"
#include "collision/clearance_settings.hpp"
#include "formats/image_io.hpp"
#include "render/hud_renderer.hpp"
#include "render/multisample_target.hpp"
#include "render/osmesa_context.hpp"
#include "render/read_pixels.hpp"

namespace globe::app {

namespace {

// The pose with a height above the terrain made absolute, and a camera inside the terrain (which
// would see the terrain's inside: a black picture) lifted to the eye height the collision response
// keeps, with a warning.
Result<camera::CameraPose> placeCamera(scene::TerrainScene& scene, camera::CameraPose pose,
                                       bool heightAboveTerrain, const core::WarningSink& warnings) {
  // Above the highest ground on Earth no camera can be inside it: no height to look up.
  constexpr double kAboveAnyGroundMeters = 9000;
  if (!heightAboveTerrain && pose.position.heightMeters > kAboveAnyGroundMeters) return pose;
  auto ground =
      scene.terrainHeightMeters(pose.position.longitudeRadians, pose.position.latitudeRadians);
  if (!ground && heightAboveTerrain) return Error{ground.error()};
  if (!ground) return pose;  // a tile that failed: drawn coarser, and said so by the scene
  if (heightAboveTerrain) pose.position.heightMeters += *ground;
  const double floorMeters = *ground + collision::ClearanceSettings{}.eyeMeters;
  if (pose.position.heightMeters < floorMeters) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "the camera at %.1f m is inside the terrain (%.1f m there): lifted to %.1f m",
                  pose.position.heightMeters, *ground, floorMeters);
    core::warn(warnings, text);
    pose.position.heightMeters = floorMeters;
  }
  return pose;
}

}  // namespace

Result<SnapshotReport> runSnapshot(const SnapshotOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  scene::SceneOptions sceneOptions = options.scene;
  sceneOptions.hysteresis = false;  // the image depends on the view only, not on the load order
  auto scene = scene::TerrainScene::open(options.pyramid, sceneOptions);
  if (!scene) return Error{scene.error()};
  camera::CameraPose pose = options.pose;
  if (!pose.isFinite()) return makeError("the camera pose is not finite");
  auto placed = placeCamera(**scene, pose, options.heightAboveTerrain, options.scene.warnings);
  if (!placed) return Error{placed.error()};
  pose = *placed;
  auto context = render::OsMesaContext::create(options.widthPixels, options.heightPixels);
  if (!context) return Error{context.error()};
  render::TerrainRendererOptions rendererOptions;
  rendererOptions.warn = options.scene.warnings;  // no sky, layers this GL cannot compile
  rendererOptions.verticesPerSide = (*scene)->store().manifest().verticesPerSide;
  auto renderer = render::TerrainRenderer::create(rendererOptions);
  if (!renderer) return Error{renderer.error()};
  auto target = render::multisampleTargetFor(options.widthPixels, options.heightPixels,
                                             options.scene.samples);
  if (!target) return Error{target.error()};
  RendererGpu gpu(**renderer, options.scene);
  if (options.imagery) {
    if (auto draped = drapeImagery(**renderer, *options.imagery); !draped)
      return Error{draped.error()};
  }
  auto frame = (*scene)->updateUntilComplete(pose, options.widthPixels, options.heightPixels, gpu,
                                             std::chrono::seconds(options.timeoutSeconds));
  if (!frame) return Error{frame.error()};
  if (*target) (*target)->bind();
  const render::FrameStats stats = gpu.draw(**scene);
  auto models = ModelDrawing::create(**scene);
  if (!models) return Error{models.error()};
  if (*models) (*models)->draw(**scene);
  auto labels = OverlayDrawing::create(**scene);
  if (!labels) return Error{labels.error()};
  if (*labels) (*labels)->draw(**scene);
  if (*target) (*target)->resolve();
  if (options.attribution) {
    if (auto block =
            attributionBlock((*scene)->attributions(), options.widthPixels, options.heightPixels)) {
      auto hud = render::HudRenderer::create({});
      if (!hud) return Error{hud.error()};
      const render::HudItem item = *block;
      (*hud)->setItems(std::span(&item, 1));
      (*hud)->draw(options.widthPixels, options.heightPixels);
    }
  }
  const std::vector<uint8_t> pixels =
      render::readPixelsRgba(options.widthPixels, options.heightPixels);
  if (auto written = formats::writePngAtomically(options.output, pixels, options.widthPixels,
                                                 options.heightPixels);
      !written) {
    return Error{written.error()};
  }
  SnapshotReport report;
  report.frame = *frame;
  report.tilesDrawn = stats.tilesDrawn;
  report.triangles = stats.triangles + (*models ? (*models)->trianglesDrawn() : 0);
  report.tileLoads = (*scene)->loader().counters().completed;
  report.failures = frame->missingTiles;
  report.terrainData =
      terrainDataText((*scene)->store().manifest(), pose.position.longitudeDegrees(),
                      pose.position.latitudeDegrees());
  if (const scene::ImageryLayers* layers = (*scene)->imagery()) {
    report.layerExposures = layers->exposures();
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace globe::app
