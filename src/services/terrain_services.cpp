#include "services/terrain_services.hpp"

#include "services/quantized_mesh_source.hpp"
#include "services/xyz_elevation_source.hpp"
#include "streaming/tile_store.hpp"

namespace globe::services {
namespace {

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

template <class T>
Result<std::unique_ptr<streaming::TerrainSource>> widen(Result<std::unique_ptr<T>> opened) {
  if (!opened) return Error{opened.error()};
  return std::unique_ptr<streaming::TerrainSource>(std::move(*opened));
}

}  // namespace

bool isTerrainService(const std::string& spec) {
  return startsWith(spec, "quantized-mesh:") || startsWith(spec, "terrarium:") ||
         startsWith(spec, "terrain-rgb:");
}

Result<std::unique_ptr<streaming::TerrainSource>> openTerrainSource(
    const std::string& spec, terrain::SeaSurface sea, std::shared_ptr<transport::Network> network) {
  if (startsWith(spec, "quantized-mesh:")) {
    return widen(openQuantizedMeshSource(spec.substr(15), sea, std::move(network)));
  }
  if (startsWith(spec, "terrarium:")) {
    return widen(openXyzElevationSource(ElevationEncoding::Terrarium, spec.substr(10), sea,
                                        std::move(network)));
  }
  if (startsWith(spec, "terrain-rgb:")) {
    return widen(openXyzElevationSource(ElevationEncoding::TerrainRgb, spec.substr(12), sea,
                                        std::move(network)));
  }
  return widen(streaming::TileStore::open(spec, sea, std::move(network)));
}

}  // namespace globe::services
