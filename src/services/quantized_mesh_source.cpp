#include "services/quantized_mesh_source.hpp"

#include <mutex>

#include <nlohmann/json.hpp>

#include "compression/gzip_bytes.hpp"
#include "formats/quantized_mesh.hpp"
#include "formats/terrain_layer_json.hpp"
#include "geo/cartographic.hpp"
#include "geo/tiling_scheme.hpp"
#include "services/tin_sampling.hpp"
#include "services/url_reader.hpp"
#include "services/url_template.hpp"

namespace globe::services {
namespace {

constexpr size_t kMaxLayerJsonBytes = size_t{64} << 20;
constexpr size_t kMaxTileBytes = size_t{16} << 20;
constexpr size_t kMaxInflatedTileBytes = size_t{64} << 20;
// Cesium ion's and other services' way to choose a tile's extensions: asked for all it knows.
constexpr const char* kQuantizedMeshAccept =
    "application/vnd.quantized-mesh;extensions=octvertexnormals-watermask-metadata,"
    "application/octet-stream;q=0.9,*/*;q=0.01";

bool covers(const std::vector<formats::TileRange>& ranges, uint32_t x, uint32_t tmsY) {
  for (const formats::TileRange& r : ranges)
    if (x >= r.startX && x <= r.endX && tmsY >= r.startY && tmsY <= r.endY) return true;
  return false;
}

// The tile's TIN as the producer made it, its triangle index built here on the loader's thread.
Result<std::shared_ptr<const terrain::TinTile>> tinOf(const formats::QuantizedMesh& mesh,
                                                      const geo::TileId& tile,
                                                      const std::string& url) {
  std::vector<terrain::TinVertex> vertices(mesh.vertexCount());
  constexpr double q = formats::kQuantizedMax;
  for (size_t i = 0; i < vertices.size(); ++i) {
    vertices[i] = {mesh.u[i] / q, mesh.v[i] / q, mesh.heightMeters[i]};
  }
  auto built = terrain::TinTile::build(geo::GeographicTilingScheme::tileRectangle(tile),
                                       std::move(vertices), mesh.triangles, url);
  if (!built) return Error{built.error()};
  if (mesh.normals.size() == mesh.vertexCount()) {
    std::vector<glm::vec3> normals(mesh.normals.size());
    for (size_t i = 0; i < normals.size(); ++i) {
      normals[i] = glm::vec3(mesh.normals[i][0], mesh.normals[i][1], mesh.normals[i][2]);
    }
    built->setNormals(std::move(normals));
  }
  return std::shared_ptr<const terrain::TinTile>(
      std::make_shared<terrain::TinTile>(std::move(*built)));
}

class QuantizedMeshSource final : public ServiceTerrainSource {
 public:
  QuantizedMeshSource(const ServiceDescription& d, terrain::SeaSurface sea,
                      formats::TerrainLayerJson layer, std::string layerUrl,
                      std::unique_ptr<UrlReader> reader)
      : ServiceTerrainSource(d, sea),
        layer_(std::move(layer)),
        layerUrl_(std::move(layerUrl)),
        reader_(std::move(reader)) {}

  std::string location(const geo::TileId& tile) const override {
    const uint32_t tmsY = geo::GeographicTilingScheme::tilesY(tile.level) - 1 - tile.y;
    const std::string& pattern = layer_.tiles[(tile.x + tmsY) % layer_.tiles.size()];
    return resolveUrl(layerUrl_,
                      expandTileUrl(pattern, {tile.level, tile.x, tmsY, layer_.version, {}}));
  }

 protected:
  bool publishes(const geo::TileId& tile) const override {
    const uint32_t tmsY = geo::GeographicTilingScheme::tilesY(tile.level) - 1 - tile.y;
    if (tile.level < layer_.available.size()) {
      if (covers(layer_.available[tile.level], tile.x, tmsY)) return true;
    } else if (layer_.available.empty()) {
      return tile.level >= layer_.minZoom && tile.level <= layer_.maxZoom;
    }
    std::lock_guard lock(mutex_);
    return tile.level < fromMetadata_.size() && covers(fromMetadata_[tile.level], tile.x, tmsY);
  }

