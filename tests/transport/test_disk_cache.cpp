// DiskCache: round trips, damage of every kind read as a miss (and deleted), LRU eviction under
// the budget, two instances sharing a directory from several threads, and file names that never
// leave the cache directory.
#include "transport/disk_cache.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iterator>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "core/big_endian.hpp"
#include "core/crc32.hpp"
#include "tests/support/test_io_util.hpp"

namespace globe::transport {
namespace {

namespace fs = std::filesystem;
using globe::testing::TempDir;

std::vector<std::byte> bytesOf(const std::string& s) {
  const auto* p = reinterpret_cast<const std::byte*>(s.data());
  return std::vector<std::byte>(p, p + s.size());
}

std::string textOf(const std::vector<std::byte>& b) {
  return std::string(reinterpret_cast<const char*>(b.data()), b.size());
}

std::vector<std::byte> pattern(size_t size, unsigned seed) {
  std::vector<std::byte> out(size);
  for (size_t i = 0; i < size; ++i) out[i] = static_cast<std::byte>((i * 31 + seed * 7) & 0xFF);
  return out;
}

CacheEntry makeEntry(std::string validator, uint64_t fileBytes, std::vector<std::byte> body) {
  CacheEntry e;
  e.validator = std::move(validator);
  e.fileBytes = fileBytes;
  e.body = std::move(body);
  return e;
}

std::unique_ptr<DiskCache> openCache(const fs::path& dir, uint64_t budget) {
  auto cache = DiskCache::open(dir, budget);
  EXPECT_TRUE(cache.ok()) << cache.error();
  return cache.ok() ? std::move(*cache) : nullptr;
}

bool isLowerHex(const std::string& s) {
  return !s.empty() && s.find_first_not_of("0123456789abcdef") == std::string::npos;
}

// "ab/ab<30 hex>.entry"; hand-checked: GCC 12 warns inside <regex> under the sanitizers.
bool isEntryPath(const std::string& rel) {
  return rel.size() == 3 + 32 + 6 && rel[2] == '/' && rel.substr(35) == ".entry" &&
         isLowerHex(rel.substr(3, 32)) && rel.substr(0, 2) == rel.substr(3, 2);
}

// Every regular file under dir, each checked to be DIR/ab/ab<30 hex>.entry.
std::vector<fs::path> entryFiles(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.is_directory()) continue;
    const std::string rel = fs::relative(e.path(), dir).string();
    EXPECT_TRUE(isEntryPath(rel)) << "unexpected file " << rel;
    files.push_back(e.path());
  }
  return files;
}

uint64_t sizeOnDisk(const fs::path& dir) {
  uint64_t total = 0;
  for (const auto& f : entryFiles(dir)) total += fs::file_size(f);
  return total;
}

