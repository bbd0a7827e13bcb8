#include "imagery_tiling/imagery_pixels.hpp"

#include <algorithm>
#include <cstdint>

#include "imagery_tiling/imagery_encoding.hpp"

namespace globe::imagery_tiling {
namespace {

constexpr size_t kPixels = size_t{kImageryTileSizePixels} * kImageryTileSizePixels;

}  // namespace

formats::ImageRgba transparentTile() {
  return {kImageryTileSizePixels, kImageryTileSizePixels, std::vector<uint8_t>(kPixels * 4, 0)};
}

bool anyCovered(const formats::ImageRgba& tile) {
  for (size_t i = 3; i < tile.pixels.size(); i += 4) {
    if (tile.pixels[i] != 0) return true;
  }
  return false;
}

bool fullyOpaque(const formats::ImageRgba& tile) {
  for (size_t i = 3; i < tile.pixels.size(); i += 4) {
    if (tile.pixels[i] != 255) return false;
  }
  return true;
}

void compositeOver(formats::ImageRgba& top, const formats::ImageRgba& under) {
  uint8_t* t = top.pixels.data();
  const uint8_t* u = under.pixels.data();
  for (size_t i = 0; i < top.pixels.size(); i += 4) {
    const uint32_t a = t[i + 3];
    const uint32_t b = u[i + 3];
    if (a == 255 || b == 0) continue;
    if (a == 0) {
      for (int k = 0; k < 4; ++k) t[i + k] = u[i + k];
      continue;
    }
    // Integer arithmetic in units of 1/255²: exact and the same on every machine.
    const uint32_t underWeight = b * (255 - a);  // /255²
    const uint32_t topWeight = a * 255;          // /255²
    const uint32_t total = topWeight + underWeight;
    for (int k = 0; k < 3; ++k) {
      t[i + k] =
          static_cast<uint8_t>((t[i + k] * topWeight + u[i + k] * underWeight + total / 2) / total);
    }
    t[i + 3] = static_cast<uint8_t>((total + 127) / 255);
  }
}

formats::ImageRgba averageChildren(
    const std::array<std::optional<formats::ImageRgba>, 4>& children) {
  formats::ImageRgba parent = transparentTile();
  constexpr int half = kImageryTileSizePixels / 2;
  for (size_t q = 0; q < 4; ++q) {
    if (!children[q]) continue;
    const uint8_t* c = children[q]->pixels.data();
    const int rowOffset = q >= 2 ? half : 0;
    const int columnOffset = q % 2 == 1 ? half : 0;
    for (int r = 0; r < half; ++r) {
      uint8_t* out =
          &parent.pixels[(size_t(rowOffset + r) * kImageryTileSizePixels + columnOffset) * 4];
      const uint8_t* row0 = c + size_t(2 * r) * kImageryTileSizePixels * 4;
      const uint8_t* row1 = row0 + size_t{kImageryTileSizePixels} * 4;
      for (int col = 0; col < half; ++col, out += 4) {
        const uint8_t* p[4] = {row0 + 8 * col, row0 + 8 * col + 4, row1 + 8 * col,
                               row1 + 8 * col + 4};
        const uint32_t alpha = p[0][3] + p[1][3] + p[2][3] + p[3][3];
        if (alpha == 0) continue;
        for (int k = 0; k < 3; ++k) {
          const uint32_t sum =
              p[0][k] * p[0][3] + p[1][k] * p[1][3] + p[2][k] * p[2][3] + p[3][k] * p[3][3];
          out[k] = static_cast<uint8_t>((sum + alpha / 2) / alpha);
        }
        out[3] = static_cast<uint8_t>((alpha + 2) / 4);
      }
    }
  }
  return parent;
}

formats::ImageRgba downsampleEdgeSampledChildren(
    const std::array<std::optional<formats::ImageRgba>, 4>& children) {
  constexpr int size = kImageryTileSizePixels;
  constexpr int grid = 2 * size - 1;
  // The stitched grid, straight RGBA; absent children leave it transparent.
  std::vector<uint8_t> samples(size_t{grid} * grid * 4, 0);
  for (size_t q = 0; q < 4; ++q) {
    if (!children[q]) continue;
    const int rowOffset = q >= 2 ? size - 1 : 0;
    const int columnOffset = q % 2 == 1 ? size - 1 : 0;
    for (int r = 0; r < size; ++r) {
      std::copy_n(&children[q]->pixels[size_t(r) * size * 4], size_t{size} * 4,
                  &samples[(size_t(rowOffset + r) * grid + columnOffset) * 4]);
    }
  }
  formats::ImageRgba parent = transparentTile();
  constexpr std::array<uint32_t, 3> kTaps{1, 2, 1};
  for (int r = 0; r < size; ++r) {
    for (int c = 0; c < size; ++c) {
      uint32_t weights = 0, alpha = 0;
      std::array<uint32_t, 3> colour{};
      // On the grid's border only along it: the neighbouring parent filters the same samples
      // for its own edge, so the two keep sharing them.
      const bool borderRow = r == 0 || r == size - 1, borderColumn = c == 0 || c == size - 1;
      for (int dy = -1; dy <= 1; ++dy) {
        if (borderRow && dy != 0) continue;
        const int y = 2 * r + dy;
        for (int dx = -1; dx <= 1; ++dx) {
          if (borderColumn && dx != 0) continue;
          const int x = 2 * c + dx;
          const uint32_t w = kTaps[size_t(dy + 1)] * kTaps[size_t(dx + 1)];
          const uint8_t* p = &samples[(size_t(y) * grid + x) * 4];
          weights += w;
          alpha += w * p[3];
          for (int k = 0; k < 3; ++k) colour[size_t(k)] += w * p[3] * p[k];
        }
      }
      if (alpha == 0) continue;
      uint8_t* out = &parent.pixels[(size_t(r) * size + c) * 4];
      for (int k = 0; k < 3; ++k) {
        out[k] = static_cast<uint8_t>((colour[size_t(k)] + alpha / 2) / alpha);
      }
      out[3] = static_cast<uint8_t>((alpha + weights / 2) / weights);
    }
  }
  return parent;
}

Result<std::vector<std::byte>> encodeTile(const formats::ImageRgba& tile, int jpegQuality,
                                          bool exactEdges) {
  return fullyOpaque(tile) ? encodeJpegFast(tile, jpegQuality, exactEdges) : encodePngFast(tile);
}

}  // namespace globe::imagery_tiling
