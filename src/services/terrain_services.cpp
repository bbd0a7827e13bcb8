#include "services/terrain_services.hpp"

#include <string_view>

#include "services/quantized_mesh_source.hpp"
#include "services/xyz_elevation_source.hpp"
#include "streaming/tile_store.hpp"

namespace globe::services {
namespace {

using Opened = Result<std::unique_ptr<streaming::TerrainSource>>;

template <class T>
Opened widen(Result<std::unique_ptr<T>> opened) {
  if (!opened) return Error{opened.error()};
  return std::unique_ptr<streaming::TerrainSource>(std::move(*opened));
}

// The terrain services a source spec names by its prefix ("terrarium:URL"), one row each: the
// prefix and what opens the rest of the spec. Anything else is a pyramid (a directory or URL).
struct TerrainService {
  std::string_view prefix;
  Opened (*open)(const std::string& url, terrain::SeaSurface sea,
                 std::shared_ptr<transport::Network> network);
};
constexpr TerrainService kTerrainServices[] = {
    {"quantized-mesh:",
     [](const std::string& url, terrain::SeaSurface sea,
        std::shared_ptr<transport::Network> network) {
       return widen(openQuantizedMeshSource(url, sea, std::move(network)));
     }},
    {"terrarium:",
     [](const std::string& url, terrain::SeaSurface sea,
        std::shared_ptr<transport::Network> network) {
       return widen(
           openXyzElevationSource(ElevationEncoding::Terrarium, url, sea, std::move(network)));
     }},
    {"terrain-rgb:",
     [](const std::string& url, terrain::SeaSurface sea,
        std::shared_ptr<transport::Network> network) {
       return widen(
           openXyzElevationSource(ElevationEncoding::TerrainRgb, url, sea, std::move(network)));
     }},
};

const TerrainService* serviceOf(const std::string& spec) {
  for (const TerrainService& service : kTerrainServices) {
    if (std::string_view(spec).starts_with(service.prefix)) return &service;
  }
  return nullptr;
}

}  // namespace

bool isTerrainService(const std::string& spec) { return serviceOf(spec) != nullptr; }

Result<std::unique_ptr<streaming::TerrainSource>> openTerrainSource(
    const std::string& spec, terrain::SeaSurface sea, std::shared_ptr<transport::Network> network) {
  if (const TerrainService* service = serviceOf(spec)) {
    return service->open(spec.substr(service->prefix.size()), sea, std::move(network));
  }
  return widen(streaming::TileStore::open(spec, sea, std::move(network)));
}

}  // namespace globe::services
