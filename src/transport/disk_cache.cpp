// The disk cache over POSIX calls: one open and one read or write per get or put, directory scans
// only at open and when over budget.
#include "transport/disk_cache.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <random>
#include <string_view>
#include <system_error>
#include <thread>
#include <utility>

#include "core/big_endian.hpp"
#include "core/crc32.hpp"
#include "transport/file_reads.hpp"
#include "transport/io_error.hpp"

namespace globe::transport {

struct DiskCache::EntryFile {
  std::string path;
  uint64_t size = 0;
  timespec mtime{};
};

namespace {

constexpr char kMagic[8] = {'G', 'L', 'O', 'B', 'E', 'C', 'E', '1'};
constexpr uint64_t kMaxTextBytes = 64 * 1024;  // key or validator: refused beyond, before reading
// Magic, the four length/size fields and the CRC: an entry with empty key, validator and body.
constexpr uint64_t kFixedBytes = 8 + 4 + 4 + 8 + 8 + 4;
constexpr std::string_view kTempPrefix = "tmp-";
constexpr time_t kStaleTempSeconds = 3600;

uint64_t fmix64(uint64_t k) {
  k ^= k >> 33;
  k *= 0xff51afd7ed558ccdULL;
  k ^= k >> 33;
  k *= 0xc4ceb9fe1a85ec53ULL;
  k ^= k >> 33;
  return k;
}

// FNV-1a from a seeded basis, finalised with MurmurHash3's mixer so every output bit depends on
// every input byte; two seeds give the 128-bit name.
uint64_t hashKey(std::string_view key, uint64_t seed) {
  uint64_t h = 0xcbf29ce484222325ULL ^ seed;
  for (char c : key) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return fmix64(h ^ key.size());
}

bool isLowerHex(std::string_view s) {
  return std::all_of(s.begin(), s.end(),
                     [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

bool isEntryName(std::string_view name, std::string_view subdir) {
  constexpr std::string_view kSuffix = ".entry";
  return name.size() == 32 + kSuffix.size() && name.substr(32) == kSuffix &&
         isLowerHex(name.substr(0, 32)) && name.substr(0, 2) == subdir;
}

bool olderThan(const timespec& a, const timespec& b) {
  return a.tv_sec != b.tv_sec ? a.tv_sec < b.tv_sec : a.tv_nsec < b.tv_nsec;
}

// pid + counter keep names unique within a process and across live ones; the random part covers
// a pid reused by a later process while an old temporary is still there.
std::string tempName() {
  static std::atomic<uint64_t> counter{0};
  thread_local std::mt19937_64 random(std::random_device{}() ^
                                      std::hash<std::thread::id>{}(std::this_thread::get_id()));
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(random()));
  return std::string(kTempPrefix) + std::to_string(::getpid()) + "-" + std::to_string(++counter) +
         "-" + hex;
}

struct DirCloser {
  void operator()(DIR* d) const { ::closedir(d); }
};
using DirPtr = std::unique_ptr<DIR, DirCloser>;

// Writes the three pieces with as few calls as the kernel allows, resuming after short writes.
bool writeAll(int fd, iovec* iov, int count) {
  int first = 0;
  size_t done = 0;
  for (;;) {
    while (first < count && done >= iov[first].iov_len) done -= iov[first++].iov_len;
    if (first == count) return true;
    iov[first].iov_base = static_cast<char*>(iov[first].iov_base) + done;
    iov[first].iov_len -= done;
    const ssize_t n = ::writev(fd, iov + first, count - first);
    if (n < 0 && errno == EINTR) {
      done = 0;
      continue;
    }
    if (n <= 0) {
      if (n == 0) errno = EIO;  // nothing written with bytes left: would loop forever
      return false;
    }
    done = static_cast<size_t>(n);
  }
}

// Cursor over an entry file's bytes, excluding the trailing CRC; every take is bounds-checked in
// 64 bits so lying length fields cannot overflow or over-read.
class Reader {
 public:
  Reader(const std::byte* data, uint64_t size) : data_(data), size_(size) {}
  uint64_t left() const { return size_ - pos_; }
  const std::byte* take(uint64_t n) {
    if (n > left()) return nullptr;
    const std::byte* p = data_ + pos_;
    pos_ += n;
    return p;
  }
  uint64_t pos() const { return pos_; }

 private:
  const std::byte* data_;
  uint64_t size_;
  uint64_t pos_ = 0;
};

}  // namespace

DiskCache::DiskCache(std::filesystem::path dir, uint64_t budgetBytes)
    : dir_(std::move(dir)), budget_(budgetBytes) {}

Result<std::unique_ptr<DiskCache>> DiskCache::open(const std::filesystem::path& dir,
                                                   uint64_t budgetBytes) {
  std::error_code ec;
  const auto status = std::filesystem::status(dir, ec);
  if (std::filesystem::exists(status) && !std::filesystem::is_directory(status)) {
    return makeError(dir.string() + ": not a directory");
  }
  if (!std::filesystem::exists(status)) {
    std::filesystem::create_directories(dir, ec);
    if (ec) return makeError(dir.string() + ": cannot create: " + ec.message());
  }
  if (::access(dir.c_str(), W_OK | X_OK) != 0) return ioError(dir, "cannot write", errno);

  std::unique_ptr<DiskCache> cache(new DiskCache(dir, budgetBytes));
  {
    std::lock_guard lock(cache->mutex_);
    auto files = cache->scan();
    uint64_t total = 0;
    for (const auto& f : files) total += f.size;
    cache->bytes_ = total;
    if (total > budgetBytes) cache->evictLocked(std::move(files));  // the budget was lowered
  }
  return cache;
}

std::filesystem::path DiskCache::defaultDirectory() {
  // XDG: a relative $XDG_CACHE_HOME is invalid and must be ignored.
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && xdg[0] == '/') {
    return std::filesystem::path(xdg) / "globe";
  }
  if (const char* home = std::getenv("HOME"); home && home[0] != '\0') {
    return std::filesystem::path(home) / ".cache" / "globe";
  }
  return ".globe-cache";
}

std::filesystem::path DiskCache::entryPath(const std::string& key) const {
  char hex[33];
  std::snprintf(hex, sizeof hex, "%016llx%016llx", static_cast<unsigned long long>(hashKey(key, 0)),
                static_cast<unsigned long long>(hashKey(key, 0x9e3779b97f4a7c15ULL)));
  return dir_ / std::string(hex, 2) / (std::string(hex, 32) + ".entry");
}

std::optional<CacheEntry> DiskCache::get(const std::string& key) {
  const auto path = entryPath(key);
  // O_NONBLOCK: a FIFO planted under an entry's name must not block the loader.
  FdCloser fd{::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK)};
  if (fd.fd < 0) return std::nullopt;  // ENOENT: not cached, or evicted by another process
  struct stat st {};
  if (::fstat(fd.fd, &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
  const auto size = static_cast<uint64_t>(st.st_size);
  auto bad = [&]() -> std::optional<CacheEntry> {
    discard(path, st.st_dev, st.st_ino, size);
    return std::nullopt;
  };
  // put() never writes a file beyond the budget, so one that is must be damage; refusing it also
  // bounds the allocation below.
  if (size < kFixedBytes || size > budget_) return bad();
  std::vector<std::byte> bytes(size);
  if (!preadFully(fd.fd, bytes.data(), bytes.size(), 0, path).ok()) return bad();

  const uint64_t crcAt = size - 4;
  if (core::crc32(std::span(bytes.data(), crcAt)) != core::loadBigEndian32(bytes.data() + crcAt))
    return bad();
  Reader in(bytes.data(), crcAt);  // size >= kFixedBytes: magic and key length are there
  const std::byte* magic = in.take(sizeof kMagic);
  if (std::memcmp(magic, kMagic, sizeof kMagic) != 0) return bad();
  const uint32_t keyLength = core::loadBigEndian32(in.take(4));
  if (keyLength > kMaxTextBytes || keyLength != key.size()) return bad();
  const std::byte* storedKey = in.take(keyLength);
  if (!storedKey || std::memcmp(storedKey, key.data(), keyLength) != 0) return bad();
  const std::byte* p = in.take(4);
  if (!p) return bad();
  const uint32_t validatorLength = core::loadBigEndian32(p);
  if (validatorLength > kMaxTextBytes) return bad();
  const std::byte* validator = in.take(validatorLength);
  const std::byte* sizes = in.take(16);
  if (!validator || !sizes) return bad();
  const uint64_t bodyLength = core::loadBigEndian64(sizes + 8);
  if (bodyLength != in.left()) return bad();

  CacheEntry entry;
  entry.validator.assign(reinterpret_cast<const char*>(validator), validatorLength);
  entry.fileBytes = core::loadBigEndian64(sizes);
  // Reuse the file's buffer for the body rather than holding two copies of it.
  const auto bodyAt = static_cast<size_t>(in.pos());
  std::memmove(bytes.data(), bytes.data() + bodyAt, static_cast<size_t>(bodyLength));
  bytes.resize(static_cast<size_t>(bodyLength));
  entry.body = std::move(bytes);

  // The hit makes it the most recent; failing that only makes it evicted sooner.
  const timespec now[2] = {{0, UTIME_NOW}, {0, UTIME_NOW}};
  ::futimens(fd.fd, now);
  return entry;
}

Result<void> DiskCache::put(const std::string& key, const CacheEntry& entry) {
  const auto path = entryPath(key);
  if (key.size() > kMaxTextBytes || entry.validator.size() > kMaxTextBytes) {
    return makeError(path.string() + ": key or validator longer than 64 KiB");
  }
  const uint64_t size = kFixedBytes + key.size() + entry.validator.size() + entry.body.size();
  if (size > budget_) {
    erase(key);
    return {};
  }

  std::vector<std::byte> header(8 + 4 + key.size() + 4 + entry.validator.size() + 16);
  std::byte* out = header.data();
  std::memcpy(out, kMagic, sizeof kMagic);
  out += sizeof kMagic;
  core::storeBigEndian32(out, static_cast<uint32_t>(key.size()));
  std::memcpy(out + 4, key.data(), key.size());
  out += 4 + key.size();
  core::storeBigEndian32(out, static_cast<uint32_t>(entry.validator.size()));
  std::memcpy(out + 4, entry.validator.data(), entry.validator.size());
  out += 4 + entry.validator.size();
  core::storeBigEndian64(out, entry.fileBytes);
  core::storeBigEndian64(out + 8, entry.body.size());
  std::byte trailer[4];
  core::storeBigEndian32(trailer, core::crc32(entry.body, core::crc32(header)));

  const auto temp = path.parent_path() / tempName();
  constexpr int kFlags = O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC;
  int raw = ::open(temp.c_str(), kFlags, 0644);
  if (raw < 0 && errno == ENOENT) {  // first entry in this subdirectory
    if (::mkdir(path.parent_path().c_str(), 0755) != 0 && errno != EEXIST) {
      return ioError(path.parent_path(), "cannot create", errno);
    }
    raw = ::open(temp.c_str(), kFlags, 0644);
  }
  if (raw < 0) return ioError(temp, "cannot create", errno);
  FdCloser fd{raw};
  iovec iov[3] = {{header.data(), header.size()},
                  {const_cast<std::byte*>(entry.body.data()), entry.body.size()},
                  {trailer, sizeof trailer}};
  const bool written = writeAll(fd.fd, iov, 3);
  const int writeErr = errno;
  fd.fd = -1;
  if (!written || ::close(raw) != 0) {
    const int err = written ? errno : writeErr;
    ::unlink(temp.c_str());
    return ioError(temp, "write failed", err);
  }

  std::lock_guard lock(mutex_);
  struct stat old {};
  const bool replacing = ::stat(path.c_str(), &old) == 0 && S_ISREG(old.st_mode);
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(temp.c_str());
    return ioError(path, "rename failed", err);
  }
  if (replacing) subtractLocked(static_cast<uint64_t>(old.st_size));
  bytes_ += size;
  if (bytes_ > budget_) evictLocked(scan());
  return {};
}

void DiskCache::erase(const std::string& key) {
  const auto path = entryPath(key);
  std::lock_guard lock(mutex_);
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::unlink(path.c_str()) == 0) {
    subtractLocked(static_cast<uint64_t>(st.st_size));
  }
}

void DiskCache::discard(const std::filesystem::path& path, uint64_t device, uint64_t inode,
                        uint64_t size) {
  std::lock_guard lock(mutex_);
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || st.st_dev != device || st.st_ino != inode) return;
  if (::unlink(path.c_str()) == 0) subtractLocked(size);
}

