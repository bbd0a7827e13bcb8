// writeFileAtomically under injected I/O faults: short and interrupted writes, a full disk at
// write, fsync, close or rename, a write that returns 0. The test links with
// -Wl,--wrap=write,--wrap=fsync,--wrap=close,--wrap=rename: only descriptors and paths whose name
// holds the armed marker are faulted, everything else goes straight to the C library.
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <ostream>
#include <string>

#include "tests/support/test_io_util.hpp"
#include "transport/atomic_file.hpp"

extern "C" {
ssize_t __real_write(int fd, const void* data, size_t bytes);
int __real_fsync(int fd);
int __real_close(int fd);
int __real_rename(const char* from, const char* to);
}

namespace {

struct Faults {
  std::string marker;  // empty: nothing is faulted
  size_t maxBytesPerWrite = SIZE_MAX;
  int interruptedWrites = 0;     // the first N writes fail with EINTR
  size_t spaceBytes = SIZE_MAX;  // writes past this many bytes fail with ENOSPC
  bool writeReturnsZero = false;
  int fsyncErrno = 0;
  int closeErrno = 0;  // after really closing, as Linux does
  int renameErrno = 0;
  size_t writtenBytes = 0;
  int writeCalls = 0;
};
Faults faults;

bool armedFor(int fd) {
  if (faults.marker.empty()) return false;
  char link[PATH_MAX];
  const std::string proc = "/proc/self/fd/" + std::to_string(fd);
  const ssize_t n = ::readlink(proc.c_str(), link, sizeof link - 1);
  return n > 0 &&
         std::string(link, static_cast<size_t>(n)).find(faults.marker) != std::string::npos;
}

}  // namespace

extern "C" ssize_t __wrap_write(int fd, const void* data, size_t bytes) {
  if (!armedFor(fd)) return __real_write(fd, data, bytes);
  ++faults.writeCalls;
  if (faults.interruptedWrites > 0) {
    --faults.interruptedWrites;
    errno = EINTR;
    return -1;
  }
  if (faults.writeReturnsZero) return 0;
  const size_t room = faults.spaceBytes - std::min(faults.spaceBytes, faults.writtenBytes);
  if (room == 0 && bytes > 0) {
    errno = ENOSPC;
    return -1;
  }
  const ssize_t n = __real_write(fd, data, std::min({bytes, faults.maxBytesPerWrite, room}));
  if (n > 0) faults.writtenBytes += static_cast<size_t>(n);
  return n;
}

extern "C" int __wrap_fsync(int fd) {
  if (faults.fsyncErrno != 0 && armedFor(fd)) {
    errno = faults.fsyncErrno;
    return -1;
  }
  return __real_fsync(fd);
}

extern "C" int __wrap_close(int fd) {
  const bool fail = faults.closeErrno != 0 && armedFor(fd);
  const int rc = __real_close(fd);
  if (fail) {
    errno = faults.closeErrno;
    return -1;
  }
  return rc;
}

extern "C" int __wrap_rename(const char* from, const char* to) {
  if (faults.renameErrno != 0 && !faults.marker.empty() &&
      std::string(from).find(faults.marker) != std::string::npos) {
    errno = faults.renameErrno;
    return -1;
  }
  return __real_rename(from, to);
}

