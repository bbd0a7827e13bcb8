// Read access to a tile pyramid on disk: tile lookups and block loads, one read per block.
#pragma once

#include <atomic>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>

#include "geo/result.hpp"
#include "geo/tile_id.hpp"
#include "io/pack_format.hpp"
#include "io/pyramid_manifest.hpp"
#include "terrain/height_block.hpp"

namespace globe::io {

class TileStore {
 public:
  static Result<std::unique_ptr<TileStore>> open(const std::filesystem::path& pyramidDir);
  ~TileStore() = default;
  TileStore(const TileStore&) = delete;
  TileStore& operator=(const TileStore&) = delete;

  const PyramidManifest& manifest() const { return manifest_; }
  const std::filesystem::path& directory() const { return dir_; }

  // The tile's index entry, or nullopt when the pyramid has no such tile. Thread-safe.
  Result<std::optional<PackEntry>> entry(const geo::TileId& tile);
  // Loads a present tile's block with one read (its pack's index is parsed once). Thread-safe.
  Result<terrain::HeightBlock> loadBlock(const geo::TileId& tile);

  uint64_t blockReads() const { return blockReads_.load(); }
  uint64_t packIndexReads() const { return packIndexReads_.load(); }

 private:
  // Owns its descriptor, so a pack evicted from the cache stays readable while a loader uses it.
  struct OpenPack {
    int fd = -1;
    PackIndex index;
    OpenPack(int descriptor, PackIndex packIndex) : fd(descriptor), index(std::move(packIndex)) {}
    OpenPack(const OpenPack&) = delete;
    OpenPack& operator=(const OpenPack&) = delete;
    ~OpenPack();
  };
  TileStore(std::filesystem::path dir, PyramidManifest manifest);
  // nullptr when the level has no such pack.
  Result<std::shared_ptr<const OpenPack>> pack(const PackId& id);

  std::filesystem::path dir_;
  PyramidManifest manifest_;
  std::mutex mutex_;
  std::map<PackId, std::shared_ptr<const OpenPack>> openPacks_;
  std::atomic<uint64_t> blockReads_{0};
  std::atomic<uint64_t> packIndexReads_{0};
};

}  // namespace globe::io
