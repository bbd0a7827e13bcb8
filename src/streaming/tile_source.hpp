// Where a loader gets tiles of one kind of payload (height blocks, imagery tiles): a directory
// of packs today, a web server next. The loader, its cache and the residency rules are written
// once against this interface, so a new payload or a new source is one new class.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "geo/tile_id.hpp"

namespace globe::streaming {

template <class Payload>
class TileSource {
 public:
  virtual ~TileSource() = default;

  // The tile's payload, nullopt when the source has no such tile (beyond its coverage: not an
  // error, never retried), or an error naming the tile's file or URL. Called on worker threads:
  // implementations are thread-safe.
  virtual Result<std::optional<Payload>> load(const geo::TileId& tile) = 0;
  // Which of `candidates` (tiles the loader also wants) this source reads in the same request as
  // `first`, known without any I/O; empty when none (the default) or not known yet.
  virtual std::vector<geo::TileId> readableWith(const geo::TileId& first,
                                                std::span<const geo::TileId> candidates) {
    (void)first;
    (void)candidates;
    return {};
  }
  // Loads `first` and what readableWith chose for it together: one result per tile, in order.
  virtual std::vector<Result<std::optional<Payload>>> loadTogether(
      std::span<const geo::TileId> tiles) {
    std::vector<Result<std::optional<Payload>>> results;
    results.reserve(tiles.size());
    for (const geo::TileId& tile : tiles) results.push_back(load(tile));
    return results;
  }
  // The file or URL a tile comes from, for error messages.
  virtual std::string location(const geo::TileId& tile) const = 0;
  // Problems with a whole file or server (a damaged pack), each once since the last call, so a
  // viewer reports them once rather than per tile or per frame.
  virtual std::vector<std::string> takeNewSourceErrors() { return {}; }
  // Lets what failed be tried again (say, after the data was repaired).
  virtual void forgetSourceFailures() {}
};

// How many bytes a payload holds in memory, for the caches' budgets: specialise per payload.
template <class Payload>
struct PayloadBytes;

}  // namespace globe::streaming
