// The packs a store has open: each opened once (at most kMaxOpenPacks at a time, so a long flight
// never runs out of descriptors), a pack that failed to open remembered with its error and not
// retried, and the first error of each pack queued once for the viewer to report. Shared by the
// height-block and imagery stores. Thread-safe.
#pragma once

#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/result.hpp"
#include "formats/pack_format.hpp"
#include "transport/byte_source.hpp"

namespace globe::streaming {

// An open pack file (local or remote) and its parsed index. Holds its file, so a pack dropped
// from the open set stays readable while a reader still holds it.
template <class Index>
struct OpenPackFile {
  std::shared_ptr<const transport::ByteFile> file;
  Index index;
  // The pack's first bytes as read with its index: blocks that lie in them need no read.
  std::vector<std::byte> head;
  OpenPackFile(std::shared_ptr<const transport::ByteFile> opened, Index packIndex,
               std::vector<std::byte> firstBytes = {})
      : file(std::move(opened)), index(std::move(packIndex)), head(std::move(firstBytes)) {}
};

// Whether a manifest's levels (a pyramid's or a layer's: levels[l].packs, sorted) list the pack.
template <class Levels>
bool listsPack(const Levels& levels, const formats::PackId& id) {
  if (id.level >= levels.size()) return false;
  const auto& packs = levels[id.level].packs;
  return std::binary_search(packs.begin(), packs.end(), id);
}

template <class Pack>
class OpenPacks {
 public:
  static constexpr size_t kMaxOpenPacks = 256;
  using Opened = Result<std::shared_ptr<const Pack>>;

  // The pack if open; its remembered error if it failed before; else open(id), whose failure is
  // remembered and queued for reporting. open runs without the lock (over a network it takes a
  // round trip: other packs open meanwhile); a second caller for the same pack waits for it.
  // *openedNowFailed is set when this call's open failed.
  template <class Open>
  Opened get(const formats::PackId& id, Open&& open, bool* openedNowFailed = nullptr) {
    std::unique_lock lock(mutex_);
    opened_.wait(lock, [&] { return !opening_.contains(id); });
    if (auto it = open_.find(id); it != open_.end()) return it->second;
    if (auto it = failed_.find(id); it != failed_.end()) return makeError(it->second);
    opening_.insert(id);
    lock.unlock();
    Opened opened = open(id);
    lock.lock();
    opening_.erase(id);
    opened_.notify_all();
    if (!opened) {
      failed_.emplace(id, opened.error());
      note(id, opened.error());
      if (openedNowFailed != nullptr) *openedNowFailed = true;
      return opened;
    }
    if (open_.size() >= kMaxOpenPacks) open_.clear();
    open_.emplace(id, *opened);
    return opened;
  }

  // Without opening anything: the pack if open, its error if it failed, nullopt if not tried yet.
  std::optional<Opened> peek(const formats::PackId& id) {
    std::lock_guard lock(mutex_);
    if (auto it = open_.find(id); it != open_.end()) return Opened(it->second);
    if (auto it = failed_.find(id); it != failed_.end()) return Opened(makeError(it->second));
    return std::nullopt;
  }

  // Queues a pack's error (a read that failed after it opened), once per pack.
  void noteError(const formats::PackId& id, const std::string& message) {
    std::lock_guard lock(mutex_);
    note(id, message);
  }
  std::vector<std::string> takeNewErrors() {
    std::lock_guard lock(mutex_);
    return std::exchange(newErrors_, {});
  }
  // A pack that failed is opened afresh next time (a repair usually renames a new file in), and
  // reported again should it still fail.
  void forgetFailures() {
    std::lock_guard lock(mutex_);
    for (const formats::PackId& id : reported_) open_.erase(id);
    failed_.clear();
    reported_.clear();
  }

 private:
  void note(const formats::PackId& id, const std::string& message) {
    if (reported_.insert(id).second) newErrors_.push_back(message);
  }

  std::mutex mutex_;
  std::condition_variable opened_;
  std::set<formats::PackId> opening_;  // being opened by some thread
  std::map<formats::PackId, std::shared_ptr<const Pack>> open_;
  std::map<formats::PackId, std::string> failed_;  // open failed: the error, not retried
  std::set<formats::PackId> reported_;             // packs whose error was queued for reporting
  std::vector<std::string> newErrors_;
};

}  // namespace globe::streaming
