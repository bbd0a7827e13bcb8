// The 3D Tiles options every scene command shares: --tileset (repeatable), --tileset-at (a
// tileset made in a local frame placed east-north-up somewhere, scaled), --tileset-clamp and
// --tileset-error, read into the scene's options.
#pragma once

#include <CLI/CLI.hpp>

#include "apps/globe/common_options.hpp"
#include "scene/terrain_scene.hpp"

namespace globe::app {

void addTilesetOptions(CLI::App& command, CommonArguments& arguments);
// Reads every tileset; false (the reason printed, naming the tileset) when one cannot be read.
bool applyTilesetArguments(const char* command, const CommonArguments& arguments,
                           scene::SceneOptions& scene);

}  // namespace globe::app
