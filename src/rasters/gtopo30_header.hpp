// The GTOPO30 .HDR file: an ESRI BIL header restricted to one band of 16-bit signed heights.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "core/result.hpp"

namespace globe::rasters {

// The height that marks "no data" (sea in GTOPO30) everywhere in globe.
inline constexpr int16_t kNoDataHeight = -9999;

struct Gtopo30Header {
  char byteOrder = 'M';        // BYTEORDER: M (Motorola, big-endian) or I (Intel)
  std::string layout = "BIL";  // LAYOUT
  int64_t rows = 0, cols = 0;  // NROWS, NCOLS
  int64_t bands = 1;           // NBANDS
  int64_t bitsPerSample = 16;  // NBITS
  int64_t bandRowBytes = 0, totalRowBytes = 0, bandGapBytes = 0;
  int32_t noData = -9999;                       // NODATA
  double ulxMapDegrees = 0, ulyMapDegrees = 0;  // centre of the upper-left sample
  double xDimDegrees = 0, yDimDegrees = 0;
};

// Keys are case-insensitive and unknown keys are ignored; every inconsistency is an error that
// names fileNameForMessages, the key and the value.
Result<Gtopo30Header> parseGtopo30Header(std::string_view text,
                                         const std::string& fileNameForMessages);

// GTOPO30's key order; doubles in the shortest form that round-trips.
std::string formatGtopo30Header(const Gtopo30Header& header);

}  // namespace globe::rasters
