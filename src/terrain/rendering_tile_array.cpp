// Building the rendering tile array's index, and its linear and indexed tile lookups.
#include "terrain/rendering_tile_array.hpp"

#include <bit>
#include <optional>

#include "geo/tiling_scheme.hpp"
#include "terrain/tile_containment.hpp"

namespace globe::terrain {

namespace {

using Scheme = geo::GeographicTilingScheme;

bool isUsable(const ArrayTile& tile) {
  if (!Scheme::isValid(tile.id) || !hasReadableBlock(tile)) return false;
  if (!terrain::isValidBlockSize(tile.block->verticesPerSide)) return false;
  const geo::GlobeRectangle rectangle = Scheme::tileRectangle(tile.id);
  return tile.westRadians == rectangle.westRadians && tile.southRadians == rectangle.southRadians &&
         tile.eastRadians == rectangle.eastRadians && tile.northRadians == rectangle.northRadians;
}

// Keeps the candidate with the highest selectionKey.
struct BestTile {
  const ArrayTile* tile = nullptr;
  uint64_t key = 0;

  void consider(const ArrayTile* candidate, const QueryPoint& point) {
    if (candidate == nullptr || !containsClosed(*candidate, point)) return;
    const uint64_t candidateKey = selectionKey(*candidate, point);
    if (tile == nullptr || candidateKey > key) tile = candidate, key = candidateKey;
  }
};

// A unique key per valid tile: the tiles of all coarser levels, then row-major (< 2^62).
uint64_t quadtreeKey(const geo::TileId& id) {
  const uint64_t tilesBefore = ((uint64_t{1} << (2 * id.level)) - 1) / 3 * 2;
  return tilesBefore + (uint64_t{id.y} << (id.level + 1)) + id.x;
}

// splitmix64's finaliser: consecutive keys land far apart.
uint64_t mix(uint64_t key) {
  key = (key ^ (key >> 30)) * 0xbf58476d1ce4e5b9ULL;
  key = (key ^ (key >> 27)) * 0x94d049bb133111ebULL;
  return key ^ (key >> 31);
}

}  // namespace

ArrayTile makeArrayTile(const geo::TileId& id, const HeightBlock& block) {
  const geo::GlobeRectangle rectangle = Scheme::tileRectangle(id);
  return {id,
          rectangle.westRadians,
          rectangle.southRadians,
          rectangle.eastRadians,
          rectangle.northRadians,
          &block,
          terrain::surfaceHeightRange(block).maximumMeters};
}

void RenderingTileArray::assign(std::vector<ArrayTile> tiles) {
  tiles_.clear();
  levels_.clear();
  northPoleTiles_.fill(kNoTile);
  southPoleTiles_.fill(kNoTile);
  rejected_ = 0;
  tiles_.reserve(tiles.size());
  const size_t capacity = std::bit_ceil(tiles.size() + tiles.size() / 2 + 1);
  slots_.assign(capacity, Slot{});
  slotMask_ = capacity - 1;
  for (const ArrayTile& tile : tiles) {
    if (!isUsable(tile) || !insertPosition(tile.id, static_cast<uint32_t>(tiles_.size()))) {
      ++rejected_;
      continue;
    }
    tiles_.push_back(tile);
  }
  std::array<bool, geo::kMaxLevel + 1> present{};
  for (uint32_t position = 0; position < tiles_.size(); ++position) {
    const geo::TileId& id = tiles_[position].id;
    present[id.level] = true;
    auto keepWesternmost = [&](uint32_t& slot) {
      if (slot == kNoTile || id.x < tiles_[slot].id.x) slot = position;
    };
    if (id.y == 0) keepWesternmost(northPoleTiles_[id.level]);
    if (id.y + 1 == Scheme::tilesY(id.level)) keepWesternmost(southPoleTiles_[id.level]);
  }
  for (uint32_t level = geo::kMaxLevel + 1; level-- > 0;) {
    if (present[level]) levels_.push_back(level);
  }
}

bool RenderingTileArray::insertPosition(const geo::TileId& id, uint32_t position) {
  const uint64_t key = quadtreeKey(id);
  for (uint64_t slot = mix(key) & slotMask_;; slot = (slot + 1) & slotMask_) {
    if (slots_[slot].key == key) return false;
    if (slots_[slot].key == kEmptyKey) {
      slots_[slot] = {key, position};
      return true;
    }
  }
}

uint32_t RenderingTileArray::findPosition(const geo::TileId& id) const {
  if (slots_.empty() || !Scheme::isValid(id)) return kNoTile;
  const uint64_t key = quadtreeKey(id);
  for (uint64_t slot = mix(key) & slotMask_;; slot = (slot + 1) & slotMask_) {
    if (slots_[slot].key == key) return slots_[slot].position;
    if (slots_[slot].key == kEmptyKey) return kNoTile;
  }
}

const ArrayTile* RenderingTileArray::find(const geo::TileId& id) const {
  return at(findPosition(id));
}

size_t RenderingTileArray::indexMemoryBytes() const { return slots_.capacity() * sizeof(Slot); }

TileLookup RenderingTileArray::lookupLinear(double longitudeRadians, double latitudeRadians) const {
  const std::optional<QueryPoint> point = makeQueryPoint(longitudeRadians, latitudeRadians);
  if (!point) return {};
  BestTile best;
  const double lat = point->latitudeRadians;
  for (const ArrayTile& tile : tiles_) {
    // containsClosed's latitude test, inline: it rejects most tiles without a call (a pole's
    // latitude passes it exactly for the tiles of the polar row).
    if (lat < tile.southRadians || lat > tile.northRadians) continue;
    best.consider(&tile, *point);
  }
  return {best.tile, static_cast<uint32_t>(tiles_.size())};
}

TileLookup RenderingTileArray::lookupIndexed(double longitudeRadians,
                                             double latitudeRadians) const {
  const std::optional<QueryPoint> point = makeQueryPoint(longitudeRadians, latitudeRadians);
  if (!point) return {};
  return lookupIndexed(*point);
}

TileLookup RenderingTileArray::lookupIndexed(const QueryPoint& point) const {
  if (levels_.empty()) return {};
  // The tile owning the point (the scheme's half-open rule) at the finest level present; the
  // owner at a coarser level is its ancestor, since edges are identical across levels.
  const uint32_t finest = levels_.front();
  const std::optional<geo::TileId> finestOwner =
      Scheme::positionToTile(point.longitudeRadians, point.latitudeRadians, finest);
  if (!finestOwner) return {};  // unreachable for a canonical point
  const ArrayTile* finestOwnerTile = find(*finestOwner);
  // The common case: the finest owner is present and the point is neither a pole nor on the
  // owner's west or north edge (its bounds are tileRectangle(owner)), so no other tile contains
  // it at this level and no coarser tile can win: the search below would return the owner too.
  if (finestOwnerTile != nullptr && point.pole == Pole::None &&
      point.longitudeRadians != finestOwnerTile->westRadians &&
      point.latitudeRadians != finestOwnerTile->northRadians) {
    return {finestOwnerTile, 1};
  }
  return lookupAcrossLevels(point, *finestOwner, finestOwnerTile);
}

// Out of line, so that the common case above keeps a small frame.
[[gnu::noinline]] TileLookup RenderingTileArray::lookupAcrossLevels(
    const QueryPoint& point, const geo::TileId& finestOwner,
    const ArrayTile* finestOwnerTile) const {
  const double lon = point.longitudeRadians;
  const double lat = point.latitudeRadians;
  const uint32_t finest = finestOwner.level;
  uint32_t probes = 1;  // the finest owner's
  auto probe = [&](uint32_t level, uint32_t x, uint32_t y) {
    ++probes;
    return find(geo::TileId{level, x, y});
  };
  // A point owned by a tile lies on its west or north edge, never on its east or south one; an
  // edge of a coarser owner is an edge of the finer owners inside it.
  const geo::GlobeRectangle finestRectangle = Scheme::tileRectangle(finestOwner);
  const bool onWestEdge = lon == finestRectangle.westRadians;
  const bool onNorthEdge = lat == finestRectangle.northRadians;

  for (const uint32_t level : levels_) {
    const uint32_t shift = finest - level;
    const geo::TileId owner{level, finestOwner.x >> shift, finestOwner.y >> shift};
    BestTile best;
    best.consider(level == finest ? finestOwnerTile : probe(level, owner.x, owner.y), point);
    if (point.pole != Pole::None) {
      // Every tile of the polar row contains the pole: the owner, else the westernmost.
      best.consider(at(point.pole == Pole::North ? northPoleTiles_[level] : southPoleTiles_[level]),
                    point);
    } else if (onWestEdge || onNorthEdge) {
      // On an edge the neighbours sharing it contain the point too (across +-180 deg as well).
      const geo::GlobeRectangle rectangle = Scheme::tileRectangle(owner);
      const bool west = onWestEdge && lon == rectangle.westRadians;
      const bool north = onNorthEdge && lat == rectangle.northRadians && owner.y > 0;
      const uint32_t westX = owner.x > 0 ? owner.x - 1 : Scheme::tilesX(level) - 1;
      if (west) best.consider(probe(level, westX, owner.y), point);
      if (north) best.consider(probe(level, owner.x, owner.y - 1), point);
      if (west && north) best.consider(probe(level, westX, owner.y - 1), point);
    }
    if (best.tile != nullptr) return {best.tile, probes};
  }
  return {nullptr, probes};
}

}  // namespace globe::terrain
