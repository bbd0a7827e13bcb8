// `globe view`'s keys as one table: each binding (a key, the mode it works in, whether it
// repeats when held) names an action; each action has its keys and help as the HUD and
// docs/view-controls.md show them, and one handler. The window's callbacks (view_input.cpp) look
// a key up here and run its handler on the ViewInput; nothing here needs a window, so the keys
// are tested without one (tests/apps/globe/test_view_actions.cpp).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "apps/globe/view_input.hpp"

namespace globe::app {

enum class ViewAction {
  Quit,
  SwitchMode,
  ResetView,
  ToggleRecording,
  Screenshot,
  ToggleFullScreen,
  ToggleHelp,
  GoTo,
  SaveView,
  OpenFile,
  NorthUp,
  ToggleRuler,
  RulerUndo,
  ToggleProfile,
  CycleLighting,
  ToggleLayer1,
  ToggleLayer2,
  ToggleLayer3,
  ToggleLayer4,
  LayerOpacityDown,
  LayerOpacityUp,
  PanUp,
  PanDown,
  PanLeft,
  PanRight,
  ZoomIn,
  ZoomOut,
  LookUp,
  LookDown,
  LookLeft,
  LookRight,
  FlyFaster,
  FlySlower,
  SunEarlier,
  SunLater,
};

enum class KeyMode { Any, Orbit, Fly };

struct KeyBinding {
  int key;  // a GLFW key code
  KeyMode mode;
  ViewAction action;
  bool repeats;  // also when the key is held down (GLFW_REPEAT)
};

// What an action may do beyond the ViewInput: the window's own operations.
class ViewWindow {
 public:
  virtual ~ViewWindow() = default;
  virtual void close() = 0;
  virtual void toggleFullScreen() = 0;
};

struct ActionInfo {
  ViewAction action;
  std::string_view name;  // for tests and messages: "toggle-ruler"
  std::string_view keys;  // as the help writes them: "M"
  std::string_view help;  // one line; empty for an action another row describes
  // The HUD's help (H) is short: a few words after the keys, the items of one hudLine on one
  // line. Empty: not on the HUD (another row's words cover it).
  std::string_view hud;
  int hudLine;
  // false when the action does nothing now (a layer key without that layer): the key is not
  // taken, and the frame is not redrawn.
  bool (*run)(ViewInput& input, ViewWindow& window);
};

std::span<const KeyBinding> keyBindings();
std::span<const ActionInfo> viewActions();
const ActionInfo& actionInfo(ViewAction action);

// The action of a key pressed (repeat false) or held (repeat true) in `mode`, if any.
std::optional<ViewAction> actionForKey(int key, camera::NavigationMode mode, bool repeat);
// Runs the action's handler; false when it did nothing.
bool runAction(ViewAction action, ViewInput& input, ViewWindow& window);

// The mouse and the held fly keys, described for the help: their handlers are the window's drag,
// click and key-tracking callbacks, which move the camera continuously rather than act once.
struct InputHelp {
  KeyMode mode;
  std::string_view input;
  std::string_view help;
  std::string_view hud;
  int hudLine;
};
std::span<const InputHelp> continuousInputHelp();

// The HUD's help overlay (H), and the Markdown table of every key for docs/view-controls.md
// (`globe view --keys`), both from the tables above.
std::vector<std::string> helpLines();
std::string keysMarkdown();

}  // namespace globe::app
