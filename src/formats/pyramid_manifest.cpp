#include "formats/pyramid_manifest.hpp"

#include <cmath>

#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "formats/bounds_json.hpp"
#include "formats/source_conditioning_json.hpp"
#include "formats/vertical_units_json.hpp"

namespace globe::formats {
namespace {

using nlohmann::json;

// An integer field out of its type's range (or not an integer at all, e.g. 1e64): nlohmann's
// get<T>() would cast it with undefined behaviour, so every integer goes through integerOf.
struct FieldError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

template <class T>
T integerOf(const json& value) {
  constexpr auto lowest = std::numeric_limits<T>::min();
  constexpr auto highest = std::numeric_limits<T>::max();
  bool inRange = false;
  if (value.is_number_unsigned()) {
    inRange = value.get<uint64_t>() <= static_cast<uint64_t>(highest);
  } else if (value.is_number_integer()) {
    const auto signedValue = value.get<int64_t>();
    if constexpr (std::is_signed_v<T>) {
      inRange = signedValue >= int64_t{lowest} && signedValue <= int64_t{highest};
    } else {
      inRange = signedValue >= 0 && static_cast<uint64_t>(signedValue) <= uint64_t{highest};
    }
  }
  if (!inRange) {
    throw FieldError("expected an integer in " + std::to_string(lowest) + ".." +
                     std::to_string(highest) + ", got " + value.dump());
  }
  return static_cast<T>(value.get<int64_t>());
}

json rangeToJson(const terrain::HeightRange& r) {
  return json::array({r.minimumMeters, r.maximumMeters});
}

VerticalUnits verticalUnitsFromJson(const json& j) {
  VerticalUnits u;
  u.fileUnit = j.at("fileUnit").get<std::string>();
  const auto origin = parseVerticalUnitOrigin(j.at("appliedBy").get<std::string>());
  if (!origin) throw json::other_error::create(501, "unknown verticalUnits.appliedBy", &j);
  u.origin = *origin;
  if (u.origin == VerticalUnitOrigin::ZUnits) {
    u.overrideUnit = j.at("overrideUnit").get<std::string>();
  }
  u.metersPerUnit = j.at("metersPerUnit").get<double>();
  u.bandScale = j.at("bandScale").get<double>();
  u.bandOffset = j.at("bandOffset").get<double>();
  return u;
}

terrain::HeightRange rangeFromJson(const json& j) {
  return {integerOf<int16_t>(j.at(0)), integerOf<int16_t>(j.at(1))};
}

SourceConditioning conditioningFromJson(const json& j) {
  SourceConditioning c;
  c.noDataSamples = integerOf<uint64_t>(j.at("noDataSamples"));
  c.seaSamples = integerOf<uint64_t>(j.at("seaSamples"));
  c.voidSamples = integerOf<uint64_t>(j.at("voidSamples"));
  c.interpolatedSamples = integerOf<uint64_t>(j.at("voidsFilledByInterpolation"));
  c.fromCoarserSamples = integerOf<uint64_t>(j.at("voidsFilledFromCoarserSource"));
  c.unfilledSamples = integerOf<uint64_t>(j.at("voidsLeftNoData"));
  // Pyramids tiled before the footprint rules name the margin "blendMarginDegrees" and count
  // samples eased inside the source instead (not kept).
  if (j.contains("outsideFootprintSamples")) {
    c.outsideSamples = integerOf<uint64_t>(j.at("outsideFootprintSamples"));
  }
  c.bendMarginDegrees = j.contains("bendMarginDegrees") ? j.at("bendMarginDegrees").get<double>()
                                                        : j.at("blendMarginDegrees").get<double>();
  c.noDataIsWater = j.value("noDataIsWater", false);
  return c;
}

}  // namespace

nlohmann::json conditioningToJson(const SourceConditioning& c) {
  return {{"noDataSamples", c.noDataSamples},
          {"seaSamples", c.seaSamples},
          {"voidSamples", c.voidSamples},
          {"voidsFilledByInterpolation", c.interpolatedSamples},
          {"voidsFilledFromCoarserSource", c.fromCoarserSamples},
          {"voidsLeftNoData", c.unfilledSamples},
          {"outsideFootprintSamples", c.outsideSamples},
          {"bendMarginDegrees", c.bendMarginDegrees},
          {"noDataIsWater", c.noDataIsWater}};
}

uint64_t PyramidManifest::tileCount() const {
  uint64_t count = 0;
  for (const LevelInfo& level : levels) count += level.tileCount;
  return count;
}

std::string manifestToJson(const PyramidManifest& manifest) {
  json levels = json::array();
  for (const LevelInfo& level : manifest.levels) {
    json packs = json::array();
    for (size_t i = 0; i < level.packs.size(); ++i) {
      if (level.packIndexBytes.size() == level.packs.size()) {
        packs.push_back({level.packs[i].x, level.packs[i].y, level.packIndexBytes[i]});
      } else {
        packs.push_back({level.packs[i].x, level.packs[i].y});
      }
    }
    levels.push_back({{"level", level.level},
                      {"tiles", level.tileCount},
                      {"boundsDegrees", boundsToJson(level.bounds)},
                      {"heightRangeMeters", rangeToJson(level.heightRange)},
                      {"packs", packs}});
  }
  json sources = json::array();
  for (const SourceInfo& source : manifest.sources) {
    sources.push_back({{"path", source.path},
                       {"format", source.format},
                       {"columns", source.columns},
                       {"rows", source.rows},
                       {"stepDegrees", source.stepDegrees},
                       {"boundsDegrees", boundsToJson(source.bounds)},
                       {"finestLevel", source.finestLevel},
                       {"conditioning", conditioningToJson(source.conditioning)}});
    if (source.verticalUnits) {
      sources.back()["verticalUnits"] = verticalUnitsToJson(*source.verticalUnits);
    }
  }
  const json j = {
      {"format", "globe-pyramid"},
      {"formatVersion", 1},
      {"tilingScheme",
       {{"name", "geographic"},
        {"level0", "2x1 tiles of 180x180 degrees; x eastwards from -180, y southwards from +90"},
        {"vertexConvention",
         "vertex (i,j): lon = west + j*width/(N-1), lat = north - i*height/(N-1)"}}},
      {"blockSize", manifest.verticesPerSide},
      {"packTilesPerSide", manifest.packTilesPerSide},
      {"encoding",
       "GTOPO30 int16 big-endian metres: -9999 = water (sea, depth unknown), -32767..-20001 = "
       "water over a sea floor at sample+20000 m, other values = land"},
      {"noData", -9999},
      {"globeModel", std::string(geo::toString(manifest.globeModel))},
      {"maxLevel", manifest.maxLevel()},
      {"levels", levels},
      {"sources", sources}};
  return j.dump(1) + "\n";
}

Result<PyramidManifest> manifestFromJson(std::string_view text, const std::filesystem::path& path) {
  const json j = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return makeError(path.string() + ": not valid JSON");
  try {
    if (j.at("format").get<std::string>() != "globe-pyramid" ||
        integerOf<int>(j.at("formatVersion")) != 1) {
      return makeError(path.string() + ": not a globe pyramid manifest of format version 1");
    }
    PyramidManifest m;
    m.verticesPerSide = integerOf<uint32_t>(j.at("blockSize"));
    m.packTilesPerSide = integerOf<uint32_t>(j.at("packTilesPerSide"));
    if (!terrain::isValidBlockSize(m.verticesPerSide)) {
      return makeError(path.string() + ": blockSize " + std::to_string(m.verticesPerSide) +
                       " is not 2^k+1 (3..1025)");
    }
    if (m.packTilesPerSide == 0 || m.packTilesPerSide > 1024) {
      return makeError(path.string() + ": packTilesPerSide out of range");
    }
    const auto model = geo::parseGlobeModel(j.at("globeModel").get<std::string>());
    if (!model) return makeError(path.string() + ": unknown globeModel");
    m.globeModel = *model;
    for (const json& level : j.at("levels")) {
      LevelInfo info;
      info.level = integerOf<uint32_t>(level.at("level"));
      if (info.level != m.levels.size()) {
        return makeError(path.string() + ": levels must be listed 0, 1, 2, ... without gaps");
      }
      info.tileCount = integerOf<uint64_t>(level.at("tiles"));
      info.bounds = boundsFromJson(level.at("boundsDegrees"));
      info.heightRange = rangeFromJson(level.at("heightRangeMeters"));
      for (const json& pack : level.at("packs")) {
        info.packs.push_back(
            {info.level, integerOf<uint32_t>(pack.at(0)), integerOf<uint32_t>(pack.at(1))});
        // [x, y, index bytes] since pack format 5; [x, y] before.
        if (pack.size() >= 3) info.packIndexBytes.push_back(integerOf<uint32_t>(pack.at(2)));
      }
      if (!info.packIndexBytes.empty() && info.packIndexBytes.size() != info.packs.size()) {
        return makeError(path.string() + ": level " + std::to_string(info.level) +
                         " gives index sizes for some packs only");
      }
      m.levels.push_back(std::move(info));
    }
    if (m.levels.empty() || m.levels.size() > 31) {
      return makeError(path.string() + ": a pyramid needs between 1 and 31 levels");
    }
    for (const json& source : j.at("sources")) {
      m.sources.push_back(
          {source.at("path").get<std::string>(), source.at("format").get<std::string>(),
           integerOf<int64_t>(source.at("columns")), integerOf<int64_t>(source.at("rows")),
           source.at("stepDegrees").get<double>(), boundsFromJson(source.at("boundsDegrees")),
           integerOf<uint32_t>(source.at("finestLevel")), SourceConditioning{}});
      if (source.contains("conditioning")) {
        m.sources.back().conditioning = conditioningFromJson(source.at("conditioning"));
      }
      if (source.contains("verticalUnits")) {
        m.sources.back().verticalUnits = verticalUnitsFromJson(source.at("verticalUnits"));
      }
    }
    return m;
  } catch (const json::exception& e) {
    return makeError(path.string() + ": missing or malformed field (" + e.what() + ")");
  } catch (const FieldError& e) {
    return makeError(path.string() + ": malformed integer field (" + e.what() + ")");
  }
}

Result<PyramidManifest> readManifest(transport::ByteSource& source) {
  const std::string path = source.locationOf(kManifestFileName);
  auto bytes = source.readWhole(kManifestFileName, kMaxManifestFileBytes);
  if (!bytes) return Error{bytes.error()};
  if (!*bytes) {
    return makeError(path + ": cannot open: not found (is " + source.location() +
                     " a pyramid made by globe-tiler?)");
  }
  return manifestFromJson(
      std::string_view(reinterpret_cast<const char*>((*bytes)->data()), (*bytes)->size()), path);
}

Result<PyramidManifest> readManifest(const std::filesystem::path& pyramidDir) {
  return readManifest(*transport::localByteSource(pyramidDir));
}

const SourceInfo* finestSourceAt(const PyramidManifest& manifest, double longitudeDegrees,
                                 double latitudeDegrees) {
  const SourceInfo* finest = nullptr;
  for (const SourceInfo& source : manifest.sources) {
    const BoundsDegrees& b = source.bounds;
    // The longitude's turn that lands at or east of the source's west edge.
    const double lon = b.west + std::fmod(std::fmod(longitudeDegrees - b.west, 360.0) + 360.0, 360.0);
    const bool inside = lon <= b.east && latitudeDegrees >= b.south && latitudeDegrees <= b.north;
    if (inside && source.stepDegrees > 0 && (!finest || source.stepDegrees < finest->stepDegrees)) {
      finest = &source;
    }
  }
  return finest;
}

}  // namespace globe::formats
