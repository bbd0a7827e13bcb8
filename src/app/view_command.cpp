#define GLFW_INCLUDE_NONE
#include "app/view_command.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "app/orbit_controls.hpp"
#include "camera/camera_controller.hpp"
#include "io/image_io.hpp"
#include "render/glfw_window_context.hpp"
#include "render/read_pixels.hpp"

namespace globe::app {
namespace {

constexpr double kPanPixelsPerKey = 60;        // an arrow key pans like a drag this long
constexpr const char* kTitlePrefix = "globe";  // tests find the window by this name

// What the GLFW callbacks change; the loop reads it between event waits.
struct InputState {
  OrbitControls* controls = nullptr;
  bool changed = true;  // the camera moved or the window needs repainting
  bool leftDown = false, rightDown = false, shiftDrag = false;
  double lastX = 0, lastY = 0;
  bool cursorKnown = false;
};

InputState& inputOf(GLFWwindow* window) {
  return *static_cast<InputState*>(glfwGetWindowUserPointer(window));
}

void onKey(GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  InputState& input = inputOf(window);
  OrbitControls& controls = *input.controls;
  int height = 0;
  glfwGetWindowSize(window, nullptr, &height);
  switch (key) {
    case GLFW_KEY_ESCAPE:
    case GLFW_KEY_Q:
      glfwSetWindowShouldClose(window, GLFW_TRUE);
      return;
    case GLFW_KEY_R:
      controls.reset();
      break;
    case GLFW_KEY_UP:
      controls.rotateByDrag(0, kPanPixelsPerKey, height);
      break;
    case GLFW_KEY_DOWN:
      controls.rotateByDrag(0, -kPanPixelsPerKey, height);
      break;
    case GLFW_KEY_LEFT:
      controls.rotateByDrag(kPanPixelsPerKey, 0, height);
      break;
    case GLFW_KEY_RIGHT:
      controls.rotateByDrag(-kPanPixelsPerKey, 0, height);
      break;
    case GLFW_KEY_EQUAL:  // '+' is shift + '=' on most layouts
    case GLFW_KEY_KP_ADD:
      controls.zoom(1);
      break;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT:
      controls.zoom(-1);
      break;
    default:
      return;
  }
  input.changed = true;
}

void onScroll(GLFWwindow* window, double /*dx*/, double dy) {
  InputState& input = inputOf(window);
  input.controls->zoom(dy);
  input.changed = true;
}

void onMouseButton(GLFWwindow* window, int button, int action, int mods) {
  InputState& input = inputOf(window);
  const bool down = action == GLFW_PRESS;
  if (button == GLFW_MOUSE_BUTTON_LEFT) {
    input.leftDown = down;
    input.shiftDrag = down && (mods & GLFW_MOD_SHIFT) != 0;
  } else if (button == GLFW_MOUSE_BUTTON_RIGHT) {
    input.rightDown = down;
  }
  // The position from the last motion event, not the pointer's now: events may lag the pointer.
  if (down && !input.cursorKnown) glfwGetCursorPos(window, &input.lastX, &input.lastY);
  input.cursorKnown = true;
}

void onCursor(GLFWwindow* window, double x, double y) {
  InputState& input = inputOf(window);
  const double dx = x - input.lastX, dy = y - input.lastY;
  input.lastX = x;
  input.lastY = y;
  input.cursorKnown = true;
  if (input.rightDown || (input.leftDown && input.shiftDrag)) {
    input.controls->tiltByDrag(dx, dy);
  } else if (input.leftDown) {
    int height = 0;
    glfwGetWindowSize(window, nullptr, &height);
    input.controls->rotateByDrag(dx, dy, height);
  } else {
    return;
  }
  input.changed = true;
}

void onRepaintNeeded(GLFWwindow* window) { inputOf(window).changed = true; }
void onFramebufferSize(GLFWwindow* window, int, int) { inputOf(window).changed = true; }

// The HUD for now: position, tiles, and what collision did this frame.
std::string titleFor(const camera::CameraPose& pose, size_t tiles, bool loading,
                     const camera::CollisionState& collision) {
  char text[320];
  std::snprintf(text, sizeof text,
                "%s  lon %.5f  lat %.5f  height %.0f m  terrain %.1f m  clearance %.1f m  %s%s  "
                "tiles %zu%s",
                kTitlePrefix, pose.position.longitudeDegrees(), pose.position.latitudeDegrees(),
                pose.position.heightMeters, collision.terrainHeightMeters,
                collision.clearanceMeters, collision.collided ? "COLLISION " : "",
                std::string(collision::toString(collision.response)).c_str(), tiles,
                loading ? " (loading)" : "");
  return text;
}

bool samePose(const camera::CameraPose& a, const camera::CameraPose& b) {
  return a.position.longitudeRadians == b.position.longitudeRadians &&
         a.position.latitudeRadians == b.position.latitudeRadians &&
         a.position.heightMeters == b.position.heightMeters &&
         a.headingRadians == b.headingRadians && a.pitchRadians == b.pitchRadians &&
         a.rollRadians == b.rollRadians;
}

std::string formatPose(const camera::CameraPose& pose) {
  char text[160];
  std::snprintf(text, sizeof text, "%.6f,%.6f,%.2f,%.3f,%.3f,%.3f",
                pose.position.longitudeDegrees(), pose.position.latitudeDegrees(),
                pose.position.heightMeters, geo::radiansToDegrees(pose.headingRadians),
                geo::radiansToDegrees(pose.pitchRadians), geo::radiansToDegrees(pose.rollRadians));
  return text;
}

}  // namespace

Result<ViewReport> runView(const ViewOptions& options) {
  if (!options.pose.isFinite()) return makeError("the camera pose is not finite");
  auto scene = TerrainScene::open(options.pyramid, options.scene);
  if (!scene) return Error{scene.error()};
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
  auto renderer = render::TerrainRenderer::create({});
  if (!renderer) return Error{renderer.error()};
  if (options.imagery) {
    auto image = io::loadImageRgba(*options.imagery);
    if (!image) return Error{image.error()};
    if (auto set = (*renderer)->setImagery(image->pixels, image->widthPixels, image->heightPixels);
        !set) {
      return Error{set.error()};
    }
  }

  OrbitControls controls((*scene)->ellipsoid(), options.pose, options.scene.fovYRadians);
  camera::CameraController controller(options.pose);
  InputState input;
  input.controls = &controls;
  GLFWwindow* handle = (*window)->window();
  glfwSetWindowUserPointer(handle, &input);
  glfwSetKeyCallback(handle, onKey);
  glfwSetScrollCallback(handle, onScroll);
  glfwSetMouseButtonCallback(handle, onMouseButton);
  glfwSetCursorPosCallback(handle, onCursor);
  glfwSetWindowRefreshCallback(handle, onRepaintNeeded);
  glfwSetFramebufferSizeCallback(handle, onFramebufferSize);

  const bool continuous = options.frames > 0;
  const auto start = std::chrono::steady_clock::now();
  auto lastChange = start, lastDraw = start, lastUpdate = start;
  ViewReport report;
  std::vector<geo::TileId> drawnTiles;
  std::string title;
  bool loading = true, wasComplete = false, tilesChanged = false;
  while (!(*window)->shouldClose()) {
    const int width = (*window)->framebufferWidthPixels();
    const int height = (*window)->framebufferHeightPixels();
    const bool visible = width > 0 && height > 0;  // not minimised
    if (visible && (input.changed || loading || continuous)) {
      const auto now = std::chrono::steady_clock::now();
      bool redraw = input.changed || continuous;
      if (input.changed) lastChange = now;
      input.changed = false;
      // The controller moves the camera to the pose the controls ask for, checked by QOTCD
      // against the tiles drawn now, and corrects it (stop, slide, heighten, raise).
      const double dtSeconds =
          std::clamp(std::chrono::duration<double>(now - lastUpdate).count(), 0.0, 0.1);
      lastUpdate = now;
      if (!samePose(controls.pose(), controller.pose())) controller.propose(controls.pose());
      controller.setNearPlane(
          {camera::projectionForHeight(0, controller.settings().clearance.eyeMeters,
                                       options.scene.fovYRadians, 1, (*scene)->ellipsoid())
               .nearMeters,
           options.scene.fovYRadians, static_cast<double>(width) / std::max(height, 1)});
      const camera::CollisionState& collisionState =
          controller.update(dtSeconds, (*scene)->renderingTileArray(), (*scene)->ellipsoid());
      if (!samePose(controls.pose(), controller.pose())) controls.adoptPose(controller.pose());
      // The controls scale zoom steps by the height above the terrain the controller found.
      if (collisionState.terrainFound) controls.setGroundHeight(collisionState.terrainHeightMeters);
      // A smooth raise over new, finer terrain takes a few frames: keep updating until done.
      if (collisionState.raisedForNewTerrain) input.changed = true;
      const FrameInfo info = (*scene)->update(controller.pose(), width, height, **renderer);
      tilesChanged =
          tilesChanged || info.arrived > 0 || info.uploaded > 0 || (*scene)->tiles() != drawnTiles;
      loading = !info.complete;
      redraw = redraw || (tilesChanged && (!loading || now - lastDraw >= kLoadingRedrawInterval));
      if (redraw) {
        tilesChanged = false;
        lastDraw = now;
        (*scene)->draw(**renderer);
        (*window)->swapBuffers();
        ++report.framesDrawn;
        drawnTiles = (*scene)->tiles();
        if (std::string next =
                titleFor(controller.pose(), drawnTiles.size(), loading, controller.state());
            next != title) {
          title = std::move(next);
          glfwSetWindowTitle(handle, title.c_str());
        }
      }
      if (options.log && info.complete && !wasComplete) {
        std::printf(
            "view complete: %zu tiles, %.0f ms after the last change, frame %d\n",
            drawnTiles.size(),
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - lastChange)
                .count(),
            report.framesDrawn);
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
      glfwWaitEvents();  // idle (or minimised): nothing moves until an event arrives
    }
  }

  report.finalPose = controller.pose();
  if (options.screenshot) {
    // The back buffer is undefined after a swap: draw the last frame again and read it back.
    const int width = (*window)->framebufferWidthPixels();
    const int height = (*window)->framebufferHeightPixels();
    (*scene)->draw(**renderer);
    const std::vector<uint8_t> pixels = render::readPixelsRgba(width, height);
    if (auto written = io::writePngAtomically(*options.screenshot, pixels, width, height);
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
