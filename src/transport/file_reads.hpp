// Reading pack files by offset: the whole range or a clear error, and a descriptor closed on scope
// exit. Shared by the block and imagery stores.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "core/result.hpp"

namespace globe::transport {

struct FdCloser {
  int fd;
  ~FdCloser() {
    if (fd >= 0) ::close(fd);
  }
};

// Reads exactly `bytes` at `offset` (retrying interrupted and short reads); errors name `path`
// and the byte where the read failed or the file ended.
Result<void> preadFully(int fd, std::byte* out, size_t bytes, uint64_t offset,
                        const std::filesystem::path& path);

}  // namespace globe::transport
