// Imagery layers and the Zion terrain for viewer tests, made once per CTest run (sharedFixture) by
// the real `globe-tiler` (terrain and `imagery`) from the bundled data. Shared: read them only.
#pragma once

#include <filesystem>
#include <string>

namespace globe::testing {

// Runs `globe-tiler imagery -q -o DIR ARGS` once per distinct name; the layer directory.
const std::filesystem::path& imageryLayer(const std::string& name, const std::string& arguments);
// The bundled Blue Marble (5400×2700), whole globe.
const std::filesystem::path& blueMarbleLayer();
// The bundled Landsat 8 RGB over Zion (UTM 12N, 30 m).
const std::filesystem::path& zionLayer();
// The bundled water mask (`globe-tiler water-mask`): GSHHG low over the world and full resolution
// in five boxes (data/coast).
const std::filesystem::path& coastMask();
// ETOPO20 + the bundled Zion SRTM 3″, tiled once.
const std::filesystem::path& zionPyramid();
// A bundled data file (data/...) or a shared one (../shared/data/...) by relative path.
std::filesystem::path bundledData(const std::string& relativePath);

}  // namespace globe::testing
