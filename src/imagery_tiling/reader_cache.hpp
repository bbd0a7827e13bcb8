// One worker's imagery readers, opened on first use and kept open up to a capacity, the least
// recently used closed first: a layer of thousands of inputs (scenes, tiles) must not hold a file
// descriptor per input per worker. A reader obtained stays valid until the next get().
#pragma once

#include <cstddef>
#include <list>
#include <memory>
#include <vector>

#include "core/result.hpp"
#include "imagery_tiling/imagery_input.hpp"
#include "imagery_tiling/imagery_reader.hpp"

namespace globe::imagery_tiling {

class ReaderCache {
 public:
  ReaderCache(const std::vector<ImageryInput>& inputs, size_t capacity);
  Result<ImageryReader*> get(size_t input);

  size_t openReaders() const { return open_.size(); }
  size_t opened() const { return opened_; }  // readers opened so far, reopened ones included

 private:
  const std::vector<ImageryInput>& inputs_;
  size_t capacity_;
  std::vector<std::unique_ptr<ImageryReader>> readers_;
  std::list<size_t> open_;  // open inputs, least recently used first
  std::vector<std::list<size_t>::iterator> where_;
  size_t opened_ = 0;
};

// Readers each of `workers` may keep open: half the descriptors this process may hold, shared
// between them (a reader holds about one), between 2 and 256.
size_t readersPerWorker(unsigned workers);

}  // namespace globe::imagery_tiling
