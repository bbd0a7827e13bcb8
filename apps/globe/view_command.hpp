// `globe view`: the interactive window (GLFW): orbit and fly modes through the camera controller,
// a HUD, path recording and screenshots. It redraws only when the camera moved, a tile arrived, the
// HUD's text or the window changed, so idling is free.
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

#include "camera/camera_pose.hpp"
#include "scene/terrain_scene.hpp"

namespace globe::app {

// While tiles load, the loop waits at most this long for one to finish (it wakes as soon as one
// does: each update starts only a few loads, so waking late would pace the streaming).
inline constexpr std::chrono::milliseconds kLoadWait{10};
// While tiles stream in with the camera still, redraw at most this often: a software-rendered
// frame can take tens of ms, and every frame drawn delays the next poll and request of tiles.
inline constexpr std::chrono::milliseconds kLoadingRedrawInterval{100};

struct ViewOptions {
  std::filesystem::path pyramid;
  camera::CameraPose pose;
  bool heightAboveTerrain = false;  // the pose's height is above the terrain (a saved KML view)
  int widthPixels = 1280, heightPixels = 720;
  std::optional<std::filesystem::path> imagery;  // equirectangular world image to drape
  scene::SceneOptions scene;
  int frames = 0;  // > 0: redraw continuously and quit after this many frames (tests, timing)
  // The last frame as a PNG, written on exit: the terrain alone, without the HUD (K/F12 keep it).
  std::optional<std::filesystem::path> screenshot;
  bool log = false;  // print when the view becomes complete, and the final camera on exit
  // Where P (recorded paths, globe-path-*.json) and K/F12 (screenshots, globe-shot-*.png) write;
  // empty: the current directory.
  std::filesystem::path recordDirectory;
  // A place or position to fly to as the window opens (as typed in its go-to box, G).
  std::optional<std::string> goTo;
};

struct ViewReport {
  int framesDrawn = 0;
  camera::CameraPose finalPose;
};

// Opens the window and runs until it is closed (Esc, the close button) or `frames` are drawn.
// The keys and mouse actions are listed in docs/view-controls.md and the help overlay (H).
// Fails without a display (GLFW cannot initialise) or when the pyramid cannot be opened.
Result<ViewReport> runView(const ViewOptions& options);

}  // namespace globe::app
