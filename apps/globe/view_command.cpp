// The `globe view` loop: input → (orbit controls | fly controls | fly-to animation) → camera
// controller (collision every frame) → scene::TerrainScene::update → draw terrain and HUD, on
// change only. The state between frames and each step: view_session.hpp.
#define GLFW_INCLUDE_NONE
#include "apps/globe/view_command.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "apps/globe/elapsed.hpp"
#include "apps/globe/imagery.hpp"
#include "apps/globe/view_session.hpp"
#include "camera/camera_controller.hpp"
#include "collision/surface_probe.hpp"
#include "formats/image_io.hpp"
#include "render/read_pixels.hpp"

namespace globe::app {
namespace {

// The window and what draws in it (the scene is open already).
Result<void> openWindow(ViewSession& s) {
  const ViewOptions& options = s.options;
  render::GlfwWindowOptions windowOptions;
  windowOptions.widthPixels = options.widthPixels;
  windowOptions.heightPixels = options.heightPixels;
  windowOptions.title = kTitlePrefix;
  auto window = render::GlfwWindowContext::create(windowOptions);
  if (!window) {
    return makeError("cannot open a window (no display? set DISPLAY or run under xvfb-run): " +
                     window.error());
  }
  s.window = std::move(*window);
  render::TerrainRendererOptions rendererOptions;
  rendererOptions.warn = options.scene.warnings;  // no sky, layers this GL cannot compile
  rendererOptions.verticesPerSide = s.scene->store().manifest().verticesPerSide;
  auto renderer = render::TerrainRenderer::create(rendererOptions);
  if (!renderer) return Error{renderer.error()};
  s.renderer = std::move(*renderer);
  s.gpu = std::make_unique<RendererGpu>(*s.renderer, options.scene);
  auto multisample =
      render::multisampleTargetFor(s.window->framebufferWidthPixels(),
                                   s.window->framebufferHeightPixels(), options.scene.samples);
  if (!multisample) return Error{multisample.error()};
  s.multisample = std::move(*multisample);
  auto hud = render::HudRenderer::create({});
  if (!hud) return Error{hud.error()};
  s.hud = std::move(*hud);
  auto labels = OverlayDrawing::create(*s.scene);
  if (!labels) return Error{labels.error()};
  s.labels = std::move(*labels);
  auto models = ModelDrawing::create(*s.scene);
  if (!models) return Error{models.error()};
  s.models = std::move(*models);
  auto profilePanel = ProfilePanel::create();
  if (!profilePanel) return Error{profilePanel.error()};
  s.profilePanel = std::move(*profilePanel);
  if (options.imagery) {
    if (auto draped = drapeImagery(*s.renderer, *options.imagery); !draped)
      return Error{draped.error()};
  }
  return {};
}

// The navigator (its picks march through the tiles drawn now), the controller and the input.
void startCamera(ViewSession& s, const camera::CameraPose& startPose) {
  const geo::Ellipsoid& ellipsoid = s.ellipsoid();
  const terrain::RenderingTileArray& drawnArray = s.scene->renderingTileArray();
  s.navigator.emplace(ellipsoid, startPose, s.options.scene.fovYRadians,
                      [&ellipsoid, &drawnArray](double lon, double lat) -> std::optional<double> {
                        const auto surface = collision::surfaceHeightAt(
                            drawnArray, ellipsoid, lon, lat, collision::SurfaceModel::Exact);
                        if (!surface || !surface->found) return std::nullopt;
                        return surface->heightMeters;
                      });
  // A start pose orbit mode cannot show is changed, and said so (never silently).
  for (const std::string& clamp : camera::describeStartClamp(startPose, s.navigator->home())) {
    std::fprintf(stderr, "globe view: --camera %s\n", clamp.c_str());
  }
  s.controller.emplace(s.navigator->home());
  ViewInput& input = s.input;
  input.navigator = &*s.navigator;
  input.goToRequest = s.options.goTo;
  input.imagery.lighting = s.options.scene.imageryLighting;
  input.sunUnixSeconds = s.options.scene.sunTimeUnixSeconds;
  input.imagery.layerCount = static_cast<uint32_t>(
      std::min<size_t>(s.options.scene.layers.size(), terrain::kMaxDrapeLayers));
  for (uint32_t k = 0; k < input.imagery.layerCount; ++k)
    input.imagery.opacity[k] = std::clamp(s.options.scene.layers[k].opacity, 0.0f, 1.0f);
  installViewCallbacks(s.window->window(), input);
}

// This frame's move, proposed to the controller, which checks it against the tiles drawn now
// (QOTCD) and corrects it (stop, slide, heighten, raise); then the scene for the pose kept.
scene::FrameInfo moveCamera(ViewSession& s, ViewClock::time_point now, double frameSeconds,
                            int width, int height, camera::CollisionState& collision) {
  camera::Navigator& navigator = *s.navigator;
  camera::CameraController& controller = *s.controller;
  const double fovY = s.options.scene.fovYRadians;
  if (const auto proposal = navigator.update(frameSeconds)) {
    controller.propose(proposal->pose, proposal->kind);
  }
  if (navigator.animating()) s.input.changed = true;  // keep flying
  controller.setNearPlane({camera::projectionForHeight(0, controller.settings().clearance.eyeMeters,
                                                       fovY, 1, s.ellipsoid())
                               .nearMeters,
                           fovY, static_cast<double>(width) / std::max(height, 1)});
  // The controller's motion integrates at most 0.1 s a frame.
  collision =
      controller.update(std::min(frameSeconds, 0.1), s.scene->renderingTileArray(), s.ellipsoid());
  navigator.adopt(controller.pose(), collision);
  // A smooth raise over new, finer terrain takes a few frames: keep updating until done.
  if (collision.raisedForNewTerrain) s.input.changed = true;
  s.recorder.sample(s.secondsAt(now), controller.pose());
  return s.scene->update(controller.pose(), width, height, *s.gpu);
}

// What the HUD shows, as it is compared to decide a redraw: its lines without the frame time,
// and the compass's degree and the scale bar's pixel.
std::vector<std::string> hudKeyOf(const HudState& hudState, double headingRadians) {
  std::vector<std::string> key = hudStatusLines(hudState, false);
  const auto rounded = [](double value) {
    return std::isfinite(value) && std::abs(value) < 1e15 ? std::to_string(std::lround(value))
                                                          : std::string("-");
  };
  key.push_back(rounded(geo::radiansToDegrees(headingRadians)) + " " +
                rounded(hudState.metersPerPixel * 100));
  return key;
}

// One frame: requests taken, the camera moved, the scene updated, drawn when something changed.
void runFrame(ViewSession& s, int width, int height) {
  ViewInput& input = s.input;
  const auto now = ViewClock::now();
  bool redraw = input.changed || s.continuous();
  if (input.changed) s.lastChange = now;
  input.changed = false;
  // Animations run on the clock.
  const double frameSeconds =
      std::max(std::chrono::duration<double>(now - s.lastUpdate).count(), 0.0);
  s.lastUpdate = now;
  takeRequests(s, now);
  takeClick(s, width);
  redraw = updateRulerAndProfile(s, width, height) || redraw;
  camera::CollisionState collision;
  s.scene->setSunTime(input.sunUnixSeconds);  // before the frame's view is made
  const scene::FrameInfo info = moveCamera(s, now, frameSeconds, width, height, collision);
  s.tilesChanged =
      s.tilesChanged || info.arrived > 0 || info.uploaded > 0 || s.scene->tiles() != s.drawnTiles;
  s.loading = !info.complete;
  const bool throttled = s.loading && now - s.lastDraw < kLoadingRedrawInterval;
  redraw = redraw || (s.tilesChanged && !throttled);
  // The HUD: redrawn when what it says changes (the frame time alone does not count).
  HudState hudState = hudStateOf(s, info, collision);
  for (uint32_t k = 0; k < input.imagery.layerCount; ++k)
    s.gpu->setLayer(k, input.imagery.shown[k], input.imagery.opacity[k]);
  s.gpu->setImageryLighting(input.imagery.lighting);
  std::vector<std::string> hudKey = hudKeyOf(hudState, s.controller->pose().headingRadians);
  const bool hudChanged = hudKey != s.drawnHud || input.helpVisible != s.drawnHelp;
  redraw = redraw || (hudChanged && !throttled) || input.screenshotRequested;
  if (redraw) {
    s.tilesChanged = false;
    s.lastDraw = now;
    drawFrame(s, hudState, std::move(hudKey), hudChanged, width, height);
  }
  if (s.options.log && info.complete && !s.wasComplete) {
    std::printf("view complete: %zu tiles, %.0f ms after the last change, frame %d\n",
                s.drawnTiles.size(), millisecondsSince(s.lastChange), s.report.framesDrawn);
    std::fflush(stdout);
  }
  s.wasComplete = info.complete;
}

// After the loop: a path being recorded written, the last frame saved (--screenshot), the
// camera said (--log).
Result<void> finishView(ViewSession& s) {
  if (s.recorder.recording()) {  // closed while recording: keep what was flown
    writeRecordedPath(s.options.recordDirectory,
                      s.recorder.stop(s.secondsAt(ViewClock::now()), s.controller->pose()));
  }
  s.report.finalPose = s.controller->pose();
  if (s.options.screenshot) {
    // The back buffer is undefined after a swap: draw the last frame again and read it back.
    const int width = s.window->framebufferWidthPixels();
    const int height = s.window->framebufferHeightPixels();
    drawWorld(s, width, height);
    if (s.labels) s.labels->drawPanel(*s.scene, width, height, s.panelPlace);
    const std::vector<uint8_t> pixels = render::readPixelsRgba(width, height);
    if (auto written = formats::writePngAtomically(*s.options.screenshot, pixels, width, height);
        !written) {
      return Error{written.error()};
    }
  }
  if (s.options.log) {
    std::printf("frames drawn: %d\ncamera %s\n", s.report.framesDrawn,
                formatPose(s.report.finalPose).c_str());
    std::fflush(stdout);
  }
  return {};
}

}  // namespace

Result<std::unique_ptr<ViewSession>> openViewSession(const ViewOptions& options) {
  if (!options.pose.isFinite()) return makeError("the camera pose is not finite");
  auto s = std::make_unique<ViewSession>(options);
  // Warnings go to stderr and, the latest for a while, to the HUD.
  s->recentWarning = std::make_shared<RecentWarning>();
  scene::SceneOptions sceneOptions = options.scene;
  sceneOptions.warnings = RecentWarning::wrap(options.scene.warnings, s->recentWarning);
  auto scene = scene::TerrainScene::open(options.pyramid, sceneOptions);
  if (!scene) return Error{scene.error()};
  s->scene = std::move(*scene);
  camera::CameraPose startPose = options.pose;
  if (options.heightAboveTerrain) {
    auto ground = s->scene->terrainHeightMeters(startPose.position.longitudeRadians,
                                                startPose.position.latitudeRadians);
    if (!ground) return Error{ground.error()};
    startPose.position.heightMeters += *ground;
  }
  s->attributions = s->scene->attributions();
  if (auto opened = openWindow(*s); !opened) return Error{opened.error()};
  s->userOverlays = s->scene->options().overlays;
  std::error_code directoryError;
  if (!options.recordDirectory.empty()) {
    std::filesystem::create_directories(options.recordDirectory, directoryError);
  }
  startCamera(*s, startPose);
  s->start = s->lastChange = s->lastDraw = s->lastUpdate = ViewClock::now();
  return s;
}

Result<ViewReport> runView(const ViewOptions& options) {
  auto session = openViewSession(options);
  if (!session) return Error{session.error()};
  ViewSession& s = **session;
  while (!s.window->shouldClose()) {
    // Events and picks take window pixels.
    const auto [windowWidth, windowHeight] = s.windowSize();
    s.navigator->setViewport(windowWidth, windowHeight);
    const int width = s.window->framebufferWidthPixels();
    const int height = s.window->framebufferHeightPixels();
    if (options.log && s.saidSize != std::pair{width, height}) {  // resizes come late (F11)
      s.saidSize = {width, height};
      std::printf("view size %dx%d\n", width, height);
    }
    const bool visible = width > 0 && height > 0;  // not minimised
    const bool messageDue = !s.shownMessage.empty() &&
                            ViewClock::now() - s.shownMessageAt >= ViewSession::kMessageLifetime;
    if (visible && (s.input.changed || s.loading || s.continuous() || messageDue)) {
      runFrame(s, width, height);
    }
    if (s.continuous() && s.report.framesDrawn >= options.frames) break;
    waitForEvents(s, visible);
  }
  if (auto finished = finishView(s); !finished) return Error{finished.error()};
  return s.report;
}

}  // namespace globe::app
