#include "imagery_tiling/reader_cache.hpp"

#include <sys/resource.h>

#include <algorithm>

namespace globe::imagery_tiling {

ReaderCache::ReaderCache(const std::vector<ImageryInput>& inputs, size_t capacity)
    : inputs_(inputs),
      capacity_(std::max<size_t>(capacity, 1)),
      readers_(inputs.size()),
      where_(inputs.size()) {}

Result<ImageryReader*> ReaderCache::get(size_t input) {
  if (readers_[input]) {
    open_.splice(open_.end(), open_, where_[input]);
    return readers_[input].get();
  }
  if (open_.size() >= capacity_) {
    readers_[open_.front()].reset();
    open_.pop_front();
  }
  auto opened = ImageryReader::open(inputs_[input]);
  if (!opened) return Error{opened.error()};
  readers_[input] = std::move(*opened);
  where_[input] = open_.insert(open_.end(), input);
  ++opened_;
  return readers_[input].get();
}

size_t readersPerWorker(unsigned workers) {
  rlim_t descriptors = 1024;
  rlimit limit{};
  if (::getrlimit(RLIMIT_NOFILE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    descriptors = limit.rlim_cur;
  }
  return std::clamp<size_t>(static_cast<size_t>(descriptors) / 2 / std::max(workers, 1U), 2, 256);
}

}  // namespace globe::imagery_tiling
