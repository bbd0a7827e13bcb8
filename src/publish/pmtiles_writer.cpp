#include "publish/pmtiles_writer.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "compression/deflate_bytes.hpp"

namespace globe::publish {
namespace {

namespace fs = std::filesystem;

// The spec keeps header and root directory within the first 16 KiB: one read opens an archive.
constexpr size_t kRootLimitBytes = 16384 - formats::kPmtilesHeaderBytes;
constexpr int kGzipLevel = 9;

uint64_t fnv1a(std::span<const std::byte> bytes) {
  uint64_t hash = 0xcbf29ce484222325ULL;
  for (std::byte b : bytes) hash = (hash ^ static_cast<uint8_t>(b)) * 0x100000001b3ULL;
  return hash;
}

std::vector<std::byte> gzipDirectory(std::span<const formats::PmtilesEntry> entries) {
  return compression::gzipCompress(formats::encodePmtilesDirectory(entries), kGzipLevel);
}

struct Directories {
  std::vector<std::byte> root, leaves;
  uint64_t leafCount = 0;
};

// The root alone when it fits; else leaves of `leafSize` entries, grown until their index fits
// (what go-pmtiles does).
Directories layOutDirectories(const std::vector<formats::PmtilesEntry>& entries) {
  Directories d;
  d.root = gzipDirectory(entries);
  if (d.root.size() <= kRootLimitBytes) return d;
  for (size_t leafSize = 4096;; leafSize += leafSize / 5) {
    d.leaves.clear();
    std::vector<formats::PmtilesEntry> index;
    for (size_t first = 0; first < entries.size(); first += leafSize) {
      const size_t count = std::min(leafSize, entries.size() - first);
      const auto leaf = gzipDirectory(std::span(entries).subspan(first, count));
      index.push_back(
          {entries[first].tileId, d.leaves.size(), static_cast<uint32_t>(leaf.size()), 0});
      d.leaves.insert(d.leaves.end(), leaf.begin(), leaf.end());
    }
    d.root = gzipDirectory(index);
    d.leafCount = index.size();
    if (d.root.size() <= kRootLimitBytes) return d;
  }
}

Error fileError(const fs::path& path, const char* doing) {
  return makeError(path.string() + ": cannot " + doing + ": " + std::strerror(errno));
}

}  // namespace

Result<std::unique_ptr<PmtilesWriter>> PmtilesWriter::create(const fs::path& archive) {
  std::error_code error;
  if (fs::is_directory(archive, error)) {
    return makeError(archive.string() + ": is a directory (a PMTiles archive is one file)");
  }
  if (archive.has_parent_path()) {
    fs::create_directories(archive.parent_path(), error);
    if (error) {
      return makeError(archive.parent_path().string() + ": cannot create: " + error.message());
    }
  }
  // A fixed name: a run killed mid-way leaves it, and the next run starts it over.
  const fs::path spool = archive.string() + ".tmp-tiles";
  std::FILE* file = std::fopen(spool.c_str(), "w+b");
  if (file == nullptr) return fileError(spool, "create");
  return std::unique_ptr<PmtilesWriter>(new PmtilesWriter(archive, spool, file));
}

PmtilesWriter::PmtilesWriter(fs::path archive, fs::path spool, std::FILE* file)
    : archive_(std::move(archive)), spool_(std::move(spool)), spoolFile_(file) {}

PmtilesWriter::~PmtilesWriter() { removeTemporaries(); }

void PmtilesWriter::removeTemporaries() {
  if (spoolFile_ != nullptr) std::fclose(spoolFile_);
  spoolFile_ = nullptr;
  std::error_code ignored;
  fs::remove(spool_, ignored);
}

Result<bool> PmtilesWriter::spooledEquals(uint64_t offset, std::span<const std::byte> bytes) {
  std::vector<std::byte> stored(bytes.size());
  if (std::fflush(spoolFile_) != 0 || ::fseeko(spoolFile_, static_cast<off_t>(offset), SEEK_SET) ||
      std::fread(stored.data(), 1, stored.size(), spoolFile_) != stored.size() ||
      ::fseeko(spoolFile_, 0, SEEK_END) != 0) {
    return fileError(spool_, "read back");
  }
  return std::equal(stored.begin(), stored.end(), bytes.begin(), bytes.end());
}

Result<void> PmtilesWriter::add(uint32_t zoom, uint32_t x, uint32_t y,
                                std::span<const std::byte> bytes) {
  const uint64_t id = formats::pmtilesTileId(zoom, x, y);
  if (!entries_.empty() && id <= entries_.back().tileId + entries_.back().runLength - 1) {
    return makeError(archive_.string() + ": tile " + std::to_string(zoom) + "/" +
                     std::to_string(x) + "/" + std::to_string(y) + " given out of tile id order");
  }
  if (bytes.size() > UINT32_MAX) return makeError(archive_.string() + ": a tile over 4 GiB");
  if (bytes.empty()) return makeError(archive_.string() + ": an empty tile");
  const auto length = static_cast<uint32_t>(bytes.size());
  // The same bytes stored before: point at them.
  std::optional<uint64_t> offset;
  std::vector<uint64_t>& twins = offsetsByHash_[fnv1a(bytes) ^ length];
  for (uint64_t candidate : twins) {
    auto same = spooledEquals(candidate, bytes);
    if (!same) return Error{same.error()};
    if (*same) {
      offset = candidate;
      break;
    }
  }
  if (!offset) {
    if (std::fwrite(bytes.data(), 1, bytes.size(), spoolFile_) != bytes.size()) {
      return fileError(spool_, "write (disk full?)");
    }
    offset = spooledBytes_;
    twins.push_back(*offset);
    spooledBytes_ += length;
    ++contents_;
  }
  formats::PmtilesEntry* last = entries_.empty() ? nullptr : &entries_.back();
  if (last != nullptr && last->offset == *offset && last->length == length &&
      last->tileId + last->runLength == id) {
    ++last->runLength;
  } else {
    entries_.push_back({id, *offset, length, 1});
  }
  return {};
}

Result<PmtilesSummary> PmtilesWriter::finish(formats::PmtilesHeader header,
                                             const std::string& metadataJson) {
  if (std::fflush(spoolFile_) != 0) return fileError(spool_, "write (disk full?)");
  const Directories directories = layOutDirectories(entries_);
  const auto metadata = compression::gzipCompress(
      std::as_bytes(std::span(metadataJson.data(), metadataJson.size())), kGzipLevel);

  header.rootOffset = formats::kPmtilesHeaderBytes;
  header.rootLength = directories.root.size();
  header.metadataOffset = header.rootOffset + header.rootLength;
  header.metadataLength = metadata.size();
  header.leavesOffset = header.metadataOffset + header.metadataLength;
  header.leavesLength = directories.leaves.size();
  header.tileDataOffset = header.leavesOffset + header.leavesLength;
  header.tileDataLength = spooledBytes_;
  header.tileEntries = entries_.size();
  header.tileContents = contents_;
  header.addressedTiles = 0;
  for (const auto& e : entries_) header.addressedTiles += e.runLength;
  header.clustered = true;
  header.internalCompression = formats::PmtilesCompression::Gzip;
  header.tileCompression = formats::PmtilesCompression::None;  // PNG, JPEG, WebP as they are

  const fs::path temporary = archive_.string() + ".tmp";
  std::FILE* out = std::fopen(temporary.c_str(), "wb");
  if (out == nullptr) return fileError(temporary, "create");
  // An empty part (no leaf directories) has no data pointer to hand fwrite.
  const auto put = [&](std::span<const std::byte> bytes) {
    return bytes.empty() || std::fwrite(bytes.data(), 1, bytes.size(), out) == bytes.size();
  };
  bool ok = put(formats::encodePmtilesHeader(header)) && put(directories.root) && put(metadata) &&
            put(directories.leaves) && ::fseeko(spoolFile_, 0, SEEK_SET) == 0;
  std::vector<std::byte> buffer(size_t{1} << 20);
  for (uint64_t left = spooledBytes_; ok && left > 0;) {
    const size_t chunk = static_cast<size_t>(std::min<uint64_t>(left, buffer.size()));
    ok = std::fread(buffer.data(), 1, chunk, spoolFile_) == chunk &&
         put(std::span(buffer).first(chunk));
    left -= chunk;
  }
  ok = ok && std::fflush(out) == 0 && ::fsync(::fileno(out)) == 0;
  const int savedErrno = errno;
  std::fclose(out);
  if (!ok) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    errno = savedErrno;
    return fileError(temporary, "write (disk full?)");
  }
  std::error_code error;
  fs::rename(temporary, archive_, error);
  if (error) {
    fs::remove(temporary, error);
    return makeError(archive_.string() + ": cannot rename into place: " + error.message());
  }
  removeTemporaries();
  PmtilesSummary summary;
  summary.addressedTiles = header.addressedTiles;
  summary.tileEntries = header.tileEntries;
  summary.tileContents = header.tileContents;
  summary.leafDirectories = directories.leafCount;
  summary.archiveBytes = header.tileDataOffset + header.tileDataLength;
  return summary;
}

}  // namespace globe::publish
