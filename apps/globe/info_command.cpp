#include "apps/globe/info_command.hpp"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string_view>
#include <vector>

#include "formats/source_conditioning_json.hpp"
#include "formats/vertical_units_json.hpp"
#include "services/imagery_services.hpp"
#include "services/terrain_services.hpp"

namespace globe::app {
namespace {

formats::BoundsDegrees overallBounds(const formats::PyramidManifest& m) {
  // Level 0 always spans the globe; the finest level shows where the detail is.
  return m.levels.empty() ? formats::BoundsDegrees{} : m.levels.back().bounds;
}

terrain::HeightRange overallRange(const formats::PyramidManifest& m) {
  terrain::HeightRange range{INT16_MAX, INT16_MIN};
  for (const formats::LevelInfo& level : m.levels) range.include(level.heightRange);
  return range;
}

std::string boundsText(const formats::BoundsDegrees& b) {
  char text[128];
  std::snprintf(text, sizeof text, "lon %.6f..%.6f, lat %.6f..%.6f", b.west, b.east, b.south,
                b.north);
  return text;
}

}  // namespace

std::string formatPyramidInfoText(const formats::PyramidManifest& m, const std::string& path) {
  std::string out;
  char line[1024];
  const auto range = overallRange(m);
  std::snprintf(
      line, sizeof line,
      "pyramid     %s\nscheme      geographic lat/long quadtree, level 0 = 2x1 tiles of "
      "180 deg\nblocks      %ux%u vertices, GTOPO30 int16 big-endian, -9999 and "
      "-32767..-20001 = water\n"
      "globe       %s\nlevels      0..%u\ntiles       %llu\nheights     %d..%d m (sea floors "
      "included)\n"
      "finest      %s\n",
      path.c_str(), m.verticesPerSide, m.verticesPerSide,
      std::string(geo::toString(m.globeModel)).c_str(), m.maxLevel(),
      static_cast<unsigned long long>(m.tileCount()), range.minimumMeters, range.maximumMeters,
      boundsText(overallBounds(m)).c_str());
  out += line;
  out += "\nlevel      tiles  packs  heights (m)     bounds (deg)\n";
  for (const formats::LevelInfo& level : m.levels) {
    std::snprintf(line, sizeof line, "%5u %10llu %6zu  %6d..%-6d  %s\n", level.level,
                  static_cast<unsigned long long>(level.tileCount), level.packs.size(),
                  level.heightRange.minimumMeters, level.heightRange.maximumMeters,
                  boundsText(level.bounds).c_str());
    out += line;
  }
  out += "\nsources (finest first)\n";
  for (const formats::SourceInfo& s : m.sources) {
    std::snprintf(line, sizeof line,
                  "  %s  %s %lldx%lld, %.6g deg (%.1f arcsec), finest level %u, %s\n",
                  s.path.c_str(), s.format.c_str(), static_cast<long long>(s.columns),
                  static_cast<long long>(s.rows), s.stepDegrees, s.stepDegrees * 3600.0,
                  s.finestLevel, boundsText(s.bounds).c_str());
    out += line;
    const formats::SourceConditioning& c = s.conditioning;
    std::snprintf(line, sizeof line,
                  "    sea %llu samples; voids %llu (%llu interpolated, %llu from a coarser "
                  "source, %llu left); %llu outside its footprint; coarser sources bend to "
                  "its edges within %.4g deg%s\n",
                  static_cast<unsigned long long>(c.seaSamples),
                  static_cast<unsigned long long>(c.voidSamples),
                  static_cast<unsigned long long>(c.interpolatedSamples),
                  static_cast<unsigned long long>(c.fromCoarserSamples),
                  static_cast<unsigned long long>(c.unfilledSamples),
                  static_cast<unsigned long long>(c.outsideSamples), c.bendMarginDegrees,
                  c.noDataIsWater ? "; its no data is its sea" : "");
    out += line;
    if (s.verticalUnits) out += "    heights " + formats::describe(*s.verticalUnits) + "\n";
  }
  return out;
}

std::string formatPyramidInfoJson(const formats::PyramidManifest& m, const std::string& path) {
  using nlohmann::json;
  auto boundsJson = [](const formats::BoundsDegrees& b) {
    return json{{"west", b.west}, {"south", b.south}, {"east", b.east}, {"north", b.north}};
  };
  const auto range = overallRange(m);
  json levels = json::array();
  for (const formats::LevelInfo& level : m.levels) {
    levels.push_back(
        {{"level", level.level},
         {"tiles", level.tileCount},
         {"packs", level.packs.size()},
         {"heightRangeMeters", {level.heightRange.minimumMeters, level.heightRange.maximumMeters}},
         {"boundsDegrees", boundsJson(level.bounds)}});
  }
  json sources = json::array();
  for (const formats::SourceInfo& s : m.sources) {
    sources.push_back({{"path", s.path},
                       {"format", s.format},
                       {"columns", s.columns},
                       {"rows", s.rows},
                       {"stepDegrees", s.stepDegrees},
                       {"finestLevel", s.finestLevel},
                       {"boundsDegrees", boundsJson(s.bounds)},
                       {"conditioning", formats::conditioningToJson(s.conditioning)}});
    if (s.verticalUnits) {
      sources.back()["verticalUnits"] = formats::verticalUnitsToJson(*s.verticalUnits);
    }
  }
  const json j = {{"pyramid", path},
                  {"blockSize", m.verticesPerSide},
                  {"globeModel", std::string(geo::toString(m.globeModel))},
                  {"minLevel", 0},
                  {"maxLevel", m.maxLevel()},
                  {"tiles", m.tileCount()},
                  {"heightRangeMeters", {range.minimumMeters, range.maximumMeters}},
                  {"finestBoundsDegrees", boundsJson(overallBounds(m))},
                  {"levels", levels},
                  {"sources", sources}};
  return j.dump(2) + "\n";
}

std::string formatLayerInfoText(const formats::LayerManifest& m, const std::string& path) {
  std::string out;
  char line[1024];
  std::snprintf(
      line, sizeof line,
      "layer       %s\n"
      "scheme      geographic lat/long quadtree, level 0 = 2x1 tiles of 180 deg\n"
      "tiles       %ux%u pixels, %s, %llu in all\n"
      "levels      0..%u\n"
      "finest      %s\n",
      path.c_str(), m.tileSizePixels, m.tileSizePixels,
      m.kind == formats::LayerKind::WaterMask
          ? "a water mask: grey+alpha PNG (water fraction; alpha 0 = undecided)"
          : "JPEG (opaque) or PNG (with alpha)",
      static_cast<unsigned long long>(m.tileCount()), m.maxLevel(),
      boundsText(m.levels.empty() ? formats::BoundsDegrees{} : m.levels.back().bounds).c_str());
  out += line;
  out += "\nlevel      tiles  packs  bounds (deg)\n";
  for (const formats::ImageryLevelInfo& info : m.levels) {
    std::snprintf(line, sizeof line, "%5u %10llu %6zu  %s\n", info.level,
                  static_cast<unsigned long long>(info.tileCount), info.packs.size(),
                  boundsText(info.bounds).c_str());
    out += line;
  }
  out += "\nsources (finest first)\n";
  for (const formats::ImagerySourceInfo& s : m.sources) {
    std::snprintf(line, sizeof line,
                  "  %s  %s %lldx%lld, %s, %.6g deg per pixel, finest level %u, bands %s%s%s, %s\n",
                  s.path.c_str(), s.driver.c_str(), static_cast<long long>(s.columns),
                  static_cast<long long>(s.rows), s.crs.c_str(), s.pixelDegrees, s.finestLevel,
                  s.bands.c_str(), s.stretch.empty() ? "" : ", stretch ", s.stretch.c_str(),
                  boundsText(s.bounds).c_str());
    out += line;
  }
  return out;
}

// A terrain service: what its layer.json or template says, as the viewer will read it.
static std::string formatServiceInfo(const streaming::TerrainSource& service, bool json) {
  const formats::PyramidManifest& m = service.manifest();
  const formats::SourceInfo& s = m.sources.front();
  if (json) {
    nlohmann::json j{{"service", service.location()},
                     {"format", s.format},
                     {"verticesPerSide", m.verticesPerSide},
                     {"maxLevel", m.maxLevel()},
                     {"stepDegrees", s.stepDegrees},
                     {"bounds", {s.bounds.west, s.bounds.south, s.bounds.east, s.bounds.north}},
                     {"attribution", service.attribution()}};
    return j.dump(2) + "\n";
  }
  char line[2048];
  std::snprintf(line, sizeof line,
                "service     %s\nformat      %s\nscheme      geographic lat/long quadtree, "
                "level 0 = 2x1 tiles of 180 deg\nblocks      %ux%u vertices sampled from each "
                "tile as it loads\nlevels      0..%u\nfinest      %.6g deg (%.1f arcsec), %s\n"
                "attribution %s\n",
                service.location().c_str(), s.format.c_str(), m.verticesPerSide, m.verticesPerSide,
                m.maxLevel(), s.stepDegrees, s.stepDegrees * 3600.0, boundsText(s.bounds).c_str(),
                service.attribution().empty() ? "(none given)" : service.attribution().c_str());
  return line;
}

Result<std::string> runInfo(const InfoOptions& options) {
  if (services::isImageryService(options.location)) {
    auto layer = services::openImageryTiles(options.location, options.network);
    if (!layer) return Error{layer.error()};
    const formats::LayerManifest& m = (*layer)->manifest();
    if (options.json) {
      nlohmann::json j = nlohmann::json::parse(formats::layerManifestToJson(m));
      j["service"] = (*layer)->location();
      j["attribution"] = (*layer)->attribution();
      return j.dump(2) + "\n";
    }
    const formats::ImagerySourceInfo& s = m.sources.front();
    char line[4096];
    std::snprintf(
        line, sizeof line,
        "layer       %s\nservice     %s, %s tiles drawn onto the geographic quadtree as "
        "they load\ntiles       %ux%u samples on the tile edges\nlevels      0..%u\n"
        "extent      %s\nfinest      %.6g deg per pixel\nattribution %s\n",
        options.location.c_str(), s.driver.c_str(), s.crs.c_str(), m.tileSizePixels,
        m.tileSizePixels, m.maxLevel(), boundsText(m.bounds).c_str(), s.pixelDegrees,
        (*layer)->attribution().empty() ? "(none given)" : (*layer)->attribution().c_str());
    return std::string(line);
  }
  if (services::isTerrainService(options.location)) {
    auto service =
        services::openTerrainSource(options.location, terrain::SeaSurface::Water, options.network);
    if (!service) return Error{service.error()};
    return formatServiceInfo(**service, options.json);
  }
  auto source = transport::openByteSource(options.location, options.network.get());
  if (!source) return Error{source.error()};
  auto asText = [](const std::vector<std::byte>& bytes) {
    return std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  };
  auto pyramidBytes =
      (*source)->readWhole(formats::kManifestFileName, formats::kMaxManifestFileBytes);
  if (!pyramidBytes) return Error{pyramidBytes.error()};
  if (!*pyramidBytes) {
    // An imagery layer (globe-tiler imagery) rather than a pyramid?
    auto layerBytes =
        (*source)->readWhole(formats::kLayerManifestFileName, formats::kMaxManifestFileBytes);
    if (!layerBytes) return Error{layerBytes.error()};
    if (*layerBytes) {
      auto layer = formats::layerManifestFromJson(
          asText(**layerBytes), (*source)->locationOf(formats::kLayerManifestFileName));
      if (!layer) return Error{layer.error()};
      return options.json ? formats::layerManifestToJson(*layer) + "\n"
                          : formatLayerInfoText(*layer, options.location);
    }
  }
  // The pyramid's manifest, or what is missing or wrong with it.
  auto manifest = *pyramidBytes
                      ? formats::manifestFromJson(asText(**pyramidBytes),
                                                  (*source)->locationOf(formats::kManifestFileName))
                      : formats::readManifest(**source);
  if (!manifest) return Error{manifest.error()};
  return options.json ? formatPyramidInfoJson(*manifest, options.location)
                      : formatPyramidInfoText(*manifest, options.location);
}

}  // namespace globe::app