std::vector<std::byte> readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string s((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return bytesOf(s);
}

void writeAll(const fs::path& path, const std::vector<std::byte>& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

void setMtime(const fs::path& path, time_t seconds) {
  const timespec times[2] = {{seconds, 0}, {seconds, 0}};
  ASSERT_EQ(::utimensat(AT_FDCWD, path.c_str(), times, 0), 0) << path;
}

// The one entry file that put() just created: the only one in a cache holding a single entry.
fs::path onlyEntryFile(const fs::path& dir) {
  const auto files = entryFiles(dir);
  EXPECT_EQ(files.size(), 1u);
  return files.empty() ? fs::path() : files[0];
}

// An entry file built by hand in the documented big-endian layout; keyLength and bodyLength can
// be made to lie while the CRC stays right.
std::vector<std::byte> encode(const std::string& key, const std::string& validator,
                              uint64_t fileBytes, const std::vector<std::byte>& body,
                              std::optional<uint32_t> keyLength = {},
                              std::optional<uint64_t> bodyLength = {}) {
  std::vector<std::byte> out = bytesOf("GLOBECE1");
  auto put32 = [&](uint32_t v) {
    std::byte b[4];
    core::storeBigEndian32(b, v);
    out.insert(out.end(), b, b + 4);
  };
  auto put64 = [&](uint64_t v) {
    std::byte b[8];
    core::storeBigEndian64(b, v);
    out.insert(out.end(), b, b + 8);
  };
  put32(keyLength.value_or(static_cast<uint32_t>(key.size())));
  const auto k = bytesOf(key);
  out.insert(out.end(), k.begin(), k.end());
  put32(static_cast<uint32_t>(validator.size()));
  const auto v = bytesOf(validator);
  out.insert(out.end(), v.begin(), v.end());
  put64(fileBytes);
  put64(bodyLength.value_or(body.size()));
  out.insert(out.end(), body.begin(), body.end());
  put32(core::crc32(out));
  return out;
}

TEST(DiskCache, RoundTripKeepsValidatorFileBytesAndBody) {
  TempDir tmp;
  const fs::path dir = tmp / "nested/cache";
  auto cache = openCache(dir, 1 << 20);
  ASSERT_TRUE(cache);
  EXPECT_EQ(cache->directory(), dir);
  EXPECT_EQ(cache->bytesOnDisk(), 0u);

  const auto body = pattern(5000, 1);
  ASSERT_TRUE(
      cache->put("https://h/a.pack#0-4999", makeEntry("\"etag-1\"", 123456789012, body)).ok());
  ASSERT_TRUE(cache->put("empty", makeEntry("", 0, {})).ok());
  // Keys that look like paths must not steer where the file goes.
  ASSERT_TRUE(cache->put("../../escape", makeEntry("w", 7, bytesOf("up"))).ok());
  ASSERT_TRUE(cache->put(std::string("nul\0key", 7), makeEntry("n", 1, bytesOf("z"))).ok());

  auto a = cache->get("https://h/a.pack#0-4999");
  ASSERT_TRUE(a.has_value());
  EXPECT_EQ(a->validator, "\"etag-1\"");
  EXPECT_EQ(a->fileBytes, 123456789012u);
  EXPECT_EQ(a->body, body);

  auto e = cache->get("empty");
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->validator, "");
  EXPECT_EQ(e->fileBytes, 0u);
  EXPECT_TRUE(e->body.empty());

  auto up = cache->get("../../escape");
  ASSERT_TRUE(up.has_value());
  EXPECT_EQ(textOf(up->body), "up");
  EXPECT_EQ(up->fileBytes, 7u);
  EXPECT_FALSE(cache->get("nul").has_value());  // the key is not cut at the NUL
  ASSERT_TRUE(cache->get(std::string("nul\0key", 7)).has_value());

  // 36 fixed bytes per entry plus key, validator and body.
  const uint64_t expected = (36 + 23 + 8 + 5000) + (36 + 5) + (36 + 12 + 1 + 2) + (36 + 7 + 1 + 1);
  EXPECT_EQ(sizeOnDisk(dir), expected);
  EXPECT_EQ(cache->bytesOnDisk(), expected);
  EXPECT_EQ(entryFiles(dir).size(), 4u);
  // Nothing beside the cache directory.
  std::vector<fs::path> top;
  for (const auto& f : fs::directory_iterator(tmp.path())) top.push_back(f.path());
  EXPECT_EQ(top, std::vector<fs::path>{tmp / "nested"});
}

TEST(DiskCache, HandWrittenFileInTheDocumentedLayoutIsRead) {
  TempDir tmp;
  auto cache = openCache(tmp.path(), 1 << 20);
  ASSERT_TRUE(cache);
  ASSERT_TRUE(cache->put("k", makeEntry("old", 1, bytesOf("old body"))).ok());
  const fs::path file = onlyEntryFile(tmp.path());
  const auto mine = encode("k", "W/\"v\"", 99, bytesOf("hand written"));
  EXPECT_EQ(readAll(file).size(), 36u + 1 + 3 + 8);
  writeAll(file, mine);
  auto got = cache->get("k");
  ASSERT_TRUE(got.has_value());
  EXPECT_EQ(got->validator, "W/\"v\"");
  EXPECT_EQ(got->fileBytes, 99u);
  EXPECT_EQ(textOf(got->body), "hand written");
  // And put() writes exactly that layout.
  ASSERT_TRUE(cache->put("k", makeEntry("W/\"v\"", 99, bytesOf("hand written"))).ok());
  EXPECT_EQ(readAll(file), mine);
}

TEST(DiskCache, PutReplacesTheEntryUnderTheSameKey) {
  TempDir tmp;
  auto cache = openCache(tmp.path(), 1 << 20);
  ASSERT_TRUE(cache);
  ASSERT_TRUE(cache->put("k", makeEntry("v1", 10, pattern(3000, 1))).ok());
  ASSERT_TRUE(cache->put("k", makeEntry("v2", 20, pattern(100, 2))).ok());
  auto got = cache->get("k");
  ASSERT_TRUE(got.has_value());
  EXPECT_EQ(got->validator, "v2");
  EXPECT_EQ(got->fileBytes, 20u);
  EXPECT_EQ(got->body, pattern(100, 2));
  EXPECT_EQ(entryFiles(tmp.path()).size(), 1u);
  EXPECT_EQ(cache->bytesOnDisk(), 36u + 1 + 2 + 100);
  EXPECT_EQ(sizeOnDisk(tmp.path()), 36u + 1 + 2 + 100);
}

TEST(DiskCache, UnknownKeyIsAMiss) {
  TempDir tmp;
  auto cache = openCache(tmp.path(), 1 << 20);
  ASSERT_TRUE(cache);
  EXPECT_FALSE(cache->get("a").has_value());
  ASSERT_TRUE(cache->put("a", makeEntry("", 1, bytesOf("x"))).ok());
  EXPECT_FALSE(cache->get("b").has_value());
  EXPECT_FALSE(cache->get("").has_value());
  EXPECT_TRUE(cache->get("a").has_value());
}

TEST(DiskCache, EraseRemovesTheEntry) {
  TempDir tmp;
  auto cache = openCache(tmp.path(), 1 << 20);
  ASSERT_TRUE(cache);
  ASSERT_TRUE(cache->put("a", makeEntry("", 1, bytesOf("x"))).ok());
  ASSERT_TRUE(cache->put("b", makeEntry("", 1, bytesOf("y"))).ok());
  cache->erase("a");
  cache->erase("never stored");
  EXPECT_FALSE(cache->get("a").has_value());
  EXPECT_TRUE(cache->get("b").has_value());
  EXPECT_EQ(entryFiles(tmp.path()).size(), 1u);
  EXPECT_EQ(cache->bytesOnDisk(), 36u + 1 + 1);
}

TEST(DiskCache, TruncatedEntryIsAMissAndIsDeleted) {
  TempDir tmp;
  auto cache = openCache(tmp.path(), 1 << 20);
  ASSERT_TRUE(cache);
  ASSERT_TRUE(cache->put("key", makeEntry("etag", 5, pattern(200, 3))).ok());
  const fs::path file = onlyEntryFile(tmp.path());
  const auto whole = readAll(file);
  ASSERT_EQ(whole.size(), 36u + 3 + 4 + 200);
  // Inside the magic, each length, the key, the body and the CRC.
  for (size_t cut :
       {size_t{0}, size_t{1}, size_t{7}, size_t{8}, size_t{11}, size_t{13}, size_t{20}, size_t{35},
        size_t{36}, whole.size() / 2, whole.size() - 5, whole.size() - 4, whole.size() - 1}) {
    writeAll(file, std::vector<std::byte>(whole.begin(), whole.begin() + static_cast<long>(cut)));
    EXPECT_FALSE(cache->get("key").has_value()) << "cut at " << cut;
    EXPECT_FALSE(fs::exists(file)) << "cut at " << cut;
  }
  writeAll(file, whole);  // the untouched file still reads
  EXPECT_TRUE(cache->get("key").has_value());
}

TEST(DiskCache, FlippedByteIsAMissAndIsDeleted) {
  TempDir tmp;
  auto cache = openCache(tmp.path(), 1 << 20);
  ASSERT_TRUE(cache);
  ASSERT_TRUE(cache->put("key", makeEntry("etag", 5, pattern(200, 3))).ok());
  const fs::path file = onlyEntryFile(tmp.path());
  const auto whole = readAll(file);
  // Magic, key length, key, validator, fileBytes, body (start, middle, end), CRC.
  for (size_t at : {size_t{0}, size_t{11}, size_t{13}, size_t{20}, size_t{25}, size_t{40},
                    whole.size() - 204, whole.size() - 104, whole.size() - 5, whole.size() - 1}) {
    auto bad = whole;
    bad[at] ^= std::byte{0x10};
    writeAll(file, bad);
    EXPECT_FALSE(cache->get("key").has_value()) << "flipped byte " << at;
    EXPECT_FALSE(fs::exists(file)) << "flipped byte " << at;
  }
  writeAll(file, whole);
  auto got = cache->get("key");
  ASSERT_TRUE(got.has_value());
  EXPECT_EQ(got->body, pattern(200, 3));
}

TEST(DiskCache, LyingLengthsWithAGoodCrcAreMisses) {
  TempDir tmp;
  auto cache = openCache(tmp.path(), 1 << 20);
  ASSERT_TRUE(cache);
  ASSERT_TRUE(cache->put("k", makeEntry("", 0, {})).ok());
  const fs::path file = onlyEntryFile(tmp.path());
  const auto body = bytesOf("body");
  for (auto bytes : {encode("k", "v", 1, body, 0xFFFFFFF0u), encode("k", "v", 1, body, 70000u),
                     encode("k", "v", 1, body, 0u), encode("k", "v", 1, body, {}, ~uint64_t{0}),
                     encode("k", "v", 1, body, {}, 3u), encode("k", "v", 1, body, {}, 5u),
                     // Well formed, but with a validator over the 64 KiB limit.
                     encode("k", std::string(70000, 'v'), 1, body)}) {
    writeAll(file, bytes);
    EXPECT_FALSE(cache->get("k").has_value());
    EXPECT_FALSE(fs::exists(file));
  }
  // Longer than 64 KiB: refused on the way in, with the file named.
  auto r = cache->put(std::string(70000, 'k'), makeEntry("", 0, {}));
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find(tmp.path().string()), std::string::npos) << r.error();
  EXPECT_NE(r.error().find(".entry"), std::string::npos) << r.error();
  EXPECT_FALSE(cache->put("k", makeEntry(std::string(70000, 'v'), 0, {})).ok());
  EXPECT_TRUE(cache->put(std::string(60000, 'k'), makeEntry(std::string(60000, 'v'), 0, {})).ok());
  EXPECT_TRUE(cache->get(std::string(60000, 'k')).has_value());
}

