// What the benchmark's camera wants each frame: the 3×3 tiles around it at the finest level
// its height calls for and at the three coarser levels, coarse and central first.
#pragma once

#include <vector>

#include "flight_path.hpp"
#include "formats/pyramid_manifest.hpp"
#include "streaming/load_request.hpp"

namespace globe::bench {

inline constexpr uint32_t kLevelsWanted = 4;

// A tile's width is about the camera's height above the ground.
uint32_t finestLevelForHeight(double heightMeters, uint32_t maxLevel);

// Only tiles inside their level's bounds in the manifest, as a viewer would ask.
std::vector<streaming::LoadRequest> wantedTiles(const CameraSample& camera,
                                                const formats::PyramidManifest& manifest);

}  // namespace globe::bench
