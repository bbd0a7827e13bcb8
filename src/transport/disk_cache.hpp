// A bounded on-disk cache of HTTP response bodies (whole small files or byte ranges), shared by
// loader threads and by several viewer processes, that a crash or power loss can only turn into
// misses, never into wrong bytes.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/result.hpp"

namespace globe::transport {

// One cached response body: a whole small file or a byte range of a larger one.
struct CacheEntry {
  std::string validator;   // the ETag (or Last-Modified) the body was served with; may be empty
  uint64_t fileBytes = 0;  // the whole file's size (the body may be a range of it)
  std::vector<std::byte> body;
};

// Layout. Each entry is one file DIR/ab/<32 hex>.entry, the name being a 128-bit hash of the key
// (never server text) and ab its first two characters. Integers are big-endian, as in the pack
// files:
//     "GLOBECE1"            8-byte magic
//     u32 keyLength, key    keyLength <= 64 KiB
//     u32 validatorLength, validator   <= 64 KiB
//     u64 fileBytes
//     u64 bodyLength, body  bodyLength is exactly what is left before the CRC
//     u32 CRC-32 (core/crc32.hpp) of every byte before it
// A file that fails any check is a miss and is deleted; so is one holding another key (a hash
// collision). Entries are written to DIR/ab/tmp-<pid>-<counter>-<random> and renamed into place,
// without fsync: the CRC, not the write order, is what catches a torn file.
//
// Recency is the file's mtime, so that it is shared between processes: a hit sets it to now, and
// eviction deletes the oldest entries first. The budget counts entry file sizes (st_size).
//
// Thread-safe; several processes may share one directory (a file that vanishes under one is a
// miss). Nothing is written outside DIR; files there that are not entries or temporaries are
// left alone.
class DiskCache {
 public:
  // Opens, creating it (and parents) if needed, a cache directory bounded to budgetBytes of entries
  // on disk (least recently used evicted). Error (naming the directory) when it is not a directory
  // or cannot be created/written. Scans it once: counts its entries, evicts when they already
  // exceed the budget and deletes temporaries older than an hour (left by a crashed writer).
  static Result<std::unique_ptr<DiskCache>> open(const std::filesystem::path& dir,
                                                 uint64_t budgetBytes);
  // $XDG_CACHE_HOME/globe, else $HOME/.cache/globe, else an error-free fallback "./.globe-cache".
  static std::filesystem::path defaultDirectory();

  // The entry stored under key, or nullopt when absent, torn, damaged or stored under another key
  // (a damaged or torn entry file is deleted). A hit marks the entry recently used.
  std::optional<CacheEntry> get(const std::string& key);
  // Stores the entry atomically (unique temporary name in the cache dir, then rename), replacing
  // any entry under the same key; then evicts least-recently-used entries while the bytes on disk
  // exceed the budget (down to ~90 % of it). Returns an error naming the file on failure (callers
  // log and carry on). An entry whose file would exceed the whole budget is not stored (and the
  // one it replaces is erased): that is a success, not an error.
  Result<void> put(const std::string& key, const CacheEntry& entry);
  // Removes the entry under key if any.
  void erase(const std::string& key);

  // This process's running estimate (scanned at open, updated by put/evict); other processes'
  // writes are seen at the next eviction scan.
  uint64_t bytesOnDisk() const { return bytes_.load(); }
  const std::filesystem::path& directory() const { return dir_; }

 private:
  struct EntryFile;
  DiskCache(std::filesystem::path dir, uint64_t budgetBytes);

  std::filesystem::path entryPath(const std::string& key) const;
  // The entry files under dir_, deleting hour-old temporaries on the way.
  std::vector<EntryFile> scan() const;
  // Deletes the oldest of `files` down to ~90 % of the budget; mutex_ held.
  void evictLocked(std::vector<EntryFile> files);
  // Deletes a bad entry file, unless a writer has already renamed a new one over it.
  void discard(const std::filesystem::path& path, uint64_t device, uint64_t inode, uint64_t size);
  void subtractLocked(uint64_t size);

  std::filesystem::path dir_;
  uint64_t budget_;
  std::mutex mutex_;  // serialises renames, deletions and the byte count within this process
  std::atomic<uint64_t> bytes_{0};
};

}  // namespace globe::transport