TEST(DiskCache, EntryCopiedUnderAnotherKeysNameIsAMiss) {
  TempDir tmp;
  auto cache = openCache(tmp.path(), 1 << 20);
  ASSERT_TRUE(cache);
  ASSERT_TRUE(cache->put("tile/1", makeEntry("va", 1, bytesOf("tile 1 body"))).ok());
  const fs::path alphaFile = onlyEntryFile(tmp.path());
  ASSERT_TRUE(cache->put("tile/2", makeEntry("vb", 2, bytesOf("tile 2 body"))).ok());
  fs::path betaFile;
  for (const auto& f : entryFiles(tmp.path())) {
    if (f != alphaFile) betaFile = f;
  }
  ASSERT_FALSE(betaFile.empty());
  fs::copy_file(alphaFile, betaFile, fs::copy_options::overwrite_existing);
  EXPECT_FALSE(cache->get("tile/2").has_value());
  auto alpha = cache->get("tile/1");
  ASSERT_TRUE(alpha.has_value());
  EXPECT_EQ(textOf(alpha->body), "tile 1 body");
}

TEST(DiskCache, EvictionKeepsTheRecentlyUsedEntryWithinBudget) {
  TempDir tmp;
  constexpr uint64_t kEntryBytes = 36 + 6 + 1 + 1000;  // "key-NN", "v", 1000-byte body
  constexpr uint64_t kBudget = 10 * kEntryBytes + 500;
  auto cache = openCache(tmp.path(), kBudget);
  ASSERT_TRUE(cache);
  auto keyOf = [](int i) { return "key-" + std::to_string(10 + i); };
  // A fake clock far in the past, so that the order does not depend on timestamp resolution:
  // entry i was last used at base + i, while get() marks key 0 as used now.
  const time_t base = std::time(nullptr) - 100000;
  std::vector<fs::path> before;
  for (int i = 0; i < 30; ++i) {
    ASSERT_TRUE(cache->put(keyOf(i), makeEntry("v", 1, pattern(1000, unsigned(i)))).ok());
    EXPECT_LE(sizeOnDisk(tmp.path()), kBudget) << "after put " << i;
    EXPECT_EQ(cache->bytesOnDisk(), sizeOnDisk(tmp.path())) << "after put " << i;
    // Stamp the file just written with its place on the fake clock.
    const auto files = entryFiles(tmp.path());
    for (const auto& f : files) {
      if (std::find(before.begin(), before.end(), f) == before.end()) setMtime(f, base + i);
    }
    before = files;
    ASSERT_TRUE(cache->get(keyOf(0)).has_value()) << "after put " << i;
  }
  const size_t kept = entryFiles(tmp.path()).size();
  EXPECT_GE(kept, 9u);  // evicted down to <= 90 % of the budget, not further
  EXPECT_LE(kept, 10u);
  EXPECT_TRUE(cache->get(keyOf(0)).has_value());
  for (int i = 1; i < 20; ++i) EXPECT_FALSE(cache->get(keyOf(i)).has_value()) << keyOf(i);
  for (int i = 22; i < 30; ++i) EXPECT_TRUE(cache->get(keyOf(i)).has_value()) << keyOf(i);
}

