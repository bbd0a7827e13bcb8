#include "services/service_terrain.hpp"

#include <algorithm>
#include <cmath>

#include "geo/tiling_scheme.hpp"
#include "terrain/upsampled_block.hpp"

namespace globe::services {
namespace {

constexpr size_t kRangeEntries = 1u << 16;
// Bounds of the Earth's surface for a tile nothing is known of yet (Dead Sea to Everest, and
// the service's sea floor should it have one).
constexpr terrain::HeightRange kUnknownRange{-11000, 8900};

int16_t landCode(double heightMeters) {
  return static_cast<int16_t>(
      std::clamp(std::lround(heightMeters), long{terrain::kLowestLandMeters}, long{32767}));
}

// A block of nothing but sea of unknown depth: where a service has no data.
bool isEmptySea(const terrain::HeightBlock& block) {
  auto unknownSea = [](int16_t sample) { return sample == terrain::kNoDataHeight; };
  return std::all_of(block.heights.begin(), block.heights.end(), unknownSea) &&
         std::all_of(block.apron.begin(), block.apron.end(), unknownSea);
}

}  // namespace

ServiceTerrainSource::ServiceTerrainSource(const ServiceDescription& d, terrain::SeaSurface sea)
    : location_(d.location),
      attribution_(d.attribution),
      remote_(d.remote),
      sea_(sea),
      ellipsoid_(geo::ellipsoidFor(geo::GlobeModel::Wgs84)) {
  manifest_.verticesPerSide = kServiceVerticesPerSide;
  manifest_.globeModel = geo::GlobeModel::Wgs84;
  for (uint32_t level = 0; level <= d.maxLevel; ++level) {
    formats::LevelInfo info;
    info.level = level;
    info.bounds = d.bounds;
    info.heightRange = kUnknownRange;
    manifest_.levels.push_back(info);
  }
  formats::SourceInfo source;
  source.path = d.location;
  source.format = d.format;
  source.stepDegrees = d.stepDegrees;
  source.bounds = d.bounds;
  source.finestLevel = d.maxLevel;
  manifest_.sources.push_back(source);
}

bool ServiceTerrainSource::exists(const geo::TileId& tile) const {
  if (!geo::GeographicTilingScheme::isValid(tile) || tile.level > manifest_.maxLevel()) {
    return false;
  }
  if (tile.level == 0) return true;
  // A tile has all four children or none: siblings the service lacks are made from the parent.
  for (const geo::TileId& sibling : tile.parent().children())
    if (publishes(sibling)) return true;
  return false;
}

std::optional<terrain::HeightRange> ServiceTerrainSource::knownRange(
    const geo::TileId& tile) const {
  std::lock_guard lock(mutex_);
  geo::TileId t = tile;
  for (;;) {
    if (auto it = ranges_.find(t); it != ranges_.end()) {
      if (t == tile) return it->second;
      // A finer tile's samples reach further than its ancestor's: widened by a margin.
      const int span = it->second.maximumMeters - it->second.minimumMeters;
      const int margin = 30 + span / 4;
      return terrain::HeightRange{
          static_cast<int16_t>(std::max(-12767, it->second.minimumMeters - margin)),
          static_cast<int16_t>(std::min(32767, it->second.maximumMeters + margin))};
    }
    if (t.level == 0) return std::nullopt;
    t = t.parent();
  }
}

streaming::TerrainSource::Peek ServiceTerrainSource::peek(const geo::TileId& tile,
                                                          terrain::TileSummary* summary) {
  if (!exists(tile)) return Peek::Absent;
  summary->subtreeHeightRange = knownRange(tile).value_or(kUnknownRange);
  summary->measuredGeometricErrorMeters = std::numeric_limits<double>::quiet_NaN();
  return Peek::Present;
}

Result<std::optional<terrain::TileSummary>> ServiceTerrainSource::summary(const geo::TileId& tile) {
  terrain::TileSummary s;
  if (peek(tile, &s) == Peek::Absent) return std::optional<terrain::TileSummary>();
  return std::optional<terrain::TileSummary>(s);
}

terrain::HeightBlock ServiceTerrainSource::assemble(const ServiceSamples& samples) const {
  const uint32_t n = kServiceVerticesPerSide;
  const int w = terrain::kApronWidth;
  const auto side = static_cast<int>(ServiceSamples::side());
  terrain::HeightBlock block;
  block.verticesPerSide = n;
  block.sea = sea_;
  block.heights.resize(size_t{n} * n);
  block.apron.resize(terrain::apronSampleCount(n));
  block.exactSurfaceMeters.resize(size_t{n} * n);
  block.exactApronSurfaceMeters.resize(block.apron.size());
  for (int row = -w; row < static_cast<int>(n) + w; ++row) {
    for (int column = -w; column < static_cast<int>(n) + w; ++column) {
      const size_t k = static_cast<size_t>((row + w) * side + column + w);
      const double h = samples.heightMeters[k];
      const bool water = !samples.water.empty() && samples.water[k] != 0;
      const int16_t code = water ? terrain::encodeWater(h) : landCode(h);
      // Land keeps its exact height (a service's centimetres); water its surface as asked.
      const double surface = water ? terrain::surfaceHeightMeters(code, sea_) : h;
      const bool inside =
          row >= 0 && row < static_cast<int>(n) && column >= 0 && column < static_cast<int>(n);
      if (inside) {
        const size_t b = static_cast<size_t>(row) * n + static_cast<size_t>(column);
        block.heights[b] = code;
        block.exactSurfaceMeters[b] = surface;
      } else {
        const size_t a = terrain::apronIndex(row, column, n);
        block.apron[a] = code;
        block.exactApronSurfaceMeters[a] = surface;
      }
    }
  }
  if (samples.normals.size() == size_t{n} * n) {
    block.shadingNormals = samples.normals;
    block.colorMeters.resize(block.heights.size());
    block.waterFraction.resize(block.heights.size());
    for (size_t b = 0; b < block.heights.size(); ++b) {
      block.colorMeters[b] = static_cast<float>(terrain::seaFloorMeters(block.heights[b]));
      block.waterFraction[b] = terrain::isWater(block.heights[b]) ? 1.0f : 0.0f;
    }
  }
  return block;
}

void ServiceTerrainSource::remember(const geo::TileId& tile, const terrain::HeightBlock& block) {
  std::lock_guard lock(mutex_);
  if (ranges_.size() >= kRangeEntries) ranges_.clear();
  ranges_[tile] = terrain::surfaceHeightRange(block);
  recent_.put(tile, std::make_shared<const terrain::HeightBlock>(block));
}

Result<terrain::HeightBlock> ServiceTerrainSource::loadBlock(const geo::TileId& tile) {
  if (auto kept = recent_.find(tile)) return **kept;
  if (!exists(tile)) return makeError(location_ + ": the service has no " + geo::tileName(tile));
  std::optional<ServiceSamples> samples;
  if (publishes(tile)) {
    auto fetched = fetchSamples(tile);
    if (!fetched) return Error{fetched.error()};
    samples = std::move(*fetched);
    if (samples) ++fetched_;
  }
  terrain::HeightBlock block;
  const bool gaps =
      samples && std::any_of(samples->heightMeters.begin(), samples->heightMeters.end(),
                             [](double h) { return std::isnan(h); });
  if (gaps) {
    auto filled = fillFromParent(tile, *samples);
    if (!filled) return Error{filled.error()};
  }
  if (samples) {
    block = assemble(*samples);
    block.tin = samples->tin;
  } else {
    std::optional<terrain::HeightBlock> parent;
    if (tile.level > 0) {
      auto loaded = loadBlock(tile.parent());
      if (!loaded) return Error{loaded.error()};
      parent = std::move(*loaded);
    }
    if (!parent || isEmptySea(*parent)) {
      // Nothing there at all: the sea surface, as a pyramid without data there reads (not the
      // parent's chords, which sag below it at coarse levels).
      ServiceSamples flat;
      flat.heightMeters.assign(ServiceSamples::count(), 0.0);
      flat.water.assign(ServiceSamples::count(), 1);
      block = assemble(flat);
    } else {
      block = terrain::upsampleBlock(*parent, tile, ellipsoid_);
      ++fromParent_;
    }
  }
  remember(tile, block);
  return block;
}

Result<void> ServiceTerrainSource::fillFromParent(const geo::TileId& tile,
                                                  ServiceSamples& samples) {
  std::optional<terrain::HeightBlock> parent;
  if (tile.level > 0) {
    auto loaded = loadBlock(tile.parent());
    if (!loaded) return Error{loaded.error()};
    if (!isEmptySea(*loaded)) parent = terrain::upsampleBlock(*loaded, tile, ellipsoid_);
  }
  const int n = static_cast<int>(kServiceVerticesPerSide);
  const int w = terrain::kApronWidth;
  size_t k = 0;
  for (int row = -w; row < n + w; ++row) {
    for (int column = -w; column < n + w; ++column, ++k) {
      if (!std::isnan(samples.heightMeters[k])) continue;
      // The parent's ground there, or the sea at 0 m where no level has anything.
      const int16_t code = parent ? parent->atWithApron(row, column) : terrain::kNoDataHeight;
      const bool water = terrain::isWater(code);
      samples.heightMeters[k] = !parent ? 0.0
                                : water ? terrain::seaFloorMeters(code)
                                        : parent->surfaceHeightMetersWithApron(row, column);
      if (water) {
        if (samples.water.empty()) samples.water.assign(ServiceSamples::count(), 0);
        samples.water[k] = 1;
      } else if (!samples.water.empty()) {
        samples.water[k] = 0;
      }
    }
  }
  return {};
}

Result<std::optional<terrain::HeightBlock>> ServiceTerrainSource::load(const geo::TileId& tile) {
  if (!exists(tile)) return std::optional<terrain::HeightBlock>();
  auto block = loadBlock(tile);
  if (!block) return Error{block.error()};
  return std::optional<terrain::HeightBlock>(std::move(*block));
}

void ServiceTerrainSource::noteServiceError(const std::string& message) {
  std::lock_guard lock(mutex_);
  if (std::find(reportedErrors_.begin(), reportedErrors_.end(), message) != reportedErrors_.end())
    return;
  reportedErrors_.push_back(message);
  newErrors_.push_back(message);
}

std::vector<std::string> ServiceTerrainSource::takeNewSourceErrors() {
  std::lock_guard lock(mutex_);
  return std::exchange(newErrors_, {});
}

}  // namespace globe::services
