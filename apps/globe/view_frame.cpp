// One frame of `globe view` after the requests: the HUD's state, the drawing (only when something
// changed) and the wait for what comes next (view_session.hpp).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "apps/globe/attribution_stamp.hpp"
#include "apps/globe/elapsed.hpp"
#include "apps/globe/go_to.hpp"
#include "apps/globe/ruler_overlay.hpp"
#include "apps/globe/view_actions.hpp"
#include "apps/globe/view_session.hpp"
#include "formats/image_io.hpp"
#include "formats/pyramid_manifest.hpp"
#include "geo/ecef.hpp"
#include "render/hud_widgets.hpp"
#include "render/read_pixels.hpp"

namespace globe::app {
namespace {

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

std::filesystem::path shown(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(path, error);
  return error ? path : absolute;
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

}  // namespace

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
  statusBlock.scale = hudScale(widthPixels, heightPixels);
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

PlacemarkPanelPlace placemarkPanelPlace(const std::vector<render::HudItem>& items,
                                        size_t textBlocks,
                                        const std::pair<glm::dvec2, glm::dvec2>& compassBox,
                                        int widthPixels) {
  float right = 0.0f, bottom = 0.0f;
  for (size_t k = 0; k < std::min(textBlocks, items.size()); ++k) {
    if (const auto* block = std::get_if<render::HudTextBlock>(&items[k])) {
      const glm::vec2 corner = block->topLeftPixels + render::hudBlockSizePixels(*block);
      right = std::max(right, corner.x);
      bottom = std::max(bottom, corner.y);
    }
  }
  PlacemarkPanelPlace place;
  place.topPixels = static_cast<float>(compassBox.second.y) + 8.0f;
  const float beside = static_cast<float>(widthPixels) - 12.0f - (right + 8.0f);
  if (beside >= kMinimumPanelWidth) {
    place.maxWidthPixels = beside;
  } else {
    place.topPixels = std::max(place.topPixels, bottom + 8.0f);
  }
  return place;
}

namespace {

// The go-to box's text and, for a place, the gazetteer's suggestions (searched again only when
// the text changes).
void promptState(ViewSession& s, HudState& hudState) {
  const ViewInput& input = s.input;
  if (!input.promptOpen) return;
  if (!s.suggestedFor || *s.suggestedFor != input.promptText) {
    s.suggestions = goToSuggestions(input.promptText, 5);
    s.suggestedFor = input.promptText;
  }
  hudState.prompt = input.promptText;
  hudState.promptSavesView = input.promptSavesView;
  hudState.promptOpensFile = input.promptOpensFile;
  if (!input.promptSavesView && !input.promptOpensFile) hudState.suggestions = s.suggestions;
}

// The HUD's line about failed loads, empty while none failed.
std::string networkState(const ViewSession& s) {
  const streaming::LoaderCounters loads = s.scene->loader().counters();
  if (loads.failed == 0) return "";
  const double retry = s.options.scene.retryFailedLoadsSeconds;
  return std::to_string(loads.failed) + " tile load" + (loads.failed == 1 ? "" : "s") + " failed" +
         (retry > 0 ? ", retried every " + std::to_string(static_cast<int>(retry)) + " s" : "");
}

// The HUD's items set anew (text, help, compass, scale bar, attribution) for this framebuffer.
void setHudItems(ViewSession& s, HudState& hudState, int width, int height) {
  hudState.frameMilliseconds = s.frameMilliseconds;
  // Picks and clicks are in window pixels, the HUD in the framebuffer's.
  const double toWindow = static_cast<double>(s.windowSize().first) / std::max(width, 1);
  std::pair<glm::dvec2, glm::dvec2> compassBox;
  std::vector<render::HudItem> items =
      hudItems(hudStatusLines(hudState), s.input.helpVisible, s.controller->pose().headingRadians,
               hudState.metersPerPixel * toWindow, width, height, compassBox);
  if (auto block = attributionBlock(s.attributions, width, height)) items.push_back(*block);
  s.panelPlace = placemarkPanelPlace(items, s.input.helpVisible ? 2 : 1, compassBox, width);
  s.input.compassTopLeft = compassBox.first * toWindow;
  s.input.compassBottomRight = compassBox.second * toWindow;
  s.hud->setItems(items);
}

}  // namespace

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

std::string formatPose(const camera::CameraPose& pose) {
  char text[160];
  std::snprintf(text, sizeof text, "%.6f,%.6f,%.2f,%.3f,%.3f,%.3f",
                pose.position.longitudeDegrees(), pose.position.latitudeDegrees(),
                pose.position.heightMeters, geo::radiansToDegrees(pose.headingRadians),
                geo::radiansToDegrees(pose.pitchRadians), geo::radiansToDegrees(pose.rollRadians));
  return text;
}

HudState hudStateOf(ViewSession& s, const scene::FrameInfo& info,
                    const camera::CollisionState& collision) {
  const camera::Navigator& navigator = *s.navigator;
  HudState hudState;
  hudState.mode = navigator.mode();
  hudState.pose = s.controller->pose();
  hudState.collision = collision;
  hudState.tilesDrawn = s.scene->tiles().size();
  hudState.tilesLoading = info.requests;
  hudState.tilesMissing = info.missingTiles;
  hudState.flySpeedMetersPerSecond = navigator.flySpeedMetersPerSecond();
  hudState.speedFactor = navigator.speed().factor();
  hudState.recording = s.recorder.recording();
  hudState.keyframes = s.recorder.keyframes().size();
  hudState.flyingTo = navigator.flyingTo();
  promptState(s, hudState);
  expireMessage(s, ViewClock::now());
  hudState.message = s.input.promptMessage;
  if (s.ruler.active()) hudState.ruler = rulerHudLine(s.ruler);
  hudState.warning = s.recentWarning->shown();
  hudState.network = networkState(s);
  if (s.input.cursorKnown) {
    if (const auto ground = navigator.groundAt(glm::dvec2(s.input.lastX, s.input.lastY))) {
      hudState.underCursor = geo::ecefToCartographic(s.ellipsoid(), *ground);
    }
  }
  hudState.metersPerPixel = navigator.metersPerPixelAtCentre();
  hudState.lighting = s.input.imagery.lighting;
  hudState.sunUnixSeconds = s.input.sunUnixSeconds;
  const geo::Cartographic& at = hudState.pose.position;
  hudState.terrainData =
      terrainDataText(s.scene->store().manifest(), at.longitudeDegrees(), at.latitudeDegrees());
  hudState.selectedLayer = s.input.imagery.selected;
  for (uint32_t k = 0; k < s.input.imagery.layerCount; ++k) {
    hudState.layers.push_back({s.input.imagery.shown[k], s.input.imagery.opacity[k]});
  }
  return hudState;
}

void drawWorld(ViewSession& s, int width, int height) {
  if (s.multisample) {
    if (s.multisample->widthPixels() != width || s.multisample->heightPixels() != height) {
      if (auto resized = s.multisample->resize(width, height); !resized) {
        std::fprintf(stderr, "globe view: %s; drawing without anti-aliasing\n",
                     resized.error().c_str());
        s.multisample.reset();
      }
    }
  }
  if (s.multisample) s.multisample->bind();
  s.gpu->draw(*s.scene);
  if (s.models) s.models->draw(*s.scene);
  if (s.labels) s.labels->draw(*s.scene);
  if (s.multisample) s.multisample->resolve();
}

namespace {

// Where ECEF points are drawn in the last frame (framebuffer pixels); those behind the camera
// are left out.
std::vector<glm::dvec2> framebufferPixelsOf(const terrain::RenderView& view,
                                            const std::vector<glm::dvec3>& pointsEcef) {
  std::vector<glm::dvec2> pixels;
  const glm::dmat4 toClip = view.projection * view.viewMatrix;
  for (const glm::dvec3& point : pointsEcef) {
    const glm::dvec4 clip = toClip * glm::dvec4(point, 1.0);
    if (!(clip.w > 0)) continue;
    pixels.emplace_back((clip.x / clip.w + 1.0) * 0.5 * view.widthPixels,
                        (1.0 - clip.y / clip.w) * 0.5 * view.heightPixels);
  }
  return pixels;
}

}  // namespace

void drawFrame(ViewSession& s, HudState& hudState, std::vector<std::string> hudKey, bool hudChanged,
               int width, int height) {
  const auto drawStart = ViewClock::now();
  if (hudChanged || s.continuous()) {
    setHudItems(s, hudState, width, height);
    s.drawnHud = std::move(hudKey);
    s.drawnHelp = s.input.helpVisible;
  }
  drawWorld(s, width, height);
  if (s.labels) s.labels->drawPanel(*s.scene, width, height, s.panelPlace);
  // Above the scale bar, in the bottom corner that hides less of the profiled path.
  const float chartMargin = 34.0f * hudScale(width, height);
  s.profilePanel->draw(
      width, height, chartMargin,
      profileChartCorner(framebufferPixelsOf(s.scene->view(), s.profilePanel->groundPointsEcef()),
                         s.profilePanel->sizePixels(), width, height, chartMargin));
  s.hud->draw(width, height);
  if (s.input.screenshotRequested) {
    s.input.screenshotRequested = false;
    writeScreenshot(s.options.recordDirectory, width, height);
  }
  s.window->swapBuffers();
  s.frameMilliseconds = millisecondsSince(drawStart);
  ++s.report.framesDrawn;
  if (s.options.log && s.saidIdle) {  // so a log's last line says whether the view moves
    std::printf("view busy: frame %d\n", s.report.framesDrawn);
    std::fflush(stdout);
    s.saidIdle = false;
  }
  s.drawnTiles = s.scene->tiles();
  if (std::string next =
          titleFor(s.controller->pose(), s.drawnTiles.size(), s.loading, s.controller->state());
      next != s.title) {
    s.title = std::move(next);
    glfwSetWindowTitle(s.window->window(), s.title.c_str());
  }
}

void expireMessage(ViewSession& s, ViewClock::time_point now) {
  if (s.input.promptMessage != s.shownMessage) {
    s.shownMessage = s.input.promptMessage;
    s.shownMessageAt = now;
    return;
  }
  if (s.shownMessage.empty() || now - s.shownMessageAt < ViewSession::kMessageLifetime) return;
  if (s.options.log) {
    std::printf("message expired: %s\n", s.shownMessage.c_str());
    std::fflush(stdout);
  }
  s.input.promptMessage.clear();
  s.shownMessage.clear();
}

void waitForEvents(ViewSession& s, bool visible) {
  if (s.continuous() || (visible && s.input.changed)) {
    glfwPollEvents();
  } else if (visible && s.loading && s.scene->loader().counters().inFlight > 0) {
    // Wake as soon as a load finishes (each update round starts only a few loads), or after
    // kLoadWait at the latest for input.
    glfwPollEvents();
    s.scene->waitForLoads(kLoadWait);
  } else if (visible && s.loading) {
    glfwWaitEventsTimeout(std::chrono::duration<double>(kLoadWait).count());
  } else {
    // Said each time the window waits for input: everything it was sent is handled and on
    // screen (scripts driving the window wait for this line instead of sleeping).
    if (s.options.log) {
      std::printf("view idle: frame %d\n", s.report.framesDrawn);
      std::fflush(stdout);
      s.saidIdle = true;
    }
    if (s.shownMessage.empty()) {
      glfwWaitEvents();  // idle (or minimised): nothing moves until an event arrives
    } else {             // a message to take down when its time is up
      const auto left = ViewSession::kMessageLifetime - (ViewClock::now() - s.shownMessageAt);
      glfwWaitEventsTimeout(std::max(0.01, std::chrono::duration<double>(left).count()));
    }
  }
}

std::pair<int, int> ViewSession::windowSize() const {
  int width = 0, height = 0;
  glfwGetWindowSize(window->window(), &width, &height);
  return {width, height};
}

}  // namespace globe::app
