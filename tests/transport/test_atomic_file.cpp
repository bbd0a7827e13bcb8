// writeFileAtomically and readWholeFile: content, replacement, no temporaries left, clear errors.
#include "transport/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <string>

#include "tests/support/test_io_util.hpp"

namespace globe::transport {
namespace {

using globe::testing::TempDir;

std::string asText(const std::vector<std::byte>& bytes) {
  return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

size_t countEntries(const std::filesystem::path& dir) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicFile, WritesThenReplacesWithoutLeavingTemporaries) {
  TempDir dir;
  const auto path = dir / "a.txt";
  ASSERT_TRUE(writeFileAtomically(path, std::string_view("first version\n")).ok());
  ASSERT_TRUE(writeFileAtomically(path, std::string_view("second")).ok());
  auto bytes = readWholeFile(path, 100);
  ASSERT_TRUE(bytes.ok()) << bytes.error();
  EXPECT_EQ(asText(*bytes), "second");
  EXPECT_EQ(countEntries(dir.path()), 1u);
}

TEST(AtomicFile, WritesBinaryAndEmptyFiles) {
  TempDir dir;
  std::vector<std::byte> data(70000);
  for (size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::byte>(i * 7);
  ASSERT_TRUE(writeFileAtomically(dir / "bin", std::span<const std::byte>(data)).ok());
  auto back = readWholeFile(dir / "bin", data.size());
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(*back, data);

  ASSERT_TRUE(writeFileAtomically(dir / "empty", std::string_view()).ok());
  auto empty = readWholeFile(dir / "empty", 0);
  ASSERT_TRUE(empty.ok()) << empty.error();
  EXPECT_TRUE(empty->empty());
}

TEST(AtomicFile, FailedRenameKeepsTargetAndRemovesTemporary) {
  TempDir dir;
  const auto target = dir / "occupied";
  std::filesystem::create_directory(target);
  globe::testing::writeText(target / "inside", "keep me");
  auto r = writeFileAtomically(target, std::string_view("x"));
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find(target.string()), std::string::npos) << r.error();
  EXPECT_NE(r.error().find("rename"), std::string::npos) << r.error();
  EXPECT_TRUE(std::filesystem::is_directory(target));
  EXPECT_EQ(countEntries(dir.path()), 1u) << "temporary left behind";
}

TEST(AtomicFile, MissingDirectoryIsAnErrorNamingThePath) {
  TempDir dir;
  const auto path = dir / "no/such/dir/file";
  auto r = writeFileAtomically(path, std::string_view("x"));
  ASSERT_FALSE(r.ok());
  // Named as given, not by the temporary name the write goes through.
  EXPECT_EQ(r.error(), path.string() + ": cannot write: its folder " +
                           path.parent_path().string() + " does not exist");
}

TEST(AtomicFile, ReadRefusesOversizedMissingAndDirectories) {
  TempDir dir;
  globe::testing::writeText(dir / "big", std::string(1000, 'x'));
  auto big = readWholeFile(dir / "big", 999);
  ASSERT_FALSE(big.ok());
  EXPECT_NE(big.error().find("1000 bytes"), std::string::npos) << big.error();
  EXPECT_NE(big.error().find("big"), std::string::npos) << big.error();
  EXPECT_TRUE(readWholeFile(dir / "big", 1000).ok());

  auto missing = readWholeFile(dir / "missing", 10);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().find("missing"), std::string::npos) << missing.error();

  auto directory = readWholeFile(dir.path(), 10);
  ASSERT_FALSE(directory.ok());
  EXPECT_NE(directory.error().find("not a regular file"), std::string::npos) << directory.error();
}

TEST(AtomicFile, ReadRefusesAFifoWithoutWaitingAndNamesADanglingLink) {
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0644), 0);
  ::alarm(20);  // opening a FIFO without a writer blocks: fail rather than hang
  auto fifo = readWholeFile(dir / "fifo", 10);
  ::alarm(0);
  ASSERT_FALSE(fifo.ok());
  EXPECT_NE(fifo.error().find("not a regular file"), std::string::npos) << fifo.error();

  std::filesystem::create_symlink(dir / "gone", dir / "link");
  auto dangling = readWholeFile(dir / "link", 10);
  ASSERT_FALSE(dangling.ok());
  EXPECT_NE(dangling.error().find("link: cannot open: No such file"), std::string::npos)
      << dangling.error();
}

}  // namespace
}  // namespace globe::transport
