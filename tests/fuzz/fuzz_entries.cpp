// Fuzz entry points: bytes in, parser called, result inspected; the path parsers read a temp file.
#include "fuzz_entries.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <span>
#include <string>

#include "camera/camera_path_file.hpp"
#include "compression/gzip_bytes.hpp"
#include "core/big_endian.hpp"
#include "core/crc32.hpp"
#include "formats/image_io.hpp"
#include "formats/image_pack.hpp"
#include "formats/layer_manifest.hpp"
#include "formats/pack_format.hpp"
#include "formats/pmtiles.hpp"
#include "formats/pyramid_manifest.hpp"
#include "formats/quantized_mesh.hpp"
#include "formats/terrain_layer_json.hpp"
#include "formats/tile_edges.hpp"
#include "overlays/overlay_file.hpp"
#include "rasters/gtopo30_header.hpp"
#include "services/tin_sampling.hpp"
#include "services/tms_tilemap.hpp"
#include "services/wmts_capabilities.hpp"
#include "services/xyz_elevation_source.hpp"
#include "tiles3d/height_grid.hpp"
#include "tiles3d/implicit_tiling.hpp"
#include "tiles3d/tile_content.hpp"
#include "transport/http_client.hpp"

namespace globe::fuzz {
namespace {

std::string_view asText(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// A per-process file in the temp folder: the path readers take a path, not text.
std::filesystem::path writeTemp(const uint8_t* data, size_t size, const char* extension) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("globe-fuzz-" + std::to_string(::getpid()) + extension);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

void touch(const Result<camera::CameraPathFile>& result) {
  if (result) {
    volatile size_t n = result->keyframes.size();
    (void)n;
  } else {
    volatile size_t n = result.error().size();
    (void)n;
  }
}

}  // namespace

void gtopo30Header(const uint8_t* data, size_t size) {
  auto header = rasters::parseGtopo30Header(asText(data, size), "fuzz.HDR");
  if (header) (void)rasters::formatGtopo30Header(*header);
}

void pack(const uint8_t* data, size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  auto whole = formats::decodePack(bytes, "fuzz.pack");
  if (whole) (void)formats::encodePack(*whole);
  // The streaming reader's path: the head and index only, against the same and a larger file.
  (void)formats::decodePackIndex(bytes, size, "fuzz.pack");
  (void)formats::decodePackIndex(bytes.first(size / 2), size, "fuzz.pack");
}

void manifest(const uint8_t* data, size_t size) {
  auto result = formats::manifestFromJson(asText(data, size), "fuzz/manifest.json");
  if (result) (void)formats::manifestToJson(*result);
}

void pathJson(const uint8_t* data, size_t size) {
  const auto path = writeTemp(data, size, ".json");
  touch(camera::readCameraPathJson(path));
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

void pathKml(const uint8_t* data, size_t size) {
  const auto path = writeTemp(data, size, ".kml");
  touch(camera::readKmlTour(path));
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

void remote(const uint8_t* data, size_t size) {
  const std::string_view text = asText(data, size);
  uint64_t first = 0;
  uint64_t last = 0;
  uint64_t total = 0;
  (void)transport::parseContentRange(std::string(text.substr(0, text.find('\n'))), &first, &last,
                                     &total);
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  // As a whole pack (its trailer CRC in its last 4 bytes), and as a head of a longer file.
  if (size >= 4) {
    const uint32_t trailer = core::loadBigEndian32(bytes.data() + size - 4);
    (void)formats::decodeImagePackIndex(bytes, trailer, size, "fuzz.pack");
    auto whole = formats::decodeImagePack(bytes, "fuzz.pack");
    if (whole) (void)whole->payloads.size();
  }
  (void)formats::decodeImagePackIndex(bytes, core::crc32(bytes), uint64_t{1} << 40, "fuzz.pack");
  auto layer = formats::layerManifestFromJson(text, "fuzz/layer.json");
  if (layer) (void)formats::layerManifestToJson(*layer);
}

void imageTile(const uint8_t* data, size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  auto image = formats::decodeImageRgba(bytes, "fuzz.jpg");  // restores the edges when it can
  if (image) (void)image->pixels.size();
  formats::ImageRgba tile{256, 256, std::vector<uint8_t>(256 * 256 * 4, 0)};
  (void)formats::restoreTileEdges(bytes, tile);
}

void terrainTile(const uint8_t* data, size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  auto inflated = compression::gunzipIfNeeded(bytes, "fuzz.terrain", size_t{1} << 24);
  if (!inflated) return;
  if (auto mesh = formats::decodeQuantizedMesh(*inflated, "fuzz.terrain")) {
    const services::ServiceSamples samples = services::sampleTin(*mesh);
    (void)samples.heightMeters.size();
  }
  if (auto heightmap = formats::decodeHeightmapTile(*inflated, "fuzz.terrain")) {
    (void)services::sampleHeightmap(*heightmap);
  }
}

void terrainLayerJson(const uint8_t* data, size_t size) {
  auto layer = formats::parseTerrainLayerJson(
      std::string_view(reinterpret_cast<const char*>(data), size), "layer.json");
  if (layer) (void)layer->available.size();
}

void elevationImage(const uint8_t* data, size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  auto image = formats::decodeImageRgba(bytes, "fuzz.png");
  if (!image) return;
  double sum = 0;
  for (size_t p = 0; p + 3 < image->pixels.size(); p += 4) {
    sum +=
        services::decodeElevationPixel(services::ElevationEncoding::Terrarium, &image->pixels[p]) +
        services::decodeElevationPixel(services::ElevationEncoding::TerrainRgb, &image->pixels[p]);
  }
  (void)sum;
}

void pmtiles(const uint8_t* data, size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  // The head of a longer archive: its sections may lie beyond these bytes.
  auto header = formats::decodePmtilesHeader(bytes, uint64_t{1} << 40, "fuzz.pmtiles");
  if (header && header->rootOffset + header->rootLength <= size) {
    const auto root = bytes.subspan(header->rootOffset, header->rootLength);
    auto inflated = compression::gunzipIfNeeded(root, "fuzz.pmtiles", size_t{1} << 24);
    if (inflated) {
      if (auto entries = formats::decodePmtilesDirectory(*inflated, "fuzz.pmtiles")) {
        (void)formats::findPmtilesEntry(*entries, formats::pmtilesTileId(3, 5, 2));
      }
    }
  }
  // The bytes as a directory of their own.
  if (auto entries = formats::decodePmtilesDirectory(bytes, "fuzz.dir")) {
    (void)formats::findPmtilesEntry(*entries, 7);
  }
}

void serviceXml(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (auto caps = services::parseWmtsCapabilities(text, "fuzz.xml")) (void)caps->layers.size();
  if (auto map = services::parseTmsTileMap(text, "fuzz.xml")) (void)map->hrefs.size();
}

void overlayFile(const uint8_t* data, size_t size) {
  // A new name each time: GDAL's /vsizip/ remembers archives by name.
  static unsigned calls = 0;
  for (const char* extension : {".kml", ".geojson", ".gpx", ".kmz"}) {
    const auto path = writeTemp(data, size, ("-" + std::to_string(++calls) + extension).c_str());
    auto document = overlays::readOverlayFile(path);
    if (document) {
      size_t positions = 0;
      for (const auto& placemark : document->placemarks) {
        for (const auto& geometry : placemark.geometries) {
          for (const auto& ring : geometry.rings) positions += ring.size();
        }
      }
      volatile size_t n = positions + document->groundOverlays.size();
      (void)n;
    } else {
      volatile size_t n = document.error().size();
      (void)n;
    }
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
  }
}

void tileContent(const uint8_t* data, size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  // Placed on the ground near Philadelphia, as the samples stand (an identity transform would
  // put them at the geocentre, where nothing has a height).
  glm::dmat4 transform(1.0);
  transform[3] = glm::dvec4(1215107.76, -4736682.90, 4081926.10, 1.0);
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  auto mesh = tiles3d::readTileContent(bytes, transform, wgs84, "fuzz.b3dm");
  if (!mesh) return;
  const auto grid = tiles3d::HeightGrid::rasterize(*mesh, wgs84, 0.5, 64);
  volatile double h = grid.empty() ? 0.0 : grid.maximumHeightMeters();
  (void)h;
}

void implicitSubtree(const uint8_t* data, size_t size) {
  const std::vector<std::byte> bytes(reinterpret_cast<const std::byte*>(data),
                                     reinterpret_cast<const std::byte*>(data) + size);
  const auto tile = nlohmann::json::parse(
      R"({"boundingVolume":{"box":[0,0,0,1,0,0,0,1,0,0,0,1]},"geometricError":8,"refine":"ADD",)"
      R"("content":{"uri":"{level}_{x}_{y}.glb"},"implicitTiling":{"subdivisionScheme":)"
      R"("QUADTREE","subtreeLevels":3,"availableLevels":6,"subtrees":{"uri":"{level}.{x}.{y}.st"}}})");
  const tiles3d::ReadRelativeFile read =
      [&](const std::string& uri) -> Result<std::optional<std::vector<std::byte>>> {
    if (uri.size() > 3 && uri.compare(uri.size() - 3, 3, ".st") == 0) return std::optional(bytes);
    return std::optional<std::vector<std::byte>>{};  // an external buffer: not there
  };
  auto expanded = tiles3d::expandImplicitTiling(tile, read, 4096, "fuzz/tileset.json");
  volatile size_t n = expanded ? expanded->size() : 0;
  (void)n;
}

Entry entryNamed(std::string_view target) {
  if (target == "gtopo30_header") return gtopo30Header;
  if (target == "pack") return pack;
  if (target == "manifest") return manifest;
  if (target == "path_json") return pathJson;
  if (target == "path_kml") return pathKml;
  if (target == "remote") return remote;
  if (target == "image_tile") return imageTile;
  if (target == "terrain_tile") return terrainTile;
  if (target == "terrain_layer_json") return terrainLayerJson;
  if (target == "elevation_image") return elevationImage;
  if (target == "pmtiles") return pmtiles;
  if (target == "service_xml") return serviceXml;
  if (target == "overlay_file") return overlayFile;
  if (target == "tile_content") return tileContent;
  if (target == "implicit_subtree") return implicitSubtree;
  return nullptr;
}

}  // namespace globe::fuzz
