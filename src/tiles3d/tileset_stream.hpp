// A tileset streamed for a moving view: each frame selects the tiles to draw
// (tileset_selection.hpp), loads the contents wanted on the injected task runner (the scene's
// loader threads: read through the tileset's byte source, so from a folder or any static
// server with the disk cache, decoded and rasterised into height grids there: no frame waits on
// collision data), and drops contents not drawn for a while once their bytes pass the budget.
// A content that fails is said once (a warning naming it) and its parent is drawn there.
// update(), drawn(), surface() and the counters are for one thread (the frame's).
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/task_runner.hpp"
#include "geo/ellipsoid.hpp"
#include "tiles3d/drawn_surface.hpp"
#include "tiles3d/loaded_content.hpp"
#include "tiles3d/tileset.hpp"
#include "tiles3d/tileset_selection.hpp"

namespace globe::tiles3d {

struct StreamFrame {
  size_t drawnTiles = 0, wanted = 0, loading = 0, arrived = 0, evicted = 0;
  bool complete = false;              // nothing this view wants is missing
  std::vector<std::string> warnings;  // contents that failed since the last frame, each once
};

// A drawn content and a number of its own: a content dropped and loaded again gets a new one.
struct DrawnItem {
  uint64_t id = 0;
  std::shared_ptr<const LoadedContent> content;
};

class TilesetStream {
 public:
  static constexpr size_t kDefaultBudgetBytes = size_t{512} << 20;
  static constexpr size_t kMaxLoadsInFlight = 4;

  TilesetStream(std::shared_ptr<const Tileset> tileset, const geo::Ellipsoid& ellipsoid,
                core::TaskRunner& runner, size_t budgetBytes = kDefaultBudgetBytes);
  ~TilesetStream();
  TilesetStream(const TilesetStream&) = delete;
  TilesetStream& operator=(const TilesetStream&) = delete;

  StreamFrame update(const TileSelectionView& view);
  // What the last update() drew, and the same contents' surface for collision.
  const std::vector<DrawnItem>& drawn() const { return drawn_; }
  std::shared_ptr<const DrawnSurface> surface() const { return surface_; }
  // Blocks until a load finishes or the timeout passes.
  void waitForLoads(std::chrono::milliseconds timeout) const;
  size_t residentBytes() const { return residentBytes_; }
  const Tileset& tileset() const { return *tileset_; }

 private:
  struct Inbox;
  struct Resident {
    std::vector<DrawnItem> contents;
    size_t bytes = 0;
    uint64_t lastDrawnFrame = 0;
  };
  void collect(StreamFrame& frame);
  void startLoads(const std::vector<TileWish>& wanted, StreamFrame& frame);
  void evict(StreamFrame& frame);

  std::shared_ptr<const Tileset> tileset_;
  geo::Ellipsoid ellipsoid_;
  core::TaskRunner& runner_;
  size_t budgetBytes_;
  std::shared_ptr<Inbox> inbox_;
  std::vector<FlatTile> tiles_;
  std::vector<ContentState> states_;
  std::vector<bool> loading_;
  std::vector<std::unique_ptr<Resident>> resident_;  // per tile, null when not loaded
  size_t residentBytes_ = 0, loadsInFlight_ = 0;
  uint64_t frame_ = 0;
  std::vector<DrawnItem> drawn_;
  std::shared_ptr<const DrawnSurface> surface_ = std::make_shared<DrawnSurface>();
};

}  // namespace globe::tiles3d
