#include "publish/export_writes.hpp"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <system_error>

namespace globe::publish {
namespace {

// A temporary beside the file, then rename: a killed run leaves whole tiles or none. Not
// fsynced (unlike the tiler's packs): thousands of small files, and a tile lost to a power cut
// is only a tile to write again.
Result<void> writeRenamed(const std::filesystem::path& path, std::span<const std::byte> bytes) {
  const std::filesystem::path temporary = path.string() + ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
    if (!out.flush()) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      return makeError(path.string() + ": cannot write (disk full or read-only?)");
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    return makeError(path.string() + ": cannot rename into place: " + error.message());
  }
  return {};
}

}  // namespace

bool parseExportLevels(const std::string& text, ExportRegion& region) {
  unsigned first = 0, last = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%u-%u%c", &first, &last, &extra) == 2 && first <= last) {
  } else if (std::sscanf(text.c_str(), "%u%c", &first, &extra) == 1) {
    last = first;
  } else {
    return false;
  }
  region.minLevel = first;
  region.maxLevel = last;
  return true;
}

bool parseExportBounds(const std::string& text, ExportRegion& region) {
  double w = 0, s = 0, e = 0, n = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf,%lf,%lf%c", &w, &s, &e, &n, &extra) != 4) return false;
  if (!(w >= -180 && e <= 180 && w < e && s >= -90 && n <= 90 && s < n)) return false;
  region = {region.minLevel, region.maxLevel, w, s, e, n};
  return true;
}

Result<void> writeFileReplacing(const std::filesystem::path& path,
                                std::span<const std::byte> bytes) {
  std::error_code error;
  std::filesystem::create_directories(path.parent_path(), error);
  if (error) {
    return makeError(path.parent_path().string() + ": cannot create: " + error.message());
  }
  return writeRenamed(path, bytes);
}

Result<void> writeTileOnce(const std::filesystem::path& path,
                           const std::function<Result<std::vector<std::byte>>()>& make,
                           ExportReport& report) {
  std::error_code error;
  if (std::filesystem::is_regular_file(path, error)) {
    ++report.tilesKept;
    return {};
  }
  auto bytes = make();
  if (!bytes) return Error{bytes.error()};
  std::filesystem::create_directories(path.parent_path(), error);
  if (error) {
    return makeError(path.parent_path().string() + ": cannot create: " + error.message());
  }
  if (auto written = writeRenamed(path, *bytes); !written) return written;
  ++report.tilesWritten;
  report.bytesWritten += bytes->size();
  return {};
}

}  // namespace globe::publish
