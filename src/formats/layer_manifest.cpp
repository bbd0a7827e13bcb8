#include "formats/layer_manifest.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "formats/bounds_json.hpp"
#include "geo/tile_id.hpp"
#include "transport/atomic_file.hpp"

namespace globe::formats {
namespace {

using nlohmann::json;

// Integers through int64 with a range check: nlohmann's get<uint32_t>() of 1e64 is undefined.
uint64_t unsignedOf(const json& value, uint64_t maximum, const char* what) {
  const bool negative = value.is_number_integer() && !value.is_number_unsigned();
  if (!value.is_number_integer() || (negative && value.get<int64_t>() < 0) ||
      value.get<uint64_t>() > maximum) {
    throw std::out_of_range(std::string(what) + " must be an integer in 0.." +
                            std::to_string(maximum) + ", not " + value.dump());
  }
  return value.get<uint64_t>();
}

uint32_t u32Of(const json& value, const char* what) {
  return static_cast<uint32_t>(unsignedOf(value, UINT32_MAX, what));
}

}  // namespace

uint64_t LayerManifest::tileCount() const {
  uint64_t count = 0;
  for (const ImageryLevelInfo& level : levels) count += level.tileCount;
  return count;
}

std::string layerManifestToJson(const LayerManifest& manifest) {
  json levels = json::array();
  for (const ImageryLevelInfo& level : manifest.levels) {
    json packs = json::array();
    for (const PackId& pack : level.packs) packs.push_back({pack.x, pack.y});
    levels.push_back({{"level", level.level},
                      {"tileCount", level.tileCount},
                      {"boundsDegrees", boundsToJson(level.bounds)},
                      {"packs", packs}});
  }
  json sources = json::array();
  for (const ImagerySourceInfo& s : manifest.sources) {
    sources.push_back({{"path", s.path},
                       {"driver", s.driver},
                       {"columns", s.columns},
                       {"rows", s.rows},
                       {"crs", s.crs},
                       {"pixelDegrees", s.pixelDegrees},
                       {"boundsDegrees", boundsToJson(s.bounds)},
                       {"finestLevel", s.finestLevel},
                       {"bands", s.bands},
                       {"stretch", s.stretch}});
  }
  const bool edges = manifest.pixelGrid == ImageryPixelGrid::Edges;
  const json j = {
      {"format", "globe-imagery-layer"},
      // Version 1 where version 1 readers draw the layer right (area pixels).
      {"formatVersion", edges ? kLayerFormatVersion : 1},
      {"kind", manifest.kind == LayerKind::WaterMask ? "water-mask" : "imagery"},
      {"tilingScheme",
       {{"name", "geographic"},
        {"level0", "2x1 tiles of 180x180 degrees; x eastwards from -180, y southwards from +90"},
        {"pixelGrid", edges ? "edges" : "area"},
        {"pixelConvention",
         edges ? "samples at the edges: pixel (r,c) is the sample at lon west + c*w/(S-1), lat "
                 "north - r*h/(S-1); the first and last rows and columns lie on the tile's edges"
               : "pixel-is-area: pixel (r,c) covers lon [west + c*w/S, west + (c+1)*w/S], lat "
                 "[north - (r+1)*h/S, north - r*h/S], row 0 at the north edge"}}},
      {"tileSizePixels", manifest.tileSizePixels},
      {"packTilesPerSide", manifest.packTilesPerSide},
      {"packFiles", "L<level>/<packX>_<packY>.pack (GLOBEIM1: header, index, JPEG/PNG payloads)"},
      {"encoding", manifest.kind == LayerKind::WaterMask
                       ? "8-bit grey+alpha PNG: grey the water fraction around each sample (255 = "
                         "water), alpha 0 where no input decides; absent = as the nearest present "
                         "ancestor"
                       : "JPEG where every pixel is opaque, PNG (RGBA) otherwise; absent = no "
                         "data"},
      {"boundsDegrees", boundsToJson(manifest.bounds)},
      {"maxLevel", manifest.maxLevel()},
      {"planFingerprint", manifest.planFingerprint},
      {"levels", levels},
      {"sources", sources}};
  return j.dump(1) + "\n";
}

Result<LayerManifest> layerManifestFromJson(std::string_view text,
                                            const std::filesystem::path& path) {
  const json j = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return makeError(path.string() + ": not valid JSON");
  try {
    const std::string kind = j.is_object() ? j.value("kind", "") : "";
    if (!j.is_object() || j.value("format", "") != "globe-imagery-layer" ||
        (kind != "imagery" && kind != "water-mask")) {
      return makeError(path.string() + ": not a globe imagery layer manifest");
    }
    const uint32_t version = u32Of(j.at("formatVersion"), "formatVersion");
    if (version < 1 || version > kLayerFormatVersion) {
      return makeError(path.string() + ": layer format version " + j.at("formatVersion").dump() +
                       " (this globe reads 1.." + std::to_string(kLayerFormatVersion) + ")");
    }
    LayerManifest m;
    m.kind = kind == "water-mask" ? LayerKind::WaterMask : LayerKind::Imagery;
    if (version >= 2) {
      const std::string grid = j.at("tilingScheme").value("pixelGrid", "");
      if (grid != "edges" && grid != "area") {
        return makeError(path.string() + ": tilingScheme.pixelGrid must be \"edges\" or \"area\"");
      }
      m.pixelGrid = grid == "edges" ? ImageryPixelGrid::Edges : ImageryPixelGrid::Area;
    }
    m.tileSizePixels = u32Of(j.at("tileSizePixels"), "tileSizePixels");
    if (m.tileSizePixels != 256) {
      return makeError(path.string() + ": tileSizePixels " + std::to_string(m.tileSizePixels) +
                       " (only 256 is supported)");
    }
    m.packTilesPerSide = u32Of(j.at("packTilesPerSide"), "packTilesPerSide");
    if (m.packTilesPerSide == 0 || m.packTilesPerSide > kImagePackMaxTilesPerSide) {
      return makeError(path.string() + ": packTilesPerSide out of range 1.." +
                       std::to_string(kImagePackMaxTilesPerSide));
    }
    m.bounds = boundsFromJson(j.at("boundsDegrees"));
    m.planFingerprint = j.value("planFingerprint", "");
    for (const json& level : j.at("levels")) {
      ImageryLevelInfo info;
      info.level = u32Of(level.at("level"), "level");
      if (info.level != m.levels.size()) {
        return makeError(path.string() + ": levels must be listed 0, 1, 2, ... without gaps");
      }
      info.tileCount = unsignedOf(level.at("tileCount"), UINT64_MAX, "tileCount");
      info.bounds = boundsFromJson(level.at("boundsDegrees"));
      if (info.level > geo::kMaxLevel) return makeError(path.string() + ": level out of range");
      const uint64_t packsPerRow =
          ((uint64_t{2} << info.level) + m.packTilesPerSide - 1) / m.packTilesPerSide;
      const uint64_t packsPerColumn =
          ((uint64_t{1} << info.level) + m.packTilesPerSide - 1) / m.packTilesPerSide;
      for (const json& pack : level.at("packs")) {
        const PackId id{info.level, u32Of(pack.at(0), "pack x"), u32Of(pack.at(1), "pack y")};
        if (id.x >= packsPerRow || id.y >= packsPerColumn) {
          return makeError(path.string() + ": level " + std::to_string(info.level) +
                           " lists pack " + std::to_string(id.x) + "_" + std::to_string(id.y) +
                           " outside the globe");
        }
        info.packs.push_back(id);
      }
      std::sort(info.packs.begin(), info.packs.end());
      m.levels.push_back(std::move(info));
    }
    if (m.levels.empty() || m.levels.size() > geo::kMaxLevel + 1) {
      return makeError(path.string() + ": a layer needs between 1 and " +
                       std::to_string(geo::kMaxLevel + 1) + " levels");
    }
    for (const json& s : j.at("sources")) {
      ImagerySourceInfo info;
      info.path = s.at("path").get<std::string>();
      info.driver = s.at("driver").get<std::string>();
      info.columns = static_cast<int64_t>(unsignedOf(s.at("columns"), INT64_MAX, "columns"));
      info.rows = static_cast<int64_t>(unsignedOf(s.at("rows"), INT64_MAX, "rows"));
      info.crs = s.at("crs").get<std::string>();
      info.pixelDegrees = s.at("pixelDegrees").get<double>();
      info.bounds = boundsFromJson(s.at("boundsDegrees"));
      info.finestLevel = u32Of(s.at("finestLevel"), "finestLevel");
      info.bands = s.at("bands").get<std::string>();
      info.stretch = s.value("stretch", "");
      m.sources.push_back(std::move(info));
    }
    return m;
  } catch (const json::exception& e) {
    return makeError(path.string() + ": missing or malformed field (" + e.what() + ")");
  } catch (const std::out_of_range& e) {
    return makeError(path.string() + ": " + e.what());
  }
}

Result<LayerManifest> readLayerManifest(transport::ByteSource& source) {
  const std::string path = source.locationOf(kLayerManifestFileName);
  auto bytes = source.readWhole(kLayerManifestFileName, kMaxManifestFileBytes);
  if (!bytes) return Error{bytes.error()};
  if (!*bytes) {
    return makeError(path + ": cannot open: not found (is " + source.location() +
                     " a layer made by globe-tiler imagery or water-mask?)");
  }
  return layerManifestFromJson(
      std::string_view(reinterpret_cast<const char*>((*bytes)->data()), (*bytes)->size()), path);
}

Result<LayerManifest> readLayerManifest(const std::filesystem::path& layerDir) {
  return readLayerManifest(*transport::localByteSource(layerDir));
}

Result<void> writeLayerManifest(const std::filesystem::path& layerDir,
                                const LayerManifest& manifest) {
  return transport::writeFileAtomically(layerDir / kLayerManifestFileName,
                                        layerManifestToJson(manifest));
}

}  // namespace globe::formats