TEST(DiskCache, OpenCountsEntriesEvictsAndRemovesStaleTemporaries) {
  TempDir tmp;
  uint64_t total = 0;
  {
    auto cache = openCache(tmp.path(), 1 << 20);
    ASSERT_TRUE(cache);
    for (int i = 0; i < 5; ++i) {
      ASSERT_TRUE(cache->put("k" + std::to_string(i), makeEntry("", 0, pattern(500, 1))).ok());
    }
    total = cache->bytesOnDisk();
    EXPECT_EQ(total, 5u * (36 + 2 + 500));
  }
  const fs::path sub = entryFiles(tmp.path())[0].parent_path();
  globe::testing::writeText(sub / "tmp-1-1-00000000deadbeef", "left by a crash");
  setMtime(sub / "tmp-1-1-00000000deadbeef", std::time(nullptr) - 7200);
  globe::testing::writeText(sub / "tmp-2-1-00000000cafebabe", "being written by another process");
  globe::testing::writeText(tmp / "README", "not ours");
  {
    auto cache = openCache(tmp.path(), 1 << 20);
    ASSERT_TRUE(cache);
    EXPECT_EQ(cache->bytesOnDisk(), total);
    EXPECT_FALSE(fs::exists(sub / "tmp-1-1-00000000deadbeef"));
    EXPECT_TRUE(fs::exists(sub / "tmp-2-1-00000000cafebabe"));
    EXPECT_TRUE(fs::exists(tmp / "README"));
  }
  fs::remove(sub / "tmp-2-1-00000000cafebabe");
  fs::remove(tmp / "README");
  // A smaller budget than what is there: evicted at open.
  auto small = openCache(tmp.path(), 2 * (36 + 2 + 500) + 10);
  ASSERT_TRUE(small);
  EXPECT_EQ(entryFiles(tmp.path()).size(), 1u);  // down to 90 %: one entry
  EXPECT_EQ(small->bytesOnDisk(), 36u + 2 + 500);
}

