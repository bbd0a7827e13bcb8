#define GLFW_INCLUDE_NONE
#include "apps/globe/view_actions.hpp"

#include <GLFW/glfw3.h>  // key codes only: nothing here calls GLFW

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace globe::app {
namespace {

using A = ViewAction;
using M = KeyMode;

// Press only unless `repeats`: holding a key must not toggle a state on and off.
constexpr KeyBinding kBindings[] = {
    {GLFW_KEY_ESCAPE, M::Any, A::Quit, false},
    {GLFW_KEY_F, M::Any, A::SwitchMode, false},
    {GLFW_KEY_TAB, M::Any, A::SwitchMode, false},
    {GLFW_KEY_R, M::Any, A::ResetView, false},
    {GLFW_KEY_P, M::Any, A::ToggleRecording, false},
    {GLFW_KEY_K, M::Any, A::Screenshot, false},
    {GLFW_KEY_F12, M::Any, A::Screenshot, false},
    {GLFW_KEY_F11, M::Any, A::ToggleFullScreen, false},
    {GLFW_KEY_H, M::Any, A::ToggleHelp, false},
    {GLFW_KEY_F1, M::Any, A::ToggleHelp, false},
    {GLFW_KEY_G, M::Any, A::GoTo, false},
    {GLFW_KEY_V, M::Any, A::SaveView, false},
    {GLFW_KEY_O, M::Any, A::OpenFile, false},  // Ctrl+O too: Google Earth's File > Open
    {GLFW_KEY_N, M::Any, A::NorthUp, false},
    {GLFW_KEY_M, M::Any, A::ToggleRuler, false},
    {GLFW_KEY_BACKSPACE, M::Any, A::RulerUndo, false},
    {GLFW_KEY_X, M::Any, A::ToggleProfile, false},
    {GLFW_KEY_L, M::Any, A::CycleLighting, false},
    {GLFW_KEY_1, M::Any, A::ToggleLayer1, false},
    {GLFW_KEY_2, M::Any, A::ToggleLayer2, false},
    {GLFW_KEY_3, M::Any, A::ToggleLayer3, false},
    {GLFW_KEY_4, M::Any, A::ToggleLayer4, false},
    {GLFW_KEY_LEFT_BRACKET, M::Any, A::LayerOpacityDown, true},
    {GLFW_KEY_RIGHT_BRACKET, M::Any, A::LayerOpacityUp, true},
    {GLFW_KEY_UP, M::Orbit, A::PanUp, true},
    {GLFW_KEY_DOWN, M::Orbit, A::PanDown, true},
    {GLFW_KEY_LEFT, M::Orbit, A::PanLeft, true},
    {GLFW_KEY_RIGHT, M::Orbit, A::PanRight, true},
    {GLFW_KEY_EQUAL, M::Orbit, A::ZoomIn, true},  // '+' is shift + '=' on most layouts
    {GLFW_KEY_KP_ADD, M::Orbit, A::ZoomIn, true},
    {GLFW_KEY_PAGE_UP, M::Orbit, A::ZoomIn, true},  // Google Earth's
    {GLFW_KEY_MINUS, M::Orbit, A::ZoomOut, true},
    {GLFW_KEY_KP_SUBTRACT, M::Orbit, A::ZoomOut, true},
    {GLFW_KEY_PAGE_DOWN, M::Orbit, A::ZoomOut, true},
    {GLFW_KEY_UP, M::Fly, A::LookUp, true},
    {GLFW_KEY_DOWN, M::Fly, A::LookDown, true},
    {GLFW_KEY_LEFT, M::Fly, A::LookLeft, true},
    {GLFW_KEY_RIGHT, M::Fly, A::LookRight, true},
    {GLFW_KEY_EQUAL, M::Fly, A::FlyFaster, true},
    {GLFW_KEY_KP_ADD, M::Fly, A::FlyFaster, true},
    {GLFW_KEY_PAGE_UP, M::Fly, A::FlyFaster, true},
    {GLFW_KEY_MINUS, M::Fly, A::FlySlower, true},
    {GLFW_KEY_KP_SUBTRACT, M::Fly, A::FlySlower, true},
    {GLFW_KEY_PAGE_DOWN, M::Fly, A::FlySlower, true},
    {GLFW_KEY_COMMA, M::Any, A::SunEarlier, true},
    {GLFW_KEY_PERIOD, M::Any, A::SunLater, true},
};

// G, V and O open the prompt: a place or saved view to go to, a name to save this view under,
// overlay files to open.
bool openPrompt(ViewInput& input, bool savesView, bool opensFile) {
  input.promptOpen = input.promptSwallowG = true;
  input.promptSavesView = savesView;
  input.promptOpensFile = opensFile;
  input.promptText.clear();
  input.promptMessage.clear();
  return true;
}

// A key for a layer that is not there says so in the HUD instead of doing nothing.
bool toggleLayer(ViewInput& input, uint32_t layer) {
  ImageryControls& imagery = input.imagery;
  if (layer >= imagery.layerCount) {
    input.promptMessage = "no layer " + std::to_string(layer + 1) + ": " +
                          std::to_string(imagery.layerCount) + " layer" +
                          (imagery.layerCount == 1 ? "" : "s") + " given (--layer)";
    return true;
  }
  imagery.shown[layer] = !imagery.shown[layer];
  imagery.selected = layer;
  return true;
}

bool stepOpacity(ViewInput& input, float step) {
  ImageryControls& imagery = input.imagery;
  if (imagery.layerCount == 0) {
    input.promptMessage = "no layer to fade: none given (--layer)";
    return true;
  }
  float& opacity = imagery.opacity[imagery.selected];
  // On the steps' grid, so ten presses go from 0 to 1 exactly.
  opacity = std::clamp(std::round((opacity + step) / kOpacityStep) * kOpacityStep, 0.0f, 1.0f);
  return true;
}

camera::Navigator& nav(ViewInput& input) { return *input.navigator; }

// , and . move the Sun an hour; without --time the first press starts from now.
bool stepSun(ViewInput& input, double seconds) {
  const double from = input.sunUnixSeconds
                          ? *input.sunUnixSeconds
                          : std::chrono::duration<double>(
                                std::chrono::system_clock::now().time_since_epoch())
                                .count();
  input.sunUnixSeconds = from + seconds;
  return true;
}
constexpr double kSunStepSeconds = 3600;

// Rows in the order the help lists them; an empty help is described by the row before it.
constexpr ActionInfo kActions[] = {
    {A::SwitchMode, "switch-mode", "F / Tab", "switch orbit <-> fly", "orbit <-> fly", 0,
     [](ViewInput& i, ViewWindow&) { return nav(i).toggleMode(), true; }},
    {A::ResetView, "reset-view", "R", "back to the start camera", "start camera", 0,
     [](ViewInput& i, ViewWindow&) { return nav(i).reset(), true; }},
    {A::NorthUp, "north-up", "N", "north up (or click the compass rose, top right)", "north up", 0,
     [](ViewInput& i, ViewWindow&) { return nav(i).northUp(), true; }},
    {A::ToggleHelp, "toggle-help", "H / F1", "show / hide this help", "help", 0,
     [](ViewInput& i, ViewWindow&) { return i.helpVisible = !i.helpVisible, true; }},
    {A::GoTo, "go-to", "G", "go to a place, a position or a saved view", "go to", 1,
     [](ViewInput& i, ViewWindow&) { return openPrompt(i, false, false); }},
    {A::SaveView, "save-view", "V", "save this view under a name", "save the view", 1,
     [](ViewInput& i, ViewWindow&) { return openPrompt(i, true, false); }},
    {A::OpenFile, "open-file", "O / Ctrl+O", "open KML, KMZ, GeoJSON or GPX (or drop files)",
     "open files", 1, [](ViewInput& i, ViewWindow&) { return openPrompt(i, false, true); }},
    {A::Quit, "quit", "Esc", "quit (a path being recorded is written first)", "quit", 1,
     [](ViewInput&, ViewWindow& w) { return w.close(), true; }},
    {A::ToggleRecording, "toggle-recording", "P",
     "start/stop recording the path (globe-path-*.json)", "record the path", 2,
     [](ViewInput& i, ViewWindow&) { return i.recordToggleRequested = true; }},
    {A::Screenshot, "screenshot", "K / F12", "screenshot (globe-shot-*.png)", "screenshot", 2,
     [](ViewInput& i, ViewWindow&) { return i.screenshotRequested = true; }},
    {A::ToggleFullScreen, "toggle-full-screen", "F11", "full screen and back", "full screen", 2,
     [](ViewInput&, ViewWindow& w) { return w.toggleFullScreen(), true; }},
    {A::ToggleRuler, "toggle-ruler", "M", "ruler: clicks add points, M again clears it", "ruler", 3,
     [](ViewInput& i, ViewWindow&) { return i.rulerOn = !i.rulerOn, true; }},
    {A::RulerUndo, "ruler-undo", "Backspace", "the ruler's last point off (or reopen its ring)",
     "undoes a point", 3,
     [](ViewInput& i, ViewWindow&) { return i.rulerUndoRequested = i.rulerOn; }},
    {A::ToggleProfile, "toggle-profile", "X", "elevation profile of the ruler / picked line",
     "elevation profile", 3,
     [](ViewInput& i, ViewWindow&) { return i.profileVisible = !i.profileVisible, true; }},
    {A::CycleLighting, "cycle-lighting", "L", "lighting on imagery: auto -> on -> off", "lighting",
     4,
     [](ViewInput& i, ViewWindow&) {
       return i.imagery.lighting = terrain::nextImageryLighting(i.imagery.lighting), true;
     }},
    {A::ToggleLayer1, "toggle-layer-1", "1 - 4", "show / hide layer 1-4 (and select it for [ ])",
     "layers", 4, [](ViewInput& i, ViewWindow&) { return toggleLayer(i, 0); }},
    {A::ToggleLayer2, "toggle-layer-2", "2", "", "", 4,
     [](ViewInput& i, ViewWindow&) { return toggleLayer(i, 1); }},
    {A::ToggleLayer3, "toggle-layer-3", "3", "", "", 4,
     [](ViewInput& i, ViewWindow&) { return toggleLayer(i, 2); }},
    {A::ToggleLayer4, "toggle-layer-4", "4", "", "", 4,
     [](ViewInput& i, ViewWindow&) { return toggleLayer(i, 3); }},
    {A::LayerOpacityDown, "layer-opacity-down", "[ / ]", "the selected layer's opacity -/+ 10%",
     "opacity -/+", 4,
     [](ViewInput& i, ViewWindow&) { return stepOpacity(i, -kOpacityStep); }},
    {A::LayerOpacityUp, "layer-opacity-up", "]", "", "", 4,
     [](ViewInput& i, ViewWindow&) { return stepOpacity(i, kOpacityStep); }},
    {A::PanUp, "pan-up", "arrows", "pan", "pan", 0,
     [](ViewInput& i, ViewWindow&) { return nav(i).panByKey(0, kPanPixelsPerKey), true; }},
    {A::PanDown, "pan-down", "Down", "", "", 0,
     [](ViewInput& i, ViewWindow&) { return nav(i).panByKey(0, -kPanPixelsPerKey), true; }},
    {A::PanLeft, "pan-left", "Left", "", "", 0,
     [](ViewInput& i, ViewWindow&) { return nav(i).panByKey(kPanPixelsPerKey, 0), true; }},
    {A::PanRight, "pan-right", "Right", "", "", 0,
     [](ViewInput& i, ViewWindow&) { return nav(i).panByKey(-kPanPixelsPerKey, 0), true; }},
    {A::ZoomIn, "zoom-in", "+/-, PgUp/PgDn", "zoom at the centre (height x0.8 per press)", "zoom",
     0, [](ViewInput& i, ViewWindow&) { return nav(i).zoom(1), true; }},
    {A::ZoomOut, "zoom-out", "-", "", "", 0,
     [](ViewInput& i, ViewWindow&) { return nav(i).zoom(-1), true; }},
    {A::LookUp, "look-up", "arrows", "look in 5 deg steps", "look", 0,
     [](ViewInput& i, ViewWindow&) { return nav(i).lookRadians(0, kLookRadiansPerKey), true; }},
    {A::LookDown, "look-down", "Down", "", "", 0,
     [](ViewInput& i, ViewWindow&) { return nav(i).lookRadians(0, -kLookRadiansPerKey), true; }},
    {A::LookLeft, "look-left", "Left", "", "", 0,
     [](ViewInput& i, ViewWindow&) { return nav(i).lookRadians(-kLookRadiansPerKey, 0), true; }},
    {A::LookRight, "look-right", "Right", "", "", 0,
     [](ViewInput& i, ViewWindow&) { return nav(i).lookRadians(kLookRadiansPerKey, 0), true; }},
    {A::FlyFaster, "fly-faster", "+/-, PgUp/PgDn", "speed factor x2 / /2 (x1/8 to x64)",
     "speed x2 / /2", 1, [](ViewInput& i, ViewWindow&) { return nav(i).changeSpeed(1), true; }},
    {A::FlySlower, "fly-slower", "-", "", "", 1,
     [](ViewInput& i, ViewWindow&) { return nav(i).changeSpeed(-1), true; }},
    {A::SunEarlier, "sun-earlier", ", / .", "the Sun an hour earlier / later (lit by the real Sun)",
     "sun -/+ 1 h", 4, [](ViewInput& i, ViewWindow&) { return stepSun(i, -kSunStepSeconds); }},
    {A::SunLater, "sun-later", ".", "", "", 4,
     [](ViewInput& i, ViewWindow&) { return stepSun(i, kSunStepSeconds); }},
};

constexpr InputHelp kContinuous[] = {
    {M::Any, "double-click", "fly to the point under the cursor", "flies there", 5},
    {M::Orbit, "left-drag", "grab the ground and turn the globe under it", "rotates", 1},
    {M::Orbit, "right/middle/Shift/Ctrl-drag", "tilt and turn about the centre", "tilts and turns",
     1},
    {M::Orbit, "scroll", "zoom toward the ground under the cursor", "zooms at the cursor", 0},
    {M::Fly, "W/S A/D E/Q", "forward/back, left/right, up/down; Shift x5", "move (Shift x5)", 0},
    {M::Fly, "drag (either button)", "look", "looks", 2},
    {M::Fly, "scroll", "speed factor; speed = max(2 m/s, clearance per second)", "speed", 2},
};

KeyMode keyModeOf(camera::NavigationMode mode) {
  return mode == camera::NavigationMode::Orbit ? M::Orbit : M::Fly;
}

constexpr int kHudLinesPerMode = 6;

// One HUD line: its items ("KEYS words") joined, after the mode's name on its first line.
void addHudLine(std::vector<std::string>& lines, std::string& line, const std::string& prefix) {
  if (line.empty()) return;
  lines.push_back(prefix + line);
  line.clear();
}

void addHudItem(std::string& line, std::string_view keys, std::string_view words) {
  if (words.empty()) return;
  line += (line.empty() ? "" : ",  ") + std::string(keys) + " " + std::string(words);
}

// The mode an action works in: the first binding's (every binding of an action shares it).
KeyMode modeOf(ViewAction action) {
  for (const KeyBinding& b : kBindings) {
    if (b.action == action) return b.mode;
  }
  return M::Any;
}

}  // namespace

std::span<const KeyBinding> keyBindings() { return kBindings; }
std::span<const ActionInfo> viewActions() { return kActions; }
std::span<const InputHelp> continuousInputHelp() { return kContinuous; }

const ActionInfo& actionInfo(ViewAction action) {
  const auto* found = std::find_if(std::begin(kActions), std::end(kActions),
                                   [&](const ActionInfo& a) { return a.action == action; });
  return *found;  // every action has a row (tests/apps/globe/test_view_actions.cpp)
}

std::optional<ViewAction> actionForKey(int key, camera::NavigationMode mode, bool repeat) {
  for (const KeyBinding& b : kBindings) {
    if (b.key != key || (repeat && !b.repeats)) continue;
    if (b.mode == M::Any || b.mode == keyModeOf(mode)) return b.action;
  }
  return std::nullopt;
}

bool runAction(ViewAction action, ViewInput& input, ViewWindow& window) {
  return actionInfo(action).run(input, window);
}

std::vector<std::string> helpLines() {
  std::vector<std::string> lines;
  for (const KeyMode mode : {M::Any, M::Orbit, M::Fly}) {
    std::string prefix = mode == M::Any ? "" : mode == M::Orbit ? "orbit: " : "fly:   ";
    for (int hudLine = 0; hudLine < kHudLinesPerMode; ++hudLine) {
      std::string line;
      for (const ActionInfo& a : kActions) {
        if (modeOf(a.action) == mode && a.hudLine == hudLine) addHudItem(line, a.keys, a.hud);
      }
      for (const InputHelp& h : kContinuous) {
        if (h.mode == mode && h.hudLine == hudLine) addHudItem(line, h.input, h.hud);
      }
      if (line.empty()) continue;
      addHudLine(lines, line, prefix);
      if (mode != M::Any) prefix = "       ";  // the mode's name on its first line only
    }
  }
  return lines;
}

std::string keysMarkdown() {
  std::string text;
  for (const KeyMode mode : {M::Any, M::Orbit, M::Fly}) {
    text += mode == M::Any     ? "| keys (any mode) | action |\n|---|---|\n"
            : mode == M::Orbit ? "\n| orbit mode | action |\n|---|---|\n"
                               : "\n| fly mode | action |\n|---|---|\n";
    for (const ActionInfo& a : kActions) {
      if (a.help.empty() || modeOf(a.action) != mode) continue;
      text += "| `" + std::string(a.keys) + "` | " + std::string(a.help) + " |\n";
    }
    for (const InputHelp& h : kContinuous) {
      if (h.mode == mode)
        text += "| " + std::string(h.input) + " | " + std::string(h.help) + " |\n";
    }
  }
  return text;
}

}  // namespace globe::app