  Result<std::optional<ServiceSamples>> fetchSamples(const geo::TileId& tile) override {
    const std::string url = location(tile);
    // A template with {version} names each version's tiles apart (CesiumJS's cache busting):
    // a tile cached under its URL is that version's, used without asking again. layer.json,
    // which says the version, is revalidated at every open.
    const bool versioned =
        !layer_.version.empty() && layer_.tiles[0].find("{version}") != std::string::npos;
    auto bytes =
        versioned ? reader_->readImmutable(url, kMaxTileBytes) : reader_->read(url, kMaxTileBytes);
    if (!bytes) return Error{bytes.error()};
    if (!*bytes) return std::optional<ServiceSamples>();  // listed but absent: the parent's
    auto inflated = compression::gunzipIfNeeded(**bytes, url, kMaxInflatedTileBytes);
    if (!inflated) return Error{inflated.error()};
    if (layer_.format == formats::TerrainLayerJson::Format::Heightmap) {
      auto heightmap = formats::decodeHeightmapTile(*inflated, url);
      if (!heightmap) return Error{heightmap.error()};
      return std::optional<ServiceSamples>(sampleHeightmap(*heightmap));
    }
    // The legacy "vertexnormals" extension writes its lengths big-endian (CesiumJS's rule).
    const bool legacy =
        layer_.hasExtension("vertexnormals") && !layer_.hasExtension("octvertexnormals");
    auto mesh = formats::decodeQuantizedMesh(
        *inflated, url,
        legacy ? formats::ExtensionLengths::BigEndian : formats::ExtensionLengths::LittleEndian);
    if (!mesh) return Error{mesh.error()};
    const auto rect = geo::GeographicTilingScheme::tileRectangle(tile);
    if (!formats::centreLiesOverTile(*mesh, geo::radiansToDegrees(rect.westRadians),
                                     geo::radiansToDegrees(rect.southRadians),
                                     geo::radiansToDegrees(rect.eastRadians),
                                     geo::radiansToDegrees(rect.northRadians))) {
      return makeError(url + ": the header's centre lies outside " + geo::tileName(tile) +
                       " of the geographic quadtree (tiles of another tiling, such as "
                       "Web Mercator?)");
    }
    if (!mesh->metadataJson.empty()) takeAvailability(tile, mesh->metadataJson);
    ServiceSamples samples = sampleTin(*mesh);
    auto tin = tinOf(*mesh, tile, url);
    if (!tin) return Error{tin.error()};
    samples.tin = std::move(*tin);
    return std::optional<ServiceSamples>(std::move(samples));
  }

 private:
  // The metadata extension's "available": its descendants' tiles, level by level below it.
  void takeAvailability(const geo::TileId& tile, const std::string& json) {
    try {
      const auto j = nlohmann::json::parse(json);
      auto a = j.find("available");
      if (a == j.end() || !a->is_array()) return;
      std::lock_guard lock(mutex_);
      uint32_t level = tile.level + 1;
      for (const auto& ranges : *a) {
        if (level > geo::kMaxLevel) break;
        if (fromMetadata_.size() <= level) fromMetadata_.resize(level + 1);
        for (const auto& r : ranges) {
          const auto range = formats::tileRangeFromJson(r);
          if (!range) {
            noteServiceError(location(tile) + ": a malformed range in its metadata (ignored)");
            return;
          }
          fromMetadata_[level].push_back(*range);
        }
        ++level;
      }
    } catch (const nlohmann::json::exception&) {
      noteServiceError(location(tile) + ": unreadable metadata extension (ignored)");
    }
  }

  formats::TerrainLayerJson layer_;
  std::string layerUrl_;
  std::unique_ptr<UrlReader> reader_;
  mutable std::mutex mutex_;
  std::vector<std::vector<formats::TileRange>> fromMetadata_;
};

}  // namespace

Result<std::unique_ptr<ServiceTerrainSource>> openQuantizedMeshSource(
    const std::string& spec, terrain::SeaSurface sea, std::shared_ptr<transport::Network> network) {
  std::string url = spec;
  auto options = takeQueryOptions(url, {"attribution"});
  std::string layerUrl = url;
  const std::string path = url.substr(0, url.find('?'));
  if (path.size() < 5 || path.compare(path.size() - 5, 5, ".json") != 0) {
    const size_t query = layerUrl.find('?');
    const std::string tail = query == std::string::npos ? "" : layerUrl.substr(query);
    std::string folder = path;
    while (!folder.empty() && folder.back() == '/') folder.pop_back();
    layerUrl = folder + "/layer.json" + tail;
  }
  auto reader = std::make_unique<UrlReader>(network, kQuantizedMeshAccept);
  auto text = reader->read(layerUrl, kMaxLayerJsonBytes);
  if (!text) return Error{text.error()};
  if (!*text) {
    return makeError(layerUrl +
                     ": not found; a Cesium terrain service publishes layer.json "
                     "beside its tiles");
  }
  auto layer = formats::parseTerrainLayerJson(
      std::string_view(reinterpret_cast<const char*>((*text)->data()), (*text)->size()), layerUrl);
  if (!layer) return Error{layer.error()};
  ServiceDescription d;
  d.location = "quantized-mesh:" + spec;
  d.format = layer->format == formats::TerrainLayerJson::Format::Heightmap ? "heightmap-1.0"
                                                                           : "quantized-mesh-1.0";
  d.maxLevel = layer->maxZoom;
  // Both formats are made on 65-sample grids: the finest level's step.
  d.stepDegrees =
      180.0 / static_cast<double>(uint64_t{1} << layer->maxZoom) / (kServiceVerticesPerSide - 1);
  if (!layer->available.empty()) {
    // The finest listed level's extent (tiles' metadata may list deeper ones).
    formats::BoundsDegrees b{180, 90, -180, -90};
    const auto z = static_cast<uint32_t>(layer->available.size() - 1);
    const double size = 180.0 / static_cast<double>(uint64_t{1} << z);
    for (const formats::TileRange& r : layer->available[z]) {
      b.west = std::min(b.west, -180 + r.startX * size);
      b.east = std::max(b.east, -180 + (r.endX + 1) * size);
      b.south = std::min(b.south, -90 + r.startY * size);
      b.north = std::max(b.north, -90 + (r.endY + 1) * size);
    }
    d.bounds = b;
  }
  d.attribution = options.count("attribution") ? options["attribution"] : layer->attribution;
  d.remote = reader->remote(layerUrl);
  return std::unique_ptr<ServiceTerrainSource>(std::make_unique<QuantizedMeshSource>(
      d, sea, std::move(*layer), std::move(layerUrl), std::move(reader)));
}

}  // namespace globe::services