TEST(DiskCache, OversizedEntryIsNotStoredAndDropsTheOldOne) {
  TempDir tmp;
  auto cache = openCache(tmp.path(), 200);
  ASSERT_TRUE(cache);
  ASSERT_TRUE(cache->put("k", makeEntry("", 0, pattern(100, 1))).ok());
  ASSERT_TRUE(cache->get("k").has_value());
  ASSERT_TRUE(cache->put("k", makeEntry("", 0, pattern(300, 1))).ok());
  EXPECT_FALSE(cache->get("k").has_value());
  EXPECT_TRUE(entryFiles(tmp.path()).empty());
  EXPECT_EQ(cache->bytesOnDisk(), 0u);
  // A well-formed file larger than the budget cannot be one put() wrote: refused unread.
  ASSERT_TRUE(cache->put("k", makeEntry("", 0, pattern(100, 1))).ok());
  const fs::path file = onlyEntryFile(tmp.path());
  writeAll(file, encode("k", "", 0, pattern(300, 1)));
  EXPECT_FALSE(cache->get("k").has_value());
  EXPECT_FALSE(fs::exists(file));
}

TEST(DiskCache, OpenOnARegularFileIsAnErrorNamingIt) {
  TempDir tmp;
  globe::testing::writeText(tmp / "file", "x");
  auto r = DiskCache::open(tmp / "file", 1000);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find((tmp / "file").string()), std::string::npos) << r.error();
  EXPECT_NE(r.error().find("not a directory"), std::string::npos) << r.error();
  auto below = DiskCache::open(tmp / "file/cache", 1000);
  ASSERT_FALSE(below.ok());
  EXPECT_NE(below.error().find((tmp / "file/cache").string()), std::string::npos) << below.error();
  EXPECT_TRUE(fs::is_regular_file(tmp / "file"));
}

