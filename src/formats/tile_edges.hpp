// Exact edge samples carried inside a JPEG imagery tile. Edge-sampled tiles share their border
// samples with their neighbours (ImageryPixelGrid::Edges), but each tile's JPEG rounds them its
// own way, up to ~2 levels: a faint line along tile edges where the picture is smooth (0° across
// England, ±180° across the Pacific). The tiler stores the border ring (rows 0 and S−1, columns 0
// and S−1) losslessly in an APP9 segment, which JPEG decoders skip, and decodeImageRgba puts it
// back, so neighbouring tiles' edges are the same samples again. Readers without it draw the
// JPEG as before.
//
//   APP9 payload: "GLOBEEDGE1", u16 width, u16 height (big-endian), then the zlib stream of the
//   ring's RGB bytes in ringOrder, each byte stored as its difference from the previous one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "formats/image_io.hpp"

namespace globe::formats {

inline constexpr uint8_t kTileEdgesMarker = 0xE9;  // APP9
inline constexpr char kTileEdgesTag[] = "GLOBEEDGE1";
inline constexpr size_t kTileEdgesTagBytes = sizeof(kTileEdgesTag) - 1;

// The ring's pixels (row, column) in order: row 0, row S−1, then columns 0 and S−1 of rows 1..S−2.
std::vector<std::pair<int, int>> ringOrder(int widthPixels, int heightPixels);

// The ring's RGB bytes, delta-coded (what the segment compresses).
std::vector<uint8_t> tileEdgeBytes(const ImageRgba& image);

// The payload's head: tag, width, height; the zlib stream follows it.
std::vector<std::byte> tileEdgesHead(int widthPixels, int heightPixels);

// Puts the ring of `jpeg`'s edge segment into `image` (its decoded pixels); false, and the image
// untouched, where there is none or it does not fit the image (a damaged segment is ignored: the
// tile is still whole).
bool restoreTileEdges(std::span<const std::byte> jpeg, ImageRgba& image);

}  // namespace globe::formats
