// `globe view`'s keys without a window: each key of the table runs its action on a real
// Navigator and ViewInput (the window's two operations counted), in the mode it belongs to, held
// keys repeating only where that makes sense; the HUD help and docs/view-controls.md's key table
// come from the same table.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>  // key codes
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "apps/globe/view_actions.hpp"
#include "geo/ellipsoid.hpp"
#include "tests/support/build_paths.hpp"

namespace globe::app {
namespace {

using camera::NavigationMode;

class CountingWindow final : public ViewWindow {
 public:
  void close() override { ++closes; }
  void toggleFullScreen() override { ++fullScreenToggles; }
  int closes = 0, fullScreenToggles = 0;
};

// A navigator over level ground at 0 m, 10 km above Zion looking 45 degrees down.
struct Keys {
  camera::Navigator navigator{geo::Ellipsoid::wgs84(),
                              camera::CameraPose::fromDegrees(-113.0, 37.3, 10000, 0, -45), 0.8,
                              [](double, double) { return std::optional<double>(0.0); }};
  ViewInput input;
  CountingWindow window;
  Keys() {
    navigator.setViewport(1280, 720);
    input.navigator = &navigator;
  }
  // A key pressed (or held): true when an action took it.
  bool press(int key, bool repeat = false) {
    const auto action = actionForKey(key, navigator.mode(), repeat);
    return action && runAction(*action, input, window);
  }
};

TEST(ViewActions, EveryActionHasOneRowAKeyAndANameAndEveryRowRuns) {
  std::set<std::string_view> names;
  std::set<ViewAction> described;
  for (const ActionInfo& a : viewActions()) {
    EXPECT_TRUE(names.insert(a.name).second) << a.name;
    EXPECT_TRUE(described.insert(a.action).second) << a.name;
    EXPECT_FALSE(a.keys.empty()) << a.name;
    EXPECT_NE(a.run, nullptr) << a.name;
    bool bound = false;
    for (const KeyBinding& b : keyBindings()) bound = bound || b.action == a.action;
    EXPECT_TRUE(bound) << a.name << " has no key";
  }
  for (const KeyBinding& b : keyBindings()) {
    EXPECT_TRUE(described.count(b.action)) << "key " << b.key << " has an action without a row";
  }
  // No key means two things in one mode.
  for (const KeyBinding& a : keyBindings()) {
    for (const KeyBinding& b : keyBindings()) {
      if (&a == &b || a.key != b.key) continue;
      EXPECT_TRUE(a.mode != KeyMode::Any && b.mode != KeyMode::Any && a.mode != b.mode)
          << "key " << a.key << " bound twice";
    }
  }
}

TEST(ViewActions, TogglesFlipAndComeBack) {
  Keys k;
  EXPECT_TRUE(k.press(GLFW_KEY_H));
  EXPECT_TRUE(k.input.helpVisible);
  EXPECT_TRUE(k.press(GLFW_KEY_F1));
  EXPECT_FALSE(k.input.helpVisible);
  EXPECT_TRUE(k.press(GLFW_KEY_M));
  EXPECT_TRUE(k.input.rulerOn);
  EXPECT_TRUE(k.press(GLFW_KEY_BACKSPACE));  // undo, with the ruler on
  EXPECT_TRUE(k.input.rulerUndoRequested);
  EXPECT_TRUE(k.press(GLFW_KEY_M));
  k.input.rulerUndoRequested = false;
  EXPECT_FALSE(k.press(GLFW_KEY_BACKSPACE));  // nothing to undo: the key is not taken
  EXPECT_FALSE(k.input.rulerUndoRequested);
  EXPECT_TRUE(k.press(GLFW_KEY_X));
  EXPECT_TRUE(k.input.profileVisible);
  EXPECT_TRUE(k.press(GLFW_KEY_P));
  EXPECT_TRUE(k.input.recordToggleRequested);
  EXPECT_TRUE(k.press(GLFW_KEY_F12));
  EXPECT_TRUE(k.input.screenshotRequested);
  EXPECT_TRUE(k.press(GLFW_KEY_F11));
  EXPECT_TRUE(k.press(GLFW_KEY_ESCAPE));
  EXPECT_EQ(k.window.fullScreenToggles, 1);
  EXPECT_EQ(k.window.closes, 1);
  EXPECT_FALSE(k.press(GLFW_KEY_H, /*repeat=*/true));  // held: toggles once, not on and off
  EXPECT_FALSE(k.input.helpVisible);
  EXPECT_FALSE(k.press(GLFW_KEY_Z));  // no action
}

TEST(ViewActions, PromptsOpenForGoToSaveAndOpen) {
  const struct {
    int key;
    bool savesView, opensFile;
  } prompts[] = {{GLFW_KEY_G, false, false}, {GLFW_KEY_V, true, false}, {GLFW_KEY_O, false, true}};
  for (const auto& p : prompts) {
    Keys k;
    k.input.promptText = "left over";
    k.input.promptMessage = "an old error";
    EXPECT_TRUE(k.press(p.key));
    EXPECT_TRUE(k.input.promptOpen);
    EXPECT_TRUE(k.input.promptSwallowG);  // the key's own character is not text
    EXPECT_EQ(k.input.promptSavesView, p.savesView);
    EXPECT_EQ(k.input.promptOpensFile, p.opensFile);
    EXPECT_TRUE(k.input.promptText.empty());
    EXPECT_TRUE(k.input.promptMessage.empty());
  }
}

TEST(ViewActions, LayerKeysActOnlyOnLayersThatExistAndSaySoOtherwise) {
  Keys k;
  // No layer: nothing changes but the HUD's message, which says why.
  EXPECT_TRUE(k.press(GLFW_KEY_1));
  EXPECT_EQ(k.input.promptMessage, "no layer 1: 0 layers given (--layer)");
  EXPECT_TRUE(k.press(GLFW_KEY_RIGHT_BRACKET));
  EXPECT_EQ(k.input.promptMessage, "no layer to fade: none given (--layer)");
  EXPECT_EQ(k.input.imagery.opacity[0], 1.0f);
  k.input.imagery.layerCount = 3;
  EXPECT_TRUE(k.press(GLFW_KEY_2));
  EXPECT_FALSE(k.input.imagery.shown[1]);
  EXPECT_EQ(k.input.imagery.selected, 1u);
  EXPECT_TRUE(k.press(GLFW_KEY_4));  // three layers
  EXPECT_EQ(k.input.promptMessage, "no layer 4: 3 layers given (--layer)");
  EXPECT_EQ(k.input.imagery.selected, 1u) << "the selection stays";
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(k.press(GLFW_KEY_LEFT_BRACKET, /*repeat=*/i > 0));
  EXPECT_FLOAT_EQ(k.input.imagery.opacity[1], 0.6f);
  for (int i = 0; i < 12; ++i) EXPECT_TRUE(k.press(GLFW_KEY_RIGHT_BRACKET, /*repeat=*/true));
  EXPECT_FLOAT_EQ(k.input.imagery.opacity[1], 1.0f);  // clamped, on the steps' grid
  EXPECT_EQ(k.input.imagery.opacity[0], 1.0f);
  const auto before = k.input.imagery.lighting;
  EXPECT_TRUE(k.press(GLFW_KEY_L));
  EXPECT_NE(k.input.imagery.lighting, before);
}

// , and . move the Sun an hour from --time's instant (held keys repeat); without --time the first
// press starts from the clock's now.
TEST(ViewActions, CommaAndPeriodMoveTheSunAnHour) {
  Keys k;
  k.input.sunUnixSeconds = 1718951400.0;  // 2024-06-21T06:30Z
  EXPECT_TRUE(k.press(GLFW_KEY_PERIOD));
  EXPECT_TRUE(k.press(GLFW_KEY_PERIOD, /*repeat=*/true));
  EXPECT_EQ(*k.input.sunUnixSeconds, 1718951400.0 + 2 * 3600);
  EXPECT_TRUE(k.press(GLFW_KEY_COMMA));
  EXPECT_EQ(*k.input.sunUnixSeconds, 1718951400.0 + 3600);
  Keys now;
  ASSERT_FALSE(now.input.sunUnixSeconds);
  const double before = std::chrono::duration<double>(
                            std::chrono::system_clock::now().time_since_epoch())
                            .count();
  EXPECT_TRUE(now.press(GLFW_KEY_COMMA));
  ASSERT_TRUE(now.input.sunUnixSeconds);
  EXPECT_NEAR(*now.input.sunUnixSeconds, before - 3600, 60.0);
}

TEST(ViewActions, ArrowsPanInOrbitAndLookInFly) {
  Keys k;
  ASSERT_EQ(k.navigator.mode(), NavigationMode::Orbit);
  EXPECT_EQ(actionForKey(GLFW_KEY_UP, NavigationMode::Orbit, false), ViewAction::PanUp);
  EXPECT_EQ(actionForKey(GLFW_KEY_UP, NavigationMode::Fly, true), ViewAction::LookUp);
  EXPECT_EQ(actionForKey(GLFW_KEY_PAGE_UP, NavigationMode::Orbit, true), ViewAction::ZoomIn);
  EXPECT_EQ(actionForKey(GLFW_KEY_KP_ADD, NavigationMode::Fly, false), ViewAction::FlyFaster);
  EXPECT_TRUE(k.press(GLFW_KEY_TAB));
  ASSERT_EQ(k.navigator.mode(), NavigationMode::Fly);
  const double pitch = k.navigator.pose().pitchRadians;
  EXPECT_TRUE(k.press(GLFW_KEY_UP));
  const auto looked = k.navigator.update(1.0 / 60);  // the look is proposed with the frame
  ASSERT_TRUE(looked);
  EXPECT_NEAR(looked->pose.pitchRadians - pitch, kLookRadiansPerKey, 1e-6);
  EXPECT_TRUE(k.press(GLFW_KEY_EQUAL, /*repeat=*/true));
  EXPECT_EQ(k.navigator.speed().factor(), 2.0);
  EXPECT_TRUE(k.press(GLFW_KEY_MINUS));
  EXPECT_TRUE(k.press(GLFW_KEY_KP_SUBTRACT));
  EXPECT_EQ(k.navigator.speed().factor(), 0.5);
  EXPECT_TRUE(k.press(GLFW_KEY_F));
  EXPECT_EQ(k.navigator.mode(), NavigationMode::Orbit);
}

// The HUD's help: short lines (it must fit beside the view at 1280x720), every action a user can
// press named with its keys, and the mouse.
TEST(ViewActions, HelpListsEveryActionAndTheMouseInAFewShortLines) {
  const std::vector<std::string> lines = helpLines();
  std::string help;
  for (const std::string& line : lines) {
    EXPECT_LE(line.size(), 72u) << line;
    help += line + "\n";
  }
  EXPECT_LE(lines.size(), 14u) << help;
  for (const ActionInfo& a : viewActions()) {
    if (a.hud.empty()) {
      EXPECT_TRUE(a.help.empty()) << a.name << ": in the document but not on the HUD";
      continue;
    }
    EXPECT_NE(help.find(std::string(a.keys) + " " + std::string(a.hud)), std::string::npos)
        << a.name << " not in\n"
        << help;
  }
  for (const char* input :
       {"W/S A/D E/Q", "double-click", "left-drag", "scroll", "orbit:", "fly:"}) {
    EXPECT_NE(help.find(input), std::string::npos) << input << " not in\n" << help;
  }
}

// docs/view-controls.md's key table is the table's own (GLOBE_UPDATE_DOCS=1 writes it there).
TEST(ViewActions, TheDocumentsKeyTableIsGeneratedFromTheTable) {
  const std::string path = std::string(GLOBE_SOURCE_DIR) + "/docs/view-controls.md";
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string doc = buffer.str();
  const std::string begin = "<!-- keys: generated from apps/globe/view_actions.cpp -->\n";
  const std::string end = "<!-- end of keys -->";
  const size_t from = doc.find(begin), to = doc.find(end);
  ASSERT_NE(from, std::string::npos) << path << " lacks " << begin;
  ASSERT_NE(to, std::string::npos) << path << " lacks " << end;
  const std::string current = doc.substr(from + begin.size(), to - from - begin.size());
  if (std::getenv("GLOBE_UPDATE_DOCS") != nullptr && current != keysMarkdown()) {
    doc.replace(from + begin.size(), current.size(), keysMarkdown());
    std::ofstream(path) << doc;
    GTEST_SKIP() << path << " rewritten";
  }
  EXPECT_EQ(current, keysMarkdown())
      << "run GLOBE_UPDATE_DOCS=1 " << ::testing::internal::GetArgvs()[0];
}

}  // namespace
}  // namespace globe::app