// Bodies encode their key and version, so that any mix-up between keys or between the fields of
// two versions shows.
std::vector<std::byte> bodyFor(const std::string& key, unsigned version) {
  std::string s = key + "|" + std::to_string(version) + "|";
  s.resize(s.size() + 100 + (version % 7) * 300, static_cast<char>('a' + version % 26));
  return bytesOf(s);
}

TEST(DiskCache, TwoInstancesHammeredFromFourThreadsNeverMixEntries) {
  TempDir tmp;
  constexpr uint64_t kBudget = 8 * 1000;  // ~8 of the 20 keys: eviction races with everything
  auto first = openCache(tmp.path(), kBudget);
  auto second = openCache(tmp.path(), kBudget);
  ASSERT_TRUE(first && second);
  std::atomic<int> wrong{0}, hits{0}, putErrors{0};
  std::vector<std::thread> threads;
  for (unsigned t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      DiskCache& cache = t % 2 ? *second : *first;
      std::mt19937 random(t);
      for (int i = 0; i < 600; ++i) {
        const std::string key = "https://host/tile/" + std::to_string(random() % 20);
        const auto op = random() % 10;
        if (op < 4) {
          const auto version = static_cast<unsigned>(random() % 1000);
          CacheEntry e = makeEntry("v" + std::to_string(version), version, bodyFor(key, version));
          if (!cache.put(key, e).ok()) ++putErrors;
        } else if (op < 9) {
          auto got = cache.get(key);
          if (!got) continue;
          ++hits;
          const auto version = static_cast<unsigned>(got->fileBytes);
          if (got->validator != "v" + std::to_string(version) ||
              got->body != bodyFor(key, version)) {
            ++wrong;
          }
        } else {
          cache.erase(key);
        }
      }
    });
  }
  for (auto& th : threads) th.join();
  EXPECT_EQ(wrong.load(), 0);
  EXPECT_EQ(putErrors.load(), 0);
  EXPECT_GT(hits.load(), 0);
  entryFiles(tmp.path());  // no temporaries left, only entry names
  first.reset();
  second.reset();
  auto reopened = openCache(tmp.path(), kBudget);
  ASSERT_TRUE(reopened);
  EXPECT_LE(sizeOnDisk(tmp.path()), kBudget);
  EXPECT_EQ(reopened->bytesOnDisk(), sizeOnDisk(tmp.path()));
}

class EnvironmentOverride {
 public:
  explicit EnvironmentOverride(const char* name) : name_(name) {
    if (const char* v = std::getenv(name)) saved_ = v;
  }
  ~EnvironmentOverride() {
    if (saved_) {
      ::setenv(name_, saved_->c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }
  EnvironmentOverride(const EnvironmentOverride&) = delete;
  EnvironmentOverride& operator=(const EnvironmentOverride&) = delete;

 private:
  const char* name_;
  std::optional<std::string> saved_;
};

TEST(DiskCache, DefaultDirectoryFollowsXdgThenHome) {
  EnvironmentOverride xdg("XDG_CACHE_HOME");
  EnvironmentOverride home("HOME");
  ::setenv("XDG_CACHE_HOME", "/var/cache/someone", 1);
  ::setenv("HOME", "/home/someone", 1);
  EXPECT_EQ(DiskCache::defaultDirectory(), fs::path("/var/cache/someone/globe"));
  ::setenv("XDG_CACHE_HOME", "relative/is/ignored", 1);
  EXPECT_EQ(DiskCache::defaultDirectory(), fs::path("/home/someone/.cache/globe"));
  ::unsetenv("XDG_CACHE_HOME");
  EXPECT_EQ(DiskCache::defaultDirectory(), fs::path("/home/someone/.cache/globe"));
  ::unsetenv("HOME");
  EXPECT_EQ(DiskCache::defaultDirectory(), fs::path(".globe-cache"));
}

}  // namespace
}  // namespace globe::transport
