#include "apps/globe/snapshot_command.hpp"

#include <chrono>

#include "apps/globe/attribution_stamp.hpp"
#include "apps/globe/imagery.hpp"
#include "apps/globe/overlay_drawing.hpp"
#include "apps/globe/renderer_gpu.hpp"
#include "formats/image_io.hpp"
#include "render/hud_renderer.hpp"
#include "render/osmesa_context.hpp"
#include "render/read_pixels.hpp"

namespace globe::app {

Result<SnapshotReport> runSnapshot(const SnapshotOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  scene::SceneOptions sceneOptions = options.scene;
  sceneOptions.hysteresis = false;  // the image depends on the view only, not on the load order
  auto scene = scene::TerrainScene::open(options.pyramid, sceneOptions);
  if (!scene) return Error{scene.error()};
  camera::CameraPose pose = options.pose;
  if (!pose.isFinite()) return makeError("the camera pose is not finite");
  if (options.heightAboveTerrain) {
    auto ground = (*scene)->terrainHeightMeters(pose.position.longitudeRadians,
                                                pose.position.latitudeRadians);
    if (!ground) return Error{ground.error()};
    pose.position.heightMeters += *ground;
  }
  auto context = render::OsMesaContext::create(options.widthPixels, options.heightPixels);
  if (!context) return Error{context.error()};
  render::TerrainRendererOptions rendererOptions;
  rendererOptions.warn = options.scene.warnings;  // no sky, layers this GL cannot compile
  rendererOptions.verticesPerSide = (*scene)->store().manifest().verticesPerSide;
  auto renderer = render::TerrainRenderer::create(rendererOptions);
  if (!renderer) return Error{renderer.error()};
  RendererGpu gpu(**renderer, options.scene);
  if (options.imagery) {
    if (auto draped = drapeImagery(**renderer, *options.imagery); !draped)
      return Error{draped.error()};
  }
  auto frame = (*scene)->updateUntilComplete(pose, options.widthPixels, options.heightPixels, gpu,
                                             std::chrono::seconds(options.timeoutSeconds));
  if (!frame) return Error{frame.error()};
  const render::FrameStats stats = gpu.draw(**scene);
  auto labels = OverlayDrawing::create(**scene);
  if (!labels) return Error{labels.error()};
  if (*labels) (*labels)->draw(**scene);
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
  report.triangles = stats.triangles;
  report.tileLoads = (*scene)->loader().counters().completed;
  report.failures = frame->missingTiles;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace globe::app
