// Drapes an equirectangular world image (JPEG/PNG, -180..180 by 90..-90) over the terrain.
#pragma once

#include <filesystem>

#include "core/result.hpp"
#include "render/terrain_renderer.hpp"

namespace globe::app {

Result<void> drapeImagery(render::TerrainRenderer& renderer, const std::filesystem::path& image);

}  // namespace globe::app
