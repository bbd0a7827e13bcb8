#include "formats/tile_edges.hpp"

#include <stb_image.h>

#include <cstring>

namespace globe::formats {

std::vector<std::pair<int, int>> ringOrder(int widthPixels, int heightPixels) {
  std::vector<std::pair<int, int>> order;
  if (widthPixels < 2 || heightPixels < 2) return order;
  for (int c = 0; c < widthPixels; ++c) order.emplace_back(0, c);
  for (int c = 0; c < widthPixels; ++c) order.emplace_back(heightPixels - 1, c);
  for (int r = 1; r + 1 < heightPixels; ++r) {
    order.emplace_back(r, 0);
    order.emplace_back(r, widthPixels - 1);
  }
  return order;
}

std::vector<uint8_t> tileEdgeBytes(const ImageRgba& image) {
  std::vector<uint8_t> bytes;
  uint8_t previous[3] = {0, 0, 0};
  for (const auto& [row, column] : ringOrder(image.widthPixels, image.heightPixels)) {
    const size_t i = (static_cast<size_t>(row) * image.widthPixels + column) * 4;
    for (int c = 0; c < 3; ++c) {
      bytes.push_back(static_cast<uint8_t>(image.pixels[i + c] - previous[c]));
      previous[c] = image.pixels[i + c];
    }
  }
  return bytes;
}

std::vector<std::byte> tileEdgesHead(int widthPixels, int heightPixels) {
  std::vector<std::byte> head(kTileEdgesTagBytes + 4);
  std::memcpy(head.data(), kTileEdgesTag, kTileEdgesTagBytes);
  head[kTileEdgesTagBytes] = std::byte(static_cast<uint8_t>(widthPixels >> 8));
  head[kTileEdgesTagBytes + 1] = std::byte(static_cast<uint8_t>(widthPixels));
  head[kTileEdgesTagBytes + 2] = std::byte(static_cast<uint8_t>(heightPixels >> 8));
  head[kTileEdgesTagBytes + 3] = std::byte(static_cast<uint8_t>(heightPixels));
  return head;
}

bool restoreTileEdges(std::span<const std::byte> jpeg, ImageRgba& image) {
  auto at = [&](size_t i) { return static_cast<uint8_t>(jpeg[i]); };
  if (jpeg.size() < 4 || at(0) != 0xFF || at(1) != 0xD8) return false;
  // Marker segments up to the scan: FF xx, u16 length (itself included), payload.
  for (size_t i = 2; i + 4 <= jpeg.size();) {
    if (at(i) != 0xFF) return false;
    const uint8_t marker = at(i + 1);
    if (marker == 0xFF) {  // fill byte
      ++i;
      continue;
    }
    if (marker == 0xDA || marker == 0xD9) return false;  // the scan (or the end): none found
    const size_t length = (size_t{at(i + 2)} << 8) | at(i + 3);
    if (length < 2 || i + 2 + length > jpeg.size()) return false;
    const size_t payload = i + 4, payloadBytes = length - 2;
    if (marker == kTileEdgesMarker && payloadBytes >= kTileEdgesTagBytes + 4 &&
        std::memcmp(&jpeg[payload], kTileEdgesTag, kTileEdgesTagBytes) == 0) {
      const size_t dims = payload + kTileEdgesTagBytes;
      const int width = (at(dims) << 8) | at(dims + 1), height = (at(dims + 2) << 8) | at(dims + 3);
      if (width != image.widthPixels || height != image.heightPixels) return false;
      const auto ring = ringOrder(width, height);
      std::vector<char> bytes(ring.size() * 3);
      const size_t stream = dims + 4;
      const int inflated =
          stbi_zlib_decode_buffer(bytes.data(), static_cast<int>(bytes.size()),
                                  reinterpret_cast<const char*>(&jpeg[stream]),
                                  static_cast<int>(payload + payloadBytes - stream));
      if (inflated != static_cast<int>(bytes.size())) return false;
      uint8_t value[3] = {0, 0, 0};
      for (size_t k = 0; k < ring.size(); ++k) {
        const size_t p =
            (static_cast<size_t>(ring[k].first) * image.widthPixels + ring[k].second) * 4;
        for (int c = 0; c < 3; ++c) {
          value[c] = static_cast<uint8_t>(value[c] + static_cast<uint8_t>(bytes[k * 3 + c]));
          image.pixels[p + c] = value[c];
        }
      }
      return true;
    }
    i += 2 + length;
  }
  return false;
}

}  // namespace globe::formats
