// Whole-file reads with a size cap, and writes that never leave a half-written file behind.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

#include "core/result.hpp"

namespace globe::transport {

// Writes `path` + ".tmp-<host>-<pid>-<counter>", fsyncs it and renames it over `path`; on any
// failure the temporary is removed and `path` is untouched.
Result<void> writeFileAtomically(const std::filesystem::path& path,
                                 std::span<const std::byte> bytes);
Result<void> writeFileAtomically(const std::filesystem::path& path, std::string_view text);

// Removes, anywhere below `dir`, the temporaries writeFileAtomically leaves when its process is
// killed mid-write: never complete files. Errors are ignored (what cannot be listed or removed
// stays, and is never read as a finished file).
void removeAtomicTemporaries(const std::filesystem::path& dir);

// Reads a regular file whole; refuses files larger than maxBytes before allocating, and anything
// that is not a regular file (a FIFO without waiting for a writer).
Result<std::vector<std::byte>> readWholeFile(const std::filesystem::path& path, uint64_t maxBytes);

}  // namespace globe::transport
