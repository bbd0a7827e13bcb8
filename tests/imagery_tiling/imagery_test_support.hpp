// Helpers shared by the imagery tiler tests: tile a layer in a temporary directory, open it, and
// decode every tile of a level.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "formats/image_io.hpp"
#include "geo/tile_id.hpp"
#include "imagery_tiling/imagery_tiler.hpp"
#include "streaming/imagery_store.hpp"

namespace globe::testing {

// Runs the tiler (2 threads unless given, no progress bar) on `inputs` into `out`.
Result<imagery_tiling::ImageryTilerReport> tileLayer(
    const std::vector<std::string>& inputs, const std::filesystem::path& out,
    imagery_tiling::ImageryTilerOptions options = {});
// The same into a fresh temporary directory; a failure is a test failure.
std::filesystem::path layerOf(const std::vector<std::string>& inputs, const std::string& name,
                              imagery_tiling::ImageryTilerOptions options = {});
std::unique_ptr<streaming::ImageryStore> openStore(const std::filesystem::path& dir);
// Every present tile of a level, decoded.
std::map<geo::TileId, formats::ImageRgba> tilesOf(streaming::ImageryStore& store, uint32_t level);

}  // namespace globe::testing
