#include "formats/image_pack.hpp"

#include <cstring>
#include <string>

#include "core/big_endian.hpp"
#include "core/crc32.hpp"

namespace globe::formats {
namespace {

constexpr char kImagePackMagic[8] = {'G', 'L', 'O', 'B', 'E', 'I', 'M', '1'};

}  // namespace

size_t ImagePackIndex::presentCount() const {
  size_t count = 0;
  for (const ImagePackEntry& entry : entries) count += entry.present() ? 1 : 0;
  return count;
}

std::vector<std::byte> encodeImagePack(const PackId& id, uint32_t tilesPerSide,
                                       const std::vector<std::vector<std::byte>>& payloads) {
  const uint64_t indexEnd = imagePackIndexEndOffset(tilesPerSide);
  uint64_t total = indexEnd + 4;
  uint32_t present = 0;
  for (const auto& payload : payloads) {
    total += payload.size();
    present += payload.empty() ? 0 : 1;
  }
  std::vector<std::byte> bytes(total);
  std::memcpy(bytes.data(), kImagePackMagic, sizeof kImagePackMagic);
  const uint32_t header[] = {
      kImagePackFormatVersion, id.level, id.x, id.y, tilesPerSide, present, 0, 0};
  for (size_t i = 0; i < std::size(header); ++i)
    core::storeBigEndian32(&bytes[8 + 4 * i], header[i]);
  uint64_t offset = indexEnd;
  for (size_t slot = 0; slot < payloads.size(); ++slot) {
    const auto& payload = payloads[slot];
    if (payload.empty()) continue;
    std::byte* entry = &bytes[kImagePackHeaderBytes + slot * kImagePackEntryBytes];
    core::storeBigEndian64(entry, offset);
    core::storeBigEndian32(entry + 8, static_cast<uint32_t>(payload.size()));
    core::storeBigEndian32(entry + 12, core::crc32(payload));
    std::memcpy(&bytes[offset], payload.data(), payload.size());
    offset += payload.size();
  }
  core::storeBigEndian32(&bytes[offset], core::crc32(std::span(bytes).first(indexEnd)));
  return bytes;
}

Result<ImagePackIndex> decodeImagePackIndex(std::span<const std::byte> headAndIndex,
                                            uint32_t trailerCrc, uint64_t fileBytes,
                                            const std::filesystem::path& path) {
  if (headAndIndex.size() < kImagePackHeaderBytes ||
      std::memcmp(headAndIndex.data(), kImagePackMagic, sizeof kImagePackMagic) != 0) {
    return packError(path, "not a globe imagery pack (bad magic or shorter than its header)");
  }
  uint32_t h[8];
  for (size_t i = 0; i < 8; ++i) h[i] = core::loadBigEndian32(&headAndIndex[8 + 4 * i]);
  if (h[0] != kImagePackFormatVersion) {
    return packError(path, "imagery pack format version " + std::to_string(h[0]) +
                               " (this globe reads " + std::to_string(kImagePackFormatVersion) +
                               ")");
  }
  ImagePackIndex index{{h[1], h[2], h[3]}, h[4], {}};
  const uint32_t p = index.tilesPerSide;
  if (p == 0 || p > kImagePackMaxTilesPerSide) {
    return packError(path, "tiles per side " + std::to_string(p) + " out of range 1.." +
                               std::to_string(kImagePackMaxTilesPerSide));
  }
  const uint64_t indexEnd = imagePackIndexEndOffset(p);
  const uint32_t present = h[5];
  if (fileBytes < indexEnd + 4 || headAndIndex.size() < indexEnd) {
    return packError(path, "truncated: " + std::to_string(fileBytes) +
                               " bytes cannot hold the header and index of " + std::to_string(p) +
                               "x" + std::to_string(p) + " tiles");
  }
  if (core::crc32(headAndIndex.first(indexEnd)) != trailerCrc) {
    return packError(path, "CRC mismatch in the header and index (corrupt pack)");
  }
  if (present > uint64_t{p} * p) return packError(path, "present tile count exceeds the slots");
  // Payloads lie back to back in slot order: anything else is a damaged or forged index.
  const uint64_t payloadEnd = fileBytes - 4;
  uint64_t expected = indexEnd;
  uint32_t seen = 0;
  index.entries.resize(size_t{p} * p);
  for (size_t slot = 0; slot < index.entries.size(); ++slot) {
    const std::byte* in = &headAndIndex[kImagePackHeaderBytes + slot * kImagePackEntryBytes];
    ImagePackEntry entry{core::loadBigEndian64(in), core::loadBigEndian32(in + 8),
                         core::loadBigEndian32(in + 12)};
    if (entry.present()) {
      if (entry.offset != expected || entry.lengthBytes == 0 ||
          entry.lengthBytes > kImageTileMaximumBytes || entry.offset > payloadEnd ||
          entry.lengthBytes > payloadEnd - entry.offset) {
        return packError(path, "index entry " + std::to_string(slot) + " (offset " +
                                   std::to_string(entry.offset) + ", " +
                                   std::to_string(entry.lengthBytes) +
                                   " bytes) points outside the payloads");
      }
      expected += entry.lengthBytes;
      ++seen;
    }
    index.entries[slot] = entry;
  }
  if (seen != present) return packError(path, "index disagrees with its present tile count");
  if (expected != payloadEnd) {
    return packError(path, "file is " + std::to_string(fileBytes) + " bytes but its index says " +
                               std::to_string(expected + 4) + " (truncated or corrupt)");
  }
  return index;
}

Result<void> checkImageTile(std::span<const std::byte> payload, const ImagePackEntry& entry,
                            size_t slot, const std::filesystem::path& path) {
  if (payload.size() != entry.lengthBytes || core::crc32(payload) != entry.crc) {
    return packError(path, "CRC mismatch in tile slot " + std::to_string(slot) + " (corrupt pack)");
  }
  return {};
}

Result<ImagePack> decodeImagePack(std::span<const std::byte> bytes,
                                  const std::filesystem::path& path) {
  if (bytes.size() < kImagePackHeaderBytes + 4) {
    return packError(path, "truncated: " + std::to_string(bytes.size()) + " bytes");
  }
  const uint32_t trailer = core::loadBigEndian32(&bytes[bytes.size() - 4]);
  auto index = decodeImagePackIndex(bytes, trailer, bytes.size(), path);
  if (!index) return Error{index.error()};
  ImagePack pack{std::move(*index), {}};
  pack.payloads.resize(pack.index.entries.size());
  for (size_t slot = 0; slot < pack.payloads.size(); ++slot) {
    const ImagePackEntry& entry = pack.index.entries[slot];
    if (!entry.present()) continue;
    const auto payload = bytes.subspan(entry.offset, entry.lengthBytes);
    if (auto checked = checkImageTile(payload, entry, slot, path); !checked) {
      return Error{checked.error()};
    }
    pack.payloads[slot].assign(payload.begin(), payload.end());
  }
  return pack;
}

}  // namespace globe::formats
