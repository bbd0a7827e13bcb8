#include "formats/pmtiles.hpp"

#include <algorithm>
#include <cstring>

namespace globe::formats {
namespace {

uint64_t u64(std::span<const std::byte> b, size_t at) {
  uint64_t v = 0;
  std::memcpy(&v, b.data() + at, 8);  // little-endian hosts
  return v;
}
int32_t i32(std::span<const std::byte> b, size_t at) {
  int32_t v = 0;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}
uint8_t u8(std::span<const std::byte> b, size_t at) { return static_cast<uint8_t>(b[at]); }

class Varints {
 public:
  explicit Varints(std::span<const std::byte> bytes) : bytes_(bytes) {}
  std::optional<uint64_t> next() {
    uint64_t value = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      if (at_ >= bytes_.size()) return std::nullopt;
      const auto byte = static_cast<uint8_t>(bytes_[at_++]);
      value |= static_cast<uint64_t>(byte & 0x7f) << shift;
      if ((byte & 0x80) == 0) return value;
    }
    return std::nullopt;  // more than ten bytes
  }
  size_t remaining() const { return bytes_.size() - at_; }

 private:
  std::span<const std::byte> bytes_;
  size_t at_ = 0;
};

}  // namespace

Result<PmtilesHeader> decodePmtilesHeader(std::span<const std::byte> b, uint64_t fileBytes,
                                          const std::string& name) {
  if (b.size() < kPmtilesHeaderBytes || std::memcmp(b.data(), "PMTiles", 7) != 0) {
    return makeError(name + ": not a PMTiles archive");
  }
  if (u8(b, 7) != 3) {
    return makeError(name + ": PMTiles version " + std::to_string(u8(b, 7)) +
                     " (version 3 is read; convert older archives with `pmtiles convert`)");
  }
  PmtilesHeader h;
  h.rootOffset = u64(b, 8);
  h.rootLength = u64(b, 16);
  h.metadataOffset = u64(b, 24);
  h.metadataLength = u64(b, 32);
  h.leavesOffset = u64(b, 40);
  h.leavesLength = u64(b, 48);
  h.tileDataOffset = u64(b, 56);
  h.tileDataLength = u64(b, 64);
  h.addressedTiles = u64(b, 72);
  h.tileEntries = u64(b, 80);
  h.tileContents = u64(b, 88);
  h.clustered = u8(b, 96) == 1;
  h.internalCompression = static_cast<PmtilesCompression>(u8(b, 97));
  h.tileCompression = static_cast<PmtilesCompression>(u8(b, 98));
  h.tileType = static_cast<PmtilesTileType>(u8(b, 99));
  h.minZoom = u8(b, 100);
  h.maxZoom = u8(b, 101);
  h.westDegrees = i32(b, 102) / 1e7;
  h.southDegrees = i32(b, 106) / 1e7;
  h.eastDegrees = i32(b, 110) / 1e7;
  h.northDegrees = i32(b, 114) / 1e7;
  h.centerZoom = u8(b, 118);
  h.centerLongitudeDegrees = i32(b, 119) / 1e7;
  h.centerLatitudeDegrees = i32(b, 123) / 1e7;
  auto within = [&](uint64_t offset, uint64_t length) {
    return offset <= fileBytes && length <= fileBytes - offset;
  };
  if (!within(h.rootOffset, h.rootLength) || !within(h.leavesOffset, h.leavesLength) ||
      !within(h.tileDataOffset, h.tileDataLength) || !within(h.metadataOffset, h.metadataLength)) {
    return makeError(name + ": a section lies beyond the archive's " + std::to_string(fileBytes) +
                     " bytes (truncated?)");
  }
  if (h.minZoom > h.maxZoom || h.maxZoom > 26) {
    return makeError(name + ": zooms " + std::to_string(h.minZoom) + ".." +
                     std::to_string(h.maxZoom) + " (0..26 expected)");
  }
  if (!(h.westDegrees >= -180 && h.eastDegrees <= 180 && h.southDegrees >= -90 &&
        h.northDegrees <= 90 && h.westDegrees < h.eastDegrees && h.southDegrees < h.northDegrees)) {
    h.westDegrees = -180, h.southDegrees = -90, h.eastDegrees = 180, h.northDegrees = 90;
  }
  return h;
}

Result<std::vector<PmtilesEntry>> decodePmtilesDirectory(std::span<const std::byte> bytes,
                                                         const std::string& name) {
  Varints v(bytes);
  auto truncated = [&] { return makeError(name + ": a truncated PMTiles directory"); };
  const auto count = v.next();
  if (!count) return truncated();
  // Every entry takes at least four bytes.
  if (*count > v.remaining() / 4 + 1) return truncated();
  std::vector<PmtilesEntry> entries(*count);
  uint64_t id = 0;
  for (PmtilesEntry& e : entries) {
    const auto delta = v.next();
    if (!delta) return truncated();
    id += *delta;
    e.tileId = id;
  }
  for (PmtilesEntry& e : entries) {
    const auto run = v.next();
    if (!run || *run > UINT32_MAX) return truncated();
    e.runLength = static_cast<uint32_t>(*run);
  }
  for (PmtilesEntry& e : entries) {
    const auto length = v.next();
    if (!length || *length > UINT32_MAX) return truncated();
    e.length = static_cast<uint32_t>(*length);
  }
  for (size_t i = 0; i < entries.size(); ++i) {
    const auto offset = v.next();
    if (!offset) return truncated();
    // Stored plus one; 0 after the first: right after the previous entry's bytes.
    if (*offset == 0 && i == 0)
      return makeError(name + ": a PMTiles directory's first offset is 0");
    entries[i].offset = *offset == 0 ? entries[i - 1].offset + entries[i - 1].length : *offset - 1;
  }
  return entries;
}

uint64_t pmtilesTileId(uint32_t z, uint64_t x, uint64_t y) {
  uint64_t acc = 0;
  for (uint32_t k = 0; k < z; ++k) acc += uint64_t{1} << (2 * k);
  uint64_t d = 0;
  for (uint64_t s = (uint64_t{1} << z) / 2; s > 0; s /= 2) {
    const uint64_t rx = (x & s) > 0 ? 1 : 0;
    const uint64_t ry = (y & s) > 0 ? 1 : 0;
    d += s * s * ((3 * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) {
        x = s - 1 - x;
        y = s - 1 - y;
      }
      std::swap(x, y);
    }
  }
  return acc + d;
}

std::optional<PmtilesEntry> findPmtilesEntry(const std::vector<PmtilesEntry>& entries,
                                             uint64_t tileId) {
  auto it = std::upper_bound(entries.begin(), entries.end(), tileId,
                             [](uint64_t id, const PmtilesEntry& e) { return id < e.tileId; });
  if (it == entries.begin()) return std::nullopt;
  const PmtilesEntry& e = *std::prev(it);
  if (e.runLength == 0) return e;  // a leaf directory: search it
  if (tileId - e.tileId < e.runLength) return e;
  return std::nullopt;
}

}  // namespace globe::formats
