#include "streaming/tile_store.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <map>
#include <utility>

#include "formats/pack_format.hpp"

namespace globe::streaming {

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
  for (formats::LevelInfo& level : manifest->levels) {
    // Sorted for lookups, each pack's index size kept beside it.
    std::vector<size_t> order(level.packs.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return level.packs[a] < level.packs[b]; });
    std::vector<formats::PackId> packs;
    std::vector<uint32_t> indexBytes;
    for (size_t i : order) {
      packs.push_back(level.packs[i]);
      if (!level.packIndexBytes.empty()) indexBytes.push_back(level.packIndexBytes[i]);
    }
    level.packs = std::move(packs);
    level.packIndexBytes = std::move(indexBytes);
  }
  std::unique_ptr<TileStore> store(new TileStore(std::move(source), std::move(*manifest), sea));
  // A pyramid of another pack format version is refused as a whole: its first level-0 pack
  // (the first any view reads, so opened now) says so. Unreadable or damaged packs are left to
  // be reported one by one when read.
  const auto& first = store->manifest_.levels;
  if (!first.empty() && !first[0].packs.empty()) {
    auto opened = store->pack(first[0].packs.front());
    if (!opened && store->versionRefused_) return Error{opened.error()};
  }
  return store;
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
  // One read (one range request) for the header and the index: a compressed index's first
  // kPackFirstReadBytes (its blocks too, for a small pack), an uncompressed one's exact size. A
  // longer index, or a pack of an older version, takes a second read.
  // The manifest says how long a version-5 pack's index is: exactly header and index then.
  size_t firstRead =
      layout.hasCompressedIndex() ? formats::kPackFirstReadBytes : layout.indexEndOffset();
  if (id.level < manifest_.levels.size()) {
    const formats::LevelInfo& level = manifest_.levels[id.level];
    const auto at = std::lower_bound(level.packs.begin(), level.packs.end(), id);
    if (at != level.packs.end() && *at == id && !level.packIndexBytes.empty()) {
      firstRead = formats::kPackHeaderBytes +
                  level.packIndexBytes[static_cast<size_t>(at - level.packs.begin())];
    }
  }
  auto opened = source_->open(name, firstRead);
  if (!opened) return Error{opened.error()};
  const uint64_t fileBytes = opened->file->sizeBytes();
  std::vector<std::byte> head = std::move(opened->head);
  auto truncated = [&] {
    return makeError(path + ": truncated pack (" + std::to_string(fileBytes) + " bytes)");
  };
  if (head.size() < formats::kPackHeaderBytes) return truncated();
  if (const auto version = formats::packFormatVersionOf(head)) {
    if (auto readable = formats::checkPackFormatVersion(*version, path); !readable) {
      versionRefused_ = true;
      return Error{readable.error()};
    }
  }
  const std::optional<uint64_t> indexEnd = formats::packIndexEndOffset(head);
  if (indexEnd && *indexEnd > head.size()) {
    if (fileBytes < *indexEnd) return truncated();
    const size_t have = head.size();
    head.resize(static_cast<size_t>(*indexEnd));
    if (auto read = opened->file->read(std::span(head).subspan(have), have); !read) {
      return Error{read.error()};
    }
    ++indexContinuations_;
  }
  auto index = formats::decodePackIndex(head, fileBytes, path);
  if (!index) return Error{index.error()};
  if (index->id != id || index->layout.tilesPerSide != layout.tilesPerSide ||
      index->layout.verticesPerSide != layout.verticesPerSide) {
    return makeError(path + ": pack header disagrees with the manifest");
  }
  ++packIndexReads_;
  return std::make_shared<const OpenPack>(std::move(opened->file), std::move(*index),
                                          std::move(head));
}

std::vector<std::string> TileStore::takeNewPackErrors() { return packs_.takeNewErrors(); }

void TileStore::forgetFailedPacks() { packs_.forgetFailures(); }

bool TileStore::failedAt(const geo::TileId& tile) {
  const auto known = packs_.peek(formats::packOf(tile, manifest_.packTilesPerSide));
  return known && !*known;
}

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

  std::vector<std::byte> bytes(e.storedBytes);
  if (e.blockOffset + bytes.size() <= p.head.size()) {
    std::memcpy(bytes.data(), p.head.data() + e.blockOffset, bytes.size());  // read with the index
    ++blocksFromHead_;
  } else if (auto read = p.file->read(bytes, e.blockOffset); !read) {
    packs_.noteError(p.index.id, read.error());
    return Error{read.error()};
  }
  return decodeLoaded(p, tile, bytes);
}

