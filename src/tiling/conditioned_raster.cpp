#include "tiling/conditioned_raster.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

namespace globe::tiling {
namespace {

// The checks and column wrapping readRow promises, over a row reader of whole source columns.
// Keeps the original's path, format and grid, not the original itself.
class ConditionedRaster : public rasters::RasterSource {
 public:
  explicit ConditionedRaster(const rasters::RasterSource& original)
      : path_(original.path()), format_(original.formatName()), grid_(original.grid()) {}
  const std::string& path() const override { return path_; }
  std::string_view formatName() const override { return format_; }
  const geo::SampleGrid& grid() const override { return grid_; }
  Result<void> readRow(int64_t row, int64_t firstColumn, int64_t count,
                       int16_t* out) const override {
    const geo::SampleGrid& g = grid_;
    if (row < 0 || row >= g.rows || count < 0 ||
        (!g.wrapsLongitude && (firstColumn < 0 || firstColumn + count > g.cols))) {
      return makeError(path() + ": row " + std::to_string(row) + " columns " +
                       std::to_string(firstColumn) + "+" + std::to_string(count) +
                       " outside the raster");
    }
    int64_t column = firstColumn % g.cols;
    if (column < 0) column += g.cols;
    for (int64_t done = 0; done < count;) {
      const int64_t run = std::min(count - done, g.cols - column);
      if (auto read = readColumns(row, column, run, out + done); !read) return read;
      done += run;
      column = 0;
    }
    return {};
  }

 protected:
  // Columns [column, column + count) of the row, all within the grid.
  virtual Result<void> readColumns(int64_t row, int64_t column, int64_t count,
                                   int16_t* out) const = 0;

 private:
  std::string path_;
  std::string format_;
  geo::SampleGrid grid_;
};

class MemoryRaster final : public ConditionedRaster {
 public:
  MemoryRaster(const rasters::RasterSource& original,
               std::shared_ptr<const conditioning::DemGrid> grid)
      : ConditionedRaster(original), grid_(std::move(grid)) {}

 private:
  Result<void> readColumns(int64_t row, int64_t column, int64_t count,
                           int16_t* out) const override {
    std::memcpy(out, grid_->samples.data() + grid_->index(row, column),
                static_cast<size_t>(count) * sizeof(int16_t));
    return {};
  }
  std::shared_ptr<const conditioning::DemGrid> grid_;
};

class SpilledRaster final : public ConditionedRaster {
 public:
  SpilledRaster(const rasters::RasterSource& original, std::shared_ptr<SpillFile> file,
                uint64_t offset, int64_t cols)
      : ConditionedRaster(original), file_(std::move(file)), offset_(offset), cols_(cols) {}

 private:
  Result<void> readColumns(int64_t row, int64_t column, int64_t count,
                           int16_t* out) const override {
    const auto at = offset_ + static_cast<uint64_t>(row * cols_ + column) * sizeof(int16_t);
    return file_->read(at, out, static_cast<size_t>(count) * sizeof(int16_t), path());
  }
  std::shared_ptr<SpillFile> file_;
  uint64_t offset_;
  int64_t cols_;
};

// An unlinked file in the directory: O_TMPFILE where the file system has it.
Result<int> openUnlinked(const std::filesystem::path& directory) {
  int fd = ::open(directory.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd >= 0) return fd;
  std::string name = (directory / ".conditioned-XXXXXX").string();
  std::vector<char> buffer(name.begin(), name.end());
  buffer.push_back('\0');
  fd = ::mkstemp(buffer.data());
  if (fd < 0) {
    return makeError(
        directory.string() +
        ": cannot create a temporary file for conditioned sources: " + std::strerror(errno));
  }
  ::unlink(buffer.data());
  return fd;
}

}  // namespace

Result<std::shared_ptr<SpillFile>> SpillFile::create(const std::filesystem::path& directory) {
  auto fd = openUnlinked(directory);
  if (!fd) return Error{fd.error()};
  return std::shared_ptr<SpillFile>(new SpillFile(*fd, directory));
}

SpillFile::~SpillFile() { ::close(fd_); }

Result<uint64_t> SpillFile::append(const void* data, size_t bytes, const std::string& what) {
  uint64_t offset = 0;
  {
    std::lock_guard lock(mutex_);
    offset = end_;
    end_ += bytes;
  }
  const auto* from = static_cast<const char*>(data);
  for (size_t left = bytes, at = 0; left > 0;) {
    const ssize_t written = ::pwrite(fd_, from + at, left, static_cast<off_t>(offset + at));
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      return makeError(directory_.string() + ": cannot write the conditioned copy of " + what +
                       ": " + (written < 0 ? std::strerror(errno) : "no progress"));
    }
    at += static_cast<size_t>(written), left -= static_cast<size_t>(written);
  }
  return offset;
}

Result<void> SpillFile::read(uint64_t offset, void* out, size_t bytes,
                             const std::string& what) const {
  auto* to = static_cast<char*>(out);
  for (size_t left = bytes, at = 0; left > 0;) {
    const ssize_t got = ::pread(fd_, to + at, left, static_cast<off_t>(offset + at));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) {
      return makeError(what + ": reading its conditioned copy back failed: " +
                       (got < 0 ? std::strerror(errno) : "unexpected end of file"));
    }
    at += static_cast<size_t>(got), left -= static_cast<size_t>(got);
  }
  return {};
}

std::unique_ptr<rasters::RasterSource> makeMemoryRaster(
    const rasters::RasterSource& original, std::shared_ptr<const conditioning::DemGrid> grid) {
  return std::make_unique<MemoryRaster>(original, std::move(grid));
}

Result<std::unique_ptr<rasters::RasterSource>> makeSpilledRaster(
    const rasters::RasterSource& original, const conditioning::DemGrid& grid,
    std::shared_ptr<SpillFile> file) {
  auto offset =
      file->append(grid.samples.data(), grid.samples.size() * sizeof(int16_t), original.path());
  if (!offset) return Error{offset.error()};
  return std::unique_ptr<rasters::RasterSource>(
      std::make_unique<SpilledRaster>(original, std::move(file), *offset, grid.cols));
}

}  // namespace globe::tiling
