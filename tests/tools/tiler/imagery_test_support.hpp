// Helpers shared by the imagery tiler tests: tile a layer in a temporary directory, open it, and
// decode every tile of a level.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "geo/result.hpp"
#include "geo/tile_id.hpp"
#include "io/image_io.hpp"
#include "io/imagery_store.hpp"
#include "tools/tiler/imagery_tiler.hpp"

namespace globe::tiler::testing {

// Runs the tiler (2 threads unless given, no progress bar) on `inputs` into `out`.
Result<ImageryTilerReport> tileLayer(const std::vector<std::string>& inputs,
                                     const std::filesystem::path& out,
                                     ImageryTilerOptions options = {});
// The same into a fresh temporary directory; a failure is a test failure.
std::filesystem::path layerOf(const std::vector<std::string>& inputs, const std::string& name,
                              ImageryTilerOptions options = {});
std::unique_ptr<io::ImageryStore> openStore(const std::filesystem::path& dir);
// Every present tile of a level, decoded.
std::map<geo::TileId, io::ImageRgba> tilesOf(io::ImageryStore& store, uint32_t level);

}  // namespace globe::tiler::testing
