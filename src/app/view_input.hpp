// `globe view`'s input: GLFW key, mouse and scroll callbacks that drive the orbit controls
// directly and leave fly-mode motion, mode switches and one-shot actions for the loop to take.
#pragma once

#include <optional>
#include <string>

#include <glm/vec2.hpp>

#include "app/hud_text.hpp"
#include "camera/fly_controls.hpp"
#include "camera/orbit_controls.hpp"

struct GLFWwindow;

namespace globe::app {

struct ViewInput {
  camera::OrbitControls* orbit = nullptr;
  ViewMode mode = ViewMode::Orbit;
  bool changed = true;     // something to update or redraw
  bool userMoved = false;  // the user moved the camera (cancels a fly-to)

  camera::FlyKeys flyKeys;                    // held now (tracked in both modes, used in fly mode)
  double lookDxPixels = 0, lookDyPixels = 0;  // fly: mouse look to apply
  double lookHeadingRadians = 0, lookPitchRadians = 0;  // fly: arrow keys to apply
  camera::SpeedSteps speed;                             // fly: scroll wheel, +/-

  // Orbit moves about the ground under a pixel, done by the loop (it has the scene to pick the
  // ground from): scroll zooms toward the ground under the cursor, tilting turns about the ground
  // at the centre.
  double zoomNotches = 0;
  glm::dvec2 zoomPixels{0.0};  // window pixels, y down
  double tiltDxPixels = 0, tiltDyPixels = 0;
  // Left-drag: the press grabs the ground under the cursor, each move brings it under the cursor.
  std::optional<glm::dvec2> grabPixels;     // a press to grab at
  double panDxPixels = 0, panDyPixels = 0;  // moves since the loop last took them
  glm::dvec2 panPixels{0.0};                // the cursor after them

  // "Go to" (G): the text typed so far while the prompt is open (it takes every key), the text
  // entered (Enter) for the loop to parse, and what the loop says back (an error).
  bool promptOpen = false;
  bool promptSwallowG = false;  // the G key's own character is not text
  std::string promptText;
  std::optional<std::string> goToRequest;
  std::string promptMessage;
  // The compass (top right, window pixels): a click there, or N, turns the view north up.
  glm::dvec2 compassTopLeft{-1.0}, compassBottomRight{-1.0};
  bool northUpRequested = false;

  // One-shot requests, cleared by the loop when taken.
  bool resetRequested = false;
  bool recordToggleRequested = false;
  bool screenshotRequested = false;
  std::optional<glm::dvec2> doubleClickPixels;  // window pixels, y down
  bool helpVisible = false;

  // Mouse state.
  bool leftDown = false, rightDown = false, shiftDrag = false;
  double lastX = 0, lastY = 0;
  bool cursorKnown = false;
  double lastClickSeconds = -1, lastClickX = 0, lastClickY = 0;
};

// Two left clicks this close in time and space are a double-click.
inline constexpr double kDoubleClickSeconds = 0.4;
inline constexpr double kDoubleClickPixels = 6;
inline constexpr double kPanPixelsPerKey = 60;  // an orbit arrow key pans like a drag this long
inline constexpr double kLookRadiansPerKey = 0.087;  // a fly arrow key turns 5 deg

// Sets the window's user pointer to `input` and installs the callbacks; `input` must outlive them.
void installViewCallbacks(GLFWwindow* window, ViewInput& input);

}  // namespace globe::app
