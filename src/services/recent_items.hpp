// The few items a service reader used last (decoded source tiles, blocks, PMTiles leaf
// directories), kept so that the next tiles, which mostly need the same ones, do not read and
// decode them again. Least recently used goes first; thread-safe.
#pragma once

#include <cstddef>
#include <list>
#include <mutex>
#include <optional>
#include <utility>

namespace globe::services {

template <class Key, class Value>
class RecentItems {
 public:
  explicit RecentItems(size_t capacity) : capacity_(capacity) {}

  // The item (now the most recent), or nullopt when it is not kept.
  std::optional<Value> find(const Key& key) {
    std::lock_guard lock(mutex_);
    for (auto it = items_.begin(); it != items_.end(); ++it) {
      if (it->first == key) {
        items_.splice(items_.begin(), items_, it);
        return it->second;
      }
    }
    return std::nullopt;
  }

  // Keeps `value` as the most recent (replacing one under the same key), dropping the oldest
  // beyond the capacity.
  void put(const Key& key, Value value) {
    std::lock_guard lock(mutex_);
    items_.remove_if([&](const auto& item) { return item.first == key; });
    items_.emplace_front(key, std::move(value));
    if (items_.size() > capacity_) items_.pop_back();
  }

 private:
  const size_t capacity_;
  std::mutex mutex_;
  std::list<std::pair<Key, Value>> items_;
};

}  // namespace globe::services
