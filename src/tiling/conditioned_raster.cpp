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
class ConditionedRaster : public rasters::RasterSource {
 public:
  explicit ConditionedRaster(std::unique_ptr<rasters::RasterSource> original)
      : original_(std::move(original)) {}
  const std::string& path() const override { return original_->path(); }
  std::string_view formatName() const override { return original_->formatName(); }
  const rasters::SampleGrid& grid() const override { return original_->grid(); }
  Result<void> readRow(int64_t row, int64_t firstColumn, int64_t count,
                       int16_t* out) const override {
    const rasters::SampleGrid& g = original_->grid();
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
  std::unique_ptr<rasters::RasterSource> original_;
};

class MemoryRaster final : public ConditionedRaster {
 public:
  MemoryRaster(std::unique_ptr<rasters::RasterSource> original,
               std::shared_ptr<const conditioning::DemGrid> grid)
      : ConditionedRaster(std::move(original)), grid_(std::move(grid)) {}

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
  SpilledRaster(std::unique_ptr<rasters::RasterSource> original, int fd, int64_t cols)
      : ConditionedRaster(std::move(original)), fd_(fd), cols_(cols) {}
  ~SpilledRaster() override { ::close(fd_); }
  SpilledRaster(const SpilledRaster&) = delete;
  SpilledRaster& operator=(const SpilledRaster&) = delete;

 private:
  Result<void> readColumns(int64_t row, int64_t column, int64_t count,
                           int16_t* out) const override {
    auto* bytes = reinterpret_cast<char*>(out);
    size_t left = static_cast<size_t>(count) * sizeof(int16_t);
    auto offset = static_cast<off_t>((row * cols_ + column) * 2);
    while (left > 0) {
      const ssize_t got = ::pread(fd_, bytes, left, offset);
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) {
        return makeError(path() + ": reading its conditioned copy back failed: " +
                         (got < 0 ? std::strerror(errno) : "unexpected end of file"));
      }
      bytes += got, left -= static_cast<size_t>(got), offset += got;
    }
    return {};
  }
  int fd_;
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
    return makeError(directory.string() +
                     ": cannot create a temporary file for a conditioned "
                     "source: " +
                     std::strerror(errno));
  }
  ::unlink(buffer.data());
  return fd;
}

}  // namespace

std::unique_ptr<rasters::RasterSource> makeMemoryRaster(
    std::unique_ptr<rasters::RasterSource> original,
    std::shared_ptr<const conditioning::DemGrid> grid) {
  return std::make_unique<MemoryRaster>(std::move(original), std::move(grid));
}

Result<std::unique_ptr<rasters::RasterSource>> makeSpilledRaster(
    std::unique_ptr<rasters::RasterSource> original, const conditioning::DemGrid& grid,
    const std::filesystem::path& directory) {
  auto fd = openUnlinked(directory);
  if (!fd) return Error{fd.error()};
  const auto* bytes = reinterpret_cast<const char*>(grid.samples.data());
  size_t left = grid.samples.size() * sizeof(int16_t);
  while (left > 0) {
    const ssize_t written = ::write(*fd, bytes, left);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      const std::string reason = written < 0 ? std::strerror(errno) : "no progress";
      ::close(*fd);
      return makeError(directory.string() + ": cannot write the conditioned copy of " +
                       original->path() + ": " + reason);
    }
    bytes += written, left -= static_cast<size_t>(written);
  }
  return std::unique_ptr<rasters::RasterSource>(
      std::make_unique<SpilledRaster>(std::move(original), *fd, grid.cols));
}

}  // namespace globe::tiling
