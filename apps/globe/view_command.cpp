// The `globe view` loop: input → (orbit controls | fly controls | fly-to animation) → camera
// controller (collision every frame) → scene::TerrainScene::update → draw terrain and HUD, on
// change only.
#define GLFW_INCLUDE_NONE
#include "apps/globe/view_command.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include <glm/geometric.hpp>

#include "apps/globe/attribution_stamp.hpp"
#include "apps/globe/elapsed.hpp"
#include "apps/globe/go_to.hpp"
#include "apps/globe/hud_text.hpp"
#include "apps/globe/imagery.hpp"
#include "apps/globe/view_actions.hpp"
#include "apps/globe/overlay_drawing.hpp"
#include "apps/globe/path_recorder.hpp"
#include "apps/globe/profile_panel.hpp"
#include "apps/globe/recent_warning.hpp"
#include "apps/globe/renderer_gpu.hpp"
#include "apps/globe/ruler.hpp"
#include "apps/globe/ruler_overlay.hpp"
#include "apps/globe/view_input.hpp"
#include "camera/camera_controller.hpp"
#include "camera/navigator.hpp"
#include "camera/saved_views.hpp"
#include "collision/surface_probe.hpp"
#include "formats/image_io.hpp"
#include "geo/ecef.hpp"
#include "overlays/overlay_file.hpp"
#include "render/glfw_window_context.hpp"
#include "render/hud_renderer.hpp"
#include "render/hud_widgets.hpp"
#include "render/read_pixels.hpp"

