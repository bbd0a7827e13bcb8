// What the benchmark's camera wants each frame: the 3×3 tiles around it at the finest level
// its height calls for and at the three coarser levels, coarse and central first.
#pragma once

#include <vector>

#include "flight_path.hpp"
#include "io/load_request.hpp"
#include "io/pyramid_manifest.hpp"

namespace globe::bench {

inline constexpr uint32_t kLevelsWanted = 4;

// A tile's width is about the camera's height above the ground.
uint32_t finestLevelForHeight(double heightMeters, uint32_t maxLevel);

// Only tiles inside their level's bounds in the manifest, as a viewer would ask.
std::vector<io::LoadRequest> wantedTiles(const CameraSample& camera,
                                         const io::PyramidManifest& manifest);

}  // namespace globe::bench