void DiskCache::subtractLocked(uint64_t size) { bytes_ -= std::min(size, bytes_.load()); }

std::vector<DiskCache::EntryFile> DiskCache::scan() const {
  std::vector<EntryFile> files;
  DirPtr top(::opendir(dir_.c_str()));
  if (!top) return files;
  const time_t staleBefore = std::time(nullptr) - kStaleTempSeconds;
  while (const dirent* sub = ::readdir(top.get())) {
    const std::string_view subName = sub->d_name;
    if (subName.size() != 2 || !isLowerHex(subName)) continue;
    const int subFd = ::openat(::dirfd(top.get()), sub->d_name, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (subFd < 0) continue;
    DirPtr subDir(::fdopendir(subFd));
    if (!subDir) {
      ::close(subFd);
      continue;
    }
    while (const dirent* file = ::readdir(subDir.get())) {
      const std::string_view name = file->d_name;
      const bool entry = isEntryName(name, subName);
      const bool temp = name.substr(0, kTempPrefix.size()) == kTempPrefix;
      if (!entry && !temp) continue;
      struct stat st {};
      // ENOENT: deleted meanwhile by another process.
      if (::fstatat(subFd, file->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISREG(st.st_mode)) {
        continue;
      }
      if (temp) {
        if (st.st_mtime < staleBefore) ::unlinkat(subFd, file->d_name, 0);
        continue;
      }
      files.push_back(
          {(dir_ / subName / name).string(), static_cast<uint64_t>(st.st_size), st.st_mtim});
    }
  }
  return files;
}

void DiskCache::evictLocked(std::vector<EntryFile> files) {
  uint64_t total = 0;
  for (const auto& f : files) total += f.size;
  // Another process may have evicted already: then the scan only corrects the estimate.
  if (total > budget_) {
    const uint64_t target = budget_ - budget_ / 10;
    std::sort(files.begin(), files.end(), [](const EntryFile& a, const EntryFile& b) {
      return olderThan(a.mtime, b.mtime) || (!olderThan(b.mtime, a.mtime) && a.path < b.path);
    });
    for (const auto& f : files) {
      if (total <= target) break;
      // ENOENT: another process evicted it already.
      if (::unlink(f.path.c_str()) == 0 || errno == ENOENT) total -= f.size;
    }
  }
  bytes_ = total;
}

}  // namespace globe::transport
