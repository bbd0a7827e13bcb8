// `globe view`'s input: GLFW key, mouse and scroll callbacks turned into the navigator's plain
// events (camera::Navigator); the window's own actions (record, screenshot, help, the go-to
// prompt) are left for the loop to take; the imagery controls (lighting, layers) are kept here
// for the loop to hand to the renderer.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "camera/fly_controls.hpp"
#include "camera/navigator.hpp"
#include "terrain/relief_shading.hpp"
#include "terrain/tile_drape.hpp"

struct GLFWwindow;

namespace globe::app {

// L cycles the lighting on imagery (auto → on → off); 1-4 show or hide layer 1-4 and select it;
// [ and ] lower and raise the selected layer's opacity by kOpacityStep.
struct ImageryControls {
  terrain::ImageryLighting lighting = terrain::ImageryLighting::Auto;
  uint32_t layerCount = 0;  // --layer given (at most kMaxDrapeLayers)
  std::array<bool, terrain::kMaxDrapeLayers> shown{true, true, true, true};
  std::array<float, terrain::kMaxDrapeLayers> opacity{1.0f, 1.0f, 1.0f, 1.0f};
  uint32_t selected = 0;  // the last toggled
};
inline constexpr float kOpacityStep = 0.1f;

struct ViewInput {
  camera::Navigator* navigator = nullptr;  // every camera move goes to it
  bool changed = true;                     // something to update or redraw
  camera::FlyKeys flyKeys;                 // held now (tracked in both modes, used in fly mode)

  // "Go to" (G): the text typed so far while the prompt is open (it takes every key), the text
  // entered (Enter) for the loop to parse, and what the loop says back (an error).
  bool promptOpen = false;
  bool promptSwallowG = false;   // the opening key's own character (G or V) is not text
  bool promptSavesView = false;  // V: the prompt names the current view to save
  bool promptOpensFile = false;  // O: the prompt takes an overlay file's path
  std::string promptText;
  std::optional<std::string> goToRequest;
  std::optional<std::string> saveViewRequest;  // V then a name then Enter
  // Overlay files to open: O then a path then Enter, or files dropped on the window.
  std::vector<std::string> openFileRequests;
  bool rulerOn = false;             // M; double-clicks do not fly while it is on
  bool rulerUndoRequested = false;  // Backspace
  bool profileVisible = false;      // X: the elevation chart of the ruler's or picked line
  // A left click that did not drag (window pixels): the loop picks the placemark there, or with
  // the ruler on adds the ground point there to it.
  std::optional<glm::dvec2> clickRequest;
  std::string promptMessage;
  // The compass (top right, window pixels): a click there, or N, turns the view north up.
  glm::dvec2 compassTopLeft{-1.0}, compassBottomRight{-1.0};

  ImageryControls imagery;
  // The Sun's instant (--time, seconds since 1970 UTC), moved an hour a press by , and . (the
  // first press without --time starts from the clock's now); nullopt: the light that follows the
  // camera.
  std::optional<double> sunUnixSeconds;

  // One-shot requests, cleared by the loop when taken.
  bool recordToggleRequested = false;
  bool screenshotRequested = false;
  bool helpVisible = false;

  // Where the window was, and how large, before F11 made it fill the monitor (x, y, w, h).
  std::array<int, 4> windowedRect{0, 0, 1280, 720};

  // Mouse state.
  bool leftDown = false, rightDown = false, shiftDrag = false;
  double lastX = 0, lastY = 0;
  bool cursorKnown = false;
  double lastClickSeconds = -1, lastClickX = 0, lastClickY = 0;
  double pressX = 0, pressY = 0;  // where the left button went down
};

// Two left clicks this close in time and space are a double-click.
inline constexpr double kDoubleClickSeconds = 0.4;
inline constexpr double kDoubleClickPixels = 6;
inline constexpr double kPanPixelsPerKey = 60;  // an orbit arrow key pans like a drag this long
inline constexpr double kLookRadiansPerKey = 0.087;  // a fly arrow key turns 5 deg

// Sets the window's user pointer to `input` and installs the callbacks; `input` must outlive them.
void installViewCallbacks(GLFWwindow* window, ViewInput& input);

}  // namespace globe::app
