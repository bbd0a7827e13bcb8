#include "tiles3d/tileset_stream.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <mutex>

namespace globe::tiles3d {
namespace {

// Numbers for drawn contents, unique across every stream of the process.
std::atomic<uint64_t> nextContentId{1};

}  // namespace

// The hand-off from load tasks to the frame's thread. Tasks hold it by shared_ptr: one that
// finishes after its stream is gone finds it closed and drops its result.
struct TilesetStream::Inbox {
  struct Arrival {
    uint32_t tile;
    std::vector<std::shared_ptr<const LoadedContent>> contents;
    std::string error;  // empty when every content loaded
  };
  std::mutex mutex;
  std::condition_variable arrived;
  bool closed = false;
  std::vector<Arrival> done;

  void put(Arrival arrival) {
    {
      std::lock_guard lock(mutex);
      if (closed) return;
      done.push_back(std::move(arrival));
    }
    arrived.notify_all();
  }
};

TilesetStream::TilesetStream(std::shared_ptr<const Tileset> tileset,
                             const geo::Ellipsoid& ellipsoid, core::TaskRunner& runner,
                             size_t budgetBytes)
    : tileset_(std::move(tileset)),
      ellipsoid_(ellipsoid),
      runner_(runner),
      budgetBytes_(budgetBytes),
      inbox_(std::make_shared<Inbox>()),
      tiles_(flattenTileset(*tileset_)) {
  states_.resize(tiles_.size(), ContentState::Missing);
  loading_.resize(tiles_.size(), false);
  resident_.resize(tiles_.size());
  for (size_t t = 0; t < tiles_.size(); ++t) {
    if (tiles_[t].node->contents.empty()) states_[t] = ContentState::Ready;
  }
}

TilesetStream::~TilesetStream() {
  std::lock_guard lock(inbox_->mutex);
  inbox_->closed = true;
}

void TilesetStream::waitForLoads(std::chrono::milliseconds timeout) const {
  std::unique_lock lock(inbox_->mutex);
  inbox_->arrived.wait_for(lock, timeout, [&] { return !inbox_->done.empty(); });
}

StreamFrame TilesetStream::update(const TileSelectionView& view) {
  ++frame_;
  StreamFrame frame;
  collect(frame);
  const TileChoice choice = selectTiles(tiles_, states_, view);
  drawn_.clear();
  std::vector<std::shared_ptr<const LoadedContent>> contents;
  for (const uint32_t t : choice.drawn) {
    resident_[t]->lastDrawnFrame = frame_;
    for (const DrawnItem& item : resident_[t]->contents) {
      drawn_.push_back(item);
      contents.push_back(item.content);
    }
  }
  surface_ = std::make_shared<const DrawnSurface>(std::move(contents));
  startLoads(choice.wanted, frame);
  evict(frame);
  frame.drawnTiles = choice.drawn.size();
  frame.wanted = choice.wanted.size();
  frame.loading = loadsInFlight_;
  frame.complete = choice.complete();
  return frame;
}

void TilesetStream::collect(StreamFrame& frame) {
  std::vector<Inbox::Arrival> done;
  {
    std::lock_guard lock(inbox_->mutex);
    done.swap(inbox_->done);
  }
  for (Inbox::Arrival& a : done) {
    loading_[a.tile] = false;
    --loadsInFlight_;
    if (!a.error.empty()) {
      states_[a.tile] = ContentState::Failed;
      frame.warnings.push_back(a.error + " (drawn coarser there)");
      continue;
    }
    auto resident = std::make_unique<Resident>();
    for (auto& content : a.contents) {
      resident->bytes += content->sizeBytes();
      resident->contents.push_back({nextContentId.fetch_add(1), std::move(content)});
    }
    resident->lastDrawnFrame = frame_;
    residentBytes_ += resident->bytes;
    resident_[a.tile] = std::move(resident);
    states_[a.tile] = ContentState::Ready;
    ++frame.arrived;
  }
}

void TilesetStream::startLoads(const std::vector<TileWish>& wanted, StreamFrame& frame) {
  (void)frame;
  std::vector<TileWish> order(wanted);
  std::stable_sort(order.begin(), order.end(),
                   [](const TileWish& a, const TileWish& b) { return a.priority > b.priority; });
  for (const TileWish& wish : order) {
    if (loadsInFlight_ >= kMaxLoadsInFlight) break;
    if (loading_[wish.tile] || states_[wish.tile] != ContentState::Missing) continue;
    loading_[wish.tile] = true;
    ++loadsInFlight_;
    runner_.post([inbox = inbox_, tileset = tileset_, node = tiles_[wish.tile].node,
                  ellipsoid = ellipsoid_, tile = wish.tile] {
      Inbox::Arrival arrival{tile, {}, {}};
      for (const std::string& name : node->contents) {
        auto content = loadTileContent(*tileset, *node, name, ellipsoid);
        if (!content) {
          arrival.error = content.error();
          arrival.contents.clear();
          break;
        }
        arrival.contents.push_back(std::make_shared<const LoadedContent>(std::move(*content)));
      }
      inbox->put(std::move(arrival));
    });
  }
}

// Over the budget, the contents drawn longest ago go first; none drawn this frame.
void TilesetStream::evict(StreamFrame& frame) {
  if (residentBytes_ <= budgetBytes_) return;
  std::vector<uint32_t> candidates;
  for (uint32_t t = 0; t < resident_.size(); ++t) {
    if (resident_[t] && resident_[t]->lastDrawnFrame < frame_) candidates.push_back(t);
  }
  std::sort(candidates.begin(), candidates.end(), [&](uint32_t a, uint32_t b) {
    return resident_[a]->lastDrawnFrame < resident_[b]->lastDrawnFrame;
  });
  for (const uint32_t t : candidates) {
    if (residentBytes_ <= budgetBytes_) break;
    residentBytes_ -= resident_[t]->bytes;
    resident_[t].reset();
    states_[t] = ContentState::Missing;
    ++frame.evicted;
  }
}

}  // namespace globe::tiles3d
