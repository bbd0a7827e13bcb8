#include "scene/tile_morphs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "geo/tiling_scheme.hpp"
#include "terrain/morphed_block.hpp"
#include "terrain/upsampled_block.hpp"

namespace globe::scene {
namespace {

// Deeper jumps than this start no morph: the ancestor's surface says little about such a tile.
constexpr uint32_t kMaximumMorphLevels = 6;
constexpr double kMeanEarthRadiusMeters = 6371008.8;

// Distance in radians from a to the interval [low, high] of longitudes, the short way round.
double longitudeGapRadians(double a, double low, double high) {
  if (a >= low && a <= high) return 0.0;
  auto around = [](double d) {
    d = std::fmod(std::abs(d), 2 * std::numbers::pi);
    return std::min(d, 2 * std::numbers::pi - d);
  };
  return std::min(around(a - low), around(a - high));
}

}  // namespace

bool TileMorphs::isNear(const geo::TileId& tile, double longitudeRadians, double latitudeRadians,
                        double radiusMeters) {
  const geo::GlobeRectangle r = geo::GeographicTilingScheme::tileRectangle(tile);
  const double nearestLatitude = std::clamp(latitudeRadians, r.southRadians, r.northRadians);
  const double dLatitude = latitudeRadians - nearestLatitude;
  const double dLongitude = longitudeGapRadians(longitudeRadians, r.westRadians, r.eastRadians) *
                            std::cos(nearestLatitude);
  return std::hypot(dLatitude, dLongitude) * kMeanEarthRadiusMeters <= radiusMeters;
}

std::shared_ptr<const terrain::HeightBlock> TileMorphs::previousSurface(
    const geo::TileId& tile) const {
  std::vector<geo::TileId> path{tile};  // tile, its parent, ... up to the drawn ancestor
  for (uint32_t k = 0; k < kMaximumMorphLevels && path.back().level > 0; ++k) {
    path.push_back(path.back().parent());
    const auto drawn = previous_.find(path.back());
    if (drawn == previous_.end()) continue;
    std::shared_ptr<const terrain::HeightBlock> surface = drawn->second;
    for (size_t i = path.size() - 1; i-- > 0;) {
      surface = std::make_shared<const terrain::HeightBlock>(
          terrain::upsampleBlock(*surface, path[i], ellipsoid_));
    }
    return surface;
  }
  return nullptr;
}

TileMorphs::Choice TileMorphs::advance(const geo::TileId& tile, Morph& morph,
                                       const std::shared_ptr<const terrain::HeightBlock>& loaded,
                                       bool drawn) {
  morph.lastFrame = frame_;
  if (++morph.step >= frames_) {
    morphs_.erase(tile);
    // The GPU's mesh is the last morph's: replaced by the block's own.
    return {loaded, drawn && morphMeshes_.erase(tile) > 0};
  }
  const double fraction = static_cast<double>(morph.step) / frames_;
  if (drawn) morphMeshes_.insert(tile);
  return {std::make_shared<const terrain::HeightBlock>(
              terrain::morphBlock(*morph.from, *loaded, fraction)),
          drawn};
}

TileMorphs::Choice TileMorphs::blockFor(const geo::TileId& tile,
                                        std::shared_ptr<const terrain::HeightBlock> loaded,
                                        bool nearCamera, bool drawn) {
  std::optional<Choice> choice;
  if (auto it = morphs_.find(tile); it != morphs_.end()) {
    choice = advance(tile, it->second, loaded, drawn);
  } else if (frames_ > 1 && nearCamera && !previous_.contains(tile) && !loaded->tin) {
    // (A TIN tile is drawn as its producer made it: its triangles are not its parent's grid.)
    if (auto from = previousSurface(tile); from && from->heights.size() == loaded->heights.size()) {
      choice = advance(tile, morphs_[tile] = Morph{std::move(from), 0, frame_}, loaded, drawn);
    }
  }
  // Drawn as loaded: a morph's mesh left on the GPU is replaced.
  if (!choice) choice = Choice{loaded, drawn && morphMeshes_.erase(tile) > 0};
  current_[tile] = choice->block;
  if (drawn) drawnNow_.insert(tile);
  return *choice;
}

std::vector<geo::TileId> TileMorphs::endFrame() {
  for (auto it = morphs_.begin(); it != morphs_.end();) {
    it = frame_ - it->second.lastFrame >= frames_ ? morphs_.erase(it) : std::next(it);
  }
  std::vector<geo::TileId> stale;
  for (auto it = morphMeshes_.begin(); it != morphMeshes_.end();) {
    if (drawnNow_.contains(*it) || morphs_.contains(*it)) {
      ++it;
      continue;
    }
    stale.push_back(*it);
    it = morphMeshes_.erase(it);
  }
  previous_.swap(current_);
  current_.clear();
  drawnNow_.clear();
  ++frame_;
  return stale;
}

}  // namespace globe::scene
