// `globe query`: a height service. Reads "lon,lat" lines (degrees), prints "lon,lat,level,height_m"
// from the finest tile the pyramid has there (or a given level), by QOTCD or the exact surface;
// with tilesets, the higher of that and their drawn surface (tiles3d/tileset_surface.hpp).
#pragma once

#include <cstdio>
#include <filesystem>
#include <istream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "collision/height_service.hpp"
#include "core/result.hpp"
#include "geo/ellipsoid.hpp"
#include "terrain/height_block.hpp"
#include "transport/network_settings.hpp"

namespace globe::app {

struct QueryOptions {
  std::filesystem::path pyramid;
  collision::HeightMode mode = collision::HeightMode::Qotcd;
  std::optional<uint32_t> level;
  geo::GlobeModel globeModel = geo::GlobeModel::Wgs84;
  terrain::SeaSurface sea = terrain::SeaSurface::Water;  // --sea-floor: SeaFloor
  std::shared_ptr<transport::Network> network;           // for an http(s) URL
  std::vector<std::string> tilesets;  // 3D Tiles (paths or URLs): the higher surface wins
};

struct QueryReport {
  uint64_t answered = 0;
  uint64_t rejected = 0;  // bad lines, each reported on errors with its line number
};

// Answers on `out`, one line per good input line; bad lines are reported on `errors`.
Result<QueryReport> runQuery(const QueryOptions& options, std::istream& in, std::FILE* out,
                             std::FILE* errors);

}  // namespace globe::app
