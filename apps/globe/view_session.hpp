// `globe view`'s state between frames and the steps of one frame, each a function of its own:
// the loop (view_command.cpp) opens a session, then per frame takes the requests the keys and
// clicks left (view_requests.cpp), moves the camera through the controller, updates the scene,
// draws when something changed and waits for the next event (view_frame.cpp).
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "apps/globe/hud_text.hpp"
#include "apps/globe/model_drawing.hpp"
#include "apps/globe/overlay_drawing.hpp"
#include "apps/globe/path_recorder.hpp"
#include "apps/globe/profile_panel.hpp"
#include "apps/globe/recent_warning.hpp"
#include "apps/globe/renderer_gpu.hpp"
#include "apps/globe/ruler.hpp"
#include "apps/globe/view_command.hpp"
#include "apps/globe/view_input.hpp"
#include "camera/camera_controller.hpp"
#include "camera/navigator.hpp"
#include "overlays/overlay_file.hpp"
#include "render/glfw_window_context.hpp"
#include "render/hud_renderer.hpp"
#include "render/multisample_target.hpp"

namespace globe::app {

using ViewClock = std::chrono::steady_clock;
using Documents = std::vector<std::shared_ptr<const overlays::OverlayDocument>>;
inline constexpr const char* kTitlePrefix = "globe";  // tests find the window by this name

// Members in the order they are made; destroyed in reverse, so every GL object goes before the
// window's context.
struct ViewSession {
  explicit ViewSession(const ViewOptions& viewOptions) : options(viewOptions) {}
  const ViewOptions& options;
  std::shared_ptr<RecentWarning> recentWarning;
  std::unique_ptr<scene::TerrainScene> scene;
  std::vector<std::string> attributions;  // shown at the bottom right as their services ask
  std::unique_ptr<render::GlfwWindowContext> window;
  std::unique_ptr<render::TerrainRenderer> renderer;
  std::unique_ptr<RendererGpu> gpu;
  std::unique_ptr<render::HudRenderer> hud;
  std::unique_ptr<render::MultisampleTarget> multisample;  // --samples > 1: the frame's target
  std::unique_ptr<OverlayDrawing> labels;                  // null: no overlay to label
  std::unique_ptr<ModelDrawing> models;                    // null: no tileset
  std::unique_ptr<ProfilePanel> profilePanel;

  // The files given and opened, kept apart from the ruler's path (M) shown after them.
  Documents userOverlays;
  Ruler ruler;
  std::shared_ptr<const overlays::OverlayDocument> rulerOverlay;
  uint64_t rulerRevisionShown = 0;
  bool profileShown = false;

  std::optional<camera::Navigator> navigator;
  std::optional<camera::CameraController> controller;
  ViewInput input;
  PathRecorder recorder;
  std::optional<std::string> suggestedFor;  // the go-to text the suggestions are for
  std::vector<std::string> suggestions;

  // The loop's clock and what the last frame drew.
  ViewClock::time_point start, lastChange, lastDraw, lastUpdate;
  ViewReport report;
  std::vector<geo::TileId> drawnTiles;
  std::string title;
  std::vector<std::string> drawnHud;  // the HUD's status lines drawn, frame time aside
  bool drawnHelp = false;
  double frameMilliseconds = 0;
  bool loading = true, wasComplete = false, tilesChanged = false;
  bool saidIdle = false;  // --log: the last state said was "view idle" (else "view busy")
  std::pair<int, int> saidSize{0, 0};
  // The HUD's one-line message (input.promptMessage) and since when it shows: it goes after
  // kMessageLifetime (expireMessage), the window waking for it.
  PlacemarkPanelPlace panelPlace;  // the placemark panel's (placemarkPanelPlace)
  std::string shownMessage;
  ViewClock::time_point shownMessageAt;
  static constexpr std::chrono::seconds kMessageLifetime{5};

  bool continuous() const { return options.frames > 0; }
  double secondsAt(ViewClock::time_point t) const {
    return std::chrono::duration<double>(t - start).count();
  }
  const geo::Ellipsoid& ellipsoid() const { return scene->ellipsoid(); }
  // The window's size in its own pixels (events, clicks, picks), not the framebuffer's.
  std::pair<int, int> windowSize() const;
};

// view_command.cpp: the scene, the window and everything drawn in it, the camera at the start.
Result<std::unique_ptr<ViewSession>> openViewSession(const ViewOptions& options);

// view_requests.cpp: what the keys and clicks asked since the last frame (recording, saving a
// view, going to a place or view, opening files; a click for the ruler or a pick); the ruler's
// overlay and the profile chart brought up to date. True when the frame must be drawn again.
void takeRequests(ViewSession& s, ViewClock::time_point now);
void takeClick(ViewSession& s, int width);
bool updateRulerAndProfile(ViewSession& s, int width, int height);

// The HUD's items in framebuffer pixels (view_frame.cpp): the status block at the top left, the
// help under it when shown, the compass rose at the top right (its box into compassBox) and the
// scale bar at the bottom left.
std::vector<render::HudItem> hudItems(std::vector<std::string> status, bool help,
                                      double headingRadians, double metersPerPixel, int widthPixels,
                                      int heightPixels,
                                      std::pair<glm::dvec2, glm::dvec2>& compassBox);

// The HUD's text and widgets twice the size on large windows (a 70-character status line at 2×
// needs ~900 pixels besides the compass rose).
inline float hudScale(int widthPixels, int heightPixels) {
  return heightPixels >= 600 && widthPixels >= 1200 ? 2.0f : 1.0f;
}

// Where the placemark panel goes: at the right edge under the rose, beside the text blocks (the
// first `textBlocks` items) when at least kMinimumPanelWidth is left there, else under them too.
inline constexpr float kMinimumPanelWidth = 200.0f;
PlacemarkPanelPlace placemarkPanelPlace(const std::vector<render::HudItem>& items,
                                        size_t textBlocks,
                                        const std::pair<glm::dvec2, glm::dvec2>& compassBox,
                                        int widthPixels);

// view_frame.cpp: the HUD's state for this frame; the frame drawn (terrain, overlays, panels,
// HUD, a screenshot when asked); the wait for the next event or load.
HudState hudStateOf(ViewSession& s, const scene::FrameInfo& info,
                    const camera::CollisionState& collision);
// The terrain and overlays (multisampled with --samples, resolved into the window's buffer, the
// target following the window's size); then panels and the HUD are drawn sharp over them.
void drawWorld(ViewSession& s, int width, int height);
void drawFrame(ViewSession& s, HudState& hudState, std::vector<std::string> hudKey, bool hudChanged,
               int width, int height);
void waitForEvents(ViewSession& s, bool visible);
// A message shown kMessageLifetime ago is cleared (said on --log); a new one starts its time.
void expireMessage(ViewSession& s, ViewClock::time_point now);
void writeRecordedPath(const std::filesystem::path& directory,
                       const std::vector<PathKeyframe>& keyframes);
std::string formatPose(const camera::CameraPose& pose);

}  // namespace globe::app
