// GTOPO30 rasters (.DEM 16-bit BIL + .HDR): whole-raster read/write and row access without loading.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/result.hpp"
#include "rasters/gtopo30_header.hpp"

namespace globe::rasters {

struct Gtopo30Raster {
  Gtopo30Header header;
  std::vector<int16_t> heights;  // rows*cols, row-major from the north-west, host byte order
  // kNoDataHeight when (row, col) is outside the raster.
  int16_t at(int64_t row, int64_t col) const;
};

// path may be the .DEM, the .HDR or the stem (extension case-insensitive: .DEM/.dem, .HDR/.hdr).
Result<Gtopo30Raster> readGtopo30(const std::filesystem::path& path);
// Writes STEM.DEM, STEM.HDR, STEM.PRJ (WGS84 geographic) and STEM.STX (band 1 min max mean stddev
// of valid samples), each atomically. Always big-endian; a trailing .DEM/.HDR on stem is dropped.
Result<void> writeGtopo30(const std::filesystem::path& stem, const Gtopo30Raster& raster);

// The data file (.DEM, or .BIL) and .HDR of a GTOPO30 raster named by either file or their stem.
struct Gtopo30Paths {
  std::filesystem::path data, header;
};
Result<Gtopo30Paths> findGtopo30Files(const std::filesystem::path& path);

// An open GTOPO30 data file whose size has been checked against its header; rows are read on
// demand with pread, so it is cheap to keep open and safe to share between threads.
class Gtopo30File {
 public:
  static Result<Gtopo30File> open(const std::filesystem::path& path);
  Gtopo30File(Gtopo30File&& other) noexcept;
  Gtopo30File& operator=(Gtopo30File&& other) noexcept;
  Gtopo30File(const Gtopo30File&) = delete;
  Gtopo30File& operator=(const Gtopo30File&) = delete;
  ~Gtopo30File();

  const Gtopo30Header& header() const { return header_; }
  const Gtopo30Paths& paths() const { return paths_; }
  // `count` samples of `row` from `firstColumn`, in host byte order, exactly as stored (no
  // no-data mapping). The span must lie inside the raster.
  Result<void> readSamples(int64_t row, int64_t firstColumn, int64_t count, int16_t* out) const;

 private:
  Gtopo30File(Gtopo30Paths paths, Gtopo30Header header, int fd);
  Gtopo30Paths paths_;
  Gtopo30Header header_;
  int fd_ = -1;
};

}  // namespace globe::rasters
