#include "io/tile_store.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

#include "io/file_reads.hpp"

namespace globe::io {
namespace {

// A pyramid of another pack format version is refused as a whole: its first level-0 pack's
// header says so. Unreadable or damaged packs are left to be reported one by one when read.
Result<void> checkFormatVersion(const std::filesystem::path& dir, const PyramidManifest& manifest) {
  if (manifest.levels.empty() || manifest.levels[0].packs.empty()) return {};
  const std::filesystem::path path = packPath(dir, manifest.levels[0].packs.front());
  FdCloser file{::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK)};
  struct stat info {};
  if (file.fd < 0 || ::fstat(file.fd, &info) != 0 || !S_ISREG(info.st_mode)) return {};
  std::byte head[kPackHeaderBytes];
  if (!preadFully(file.fd, head, sizeof head, 0, path)) return {};
  const std::optional<uint32_t> version = packFormatVersionOf(head);
  return version ? checkPackFormatVersion(*version, path) : Result<void>{};
}

}  // namespace

TileStore::TileStore(std::filesystem::path dir, PyramidManifest manifest, terrain::SeaSurface sea)
    : dir_(std::move(dir)), manifest_(std::move(manifest)), sea_(sea) {}

Result<std::unique_ptr<TileStore>> TileStore::open(const std::filesystem::path& pyramidDir,
                                                   terrain::SeaSurface sea) {
  auto manifest = readManifest(pyramidDir);
  if (!manifest) return Error{manifest.error()};
  for (LevelInfo& level : manifest->levels) std::sort(level.packs.begin(), level.packs.end());
  if (auto version = checkFormatVersion(pyramidDir, *manifest); !version) {
    return Error{version.error()};
  }
  return std::unique_ptr<TileStore>(new TileStore(pyramidDir, std::move(*manifest), sea));
}

Result<std::shared_ptr<const TileStore::OpenPack>> TileStore::pack(const PackId& id) {
  if (id.level >= manifest_.levels.size()) return std::shared_ptr<const OpenPack>();
  const auto& packs = manifest_.levels[id.level].packs;
  if (!std::binary_search(packs.begin(), packs.end(), id)) return std::shared_ptr<const OpenPack>();
  bool failed = false;
  auto opened = packs_.get(
      id, [this](const PackId& p) { return openPack(p); }, &failed);
  if (failed) ++packOpenFailures_;
  return opened;
}

Result<std::shared_ptr<const TileStore::OpenPack>> TileStore::openPack(const PackId& id) {
  const std::filesystem::path path = packPath(dir_, id);
  // O_NONBLOCK: a FIFO in the pack's place must not block the viewer; it is refused below.
  FdCloser file{::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK)};
  if (file.fd < 0) return makeError(path.string() + ": cannot open: " + std::strerror(errno));
  struct stat info {};
  if (::fstat(file.fd, &info) != 0) {
    return makeError(path.string() + ": cannot stat: " + std::strerror(errno));
  }
  if (!S_ISREG(info.st_mode)) return makeError(path.string() + ": not a regular file");
  std::vector<std::byte> head;
  PackLayout layout = manifest_.packLayout();
  auto readHead = [&](size_t bytes) -> Result<void> {
    if (static_cast<uint64_t>(info.st_size) < bytes) {
      return makeError(path.string() + ": truncated pack (" + std::to_string(info.st_size) +
                       " bytes)");
    }
    head.resize(bytes);
    return preadFully(file.fd, head.data(), head.size(), 0, path);
  };
  // The header's version sets the index's size; decodePackIndex refuses unknown versions.
  if (auto read = readHead(kPackHeaderBytes); !read) return Error{read.error()};
  const std::optional<uint32_t> version = packFormatVersionOf(head);
  if (version && checkPackFormatVersion(*version, path)) layout.formatVersion = *version;
  if (auto read = readHead(layout.indexEndOffset()); !read) return Error{read.error()};
  auto index = decodePackIndex(head, static_cast<uint64_t>(info.st_size), path);
  if (!index) return Error{index.error()};
  if (index->id != id || index->layout.tilesPerSide != layout.tilesPerSide ||
      index->layout.verticesPerSide != layout.verticesPerSide) {
    return makeError(path.string() + ": pack header disagrees with the manifest");
  }
  ++packIndexReads_;
  auto opened = std::make_shared<const OpenPack>(file.fd, std::move(*index));
  file.fd = -1;
  return opened;
}

std::vector<std::string> TileStore::takeNewPackErrors() { return packs_.takeNewErrors(); }

void TileStore::forgetFailedPacks() { packs_.forgetFailures(); }

Result<std::optional<PackEntry>> TileStore::entry(const geo::TileId& tile) {
  auto opened = pack(packOf(tile, manifest_.packTilesPerSide));
  if (!opened) return Error{opened.error()};
  if (!*opened) return std::optional<PackEntry>();
  const PackEntry& e = (*opened)->index.entries[slotOf(tile, manifest_.packTilesPerSide)];
  return e.present() ? std::optional<PackEntry>(e) : std::nullopt;
}

Result<terrain::HeightBlock> TileStore::loadBlock(const geo::TileId& tile) {
  auto opened = pack(packOf(tile, manifest_.packTilesPerSide));
  if (!opened) return Error{opened.error()};
  const std::string name = geo::tileName(tile);
  if (!*opened) return makeError(dir_.string() + ": the pyramid has no " + name);
  const OpenPack& p = **opened;
  const PackEntry& e = p.index.entries[slotOf(tile, manifest_.packTilesPerSide)];
  if (!e.present()) return makeError(dir_.string() + ": the pyramid has no " + name);

  std::vector<std::byte> bytes(p.index.layout.blockBytes());
  if (auto read =
          preadFully(p.fd, bytes.data(), bytes.size(), e.blockOffset, packPath(dir_, p.index.id));
      !read) {
    packs_.noteError(p.index.id, read.error());
    return Error{read.error()};
  }
  ++blockReads_;
  const PackLayout& layout = p.index.layout;
  terrain::HeightBlock block{manifest_.verticesPerSide, {}, sea_};
  block.heights.resize(size_t{layout.verticesPerSide} * layout.verticesPerSide);
  if (layout.hasApron()) block.apron.resize(terrain::apronSampleCount(layout.verticesPerSide));
  decodeBlock(bytes, layout, block.heights, block.apron);
  return block;
}

Result<std::optional<terrain::HeightBlock>> TileStore::load(const geo::TileId& tile) {
  auto present = entry(tile);
  if (!present) return Error{present.error()};
  if (!*present) return std::optional<terrain::HeightBlock>{};
  auto block = loadBlock(tile);
  if (!block) return Error{block.error()};
  return std::optional<terrain::HeightBlock>{std::move(*block)};
}

std::string TileStore::location(const geo::TileId& tile) const {
  return packPath(dir_, packOf(tile, manifest_.packTilesPerSide)).string();
}

}  // namespace globe::io
