// A conditioned source read like the original (same path, format and grid): its samples held in
// memory, or spilled to an unlinked temporary file beside the pyramid and read a row at a time,
// so a continent of inputs does not have to fit in memory at once. Neither keeps the original
// open: thousands of inputs must not hold thousands of file descriptors.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>

#include "conditioning/dem_grid.hpp"
#include "core/result.hpp"
#include "rasters/raster_source.hpp"

namespace globe::tiling {

// One unlinked file in a directory (gone when the process ends) that every spilled source of a
// run is appended to: one descriptor however many sources spill. Appends and reads may come from
// several threads at once.
class SpillFile {
 public:
  static Result<std::shared_ptr<SpillFile>> create(const std::filesystem::path& directory);
  ~SpillFile();
  SpillFile(const SpillFile&) = delete;
  SpillFile& operator=(const SpillFile&) = delete;

  // Appends the bytes; returns the offset they start at. `what` names them in an error.
  Result<uint64_t> append(const void* data, size_t bytes, const std::string& what);
  Result<void> read(uint64_t offset, void* out, size_t bytes, const std::string& what) const;

 private:
  SpillFile(int fd, std::filesystem::path directory) : fd_(fd), directory_(std::move(directory)) {}
  int fd_;
  std::filesystem::path directory_;
  std::mutex mutex_;  // guards end_: each append reserves its range, then writes unlocked
  uint64_t end_ = 0;
};

std::unique_ptr<rasters::RasterSource> makeMemoryRaster(
    const rasters::RasterSource& original, std::shared_ptr<const conditioning::DemGrid> grid);

// Appends the grid's samples to the spill file.
Result<std::unique_ptr<rasters::RasterSource>> makeSpilledRaster(
    const rasters::RasterSource& original, const conditioning::DemGrid& grid,
    std::shared_ptr<SpillFile> file);

}  // namespace globe::tiling
