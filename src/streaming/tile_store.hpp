// Read access to a tile pyramid on disk: tile lookups and block loads, one read per block.
#pragma once

#include <atomic>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "formats/pack_format.hpp"
#include "formats/pyramid_manifest.hpp"
#include "geo/tile_id.hpp"
#include "streaming/open_packs.hpp"
#include "streaming/terrain_source.hpp"
#include "streaming/tile_source.hpp"
#include "terrain/height_block.hpp"
#include "transport/byte_source.hpp"
#include "transport/network_settings.hpp"

namespace globe::streaming {

// The height-block source of the loader (TileSource<HeightBlock>).
class TileStore final : public TerrainSource {
 public:
  // `sea`: the surface every block loaded from this store reads as the ground over water
  // (HeightBlock::sea): the one place a viewer's --sea-floor reaches rendering, collision and
  // heights alike. Refuses a pyramid whose packs have another format version (checked on the
  // first level-0 pack; every pack is checked again when opened).
  // `pyramid`: a directory, or the http(s) URL of one on a static server read through `network`
  // (the program's: transport/network_settings.hpp). Without a network (the default, for callers
  // that open local directories only) a URL is an error naming it.
  static Result<std::unique_ptr<TileStore>> open(
      const std::string& pyramid, terrain::SeaSurface sea = terrain::SeaSurface::Water,
      std::shared_ptr<transport::Network> network = nullptr);
  static Result<std::unique_ptr<TileStore>> open(
      std::shared_ptr<transport::ByteSource> source,
      terrain::SeaSurface sea = terrain::SeaSurface::Water);
  ~TileStore() override = default;
  TileStore(const TileStore&) = delete;
  TileStore& operator=(const TileStore&) = delete;

  const formats::PyramidManifest& manifest() const override { return manifest_; }
  // The pyramid's directory or URL.
  const std::string& location() const override { return source_->location(); }
  bool remote() const override { return source_->remote(); }
  terrain::SeaSurface sea() const override { return sea_; }

  // The tile's index entry, or nullopt when the pyramid has no such tile. Thread-safe.
  Result<std::optional<formats::PackEntry>> entry(const geo::TileId& tile);
  // For a render thread that must not wait on a server: the tile's entry from its pack's index
  // without any I/O. Absent also for a pack that failed (its parent is drawn); NotOpen when the
  // pack was not read yet: entry() (on a worker) reads it.
  Peek peekEntry(const geo::TileId& tile, formats::PackEntry* entry);
  // TerrainSource: the entry's height bounds and measured error.
  Peek peek(const geo::TileId& tile, terrain::TileSummary* summary) override;
  Result<std::optional<terrain::TileSummary>> summary(const geo::TileId& tile) override;

  // Loads a present tile's block with one read (its pack's index is parsed once), its `sea` set
  // to the store's. Thread-safe.
  Result<terrain::HeightBlock> loadBlock(const geo::TileId& tile) override;

  // TileSource: the entry first, so that a tile beyond the pyramid's coverage (nullopt) is told
  // apart from a pack that is missing or damaged (an error); then loadBlock.
  Result<std::optional<terrain::HeightBlock>> load(const geo::TileId& tile) override;
  std::string location(const geo::TileId& tile) const override;
  // Over HTTP: the candidates whose blocks, with first's, make one run of adjacent bytes in
  // first's pack (version 6 stores a square of neighbours together), so one range request reads
  // them all; at most kReadTogetherBytes. Local packs read each block alone (a pread is cheap).
  std::vector<geo::TileId> readableWith(const geo::TileId& first,
                                        std::span<const geo::TileId> candidates) override;
  std::vector<Result<std::optional<terrain::HeightBlock>>> loadTogether(
      std::span<const geo::TileId> tiles) override;
  std::vector<std::string> takeNewSourceErrors() override { return takeNewPackErrors(); }
  bool failedAt(const geo::TileId& tile) override;
  void forgetSourceFailures() override { forgetFailedPacks(); }

  static constexpr uint64_t kReadTogetherBytes = 256 * 1024;

  // Blocks loaded, and of them those found in the bytes read with their pack's index.
  uint64_t blockReads() const { return blockReads_.load(); }
  uint64_t blocksFromHead() const { return blocksFromHead_.load(); }
  // Reads of several adjacent blocks at once (loadTogether), and the blocks they held.
  uint64_t groupReads() const { return groupReads_.load(); }
  uint64_t groupBlocks() const { return groupBlocks_.load(); }
  // Pack indexes longer than the first read (or of an older version): a second read each.
  uint64_t indexContinuations() const { return indexContinuations_.load(); }
  uint64_t packIndexReads() const { return packIndexReads_.load(); }
  // Packs that could not be opened: each is tried once, then its error is returned from memory.
  uint64_t packOpenFailures() const { return packOpenFailures_.load(); }

  // The first error of each pack found missing or damaged (at open or at a block read) since the
  // last call, each pack once: a viewer reports these instead of one error per tile or frame.
  std::vector<std::string> takeNewPackErrors();
  // Lets failed packs be opened (again, from their current file) and reported again: say, after
  // the pyramid was repaired.
  void forgetFailedPacks();

 private:
  using OpenPack = OpenPackFile<formats::PackIndex>;
  TileStore(std::shared_ptr<transport::ByteSource> source, formats::PyramidManifest manifest,
            terrain::SeaSurface sea);
  // nullptr when the level has no such pack.
  Result<std::shared_ptr<const OpenPack>> pack(const formats::PackId& id);
  Result<std::shared_ptr<const OpenPack>> openPack(const formats::PackId& id);
  // A present tile's block from its stored bytes: checked, decoded, counted; a damaged one noted
  // as its pack's error.
  Result<terrain::HeightBlock> decodeLoaded(const OpenPack& p, const geo::TileId& tile,
                                            std::span<const std::byte> stored);

  std::shared_ptr<transport::ByteSource> source_;
  formats::PyramidManifest manifest_;
  terrain::SeaSurface sea_;
  OpenPacks<OpenPack> packs_;
  std::atomic<uint64_t> blockReads_{0};
  std::atomic<uint64_t> blocksFromHead_{0};
  std::atomic<uint64_t> groupReads_{0};
  std::atomic<uint64_t> groupBlocks_{0};
  std::atomic<uint64_t> indexContinuations_{0};
  std::atomic<bool> versionRefused_{false};  // a pack of a version this globe does not read
  std::atomic<uint64_t> packIndexReads_{0};
  std::atomic<uint64_t> packOpenFailures_{0};
};

}  // namespace globe::streaming
