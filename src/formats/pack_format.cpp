#include "formats/pack_format.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <string>

#include "core/big_endian.hpp"
#include "core/crc32.hpp"
#include "compression/deflate_bytes.hpp"
#include "formats/pack_block_codec.hpp"
#include "formats/pack_index_codec.hpp"

namespace globe::formats {
namespace {

constexpr char kPackMagic[8] = {'G', 'L', 'O', 'B', 'E', 'P', 'K', '1'};

void storeEntry(std::byte* out, const PackEntry& entry, uint32_t formatVersion) {
  core::storeBigEndian64(out, entry.blockOffset);
  core::storeBigEndian16(out + 8, static_cast<uint16_t>(entry.vertexRange.minimumMeters));
  core::storeBigEndian16(out + 10, static_cast<uint16_t>(entry.vertexRange.maximumMeters));
  core::storeBigEndian16(out + 12, static_cast<uint16_t>(entry.subtreeRange.minimumMeters));
  core::storeBigEndian16(out + 14, static_cast<uint16_t>(entry.subtreeRange.maximumMeters));
  if (formatVersion >= 3) {
    core::storeBigEndian32(out + 16, std::bit_cast<uint32_t>(entry.geometricErrorMeters));
  }
  if (formatVersion >= 4) core::storeBigEndian32(out + 20, entry.blockCrc);
}

PackEntry loadEntry(const std::byte* in, uint32_t formatVersion) {
  PackEntry entry;
  entry.blockOffset = core::loadBigEndian64(in);
  entry.vertexRange = {static_cast<int16_t>(core::loadBigEndian16(in + 8)),
                       static_cast<int16_t>(core::loadBigEndian16(in + 10))};
  entry.subtreeRange = {static_cast<int16_t>(core::loadBigEndian16(in + 12)),
                        static_cast<int16_t>(core::loadBigEndian16(in + 14))};
  if (formatVersion >= 3) {
    entry.geometricErrorMeters = std::bit_cast<float>(core::loadBigEndian32(in + 16));
  }
  if (formatVersion >= 4) entry.blockCrc = core::loadBigEndian32(in + 20);
  return entry;
}

// Visits a stored block's samples in file order: (N+2w)² with the apron (rows and columns
// -w..N+w-1, w = terrain::kApronWidth), else N².
template <class Visit>
void forEachStoredSample(const PackLayout& layout, Visit visit) {
  const auto n = static_cast<int>(layout.verticesPerSide);
  const int first = layout.hasApron() ? -terrain::kApronWidth : 0;
  const int end = layout.hasApron() ? n + terrain::kApronWidth : n;
  for (int row = first; row < end; ++row) {
    for (int column = first; column < end; ++column) {
      const bool inside = row >= 0 && row < n && column >= 0 && column < n;
      visit(inside, inside ? static_cast<size_t>(row * n + column)
                           : terrain::apronIndex(row, column, layout.verticesPerSide));
    }
  }
}

// The raw big-endian samples of a slot's block (versions 3 to 5 store them so; version 6
// compresses them).
std::vector<std::byte> rawBlock(const Pack& pack, size_t slot) {
  std::vector<std::byte> bytes(pack.layout.blockBytes());
  std::byte* out = bytes.data();
  const std::span<const int16_t> heights = pack.block(slot), apron = pack.apron(slot);
  forEachStoredSample(pack.layout, [&](bool inside, size_t index) {
    core::storeBigEndian16(out, static_cast<uint16_t>(inside ? heights[index] : apron[index]));
    out += 2;
  });
  return bytes;
}

void storeHeader(std::byte* out, const PackId& id, const PackLayout& layout, size_t present,
                 uint32_t indexBytes) {
  std::memcpy(out, kPackMagic, sizeof kPackMagic);
  const uint32_t header[] = {layout.formatVersion,
                             id.level,
                             id.x,
                             id.y,
                             layout.tilesPerSide,
                             layout.verticesPerSide,
                             static_cast<uint32_t>(present),
                             indexBytes};
  for (size_t i = 0; i < std::size(header); ++i) core::storeBigEndian32(out + 8 + 4 * i, header[i]);
}

void appendCrc(std::vector<std::byte>& bytes) {
  const size_t body = bytes.size();
  bytes.resize(body + 4);
  core::storeBigEndian32(&bytes[body], core::crc32(std::span(bytes).first(body)));
}

// Version 6: the blocks compressed in storage order, the index as columns.
std::vector<std::byte> encodePackV6(const Pack& pack) {
  const PackLayout& layout = pack.layout;
  const std::vector<size_t> order = storageOrder(pack.entries, layout.tilesPerSide);
  const size_t side = layout.verticesPerSide + 2 * terrain::kApronWidth;
  std::vector<PackEntry> entries = pack.entries;
  std::vector<std::byte> blocks;
  for (size_t slot : order) {
    const std::vector<std::byte> stored = encodeCompressedBlock(rawBlock(pack, slot), side);
    entries[slot].storedBytes = static_cast<uint32_t>(stored.size());
    blocks.insert(blocks.end(), stored.begin(), stored.end());
  }
  const std::vector<std::byte> index =
      compression::zlibCompress(encodeIndexColumns(entries, order, layout.tilesPerSide), 9);
  std::vector<std::byte> bytes(kPackHeaderBytes);
  storeHeader(bytes.data(), pack.id, layout, order.size(), static_cast<uint32_t>(index.size()));
  bytes.insert(bytes.end(), index.begin(), index.end());
  bytes.insert(bytes.end(), blocks.begin(), blocks.end());
  appendCrc(bytes);
  return bytes;
}

}  // namespace

PackId packOf(const geo::TileId& tile, uint32_t tilesPerSide) {
  return {tile.level, tile.x / tilesPerSide, tile.y / tilesPerSide};
}

size_t slotOf(const geo::TileId& tile, uint32_t tilesPerSide) {
  return size_t{tile.y % tilesPerSide} * tilesPerSide + tile.x % tilesPerSide;
}

geo::TileId tileOfSlot(const PackId& pack, size_t slot, uint32_t tilesPerSide) {
  const auto localX = static_cast<uint32_t>(slot % tilesPerSide);
  const auto localY = static_cast<uint32_t>(slot / tilesPerSide);
  return {pack.level, pack.x * tilesPerSide + localX, pack.y * tilesPerSide + localY};
}

std::string packName(const PackId& pack) {
  return "L" + std::to_string(pack.level) + "/" + std::to_string(pack.x) + "_" +
         std::to_string(pack.y) + ".pack";
}

std::filesystem::path packPath(const std::filesystem::path& pyramidDir, const PackId& pack) {
  return pyramidDir / packName(pack);
}

Pack Pack::empty(const PackId& id, const PackLayout& layout) {
  Pack pack{id, layout, {}, {}, {}};
  pack.entries.resize(layout.slotCount());
  pack.heights.assign(layout.slotCount() * layout.verticesPerSide * layout.verticesPerSide,
                      terrain::kNoDataHeight);
  if (layout.hasApron()) {
    pack.aprons.assign(layout.slotCount() * terrain::apronSampleCount(layout.verticesPerSide),
                       terrain::kNoDataHeight);
  }
  return pack;
}

Pack Pack::unset(const PackId& id, const PackLayout& layout) {
  Pack pack{id, layout, {}, {}, {}};
  pack.entries.resize(layout.slotCount());
  pack.heights.resize(layout.slotCount() * layout.verticesPerSide * layout.verticesPerSide);
  if (layout.hasApron()) {
    pack.aprons.resize(layout.slotCount() * terrain::apronSampleCount(layout.verticesPerSide));
  }
  return pack;
}

std::span<int16_t> Pack::block(size_t slot) {
  const size_t n = size_t{layout.verticesPerSide} * layout.verticesPerSide;
  return {heights.data() + slot * n, n};
}

std::span<const int16_t> Pack::block(size_t slot) const {
  const size_t n = size_t{layout.verticesPerSide} * layout.verticesPerSide;
  return {heights.data() + slot * n, n};
}

std::span<int16_t> Pack::apron(size_t slot) {
  if (aprons.empty()) return {};
  const size_t n = terrain::apronSampleCount(layout.verticesPerSide);
  return {aprons.data() + slot * n, n};
}

std::span<const int16_t> Pack::apron(size_t slot) const {
  if (aprons.empty()) return {};
  const size_t n = terrain::apronSampleCount(layout.verticesPerSide);
  return {aprons.data() + slot * n, n};
}

size_t Pack::presentCount() const {
  size_t count = 0;
  for (const PackEntry& entry : entries) count += entry.present() ? 1 : 0;
  return count;
}

std::vector<std::byte> encodePack(const Pack& pack) {
  if (pack.layout.hasCompressedBlocks()) return encodePackV6(pack);
  if (pack.layout.hasCompressedIndex()) {
    // The uncompressed form with offsets from the index's end, whose index is then compressed.
    Pack uncompressed = pack;
    uncompressed.layout.formatVersion = 4;
    uncompressed.layout.indexBytes = 0;
    const std::vector<std::byte> plain = encodePack(uncompressed);
    const size_t plainIndexEnd = uncompressed.layout.indexEndOffset();
    std::vector<std::byte> entries(plain.begin() + kPackHeaderBytes,
                                   plain.begin() + static_cast<ptrdiff_t>(plainIndexEnd));
    for (size_t slot = 0; slot < pack.layout.slotCount(); ++slot) {
      std::byte* entry = &entries[slot * packEntryBytes(4)];
      const uint64_t offset = core::loadBigEndian64(entry);
      core::storeBigEndian64(entry, offset == 0 ? 0 : offset - plainIndexEnd + 1);
    }
    const std::vector<std::byte> index = compression::zlibCompress(entries, 9);
    std::vector<std::byte> bytes(plain.begin(), plain.begin() + kPackHeaderBytes);
    core::storeBigEndian32(&bytes[8], pack.layout.formatVersion);
    core::storeBigEndian32(&bytes[36], static_cast<uint32_t>(index.size()));
    bytes.insert(bytes.end(), index.begin(), index.end());
    bytes.insert(bytes.end(), plain.begin() + static_cast<ptrdiff_t>(plainIndexEnd),
                 plain.end() - 4);
    const size_t body = bytes.size();
    bytes.resize(body + 4);
    core::storeBigEndian32(&bytes[body], core::crc32(std::span(bytes).first(body)));
    return bytes;
  }
  const PackLayout& layout = pack.layout;
  const size_t present = pack.presentCount();
  std::vector<std::byte> bytes(layout.fileBytes(present));
  std::memcpy(bytes.data(), kPackMagic, sizeof kPackMagic);
  const uint32_t header[] = {layout.formatVersion,
                             pack.id.level,
                             pack.id.x,
                             pack.id.y,
                             layout.tilesPerSide,
                             layout.verticesPerSide,
                             static_cast<uint32_t>(present),
                             0};
  for (size_t i = 0; i < std::size(header); ++i)
    core::storeBigEndian32(&bytes[8 + 4 * i], header[i]);

  uint64_t offset = layout.indexEndOffset();
  for (size_t slot = 0; slot < layout.slotCount(); ++slot) {
    PackEntry entry = pack.entries[slot];
    if (entry.present()) {
      entry.blockOffset = offset;
      std::byte* out = &bytes[offset];
      const std::span<const int16_t> heights = pack.block(slot), apron = pack.apron(slot);
      forEachStoredSample(layout, [&](bool inside, size_t index) {
        core::storeBigEndian16(out, static_cast<uint16_t>(inside ? heights[index] : apron[index]));
        out += 2;
      });
      entry.blockCrc = layout.hasBlockCrc()
                           ? core::crc32(std::span(bytes).subspan(offset, layout.blockBytes()))
                           : 0;
      offset += layout.blockBytes();
    }
    storeEntry(&bytes[kPackHeaderBytes + slot * layout.entryBytes()], entry, layout.formatVersion);
  }
  const size_t body = bytes.size() - 4;
  core::storeBigEndian32(&bytes[body], core::crc32(std::span(bytes).first(body)));
  return bytes;
}

std::optional<uint32_t> packFormatVersionOf(std::span<const std::byte> head) {
  if (head.size() < kPackHeaderBytes || std::memcmp(head.data(), kPackMagic, 8) != 0) {
    return std::nullopt;
  }
  return core::loadBigEndian32(&head[8]);
}

Result<void> checkPackFormatVersion(uint32_t version, const std::filesystem::path& path) {
  if (version >= kOldestReadPackFormatVersion && version <= kPackFormatVersion) return {};
  if (version < kOldestReadPackFormatVersion) {
    return packError(path, "pack format version " + std::to_string(version) +
                               " was made by an older globe-tiler (samples below 0 m meant sea; "
                               "version " +
                               std::to_string(kPackFormatVersion) +
                               " tells water from land below sea level): the pyramid must be "
                               "re-tiled with this globe-tiler");
  }
  return packError(path, "pack format version " + std::to_string(version) +
                             " is newer than this globe reads (" +
                             std::to_string(kPackFormatVersion) + ")");
}

std::optional<uint64_t> packIndexEndOffset(std::span<const std::byte> head) {
  const std::optional<uint32_t> version = packFormatVersionOf(head);
  if (!version) return std::nullopt;
  if (*version >= 5) return kPackHeaderBytes + uint64_t{core::loadBigEndian32(&head[36])};
  const uint32_t tiles = core::loadBigEndian32(&head[24]);
  return kPackHeaderBytes + uint64_t{tiles} * tiles * packEntryBytes(*version);
}

namespace {

Result<PackIndex> decodeIndexV6(PackIndex index, uint32_t present,
                                std::span<const std::byte> headAndIndex, uint64_t fileBytes,
                                const std::filesystem::path& path) {
  const PackLayout& layout = index.layout;
  if (present > layout.slotCount()) {
    return packError(path, "pack header says " + std::to_string(present) + " tiles in " +
                               std::to_string(layout.slotCount()) + " slots (corrupt pack)");
  }
  const uint64_t indexEnd = layout.indexEndOffset();
  if (fileBytes < indexEnd + 4) {
    return packError(path, "file is " + std::to_string(fileBytes) +
                               " bytes, shorter than its header and index (truncated or corrupt)");
  }
  if (headAndIndex.size() < indexEnd) return packError(path, "pack index is truncated");
  std::vector<std::byte> columns(presenceBitmapBytes(layout.tilesPerSide) +
                                 indexColumnBytes(present));
  if (!compression::zlibInflateExactly(headAndIndex.subspan(kPackHeaderBytes, layout.indexBytes), columns)) {
    return packError(path, "pack index does not inflate to its " + std::to_string(present) +
                               " tiles (corrupt pack)");
  }
  if (auto decoded = decodeIndexColumns(columns, layout.tilesPerSide, present, indexEnd,
                                        layout.maxStoredBlockBytes(), index.entries);
      !decoded) {
    return packError(path, decoded.error() + " (corrupt pack)");
  }
  uint64_t end = indexEnd;
  for (const PackEntry& entry : index.entries) {
    if (entry.present()) end = std::max(end, entry.blockOffset + entry.storedBytes);
  }
  if (end + 4 != fileBytes) {
    return packError(path, "file is " + std::to_string(fileBytes) + " bytes but its index says " +
                               std::to_string(end + 4) + " (truncated or corrupt)");
  }
  return index;
}

}  // namespace

Result<PackIndex> decodePackIndex(std::span<const std::byte> headAndIndex, uint64_t fileBytes,
                                  const std::filesystem::path& path) {
  const std::optional<uint32_t> version = packFormatVersionOf(headAndIndex);
  if (!version) {
    return packError(path, "not a globe pack file (bad magic or shorter than its header)");
  }
  if (auto supported = checkPackFormatVersion(*version, path); !supported) {
    return Error{supported.error()};
  }
  uint32_t h[8];
  for (size_t i = 0; i < 8; ++i) h[i] = core::loadBigEndian32(&headAndIndex[8 + 4 * i]);
  PackIndex index{{h[1], h[2], h[3]}, {h[4], h[5], *version, *version >= 5 ? h[7] : 0}, {}};
  const PackLayout& layout = index.layout;
  if (layout.tilesPerSide == 0 || layout.tilesPerSide > 1024 ||
      !terrain::isValidBlockSize(layout.verticesPerSide)) {
    return packError(path, "pack header has an invalid tiles-per-side or block size");
  }
  const uint32_t present = h[6];
  if (layout.hasCompressedBlocks())
    return decodeIndexV6(std::move(index), present, headAndIndex, fileBytes, path);
  if (present > layout.slotCount() || fileBytes != layout.fileBytes(present)) {
    return packError(
        path, "file is " + std::to_string(fileBytes) + " bytes but its header says " +
                  std::to_string(layout.fileBytes(std::min<size_t>(present, layout.slotCount()))) +
                  " (truncated or corrupt)");
  }
  if (headAndIndex.size() < layout.indexEndOffset()) {
    return packError(path, "pack index is truncated");
  }
  // Version 5: the entries inflated, their offsets made the file's.
  std::vector<std::byte> inflated;
  std::span<const std::byte> entries =
      headAndIndex.subspan(kPackHeaderBytes, layout.indexEndOffset() - kPackHeaderBytes);
  if (layout.hasCompressedIndex()) {
    inflated.resize(layout.slotCount() * layout.entryBytes());
    if (!compression::zlibInflateExactly(entries, inflated)) {
      return packError(path, "pack index does not inflate to its " +
                                 std::to_string(layout.slotCount()) + " entries (corrupt pack)");
    }
    entries = inflated;
  }
  index.entries.resize(layout.slotCount());
  uint32_t seen = 0;
  for (size_t slot = 0; slot < layout.slotCount(); ++slot) {
    PackEntry entry = loadEntry(&entries[slot * layout.entryBytes()], *version);
    if (layout.hasCompressedIndex() && entry.present()) {
      entry.blockOffset += layout.indexEndOffset() - 1;
    }
    if (entry.present()) {
      entry.storedBytes = static_cast<uint32_t>(layout.blockBytes());
      const uint64_t relative = entry.blockOffset - layout.indexEndOffset();
      if (entry.blockOffset < layout.indexEndOffset() || relative % layout.blockBytes() != 0 ||
          relative / layout.blockBytes() >= present) {
        return packError(path,
                         "pack index entry " + std::to_string(slot) + " points outside the blocks");
      }
      ++seen;
    }
    index.entries[slot] = entry;
  }
  if (seen != present) return packError(path, "pack index disagrees with its tile count");
  return index;
}

void decodeBlock(std::span<const std::byte> bytes, const PackLayout& layout,
                 std::span<int16_t> heights, std::span<int16_t> apron) {
  size_t offset = 0;
  forEachStoredSample(layout, [&](bool inside, size_t index) {
    (inside ? heights : apron)[index] = static_cast<int16_t>(core::loadBigEndian16(&bytes[offset]));
    offset += 2;
  });
}

Result<void> decodeStoredBlock(std::span<const std::byte> stored, const PackLayout& layout,
                               const PackEntry& entry, std::span<int16_t> heights,
                               std::span<int16_t> apron) {
  if (layout.hasCompressedBlocks()) {
    std::vector<std::byte> samples(layout.blockBytes());
    if (auto inflated = decodeCompressedBlock(
            stored, layout.verticesPerSide + 2 * terrain::kApronWidth, samples);
        !inflated) {
      return makeError("the block " + inflated.error() + " (corrupt pack)");
    }
    decodeBlock(samples, layout, heights, apron);
    return {};
  }
  if (stored.size() != layout.blockBytes()) return makeError("the block is cut short");
  if (layout.hasBlockCrc() && core::crc32(stored) != entry.blockCrc) {
    return makeError("the block fails its CRC (corrupt pack)");
  }
  decodeBlock(stored, layout, heights, apron);
  return {};
}

Result<Pack> decodePack(std::span<const std::byte> bytes, const std::filesystem::path& path) {
  auto index = decodePackIndex(bytes, bytes.size(), path);
  if (!index) return Error{index.error()};
  // Pack::empty holds every slot's block: bound what a (small) hostile header can make us allocate.
  const uint64_t memoryBytes = uint64_t{index->layout.slotCount()} * index->layout.blockBytes();
  if (memoryBytes > kPackMaximumMemoryBytes) {
    return packError(path, "pack of " + std::to_string(index->layout.tilesPerSide) + "x" +
                               std::to_string(index->layout.tilesPerSide) + " tiles of " +
                               std::to_string(index->layout.verticesPerSide) +
                               " vertices would need " + std::to_string(memoryBytes >> 20) +
                               " MiB in memory (more than " +
                               std::to_string(kPackMaximumMemoryBytes >> 20) + " MiB)");
  }
  const size_t body = bytes.size() - 4;
  if (core::crc32(bytes.first(body)) != core::loadBigEndian32(&bytes[body])) {
    return packError(path, "CRC mismatch (corrupt pack)");
  }
  Pack pack = Pack::unset(index->id, index->layout);  // every present slot is decoded whole
  pack.entries = std::move(index->entries);
  for (size_t slot = 0; slot < pack.layout.slotCount(); ++slot) {
    const PackEntry& entry = pack.entries[slot];
    if (!entry.present()) continue;
    if (auto decoded = decodeStoredBlock(bytes.subspan(entry.blockOffset, entry.storedBytes),
                                         pack.layout, entry, pack.block(slot), pack.apron(slot));
        !decoded) {
      return packError(path, geo::tileName(tileOfSlot(pack.id, slot, pack.layout.tilesPerSide)) +
                                 ": " + decoded.error());
    }
  }
  return pack;
}

}  // namespace globe::formats
