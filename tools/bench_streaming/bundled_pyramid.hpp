// Where the benchmark's pyramid comes from: by default the bundled data/dem (ETOPO20, W002N52,
// Fuji) tiled into `scratch`; a pyramid given by URL is read through a default network.
#pragma once

#include <filesystem>
#include <memory>

#include "core/result.hpp"
#include "transport/network_settings.hpp"

namespace globe::bench {

Result<std::filesystem::path> tileBundledPyramid(const std::filesystem::path& scratch);

// Default network settings, its warnings ("no disk cache") on stderr as `globe` prints them.
std::shared_ptr<transport::Network> defaultNetwork();

}  // namespace globe::bench
