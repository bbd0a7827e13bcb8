// GLFW callbacks of `globe view`: keys by mode, drags, double-clicks, the scroll wheel.
#define GLFW_INCLUDE_NONE
#include "apps/globe/view_input.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>

namespace globe::app {
namespace {

ViewInput& inputOf(GLFWwindow* window) {
  return *static_cast<ViewInput*>(glfwGetWindowUserPointer(window));
}

// Held movement keys; true when the key is one of them.
bool trackFlyKey(camera::FlyKeys& keys, int key, bool down) {
  switch (key) {
    case GLFW_KEY_W:
      keys.forward = down;
      return true;
    case GLFW_KEY_S:
      keys.back = down;
      return true;
    case GLFW_KEY_A:
      keys.left = down;
      return true;
    case GLFW_KEY_D:
      keys.right = down;
      return true;
    case GLFW_KEY_Q:
      keys.down = down;
      return true;
    case GLFW_KEY_E:
      keys.up = down;
      return true;
    case GLFW_KEY_LEFT_SHIFT:
    case GLFW_KEY_RIGHT_SHIFT:
      keys.fast = down;
      return true;
    default:
      return false;
  }
}

// F11: the window over the whole primary monitor and back to where and how large it was.
void toggleFullscreen(GLFWwindow* window, ViewInput& input) {
  if (glfwGetWindowMonitor(window) != nullptr) {
    const auto& r = input.windowedRect;
    glfwSetWindowMonitor(window, nullptr, r[0], r[1], r[2], r[3], GLFW_DONT_CARE);
    return;
  }
  GLFWmonitor* monitor = glfwGetPrimaryMonitor();
  const GLFWvidmode* mode = monitor != nullptr ? glfwGetVideoMode(monitor) : nullptr;
  if (mode == nullptr) return;  // no monitor to fill (a headless display without RandR)
  auto& r = input.windowedRect;
  glfwGetWindowPos(window, &r[0], &r[1]);
  glfwGetWindowSize(window, &r[2], &r[3]);
  glfwSetWindowMonitor(window, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
}

// Keys that do the same in both modes; false when the key is not one of them.
bool commonKey(GLFWwindow* window, ViewInput& input, int key) {
  switch (key) {
    case GLFW_KEY_ESCAPE:
      glfwSetWindowShouldClose(window, GLFW_TRUE);
      return true;
    case GLFW_KEY_F:
    case GLFW_KEY_TAB:
      input.navigator->toggleMode();
      return true;
    case GLFW_KEY_R:
      input.navigator->reset();
      return true;
    case GLFW_KEY_P:
      input.recordToggleRequested = true;
      return true;
    case GLFW_KEY_K:
    case GLFW_KEY_F12:
      input.screenshotRequested = true;
      return true;
    case GLFW_KEY_H:
    case GLFW_KEY_F1:
      input.helpVisible = !input.helpVisible;
      return true;
    case GLFW_KEY_G:
    case GLFW_KEY_V:
    case GLFW_KEY_O:  // Ctrl+O too: Google Earth's File > Open
      input.promptOpen = input.promptSwallowG = true;
      input.promptSavesView = key == GLFW_KEY_V;
      input.promptOpensFile = key == GLFW_KEY_O;
      input.promptText.clear();
      input.promptMessage.clear();
      return true;
    case GLFW_KEY_N:
      input.navigator->northUp();
      return true;
    case GLFW_KEY_M:
      input.rulerOn = !input.rulerOn;
      return true;
    case GLFW_KEY_BACKSPACE:
      input.rulerUndoRequested = input.rulerOn;
      return input.rulerOn;
    case GLFW_KEY_X:
      input.profileVisible = !input.profileVisible;
      return true;
    case GLFW_KEY_F11:
      toggleFullscreen(window, input);
      return true;
    default:
      return false;
  }
}

// L, 1-4, [ and ] (ImageryControls); false when the key is not one of them or does nothing here
// (a layer key without that layer). Only [ and ] repeat.
bool imageryKey(ImageryControls& imagery, int key, bool press) {
  if (key == GLFW_KEY_L && press) {
    imagery.lighting = terrain::nextImageryLighting(imagery.lighting);
    return true;
  }
  if (key >= GLFW_KEY_1 && key <= GLFW_KEY_4 && press) {
    const auto layer = static_cast<uint32_t>(key - GLFW_KEY_1);
    if (layer >= imagery.layerCount) return false;
    imagery.shown[layer] = !imagery.shown[layer];
    imagery.selected = layer;
    return true;
  }
  if ((key == GLFW_KEY_LEFT_BRACKET || key == GLFW_KEY_RIGHT_BRACKET) && imagery.layerCount > 0) {
    float& opacity = imagery.opacity[imagery.selected];
    const float step = key == GLFW_KEY_RIGHT_BRACKET ? kOpacityStep : -kOpacityStep;
    // On the steps' grid, so ten presses go from 0 to 1 exactly.
    opacity = std::clamp(std::round((opacity + step) / kOpacityStep) * kOpacityStep, 0.0f, 1.0f);
    return true;
  }
  return false;
}

bool orbitKey(ViewInput& input, int key) {
  camera::Navigator& navigator = *input.navigator;
  switch (key) {
    case GLFW_KEY_UP:
      navigator.panByKey(0, kPanPixelsPerKey);
      return true;
    case GLFW_KEY_DOWN:
      navigator.panByKey(0, -kPanPixelsPerKey);
      return true;
    case GLFW_KEY_LEFT:
      navigator.panByKey(kPanPixelsPerKey, 0);
      return true;
    case GLFW_KEY_RIGHT:
      navigator.panByKey(-kPanPixelsPerKey, 0);
      return true;
    case GLFW_KEY_EQUAL:  // '+' is shift + '=' on most layouts
    case GLFW_KEY_KP_ADD:
    case GLFW_KEY_PAGE_UP:  // Google Earth's
      navigator.zoom(1);
      return true;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT:
    case GLFW_KEY_PAGE_DOWN:
      navigator.zoom(-1);
      return true;
    default:
      return false;
  }
}

bool flyKey(ViewInput& input, int key) {
  camera::Navigator& navigator = *input.navigator;
  switch (key) {
    case GLFW_KEY_UP:
      navigator.lookRadians(0, kLookRadiansPerKey);
      return true;
    case GLFW_KEY_DOWN:
      navigator.lookRadians(0, -kLookRadiansPerKey);
      return true;
    case GLFW_KEY_LEFT:
      navigator.lookRadians(-kLookRadiansPerKey, 0);
      return true;
    case GLFW_KEY_RIGHT:
      navigator.lookRadians(kLookRadiansPerKey, 0);
      return true;
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD:
    case GLFW_KEY_PAGE_UP:
      navigator.changeSpeed(1);
      return true;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT:
    case GLFW_KEY_PAGE_DOWN:
      navigator.changeSpeed(-1);
      return true;
    default:
      return false;
  }
}

// While the go-to prompt is open it takes every key: Enter submits, Escape closes it, Backspace
// deletes; the text itself comes from the character callback.
void promptKey(ViewInput& input, int key) {
  if (key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER) {
    if (input.promptOpensFile) {
      input.openFileRequests.push_back(input.promptText);
    } else {
      (input.promptSavesView ? input.saveViewRequest : input.goToRequest) = input.promptText;
    }
    input.promptOpen = false;
  } else if (key == GLFW_KEY_ESCAPE) {
    input.promptOpen = false;
    input.promptMessage.clear();
  } else if (key == GLFW_KEY_BACKSPACE && !input.promptText.empty()) {
    // The whole last character: its UTF-8 continuation bytes, then its lead byte.
    while (input.promptText.size() > 1 && (input.promptText.back() & 0xc0) == 0x80) {
      input.promptText.pop_back();
    }
    input.promptText.pop_back();
  }
  input.changed = true;
}

void onChar(GLFWwindow* window, unsigned int codepoint) {
  ViewInput& input = inputOf(window);
  if (!input.promptOpen) return;
  // The G that opened the prompt arrives as a character too: it is not part of the text.
  if (input.promptSwallowG) {
    input.promptSwallowG = false;
    if (codepoint == 'g' || codepoint == 'G' || codepoint == 'v' || codepoint == 'V' ||
        codepoint == 'o' || codepoint == 'O') {
      return;
    }
  }
  // A file's path may be long and hold any character; names and positions are short.
  const size_t limit = input.promptOpensFile ? 4096 : 80;
  if (codepoint < 0x20 || codepoint == 0x7f || codepoint > 0x10ffff ||
      input.promptText.size() + 4 > limit) {
    return;
  }
  if (codepoint < 0x80) {
    input.promptText.push_back(static_cast<char>(codepoint));
  } else if (codepoint < 0x800) {
    input.promptText.push_back(static_cast<char>(0xc0 | (codepoint >> 6)));
    input.promptText.push_back(static_cast<char>(0x80 | (codepoint & 0x3f)));
  } else if (codepoint < 0x10000) {
    input.promptText.push_back(static_cast<char>(0xe0 | (codepoint >> 12)));
    input.promptText.push_back(static_cast<char>(0x80 | ((codepoint >> 6) & 0x3f)));
    input.promptText.push_back(static_cast<char>(0x80 | (codepoint & 0x3f)));
  } else {
    input.promptText.push_back(static_cast<char>(0xf0 | (codepoint >> 18)));
    input.promptText.push_back(static_cast<char>(0x80 | ((codepoint >> 12) & 0x3f)));
    input.promptText.push_back(static_cast<char>(0x80 | ((codepoint >> 6) & 0x3f)));
    input.promptText.push_back(static_cast<char>(0x80 | (codepoint & 0x3f)));
  }
  input.changed = true;
}

void onKey(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
  ViewInput& input = inputOf(window);
  if (input.promptOpen) {
    if (action != GLFW_RELEASE) promptKey(input, key);
    return;
  }
  if (trackFlyKey(input.flyKeys, key, action != GLFW_RELEASE)) {
    input.navigator->setFlyKeys(input.flyKeys);
    input.changed = true;
    return;
  }
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  const bool handled =
      (action == GLFW_PRESS && commonKey(window, input, key)) ||
      imageryKey(input.imagery, key, action == GLFW_PRESS) ||
      (input.navigator->mode() == camera::NavigationMode::Orbit ? orbitKey(input, key)
                                                                : flyKey(input, key));
  // With Ctrl held no character follows the key: nothing to swallow.
  if (handled && input.promptOpen && (mods & GLFW_MOD_CONTROL) != 0) input.promptSwallowG = false;
  if (handled) input.changed = true;
}

void onScroll(GLFWwindow* window, double /*dx*/, double dy) {
  ViewInput& input = inputOf(window);
  if (input.navigator->mode() == camera::NavigationMode::Orbit) {
    if (!input.cursorKnown) glfwGetCursorPos(window, &input.lastX, &input.lastY);
    input.cursorKnown = true;
    input.navigator->zoomAt(dy, glm::dvec2(input.lastX, input.lastY));
  } else {
    input.navigator->changeSpeed(dy);
  }
  input.changed = true;
}

void onMouseButton(GLFWwindow* window, int button, int action, int mods) {
  ViewInput& input = inputOf(window);
  const bool down = action == GLFW_PRESS;
  // The position from the last motion event, not the pointer's now: events may lag the pointer.
  if (down && !input.cursorKnown) glfwGetCursorPos(window, &input.lastX, &input.lastY);
  input.cursorKnown = true;
  if (button == GLFW_MOUSE_BUTTON_LEFT) {
    if (down && input.lastX >= input.compassTopLeft.x && input.lastY >= input.compassTopLeft.y &&
        input.lastX <= input.compassBottomRight.x && input.lastY <= input.compassBottomRight.y) {
      input.navigator->northUp();  // a click on the compass
      input.changed = true;
      return;
    }
    input.leftDown = down;
    // Shift or Ctrl + drag tilts and turns (Ctrl as CesiumJS and Google Earth have it).
    input.shiftDrag = down && (mods & (GLFW_MOD_SHIFT | GLFW_MOD_CONTROL)) != 0;
    if (down && !input.shiftDrag) input.navigator->grab(glm::dvec2(input.lastX, input.lastY));
    if (down && input.shiftDrag) input.navigator->beginTilt();
    if (!down) {
      input.navigator->release();
      input.navigator->endTilt();
    }
    if (down) {
      input.pressX = input.lastX;
      input.pressY = input.lastY;
    } else if (std::abs(input.lastX - input.pressX) <= kDoubleClickPixels &&
               std::abs(input.lastY - input.pressY) <= kDoubleClickPixels) {
      input.clickRequest = glm::dvec2(input.lastX, input.lastY);  // a click, not a drag
      input.changed = true;
    }
    if (down && !input.rulerOn) {  // the ruler's clicks may come fast
      const double now = glfwGetTime();
      if (now - input.lastClickSeconds <= kDoubleClickSeconds &&
          std::abs(input.lastX - input.lastClickX) <= kDoubleClickPixels &&
          std::abs(input.lastY - input.lastClickY) <= kDoubleClickPixels) {
        input.navigator->flyToPixel(glm::dvec2(input.lastX, input.lastY));
        input.lastClickSeconds = -1;  // a third click starts a new pair
        input.changed = true;
      } else {
        input.lastClickSeconds = now;
        input.lastClickX = input.lastX;
        input.lastClickY = input.lastY;
      }
    }
  } else if (button == GLFW_MOUSE_BUTTON_RIGHT || button == GLFW_MOUSE_BUTTON_MIDDLE) {
    input.rightDown = down;  // the middle button tilts and turns too (CesiumJS, Google Earth)
    if (down) {
      input.navigator->beginTilt();  // one pivot for the whole drag
    } else {
      input.navigator->endTilt();
    }
  }
}

void onCursor(GLFWwindow* window, double x, double y) {
  ViewInput& input = inputOf(window);
  const double dx = x - input.lastX, dy = y - input.lastY;
  input.lastX = x;
  input.lastY = y;
  input.cursorKnown = true;
  if (!input.leftDown && !input.rightDown) {
    input.changed = true;  // the HUD shows the ground under the pointer
    return;
  }
  camera::Navigator& navigator = *input.navigator;
  if (navigator.mode() == camera::NavigationMode::Fly) {
    navigator.look(dx, dy);
  } else if (input.rightDown || input.shiftDrag) {
    navigator.tilt(dx, dy);
  } else {
    navigator.dragTo(glm::dvec2(x, y), dx, dy);
  }
  input.changed = true;
}

void onRepaintNeeded(GLFWwindow* window) { inputOf(window).changed = true; }

// Files dropped on the window are opened as overlays.
void onDrop(GLFWwindow* window, int count, const char** paths) {
  ViewInput& input = inputOf(window);
  for (int i = 0; i < count; ++i) input.openFileRequests.emplace_back(paths[i]);
  input.changed = true;
}
void onFramebufferSize(GLFWwindow* window, int, int) { inputOf(window).changed = true; }

}  // namespace

void installViewCallbacks(GLFWwindow* window, ViewInput& input) {
  glfwSetWindowUserPointer(window, &input);
  glfwSetKeyCallback(window, onKey);
  glfwSetCharCallback(window, onChar);
  glfwSetScrollCallback(window, onScroll);
  glfwSetMouseButtonCallback(window, onMouseButton);
  glfwSetCursorPosCallback(window, onCursor);
  glfwSetWindowRefreshCallback(window, onRepaintNeeded);
  glfwSetDropCallback(window, onDrop);
  glfwSetFramebufferSizeCallback(window, onFramebufferSize);
}

}  // namespace globe::app