namespace globe::app {
namespace {

// V then a name: the current pose saved under it in the user's views file; what to say back.
std::string saveView(const std::string& name, const camera::CameraPose& pose) {
  if (name.empty()) return "save view: type a name";
  const std::filesystem::path file = camera::userViewsFile();
  auto views = camera::readSavedViews(file);
  if (!views) return "save view: " + views.error();
  camera::putSavedView(*views, {name, pose, false});
  if (auto written = camera::writeSavedViews(file, *views); !written) {
    return "save view: " + written.error();
  }
  std::printf("saved view %s in %s\n", name.c_str(), file.string().c_str());
  std::fflush(stdout);
  return "saved view \"" + name + "\" (" + std::to_string(views->size()) + " in " + file.string() +
         ")";
}

using Documents = std::vector<std::shared_ptr<const overlays::OverlayDocument>>;

// The user's documents and the ruler's shown in the scene; a new renderer takes their icons and
// keeps the picked placemark when it is still one of the user's.
Result<void> showOverlays(scene::TerrainScene& scene, RendererGpu& gpu, const Documents& user,
                          const std::shared_ptr<const overlays::OverlayDocument>& ruler,
                          std::unique_ptr<OverlayDrawing>& labels) {
  if (auto set = scene.setOverlays(withRuler(user, ruler), gpu); !set) return set;
  const auto selected = labels ? labels->selected() : std::nullopt;
  auto created = OverlayDrawing::create(scene);
  if (!created) return Error{created.error()};
  labels = std::move(*created);
  if (labels && selected && selected->document < user.size()) labels->select(selected);
  return {};
}

// O then a path, or files dropped on the window: each read and shown with the overlays already
// open; what to say back (the files opened, or why one could not be).
std::string openOverlays(scene::TerrainScene& scene, RendererGpu& gpu,
                         const std::vector<std::string>& files, Documents& user,
                         const std::shared_ptr<const overlays::OverlayDocument>& ruler,
                         std::unique_ptr<OverlayDrawing>& labels) {
  Documents documents = user;
  std::string opened;
  for (const std::string& file : files) {
    auto document = overlays::readOverlayFile(file);
    if (!document) return "open: " + document.error();
    for (const std::string& warning : document->warnings) {
      std::fprintf(stderr, "globe view: warning: %s\n", warning.c_str());
    }
    opened += (opened.empty() ? "" : ", ") + std::filesystem::path(file).filename().string();
    documents.push_back(std::make_shared<const overlays::OverlayDocument>(std::move(*document)));
  }
  if (opened.empty()) return "open: type a file's path";
  if (auto shown = showOverlays(scene, gpu, documents, ruler, labels); !shown) {
    return "open: " + shown.error();
  }
  user = std::move(documents);
  std::printf("opened %s\n", opened.c_str());
  std::fflush(stdout);
  return "opened " + opened;
}

// Where a ground point is drawn in the last frame, window pixels; nullopt behind the camera.
std::optional<glm::dvec2> windowPixelOf(const terrain::RenderView& view,
                                        const geo::Ellipsoid& ellipsoid, const RulerPoint& point,
                                        double toWindow) {
  const glm::dvec3 ecef = geo::cartographicToEcef(
      ellipsoid, geo::Cartographic::fromDegrees(point.longitudeDegrees, point.latitudeDegrees,
                                                point.heightMeters));
  const glm::dvec4 clip = view.projection * view.viewMatrix * glm::dvec4(ecef, 1.0);
  if (!(clip.w > 0)) return std::nullopt;
  return glm::dvec2((clip.x / clip.w + 1.0) * 0.5 * view.widthPixels,
                    (1.0 - clip.y / clip.w) * 0.5 * view.heightPixels) *
         toWindow;
}

// What X profiles: the ruler's path (two points or more), else the picked placemark's first line.
std::vector<measure::PathPoint> profilePath(const Ruler& ruler, const scene::TerrainScene& scene,
                                            const OverlayDrawing* labels) {
  if (ruler.points().size() >= 2) return ruler.path();
  if (labels == nullptr || !labels->selected()) return {};
  const overlays::PlacemarkRef ref = *labels->selected();
  return placemarkLine(scene.options().overlays[ref.document]->placemarks[ref.placemark])
      .value_or(std::vector<measure::PathPoint>());
}

constexpr const char* kTitlePrefix = "globe";  // tests find the window by this name
using Clock = std::chrono::steady_clock;

// The window title: position, tiles, and what collision did this frame.
std::string titleFor(const camera::CameraPose& pose, size_t tiles, bool loading,
                     const camera::CollisionState& collision) {
  char text[320];
  std::snprintf(text, sizeof text, "%s  lon %.5f  lat %.5f  height %.0f m  %s  %s%s  tiles %zu%s",
                kTitlePrefix, pose.position.longitudeDegrees(), pose.position.latitudeDegrees(),
                pose.position.heightMeters, terrainStatus(collision).c_str(),
                collision.collided ? "COLLISION " : "",
                std::string(collision::toString(collision.response)).c_str(), tiles,
                loading ? " (loading)" : "");
  return text;
}

std::string formatPose(const camera::CameraPose& pose) {
  char text[160];
  std::snprintf(text, sizeof text, "%.6f,%.6f,%.2f,%.3f,%.3f,%.3f",
                pose.position.longitudeDegrees(), pose.position.latitudeDegrees(),
                pose.position.heightMeters, geo::radiansToDegrees(pose.headingRadians),
                geo::radiansToDegrees(pose.pitchRadians), geo::radiansToDegrees(pose.rollRadians));
  return text;
}

std::filesystem::path shown(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(path, error);
  return error ? path : absolute;
}

void writeRecordedPath(const std::filesystem::path& directory,
                       const std::vector<PathKeyframe>& keyframes) {
  const std::filesystem::path path = timestampedPath(directory, "globe-path", ".json");
  if (auto written = camera::writeCameraPathJson(path, recordedPathFile(keyframes)); !written) {
    std::fprintf(stderr, "globe view: cannot write the path: %s\n", written.error().c_str());
    return;
  }
  std::printf("wrote path %s (%zu keyframes)\n", shown(path).string().c_str(), keyframes.size());
  std::fflush(stdout);
}

// Reads the frame drawn into the back buffer (before the swap) and writes it as a PNG.
void writeScreenshot(const std::filesystem::path& directory, int width, int height) {
  const std::filesystem::path path = timestampedPath(directory, "globe-shot", ".png");
  const std::vector<uint8_t> pixels = render::readPixelsRgba(width, height);
  if (auto written = formats::writePngAtomically(path, pixels, width, height); !written) {
    std::fprintf(stderr, "globe view: cannot write the screenshot: %s\n", written.error().c_str());
    return;
  }
  std::printf("wrote screenshot %s\n", shown(path).string().c_str());
  std::fflush(stdout);
}

// The HUD, in framebuffer pixels: the status block at the top left and, when shown, the help
// under it, the compass rose at the top right and the scale bar at the bottom left; larger on
// tall windows. compassBox gets the rose's bounding box (a click there turns north up).
std::vector<render::HudItem> hudItems(std::vector<std::string> status, bool help,
                                      double headingRadians, double metersPerPixel, int widthPixels,
                                      int heightPixels,
                                      std::pair<glm::dvec2, glm::dvec2>& compassBox) {
  std::vector<render::HudItem> items;
  render::HudTextBlock statusBlock;
  statusBlock.lines = std::move(status);
  statusBlock.scale = heightPixels >= 600 ? 2.0f : 1.0f;
  const float scale = statusBlock.scale;
  if (help) {
    render::HudTextBlock helpBlock;
    helpBlock.lines = helpLines();  // view_actions.hpp
    helpBlock.scale = scale;
    helpBlock.topLeftPixels = statusBlock.topLeftPixels +
                              glm::vec2(0.0f, render::hudBlockSizePixels(statusBlock).y + 8.0f);
    helpBlock.textRgba = {1.0f, 1.0f, 0.75f, 1.0f};
    items.emplace_back(std::move(helpBlock));
  }
  items.emplace(items.begin(), std::move(statusBlock));
  const float radius = 28.0f * scale;
  const glm::vec2 centre(static_cast<float>(widthPixels) - 8.0f - radius, 8.0f + radius);
  for (render::HudItem& item : render::compassRose(centre, radius, scale, -headingRadians)) {
    items.push_back(std::move(item));
  }
  compassBox = {glm::dvec2(centre - radius), glm::dvec2(centre + radius)};
  if (const auto bar = scaleBarLength(metersPerPixel, 100.0 * scale)) {
    const glm::vec2 leftEnd(12.0f * scale, static_cast<float>(heightPixels) - 10.0f * scale);
    for (render::HudItem& item :
         render::scaleBar(leftEnd, static_cast<float>(bar->pixels), bar->label, scale)) {
      items.push_back(std::move(item));
    }
  }
  return items;
}

}  // namespace

Result<ViewReport> runView(const ViewOptions& options) {
  if (!options.pose.isFinite()) return makeError("the camera pose is not finite");
  // Warnings go to stderr and, the latest for a while, to the HUD.
  auto recentWarning = std::make_shared<RecentWarning>();
  scene::SceneOptions sceneOptions = options.scene;
  sceneOptions.warnings = RecentWarning::wrap(options.scene.warnings, recentWarning);
  auto scene = scene::TerrainScene::open(options.pyramid, sceneOptions);
  if (!scene) return Error{scene.error()};
  camera::CameraPose startPose = options.pose;
  if (options.heightAboveTerrain) {
    auto ground = (*scene)->terrainHeightMeters(startPose.position.longitudeRadians,
                                                startPose.position.latitudeRadians);
    if (!ground) return Error{ground.error()};
    startPose.position.heightMeters += *ground;
  }
  // Who the terrain and imagery are from, shown at the bottom right as their services ask.
  const std::vector<std::string> attributions = (*scene)->attributions();
  render::GlfwWindowOptions windowOptions;
  windowOptions.widthPixels = options.widthPixels;
  windowOptions.heightPixels = options.heightPixels;
  windowOptions.title = kTitlePrefix;
  auto window = render::GlfwWindowContext::create(windowOptions);
  if (!window) {
    return makeError("cannot open a window (no display? set DISPLAY or run under xvfb-run): " +
                     window.error());
  }
  // Declared after the window: destroyed before its context goes.
  render::TerrainRendererOptions rendererOptions;
  rendererOptions.warn = options.scene.warnings;  // no sky, layers this GL cannot compile
  rendererOptions.verticesPerSide = (*scene)->store().manifest().verticesPerSide;
  auto renderer = render::TerrainRenderer::create(rendererOptions);
  if (!renderer) return Error{renderer.error()};
  RendererGpu gpu(**renderer, options.scene);
  auto hud = render::HudRenderer::create({});
  if (!hud) return Error{hud.error()};
  auto labels = OverlayDrawing::create(**scene);
  if (!labels) return Error{labels.error()};
  auto profilePanel = ProfilePanel::create();
  if (!profilePanel) return Error{profilePanel.error()};
  // The files given and opened, kept apart from the ruler's path (M) shown after them.
  Documents userOverlays = (*scene)->options().overlays;
  Ruler ruler;
  std::shared_ptr<const overlays::OverlayDocument> rulerOverlay;
  uint64_t rulerRevisionShown = 0;
  bool profileShown = false;
  if (options.imagery) {
    if (auto draped = drapeImagery(**renderer, *options.imagery); !draped)
      return Error{draped.error()};
  }
  std::error_code directoryError;
  if (!options.recordDirectory.empty()) {
    std::filesystem::create_directories(options.recordDirectory, directoryError);
  }

  const geo::Ellipsoid& ellipsoid = (*scene)->ellipsoid();
  const double fovY = options.scene.fovYRadians;
  // Picks march through the tiles drawn now (the scene keeps one array, updated each frame).
  const terrain::RenderingTileArray& drawnArray = (*scene)->renderingTileArray();
  camera::Navigator navigator(
      ellipsoid, startPose, fovY, [&](double lon, double lat) -> std::optional<double> {
        const auto surface = collision::surfaceHeightAt(drawnArray, ellipsoid, lon, lat,
                                                        collision::SurfaceModel::Exact);
        if (!surface || !surface->found) return std::nullopt;
        return surface->heightMeters;
      });
  // A start pose orbit mode cannot show is changed, and said so (never silently).
  for (const std::string& clamp : camera::describeStartClamp(startPose, navigator.home())) {
    std::fprintf(stderr, "globe view: --camera %s\n", clamp.c_str());
  }
  camera::CameraController controller(navigator.home());
  ViewInput input;
  input.navigator = &navigator;
  input.goToRequest = options.goTo;
  GLFWwindow* handle = (*window)->window();
  input.imagery.lighting = options.scene.imageryLighting;
  input.imagery.layerCount = static_cast<uint32_t>(
      std::min<size_t>(options.scene.layers.size(), terrain::kMaxDrapeLayers));
  for (uint32_t k = 0; k < input.imagery.layerCount; ++k)
    input.imagery.opacity[k] = std::clamp(options.scene.layers[k].opacity, 0.0f, 1.0f);
  installViewCallbacks(handle, input);
  const auto setViewport = [&] {
    int windowWidth = 0, windowHeight = 0;  // events and picks take window pixels
    glfwGetWindowSize(handle, &windowWidth, &windowHeight);
    navigator.setViewport(windowWidth, windowHeight);
  };
  setViewport();
  PathRecorder recorder;
  std::optional<std::string> suggestedFor;  // the go-to text the suggestions are for
  std::vector<std::string> suggestions;

  const bool continuous = options.frames > 0;
  const auto start = Clock::now();
  auto lastChange = start, lastDraw = start, lastUpdate = start;
  const auto secondsAt = [&](Clock::time_point t) {
    return std::chrono::duration<double>(t - start).count();
  };
  ViewReport report;
  std::vector<geo::TileId> drawnTiles;
  std::string title;
  std::vector<std::string> drawnHud;  // the HUD's status lines drawn, frame time aside
  bool drawnHelp = false;
  double frameMilliseconds = 0;
  bool loading = true, wasComplete = false, tilesChanged = false;
  bool saidIdle = false;  // --log: the last state said was "view idle" (else "view busy")
  std::pair<int, int> saidSize{0, 0};
  while (!(*window)->shouldClose()) {
    setViewport();
    const int width = (*window)->framebufferWidthPixels();
    const int height = (*window)->framebufferHeightPixels();
    if (options.log && saidSize != std::pair{width, height}) {  // resizes come late (F11)
      saidSize = {width, height};
      std::printf("view size %dx%d\n", width, height);
    }
    const bool visible = width > 0 && height > 0;  // not minimised
    if (visible && (input.changed || loading || continuous)) {
      const auto now = Clock::now();
      bool redraw = input.changed || continuous;
      if (input.changed) lastChange = now;
      input.changed = false;
      // Animations run on the clock; the controller's motion integrates at most 0.1 s a frame.
      const double frameSeconds =
          std::max(std::chrono::duration<double>(now - lastUpdate).count(), 0.0);
      const double dtSeconds = std::min(frameSeconds, 0.1);
      lastUpdate = now;

      // One-shot requests.
      if (input.recordToggleRequested) {
        input.recordToggleRequested = false;
        if (recorder.recording()) {
          writeRecordedPath(options.recordDirectory,
                            recorder.stop(secondsAt(now), controller.pose()));
        } else {
          recorder.start(secondsAt(now), controller.pose());
          std::printf("recording the path (P again stops and writes it)\n");
          std::fflush(stdout);
        }
      }
      if (input.saveViewRequest) {
        input.promptMessage = saveView(*input.saveViewRequest, controller.pose());
        input.saveViewRequest.reset();
        input.changed = true;
      }
      if (input.goToRequest) {
        // A saved view by its name first, then a place or a position.
        auto views = camera::readSavedViews(camera::userViewsFile());
        const camera::SavedView* view =
            views ? camera::findSavedView(*views, *input.goToRequest) : nullptr;
        if (view != nullptr) {
          camera::CameraPose pose = view->pose;
          if (view->heightAboveTerrain) {
            if (auto ground = (*scene)->terrainHeightMeters(pose.position.longitudeRadians,
                                                            pose.position.latitudeRadians)) {
              pose.position.heightMeters += *ground;
            }
          }
          navigator.flyToPose(pose);
          input.promptMessage.clear();
          std::printf("go to view %s\n", view->name.c_str());
          std::fflush(stdout);
          input.goToRequest.reset();
          input.changed = true;
        }
      }
      if (input.goToRequest) {
        auto target = parseGoTo(*input.goToRequest);
        input.goToRequest.reset();
        if (!target) {
          input.promptMessage = target.error();
        } else {
          input.promptMessage.clear();
          navigator.goTo(geo::degreesToRadians(target->longitudeDegrees),
                         geo::degreesToRadians(target->latitudeDegrees));
          std::printf("go to %s (%.5f, %.5f)\n", target->name.c_str(), target->latitudeDegrees,
                      target->longitudeDegrees);
          std::fflush(stdout);
        }
        input.changed = true;
      }

      if (!input.openFileRequests.empty()) {
        input.promptMessage =
            openOverlays(**scene, gpu, input.openFileRequests, userOverlays, rulerOverlay, *labels);
        input.openFileRequests.clear();
        input.changed = true;
      }
      // The ruler: M turns it on, or off and clears it; a click adds a point; Backspace undoes.
      if (input.rulerOn != ruler.active()) ruler.setActive(input.rulerOn);
      if (input.rulerUndoRequested) {
        input.rulerUndoRequested = false;
        ruler.undo();
      }
      if (input.clickRequest && input.rulerOn) {
        if (const auto ground = navigator.groundAt(*input.clickRequest)) {
          if (const auto at = geo::ecefToCartographic(ellipsoid, *ground)) {
            int windowWidth = 0;
            glfwGetWindowSize(handle, &windowWidth, nullptr);
            const double toWindow = static_cast<double>(windowWidth) / std::max(width, 1);
            const RulerPoint point{at->longitudeDegrees(), at->latitudeDegrees(), at->heightMeters};
            ruler.click(point, *input.clickRequest,
                        ruler.points().empty() ? std::nullopt
                                               : windowPixelOf((*scene)->view(), ellipsoid,
                                                               ruler.points().front(), toWindow));
            if (!ruler.closed()) {
              std::printf("ruler point %zu: %.7f,%.7f\n", ruler.points().size(),
                          point.longitudeDegrees, point.latitudeDegrees);
            }
          }
        }
        input.clickRequest.reset();
        input.changed = true;
      }
      if (input.clickRequest) {
        if (*labels) {
          const glm::dvec2 pixel = *input.clickRequest;
          int windowWidth = 0, windowHeight = 0;
          glfwGetWindowSize(handle, &windowWidth, &windowHeight);
          std::optional<geo::Cartographic> ground;
          double metersPerPixel = 0;
          if (const auto groundEcef = navigator.groundAt(pixel)) {
            ground = geo::ecefToCartographic(ellipsoid, *groundEcef);
            metersPerPixel = glm::length(*groundEcef - (*scene)->view().cameraEcefMeters) * 2 *
                             std::tan(fovY / 2) / std::max(windowHeight, 1);
          }
          // Label boxes are in framebuffer pixels, clicks in window pixels.
          const double toFramebuffer = static_cast<double>(width) / std::max(windowWidth, 1);
          const auto picked =
              (*labels)->pick(**scene, pixel * toFramebuffer, ground, metersPerPixel);
          // The ruler's own marks are not placemarks to pick.
          (*labels)->select(picked && picked->document < userOverlays.size() ? picked
                                                                             : std::nullopt);
          if ((*labels)->selected()) {
            std::printf("placemark: %s\n", (*scene)
                                               ->options()
                                               .overlays[picked->document]
                                               ->placemarks[picked->placemark]
                                               .name.c_str());
            std::fflush(stdout);
          }
        }
        input.clickRequest.reset();
        input.changed = true;
      }

      if (ruler.revision() != rulerRevisionShown) {
        rulerRevisionShown = ruler.revision();
        rulerOverlay = rulerDocument(ruler);
        if (auto shown = showOverlays(**scene, gpu, userOverlays, rulerOverlay, *labels); !shown) {
          input.promptMessage = "ruler: " + shown.error();
        }
        std::printf("%s\n", rulerLogLine(ruler).c_str());
        std::fflush(stdout);
        input.changed = true;
      }
      // X: the chart of profilePath(), remade when it changes; hidden while there is none.
      if (input.profileVisible) {
        const std::vector<measure::PathPoint> path = profilePath(ruler, **scene, labels->get());
        if (path.size() < 2) {
          (*profilePanel)->clear();
          if (!profileShown) {
            input.promptMessage = "profile: measure a path (M) or pick a line first";
            input.profileVisible = false;
          }
        } else if (auto updated =
                       (*profilePanel)->update(path, (*scene)->store(), ellipsoid, width, height);
                   !updated) {
          input.promptMessage = "profile: " + updated.error();
          input.profileVisible = false;
        } else if (*updated) {
          if (input.promptMessage.starts_with("profile: ")) input.promptMessage.clear();
          std::printf("profile: %zu samples, %.2f m, min %.1f m, max %.1f m\n", (*updated)->samples,
                      (*updated)->lengthMeters, (*updated)->lowestMeters,
                      (*updated)->highestMeters);
          std::fflush(stdout);
          redraw = true;
        }
        profileShown = input.profileVisible;
      } else if (profileShown) {
        (*profilePanel)->clear();
        profileShown = false;
        redraw = true;
      }

      // This frame's move, proposed to the controller, which checks it against the tiles drawn
      // now (QOTCD) and corrects it (stop, slide, heighten, raise).
      if (const auto proposal = navigator.update(frameSeconds)) {
        controller.propose(proposal->pose, proposal->kind);
      }
      if (navigator.animating()) input.changed = true;  // keep flying
      controller.setNearPlane({camera::projectionForHeight(
                                   0, controller.settings().clearance.eyeMeters, fovY, 1, ellipsoid)
                                   .nearMeters,
                               fovY, static_cast<double>(width) / std::max(height, 1)});
      const camera::CollisionState& collisionState =
          controller.update(dtSeconds, (*scene)->renderingTileArray(), ellipsoid);
      navigator.adopt(controller.pose(), collisionState);
      // A smooth raise over new, finer terrain takes a few frames: keep updating until done.
      if (collisionState.raisedForNewTerrain) input.changed = true;
      recorder.sample(secondsAt(now), controller.pose());
      const scene::FrameInfo info = (*scene)->update(controller.pose(), width, height, gpu);
      tilesChanged =
          tilesChanged || info.arrived > 0 || info.uploaded > 0 || (*scene)->tiles() != drawnTiles;
      loading = !info.complete;
      const bool throttled = loading && now - lastDraw < kLoadingRedrawInterval;
      redraw = redraw || (tilesChanged && !throttled);

      // The HUD: redrawn when what it says changes (the frame time alone does not count).
      HudState hudState;
      hudState.mode = navigator.mode();
      hudState.pose = controller.pose();
      hudState.collision = collisionState;
      hudState.tilesDrawn = (*scene)->tiles().size();
      hudState.tilesLoading = info.requests;
      hudState.tilesMissing = info.missingTiles;
      hudState.flySpeedMetersPerSecond = navigator.flySpeedMetersPerSecond();
      hudState.speedFactor = navigator.speed().factor();
      hudState.recording = recorder.recording();
      hudState.keyframes = recorder.keyframes().size();
      hudState.flyingTo = navigator.flyingTo();
      if (input.promptOpen) {
        // The gazetteer searched again only when the text changes (tens of ms a search).
        if (!suggestedFor || *suggestedFor != input.promptText) {
          suggestions = goToSuggestions(input.promptText, 5);
          suggestedFor = input.promptText;
        }
        hudState.prompt = input.promptText;
        hudState.promptSavesView = input.promptSavesView;
        hudState.promptOpensFile = input.promptOpensFile;
        if (!input.promptSavesView && !input.promptOpensFile) hudState.suggestions = suggestions;
      }
      hudState.message = input.promptMessage;
      if (ruler.active()) hudState.ruler = rulerHudLine(ruler);
      hudState.warning = recentWarning->shown();
      const streaming::LoaderCounters loads = (*scene)->loader().counters();
      if (loads.failed > 0) {
        hudState.network =
            std::to_string(loads.failed) + " tile load" + (loads.failed == 1 ? "" : "s") +
            " failed" +
            (options.scene.retryFailedLoadsSeconds > 0
                 ? ", retried every " +
                       std::to_string(static_cast<int>(options.scene.retryFailedLoadsSeconds)) +
                       " s"
                 : "");
      }
      if (input.cursorKnown) {
        if (const auto ground = navigator.groundAt(glm::dvec2(input.lastX, input.lastY))) {
          hudState.underCursor = geo::ecefToCartographic(ellipsoid, *ground);
        }
      }
      hudState.metersPerPixel = navigator.metersPerPixelAtCentre();
      hudState.lighting = input.imagery.lighting;
      hudState.selectedLayer = input.imagery.selected;
      for (uint32_t k = 0; k < input.imagery.layerCount; ++k) {
        hudState.layers.push_back({input.imagery.shown[k], input.imagery.opacity[k]});
        gpu.setLayer(k, input.imagery.shown[k], input.imagery.opacity[k]);
      }
      gpu.setImageryLighting(input.imagery.lighting);
      std::vector<std::string> hudKey = hudStatusLines(hudState, false);
      // The compass and the scale bar change the HUD too (to the degree, to the pixel).
      const auto rounded = [](double value) {
        return std::isfinite(value) && std::abs(value) < 1e15 ? std::to_string(std::lround(value))
                                                              : std::string("-");
      };
      hudKey.push_back(rounded(geo::radiansToDegrees(controller.pose().headingRadians)) + " " +
                       rounded(hudState.metersPerPixel * 100));
      const bool hudChanged = hudKey != drawnHud || input.helpVisible != drawnHelp;
      redraw = redraw || (hudChanged && !throttled) || input.screenshotRequested;

      if (redraw) {
        const auto drawStart = Clock::now();
        tilesChanged = false;
        lastDraw = now;
        if (hudChanged || continuous) {
          hudState.frameMilliseconds = frameMilliseconds;
          // Picks and clicks are in window pixels, the HUD in the framebuffer's.
          int windowWidth = 0, windowHeight = 0;
          glfwGetWindowSize(handle, &windowWidth, &windowHeight);
          const double toWindow = static_cast<double>(windowWidth) / std::max(width, 1);
          std::pair<glm::dvec2, glm::dvec2> compassBox;
          std::vector<render::HudItem> items = hudItems(
              hudStatusLines(hudState), input.helpVisible, controller.pose().headingRadians,
              hudState.metersPerPixel * toWindow, width, height, compassBox);
          if (auto block = attributionBlock(attributions, width, height)) {
            items.push_back(*block);
          }
          input.compassTopLeft = compassBox.first * toWindow;
          input.compassBottomRight = compassBox.second * toWindow;
          (*hud)->setItems(items);
          drawnHud = std::move(hudKey);
          drawnHelp = input.helpVisible;
        }
        gpu.draw(**scene);
        if (*labels) {
          (*labels)->draw(**scene);
          (*labels)->drawPanel(**scene, width, height);
        }
        // Above the scale bar at the bottom left.
        (*profilePanel)->draw(width, height, height >= 600 ? 68.0f : 34.0f);
        (*hud)->draw(width, height);
        if (input.screenshotRequested) {
          input.screenshotRequested = false;
          writeScreenshot(options.recordDirectory, width, height);
        }
        (*window)->swapBuffers();
        frameMilliseconds = millisecondsSince(drawStart);
        ++report.framesDrawn;
        if (options.log && saidIdle) {  // so a log's last line says whether the view moves
          std::printf("view busy: frame %d\n", report.framesDrawn);
          std::fflush(stdout);
          saidIdle = false;
        }
        drawnTiles = (*scene)->tiles();
        if (std::string next =
                titleFor(controller.pose(), drawnTiles.size(), loading, controller.state());
            next != title) {
          title = std::move(next);
          glfwSetWindowTitle(handle, title.c_str());
        }
      }
      if (options.log && info.complete && !wasComplete) {
        std::printf("view complete: %zu tiles, %.0f ms after the last change, frame %d\n",
                    drawnTiles.size(), millisecondsSince(lastChange), report.framesDrawn);
        std::fflush(stdout);
      }
      wasComplete = info.complete;
    }
    if (continuous && report.framesDrawn >= options.frames) break;
    if (continuous || (visible && input.changed)) {
      glfwPollEvents();
    } else if (visible && loading && (*scene)->loader().counters().inFlight > 0) {
      // Wake as soon as a load finishes (each update round starts only a few loads), or after
      // kLoadWait at the latest for input.
      glfwPollEvents();
      (*scene)->waitForLoads(kLoadWait);
    } else if (visible && loading) {
      glfwWaitEventsTimeout(std::chrono::duration<double>(kLoadWait).count());
    } else {
      // Said each time the window waits for input: everything it was sent is handled and on
      // screen (scripts driving the window wait for this line instead of sleeping).
      if (options.log) {
        std::printf("view idle: frame %d\n", report.framesDrawn);
        std::fflush(stdout);
        saidIdle = true;
      }
      glfwWaitEvents();  // idle (or minimised): nothing moves until an event arrives
    }
  }

  if (recorder.recording()) {  // closed while recording: keep what was flown
    writeRecordedPath(options.recordDirectory,
                      recorder.stop(secondsAt(Clock::now()), controller.pose()));
  }
  report.finalPose = controller.pose();
  if (options.screenshot) {
    // The back buffer is undefined after a swap: draw the last frame again and read it back.
    const int width = (*window)->framebufferWidthPixels();
    const int height = (*window)->framebufferHeightPixels();
    gpu.draw(**scene);
    if (*labels) {
      (*labels)->draw(**scene);
      (*labels)->drawPanel(**scene, width, height);
    }
    const std::vector<uint8_t> pixels = render::readPixelsRgba(width, height);
    if (auto written = formats::writePngAtomically(*options.screenshot, pixels, width, height);
        !written) {
      return Error{written.error()};
    }
  }
  if (options.log) {
    std::printf("frames drawn: %d\ncamera %s\n", report.framesDrawn,
                formatPose(report.finalPose).c_str());
    std::fflush(stdout);
  }
  return report;
}

}  // namespace globe::app