namespace globe::transport {
namespace {

using globe::testing::TempDir;

std::vector<std::byte> pattern(size_t bytes) {
  std::vector<std::byte> data(bytes);
  for (size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::byte>(i * 13 + 5);
  return data;
}

std::vector<std::string> entries(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    names.push_back(e.path().filename().string());
  }
  return names;
}

size_t openDescriptors() {
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator("/proc/self/fd")) ++n;
  return n;
}

// Arms `f` for files under `dir` for one call.
Result<void> writeWith(Faults f, const TempDir& dir, const std::filesystem::path& path,
                       std::span<const std::byte> bytes) {
  f.marker = dir.path().filename().string();
  faults = f;
  auto result = writeFileAtomically(path, bytes);
  const Faults seen = faults;
  faults = Faults{};
  if (f.maxBytesPerWrite != SIZE_MAX) {
    EXPECT_GT(seen.writeCalls, 1) << "the fault never fired";
  }
  return result;
}

TEST(AtomicFileFaults, ShortAndInterruptedWritesStillWriteEverything) {
  TempDir dir;
  const auto data = pattern(70000);
  Faults f;
  f.maxBytesPerWrite = 999;
  f.interruptedWrites = 3;
  ASSERT_TRUE(writeWith(f, dir, dir / "pack", data).ok());
  auto back = readWholeFile(dir / "pack", data.size());
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(*back, data);
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"pack"});
}

struct FaultCase {
  const char* name;
  Faults faults;
  const char* step;       // the failed step the message names
  const char* errnoText;  // and the reason
};

// Shown by its name, not its raw bytes (pointers that differ from run to run, in CTest's names).
void PrintTo(const FaultCase& c, std::ostream* out) { *out << c.name; }

class AtomicFileFault : public ::testing::TestWithParam<FaultCase> {};

TEST_P(AtomicFileFault, KeepsTheOldFileRemovesTheTemporaryAndNamesFileAndReason) {
  const FaultCase& c = GetParam();
  TempDir dir;
  const auto target = dir / "L3_0_0.pack";
  globe::testing::writeText(target, "the previous, complete version");
  const size_t descriptors = openDescriptors();
  ::alarm(20);  // a write loop that never ends fails the test instead of hanging it
  auto r = writeWith(c.faults, dir, target, pattern(70000));
  ::alarm(0);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find(target.string()), std::string::npos) << r.error();
  EXPECT_NE(r.error().find(c.step), std::string::npos) << r.error();
  EXPECT_NE(r.error().find(c.errnoText), std::string::npos) << r.error();
  auto kept = readWholeFile(target, 1000);
  ASSERT_TRUE(kept.ok()) << kept.error();
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(kept->data()), kept->size()),
            "the previous, complete version");
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"L3_0_0.pack"}) << "temporary left";
  EXPECT_EQ(openDescriptors(), descriptors) << "descriptor leaked";
}

Faults diskFullAfter(size_t bytes) {
  Faults f;
  f.spaceBytes = bytes;
  return f;
}
Faults with(int Faults::*member, int err) {
  Faults f;
  f.*member = err;
  return f;
}
Faults zeroWrites() {
  Faults f;
  f.writeReturnsZero = true;
  return f;
}

INSTANTIATE_TEST_SUITE_P(
    Faults, AtomicFileFault,
    ::testing::Values(
        FaultCase{"FullBeforeTheFirstByte", diskFullAfter(0), "write failed",
                  "No space left on device"},
        FaultCase{"FullMidWrite", diskFullAfter(30000), "write failed", "No space left on device"},
        FaultCase{"FullAtFsync", with(&Faults::fsyncErrno, ENOSPC), "fsync failed",
                  "No space left on device"},
        FaultCase{"IoErrorAtFsync", with(&Faults::fsyncErrno, EIO), "fsync failed",
                  "Input/output error"},
        FaultCase{"FullAtClose", with(&Faults::closeErrno, ENOSPC), "close failed",
                  "No space left on device"},
        FaultCase{"QuotaAtClose", with(&Faults::closeErrno, EDQUOT), "close failed",
                  "Disk quota exceeded"},
        FaultCase{"FullAtRename", with(&Faults::renameErrno, ENOSPC), "rename failed",
                  "No space left on device"},
        FaultCase{"WriteReturnsZero", zeroWrites(), "write failed", "Input/output error"}),
    [](const ::testing::TestParamInfo<FaultCase>& param) { return std::string(param.param.name); });

}  // namespace
}  // namespace globe::transport
