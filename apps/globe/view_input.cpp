// GLFW callbacks of `globe view`: keys by mode, drags, double-clicks, the scroll wheel.
#define GLFW_INCLUDE_NONE
#include "apps/globe/view_input.hpp"

#include "apps/globe/view_actions.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace globe::app {
namespace {

ViewInput& inputOf(GLFWwindow* window) {
  return *static_cast<ViewInput*>(glfwGetWindowUserPointer(window));
}

// Held movement keys: each key and the FlyKeys flag it holds.
constexpr std::pair<int, bool camera::FlyKeys::*> kFlyKeys[] = {
    {GLFW_KEY_W, &camera::FlyKeys::forward},   {GLFW_KEY_S, &camera::FlyKeys::back},
    {GLFW_KEY_A, &camera::FlyKeys::left},      {GLFW_KEY_D, &camera::FlyKeys::right},
    {GLFW_KEY_Q, &camera::FlyKeys::down},      {GLFW_KEY_E, &camera::FlyKeys::up},
    {GLFW_KEY_LEFT_SHIFT, &camera::FlyKeys::fast}, {GLFW_KEY_RIGHT_SHIFT, &camera::FlyKeys::fast},
};

// True when the key is one of them.
bool trackFlyKey(camera::FlyKeys& keys, int key, bool down) {
  for (const auto& [flyKey, flag] : kFlyKeys) {
    if (flyKey == key) {
      keys.*flag = down;
      return true;
    }
  }
  return false;
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

// The window's side of the actions (view_actions.hpp): closing it and full screen.
class GlfwViewWindow final : public ViewWindow {
 public:
  GlfwViewWindow(GLFWwindow* window, ViewInput& input) : window_(window), input_(input) {}
  void close() override { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
  void toggleFullScreen() override { toggleFullscreen(window_, input_); }

 private:
  GLFWwindow* window_;
  ViewInput& input_;
};

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
  const auto viewAction = actionForKey(key, input.navigator->mode(), action == GLFW_REPEAT);
  if (!viewAction) return;
  GlfwViewWindow viewWindow(window, input);
  const bool handled = runAction(*viewAction, input, viewWindow);
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
