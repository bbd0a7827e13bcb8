// The writing half of pmtiles.hpp: the same layout decodePmtilesHeader and
// decodePmtilesDirectory read.
#include <cmath>
#include <cstring>

#include "formats/pmtiles.hpp"

namespace globe::formats {
namespace {

void putU64(std::vector<std::byte>& b, size_t at, uint64_t v) {
  std::memcpy(b.data() + at, &v, 8);  // little-endian hosts, as the decoder
}
void putI32(std::vector<std::byte>& b, size_t at, int32_t v) { std::memcpy(b.data() + at, &v, 4); }
int32_t e7(double degrees) { return static_cast<int32_t>(std::lround(degrees * 1e7)); }

void putVarint(std::vector<std::byte>& out, uint64_t value) {
  while (value >= 0x80) {
    out.push_back(static_cast<std::byte>((value & 0x7f) | 0x80));
    value >>= 7;
  }
  out.push_back(static_cast<std::byte>(value));
}

}  // namespace

std::vector<std::byte> encodePmtilesHeader(const PmtilesHeader& h) {
  std::vector<std::byte> b(kPmtilesHeaderBytes);
  std::memcpy(b.data(), "PMTiles", 7);
  b[7] = std::byte{3};
  putU64(b, 8, h.rootOffset);
  putU64(b, 16, h.rootLength);
  putU64(b, 24, h.metadataOffset);
  putU64(b, 32, h.metadataLength);
  putU64(b, 40, h.leavesOffset);
  putU64(b, 48, h.leavesLength);
  putU64(b, 56, h.tileDataOffset);
  putU64(b, 64, h.tileDataLength);
  putU64(b, 72, h.addressedTiles);
  putU64(b, 80, h.tileEntries);
  putU64(b, 88, h.tileContents);
  b[96] = std::byte{static_cast<uint8_t>(h.clustered ? 1 : 0)};
  b[97] = static_cast<std::byte>(h.internalCompression);
  b[98] = static_cast<std::byte>(h.tileCompression);
  b[99] = static_cast<std::byte>(h.tileType);
  b[100] = std::byte{h.minZoom};
  b[101] = std::byte{h.maxZoom};
  putI32(b, 102, e7(h.westDegrees));
  putI32(b, 106, e7(h.southDegrees));
  putI32(b, 110, e7(h.eastDegrees));
  putI32(b, 114, e7(h.northDegrees));
  b[118] = std::byte{h.centerZoom};
  putI32(b, 119, e7(h.centerLongitudeDegrees));
  putI32(b, 123, e7(h.centerLatitudeDegrees));
  return b;
}

std::vector<std::byte> encodePmtilesDirectory(std::span<const PmtilesEntry> entries) {
  // Column by column (ids as deltas, run lengths, lengths, offsets) so that gzip finds the
  // repeats; an offset right after the previous entry's bytes is 0, any other is stored plus one.
  std::vector<std::byte> out;
  putVarint(out, entries.size());
  uint64_t lastId = 0;
  for (const PmtilesEntry& e : entries) {
    putVarint(out, e.tileId - lastId);
    lastId = e.tileId;
  }
  for (const PmtilesEntry& e : entries) putVarint(out, e.runLength);
  for (const PmtilesEntry& e : entries) putVarint(out, e.length);
  for (size_t i = 0; i < entries.size(); ++i) {
    const bool follows =
        i > 0 && entries[i].offset == entries[i - 1].offset + entries[i - 1].length;
    putVarint(out, follows ? 0 : entries[i].offset + 1);
  }
  return out;
}

}  // namespace globe::formats
