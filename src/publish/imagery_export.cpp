#include "publish/imagery_export.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <sstream>
#include <vector>

#include "transport/read_file.hpp"
#include "core/xml_escape.hpp"
#include "formats/pmtiles.hpp"
#include "publish/layer_sampler.hpp"
#include "publish/pmtiles_writer.hpp"
#include "geo/web_mercator.hpp"
#include "transport/atomic_file.hpp"

namespace globe::publish {
namespace {

namespace fs = std::filesystem;
constexpr uint32_t kImageryTileSize = geo::kWebMercatorTileSizePixels;
constexpr uint32_t kMaxExportZoom = 24;
constexpr std::uintmax_t kMaxTileJsonBytes = 4u << 20;  // an earlier export's tilejson.json

// What an export covers: zooms, and where the layer's sources lie within the region (latitudes
// within the projection's). The sources' own rectangles, not the layer's (the union of its
// tiles, whole hemispheres at level 0): a layer of two far-apart inputs is two small areas.
struct ImageryPlan {
  uint32_t minZoom = 0, maxZoom = 0;
  std::vector<formats::BoundsDegrees> areas;
  formats::BoundsDegrees bounds;  // their union
  uint32_t tileSizePixels = 256;
  uint32_t maxLevel = 0;
  uint32_t levelOf(uint32_t zoom) const {
    return std::min(layerLevelForZoom(zoom, tileSizePixels), maxLevel);
  }
};

std::string degreesText(const formats::BoundsDegrees& b) {
  char text[128];
  std::snprintf(text, sizeof text, "%.6g,%.6g,%.6g,%.6g", b.west, b.south, b.east, b.north);
  return text;
}

Result<ImageryPlan> planExport(streaming::ImageryTiles& layer, const ExportRegion& region) {
  const formats::LayerManifest& m = layer.manifest();
  if (m.kind != formats::LayerKind::Imagery) {
    return makeError(layer.location() + ": a water mask, not imagery");
  }
  if (m.levels.empty() || m.tileCount() == 0) {
    return makeError(layer.location() + ": the layer has no tiles");
  }
  ImageryPlan plan;
  plan.tileSizePixels = m.tileSizePixels;
  plan.maxLevel = m.maxLevel();
  const uint32_t finest =
      std::min(finestZoomOfLayer(plan.maxLevel, m.tileSizePixels), kMaxExportZoom);
  if (region.minLevel > finest) {
    return makeError("zooms " + std::to_string(region.minLevel) + "-" +
                     std::to_string(region.maxLevel) + ": " + layer.location() +
                     "'s finest is zoom " + std::to_string(finest) + " (its level " +
                     std::to_string(plan.maxLevel) + "); deeper zooms would only magnify it");
  }
  plan.minZoom = region.minLevel;
  plan.maxZoom = std::min(region.maxLevel, finest);
  std::vector<formats::BoundsDegrees> sources;
  for (const formats::ImagerySourceInfo& s : m.sources) sources.push_back(s.bounds);
  if (sources.empty()) sources.push_back(m.bounds);
  for (const formats::BoundsDegrees& s : sources) {
    const formats::BoundsDegrees a{
        std::max(region.westDegrees, s.west),
        std::max({region.southDegrees, s.south, -geo::kWebMercatorMaxLatitudeDegrees}),
        std::min(region.eastDegrees, s.east),
        std::min({region.northDegrees, s.north, geo::kWebMercatorMaxLatitudeDegrees})};
    if (!(a.west < a.east && a.south < a.north)) continue;
    plan.bounds = plan.areas.empty() ? a
                                     : formats::BoundsDegrees{std::min(plan.bounds.west, a.west),
                                                              std::min(plan.bounds.south, a.south),
                                                              std::max(plan.bounds.east, a.east),
                                                              std::max(plan.bounds.north, a.north)};
    plan.areas.push_back(a);
  }
  if (plan.areas.empty()) {
    return makeError("bounds " +
                     degreesText({region.westDegrees, region.southDegrees, region.eastDegrees,
                                  region.northDegrees}) +
                     " do not meet " + layer.location() + "'s imagery (" + degreesText(m.bounds) +
                     ") within Web Mercator's latitudes");
  }
  return plan;
}

struct MercatorTile {
  uint64_t tileId = 0;  // PMTiles' (Hilbert order within a zoom)
  uint32_t x = 0, y = 0;
  auto operator<=>(const MercatorTile&) const = default;
};

// The zoom's tiles over the plan's areas, each once, in tile id order: an archive's clustered
// order, and a tree's with good locality.
std::vector<MercatorTile> tilesOfZoom(const ImageryPlan& plan, uint32_t zoom) {
  std::vector<MercatorTile> tiles;
  for (const formats::BoundsDegrees& a : plan.areas) {
    const geo::WebMercatorTileRange range =
        geo::webMercatorTilesOf(a.west, a.south, a.east, a.north, zoom);
    for (uint32_t y = range.firstY; y <= range.lastY; ++y) {
      for (uint32_t x = range.firstX; x <= range.lastX; ++x) {
        tiles.push_back({formats::pmtilesTileId(zoom, x, y), x, y});
      }
    }
  }
  std::sort(tiles.begin(), tiles.end());
  tiles.erase(std::unique(tiles.begin(), tiles.end()), tiles.end());
  return tiles;
}

// The tile's pixels at their centres; nullopt when every one is transparent.
Result<std::optional<formats::ImageRgba>> renderMercatorTile(LayerSampler& sampler,
                                                             const ImageryPlan& plan, uint32_t zoom,
                                                             uint32_t x, uint32_t y) {
  const uint32_t level = plan.levelOf(zoom);
  formats::ImageRgba image{static_cast<int>(kImageryTileSize), static_cast<int>(kImageryTileSize),
                           std::vector<uint8_t>(size_t{kImageryTileSize} * kImageryTileSize * 4)};
  bool any = false;
  for (uint32_t r = 0; r < kImageryTileSize; ++r) {
    const double latitudeDegrees =
        geo::webMercatorLatitudeRadiansOfRow(y + (r + 0.5) / kImageryTileSize, zoom) * 180 /
        std::numbers::pi;
    for (uint32_t c = 0; c < kImageryTileSize; ++c) {
      const double longitudeDegrees =
          geo::webMercatorLongitudeDegreesOfColumn(x + (c + 0.5) / kImageryTileSize, zoom);
      auto pixel = sampler.sample(longitudeDegrees, latitudeDegrees, level);
      if (!pixel) return Error{pixel.error()};
      any = any || (*pixel)[3] > 0;
      std::copy(pixel->begin(), pixel->end(),
                &image.pixels[(size_t{r} * kImageryTileSize + c) * 4]);
    }
  }
  if (!any) return std::optional<formats::ImageRgba>();
  return std::optional<formats::ImageRgba>(std::move(image));
}

std::string outputName(const fs::path& out, const ImageryExportOptions& options) {
  if (!options.name.empty()) return options.name;
  const fs::path trimmed = out.filename().empty() ? out.parent_path() : out;
  return trimmed.stem().string();
}

std::string attributionOf(streaming::ImageryTiles& layer, const ImageryExportOptions& options) {
  return options.attribution.empty() ? layer.attribution() : options.attribution;
}

// tilejson.json: this run's zooms and bounds joined with an earlier run's into the same tree.
Result<nlohmann::json> mergedTileJson(const fs::path& outDir, const ImageryPlan& plan,
                                      const std::string& scheme, const std::string& tiles,
                                      const std::string& name, const std::string& attribution) {
  const formats::BoundsDegrees& b = plan.bounds;
  nlohmann::json j = {{"tilejson", "3.0.0"},
                      {"name", name},
                      {"scheme", scheme},
                      {"tiles", {tiles}},
                      {"minzoom", plan.minZoom},
                      {"maxzoom", plan.maxZoom},
                      {"bounds", {b.west, b.south, b.east, b.north}}};
  if (!attribution.empty()) j["attribution"] = attribution;
  const fs::path path = outDir / "tilejson.json";
  std::error_code missing;
  if (fs::exists(path, missing)) {
    const auto text = transport::readFileBounded(path, kMaxTileJsonBytes);
    if (!text) return makeError(text.error() + "; remove it or the tree");
    nlohmann::json earlier;
    try {
      earlier = nlohmann::json::parse(*text);
    } catch (const nlohmann::json::exception& e) {
      return makeError(path.string() + ": not JSON (" + e.what() + "); remove it or the tree");
    }
    const auto earlierTiles = earlier.value("tiles", nlohmann::json::array());
    if (earlier.value("scheme", "xyz") != scheme || earlierTiles.size() != 1 ||
        earlierTiles[0] != tiles) {
      return makeError(path.string() + ": an earlier export of other tiles (" +
                       earlierTiles.dump() + ", scheme " + earlier.value("scheme", "xyz") +
                       ") is in this directory; export " + tiles + " (" + scheme +
                       ") into another");
    }
    j["minzoom"] = std::min<uint32_t>(plan.minZoom, earlier.value("minzoom", plan.minZoom));
    j["maxzoom"] = std::max<uint32_t>(plan.maxZoom, earlier.value("maxzoom", plan.maxZoom));
    const auto e = earlier.value("bounds", nlohmann::json::array());
    if (e.size() == 4 && e[0].is_number() && e[1].is_number() && e[2].is_number() &&
        e[3].is_number()) {
      j["bounds"] = {std::min(b.west, e[0].get<double>()), std::min(b.south, e[1].get<double>()),
                     std::max(b.east, e[2].get<double>()), std::max(b.north, e[3].get<double>())};
    }
    if (attribution.empty() && earlier.contains("attribution")) {
      j["attribution"] = earlier["attribution"];
    }
  }
  const auto& merged = j["bounds"];
  j["center"] = {(merged[0].get<double>() + merged[2].get<double>()) / 2,
                 (merged[1].get<double>() + merged[3].get<double>()) / 2, j["minzoom"]};
  return j;
}


// OSGeo TMS 1.0.0's TileMap, global-mercator profile: the box in projected metres, the origin at
// the world's south-west corner, one TileSet per zoom (href is the zoom's folder).
std::string tileMapResource(const nlohmann::json& tileJson, ImageryTileFormat format) {
  const auto& b = tileJson["bounds"];
  std::ostringstream xml;
  xml.precision(17);
  xml << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      << "<TileMap version=\"1.0.0\" tilemapservice=\"http://tms.osgeo.org/1.0.0\">\n"
      << "  <Title>" << xmlEscaped(tileJson.value("name", "")) << "</Title>\n"
      << "  <Abstract>" << xmlEscaped(tileJson.value("attribution", "")) << "</Abstract>\n"
      << "  <SRS>EPSG:3857</SRS>\n"
      << "  <BoundingBox minx=\"" << geo::webMercatorXMeters(b[0].get<double>()) << "\" miny=\""
      << geo::webMercatorYMeters(b[1].get<double>()) << "\" maxx=\""
      << geo::webMercatorXMeters(b[2].get<double>()) << "\" maxy=\""
      << geo::webMercatorYMeters(b[3].get<double>()) << "\"/>\n"
      << "  <Origin x=\"" << -geo::kWebMercatorHalfWorldMeters << "\" y=\""
      << -geo::kWebMercatorHalfWorldMeters << "\"/>\n"
      << "  <TileFormat width=\"" << kImageryTileSize << "\" height=\"" << kImageryTileSize
      << "\" mime-type=\"" << mimeTypeOf(format) << "\" extension=\"" << extensionOf(format)
      << "\"/>\n"
      << "  <TileSets profile=\"global-mercator\">\n";
  for (uint32_t z = tileJson["minzoom"]; z <= tileJson["maxzoom"].get<uint32_t>(); ++z) {
    xml << "    <TileSet href=\"" << z << "\" units-per-pixel=\""
        << geo::webMercatorMetersPerPixel(z) << "\" order=\"" << z << "\"/>\n";
  }
  xml << "  </TileSets>\n</TileMap>\n";
  return xml.str();
}

}  // namespace

uint32_t layerLevelForZoom(uint32_t zoom, uint32_t tileSizePixels) {
  uint32_t level = 0;
  while (180.0 / std::ldexp(1.0, static_cast<int>(level)) / tileSizePixels >
         360.0 / std::ldexp(1.0, static_cast<int>(zoom)) / kImageryTileSize) {
    ++level;
  }
  return level;
}

uint32_t finestZoomOfLayer(uint32_t maxLevel, uint32_t tileSizePixels) {
  uint32_t zoom = 0;
  while (zoom < kMaxExportZoom && layerLevelForZoom(zoom + 1, tileSizePixels) <= maxLevel) ++zoom;
  return zoom;
}

Result<ImageryExportReport> exportImageryTree(streaming::ImageryTiles& layer,
                                              const ExportRegion& region, const fs::path& outDir,
                                              ImageryTreeScheme scheme,
                                              const ImageryExportOptions& options) {
  auto plan = planExport(layer, region);
  if (!plan) return Error{plan.error()};
  const bool tms = scheme == ImageryTreeScheme::Tms;
  const std::string extension = extensionOf(options.tileFormat);
  // Checked before any tile: a tree of other tiles in the directory is an error, not a mix.
  auto tileJson =
      mergedTileJson(outDir, *plan, tms ? "tms" : "xyz", std::string("{z}/{x}/{y}.") + extension,
                     outputName(outDir, options), attributionOf(layer, options));
  if (!tileJson) return Error{tileJson.error()};
  std::error_code error;
  fs::create_directories(outDir, error);
  if (error) return makeError(outDir.string() + ": cannot create: " + error.message());

  LayerSampler sampler(layer);
  ImageryExportReport report;
  report.minZoom = plan->minZoom;
  report.maxZoom = plan->maxZoom;
  for (uint32_t zoom = plan->minZoom; zoom <= plan->maxZoom; ++zoom) {
    for (const MercatorTile& t : tilesOfZoom(*plan, zoom)) {
      const uint32_t row = tms ? (1U << zoom) - 1 - t.y : t.y;
      const fs::path path = outDir / std::to_string(zoom) / std::to_string(t.x) /
                            (std::to_string(row) + "." + extension);
      std::optional<formats::ImageRgba> image;
      if (!fs::is_regular_file(path, error)) {
        auto rendered = renderMercatorTile(sampler, *plan, zoom, t.x, t.y);
        if (!rendered) return Error{rendered.error()};
        if (!*rendered) {
          ++report.tilesEmpty;
          continue;
        }
        image = std::move(*rendered);
      }
      // Kept when already there (image unset: never encoded).
      auto written = writeTileOnce(
          path, [&] { return encodeImageryTile(*image, options.tileFormat, options.quality); },
          report);
      if (!written) return Error{written.error()};
    }
  }
  if (auto w = transport::writeFileAtomically(outDir / "tilejson.json", tileJson->dump(2) + "\n");
      !w) {
    return Error{w.error()};
  }
  if (tms) {
    auto w = transport::writeFileAtomically(outDir / "tilemapresource.xml",
                                            tileMapResource(*tileJson, options.tileFormat));
    if (!w) return Error{w.error()};
  }
  return report;
}

Result<ImageryExportReport> exportImageryPmtiles(streaming::ImageryTiles& layer,
                                                 const ExportRegion& region,
                                                 const fs::path& archive,
                                                 const ImageryExportOptions& options) {
  auto plan = planExport(layer, region);
  if (!plan) return Error{plan.error()};
  auto writer = PmtilesWriter::create(archive);
  if (!writer) return Error{writer.error()};
  LayerSampler sampler(layer);
  ImageryExportReport report;
  report.minZoom = plan->minZoom;
  report.maxZoom = plan->maxZoom;
  // Clustered: tile data in tile id order (zoom by zoom, Hilbert order within one).
  for (uint32_t zoom = plan->minZoom; zoom <= plan->maxZoom; ++zoom) {
    for (const MercatorTile& t : tilesOfZoom(*plan, zoom)) {
      auto rendered = renderMercatorTile(sampler, *plan, zoom, t.x, t.y);
      if (!rendered) return Error{rendered.error()};
      if (!*rendered) {
        ++report.tilesEmpty;
        continue;
      }
      auto bytes = encodeImageryTile(**rendered, options.tileFormat, options.quality);
      if (!bytes) return Error{bytes.error()};
      if (auto added = (*writer)->add(zoom, t.x, t.y, *bytes); !added) {
        return Error{added.error()};
      }
      ++report.tilesWritten;
      report.bytesWritten += bytes->size();
    }
  }
  formats::PmtilesHeader header;
  header.tileType = options.tileFormat == ImageryTileFormat::Png ? formats::PmtilesTileType::Png
                    : options.tileFormat == ImageryTileFormat::Jpeg
                        ? formats::PmtilesTileType::Jpeg
                        : formats::PmtilesTileType::Webp;
  header.minZoom = static_cast<uint8_t>(plan->minZoom);
  header.maxZoom = static_cast<uint8_t>(plan->maxZoom);
  header.westDegrees = plan->bounds.west;
  header.southDegrees = plan->bounds.south;
  header.eastDegrees = plan->bounds.east;
  header.northDegrees = plan->bounds.north;
  header.centerZoom = header.minZoom;
  header.centerLongitudeDegrees = (plan->bounds.west + plan->bounds.east) / 2;
  header.centerLatitudeDegrees = (plan->bounds.south + plan->bounds.north) / 2;
  nlohmann::json metadata = {
      {"name", outputName(archive, options)},
      {"type", "baselayer"},
      {"format", extensionOf(options.tileFormat)},
      {"minzoom", plan->minZoom},
      {"maxzoom", plan->maxZoom},
      {"tileSize", kImageryTileSize},
      {"bounds", {plan->bounds.west, plan->bounds.south, plan->bounds.east, plan->bounds.north}},
      {"description", "globe-tiler export-imagery of " + layer.location()}};
  if (const std::string a = attributionOf(layer, options); !a.empty()) metadata["attribution"] = a;
  auto summary = (*writer)->finish(header, metadata.dump());
  if (!summary) return Error{summary.error()};
  report.tilesDistinct = summary->tileContents;
  report.archiveBytes = summary->archiveBytes;
  return report;
}

}  // namespace globe::publish