Result<terrain::HeightBlock> TileStore::decodeLoaded(const OpenPack& p, const geo::TileId& tile,
                                                     std::span<const std::byte> stored) {
  const formats::PackLayout& layout = p.index.layout;
  const formats::PackEntry& e = p.index.entries[formats::slotOf(tile, manifest_.packTilesPerSide)];
  terrain::HeightBlock block{manifest_.verticesPerSide, {}, sea_};
  block.heights.resize(size_t{layout.verticesPerSide} * layout.verticesPerSide);
  if (layout.hasApron()) block.apron.resize(terrain::apronSampleCount(layout.verticesPerSide));
  if (auto decoded = formats::decodeStoredBlock(stored, layout, e, block.heights, block.apron);
      !decoded) {
    const std::string message =
        p.file->location() + ": " + geo::tileName(tile) + ": " + decoded.error();
    packs_.noteError(p.index.id, message);
    return makeError(message);
  }
  ++blockReads_;
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

std::vector<geo::TileId> TileStore::readableWith(const geo::TileId& first,
                                                 std::span<const geo::TileId> candidates) {
  if (!remote()) return {};
  const uint32_t perSide = manifest_.packTilesPerSide;
  const formats::PackId id = formats::packOf(first, perSide);
  const auto opened = packs_.peek(id);
  if (!opened || !*opened) return {};
  const OpenPack& p = ***opened;
  const formats::PackEntry& start = p.index.entries[formats::slotOf(first, perSide)];
  if (!start.present() || start.blockOffset + start.storedBytes <= p.head.size()) return {};
  // Candidates' blocks by where they start: a run grows at either end while one begins where it
  // ends or ends where it begins.
  std::map<uint64_t, geo::TileId> byOffset;
  std::map<uint64_t, geo::TileId> byEnd;
  for (const geo::TileId& tile : candidates) {
    if (tile == first || formats::packOf(tile, perSide) != id) continue;
    const formats::PackEntry& e = p.index.entries[formats::slotOf(tile, perSide)];
    if (!e.present() || e.blockOffset < p.head.size()) continue;
    byOffset.emplace(e.blockOffset, tile);
    byEnd.emplace(e.blockOffset + e.storedBytes, tile);
  }
  uint64_t begin = start.blockOffset;
  uint64_t end = start.blockOffset + start.storedBytes;
  std::vector<geo::TileId> after;
  std::vector<geo::TileId> before;
  for (bool grew = true; grew && end - begin < kReadTogetherBytes;) {
    grew = false;
    if (auto next = byOffset.find(end); next != byOffset.end()) {
      end += p.index.entries[formats::slotOf(next->second, perSide)].storedBytes;
      after.push_back(next->second);
      grew = true;
    }
    if (auto previous = byEnd.find(begin);
        previous != byEnd.end() && end - begin < kReadTogetherBytes) {
      begin -= p.index.entries[formats::slotOf(previous->second, perSide)].storedBytes;
      before.push_back(previous->second);
      grew = true;
    }
  }
  std::vector<geo::TileId> together(before.rbegin(), before.rend());
  together.insert(together.end(), after.begin(), after.end());
  return together;
}

std::vector<Result<std::optional<terrain::HeightBlock>>> TileStore::loadTogether(
    std::span<const geo::TileId> tiles) {
  using Loaded = Result<std::optional<terrain::HeightBlock>>;
  const auto eachAlone = [&] {
    std::vector<Loaded> results;
    for (const geo::TileId& tile : tiles) results.push_back(load(tile));
    return results;
  };
  if (tiles.size() < 2) return eachAlone();
  const uint32_t perSide = manifest_.packTilesPerSide;
  const formats::PackId id = formats::packOf(tiles[0], perSide);
  auto opened = pack(id);
  if (!opened || !*opened) return eachAlone();
  const OpenPack& p = **opened;
  // The tiles by offset; read together only when they are one run of adjacent blocks.
  std::vector<std::pair<uint64_t, size_t>> order;
  for (size_t i = 0; i < tiles.size(); ++i) {
    if (formats::packOf(tiles[i], perSide) != id) return eachAlone();
    const formats::PackEntry& e = p.index.entries[formats::slotOf(tiles[i], perSide)];
    if (!e.present()) return eachAlone();
    order.emplace_back(e.blockOffset, i);
  }
  std::sort(order.begin(), order.end());
  std::vector<uint32_t> pieces;
  uint64_t end = order.front().first;
  for (const auto& [offset, i] : order) {
    if (offset != end) return eachAlone();
    pieces.push_back(p.index.entries[formats::slotOf(tiles[i], perSide)].storedBytes);
    end += pieces.back();
  }
  std::vector<std::byte> bytes(end - order.front().first);
  if (auto read = p.file->readPieces(bytes, order.front().first, pieces); !read) {
    // Each alone then: offline, the cache may hold some of them; online, each failure is its
    // own tile's (and its own pack error, once).
    return eachAlone();
  }
  ++groupReads_;
  groupBlocks_ += tiles.size();
  std::vector<Loaded> results(tiles.size(), Loaded(std::optional<terrain::HeightBlock>()));
  uint64_t at = 0;
  for (size_t k = 0; k < order.size(); ++k) {
    const size_t i = order[k].second;
    auto block = decodeLoaded(p, tiles[i], std::span(bytes).subspan(at, pieces[k]));
    at += pieces[k];
    results[i] = block ? Loaded(std::optional<terrain::HeightBlock>(std::move(*block)))
                       : Loaded(Error{block.error()});
  }
  return results;
}

std::string TileStore::location(const geo::TileId& tile) const {
  return source_->locationOf(formats::packName(formats::packOf(tile, manifest_.packTilesPerSide)));
}

}  // namespace globe::streaming
