#include "streaming/tile_store.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

#include "core/crc32.hpp"

namespace globe::streaming {
namespace {

// A pyramid of another pack format version is refused as a whole: its first level-0 pack's
// header says so. Unreadable or damaged packs are left to be reported one by one when read.
Result<void> checkFormatVersion(transport::ByteSource& source,
                                const formats::PyramidManifest& manifest) {
  if (manifest.levels.empty() || manifest.levels[0].packs.empty()) return {};
  const std::string name = formats::packName(manifest.levels[0].packs.front());
  auto opened = source.open(name, formats::kPackHeaderBytes);
  if (!opened || opened->head.size() < formats::kPackHeaderBytes) return {};
  const std::optional<uint32_t> version = formats::packFormatVersionOf(opened->head);
  return version ? formats::checkPackFormatVersion(*version, source.locationOf(name))
                 : Result<void>{};
}

}  // namespace

TileStore::TileStore(std::shared_ptr<transport::ByteSource> source,
                     formats::PyramidManifest manifest, terrain::SeaSurface sea)
    : source_(std::move(source)), manifest_(std::move(manifest)), sea_(sea) {}

Result<std::unique_ptr<TileStore>> TileStore::open(const std::string& pyramid,
                                                   terrain::SeaSurface sea,
                                                   std::shared_ptr<transport::Network> network) {
  auto source = transport::openByteSource(pyramid, network.get());
  if (!source) return Error{source.error()};
  return open(std::move(*source), sea);
}

Result<std::unique_ptr<TileStore>> TileStore::open(std::shared_ptr<transport::ByteSource> source,
                                                   terrain::SeaSurface sea) {
  auto manifest = formats::readManifest(*source);
  if (!manifest) return Error{manifest.error()};
  for (formats::LevelInfo& level : manifest->levels)
    std::sort(level.packs.begin(), level.packs.end());
  if (auto version = checkFormatVersion(*source, *manifest); !version) {
    return Error{version.error()};
  }
  return std::unique_ptr<TileStore>(new TileStore(std::move(source), std::move(*manifest), sea));
}

Result<std::shared_ptr<const TileStore::OpenPack>> TileStore::pack(const formats::PackId& id) {
  if (!listsPack(manifest_.levels, id)) return std::shared_ptr<const OpenPack>();
  bool failed = false;
  auto opened = packs_.get(
      id, [this](const formats::PackId& p) { return openPack(p); }, &failed);
  if (failed) ++packOpenFailures_;
  return opened;
}

Result<std::shared_ptr<const TileStore::OpenPack>> TileStore::openPack(const formats::PackId& id) {
  const std::string name = formats::packName(id);
  const std::string path = source_->locationOf(name);
  formats::PackLayout layout = manifest_.packLayout();
  // One read (one range request) for the header and the index the manifest's layout predicts;
  // a pack of another readable version has another index size and takes a second read.
  auto opened = source_->open(name, layout.indexEndOffset());
  if (!opened) return Error{opened.error()};
  const uint64_t fileBytes = opened->file->sizeBytes();
  std::vector<std::byte> head = std::move(opened->head);
  auto truncated = [&] {
    return makeError(path + ": truncated pack (" + std::to_string(fileBytes) + " bytes)");
  };
  if (head.size() < formats::kPackHeaderBytes) return truncated();
  const std::optional<uint32_t> version = formats::packFormatVersionOf(head);
  if (version && formats::checkPackFormatVersion(*version, path)) layout.formatVersion = *version;
  if (head.size() != layout.indexEndOffset()) {
    if (fileBytes < layout.indexEndOffset()) return truncated();
    head.resize(layout.indexEndOffset());
    if (auto read = opened->file->read(head, 0); !read) return Error{read.error()};
  }
  auto index = formats::decodePackIndex(head, fileBytes, path);
  if (!index) return Error{index.error()};
  if (index->id != id || index->layout.tilesPerSide != layout.tilesPerSide ||
      index->layout.verticesPerSide != layout.verticesPerSide) {
    return makeError(path + ": pack header disagrees with the manifest");
  }
  ++packIndexReads_;
  return std::make_shared<const OpenPack>(std::move(opened->file), std::move(*index));
}

std::vector<std::string> TileStore::takeNewPackErrors() { return packs_.takeNewErrors(); }

void TileStore::forgetFailedPacks() { packs_.forgetFailures(); }

Result<std::optional<formats::PackEntry>> TileStore::entry(const geo::TileId& tile) {
  auto opened = pack(formats::packOf(tile, manifest_.packTilesPerSide));
  if (!opened) return Error{opened.error()};
  if (!*opened) return std::optional<formats::PackEntry>();
  const formats::PackEntry& e =
      (*opened)->index.entries[formats::slotOf(tile, manifest_.packTilesPerSide)];
  return e.present() ? std::optional<formats::PackEntry>(e) : std::nullopt;
}

TileStore::Peek TileStore::peekEntry(const geo::TileId& tile, formats::PackEntry* entry) {
  const formats::PackId id = formats::packOf(tile, manifest_.packTilesPerSide);
  if (!listsPack(manifest_.levels, id)) return Peek::Absent;
  const auto opened = packs_.peek(id);
  if (!opened) return Peek::NotOpen;
  if (!*opened) return Peek::Absent;
  const formats::PackEntry& e =
      (**opened)->index.entries[formats::slotOf(tile, manifest_.packTilesPerSide)];
  if (!e.present()) return Peek::Absent;
  *entry = e;
  return Peek::Present;
}

TileStore::Peek TileStore::peek(const geo::TileId& tile, terrain::TileSummary* summary) {
  formats::PackEntry e;
  const Peek peeked = peekEntry(tile, &e);
  if (peeked == Peek::Present) *summary = {e.subtreeRange, e.geometricErrorMeters};
  return peeked;
}

Result<std::optional<terrain::TileSummary>> TileStore::summary(const geo::TileId& tile) {
  auto e = entry(tile);
  if (!e) return Error{e.error()};
  if (!*e) return std::optional<terrain::TileSummary>();
  return std::optional<terrain::TileSummary>(
      terrain::TileSummary{(*e)->subtreeRange, (*e)->geometricErrorMeters});
}

Result<terrain::HeightBlock> TileStore::loadBlock(const geo::TileId& tile) {
  auto opened = pack(formats::packOf(tile, manifest_.packTilesPerSide));
  if (!opened) return Error{opened.error()};
  const std::string name = geo::tileName(tile);
  if (!*opened) return makeError(location() + ": the pyramid has no " + name);
  const OpenPack& p = **opened;
  const formats::PackEntry& e = p.index.entries[formats::slotOf(tile, manifest_.packTilesPerSide)];
  if (!e.present()) return makeError(location() + ": the pyramid has no " + name);

  std::vector<std::byte> bytes(p.index.layout.blockBytes());
  if (auto read = p.file->read(bytes, e.blockOffset); !read) {
    packs_.noteError(p.index.id, read.error());
    return Error{read.error()};
  }
  const formats::PackLayout& layout = p.index.layout;
  if (layout.hasBlockCrc() && core::crc32(bytes) != e.blockCrc) {
    const std::string message =
        p.file->location() + ": the block of " + name + " fails its CRC (corrupt pack)";
    packs_.noteError(p.index.id, message);
    return makeError(message);
  }
  ++blockReads_;
  terrain::HeightBlock block{manifest_.verticesPerSide, {}, sea_};
  block.heights.resize(size_t{layout.verticesPerSide} * layout.verticesPerSide);
  if (layout.hasApron()) block.apron.resize(terrain::apronSampleCount(layout.verticesPerSide));
  formats::decodeBlock(bytes, layout, block.heights, block.apron);
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
  return source_->locationOf(formats::packName(formats::packOf(tile, manifest_.packTilesPerSide)));
}

}  // namespace globe::streaming
